// fluidbed — a complete kinetic-theory closure for one solids phase, per cell.
//
// ConstitutiveSet bundles the laws a two-fluid solver needs (the radial distribution, the
// granular pressure, shear and bulk viscosities, the conductivity and the dissipation) and
// evaluates them together from (φ, Θ) — g0 once — with or without the partial derivatives
// in φ and Θ, and gives the algebraic granular temperature with the same laws. For
// example, seed 001's FLUENT set is
//   ConstitutiveSet{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{}, SyamlalConductivity{}}
// (with Gidaspow's collisional viscosity and Lun's bulk viscosity and dissipation, the
// defaults). Friction (friction.hpp) and gas exchange (gas_exchange.hpp) need more inputs
// and are added by the host.
#pragma once

#include <concepts>
#include <string_view>

#include "algebraic_temperature.hpp"
#include "dissipation.hpp"
#include "granular_state.hpp"
#include "viscosity.hpp"

namespace fluidbed::kinetic_theory {

template <class V>
struct ConstitutiveValues {
  V radial_distribution;  // g0
  V pressure;             // p_s [Pa]
  V shear_viscosity;      // μ_s [Pa s]
  V bulk_viscosity;       // λ_s [Pa s]
  V conductivity;         // κ_s [kg m⁻¹ s⁻¹]
  V dissipation;          // γ [W m⁻³], a positive sink
};

template <class RadialDistribution, class Pressure, class ShearViscosity, class Conductivity,
          class BulkViscosity = LunBulkViscosity, class Dissipation = LunDissipation>
struct ConstitutiveSet {
  RadialDistribution radial_distribution;
  Pressure pressure;
  ShearViscosity shear_viscosity;
  Conductivity conductivity;
  BulkViscosity bulk_viscosity{};
  Dissipation dissipation{};

  // φ ∈ [0, 1), Θ ≥ 0, material as domain(GranularMaterial).
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 5> argument_domain(const T& phi, const T& theta,
                                                                          const GranularMaterial<T>& m) {
    return join(Arguments<T, 2>{detail::solid_fraction(phi), detail::granular_temperature(theta)}, domain(m));
  }

  // Hot path. Preconditions (asserted in debug builds): argument_domain, and each law's.
  template <class S, class T>
  FLUIDBED_HOST_DEVICE ConstitutiveValues<S> operator()(const S& phi, const S& theta,
                                                        const GranularMaterial<T>& m) const {
    FLUIDBED_EXPECTS(within(argument_domain(value_of(phi), value_of(theta), m)));
    const S g0 = radial_distribution(phi);
    return {g0,
            pressure(phi, theta, g0, m),
            shear_viscosity(phi, theta, g0, m),
            bulk_viscosity(phi, theta, g0, m),
            conductivity(phi, theta, g0, m),
            dissipation(phi, theta, g0, m)};
  }

  // Every value with ∂/∂φ (g0's slope included) and ∂/∂Θ, from one Dual evaluation.
  template <class T>
  FLUIDBED_HOST_DEVICE ConstitutiveValues<ValueAndDerivatives<T>> with_derivatives(const T& phi, const T& theta,
                                                                                   const GranularMaterial<T>& m) const {
    using D = Dual<T, 2>;
    const ConstitutiveValues<D> r = (*this)(D::variable(phi, 0), D::variable(theta, 1), m);
    const auto split = [](const D& x) { return ValueAndDerivatives<T>{x.value, x.derivative[0], x.derivative[1]}; };
    return {split(r.radial_distribution), split(r.pressure),     split(r.shear_viscosity),
            split(r.bulk_viscosity),      split(r.conductivity), split(r.dissipation)};
  }

