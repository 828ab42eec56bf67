! A user drag routine shaped like MFiX's DRAG_USR hook (usr_drag.f: one cell per call, the gas
! volume fraction, viscosity and density, the slip speed, the particle diameter and density, the
! gas velocity), returning a fluidbed law's drag coefficient. The law is chosen once, by name,
! on the first call; MFiX's two-fluid momentum equations carry the gas pressure gradient in both
! phases (its "model A"), so the coefficient is β in the pressure-gradient convention, per unit
! volume of suspension [kg m^-3 s^-1]. A failed evaluation stops the run with the library's
! message, where MFiX's own routines would go on with a NaN.
!
! The driver below calls it for a column of cells, as a host would, and checks it against one
! call of the library over the whole column (ctest fortran.mfix_usr_drag_example).
module usr_drag_fluidbed
  use, intrinsic :: iso_c_binding, only: c_double
  use fluidbed
  implicit none
  private
  public :: drag_usr
  character(len=*), parameter, public :: law_name = 'MazzeiLettieri'

contains

  subroutine drag_usr(ijk, m_np, ldga, epg, mug, rog, vrel, dpm, ros, lug, lvg, lwg)
    integer, intent(in) :: ijk, m_np                     ! cell, solids phase (unused: one law for all)
    real(c_double), intent(out) :: ldga                  ! β, pressure-gradient convention
    real(c_double), intent(in) :: epg, mug, rog, vrel, dpm, ros, lug, lvg, lwg
    type(fluidbed_closure), save :: law
    logical, save :: chosen = .false.
    real(c_double) :: beta(1)
    character(len=:), allocatable :: message
    integer :: status
    if (.not. chosen) then
      status = fluidbed_create(law_name, law, message)
      if (status /= FLUIDBED_OK) then
        print '(2a)', 'drag_usr: ', message
        error stop 1
      end if
      chosen = .true.
    end if
    status = fluidbed_drag(law, FLUIDBED_BUOYANCY_PRESSURE_GRADIENT, [epg], [vrel], [rog], [mug], [dpm], beta, &
                           message=message)
    if (status /= FLUIDBED_OK) then
      print '(a, i0, a, i0, 2a)', 'drag_usr: cell ', ijk, ', phase ', m_np, ': ', message
      error stop 1
    end if
    ldga = beta(1)  ! ros and the gas velocity, which MFiX's hook passes too, this law does not need
  end subroutine

end module

program mfix_usr_drag
  use, intrinsic :: iso_c_binding, only: c_double
  use fluidbed
  use usr_drag_fluidbed
  implicit none
  integer, parameter :: cells = 8
  real(c_double) :: epg(cells), slip(cells), rog(cells), mug(cells), dpm(cells), per_cell(cells), whole(cells)
  type(fluidbed_closure) :: law
  character(len=:), allocatable :: message
  integer :: ijk, status
  ! A bed of 300 µm sand in air at 600 K: voidage from packed to dilute, slip 0.05 to 0.4 m/s.
  do ijk = 1, cells
    epg(ijk) = 0.4_c_double + 0.08_c_double * (ijk - 1)
    slip(ijk) = 0.05_c_double * ijk
  end do
  rog = 0.59_c_double
  mug = 3.0e-5_c_double
  dpm = 3.0e-4_c_double
  do ijk = 1, cells
    call drag_usr(ijk, 1, per_cell(ijk), epg(ijk), mug(ijk), rog(ijk), slip(ijk), dpm(ijk), 2500.0_c_double, &
                  0.0_c_double, slip(ijk), 0.0_c_double)
    print '(a, i0, a, f5.2, a, f5.2, a, es12.5, a)', 'cell ', ijk, ': epsilon ', epg(ijk), ', slip ', slip(ijk), &
          ' m/s: beta ', per_cell(ijk), ' kg/m3/s'
  end do
  status = fluidbed_create(law_name, law, message)
  if (status == FLUIDBED_OK) &
    status = fluidbed_drag(law, FLUIDBED_BUOYANCY_PRESSURE_GRADIENT, epg, slip, rog, mug, dpm, whole, message=message)
  if (status /= FLUIDBED_OK) then
    print '(a)', message
    error stop 1
  end if
  if (any(transfer(per_cell, 0_8, cells) /= transfer(whole, 0_8, cells))) then
    print '(a)', 'the per-cell hook differs from the whole-column evaluation'
    error stop 1
  end if
  print '(a)', 'drag_usr per cell equals the whole-column evaluation bit for bit'
  call fluidbed_destroy(law)
end program
