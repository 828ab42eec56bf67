// fluidbed — Mazzei–Lettieri (2007) drag: exact Richardson–Zaki consistency.
#pragma once

#include <cmath>
#include <limits>
#include <string_view>
#include <type_traits>

#include "../core/dual.hpp"
#include "../settling/richardson_zaki.hpp"
#include "../single_particle/drag_coefficient.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

// Mazzei, L., Lettieri, P. (2007), "A drag force closure for uniformly dispersed
// fluidized suspensions", Chem. Eng. Sci. 62, 6129–6142, doi:10.1016/j.ces.2007.06.028;
// seed 000 §3.4.5 and Table 3.1:
//
//   β_classical = ¾ C_D(Re) ρ_f w (1 − ε)/d · ε^(−ψ_e(ε, Re))                  (3.65)
//   ψ_e = −ln φ_ML / ln ε,   φ_ML = [C_D(Re*)/C_D(Re)] ε^(2(1 − n_e(Re*)))     (3.57, 3.64)
//   Re* = Re / ε^(n_e(Re*))                                                   (3.53)
//   C_D(Re) = (0.63 + 4.8 Re^−½)²  (Dallavalle),  n_e from seed eq. 3.24,
//   Re = ρ_f ε w d / μ_f  (eq. 3.33).
//
// Native convention: classical. Re* is the terminal Reynolds number that Richardson–Zaki
// assigns to the state; the relation is implicit because n_e depends on Re*. With
// g(x) = x + n_e(eˣ) ln ε − ln Re, x = ln Re*, g' = 1 + Re* n_e'(Re*) ln ε ≥ 1 for ε ≤ 1,
// so the root is unique, bracketed by Re ε^−2.4 ≤ Re* ≤ Re ε^−4.8 (2.4 < n_e < 4.8); it is
// found by Halley's method in x (settling::richardson_zaki_terminal_reynolds, which
// solves the same relation for Re_t).
//
// Evaluated form. Because C_D(Re) Re φ_ML = C_D(Re*) Re* ε^(2 − n_e), eq. 3.65 equals
//   β_classical = ¾ μ_f (1 − ε)/d² · (0.63 √Re* + 4.8)² · ε^(1 − n_e(Re*)),
// which has no 0·∞ at w = 0 (β → 17.28 μ_f (1 − ε)/(d² ε^3.8)) and is exactly 0 at ε = 1.
// ψ_e itself is 0/0 at ε = 1; equivalent_exponent() returns its limit there.
//
// Property: at homogeneous equilibrium (eq. 3.28) this law gives Richardson–Zaki
// expansion u_s = u_t ε^n_e(Re_t) exactly, with Dallavalle's u_t: eq. 3.28 with this β is
// Dallavalle's terminal-velocity balance at U = u_s ε^−n_e, so Re* = Re_t (seed 000 Fig. 3.5).
// Validity: every ε in (0, 1] and Re, by construction, wherever eq. 3.24 and
// Dallavalle's C_D hold for the single particle.
struct MazzeiLettieri : DragLaw<MazzeiLettieri> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::classical;

  constexpr std::string_view name() const { return "MazzeiLettieri"; }
  constexpr std::string_view reference() const {
    return "Mazzei, L., Lettieri, P. (2007) Chem. Eng. Sci. 62, 6129-6142, doi:10.1016/j.ces.2007.06.028";
  }
  constexpr ValidityRange validity() const { return {0.0, 1.0, 0.0, std::numeric_limits<double>::infinity()}; }

  // Re* for a state (ε, Re), eq. 3.53. For S = Dual the derivatives follow from the
  // implicit function theorem: one Newton step taken in S from the converged root.
  template <class S>
  FLUIDBED_HOST_DEVICE static S effective_reynolds(const S& voidage, const S& re) {
    using T = value_type_of<S>;
    using std::exp;
    using std::pow;
    const T re_value = value_of(re);
    if (!(re_value > T(0))) return re * pow(voidage, FLUIDBED_DECIMAL(T, -4.8));  // Re* = Re ε^−4.8 as Re → 0
    // The relation's solve itself rather than settling::richardson_zaki_terminal_reynolds, which
    // asserts a finite Re: inside this law's domain Re = ρ_f ε w d/μ_f may overflow to +∞, where
    // the law's contract is a non-finite β for `checked` to report, not an assertion.
    const T e = value_of(voidage);
    const T re_star =
        e == T(1) ? re_value : exp(settling::solve_richardson_zaki_terminal_reynolds(re_value, e).log_terminal_reynolds);
    if constexpr (std::is_same_v<S, T>) {
      return re_star;
    } else {
      static_assert(is_dual<S>::value, "Re* derivatives are propagated through fluidbed::Dual");
      using std::log;
      const T log_re_star = log(re_star);
      const T slope = T(1) + re_star * settling::MazzeiExponent::slope(re_star) * T(log(value_of(voidage)));
      const S residual = log_re_star + settling::MazzeiExponent{}.exponent(re_star) * log(voidage) - log(re);
      S result = exp(log_re_star - residual / slope);
      result.value = re_star;  // the same value as the plain evaluation, bit for bit
      return result;
    }
  }

  // φ_ML(ε, Re) of eq. 3.57, as [(0.63√Re* + 4.8)/(0.63√Re + 4.8)]² ε^(2 − n_e(Re*)),
  // which uses Re/Re* = ε^n_e and is regular at Re = 0.
  template <class S>
  FLUIDBED_HOST_DEVICE static S voidage_function(const S& voidage, const S& re) {
    using std::pow;
    using std::sqrt;
    using T = value_type_of<S>;
    const S re_star = effective_reynolds(voidage, re);
    const S ratio = (FLUIDBED_DECIMAL(T, 0.63) * sqrt(re_star) + FLUIDBED_DECIMAL(T, 4.8)) /
                    (FLUIDBED_DECIMAL(T, 0.63) * sqrt(re) + FLUIDBED_DECIMAL(T, 4.8));
    return ratio * ratio * pow(voidage, 2 - settling::MazzeiExponent{}.exponent(re_star));
  }

  // ψ_e(ε, Re) = −ln φ_ML/ln ε (eq. 3.64). At ε = 1 the limit n_e (2 − D) − 2 with
  // D = 4.8/(0.63√Re + 4.8) (from Re* = Re ε^−n_e to first order in ln ε); → 2.80 for
  // Re → 0 and Re → ∞ (eqs. 3.68, 3.71).
  template <class S>
  FLUIDBED_HOST_DEVICE static S equivalent_exponent(const S& voidage, const S& re) {
    using std::log;
    using std::sqrt;
    if (voidage == S(1)) {
      using T = value_type_of<S>;
      const S d = FLUIDBED_DECIMAL(T, 4.8) / (FLUIDBED_DECIMAL(T, 0.63) * sqrt(re) + FLUIDBED_DECIMAL(T, 4.8));
      return settling::MazzeiExponent{}(re) * (2 - d) - 2;
    }
    return -log(voidage_function(voidage, re)) / log(voidage);
  }

  // A state with Re > 0 solved for Re* (plain floating point): what the hot paths of β and of
  // the elastic modulus (elastic/elastic_modulus.hpp) share. E = ε^(−n_e/2), so that
  // √Re* = √Re E (eq. 3.53) and ε^(1 − n_e) = ε E².
  template <class T>
  struct SolvedState {
    T root_reynolds;       // √Re
    T inverse_root_power;  // E
    T scaled_power;        // y = 0.175 Re*^¾
    T log_voidage;         // ln ε
    T exponent;            // n_e(Re*)
  };

  template <class T>
  FLUIDBED_HOST_DEVICE static SolvedState<T> solve_state(const T& re, const T& voidage) {
    using std::exp;
    using std::sqrt;
    const auto r = settling::solve_richardson_zaki_terminal_reynolds(re, voidage);
    const T n = settling::MazzeiExponent::of_scaled_power(r.scaled_power);
    return {sqrt(re), exp(T(-0.5) * n * r.log_voidage), r.scaled_power, r.log_voidage, n};
  }

  // β = ¾ μ_f (1 − ε) ε (0.63 √Re E² + 4.8 E)² / d² of a solved state: one exp after the solve.
  // Where a factor leaves the range of T while β does not (μ_f/d² → 0 against E = ε^(−n/2) → ∞,
  // e.g. ε = 1e-100, Re = 1e198 in double: E² = 1e240, (√Re E²)² = 1e438, β ~ 1e285), the
  // product is ∞ or NaN (∞·0); it is then taken as the exponential of the sum of the factors'
  // logarithms, each finite (ln E = −n ln ε/2), which is ∞ only where β itself is and 0 at ε = 1.
  template <class T>
  FLUIDBED_HOST_DEVICE static T beta_of_state(const SolvedState<T>& state, const T& voidage, const Fluid<T>& fluid,
                                              const T& diameter) {
    using std::exp;
    using std::isfinite;
    using std::log;
    using std::log1p;
    const T prefactor = T(0.75) * fluid.viscosity / (diameter * diameter);
    const T e = state.inverse_root_power;
    const T root = (FLUIDBED_DECIMAL(T, 0.63) * state.root_reynolds * e + FLUIDBED_DECIMAL(T, 4.8)) * e;
    const T beta = prefactor * (T(1) - voidage) * voidage * root * root;
    if (isfinite(beta)) return beta;
    const T log_e = T(-0.5) * state.exponent * state.log_voidage;  // (0.63 √Re E² + 4.8 E)² = E⁴ (0.63 √Re + 4.8/E)²
    return exp(log(T(0.75)) + log(fluid.viscosity) - T(2) * log(diameter) + log1p(-voidage) + state.log_voidage +
               T(4) * log_e +
               T(2) * log(FLUIDBED_DECIMAL(T, 0.63) * state.root_reynolds + FLUIDBED_DECIMAL(T, 4.8) / e));
  }

  // ∂β/∂ε and ∂β/∂w of a solved state, through the first-order variations (dual numbers of value
  // 0) of ln ε and ln Re: no second solve and no transcendental function. Writing
  // β = P (1 − ε) Q, P = ¾ μ_f/d², Q = ε^(1 − n) (0.63 √Re* + 4.8)², x = ln Re*, L = ln ε,
  // p = 1 + y (y = 0.175 Re*^¾, dn/dx = −1.8 y/p²), s = √Re*, R = 0.63 s + 4.8:
  //   δx     = (δ ln Re − n δL)/g',   g' = 1 − 1.8 L y/p²   implicit function theorem on g(x) = 0
  //   δ ln Q = (1 − n) δL + (0.63 s/R + 1.8 L y/p²) δx = (1 − n − k n) δL + k δ ln Re,
  //   k = (0.63 s p² + 1.8 L y R)/((p² − 1.8 L y) R):
  // one division on the path, and no 1 − r or 1 − 4.8/R that would lose ∂β/∂w's digits where
  // Re* → 0. y is held below 2^(max_exponent/5), so that p² s stays finite: beyond, the term
  // 1.8 L y/p² ≈ 1.8 L/y it stands for is below the rounding of c ≈ 1 (in double for every ε).
  template <class S, class T>
  FLUIDBED_HOST_DEVICE static S beta_with_derivatives(const SolvedState<T>& state, const T& beta, const S& voidage,
                                                      const S& re, const T& prefactor) {
    const T e = value_of(voidage);
    using std::ldexp;
    const T y_cap = ldexp(T(1), std::numeric_limits<T>::max_exponent / 5);
    const T y = state.scaled_power < y_cap ? state.scaled_power : y_cap;
    const T p2 = (T(1) + y) * (T(1) + y);
    const T y_slope = FLUIDBED_DECIMAL(T, 1.8) * state.log_voidage * y;  // 1.8 L y
    const T root_star = state.root_reynolds * state.inverse_root_power;  // √Re*
    const T root = FLUIDBED_DECIMAL(T, 0.63) * root_star + FLUIDBED_DECIMAL(T, 4.8);
    const T k = (FLUIDBED_DECIMAL(T, 0.63) * root_star * p2 + y_slope * root) / ((p2 - y_slope) * root);
    const S d_log_q = chain_rule(T(0), (T(1) - state.exponent - k * state.exponent) * (T(1) / e), voidage) +
                      chain_rule(T(0), k * (T(1) / value_of(re)), re);
    const T q = e * root * root * (state.inverse_root_power * state.inverse_root_power);
    S result = prefactor * (1 - voidage) * chain_rule(q, q, d_log_q);
    result.value = beta;  // the hot path's value, bit for bit
    return result;
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    using std::pow;
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    const T prefactor = T(0.75) * fluid.viscosity / (diameter * diameter);
    if (value_of(re) > T(0)) {
      const SolvedState<T> state = solve_state(value_of(re), value_of(voidage));
      const T beta = beta_of_state(state, value_of(voidage), fluid, diameter);
      if constexpr (std::is_same_v<S, T>)
        return beta;
      else
        return beta_with_derivatives(state, beta, voidage, re, prefactor);
    }
    // Re = 0: Re* = Re ε^−4.8, and n_e is held at its limit 4.8: both √Re* and n_e(Re*) have
    // infinite slopes there, and the √Re* one dominates (∂β/∂w = +∞, not ∞ − ∞).
    const S re_star = effective_reynolds(voidage, re);
    return prefactor * (1 - voidage) * single_particle::DallavalleCoefficient::cd_times_re(re_star) *
           pow(voidage, 1 - FLUIDBED_DECIMAL(T, 4.8));
  }
};

}  // namespace fluidbed::drag
