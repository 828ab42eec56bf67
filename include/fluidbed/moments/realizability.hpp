// fluidbed — realizability of a moment set: how many nodes it supports, where it fails.
//
// A moment set m_0 … m_{2n−1} is the moment sequence of a positive measure with n points of
// increase on [0, ∞) iff its Stieltjes coefficients ζ_1 … ζ_{2n−1} are all > 0, and on the
// real line iff β_1 … β_{n−1} > 0 (equivalently, positive Hankel determinants H_0 … ;
// Shohat & Tamarkin (1943), The Problem of Moments, AMS; seed 003 eq. 0.22). The signs are
// read from the recurrence (recurrence.hpp), which is computed on exactly scaled moments, so
// the test involves no absolute threshold and no units.
//
// Counting moments rather than nodes. ζ_j depends on m_0 … m_j only, so the longest
// realizable prefix of the set is m_0 … m_{R−1} with R = the index of the first ζ_j <= 0
// (R = all moments if none fails); on the real line β_k depends on m_0 … m_{2k}, and R = 2k
// for the first β_k <= 0. R may be odd: m_0 … m_{2n} realizable on [0, ∞) is what a
// Gauss–Radau rule with a node at 0 needs (adaptive.hpp). The Gauss rule uses ⌊R/2⌋ nodes.
// This is the count OpenQBMM calls nRealizableMoments (univariateMomentSet::checkRealizability
// in src/quadratureMethods/momentSets/univariateMomentSet/univariateMomentSet.C), here with no
// absolute threshold: the comparison is with 0 on exactly scaled moments.
#pragma once

#include <array>
#include <cmath>
#include <span>

#include "../core/config.hpp"
#include "jacobi_eigen.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

enum class InversionStatus {
  ok,              // all n requested nodes
  reduced,         // fewer nodes: the set is realizable (strictly) only with quadrature.size nodes
  zero_mass,       // m_0 = 0 and every moment 0: an empty cell, no nodes
  not_realizable,  // not even one node: m_0 < 0, or moments of an empty cell nonzero, or the mean
                   // outside the support
  invalid_input,   // a moment is NaN or infinite, or the set spans more than the floating-point
                   // range: its exactly scaled moments (recurrence.hpp), or its nodes, weights or
                   // coefficients in the caller's units, overflow
  eigen_failure,   // the QL iteration did not converge, or the rule is not representable in
                   // scaled units (nodes spread beyond the floating-point range); never observed
                   // for size distributions; no nodes
  inaccurate,      // a rule (returned, as for ok or reduced) whose estimated error exceeds the
                   // caller's InversionOptions::required_accuracy (accuracy.hpp); only when asked
};

// The enumerator's name ("ok", "reduced", …), for messages and logs.
constexpr const char* status_name(InversionStatus status) {
  switch (status) {
    case InversionStatus::ok:
      return "ok";
    case InversionStatus::reduced:
      return "reduced";
    case InversionStatus::zero_mass:
      return "zero_mass";
    case InversionStatus::not_realizable:
      return "not_realizable";
    case InversionStatus::invalid_input:
      return "invalid_input";
    case InversionStatus::eigen_failure:
      return "eigen_failure";
    case InversionStatus::inaccurate:
      return "inaccurate";
  }
  return "<not an InversionStatus>";
}

// Whether a result with this status carries a rule (ok, reduced, inaccurate).
constexpr bool has_rule(InversionStatus status) {
  return status == InversionStatus::ok || status == InversionStatus::reduced || status == InversionStatus::inaccurate;
}

// Estimated relative errors of a rule, the largest over its nodes and over its weights
// (accuracy.hpp): node errors relative to the node on [0, ∞), to the largest |node| on the real
// line; weight errors relative to the weight. −1 where no estimate was asked for; +∞ where the
// rule has no digit to estimate.
template <class T>
struct RuleError {
  T nodes = T(-1);
  T weights = T(-1);
  // The largest estimated error, relative to its threshold, of the realizability decisions that set
  // the node count: every Stieltjes coefficient ζ_j (β_k on the real line) the rule passed, and for
  // a reduced rule the one that failed (first_failing_index). >= 1: the count lies within the
  // error (the set may be realizable with another count).
  T count = T(-1);
};

