// fluidbed — Koch–Hill drag: the Hill, Koch & Ladd (2001) lattice-Boltzmann fits as
// extended by Benyahia, Syamlal & O'Brien (2006) (MFiX KOCH_HILL).
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../properties.hpp"
#include "dimensionless_force.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

// Hill, R.J., Koch, D.L., Ladd, A.J.C. (2001), J. Fluid Mech. 448, 213–241 ("The first
// effects of fluid inertia on flows in ordered and random arrays of spheres") and 243–278
// ("Moderate-Reynolds-number flows in ordered and random arrays of spheres"); extended to
// all φ and Re by
// Benyahia, S., Syamlal, M., O'Brien, T.J. (2006), "Extension of Hill–Koch–Ladd drag
// correlation over all ranges of Reynolds number and solids volume fraction", Powder
// Technol. 162, 166–174, doi:10.1016/j.powtec.2005.12.014. This is that extension, in the
// form MFiX implements it (DRAG_KOCH_HILL in model/drag_gs.f, MFiX 25.2.1):
//
//   Re_h = Re/2 = ρ_f ε w d/(2 μ_f)   (Hill's Reynolds number: radius, superficial slip)
//   w_b  = exp(−10 (0.4 − φ)/φ)       (blend towards the dense Carman form, = 1 at φ = 0.4)
//   R(a, b, c) = [1 + 3√(φ/2) + (135/64) φ ln φ + a φ] / [1 + 0.681 φ + b φ² + c φ³]
//   F0 = (1 − w_b) R(17.14, −8.48, 8.16) + w_b 10φ/ε³   (0.01 < φ < 0.4);  10φ/ε³ (φ ≥ 0.4)
//   F1 = √(2/φ)/40  (0.01 < φ ≤ 0.1);   0.11 + 5.1·10⁻⁴ e^(11.6 φ)  (φ > 0.1)
//   F2 = (1 − w_b) R(17.89, −11.03, 15.41) + w_b 10φ/ε³   (φ < 0.4);   10φ/ε³ (φ ≥ 0.4)
//   F3 = 0.9351 φ + 0.03667  (φ < 0.0953);   0.0673 + 0.212 φ + 0.0232/ε⁵  (φ ≥ 0.0953)
//   φ > 0.01:  F = F0 + F1 Re_h²  for Re_h ≤ Re_T = [F3 + √(F3² − 4 F1 (F0 − F2))]/(2 F1),
//              F = F2 + F3 Re_h   above;
//   φ ≤ 0.01:  F = 1 + 3 Re_h/8   for Re_h ≤ Re_T1 = (F2 − 1)/(3/8 − F3),
//              F = F2 + F3 Re_h   above;
//   β_pressure_gradient = 18 μ_f ε² φ F / d².
//
// Native convention: pressure_gradient. F is Hill's TOTAL force normalisation (it includes
// the mean-pressure-gradient share; dimensionless_force.hpp), hence ε² (seed 002 §II.D).
// The constants (17.14; 17.89, −11.03, 15.41; F1; F3's dilute branch; the switches) are
// those of MFiX's DRAG_KOCH_HILL, which cites Benyahia et al. (2006); the paper itself
// could not be consulted here.
//
// How this differs from the original Hill–Koch–Ladd form (CFDEMcoupling KochHillDrag,
// Lethe; seed 002 §III.D.1): HKL has 16.14 where F0 here has 17.14, uses F0 for φ < 0.4
// without blending, has no quadratic low-Re term and no separate F2:
// β = 18 μ_f ε² φ (F0 + F3 Re_h)/d² (Lethe writes 8.14 for 8.16). At φ = 0.2, air,
// d = 500 µm, w = 0.5 m/s, HKL gives 1065 and this law 1182 kg m⁻³ s⁻¹ (both evaluated
// as the two codes write them).
// Seed 002 prints the HKL Stokes coefficient A_o with the (135/64)φ ln φ term missing its
// logarithm and a duplicated middle case (§III.D.1), and its eq. (47) is HKL's linear law
// F2 + F3 Re_h in Ergun form with A_2 = A_o (the 9 = 18/2 there is Re_h = Re/2).
//
// Switches and limits. β is continuous across Re_T (the larger root of the two branches'
// difference) and across Re_T1. The discriminant F3² − 4 F1 (F0 − F2) never vanishes for
// φ > 0.01: F0 − F2 < 0 except for 0.3698 < φ < 0.4, where F3² − 4 F1 (F0 − F2) ≥ 0.23 F3²
// (minimum at φ ≈ 0.387, found on a 10⁻⁵ grid of (0, 1) in 30-digit arithmetic); for
// φ ≥ 0.4 it is F3². So Re_T is always real and positive: no fallback is needed (MFiX
// prints "neg sqrt" for this case). In φ: F0 and F2 are continuous at 0.4 (w_b = 1 there)
// with a jump in slope; F1 jumps by 0.16 % at 0.1 and F3 by 0.002 % at 0.0953; at φ = 0.01
// the Stokes limit jumps from 1 (dilute) to F0(0.01) = 1.279, as in MFiX (β ∝ φ keeps the
// absolute jump small). At ε = 1 (φ = 0) F = 1 + 0.03667 Re_h for Re > 0, F = 1 at Re = 0.
// At w = 0 β is the finite Stokes value 18 μ_f ε² φ F0/d² (F = 1 for φ ≤ 0.01); MFiX returns 0.
// Validity: HKL's simulations cover random arrays up to φ ≈ 0.6 and moderate Re (Re_h up
// to O(100)); Benyahia et al. extrapolate to all φ and Re.
struct KochHill : DragLaw<KochHill> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;
  // φ ≤ this: dilute branch
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T dilute_solid_fraction() {
    return FLUIDBED_DECIMAL(T, 0.01);
  }
  // φ ≥ this: Carman form 10φ/ε³
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T dense_solid_fraction() {
    return FLUIDBED_DECIMAL(T, 0.4);
  }

  constexpr std::string_view name() const { return "KochHill"; }
  constexpr std::string_view reference() const {
    return "Benyahia, S., Syamlal, M., O'Brien, T.J. (2006) Powder Technol. 162, 166-174, "
           "doi:10.1016/j.powtec.2005.12.014; Hill, R.J., Koch, D.L., Ladd, A.J.C. (2001) J. Fluid Mech. 448, "
           "213-241 and 243-278";
  }
  constexpr ValidityRange validity() const { return {0.4, 0.99, 0.0, 200.0}; }

  // F0(φ): zero-Re intercept of the low-Re branch (defined for φ > 0).
  template <class S>
  FLUIDBED_HOST_DEVICE static S f0(const S& phi) {
    return intercepts(phi).low;
  }

  // F1(φ): coefficient of Re_h² of the low-Re branch (defined for φ > 0).
  template <class S>
  FLUIDBED_HOST_DEVICE static S f1(const S& phi) {
    using std::exp;
    using std::sqrt;
    using T = value_type_of<S>;
    if (phi <= FLUIDBED_DECIMAL(T, 0.1)) return sqrt(2 / phi) / 40;
    return FLUIDBED_DECIMAL(T, 0.11) + FLUIDBED_DECIMAL(T, 5.1e-4) * exp(FLUIDBED_DECIMAL(T, 11.6) * phi);
  }

  // F2(φ): zero-Re intercept of the high-Re linear branch (defined for φ >= 0).
  template <class S>
  FLUIDBED_HOST_DEVICE static S f2(const S& phi) {
    return intercepts(phi).high;
  }

  // F3(φ): slope in Re_h of the high-Re linear branch.
  template <class S>
  FLUIDBED_HOST_DEVICE static S f3(const S& phi) {
    using T = value_type_of<S>;
    if (phi < FLUIDBED_DECIMAL(T, 0.0953)) return FLUIDBED_DECIMAL(T, 0.9351) * phi + FLUIDBED_DECIMAL(T, 0.03667);
    const S eps = 1 - phi;
    return FLUIDBED_DECIMAL(T, 0.0673) + FLUIDBED_DECIMAL(T, 0.212) * phi +
           FLUIDBED_DECIMAL(T, 0.0232) / ((eps * eps) * (eps * eps) * eps);
  }

  // Re_h where the branches meet: Re_T (φ > 0.01) or Re_T1 (φ ≤ 0.01).
  template <class S>
  FLUIDBED_HOST_DEVICE static S transition_reynolds(const S& phi) {
    using T = value_type_of<S>;
    const Intercepts<S> f = intercepts(phi);
    if (phi <= dilute_solid_fraction<T>()) return dilute_transition(f.high, f3(phi));
    return dense_transition(f.low, f1(phi), f.high, f3(phi));
  }

  // F(φ, Re), total-force normalisation; Re = ρ_f ε w d / μ_f (halved inside). Each F_i once,
  // formed with one derivative (single_variable, core/dual.hpp); the transition, which only
  // chooses the branch, without any.
  template <class S>
  FLUIDBED_HOST_DEVICE static S dimensionless_force(const S& phi, const S& re) {
    using T = value_type_of<S>;
    const S re_h = T(0.5) * re;
    const auto x = single_variable(phi);
    const auto f = intercepts(x);
    const auto high_slope = f3(x);
    if (phi <= dilute_solid_fraction<T>()) {
      if (value_of(re_h) > dilute_transition(value_of(f.high), value_of(high_slope)))
        return of_single_variable(f.high, phi) + of_single_variable(high_slope, phi) * re_h;
      return 1 + T(0.375) * re_h;
    }
    const auto low_curvature = f1(x);
    if (value_of(re_h) >
        dense_transition(value_of(f.low), value_of(low_curvature), value_of(f.high), value_of(high_slope)))
      return of_single_variable(f.high, phi) + of_single_variable(high_slope, phi) * re_h;
    return of_single_variable(f.low, phi) + of_single_variable(low_curvature, phi) * (re_h * re_h);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    return beta_from_total_force(dimensionless_force(S(1 - voidage), re), voidage, fluid.viscosity, diameter);
  }

 private:
  // Re_T1 = (F2 − 1)/(0.375 − F3), where 1 + 0.375 Re_h meets the high-Re line (φ ≤ 0.01).
  template <class S>
  FLUIDBED_HOST_DEVICE static S dilute_transition(const S& f2, const S& f3) {
    using T = value_type_of<S>;
    return (f2 - 1) / (T(0.375) - f3);
  }

  // Re_T, the larger root of F0 + F1 Re_h² = F2 + F3 Re_h (φ > 0.01).
  template <class S>
  FLUIDBED_HOST_DEVICE static S dense_transition(const S& f0, const S& f1, const S& f2, const S& f3) {
    using std::sqrt;
    return (f3 + sqrt(f3 * f3 - 4 * f1 * (f0 - f2))) / (2 * f1);
  }

  template <class S>
  struct Intercepts {
    S low, high;  // F0, F2
  };

  // F0 and F2, each (1 − w_b) R(a, b, c) + w_b 10φ/ε³ for φ < 0.4 with its own (a, b, c), and
  // 10φ/ε³ above: one w_b, 10φ/ε³ and numerator but for its aφ for both. At φ = 0 they are 1:
  // the φ ln φ term and w_b take their limits (0), so nothing evaluates 0·∞.
  template <class S>
  FLUIDBED_HOST_DEVICE static Intercepts<S> intercepts(const S& phi) {
    using std::exp;
    using std::log;
    using std::sqrt;
    using T = value_type_of<S>;
    const S eps = 1 - phi;
    const S carman = 10 * phi / (eps * eps * eps);
    if (phi >= dense_solid_fraction<T>()) return {carman, carman};
    if (!(phi > 0)) return {S(1), S(1)};
    const S weight = exp(-10 * (dense_solid_fraction<T>() - phi) / phi);
    const S numerator = 1 + 3 * sqrt(T(0.5) * phi) + T(135) / 64 * phi * log(phi);  // R's, but for a φ
    return {blend(phi, weight, carman, numerator, FLUIDBED_DECIMAL(T, 17.14), FLUIDBED_DECIMAL(T, -8.48),
                  FLUIDBED_DECIMAL(T, 8.16)),
            blend(phi, weight, carman, numerator, FLUIDBED_DECIMAL(T, 17.89), FLUIDBED_DECIMAL(T, -11.03),
                  FLUIDBED_DECIMAL(T, 15.41))};
  }

  // (1 − w_b) R(a, b, c) + w_b 10φ/ε³, R = (numerator + a φ)/(1 + φ (0.681 + φ (b + c φ))).
  template <class S>
  FLUIDBED_HOST_DEVICE static S blend(const S& phi, const S& weight, const S& carman, const S& numerator,
                                      const value_type_of<S>& a, const value_type_of<S>& b,
                                      const value_type_of<S>& c) {
    using T = value_type_of<S>;
    const S rational = (numerator + a * phi) / (1 + phi * (FLUIDBED_DECIMAL(T, 0.681) + phi * (b + c * phi)));
    return (1 - weight) * rational + weight * carman;
  }
};

}  // namespace fluidbed::drag
