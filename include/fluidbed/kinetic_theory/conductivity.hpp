// fluidbed — granular conductivity κ_s [kg m⁻¹ s⁻¹] (the flux of granular energy is
// −κ_s ∇Θ), per unit volume of suspension in every seed.
//
// Shape: ConstitutiveLaw (granular_state.hpp), law(φ, Θ, g0, material) → κ ≥ 0 =
// law.kinetic(...) + law.collisional(...), templated on the scalar, with
// law.with_derivatives(φ, Θ, rdf, material) and the checked entry points. Every form is ∝ √Θ
// (∂κ/∂Θ = κ/(2Θ), +∞ at Θ = 0). Preconditions (asserted in debug builds; the checked entry
// points throw std::domain_error): φ ∈ [0, 1), Θ ≥ 0, g0 > 0, material as in
// granular_state.hpp; HrenyaSinclairConductivity also length_scale > 0. Validity: dense-gas
// kinetic theory, no fitted range (granular_state.hpp's dense_gas_validity).
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "../core/constants.hpp"
#include "granular_state.hpp"
#include "viscosity.hpp"

namespace fluidbed::kinetic_theory {

// The collisional conductivity of every law below is Gidaspow's (1994), seed 001 eq. 31
// (second term), seed 002 eq. 80: 2 φ² ρ_s d g0 (1 + e) √(Θ/π) (for Syamlal's, the last
// term of seed 001 eq. 32 is this term).
template <class Law>
using WithGidaspowCollisionalConductivity = KineticPlusCollisional<Law, 2, 1>;

// Gidaspow (1994), Multiphase Flow and Fluidization, ch. 9; seed 001 eq. 31, seed 002
// eqs 80 and 83:
//   κ_kin = 150 ρ_s d √(πΘ) / (384 (1 + e) g0) · [1 + (6/5) φ g0 (1 + e)]²
// (= 2κ_dil/((1 + e) g0)[…]², κ_dil = (75/384) ρ_s d √(πΘ)). → 2κ_dil/(1 + e) as φ → 0.
struct GidaspowConductivity : WithGidaspowCollisionalConductivity<GidaspowConductivity> {
  constexpr std::string_view name() const { return "GidaspowConductivity"; }
  constexpr std::string_view reference() const { return detail::references::gidaspow_1994; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kinetic(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    using std::sqrt;
    const T one_plus_e = 1 + m.restitution;
    const S bracket = 1 + (FLUIDBED_DECIMAL(T, 1.2) * one_plus_e) * phi * g0;
    return (T(150) / 384 * numbers::sqrt_pi<T>() * m.density * m.diameter / one_plus_e) * sqrt(theta) * bracket *
           bracket / g0;
  }
};

// Syamlal, Rogers & O'Brien (1993), MFIX Theory Guide; seed 001 eqs 32–33, η = (1 + e)/2:
//   κ = 15 ρ_s d φ √(πΘ) / (4 (41 − 33η)) · [1 + (12/5) η² (4η − 3) φ g0
//                                            + (16/(15π)) (41 − 33η) η φ g0],
// whose last term is the collisional conductivity; kinetic = the rest. → 0 as φ → 0.
struct SyamlalConductivity : WithGidaspowCollisionalConductivity<SyamlalConductivity> {
  constexpr std::string_view name() const { return "SyamlalConductivity"; }
  constexpr std::string_view reference() const { return detail::references::syamlal_rogers_obrien_1993; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kinetic(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    using std::sqrt;
    const T eta = T(0.5) * (1 + m.restitution);
    const S bracket = 1 + (FLUIDBED_DECIMAL(T, 2.4) * eta * eta * (4 * eta - 3)) * phi * g0;
    return (15 * numbers::sqrt_pi<T>() * m.density * m.diameter / (4 * (41 - 33 * eta))) * phi * sqrt(theta) * bracket;
  }
};

// Hrenya & Sinclair (1997), AIChE J. 43, 853–869, as in OpenFOAM's current
// HrenyaSinclairConductivity (older OpenFOAM versions omit g0 in the second term), with
// D = 49/16 − 33e/16 and λ as in HrenyaSinclairViscosity:
//   κ_kin = ρ_s d √Θ [ (9/32) √π g0 (1+e)² (2e−1) φ²/D
//                     + (15/16) √π φ (e²/2 + e/4 − 3/4 + λ)/(D λ)
//                     + (25/64) √π / ((1+e) D λ g0) ].
// Registered with L = 0.05 m, as the viscosity.
struct HrenyaSinclairConductivity : WithGidaspowCollisionalConductivity<HrenyaSinclairConductivity> {
  double length_scale;  // L [m]

