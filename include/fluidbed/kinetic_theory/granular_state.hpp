// fluidbed — kinetic theory of granular flow (KTGF): the state, the conventions and the
// pieces every constitutive function shares.
//
// Conventions of the whole kinetic_theory/ folder
// * φ (`solid_fraction`) is the solids volume fraction, Θ (`granular_temperature`) the
//   granular temperature Θ = ⟨C²⟩/3 [m² s⁻²], e the normal restitution coefficient.
// * Every pressure, viscosity, conductivity and energy rate is per unit volume of
//   SUSPENSION (seeds 002 and 004, OpenFOAM's ρ_s ν_s, MFiX). FLUENT and seed 001 quote
//   shear and bulk viscosities per unit volume of the solids PHASE: divide ours by φ.
// * Signs: p_s, μ_s, λ_s, κ_s and the collisional dissipation γ are ≥ 0. The granular
//   energy balance they enter is (seed 001 eq. 30, seed 002 eq. 61)
//     (3/2)[∂(φρ_sΘ)/∂t + ∇·(φρ_sΘu_s)] = (−p_s I + τ_s):∇u_s + ∇·(κ_s∇Θ) − γ + J,
//     τ_s = 2μ_s D + (λ_s − (2/3)μ_s)(∇·u_s) I,   D = ½(∇u_s + ∇u_sᵀ),
//   where J (gas_exchange.hpp) is signed: the gas sink −3βΘ is negative.
// * Every function is a template on its scalar S: S = T gives the value, S = Dual<T, N>
//   the value and exact partial derivatives (core/dual.hpp). The radial distribution
//   function g0 is an argument, so that a derivative in φ carries dg0/dφ through the
//   chain rule whichever g0 the host picked (radial_distribution.hpp).
// * One shape per kind of closure, from a CRTP base (below): each law writes its kernel
//   `kernel(args…)` (templated on the scalar), name(), reference(), validity() and, if it has
//   parameters, parameter_domain(); the base gives the hot path law(args…) (asserting
//   within(domain) in debug builds only), law.with_derivatives(…), law.checked(args…) and
//   law.checked_with_derivatives(…) (throwing std::domain_error naming the argument, its
//   value and the law, "kinetic_theory::<name>"). Each argument's domain is declared once
//   (the argument_domain of the shape, the law's parameter_domain): the assertion and the
//   exception both derive from it.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/constants.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"

namespace fluidbed::kinetic_theory {

// The particles' properties the constitutive functions need.
template <class T>
struct GranularMaterial {
  T diameter;     // d [m]
  T density;      // ρ_s [kg m⁻³], material density
  T restitution;  // e, normal restitution coefficient in [0, 1]
};

// The two invariants of the rate-of-strain tensor D = ½(∇u + ∇uᵀ) that isotropic closures
// use: its trace and the contraction of its deviator D' = D − (tr D/3) I with itself.
// Schaeffer's I_2D (seed 001 eq. 39) is ½ D':D'; in simple shear u_x = γ̇ y,
// D':D' = γ̇²/2.
template <class S>
struct StrainRate {
  S divergence;              // tr D = ∇·u [s⁻¹]
  S deviatoric_contraction;  // D':D' [s⁻²], ≥ 0
};

// The invariants from a velocity gradient, gradient[i][j] = ∂u_j/∂x_i (either index order
// gives the same invariants).
template <class S>
FLUIDBED_HOST_DEVICE constexpr StrainRate<S> strain_rate_of(const std::array<std::array<S, 3>, 3>& gradient) {
  const S trace = gradient[0][0] + gradient[1][1] + gradient[2][2];
  S contraction(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      S d = value_type_of<S>(0.5) * (gradient[i][j] + gradient[j][i]);
      if (i == j) d = d - trace / 3;
      contraction = contraction + d * d;
    }
  return {trace, contraction};
}

// A value with its partial derivatives in φ and Θ: law(φ, Θ, g0, material).with_derivatives.
template <class T>
struct ValueAndDerivatives {
  T value;
  T d_solid_fraction;        // ∂/∂φ at fixed Θ (through g0(φ) as well)
  T d_granular_temperature;  // ∂/∂Θ at fixed φ
};

// A value with its derivative in φ: g(φ).with_derivatives (radial distributions, frictional
// pressures).
template <class T>
struct ValueAndSlope {
  T value;
  T d_solid_fraction;  // dg/dφ
};

// The domains of the arguments the closures share, declared once: d, ρ_s > 0, e ∈ [0, 1].
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 3> domain(const GranularMaterial<T>& m) {
  return {{{"material.diameter", m.diameter, domains::positive<T>()},
           {"material.density", m.density, domains::positive<T>()},
           {"material.restitution", m.restitution, domains::closed(T(0), T(1))}}};
}

// ∇·u finite, D':D' ≥ 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 2> domain(const StrainRate<T>& rate) {
  return {{{"rate.divergence", rate.divergence, domains::finite<T>()},
           {"rate.deviatoric_contraction", rate.deviatoric_contraction, domains::non_negative<T>()}}};
}

