// fluidbed — adaptive inversion: as many nodes as the moment set really carries.
//
// invert() (inversion.hpp) returns the nodes the set supports by the sign test of the
// Stieltjes coefficients. A set on (or within round-off of) the boundary of moment space —
// fewer atoms than nodes requested, coincident or nearly coincident atoms, an empty class —
// can pass that test by rounding and give spurious nodes: a node of tiny weight somewhere, or
// two nodes splitting one atom. Marchisio & Fox (2013), Computational Models for Polydisperse
// Particulate and Multiphase Systems, Cambridge University Press, ch. 3, give the adaptive
// Wheeler algorithm for this (thresholds rmin and eabs): drop a node while the rule is
// degenerate. Here, after the realizable moment count R (realizability.hpp), three relative
// rules, in this order:
//   boundary rule  R is cut at the first ζ_j < τ ζ_1, j >= 2 (real line: β_k < τ m_2/m_0);
//   weight rule    min_i w_i < r_min m_0;
//   node rule      min_i (x_{i+1} − x_i) < e_abs x_rms,  x_rms = √(Σ w x²/Σ w) = √(m_2/m_0);
// and a degenerate n-node rule is replaced by the Gauss rule of the leading 2(n − 1) moments
// (the leading recurrence coefficients are those of the shorter set, so this is exactly the
// inversion of m_0 … m_{2n−3}). Each test compares like with like (ζ/ζ_1, w/m_0, Δx/x_rms):
// no units enter, and the inversion itself runs on exactly scaled moments.
//
// Defaults: r_min = e_abs = ε^{1/3} and τ = ε^{2/3}, ε the machine epsilon of T (6.06e-6 and
// 3.7e-11 in double; 4.9e-3 and 2.4e-5 in float). Why:
//   * τ. A coefficient that lies δ (relative) from the boundary leaves the coefficients after
//     it with relative errors ~ε/δ; for the nodes they produce to be resolved to e_abs, δ must
//     be >= ε/e_abs = ε^{2/3}. Two atoms d apart (relative) have ζ_2/ζ_1 ≈ d²/4: in double,
//     equal atoms 1e-6 … 1.2e-5 apart otherwise give a 2-node rule with one node 1e-4 away and
//     weight ~1e-5 m_0, which neither of the other rules catches; with τ they merge.
//   * r_min, e_abs. A spurious node at relative distance d from a real one, made by a rounding
//     error κε in the last β, has w/m_0 ≈ κε/d²; it escapes both rules only if
//     r_min e_abs² <= κε, i.e. κ >= 1 for the cube root — the two rules share the round-off
//     range evenly, in any precision. Measured in double (10 000 seeded sets each): 1 to 4
//     random atoms (sizes 10–410 in µm or m, 30% with two coincident) given 2n > 2k moments,
//     n <= 6: 1 wrong node count with these defaults, 6 with r_min = e_abs = 1e-8 (QuadMomPy),
//     0 with 1e-4; the wrong ones are ill-conditioned sets (atoms < 1% apart, or a spurious
//     weight of 1e-5 m_0 between atoms 1% apart). Single and coincident atoms, any unit from
//     1e-8 to 1e2: spurious nodes never had weight and separation both above 7.5e-10. The
//     price: genuine weights below r_min m_0 are dropped too — 5.8% of random continuous sets
//     (log-normal s <= 0.75, gamma, sieve PSDs; n = 2 … 5) lost their smallest node (all n >= 4
//     log-normals with s > 0.4; 1.6% with 1e-8, 9% with 1e-4). A class holding less than
//     6e-6 of the solids carries no physics in a fluidized bed and is a stiff, nearly empty
//     phase in a multi-fluid solver; set smaller thresholds (or call invert()) to keep such
//     tails.
//   Existing codes use fixed values of r_min/e_abs: QBMMlib (AdaptiveWheeler in QBMMlib.wl)
//   1e-2/1e-4, QuadMomPy (its adaptive Wheeler) 1e-8/1e-8, Uintah (CQMOMInversion.h, WeightRatio
//   and AbscissaRatio) 1e-5/1e-5 — close to ours in double, too small for float. Their node rule
//   compares the smallest gap with the largest, which never fires for n = 2; x_rms is used here
//   instead.
//
// Gauss–Radau (optional). With 2n + 1 realizable moments — an odd input set, or a first failing
// ζ of odd index — the Gauss rule must drop the last moment, while the (n + 1)-point
// Gauss–Radau rule with one node fixed at a uses all 2n + 1. Golub (1973), "Some modified matrix
// eigenvalue problems", SIAM Rev. 15, 318–334, doi:10.1137/1015032: extend J_n by β_n and
//   α_n' = a + δ_n,  (J_n − a I) δ = β_n e_n,
// whose last component, by elimination of the tridiagonal system, is δ_n = −β_n/ρ_n with
// ρ_1 = a − α_0, ρ_{k+1} = (a − α_k) − β_k/ρ_k (ρ_k = p_k(a)/p_{k−1}(a); OpenQBMM's
// α_n' = a − β_n p_{n−1}(a)/p_n(a), in its univariateMomentSet). It helps where the distribution
// really reaches a: a = 0 for sizes that grow from nucleation, or a = the lower sieve aperture
// for a sieved powder. Elsewhere it invents a class at a: for a 45–150 µm sieve cut (apertures
// 45, 53, 63, 75, 90, 106, 125, 150 µm, mass fractions 0.05, 0.10, 0.20, 0.30, 0.20, 0.10, 0.05),
// 7 moments and a = 0 give a node at 0 holding 5.4e-4 of the solids (the weight at a decays
// only geometrically with n as a moves away from the support, and stays above r_min there);
// hence it is off by default. With 2n + 1 moments realizable on [0, ∞) (ζ_1 … ζ_{2n} > 0) and
// a = 0 the weights are positive; for another a, positivity (and nodes >= 0 on [0, ∞)) is
// checked and the Gauss rule used if it fails (reduced_by = radau_invalid). After a
// degeneracy reduction the Gauss rule of the even prefix is used (it reproduces more moments
// than a Radau rule with as many nodes).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "../core/config.hpp"
#include "inversion.hpp"
#include "jacobi_eigen.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

