! What the Fortran test programs share: a check that counts and reports failures, the end of a
! program (its summary, and exit status 1 if any check failed), and bitwise equality of doubles.
module fortran_checks
  use, intrinsic :: iso_c_binding, only: c_double
  implicit none
  private
  public :: check, finish, same_bits

  integer :: failures = 0

contains

  ! Counts a failed check; the first 20 are printed.
  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    if (.not. ok) then
      failures = failures + 1
      if (failures <= 20) print '(2a)', 'FAILED: ', what
    end if
  end subroutine

  ! Prints `passed` if every check passed, else the number that failed, and stops with status 1.
  subroutine finish(passed)
    character(len=*), intent(in) :: passed
    if (failures == 0) then
      print '(a)', passed
    else
      print '(a, i0, a)', 'fortran: ', failures, ' checks FAILED'
      error stop 1
    end if
  end subroutine

  elemental logical function same_bits(a, b)
    real(c_double), intent(in) :: a, b
    same_bits = transfer(a, 0_8) == transfer(b, 0_8)
  end function

end module fortran_checks