template <class T, int N>
struct InversionResult {
  Quadrature<T, N> quadrature;  // nodes ascending, weights; quadrature.size nodes
  InversionStatus status = InversionStatus::invalid_input;
  int realizable_nodes = 0;      // nodes the set supports (= quadrature.size unless eigen_failure)
  // The first coefficient that fails: j for ζ_j <= 0 or not finite ([0, ∞), 1-based), or k for
  // β_k <= 0 or α_k not finite (real line), with its value in the caller's units; 0 and 0 when
  // every tested coefficient passes.
  int first_failing_index = 0;
  T failing_value = T(0);
  // How far inside moment space the retained coefficients lie, relative: min_j ζ_j/ζ_1 over
  // j = 1 … 2 size − 1 ([0, ∞)), or min_k β_k/(m_2/m_0) over k = 1 … size − 1 (real line); 1
  // for a single node. Near 0: close to the boundary (a nearly degenerate set).
  T boundary_distance = T(0);
  // The estimated relative error of the rule, when InversionOptions asked for it (estimate_error
  // or required_accuracy): from the rounding of the inversion and the caller's moment_accuracy.
  RuleError<T> error;
};

namespace detail {

// The first failing coefficient of a recurrence computed to `levels` levels (r.size <= levels
// passed Wheeler's β test) from `moment_count` moments, and the length R of the realizable
// moment prefix. On [0, ∞) the ζ tested are ζ_1 … ζ_{2 size − 1}, plus ζ_{2 size} when the
// recurrence stopped early (it holds the failing β_size), and never beyond ζ_{moment_count − 1}
// (the last ζ of a padded recurrence depends on the padding). Everything in scaled units.
template <class T, int N>
struct CoefficientScan {
  std::array<T, 2 * N> zeta{};  // zeta[j − 1] = ζ_j, j = 1 … zeta_count
  int zeta_count = 0;
  int realizable_moments = 0;   // R
  int first_failing_index = 0;  // j (ζ_j) or k (β_k); 0 if none fails
  T failing_value = T(0);
};

template <class T, int N>
FLUIDBED_HOST_DEVICE CoefficientScan<T, N> scan_coefficients(const Recurrence<T, N>& r, int levels, int moment_count,
                                                             Support support) {
  using std::isfinite;
  CoefficientScan<T, N> out;
  out.zeta = stieltjes_coefficients(r);
  out.zeta_count = r.size > 0 ? 2 * r.size - 1 : 0;
  if (r.size > 0 && r.size < levels) {
    out.zeta[2 * r.size - 1] = r.beta[r.size] / out.zeta[2 * r.size - 2];
    out.zeta_count = 2 * r.size;
  }
  if (out.zeta_count > moment_count - 1) out.zeta_count = moment_count - 1;
  out.realizable_moments = moment_count;
  if (support == Support::positive_half_line) {
    for (int j = 1; j <= out.zeta_count; ++j)
      if (!(out.zeta[j - 1] > T(0)) || !isfinite(out.zeta[j - 1])) {
        out.first_failing_index = j;
        out.failing_value = out.zeta[j - 1];
        out.realizable_moments = j;
        break;
      }
  } else {
    // Wheeler's stop test sees β only; an α_k that over- or underflowed (a last moment corrupted
    // to 0: σ_{k,k} ≈ 0) ends the set at m_{2k} as ζ_{2k+1} does on [0, ∞).
    for (int k = 1; k < r.size && 2 * k + 1 < moment_count; ++k)  // α_0 = m̃_1/m̃_0 is finite
      if (!isfinite(r.alpha[k])) {
        out.first_failing_index = k;
        out.failing_value = r.alpha[k];
        out.realizable_moments = 2 * k + 1;
        return out;
      }
    if (r.size < levels && 2 * r.size < moment_count) {
      out.first_failing_index = r.size;
      out.failing_value = r.beta[r.size];
      out.realizable_moments = 2 * r.size;
    }
  }
  return out;
}

// The relative boundary distance of a rule built from m_0 … m_{moments−1} (see
// InversionResult): over ζ_2 … ζ_{moments−1} ([0, ∞)) or β_1 … β_{⌊(moments−1)/2⌋} (real line);
// 0 without a node. One node from m_0, m_1 tests no coefficient and is at distance 1 by
// definition: returned as such, since the ratio would be 0/0 for a Dirac at 0 on the real line
// (m_2/m_0 = α_0² = 0: particles at rest).
template <class T, int N>
FLUIDBED_HOST_DEVICE T boundary_distance(const Recurrence<T, N>& r, const std::array<T, 2 * N>& zeta, int moments,
                                         Support support) {
  if (moments < 2) return T(0);
  if (moments == 2) return T(1);
  // The smallest coefficient first, one division at the end.
  if (support == Support::positive_half_line) {
    T smallest = zeta[0];
    for (int j = 2; j <= moments - 1; ++j)
      if (zeta[j - 1] < smallest) smallest = zeta[j - 1];
    return smallest / zeta[0];
  }
  const T second = r.alpha[0] * r.alpha[0] + (moments >= 3 ? r.beta[1] : T(0));  // m_2/m_0
  T smallest = second;
  for (int k = 1; 2 * k <= moments - 1; ++k)
    if (r.beta[k] < smallest) smallest = r.beta[k];
  return smallest / second;
}

// The caller's-unit value of a failing coefficient: ζ scales like a length, β like its square.
FLUIDBED_HOST_DEVICE inline int failing_value_exponent(Support support, MomentScaling s) {
  return support == Support::positive_half_line ? s.length_exponent : 2 * s.length_exponent;
}

// Realizability of a scaled recurrence (r.size levels computed) on the support: trims
// r.size to the realizable node count and fills the diagnostics.
template <class T, int N>
FLUIDBED_HOST_DEVICE void assess(Recurrence<T, N>& r, int requested, Support support, MomentScaling s,
                                 InversionResult<T, N>& out) {
  using std::ldexp;
  const CoefficientScan<T, N> scan = scan_coefficients(r, requested, 2 * requested, support);
  r.size = scan.realizable_moments / 2;
  out.first_failing_index = scan.first_failing_index;
  out.failing_value = ldexp(scan.failing_value, failing_value_exponent(support, s));
  out.boundary_distance = boundary_distance(r, scan.zeta, 2 * r.size, support);
}

// Everything the realizability test, the adaptive inversion and the correction need, in
// scaled units: the input checks of inversion.hpp, the exact power-of-two scaling, Wheeler's
// recurrence (on ⌈size/2⌉ levels; an odd set is padded with one zero moment, which only
// α_{⌈size/2⌉−1} sees, and that α is never used) and the coefficient scan.
template <class T, int N>
struct ScaledAnalysis {
  InversionStatus status = InversionStatus::invalid_input;  // ok, reduced or an input status
  ScaledMoments<T, N> moments;  // m̃ and the scaling (size 0 when the input was not scaled)
  // Scaled; every level Wheeler computed (entries beyond size included), r.size of them
  // passed, beta[size] the failing β if any.
  Recurrence<T, N> recurrence;
  int levels = 0;
  CoefficientScan<T, N> scan;
};

// The statuses the input alone decides, before scaling: invalid_input (no moment, or a moment
// NaN or infinite), zero_mass (every moment 0: an empty cell), not_realizable (m_0 <= 0, or an
// empty cell with nonzero higher moments); ok otherwise (m_0 > 0 and every moment finite).
template <class T>
FLUIDBED_HOST_DEVICE InversionStatus input_status(std::span<const T> m) {
  using std::isfinite;
  if (m.empty()) return InversionStatus::invalid_input;
  bool all_zero = true;
  for (const T& x : m) {
    if (!isfinite(x)) return InversionStatus::invalid_input;
    all_zero = all_zero && x == T(0);
  }
  if (all_zero) return InversionStatus::zero_mass;
  return m[0] > T(0) ? InversionStatus::ok : InversionStatus::not_realizable;
}

// The analysis of 1 … 2N moments (another count: invalid_input, nothing read).
template <class T, int N>
FLUIDBED_HOST_DEVICE ScaledAnalysis<T, N> analyse(std::span<const T> m, Support support) {
  ScaledAnalysis<T, N> a;
  if (!count_within(m.size(), 1, 2 * N)) return a;
  a.status = input_status(m);
  if (a.status != InversionStatus::ok) {
    if (a.status == InversionStatus::not_realizable) a.scan.failing_value = m[0];
    return a;
  }
  const int count = int(m.size());
  a.moments = scaled_moments<T, N>(m);
  if (!scaled_moments_in_range(m, a.moments.view())) {
    a.status = InversionStatus::invalid_input;
    return a;
  }
  if (count == 1) {  // m_0 > 0 alone: realizable, no node
    a.recurrence.beta[0] = a.moments.values[0];
    a.scan.realizable_moments = 1;
    a.status = InversionStatus::ok;
    return a;
  }
  a.levels = (count + 1) / 2;
  a.recurrence = wheeler_unscaled<T, N>(std::span<const T>(a.moments.values.data(), std::size_t(2 * a.levels)));
  a.scan = scan_coefficients(a.recurrence, a.levels, count, support);
  a.status = a.scan.realizable_moments == count ? InversionStatus::ok
             : a.scan.realizable_moments >= 2   ? InversionStatus::reduced
                                                : InversionStatus::not_realizable;
  return a;
}

// The failing value of an analysis in the caller's units (for m_0 <= 0 it is m_0 itself, and
// the scaling is the identity).
template <class T, int N>
FLUIDBED_HOST_DEVICE T failing_value(const ScaledAnalysis<T, N>& a, Support support) {
  using std::ldexp;
  return ldexp(a.scan.failing_value, failing_value_exponent(support, a.moments.scaling));
}

}  // namespace detail

