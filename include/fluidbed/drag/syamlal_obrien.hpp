// fluidbed — Syamlal–O'Brien drag (MFiX). Its calibration from a measured minimum fluidization
// state is fluidization::syamlal_obrien_from_minimum_fluidization (fluidization/syamlal_obrien_calibration.hpp).
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../properties.hpp"
#include "../single_particle/drag_coefficient.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

// Syamlal, M., O'Brien, T.J. (1989), "Computer simulation of bubbles in a fluidized bed",
// AIChE Symp. Ser. 85(270), 22–31; Syamlal, M., Rogers, W., O'Brien, T.J. (1993), MFIX
// Documentation: Theory Guide, Technical Note DOE/METC-94/1004, U.S. DOE, Morgantown WV.
// From the velocity–voidage correlation of Garside & Al-Dibouni
// (1977), Ind. Eng. Chem. Process Des. Dev. 16, 206–214:
//
//   Re_s = ρ_f w d / μ_f          (THIS LAW'S OWN Reynolds number: interstitial slip w,
//                                  NO factor ε, unlike the library's Re = ρ_f ε w d / μ_f)
//   A = ε^4.14,   B = c1 ε^1.28 (ε ≤ 0.85),   B = ε^d1 (ε > 0.85)
//   V_r = ½ [A − 0.06 Re_s + √((0.06 Re_s)² + 0.12 Re_s (2B − A) + A²)]
//   β_pressure_gradient = ¾ C_D(Re_s/V_r) φ ε ρ_f w / (V_r² d)
//                       = ¾ μ_f φ ε (0.63 √(Re_s/V_r) + 4.8)² / (V_r d²),
//
// C_D the Dallavalle coefficient (single_particle/drag_coefficient.hpp). V_r is the ratio of the terminal
// velocity of the suspension to that of an isolated particle: it solves Garside and
// Al-Dibouni's V_r (1 + 0.06 Re_t) = A + 0.06 B Re_t with Re_t = Re_s/V_r. Native
// convention: pressure_gradient (MFiX's and OpenFOAM's). Not in the seeds (seed 001 cites
// Syamlal only for kinetic-theory closures). Defaults c1 = 0.8, d1 = 2.65 (MFiX, OpenFOAM).
//
// Evaluated form. The root is written √((A − 0.06 Re_s)² + 0.24 B Re_s) (identical), and
// for 0.06 Re_s > A as 2 B (0.06 Re_s)/(√… − (A − 0.06 Re_s)) (the same root, without the
// cancellation that loses all digits of V_r → B at large Re_s).
// Limits: V_r → A as Re_s → 0, so β → 17.28 μ_f φ ε^−3.14/d² at w = 0 (finite); V_r → B
// as Re_s → ∞; V_r = 1 at ε = 1, Re_s = 0. β = 0 at ε = 1.
// The switch at ε = 0.85 is continuous only if c1 = 0.85^(d1 − 1.28); the defaults miss
// that by 0.05 % (0.85^1.37 = 0.80040): β jumps by 0.05 % (V_r ≈ B) to 0.1 % (β ∝ V_r⁻² as
// Re_s → ∞) at large Re_s, not at all at Re_s = 0 (V_r = A). continuous_at_switch()
// derives c1 from d1. Neither OpenFOAM nor MFiX enforces continuity (MFiX
// uses B = c1 ε^1.28 at ε = 0.85 exactly, as here, OpenFOAM uses ε < 0.85).
// Validity: the velocity–voidage data behind it, liquid fluidization and sedimentation,
// 0.4 ≲ ε ≤ 1; Dallavalle's C_D up to Re ≈ 10⁴.
class SyamlalOBrien : public DragLaw<SyamlalOBrien> {
 public:
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T switch_voidage() {
    return FLUIDBED_DECIMAL(T, 0.85);
  }

  constexpr explicit SyamlalOBrien(double c1 = 0.8, double d1 = 2.65) : c1_(c1), d1_(d1) {}

  // d1 given, c1 = 0.85^(d1 − 1.28): B continuous at ε = 0.85.
  static SyamlalOBrien continuous_at_switch(double d1) {
    return SyamlalOBrien(std::pow(switch_voidage<double>(), d1 - 1.28), d1);
  }

  constexpr double c1() const { return c1_; }
  constexpr double d1() const { return d1_; }
  // B = c1 ε^1.28 must be > 0: the root of V_r is real for B >= 0, and V_r > 0 for B > 0
  // (V_r = 0, β = ∞, for B = 0 once 0.06 Re_s > A). d1 may be any finite number.
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr Arguments<T, 2> parameter_domain() const {
    return {{{"c1", T(c1_), domains::positive<T>()}, {"d1", T(d1_), domains::finite<T>()}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&SyamlalOBrien::c1_>("c1"), parameter<&SyamlalOBrien::d1_>("d1")};
  }
  constexpr std::string_view name() const { return "SyamlalOBrien"; }
  constexpr std::string_view reference() const {
    return "Syamlal, M., O'Brien, T.J. (1989) AIChE Symp. Ser. 85(270), 22-31; Syamlal, M., Rogers, W., "
           "O'Brien, T.J. (1993) MFIX Documentation: Theory Guide, DOE/METC-94/1004";
  }
  constexpr ValidityRange validity() const { return {0.4, 1.0, 0.0, 1.0e4}; }

  // V_r(ε, Re_s), Re_s = ρ_f w d / μ_f (no ε).
  template <class S>
  FLUIDBED_HOST_DEVICE S velocity_ratio(const S& voidage, const S& re_s) const {
    using std::pow;
    using std::sqrt;
    using T = value_type_of<S>;
    const S a = pow(voidage, FLUIDBED_DECIMAL(T, 4.14));
    const S b =
        voidage <= switch_voidage<T>() ? S(T(c1_) * pow(voidage, FLUIDBED_DECIMAL(T, 1.28))) : S(pow(voidage, T(d1_)));
    const S x = FLUIDBED_DECIMAL(T, 0.06) * re_s;
    const S difference = a - x;
    const S root = sqrt(difference * difference + 4 * b * x);
    if (difference >= 0) return T(0.5) * (difference + root);
    return 2 * b * x / (root - difference);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    const S re_s = fluid.density * diameter / fluid.viscosity * slip;
    const S ratio = velocity_ratio(voidage, re_s);
    return T(0.75) * fluid.viscosity / (diameter * diameter) * (voidage * (1 - voidage)) *
           single_particle::DallavalleCoefficient::cd_times_re(S(re_s / ratio)) / ratio;
  }

 private:
  double c1_;
  double d1_;
};

}  // namespace fluidbed::drag
