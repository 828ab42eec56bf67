// fluidbed — the van der Hoef et al. (2005) Stokes-flow drag law (lattice-Boltzmann fit for
// random arrays of spheres), whose F0 is also the Stokes term of Beetstra (2007) and Tang (2015).
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../properties.hpp"
#include "dimensionless_force.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

namespace detail {

// van der Hoef et al. (2005) fit of their Stokes-flow lattice-Boltzmann data for random
// monodisperse arrays, in the drag-only normalisation (dimensionless_force.hpp):
//   F0(φ) = 10 φ/(1 − φ)² + (1 − φ)² (1 + 1.5 √φ).
// F0(0) = 1 (Stokes drag of an isolated sphere). It is also the Stokes term of Beetstra
// et al. (2007) and Tang et al. (2015), and exactly the A term of seed 002 eq. (19):
// A (1 − ε)/(18 ε²) = F0 (an algebraic identity; checked to 10 digits for 0.01 ≤ φ ≤ 0.6).
template <class S>
FLUIDBED_HOST_DEVICE S van_der_hoef_stokes_force(const S& phi) {
  using std::sqrt;
  using T = value_type_of<S>;
  const S eps = 1 - phi;
  return 10 * phi / (eps * eps) + eps * eps * (1 + T(1.5) * sqrt(phi));
}

}  // namespace detail

// van der Hoef, M.A., Beetstra, R., Kuipers, J.A.M. (2005), "Lattice-Boltzmann simulations
// of low-Reynolds-number flow past mono- and bidisperse arrays of spheres: results for the
// permeability and drag force", J. Fluid Mech. 528, 233–254, doi:10.1017/S0022112004003295:
//
//   β_pressure_gradient = 18 μ_f ε φ F0(φ) / d²,
//   F0(φ) = 10 φ/ε² + ε² (1 + 1.5 √φ)          (φ = 1 − ε; drag-only normalisation)
//
// Native convention: pressure_gradient. No Reynolds number: creeping (Stokes) flow, β is
// independent of the slip. Seed 002: the Stokes part of eq. (19), A = 180 + 18 ε⁴ (1 +
// 1.5 √φ)/φ, equals 18 ε² F0/φ exactly. Limits: β/(18 μ_f φ/d²) → 1 as ε → 1 (isolated
// sphere); β = 0 at ε = 1.
// Validity: the fitted data, random arrays 0.1 ≤ φ ≤ 0.6, and Re ≲ 1 (at Re = 1 the
// inertial correction of Beetstra 2007 adds 0.3 % at φ = 0.4 and 4 % at φ = 0.05).
struct VanDerHoef : DragLaw<VanDerHoef> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;

  constexpr std::string_view name() const { return "VanDerHoef"; }
  constexpr std::string_view reference() const {
    return "van der Hoef, M.A., Beetstra, R., Kuipers, J.A.M. (2005) J. Fluid Mech. 528, 233-254, "
           "doi:10.1017/S0022112004003295";
  }
  constexpr ValidityRange validity() const { return {0.4, 0.9, 0.0, 1.0}; }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& /*slip*/, const Fluid<T>& fluid,
                                     const T& diameter) const {
    const S phi = 1 - voidage;  // F0(φ) formed with one derivative (single_variable, core/dual.hpp)
    return beta_from_drag_force(of_single_variable(detail::van_der_hoef_stokes_force(single_variable(phi)), phi),
                                voidage, fluid.viscosity, diameter);
  }
};

}  // namespace fluidbed::drag