// What reduced the number of nodes below the number requested.
enum class ReductionRule {
  none,           // all requested nodes
  realizability,  // the realizable moment count (first ζ_j <= 0 or β_k <= 0)
  small_weight,   // a weight below min_weight_fraction × m_0
  close_nodes,    // two nodes closer than min_node_separation × x_rms
  near_boundary,  // a ζ_j < boundary_tolerance × ζ_1 (β_k < boundary_tolerance × m_2/m_0 on the line)
  radau_invalid,  // the Gauss–Radau rule had a weight <= 0 (or a node < 0 on [0, ∞)): Gauss used
  inaccurate,     // the estimated error exceeded inversion.required_accuracy (accuracy.hpp)
};

// ε^{1/3} of T, the default of both relative thresholds (see the header comment).
template <class T>
FLUIDBED_HOST_DEVICE T default_degeneracy_threshold() {
  using std::cbrt;
  return T(cbrt(std::numeric_limits<T>::epsilon()));
}

// ε^{2/3} of T, the default relative distance to the boundary of moment space below which the
// coefficients that follow are round-off (see the header comment).
template <class T>
FLUIDBED_HOST_DEVICE T default_boundary_tolerance() {
  const T t = default_degeneracy_threshold<T>();
  return t * t;
}

template <class T>
struct AdaptiveOptions {
  InversionOptions inversion{};                                      // algorithm, solver, support
  T min_weight_fraction = default_degeneracy_threshold<T>();         // r_min
  T min_node_separation = default_degeneracy_threshold<T>();         // e_abs
  T boundary_tolerance = default_boundary_tolerance<T>();            // τ
  bool radau = false;  // (n + 1)-point Gauss–Radau when 2n + 1 moments are realizable
  T fixed_node = T(0);  // its fixed node a, in the units of the moments
};

