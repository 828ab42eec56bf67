// fluidbed — radial distribution functions at contact g0(φ), one solids class.
//
// Every stress, viscosity, conductivity and dissipation of kinetic theory is proportional
// to g0 (or to 1/g0), and the forms in use differ by a factor of 3 at φ = 0.55 (g0 =
// Percus–Yevick 6.30, Carnahan–Starling 7.96, Ma–Ahmadi 8.77, Ogawa
// (φ_max = 0.63) 22.6, Lathouwers–Bellan (0.64) 103). So g0 is a separate, pluggable
// object: call it with φ (a Dual φ gives dg0/dφ) and pass its value to the closures.
//
// Shape: SolidFractionLaw (granular_state.hpp): g0(φ) templated on the scalar,
// g0.with_derivatives(φ) → {g0, dg0/dφ}, g0.checked(φ), g0.checked_with_derivatives(φ); name(),
// reference(), validity() (the φ range each form was derived or fitted for). φ ∈ [0, 1) is the
// precondition of every form (asserted in debug builds), and for the forms with a packing
// limit φ_max ∈ (0, 1] and 0 < packing_margin < φ_max (parameter_domain); the checked entry
// points throw std::domain_error for either. RadialDistributions (registry.hpp) lists them.
// Every form → 1 as φ → 0 except
// GidaspowRadialDistribution (→ 3/5, as published). The cube-root forms approach 1 like 1 + (φ/φ_max)^(1/3): their
// slope is +∞ at φ = 0.
//
// Behaviour at and beyond maximum packing. The forms with a packing limit φ_max diverge
// there. Codes cap φ (MFiX Ma–Ahmadi at 0.643), freeze g0 (OpenFOAM SinclairJackson above
// alphaMinFriction) or do nothing (OpenFOAM LunSavage: NaN beyond φ_max), and the capped
// forms' derivatives are then not the derivatives of the values (OpenFOAM's
// SinclairJackson g0′ is not the slope of its frozen g0; MFiX's Ma–Ahmadi g0′ uses the
// uncapped φ and is NaN beyond φ_max).
// Here the singular factor is continued linearly beyond φ_c = φ_max − packing_margin
// (default 0.01): g0 is finite for every φ < 1, continuous with a continuous slope,
// increasing, and its derivative is exactly that of the continued function. Below φ_c
// every form is the published formula.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// The default distance below φ_max where singular factors are continued linearly.
inline constexpr double default_packing_margin = 0.01;

// Carnahan & Starling (1969), J. Chem. Phys. 51, 635–636, doi:10.1063/1.1672048;
// seed 002 eq. 53: g0 = (1 − φ/2)/(1 − φ)³. Hard-sphere fluid, accurate to the freezing
// point φ ≈ 0.49 and used up to 0.55 (seed 002 Fig. 21); no packing limit (13.5 at 0.63),
// finite for φ < 1.
struct CarnahanStarling : SolidFractionLaw<CarnahanStarling> {
  constexpr std::string_view name() const { return "CarnahanStarling"; }
  constexpr std::string_view reference() const {
    return "Carnahan, N.F. & Starling, K.E. (1969) J. Chem. Phys. 51, 635-636, doi:10.1063/1.1672048";
  }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", 0.0, 0.55}}}; }
  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S kernel(const S& phi) const {
    const S gap = 1 - phi;
    return (1 - value_type_of<S>(0.5) * phi) / (gap * gap * gap);
  }
};

// Percus–Yevick contact value (Lebowitz 1964, Phys. Rev. 133, A895–A899,
// doi:10.1103/PhysRev.133.A895, one class): g0 = (1 + φ/2)/(1 − φ)². The one-class limit of
// the Lebowitz mixture form (seed 000 eq. 6.16); finite for φ < 1. Validity: the hard-sphere
// fluid, to the freezing point φ ≈ 0.49.
struct PercusYevick : SolidFractionLaw<PercusYevick> {
  constexpr std::string_view name() const { return "PercusYevick"; }
  constexpr std::string_view reference() const {
    return "Lebowitz, J.L. (1964) Phys. Rev. 133, A895-A899, doi:10.1103/PhysRev.133.A895";
  }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", 0.0, 0.49}}}; }
  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S kernel(const S& phi) const {
    const S gap = 1 - phi;
    return (1 + value_type_of<S>(0.5) * phi) / (gap * gap);
  }
};

