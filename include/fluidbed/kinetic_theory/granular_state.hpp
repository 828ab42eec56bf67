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
// * Hot path and checked entry point. law(args…) asserts its documented preconditions in
//   debug builds only; evaluate_checked(law, args…), with the same arguments, validates
//   them and the law's own parameters and throws std::domain_error naming the argument and
//   its value. The generic forms below serve every law of the shapes g0(φ) (and the
//   frictional pressures p_f(φ)) and law(φ, Θ, g0, material); the other shapes have their
//   own overloads next to the law. ConstitutiveSet::checked validates a whole set.
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <string>
#include <string_view>

#include "../core/config.hpp"
#include "../core/constants.hpp"
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

// A value with its partial derivatives in φ and Θ.
template <class T>
struct ValueAndDerivatives {
  T value;
  T d_solid_fraction;        // ∂/∂φ at fixed Θ (through g0(φ) as well)
  T d_granular_temperature;  // ∂/∂Θ at fixed φ
};

// Validates the material for the checked entry points; `function` names the caller.
template <class T>
void validate(std::string_view function, const GranularMaterial<T>& m) {
  require_positive(function, "material.diameter", m.diameter);
  require_positive(function, "material.density", m.density);
  require_in_closed(function, "material.restitution", m.restitution, T(0), T(1));
}

// Validates φ ∈ [0, 1) for the checked entry points.
template <class T>
void validate_solid_fraction(std::string_view function, const T& solid_fraction) {
  require_in_closed_open(function, "solid_fraction", solid_fraction, T(0), T(1));
}

// Validates φ ∈ [0, 1) and Θ ≥ 0 for the checked entry points.
template <class T>
void validate_state(std::string_view function, const T& solid_fraction, const T& granular_temperature) {
  validate_solid_fraction(function, solid_fraction);
  require_non_negative(function, "granular_temperature", granular_temperature);
}

// Validates the strain-rate invariants (∇·u finite, D':D' ≥ 0) for the checked entry points.
template <class T>
void validate(std::string_view function, const StrainRate<T>& rate) {
  require_finite(function, "rate.divergence", rate.divergence);
  require_non_negative(function, "rate.deviatoric_contraction", rate.deviatoric_contraction);
}

