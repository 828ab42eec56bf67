// fluidbed — exchange of granular (fluctuating) energy between the gas and the particles
// [W m⁻³], signed as terms on the right-hand side of the granular energy balance
// (granular_state.hpp): the viscous damping sink is negative, the sources positive.
//
// β is the interphase drag coefficient [kg m⁻³ s⁻¹] of the host's momentum equation
// (drag/, in the buoyancy convention that equation uses: the exchange term comes from the
// same force), w = |u_g − u_s| the slip speed [m s⁻¹]. Preconditions (asserted in debug
// builds): β ≥ 0, Θ ≥ 0, w ≥ 0, φ ∈ (0, 1) for DragFluctuationSource, [0, 1) otherwise,
// g0 > 0, μ_g > 0, material as in granular_state.hpp, temperature_floor > 0.
// gas_damping(β, Θ, fluidbed::checked) and source.checked(args…) validate them and throw
// std::domain_error naming the argument and its value. The two sources take different
// arguments; each has with_derivatives → GasExchangeDerivatives.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/constants.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// Damping of particle velocity fluctuations by the gas, −3 β Θ: Gidaspow (1994); seed 001
// eq. 35 (φ_gs = −3 K_gs Θ), seed 002 eq. 61 (−3βθ), seed 004 (−3β_iΘ_i). Linear in Θ, so
// hosts usually treat it implicitly (seed 002 eq. 86).
// Not a closure of a family (no alternatives): the error policy picks the hot path
// (fluidbed::unchecked, the default) or the checked one (fluidbed::checked: throws for β < 0 or
// Θ < 0, naming "kinetic_theory::gas_damping").
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr S gas_damping(const S& beta, const S& granular_temperature, Policy policy = {}) {
  check_domain(policy, "kinetic_theory::gas_damping",
               arguments(Argument<value_type_of<S>>{"beta", value_of(beta), domains::non_negative<value_type_of<S>>()},
                         detail::granular_temperature(value_of(granular_temperature))));
  return -3 * beta * granular_temperature;
}

// A source with its partial derivatives in the state (KochSanganiSource: ∂/∂φ through g0(φ)
// too, ∂/∂β = 0).
template <class T>
struct GasExchangeDerivatives {
  T value;
  T d_solid_fraction;
  T d_granular_temperature;
  T d_beta;
  T d_slip;
};

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
FLUIDBED_HOST_DEVICE constexpr Arguments<double, 1> temperature_floor_domain(double temperature_floor) {
  return {{{"temperature_floor", temperature_floor, domains::positive<double>()}}};
}

// w ≥ 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> slip(const T& w) {
  return {"slip", w, domains::non_negative<T>()};
}

}  // namespace detail

// Production of fluctuations by the gas's own velocity fluctuations, Koch & Sangani (1999),
// J. Fluid Mech. 400, 229–263, doi:10.1017/S0022112099006515 (MFiX):
//   J = 81 φ μ_g² w² / (g0 d³ ρ_s √π (√Θ + √Θ_floor)).
// Derived for Stokes flow (low Re), without a stated φ range (Validity<0>); → 0 as φ → 0.
struct KochSanganiSource : KineticTheoryLaw<KochSanganiSource> {
  double temperature_floor = default_temperature_floor;  // Θ_floor [m² s⁻²]

  constexpr explicit KochSanganiSource(double temperature_floor_ = default_temperature_floor)
      : temperature_floor(temperature_floor_) {}
  constexpr std::string_view name() const { return "KochSanganiSource"; }
  constexpr std::string_view reference() const {
    return "Koch, D.L. & Sangani, A.S. (1999) J. Fluid Mech. 400, 229-263, doi:10.1017/S0022112099006515";
  }
  constexpr Validity<0> validity() const { return {}; }
  constexpr Arguments<double, 1> parameter_domain() const {
    return detail::temperature_floor_domain(temperature_floor);
  }
  static constexpr auto parameters() {
    return std::array{parameter<&KochSanganiSource::temperature_floor>("temperature_floor")};
  }
  // φ ∈ [0, 1), Θ ≥ 0, g0 > 0, w ≥ 0, μ_g > 0, material as domain(GranularMaterial).
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 8> argument_domain(const T& phi, const T& theta, const T& g0,
                                                                          const T& slip, const T& gas_viscosity,
                                                                          const GranularMaterial<T>& m) {
    return join(Arguments<T, 5>{detail::solid_fraction(phi), detail::granular_temperature(theta),
                                detail::radial_distribution_value(g0), detail::slip(slip),
                                {"gas_viscosity", gas_viscosity, domains::positive<T>()}},
                kinetic_theory::domain(m));
  }

