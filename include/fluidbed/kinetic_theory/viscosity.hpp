// fluidbed — solids shear viscosity μ_s and bulk viscosity λ_s [Pa s], per unit volume of
// suspension (FLUENT/seed 001 quote μ_s and λ_s per unit volume of the solids phase:
// theirs = ours/φ).
//
// Shape: ConstitutiveLaw (granular_state.hpp), law(φ, Θ, g0, material) → μ ≥ 0, templated on
// the scalar, with law.with_derivatives(φ, Θ, rdf, material), law.checked(…) and
// law.checked_with_derivatives(…); the shear-viscosity laws with a kinetic and a collisional
// part (all but EnskogViscosity) also give law.kinetic(...) and law.collisional(...). Every
// form is ∝ √Θ, so ∂μ/∂Θ = μ/(2Θ), +∞ at Θ = 0 (the true
// derivative; the value is 0 there). Preconditions (asserted in debug builds; the checked
// entry points throw std::domain_error): φ ∈ [0, 1), Θ ≥ 0, g0 > 0, material as in
// granular_state.hpp; the Hrenya–Sinclair laws also length_scale > 0. Validity: dense-gas
// kinetic theory, no fitted range (granular_state.hpp's dense_gas_validity). Frictional
// viscosity: friction.hpp.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "../core/constants.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

namespace detail {

// μ_dil = (5/96) ρ_s d √(πΘ): the dilute (Chapman–Enskog) viscosity, seed 002 eq. 72.
template <class S, class T>
FLUIDBED_HOST_DEVICE S dilute_viscosity(const S& theta, const GranularMaterial<T>& m) {
  using std::sqrt;
  return (T(5) / 96 * numbers::sqrt_pi<T>() * m.density * m.diameter) * sqrt(theta);
}

// The reference of the Enskog viscosity and conductivity (elastic hard spheres): the theory and
// the seed that writes it with the excess compressibility.
inline constexpr std::string_view enskog_reference =
    "Chapman, S. & Cowling, T.G. (1970) The Mathematical Theory of Non-Uniform Gases, 3rd ed., Cambridge "
    "University Press, ch. 16; van der Hoef, M.A. et al. (2006) Adv. Chem. Eng. 31, 65-149, "
    "doi:10.1016/S0065-2377(06)31002-2, eqs 75-76";

// Hrenya & Sinclair's mean-free-path factor λ = 1 + d/(6√2 (φ + 10⁻⁵) L) (OpenFOAM's form;
// the 10⁻⁵ keeps it finite at φ = 0), shared by their viscosity and conductivity.
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S hrenya_sinclair_path_factor(const S& phi, const T& diameter, double length_scale) {
  return 1 + diameter / (6 * numbers::sqrt2<T>() * T(length_scale)) / (phi + FLUIDBED_DECIMAL(T, 1e-5));
}

// Hrenya and Sinclair's length L > 0 (their viscosity and conductivity), and the L they are
// registered with.
FLUIDBED_HOST_DEVICE constexpr Arguments<double, 1> length_scale_domain(double length_scale) {
  return {{{"length_scale", length_scale, domains::positive<double>()}}};
}
inline constexpr double registered_length_scale = 0.05;  // [m]

}  // namespace detail

// The collisional shear viscosity of every law below is Gidaspow's (1994), seed 001 eq. 26
// (× φ), seed 002 eq. 79 (second term): (4/5) φ² ρ_s d g0 (1 + e) √(Θ/π).
template <class Law>
using WithGidaspowCollisionalViscosity = KineticPlusCollisional<Law, 4, 5>;

// Gidaspow (1994), Multiphase Flow and Fluidization, Academic Press, eqs 9.183 ff.; seed 002
// eq. 82 (the "exact" y-form it equals):
//   μ_kin = 2 μ_dil / ((1 + e) g0) · [1 + (4/5)(1 + e) g0 φ]²,   μ_dil = (5/96) ρ_s d √(πΘ).
// Misprints: seed 001 eq. 27 has (3 − e) where (1 + e) belongs (the (3 − e) is Syamlal's);
// seed 002 eq. 79 puts (1 + e) g0 under the square root and drops the factor 2. Both are
// tested against this form. → 2 μ_dil/(1 + e) as φ → 0 (finite).
struct GidaspowViscosity : WithGidaspowCollisionalViscosity<GidaspowViscosity> {
  constexpr std::string_view name() const { return "GidaspowViscosity"; }
  constexpr std::string_view reference() const { return detail::references::gidaspow_1994; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kinetic(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    const T one_plus_e = 1 + m.restitution;
    const S bracket = 1 + (FLUIDBED_DECIMAL(T, 0.8) * one_plus_e) * g0 * phi;
    return 2 * detail::dilute_viscosity(theta, m) * bracket * bracket / (one_plus_e * g0);
  }
};

// Syamlal, Rogers & O'Brien (1993), MFIX Theory Guide, DOE/METC-94/1004; seed 001 eq. 28
// (× φ, the MFiX/OpenFOAM form):
//   μ_kin = φ ρ_s d √(πΘ) / (6 (3 − e)) · [1 + (2/5)(1 + e)(3e − 1) φ g0],
// plus Gidaspow's collisional part (OpenFOAM Syamlal). → 0 as φ → 0.
struct SyamlalViscosity : WithGidaspowCollisionalViscosity<SyamlalViscosity> {
  constexpr std::string_view name() const { return "SyamlalViscosity"; }
  constexpr std::string_view reference() const { return detail::references::syamlal_rogers_obrien_1993; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kinetic(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    using std::sqrt;
    const T e = m.restitution;
    const S bracket = 1 + (FLUIDBED_DECIMAL(T, 0.4) * (1 + e) * (3 * e - 1)) * phi * g0;
    return (numbers::sqrt_pi<T>() * m.density * m.diameter / (6 * (3 - e))) * phi * sqrt(theta) * bracket;
  }
};

// Hrenya & Sinclair (1997), AIChE J. 43, 853–869, doi:10.1002/aic.690430402, as in
// OpenFOAM's HrenyaSinclair: the mean free path is limited by a length L (e.g. the riser
// diameter) through λ = 1 + d/(6√2 (φ + 10⁻⁵) L) (10⁻⁵: OpenFOAM's guard at φ = 0), and
//   μ_kin = ρ_s d √Θ [ (√π/15) g0 (1+e)(3e−1) φ²/(3−e)
//                     + (√π/6) φ (λ/2 + (3e−1)/4) / ((3−e) λ/2)
//                     + (10/96) √π / ((1+e) ((3−e)/2) g0 λ) ],
// plus Gidaspow's collisional part. Registered with L = 0.05 m (a laboratory riser).
struct HrenyaSinclairViscosity : WithGidaspowCollisionalViscosity<HrenyaSinclairViscosity> {
  double length_scale;  // L [m]