// Lun & Savage (1986), Acta Mech. 63, 15–44 (OpenFOAM LunSavage):
// g0 = (1 − φ/φ_max)^(−2.5 φ_max), continued linearly above φ_max − packing_margin. Validity:
// φ up to φ_max. Registered with φ_max = 0.63.
struct LunSavage : SolidFractionLaw<LunSavage> {
  double max_packing;
  double packing_margin = default_packing_margin;

  constexpr LunSavage(double max_packing_, double packing_margin_ = default_packing_margin)
      : max_packing(max_packing_), packing_margin(packing_margin_) {}
  static constexpr std::array<LunSavage, 1> registered() { return {LunSavage{0.63}}; }
  constexpr std::string_view name() const { return "LunSavage"; }
  constexpr std::string_view reference() const { return "Lun, C.K.K. & Savage, S.B. (1986) Acta Mech. 63, 15-44"; }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", 0.0, max_packing}}}; }
  constexpr Arguments<double, 2> parameter_domain() const {
    return detail::packing_domain(max_packing, packing_margin);
  }
  static constexpr auto parameters() {
    return std::array{parameter<&LunSavage::max_packing>("max_packing"),
                      parameter<&LunSavage::packing_margin>("packing_margin")};
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi) const {
    using std::pow;
    using T = value_type_of<S>;
    const T m = T(max_packing), exponent = T(-2.5) * m;
    return detail::continued_linearly_above(phi, m - T(packing_margin),
                                            [&](const auto& x) { return pow(1 - x / m, exponent); });
  }
};

namespace detail {

// g0 = prefactor/(1 − (φ/φ_max)^(1/3)), the cube-root form shared by Ogawa,
// Sinclair–Jackson and Gidaspow, continued linearly above φ_max − packing_margin. The
// prefactor is the ratio numerator/denominator: a floating-point template argument would
// need clang 18 or later. Validity: φ up to φ_max.
template <class Law, int numerator, int denominator>
struct CubeRootContact : SolidFractionLaw<Law> {
  double max_packing;
  double packing_margin;

  constexpr CubeRootContact(double max_packing_, double packing_margin_)
      : max_packing(max_packing_), packing_margin(packing_margin_) {}
  constexpr Validity<1> validity() const { return {{{"solid_fraction", 0.0, max_packing}}}; }
  constexpr Arguments<double, 2> parameter_domain() const { return packing_domain(max_packing, packing_margin); }
  static constexpr auto parameters() {
    return std::array{parameter<&CubeRootContact::max_packing, Law>("max_packing"),
                      parameter<&CubeRootContact::packing_margin, Law>("packing_margin")};
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi) const {
    using std::cbrt;
    using T = value_type_of<S>;
    const T m = T(max_packing);
    return T(numerator) / denominator *
           continued_linearly_above(phi, m - T(packing_margin), [&](const auto& x) { return 1 / (1 - cbrt(x / m)); });
  }
};

}  // namespace detail

// Ogawa, Umemura & Oshima (1980), Z. angew. Math. Phys. 31, 483–493; seed 001 eq. 24
// (FLUENT calls it "Lun et al."): g0 = 1/(1 − (φ/φ_max)^(1/3)), continued linearly above
// φ_max − packing_margin. Seed 001 uses φ_max = 0.63, with which it is registered.
struct Ogawa : detail::CubeRootContact<Ogawa, 1, 1> {
  constexpr explicit Ogawa(double max_packing, double packing_margin = default_packing_margin)
      : CubeRootContact{max_packing, packing_margin} {}
  static constexpr std::array<Ogawa, 1> registered() { return {Ogawa{0.63}}; }
  constexpr std::string_view name() const { return "Ogawa"; }
  constexpr std::string_view reference() const {
    return "Ogawa, S., Umemura, A. & Oshima, N. (1980) Z. angew. Math. Phys. 31, 483-493";
  }
};

// Sinclair & Jackson (1989), AIChE J. 35, 1473–1486, doi:10.1002/aic.690350908: the same
// expression as Ogawa, 1/(1 − (φ/φ_max)^(1/3)). OpenFOAM's SinclairJackson also freezes
// g0 above alphaMinFriction while its g0prime does not; here there is no freeze, only the
// linear continuation above φ_max − packing_margin, with a consistent derivative. Registered
// with φ_max = 0.63.
struct SinclairJackson : detail::CubeRootContact<SinclairJackson, 1, 1> {
  constexpr explicit SinclairJackson(double max_packing, double packing_margin = default_packing_margin)
      : CubeRootContact{max_packing, packing_margin} {}
  static constexpr std::array<SinclairJackson, 1> registered() { return {SinclairJackson{0.63}}; }
  constexpr std::string_view name() const { return "SinclairJackson"; }
  constexpr std::string_view reference() const {
    return "Sinclair, J.L. & Jackson, R. (1989) AIChE J. 35, 1473-1486, doi:10.1002/aic.690350908";
  }
};

