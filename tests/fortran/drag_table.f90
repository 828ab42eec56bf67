! The Fortran module (bindings/fortran/fluidbed.f90) on every row of the drag reference table
! (tests/reference/drag_reference.csv, mpmath), ctest fortran.drag_table:
!  - β in both conventions within 1e-12 of the table (the C++ tests' tolerance), its derivatives
!    and ∂(βw)/∂w through the wrapper equal bit for bit to the C function called directly (which
!    tests/test_c_interface.cpp shows equal bit for bit to the C++ library);
!  - bad input: arrays of different sizes, a NaN voidage (the status, the 1-based cell, the
!    checked API's message), an unknown law, an unknown parameter and one out of its domain.
! Usage: fluidbed_fortran_drag_table PATH/TO/drag_reference.csv
program drag_table
  use, intrinsic :: iso_c_binding, only: c_double, c_size_t, c_int, c_loc
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use fluidbed
  use fortran_checks
  implicit none
  integer, parameter :: max_rows = 4000
  character(len=64) :: law_of(max_rows)
  real(c_double) :: cells(8, max_rows)  ! voidage, slip, density, viscosity, diameter, Re, beta_cl, beta_pg
  integer :: rows, first, last
  character(len=1024) :: path

  call get_command_argument(1, path)
  call read_table(trim(path))
  first = 1
  do while (first <= rows)
    last = first
    do while (last < rows)
      if (law_of(last + 1) /= law_of(first)) exit
      last = last + 1
    end do
    call check_law(first, last)
    first = last + 1
  end do
  call check_bad_input()
  block
    character(len=96) :: passed
    write(passed, '(a, i0, a)') 'fortran: ', rows, ' drag reference rows, both conventions: all checks passed'
    call finish(trim(passed))
  end block

contains

  subroutine read_table(file)
    character(len=*), intent(in) :: file
    character(len=512) :: line
    integer :: unit, status, comma
    open(newunit=unit, file=file, status='old', action='read')
    read(unit, '(a)') line  ! the header
    rows = 0
    do
      read(unit, '(a)', iostat=status) line
      if (status /= 0) exit
      if (len_trim(line) == 0) cycle
      rows = rows + 1
      comma = index(line, ',')
      law_of(rows) = line(1:comma - 1)
      read(line(comma + 1:), *) cells(:, rows)
    end do
    close(unit)
  end subroutine

  subroutine check_law(first, last)
    integer, intent(in) :: first, last
    type(fluidbed_closure) :: law
    integer :: status, convention, i, n
    real(c_double), allocatable, target :: beta(:), d_voidage(:), d_slip(:), d_force(:), &
                                           raw(:), raw_d_voidage(:), raw_d_slip(:), raw_d_force(:)
    real(c_double) :: expected
    character(len=:), allocatable :: message
    n = last - first + 1
    allocate(beta(n), d_voidage(n), d_slip(n), d_force(n), raw(n), raw_d_voidage(n), raw_d_slip(n), raw_d_force(n))
    status = fluidbed_create(trim(law_of(first)), law, message)
    call check(status == FLUIDBED_OK, 'create ' // trim(law_of(first)) // ': ' // message)
    do convention = FLUIDBED_BUOYANCY_CLASSICAL, FLUIDBED_BUOYANCY_PRESSURE_GRADIENT
      associate (c => cells(:, first:last))
        status = fluidbed_drag(law, convention, c(1, :), c(2, :), c(3, :), c(4, :), c(5, :), beta, &
                               d_voidage, d_slip, d_force, message)
        call check(status == FLUIDBED_OK, trim(law_of(first)) // ': ' // message)
        status = raw_drag(law, convention, c, raw, raw_d_voidage, raw_d_slip, raw_d_force)
        call check(status == FLUIDBED_OK, trim(law_of(first)) // ': the C function')
        do i = 1, n
          expected = c(7 + convention, i)
          call check(abs(beta(i) - expected) <= 1e-12_c_double * abs(expected), &
                     trim(law_of(first)) // ': beta against the reference table')
        end do
        call check(all(same_bits(beta, raw)) .and. all(same_bits(d_voidage, raw_d_voidage)) .and. &
                   all(same_bits(d_slip, raw_d_slip)) .and. all(same_bits(d_force, raw_d_force)), &
                   trim(law_of(first)) // ': the wrapper equals the C function bit for bit')
      end associate
    end do
    call fluidbed_destroy(law)
  end subroutine

  ! The C function called directly, with the derivative outputs as C pointers.
  integer function raw_drag(law, convention, c, beta, d_voidage, d_slip, d_force) result(status)
    type(fluidbed_closure), intent(in) :: law
    integer, intent(in) :: convention
    real(c_double), intent(in) :: c(:, :)
    real(c_double), intent(out), target :: beta(:), d_voidage(:), d_slip(:), d_force(:)
    real(c_double) :: columns(size(c, 2), 5)
    type(fluidbed_c_error) :: error
    columns = transpose(c(1:5, :))  ! one contiguous array per argument
    status = fluidbed_c_drag(law%handle, int(convention, c_int), int(size(beta), c_size_t), columns(:, 1), &
                             columns(:, 2), columns(:, 3), columns(:, 4), columns(:, 5), beta, &
                             c_loc(d_voidage(1)), c_loc(d_slip(1)), c_loc(d_force(1)), error)
  end function

  subroutine check_bad_input()
    type(fluidbed_closure) :: law
    integer :: status, cell
    real(c_double) :: voidage(3), slip(3), density(3), viscosity(3), diameter(3), beta(3), short(2), c1
    character(len=:), allocatable :: message
    voidage = [0.5_c_double, ieee_value(0.5_c_double, ieee_quiet_nan), 0.5_c_double]
    slip = 0.1_c_double
    density = 1.2_c_double
    viscosity = 1.8e-5_c_double
    diameter = 3e-4_c_double
    status = fluidbed_create('SyamlalOBrien', law, message)
    call check(status == FLUIDBED_OK, 'create SyamlalOBrien')
    status = fluidbed_drag(law, FLUIDBED_BUOYANCY_CLASSICAL, voidage, slip, density, viscosity, diameter, beta, &
                           message=message, cell=cell)
    call check(status == FLUIDBED_DOMAIN_ERROR, 'a NaN voidage is a domain error')
    call check(cell == 2, 'the failing cell, 1-based')
    call check(index(message, "fluidbed::SyamlalOBrien: argument 'voidage' = nan is out of domain") == 1, &
               'the checked message: ' // message)
    print '(a, i0, 2a)', 'cell ', cell, ': ', message
    status = fluidbed_drag(law, FLUIDBED_BUOYANCY_CLASSICAL, voidage, slip(1:2), density, viscosity, diameter, beta, &
                           message=message)
    call check(status == FLUIDBED_INVALID_ARGUMENT, 'arrays of different sizes')
    status = fluidbed_drag(law, FLUIDBED_BUOYANCY_CLASSICAL, voidage, slip, density, viscosity, diameter, beta, &
                           d_slip=short, message=message)
    call check(status == FLUIDBED_INVALID_ARGUMENT, 'a derivative array of another size')
    status = fluidbed_drag(law, 7, voidage, slip, density, viscosity, diameter, beta, message=message)
    call check(status == FLUIDBED_INVALID_ARGUMENT, 'an unknown convention')
    status = fluidbed_set_parameter(law, 'c1', -1.0_c_double, message)
    call check(status == FLUIDBED_DOMAIN_ERROR, 'c1 = -1')
    call check(message == "fluidbed::SyamlalOBrien: argument 'c1' = -1 is out of domain (must be finite and > 0)", &
               'the parameter message: ' // message)
    status = fluidbed_get_parameter(law, 'c1', c1)
    call check(status == FLUIDBED_OK .and. same_bits(c1, 0.8_c_double), 'c1 unchanged')
    status = fluidbed_set_parameter(law, 'exponent', 2.65_c_double, message)
    call check(status == FLUIDBED_UNKNOWN_PARAMETER, 'no parameter exponent')
    call check(fluidbed_name(law) == 'SyamlalOBrien', 'the name')
    call fluidbed_destroy(law)
    status = fluidbed_create('NoSuchLaw', law, message)
    call check(status == FLUIDBED_UNKNOWN_NAME, 'an unknown law')
    call check(index(message, "fluidbed: unknown closure 'NoSuchLaw'; known: ") == 1, 'the unknown-name message')
  end subroutine

end program