  constexpr explicit HrenyaSinclairConductivity(double length) : length_scale(length) {}
  static constexpr std::array<HrenyaSinclairConductivity, 1> registered() {
    return {HrenyaSinclairConductivity(detail::registered_length_scale)};
  }
  constexpr std::string_view name() const { return "HrenyaSinclairConductivity"; }
  constexpr std::string_view reference() const { return detail::references::hrenya_sinclair_1997; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  constexpr Arguments<double, 1> parameter_domain() const { return detail::length_scale_domain(length_scale); }
  static constexpr auto parameters() {
    return std::array{parameter<&HrenyaSinclairConductivity::length_scale>("length_scale")};
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kinetic(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    using std::sqrt;
    FLUIDBED_EXPECTS(detail::parameters_within(*this));
    const T e = m.restitution, d_factor = T(49) / 16 - T(33) / 16 * e;
    const T sqrt_pi = numbers::sqrt_pi<T>();
    const S lambda = detail::hrenya_sinclair_path_factor(phi, m.diameter, length_scale);
    const S bracket = (T(9) / 32 * sqrt_pi * (1 + e) * (1 + e) * (2 * e - 1) / d_factor) * g0 * phi * phi +
                      (T(15) / 16 * sqrt_pi / d_factor) * phi * (T(0.5) * e * e + T(0.25) * e - T(0.75) + lambda) /
                          lambda +
                      (T(25) / 64 * sqrt_pi / ((1 + e) * d_factor)) / (lambda * g0);
    return (m.density * m.diameter) * sqrt(theta) * bracket;
  }
};

// Enskog's conductivity of elastic hard spheres (standard Enskog theory, Chapman & Cowling 1970,
// ch. 16), seed 002 eq. 76 (= eq. 74 with bρ_s = 4φ):
//   κ = 4 κ_dil φ (1/y + 6/5 + 0.7574 y),   y = 4 φ g0,   κ_dil = (75/384) ρ_s d √(πΘ) (eq. 72),
// evaluated as κ_dil (1/g0 + (24/5) φ + 16 · 0.7574 g0 φ²), finite at φ = 0 (→ κ_dil). The
// constant is the seed's printed 0.7574, kept as the seed's model: (9/25)(1 + 32/(9π c)) with the
// factor c = 1.025 is 0.757499, of which 0.7574 is the truncation (1.3e-4 relative); c = 1 gives
// Gidaspow's 0.7674 (GidaspowConductivity at e = 1). The restitution is not
// used (elastic spheres). No kinetic/collisional split. Validity: seed 002 states the molecular
// dynamics comparison (Alder, Gass & Wainwright 1970) for the viscosity only; declared as the
// dense-gas laws' range.
struct EnskogConductivity : ConstitutiveLaw<EnskogConductivity> {
  constexpr std::string_view name() const { return "EnskogConductivity"; }
  constexpr std::string_view reference() const { return detail::enskog_reference; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    using std::sqrt;
    const S dilute = (T(75) / 384 * numbers::sqrt_pi<T>() * m.density * m.diameter) * sqrt(theta);
    return dilute * (1 / g0 + FLUIDBED_DECIMAL(T, 4.8) * phi + (16 * FLUIDBED_DECIMAL(T, 0.7574)) * g0 * phi * phi);
  }
};

}  // namespace fluidbed::kinetic_theory
