// fluidbed — exchange of granular (fluctuating) energy between the gas and the particles
// [W m⁻³], signed as terms on the right-hand side of the granular energy balance
// (granular_state.hpp): the viscous damping sink is negative, the sources positive.
//
// β is the interphase drag coefficient [kg m⁻³ s⁻¹] of the host's momentum equation
// (drag/, in the buoyancy convention that equation uses: the exchange term comes from the
// same force), w = |u_g − u_s| the slip speed [m s⁻¹]. Preconditions (asserted in debug
// builds): β ≥ 0, Θ ≥ 0, w ≥ 0, φ ∈ (0, 1) for DragFluctuationSource, [0, 1) otherwise,
// g0 > 0, μ_g > 0, material as in granular_state.hpp, temperature_floor > 0.
// gas_damping_checked and evaluate_checked(source, args…) validate them and throw
// std::domain_error naming the argument and its value.
#pragma once

#include <cmath>
#include <string>
#include <string_view>

#include "../core/constants.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// Damping of particle velocity fluctuations by the gas, −3 β Θ: Gidaspow (1994); seed 001
// eq. 35 (φ_gs = −3 K_gs Θ), seed 002 eq. 61 (−3βθ), seed 004 (−3β_iΘ_i). Linear in Θ, so
// hosts usually treat it implicitly (seed 002 eq. 86).
template <class S>
FLUIDBED_HOST_DEVICE constexpr S gas_damping(const S& beta, const S& granular_temperature) {
  FLUIDBED_EXPECTS(value_of(beta) >= 0 && value_of(granular_temperature) >= 0);
  return -3 * beta * granular_temperature;
}

template <class T>
T gas_damping_checked(const T& beta, const T& granular_temperature) {
  constexpr std::string_view function = "kinetic_theory::gas_damping";
  require_non_negative(function, "beta", beta);
  require_non_negative(function, "granular_temperature", granular_temperature);
  return gas_damping(beta, granular_temperature);
}

// The regularisation of 1/√Θ shared by the sources: 1/(√Θ + √Θ_floor), Θ_floor = 10⁻⁶
// m² s⁻² by default (OpenFOAM's ThetaSmall). Both sources are ∝ 1/√Θ and would be
// infinite at Θ = 0.
inline constexpr double default_temperature_floor = 1e-6;

namespace detail {

template <class S>
FLUIDBED_HOST_DEVICE S regularised_inverse_sqrt(const S& theta, double floor) {
  using std::sqrt;
  using T = value_type_of<S>;
  return 1 / (sqrt(theta) + sqrt(T(floor)));
}

// Θ_floor > 0: with 0 both sources are infinite at Θ = 0.
inline void validate_temperature_floor(std::string_view function, double temperature_floor) {
  require_positive(function, "temperature_floor", temperature_floor);
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
  void validate(std::string_view function) const { detail::validate_temperature_floor(function, temperature_floor); }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S operator()(const S& phi, const S& theta, const S& g0, const S& slip, const T& gas_viscosity,
                                    const GranularMaterial<T>& m) const {
    FLUIDBED_EXPECTS(detail::valid_closure_arguments(phi, theta, g0, m) && value_of(slip) >= 0 &&
                     gas_viscosity > T(0) && temperature_floor > 0);
    const T d = m.diameter;
    return (81 * gas_viscosity * gas_viscosity / (d * d * d * m.density * numbers::sqrt_pi<T>())) * phi * slip * slip /
           g0 * detail::regularised_inverse_sqrt(theta, temperature_floor);
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
  void validate(std::string_view function) const { detail::validate_temperature_floor(function, temperature_floor); }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S operator()(const S& phi, const S& theta, const S& beta, const S& slip,
                                    const GranularMaterial<T>& m) const {
    FLUIDBED_EXPECTS(value_of(phi) > 0 && value_of(phi) < 1 && value_of(theta) >= 0 && value_of(beta) >= 0 &&
                     value_of(slip) >= 0 && detail::valid_material(m) && temperature_floor > 0);
    return (m.diameter / (4 * m.density * numbers::sqrt_pi<T>())) * beta * beta * slip * slip / phi *
           detail::regularised_inverse_sqrt(theta, temperature_floor);
  }
};

// Checked entry points of the sources: validate the arguments and the source's parameters,
// throwing std::domain_error naming the argument and its value, then evaluate.
template <class T>
T evaluate_checked(const KochSanganiSource& source, const T& phi, const T& theta, const T& g0, const T& slip,
                   const T& gas_viscosity, const GranularMaterial<T>& m) {
  const std::string function = detail::checked_function_name(source);
  validate_state(function, phi, theta);
  require_positive(function, "g0", g0);
  require_non_negative(function, "slip", slip);
  require_positive(function, "gas_viscosity", gas_viscosity);
  validate(function, m);
  source.validate(function);
  return source(phi, theta, g0, slip, gas_viscosity, m);
}

template <class T>
T evaluate_checked(const DragFluctuationSource& source, const T& phi, const T& theta, const T& beta, const T& slip,
                   const GranularMaterial<T>& m) {
  const std::string function = detail::checked_function_name(source);
  require_in_open(function, "solid_fraction", phi, T(0), T(1));  // the source divides by φ
  require_non_negative(function, "granular_temperature", theta);
  require_non_negative(function, "beta", beta);
  require_non_negative(function, "slip", slip);
  validate(function, m);
  source.validate(function);
  return source(phi, theta, beta, slip, m);
}

}  // namespace fluidbed::kinetic_theory