namespace detail {

// The references cited by several closures of this folder.
namespace references {
inline constexpr std::string_view gidaspow_1994 =
    "Gidaspow, D. (1994) Multiphase Flow and Fluidization, Academic Press";
inline constexpr std::string_view lun_1984 =
    "Lun, C.K.K., Savage, S.B., Jeffrey, D.J. & Chepurniy, N. (1984) J. Fluid Mech. 140, 223-256, "
    "doi:10.1017/S0022112084000586";
inline constexpr std::string_view syamlal_rogers_obrien_1993 =
    "Syamlal, M., Rogers, W. & O'Brien, T.J. (1993) MFIX Documentation: Theory Guide, DOE/METC-94/1004";
inline constexpr std::string_view schaeffer_1987 =
    "Schaeffer, D.G. (1987) J. Differential Equations 66, 19-50, doi:10.1016/0022-0396(87)90038-6";
inline constexpr std::string_view hrenya_sinclair_1997 =
    "Hrenya, C.M. & Sinclair, J.L. (1997) AIChE J. 43, 853-869, doi:10.1002/aic.690430402";
}  // namespace references

// The validity of the constitutive laws of kinetic theory: derived for a dense gas of
// inelastic spheres without a fitted range; stated as φ up to random close packing, 0.64.
inline constexpr Validity<1> dense_gas_validity{{{"solid_fraction", 0.0, 0.64}}};

// The state arguments the shapes share, each with its domain: φ ∈ [0, 1), Θ ≥ 0, g0 > 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> solid_fraction(const T& phi) {
  return {"solid_fraction", phi, domains::closed_open(T(0), T(1))};
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> granular_temperature(const T& theta) {
  return {"granular_temperature", theta, domains::non_negative<T>()};
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> radial_distribution_value(const T& g0) {
  return {"g0", g0, domains::positive<T>()};
}

// A packing limit φ_max ∈ (0, 1] and the margin 0 < margin < φ_max below it where a singular
// factor is continued linearly (a zero margin would take the slope at the pole).
FLUIDBED_HOST_DEVICE constexpr Arguments<double, 2> packing_domain(double max_packing, double packing_margin) {
  return {{{"max_packing", max_packing, domains::half_open(0.0, 1.0)},
           {"packing_margin", packing_margin, domains::open(0.0, max_packing)}}};
}

// The plain value of an argument, for its domain: a dual number's value, the values of a
// strain rate of dual numbers; any other argument as it is.
template <class X>
FLUIDBED_HOST_DEVICE constexpr const auto& plain(const X& x) {
  return value_of(x);
}
template <class S>
FLUIDBED_HOST_DEVICE constexpr StrainRate<value_type_of<S>> plain(const StrainRate<S>& rate) {
  return {value_of(rate.divergence), value_of(rate.deviatoric_contraction)};
}

// The law's own parameters in their domain (true for a law without parameters).
template <class Law>
FLUIDBED_HOST_DEVICE constexpr bool parameters_within(const Law& law) {
  if constexpr (requires { law.parameter_domain(); })
    return within(law.parameter_domain());
  else
    return true;
}

// The function a checked entry point names in its messages: "kinetic_theory::<law name>".
template <class Law>
std::string checked_function_name(const Law& law) {
  return "kinetic_theory::" + std::string(law.name());
}

// Throws std::domain_error naming `function` unless the law's parameters lie in their domain.
template <class Law>
void require_parameters(std::string_view function, const Law& law) {
  if constexpr (requires { law.parameter_domain(); }) require_within(function, law.parameter_domain());
}

// f(x) for x ≤ x_c and its tangent at x_c beyond: f(x_c) + f'(x_c)(x − x_c). The closures
// use it for factors that are singular at a packing limit (documented per closure): the
// result is finite for every x, continuous with a continuous slope, and the derivative
// a Dual carries is the derivative of the continued function. f must accept any scalar
// type (a generic lambda); its slope at x_c is taken with a one-component Dual.
template <class S, class F>
FLUIDBED_HOST_DEVICE S continued_linearly_above(const S& x, const value_type_of<S>& x_c, const F& f) {
  using T = value_type_of<S>;
  if (!(value_of(x) > x_c)) return f(x);
  const Dual<T, 1> at = f(Dual<T, 1>::variable(x_c, 0));
  return at.value + at.derivative[0] * (x - x_c);
}

// max(x, 0) for a value with derivatives: the derivative is that of the branch taken.
template <class S>
FLUIDBED_HOST_DEVICE constexpr S non_negative_part(const S& x) {
  return x > 0 ? x : S(0);
}

// φ² ρ_s d g0 (1 + e) √(Θ/π): the collisional transfer common to the Gidaspow/Lun shear
// viscosity (× 4/5), Lun's bulk viscosity (× 4/3) and the collisional conductivity (× 2).
template <class S, class T>
FLUIDBED_HOST_DEVICE S collisional_transfer(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) {
  using std::sqrt;
  return (m.density * m.diameter * (1 + m.restitution) / numbers::sqrt_pi<T>()) * (phi * phi * g0 * sqrt(theta));
}

}  // namespace detail

// The entry points every kinetic-theory closure shares (CRTP). Law provides name() and
//   static constexpr Arguments<T, N> argument_domain(args…)   (plain scalars: the shape's)
//   template <class S, …> … kernel(args…) const               (S a scalar or a Dual)
//   constexpr Arguments<double, K> parameter_domain() const   (if it has parameters)
template <class Law>
struct KineticTheoryLaw {
  // Hot path: the arguments and parameters in their domains are asserted in debug builds only.
  template <class... Args>
  FLUIDBED_HOST_DEVICE constexpr auto operator()(const Args&... args) const {
    FLUIDBED_EXPECTS(within(Law::argument_domain(detail::plain(args)...)) && detail::parameters_within(self()));
    return self().kernel(args...);
  }

