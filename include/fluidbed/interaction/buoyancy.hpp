// fluidbed — the fluid–particle interaction forces other than drag (seed 000 §3.3), per unit
// volume of suspension [N m⁻³], as the force the fluid exerts
// on the particles (it enters the particle momentum equation with +, the fluid's with −).
//
// φ = 1 − ε is the solid volume fraction; g is the gravity vector (pointing down); every
// vector is Cartesian in the host code's frame. Which buoyancy a drag closure goes with is
// its native convention (drag/drag_law.hpp): classical closures with eq. 3.4, pressure-
// gradient closures with eq. 3.6; β_pressure_gradient = ε β_classical (eq. 3.19).
//
// Preconditions of every force (asserted in debug builds): φ ∈ [0, 1), densities and the
// viscosity > 0, coefficients ≥ 0, every vector component finite. Each has a `_checked` form
// that validates them and throws std::domain_error naming the argument and its value.
#pragma once

#include <string_view>

#include "../core/config.hpp"
#include "../core/errors.hpp"
#include "../core/vector3.hpp"

namespace fluidbed::elastic {

namespace detail {

template <class T>
FLUIDBED_HOST_DEVICE constexpr bool valid_solid_fraction(const T& solid_fraction) {
  return solid_fraction >= T(0) && solid_fraction < T(1);
}

// φ ∈ [0, 1) and a property of one phase (density or viscosity) > 0, for the checked forms.
template <class T>
void validate_fraction_and_property(std::string_view function, const T& solid_fraction, std::string_view property,
                                    const T& value) {
  require_in_closed_open(function, "solid_fraction", solid_fraction, T(0), T(1));
  require_positive(function, property, value);
}

}  // namespace detail

// Classical (Archimedes) buoyancy, eq. 3.4: −φ ρ_f g.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> classical_buoyancy(const T& solid_fraction, const T& fluid_density,
                                                   const Vector3<T>& gravity) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction) && fluid_density > T(0));
  return scaled(-solid_fraction * fluid_density, gravity);
}

// Stress-based buoyancy (Jackson 2000), eq. 3.5: φ ∇·⟨S⟩_f, given the divergence of the
// fluid-phase stress.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> stress_buoyancy(const T& solid_fraction, const Vector3<T>& fluid_stress_divergence) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction));
  return scaled(solid_fraction, fluid_stress_divergence);
}

// Pressure-gradient buoyancy, eq. 3.6: −φ ∇⟨p⟩_f.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> pressure_gradient_buoyancy(const T& solid_fraction,
                                                           const Vector3<T>& pressure_gradient) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction));
  return scaled(-solid_fraction, pressure_gradient);
}

// Eqs. 3.5 and 3.6 in a homogeneous suspension at equilibrium, eq. 3.10:
// −φ (ε ρ_f + φ ρ_p) g, the suspension density replacing ρ_f.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> homogeneous_buoyancy(const T& solid_fraction, const T& fluid_density,
                                                     const T& particle_density, const Vector3<T>& gravity) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction) && fluid_density > T(0) && particle_density > T(0));
  const T suspension_density = (T(1) - solid_fraction) * fluid_density + solid_fraction * particle_density;
  return scaled(-solid_fraction * suspension_density, gravity);
}

// Local fluid acceleration force, eq. 3.11: φ ρ_f D_f⟨u⟩_f/Dt. Belongs with classical
// buoyancy only: under a uniform acceleration g the two cancel exactly (eqs. 3.13–3.14).
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> local_fluid_acceleration_force(const T& solid_fraction, const T& fluid_density,
                                                               const Vector3<T>& fluid_acceleration) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction) && fluid_density > T(0));
  return scaled(solid_fraction * fluid_density, fluid_acceleration);
}

// Coefficients of a single sphere in an unbounded fluid (the dilute limit): virtual mass and
// lift ½ (equal, as frame indifference of their sum requires; seed 000 §3.3), Faxen ¾.
inline constexpr double dilute_virtual_mass_coefficient = 0.5;
inline constexpr double dilute_lift_coefficient = 0.5;
inline constexpr double dilute_faxen_coefficient = 0.75;

// Virtual mass force, eq. 3.15: C_v φ ρ_f (D_f⟨u⟩_f/Dt − D_p⟨v⟩_p/Dt), material accelerations
// of each phase following its own velocity.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> virtual_mass_force(const T& solid_fraction, const T& fluid_density,
                                                   const Vector3<T>& fluid_acceleration,
                                                   const Vector3<T>& particle_acceleration,
                                                   const T& coefficient = T(dilute_virtual_mass_coefficient)) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction) && fluid_density > T(0) && coefficient >= T(0));
  return scaled(coefficient * solid_fraction * fluid_density, difference(fluid_acceleration, particle_acceleration));
}

// Lift force, eq. 3.16 as printed: −C_l φ ρ_f (∇ × ⟨u⟩_f) × (⟨u⟩_f − ⟨v⟩_p).
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> lift_force(const T& solid_fraction, const T& fluid_density,
                                           const Vector3<T>& fluid_vorticity, const Vector3<T>& slip_velocity,
                                           const T& coefficient = T(dilute_lift_coefficient)) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction) && fluid_density > T(0) && coefficient >= T(0));
  return scaled(-coefficient * solid_fraction * fluid_density, cross(fluid_vorticity, slip_velocity));
}

