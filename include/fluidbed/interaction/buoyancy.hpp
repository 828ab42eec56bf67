// fluidbed — buoyancy in its three definitions and the local fluid acceleration force
// (seed 000 §3.3), per unit volume of suspension [N m⁻³], as the force the fluid exerts on the
// particles (it enters the particle momentum equation with +, the fluid's with −).
//
// φ = 1 − ε is the solid volume fraction; g is the gravity vector (pointing down); every
// vector is Cartesian in the host code's frame. Which buoyancy a drag closure goes with is
// its native convention (drag/drag_law.hpp): classical closures with eq. 3.4, pressure-
// gradient closures with eq. 3.6; β_pressure_gradient = ε β_classical (eq. 3.19).
//
// The three definitions are separate functions, not a registry of alternatives: each takes
// other inputs (g; the fluid stress divergence; the pressure gradient), and which one a host
// needs is fixed by its momentum equations and its drag's convention, not chosen at run time.
//
// Every function takes an error policy as last argument (core/errors.hpp): fluidbed::unchecked
// (default; preconditions asserted in debug builds) or fluidbed::checked (std::domain_error
// naming the argument and its value). Preconditions: φ ∈ [0, 1), densities > 0, every vector
// component finite.
#pragma once

#include <string_view>

#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/errors.hpp"
#include "../core/vector3.hpp"
#include "vector_arguments.hpp"

namespace fluidbed::interaction {

namespace detail {

// The scalar arguments of the interaction forces, each domain declared once.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> solid_fraction_argument(const T& solid_fraction) {
  return {"solid_fraction", solid_fraction, domains::closed_open(T(0), T(1))};  // φ ∈ [0, 1)
}
// A density or a viscosity.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> property_argument(const char* name, const T& value) {
  return {name, value, domains::positive<T>()};
}

}  // namespace detail

// Classical (Archimedes) buoyancy, eq. 3.4: −φ ρ_f g.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> classical_buoyancy(const T& solid_fraction, const T& fluid_density,
                                                   const Vector3<T>& gravity, Policy policy = {}) {
  check_force_domain(policy, "classical_buoyancy",
                       arguments(detail::solid_fraction_argument(solid_fraction),
                                 detail::property_argument("fluid_density", fluid_density)),
                       FiniteVector<T>{"gravity", gravity});
  return scaled(-solid_fraction * fluid_density, gravity);
}

// Stress-based buoyancy (Jackson 2000), eq. 3.5: φ ∇·⟨S⟩_f, given the divergence of the
// fluid-phase stress.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> stress_buoyancy(const T& solid_fraction, const Vector3<T>& fluid_stress_divergence,
                                                Policy policy = {}) {
  check_force_domain(policy, "stress_buoyancy", arguments(detail::solid_fraction_argument(solid_fraction)),
                       FiniteVector<T>{"fluid_stress_divergence", fluid_stress_divergence});
  return scaled(solid_fraction, fluid_stress_divergence);
}

// Pressure-gradient buoyancy, eq. 3.6: −φ ∇⟨p⟩_f.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> pressure_gradient_buoyancy(const T& solid_fraction, const Vector3<T>& pressure_gradient,
                                                           Policy policy = {}) {
  check_force_domain(policy, "pressure_gradient_buoyancy", arguments(detail::solid_fraction_argument(solid_fraction)),
                       FiniteVector<T>{"pressure_gradient", pressure_gradient});
  return scaled(-solid_fraction, pressure_gradient);
}

// Eqs. 3.5 and 3.6 in a homogeneous suspension at equilibrium, eq. 3.10:
// −φ (ε ρ_f + φ ρ_p) g, the suspension density replacing ρ_f.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> homogeneous_buoyancy(const T& solid_fraction, const T& fluid_density,
                                                     const T& particle_density, const Vector3<T>& gravity,
                                                     Policy policy = {}) {
  check_force_domain(policy, "homogeneous_buoyancy",
                       arguments(detail::solid_fraction_argument(solid_fraction),
                                 detail::property_argument("fluid_density", fluid_density),
                                 detail::property_argument("particle_density", particle_density)),
                       FiniteVector<T>{"gravity", gravity});
  const T suspension_density = (T(1) - solid_fraction) * fluid_density + solid_fraction * particle_density;
  return scaled(-solid_fraction * suspension_density, gravity);
}

// Local fluid acceleration force, eq. 3.11: φ ρ_f D_f⟨u⟩_f/Dt. Belongs with classical
// buoyancy only: under a uniform acceleration g the two cancel exactly (eqs. 3.13–3.14).
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> local_fluid_acceleration_force(const T& solid_fraction, const T& fluid_density,
                                                               const Vector3<T>& fluid_acceleration,
                                                               Policy policy = {}) {
  check_force_domain(policy, "local_fluid_acceleration_force",
                       arguments(detail::solid_fraction_argument(solid_fraction),
                                 detail::property_argument("fluid_density", fluid_density)),
                       FiniteVector<T>{"fluid_acceleration", fluid_acceleration});
  return scaled(solid_fraction * fluid_density, fluid_acceleration);
}

}  // namespace fluidbed::interaction