  // Checked entry point: throws std::domain_error naming the first argument or parameter out
  // of its domain, its value and the law, then evaluates.
  template <class... Args>
  auto checked(const Args&... args) const {
    require_valid(args...);
    return self().kernel(args...);
  }

  // Throws as `checked` would, without evaluating.
  template <class... Args>
  void require_valid(const Args&... args) const {
    const std::string function = detail::checked_function_name(self());
    require_within(function, Law::argument_domain(args...));
    detail::require_parameters(function, self());
  }

 protected:
  FLUIDBED_HOST_DEVICE constexpr const Law& self() const { return static_cast<const Law&>(*this); }
};

// Value and (∂/∂φ, ∂/∂Θ) of any callable f(φ, Θ) written for a generic scalar, e.g. a sum of
// laws or a host's own closure:
//   with_derivatives([&](auto phi, auto theta) { return law(phi, theta, rdf(phi), m); }, φ, Θ)
// (the same as law.with_derivatives(φ, Θ, rdf, m)).
template <class T, class F>
FLUIDBED_HOST_DEVICE ValueAndDerivatives<T> with_derivatives(const F& f, const T& solid_fraction,
                                                             const T& granular_temperature) {
  using D = Dual<T, 2>;
  const D r = f(D::variable(solid_fraction, 0), D::variable(granular_temperature, 1));
  return {r.value, r.derivative[0], r.derivative[1]};
}

// The shape g(φ): the radial distribution functions and the frictional pressures. Law
// provides kernel(φ) templated on the scalar.
template <class Law>
struct SolidFractionLaw : KineticTheoryLaw<Law> {
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 1> argument_domain(const T& phi) {
    return {detail::solid_fraction(phi)};
  }