template <class T, int N>
struct AdaptiveInversionResult : InversionResult<T, N> {
  // The rule of the last reduction: none when the rule reproduces every moment it can (all of
  // them with radau or an even size, all but the last for an odd size without radau; status ok),
  // otherwise the reason the last node or moment was dropped (status reduced). realizable_nodes
  // holds the nodes the sign test allows (Radau-counted when radau is set), which may exceed
  // quadrature.size; first_failing_index and failing_value are those of the whole input set.
  ReductionRule reduced_by = ReductionRule::none;
  bool radau = false;     // the quadrature is the Gauss–Radau rule (fixed_node is one of its nodes)
  int moments_used = 0;   // the quadrature reproduces m_0 … m_{moments_used − 1}
};

namespace detail {

// The first degeneracy rule a quadrature violates (none for <= 1 node). A NaN fails both.
template <class T, int N>
FLUIDBED_HOST_DEVICE ReductionRule degeneracy(const Quadrature<T, N>& q, const T& min_weight_fraction,
                                              const T& min_node_separation) {
  using std::sqrt;
  if (q.size <= 1) return ReductionRule::none;
  T m0(0), m2(0);
  for (int i = 0; i < q.size; ++i) {
    m0 += q.weights[i];
    m2 += q.weights[i] * q.nodes[i] * q.nodes[i];
  }
  for (int i = 0; i < q.size; ++i)
    if (!(q.weights[i] >= min_weight_fraction * m0)) return ReductionRule::small_weight;
  const T rms = sqrt(m2 / m0);
  for (int i = 1; i < q.size; ++i)
    if (!(q.nodes[i] - q.nodes[i - 1] >= min_node_separation * rms)) return ReductionRule::close_nodes;
  return ReductionRule::none;
}

// The realizable moment count R of an analysis, shortened to j (ζ_j, [0, ∞)) or 2k (β_k, real
// line) at the first coefficient within tolerance of the boundary: ζ_j < tolerance × ζ_1, or
// β_k < tolerance × m_2/m_0 (j >= 2, k >= 1; all relative, in scaled units).
template <class T, int N>
FLUIDBED_HOST_DEVICE int moments_clear_of_boundary(const ScaledAnalysis<T, N>& a, Support support, const T& tolerance) {
  const int R = a.scan.realizable_moments;
  if (support == Support::positive_half_line) {
    for (int j = 2; j <= R - 1; ++j)
      if (a.scan.zeta[j - 1] < tolerance * a.scan.zeta[0]) return j;
  } else {
    const Recurrence<T, N>& r = a.recurrence;
    const T second = r.alpha[0] * r.alpha[0] + (R >= 3 ? r.beta[1] : T(0));  // m_2/m_0
    for (int k = 1; 2 * k <= R - 1; ++k)
      if (r.beta[k] < tolerance * second) return 2 * k;
  }
  return R;
}

// The (k + 1)-point Gauss–Radau rule with node a (caller's units) from m_0 … m_{2k} (k >= 1),
// using the scaled recurrence of an analysis that covers those moments (β_k computed). Returns
// false, with q.size = 0, if the rule does not exist (a is a node of the k-point Gauss rule),
// the eigen-solve fails, or a weight is <= 0 / a node < 0 on [0, ∞).
template <class T, int N>
FLUIDBED_HOST_DEVICE bool gauss_radau_rule(const ScaledAnalysis<T, N>& analysis, int k, const T& a,
                                           const InversionOptions& options, Quadrature<T, N>& q) {
  using std::abs;
  using std::isfinite;
  using std::ldexp;
  FLUIDBED_EXPECTS(k >= 1 && k + 1 <= N);  // the callers' counts
  q.size = 0;
  Recurrence<T, N> r = analysis.recurrence;
  const T fixed = ldexp(a, -analysis.moments.scaling.length_exponent);
  T ratio = fixed - r.alpha[0];  // ρ_1
  for (int j = 1; j < k; ++j) ratio = (fixed - r.alpha[j]) - r.beta[j] / ratio;
  r.alpha[k] = fixed - r.beta[k] / ratio;
  r.size = k + 1;
  if (!isfinite(r.alpha[k])) return false;
  if (options.solver == EigenSolver::automatic && r.size <= 2) {
    q = gauss_closed_form(r);
  } else if (!gauss_golub_welsch(r, q)) {
    return false;
  }
  int nearest = 0;  // a is an exact eigenvalue: snap the computed one (off by ~ε‖J‖) onto it
  for (int i = 1; i < q.size; ++i)
    if (abs(q.nodes[i] - fixed) < abs(q.nodes[nearest] - fixed)) nearest = i;
  q.nodes[nearest] = fixed;
  unscale(q, analysis.moments.scaling);
  for (int i = 0; i < q.size; ++i)
    if (!(q.weights[i] > T(0)) || !isfinite(q.weights[i]) || !isfinite(q.nodes[i]) ||
        (options.support == Support::positive_half_line && q.nodes[i] < T(0))) {
      q.size = 0;
      return false;
    }
  return true;
}

}  // namespace detail

