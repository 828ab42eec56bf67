// fluidbed — the Beetstra et al. (2007) finite-Reynolds-number drag law (lattice-Boltzmann fit
// for random arrays of spheres). Its polydisperse form is in beetstra_polydisperse.hpp.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../properties.hpp"
#include "dimensionless_force.hpp"
#include "drag_law.hpp"
#include "van_der_hoef.hpp"

namespace fluidbed::drag {

// Beetstra, R., van der Hoef, M.A., Kuipers, J.A.M. (2007), "Drag force of intermediate
// Reynolds number flow past mono- and bidisperse arrays of spheres", AIChE J. 53, 489–501,
// doi:10.1002/aic.11065:
//
//   F(φ, Re) = F0(φ) + 0.413 Re/(24 ε²) · [1/ε + 3 ε φ + 8.4 Re^−0.343]
//                                       / [1 + 10^(3φ) Re^(−(1 + 4φ)/2)]
//   β_pressure_gradient = 18 μ_f ε φ F / d²,    Re = ρ_f ε w d / μ_f (superficial slip),
//
// F0 the van der Hoef (2005) Stokes term above. Native convention: pressure_gradient.
//
// Seed 002 eq. (19) is misprinted: it writes the Ergun-form B as
// 0.31 (1/ε + 3εφ) + 8.4 Re^−0.343, leaving 8.4 Re^−0.343 outside the factor 0.31 (=
// 18 · 0.413/24 rounded). The published form, used here and by OpenFOAM and MFiX, has
// 0.413/24 multiplying all three terms; the misprint changes β by up to +89 % (φ = 0.1,
// Re = 100). The exact 0.413/24 is used, not the rounded 0.31.
//
// Evaluated form. Multiplying numerator and denominator by Re^p, p = (1 + 4φ)/2,
//   F = F0 + 0.413/(24 ε²) · [Re (1/ε + 3εφ) + 8.4 Re^0.657] · Re^p / (Re^p + 10^(3φ)),
// which has no negative power of Re: F(φ, 0) = F0 exactly (the van der Hoef 2005 law),
// and F → F0 continuously as Re → 0 (the inertial term is O(Re^(1.157 + 2φ))).
// Validity: the fitted LB data, 0.1 ≤ φ ≤ 0.6 and Re ≤ 1000, "within 8 %" (seed 002
// §II.D). It is a fit for arrays, not for isolated spheres: as φ → 0 it is 16 % above
// Schiller–Naumann at Re = 100 and 68 % above at Re = 1000 (F(0, Re) = 5.27 and 30.8
// against 4.55 and 18.3).
struct Beetstra : DragLaw<Beetstra> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;

  constexpr std::string_view name() const { return "Beetstra"; }
  constexpr std::string_view reference() const {
    return "Beetstra, R., van der Hoef, M.A., Kuipers, J.A.M. (2007) AIChE J. 53, 489-501, doi:10.1002/aic.11065";
  }
  constexpr ValidityRange validity() const { return {0.4, 0.9, 0.0, 1000.0}; }

  // F(φ, Re), drag-only normalisation, Re = ρ_f ε w d / μ_f.
  template <class S>
  FLUIDBED_HOST_DEVICE static S dimensionless_force(const S& phi, const S& re) {
    using std::pow;
    using T = value_type_of<S>;
    const S eps = 1 - phi;
    const S re_p = pow(re, S(T(0.5) + 2 * phi));
    const S inertial =
        (re * (1 / eps + 3 * eps * phi) + FLUIDBED_DECIMAL(T, 8.4) * pow(re, FLUIDBED_DECIMAL(T, 0.657))) *
        (re_p / (re_p + pow(T(10), 3 * phi)));
    return detail::van_der_hoef_stokes_force(phi) + FLUIDBED_DECIMAL(T, 0.413) / 24 / (eps * eps) * inertial;
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    return beta_from_drag_force(dimensionless_force(S(1 - voidage), re), voidage, fluid.viscosity, diameter);
  }
};

}  // namespace fluidbed::drag