  // g and dg/dφ (hot path).
  template <class T>
  FLUIDBED_HOST_DEVICE ValueAndSlope<T> with_derivatives(const T& phi) const {
    const Dual<T, 1> g = (*this)(Dual<T, 1>::variable(phi, 0));
    return {g.value, g.derivative[0]};
  }
  template <class T>
  ValueAndSlope<T> checked_with_derivatives(const T& phi) const {
    this->require_valid(phi);
    return with_derivatives(phi);
  }
};

// The shape law(φ, Θ, g0, material): granular pressures, shear and bulk viscosities,
// conductivities, dissipation. Law provides kernel(φ, Θ, g0, material) templated on the scalar.
template <class Law>
struct ConstitutiveLaw : KineticTheoryLaw<Law> {
  // φ ∈ [0, 1), Θ ≥ 0, g0 > 0, material as domain(GranularMaterial).
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 6> argument_domain(const T& phi, const T& theta, const T& g0,
                                                                          const GranularMaterial<T>& m) {
    return join(Arguments<T, 3>{detail::solid_fraction(phi), detail::granular_temperature(theta),
                                detail::radial_distribution_value(g0)},
                kinetic_theory::domain(m));
  }

  // The value with ∂/∂φ (g0's slope included: `rdf` is the radial distribution, called with
  // the dual φ) and ∂/∂Θ (hot path).
  template <class T, class RadialDistribution>
  FLUIDBED_HOST_DEVICE ValueAndDerivatives<T> with_derivatives(const T& phi, const T& theta,
                                                               const RadialDistribution& rdf,
                                                               const GranularMaterial<T>& m) const {
    return kinetic_theory::with_derivatives(
        [&](const auto& p, const auto& t) { return (*this)(p, t, rdf(p), m); }, phi, theta);
  }

  // Checked: the radial distribution's argument and parameters (rdf.checked), then this law's.
  template <class T, class RadialDistribution>
  ValueAndDerivatives<T> checked_with_derivatives(const T& phi, const T& theta, const RadialDistribution& rdf,
                                                  const GranularMaterial<T>& m) const {
    this->require_valid(phi, theta, rdf.checked(phi), m);
    return with_derivatives(phi, theta, rdf, m);
  }
};

// The shape of a transport coefficient with a kinetic (streaming) and a collisional part,
// the latter (numerator/denominator) × φ² ρ_s d g0 (1 + e) √(Θ/π) (Gidaspow's collisional
// viscosity: 4/5, conductivity: 2). Law provides kinetic(φ, Θ, g0, m); the call is the sum.
// The factor is a ratio of integers: a floating-point template argument would need clang 18 or later.
template <class Law, int numerator, int denominator>
struct KineticPlusCollisional : ConstitutiveLaw<Law> {
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S collisional(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    FLUIDBED_EXPECTS(within(ConstitutiveLaw<Law>::argument_domain(value_of(phi), value_of(theta), value_of(g0), m)));
    return value_type_of<S>(numerator) / denominator * detail::collisional_transfer(phi, theta, g0, m);
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    return this->self().kinetic(phi, theta, g0, m) + collisional(phi, theta, g0, m);
  }
};

}  // namespace fluidbed::kinetic_theory