  // J with ∂/∂φ (g0 from `rdf`, called with the dual φ), ∂/∂Θ and ∂/∂w.
  template <class T, class RadialDistribution>
  FLUIDBED_HOST_DEVICE GasExchangeDerivatives<T> with_derivatives(const T& phi, const T& theta,
                                                                  const RadialDistribution& rdf, const T& slip,
                                                                  const T& gas_viscosity,
                                                                  const GranularMaterial<T>& m) const {
    using D = Dual<T, 3>;
    const D p = D::variable(phi, 0);
    const D j = (*this)(p, D::variable(theta, 1), rdf(p), D::variable(slip, 2), gas_viscosity, m);
    return {j.value, j.derivative[0], j.derivative[1], T(0), j.derivative[2]};
  }
  template <class T, class RadialDistribution>
  GasExchangeDerivatives<T> checked_with_derivatives(const T& phi, const T& theta, const RadialDistribution& rdf,
                                                     const T& slip, const T& gas_viscosity,
                                                     const GranularMaterial<T>& m) const {
    require_valid(phi, theta, rdf.checked(phi), slip, gas_viscosity, m);
    return with_derivatives(phi, theta, rdf, slip, gas_viscosity, m);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi, const S& theta, const S& g0, const S& slip, const T& gas_viscosity,
                                const GranularMaterial<T>& m) const {
    const T d = m.diameter;
    return (81 * gas_viscosity * gas_viscosity / (d * d * d * m.density * numbers::sqrt_pi<T>())) * phi * slip * slip /
           g0 * detail::regularised_inverse_sqrt(theta, temperature_floor);
  }
};

// The same production written with the drag coefficient (Gidaspow 1994; OpenFOAM's J2):
//   J = β² d w² / (4 φ ρ_s √π (√Θ + √Θ_floor)).
// With Stokes drag β = 18 μ_g φ/d² it is the Koch–Sangani source with g0 = 1 (tested).
// Precondition φ > 0 (β²/φ → 0 as φ → 0 for every drag law, but 0/0 in floating point).
// Validity: as Koch–Sangani's with Stokes drag, the low-Re limit; no range stated (Validity<0>).
struct DragFluctuationSource : KineticTheoryLaw<DragFluctuationSource> {
  double temperature_floor = default_temperature_floor;  // Θ_floor [m² s⁻²]

  constexpr explicit DragFluctuationSource(double temperature_floor_ = default_temperature_floor)
      : temperature_floor(temperature_floor_) {}
  constexpr std::string_view name() const { return "DragFluctuationSource"; }
  constexpr std::string_view reference() const { return detail::references::gidaspow_1994; }
  constexpr Validity<0> validity() const { return {}; }
  constexpr Arguments<double, 1> parameter_domain() const {
    return detail::temperature_floor_domain(temperature_floor);
  }
  static constexpr auto parameters() {
    return std::array{parameter<&DragFluctuationSource::temperature_floor>("temperature_floor")};
  }
  // φ ∈ (0, 1) (the source divides by φ), Θ ≥ 0, β ≥ 0, w ≥ 0, material as domain(GranularMaterial).
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 7> argument_domain(const T& phi, const T& theta, const T& beta,
                                                                          const T& slip,
                                                                          const GranularMaterial<T>& m) {
    return join(Arguments<T, 4>{{{"solid_fraction", phi, domains::open(T(0), T(1))},
                                 detail::granular_temperature(theta),
                                 {"beta", beta, domains::non_negative<T>()},
                                 detail::slip(slip)}},
                kinetic_theory::domain(m));
  }

  // J with ∂/∂φ, ∂/∂Θ, ∂/∂β and ∂/∂w.
  template <class T>
  FLUIDBED_HOST_DEVICE GasExchangeDerivatives<T> with_derivatives(const T& phi, const T& theta, const T& beta,
                                                                  const T& slip, const GranularMaterial<T>& m) const {
    using D = Dual<T, 4>;
    const D j = (*this)(D::variable(phi, 0), D::variable(theta, 1), D::variable(beta, 2), D::variable(slip, 3), m);
    return {j.value, j.derivative[0], j.derivative[1], j.derivative[2], j.derivative[3]};
  }
  template <class T>
  GasExchangeDerivatives<T> checked_with_derivatives(const T& phi, const T& theta, const T& beta, const T& slip,
                                                     const GranularMaterial<T>& m) const {
    require_valid(phi, theta, beta, slip, m);
    return with_derivatives(phi, theta, beta, slip, m);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi, const S& theta, const S& beta, const S& slip,
                                const GranularMaterial<T>& m) const {
    return (m.diameter / (4 * m.density * numbers::sqrt_pi<T>())) * beta * beta * slip * slip / phi *
           detail::regularised_inverse_sqrt(theta, temperature_floor);
  }
};

}  // namespace fluidbed::kinetic_theory
