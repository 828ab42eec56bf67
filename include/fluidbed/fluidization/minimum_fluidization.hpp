// fluidbed — minimum fluidization velocity u_mf.
//
// At minimum fluidization the packed bed's pressure drop carries its buoyant weight.
// Reynolds and Archimedes numbers:
//   Re_mf = ρ_f u_mf d / μ_f  (superficial velocity; the multiphase Re of seed 000 eq. 3.33
//                              at equilibrium),
//   Ar    = ρ_f (ρ_p − ρ_f) g d³ / μ_f².
// d is Particles::diameter, the volume-equivalent sphere diameter. Heavier-than-fluid
// particles only. Each correlation is a value type with the calling shape of
// single_particle/settling_system.hpp: law.reynolds(Ar) = Re_mf, law(fluid, particles, g) =
// u_mf, law.with_derivatives(Ar) (dRe_mf/dAr), law.checked(...) (std::domain_error naming the
// argument). Registry: MinimumFluidizations.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/registry.hpp"
#include "../drag/ergun.hpp"
#include "../properties.hpp"
#include "../single_particle/settling_system.hpp"

namespace fluidbed::fluidization {

// Ergun, S. (1952), "Fluid flow through packed columns", Chem. Eng. Prog. 48, 89–94, at
// the voidage ε_mf of the bed at minimum fluidization, with the sphericity φ_s as in Kunii,
// D., Levenspiel, O. (1991), Fluidization Engineering, 2nd ed., Butterworth–Heinemann, ch. 3:
//
//   150 (1 − ε_mf) Re_mf / (ε_mf³ φ_s²) + 1.75 Re_mf² / (ε_mf³ φ_s) = Ar
//
// (Ergun's pressure drop with the surface–volume diameter φ_s d, equated to the weight
// (1 − ε_mf)(ρ_p − ρ_f) g; for φ_s = 1 it is the equilibrium, eq. 3.28, of seed 000's Ergun
// drag, eq. 3.32, which gives the u_mf = 8.73·10⁻³ m s⁻¹ of its §4.3.3). A quadratic a Re² + b Re = Ar, solved in the
// cancellation-free form Re_mf = 2 Ar / (b + √(b² + 4 a Ar)).
// Parameters: ε_mf ∈ (0, 1) (default 0.4, seed 000 §4.3.3), φ_s ∈ (0, 1] (default 1), doubles
// like every law's parameters.
// Validity: Ergun's, all Re_mf; ε_mf and φ_s as measured for the bed.
struct ErgunMinimumFluidization : single_particle::ArchimedesCorrelation<ErgunMinimumFluidization> {
  double voidage;     // ε_mf
  double sphericity;  // φ_s

  constexpr explicit ErgunMinimumFluidization(double voidage = 0.4, double sphericity = 1)
      : voidage(voidage), sphericity(sphericity) {}

  constexpr std::string_view name() const { return "ErgunMinimumFluidization"; }
  constexpr std::string_view reference() const {
    return "Ergun, S. (1952) Chem. Eng. Prog. 48, 89-94; with sphericity: Kunii, D., Levenspiel, O. (1991) "
           "Fluidization Engineering, 2nd ed., Butterworth-Heinemann";
  }
  constexpr Validity<0> validity() const { return {}; }  // no range stated beyond the bed's own ε_mf, φ_s

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr Arguments<T, 2> parameter_domain() const {
    return {{{"voidage", T(voidage), domains::open(T(0), T(1))},
             {"sphericity", T(sphericity), domains::half_open(T(0), T(1))}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&ErgunMinimumFluidization::voidage>("voidage"),
                      parameter<&ErgunMinimumFluidization::sphericity>("sphericity")};
  }

  template <class S>
  FLUIDBED_HOST_DEVICE S reynolds_of_archimedes(const S& archimedes) const {
    using std::sqrt;
    using T = value_type_of<S>;
    const T e = T(voidage);
    const T s = T(sphericity);
    const T voidage_cubed = e * e * e;
    const T a = T(drag::Ergun::inertial_constant) / (voidage_cubed * s);
    const T b = T(drag::Ergun::viscous_constant) * (1 - e) / (voidage_cubed * s * s);
    return 2 * archimedes / (b + sqrt(b * b + 4 * a * archimedes));
  }
};

// Wen, C.Y., Yu, Y.H. (1966), "A generalized method for predicting the minimum
// fluidization velocity", AIChE J. 12, 610–612, doi:10.1002/aic.690120343:
//
//   Re_mf = √(33.7² + 0.0408 Ar) − 33.7 = 0.0408 Ar / (√(33.7² + 0.0408 Ar) + 33.7),
//
// the Ergun quadratic with their empirical 1/(φ_s ε_mf³) ≈ 14 and
// (1 − ε_mf)/(φ_s² ε_mf³) ≈ 11, evaluated in the second (cancellation-free) form.
// Fitted for 0.001 < Re_mf < 4000.
struct WenYuMinimumFluidization : single_particle::ArchimedesCorrelation<WenYuMinimumFluidization> {
  constexpr std::string_view name() const { return "WenYuMinimumFluidization"; }
  constexpr std::string_view reference() const {
    return "Wen, C.Y., Yu, Y.H. (1966) AIChE J. 12, 610-612, doi:10.1002/aic.690120343";
  }
  constexpr Validity<1> validity() const { return {{{"reynolds", 1.0e-3, 4.0e3}}}; }

  template <class S>
  FLUIDBED_HOST_DEVICE S reynolds_of_archimedes(const S& archimedes) const {
    using std::sqrt;
    using T = value_type_of<S>;
    const T c = FLUIDBED_DECIMAL(T, 33.7);
    const S k = FLUIDBED_DECIMAL(T, 0.0408) * archimedes;
    return k / (sqrt(c * c + k) + c);
  }
};

struct MinimumFluidizationFamily {
  static constexpr std::string_view what = "minimum fluidization correlation";
  static constexpr std::string_view convention =
      "Re_mf = ρ_f u_mf d/μ_f with u_mf [m s⁻¹] the superficial fluid velocity at minimum fluidization, as a "
      "function of Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f²; d is the volume-equivalent sphere diameter, ρ_p > ρ_f.";
};

// The minimum fluidization correlations (Ergun at its defaults ε_mf = 0.4, φ_s = 1); extend
// with `MinimumFluidizations::with<MyCorrelation>`.
using MinimumFluidizations = Registry<MinimumFluidizationFamily, ErgunMinimumFluidization, WenYuMinimumFluidization>;

}  // namespace fluidbed::fluidization
