! fluidbed — the library's closures from Fortran (2008, iso_c_binding), over the C interface
! (fluidbed_c.h, libfluidbed_c; every function of it but the float variants). A closure is chosen
! by name once and evaluated over arrays of cells; every evaluation validates each cell as the
! C++ checked API does and returns a status, with the failing cell (1-based) and the C++
! library's message. Array arguments must have the same size (checked: a mismatch is
! FLUIDBED_INVALID_ARGUMENT, never a read past an array). The fields that are 2-D in C (moment k
! of cell c at moments[k n + c]) are arrays shaped (cells, count): element (c, k + 1) is that
! moment (a contiguous array is passed without a copy). Indices (catalogue, parameters, validity
! ranges, classes) are 1-based here.
! The values are those of the C interface, bit for bit: the wrappers only pass the arrays.
!
!   use fluidbed
!   type(fluidbed_closure) :: law
!   integer :: status
!   character(len=:), allocatable :: message
!   status = fluidbed_create('MazzeiLettieri', law, message)
!   status = fluidbed_drag(law, FLUIDBED_BUOYANCY_PRESSURE_GRADIENT, voidage, slip, &
!                          rho_g, mu_g, d_p, beta, message=message)
!   call fluidbed_destroy(law)
module fluidbed
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_int, c_size_t, c_double, c_char, &
                                         c_null_char, c_associated, c_loc, c_f_pointer
  implicit none
  private

  ! Statuses (fluidbed_status).
  integer, parameter, public :: FLUIDBED_OK = 0, FLUIDBED_UNKNOWN_NAME = 1, &
                                FLUIDBED_UNKNOWN_PARAMETER = 2, FLUIDBED_DOMAIN_ERROR = 3, &
                                FLUIDBED_INVALID_ARGUMENT = 4, FLUIDBED_INTERNAL_ERROR = 5
  ! Families (fluidbed_family), one per registry of the C++ library: the C enumerators with
  ! FAMILY_ added (FLUIDBED_FAMILY_DRAG_LAW), since Fortran, blind to case, would take
  ! FLUIDBED_SPHERE_DRAG_COEFFICIENT for the function fluidbed_sphere_drag_coefficient.
  integer, parameter, public :: FLUIDBED_FAMILY_SPHERE_DRAG_COEFFICIENT = 0, &
                                FLUIDBED_FAMILY_TERMINAL_VELOCITY = 1, &
                                FLUIDBED_FAMILY_RICHARDSON_ZAKI_EXPONENT = 2, &
                                FLUIDBED_FAMILY_MINIMUM_FLUIDIZATION = 3, &
                                FLUIDBED_FAMILY_DRAG_LAW = 4, &
                                FLUIDBED_FAMILY_ELASTIC_MODULUS = 5, &
                                FLUIDBED_FAMILY_RADIAL_DISTRIBUTION = 6, &
                                FLUIDBED_FAMILY_MIXTURE_RADIAL_DISTRIBUTION = 7, &
                                FLUIDBED_FAMILY_GRANULAR_PRESSURE = 8, &
                                FLUIDBED_FAMILY_SHEAR_VISCOSITY = 9, &
                                FLUIDBED_FAMILY_BULK_VISCOSITY = 10, &
                                FLUIDBED_FAMILY_CONDUCTIVITY = 11, &
                                FLUIDBED_FAMILY_DISSIPATION = 12, &
                                FLUIDBED_FAMILY_FRICTIONAL_PRESSURE = 13, &
                                FLUIDBED_FAMILY_FRICTIONAL_VISCOSITY = 14, &
                                FLUIDBED_FAMILY_FRICTIONAL_STRESS = 15, &
                                FLUIDBED_FAMILY_GAS_EXCHANGE_SOURCE = 16, &
                                FLUIDBED_FAMILY_SOLID_SOLID_DRAG = 17, &
                                FLUIDBED_FAMILY_WALL_BOUNDARY_CONDITION = 18, &
                                FLUIDBED_FAMILY_COUNT = 19
  ! Buoyancy conventions (fluidbed_buoyancy): classical −φ ρ_f g, or pressure gradient −φ ∇p
  ! (MFiX model A, OpenFOAM, Fluent); β_pressure_gradient = ε β_classical.
  integer, parameter, public :: FLUIDBED_BUOYANCY_CLASSICAL = 0, &
                                FLUIDBED_BUOYANCY_PRESSURE_GRADIENT = 1
  ! The most solids classes of the mixture functions, and nodes of the moment functions.
  integer, parameter, public :: FLUIDBED_MAX_CLASSES = 10, FLUIDBED_MAX_NODES = 8
  ! Supports of the distributions (fluidbed_support): [0, ∞) (sizes) or the real line (velocities).
  integer, parameter, public :: FLUIDBED_SUPPORT_POSITIVE_HALF_LINE = 0, FLUIDBED_SUPPORT_REAL_LINE = 1
  ! A cell's outcome of the inversion and the realizability test (fluidbed_inversion_status).
  integer, parameter, public :: FLUIDBED_INVERSION_OK = 0, FLUIDBED_INVERSION_REDUCED = 1, &
                                FLUIDBED_INVERSION_ZERO_MASS = 2, FLUIDBED_INVERSION_NOT_REALIZABLE = 3, &
                                FLUIDBED_INVERSION_INVALID_INPUT = 4, FLUIDBED_INVERSION_EIGEN_FAILURE = 5, &
                                FLUIDBED_INVERSION_INACCURATE = 6
  ! A cell's outcome of the correction (fluidbed_correction_status).
  integer, parameter, public :: FLUIDBED_CORRECTION_UNCHANGED = 0, FLUIDBED_CORRECTION_MCGRAW = 1, &
                                FLUIDBED_CORRECTION_LOGNORMAL = 2, FLUIDBED_CORRECTION_MONODISPERSE = 3, &
                                FLUIDBED_CORRECTION_ZERO_MASS = 4, FLUIDBED_CORRECTION_FAILED = 5
  ! A cell's outcome of the DQMOM source solve (fluidbed_dqmom_status), and what the weights are
  ! (fluidbed_dqmom_weights).
  integer, parameter, public :: FLUIDBED_DQMOM_OK = 0, FLUIDBED_DQMOM_MERGED_NODES = 1, &
                                FLUIDBED_DQMOM_INVALID_INPUT = 2
  integer, parameter, public :: FLUIDBED_DQMOM_VOLUME_FRACTION = 0, FLUIDBED_DQMOM_NUMBER_DENSITY = 1
  integer, parameter :: message_size = 512

  ! A closure chosen by name; fluidbed_destroy frees it.
  type, public :: fluidbed_closure
    type(c_ptr) :: handle = c_null_ptr
  end type

  ! fluidbed_error of the C interface, for hosts that call its functions directly (index 0-based).
  type, bind(C), public :: fluidbed_c_error
    integer(c_int) :: status
    integer(c_size_t) :: index
    character(kind=c_char) :: message(message_size)
  end type

  ! The correction's options (fluidbed_correction_options): moments McGraw never changes (>= 1),
  ! his iterations (>= 0), the relative tolerance at the boundary of moment space (>= 0).
  type, bind(C), public :: fluidbed_correction_options
    integer(c_int) :: protected_moments
    integer(c_int) :: max_iterations
    real(c_double) :: degenerate_tolerance
  end type

  public :: fluidbed_status_name, fluidbed_family_what, fluidbed_family_convention, fluidbed_closure_count, &
            fluidbed_closure_name_at, fluidbed_create, fluidbed_copy, fluidbed_destroy, fluidbed_family, &
            fluidbed_name, fluidbed_reference, fluidbed_validity_count, fluidbed_validity, &
            fluidbed_parameter_count, fluidbed_parameter_name, fluidbed_set_parameter, fluidbed_get_parameter, &
            fluidbed_drag, fluidbed_c_drag, fluidbed_sphere_drag_coefficient, fluidbed_reynolds_of_archimedes, &
            fluidbed_richardson_zaki_exponent, fluidbed_richardson_zaki_argument, &
            fluidbed_elastic_modulus_at_equilibrium, fluidbed_elastic_modulus_at_state, &
            fluidbed_of_solid_fraction, fluidbed_constitutive, fluidbed_frictional_viscosity, &
            fluidbed_frictional_stress, fluidbed_mixture_radial_distribution, fluidbed_solid_solid_drag, &
            fluidbed_gas_exchange_source, fluidbed_invert_moments, fluidbed_moment_realizability, &
            fluidbed_correction_default_options, fluidbed_correct_moments, fluidbed_dqmom_sources, &
            fluidbed_dqmom_growth_diffusion_sources, fluidbed_unequal_temperature_mixture

  ! Whether the arrays agree in size (see sizes_agree_each).
  interface sizes_agree
    module procedure sizes_agree_each, sizes_agree_all
  end interface

  interface
    integer(c_size_t) function c_strlen(string) bind(C, name='strlen')
      import :: c_ptr, c_size_t
      type(c_ptr), value :: string
    end function
    type(c_ptr) function c_status_name(status) bind(C, name='fluidbed_status_name')
      import :: c_ptr, c_int
      integer(c_int), value :: status
    end function
    type(c_ptr) function c_family_what(family) bind(C, name='fluidbed_family_what')
      import :: c_ptr, c_int
      integer(c_int), value :: family
    end function
    type(c_ptr) function c_family_convention(family) bind(C, name='fluidbed_family_convention')
      import :: c_ptr, c_int
      integer(c_int), value :: family
    end function
    integer(c_size_t) function c_closure_count() bind(C, name='fluidbed_closure_count')
      import :: c_size_t
    end function
    type(c_ptr) function c_closure_name_at(index) bind(C, name='fluidbed_closure_name_at')
      import :: c_ptr, c_size_t
      integer(c_size_t), value :: index
    end function
    integer(c_int) function c_create(name, closure, error) bind(C, name='fluidbed_closure_create')
      import :: c_char, c_ptr, c_int, fluidbed_c_error
      character(kind=c_char), intent(in) :: name(*)
      type(c_ptr), intent(out) :: closure
      type(fluidbed_c_error), intent(out) :: error
    end function
    type(c_ptr) function c_copy(closure) bind(C, name='fluidbed_closure_copy')
      import :: c_ptr
      type(c_ptr), value :: closure
    end function
    subroutine c_destroy(closure) bind(C, name='fluidbed_closure_destroy')
      import :: c_ptr
      type(c_ptr), value :: closure
    end subroutine
    integer(c_int) function c_family(closure) bind(C, name='fluidbed_closure_family')
      import :: c_ptr, c_int
      type(c_ptr), value :: closure
    end function
    type(c_ptr) function c_name(closure) bind(C, name='fluidbed_closure_name')
      import :: c_ptr
      type(c_ptr), value :: closure
    end function
    type(c_ptr) function c_reference(closure) bind(C, name='fluidbed_closure_reference')
      import :: c_ptr
      type(c_ptr), value :: closure
    end function
    integer(c_size_t) function c_validity_count(closure) bind(C, name='fluidbed_closure_validity_count')
      import :: c_ptr, c_size_t
      type(c_ptr), value :: closure
    end function
    integer(c_int) function c_validity(closure, index, quantity, minimum, maximum, error) &
        bind(C, name='fluidbed_closure_validity')
      import :: c_ptr, c_size_t, c_double, c_int, fluidbed_c_error
      type(c_ptr), value :: closure
      integer(c_size_t), value :: index
      type(c_ptr), intent(inout) :: quantity  ! (written on success only)
      real(c_double), intent(inout) :: minimum, maximum
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_size_t) function c_parameter_count(closure) bind(C, name='fluidbed_closure_parameter_count')
      import :: c_ptr, c_size_t
      type(c_ptr), value :: closure
    end function
    type(c_ptr) function c_parameter_name(closure, index) bind(C, name='fluidbed_closure_parameter_name')
      import :: c_ptr, c_size_t
      type(c_ptr), value :: closure
      integer(c_size_t), value :: index
    end function
    integer(c_int) function c_set_parameter(closure, name, value, error) &
        bind(C, name='fluidbed_closure_set_parameter')
      import :: c_ptr, c_char, c_double, c_int, fluidbed_c_error
      type(c_ptr), value :: closure
      character(kind=c_char), intent(in) :: name(*)
      real(c_double), value :: value
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_get_parameter(closure, name, value, error) &
        bind(C, name='fluidbed_closure_get_parameter')
      import :: c_ptr, c_char, c_double, c_int, fluidbed_c_error
      type(c_ptr), value :: closure
      character(kind=c_char), intent(in) :: name(*)
      real(c_double), intent(out) :: value
      type(fluidbed_c_error), intent(out) :: error
    end function
    ! The C function itself, for hosts that manage their own arrays (fluidbed_c_drag); the
    ! optional derivative outputs are C pointers (c_null_ptr: not computed).
    integer(c_int) function fluidbed_c_drag(law, convention, n, voidage, slip, density, viscosity, &
                                            diameter, beta, d_voidage, d_slip, d_force_d_slip, error) &
        bind(C, name='fluidbed_drag')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_int), value :: convention
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: voidage(*), slip(*), density(*), viscosity(*), diameter(*)
      real(c_double), intent(out) :: beta(*)
      type(c_ptr), value :: d_voidage, d_slip, d_force_d_slip
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_sphere_drag_coefficient(law, n, reynolds, cd_re, d_reynolds, error) &
        bind(C, name='fluidbed_sphere_drag_coefficient')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: reynolds(*)
      real(c_double), intent(out) :: cd_re(*)
      type(c_ptr), value :: d_reynolds
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_reynolds_of_archimedes(law, n, archimedes, reynolds, d_archimedes, error) &
        bind(C, name='fluidbed_reynolds_of_archimedes')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: archimedes(*)
      real(c_double), intent(out) :: reynolds(*)
      type(c_ptr), value :: d_archimedes
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_richardson_zaki_exponent(law, n, argument, exponent, d_argument, error) &
        bind(C, name='fluidbed_richardson_zaki_exponent')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: argument(*)
      real(c_double), intent(out) :: exponent(*)
      type(c_ptr), value :: d_argument
      type(fluidbed_c_error), intent(out) :: error
    end function
    type(c_ptr) function c_richardson_zaki_argument(law) bind(C, name='fluidbed_richardson_zaki_argument')
      import :: c_ptr
      type(c_ptr), value :: law
    end function
    integer(c_int) function c_elastic_modulus_at_equilibrium(model, n, voidage, fluid_density, fluid_viscosity, &
                                                             particle_density, diameter, terminal_reynolds, gravity, &
                                                             modulus, d_voidage, error) &
        bind(C, name='fluidbed_elastic_modulus_at_equilibrium')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: model
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: voidage(*), fluid_density(*), fluid_viscosity(*), particle_density(*), &
                                    diameter(*), terminal_reynolds(*), gravity(*)
      real(c_double), intent(out) :: modulus(*)
      type(c_ptr), value :: d_voidage
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_elastic_modulus_at_state(model, n, voidage, slip, fluid_density, fluid_viscosity, &
                                                       diameter, modulus, d_voidage, d_slip, error) &
        bind(C, name='fluidbed_elastic_modulus_at_state')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: model
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: voidage(*), slip(*), fluid_density(*), fluid_viscosity(*), diameter(*)
      real(c_double), intent(out) :: modulus(*)
      type(c_ptr), value :: d_voidage, d_slip
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_of_solid_fraction(law, n, solid_fraction, value, d_solid_fraction, error) &
        bind(C, name='fluidbed_of_solid_fraction')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: solid_fraction(*)
      real(c_double), intent(out) :: value(*)
      type(c_ptr), value :: d_solid_fraction
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_constitutive(law, radial, n, solid_fraction, granular_temperature, diameter, &
                                           solid_density, restitution, value, d_solid_fraction, &
                                           d_granular_temperature, error) bind(C, name='fluidbed_constitutive')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law, radial
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: solid_fraction(*), granular_temperature(*), diameter(*), solid_density(*), &
                                    restitution(*)
      real(c_double), intent(out) :: value(*)
      type(c_ptr), value :: d_solid_fraction, d_granular_temperature
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_frictional_viscosity(law, n, frictional_pressure, divergence, contraction, viscosity, &
                                                   d_frictional_pressure, error) &
        bind(C, name='fluidbed_frictional_viscosity')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: frictional_pressure(*), divergence(*), contraction(*)
      real(c_double), intent(out) :: viscosity(*)
      type(c_ptr), value :: d_frictional_pressure
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_frictional_stress(law, n, solid_fraction, granular_temperature, diameter, divergence, &
                                                contraction, pressure, viscosity, d_pressure, d_viscosity, error) &
        bind(C, name='fluidbed_frictional_stress')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: solid_fraction(*), granular_temperature(*), diameter(*), divergence(*), &
                                    contraction(*)
      real(c_double), intent(out) :: pressure(*), viscosity(*)
      type(c_ptr), value :: d_pressure, d_viscosity
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_mixture_radial_distribution(law, n, class_count, i, k, fractions, diameters, value, &
                                                          d_fractions, error) &
        bind(C, name='fluidbed_mixture_radial_distribution')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n, class_count, i, k
      real(c_double), intent(in) :: fractions(*), diameters(*)
      real(c_double), intent(out) :: value(*)
      type(c_ptr), value :: d_fractions
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_solid_solid_drag(law, n, phi_p, phi_q, density_p, diameter_p, density_q, diameter_q, &
                                               restitution, contact_rdf, relative_speed, coefficient, d_phi_p, &
                                               d_phi_q, d_contact_rdf, d_relative_speed, error) &
        bind(C, name='fluidbed_solid_solid_drag')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: phi_p(*), phi_q(*), density_p(*), diameter_p(*), density_q(*), diameter_q(*), &
                                    restitution(*), contact_rdf(*), relative_speed(*)
      real(c_double), intent(out) :: coefficient(*)
      type(c_ptr), value :: d_phi_p, d_phi_q, d_contact_rdf, d_relative_speed
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_gas_exchange_source(law, radial, n, solid_fraction, granular_temperature, slip, beta, &
                                                  gas_viscosity, diameter, solid_density, restitution, source, &
                                                  d_solid_fraction, d_granular_temperature, d_beta, d_slip, error) &
        bind(C, name='fluidbed_gas_exchange_source')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: law, radial
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: solid_fraction(*), granular_temperature(*), slip(*)
      type(c_ptr), value :: beta, gas_viscosity
      real(c_double), intent(in) :: diameter(*), solid_density(*), restitution(*)
      real(c_double), intent(out) :: source(*)
      type(c_ptr), value :: d_solid_fraction, d_granular_temperature, d_beta, d_slip
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_unequal_temperature_mixture(radial, n, class_count, fractions, temperatures, diameters, &
                                                          densities, restitution, pressure, d_pressure_d_fractions, &
                                                          d_pressure_d_temperatures, shear_viscosity, &
                                                          d_shear_viscosity_d_fractions, &
                                                          d_shear_viscosity_d_temperatures, bulk_viscosity, &
                                                          d_bulk_viscosity_d_fractions, &
                                                          d_bulk_viscosity_d_temperatures, conductivity, &
                                                          d_conductivity_d_fractions, d_conductivity_d_temperatures, &
                                                          dissipation, d_dissipation_d_fractions, &
                                                          d_dissipation_d_temperatures, drag, d_drag_d_fractions, &
                                                          d_drag_d_temperatures, segregation, &
                                                          d_segregation_d_fractions, d_segregation_d_temperatures, &
                                                          radial_distribution, d_radial_distribution_d_fractions, &
                                                          d_radial_distribution_d_temperatures, error) &
        bind(C, name='fluidbed_unequal_temperature_mixture_with_derivatives')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      type(c_ptr), value :: radial
      integer(c_size_t), value :: n, class_count
      real(c_double), intent(in) :: fractions(*), temperatures(*), diameters(*), densities(*), restitution(*)
      type(c_ptr), value :: pressure, d_pressure_d_fractions, d_pressure_d_temperatures, shear_viscosity, &
                            d_shear_viscosity_d_fractions, d_shear_viscosity_d_temperatures, bulk_viscosity, &
                            d_bulk_viscosity_d_fractions, d_bulk_viscosity_d_temperatures, conductivity, &
                            d_conductivity_d_fractions, d_conductivity_d_temperatures, dissipation, &
                            d_dissipation_d_fractions, d_dissipation_d_temperatures, drag, d_drag_d_fractions, &
                            d_drag_d_temperatures, segregation, d_segregation_d_fractions, &
                            d_segregation_d_temperatures, radial_distribution, d_radial_distribution_d_fractions, &
                            d_radial_distribution_d_temperatures
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_invert_moments_with_accuracy(node_count, support, n, moments, moment_accuracy, &
                                                           required_accuracy, nodes, weights, sizes, status, &
                                                           node_errors, weight_errors, count_errors, error) &
        bind(C, name='fluidbed_invert_moments_with_accuracy')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      integer(c_int), value :: node_count, support
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: moments(*)
      real(c_double), value :: moment_accuracy, required_accuracy
      real(c_double), intent(out) :: nodes(*), weights(*)
      integer(c_int), intent(out) :: sizes(*), status(*)
      type(c_ptr), value :: node_errors, weight_errors, count_errors
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_moment_realizability(support, moment_count, n, moments, status, realizable_moments, &
                                                   first_failing_index, failing_value, error) &
        bind(C, name='fluidbed_moment_realizability')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      integer(c_int), value :: support, moment_count
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: moments(*)
      integer(c_int), intent(out) :: status(*), realizable_moments(*)
      type(c_ptr), value :: first_failing_index, failing_value
      type(fluidbed_c_error), intent(out) :: error
    end function
    type(fluidbed_correction_options) function c_correction_default_options() &
        bind(C, name='fluidbed_correction_default_options')
      import :: fluidbed_correction_options
    end function
    integer(c_int) function c_dqmom_sources(node_count, n, nodes, weights, moment_sources, weight_sources, &
                                            weighted_node_sources, status, condition, error) &
        bind(C, name='fluidbed_dqmom_sources')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      integer(c_int), value :: node_count
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: nodes(*), weights(*), moment_sources(*)
      real(c_double), intent(out) :: weight_sources(*), weighted_node_sources(*)
      integer(c_int), intent(out) :: status(*)
      type(c_ptr), value :: condition
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_dqmom_growth_diffusion_sources(node_count, weights_kind, n, nodes, weights, growth_rate, &
                                                             diffusion_intensity, weight_sources, &
                                                             weighted_node_sources, status, condition, error) &
        bind(C, name='fluidbed_dqmom_growth_diffusion_sources')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      integer(c_int), value :: node_count, weights_kind
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: nodes(*), weights(*)
      type(c_ptr), value :: growth_rate, diffusion_intensity
      real(c_double), intent(out) :: weight_sources(*), weighted_node_sources(*)
      integer(c_int), intent(out) :: status(*)
      type(c_ptr), value :: condition
      type(fluidbed_c_error), intent(out) :: error
    end function
    integer(c_int) function c_correct_moments(moment_count, n, moments, options, corrected, status, &
                                              realizable_moments, error) bind(C, name='fluidbed_correct_moments')
      import :: c_ptr, c_int, c_size_t, c_double, fluidbed_c_error
      integer(c_int), value :: moment_count
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: moments(*)
      type(c_ptr), value :: options
      real(c_double), intent(out) :: corrected(*)
      integer(c_int), intent(out) :: status(*)
      type(c_ptr), value :: realizable_moments
      type(fluidbed_c_error), intent(out) :: error
    end function
  end interface

