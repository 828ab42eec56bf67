// fluidbed — terminal settling velocity of a single sphere in an unbounded fluid: every form.
// The closed forms (Stokes, Newton, Dallavalle), the conventions and the preconditions are in
// terminal_velocity_closed_forms.hpp; this header adds Schiller–Naumann, whose balance is solved
// with Boost.Math.
#pragma once

#include "../core/root_finding.hpp"
#include "terminal_velocity_closed_forms.hpp"

namespace fluidbed::settling {

// Schiller, L., Naumann, A. (1933), Z. Ver. Dtsch. Ing. 77, 318; seed 000 eq. 3.35, with
// the 0.44 branch for Re >= 1000 (drag::SchillerNaumannCoefficient). ¾ C_D Re_t² = Ar is
// solved with Boost.Math toms748 on the bracket [0, Ar/18] (C_D Re >= 24 gives
// Re_t <= Ar/18).
// The law jumps at Re = 1000 (¾ C_D Re² goes from 328 716 to 330 000), so for
// 328 716 < Ar < 330 000 the balance has no root: the drag is below the weight just under
// Re = 1000 and above it at Re = 1000. There the solver converges to the sign change and
// Re_t = 1000 (to rounding) is returned, which keeps Re_t(Ar) continuous and
// non-decreasing.
template <class T>
T terminal_reynolds_schiller_naumann(const T& archimedes) {
  FLUIDBED_EXPECTS(!(archimedes < T(0)));
  if (archimedes == T(0)) return T(0);
  const auto balance = [&](const T& re) {
    return T(0.75) * drag::SchillerNaumannCoefficient::cd_times_re(re) * re / archimedes - 1;
  };
  const T hi = archimedes / 18;
  return fluidbed::detail::bracketed_root(balance, T(0), hi, T(-1), balance(hi));
}

// Schiller–Naumann's u_t (see terminal_reynolds_schiller_naumann for the jump at Re = 1000).
template <class T>
T terminal_velocity_schiller_naumann(const Fluid<T>& fluid, const Particles<T>& particles,
                                     const T& gravity = standard_gravity_as<T>()) {
  return detail::velocity_from_reynolds(
      terminal_reynolds_schiller_naumann(detail::archimedes_of_settling_system(fluid, particles, gravity)), fluid,
      particles);
}

// ----------------------------------------------------------------------------- checked

template <class T>
T terminal_reynolds_schiller_naumann_checked(const T& archimedes) {
  require_non_negative("terminal_reynolds_schiller_naumann", "archimedes", archimedes);
  return terminal_reynolds_schiller_naumann(archimedes);
}

template <class T>
T terminal_velocity_schiller_naumann_checked(const Fluid<T>& fluid, const Particles<T>& particles,
                                             const T& gravity = standard_gravity_as<T>()) {
  detail::validate_settling("terminal_velocity_schiller_naumann", fluid, particles, gravity);
  return terminal_velocity_schiller_naumann(fluid, particles, gravity);
}

}  // namespace fluidbed::settling