// Faxen force, eq. 3.17 (the seed's subscript "n⟨f_f⟩_n" is a typo for _p):
// C_f φ μ_f ∇²⟨u⟩_f.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> faxen_force(const T& solid_fraction, const T& fluid_viscosity,
                                            const Vector3<T>& fluid_velocity_laplacian,
                                            const T& coefficient = T(dilute_faxen_coefficient)) {
  FLUIDBED_EXPECTS(detail::valid_solid_fraction(solid_fraction) && fluid_viscosity > T(0) && coefficient >= T(0));
  return scaled(coefficient * solid_fraction * fluid_viscosity, fluid_velocity_laplacian);
}

// ---------------------------------------------------------------- checked

template <class T>
Vector3<T> classical_buoyancy_checked(const T& solid_fraction, const T& fluid_density, const Vector3<T>& gravity) {
  constexpr std::string_view function = "classical_buoyancy";
  detail::validate_fraction_and_property(function, solid_fraction, "fluid_density", fluid_density);
  require_finite_elements(function, "gravity", gravity);
  return classical_buoyancy(solid_fraction, fluid_density, gravity);
}

template <class T>
Vector3<T> stress_buoyancy_checked(const T& solid_fraction, const Vector3<T>& fluid_stress_divergence) {
  constexpr std::string_view function = "stress_buoyancy";
  require_in_closed_open(function, "solid_fraction", solid_fraction, T(0), T(1));
  require_finite_elements(function, "fluid_stress_divergence", fluid_stress_divergence);
  return stress_buoyancy(solid_fraction, fluid_stress_divergence);
}

template <class T>
Vector3<T> pressure_gradient_buoyancy_checked(const T& solid_fraction, const Vector3<T>& pressure_gradient) {
  constexpr std::string_view function = "pressure_gradient_buoyancy";
  require_in_closed_open(function, "solid_fraction", solid_fraction, T(0), T(1));
  require_finite_elements(function, "pressure_gradient", pressure_gradient);
  return pressure_gradient_buoyancy(solid_fraction, pressure_gradient);
}

template <class T>
Vector3<T> homogeneous_buoyancy_checked(const T& solid_fraction, const T& fluid_density, const T& particle_density,
                                        const Vector3<T>& gravity) {
  constexpr std::string_view function = "homogeneous_buoyancy";
  detail::validate_fraction_and_property(function, solid_fraction, "fluid_density", fluid_density);
  require_positive(function, "particle_density", particle_density);
  require_finite_elements(function, "gravity", gravity);
  return homogeneous_buoyancy(solid_fraction, fluid_density, particle_density, gravity);
}

template <class T>
Vector3<T> local_fluid_acceleration_force_checked(const T& solid_fraction, const T& fluid_density,
                                                  const Vector3<T>& fluid_acceleration) {
  constexpr std::string_view function = "local_fluid_acceleration_force";
  detail::validate_fraction_and_property(function, solid_fraction, "fluid_density", fluid_density);
  require_finite_elements(function, "fluid_acceleration", fluid_acceleration);
  return local_fluid_acceleration_force(solid_fraction, fluid_density, fluid_acceleration);
}

template <class T>
Vector3<T> virtual_mass_force_checked(const T& solid_fraction, const T& fluid_density,
                                      const Vector3<T>& fluid_acceleration, const Vector3<T>& particle_acceleration,
                                      const T& coefficient = T(dilute_virtual_mass_coefficient)) {
  constexpr std::string_view function = "virtual_mass_force";
  detail::validate_fraction_and_property(function, solid_fraction, "fluid_density", fluid_density);
  require_finite_elements(function, "fluid_acceleration", fluid_acceleration);
  require_finite_elements(function, "particle_acceleration", particle_acceleration);
  require_non_negative(function, "coefficient", coefficient);
  return virtual_mass_force(solid_fraction, fluid_density, fluid_acceleration, particle_acceleration, coefficient);
}

template <class T>
Vector3<T> lift_force_checked(const T& solid_fraction, const T& fluid_density, const Vector3<T>& fluid_vorticity,
                              const Vector3<T>& slip_velocity, const T& coefficient = T(dilute_lift_coefficient)) {
  constexpr std::string_view function = "lift_force";
  detail::validate_fraction_and_property(function, solid_fraction, "fluid_density", fluid_density);
  require_finite_elements(function, "fluid_vorticity", fluid_vorticity);
  require_finite_elements(function, "slip_velocity", slip_velocity);
  require_non_negative(function, "coefficient", coefficient);
  return lift_force(solid_fraction, fluid_density, fluid_vorticity, slip_velocity, coefficient);
}

template <class T>
Vector3<T> faxen_force_checked(const T& solid_fraction, const T& fluid_viscosity,
                               const Vector3<T>& fluid_velocity_laplacian,
                               const T& coefficient = T(dilute_faxen_coefficient)) {
  constexpr std::string_view function = "faxen_force";
  detail::validate_fraction_and_property(function, solid_fraction, "fluid_viscosity", fluid_viscosity);
  require_finite_elements(function, "fluid_velocity_laplacian", fluid_velocity_laplacian);
  require_non_negative(function, "coefficient", coefficient);
  return faxen_force(solid_fraction, fluid_viscosity, fluid_velocity_laplacian, coefficient);
}

}  // namespace fluidbed::elastic