// The outcome of realizability(): the count, the failure, the coefficients, and the two
// diagnostics of seed 003 (log-convexity of ln m_k and the Hankel–Hadamard determinants),
// all in the caller's units.
template <class T, int N>
struct RealizabilityReport {
  // ok: the whole set is realizable; reduced: a proper prefix with >= 1 node is; zero_mass,
  // not_realizable (m_0 <= 0 with nonzero moments, or not even m_0, m_1: e.g. a mean <= 0 on
  // [0, ∞)), invalid_input (NaN or ±∞, or a set spanning more than the range: its scaled
  // moments, or its recurrence in the caller's units, overflow; nothing else is filled then).
  InversionStatus status = InversionStatus::invalid_input;
  int realizable_moments = 0;   // R: m_0 … m_{R−1} is strictly inside moment space
  int realizable_nodes = 0;     // ⌊R/2⌋, the Gauss nodes the set supports
  int first_failing_index = 0;  // j for ζ_j <= 0 ([0, ∞)), k for β_k <= 0 or α_k ±∞ (real line); 0: none
  T failing_value = T(0);       // that coefficient (m_0 itself when m_0 <= 0)
  // α_k, β_k of the realizable_nodes levels (beta[0] = m_0).
  Recurrence<T, N> recurrence;
  // ζ_1 … ζ_zeta_count (zeta[j − 1] = ζ_j), up to and including the first failing one (Wheeler
  // stops at the first β_k <= 0; a ζ_{2k+1} <= 0 with β_{k+1} > 0 lets it go on, and the later
  // ζ are then listed too). On the real line with m_1 = 0 the ζ are not finite (ζ_2 = β_1/0).
  // Computed in scaled units, hence +∞ (as IEEE rounds an overflow) where a ζ lies beyond the
  // range in the caller's: the status and counts, decided in scaled units, stand.
  std::array<T, 2 * N> zeta{};
  int zeta_count = 0;
  T boundary_distance = T(0);  // as InversionResult::boundary_distance, over the realizable moments