// Gidaspow (1994), Multiphase Flow and Fluidization, Academic Press (SedFoam Gidaspow):
// g0 = (3/5)/(1 − (φ/φ_max)^(1/3)). As published it tends to 3/5, not 1, as φ → 0; it is
// offered for reproducing codes that use it, not as a dilute-consistent form. Registered with
// φ_max = 0.63.
struct GidaspowRadialDistribution : detail::CubeRootContact<GidaspowRadialDistribution, 3, 5> {
  constexpr explicit GidaspowRadialDistribution(double max_packing, double packing_margin = default_packing_margin)
      : CubeRootContact{max_packing, packing_margin} {}
  static constexpr std::array<GidaspowRadialDistribution, 1> registered() {
    return {GidaspowRadialDistribution{0.63}};
  }
  constexpr std::string_view name() const { return "GidaspowRadialDistribution"; }
  constexpr std::string_view reference() const { return detail::references::gidaspow_1994; }
};

// Ma & Ahmadi (1986), J. Chem. Phys. 84, 3449–3450; seed 002 eq. 77
// with Table III (the Twente TFM):
//   g0 = (1 + 2.5φ + 4.5904φ² + 4.515439φ³) / (1 − (φ/0.64356)³)^0.67802.
// MFiX's source writes 4.5094, a transposition of the published 4.5904. The
// denominator factor is continued linearly above 0.64356 − packing_margin. Validity: fitted
// to hard-sphere data up to its packing limit 0.64356.
struct MaAhmadi : SolidFractionLaw<MaAhmadi> {
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T max_packing() {
    return FLUIDBED_DECIMAL(T, 0.64356);
  }
  double packing_margin = default_packing_margin;

  constexpr explicit MaAhmadi(double packing_margin_ = default_packing_margin) : packing_margin(packing_margin_) {}
  constexpr std::string_view name() const { return "MaAhmadi"; }
  constexpr std::string_view reference() const { return "Ma, D. & Ahmadi, G. (1986) J. Chem. Phys. 84, 3449-3450"; }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", 0.0, max_packing<double>()}}}; }
  constexpr Arguments<double, 2> parameter_domain() const {
    return detail::packing_domain(max_packing<double>(), packing_margin);
  }
  // The packing limit is a constant of Ma and Ahmadi's fit, not a parameter.
  static constexpr auto parameters() { return std::array{parameter<&MaAhmadi::packing_margin>("packing_margin")}; }
  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi) const {
    using std::pow;
    using T = value_type_of<S>;
    const S polynomial = 1 + phi * (T(2.5) + phi * (FLUIDBED_DECIMAL(T, 4.5904) + phi * FLUIDBED_DECIMAL(T, 4.515439)));
    const S packing = detail::continued_linearly_above(phi, max_packing<T>() - T(packing_margin), [](const auto& x) {
      const auto r = x / max_packing<T>();
      return pow(1 - r * r * r, FLUIDBED_DECIMAL(T, -0.67802));
    });
    return polynomial * packing;
  }
};

// The two further fits of seed 002 eq. 77 with its Table III, in the form
//   g0 = y/(4φ) = Σ_n c_n (4φ)^n / (1 − φ/φ_cp)^b
// (y = 4φ g0 the excess compressibility, seed 002 eq. 77 with a = 1). The polynomial is
// evaluated in x = 4φ with Table III's c_n as printed. Unlike Ma–Ahmadi's, these polynomials
// have negative high-order coefficients: continued beyond the pole they would turn down near
// φ ≈ 0.77 and below zero near 0.86. So the whole g0 (not only its singular factor) is
// continued linearly above φ_cp − packing_margin: finite, increasing and positive for φ < 1.
// Both → 1 as φ → 0, with the slope 4 c_1 + b/φ_cp (2.50024 and 2.49975; the second virial
// coefficient gives 5/2).

namespace detail {

// What the two fits share: a pole φ_cp that is a constant of the fit (Law::max_packing<T>()), and
// the whole published formula Law::formula(φ) continued linearly above φ_cp − packing_margin.
template <class Law>
struct CompressibilityFit : SolidFractionLaw<Law> {
  double packing_margin;

