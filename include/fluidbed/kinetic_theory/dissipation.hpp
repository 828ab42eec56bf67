// fluidbed — collisional dissipation of granular energy γ [W m⁻³], a positive sink: it
// enters the granular energy balance as −γ (granular_state.hpp).
//
// Shape: ConstitutiveLaw (granular_state.hpp), law(φ, Θ, g0, material) → γ ≥ 0, templated on
// the scalar, with law.with_derivatives(φ, Θ, rdf, material) and the checked entry points;
// ∝ Θ^(3/2), so ∂γ/∂Θ = (3/2) γ/Θ, 0 at Θ = 0. Preconditions (asserted in debug builds; the
// checked entry points throw std::domain_error): φ ∈ [0, 1), Θ ≥ 0, g0 > 0, material as in
// granular_state.hpp. Validity: dense-gas kinetic theory, no fitted range.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/constants.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// Lun, Savage, Jeffrey & Chepurniy (1984), J. Fluid Mech. 140, 223–256,
// doi:10.1017/S0022112084000586:
//   γ = 12 (1 − e²) g0 φ² ρ_s Θ^(3/2) / (d √π).
// Seed 001 eq. 34 prints (1 + e²): that dissipates energy in elastic collisions and is
// 9.5 times too large at e = 0.9 (tested). It equals seed 002's γ at ∇·u = 0 (the
// Jenkins–Savage compression term −3(1 − e²) g0 φ² ρ_s Θ ∇·u is not included), MFiX's
// (48/√π) η(1 − η) ρ_s φ² g0 Θ^(3/2)/d, and seed 004's binary γ_i for one class.
struct LunDissipation : ConstitutiveLaw<LunDissipation> {
  constexpr std::string_view name() const { return "LunDissipation"; }
  constexpr std::string_view reference() const { return detail::references::lun_1984; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    using std::sqrt;
    const T e = m.restitution;
    return (12 * (1 - e * e) * m.density / (m.diameter * numbers::sqrt_pi<T>())) * (g0 * phi * phi) *
           (theta * sqrt(theta));
  }
};

}  // namespace fluidbed::kinetic_theory