  // Seed 003 check 1: Δ²_k = ln m_k − 2 ln m_{k+1} + ln m_{k+2}, k = 0 … size − 3, evaluated as
  // ln(m̃_k m̃_{k+2}/m̃_{k+1}²) on the scaled moments (no cancellation of large logarithms).
  // Only when every m_k > 0 (count 0 and log_convex false otherwise). Necessary, not sufficient
  // beyond 4 moments (for m_0 … m_3 it is equivalent to the two Hankel conditions m_0 m_2 >= m_1²
  // and m_1 m_3 >= m_2²; beyond, it is only the Cauchy–Schwarz inequality m_k m_{k+2} >= m_{k+1}²):
  // the printed seed-003 8-moment sets are log-convex and fail.
  std::array<T, 2 * N> log_second_differences{};
  int log_second_difference_count = 0;
  bool log_convex = false;

  // Seed 003 check 2 (eq. 0.22): the Hankel–Hadamard determinants H_{2i} = det[m_{j+l}]_{0..i}
  // (a = 0) and H_{2i+1} = det[m_{j+l+1}]_{0..i} (a = 1), k = 0 … hankel_count − 1, as sign and
  // ln|H_k| (the determinants themselves overflow: ~1e62 for 8 moments in µm; ln|H_k| = −∞ for
  // H_k = 0, sign 0). Never formed as determinants, and never from the ζ, which are 0 or ±∞ at
  // the boundary of moment space (a zero mean: ζ_1 = 0, ζ_2 = ∞) where the determinants are
  // finite: from the recurrence, the squared norms of the monic orthogonal polynomials
  // (H_{2i}/H_{2i−2} = ⟨p_i, p_i⟩ = m_0 β_1 ⋯ β_i) and their values at 0
  // (H_{2i+1}/H_{2i} = (−1)^{i+1} p_{i+1}(0)), exact identities of the moment functional that
  // hold wherever the H_{2i} are nonzero, positive or not (Chihara (1978), An Introduction to
  // Orthogonal Polynomials, Gordon and Breach, ch. I):
  //   H_{2i} = H_{2i−2} m_0 β_1 ⋯ β_i,   H_{2i+1} = (−1)^{i+1} p_{i+1}(0) H_{2i},
  //   p_{k+1}(0) = −α_k p_k(0) − β_k p_{k−1}(0),  p_0 = 1, p_{−1} = 0,  H_{−2} = 1;
  // computed on the scaled recurrence as mantissa and binary exponent, then in the caller's
  // units H_k = 2^(s(a + b(s − 1 + c))) H̃_k (s = ⌊k/2⌋ + 1 rows, c = k mod 2). Every H_k of the set
  // is reported (k < size) up to the first one the recurrence does not determine (after an
  // H_{2i} = 0 the next α is not finite). On the real line only the a = 0 determinants are
  // conditions: hankel_positive ignores the odd ones there.
  std::array<T, 2 * N> log_abs_hankel{};
  std::array<int, 2 * N> hankel_sign{};
  int hankel_count = 0;
  bool hankel_positive = false;  // every tested determinant among the hankel_count is > 0
};