  constexpr explicit CompressibilityFit(double packing_margin_) : packing_margin(packing_margin_) {}
  constexpr Validity<1> validity() const {
    return {{{"solid_fraction", 0.0, Law::template max_packing<double>()}}};
  }
  constexpr Arguments<double, 2> parameter_domain() const {
    return packing_domain(Law::template max_packing<double>(), packing_margin);
  }
  // The pole is a constant of the fit, not a parameter.
  static constexpr auto parameters() {
    return std::array{parameter<&CompressibilityFit::packing_margin, Law>("packing_margin")};
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi) const {
    using T = value_type_of<S>;
    return continued_linearly_above(phi, Law::template max_packing<T>() - T(packing_margin),
                                    [](const auto& q) { return Law::formula(q); });
  }
};

}  // namespace detail

// Song, Stratt & Mason (1988), J. Chem. Phys. 88, 1126 (seed 002 Table III prints "Strat"),
// φ_cp = 0.6435, b = 0.76:
//   c_n = 1, 0.3298, 0.08867, 0.01472, 0.0005396, −0.0003574, −0.0005705, −0.0001212, −0.0001151.
// Validity: declared up to the fit's pole φ_cp = 0.6435 (random close packing), as for Ma–Ahmadi;
// seed 002 Fig. 23 compares it with hard-sphere molecular dynamics.
struct SongStrattMason : detail::CompressibilityFit<SongStrattMason> {
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T max_packing() {
    return FLUIDBED_DECIMAL(T, 0.6435);
  }

  constexpr explicit SongStrattMason(double packing_margin_ = default_packing_margin) : CompressibilityFit{packing_margin_} {}
  constexpr std::string_view name() const { return "SongStrattMason"; }
  constexpr std::string_view reference() const {
    return "Song, Y., Stratt, R.M. & Mason, E.A. (1988) J. Chem. Phys. 88, 1126-1133; seed 002 eq. 77, Table III";
  }
  // The published formula, for any scalar (continued above φ_cp − packing_margin by the base).
  template <class S>
  FLUIDBED_HOST_DEVICE static S formula(const S& phi) {
    using std::pow;
    using T = value_type_of<S>;
    const S x = 4 * phi;
    const S polynomial =
        1 + x * (FLUIDBED_DECIMAL(T, 0.3298) +
                 x * (FLUIDBED_DECIMAL(T, 0.08867) +
                      x * (FLUIDBED_DECIMAL(T, 0.01472) +
                           x * (FLUIDBED_DECIMAL(T, 0.0005396) +
                                x * (FLUIDBED_DECIMAL(T, -0.0003574) +
                                     x * (FLUIDBED_DECIMAL(T, -0.0005705) +
                                          x * (FLUIDBED_DECIMAL(T, -0.0001212) +
                                               x * FLUIDBED_DECIMAL(T, -0.0001151))))))));
    return polynomial * pow(1 - phi / max_packing<T>(), FLUIDBED_DECIMAL(T, -0.76));
  }
};

// Tobochnik & Chapin (1988), J. Chem. Phys. 88, 5824 (as credited by seed 002 Table III),
// φ_cp = 0.6875, b = 1:
//   c_n = 1, 0.2613, 0.05968, 0.005905, −0.001191, −0.0004455, −0.0004818, −0.00003636,
//         −0.00008182.
// Validity: declared up to the fit's pole φ_cp = 0.6875, as Table III gives it; above random
// close packing (≈ 0.64) there is no disordered hard-sphere state to compare it with.
struct TobochnikChapin : detail::CompressibilityFit<TobochnikChapin> {
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr T max_packing() {
    return FLUIDBED_DECIMAL(T, 0.6875);
  }

  constexpr explicit TobochnikChapin(double packing_margin_ = default_packing_margin) : CompressibilityFit{packing_margin_} {}
  constexpr std::string_view name() const { return "TobochnikChapin"; }
  constexpr std::string_view reference() const {
    return "Tobochnik, J. & Chapin, P.M. (1988) J. Chem. Phys. 88, 5824; seed 002 eq. 77, Table III";
  }
  // The published formula, for any scalar (continued above φ_cp − packing_margin by the base).
  template <class S>
  FLUIDBED_HOST_DEVICE static S formula(const S& phi) {
    using T = value_type_of<S>;
    const S x = 4 * phi;
    const S polynomial =
        1 + x * (FLUIDBED_DECIMAL(T, 0.2613) +
                 x * (FLUIDBED_DECIMAL(T, 0.05968) +
                      x * (FLUIDBED_DECIMAL(T, 0.005905) +
                           x * (FLUIDBED_DECIMAL(T, -0.001191) +
                                x * (FLUIDBED_DECIMAL(T, -0.0004455) +
                                     x * (FLUIDBED_DECIMAL(T, -0.0004818) +
                                          x * (FLUIDBED_DECIMAL(T, -0.00003636) +
                                               x * FLUIDBED_DECIMAL(T, -0.00008182))))))));
    return polynomial / (1 - phi / max_packing<T>());
  }
};

