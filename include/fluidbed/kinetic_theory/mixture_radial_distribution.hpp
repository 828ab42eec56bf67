// fluidbed — radial distribution functions at contact for several solids classes, g_ik.
//
// Classes m = 1..n with volume fractions φ_m and diameters d_m; with
//   φ_t = Σ φ_m,   ξ = Σ φ_m/d_m [m⁻¹],   d_ik = d_i d_k/(d_i + d_k),
// each form gives the contact value between a particle of class i and one of class k.
// The fractions are a span of the scalar S (a Dual per class gives ∂g_ik/∂φ_m for every
// m), the diameters a span of T. Preconditions (asserted in debug builds): equal non-zero
// lengths, i and k valid indices, φ_m ≥ 0, d_m > 0, φ_t < 1, and for ModifiedMansoori
// φ_max ∈ (0, 1] and 0 < packing_margin < φ_max. law.checked(fractions, diameters, i, k)
// validates them and throws std::domain_error naming the argument and its value (e.g.
// 'fractions[2]'); law.with_derivatives(fractions, diameters, i, k), for an array of N
// fractions, gives g_ik with ∂g_ik/∂φ_m for every m. Shape: MixtureRadialDistribution below.
//
// One-class limits (tested): Lebowitz → PercusYevick, Mansoori → CarnahanStarling,
// ModifiedMansoori → LathouwersBellan; splitting a class into identical halves changes
// nothing.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "radial_distribution.hpp"

namespace fluidbed::kinetic_theory {

namespace detail {

template <class S>
struct MixtureSums {
  S total_fraction;          // φ_t
  S fraction_over_diameter;  // ξ = Σ φ_m/d_m
};

// The domains of the mixture's arguments, declared once for the hot path's assertions and the
// checked path's exceptions: every φ_m ≥ 0, every d_m > 0, φ_t = Σ φ_m ∈ [0, 1).
template <class T>
struct MixtureDomain {
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> fraction() { return domains::non_negative<T>(); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> diameter() { return domains::positive<T>(); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> total_fraction() { return domains::closed_open(T(0), T(1)); }
};

// φ_t and ξ of the classes, asserting the preconditions of g_ik (i, k the pair's classes).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr MixtureSums<S> mixture_sums(std::span<const S> fractions, std::span<const T> diameters,
                                                           std::size_t i, std::size_t k) {
  using Domain = MixtureDomain<T>;
  FLUIDBED_EXPECTS(!fractions.empty() && fractions.size() == diameters.size() && i < fractions.size() &&
                   k < fractions.size());
  S total(0), xi(0);
  for (std::size_t m = 0; m < fractions.size(); ++m) {
    FLUIDBED_EXPECTS(Domain::fraction().contains(value_of(fractions[m])) && Domain::diameter().contains(diameters[m]));
    total = total + fractions[m];
    xi = xi + fractions[m] / diameters[m];
  }
  FLUIDBED_EXPECTS(Domain::total_fraction().contains(value_of(total)));
  return {total, xi};
}

// d_ik ξ, the Mansoori sum's reduced ξ for the pair (i, k).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S reduced_xi(const S& xi, const T& d_i, const T& d_k) {
  return (d_i * d_k / (d_i + d_k)) * xi;
}

}  // namespace detail

// g_ik with its derivatives in the N fractions.
template <class T, std::size_t N>
struct MixtureValueAndDerivatives {
  T value;
  std::array<T, N> d_fractions;  // ∂g_ik/∂φ_m, m = 0 … N − 1
};

// The shape g(fractions, diameters, i, k) of the mixture forms (CRTP). Law provides
// kernel(fractions, diameters, i, k), templated on the scalar of the fractions, which calls
// detail::mixture_sums (asserting the domains), and, if it has parameters, parameter_domain().
template <class Law>
struct MixtureRadialDistribution {
  // Hot path.
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S operator()(std::span<const S> fractions, std::span<const T> diameters,
                                              std::size_t i, std::size_t k) const {
    FLUIDBED_EXPECTS(detail::parameters_within(self()));
    return self().kernel(fractions, diameters, i, k);
  }