contains

  ! A Fortran string as a terminated C string.
  pure function c_string(text) result(c)
    character(len=*), intent(in) :: text
    character(kind=c_char) :: c(len_trim(text) + 1)
    integer :: i
    do i = 1, len_trim(text)
      c(i) = text(i:i)
    end do
    c(len_trim(text) + 1) = c_null_char
  end function

  ! A C string the library returns as a Fortran string ('' for NULL).
  function string_of(address) result(text)
    type(c_ptr), intent(in) :: address
    character(len=:), allocatable :: text
    character(kind=c_char), pointer :: chars(:)
    integer :: n, i
    n = 0
    if (c_associated(address)) n = int(c_strlen(address))
    allocate(character(len=n) :: text)
    if (n == 0) return
    call c_f_pointer(address, chars, [n])
    do i = 1, n
      text(i:i) = chars(i)
    end do
  end function

  ! The error's message as a Fortran string (each wrapper assigns it to its own optional
  ! `message` itself: gfortran 12 loses the length of a deferred-length optional passed on).
  function message_of(error) result(text)
    type(fluidbed_c_error), intent(in) :: error
    character(len=:), allocatable :: text
    integer :: n, i
    n = 0
    do while (n < message_size)
      if (error%message(n + 1) == c_null_char) exit
      n = n + 1
    end do
    allocate(character(len=n) :: text)
    do i = 1, n
      text(i:i) = error%message(i)
    end do
  end function

  ! ---- Statuses, families, the catalogue ---------------------------------------------------

  ! The status's name ('FLUIDBED_DOMAIN_ERROR').
  function fluidbed_status_name(status) result(name)
    integer, intent(in) :: status
    character(len=:), allocatable :: name
    name = string_of(c_status_name(int(status, c_int)))
  end function

  ! What a family's closures are ('drag law'), and their convention (quantity, units, sign,
  ! arguments); '' for a value that is not a family.
  function fluidbed_family_what(family) result(text)
    integer, intent(in) :: family
    character(len=:), allocatable :: text
    text = string_of(c_family_what(int(family, c_int)))
  end function

  function fluidbed_family_convention(family) result(text)
    integer, intent(in) :: family
    character(len=:), allocatable :: text
    text = string_of(c_family_convention(int(family, c_int)))
  end function

  ! The closures of the library, presets included: their number, and the index-th name
  ! (1-based; '' beyond the last).
  integer function fluidbed_closure_count() result(count)
    count = int(c_closure_count())
  end function

  function fluidbed_closure_name_at(index) result(name)
    integer, intent(in) :: index
    character(len=:), allocatable :: name
    name = string_of(c_closure_name_at(int(index - 1, c_size_t)))
  end function

  ! ---- Closures ------------------------------------------------------------------------------

  ! The closure called `name` (the C++ registries' run-time names).
  integer function fluidbed_create(name, closure, message) result(status)
    character(len=*), intent(in) :: name
    type(fluidbed_closure), intent(out) :: closure
    character(len=:), allocatable, intent(out), optional :: message
    type(fluidbed_c_error) :: error
    status = c_create(c_string(name), closure%handle, error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
  end function

  ! A copy of `closure`, its parameters included (a null handle where out of memory); to be
  ! destroyed as well.
  function fluidbed_copy(closure) result(copy)
    type(fluidbed_closure), intent(in) :: closure
    type(fluidbed_closure) :: copy
    copy%handle = c_copy(closure%handle)
  end function

  subroutine fluidbed_destroy(closure)
    type(fluidbed_closure), intent(inout) :: closure
    if (c_associated(closure%handle)) call c_destroy(closure%handle)
    closure%handle = c_null_ptr
  end subroutine

  ! The closure's family (FLUIDBED_FAMILY_DRAG_LAW, ...).
  integer function fluidbed_family(closure) result(family)
    type(fluidbed_closure), intent(in) :: closure
    family = int(c_family(closure%handle))
  end function

  function fluidbed_name(closure) result(name)
    type(fluidbed_closure), intent(in) :: closure
    character(len=:), allocatable :: name
    name = string_of(c_name(closure%handle))
  end function

  ! Its reference (authors, year, journal, DOI).
  function fluidbed_reference(closure) result(reference)
    type(fluidbed_closure), intent(in) :: closure
    character(len=:), allocatable :: reference
    reference = string_of(c_reference(closure%handle))
  end function

  ! The ranges the closure was fitted or derived for: their number, and the index-th (1-based)
  ! quantity and bounds (FLUIDBED_INVALID_ARGUMENT beyond the last).
  integer function fluidbed_validity_count(closure) result(count)
    type(fluidbed_closure), intent(in) :: closure
    count = int(c_validity_count(closure%handle))
  end function

  integer function fluidbed_validity(closure, index, quantity, minimum, maximum, message) result(status)
    type(fluidbed_closure), intent(in) :: closure
    integer, intent(in) :: index
    character(len=:), allocatable, intent(out) :: quantity
    real(c_double), intent(out) :: minimum, maximum
    character(len=:), allocatable, intent(out), optional :: message
    type(fluidbed_c_error) :: error
    type(c_ptr) :: name
    name = c_null_ptr
    minimum = 0
    maximum = 0
    status = c_validity(closure%handle, int(index - 1, c_size_t), name, minimum, maximum, error)
    status = int(error%status)
    quantity = string_of(name)
    if (present(message)) message = message_of(error)
  end function

  ! The closure's parameters (snake_case, angles in radians): their number, the index-th name
  ! (1-based; '' beyond the last).
  integer function fluidbed_parameter_count(closure) result(count)
    type(fluidbed_closure), intent(in) :: closure
    count = int(c_parameter_count(closure%handle))
  end function

  function fluidbed_parameter_name(closure, index) result(name)
    type(fluidbed_closure), intent(in) :: closure
    integer, intent(in) :: index
    character(len=:), allocatable :: name
    name = string_of(c_parameter_name(closure%handle, int(index - 1, c_size_t)))
  end function

  ! Sets the closure's parameter `name` (snake_case, angles in radians), validated at once.
  integer function fluidbed_set_parameter(closure, name, value, message) result(status)
    type(fluidbed_closure), intent(inout) :: closure
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    character(len=:), allocatable, intent(out), optional :: message
    type(fluidbed_c_error) :: error
    status = c_set_parameter(closure%handle, c_string(name), value, error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
  end function

  integer function fluidbed_get_parameter(closure, name, value, message) result(status)
    type(fluidbed_closure), intent(in) :: closure
    character(len=*), intent(in) :: name
    real(c_double), intent(out) :: value
    character(len=:), allocatable, intent(out), optional :: message
    type(fluidbed_c_error) :: error
    status = c_get_parameter(closure%handle, c_string(name), value, error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
  end function

  ! ---- Evaluations over cells (fluidbed_c.h has each function's full definition) -------------

  ! β [kg m^-3 s^-1] of a drag law in `convention` over the cells (voidage ε, slip |u_f − v_p|
  ! [m/s], fluid density [kg/m^3] and viscosity [Pa s], particle diameter [m]); optionally
  ! ∂β/∂ε, ∂β/∂w and ∂(βw)/∂w. Every array the size of voidage.
  integer function fluidbed_drag(law, convention, voidage, slip, density, viscosity, diameter, beta, &
                                 d_voidage, d_slip, d_force_d_slip, message, cell) result(status)
    type(fluidbed_closure), intent(in) :: law
    integer, intent(in) :: convention
    real(c_double), intent(in), contiguous, target :: voidage(:), slip(:), density(:), viscosity(:), diameter(:)
    real(c_double), intent(out), contiguous, target :: beta(:)
    real(c_double), intent(out), contiguous, target, optional :: d_voidage(:), d_slip(:), d_force_d_slip(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(voidage)
    if (sizes_agree(error, 'fluidbed_drag', 'voidage', [size(slip), size(density), size(viscosity), size(diameter), &
                    size(beta), optional_size(d_voidage, n), optional_size(d_slip, n), &
                    optional_size(d_force_d_slip, n)], n)) &
      status = fluidbed_c_drag(law%handle, int(convention, c_int), int(n, c_size_t), voidage, slip, density, &
                               viscosity, diameter, beta, optional_array(d_voidage), optional_array(d_slip), &
                               optional_array(d_force_d_slip), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_SPHERE_DRAG_COEFFICIENT: C_D·Re of one sphere at Re >= 0, optionally
  ! d(C_D·Re)/dRe.
  integer function fluidbed_sphere_drag_coefficient(law, reynolds, cd_re, d_reynolds, message, cell) result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: reynolds(:)
    real(c_double), intent(out), contiguous, target :: cd_re(:)
    real(c_double), intent(out), contiguous, target, optional :: d_reynolds(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(reynolds)
    if (sizes_agree(error, 'fluidbed_sphere_drag_coefficient', 'reynolds', &
                    [size(cd_re), optional_size(d_reynolds, n)], n)) &
      status = c_sphere_drag_coefficient(law%handle, int(n, c_size_t), reynolds, cd_re, optional_array(d_reynolds), &
                                         error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_TERMINAL_VELOCITY, FLUIDBED_FAMILY_MINIMUM_FLUIDIZATION: Re_t or Re_mf at
  ! Ar >= 0, optionally dRe/dAr.
  integer function fluidbed_reynolds_of_archimedes(law, archimedes, reynolds, d_archimedes, message, cell) &
      result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: archimedes(:)
    real(c_double), intent(out), contiguous, target :: reynolds(:)
    real(c_double), intent(out), contiguous, target, optional :: d_archimedes(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(archimedes)
    if (sizes_agree(error, 'fluidbed_reynolds_of_archimedes', 'archimedes', &
                    [size(reynolds), optional_size(d_archimedes, n)], n)) &
      status = c_reynolds_of_archimedes(law%handle, int(n, c_size_t), archimedes, reynolds, &
                                        optional_array(d_archimedes), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_RICHARDSON_ZAKI_EXPONENT: n at Re_t or Ar (fluidbed_richardson_zaki_argument
  ! says which), optionally dn/d(argument).
  integer function fluidbed_richardson_zaki_exponent(law, argument, exponent, d_argument, message, cell) &
      result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: argument(:)
    real(c_double), intent(out), contiguous, target :: exponent(:)
    real(c_double), intent(out), contiguous, target, optional :: d_argument(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(argument)
    if (sizes_agree(error, 'fluidbed_richardson_zaki_exponent', 'argument', &
                    [size(exponent), optional_size(d_argument, n)], n)) &
      status = c_richardson_zaki_exponent(law%handle, int(n, c_size_t), argument, exponent, &
                                          optional_array(d_argument), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! 'terminal_reynolds' or 'archimedes'; '' for a closure of another family.
  function fluidbed_richardson_zaki_argument(law) result(argument)
    type(fluidbed_closure), intent(in) :: law
    character(len=:), allocatable :: argument
    argument = string_of(c_richardson_zaki_argument(law%handle))
  end function

  ! FLUIDBED_FAMILY_ELASTIC_MODULUS: E^e [Pa] of a homogeneous bed at equilibrium (ε, fluid density
  ! [kg/m^3] and viscosity [Pa s], particle density [kg/m^3] and diameter [m], Re_t, gravity
  ! [m/s^2]), optionally ∂E^e/∂ε.
  integer function fluidbed_elastic_modulus_at_equilibrium(model, voidage, fluid_density, fluid_viscosity, &
                                                           particle_density, diameter, terminal_reynolds, gravity, &
                                                           modulus, d_voidage, message, cell) result(status)
    type(fluidbed_closure), intent(in) :: model
    real(c_double), intent(in), contiguous, target :: voidage(:), fluid_density(:), fluid_viscosity(:), &
                                                      particle_density(:), diameter(:), terminal_reynolds(:), &
                                                      gravity(:)
    real(c_double), intent(out), contiguous, target :: modulus(:)
    real(c_double), intent(out), contiguous, target, optional :: d_voidage(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(voidage)
    if (sizes_agree(error, 'fluidbed_elastic_modulus_at_equilibrium', 'voidage', &
                    [size(fluid_density), size(fluid_viscosity), size(particle_density), size(diameter), &
                     size(terminal_reynolds), size(gravity), size(modulus), optional_size(d_voidage, n)], n)) &
      status = c_elastic_modulus_at_equilibrium(model%handle, int(n, c_size_t), voidage, fluid_density, &
                                                fluid_viscosity, particle_density, diameter, terminal_reynolds, &
                                                gravity, modulus, optional_array(d_voidage), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! E [Pa] off equilibrium at the drag state (ε, w, ρ_f, μ_f, d) of fluidbed_drag, for the models
  ! that define one; optionally ∂E/∂ε and ∂E/∂w.
  integer function fluidbed_elastic_modulus_at_state(model, voidage, slip, fluid_density, fluid_viscosity, diameter, &
                                                     modulus, d_voidage, d_slip, message, cell) result(status)
    type(fluidbed_closure), intent(in) :: model
    real(c_double), intent(in), contiguous, target :: voidage(:), slip(:), fluid_density(:), fluid_viscosity(:), &
                                                      diameter(:)
    real(c_double), intent(out), contiguous, target :: modulus(:)
    real(c_double), intent(out), contiguous, target, optional :: d_voidage(:), d_slip(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(voidage)
    if (sizes_agree(error, 'fluidbed_elastic_modulus_at_state', 'voidage', &
                    [size(slip), size(fluid_density), size(fluid_viscosity), size(diameter), size(modulus), &
                     optional_size(d_voidage, n), optional_size(d_slip, n)], n)) &
      status = c_elastic_modulus_at_state(model%handle, int(n, c_size_t), voidage, slip, fluid_density, &
                                          fluid_viscosity, diameter, modulus, optional_array(d_voidage), &
                                          optional_array(d_slip), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_RADIAL_DISTRIBUTION (g0) and FLUIDBED_FAMILY_FRICTIONAL_PRESSURE (p_f [Pa]) at
  ! the solids volume fraction φ ∈ [0, 1); optionally d/dφ.
  integer function fluidbed_of_solid_fraction(law, solid_fraction, value, d_solid_fraction, message, cell) &
      result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: solid_fraction(:)
    real(c_double), intent(out), contiguous, target :: value(:)
    real(c_double), intent(out), contiguous, target, optional :: d_solid_fraction(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(solid_fraction)
    if (sizes_agree(error, 'fluidbed_of_solid_fraction', 'solid_fraction', &
                    [size(value), optional_size(d_solid_fraction, n)], n)) &
      status = c_of_solid_fraction(law%handle, int(n, c_size_t), solid_fraction, value, &
                                   optional_array(d_solid_fraction), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_GRANULAR_PRESSURE [Pa], _SHEAR_VISCOSITY, _BULK_VISCOSITY [Pa s], _CONDUCTIVITY
  ! [kg m^-1 s^-1], _DISSIPATION [W m^-3], per unit volume of suspension: law(φ, Θ [m^2 s^-2],
  ! g0(φ) of the FLUIDBED_FAMILY_RADIAL_DISTRIBUTION `radial`, material {d [m], ρ_s [kg m^-3], e});
  ! optionally ∂/∂φ (through g0) and ∂/∂Θ.
  integer function fluidbed_constitutive(law, radial, solid_fraction, granular_temperature, diameter, solid_density, &
                                         restitution, value, d_solid_fraction, d_granular_temperature, message, &
                                         cell) result(status)
    type(fluidbed_closure), intent(in) :: law, radial
    real(c_double), intent(in), contiguous, target :: solid_fraction(:), granular_temperature(:), diameter(:), &
                                                      solid_density(:), restitution(:)
    real(c_double), intent(out), contiguous, target :: value(:)
    real(c_double), intent(out), contiguous, target, optional :: d_solid_fraction(:), d_granular_temperature(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(solid_fraction)
    if (sizes_agree(error, 'fluidbed_constitutive', 'solid_fraction', &
                    [size(granular_temperature), size(diameter), size(solid_density), size(restitution), &
                     size(value), optional_size(d_solid_fraction, n), optional_size(d_granular_temperature, n)], n)) &
      status = c_constitutive(law%handle, radial%handle, int(n, c_size_t), solid_fraction, granular_temperature, &
                              diameter, solid_density, restitution, value, optional_array(d_solid_fraction), &
                              optional_array(d_granular_temperature), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_FRICTIONAL_VISCOSITY: μ_f [Pa s] at p_f >= 0 [Pa], ∇·u [s^-1] and
  ! D':D' >= 0 [s^-2]; optionally ∂μ_f/∂p_f.
  integer function fluidbed_frictional_viscosity(law, frictional_pressure, divergence, contraction, viscosity, &
                                                 d_frictional_pressure, message, cell) result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: frictional_pressure(:), divergence(:), contraction(:)
    real(c_double), intent(out), contiguous, target :: viscosity(:)
    real(c_double), intent(out), contiguous, target, optional :: d_frictional_pressure(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(frictional_pressure)
    if (sizes_agree(error, 'fluidbed_frictional_viscosity', 'frictional_pressure', &
                    [size(divergence), size(contraction), size(viscosity), optional_size(d_frictional_pressure, n)], &
                    n)) &
      status = c_frictional_viscosity(law%handle, int(n, c_size_t), frictional_pressure, divergence, contraction, &
                                      viscosity, optional_array(d_frictional_pressure), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_FRICTIONAL_STRESS: p_f [Pa] and μ_f [Pa s] of (φ, Θ, d, ∇·u, D':D');
  ! optionally ∂p_f/∂φ and ∂μ_f/∂φ.
  integer function fluidbed_frictional_stress(law, solid_fraction, granular_temperature, diameter, divergence, &
                                              contraction, pressure, viscosity, d_pressure, d_viscosity, message, &
                                              cell) result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: solid_fraction(:), granular_temperature(:), diameter(:), &
                                                      divergence(:), contraction(:)
    real(c_double), intent(out), contiguous, target :: pressure(:), viscosity(:)
    real(c_double), intent(out), contiguous, target, optional :: d_pressure(:), d_viscosity(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(solid_fraction)
    if (sizes_agree(error, 'fluidbed_frictional_stress', 'solid_fraction', &
                    [size(granular_temperature), size(diameter), size(divergence), size(contraction), &
                     size(pressure), size(viscosity), optional_size(d_pressure, n), optional_size(d_viscosity, n)], &
                    n)) &
      status = c_frictional_stress(law%handle, int(n, c_size_t), solid_fraction, granular_temperature, diameter, &
                                   divergence, contraction, pressure, viscosity, optional_array(d_pressure), &
                                   optional_array(d_viscosity), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_MIXTURE_RADIAL_DISTRIBUTION: value(c) = g_ik between classes i and k (1-based here;
  ! passed to C as i − 1, k − 1) of cell c, whose class m has the fraction fractions(c, m) >= 0
  ! (Σ < 1) and the diameter diameters(c, m) > 0 [m]; shapes (cells, classes), 1 to
  ! FLUIDBED_MAX_CLASSES classes; optionally d_fractions(c, m) = ∂g_ik/∂φ_m.
  integer function fluidbed_mixture_radial_distribution(law, i, k, fractions, diameters, value, d_fractions, &
                                                        message, cell) result(status)
    type(fluidbed_closure), intent(in) :: law
    integer, intent(in) :: i, k
    real(c_double), intent(in), contiguous, target :: fractions(:, :), diameters(:, :)
    real(c_double), intent(out), contiguous, target :: value(:)
    real(c_double), intent(out), contiguous, target, optional :: d_fractions(:, :)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n, classes
    n = size(fractions, 1)
    classes = size(fractions, 2)
    if (sizes_agree(error, 'fluidbed_mixture_radial_distribution', 'fractions', &
                    [shape(diameters), size(value), optional_shape(d_fractions, [n, classes])], &
                    [n, classes, n, n, classes])) &
      status = c_mixture_radial_distribution(law%handle, int(n, c_size_t), int(classes, c_size_t), &
                                             int(i - 1, c_size_t), int(k - 1, c_size_t), fractions, diameters, &
                                             value, optional_matrix(d_fractions), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_SOLID_SOLID_DRAG: K_pq [kg m^-3 s^-1] between classes p and q (force on p
  ! K_pq (v_q − v_p)) at φ_p, φ_q, their densities [kg m^-3] and diameters [m], the restitution,
  ! g_pq (fluidbed_mixture_radial_distribution) and |v_p − v_q| [m/s]; optionally its
  ! derivatives in φ_p, φ_q, g_pq and |v_p − v_q|.
  integer function fluidbed_solid_solid_drag(law, phi_p, phi_q, density_p, diameter_p, density_q, diameter_q, &
                                             restitution, contact_rdf, relative_speed, coefficient, d_phi_p, &
                                             d_phi_q, d_contact_rdf, d_relative_speed, message, cell) result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: phi_p(:), phi_q(:), density_p(:), diameter_p(:), &
                                                      density_q(:), diameter_q(:), restitution(:), contact_rdf(:), &
                                                      relative_speed(:)
    real(c_double), intent(out), contiguous, target :: coefficient(:)
    real(c_double), intent(out), contiguous, target, optional :: d_phi_p(:), d_phi_q(:), d_contact_rdf(:), &
                                                                 d_relative_speed(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(phi_p)
    if (sizes_agree(error, 'fluidbed_solid_solid_drag', 'phi_p', &
                    [size(phi_q), size(density_p), size(diameter_p), size(density_q), size(diameter_q), &
                     size(restitution), size(contact_rdf), size(relative_speed), size(coefficient), &
                     optional_size(d_phi_p, n), optional_size(d_phi_q, n), optional_size(d_contact_rdf, n), &
                     optional_size(d_relative_speed, n)], n)) &
      status = c_solid_solid_drag(law%handle, int(n, c_size_t), phi_p, phi_q, density_p, diameter_p, density_q, &
                                  diameter_q, restitution, contact_rdf, relative_speed, coefficient, &
                                  optional_array(d_phi_p), optional_array(d_phi_q), optional_array(d_contact_rdf), &
                                  optional_array(d_relative_speed), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! FLUIDBED_FAMILY_GAS_EXCHANGE_SOURCE: the gas's production of granular energy [W m^-3] at φ, Θ
  ! [m^2 s^-2], the slip |u_g − u_s| [m/s] and the material {d [m], ρ_s [kg m^-3], e}; optionally
  ! ∂/∂φ, ∂/∂Θ, ∂/∂β, ∂/∂w. KochSanganiSource reads `radial` and gas_viscosity [Pa s],
  ! DragFluctuationSource beta [kg m^-3 s^-1]: each may be absent where the source does not.
  integer function fluidbed_gas_exchange_source(law, solid_fraction, granular_temperature, slip, diameter, &
                                                solid_density, restitution, source, d_solid_fraction, &
                                                d_granular_temperature, d_beta, d_slip, radial, beta, gas_viscosity, &
                                                message, cell) result(status)
    type(fluidbed_closure), intent(in) :: law
    real(c_double), intent(in), contiguous, target :: solid_fraction(:), granular_temperature(:), slip(:), &
                                                      diameter(:), solid_density(:), restitution(:)
    real(c_double), intent(out), contiguous, target :: source(:)
    real(c_double), intent(out), contiguous, target, optional :: d_solid_fraction(:), d_granular_temperature(:), &
                                                                 d_beta(:), d_slip(:)
    type(fluidbed_closure), intent(in), optional :: radial
    real(c_double), intent(in), contiguous, target, optional :: beta(:), gas_viscosity(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    type(c_ptr) :: radial_handle
    integer :: n
    n = size(solid_fraction)
    radial_handle = c_null_ptr
    if (present(radial)) radial_handle = radial%handle
    if (sizes_agree(error, 'fluidbed_gas_exchange_source', 'solid_fraction', &
                    [size(granular_temperature), size(slip), size(diameter), size(solid_density), size(restitution), &
                     size(source), optional_size(d_solid_fraction, n), optional_size(d_granular_temperature, n), &
                     optional_size(d_beta, n), optional_size(d_slip, n), optional_size(beta, n), &
                     optional_size(gas_viscosity, n)], n)) &
      status = c_gas_exchange_source(law%handle, radial_handle, int(n, c_size_t), solid_fraction, &
                                     granular_temperature, slip, optional_array(beta), &
                                     optional_array(gas_viscosity), diameter, solid_density, restitution, source, &
                                     optional_array(d_solid_fraction), optional_array(d_granular_temperature), &
                                     optional_array(d_beta), optional_array(d_slip), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! ---- Moments (fields shaped (cells, count): moments(c, k + 1) = m_k of cell c) ------------

  ! node_count-node Gauss rules (1 to FLUIDBED_MAX_NODES) of the cells' 2 node_count moments
  ! (moments shaped (cells, 2 node_count)) on `support`: nodes(c, i) ascending, weights(c, i) (0
  ! beyond sizes(c)), shaped (cells, node_count), and each cell's status(c)
  ! (FLUIDBED_INVERSION_*); a cell that cannot be inverted is a status, not an error.
  ! The error estimate (fluidbed_invert_moments_with_accuracy), optional: moment_accuracy, the
  ! relative accuracy of each moment (absent: 0, exact as given); required_accuracy (absent: 0,
  ! none), a rule whose estimate exceeds it has the status FLUIDBED_INVERSION_INACCURATE (the rule
  ! still returned); node_errors(c) and weight_errors(c), each cell's estimated largest relative
  ! node error (to the node on [0, ∞), to the largest |node| on the real line) and weight error
  ! (−1: no rule); count_errors(c), the largest error, relative to its threshold, of the
  ! realizability decisions that set the cell's node count (>= 1: the count lies within the error;
  ! −1: no rule). Accuracies must be finite and >= 0 (FLUIDBED_DOMAIN_ERROR).
  integer function fluidbed_invert_moments(node_count, support, moments, nodes, weights, sizes, status, message, &
                                           cell, moment_accuracy, required_accuracy, node_errors, weight_errors, &
                                           count_errors) result(code)
    integer, intent(in) :: node_count, support
    real(c_double), intent(in), contiguous, target :: moments(:, :)
    real(c_double), intent(out), contiguous, target :: nodes(:, :), weights(:, :)
    integer(c_int), intent(out), contiguous, target :: sizes(:), status(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    real(c_double), intent(in), optional :: moment_accuracy, required_accuracy
    real(c_double), intent(out), contiguous, target, optional :: node_errors(:), weight_errors(:), &
                                                                 count_errors(:)
    type(fluidbed_c_error) :: error
    real(c_double) :: accuracy_of_moments, required
    integer :: n
    n = size(moments, 1)
    accuracy_of_moments = 0
    if (present(moment_accuracy)) accuracy_of_moments = moment_accuracy
    required = 0
    if (present(required_accuracy)) required = required_accuracy
    if (sizes_agree(error, 'fluidbed_invert_moments', 'moments', &
                    [size(moments, 2), shape(nodes), shape(weights), size(sizes), size(status), &
                     optional_size(node_errors, n), optional_size(weight_errors, n), &
                     optional_size(count_errors, n)], &
                    [2 * node_count, n, node_count, n, node_count, n, n, n, n, n])) &
      code = c_invert_moments_with_accuracy(int(node_count, c_int), int(support, c_int), int(n, c_size_t), moments, &
                                            accuracy_of_moments, required, nodes, weights, sizes, status, &
                                            optional_array(node_errors), optional_array(weight_errors), &
                                            optional_array(count_errors), error)
    code = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! The realizability of the cells' moment sets m_0 … m_{count−1} (moments shaped (cells, count),
  ! count 1 to 2 FLUIDBED_MAX_NODES) on `support`: status(c) (FLUIDBED_INVERSION_OK, or _REDUCED
  ! when only a prefix is realizable) and the prefix's length realizable_moments(c); optionally
  ! the first failing coefficient's index (0: none) and value (caller's units).
  integer function fluidbed_moment_realizability(support, moments, status, realizable_moments, first_failing_index, &
                                                 failing_value, message, cell) result(code)
    integer, intent(in) :: support
    real(c_double), intent(in), contiguous, target :: moments(:, :)
    integer(c_int), intent(out), contiguous, target :: status(:), realizable_moments(:)
    integer(c_int), intent(out), contiguous, target, optional :: first_failing_index(:)
    real(c_double), intent(out), contiguous, target, optional :: failing_value(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n
    n = size(moments, 1)
    if (sizes_agree(error, 'fluidbed_moment_realizability', 'moments', &
                    [size(status), size(realizable_moments), optional_int_size(first_failing_index, n), &
                     optional_size(failing_value, n)], n)) &
      code = c_moment_realizability(int(support, c_int), int(size(moments, 2), c_int), int(n, c_size_t), moments, &
                                    status, realizable_moments, optional_int_array(first_failing_index), &
                                    optional_array(failing_value), error)
    code = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! The library's correction options: 1, 20, the cube root of double's epsilon.
  function fluidbed_correction_default_options() result(options)
    type(fluidbed_correction_options) :: options
    options = c_correction_default_options()
  end function

  ! The cells' size moment sets on [0, ∞) (moments shaped (cells, count), count 1 to
  ! 2 FLUIDBED_MAX_NODES) made realizable: McGraw's iterations, the log-normal fallback.
  ! corrected (the shape of moments; another array), status(c) (FLUIDBED_CORRECTION_*),
  ! optionally realizable_moments(c) of the returned set; options absent: the defaults.
  integer function fluidbed_correct_moments(moments, corrected, status, realizable_moments, options, message, cell) &
      result(code)
    real(c_double), intent(in), contiguous, target :: moments(:, :)
    real(c_double), intent(out), contiguous, target :: corrected(:, :)
    integer(c_int), intent(out), contiguous, target :: status(:)
    integer(c_int), intent(out), contiguous, target, optional :: realizable_moments(:)
    type(fluidbed_correction_options), intent(in), target, optional :: options
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    type(c_ptr) :: options_address
    integer :: n
    n = size(moments, 1)
    options_address = c_null_ptr
    if (present(options)) options_address = c_loc(options)
    if (sizes_agree(error, 'fluidbed_correct_moments', 'moments', &
                    [shape(corrected), size(status), optional_int_size(realizable_moments, n)], &
                    [n, size(moments, 2), n, n])) &
      code = c_correct_moments(int(size(moments, 2), c_int), int(n, c_size_t), moments, options_address, corrected, &
                               status, optional_int_array(realizable_moments), error)
    code = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! DQMOM source terms of the cells' nodes and weights (shaped (cells, N), N 1 to FLUIDBED_MAX_NODES)
  ! for moment sources (cells, 2N), moments k = 0 … 2N − 1: weight_sources (c^a) and
  ! weighted_node_sources (c^ξ), (cells, N), status(c) (FLUIDBED_DQMOM_*) and optionally the
  ! condition number of each cell's system.
  integer function fluidbed_dqmom_sources(nodes, weights, moment_sources, weight_sources, weighted_node_sources, &
                                          status, condition, message, cell) result(code)
    real(c_double), intent(in), contiguous, target :: nodes(:, :), weights(:, :), moment_sources(:, :)
    real(c_double), intent(out), contiguous, target :: weight_sources(:, :), weighted_node_sources(:, :)
    integer(c_int), intent(out), contiguous, target :: status(:)
    real(c_double), intent(out), contiguous, target, optional :: condition(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n, count
    n = size(nodes, 1)
    count = size(nodes, 2)
    if (sizes_agree(error, 'fluidbed_dqmom_sources', 'nodes', &
                    [shape(weights), shape(moment_sources), shape(weight_sources), shape(weighted_node_sources), &
                     size(status), optional_size(condition, n)], &
                    [n, count, n, 2 * count, n, count, n, count, n, n])) &
      code = c_dqmom_sources(int(count, c_int), int(n, c_size_t), nodes, weights, moment_sources, weight_sources, &
                             weighted_node_sources, status, optional_array(condition), error)
    code = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! DQMOM source terms of growth (growth_rate, m/s) and of diffusion (diffusion_intensity,
  ! 𝒞 = 𝒟 φ |∇ξ|²), each optional and shaped (cells, N) like the nodes, solved as point functionals;
  ! weights_kind FLUIDBED_DQMOM_VOLUME_FRACTION or FLUIDBED_DQMOM_NUMBER_DENSITY. Outputs as
  ! fluidbed_dqmom_sources.
  integer function fluidbed_dqmom_growth_diffusion_sources(weights_kind, nodes, weights, weight_sources, &
                                                           weighted_node_sources, status, growth_rate, &
                                                           diffusion_intensity, condition, message, cell) result(code)
    integer, intent(in) :: weights_kind
    real(c_double), intent(in), contiguous, target :: nodes(:, :), weights(:, :)
    real(c_double), intent(out), contiguous, target :: weight_sources(:, :), weighted_node_sources(:, :)
    integer(c_int), intent(out), contiguous, target :: status(:)
    real(c_double), intent(in), contiguous, target, optional :: growth_rate(:, :), diffusion_intensity(:, :)
    real(c_double), intent(out), contiguous, target, optional :: condition(:)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n, count
    n = size(nodes, 1)
    count = size(nodes, 2)
    if (sizes_agree(error, 'fluidbed_dqmom_growth_diffusion_sources', 'nodes', &
                    [shape(weights), shape(weight_sources), shape(weighted_node_sources), size(status), &
                     optional_shape(growth_rate, [n, count]), optional_shape(diffusion_intensity, [n, count]), &
                     optional_size(condition, n)], &
                    [n, count, n, count, n, count, n, n, count, n, count, n])) &
      code = c_dqmom_growth_diffusion_sources(int(count, c_int), int(weights_kind, c_int), int(n, c_size_t), nodes, &
                                              weights, optional_matrix(growth_rate), &
                                              optional_matrix(diffusion_intensity), weight_sources, &
                                              weighted_node_sources, status, optional_array(condition), error)
    code = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! The kinetic theory of classes with their own granular temperatures (Lathouwers & Bellan 2001;
  ! fluidbed_unequal_temperature_mixture_with_derivatives), h_ik the mixture radial distribution
  ! `radial` (FLUIDBED_FAMILY_MIXTURE_RADIAL_DISTRIBUTION, with its parameters). Class m of cell c
  ! has fractions(c, m) = α_m >= 0 (Σ < 1), temperatures(c, m) = Θ_m > 0 [m^2 s^-2],
  ! diameters(c, m) [m] and densities(c, m) [kg m^-3], shapes (cells, classes), 1 to
  ! FLUIDBED_MAX_CLASSES classes; every pair of cell c has the restitution restitution(c). Every
  ! output is optional (absent: not computed), per unit volume of suspension: pressure (p_i [Pa])
  ! and dissipation (γ_i [W m^-3], a sink) shaped (cells, classes), element (c, i); the matrices
  ! shear_viscosity (μ_ik [Pa s]), bulk_viscosity (λ_ik), conductivity (κ_ik [kg m^-1 s^-1]), drag
  ! (β_ik [kg m^-3 s^-1]), segregation (s_ik [Pa]) and radial_distribution (h_ik) shaped
  ! (cells, classes, classes) with element (c, k, i) = X_ik (C's row-major layout: the class i whose
  ! quantity it is comes last); d_<X>_d_fractions and d_<X>_d_temperatures have X's shape with one
  ! more last dimension, the class m: ∂X/∂α_m and ∂X/∂Θ_m.
  integer function fluidbed_unequal_temperature_mixture(radial, fractions, temperatures, diameters, densities, &
                                                        restitution, pressure, shear_viscosity, bulk_viscosity, &
                                                        conductivity, dissipation, drag, segregation, &
                                                        radial_distribution, d_pressure_d_fractions, &
                                                        d_pressure_d_temperatures, d_shear_viscosity_d_fractions, &
                                                        d_shear_viscosity_d_temperatures, &
                                                        d_bulk_viscosity_d_fractions, &
                                                        d_bulk_viscosity_d_temperatures, d_conductivity_d_fractions, &
                                                        d_conductivity_d_temperatures, d_dissipation_d_fractions, &
                                                        d_dissipation_d_temperatures, d_drag_d_fractions, &
                                                        d_drag_d_temperatures, d_segregation_d_fractions, &
                                                        d_segregation_d_temperatures, &
                                                        d_radial_distribution_d_fractions, &
                                                        d_radial_distribution_d_temperatures, message, cell) &
      result(status)
    type(fluidbed_closure), intent(in) :: radial
    real(c_double), intent(in), contiguous, target :: fractions(:, :), temperatures(:, :), diameters(:, :), &
                                                      densities(:, :), restitution(:)
    real(c_double), intent(out), contiguous, target, optional :: pressure(:, :), dissipation(:, :), &
                                                                 shear_viscosity(:, :, :), bulk_viscosity(:, :, :), &
                                                                 conductivity(:, :, :), drag(:, :, :), &
                                                                 segregation(:, :, :), radial_distribution(:, :, :)
    real(c_double), intent(out), contiguous, target, optional :: &
      d_pressure_d_fractions(:, :, :), d_pressure_d_temperatures(:, :, :), d_dissipation_d_fractions(:, :, :), &
      d_dissipation_d_temperatures(:, :, :)
    real(c_double), intent(out), contiguous, target, optional :: &
      d_shear_viscosity_d_fractions(:, :, :, :), d_shear_viscosity_d_temperatures(:, :, :, :), &
      d_bulk_viscosity_d_fractions(:, :, :, :), d_bulk_viscosity_d_temperatures(:, :, :, :), &
      d_conductivity_d_fractions(:, :, :, :), d_conductivity_d_temperatures(:, :, :, :), &
      d_drag_d_fractions(:, :, :, :), d_drag_d_temperatures(:, :, :, :), d_segregation_d_fractions(:, :, :, :), &
      d_segregation_d_temperatures(:, :, :, :), d_radial_distribution_d_fractions(:, :, :, :), &
      d_radial_distribution_d_temperatures(:, :, :, :)
    character(len=:), allocatable, intent(out), optional :: message
    integer, intent(out), optional :: cell
    type(fluidbed_c_error) :: error
    integer :: n, classes, j, per_class(2), matrix(3), per_class_slopes(3), matrix_slopes(4)
    n = size(fractions, 1)
    classes = size(fractions, 2)
    per_class = [n, classes]
    matrix = [n, classes, classes]
    per_class_slopes = [n, classes, classes]
    matrix_slopes = [n, classes, classes, classes]
    if (sizes_agree(error, 'fluidbed_unequal_temperature_mixture', 'fractions', &
                    [shape(temperatures), shape(diameters), shape(densities), size(restitution), &
                     optional_shape(pressure, per_class), optional_shape(dissipation, per_class), &
                     optional_shape3(shear_viscosity, matrix), optional_shape3(bulk_viscosity, matrix), &
                     optional_shape3(conductivity, matrix), optional_shape3(drag, matrix), &
                     optional_shape3(segregation, matrix), optional_shape3(radial_distribution, matrix), &
                     optional_shape3(d_pressure_d_fractions, per_class_slopes), &
                     optional_shape3(d_pressure_d_temperatures, per_class_slopes), &
                     optional_shape3(d_dissipation_d_fractions, per_class_slopes), &
                     optional_shape3(d_dissipation_d_temperatures, per_class_slopes), &
                     optional_shape4(d_shear_viscosity_d_fractions, matrix_slopes), &
                     optional_shape4(d_shear_viscosity_d_temperatures, matrix_slopes), &
                     optional_shape4(d_bulk_viscosity_d_fractions, matrix_slopes), &
                     optional_shape4(d_bulk_viscosity_d_temperatures, matrix_slopes), &
                     optional_shape4(d_conductivity_d_fractions, matrix_slopes), &
                     optional_shape4(d_conductivity_d_temperatures, matrix_slopes), &
                     optional_shape4(d_drag_d_fractions, matrix_slopes), &
                     optional_shape4(d_drag_d_temperatures, matrix_slopes), &
                     optional_shape4(d_segregation_d_fractions, matrix_slopes), &
                     optional_shape4(d_segregation_d_temperatures, matrix_slopes), &
                     optional_shape4(d_radial_distribution_d_fractions, matrix_slopes), &
                     optional_shape4(d_radial_distribution_d_temperatures, matrix_slopes)], &
                    [per_class, per_class, per_class, n, per_class, per_class, (matrix, j = 1, 6), &
                     (per_class_slopes, j = 1, 4), (matrix_slopes, j = 1, 12)])) &
      status = c_unequal_temperature_mixture( &
               radial%handle, int(n, c_size_t), int(classes, c_size_t), fractions, temperatures, &
               diameters, densities, restitution, optional_matrix(pressure), optional_tensor3(d_pressure_d_fractions), &
               optional_tensor3(d_pressure_d_temperatures), optional_tensor3(shear_viscosity), &
               optional_tensor4(d_shear_viscosity_d_fractions), optional_tensor4(d_shear_viscosity_d_temperatures), &
               optional_tensor3(bulk_viscosity), optional_tensor4(d_bulk_viscosity_d_fractions), &
               optional_tensor4(d_bulk_viscosity_d_temperatures), optional_tensor3(conductivity), &
               optional_tensor4(d_conductivity_d_fractions), optional_tensor4(d_conductivity_d_temperatures), &
               optional_matrix(dissipation), optional_tensor3(d_dissipation_d_fractions), &
               optional_tensor3(d_dissipation_d_temperatures), optional_tensor3(drag), &
               optional_tensor4(d_drag_d_fractions), optional_tensor4(d_drag_d_temperatures), &
               optional_tensor3(segregation), optional_tensor4(d_segregation_d_fractions), &
               optional_tensor4(d_segregation_d_temperatures), optional_tensor3(radial_distribution), &
               optional_tensor4(d_radial_distribution_d_fractions), &
               optional_tensor4(d_radial_distribution_d_temperatures), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  ! ---- The wrappers' helpers -----------------------------------------------------------------

  ! The wrappers' check of their arrays before C is called: whether `extents` (the sizes, or
  ! shapes, of every array but `first`, and of each optional one present) equal `expected`
  ! (those that `first` implies). Where not, `error` is FLUIDBED_INVALID_ARGUMENT, 'fluidbed:
  ! <wrapper>: the arrays differ in size from <first>', with index −1 (cell 0: no cell), and the
  ! wrapper returns it without calling C.
  logical function sizes_agree_each(error, wrapper, first, extents, expected) result(agree)
    type(fluidbed_c_error), intent(out) :: error
    character(len=*), intent(in) :: wrapper, first
    integer, intent(in) :: extents(:), expected(:)
    character(len=:), allocatable :: text
    integer :: i
    agree = all(extents == expected)
    error%status = FLUIDBED_OK
    error%index = 0
    error%message = c_null_char
    if (agree) return
    text = 'fluidbed: ' // wrapper // ': the arrays differ in size from ' // first
    error%status = FLUIDBED_INVALID_ARGUMENT
    error%index = -1
    do i = 1, min(len(text), message_size - 1)
      error%message(i) = text(i:i)
    end do
  end function

  ! The same where every extent should be n (arrays of one dimension).
  logical function sizes_agree_all(error, wrapper, first, extents, n) result(agree)
    type(fluidbed_c_error), intent(out) :: error
    character(len=*), intent(in) :: wrapper, first
    integer, intent(in) :: extents(:), n
    agree = sizes_agree_each(error, wrapper, first, extents, spread(n, 1, size(extents)))
  end function

  ! An optional array's size (shape), or the expected one where it is absent.
  integer function optional_size(array, n) result(extent)
    real(c_double), intent(in), optional :: array(:)
    integer, intent(in) :: n
    extent = n
    if (present(array)) extent = size(array)
  end function

  integer function optional_int_size(array, n) result(extent)
    integer(c_int), intent(in), optional :: array(:)
    integer, intent(in) :: n
    extent = n
    if (present(array)) extent = size(array)
  end function

  function optional_shape(array, expected) result(extents)
    real(c_double), intent(in), optional :: array(:, :)
    integer, intent(in) :: expected(2)
    integer :: extents(2)
    extents = expected
    if (present(array)) extents = shape(array)
  end function

  function optional_shape3(array, expected) result(extents)
    real(c_double), intent(in), optional :: array(:, :, :)
    integer, intent(in) :: expected(3)
    integer :: extents(3)
    extents = expected
    if (present(array)) extents = shape(array)
  end function

  function optional_shape4(array, expected) result(extents)
    real(c_double), intent(in), optional :: array(:, :, :, :)
    integer, intent(in) :: expected(4)
    integer :: extents(4)
    extents = expected
    if (present(array)) extents = shape(array)
  end function

  ! An optional array as a C pointer: c_null_ptr where absent (or empty).
  type(c_ptr) function optional_array(array) result(address)
    real(c_double), intent(in), contiguous, target, optional :: array(:)
    address = c_null_ptr
    if (present(array)) then
      if (size(array) > 0) address = c_loc(array(1))
    end if
  end function

  type(c_ptr) function optional_int_array(array) result(address)
    integer(c_int), intent(in), contiguous, target, optional :: array(:)
    address = c_null_ptr
    if (present(array)) then
      if (size(array) > 0) address = c_loc(array(1))
    end if
  end function

  type(c_ptr) function optional_matrix(array) result(address)
    real(c_double), intent(in), contiguous, target, optional :: array(:, :)
    address = c_null_ptr
    if (present(array)) then
      if (size(array) > 0) address = c_loc(array(1, 1))
    end if
  end function

  type(c_ptr) function optional_tensor3(array) result(address)
    real(c_double), intent(in), contiguous, target, optional :: array(:, :, :)
    address = c_null_ptr
    if (present(array)) then
      if (size(array) > 0) address = c_loc(array(1, 1, 1))
    end if
  end function

  type(c_ptr) function optional_tensor4(array) result(address)
    real(c_double), intent(in), contiguous, target, optional :: array(:, :, :, :)
    address = c_null_ptr
    if (present(array)) then
      if (size(array) > 0) address = c_loc(array(1, 1, 1, 1))
    end if
  end function

end module fluidbed