namespace detail {

// (1 − x/x_max)^(−power), continued linearly above x_max − margin: the factors of the
// modified Mansoori form (Lathouwers–Bellan).
template <class S>
FLUIDBED_HOST_DEVICE S inverse_gap_power(const S& x, double max_packing, double margin, int power) {
  using T = value_type_of<S>;
  const T m = T(max_packing);
  return continued_linearly_above(x, m - T(margin), [&](const auto& y) {
    const auto inverse_gap = 1 / (1 - y / m);
    auto result = inverse_gap;
    for (int i = 1; i < power; ++i) result = result * inverse_gap;
    return result;
  });
}

// The three factors 1/(1−x), 1/(1−x)², 1/(1−x)³ of the Mansoori form, with x = φ_t/φ_max.
template <class S>
struct MansooriFactors {
  S first, second, third;
};

template <class S>
FLUIDBED_HOST_DEVICE MansooriFactors<S> modified_mansoori_factors(const S& total_fraction, double max_packing,
                                                                  double margin) {
  return {inverse_gap_power(total_fraction, max_packing, margin, 1),
          inverse_gap_power(total_fraction, max_packing, margin, 2),
          inverse_gap_power(total_fraction, max_packing, margin, 3)};
}

// The Mansoori sum F1 + 3 r F2 + 2 r² F3 for gap factors F_j and r = d_ik ξ (for one class
// r = φ/2).
template <class S>
FLUIDBED_HOST_DEVICE constexpr S mansoori_sum(const MansooriFactors<S>& f, const S& reduced_xi) {
  return f.first + 3 * reduced_xi * f.second + 2 * reduced_xi * reduced_xi * f.third;
}

}  // namespace detail

// Lathouwers & Bellan (2001), Int. J. Multiphase Flow 27, 2155–2187; seed 004 (binary
// h_ik) for one class: the Mansoori mixture form with the gas fraction replaced by
// 1 − φ/φ_max,
//   g0 = 1/(1 − x) + (3/2) φ/(1 − x)² + (1/2) φ²/(1 − x)³,   x = φ/φ_max.
// Seed 004 prints the third term of h_ik as 8 r² ξ/(1 − x)²: dimensionally wrong (it has
// units of length) — the Mansoori et al. (1971) term is 8 r² ξ²/(1 − x)³, which is what
// reduces to Carnahan–Starling at φ_max = 1. Each factor (1 − x)^(−j) is continued linearly
// above φ_max − packing_margin. Seed 004 uses φ_max = 0.64, with which it is registered.
// Validity: φ up to φ_max.
struct LathouwersBellan : SolidFractionLaw<LathouwersBellan> {
  double max_packing;
  double packing_margin = default_packing_margin;

  constexpr LathouwersBellan(double max_packing_, double packing_margin_ = default_packing_margin)
      : max_packing(max_packing_), packing_margin(packing_margin_) {}
  static constexpr std::array<LathouwersBellan, 1> registered() { return {LathouwersBellan{0.64}}; }
  constexpr std::string_view name() const { return "LathouwersBellan"; }
  constexpr std::string_view reference() const {
    return "Lathouwers, D. & Bellan, J. (2001) Int. J. Multiphase Flow 27, 2155-2187";
  }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", 0.0, max_packing}}}; }
  constexpr Arguments<double, 2> parameter_domain() const {
    return detail::packing_domain(max_packing, packing_margin);
  }
  static constexpr auto parameters() {
    return std::array{parameter<&LathouwersBellan::max_packing>("max_packing"),
                      parameter<&LathouwersBellan::packing_margin>("packing_margin")};
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi) const {
    const auto f = detail::modified_mansoori_factors(phi, max_packing, packing_margin);
    return detail::mansoori_sum(f, S(value_type_of<S>(0.5) * phi));
  }
};

}  // namespace fluidbed::kinetic_theory
