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
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "../core/config.hpp"
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
      S d = 0.5 * (gradient[i][j] + gradient[j][i]);
      if (i == j) d = d - trace / 3.0;
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
  if (!detail::is_finite_number(m.restitution) || !(m.restitution >= T(0)) || !(m.restitution <= T(1)))
    detail::throw_domain_error(function, "material.restitution", m.restitution, "must lie in [0, 1]");
}

// Validates φ ∈ [0, 1) and Θ ≥ 0 for the checked entry points.
template <class T>
void validate_state(std::string_view function, const T& solid_fraction, const T& granular_temperature) {
  if (!detail::is_finite_number(solid_fraction) || !(solid_fraction >= T(0)) || !(solid_fraction < T(1)))
    detail::throw_domain_error(function, "solid_fraction", solid_fraction, "must lie in [0, 1)");
  require_non_negative(function, "granular_temperature", granular_temperature);
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

inline constexpr double sqrt_pi = 1.7724538509055160273;

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

// φ² ρ_s d g0 (1 + e) √(Θ/π): the collisional transfer common to the Gidaspow/Lun shear
// viscosity (× 4/5), Lun's bulk viscosity (× 4/3) and the collisional conductivity (× 2).
template <class S, class T>
FLUIDBED_HOST_DEVICE S collisional_transfer(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) {
  using std::sqrt;
  return (m.density * m.diameter * (1.0 + m.restitution) / sqrt_pi) * (phi * phi * g0 * sqrt(theta));
}

}  // namespace detail

// The shape of a transport coefficient with a kinetic (streaming) and a collisional part,
// the latter collisional_factor × φ² ρ_s d g0 (1 + e) √(Θ/π) (Gidaspow's collisional
// viscosity: 4/5, conductivity: 2). Law provides kinetic(φ, Θ, g0, m); the call is the sum.
template <class Law, double collisional_factor>
struct KineticPlusCollisional {
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S collisional(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    return collisional_factor * detail::collisional_transfer(phi, theta, g0, m);
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

}  // namespace fluidbed::kinetic_theory
