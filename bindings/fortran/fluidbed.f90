! fluidbed — the library's closures from Fortran (2008, iso_c_binding), over the C interface
! (fluidbed_c.h, libfluidbed_c). A closure is chosen by name once and evaluated over arrays of
! cells; every evaluation validates each cell as the C++ checked API does and returns a status,
! with the failing cell (1-based) and the C++ library's message. Array arguments must have the
! same size (checked: a mismatch is FLUIDBED_INVALID_ARGUMENT, never a read past an array).
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
  ! Buoyancy conventions (fluidbed_buoyancy): classical −φ ρ_f g, or pressure gradient −φ ∇p
  ! (MFiX model A, OpenFOAM, Fluent); β_pressure_gradient = ε β_classical.
  integer, parameter, public :: FLUIDBED_BUOYANCY_CLASSICAL = 0, &
                                FLUIDBED_BUOYANCY_PRESSURE_GRADIENT = 1
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

  public :: fluidbed_create, fluidbed_destroy, fluidbed_name, fluidbed_set_parameter, &
            fluidbed_get_parameter, fluidbed_drag, fluidbed_c_drag

  interface
    integer(c_int) function c_create(name, closure, error) bind(C, name='fluidbed_closure_create')
      import :: c_char, c_ptr, c_int, fluidbed_c_error
      character(kind=c_char), intent(in) :: name(*)
      type(c_ptr), intent(out) :: closure
      type(fluidbed_c_error), intent(out) :: error
    end function
    subroutine c_destroy(closure) bind(C, name='fluidbed_closure_destroy')
      import :: c_ptr
      type(c_ptr), value :: closure
    end subroutine
    type(c_ptr) function c_name(closure) bind(C, name='fluidbed_closure_name')
      import :: c_ptr
      type(c_ptr), value :: closure
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

  subroutine fluidbed_destroy(closure)
    type(fluidbed_closure), intent(inout) :: closure
    if (c_associated(closure%handle)) call c_destroy(closure%handle)
    closure%handle = c_null_ptr
  end subroutine

  function fluidbed_name(closure) result(name)
    type(fluidbed_closure), intent(in) :: closure
    character(len=:), allocatable :: name
    character(kind=c_char), pointer :: chars(:)
    integer :: n, i
    call c_f_pointer(c_name(closure%handle), chars, [256])
    n = 0
    do while (chars(n + 1) /= c_null_char)
      n = n + 1
    end do
    allocate(character(len=n) :: name)
    do i = 1, n
      name(i:i) = chars(i)
    end do
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
    if (any([size(slip), size(density), size(viscosity), size(diameter), size(beta)] /= n) .or. &
        mismatched(d_voidage, n) .or. mismatched(d_slip, n) .or. mismatched(d_force_d_slip, n)) then
      status = FLUIDBED_INVALID_ARGUMENT
      if (present(message)) message = 'fluidbed: fluidbed_drag: the arrays differ in size from voidage'
      if (present(cell)) cell = 0
      return
    end if
    status = fluidbed_c_drag(law%handle, int(convention, c_int), int(n, c_size_t), voidage, slip, density, &
                             viscosity, diameter, beta, optional_array(d_voidage), optional_array(d_slip), &
                             optional_array(d_force_d_slip), error)
    status = int(error%status)
    if (present(message)) message = message_of(error)
    if (present(cell)) cell = int(error%index) + 1
  end function

  logical function mismatched(array, n)
    real(c_double), intent(in), optional :: array(:)
    integer, intent(in) :: n
    mismatched = .false.
    if (present(array)) mismatched = size(array) /= n
  end function

  type(c_ptr) function optional_array(array)
    real(c_double), intent(in), contiguous, target, optional :: array(:)
    optional_array = c_null_ptr
    if (present(array)) then
      if (size(array) > 0) optional_array = c_loc(array(1))
    end if
  end function

end module fluidbed
