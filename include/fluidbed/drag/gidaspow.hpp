// fluidbed — Gidaspow's combination of Ergun and Wen–Yu, switched and blended.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/constants.hpp"
#include "../core/dual.hpp"
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
    const S psi = blending_weight(voidage);
    return (1 - psi) * Ergun{}.native_beta(voidage, slip, fluid, diameter) +
           psi * GidaspowSwitched::pressure_gradient_wen_yu(voidage, slip, fluid, diameter);
  }
};

}  // namespace fluidbed::drag
