// fluidbed — radial distribution functions at contact for several solids classes, g_ik.
//
// Classes m = 1..n with volume fractions φ_m and diameters d_m; with
//   φ_t = Σ φ_m,   ξ = Σ φ_m/d_m [m⁻¹],   d_ik = d_i d_k/(d_i + d_k),
// each form gives the contact value between a particle of class i and one of class k.
// The fractions are a span of the scalar S (a Dual per class gives ∂g_ik/∂φ_m for every
// m), the diameters a span of T. Preconditions (asserted in debug builds): equal non-zero
// lengths, i and k valid indices, φ_m ≥ 0, d_m > 0, φ_t < 1, and for ModifiedMansoori
// φ_max ∈ (0, 1] and 0 < packing_margin < φ_max. evaluate_checked(law, fractions,
// diameters, i, k) validates them and throws std::domain_error naming the argument and its
// value (e.g. 'fractions[2]').
//
// One-class limits (tested): Lebowitz → PercusYevick, Mansoori → CarnahanStarling,
// ModifiedMansoori → LathouwersBellan; splitting a class into identical halves changes
// nothing.
#pragma once

#include <concepts>
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

// φ_t and ξ of the classes, asserting the preconditions of g_ik (i, k the pair's classes).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr MixtureSums<S> mixture_sums(std::span<const S> fractions, std::span<const T> diameters,
                                                           std::size_t i, std::size_t k) {
  FLUIDBED_EXPECTS(!fractions.empty() && fractions.size() == diameters.size() && i < fractions.size() &&
                   k < fractions.size());
  S total(0), xi(0);
  for (std::size_t m = 0; m < fractions.size(); ++m) {
    FLUIDBED_EXPECTS(value_of(fractions[m]) >= 0 && diameters[m] > T(0));
    total = total + fractions[m];
    xi = xi + fractions[m] / diameters[m];
  }
  FLUIDBED_EXPECTS(value_of(total) < 1);
  return {total, xi};
}

// d_ik ξ, the Mansoori sum's reduced ξ for the pair (i, k).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S reduced_xi(const S& xi, const T& d_i, const T& d_k) {
  return (d_i * d_k / (d_i + d_k)) * xi;
}

}  // namespace detail

// Lebowitz (1964), Phys. Rev. 133, A895–A899, doi:10.1103/PhysRev.133.A895 (Percus–Yevick
// mixture), in MFiX's general form
//   g_ik = 1/(1 − φ_t) + 3 ξ d_i d_k / ((1 − φ_t)² (d_i + d_k)).
// Seed 000 eq. 6.16 writes the bracket as (φ_i/ξ_i + φ_k/ξ_k) (ξ = diameters there): that is
// Σ_m φ_m/d_m only for two classes with i ≠ k, the case it is used for.
struct Lebowitz {
  constexpr std::string_view name() const { return "Lebowitz"; }
  constexpr std::string_view reference() const {
    return "Lebowitz, J.L. (1964) Phys. Rev. 133, A895-A899, doi:10.1103/PhysRev.133.A895";
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S operator()(std::span<const S> fractions, std::span<const T> diameters, std::size_t i,
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
struct Mansoori {
  constexpr std::string_view name() const { return "Mansoori"; }
  constexpr std::string_view reference() const {
    return "Mansoori, G.A., Carnahan, N.F., Starling, K.E. & Leland, T.W. (1971) J. Chem. Phys. 54, 1523-1525, "
           "doi:10.1063/1.1675048";
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S operator()(std::span<const S> fractions, std::span<const T> diameters, std::size_t i,
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
// above φ_max − packing_margin.
struct ModifiedMansoori {
  double max_packing;
  double packing_margin = default_packing_margin;

  constexpr std::string_view name() const { return "ModifiedMansoori"; }
  constexpr std::string_view reference() const {
    return "Lathouwers, D. & Bellan, J. (2001) Int. J. Multiphase Flow 27, 2155-2187; Mansoori et al. (1971) J. Chem. "
           "Phys. 54, 1523-1525";
  }
  void validate(std::string_view function) const { detail::validate_packing(function, max_packing, packing_margin); }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S operator()(std::span<const S> fractions, std::span<const T> diameters, std::size_t i,
                                    std::size_t k) const {
    const auto sums = detail::mixture_sums(fractions, diameters, i, k);
    FLUIDBED_EXPECTS(detail::valid_packing(max_packing, packing_margin));
    const auto f = detail::modified_mansoori_factors(sums.total_fraction, max_packing, packing_margin);
    return detail::mansoori_sum(f, detail::reduced_xi(sums.fraction_over_diameter, diameters[i], diameters[k]));
  }
};

// The calling shape of the mixture forms.
template <class Law, class T>
concept MixtureLaw = requires(const Law& law, std::span<const T> values, std::size_t i) {
  { law(values, values, i, i) } -> std::convertible_to<T>;
};

// Checked entry point of the mixture forms: validates the spans (equal lengths >= 1, every
// φ_m ≥ 0, d_m > 0, φ_t < 1), the pair (i, k) and the law's parameters, throwing
// std::domain_error naming the argument and its value, then evaluates g_ik.
template <class T, MixtureLaw<T> Law>
T evaluate_checked(const Law& law, std::span<const T> fractions, std::span<const T> diameters, std::size_t i,
                   std::size_t k) {
  const std::string function = detail::checked_function_name(law);
  if (fractions.empty()) fluidbed::detail::throw_domain_error(function, "fractions.size()", 0, "must be >= 1");
  if (diameters.size() != fractions.size())
    fluidbed::detail::throw_domain_error(function, "diameters.size()", diameters.size(),
                                         "must equal fractions.size() = " + std::to_string(fractions.size()));
  const std::string classes = "must be < fractions.size() = " + std::to_string(fractions.size());
  if (i >= fractions.size()) fluidbed::detail::throw_domain_error(function, "i", i, classes);
  if (k >= fractions.size()) fluidbed::detail::throw_domain_error(function, "k", k, classes);
  T total(0);
  for (std::size_t m = 0; m < fractions.size(); ++m) {
    require_non_negative(function, indexed_argument("fractions", m), fractions[m]);
    require_positive(function, indexed_argument("diameters", m), diameters[m]);
    total += fractions[m];
  }
  require_in_closed_open(function, "sum of fractions", total, T(0), T(1));
  validate_parameters(function, law);
  return law(fractions, diameters, i, k);
}

}  // namespace fluidbed::kinetic_theory
