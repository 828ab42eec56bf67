// fluidbed — moment sets: the moments of a quadrature, of a sieve analysis and of a log-normal
// distribution; mean diameters; VDF ↔ NDF moments.
//
// Conventions (seed 000 §5.2, §5.7; seed 003 eqs. 0.5–0.7, 0.11):
//   M_k = ∫ f_v(ξ) ξ^k dξ, the raw moments of the VOLUME density function f_v over the particle
//   DIAMETER ξ, dimensional (m^k) and unnormalised; the tracked set is k = 0 … 2ν − 1.
//   f_v = f_n π ξ³/6 (spheres), so M_k = (π/6) μ_{k+3} with μ_j = ∫ f_n ξ^j dξ the NDF moments.
//   M_0 = φ = 1 − ε, the solids volume fraction (voids included in the unit volume).
//   A quadrature {φ_i, ξ_i} (weights = class volume fractions, nodes = diameters) stands for
//   f_v ≈ Σ φ_i δ(ξ − ξ_i), so M_k = Σ φ_i ξ_i^k for every k, negative orders included.
// Mean diameters: d_pq = (μ_p/μ_q)^{1/(p−q)} = (M_{p−3}/M_{q−3})^{1/(p−q)}; d43 = M_1/M_0
// (De Brouckère), d32 = M_0/M_{−1} (Sauter), d10 = M_{−2}/M_{−3} (number mean).
//
// Counts. A function that fills a caller's span returns false, with every entry of that span
// NaN, when the spans it is given do not match (nodes and weights of different lengths, an
// output longer than its input); a function returning one value returns NaN for too few
// moments, a sieve analysis whose edges are not one more than its fractions (or without a bin),
// or a quadrature whose size is not within 0 … N. Nothing is read beyond a span, at any
// optimisation level; sieve_moment(…, fluidbed::checked) throws instead, naming the counts.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "../core/config.hpp"
#include "../core/constants.hpp"
#include "../core/errors.hpp"
#include "jacobi_eigen.hpp"

