// fluidbed — terminal settling velocity of a single sphere in an unbounded fluid: the closed
// forms (Stokes, Newton, Dallavalle), which need nothing beyond the standard library. The
// Schiller–Naumann form is solved numerically (Boost.Math) and lives in terminal_velocity.hpp,
// which includes this header; include that one unless Boost must be avoided (the drag laws do:
// Syamlal–O'Brien's calibration uses Dallavalle's Re_t).
//
// The force balance ¾ C_D(Re_t) ρ_f u_t²/d = (ρ_p − ρ_f) g, multiplied by ρ_f d³/μ_f², is
//
//   ¾ C_D(Re_t) Re_t² = Ar,    Re_t = ρ_f u_t d / μ_f,   Ar = ρ_f (ρ_p − ρ_f) g d³ / μ_f²,
//
// so each law is a function Re_t(Ar) (`terminal_reynolds_*`) and u_t = Re_t μ_f/(ρ_f d)
// (`terminal_velocity_*`, taking the fluid, the particles and g). The laws differ in the
// single-sphere C_D they assume:
//   Stokes            C_D = 24/Re                   Re_t = Ar/18           (seed 000 eq. 3.37)
//   Newton            C_D = 0.44                    Re_t = √(Ar/0.33)      (seed 000 eq. 3.41)
//   Dallavalle        C_D = (0.63 + 4.8/√Re)²       closed form below     (seed 000 eq. 3.51)
//   Schiller–Naumann  C_D = 24/Re (1 + 0.15 Re^0.687), 0.44 for Re >= 1000  (eq. 3.35; solved in terminal_velocity.hpp)
// Seed 000 uses Dallavalle's u_t for Richardson–Zaki and for its Tables 4.4 and 4.6 (no other
// u_t reproduces them); Stokes and Newton are the Schiller–Naumann limits its exponent
// derivations use.
//
// Heavier-than-fluid particles only (ρ_p > ρ_f: Ar > 0). The hot-path functions assert
// their preconditions in debug builds (Re_t(Ar): Ar ≥ 0; u_t: ρ_f, μ_f, d, g > 0 and
// ρ_p > ρ_f, all finite); the `_checked` ones throw std::domain_error naming the argument and
// its value.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../core/errors.hpp"
#include "../drag/single_particle.hpp"
#include "../properties.hpp"