  // g_ik and ∂g_ik/∂φ_m for each of the N classes (hot path).
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE MixtureValueAndDerivatives<T, N> with_derivatives(const std::array<T, N>& fractions,
                                                                         std::span<const T> diameters, std::size_t i,
                                                                         std::size_t k) const {
    using D = Dual<T, int(N)>;
    std::array<D, N> dual_fractions{};
    for (std::size_t m = 0; m < N; ++m) dual_fractions[m] = D::variable(fractions[m], int(m));
    const D g = (*this)(std::span<const D>(dual_fractions), diameters, i, k);
    MixtureValueAndDerivatives<T, N> result{g.value, {}};
    for (std::size_t m = 0; m < N; ++m) result.d_fractions[m] = g.derivative[m];
    return result;
  }

  // Checked entry point: validates the spans (equal lengths >= 1, every φ_m ≥ 0, d_m > 0,
  // φ_t < 1), the pair (i, k) and the law's parameters, throwing std::domain_error naming the
  // argument and its value, then evaluates g_ik.
  template <class T>
  T checked(std::span<const T> fractions, std::span<const T> diameters, std::size_t i, std::size_t k) const {
    require_valid(fractions, diameters, i, k);
    return self().kernel(fractions, diameters, i, k);
  }
  template <class T, std::size_t N>
  MixtureValueAndDerivatives<T, N> checked_with_derivatives(const std::array<T, N>& fractions,
                                                            std::span<const T> diameters, std::size_t i,
                                                            std::size_t k) const {
    require_valid(std::span<const T>(fractions), diameters, i, k);
    return with_derivatives(fractions, diameters, i, k);
  }

  // Throws as `checked` would, without evaluating.
  template <class T>
  void require_valid(std::span<const T> fractions, std::span<const T> diameters, std::size_t i, std::size_t k) const {
    using Domain = detail::MixtureDomain<T>;
    const std::string function = detail::checked_function_name(self());
    if (fractions.empty()) fluidbed::detail::throw_domain_error(function, "fractions.size()", 0, "must be >= 1");
    if (diameters.size() != fractions.size())
      fluidbed::detail::throw_domain_error(function, "diameters.size()", diameters.size(),
                                           "must equal fractions.size() = " + std::to_string(fractions.size()));
    const std::string classes = "must be < fractions.size() = " + std::to_string(fractions.size());
    if (i >= fractions.size()) fluidbed::detail::throw_domain_error(function, "i", i, classes);
    if (k >= fractions.size()) fluidbed::detail::throw_domain_error(function, "k", k, classes);
    T total(0);
    for (std::size_t m = 0; m < fractions.size(); ++m) {
      require_in(function, indexed_argument("fractions", m), fractions[m], Domain::fraction());
      require_in(function, indexed_argument("diameters", m), diameters[m], Domain::diameter());
      total += fractions[m];
    }
    require_in(function, "sum of fractions", total, Domain::total_fraction());
    detail::require_parameters(function, self());
  }

