// fluidbed — Tenneti, Garg & Subramaniam (2011) particle-resolved DNS drag.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../properties.hpp"
#include "dimensionless_force.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

// Tenneti, S., Garg, R., Subramaniam, S. (2011), "Drag law for monodisperse gas–solid
// systems using particle-resolved direct numerical simulation of flow past fixed
// assemblies of spheres", Int. J. Multiphase Flow 37, 1072–1092,
// doi:10.1016/j.ijmultiphaseflow.2011.05.010:
//
//   F_tot(φ, Re) = F_iso(Re)/ε³ + F_φ(φ) + F_φRe(φ, Re)
//   F_iso  = 1 + 0.15 Re^0.687                      (Schiller–Naumann, no Newton branch)
//   F_φ    = 5.81 φ/ε³ + 0.48 φ^(1/3)/ε⁴
//   F_φRe  = φ³ Re (0.95 + 0.61 φ³/ε²)
//   β_pressure_gradient = 18 μ_f ε² φ F_tot / d²,   Re = ρ_f ε w d / μ_f (superficial slip).
//
// Native convention: pressure_gradient. Not in the seeds.
//
// Convention. Tenneti's F is the TOTAL mean force on a particle, including the share of
// the mean pressure gradient, normalised by the Stokes drag at the superficial slip (the
// Hill convention; dimensionless_force.hpp). The drag alone is ε F_tot, hence ε² above:
// this is waLBerla's form ("version from Finn et al."). Two other forms are in use, both
// inconsistent with that normalisation (β at φ = 0.4, air, d = 500 µm, w = 0.5 m/s):
//   MFiX 25.2.1  β = 18 μ ε φ F_tot/d²                        (1/ε times this law: it
//                treats the total force as drag, counting the pressure share twice in a
//                −φ∇p momentum equation; 6897 against 4138 kg m⁻³ s⁻¹ at φ = 0.4);
//   OpenFOAM     β = 18 μ φ [F_iso + ε² (F_φ + F_φRe)]/d²      (the isolated-sphere term
//                carries ε⁰ where ε² F_iso/ε³ = F_iso/ε is consistent; ε times too small).
// (MFiX 21.3.2 also had φ^(1/3) for φ³ in F_φRe and dispatched TGS to Tang's law.)
// Limits: F_tot → F_iso as φ → 0, so β/(18 μ_f φ/d²) → 1 + 0.15 Re^0.687, the isolated
// sphere; at w = 0, F_tot = 1/ε³ + F_φ (finite). β = 0 at ε = 1.
// Validity: the fitted simulations, 0.1 ≤ φ ≤ 0.5 and 0.01 ≤ Re ≤ 300 (below 0.01 the fit
// is at its creeping-flow limit).
struct Tenneti : DragLaw<Tenneti> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;

  constexpr std::string_view name() const { return "Tenneti"; }
  constexpr std::string_view reference() const {
    return "Tenneti, S., Garg, R., Subramaniam, S. (2011) Int. J. Multiphase Flow 37, 1072-1092, "
           "doi:10.1016/j.ijmultiphaseflow.2011.05.010";
  }
  constexpr ValidityRange validity() const { return {0.5, 0.9, 0.01, 300.0}; }

  // F_tot(φ, Re), total-force normalisation.
  template <class S>
  FLUIDBED_HOST_DEVICE static S dimensionless_force(const S& phi, const S& re) {
    using std::pow;
    using T = value_type_of<S>;
    const S eps = 1 - phi;
    const S eps3 = eps * eps * eps;
    const S phi3 = phi * phi * phi;
    const S isolated = 1 + FLUIDBED_DECIMAL(T, 0.15) * pow(re, FLUIDBED_DECIMAL(T, 0.687));
    const S volume_fraction =
        FLUIDBED_DECIMAL(T, 5.81) * phi / eps3 + FLUIDBED_DECIMAL(T, 0.48) * pow(phi, T(1) / 3) / (eps3 * eps);
    const S inertial = phi3 * re * (FLUIDBED_DECIMAL(T, 0.95) + FLUIDBED_DECIMAL(T, 0.61) * phi3 / (eps * eps));
    return isolated / eps3 + volume_fraction + inertial;
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    return beta_from_total_force(dimensionless_force(S(1 - voidage), re), voidage, fluid.viscosity, diameter);
  }
};

}  // namespace fluidbed::drag