namespace detail {

// A product kept as mantissa · 2^exponent, the mantissa within ±[1/2, 1) (or 0, or not finite):
// the Hankel determinants leave the floating-point range where their factors do not.
template <class T>
struct WideProduct {
  T mantissa = T(1);
  int exponent = 0;
  FLUIDBED_HOST_DEVICE void multiply(const T& factor, int factor_exponent = 0) {
    using std::frexp;
    using std::isfinite;
    mantissa *= factor;
    exponent += factor_exponent;
    if (!isfinite(mantissa) || mantissa == T(0)) return;
    int e = 0;
    mantissa = frexp(mantissa, &e);
    exponent += e;
  }
};

// H_0 … H_{hankel_count − 1} of an analysed set with m_0 > 0 into the report (see
// RealizabilityReport::log_abs_hankel).
template <class T, int N>
FLUIDBED_HOST_DEVICE void hankel_determinants(const ScaledAnalysis<T, N>& a, Support support,
                                              RealizabilityReport<T, N>& out) {
  using std::abs;
  using std::frexp;
  using std::isfinite;
  using std::ldexp;
  using std::log;
  const Recurrence<T, N>& r = a.recurrence;
  const MomentScaling units = a.moments.scaling;
  const T ln2 = log(T(2));
  WideProduct<T> norm;  // H̃_{2i}/H̃_{2i−2} = m̃_0 β̃_1 ⋯ β̃_i
  WideProduct<T> even;  // H̃_{2i}
  T p = T(1), p_previous = T(0);  // p̃_i(0), p̃_{i−1}(0), times 2^−p_exponent
  int p_exponent = 0;
  out.hankel_positive = true;
  for (int k = 0; k < int(a.moments.size); ++k) {
    const int i = k / 2;
    WideProduct<T> h;
    if (k % 2 == 0) {
      norm.multiply(i == 0 ? a.moments.values[0] : r.beta[std::size_t(i)]);
      even.multiply(norm.mantissa, norm.exponent);
      h = even;
    } else {
      const T next = -r.alpha[std::size_t(i)] * p - (i > 0 ? r.beta[std::size_t(i)] * p_previous : T(0));
      p_previous = p;
      p = next;
      const T larger = abs(p) > abs(p_previous) ? abs(p) : abs(p_previous);
      if (isfinite(larger) && larger > T(0)) {  // keep the pair within the range, exactly
        int e = 0;
        frexp(larger, &e);
        p = ldexp(p, -e);
        p_previous = ldexp(p_previous, -e);
        p_exponent += e;
      }
      h = even;
      h.multiply(i % 2 == 0 ? -p : p, p_exponent);
    }
    if (!isfinite(h.mantissa)) return;
    const int rows = i + 1;
    const int unit_exponent = rows * (units.weight_exponent + units.length_exponent * (rows - 1 + k % 2));
    const int sign = h.mantissa > T(0) ? 1 : (h.mantissa < T(0) ? -1 : 0);
    out.hankel_sign[std::size_t(k)] = sign;
    out.log_abs_hankel[std::size_t(k)] = log(abs(h.mantissa)) + T(h.exponent + unit_exponent) * ln2;
    if (support == Support::positive_half_line || k % 2 == 0) out.hankel_positive = out.hankel_positive && sign > 0;
    out.hankel_count = k + 1;
  }
}

}  // namespace detail

