// fluidbed — granular (solids) pressure p_s [Pa], per unit volume of suspension.
//
// Shape: ConstitutiveLaw (granular_state.hpp), law(φ, Θ, g0, material) → p_s ≥ 0, templated
// on the scalar; law.with_derivatives(φ, Θ, rdf, material) gives ∂p_s/∂φ (through g0(φ): the
// "pPrime" implicit solvers need) and ∂p_s/∂Θ = p_s/Θ. Every form is linear in Θ.
// Preconditions (asserted in debug builds; law.checked(…) throws std::domain_error): φ ∈ [0, 1),
// Θ ≥ 0, g0 > 0, material as in granular_state.hpp; AhmadiMaPressure also
// friction_coefficient ≥ 0. Validity: kinetic theory of dense gases, φ up to random close
// packing (0.64) — the papers state no fitted range. Frictional pressure: friction.hpp.
#pragma once

#include <string_view>

#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

namespace detail {

// 2 ρ_s (1 + e) φ² g0 Θ: the collisional pressure of Lun et al. (1984).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S collisional_pressure(const S& phi, const S& theta, const S& g0,
                                                      const GranularMaterial<T>& m) {
  return (2 * m.density * (1 + m.restitution)) * (phi * phi * g0 * theta);
}

}  // namespace detail

// Lun, Savage, Jeffrey & Chepurniy (1984), J. Fluid Mech. 140, 223–256,
// doi:10.1017/S0022112084000586; seed 001 eq. 21, seed 002 eq. 78 (Gidaspow 1994 T.9.1):
//   p_s = φ ρ_s Θ [1 + 2 (1 + e) φ g0].
// Kinetic (ideal-gas) plus collisional part; → φρ_sΘ as φ → 0. Seed 002 eq. 54 prints the
// inelastic excess compressibility as ((1 − e)/2) y^ES; its eq. 81 and text give (1 + e)/2,
// which is what reproduces this form (tested).
struct LunPressure : ConstitutiveLaw<LunPressure> {
  constexpr std::string_view name() const { return "LunPressure"; }
  constexpr std::string_view reference() const { return detail::references::lun_1984; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S kernel(const S& phi, const S& theta, const S& g0,
                                          const GranularMaterial<T>& m) const {
    return m.density * (phi * theta) + detail::collisional_pressure(phi, theta, g0, m);
  }
};

// Syamlal, Rogers & O'Brien (1993), MFIX documentation: Theory guide, DOE/METC-94/1004;
// seed 001 eq. 22: p_s = 2 ρ_s (1 + e) φ² g0 Θ — the collisional part only (no kinetic
// term, → 0 as φ → 0).
struct SyamlalRogersOBrienPressure : ConstitutiveLaw<SyamlalRogersOBrienPressure> {
  constexpr std::string_view name() const { return "SyamlalRogersOBrienPressure"; }
  constexpr std::string_view reference() const { return detail::references::syamlal_rogers_obrien_1993; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S kernel(const S& phi, const S& theta, const S& g0,
                                          const GranularMaterial<T>& m) const {
    return detail::collisional_pressure(phi, theta, g0, m);
  }
};

// Ahmadi & Ma (1990), Int. J. Multiphase Flow 16, 323–351;
// seed 001 eq. 23:
//   p_s = φ ρ_s Θ [(1 + 4 φ g0) + ½ (1 + e)(1 − e + 2 μ_fr)].
// Its collisional part 4φg0 does not depend on e. μ_fr (`friction_coefficient`) must be a
// dimensionless particle friction coefficient: seed 001 calls it "the frictional viscosity",
// which would make the bracket dimensional. "Ma–Ahmadi" is an RDF in seed 002 (MaAhmadi in
// radial_distribution.hpp) and this pressure in seed 001: two different things.
struct AhmadiMaPressure : ConstitutiveLaw<AhmadiMaPressure> {
  double friction_coefficient = 0.0;  // μ_fr, dimensionless

  constexpr explicit AhmadiMaPressure(double friction_coefficient_ = 0.0)
      : friction_coefficient(friction_coefficient_) {}
  constexpr std::string_view name() const { return "AhmadiMaPressure"; }
  constexpr std::string_view reference() const {
    return "Ahmadi, G. & Ma, D. (1990) Int. J. Multiphase Flow 16, 323-351";
  }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  constexpr Arguments<double, 1> parameter_domain() const {
    return {{{"friction_coefficient", friction_coefficient, domains::non_negative<double>()}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&AhmadiMaPressure::friction_coefficient>("friction_coefficient")};
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S kernel(const S& phi, const S& theta, const S& g0,
                                          const GranularMaterial<T>& m) const {
    const T e = m.restitution;
    const T inelastic = 1 + T(0.5) * (1 + e) * (1 - e + 2 * T(friction_coefficient));
    return m.density * (phi * theta) * (inelastic + 4 * phi * g0);
  }
};

}  // namespace fluidbed::kinetic_theory
