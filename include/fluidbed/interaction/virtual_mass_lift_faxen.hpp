// fluidbed — the virtual mass, lift and Faxen forces (seed 000 §3.3), per unit volume of
// suspension [N m⁻³], as the force the fluid exerts on the particles; the conventions and the
// error policy of buoyancy.hpp. Preconditions: φ ∈ [0, 1), ρ_f, μ_f > 0, coefficients ≥ 0,
// every vector component finite. To pass fluidbed::checked, pass the coefficient too.
#pragma once

#include <string_view>

#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/errors.hpp"
#include "../core/vector3.hpp"
#include "buoyancy.hpp"
#include "vector_arguments.hpp"

namespace fluidbed::interaction {

// Coefficients of a single sphere in an unbounded fluid (the dilute limit): virtual mass and
// lift ½ (equal, as frame indifference of their sum requires; seed 000 §3.3), Faxen ¾.
inline constexpr double dilute_virtual_mass_coefficient = 0.5;
inline constexpr double dilute_lift_coefficient = 0.5;
inline constexpr double dilute_faxen_coefficient = 0.75;

namespace detail {

// The arguments every force of this header has: φ, a fluid property and the coefficient.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 3> force_domain(const T& solid_fraction, const char* property,
                                                            const T& property_value, const T& coefficient) {
  return arguments(solid_fraction_argument(solid_fraction), property_argument(property, property_value),
                   Argument<T>{"coefficient", coefficient, domains::non_negative<T>()});
}

}  // namespace detail

// Virtual mass force, eq. 3.15: C_v φ ρ_f (D_f⟨u⟩_f/Dt − D_p⟨v⟩_p/Dt), material accelerations
// of each phase following its own velocity.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> virtual_mass_force(const T& solid_fraction, const T& fluid_density,
                                                   const Vector3<T>& fluid_acceleration,
                                                   const Vector3<T>& particle_acceleration,
                                                   const T& coefficient = T(dilute_virtual_mass_coefficient),
                                                   Policy policy = {}) {
  check_force_domain(policy, "virtual_mass_force",
                       detail::force_domain(solid_fraction, "fluid_density", fluid_density, coefficient),
                       FiniteVector<T>{"fluid_acceleration", fluid_acceleration},
                       FiniteVector<T>{"particle_acceleration", particle_acceleration});
  return scaled(coefficient * solid_fraction * fluid_density, difference(fluid_acceleration, particle_acceleration));
}

// Lift force, eq. 3.16 as printed: −C_l φ ρ_f (∇ × ⟨u⟩_f) × (⟨u⟩_f − ⟨v⟩_p).
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> lift_force(const T& solid_fraction, const T& fluid_density,
                                           const Vector3<T>& fluid_vorticity, const Vector3<T>& slip_velocity,
                                           const T& coefficient = T(dilute_lift_coefficient), Policy policy = {}) {
  check_force_domain(policy, "lift_force",
                       detail::force_domain(solid_fraction, "fluid_density", fluid_density, coefficient),
                       FiniteVector<T>{"fluid_vorticity", fluid_vorticity},
                       FiniteVector<T>{"slip_velocity", slip_velocity});
  return scaled(-coefficient * solid_fraction * fluid_density, cross(fluid_vorticity, slip_velocity));
}

// Faxen force, eq. 3.17 (the seed's subscript "n⟨f_f⟩_n" is a typo for _p):
// C_f φ μ_f ∇²⟨u⟩_f.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> faxen_force(const T& solid_fraction, const T& fluid_viscosity,
                                            const Vector3<T>& fluid_velocity_laplacian,
                                            const T& coefficient = T(dilute_faxen_coefficient), Policy policy = {}) {
  check_force_domain(policy, "faxen_force",
                       detail::force_domain(solid_fraction, "fluid_viscosity", fluid_viscosity, coefficient),
                       FiniteVector<T>{"fluid_velocity_laplacian", fluid_velocity_laplacian});
  return scaled(coefficient * solid_fraction * fluid_viscosity, fluid_velocity_laplacian);
}

}  // namespace fluidbed::interaction