// The (n + 1)-point Gauss–Radau rule with the node `fixed_node` (caller's units) from the 2n + 1
// moments m_0 … m_{2n} (odd size, 3 <= size <= 2N − 1, so that n + 1 <= N); exact for
// polynomials of degree <= 2n. Another count is invalid_input with no nodes. The whole set must
// be realizable on the support; otherwise, or if the rule has a weight <= 0 (or a node < 0 on
// [0, ∞)), status is not_realizable with no nodes (first_failing_index = 0 and failing_value = 0
// for the latter). Tested on Radau-6 of uniform [0, 1], w(0) = 1/36 (Golub 1973's construction,
// checked to 50 digits by tests/reference/moments_reference.py).
template <class T, int N>
FLUIDBED_HOST_DEVICE InversionResult<T, N> gauss_radau(std::span<const T> m, const T& fixed_node,
                                                       const InversionOptions& options = {}) {
  InversionResult<T, N> out;  // invalid_input
  if (!detail::count_within(m.size(), 3, 2 * N - 1, detail::Parity::odd)) return out;
  const detail::ScaledAnalysis<T, N> a = detail::analyse<T, N>(m, options.support);
  out.status = a.status == InversionStatus::reduced ? InversionStatus::not_realizable : a.status;
  out.first_failing_index = a.scan.first_failing_index;
  out.failing_value = detail::failing_value(a, options.support);
  if (a.status != InversionStatus::ok) return out;
  const int k = int(m.size() / 2);
  out.realizable_nodes = k + 1;
  out.boundary_distance = detail::boundary_distance(a.recurrence, a.scan.zeta, int(m.size()), options.support);
  if (!detail::gauss_radau_rule(a, k, fixed_node, options, out.quadrature)) {
    out.status = InversionStatus::not_realizable;
    return out;
  }
  out.status = InversionStatus::ok;
  return out;
}