  constexpr explicit HrenyaSinclairViscosity(double length) : length_scale(length) {}
  static constexpr std::array<HrenyaSinclairViscosity, 1> registered() {
    return {HrenyaSinclairViscosity(detail::registered_length_scale)};
  }
  constexpr std::string_view name() const { return "HrenyaSinclairViscosity"; }
  constexpr std::string_view reference() const { return detail::references::hrenya_sinclair_1997; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  constexpr Arguments<double, 1> parameter_domain() const { return detail::length_scale_domain(length_scale); }
  static constexpr auto parameters() {
    return std::array{parameter<&HrenyaSinclairViscosity::length_scale>("length_scale")};
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kinetic(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    using std::sqrt;
    FLUIDBED_EXPECTS(detail::parameters_within(*this));
    const T e = m.restitution, three_minus_e = 3 - e;
    const T sqrt_pi = numbers::sqrt_pi<T>();
    const S lambda = detail::hrenya_sinclair_path_factor(phi, m.diameter, length_scale);
    const S bracket =
        (sqrt_pi / 15 * (1 + e) * (3 * e - 1) / three_minus_e) * g0 * phi * phi +
        (sqrt_pi / 6) * phi * (T(0.5) * lambda + T(0.25) * (3 * e - 1)) / (T(0.5) * three_minus_e * lambda) +
        (T(10) / 96 * sqrt_pi / ((1 + e) * T(0.5) * three_minus_e)) / (g0 * lambda);
    return (m.density * m.diameter) * sqrt(theta) * bracket;
  }
};

// Enskog's shear viscosity of elastic hard spheres (standard Enskog theory, Chapman & Cowling
// 1970, ch. 16), seed 002 eq. 75 (= eq. 73 with bρ_s = 4φ):
//   μ = 4 μ_dil φ (1/y + 4/5 + 0.7614 y),   y = 4 φ g0,   μ_dil = (5/96) ρ_s d √(πΘ) (eq. 72),
// evaluated as μ_dil (1/g0 + (16/5) φ + 16 · 0.7614 g0 φ²), finite at φ = 0 (→ μ_dil/g0(0) = μ_dil).
// The constant is the seed's printed 0.7614, kept as the seed's model (its eqs 73 and 75 and its
// TFM). Its footnote 3 derives it as (4/25)(1 + 12/(π c_2)) with c_2 = 1.016, which is 0.761530
// (0.7615 rounded): the printed value is 1.7e-4 low, which moves μ by at most 1.7e-4 relative, far
// below the theory's own error, and c_2 = 1.016 and c_1 = 1 are themselves approximations of
// Chapman and Cowling's series; c_2 = 1 gives Gidaspow's 0.7712 (GidaspowViscosity at e = 1). The restitution is not used
// (elastic spheres; the inelastic form is GidaspowViscosity). No kinetic/collisional split.
// Validity: the Enskog viscosity is accurate to φ ≈ 0.3 against molecular dynamics and up to
// 2× too low at φ ≈ 0.5 (Alder, Gass & Wainwright 1970, as seed 002 reports).
struct EnskogViscosity : ConstitutiveLaw<EnskogViscosity> {
  constexpr std::string_view name() const { return "EnskogViscosity"; }
  constexpr std::string_view reference() const { return detail::enskog_reference; }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", 0.0, 0.3}}}; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    return detail::dilute_viscosity(theta, m) *
           (1 / g0 + FLUIDBED_DECIMAL(T, 3.2) * phi + (16 * FLUIDBED_DECIMAL(T, 0.7614)) * g0 * phi * phi);
  }
};

// Lun et al. (1984), J. Fluid Mech. 140, 223–256; seed 001 eq. 29 (× φ):
//   λ_s = (4/3) φ² ρ_s d g0 (1 + e) √(Θ/π).
// Seed 004's binary closure implies λ = (5/3) μ_coll, the same value for one class.
struct LunBulkViscosity : ConstitutiveLaw<LunBulkViscosity> {
  constexpr std::string_view name() const { return "LunBulkViscosity"; }
  constexpr std::string_view reference() const { return detail::references::lun_1984; }
  constexpr Validity<1> validity() const { return detail::dense_gas_validity; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi, const S& theta, const S& g0, const GranularMaterial<T>& m) const {
    return value_type_of<S>(4) / 3 * detail::collisional_transfer(phi, theta, g0, m);
  }
};

}  // namespace fluidbed::kinetic_theory
