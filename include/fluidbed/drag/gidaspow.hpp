// fluidbed — Gidaspow's combination of Ergun and Wen–Yu: switched, blended, and switched
// smoothly at a voidage the caller sets (Leboreiro et al.).
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "../core/constants.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/parameters.hpp"
#include "wen_yu.hpp"
#include "drag_law.hpp"
#include "ergun.hpp"

namespace fluidbed::drag {

// Gidaspow (1994), Multiphase Flow and Fluidization, Academic Press:
//
//   β = β_Ergun                    for ε <  0.8
//   β = β_WenYuGidaspow            for ε >= 0.8
//
// (both in the pressure-gradient convention, which is native here; see ergun.hpp and
// wen_yu.hpp for the two laws and their Reynolds numbers).
// The law is discontinuous at ε = 0.8: the ratio Wen–Yu/Ergun there is 0.89 at Re = 0.1
// and 0.27 at Re = 1000 (seed 002 eqs. 45, 46). The switch follows OpenFOAM's rule
// (Wen–Yu at ε = 0.8 exactly). Use GidaspowBlended for a continuous law.
struct GidaspowSwitched : DragLaw<GidaspowSwitched> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T switch_voidage() {
    return FLUIDBED_DECIMAL(T, 0.8);
  }

  constexpr std::string_view name() const { return "GidaspowSwitched"; }
  constexpr std::string_view reference() const {
    return "Gidaspow, D. (1994) Multiphase Flow and Fluidization, Academic Press";
  }
  constexpr ValidityRange validity() const { return {0.36, 1.0, 0.0, 1.0e5}; }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    if (voidage < switch_voidage<value_type_of<S>>()) return Ergun{}.native_beta(voidage, slip, fluid, diameter);
    return pressure_gradient_wen_yu(voidage, slip, fluid, diameter);
  }

  // The dilute branch, β_pg = ε β_classical of ConstantExponentDrag::wen_yu_gidaspow().
  template <class S, class T>
  FLUIDBED_HOST_DEVICE static S pressure_gradient_wen_yu(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                                         const T& diameter) {
    return voidage * ConstantExponentDrag::wen_yu_gidaspow().native_beta(voidage, slip, fluid, diameter);
  }

  // (1 − w) β_Ergun + w β_WenYuGidaspow (pressure-gradient convention), the blends below; where the
  // weight w is exactly 0 or 1, that branch alone (the other law is not evaluated).
  template <class S, class T>
  FLUIDBED_HOST_DEVICE static S blend(const S& wen_yu_weight, const S& voidage, const S& slip, const Fluid<T>& fluid,
                                      const T& diameter) {
    using V = value_type_of<S>;
    if (wen_yu_weight == V(0)) return Ergun{}.native_beta(voidage, slip, fluid, diameter);
    if (wen_yu_weight == V(1)) return pressure_gradient_wen_yu(voidage, slip, fluid, diameter);
    return (1 - wen_yu_weight) * Ergun{}.native_beta(voidage, slip, fluid, diameter) +
           wen_yu_weight * pressure_gradient_wen_yu(voidage, slip, fluid, diameter);
  }
};

// The arctan blend of Ergun and Wen–Yu of Lu Huilin & Gidaspow (2003), Chem. Eng. Sci.
// 58, 3777–3792, doi:10.1016/S0009-2509(03)00238-0 (MFiX GIDASPOW_BLEND, MFIX-Exa):
//
//   ψ = ½ + arctan(150 · 1.75 · (ε − 0.8)) / π
//   β = (1 − ψ) β_Ergun + ψ β_WenYuGidaspow          (pressure-gradient convention)
//
// Smooth (C^∞), with ψ(0.8) = ½; ψ never vanishes (0.024 at ε = 0.75), so the blend
// differs slightly from either law everywhere.
struct GidaspowBlended : DragLaw<GidaspowBlended> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T centre_voidage() {
    return FLUIDBED_DECIMAL(T, 0.8);
  }
  static constexpr double steepness = 150.0 * 1.75;

  constexpr std::string_view name() const { return "GidaspowBlended"; }
  constexpr std::string_view reference() const {
    return "Lu Huilin, Gidaspow, D. (2003) Chem. Eng. Sci. 58, 3777-3792, doi:10.1016/S0009-2509(03)00238-0";
  }
  constexpr ValidityRange validity() const { return {0.36, 1.0, 0.0, 1.0e5}; }

  template <class S>
  FLUIDBED_HOST_DEVICE static S blending_weight(const S& voidage) {
    using std::atan;
    using T = value_type_of<S>;
    return T(0.5) + atan(T(steepness) * (voidage - centre_voidage<T>())) / numbers::pi<T>();
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    return GidaspowSwitched::blend(blending_weight(voidage), voidage, slip, fluid, diameter);
  }
};