// Validates a law's own parameters (a maximum packing, a length scale, …) for the checked
// entry points. Laws with parameters provide a member validate(function); the others have
// nothing to validate.
template <class Law>
void validate_parameters(std::string_view function, const Law& law) {
  if constexpr (requires { law.validate(function); }) law.validate(function);
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

template <class S>
struct scalar_of {
  using type = S;
};
template <class T, int N>
struct scalar_of<Dual<T, N>> {
  using type = T;
};
// The plain floating type under S (T for Dual<T, N>).
template <class S>
using scalar_of_t = typename scalar_of<S>::type;

// f(x) for x ≤ x_c and its tangent at x_c beyond: f(x_c) + f'(x_c)(x − x_c). The closures
// use it for factors that are singular at a packing limit (documented per closure): the
// result is finite for every x, continuous with a continuous slope, and the derivative
// a Dual carries is the derivative of the continued function. f must accept any scalar
// type (a generic lambda); its slope at x_c is taken with a one-component Dual.
template <class S, class F>
FLUIDBED_HOST_DEVICE S continued_linearly_above(const S& x, const scalar_of_t<S>& x_c, const F& f) {
  using T = scalar_of_t<S>;
  if (!(value_of(x) > x_c)) return f(x);
  const Dual<T, 1> at = f(Dual<T, 1>::variable(x_c, 0));
  return at.value + at.derivative[0] * (x - x_c);
}

// max(x, 0) for a value with derivatives: the derivative is that of the branch taken.
template <class S>
FLUIDBED_HOST_DEVICE constexpr S non_negative_part(const S& x) {
  return x > 0 ? x : S(0);
}

// The hot-path preconditions shared by the laws, as predicates for FLUIDBED_EXPECTS (no
// exceptions, usable in device code; NaN fails every comparison). S may be a Dual.
template <class S>
FLUIDBED_HOST_DEVICE constexpr bool valid_solid_fraction(const S& phi) {
  return value_of(phi) >= 0 && value_of(phi) < 1;
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr bool valid_material(const GranularMaterial<T>& m) {
  return m.diameter > T(0) && m.density > T(0) && m.restitution >= T(0) && m.restitution <= T(1);
}

// The preconditions of law(φ, Θ, g0, material): φ ∈ [0, 1), Θ ≥ 0, g0 > 0, material valid.
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr bool valid_closure_arguments(const S& phi, const S& theta, const S& g0,
                                                            const GranularMaterial<T>& m) {
  return valid_solid_fraction(phi) && value_of(theta) >= 0 && value_of(g0) > 0 && valid_material(m);
}

// A packing limit φ_max ∈ (0, 1] and the margin 0 < margin < φ_max below it where a
// singular factor is continued linearly (a zero margin would take the slope at the pole).
FLUIDBED_HOST_DEVICE constexpr bool valid_packing(double max_packing, double packing_margin) {
  return max_packing > 0 && max_packing <= 1 && packing_margin > 0 && packing_margin < max_packing;
}

inline void validate_packing(std::string_view function, double max_packing, double packing_margin) {
  require_in_half_open(function, "max_packing", max_packing, 0.0, 1.0);
  require_in_open(function, "packing_margin", packing_margin, 0.0, max_packing);
}

// The function a checked entry point names in its messages: "kinetic_theory::<law name>".
template <class Law>
std::string checked_function_name(const Law& law) {
  return "kinetic_theory::" + std::string(law.name());
}

// φ² ρ_s d g0 (1 + e) √(Θ/π): the collisional transfer common to the Gidaspow/Lun shear
// viscosity (× 4/5), Lun's bulk viscosity (× 4/3) and the collisional conductivity (× 2).
template <class S, class T>
FLUIDBED_HOST_DEVICE S collisional_transfer(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) {
  using std::sqrt;
  return (m.density * m.diameter * (1 + m.restitution) / numbers::sqrt_pi<T>()) * (phi * phi * g0 * sqrt(theta));
}

}  // namespace detail

// The shape of a transport coefficient with a kinetic (streaming) and a collisional part,
// the latter (numerator/denominator) × φ² ρ_s d g0 (1 + e) √(Θ/π) (Gidaspow's collisional
// viscosity: 4/5, conductivity: 2). Law provides kinetic(φ, Θ, g0, m); the call is the sum.
// The factor is a ratio of integers: a floating-point template argument would need clang 18 or later.
template <class Law, int numerator, int denominator>
struct KineticPlusCollisional {
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S collisional(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    FLUIDBED_EXPECTS(detail::valid_closure_arguments(phi, theta, g0, m));
    return value_type_of<S>(numerator) / denominator * detail::collisional_transfer(phi, theta, g0, m);
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S operator()(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    return static_cast<const Law&>(*this).kinetic(phi, theta, g0, m) + collisional(phi, theta, g0, m);
  }
};

// Value and (∂/∂φ, ∂/∂Θ) of any callable f(φ, Θ) written for a generic scalar: the usual
// way to get a closure's derivatives, e.g.
//   with_derivatives([&](auto phi, auto theta) { return law(phi, theta, rdf(phi), m); }, φ, Θ)
template <class T, class F>
FLUIDBED_HOST_DEVICE ValueAndDerivatives<T> with_derivatives(const F& f, const T& solid_fraction,
                                                             const T& granular_temperature) {
  using D = Dual<T, 2>;
  const D r = f(D::variable(solid_fraction, 0), D::variable(granular_temperature, 1));
  return {r.value, r.derivative[0], r.derivative[1]};
}

// The calling shapes served by the generic checked entry points below.
template <class Law, class T>
concept FractionLaw = requires(const Law& law, const T& phi) {
  { law(phi) } -> std::convertible_to<T>;
};
template <class Law, class T>
concept ClosureLaw = requires(const Law& law, const T& x, const GranularMaterial<T>& m) {
  { law(x, x, x, m) } -> std::convertible_to<T>;
};

// Checked entry point of the laws g(φ): the radial distribution functions and the
// frictional pressures. Throws std::domain_error unless φ ∈ [0, 1) and the law's parameters
// are valid.
template <class T, FractionLaw<T> Law>
T evaluate_checked(const Law& law, const T& phi) {
  const std::string function = detail::checked_function_name(law);
  validate_solid_fraction(function, phi);
  validate_parameters(function, law);
  return law(phi);
}

// Checked entry point of the closures law(φ, Θ, g0, material): granular pressures, shear and
// bulk viscosities, conductivities, dissipation. Throws std::domain_error unless φ ∈ [0, 1),
// Θ ≥ 0, g0 > 0, the material and the law's parameters are valid.
template <class T, ClosureLaw<T> Law>
T evaluate_checked(const Law& law, const T& phi, const T& theta, const T& g0, const GranularMaterial<T>& m) {
  const std::string function = detail::checked_function_name(law);
  validate_state(function, phi, theta);
  require_positive(function, "g0", g0);
  validate(function, m);
  validate_parameters(function, law);
  return law(phi, theta, g0, m);
}

}  // namespace fluidbed::kinetic_theory