// Adaptive inversion of m_0 … m_{size−1}, 2 <= size <= 2N (an odd size is used by Gauss–Radau,
// or its last moment dropped, as reduced_by and moments_used say); another count is
// invalid_input with no nodes. Steps: realizability (the realizable moment count R, as in
// realizability()); the rule for R (Gauss–Radau with ⌊R/2⌋ + 1 nodes if R is odd and radau is
// set, else Gauss with ⌊R/2⌋ nodes); then, while the rule has > 1 node and is degenerate, or
// (with inversion.required_accuracy > 0) its estimated error exceeds the requirement, the Gauss
// rule with one node less: the largest rule that meets the requirement, or status inaccurate with
// the one-node rule if none does. The Gauss–Radau rule carries no estimate (error −1).
// Allocation-free, no exceptions; statuses as invert().
// Preconditions: the three thresholds of `options` >= 0 (NaN moments are a status, NaN options
// are not).
template <class T, int N>
FLUIDBED_HOST_DEVICE AdaptiveInversionResult<T, N> invert_adaptive(std::span<const T> m,
                                                                   const AdaptiveOptions<T>& options = {}) {
  FLUIDBED_EXPECTS(options.min_weight_fraction >= T(0) && options.min_node_separation >= T(0) &&
                   options.boundary_tolerance >= T(0));
  AdaptiveInversionResult<T, N> out;  // invalid_input
  if (!detail::count_within(m.size(), 2, 2 * N)) return out;
  const Support support = options.inversion.support;
  const detail::ScaledAnalysis<T, N> a = detail::analyse<T, N>(m, support);
  out.status = a.status;
  out.first_failing_index = a.scan.first_failing_index;
  out.failing_value = detail::failing_value(a, support);
  if (a.status != InversionStatus::ok && a.status != InversionStatus::reduced) return out;
  const int count = int(m.size());
  const int R = detail::moments_clear_of_boundary(a, support, options.boundary_tolerance);
  const auto nodes_of = [&](int moments) { return moments % 2 == 1 ? moments / 2 + 1 : moments / 2; };
  const int full = options.radau ? count : 2 * (count / 2);  // the moments a full rule reproduces
  out.realizable_nodes = options.radau ? nodes_of(a.scan.realizable_moments) : a.scan.realizable_moments / 2;
  out.reduced_by = R >= full                            ? ReductionRule::none
                   : R == a.scan.realizable_moments ? ReductionRule::realizability
                                                    : ReductionRule::near_boundary;

  int used = options.radau && R % 2 == 1 ? R : 2 * (R / 2);
  InversionResult<T, N> gauss;  // the last Gauss rule of the loop below
  if (used % 2 == 1) {
    out.radau = detail::gauss_radau_rule(a, used / 2, options.fixed_node, options.inversion, out.quadrature);
    if (!out.radau) {
      out.reduced_by = ReductionRule::radau_invalid;
      --used;
    }
  }
  for (;;) {
    if (used % 2 == 0) {
      gauss = invert<T, N>(m.first(std::size_t(used)), options.inversion);
      if (gauss.status != InversionStatus::ok && gauss.status != InversionStatus::reduced &&
          gauss.status != InversionStatus::inaccurate) {
        out.status = gauss.status;  // eigen_failure (the prefix itself passed the checks above)
        out.quadrature = gauss.quadrature;
        return out;
      }
      out.quadrature = gauss.quadrature;
      out.error = gauss.error;
      if (gauss.quadrature.size < used / 2) {  // product-difference rounding: fewer than Wheeler
        out.reduced_by = ReductionRule::realizability;
        used = 2 * gauss.quadrature.size;
      }
    }
    ReductionRule rule = detail::degeneracy(out.quadrature, options.min_weight_fraction, options.min_node_separation);
    if (rule == ReductionRule::none && gauss.status == InversionStatus::inaccurate && used % 2 == 0) {
      if (out.quadrature.size <= 1) {  // no rule meets the requirement
        out.status = InversionStatus::inaccurate;
        out.moments_used = used;
        out.boundary_distance = detail::boundary_distance(a.recurrence, a.scan.zeta, used, support);
        return out;
      }
      rule = ReductionRule::inaccurate;
    }
    if (rule == ReductionRule::none) break;
    out.reduced_by = rule;
    out.radau = false;
    used = 2 * (nodes_of(used) - 1);
  }
  out.moments_used = used;
  out.boundary_distance = detail::boundary_distance(a.recurrence, a.scan.zeta, used, support);
  out.status = used == full ? InversionStatus::ok : InversionStatus::reduced;
  return out;
}

// Fixed 2N moments at compile time.
template <int N, class T>
FLUIDBED_HOST_DEVICE AdaptiveInversionResult<T, N> invert_adaptive(const std::array<T, 2 * N>& m,
                                                                   const AdaptiveOptions<T>& options = {}) {
  return invert_adaptive<T, N>(std::span<const T>(m.data(), m.size()), options);
}

}  // namespace fluidbed::moments