namespace fluidbed::moments {

namespace detail {

// x^k for any integer k, by repeated multiplication (exact for the small k of moment sets and
// valid for any T, where std::pow(T, int) is not always available).
template <class T>
FLUIDBED_HOST_DEVICE T integer_power(const T& x, int k) {
  const T base = k < 0 ? T(1) / x : x;
  T result(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) result *= base;
  return result;
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Moments of a quadrature (a sum of atoms)

// m_k = Σ_i w_i x_i^k for k = 0 … out.size() − 1. Returns false (every out[k] NaN) unless
// nodes.size() == weights.size().
template <class T>
FLUIDBED_HOST_DEVICE bool moments_from_quadrature(std::span<const T> nodes, std::span<const T> weights,
                                                  std::span<T> out) {
  if (nodes.size() != weights.size()) {
    detail::fill_with_nan(out);
    return false;
  }
  for (T& m : out) m = T(0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    T term = weights[i];
    for (T& m : out) {
      m += term;
      term *= nodes[i];
    }
  }
  return true;
}

// The same for the q.size nodes of a quadrature (false, out NaN, for a size not within 0 … N).
template <class T, int N>
FLUIDBED_HOST_DEVICE bool moments_from_quadrature(const Quadrature<T, N>& q, std::span<T> out) {
  if (!detail::size_in_storage(q)) {
    detail::fill_with_nan(out);
    return false;
  }
  return moments_from_quadrature<T>(std::span<const T>(q.nodes.data(), std::size_t(q.size)),
                                    std::span<const T>(q.weights.data(), std::size_t(q.size)), out);
}

// One moment of any integer order k of a quadrature: Σ_i w_i x_i^k (k < 0 needs nodes ≠ 0); NaN
// for a size not within 0 … N.
template <class T, int N>
FLUIDBED_HOST_DEVICE T quadrature_moment(const Quadrature<T, N>& q, int k) {
  if (!detail::size_in_storage(q)) return std::numeric_limits<T>::quiet_NaN();
  T sum(0);
  for (int i = 0; i < q.size; ++i) sum += q.weights[i] * detail::integer_power(q.nodes[i], k);
  return sum;
}

// ---------------------------------------------------------------------------------------------
// Moments of a sieve analysis (seed 000 App. E)

// What the fractions of a sieve analysis count.
enum class SizeBasis {
  volume,  // mass fractions (equal density: volume fractions) — the sieve's own output
  number,  // number fractions (counting, image analysis)
};

// A particle size distribution given by bins: bin i (i = 1 … n) holds the fraction
// fractions[i−1] of the particles between the apertures edges[i−1] < edges[i] (n + 1 edges,
// strictly increasing, >= 0; a pan is a bin with lower edge 0). The fractions need not sum to 1:
// they are normalised (seed 000 App. E takes Σ ω_i = 1 and M_0 = 1 − ε; it does not say what to
// do otherwise, and normalising keeps M_0 = 1 − ε, the solids fraction, exact).
template <class T>
struct SieveAnalysis {
  std::span<const T> edges;
  std::span<const T> fractions;
  SizeBasis basis = SizeBasis::volume;
};

namespace detail {

// ⟨ξ^p⟩ over [a, b], 0 <= a < b: (b^{p+1} − a^{p+1})/((p + 1)(b − a)), the logarithmic limit
// ln(b/a)/(b − a) for p = −1, each written as a sum of positive terms so that a narrow bin
// loses nothing to cancellation:
//   p >= 0:  Σ_{j=0}^{p} a^j b^{p−j} / (p + 1)
//   p = −1:  log1p((b − a)/a) / (b − a)
//   p <= −2: Σ_{j=0}^{q−1} a^{j−q} b^{−1−j} / q,  q = −p − 1
// For a = 0 and p < 0 the mean is +∞ (a pan with a uniform VDF down to ξ = 0 holds infinitely
// many particles).
template <class T>
FLUIDBED_HOST_DEVICE T bin_power_mean(const T& a, const T& b, int p) {
  using std::log1p;
  if (p >= 0) {
    T sum(0);
    for (int j = 0; j <= p; ++j) sum += integer_power(a, j) * integer_power(b, p - j);
    return sum / T(p + 1);
  }
  if (p == -1) return log1p((b - a) / a) / (b - a);
  const int q = -p - 1;
  T sum(0);
  for (int j = 0; j < q; ++j) sum += integer_power(a, j - q) * integer_power(b, -1 - j);
  return sum / T(q);
}

// Whether the edges of a sieve analysis are one more than its fractions, with at least one bin.
template <class T>
FLUIDBED_HOST_DEVICE bool bins_match(const SieveAnalysis<T>& psd) {
  return !psd.fractions.empty() && psd.edges.size() == psd.fractions.size() + 1;
}

// Σ_i f_i ⟨ξ^{k+s}⟩_i, s = 0 (volume basis) or 3 (number basis): the unnormalised M_k (NaN
// unless bins_match).
template <class T>
FLUIDBED_HOST_DEVICE T sieve_sum(const SieveAnalysis<T>& psd, int k) {
  if (!bins_match(psd)) return std::numeric_limits<T>::quiet_NaN();
  const int shift = psd.basis == SizeBasis::number ? 3 : 0;
  T sum(0);
  for (std::size_t i = 0; i < psd.fractions.size(); ++i)
    sum += psd.fractions[i] * bin_power_mean(psd.edges[i], psd.edges[i + 1], k + shift);
  return sum;
}

}  // namespace detail

// The VDF moment M_k, any integer k, of a sieve analysis in a bed of voidage ε: seed 000
// eq. E.7 (= eq. 6.3 = seed 003 eq. 0.17), the VDF taken uniform within each bin,
//   M_k = (1 − ε) Σ_i ω_i (ξ_i^{k+1} − ξ_{i−1}^{k+1}) / ((k + 1)(ξ_i − ξ_{i−1})) / Σ_i ω_i,
// with the exact logarithmic limit (1 − ε) Σ ω_i ln(ξ_i/ξ_{i−1})/(ξ_i − ξ_{i−1}) at k = −1,
// where E.7 divides by zero. Units: those of the edges, to the power k.
//
// Number-based input (basis = number) is converted consistently by taking the NDF, not the
// VDF, uniform within each bin (the number analogue of E.7): f_v = (π/6) ξ³ f_n gives
//   M_k = (1 − ε) Σ_i ν_i ⟨ξ^{k+3}⟩_i / Σ_i ν_i ⟨ξ³⟩_i,   ⟨ξ^p⟩_i = bin mean of ξ^p,
// i.e. bin volume fractions ω_i = ν_i⟨ξ³⟩_i/Σ_j ν_j⟨ξ³⟩_j with a VDF ∝ ξ³ inside each bin. Feeding
// those ω_i to E.7 instead would differ at second order in the bin width.
// NaN unless edges.size() == fractions.size() + 1 >= 2 (see Counts above). Preconditions
// (validated with fluidbed::checked): edges strictly increasing and >= 0, fractions >= 0 with a
// positive sum, 0 < ε <= 1, edges[0] > 0 if k < 0 (else the result is +∞), and M_k within the
// range of T (edges whose powers overflow give ±∞ or NaN: the checked path rejects them;
// below the range, 0).
namespace detail {

// sieve_moment's preconditions validated (the checked path): throws std::domain_error naming
// the offending argument.
template <class T>
void require_valid_sieve(const SieveAnalysis<T>& psd, const T& voidage, int k) {
  constexpr const char* function = "moments::sieve_moment";
  if (psd.fractions.empty())
    fluidbed::detail::throw_domain_error(function, "fractions.size()", psd.fractions.size(), "must be >= 1 (a bin)");
  if (!detail::bins_match(psd))
    fluidbed::detail::throw_domain_error(function, "edges.size()", psd.edges.size(),
                                         "must be fractions.size() + 1 = " + std::to_string(psd.fractions.size() + 1));
  require_non_negative(function, "edges[0]", psd.edges[0]);
  if (k < 0) require_positive(function, "edges[0] (negative order k)", psd.edges[0]);
  for (std::size_t i = 1; i < psd.edges.size(); ++i)
    if (!fluidbed::detail::is_finite_number(psd.edges[i]) || !(psd.edges[i] > psd.edges[i - 1]))
      fluidbed::detail::throw_domain_error(function, indexed_argument("edges", i), psd.edges[i],
                                           "must be finite and increasing");
  T total(0);
  for (std::size_t i = 0; i < psd.fractions.size(); ++i) {
    require_non_negative(function, indexed_argument("fractions", i), psd.fractions[i]);
    total += psd.fractions[i];
  }
  require_positive(function, "sum of fractions", total);
  require_in_half_open(function, "voidage", voidage, T(0), T(1));
}

}  // namespace detail

// With `fluidbed::checked` as the last argument, the preconditions are validated and
// std::domain_error names the offending argument; it also names k when the moment itself is
// beyond the range of T: the powers of the edges (or the sums of the fractions) overflow, and the
// result would be ±∞ or NaN. A moment below the range underflows to 0 (or a subnormal) as any
// product does, in either path: float in SI units gives M_k = 0 from k ~ 12.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE T sieve_moment(const SieveAnalysis<T>& psd, const T& voidage, int k, Policy = {}) {
  if constexpr (std::same_as<Policy, Checked>) detail::require_valid_sieve(psd, voidage, k);
  const T moment = (T(1) - voidage) * detail::sieve_sum(psd, k) / detail::sieve_sum(psd, 0);
  if constexpr (std::same_as<Policy, Checked>)
    if (!fluidbed::detail::is_finite_number(moment))
      fluidbed::detail::throw_domain_error("moments::sieve_moment", "k", k,
                                           "M_k of these edges and fractions evaluates to " +
                                               fluidbed::detail::number_text(moment) +
                                               ": beyond the range of the floating type");
  return moment;
}

// M_0 … M_{out.size()−1} of a sieve analysis (as sieve_moment). Returns false, every entry NaN,
// unless edges.size() == fractions.size() + 1 >= 2.
template <class T>
FLUIDBED_HOST_DEVICE bool sieve_moments(const SieveAnalysis<T>& psd, const T& voidage, std::span<T> out) {
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = sieve_moment(psd, voidage, int(k));
  return detail::bins_match(psd);
}

// Geldart's estimate of the Sauter diameter from sieve data, seed 000 eq. 6.1:
// d_sv = (Σ_i ω_i/d̄_i)^{−1} with the arithmetic bin means d̄_i = (ξ_{i−1} + ξ_i)/2 and the mass
// fractions ω_i (normalised; number data converted to volume fractions as in sieve_moment). It
// is not M_0/M_{−1} of the piecewise-uniform VDF: the two differ by 0.25% on a 45–150 µm sieve
// cut (apertures 45, 53, 63, 75, 90, 106, 125, 150 µm, mass fractions 0.05, 0.10, 0.20, 0.30,
// 0.20, 0.10, 0.05: 79.683 against 79.484 µm). NaN unless edges.size() == fractions.size() + 1 >= 2.
template <class T>
FLUIDBED_HOST_DEVICE T geldart_sauter_diameter(const SieveAnalysis<T>& psd) {
  if (!detail::bins_match(psd)) return std::numeric_limits<T>::quiet_NaN();
  const int shift = psd.basis == SizeBasis::number ? 3 : 0;
  T volume(0), surface(0);
  for (std::size_t i = 0; i < psd.fractions.size(); ++i) {
    const T omega = psd.fractions[i] * detail::bin_power_mean(psd.edges[i], psd.edges[i + 1], shift);
    volume += omega;
    surface += omega / ((psd.edges[i] + psd.edges[i + 1]) / T(2));
  }
  return volume / surface;
}

// ---------------------------------------------------------------------------------------------
// Mean diameters and other statistics of VDF moments

// d_pq = (μ_p/μ_q)^{1/(p−q)} = (M_{p−3}/M_{q−3})^{1/(p−q)}, p ≠ q, from any source of VDF
// moments: `vdf_moment(k)` returns M_k (e.g. a lambda over quadrature_moment or sieve_moment).
template <class T, class VdfMoment>
FLUIDBED_HOST_DEVICE T mean_diameter(int p, int q, VdfMoment&& vdf_moment) {
  using std::pow;
  FLUIDBED_EXPECTS(p != q);
  const T ratio = T(vdf_moment(p - 3)) / T(vdf_moment(q - 3));
  return p - q == 1 ? ratio : T(pow(ratio, T(1) / T(p - q)));
}

// d43 = M_1/M_0, the volume-mean (De Brouckère) diameter (seed 003 text after eq. 0.12); NaN for
// fewer than 2 moments.
template <class T>
FLUIDBED_HOST_DEVICE T d43(std::span<const T> m) {
  return m.size() >= 2 ? m[1] / m[0] : std::numeric_limits<T>::quiet_NaN();
}

// d32 = Σφ_i / Σ(φ_i/ξ_i), the Sauter diameter of a quadrature (88.56 and 272.3 µm for the
// published 2-node quadratures of powders A and B, seed 000 Table 6.2, whose reported d_sv are
// 88 and 273 µm).
template <class T, int N>
FLUIDBED_HOST_DEVICE T d32(const Quadrature<T, N>& q) {
  return mean_diameter<T>(3, 2, [&](int k) { return quadrature_moment(q, k); });
}

// d32 = M_0/M_{−1} of a sieve analysis (exact logarithmic M_{−1}; 79.48364158 µm for the sieve
// cut of geldart_sauter_diameter).
template <class T>
FLUIDBED_HOST_DEVICE T d32(const SieveAnalysis<T>& psd) {
  return mean_diameter<T>(3, 2, [&](int k) { return detail::sieve_sum(psd, k); });
}

// d10 = μ_1/μ_0 = M_{−2}/M_{−3}, the number-mean diameter of a quadrature.
template <class T, int N>
FLUIDBED_HOST_DEVICE T d10(const Quadrature<T, N>& q) {
  return mean_diameter<T>(1, 0, [&](int k) { return quadrature_moment(q, k); });
}

// d10 of a sieve analysis.
template <class T>
FLUIDBED_HOST_DEVICE T d10(const SieveAnalysis<T>& psd) {
  return mean_diameter<T>(1, 0, [&](int k) { return detail::sieve_sum(psd, k); });
}

// σ² = M_2/M_0 − (M_1/M_0)², the volume-weighted variance of the diameter (seed 003 eq. 0.21,
// which calls it the "standard deviation"). Negative for a non-realizable set; NaN for fewer
// than 3 moments.
template <class T>
FLUIDBED_HOST_DEVICE T variance(std::span<const T> m) {
  if (m.size() < 3) return std::numeric_limits<T>::quiet_NaN();
  const T mean = m[1] / m[0];
  return m[2] / m[0] - mean * mean;
}

// φ = M_0, the solids volume fraction (1 − ε) of VDF moments; NaN for an empty set.
template <class T>
FLUIDBED_HOST_DEVICE T solid_fraction(std::span<const T> m) {
  return m.empty() ? std::numeric_limits<T>::quiet_NaN() : m[0];
}

// n_i = 6 φ_i/(π ξ_i³), the number of particles per unit volume in a class of volume fraction
// φ_i and diameter ξ_i (the n_i of the force terms of seed 000 eq. 6.8).
template <class T>
FLUIDBED_HOST_DEVICE T class_number_density(const T& volume_fraction, const T& diameter) {
  return T(6) * volume_fraction / (numbers::pi<T>() * diameter * diameter * diameter);
}

// VDF moments from NDF moments: M_k = (π/6) μ_{k+3}, k = 0 … vdf.size() − 1, where
// ndf_from_order_3[k] = μ_{k+3} (spheres, whose particle volume is πξ³/6). Returns false (every
// vdf[k] NaN) if ndf_from_order_3 has fewer entries than vdf.
template <class T>
FLUIDBED_HOST_DEVICE bool vdf_from_ndf_moments(std::span<const T> ndf_from_order_3, std::span<T> vdf) {
  if (ndf_from_order_3.size() < vdf.size()) {
    detail::fill_with_nan(vdf);
    return false;
  }
  for (std::size_t k = 0; k < vdf.size(); ++k)
    vdf[k] = numbers::pi<T>() / T(6) * ndf_from_order_3[k];
  return true;
}

// NDF moments from VDF moments: ndf_from_order_3[k] = μ_{k+3} = (6/π) M_k, k = 0 … vdf.size() − 1
// (μ_0 … μ_2 are the VDF moments of negative order M_{−3} … M_{−1}, which a set M_0 … does not
// contain). Returns false (every ndf_from_order_3[k] NaN) if it has fewer entries than vdf.
template <class T>
FLUIDBED_HOST_DEVICE bool ndf_from_vdf_moments(std::span<const T> vdf, std::span<T> ndf_from_order_3) {
  if (ndf_from_order_3.size() < vdf.size()) {
    detail::fill_with_nan(ndf_from_order_3);
    return false;
  }
  for (std::size_t k = 0; k < vdf.size(); ++k) ndf_from_order_3[k] = T(6) * vdf[k] / numbers::pi<T>();
  return true;
}

// ---------------------------------------------------------------------------------------------
// Log-normal moment sets

// The parameters of ln ξ ~ Normal(μ, s²).
template <class T>
struct LognormalParameters {
  T mu = T(0);               // ln of the median (of the distribution the moments weigh)
  T sigma_squared = T(0);    // s²
};

// m_k = m_0 exp(k μ + k² s²/2), k = 0 … out.size() − 1: a log-normal distribution of total
// weight m_0. Realizable to any order for s² > 0; second differences of ln m_k are exactly s²
// and third differences 0.
template <class T>
FLUIDBED_HOST_DEVICE void lognormal_moments(const T& m0, const LognormalParameters<T>& p, std::span<T> out) {
  using std::exp;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const T kk(static_cast<int>(k));
    out[k] = m0 * exp(kk * p.mu + kk * kk * p.sigma_squared / T(2));
  }
}

// The log-normal sharing m_0, m_1, m_2 (seed 003's fallback for a corrupted set): with r = m_1/m_0 and
// q = m_0 m_2/m_1², s² = ln q and μ = ln r − s²/2, i.e. m_k = m_0 r^k q^{k(k−1)/2}.
// Preconditions: m_0, m_1 > 0. s² < 0 (q < 1, i.e. m_0 m_2 < m_1²) means m_0 … m_2 are not
// themselves realizable; the formula then describes no distribution (correction.hpp falls back
// to the monodisperse m_0 r^k there).
template <class T>
FLUIDBED_HOST_DEVICE LognormalParameters<T> lognormal_matching(const T& m0, const T& m1, const T& m2) {
  using std::log;
  FLUIDBED_EXPECTS(m0 > T(0) && m1 > T(0));
  LognormalParameters<T> p;
  p.sigma_squared = log((m0 / m1) * (m2 / m1));
  p.mu = log(m1 / m0) - p.sigma_squared / T(2);
  return p;
}

}  // namespace fluidbed::moments
