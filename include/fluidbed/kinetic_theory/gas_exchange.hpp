// fluidbed — exchange of granular (fluctuating) energy between the gas and the particles
// [W m⁻³], signed as terms on the right-hand side of the granular energy balance
// (granular_state.hpp): the viscous damping sink is negative, the sources positive.
//
// β is the interphase drag coefficient [kg m⁻³ s⁻¹] of the host's momentum equation
// (drag/, in the buoyancy convention that equation uses: the exchange term comes from the
// same force), w = |u_g − u_s| the slip speed [m s⁻¹]. Preconditions: β ≥ 0, Θ ≥ 0, w ≥ 0,
// φ ∈ (0, 1) for DragFluctuationSource, [0, 1) otherwise.
#pragma once

#include <cmath>
#include <string_view>

#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// Damping of particle velocity fluctuations by the gas, −3 β Θ: Gidaspow (1994); seed 001
// eq. 35 (φ_gs = −3 K_gs Θ), seed 002 eq. 61 (−3βθ), seed 004 (−3β_iΘ_i). Linear in Θ, so
// hosts usually treat it implicitly (seed 002 eq. 86).
template <class S>
FLUIDBED_HOST_DEVICE constexpr S gas_damping(const S& beta, const S& granular_temperature) {
  return -3.0 * beta * granular_temperature;
}

// The regularisation of 1/√Θ shared by the sources: 1/(√Θ + √Θ_floor), Θ_floor = 10⁻⁶
// m² s⁻² by default (OpenFOAM's ThetaSmall). Both sources are ∝ 1/√Θ and would be
// infinite at Θ = 0.
inline constexpr double default_temperature_floor = 1e-6;

namespace detail {

template <class S>
FLUIDBED_HOST_DEVICE S regularised_inverse_sqrt(const S& theta, double floor) {
  using std::sqrt;
  return 1.0 / (sqrt(theta) + std::sqrt(floor));
}

}  // namespace detail

// Production of fluctuations by the gas's own velocity fluctuations, Koch & Sangani (1999),
// J. Fluid Mech. 400, 229–263, doi:10.1017/S0022112099006515 (MFiX):
//   J = 81 φ μ_g² w² / (g0 d³ ρ_s √π (√Θ + √Θ_floor)).
// Derived for Stokes flow (low Re); → 0 as φ → 0.
struct KochSanganiSource {
  double temperature_floor = default_temperature_floor;  // Θ_floor [m² s⁻²]

  constexpr std::string_view name() const { return "KochSangani"; }
  constexpr std::string_view reference() const {
    return "Koch, D.L. & Sangani, A.S. (1999) J. Fluid Mech. 400, 229-263, doi:10.1017/S0022112099006515";
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S operator()(const S& phi, const S& theta, const S& g0, const S& slip, const T& gas_viscosity,
                                    const GranularMaterial<T>& m) const {
    const T d = m.diameter;
    return (81.0 * gas_viscosity * gas_viscosity / (d * d * d * m.density * detail::sqrt_pi)) * phi * slip * slip / g0 *
           detail::regularised_inverse_sqrt(theta, temperature_floor);
  }
};

// The same production written with the drag coefficient (Gidaspow 1994; OpenFOAM's J2):
//   J = β² d w² / (4 φ ρ_s √π (√Θ + √Θ_floor)).
// With Stokes drag β = 18 μ_g φ/d² it is the Koch–Sangani source with g0 = 1 (tested).
// Precondition φ > 0 (β²/φ → 0 as φ → 0 for every drag law, but 0/0 in floating point).
struct DragFluctuationSource {
  double temperature_floor = default_temperature_floor;  // Θ_floor [m² s⁻²]

  constexpr std::string_view name() const { return "Gidaspow"; }
  constexpr std::string_view reference() const { return detail::references::gidaspow_1994; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S operator()(const S& phi, const S& theta, const S& beta, const S& slip,
                                    const GranularMaterial<T>& m) const {
    return (m.diameter / (4.0 * m.density * detail::sqrt_pi)) * beta * beta * slip * slip / phi *
           detail::regularised_inverse_sqrt(theta, temperature_floor);
  }
};

}  // namespace fluidbed::kinetic_theory
