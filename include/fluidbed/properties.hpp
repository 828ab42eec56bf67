// fluidbed — material properties and dimensionless groups.
//
// Reynolds numbers, stated once for the whole library:
//   particle Reynolds number   Re   = ρ_f ε w d / μ_f   (seed 000 eq. 3.33: the interstitial
//                                     slip w times ε, i.e. based on the superficial slip)
//   terminal Reynolds number   Re_t = ρ_f u_t d / μ_f   (seed 000 eq. 3.23)
//   Archimedes number          Ar   = ρ_f (ρ_p − ρ_f) g d³ / μ_f²
#pragma once

#include "core/config.hpp"
#include "core/constants.hpp"

namespace fluidbed {

// Standard gravity [m s⁻²], 9.81 as in seed 000; every function that needs g takes it as an
// argument defaulting to standard_gravity_as<T>(), 9.81 rounded once to T (a double 9.81
// would carry only 53 bits into a long double evaluation).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T standard_gravity_as() {
  return FLUIDBED_DECIMAL(T, 9.81);
}
inline constexpr double standard_gravity = standard_gravity_as<double>();

template <class T>
struct Fluid {
  T density;    // ρ_f [kg m⁻³]
  T viscosity;  // μ_f [Pa s], dynamic
};

template <class T>
struct Particles {
  T density;   // ρ_p [kg m⁻³]
  T diameter;  // d [m], volume-equivalent sphere diameter
};

// Re = ρ_f ε w d / μ_f, with w the interstitial slip speed |u_f − v_p|.
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S particle_reynolds(const Fluid<T>& fluid, const T& diameter, const S& voidage,
                                                   const S& slip) {
  return fluid.density * diameter / fluid.viscosity * (voidage * slip);
}

// Re_t = ρ_f u_t d / μ_f.
template <class T>
FLUIDBED_HOST_DEVICE constexpr T terminal_reynolds(const Fluid<T>& fluid, const T& diameter, const T& terminal_velocity) {
  return fluid.density * terminal_velocity * diameter / fluid.viscosity;
}

// Ar = ρ_f (ρ_p − ρ_f) g d³ / μ_f² (negative for particles lighter than the fluid).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T archimedes(const Fluid<T>& fluid, const Particles<T>& particles,
                                            const T& gravity = standard_gravity_as<T>()) {
  const T d = particles.diameter;
  return fluid.density * (particles.density - fluid.density) * gravity * d * d * d /
         (fluid.viscosity * fluid.viscosity);
}

}  // namespace fluidbed