namespace fluidbed::settling {

namespace detail {

// The hot-path form of validate_settling, for FLUIDBED_EXPECTS (NaN fails every comparison).
template <class T>
FLUIDBED_HOST_DEVICE constexpr bool valid_settling_inputs(const Fluid<T>& fluid, const Particles<T>& particles,
                                                          const T& gravity) {
  return fluid.density > T(0) && fluid.viscosity > T(0) && particles.diameter > T(0) && gravity > T(0) &&
         particles.density > fluid.density;
}

// Throws unless ρ_f, μ_f, d, g are finite and > 0 and ρ_p is finite and > ρ_f.
template <class T>
void validate_settling(std::string_view function, const Fluid<T>& fluid, const Particles<T>& particles,
                       const T& gravity) {
  require_positive(function, "fluid.density", fluid.density);
  require_positive(function, "fluid.viscosity", fluid.viscosity);
  require_positive(function, "particles.diameter", particles.diameter);
  require_positive(function, "gravity", gravity);
  if (!fluidbed::detail::is_finite_number(particles.density) || !(particles.density > fluid.density))
    fluidbed::detail::throw_domain_error(function, "particles.density", particles.density,
                                         "must be finite and > fluid.density: heavier-than-fluid particles only");
}

// u = Re μ_f / (ρ_f d).
template <class T>
T velocity_from_reynolds(const T& reynolds, const Fluid<T>& fluid, const Particles<T>& particles) {
  return reynolds * fluid.viscosity / (fluid.density * particles.diameter);
}

// Ar of a validated system, the hot-path preconditions of every u_t and u_mf asserted.
template <class T>
T archimedes_of_settling_system(const Fluid<T>& fluid, const Particles<T>& particles, const T& gravity) {
  FLUIDBED_EXPECTS(valid_settling_inputs(fluid, particles, gravity));
  return archimedes(fluid, particles, gravity);
}

}  // namespace detail

// ----------------------------------------------------------------------------- Re_t(Ar)

// Stokes (1851), Trans. Camb. Philos. Soc. 9, 8: Re_t = Ar/18. Valid for Re_t <~ 0.1.
template <class T>
FLUIDBED_HOST_DEVICE T terminal_reynolds_stokes(const T& archimedes) {
  FLUIDBED_EXPECTS(!(archimedes < T(0)));
  return archimedes / 18;
}

// Newton regime, C_D = 0.44 (the inertial branch of Schiller–Naumann; seed 000 eq. 3.41
// from Gibilaro (2001), Fluidization-Dynamics, Butterworth-Heinemann): Re_t = √(Ar/0.33),
// i.e. u_t = √(3.0303 g d (ρ_p − ρ_f)/ρ_f). The seed prints 3.03 for 4/(3·0.44) = 3.0303;
// the exact constant is used so that the Schiller–Naumann u_t tends to this one.
// Valid for 1000 <~ Re_t <~ 2·10⁵.
template <class T>
FLUIDBED_HOST_DEVICE T terminal_reynolds_newton(const T& archimedes) {
  using std::sqrt;
  FLUIDBED_EXPECTS(!(archimedes < T(0)));
  return sqrt(archimedes / (T(0.75) * T(0.44L)));
}

// Dallavalle, J.M. (1948), Micromeritics, 2nd ed., Pitman; seed 000 eq. 3.51:
// C_D = (0.63 + 4.8 Re^−½)², so ¾ C_D Re_t² = ¾ (0.63 Re_t + 4.8 √Re_t)² = Ar is a quadratic
// in √Re_t:
//
//   √Re_t = [−4.8 + √(4.8² + 4·0.63·s)] / (2·0.63) = 2 s / (4.8 + √(4.8² + 2.52 s)),  s = √(4Ar/3),
//
// evaluated in the second (cancellation-free) form. Limits: Re_t → Ar/17.28
// (C_D Re → 23.04, not Stokes's 24) and Re_t → √(4Ar/(3·0.3969)) (C_D → 0.3969, not 0.44).
// Smooth over all Ar >= 0.
template <class T>
FLUIDBED_HOST_DEVICE T terminal_reynolds_dallavalle(const T& archimedes) {
  using std::sqrt;
  FLUIDBED_EXPECTS(!(archimedes < T(0)));
  const T s = sqrt(4 * archimedes / 3);
  const T root = 2 * s / (T(4.8L) + sqrt(T(4.8L) * T(4.8L) + T(2.52L) * s));
  return root * root;
}

// ----------------------------------------------------------------------------- u_t

// u_t = (ρ_p − ρ_f) g d² / (18 μ_f) (seed 000 eq. 3.37).
template <class T>
T terminal_velocity_stokes(const Fluid<T>& fluid, const Particles<T>& particles,
                           const T& gravity = standard_gravity_as<T>()) {
  return detail::velocity_from_reynolds(
      terminal_reynolds_stokes(detail::archimedes_of_settling_system(fluid, particles, gravity)), fluid, particles);
}

// u_t = √(4 g d (ρ_p − ρ_f) / (3 · 0.44 ρ_f)) (seed 000 eq. 3.41).
template <class T>
T terminal_velocity_newton(const Fluid<T>& fluid, const Particles<T>& particles,
                           const T& gravity = standard_gravity_as<T>()) {
  return detail::velocity_from_reynolds(
      terminal_reynolds_newton(detail::archimedes_of_settling_system(fluid, particles, gravity)), fluid, particles);
}

// Dallavalle's u_t, the one seed 000 uses with Richardson–Zaki (see terminal_reynolds_dallavalle).
template <class T>
T terminal_velocity_dallavalle(const Fluid<T>& fluid, const Particles<T>& particles,
                               const T& gravity = standard_gravity_as<T>()) {
  return detail::velocity_from_reynolds(
      terminal_reynolds_dallavalle(detail::archimedes_of_settling_system(fluid, particles, gravity)), fluid, particles);
}

// ----------------------------------------------------------------------------- checked

template <class T>
T terminal_reynolds_stokes_checked(const T& archimedes) {
  require_non_negative("terminal_reynolds_stokes", "archimedes", archimedes);
  return terminal_reynolds_stokes(archimedes);
}

template <class T>
T terminal_reynolds_newton_checked(const T& archimedes) {
  require_non_negative("terminal_reynolds_newton", "archimedes", archimedes);
  return terminal_reynolds_newton(archimedes);
}

template <class T>
T terminal_reynolds_dallavalle_checked(const T& archimedes) {
  require_non_negative("terminal_reynolds_dallavalle", "archimedes", archimedes);
  return terminal_reynolds_dallavalle(archimedes);
}

template <class T>
T terminal_velocity_stokes_checked(const Fluid<T>& fluid, const Particles<T>& particles,
                                   const T& gravity = standard_gravity_as<T>()) {
  detail::validate_settling("terminal_velocity_stokes", fluid, particles, gravity);
  return terminal_velocity_stokes(fluid, particles, gravity);
}

template <class T>
T terminal_velocity_newton_checked(const Fluid<T>& fluid, const Particles<T>& particles,
                                   const T& gravity = standard_gravity_as<T>()) {
  detail::validate_settling("terminal_velocity_newton", fluid, particles, gravity);
  return terminal_velocity_newton(fluid, particles, gravity);
}

template <class T>
T terminal_velocity_dallavalle_checked(const Fluid<T>& fluid, const Particles<T>& particles,
                                       const T& gravity = standard_gravity_as<T>()) {
  detail::validate_settling("terminal_velocity_dallavalle", fluid, particles, gravity);
  return terminal_velocity_dallavalle(fluid, particles, gravity);
}

}  // namespace fluidbed::settling
