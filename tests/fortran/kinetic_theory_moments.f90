! The Fortran module (bindings/fortran/fluidbed.f90) beyond drag, against independent values,
! ctest fortran.kinetic_theory_moments (the constitutive and mixture rows also bit for bit with the
! C functions called directly on the same arrays):
!  - every radial distribution row and every one-class law row of tests/reference/ktgf_reference.csv
!    (mpmath; the tables' names mapped as tests/kinetic_theory_table_names.hpp does), value within
!    1e-13 and slopes within 1e-12 (relative, the C++ tests' scales), over arrays of cells;
!  - every row of ktgf_mixture_reference.csv: the mixture radial distributions (value, ∂/∂φ_m) and
!    Syamlal's solid-solid drag with g from the mixture distribution (derivatives by the chain
!    rule), 1e-13 value and 1e-12 derivatives scaled as tests/test_kinetic_theory_mixture.cpp;
!  - every gas exchange source row of ktgf_exchange_reference.csv (each source with only its own
!    arguments), 1e-13 value and 1e-11 derivatives as tests/test_kinetic_theory_friction_exchange.cpp;
!  - every row of cd_reference.csv: C_D Re of the single-sphere closures (law//'Coefficient'), Stokes
!    exactly and the others within 1e-14 as tests/test_drag_family.cpp (the table has no derivative);
!  - the 96 closure rows of settling_reference.csv (tests/test_c_interface.cpp's mapping): the
!    Richardson-Zaki exponents within 1e-14, Re_mf within 1e-13, the terminal velocities
!    u_t = Re_t(Ar) μ/(ρ_f d), Ar with g = 9.81 as the library's archimedes(), within 1e-13
!    (Schiller-Naumann's root 1e-12), as tests/test_settling.cpp but relative;
!  - every row of ktgf_friction_reference.csv: the Johnson-Jackson and Schaeffer pressures, Schaeffer's
!    viscosity of either (∂/∂φ by the chain rule) and the Srivastava-Sundaresan stress, with the row's
!    parameters, value within 1e-13 and ∂/∂φ within 1e-11 of |∂| + 1e-9 |value| as
!    tests/test_kinetic_theory_friction_exchange.cpp (the C functions give no other derivative);
!  - elastic_state_reference.csv: Mazzei-Lettieri's modulus at each drag state (ε, w) within 1e-13 of
!    the table's, as tests/test_elastic.cpp; the three moduli at equilibrium (g = 9.80665, Re_t =
!    the reynolds column, as tests/test_c_interface.cpp) have no value in the table: a status and a
!    finite modulus only; the models with no modulus off equilibrium refuse a state;
!  - moments_reference.csv: every case and node count (1 to FLUIDBED_MAX_NODES) with a Gauss rule,
!    inverted from its 2N moments (whole line for hermite_* and random_jacobi_*), nodes within
!    8·2N·node_condition + 8e-16 of the spread and weights within 8·2N·weight_condition + 8e-16
!    of m_0, as tests/test_moment_oracle.cpp (the Radau rule, not a Gauss rule, is left out);
!  - moments: the inversion recovers known atoms, a zero cell is zero mass, the realizability of
!    sets with m_0 m_2 < m_1^2 and m_1 m_3 < m_2^2, the correction's monodisperse and log-normal
!    sets (tests/test_moment_correction.cpp's numbers) and that they come back realizable;
!  - DQMOM sources: pure growth gives c^φ = 3φG/ξ and c^ξ = 4φG (the point functionals, to a few
!    ulp; the moment sources, within the condition number), a cell with merged nodes, the wrappers'
!    bits equal to the C functions', and arrays of the wrong shape;
!  - the unequal-temperature mixture: the wrapper's values and derivatives equal to the C function's
!    bits (3 classes, 4 cells); one class gives Lun's pressure αρΘ(1 + 2(1 + e)α h) with h the
!    returned contact value (1e-14); μ_12/μ_21 = m_1Θ_1/(m_2Θ_2), which fixes the (cell, k, i)
!    layout; β and s symmetric with a zero diagonal, λ = (5/3)μ; Σ_i γ_i = 0 at e = 1; bad input;
!  - the catalogue and the closures' metadata;
!  - bad input: arrays of different sizes or shapes, NaN fractions (the status, the 1-based cell, the
!    message naming the argument), an unknown name, closures of the wrong family, bad options.
! Usage: fluidbed_fortran_kinetic_theory_moments PATH/TO/tests/reference
program kinetic_theory_moments
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_size_t, c_ptr, c_null_ptr, c_loc
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
  use fluidbed
  use fortran_checks
  implicit none
  ! Four C functions themselves, called on the same arrays to show that the wrappers return their
  ! bits (the wrappers pass the arrays' addresses; fortran.drag_table shows the same for drag).
  interface
    integer(c_int) function c_constitutive(law, radial, n, phi, theta, d, rho, e, value, d_phi, d_theta, error) &
        bind(C, name='fluidbed_constitutive')
      import :: c_int, c_size_t, c_double, c_ptr
      type(c_ptr), value :: law, radial, error
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: phi(*), theta(*), d(*), rho(*), e(*)
      real(c_double), intent(out) :: value(*), d_phi(*), d_theta(*)
    end function
    integer(c_int) function c_mixture_radial_distribution(law, n, classes, i, k, fractions, diameters, g, &
                                                          d_fractions, error) &
        bind(C, name='fluidbed_mixture_radial_distribution')
      import :: c_int, c_size_t, c_double, c_ptr
      type(c_ptr), value :: law, error
      integer(c_size_t), value :: n, classes, i, k
      real(c_double), intent(in) :: fractions(*), diameters(*)
      real(c_double), intent(out) :: g(*), d_fractions(*)
    end function
    integer(c_int) function c_dqmom_sources(node_count, n, nodes, weights, moment_sources, weight_sources, &
                                            weighted_node_sources, status, condition, error) &
        bind(C, name='fluidbed_dqmom_sources')
      import :: c_int, c_size_t, c_double, c_ptr
      integer(c_int), value :: node_count
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: nodes(*), weights(*), moment_sources(*)
      real(c_double), intent(out) :: weight_sources(*), weighted_node_sources(*)
      integer(c_int), intent(out) :: status(*)
      type(c_ptr), value :: condition, error
    end function
    integer(c_int) function c_dqmom_growth_diffusion_sources(node_count, weights_kind, n, nodes, weights, growth_rate, &
                                                             diffusion_intensity, weight_sources, &
                                                             weighted_node_sources, status, condition, error) &
        bind(C, name='fluidbed_dqmom_growth_diffusion_sources')
      import :: c_int, c_size_t, c_double, c_ptr
      integer(c_int), value :: node_count, weights_kind
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: nodes(*), weights(*)
      type(c_ptr), value :: growth_rate, diffusion_intensity, condition, error
      real(c_double), intent(out) :: weight_sources(*), weighted_node_sources(*)
      integer(c_int), intent(out) :: status(*)
    end function
    integer(c_int) function c_unequal_temperature_mixture(radial, n, classes, fractions, temperatures, diameters, &
                                                          densities, restitution, p1, p2, p3, p4, p5, p6, p7, p8, p9, &
                                                          p10, p11, p12, p13, p14, p15, p16, p17, p18, p19, p20, p21, &
                                                          p22, p23, p24, error) &
        bind(C, name='fluidbed_unequal_temperature_mixture_with_derivatives')
      import :: c_int, c_size_t, c_double, c_ptr
      type(c_ptr), value :: radial, error
      integer(c_size_t), value :: n, classes
      real(c_double), intent(in) :: fractions(*), temperatures(*), diameters(*), densities(*), restitution(*)
      type(c_ptr), value :: p1, p2, p3, p4, p5, p6, p7, p8, p9, p10, p11, p12, p13, p14, p15, p16, p17, p18, p19, &
                            p20, p21, p22, p23, p24
    end function
  end interface
  integer, parameter :: field = 40, key_length = 8 * (field + 1)
  ! A CSV table: its header's names and its cells as text, cells(column, row).
  type :: table
    character(len=field), allocatable :: names(:)
    character(len=field), allocatable :: cells(:, :)
  end type
  ! The tables' names and the library's (tests/kinetic_theory_table_names.hpp).
  character(len=*), parameter :: radial_tables(10) = [character(len=24) :: 'carnahan_starling', 'percus_yevick', &
    'lun_savage', 'sinclair_jackson', 'ogawa', 'gidaspow', 'ma_ahmadi', 'lathouwers_bellan', 'song_stratt_mason', &
    'tobochnik_chapin']
  character(len=*), parameter :: radial_names(10) = [character(len=32) :: 'CarnahanStarling', 'PercusYevick', &
    'LunSavage', 'SinclairJackson', 'Ogawa', 'GidaspowRadialDistribution', 'MaAhmadi', 'LathouwersBellan', &
    'SongStrattMason', 'TobochnikChapin']
  character(len=*), parameter :: law_tables(13) = [character(len=48) :: 'granular_pressure:lun', &
    'granular_pressure:syamlal_rogers_obrien', 'granular_pressure:ma_ahmadi', 'shear_viscosity:gidaspow', &
    'shear_viscosity:syamlal', 'shear_viscosity:hrenya_sinclair', 'bulk_viscosity:lun', 'conductivity:gidaspow', &
    'conductivity:syamlal', 'conductivity:hrenya_sinclair', 'dissipation:lun', 'shear_viscosity:enskog', &
    'conductivity:enskog']
  character(len=*), parameter :: law_names(13) = [character(len=32) :: 'LunPressure', &
    'SyamlalRogersOBrienPressure', 'AhmadiMaPressure', 'GidaspowViscosity', 'SyamlalViscosity', &
    'HrenyaSinclairViscosity', 'LunBulkViscosity', 'GidaspowConductivity', 'SyamlalConductivity', &
    'HrenyaSinclairConductivity', 'LunDissipation', 'EnskogViscosity', 'EnskogConductivity']
  character(len=*), parameter :: mixture_tables(3) = [character(len=24) :: 'lebowitz', 'mansoori', &
    'modified_mansoori']
  character(len=*), parameter :: mixture_names(3) = [character(len=24) :: 'Lebowitz', 'Mansoori', 'ModifiedMansoori']
  ! settling_reference.csv's closure rows: the closure and the parameter param2 sets
  ! (tests/test_c_interface.cpp), and tests/test_settling.cpp's tolerance.
  character(len=*), parameter :: settling_tables(11) = [character(len=40) :: 'rz_exponent_mazzei', &
    'rz_exponent_rowe1987', 'rz_exponent_garside_aldibouni1977', 'rz_exponent_khan_richardson1989', &
    'rz_exponent_richardson_zaki1954', 'terminal_velocity_stokes', 'terminal_velocity_newton', &
    'terminal_velocity_dallavalle', 'terminal_velocity_schillernaumann', 'remf_ergun', 'remf_wenyu1966']
  character(len=*), parameter :: settling_names(11) = [character(len=40) :: 'MazzeiExponent', 'RoweExponent', &
    'GarsideAlDibouniExponent', 'KhanRichardsonExponent', 'RichardsonZaki1954Exponent', 'StokesTerminalVelocity', &
    'NewtonTerminalVelocity', 'DallavalleTerminalVelocity', 'SchillerNaumannTerminalVelocity', &
    'ErgunMinimumFluidization', 'WenYuMinimumFluidization']
  character(len=*), parameter :: settling_parameters(11) = [character(len=12) :: '', '', '', 'wall_ratio', &
    'wall_ratio', '', '', '', '', 'voidage', '']
  real(c_double), parameter :: settling_tolerances(11) = [1e-14_c_double, 1e-14_c_double, 1e-14_c_double, &
    1e-14_c_double, 1e-14_c_double, 1e-13_c_double, 1e-13_c_double, 1e-13_c_double, 1e-12_c_double, &
    1e-13_c_double, 1e-13_c_double]
  ! The library's g for Ar (include/fluidbed/properties.hpp) and π.
  real(c_double), parameter :: standard_gravity = 9.81_c_double
  real(c_double), parameter :: pi = 3.14159265358979323846264338327950288_c_double
  real(c_double), parameter :: zero = 0
  character(len=1024) :: directory
  integer :: radial_rows, law_rows, mixture_rows, solid_drag_rows, exchange_rows, sphere_drag_rows, &
             settling_rows, friction_rows, elastic_rows, moment_rules
  real(c_double) :: nan

  nan = ieee_value(zero, ieee_quiet_nan)
  call get_command_argument(1, directory)
  call check_one_class(trim(directory) // '/ktgf_reference.csv')
  call check_mixture(trim(directory) // '/ktgf_mixture_reference.csv')
  call check_exchange(trim(directory) // '/ktgf_exchange_reference.csv')
  call check_sphere_drag(trim(directory) // '/cd_reference.csv')
  call check_settling(trim(directory) // '/settling_reference.csv')
  call check_friction(trim(directory) // '/ktgf_friction_reference.csv')
  call check_elastic(trim(directory) // '/elastic_state_reference.csv')
  call check_moment_table(trim(directory) // '/moments_reference.csv')
  call check_moments()
  call check_dqmom()
  call check_unequal_temperature_mixture()
  call check_metadata()
  call check_bad_input()
  print '(a, 5(i0, a))', 'fortran: ', radial_rows, ' radial distribution rows, ', law_rows, &
        ' one-class law rows, ', mixture_rows, ' mixture radial distribution rows, ', solid_drag_rows, &
        ' solid-solid drag rows, ', exchange_rows, ' gas exchange rows'
  print '(a, 5(i0, a))', 'fortran: ', sphere_drag_rows, ' sphere drag rows, ', settling_rows, &
        ' settling closure rows, ', friction_rows, ' friction rows, ', elastic_rows, ' elastic state rows, ', &
        moment_rules, ' moment rules (case, node count)'
  call check(radial_rows == 214 .and. law_rows == 1260 .and. mixture_rows == 130 .and. solid_drag_rows == 224 .and. &
             exchange_rows == 72 .and. sphere_drag_rows == 30 .and. settling_rows == 96 .and. &
             friction_rows == 1253 .and. elastic_rows == 75 .and. moment_rules == 215, &
             'every row of the tables compared')
  call finish('fortran: kinetic theory and moments: all checks passed')

contains

  ! |a − b|/|b|, 0 when a = b (±∞ included); NaN gives NaN.
  elemental real(c_double) function relative_difference(a, b)
    real(c_double), intent(in) :: a, b
    relative_difference = 0
    if (.not. abs(a - b) <= 0) relative_difference = abs(a - b) / max(abs(b), tiny(b))
  end function

  ! |a − b|/(|b| + scale), 0 when a = b.
  elemental real(c_double) function scaled_error(a, b, scale)
    real(c_double), intent(in) :: a, b, scale
    scaled_error = 0
    if (.not. abs(a - b) <= 0) scaled_error = abs(a - b) / (abs(b) + scale)
  end function

  ! ---- Tables -----------------------------------------------------------------------------------

  subroutine split(line, fields, count)
    character(len=*), intent(in) :: line
    character(len=field), intent(out) :: fields(:)
    integer, intent(out) :: count
    integer :: start, comma
    count = 0
    start = 1
    do
      comma = index(line(start:), ',')
      count = count + 1
      if (comma == 0) then
        fields(count) = line(start:len_trim(line))
        return
      end if
      fields(count) = line(start:start + comma - 2)
      start = start + comma
    end do
  end subroutine

  function read_table(file) result(t)
    character(len=*), intent(in) :: file
    type(table) :: t
    character(len=2048) :: line
    character(len=field) :: fields(64)
    integer :: unit, status, count, rows, columns
    open(newunit=unit, file=file, status='old', action='read')
    read(unit, '(a)') line
    call split(line, fields, columns)
    allocate(t%names(columns))
    t%names = fields(1:columns)
    rows = 0
    do
      read(unit, '(a)', iostat=status) line
      if (status /= 0) exit
      if (len_trim(line) > 0) rows = rows + 1
    end do
    allocate(t%cells(columns, rows))
    rewind(unit)
    read(unit, '(a)') line
    rows = 0
    do
      read(unit, '(a)', iostat=status) line
      if (status /= 0) exit
      if (len_trim(line) == 0) cycle
      rows = rows + 1
      call split(line, fields, count)
      if (count /= columns) error stop 'a row of another length'
      t%cells(:, rows) = fields(1:columns)
    end do
    close(unit)
  end function

  integer function column(t, name)
    type(table), intent(in) :: t
    character(len=*), intent(in) :: name
    do column = 1, size(t%names)
      if (t%names(column) == name) return
    end do
    print '(2a)', 'no column ', name
    error stop 1
  end function

  function text(t, row, name)
    type(table), intent(in) :: t
    integer, intent(in) :: row
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: text
    text = trim(t%cells(column(t, name), row))
  end function

  real(c_double) function number(t, row, name)
    type(table), intent(in) :: t
    integer, intent(in) :: row
    character(len=*), intent(in) :: name
    read(t%cells(column(t, name), row), *) number
  end function

  ! The column `name` of the rows `rows`, as numbers.
  function numbers(t, rows, name) result(values)
    type(table), intent(in) :: t
    integer, intent(in) :: rows(:)
    character(len=*), intent(in) :: name
    real(c_double) :: values(size(rows))
    integer :: c
    do c = 1, size(rows)
      values(c) = number(t, rows(c), name)
    end do
  end function

  ! Each row's key: the texts of the named columns (up to 8), joined.
  function keys_of(t, columns) result(keys)
    type(table), intent(in) :: t
    character(len=*), intent(in) :: columns(:)
    character(len=key_length), allocatable :: keys(:)
    integer :: row, j
    if (size(columns) > key_length / (field + 1)) error stop 'keys_of: too many columns'
    allocate(keys(size(t%cells, 2)))
    keys = ''
    do row = 1, size(keys)
      do j = 1, size(columns)
        keys(row) = trim(keys(row)) // ' ' // text(t, row, trim(columns(j)))
      end do
    end do
  end function

  ! The rows whose key is that of `row` and that are not done yet (then done).
  function group_of(keys, row, done) result(rows)
    character(len=*), intent(in) :: keys(:)
    integer, intent(in) :: row
    logical, intent(inout) :: done(:)
    integer, allocatable :: rows(:)
    logical :: same(size(keys))
    integer :: r
    same = keys == keys(row) .and. .not. done
    rows = pack([(r, r = 1, size(keys))], same)
    done = done .or. same
  end function

  function library_name(tables, names, name) result(library)
    character(len=*), intent(in) :: tables(:), names(:), name
    character(len=:), allocatable :: library
    integer :: i
    library = ''
    do i = 1, size(tables)
      if (tables(i) == name) library = trim(names(i))
    end do
  end function

  ! The position of name in list, 0 if absent.
  integer function position(list, name)
    character(len=*), intent(in) :: list(:), name
    do position = 1, size(list)
      if (list(position) == name) return
    end do
    position = 0
  end function

  logical function ends_with(string, suffix)
    character(len=*), intent(in) :: string, suffix
    ends_with = len(string) >= len(suffix)
    if (ends_with) ends_with = string(len(string) - len(suffix) + 1:) == suffix
  end function

  logical function has_parameter(closure, name)
    type(fluidbed_closure), intent(in) :: closure
    character(len=*), intent(in) :: name
    integer :: i
    has_parameter = .false.
    do i = 1, fluidbed_parameter_count(closure)
      if (fluidbed_parameter_name(closure, i) == name) has_parameter = .true.
    end do
  end function

  ! A closure by name, with its parameter `parameter` set where given.
  function created(name, parameter, value) result(closure)
    character(len=*), intent(in) :: name
    character(len=*), intent(in), optional :: parameter
    real(c_double), intent(in), optional :: value
    type(fluidbed_closure) :: closure
    character(len=:), allocatable :: message
    integer :: status
    status = fluidbed_create(name, closure, message)
    call check(status == FLUIDBED_OK, 'create ' // name // ': ' // message)
    if (present(parameter)) then
      status = fluidbed_set_parameter(closure, parameter, value, message)
      call check(status == FLUIDBED_OK, name // ' ' // parameter // ': ' // message)
    end if
  end function

  ! The radial distribution of a table's name; Ogawa with φ_max = 0.63 (tests/reference/README.md).
  function table_radial(name) result(radial)
    character(len=*), intent(in) :: name
    type(fluidbed_closure) :: radial
    if (name == 'ogawa') then
      radial = created('Ogawa', 'max_packing', 0.63_c_double)
    else
      radial = created(library_name(radial_tables, radial_names, name))
    end if
  end function

  ! ---- One class: radial distributions and the laws of (φ, Θ, g0, material) ---------------------

  subroutine check_one_class(file)
    character(len=*), intent(in) :: file
    type(table) :: t
    character(len=key_length), allocatable :: keys(:)
    logical, allocatable :: done(:)
    integer, allocatable :: rows(:)
    integer :: row
    t = read_table(file)
    keys = keys_of(t, [character(len=8) :: 'function', 'variant', 'extra'])
    allocate(done(size(keys)))
    done = .false.
    radial_rows = 0
    law_rows = 0
    do row = 1, size(keys)
      if (done(row)) cycle
      rows = group_of(keys, row, done)
      if (text(t, row, 'function') == 'radial_distribution') then
        call check_radial_rows(t, rows)
      else
        call check_law_rows(t, rows)
      end if
    end do
  end subroutine

  subroutine check_radial_rows(t, rows)
    type(table), intent(in) :: t
    integer, intent(in) :: rows(:)
    type(fluidbed_closure) :: law
    real(c_double) :: phi(size(rows)), value(size(rows)), slope(size(rows))
    character(len=:), allocatable :: message, name
    integer :: status, c
    name = library_name(radial_tables, radial_names, text(t, rows(1), 'variant'))
    law = created(name)
    if (has_parameter(law, 'max_packing')) then
      status = fluidbed_set_parameter(law, 'max_packing', number(t, rows(1), 'extra'), message)
      call check(status == FLUIDBED_OK, name // ' max_packing: ' // message)
    end if
    phi = numbers(t, rows, 'solid_fraction')
    status = fluidbed_of_solid_fraction(law, phi, value, slope, message)
    call check(status == FLUIDBED_OK, name // ': ' // message)
    do c = 1, size(rows)
      call check(relative_difference(value(c), number(t, rows(c), 'value')) < 1e-13_c_double, &
                 name // ': g0 against the reference table')
      call check(relative_difference(slope(c), number(t, rows(c), 'd_solid_fraction')) < 1e-12_c_double, &
                 name // ': dg0/dphi against the reference table')
    end do
    radial_rows = radial_rows + size(rows)
    call fluidbed_destroy(law)
  end subroutine

  subroutine check_law_rows(t, rows)
    type(table), intent(in) :: t
    integer, intent(in) :: rows(:)
    type(fluidbed_closure) :: law, radial
    real(c_double), dimension(size(rows)) :: phi, theta, d, rho, e, value, d_phi, d_theta, c_value, c_d_phi, &
                                             c_d_theta
    real(c_double) :: expected
    character(len=:), allocatable :: message, variant, name
    integer :: status, c, colon
    variant = text(t, rows(1), 'variant')
    colon = index(variant, ':')
    ! The kinetic and collisional parts and the algebraic temperature are not closures.
    name = library_name(law_tables, law_names, text(t, rows(1), 'function') // ':' // variant(1:colon - 1))
    if (name == '') return
    law = created(name)
    ! The table's extra is the law's one parameter (Hrenya-Sinclair's L, Ahmadi-Ma's friction).
    if (fluidbed_parameter_count(law) == 1) then
      status = fluidbed_set_parameter(law, fluidbed_parameter_name(law, 1), number(t, rows(1), 'extra'), message)
      call check(status == FLUIDBED_OK, name // ': ' // message)
    end if
    radial = table_radial(variant(colon + 1:))
    phi = numbers(t, rows, 'solid_fraction')
    theta = numbers(t, rows, 'granular_temperature')
    d = numbers(t, rows, 'diameter')
    rho = numbers(t, rows, 'particle_density')
    e = numbers(t, rows, 'restitution')
    status = fluidbed_constitutive(law, radial, phi, theta, d, rho, e, value, d_phi, d_theta, message)
    call check(status == FLUIDBED_OK, name // ': ' // message)
    status = c_constitutive(law%handle, radial%handle, size(rows, kind=c_size_t), phi, theta, d, rho, e, c_value, &
                            c_d_phi, c_d_theta, c_null_ptr)
    call check(status == FLUIDBED_OK .and. all(same_bits(value, c_value)) .and. all(same_bits(d_phi, c_d_phi)) .and. &
               all(same_bits(d_theta, c_d_theta)), name // ': the wrapper returns the C function''s bits')
    do c = 1, size(rows)
      expected = number(t, rows(c), 'value')
      call check(relative_difference(value(c), expected) < 1e-13_c_double, name // ' ' // variant // ': value')
      ! Derivative scales: value/φ and value/Θ.
      call check(scaled_error(d_phi(c), number(t, rows(c), 'd_solid_fraction'), abs(expected) / phi(c)) &
                 < 1e-12_c_double, name // ' ' // variant // ': d/dphi')
      call check(scaled_error(d_theta(c), number(t, rows(c), 'd_granular_temperature'), abs(expected) / theta(c)) &
                 < 1e-12_c_double, name // ' ' // variant // ': d/dTheta')
    end do
    law_rows = law_rows + size(rows)
    call fluidbed_destroy(law)
    call fluidbed_destroy(radial)
  end subroutine

  ! ---- Several classes ----------------------------------------------------------------------------

  subroutine check_mixture(file)
    character(len=*), intent(in) :: file
    type(table) :: t
    character(len=key_length), allocatable :: keys(:)
    logical, allocatable :: done(:)
    integer, allocatable :: rows(:)
    integer :: row
    t = read_table(file)
    keys = keys_of(t, [character(len=24) :: 'function', 'variant', 'classes', 'i', 'k', 'max_packing', &
                                            'restitution', 'friction_coefficient'])
    allocate(done(size(keys)))
    done = .false.
    mixture_rows = 0
    solid_drag_rows = 0
    do row = 1, size(keys)
      if (.not. done(row)) then
        rows = group_of(keys, row, done)
        call check_mixture_rows(t, rows)
      end if
    end do
  end subroutine

  ! A group of rows of one law, class count and pair (i, k): the mixture distribution over the
  ! cells (fractions(c, m), diameters(c, m)) and, for the drag rows, K_ik of its g_ik.
  subroutine check_mixture_rows(t, rows)
    type(table), intent(in) :: t
    integer, intent(in) :: rows(:)
    type(fluidbed_closure) :: rdf, drag
    real(c_double), allocatable :: fractions(:, :), diameters(:, :), d_fractions(:, :), c_d_fractions(:, :)
    real(c_double), dimension(size(rows)) :: g, rho_i, rho_k, e, w, k_ik, d_phi_p, d_phi_q, d_g, d_w, c_g
    real(c_double) :: expected, derivative
    character(len=:), allocatable :: message, what, variant, rdf_table, name
    integer :: status, classes, i, k, c, m, colon, n
    character(len=1) :: digit
    n = size(rows)
    what = text(t, rows(1), 'function')
    variant = text(t, rows(1), 'variant')
    colon = index(variant, ':')
    rdf_table = variant(colon + 1:)
    classes = nint(number(t, rows(1), 'classes'))
    i = nint(number(t, rows(1), 'i')) + 1  ! 1-based, as the wrapper takes them
    k = nint(number(t, rows(1), 'k')) + 1
    allocate(fractions(n, classes), diameters(n, classes), d_fractions(n, classes), c_d_fractions(n, classes))
    do m = 1, classes
      digit = achar(iachar('0') + m)
      do c = 1, n
        fractions(c, m) = number(t, rows(c), 'phi' // digit)
        diameters(c, m) = number(t, rows(c), 'd' // digit)
      end do
    end do
    name = library_name(mixture_tables, mixture_names, rdf_table)
    rdf = created(name)
    if (has_parameter(rdf, 'max_packing')) then
      status = fluidbed_set_parameter(rdf, 'max_packing', number(t, rows(1), 'max_packing'), message)
      call check(status == FLUIDBED_OK, name // ' max_packing: ' // message)
    end if
    status = fluidbed_mixture_radial_distribution(rdf, i, k, fractions, diameters, g, d_fractions, message)
    call check(status == FLUIDBED_OK, name // ': ' // message)
    status = c_mixture_radial_distribution(rdf%handle, int(n, c_size_t), int(classes, c_size_t), int(i - 1, c_size_t), &
                                           int(k - 1, c_size_t), fractions, diameters, c_g, c_d_fractions, c_null_ptr)
    call check(status == FLUIDBED_OK .and. all(same_bits(g, c_g)) .and. all(same_bits(d_fractions, c_d_fractions)), &
               name // ': the wrapper returns the C function''s bits')
    if (what == 'radial_distribution') then
      do c = 1, n
        expected = number(t, rows(c), 'value')
        call check(relative_difference(g(c), expected) < 1e-13_c_double, name // ': g_ik')
        do m = 1, 3
          derivative = 0
          if (m <= classes) derivative = d_fractions(c, m)
          call check(scaled_error(derivative, number(t, rows(c), 'd_phi' // achar(iachar('0') + m)), abs(expected)) &
                     < 1e-12_c_double, name // ': dg_ik/dphi_m')
        end do
      end do
      mixture_rows = mixture_rows + n
    else
      call check(what == 'solid_solid_drag' .and. variant(1:colon - 1) == 'syamlal', 'a Syamlal drag row')
      drag = created('SyamlalSolidSolidDrag', 'friction_coefficient', number(t, rows(1), 'friction_coefficient'))
      rho_i = numbers(t, rows, 'rho_i')
      rho_k = numbers(t, rows, 'rho_k')
      e = numbers(t, rows, 'restitution')
      w = numbers(t, rows, 'relative_speed')
      status = fluidbed_solid_solid_drag(drag, fractions(:, i), fractions(:, k), rho_i, diameters(:, i), rho_k, &
                                         diameters(:, k), e, g, w, k_ik, d_phi_p, d_phi_q, d_g, d_w, message)
      call check(status == FLUIDBED_OK, 'SyamlalSolidSolidDrag: ' // message)
      do c = 1, n
        expected = number(t, rows(c), 'value')
        call check(relative_difference(k_ik(c), expected) < 1e-13_c_double, 'SyamlalSolidSolidDrag ' // variant)
        ! dK/dφ_m through φ_p (m = i), φ_q (m = k) and g_ik.
        do m = 1, 3
          derivative = 0
          if (m <= classes) derivative = d_g(c) * d_fractions(c, m)
          if (m == i) derivative = derivative + d_phi_p(c)
          if (m == k) derivative = derivative + d_phi_q(c)
          call check(scaled_error(derivative, number(t, rows(c), 'd_phi' // achar(iachar('0') + m)), abs(expected)) &
                     < 1e-12_c_double, 'SyamlalSolidSolidDrag ' // variant // ': dK/dphi_m')
        end do
        call check(scaled_error(d_w(c), number(t, rows(c), 'd_relative_speed'), abs(expected)) < 1e-12_c_double, &
                   'SyamlalSolidSolidDrag ' // variant // ': dK/dw')
      end do
      solid_drag_rows = solid_drag_rows + n
      call fluidbed_destroy(drag)
    end if
    call fluidbed_destroy(rdf)
  end subroutine

  ! ---- Gas exchange sources -------------------------------------------------------------------------

  subroutine check_exchange(file)
    character(len=*), intent(in) :: file
    type(table) :: t
    character(len=key_length), allocatable :: keys(:)
    logical, allocatable :: done(:)
    integer, allocatable :: rows(:)
    integer :: row
    t = read_table(file)
    keys = keys_of(t, [character(len=7) :: 'variant'])
    done = [(text(t, row, 'function') /= 'fluctuating_energy_source', row = 1, size(keys))]
    exchange_rows = 0
    do row = 1, size(keys)
      if (.not. done(row)) then
        rows = group_of(keys, row, done)
        call check_exchange_rows(t, rows)
      end if
    end do
  end subroutine

  subroutine check_exchange_rows(t, rows)
    type(table), intent(in) :: t
    integer, intent(in) :: rows(:)
    type(fluidbed_closure) :: law, radial
    real(c_double), dimension(size(rows)) :: phi, theta, slip, beta, mu, d, rho, e, source, d_phi, d_theta, d_beta, &
                                             d_slip
    real(c_double) :: expected
    character(len=:), allocatable :: message, variant
    integer :: status, c
    variant = text(t, rows(1), 'variant')
    phi = numbers(t, rows, 'solid_fraction')
    theta = numbers(t, rows, 'granular_temperature')
    slip = numbers(t, rows, 'slip')
    beta = numbers(t, rows, 'beta')
    mu = numbers(t, rows, 'gas_viscosity')
    d = numbers(t, rows, 'diameter')
    rho = numbers(t, rows, 'particle_density')
    e = numbers(t, rows, 'restitution')
    ! Each source with only its own arguments.
    if (variant == 'drag') then
      law = created('DragFluctuationSource')
      status = fluidbed_gas_exchange_source(law, phi, theta, slip, d, rho, e, source, d_phi, d_theta, d_beta, &
                                            d_slip, beta=beta, message=message)
    else
      call check(index(variant, 'koch_sangani:') == 1, 'a Koch-Sangani row')
      law = created('KochSanganiSource')
      radial = table_radial(variant(len('koch_sangani:') + 1:))
      status = fluidbed_gas_exchange_source(law, phi, theta, slip, d, rho, e, source, d_phi, d_theta, d_beta, &
                                            d_slip, radial=radial, gas_viscosity=mu, message=message)
      call fluidbed_destroy(radial)
    end if
    call check(status == FLUIDBED_OK, variant // ': ' // message)
    do c = 1, size(rows)
      expected = number(t, rows(c), 'value')
      call check(relative_difference(source(c), expected) < 1e-13_c_double, variant // ': source')
      call check(all(scaled_error([d_phi(c), d_theta(c), d_beta(c), d_slip(c)], &
                                  [number(t, rows(c), 'd_solid_fraction'), &
                                   number(t, rows(c), 'd_granular_temperature'), number(t, rows(c), 'd_beta'), &
                                   number(t, rows(c), 'd_slip')], 1e-9_c_double * abs(expected)) < 1e-11_c_double), &
                 variant // ': derivatives')
    end do
    exchange_rows = exchange_rows + size(rows)
    call fluidbed_destroy(law)
  end subroutine

  ! ---- Single spheres, settling and minimum fluidization -------------------------------------------

  ! cd_reference.csv: C_D Re of law//'Coefficient' at each Re, Stokes exactly (24) and the others within
  ! 1e-14 (tests/test_drag_family.cpp). The table has no derivative.
  subroutine check_sphere_drag(file)
    character(len=*), intent(in) :: file
    type(table) :: t
    type(fluidbed_closure) :: law
    character(len=key_length), allocatable :: keys(:)
    character(len=:), allocatable :: message, name
    logical, allocatable :: done(:)
    integer, allocatable :: rows(:)
    real(c_double), allocatable :: re(:), value(:)
    real(c_double) :: tolerance
    integer :: row, c, status
    t = read_table(file)
    keys = keys_of(t, [character(len=3) :: 'law'])
    allocate(done(size(keys)))
    done = .false.
    sphere_drag_rows = 0
    do row = 1, size(keys)
      if (done(row)) cycle
      rows = group_of(keys, row, done)
      name = text(t, row, 'law') // 'Coefficient'
      law = created(name)
      re = [(number(t, rows(c), 'reynolds'), c = 1, size(rows))]
      allocate(value(size(rows)))
      status = fluidbed_sphere_drag_coefficient(law, re, value, message=message)
      call check(status == FLUIDBED_OK, name // ': ' // message)
      tolerance = 1e-14_c_double
      if (name == 'StokesCoefficient') tolerance = 0
      do c = 1, size(rows)
        call check(relative_difference(value(c), number(t, rows(c), 'cd_times_re')) <= tolerance, &
                   name // ': C_D Re against the reference table')
      end do
      sphere_drag_rows = sphere_drag_rows + size(rows)
      deallocate(value)
      call fluidbed_destroy(law)
    end do
  end subroutine

  ! settling_reference.csv's closure rows (the bed expansion and u_mf in m/s are not closures): the
  ! Richardson-Zaki exponents of Re_t or Ar, Re_mf of Ar, and the terminal velocities from Re_t of
  ! Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f² (param1 … param4 = ρ_f, μ_f, ρ_p, d), u_t = Re_t μ_f/(ρ_f d) as
  ! the library's velocity_from_reynolds.
  subroutine check_settling(file)
    character(len=*), intent(in) :: file
    type(table) :: t
    type(fluidbed_closure) :: law
    character(len=key_length), allocatable :: keys(:)
    character(len=:), allocatable :: message, name, parameter
    logical, allocatable :: done(:)
    integer, allocatable :: rows(:)
    real(c_double), allocatable :: x(:), value(:), velocity_scale(:)
    real(c_double) :: rho_f, mu, rho_p, d
    integer :: row, c, status, i
    t = read_table(file)
    keys = keys_of(t, [character(len=8) :: 'quantity', 'param2'])
    done = [(position(settling_tables, text(t, row, 'quantity')) == 0, row = 1, size(keys))]
    settling_rows = 0
    do row = 1, size(keys)
      if (done(row)) cycle
      rows = group_of(keys, row, done)
      i = position(settling_tables, text(t, row, 'quantity'))
      name = trim(settling_names(i))
      parameter = trim(settling_parameters(i))
      if (parameter == '') then
        law = created(name)
      else
        law = created(name, parameter, number(t, row, 'param2'))
      end if
      ! (explicit loops, not array constructors of conditionally set arrays: gfortran 12 at -O3
      ! reports those as maybe uninitialized)
      allocate(x(size(rows)), value(size(rows)), velocity_scale(size(rows)))
      do c = 1, size(rows)
        x(c) = number(t, rows(c), 'param1')  ! Re_t or Ar
        velocity_scale(c) = 1
        if (ends_with(name, 'TerminalVelocity')) then
          rho_f = x(c)
          mu = number(t, rows(c), 'param2')
          rho_p = number(t, rows(c), 'param3')
          d = number(t, rows(c), 'param4')
          x(c) = rho_f * (rho_p - rho_f) * standard_gravity * d * d * d / (mu * mu)
          velocity_scale(c) = mu / (rho_f * d)
        end if
      end do
      if (fluidbed_richardson_zaki_argument(law) /= '') then
        status = fluidbed_richardson_zaki_exponent(law, x, value, message=message)
      else
        status = fluidbed_reynolds_of_archimedes(law, x, value, message=message)
        value = value * velocity_scale  ! u_t for the terminal velocities; Re_mf unchanged
      end if
      call check(status == FLUIDBED_OK, name // ': ' // message)
      do c = 1, size(rows)
        call check(relative_difference(value(c), number(t, rows(c), 'value')) < settling_tolerances(i), &
                   name // ': against the reference table')
      end do
      settling_rows = settling_rows + size(rows)
      deallocate(x, value, velocity_scale)
      call fluidbed_destroy(law)
    end do
  end subroutine

  ! ---- Friction -------------------------------------------------------------------------------------

  ! The row's parameters that the closure has (tests/test_c_interface.cpp), the friction angle in
  ! radians.
  subroutine set_friction_parameters(law, t, row)
    type(fluidbed_closure), intent(inout) :: law
    type(table), intent(in) :: t
    integer, intent(in) :: row
    character(len=*), parameter :: names(5) = [character(len=20) :: 'min_fraction', 'max_packing', 'coefficient', &
                                               'numerator_exponent', 'denominator_exponent']
    character(len=:), allocatable :: message
    integer :: j, status
    do j = 1, size(names)
      if (has_parameter(law, trim(names(j)))) then
        status = fluidbed_set_parameter(law, trim(names(j)), number(t, row, trim(names(j))), message)
        call check(status == FLUIDBED_OK, fluidbed_name(law) // ' ' // trim(names(j)) // ': ' // message)
      end if
    end do
    if (has_parameter(law, 'friction_angle')) then
      status = fluidbed_set_parameter(law, 'friction_angle', number(t, row, 'friction_angle_deg') * pi / 180, message)
      call check(status == FLUIDBED_OK, fluidbed_name(law) // ' friction_angle: ' // message)
    end if
  end subroutine

  ! Every row of ktgf_friction_reference.csv, in groups of one function, variant and parameter set.
  subroutine check_friction(file)
    character(len=*), intent(in) :: file
    type(table) :: t
    character(len=key_length), allocatable :: keys(:)
    logical, allocatable :: done(:)
    integer, allocatable :: rows(:)
    integer :: row
    t = read_table(file)
    keys = keys_of(t, [character(len=20) :: 'function', 'variant', 'min_fraction', 'max_packing', 'coefficient', &
                                            'numerator_exponent', 'denominator_exponent', 'friction_angle_deg'])
    allocate(done(size(keys)))
    done = .false.
    friction_rows = 0
    do row = 1, size(keys)
      if (done(row)) cycle
      rows = group_of(keys, row, done)
      call check_friction_rows(t, rows)
    end do
  end subroutine

  ! The Johnson-Jackson and Schaeffer pressures (fluidbed_of_solid_fraction), Schaeffer's viscosity
  ! of either (fluidbed_frictional_viscosity of p_f; ∂μ/∂φ = ∂μ/∂p_f dp_f/dφ) and the
  ! Srivastava-Sundaresan stress (fluidbed_frictional_stress): the value within 1e-13 and ∂/∂φ
  ! within 1e-11 of |∂| + 1e-9 |value| (tests/test_kinetic_theory_friction_exchange.cpp).
  subroutine check_friction_rows(t, rows)
    type(table), intent(in) :: t
    integer, intent(in) :: rows(:)
    type(fluidbed_closure) :: law, pressure_law
    real(c_double), dimension(size(rows)) :: phi, theta, d, divergence, contraction, pressure, viscosity, &
                                             d_pressure, d_viscosity, value, d_phi
    real(c_double) :: expected
    character(len=:), allocatable :: message, what, variant, name
    integer :: status, c
    what = text(t, rows(1), 'function')
    variant = text(t, rows(1), 'variant')
    phi = numbers(t, rows, 'solid_fraction')
    theta = numbers(t, rows, 'granular_temperature')
    d = numbers(t, rows, 'diameter')
    divergence = numbers(t, rows, 'divergence')
    contraction = numbers(t, rows, 'deviatoric_contraction')
    if (variant == 'srivastava_sundaresan') then
      name = 'SrivastavaSundaresan'
      law = created(name)
      call set_friction_parameters(law, t, rows(1))
      status = fluidbed_frictional_stress(law, phi, theta, d, divergence, contraction, pressure, viscosity, &
                                          d_pressure, d_viscosity, message)
      call check(status == FLUIDBED_OK, name // ': ' // message)
      call fluidbed_destroy(law)
    else
      name = 'SchaefferPressure'
      if (ends_with(variant, 'johnson_jackson')) name = 'JohnsonJacksonPressure'
      pressure_law = created(name)
      call set_friction_parameters(pressure_law, t, rows(1))
      status = fluidbed_of_solid_fraction(pressure_law, phi, pressure, d_pressure, message)
      call check(status == FLUIDBED_OK, name // ': ' // message)
      call fluidbed_destroy(pressure_law)
      if (what == 'frictional_viscosity') then
        name = 'SchaefferViscosity of ' // name
        law = created('SchaefferViscosity')
        call set_friction_parameters(law, t, rows(1))
        status = fluidbed_frictional_viscosity(law, pressure, divergence, contraction, viscosity, d_viscosity, &
                                               message)
        call check(status == FLUIDBED_OK, name // ': ' // message)
        d_viscosity = d_viscosity * d_pressure
        call fluidbed_destroy(law)
      end if
    end if
    if (what == 'frictional_pressure') then
      value = pressure
      d_phi = d_pressure
    else
      call check(what == 'frictional_viscosity', 'a friction row: ' // what)
      value = viscosity
      d_phi = d_viscosity
    end if
    do c = 1, size(rows)
      expected = number(t, rows(c), 'value')
      call check(relative_difference(value(c), expected) < 1e-13_c_double, name // ' ' // what // ': value')
      call check(scaled_error(d_phi(c), number(t, rows(c), 'd_solid_fraction'), 1e-9_c_double * abs(expected)) &
                 < 1e-11_c_double, name // ' ' // what // ': d/dphi')
    end do
    friction_rows = friction_rows + size(rows)
  end subroutine

  ! ---- Elastic moduli -------------------------------------------------------------------------------

  ! elastic_state_reference.csv: states (ε, w) off equilibrium; its modulus column is
  ! Mazzei-Lettieri's E_r = −[4(1−ε)/(π d²)] H F̂ at the state, within 1e-13 (tests/test_elastic.cpp).
  ! The table has no modulus at equilibrium: the three models there (g = 9.80665, Re_t = the
  ! reynolds column, as tests/test_c_interface.cpp) are only called (a status, a finite value), and
  ! the two without a modulus off equilibrium refuse a state.
  subroutine check_elastic(file)
    character(len=*), intent(in) :: file
    character(len=*), parameter :: models(3) = [character(len=24) :: 'FoscoloGibilaroModulus', 'JeanFanModulus', &
                                                'MazzeiLettieriModulus']
    type(table) :: t
    type(fluidbed_closure) :: model
    real(c_double), allocatable :: e(:), w(:), rho_f(:), mu(:), rho_p(:), d(:), re_t(:), g(:), modulus(:), &
                                   d_voidage(:), d_slip(:)
    character(len=:), allocatable :: message, name
    integer :: status, row, j, n
    t = read_table(file)
    n = size(t%cells, 2)
    e = [(number(t, row, 'voidage'), row = 1, n)]
    w = [(number(t, row, 'slip'), row = 1, n)]
    rho_f = [(number(t, row, 'fluid_density'), row = 1, n)]
    mu = [(number(t, row, 'fluid_viscosity'), row = 1, n)]
    rho_p = [(number(t, row, 'particle_density'), row = 1, n)]
    d = [(number(t, row, 'diameter'), row = 1, n)]
    re_t = [(number(t, row, 'reynolds'), row = 1, n)]
    allocate(g(n), modulus(n), d_voidage(n), d_slip(n))
    g = 9.80665_c_double
    elastic_rows = 0
    do j = 1, size(models)
      name = trim(models(j))
      model = created(name)
      status = fluidbed_elastic_modulus_at_equilibrium(model, e, rho_f, mu, rho_p, d, re_t, g, modulus, d_voidage, &
                                                       message)
      call check(status == FLUIDBED_OK .and. all(ieee_is_finite(modulus)) .and. all(ieee_is_finite(d_voidage)), &
                 name // ' at equilibrium: ' // message)
      status = fluidbed_elastic_modulus_at_state(model, e, w, rho_f, mu, d, modulus, d_voidage, d_slip, message)
      if (name == 'MazzeiLettieriModulus') then
        call check(status == FLUIDBED_OK, name // ' at a state: ' // message)
        do row = 1, n
          call check(relative_difference(modulus(row), number(t, row, 'modulus')) < 1e-13_c_double, &
                     name // ' at a state: against the reference table')
        end do
        elastic_rows = elastic_rows + n
      else
        call check(status == FLUIDBED_INVALID_ARGUMENT, name // ' refuses a state: ' // message)
      end if
      call fluidbed_destroy(model)
    end do
  end subroutine

  ! ---- Moments ----------------------------------------------------------------------------------------

  ! The moments m_0 … m_{count−1} of the atoms (weights, nodes).
  pure function moments_of(weights, nodes, count) result(m)
    real(c_double), intent(in) :: weights(:), nodes(:)
    integer, intent(in) :: count
    real(c_double) :: m(count)
    integer :: j
    do j = 1, count
      m(j) = sum(weights * nodes**(j - 1))
    end do
  end function

  ! DQMOM sources of three cells of three nodes (the third cell's last two nodes merged), growth as
  ! point functionals and as moment sources (3 + k) Σ φ ξ^(k−1) G.
  subroutine check_dqmom()
    real(c_double) :: xi(3, 3), phi(3, 3), g(3, 3), s(3, 6), a(3, 3), b(3, 3), ca(3, 3), cb(3, 3), condition(3)
    real(c_double) :: moment_a(3, 3), moment_b(3, 3), bad(3, 2)
    real(c_double), target :: growth(3, 3)
    integer(c_int) :: status(3), c_status(3)
    character(len=:), allocatable :: message
    integer :: code, c, k
    xi(1, :) = [75e-6_c_double, 103e-6_c_double, 240e-6_c_double]
    xi(2, :) = [60e-6_c_double, 130e-6_c_double, 420e-6_c_double]
    xi(3, :) = [75e-6_c_double, 200e-6_c_double, 200e-6_c_double * (1 + 1e-9_c_double)]
    phi(1, :) = [0.131_c_double, 0.169_c_double, 0.19_c_double]
    phi(2, :) = [0.03_c_double, 0.04_c_double, 0.02_c_double]
    phi(3, :) = [0.2_c_double, 0.1_c_double, 0.3_c_double]
    g(1, :) = [1e-7_c_double, -2e-7_c_double, 3e-7_c_double]
    g(2, :) = [2e-8_c_double, 1e-7_c_double, -5e-8_c_double]
    g(3, :) = [1e-7_c_double, 1e-7_c_double, 1e-7_c_double]
    growth = g
    code = fluidbed_dqmom_growth_diffusion_sources(FLUIDBED_DQMOM_VOLUME_FRACTION, xi, phi, a, b, status, &
                                                   growth_rate=g, condition=condition, message=message)
    call check(code == FLUIDBED_OK, 'dqmom growth: ' // message)
    call check(all(status == [FLUIDBED_DQMOM_OK, FLUIDBED_DQMOM_OK, FLUIDBED_DQMOM_MERGED_NODES]), &
               'dqmom growth: the statuses')
    call check(all(relative_difference(a(1:2, :), 3 * phi(1:2, :) * g(1:2, :) / xi(1:2, :)) < 1e-14_c_double) .and. &
               all(relative_difference(b(1:2, :), 4 * phi(1:2, :) * g(1:2, :)) < 1e-14_c_double), &
               'dqmom growth: c^phi = 3 phi G/xi, c^xi = 4 phi G')
    call check(all(relative_difference(a(3, :), 3 * phi(3, :) * g(3, :) / xi(3, :)) < 1e-8_c_double), &
               'dqmom growth: merged nodes keep the growth identity (to their gap)')
    code = c_dqmom_growth_diffusion_sources(3_c_int, int(FLUIDBED_DQMOM_VOLUME_FRACTION, c_int), 3_c_size_t, xi, phi, &
                                            c_loc(growth), c_null_ptr, ca, cb, c_status, c_null_ptr, c_null_ptr)
    call check(code == FLUIDBED_OK .and. all(same_bits(a, ca)) .and. all(same_bits(b, cb)) .and. &
               all(c_status == status), 'dqmom growth: the wrapper returns the C function''s bits')
    do c = 1, 3
      do k = 0, 5
        s(c, k + 1) = (3 + k) * sum(phi(c, :) * xi(c, :)**(k - 1) * g(c, :))
      end do
    end do
    code = fluidbed_dqmom_sources(xi(1:2, :), phi(1:2, :), s(1:2, :), moment_a(1:2, :), moment_b(1:2, :), &
                                  status(1:2), condition(1:2), message)
    call check(code == FLUIDBED_OK .and. all(status(1:2) == FLUIDBED_DQMOM_OK), 'dqmom sources: ' // message)
    do c = 1, 2
      call check(all(abs(moment_a(c, :) - a(c, :)) < 8 * epsilon(1.0_c_double) * condition(c) * maxval(abs(a(c, :)))) &
                 .and. all(abs(moment_b(c, :) - b(c, :)) < 8 * epsilon(1.0_c_double) * condition(c) * &
                           maxval(abs(b(c, :)))), 'dqmom sources: growth as moments, within the condition number')
    end do
    code = c_dqmom_sources(3_c_int, 2_c_size_t, xi(1:2, :), phi(1:2, :), s(1:2, :), ca(1:2, :), cb(1:2, :), &
                           c_status(1:2), c_null_ptr, c_null_ptr)
    call check(code == FLUIDBED_OK .and. all(same_bits(moment_a(1:2, :), ca(1:2, :))) .and. &
               all(same_bits(moment_b(1:2, :), cb(1:2, :))), 'dqmom sources: the wrapper returns the C function''s bits')
    ! Shapes that do not agree, and a weights kind that is none.
    code = fluidbed_dqmom_sources(xi, phi, s(:, 1:5), a, b, status, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'dqmom sources: 5 moment sources for 3 nodes')
    code = fluidbed_dqmom_growth_diffusion_sources(FLUIDBED_DQMOM_NUMBER_DENSITY, xi, phi, a, b, status, &
                                                   diffusion_intensity=bad, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'dqmom growth: a diffusion intensity of 2 nodes for 3')
    code = fluidbed_dqmom_growth_diffusion_sources(7, xi, phi, a, b, status, growth_rate=g, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. message == 'fluidbed: unknown fluidbed_dqmom_weights 7', &
               'dqmom growth: weights kind 7: ' // message)
  end subroutine

  ! The kinetic theory of classes with their own granular temperatures (see the header comment).
  subroutine check_unequal_temperature_mixture()
    integer, parameter :: n = 4, nc = 3
    type(fluidbed_closure) :: radial
    real(c_double) :: alpha(n, nc), theta(n, nc), d(n, nc), rho(n, nc), e(n), mass(nc)
    real(c_double) :: p(n, nc), gamma(n, nc), mu(n, nc, nc), lambda(n, nc, nc), beta(n, nc, nc), s(n, nc, nc), &
                      h(n, nc, nc), dp_da(n, nc, nc), dmu_dt(n, nc, nc, nc), one_p(n, 1), one_h(n, 1, 1), bad(n, 2)
    real(c_double), target :: cp(n, nc), cdp_da(n, nc, nc), cmu(n, nc, nc), cdmu_dt(n, nc, nc, nc)
    character(len=:), allocatable :: message
    integer :: code, c, i, k, cell
    code = fluidbed_create('ModifiedMansoori', radial, message)
    call check(code == FLUIDBED_OK, 'unequal temperatures: ' // message)
    do i = 1, nc
      alpha(:, i) = [0.05_c_double, 0.1_c_double, 0.15_c_double, 0.16_c_double] * (1 + 0.2_c_double * (i - 1))
      theta(:, i) = [1e-3_c_double, 4e-3_c_double, 2e-2_c_double, 5e-4_c_double] * i
      d(:, i) = 1e-4_c_double * (1 + 0.7_c_double * (i - 1))
      rho(:, i) = 2500 - 400 * (i - 1)
    end do
    e = [0.9_c_double, 0.7_c_double, 1.0_c_double, 0.95_c_double]
    code = fluidbed_unequal_temperature_mixture(radial, alpha, theta, d, rho, e, pressure=p, shear_viscosity=mu, &
                                                bulk_viscosity=lambda, dissipation=gamma, drag=beta, segregation=s, &
                                                radial_distribution=h, d_pressure_d_fractions=dp_da, &
                                                d_shear_viscosity_d_temperatures=dmu_dt, message=message)
    call check(code == FLUIDBED_OK, 'unequal temperatures: ' // message)
    code = c_unequal_temperature_mixture(radial%handle, int(n, c_size_t), int(nc, c_size_t), alpha, theta, d, rho, e, &
                                         c_loc(cp), c_loc(cdp_da), c_null_ptr, c_loc(cmu), c_null_ptr, c_loc(cdmu_dt), &
                                         c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, &
                                         c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, &
                                         c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, &
                                         c_null_ptr)
    call check(code == FLUIDBED_OK .and. all(same_bits(p, cp)) .and. all(same_bits(dp_da, cdp_da)) .and. &
               all(same_bits(mu, cmu)) .and. all(same_bits(dmu_dt, cdmu_dt)), &
               'unequal temperatures: the wrapper returns the C function''s bits')
    ! μ_ik = (√(2π)/15) c_ik M_i σ⁴ Σ^(3/2)/Θ_k for k ≠ i, so μ_12/μ_21 = M_1Θ_1/(M_2Θ_2): element (c, k, i) is μ_ik.
    mass = rho(1, :) * d(1, :)**3
    do c = 1, n
      call check(relative_difference(mu(c, 2, 1) / mu(c, 1, 2), mass(1) * theta(c, 1) / (mass(2) * theta(c, 2))) < &
                 1e-13_c_double, 'unequal temperatures: mu_12/mu_21 = m_1 Theta_1/(m_2 Theta_2)')
      do i = 1, nc
        call check(abs(beta(c, i, i)) <= 0 .and. abs(s(c, i, i)) <= 0, &
                   'unequal temperatures: no drag of a class on itself')
        do k = 1, nc
          call check(same_bits(beta(c, k, i), beta(c, i, k)) .and. same_bits(s(c, k, i), s(c, i, k)) .and. &
                     same_bits(h(c, k, i), h(c, i, k)), 'unequal temperatures: beta, s and h symmetric')
          call check(relative_difference(lambda(c, k, i), 5 * mu(c, k, i) / 3) < 1e-15_c_double, &
                     'unequal temperatures: lambda = (5/3) mu')
        end do
      end do
    end do
    call check(abs(sum(gamma(3, :))) < 1e-13_c_double * sum(abs(gamma(3, :))), &
               'unequal temperatures: the classes only exchange energy at e = 1')
    ! One class: Lun's pressure αρΘ(1 + 2(1 + e)α h).
    code = fluidbed_unequal_temperature_mixture(radial, alpha(:, 1:1), theta(:, 1:1), d(:, 1:1), rho(:, 1:1), e, &
                                                pressure=one_p, radial_distribution=one_h, message=message)
    call check(code == FLUIDBED_OK .and. all(relative_difference(one_p(:, 1), alpha(:, 1) * rho(:, 1) * theta(:, 1) * &
                                             (1 + 2 * (1 + e) * alpha(:, 1) * one_h(:, 1, 1))) < 1e-14_c_double), &
               'unequal temperatures: one class gives Lun''s pressure')
    ! A cold class in cell 2, shapes that disagree, a closure of another family.
    theta(2, 3) = 0
    code = fluidbed_unequal_temperature_mixture(radial, alpha, theta, d, rho, e, pressure=p, message=message, cell=cell)
    call check(code == FLUIDBED_DOMAIN_ERROR .and. cell == 2 .and. index(message, 'state.temperatures[2]') > 0, &
               'unequal temperatures: a cold class: ' // message)
    code = fluidbed_unequal_temperature_mixture(radial, alpha, theta, d, rho, e, pressure=bad, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'unequal temperatures: a pressure of 2 classes for 3')
    call fluidbed_destroy(radial)
    code = fluidbed_create('CarnahanStarling', radial)
    code = fluidbed_unequal_temperature_mixture(radial, alpha, theta, d, rho, e, pressure=p, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'unequal temperatures: CarnahanStarling is not a mixture one')
    call fluidbed_destroy(radial)
  end subroutine

  subroutine check_moments()
    real(c_double) :: m(4, 4), nodes(4, 2), weights(4, 2), corrected(4, 4), failing(4), again(3, 4)
    real(c_double) :: node_errors(2), weight_errors(2), count_errors(2)
    integer(c_int) :: sizes(4), status(4), realizable(4), first_failing(4), corrected_realizable(4)
    type(fluidbed_correction_options) :: options
    character(len=:), allocatable :: message
    integer :: code
    ! Inversion: two cells of known atoms, an empty cell, and atoms on the real line.
    m(1, :) = moments_of([0.3_c_double, 0.7_c_double], [1e-4_c_double, 2e-4_c_double], 4)
    m(2, :) = 0
    m(3, :) = moments_of([2.0_c_double, 0.5_c_double], [5e-5_c_double, 3e-4_c_double], 4)
    m(4, :) = moments_of([0.4_c_double, 0.6_c_double], [-1.0_c_double, 2.0_c_double], 4)
    code = fluidbed_invert_moments(2, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, m(1:3, :), nodes(1:3, :), &
                                   weights(1:3, :), sizes(1:3), status(1:3), message)
    call check(code == FLUIDBED_OK, 'invert: ' // message)
    call check(all(status(1:3) == [FLUIDBED_INVERSION_OK, FLUIDBED_INVERSION_ZERO_MASS, FLUIDBED_INVERSION_OK]), &
               'invert: the statuses')
    call check(all(sizes(1:3) == [2, 0, 2]), 'invert: the node counts')
    call check(all(relative_difference(nodes(1, :), [1e-4_c_double, 2e-4_c_double]) < 1e-12_c_double) .and. &
               all(relative_difference(weights(1, :), [0.3_c_double, 0.7_c_double]) < 1e-12_c_double), &
               'invert: the atoms 0.3, 0.7 at 1e-4, 2e-4 m')
    call check(all(relative_difference(nodes(3, :), [5e-5_c_double, 3e-4_c_double]) < 1e-12_c_double) .and. &
               all(relative_difference(weights(3, :), [2.0_c_double, 0.5_c_double]) < 1e-12_c_double), &
               'invert: the atoms 2, 0.5 at 5e-5, 3e-4 m')
    call check(all(same_bits(weights(2, :), zero)), 'invert: an empty cell has no weight')
    code = fluidbed_invert_moments(2, FLUIDBED_SUPPORT_REAL_LINE, m(4:4, :), nodes(4:4, :), weights(4:4, :), &
                                   sizes(4:4), status(4:4), message)
    call check(code == FLUIDBED_OK .and. status(4) == FLUIDBED_INVERSION_OK, 'invert on the real line: ' // message)
    call check(all(relative_difference(nodes(4, :), [-1.0_c_double, 2.0_c_double]) < 1e-12_c_double) .and. &
               all(relative_difference(weights(4, :), [0.4_c_double, 0.6_c_double]) < 1e-12_c_double), &
               'invert: the atoms 0.4, 0.6 at -1, 2 on the real line')
    ! The error estimate: one node (x = m_1/m_0, w = m_0) with moments accurate to 1e-6 relative is
    ! good to 2e-6 and 1e-6 (first order, exact; the rounding adds ~1e-17); an empty cell has no
    ! rule (−1). A requirement of 1.5e-6: the status inaccurate, the rule still returned.
    m(1, 1:2) = [3.0_c_double, 1.5e-4_c_double]
    m(2, 1:2) = 0
    code = fluidbed_invert_moments(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, m(1:2, 1:2), nodes(1:2, 1:1), &
                                   weights(1:2, 1:1), sizes(1:2), status(1:2), message, moment_accuracy=1e-6_c_double, &
                                   node_errors=node_errors, weight_errors=weight_errors, &
                                   count_errors=count_errors)
    call check(code == FLUIDBED_OK .and. all(status(1:2) == [FLUIDBED_INVERSION_OK, FLUIDBED_INVERSION_ZERO_MASS]), &
               'invert with an error estimate: ' // message)
    call check(abs(node_errors(1) / 2e-6_c_double - 1) < 1e-9_c_double .and. &
               abs(weight_errors(1) / 1e-6_c_double - 1) < 1e-9_c_double, &
               'invert: one node is good to 2 moment accuracies, its weight to 1')
    call check(same_bits(node_errors(2), -1.0_c_double) .and. same_bits(weight_errors(2), -1.0_c_double), &
               'invert: an empty cell has no estimate')
    call check(abs(count_errors(1) / (1e-6_c_double + epsilon(1.0_c_double)) - 1) < 1e-12_c_double .and. &
               same_bits(count_errors(2), -1.0_c_double), &
               'invert: one node decided by zeta_1 > 0 (count error delta + eps), an empty cell none')
    code = fluidbed_invert_moments(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, m(1:1, 1:2), nodes(1:1, 1:1), &
                                   weights(1:1, 1:1), sizes(1:1), status(1:1), message, moment_accuracy=1e-6_c_double, &
                                   required_accuracy=1.5e-6_c_double)
    call check(code == FLUIDBED_OK .and. FLUIDBED_INVERSION_INACCURATE == 6 .and. &
               status(1) == FLUIDBED_INVERSION_INACCURATE .and. sizes(1) == 1 .and. &
               abs(nodes(1, 1) / 5e-5_c_double - 1) < 1e-14_c_double, 'invert beyond a required accuracy: ' // message)
    code = fluidbed_invert_moments(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, m(1:1, 1:2), nodes(1:1, 1:1), &
                                   weights(1:1, 1:1), sizes(1:1), status(1:1), message, moment_accuracy=-1e-6_c_double)
    call check(code == FLUIDBED_DOMAIN_ERROR .and. index(message, 'moment_accuracy') > 0, &
               'invert: a negative moment accuracy: ' // message)
    code = fluidbed_invert_moments(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, m(1:2, 1:2), nodes(1:2, 1:1), &
                                   weights(1:2, 1:1), sizes(1:2), status(1:2), message, node_errors=node_errors(1:1))
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'invert: node errors of 1 cell for 2')

    ! Realizability: m_0 m_2 < m_1^2 (ζ_2 = m_2/m_1 − m_1/m_0 = −0.5), m_1 m_3 < m_2^2, a realizable set.
    m(1, :) = [1.0_c_double, 1.0_c_double, 0.5_c_double, 0.3_c_double]
    m(2, :) = [1.0_c_double, 2.0_c_double, 5.0_c_double, 9.0_c_double]
    m(3, :) = moments_of([0.3_c_double, 0.7_c_double], [1e-4_c_double, 2e-4_c_double], 4)
    m(4, :) = [1.0_c_double, 2.0_c_double, 3.0_c_double, 8.0_c_double]
    code = fluidbed_moment_realizability(FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, m(1:3, :), status(1:3), &
                                         realizable(1:3), first_failing(1:3), failing(1:3), message)
    call check(code == FLUIDBED_OK, 'realizability: ' // message)
    call check(all(status(1:3) == [FLUIDBED_INVERSION_REDUCED, FLUIDBED_INVERSION_REDUCED, FLUIDBED_INVERSION_OK]), &
               'realizability: the statuses')
    call check(all(realizable(1:3) == [2, 3, 4]), 'realizability: the realizable prefixes 2, 3, 4')
    call check(all(first_failing(1:3) == [2, 3, 0]), 'realizability: the failing coefficients zeta_2, zeta_3')
    call check(abs(failing(1) + 0.5_c_double) < 1e-14_c_double .and. failing(2) < 0 .and. &
               same_bits(failing(3), zero), 'realizability: zeta_2 = -0.5')
    ! Without the optional outputs, the same.
    code = fluidbed_moment_realizability(FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, m(1:3, :), sizes(1:3), &
                                         corrected_realizable(1:3))
    call check(code == FLUIDBED_OK .and. all(sizes(1:3) == status(1:3)) .and. &
               all(corrected_realizable(1:3) == realizable(1:3)), 'realizability without the optional outputs')

    ! Correction (tests/test_moment_correction.cpp): 1, 2, 3, 8 → the atom 1, 2, 4, 8; 1, 2, 5, 9
    ! → the log-normal sharing m_0 … m_2 (m_3 = 8 (5/4)^3); a realizable set unchanged; zero mass.
    m(1, :) = [1.0_c_double, 2.0_c_double, 3.0_c_double, 8.0_c_double]
    m(2, :) = [1.0_c_double, 2.0_c_double, 5.0_c_double, 9.0_c_double]
    m(4, :) = 0
    code = fluidbed_correct_moments(m, corrected, status, corrected_realizable, message=message)
    call check(code == FLUIDBED_OK, 'correct: ' // message)
    call check(all(status == [FLUIDBED_CORRECTION_MONODISPERSE, FLUIDBED_CORRECTION_LOGNORMAL, &
                              FLUIDBED_CORRECTION_UNCHANGED, FLUIDBED_CORRECTION_ZERO_MASS]), 'correct: the statuses')
    call check(all(relative_difference(corrected(1, :), [1.0_c_double, 2.0_c_double, 4.0_c_double, 8.0_c_double]) &
                   < 1e-15_c_double), 'correct: the monodisperse set')
    call check(all(same_bits(corrected(2, 1:3), m(2, 1:3))) .and. &
               relative_difference(corrected(2, 4), 8 * 1.25_c_double**3) < 1e-14_c_double, &
               'correct: the log-normal set')
    call check(all(same_bits(corrected(3, :), m(3, :))) .and. all(same_bits(corrected(4, :), zero)), &
               'correct: unchanged sets')
    call check(all(corrected_realizable(1:3) == [2, 4, 4]), 'correct: the realizable moments of the returned sets')
    ! The corrected sets are realizable (the atom on the boundary: m_0, m_1 only).
    code = fluidbed_moment_realizability(FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, corrected(1:3, :), status(1:3), &
                                         realizable(1:3))
    call check(code == FLUIDBED_OK .and. all(status(2:3) == FLUIDBED_INVERSION_OK) .and. &
               all(realizable(1:3) == corrected_realizable(1:3)), 'correct: the returned sets are realizable')
    ! The defaults, given or not; options out of their domain.
    options = fluidbed_correction_default_options()
    call check(options%protected_moments == 1 .and. options%max_iterations == 20 .and. &
               relative_difference(options%degenerate_tolerance, epsilon(zero)**(1 / 3.0_c_double)) &
               < 1e-14_c_double, &
               'the default correction options')
    code = fluidbed_correct_moments(m(1:3, :), again, status(1:3), options=options, message=message)
    call check(code == FLUIDBED_OK .and. all(same_bits(again(1:3, :), corrected(1:3, :))), &
               'correct: the defaults given are the defaults')
    options%protected_moments = 0
    code = fluidbed_correct_moments(m(1:3, :), again, status(1:3), options=options, message=message)
    call check(code == FLUIDBED_DOMAIN_ERROR, 'correct: protected_moments = 0 is a domain error')
    print '(2a)', 'options: ', message
  end subroutine

  ! ---- The moments reference table --------------------------------------------------------------------

  ! The table's values of (case, n_nodes, quantity) by index (index k at k + 1); none: size 0.
  function oracle(cases, counts, quantities, indices, values, name, n, quantity) result(v)
    character(len=*), intent(in) :: cases(:), quantities(:), name, quantity
    integer, intent(in) :: counts(:), indices(:), n
    real(c_double), intent(in) :: values(:)
    real(c_double), allocatable :: v(:)
    logical :: mask(size(cases))
    integer :: row
    mask = cases == name .and. counts == n .and. quantities == quantity
    if (.not. any(mask)) then
      allocate(v(0))
      return
    end if
    allocate(v(maxval(indices, mask=mask) + 1))
    v = nan  ! an index the table lacks compares as a failure
    do row = 1, size(cases)
      if (mask(row)) v(indices(row) + 1) = values(row)
    end do
  end function

  ! Every case and node count N <= FLUIDBED_MAX_NODES of moments_reference.csv with a Gauss rule,
  ! inverted from its first 2N moments, all cases of one N and support in one call: nodes within
  ! 8·2N·node_condition + 8e-16 of their spread (|x_1| for N = 1), weights within
  ! 8·2N·weight_condition + 8e-16 of m_0 (tests/test_moment_oracle.cpp). hermite_* and
  ! random_jacobi_* on the whole line, the others on [0, ∞); the printed seed-003 sets at the node
  ! counts they are realizable for (the only ones with a rule) as well. The Radau rule (a fixed node,
  ! from 11 moments) is not a Gauss rule of its moments: left out, as there.
  subroutine check_moment_table(file)
    character(len=*), intent(in) :: file
    type(table) :: t
    character(len=field), allocatable :: cases(:), quantities(:), names(:)
    integer, allocatable :: counts(:), indices(:), sizes(:), status(:)
    real(c_double), allocatable :: values(:), m(:, :), nodes(:, :), weights(:, :), x(:), w(:), moments(:)
    logical, allocatable :: real_line(:), first(:)
    integer, parameter :: supports(2) = [FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, FLUIDBED_SUPPORT_REAL_LINE]
    character(len=:), allocatable :: message, what
    real(c_double) :: spread, node_error, weight_error
    integer :: row, rows, n, c, cell, code, s
    character(len=8) :: label
    t = read_table(file)
    rows = size(t%cells, 2)
    cases = t%cells(column(t, 'case'), :)
    quantities = t%cells(column(t, 'quantity'), :)
    allocate(counts(rows), indices(rows), values(rows), first(rows))
    do row = 1, rows
      counts(row) = nint(number(t, row, 'n_nodes'))
      indices(row) = nint(number(t, row, 'index'))
      values(row) = number(t, row, 'value')
      first(row) = quantities(row) == 'node' .and. indices(row) == 0
    end do
    moment_rules = 0
    do n = 1, FLUIDBED_MAX_NODES
      write(label, '(a, i0)') ' N = ', n
      do s = 1, size(supports)
        ! The cases with an n-node rule on this support (each must have 2n moments).
        names = pack(cases, first .and. counts == n .and. cases /= 'radau_legendre01')
        real_line = [(index(names(c), 'hermite') == 1 .or. index(names(c), 'random_jacobi') == 1, &
                      c = 1, size(names))]
        names = pack(names, real_line .eqv. (supports(s) == FLUIDBED_SUPPORT_REAL_LINE))
        if (size(names) == 0) cycle
        allocate(m(size(names), 2 * n), nodes(size(names), n), weights(size(names), n), sizes(size(names)), &
                 status(size(names)))
        do c = 1, size(names)
          moments = oracle(cases, counts, quantities, indices, values, names(c), 0, 'moment')
          call check(size(moments) >= 2 * n, trim(names(c)) // ': 2N moments')
          m(c, :) = 0
          m(c, 1:min(2 * n, size(moments))) = moments(1:min(2 * n, size(moments)))
        end do
        code = fluidbed_invert_moments(n, supports(s), m, nodes, weights, sizes, status, message)
        call check(code == FLUIDBED_OK, 'invert the reference moments: ' // message)
        do cell = 1, size(names)
          what = trim(names(cell)) // trim(label)
          call check(status(cell) == FLUIDBED_INVERSION_OK .and. sizes(cell) == n, what // ': status and size')
          x = oracle(cases, counts, quantities, indices, values, names(cell), n, 'node')
          w = oracle(cases, counts, quantities, indices, values, names(cell), n, 'weight')
          spread = abs(x(1))
          if (n > 1) spread = x(n) - x(1)
          node_error = maxval(abs(nodes(cell, :) - x)) / spread
          weight_error = maxval(abs(weights(cell, :) - w)) / m(cell, 1)
          call check(node_error <= moment_tolerance(oracle(cases, counts, quantities, indices, values, names(cell), &
                                                           n, 'node_condition'), n), &
                     what // ': nodes against the reference table')
          call check(weight_error <= moment_tolerance(oracle(cases, counts, quantities, indices, values, &
                                                             names(cell), n, 'weight_condition'), n), &
                     what // ': weights against the reference table')
        end do
        moment_rules = moment_rules + size(names)
        deallocate(m, nodes, weights, sizes, status)
      end do
    end do
  end subroutine

  ! tests/test_moment_oracle.cpp's 8·2N·conditioning + 8e-16 (the table's one condition row).
  real(c_double) function moment_tolerance(condition, n)
    real(c_double), intent(in) :: condition(:)
    integer, intent(in) :: n
    moment_tolerance = nan
    if (size(condition) == 1) moment_tolerance = 8 * 2 * n * condition(1) + 8e-16_c_double
  end function

  ! ---- The catalogue and the closures' metadata ---------------------------------------------------

  subroutine check_metadata()
    type(fluidbed_closure) :: law, copy
    character(len=:), allocatable :: quantity, message
    real(c_double) :: low, high, value, pair(2), slope(2)
    integer :: i, status
    logical :: lebowitz, syamlal
    lebowitz = .false.
    syamlal = .false.
    do i = 1, fluidbed_closure_count()
      ! (no impure function in a .or./.and. operand gfortran may skip: -Wfunction-elimination at -O)
      if (fluidbed_closure_name_at(i) == 'Lebowitz') lebowitz = .true.
      if (fluidbed_closure_name_at(i) == 'SyamlalSolidSolidDrag') syamlal = .true.
    end do
    call check(fluidbed_closure_count() > 50 .and. lebowitz .and. syamlal, 'the catalogue')
    call check(fluidbed_closure_name_at(fluidbed_closure_count() + 1) == '', 'no name beyond the catalogue')
    call check(fluidbed_closure_name_at(0) == '', 'no name before the catalogue')
    do i = 0, FLUIDBED_FAMILY_COUNT - 1
      call check(len(fluidbed_family_what(i)) > 0, 'a family''s what')
      call check(len(fluidbed_family_convention(i)) > 0, 'a family''s convention')
    end do
    call check(fluidbed_family_what(FLUIDBED_FAMILY_COUNT) == '', 'no family beyond the last')
    call check(fluidbed_status_name(FLUIDBED_DOMAIN_ERROR) == 'FLUIDBED_DOMAIN_ERROR', 'a status name')
    law = created('ModifiedMansoori', 'max_packing', 0.6_c_double)
    call check(fluidbed_family(law) == FLUIDBED_FAMILY_MIXTURE_RADIAL_DISTRIBUTION, 'the family of ModifiedMansoori')
    call check(len(fluidbed_reference(law)) > 20, 'a reference: ' // fluidbed_reference(law))
    call check(has_parameter(law, 'max_packing'), 'the parameters')
    call check(fluidbed_parameter_name(law, 0) == '', 'no parameter 0')
    call check(fluidbed_parameter_name(law, fluidbed_parameter_count(law) + 1) == '', 'no parameter beyond the last')
    copy = fluidbed_copy(law)
    status = fluidbed_get_parameter(copy, 'max_packing', value)
    call check(status == FLUIDBED_OK .and. same_bits(value, 0.6_c_double), 'a copy keeps the parameters')
    call check(fluidbed_name(copy) == 'ModifiedMansoori', 'a copy keeps the name')
    call fluidbed_destroy(copy)
    call fluidbed_destroy(law)
    law = created('SyamlalSolidSolidDrag')
    call check(fluidbed_family(law) == FLUIDBED_FAMILY_SOLID_SOLID_DRAG, 'the family of SyamlalSolidSolidDrag')
    call check(fluidbed_richardson_zaki_argument(law) == '', 'no Richardson-Zaki argument for another family')
    call fluidbed_destroy(law)
    ! Single spheres and settling, closed forms: Schiller-Naumann C_D Re = 24 (1 + 0.15 Re^0.687)
    ! below Re = 1000 and 0.44 Re above; its terminal Re_t → Ar/18 (Stokes); Rowe's
    ! n = (4.7 + 0.41 Re_t^¾)/(1 + 0.175 Re_t^¾).
    law = created('SchillerNaumannCoefficient')
    status = fluidbed_validity(law, 1, quantity, low, high, message)
    call check(fluidbed_validity_count(law) == 1 .and. status == FLUIDBED_OK .and. quantity == 'reynolds' .and. &
               same_bits(low, zero) .and. same_bits(high, 2e5_c_double), &
               'the validity range of SchillerNaumannCoefficient: ' // message)
    status = fluidbed_validity(law, 2, quantity, low, high, message)
    call check(status == FLUIDBED_INVALID_ARGUMENT .and. quantity == '', 'no validity range beyond the last')
    status = fluidbed_sphere_drag_coefficient(law, [1.0_c_double, 2000.0_c_double], pair, slope, message)
    call check(status == FLUIDBED_OK .and. &
               all(relative_difference(pair, [27.6_c_double, 880.0_c_double]) < 1e-15_c_double) .and. &
               relative_difference(slope(2), 0.44_c_double) < 1e-15_c_double, 'C_D Re of Schiller-Naumann')
    call fluidbed_destroy(law)
    law = created('SchillerNaumannTerminalVelocity')
    status = fluidbed_reynolds_of_archimedes(law, [1e-3_c_double, 1e-2_c_double], pair, slope, message)
    call check(status == FLUIDBED_OK .and. all(relative_difference(pair, [1e-3_c_double, 1e-2_c_double] / 18) &
               < 1e-3_c_double) .and. all(relative_difference(slope, [1.0_c_double, 1.0_c_double] / 18) &
               < 1e-2_c_double), 'Re_t of Schiller-Naumann, Stokes limit: ' // message)
    call fluidbed_destroy(law)
    law = created('RoweExponent')
    call check(fluidbed_richardson_zaki_argument(law) == 'terminal_reynolds', 'Rowe''s argument')
    status = fluidbed_richardson_zaki_exponent(law, [1.0_c_double, 0.0_c_double], pair, message=message)
    call check(status == FLUIDBED_OK .and. relative_difference(pair(1), 5.11_c_double / 1.175_c_double) &
               < 1e-15_c_double .and. same_bits(pair(2), 4.7_c_double), 'Rowe''s exponent: ' // message)
    call fluidbed_destroy(law)
  end subroutine

  ! ---- Bad input --------------------------------------------------------------------------------------

  subroutine check_bad_input()
    type(fluidbed_closure) :: rdf, law, mixture, drag, source, wrong
    real(c_double) :: phi(4), value(4), short(3), theta(4), d(4), rho(4), e(4), fractions(4, 2), diameters(4, 2), &
                      g(4), d_short(3, 2), moments(4, 4), nodes(4, 2), weights(4, 2), moments_9(1, 18), &
                      nodes_9(1, 9), weights_9(1, 9)
    integer(c_int) :: sizes(4), status(4), short_status(3)
    character(len=:), allocatable :: message
    integer :: code, cell
    phi = [0.1_c_double, 0.2_c_double, nan, 0.3_c_double]
    theta = 0.01_c_double
    d = 5e-4_c_double
    rho = 2500
    e = 0.9_c_double
    rdf = created('CarnahanStarling')
    law = created('LunPressure')
    mixture = created('Lebowitz')
    drag = created('SyamlalSolidSolidDrag')
    source = created('KochSanganiSource')

    ! Arrays of different sizes or shapes: the wrapper's own error, C not called.
    code = fluidbed_of_solid_fraction(rdf, phi, short, message=message, cell=cell)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. cell == 0 .and. &
               message == 'fluidbed: fluidbed_of_solid_fraction: the arrays differ in size from solid_fraction', &
               'of_solid_fraction, arrays of different sizes: ' // message)
    code = fluidbed_constitutive(law, rdf, phi, theta, d, rho, e, value, d_granular_temperature=short, &
                                 message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. &
               message == 'fluidbed: fluidbed_constitutive: the arrays differ in size from solid_fraction', &
               'constitutive, a derivative of another size: ' // message)
    fractions(:, 1) = [0.1_c_double, 0.2_c_double, 0.3_c_double, 0.2_c_double]
    fractions(:, 2) = [0.2_c_double, nan, 0.1_c_double, 0.2_c_double]
    diameters(:, 1) = 1e-4_c_double
    diameters(:, 2) = 2e-4_c_double
    code = fluidbed_mixture_radial_distribution(mixture, 1, 2, fractions, diameters(:, 1:1), g, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. message == &
               'fluidbed: fluidbed_mixture_radial_distribution: the arrays differ in size from fractions', &
               'mixture distribution, diameters of another class count: ' // message)
    code = fluidbed_mixture_radial_distribution(mixture, 1, 2, fractions, diameters, g, d_short, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'mixture distribution, derivatives of another cell count')
    code = fluidbed_solid_solid_drag(drag, phi, phi, rho, d, rho, d, e, phi, phi, value, d_relative_speed=short, &
                                     message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. &
               message == 'fluidbed: fluidbed_solid_solid_drag: the arrays differ in size from phi_p', &
               'solid-solid drag, a derivative of another size: ' // message)
    code = fluidbed_gas_exchange_source(source, phi, theta, phi, d, rho, e, value, radial=rdf, gas_viscosity=short, &
                                        message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'gas exchange, a gas viscosity of another size')
    moments = 1
    code = fluidbed_invert_moments(2, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, moments(:, 1:3), nodes, weights, sizes, &
                                   status, message)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. &
               message == 'fluidbed: fluidbed_invert_moments: the arrays differ in size from moments', &
               'invert, 3 moments for 2 nodes: ' // message)
    code = fluidbed_invert_moments(2, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, moments, nodes, weights, sizes, &
                                   short_status, message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'invert, a status array of another size')
    code = fluidbed_moment_realizability(FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, moments, status, sizes, &
                                         first_failing_index=short_status, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'realizability, an optional output of another size')
    code = fluidbed_correct_moments(moments, nodes, status, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. &
               message == 'fluidbed: fluidbed_correct_moments: the arrays differ in size from moments', &
               'correct, a corrected array of another shape: ' // message)

    ! NaN fractions: the checked API's domain error, the 1-based cell, the argument named.
    code = fluidbed_of_solid_fraction(rdf, phi, value, message=message, cell=cell)
    call check(code == FLUIDBED_DOMAIN_ERROR .and. cell == 3, 'a NaN solid fraction in cell 3')
    call check(index(message, "fluidbed::kinetic_theory::CarnahanStarling: argument 'solid_fraction' = nan") == 1, &
               'the checked message: ' // message)
    print '(a, i0, 2a)', 'cell ', cell, ': ', message
    code = fluidbed_constitutive(law, rdf, phi, theta, d, rho, e, value, message=message, cell=cell)
    call check(code == FLUIDBED_DOMAIN_ERROR .and. cell == 3 .and. index(message, "'solid_fraction' = nan") > 0, &
               'constitutive, a NaN solid fraction in cell 3: ' // message)
    code = fluidbed_mixture_radial_distribution(mixture, 1, 2, fractions, diameters, g, message=message, cell=cell)
    call check(code == FLUIDBED_DOMAIN_ERROR .and. cell == 2 .and. &
               index(message, "fluidbed::kinetic_theory::Lebowitz: argument 'fractions[1]' = nan") == 1, &
               'mixture distribution, a NaN fraction of class 2 in cell 2: ' // message)
    print '(a, i0, 2a)', 'cell ', cell, ': ', message
    code = fluidbed_mixture_radial_distribution(mixture, 3, 1, fractions(1:1, :), diameters(1:1, :), g(1:1), &
                                                message=message)
    call check(code == FLUIDBED_DOMAIN_ERROR .and. index(message, "'i'") > 0, 'class 3 of 2: ' // message)
    code = fluidbed_mixture_radial_distribution(mixture, 0, 1, fractions(1:1, :), diameters(1:1, :), g(1:1), &
                                                message=message)
    call check(code == FLUIDBED_DOMAIN_ERROR, 'class 0 (1-based): ' // message)

    ! An unknown name; closures of the wrong family.
    code = fluidbed_create('NoSuchRadialDistribution', wrong, message)
    call check(code == FLUIDBED_UNKNOWN_NAME .and. index(message, "unknown closure 'NoSuchRadialDistribution'") > 0, &
               'an unknown name: ' // message)
    phi(3) = 0.3_c_double
    code = fluidbed_of_solid_fraction(law, phi, value, message=message, cell=cell)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'of_solid_fraction of a granular pressure: ' // message)
    code = fluidbed_constitutive(law, law, phi, theta, d, rho, e, value, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'a granular pressure as the radial distribution: ' // message)
    code = fluidbed_constitutive(rdf, rdf, phi, theta, d, rho, e, value, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'a radial distribution as the law: ' // message)
    code = fluidbed_mixture_radial_distribution(rdf, 1, 1, fractions(1:1, :), diameters(1:1, :), g(1:1), &
                                                message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'a one-class distribution as a mixture one: ' // message)
    code = fluidbed_solid_solid_drag(mixture, phi, phi, rho, d, rho, d, e, phi, phi, value, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'a mixture distribution as a solid-solid drag: ' // message)
    code = fluidbed_gas_exchange_source(source, phi, theta, phi, d, rho, e, value, radial=law, gas_viscosity=phi, &
                                        message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'a granular pressure as the radial distribution of a source')
    ! A source without its own arguments.
    code = fluidbed_gas_exchange_source(source, phi, theta, phi, d, rho, e, value, gas_viscosity=phi, message=message)
    call check(code == FLUIDBED_INVALID_ARGUMENT, 'Koch-Sangani without a radial distribution: ' // message)
    code = fluidbed_of_solid_fraction(rdf, phi(1:0), value(1:0), message=message)
    call check(code == FLUIDBED_OK, 'no cells: ' // message)
    moments_9 = 1
    code = fluidbed_invert_moments(9, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, moments_9, nodes_9, weights_9, &
                                   sizes(1:1), status(1:1), message)
    call check(code == FLUIDBED_INVALID_ARGUMENT .and. index(message, '9 nodes') > 0, '9 nodes: ' // message)
    call fluidbed_destroy(rdf)
    call fluidbed_destroy(law)
    call fluidbed_destroy(mixture)
    call fluidbed_destroy(drag)
    call fluidbed_destroy(source)
  end subroutine

end program