// The realizability test of m_0 … m_{size−1}, 1 <= size <= 2N, on the support (another count:
// invalid_input, nothing else filled). Reuses the recurrence of recurrence.hpp (Wheeler on
// exactly scaled moments); no threshold.
template <class T, int N>
FLUIDBED_HOST_DEVICE RealizabilityReport<T, N> realizability(std::span<const T> m,
                                                             Support support = Support::positive_half_line) {
  using std::ldexp;
  using std::log;
  const detail::ScaledAnalysis<T, N> a = detail::analyse<T, N>(m, support);
  RealizabilityReport<T, N> out;
  out.status = a.status;
  out.failing_value = detail::failing_value(a, support);
  // (invalid_input covers every count but 1 … 2N, so m[0] exists below)
  if (a.status == InversionStatus::invalid_input || !(m[0] > T(0))) return out;  // and zero_mass
  out.realizable_moments = a.scan.realizable_moments;
  out.realizable_nodes = out.realizable_moments / 2;
  out.first_failing_index = a.scan.first_failing_index;
  out.recurrence = a.recurrence;
  out.recurrence.size = out.realizable_nodes;
  out.boundary_distance = detail::boundary_distance(a.recurrence, a.scan.zeta, out.realizable_moments, support);
  unscale(out.recurrence, a.moments.scaling);
  out.recurrence.beta[0] = m[0];  // also when no level is realizable
  out.zeta_count = a.scan.zeta_count;
  for (int j = 0; j < out.zeta_count; ++j)
    out.zeta[std::size_t(j)] = ldexp(a.scan.zeta[std::size_t(j)], a.moments.scaling.length_exponent);
  // A realizable set whose mean or variance lies beyond the floating-point range ({2e-139,
  // 3.7e210, 1, …}) has its recurrence finite only in scaled units: invalid_input. (The ζ are
  // diagnostics, +∞ there where beyond the range.)
  if (!detail::finite_prefix(out.recurrence.alpha, out.recurrence.beta, out.recurrence.size))
    return RealizabilityReport<T, N>{};

  const int count = int(m.size());
  const std::array<T, 2 * N>& scaled = a.moments.values;
  bool positive = true;
  for (int k = 0; k < count; ++k) positive = positive && scaled[std::size_t(k)] > T(0);
  if (positive) {
    out.log_convex = true;
    out.log_second_difference_count = count >= 3 ? count - 2 : 0;
    for (std::size_t k = 0; k + 2 < std::size_t(count); ++k) {
      const T d = log((scaled[k] / scaled[k + 1]) / (scaled[k + 1] / scaled[k + 2]));
      out.log_second_differences[k] = d;
      out.log_convex = out.log_convex && d >= T(0);
    }
  }
  detail::hankel_determinants(a, support, out);
  return out;
}

}  // namespace fluidbed::moments
