// fluidbed — Tang et al. (2015) immersed-boundary drag for monodisperse arrays.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../properties.hpp"
#include "van_der_hoef.hpp"
#include "dimensionless_force.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

// Tang, Y., Peters, E.A.J.F., Kuipers, J.A.M., Kriebitzsch, S.H.L., van der Hoef, M.A.
// (2015), "A new drag correlation from fully resolved simulations of flow past monodisperse
// static arrays of spheres", AIChE J. 61, 688–698, doi:10.1002/aic.14645:
//
//   F(φ, Re) = F0(φ) + (0.11 φ (1 + φ) − 0.00456/ε⁴) Re + (0.169 ε + 0.0644/ε⁴) Re^0.657
//   β_pressure_gradient = 18 μ_f ε φ F / d²,    Re = ρ_f ε w d / μ_f (superficial slip),
//
// F0 the van der Hoef (2005) Stokes term (van_der_hoef.hpp), F in the drag-only normalisation.
// Native convention: pressure_gradient (as MFiX TPKKV, MFIX-Exa "BVK2" and waLBerla use
// it). Not in the seeds. Validity: the fitted simulations, 0.1 ≤ φ ≤ 0.6 and Re ≤ 1000;
// F(φ, 0) = F0 exactly.
//
// Extension beyond Re = 1000 (a library decision, outside the fitted range). As published
// the Re-linear coefficient 0.11 φ(1 + φ) − 0.00456/ε⁴ is negative for φ > 0.52209, so F
// decreases at large Re and turns negative (at Re ≈ 3.5·10⁴ for φ = 0.6, 1.1·10⁴ for
// φ = 0.65). For Re > 1000 the Re-dependent part continues in proportion to Re from its
// value at Re = 1000,
//   F = F0 + (Re/1000) · [F(φ, 1000) − F0],
// i.e. a constant inertial drag coefficient (a Newton-like regime; C_D ∝ F/Re tends to a
// constant). F(φ, 1000) − F0 = 1000 [0.11 φ(1 + φ) + 0.01581 ε + 0.00146/ε⁴] > 0 for every
// φ (coefficients rounded), so F stays positive and increasing; F is continuous at
// Re = 1000 with a jump in ∂F/∂Re. Re ≤ 1000 is evaluated exactly as published.
struct Tang : DragLaw<Tang> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;
  static constexpr double fitted_reynolds_max = 1000.0;

  constexpr std::string_view name() const { return "Tang"; }
  constexpr std::string_view reference() const {
    return "Tang, Y., Peters, E.A.J.F., Kuipers, J.A.M., Kriebitzsch, S.H.L., van der Hoef, M.A. (2015) AIChE J. "
           "61, 688-698, doi:10.1002/aic.14645";
  }
  constexpr ValidityRange validity() const { return {0.4, 0.9, 0.0, fitted_reynolds_max}; }

  // F(φ, Re) with the extension above, drag-only normalisation.
  // The coefficients of φ alone are formed with one derivative (single_variable, core/dual.hpp).
  template <class S>
  FLUIDBED_HOST_DEVICE static S dimensionless_force(const S& phi, const S& re) {
    using std::pow;
    using T = value_type_of<S>;
    const auto x = single_variable(phi);
    const auto eps = 1 - x;
    const auto eps4 = (eps * eps) * (eps * eps);
    const S linear =
        of_single_variable(FLUIDBED_DECIMAL(T, 0.11) * x * (1 + x) - FLUIDBED_DECIMAL(T, 0.00456) / eps4, phi);
    const S power = of_single_variable(FLUIDBED_DECIMAL(T, 0.169) * eps + FLUIDBED_DECIMAL(T, 0.0644) / eps4, phi);
    const S stokes = of_single_variable(detail::van_der_hoef_stokes_force(x), phi);
    if (re <= constant_as<S>(fitted_reynolds_max))
      return stokes + linear * re + power * pow(re, FLUIDBED_DECIMAL(T, 0.657));
    return stokes + (linear + power * pow(T(fitted_reynolds_max), FLUIDBED_DECIMAL(T, 0.657) - 1)) * re;
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    return beta_from_drag_force(dimensionless_force(S(1 - voidage), re), voidage, fluid.viscosity, diameter);
  }
};

}  // namespace fluidbed::drag