// Gidaspow's Ergun/Wen–Yu pair joined smoothly at a switch voidage the caller sets, after
// Leboreiro, J., Joseph, G.G., Hrenya, C.M. (2008), "Revisiting the standard drag law for
// bubbling, gas-fluidized beds", Powder Technol. 183, 385–400, doi:10.1016/j.powtec.2008.01.008,
// as seed 001 §3.3 reports it: the jump of eq. 45 (GidaspowSwitched) is unphysical, a smooth
// switch changes the simulated bed noticeably, and the switch point matters, a solids fraction
// φ_s = 0.46 (ε_s = 0.54) being a better choice than 0.2. Seed 001 gives no formula for the
// smoothing ("for example linear interpolation between the two models near the transition
// point"), and the paper's own could not be checked here, so the weight is this library's:
// the cubic Hermite step over the window ε_s ± δ,
//
//   t = (ε − ε_s + δ)/(2δ),   s = 0 (t <= 0),  3t² − 2t³ (0 < t < 1),  1 (t >= 1)
//   β = (1 − s) β_Ergun + s β_WenYuGidaspow                 (pressure-gradient convention)
//
// Exactly Ergun for ε <= ε_s − δ and exactly Wen–Yu (Gidaspow's, exponent 2.65) for
// ε >= ε_s + δ; β and ∂β/∂ε continuous everywhere (s' = 0 at both window edges), which an
// implicit solver linearising in ε needs; at ε_s, s = ½ and β is the mean of the two laws.
// Linear interpolation would be continuous too but would give ∂β/∂ε two jumps.
// Parameters: switch_voidage ε_s ∈ (0, 1) (default 0.54, Leboreiro et al.'s φ_s = 0.46),
// half_width δ > 0 (default 0.02, this library's choice, not the paper's); ε_s = 0.8 with a
// small δ is a smoothed GidaspowSwitched. Reynolds numbers as in ergun.hpp and wen_yu.hpp.
struct GidaspowLeboreiro : DragLaw<GidaspowLeboreiro> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;

  double switch_voidage;  // ε_s
  double half_width;      // δ

  constexpr explicit GidaspowLeboreiro(double switch_voidage = 0.54, double half_width = 0.02)
      : switch_voidage(switch_voidage), half_width(half_width) {}

  constexpr std::string_view name() const { return "GidaspowLeboreiro"; }
  constexpr std::string_view reference() const {
    return "Leboreiro, J., Joseph, G.G., Hrenya, C.M. (2008) Powder Technol. 183, 385-400, "
           "doi:10.1016/j.powtec.2008.01.008; Gidaspow, D. (1994) Multiphase Flow and Fluidization, Academic Press";
  }
  constexpr ValidityRange validity() const { return {0.36, 1.0, 0.0, 1.0e5}; }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr Arguments<T, 2> parameter_domain() const {
    return {{{"switch_voidage", T(switch_voidage), domains::open(T(0), T(1))},
             {"half_width", T(half_width), domains::positive<T>()}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&GidaspowLeboreiro::switch_voidage>("switch_voidage"),
                      parameter<&GidaspowLeboreiro::half_width>("half_width")};
  }

  // The Wen–Yu weight s(ε) above.
  template <class S>
  FLUIDBED_HOST_DEVICE S switch_weight(const S& voidage) const {
    using T = value_type_of<S>;
    const S t = (voidage - (T(switch_voidage) - T(half_width))) / (2 * T(half_width));
    if (t <= T(0)) return S(T(0));
    if (t >= T(1)) return S(T(1));
    return t * t * (3 - 2 * t);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    return GidaspowSwitched::blend(switch_weight(voidage), voidage, slip, fluid, diameter);
  }
};

}  // namespace fluidbed::drag
