// fluidbed — minimum fluidization velocity u_mf.
//
// At minimum fluidization the packed bed's pressure drop carries its buoyant weight.
// Reynolds and Archimedes numbers:
//   Re_mf = ρ_f u_mf d / μ_f  (superficial velocity; the multiphase Re of seed 000 eq. 3.33
//                              at equilibrium),
//   Ar    = ρ_f (ρ_p − ρ_f) g d³ / μ_f².
// d is Particles::diameter, the volume-equivalent sphere diameter. Heavier-than-fluid
// particles only. The hot-path functions assert their preconditions in debug builds; the
// `_checked` functions throw std::domain_error naming the argument and its value.
#pragma once

#include <cmath>

#include "../core/config.hpp"
#include "../core/errors.hpp"
#include "../drag/ergun.hpp"
#include "../properties.hpp"
#include "terminal_velocity.hpp"

namespace fluidbed::settling {

namespace detail {

// ε_mf ∈ (0, 1) and φ_s ∈ (0, 1], for the checked Ergun forms.
template <class T>
void validate_ergun_bed(std::string_view function, const T& voidage, const T& sphericity) {
  require_in_open(function, "voidage", voidage, T(0), T(1));
  require_in_half_open(function, "sphericity", sphericity, T(0), T(1));
}

}  // namespace detail

// Ergun, S. (1952), "Fluid flow through packed columns", Chem. Eng. Prog. 48, 89–94, at
// the voidage ε_mf of the bed at minimum fluidization, with the sphericity φ_s as in Kunii,
// D., Levenspiel, O. (1991), Fluidization Engineering, 2nd ed., Butterworth–Heinemann, ch. 3:
//
//   150 (1 − ε_mf) Re_mf / (ε_mf³ φ_s²) + 1.75 Re_mf² / (ε_mf³ φ_s) = Ar
//
// (Ergun's pressure drop with the surface–volume diameter φ_s d, equated to the weight
// (1 − ε_mf)(ρ_p − ρ_f) g; for φ_s = 1 it is the equilibrium, eq. 3.28, of seed 000's Ergun
// drag, eq. 3.32, which gives the u_mf = 8.73·10⁻³ m s⁻¹ of its §4.3.3). A quadratic a Re² + b Re = Ar, solved in the
// cancellation-free form Re_mf = 2 Ar / (b + √(b² + 4 a Ar)).
// Preconditions: Ar >= 0, ε_mf ∈ (0, 1), φ_s ∈ (0, 1].
template <class T>
FLUIDBED_HOST_DEVICE T minimum_fluidization_reynolds_ergun(const T& archimedes, const T& voidage,
                                                           const T& sphericity = T(1)) {
  using std::sqrt;
  FLUIDBED_EXPECTS(!(archimedes < T(0)) && voidage > T(0) && voidage < T(1) && sphericity > T(0) && sphericity <= T(1));
  const T voidage_cubed = voidage * voidage * voidage;
  const T a = T(drag::Ergun::inertial_constant) / (voidage_cubed * sphericity);
  const T b = T(drag::Ergun::viscous_constant) * (1 - voidage) / (voidage_cubed * sphericity * sphericity);
  return 2 * archimedes / (b + sqrt(b * b + 4 * a * archimedes));
}

// Wen, C.Y., Yu, Y.H. (1966), "A generalized method for predicting the minimum
// fluidization velocity", AIChE J. 12, 610–612, doi:10.1002/aic.690120343:
//
//   Re_mf = √(33.7² + 0.0408 Ar) − 33.7 = 0.0408 Ar / (√(33.7² + 0.0408 Ar) + 33.7),
//
// the Ergun quadratic with their empirical 1/(φ_s ε_mf³) ≈ 14 and
// (1 − ε_mf)/(φ_s² ε_mf³) ≈ 11, evaluated in the second (cancellation-free) form.
// Fitted for 0.001 < Re_mf < 4000. Precondition: Ar >= 0.
template <class T>
FLUIDBED_HOST_DEVICE T minimum_fluidization_reynolds_wen_yu(const T& archimedes) {
  using std::sqrt;
  FLUIDBED_EXPECTS(!(archimedes < T(0)));
  const T c = T(33.7L);
  const T k = T(0.0408L) * archimedes;
  return k / (sqrt(c * c + k) + c);
}

// u_mf from the Ergun relation above at ε_mf (and sphericity φ_s).
template <class T>
T minimum_fluidization_velocity_ergun(const Fluid<T>& fluid, const Particles<T>& particles, const T& voidage,
                                      const T& sphericity = T(1), const T& gravity = standard_gravity_as<T>()) {
  return detail::velocity_from_reynolds(
      minimum_fluidization_reynolds_ergun(detail::archimedes_of_settling_system(fluid, particles, gravity), voidage,
                                          sphericity),
      fluid, particles);
}

// u_mf from Wen & Yu (1966).
template <class T>
T minimum_fluidization_velocity_wen_yu(const Fluid<T>& fluid, const Particles<T>& particles,
                                       const T& gravity = standard_gravity_as<T>()) {
  return detail::velocity_from_reynolds(
      minimum_fluidization_reynolds_wen_yu(detail::archimedes_of_settling_system(fluid, particles, gravity)), fluid,
      particles);
}

template <class T>
T minimum_fluidization_reynolds_ergun_checked(const T& archimedes, const T& voidage, const T& sphericity = T(1)) {
  constexpr std::string_view function = "minimum_fluidization_reynolds_ergun";
  require_non_negative(function, "archimedes", archimedes);
  detail::validate_ergun_bed(function, voidage, sphericity);
  return minimum_fluidization_reynolds_ergun(archimedes, voidage, sphericity);
}

template <class T>
T minimum_fluidization_reynolds_wen_yu_checked(const T& archimedes) {
  require_non_negative("minimum_fluidization_reynolds_wen_yu", "archimedes", archimedes);
  return minimum_fluidization_reynolds_wen_yu(archimedes);
}

template <class T>
T minimum_fluidization_velocity_ergun_checked(const Fluid<T>& fluid, const Particles<T>& particles, const T& voidage,
                                              const T& sphericity = T(1), const T& gravity = standard_gravity_as<T>()) {
  constexpr std::string_view function = "minimum_fluidization_velocity_ergun";
  detail::validate_settling(function, fluid, particles, gravity);
  detail::validate_ergun_bed(function, voidage, sphericity);
  return minimum_fluidization_velocity_ergun(fluid, particles, voidage, sphericity, gravity);
}

template <class T>
T minimum_fluidization_velocity_wen_yu_checked(const Fluid<T>& fluid, const Particles<T>& particles,
                                               const T& gravity = standard_gravity_as<T>()) {
  detail::validate_settling("minimum_fluidization_velocity_wen_yu", fluid, particles, gravity);
  return minimum_fluidization_velocity_wen_yu(fluid, particles, gravity);
}

}  // namespace fluidbed::settling
