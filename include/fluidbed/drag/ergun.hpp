// fluidbed — Ergun (1952) packed-bed drag.
#pragma once

#include <string_view>

#include "drag_law.hpp"

namespace fluidbed::drag {

// Ergun, S. (1952), "Fluid flow through packed columns", Chem. Eng. Prog. 48, 89–94,
// written as an interphase coefficient by Gidaspow (1994), Multiphase Flow and
// Fluidization, Academic Press:
//
//   β_pressure_gradient = 150 φ² μ_f / (ε d²) + 1.75 φ ρ_f w / d
//
// Native convention: pressure_gradient. Divided by ε it is seed 000 eq. 3.32 (classical):
// β = 150 μ_f φ²/(d² ε²) + 1.75 ρ_f w φ/(d ε), the exponents being ε² and ε (not ε³)
// because w is the interstitial slip. No Reynolds number enters explicitly
// (in terms of Re = ρ_f ε w d/μ_f the second term is 1.75 φ μ_f Re/(ε d²)).
// Validity: fixed and dense beds, ε ≲ 0.8 (Gidaspow's switch), all Re.
// At w = 0 it is the Blake–Kozeny (Carman) viscous term; at ε = 1 it is 0.
struct Ergun : DragLaw<Ergun> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;
  static constexpr double viscous_constant = 150.0;
  static constexpr double inertial_constant = 1.75;

  constexpr std::string_view name() const { return "Ergun"; }
  constexpr std::string_view reference() const {
    return "Ergun, S. (1952) Chem. Eng. Prog. 48, 89-94; as beta: Gidaspow, D. (1994) Multiphase Flow and "
           "Fluidization, Academic Press";
  }
  constexpr ValidityRange validity() const { return {0.36, 0.8, 0.0, 1.0e4}; }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                               const T& diameter) const {
    const S phi = 1 - voidage;
    return T(viscous_constant) * fluid.viscosity / (diameter * diameter) * phi * phi / voidage +
           T(inertial_constant) * fluid.density / diameter * phi * slip;
  }
};

}  // namespace fluidbed::drag