  // Validates the state, the material and the laws' parameters (std::domain_error naming the
  // argument and its value), then evaluates.
  template <class T>
  ConstitutiveValues<T> checked(const T& phi, const T& theta, const GranularMaterial<T>& m) const {
    require_valid(phi, theta, m);
    return (*this)(phi, theta, m);
  }
  template <class T>
  ConstitutiveValues<ValueAndDerivatives<T>> checked_with_derivatives(const T& phi, const T& theta,
                                                                      const GranularMaterial<T>& m) const {
    require_valid(phi, theta, m);
    return with_derivatives(phi, theta, m);
  }

  // The local-equilibrium Θ with these laws (algebraic_temperature.hpp); with fluidbed::checked
  // also φ (before g0(φ) is evaluated) and every law's parameters are validated.
  template <class S, class T, ErrorPolicy Policy = Unchecked>
  FLUIDBED_HOST_DEVICE S algebraic_granular_temperature(const S& phi, const GranularMaterial<T>& m,
                                                        const StrainRate<S>& rate, const S& beta,
                                                        Policy policy = {}) const {
    if constexpr (std::same_as<Policy, Checked>) {
      require_within(checked_function, Arguments<T, 1>{detail::solid_fraction(value_of(phi))});
      require_laws_parameters();
    }
    return kinetic_theory::algebraic_granular_temperature(pressure, shear_viscosity, bulk_viscosity, dissipation, phi,
                                                          radial_distribution(phi), m, rate, beta, policy);
  }

  template <class T>
  FLUIDBED_HOST_DEVICE AlgebraicTemperatureSensitivities<T> algebraic_granular_temperature_with_sensitivities(
      const T& phi, const GranularMaterial<T>& m, const StrainRate<T>& rate, const T& beta) const {
    using D = Dual<T, 4>;
    const D theta = algebraic_granular_temperature(
        D::variable(phi, 0), m,
        StrainRate<D>{D::variable(rate.divergence, 2), D::variable(rate.deviatoric_contraction, 3)},
        D::variable(beta, 1));
    return {theta.value, theta.derivative[0], theta.derivative[1], theta.derivative[2], theta.derivative[3]};
  }

 private:
  static constexpr std::string_view checked_function = "kinetic_theory::ConstitutiveSet";

  template <class T>
  void require_valid(const T& phi, const T& theta, const GranularMaterial<T>& m) const {
    require_within(checked_function, argument_domain(phi, theta, m));
    require_laws_parameters();
  }

  void require_laws_parameters() const {
    detail::require_parameters(checked_function, radial_distribution);
    detail::require_parameters(checked_function, pressure);
    detail::require_parameters(checked_function, shear_viscosity);
    detail::require_parameters(checked_function, conductivity);
    detail::require_parameters(checked_function, bulk_viscosity);
    detail::require_parameters(checked_function, dissipation);
  }
};

// Deduction from the laws, e.g. ConstitutiveSet{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{},
// SyamlalConductivity{}}: explicit, since clang before 17 deduces no template arguments of an
// aggregate by itself (C++20's P1816).
template <class RadialDistribution, class Pressure, class ShearViscosity, class Conductivity>
ConstitutiveSet(RadialDistribution, Pressure, ShearViscosity, Conductivity)
    -> ConstitutiveSet<RadialDistribution, Pressure, ShearViscosity, Conductivity>;
template <class RadialDistribution, class Pressure, class ShearViscosity, class Conductivity, class BulkViscosity>
ConstitutiveSet(RadialDistribution, Pressure, ShearViscosity, Conductivity, BulkViscosity)
    -> ConstitutiveSet<RadialDistribution, Pressure, ShearViscosity, Conductivity, BulkViscosity>;
template <class RadialDistribution, class Pressure, class ShearViscosity, class Conductivity, class BulkViscosity,
          class Dissipation>
ConstitutiveSet(RadialDistribution, Pressure, ShearViscosity, Conductivity, BulkViscosity, Dissipation)
    -> ConstitutiveSet<RadialDistribution, Pressure, ShearViscosity, Conductivity, BulkViscosity, Dissipation>;

}  // namespace fluidbed::kinetic_theory