 private:
  FLUIDBED_HOST_DEVICE constexpr const Law& self() const { return static_cast<const Law&>(*this); }
};

// Lebowitz (1964), Phys. Rev. 133, A895–A899, doi:10.1103/PhysRev.133.A895 (Percus–Yevick
// mixture), in MFiX's general form
//   g_ik = 1/(1 − φ_t) + 3 ξ d_i d_k / ((1 − φ_t)² (d_i + d_k)).
// Seed 000 eq. 6.16 writes the bracket as (φ_i/ξ_i + φ_k/ξ_k) (ξ = diameters there): that is
// Σ_m φ_m/d_m only for two classes with i ≠ k, the case it is used for. Validity: the
// hard-sphere fluid, φ_t to the freezing point ≈ 0.49.
struct Lebowitz : MixtureRadialDistribution<Lebowitz> {
  constexpr std::string_view name() const { return "Lebowitz"; }
  constexpr std::string_view reference() const {
    return "Lebowitz, J.L. (1964) Phys. Rev. 133, A895-A899, doi:10.1103/PhysRev.133.A895";
  }
  constexpr Validity<1> validity() const { return {{{"total_solid_fraction", 0.0, 0.49}}}; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S kernel(std::span<const S> fractions, std::span<const T> diameters, std::size_t i,
                                              std::size_t k) const {
    const auto sums = detail::mixture_sums(fractions, diameters, i, k);
    const S inverse_gap = 1 / (1 - sums.total_fraction);
    const T d_i = diameters[i], d_k = diameters[k];
    return inverse_gap + 3 * (d_i * d_k / (d_i + d_k)) * sums.fraction_over_diameter * inverse_gap * inverse_gap;
  }
};

// Mansoori, Carnahan, Starling & Leland (1971), J. Chem. Phys. 54, 1523–1525,
// doi:10.1063/1.1675048 (the Boublík–Mansoori mixture extension of Carnahan–Starling):
//   g_ik = 1/(1 − φ_t) + 3 d_ik ξ/(1 − φ_t)² + 2 d_ik² ξ²/(1 − φ_t)³.
// Validity: as Carnahan–Starling, φ_t up to 0.55.
struct Mansoori : MixtureRadialDistribution<Mansoori> {
  constexpr std::string_view name() const { return "Mansoori"; }
  constexpr std::string_view reference() const {
    return "Mansoori, G.A., Carnahan, N.F., Starling, K.E. & Leland, T.W. (1971) J. Chem. Phys. 54, 1523-1525, "
           "doi:10.1063/1.1675048";
  }
  constexpr Validity<1> validity() const { return {{{"total_solid_fraction", 0.0, 0.55}}}; }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S kernel(std::span<const S> fractions, std::span<const T> diameters, std::size_t i,
                                              std::size_t k) const {
    const auto sums = detail::mixture_sums(fractions, diameters, i, k);
    const S inverse_gap = 1 / (1 - sums.total_fraction);
    const detail::MansooriFactors<S> f{inverse_gap, inverse_gap * inverse_gap, inverse_gap * inverse_gap * inverse_gap};
    return detail::mansoori_sum(f, detail::reduced_xi(sums.fraction_over_diameter, diameters[i], diameters[k]));
  }
};

// The Mansoori form with 1 − φ_t replaced by 1 − φ_t/φ_max, so that it diverges at
// packing: seed 004's h_ik (Lathouwers & Bellan 2001) with its third term corrected (see
// LathouwersBellan), MFiX MODIFIED_MANSOORI. Each factor is continued linearly in φ_t
// above φ_max − packing_margin. Registered with φ_max = 0.64 (seed 004). Validity: φ_t up
// to φ_max.
struct ModifiedMansoori : MixtureRadialDistribution<ModifiedMansoori> {
  double max_packing;
  double packing_margin = default_packing_margin;

  constexpr ModifiedMansoori(double max_packing_, double packing_margin_ = default_packing_margin)
      : max_packing(max_packing_), packing_margin(packing_margin_) {}
  static constexpr std::array<ModifiedMansoori, 1> registered() { return {ModifiedMansoori{0.64}}; }
  constexpr std::string_view name() const { return "ModifiedMansoori"; }
  constexpr std::string_view reference() const {
    return "Lathouwers, D. & Bellan, J. (2001) Int. J. Multiphase Flow 27, 2155-2187; Mansoori et al. (1971) J. Chem. "
           "Phys. 54, 1523-1525";
  }
  constexpr Validity<1> validity() const { return {{{"total_solid_fraction", 0.0, max_packing}}}; }
  constexpr Arguments<double, 2> parameter_domain() const {
    return detail::packing_domain(max_packing, packing_margin);
  }
  static constexpr auto parameters() {
    return std::array{parameter<&ModifiedMansoori::max_packing>("max_packing"),
                      parameter<&ModifiedMansoori::packing_margin>("packing_margin")};
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S kernel(std::span<const S> fractions, std::span<const T> diameters, std::size_t i,
                                std::size_t k) const {
    const auto sums = detail::mixture_sums(fractions, diameters, i, k);
    const auto f = detail::modified_mansoori_factors(sums.total_fraction, max_packing, packing_margin);
    return detail::mansoori_sum(f, detail::reduced_xi(sums.fraction_over_diameter, diameters[i], diameters[k]));
  }
};

}  // namespace fluidbed::kinetic_theory
