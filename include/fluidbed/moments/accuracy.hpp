// fluidbed — how many digits an n-node Gauss rule has: a first-order estimate of the relative
// error of its nodes and weights, from the rule and the moments it came from.
//
// Sensitivity. The rule (x_i, w_i) reproduces m_k = Σ_i w_i x_i^k, k = 0 … 2n−1, so a change
// δm of the moments moves it by the solution of the confluent Vandermonde system
//   δm_k = Σ_i (x_i^k δw_i + k w_i x_i^(k−1) δx_i).
// For any polynomial h of degree <= 2n−1 with coefficients h_k, Σ_k h_k δm_k = Σ_i (h(x_i) δw_i
// + w_i h'(x_i) δx_i), so the Hermite basis polynomials invert it in O(n²) per node: with
// P(x) = Π_j (x − x_j) and Q_i(x) = P(x)/(x − x_i),
//   H̃_i = P Q_i / Q_i(x_i)²                       (H̃_i(x_j) = 0, H̃_i'(x_j) = δ_ij):
//       w_i δx_i = Σ_k h̃_ik δm_k,
//   H_i = Q_i² / Q_i(x_i)² − 2 Q_i'(x_i)/Q_i(x_i) · H̃_i   (H_i(x_j) = δ_ij, H_i'(x_j) = 0):
//       δw_i = Σ_k h_ik δm_k
// (Hermite interpolation; e.g. Gautschi (2004), Orthogonal Polynomials: Computation and
// Approximation, Oxford, §2.1, for the conditioning of the moment map it measures).
//
// Estimate. With the sensitivities S_i = Σ_k |h_ik m_k| (and S̃_i for the nodes), two sources:
//   * the caller's moments, each off by up to a relative δ (transport, measurement, printed
//     digits): the worst case δ S_i, a bound to first order (attained by one sign pattern of the
//     moment errors);
//   * the rounding of the inversion itself (scaling, Wheeler's recurrence, the eigen-solver):
//     it acts on the rule like a random relative perturbation of the moments of a fraction of
//     an ulp, estimated as κ ε S_i/√(2n) with κ = 1/16. κ and the √(2n) were measured, not
//     derived: over random 2…8-atom size distributions (log-normal sizes around 100 µm,
//     σ_ln 0.45 and 1.3) the double inversion's error against a 50-digit inversion of the same
//     moments has a median of about ε S_i/(11–14 √(2n)), independent of the conditioning from
//     1e-15 to 1 and of n; κ = 1/16 puts the estimate at 0.6–0.8 of the median error (about
//     97 % of cells within a factor 10 of it; examples/inversion_error_estimate.cpp). With
//     floating-point contraction (FMA) the inversion errs about half as much, and the estimate
//     is then above the median error by about as much.
// Weights of less than ε³ of the mass are given no digit (tiny_weight_share below).
// The sensitivities: on [0, ∞) in O(n²) for the whole rule from the nodes alone (the coefficients of H̃_i
// alternate in sign; positive_sensitivities); on the real line from the coefficients, summed
// against the moments (general_node_sensitivity).
// The error of one inversion is one draw: perturbing a cell's moments by one ulp moves its
// measured error by 0.40 decades (standard deviation of log10; p1–p99 of 2 decades) around
// that cell's mean, so no estimate from the rule can bracket more than about 98 % of cells
// within a factor 10; this one is, at the median, that cell mean.
//
// Units: node errors are relative to the node on [0, ∞) and to the largest |node| on the real
// line (a velocity node near zero has no relative error of its own); weight errors to the
// weight. First order: an estimate above about 0.01 means few or no correct digits, not how many
// (invert() goes beyond it on [0, ∞) where the caller's moment_accuracy dominates: the rules of the
// worst-case moment sets, inversion.hpp, add_vertex_changes).
//
// The node count is a set of decisions too, the signs of the Stieltjes coefficients; its error
// (RuleError::count: passed_decisions_error, failed_decision_error below) is the largest of theirs,
// each relative to its threshold.
#pragma once

#include <cmath>
#include <limits>
#include <span>

#include "../core/config.hpp"
#include "jacobi_eigen.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

namespace detail {

// The rounding of the inversion as a relative perturbation of each moment (κ ε above), to be
// divided by √(2n).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T inversion_rounding() {
  return std::numeric_limits<T>::epsilon() / T(16);
}

// ε³: a weight below this share of the rule's mass is given no digit (tiny_weight_share × mass/w
// is added to its error estimate). The sensitivity misses what happens to such weights: in float,
// a 9-node log-normal cell's rule had a weight of 7e-35 of the mass, off by 42 %, where the
// sensitivity said 5e-5. ε³ is 1.7e-21 in float and 1.1e-47 in double: on the cells of
// examples/inversion_error_estimate.cpp it marks that weight, leaves every double estimate as it
// was, and raises float ones only for log-normal cells of 7–9 nodes. ε or ε² instead would
// overestimate double log-normal cells of 9–10 nodes by 10–20× (the QL resolves their small
// weights far better than that).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T tiny_weight_share() {
  const T epsilon = std::numeric_limits<T>::epsilon();
  return epsilon * epsilon * epsilon;
}

// Whether both estimated errors are within a required relative accuracy.
template <class T>
FLUIDBED_HOST_DEVICE bool meets(const RuleError<T>& error, const T& required) {
  return error.nodes <= required && error.weights <= required;
}

// Σ_k |h̃_ik m_k| and Σ_k |h_ik m_k| of node i: the sensitivities of w_i x_i and w_i to the moments.
template <class T>
struct NodeSensitivity {
  T node, weight;
};

// On [0, ∞), nodes > 0: H̃_i = P Q_i/Q_i(x_i)² has positive roots only, so its coefficients
// alternate in sign and Σ_k |h̃_ik| x^k = |H̃_i(−x)| for x > 0; with m_k = Σ_j w_j x_j^k (the
// rule reproduces its moments),
//   Σ_k |h̃_ik| m_k = Σ_j w_j |P(−x_j) Q_i(−x_j)| / Q_i(x_i)² = Σ_j w_j A_j B_ij / d_i²,
//   A_j = Π_l (x_j + x_l),  B_ij = Π_{l≠i} (x_j + x_l),  d_i = Q_i(x_i) = Π_{l≠i} (x_i − x_l).
// H_i = ℓ_i² (1 − 2 ℓ_i'(x_i) (x − x_i)), ℓ_i = Q_i/d_i, ℓ_i'(x_i) = Q_i'(x_i)/d_i: the absolute
// coefficients of a product are at most the product of the factors' (equality when the linear
// factor's root is positive too), so
//   Σ_k |h_ik| m_k <= Σ_j w_j (B_ij/d_i)² (|1 + 2 ℓ_i'(x_i) x_i| + 2 |ℓ_i'(x_i)| x_j).
// O(n²) for the whole rule, no polynomial formed.
// On a scalar or on a lane of cells (V, as lane_ops), for every node of the n nodes x and weights
// w at once: O(n²) in all, B_ij as a product of a prefix and a suffix of (x_j + x_l), l ≠ i.
template <class V, int N>
FLUIDBED_HOST_DEVICE void positive_sensitivities(const V* x, const V* w, int n, NodeSensitivity<V> (&s)[N]) {
  using ops = lane_ops<V>;
  using T = typename ops::scalar;
  n = n < N ? n : N;  // as rule_error_terms
  V constant[N], linear[N], inverse_square[N];
  for (int i = 0; i < n; ++i) {
    V d = ops::constant(T(1)), slope = ops::constant(T(0));  // Q_i(x_i) and Q_i'(x_i), by the product rule
    for (int l = 0; l < n; ++l)
      if (l != i) {
        slope = slope * (x[i] - x[l]) + d;
        d = d * (x[i] - x[l]);
      }
    const V inverse_d = T(1) / d;
    const V lagrange_slope = T(2) * slope * inverse_d;  // 2 ℓ_i'(x_i)
    constant[i] = ops::abs(T(1) + lagrange_slope * x[i]);
    linear[i] = ops::abs(lagrange_slope);
    inverse_square[i] = inverse_d * inverse_d;
    s[i] = {ops::constant(T(0)), ops::constant(T(0))};
  }
  for (int j = 0; j < n; ++j) {
    V suffix[N + 1];  // suffix[l] = Π_{l' >= l} (x_j + x_l')
    suffix[n] = ops::constant(T(1));
    for (int l = n - 1; l >= 0; --l) suffix[l] = suffix[l + 1] * (x[j] + x[l]);
    V prefix = ops::constant(T(1));  // Π_{l < i} (x_j + x_l)
    for (int i = 0; i < n; ++i) {
      const V others = prefix * suffix[i + 1];  // B_ij
      const V term = w[j] * others * others;
      s[i].node = s[i].node + term * (x[j] + x[i]);  // w_j A_j B_ij = w_j (x_j + x_i) B_ij²
      s[i].weight = s[i].weight + term * (constant[i] + linear[i] * x[j]);
      prefix = prefix * (x[j] + x[i]);
    }
  }
  for (int i = 0; i < n; ++i) {
    s[i].node = s[i].node * inverse_square[i];
    s[i].weight = s[i].weight * inverse_square[i];
  }
}

// Any support: the coefficients of H̃_i and H_i formed (O(n²) per node) and summed against the
// moments m_0 … m_{2n−1}; P's coefficients in p (lowest first).
template <class T, int N>
FLUIDBED_HOST_DEVICE NodeSensitivity<T> general_node_sensitivity(std::span<const T> m, const Quadrature<T, N>& q,
                                                                 const T (&p)[N + 1], int i) {
  using std::abs;
  const int n = q.size;
  const T x = q.nodes[i];
  T quotient[N];  // Q_i = P/(x − x_i) by synthetic division
  quotient[n - 1] = p[n];
  for (int k = n - 1; k > 0; --k) quotient[k - 1] = p[k] + x * quotient[k];
  T d = T(0), slope = T(0);  // Q_i(x_i) = P'(x_i) and Q_i'(x_i), by Horner
  for (int k = n - 1; k >= 0; --k) {
    slope = slope * x + d;
    d = d * x + quotient[k];
  }
  T node_part[2 * N] = {}, square_part[2 * N] = {};  // P Q_i and Q_i²
  for (int b = 0; b < n; ++b) {
    for (int a = 0; a < n; ++a) square_part[a + b] += quotient[a] * quotient[b];
    for (int a = 0; a <= n; ++a) node_part[a + b] += p[a] * quotient[b];
  }
  const T inverse_d = T(1) / d;
  const T lagrange_slope = T(2) * slope * inverse_d;  // 2 ℓ_i'(x_i)
  NodeSensitivity<T> s{T(0), T(0)};
  for (int k = 0; k < 2 * n; ++k) {
    const T mk = m[std::size_t(k)];
    s.node += abs(node_part[k] * mk);
    s.weight += abs((square_part[k] - lagrange_slope * node_part[k]) * mk);
  }
  s.node *= inverse_d * inverse_d;
  s.weight *= inverse_d * inverse_d;
  return s;
}

// What turns node i's sensitivities into relative errors: the relative moment perturbation
// (caller's accuracy plus rounding) and the weight below which no digit is given.
template <class V>
struct RuleErrorTerms {
  V perturbation, tiny_weight;
};

// The terms of a rule of n <= N nodes with weights w (scalar or lanes, as lane_ops).
template <int N, class V>
FLUIDBED_HOST_DEVICE RuleErrorTerms<V> rule_error_terms(const V* w, int n,
                                                        const typename lane_ops<V>::scalar& moment_accuracy) {
  using ops = lane_ops<V>;
  using T = typename ops::scalar;
  using std::sqrt;
  n = n < N ? n : N;  // (the callers' n is; GCC 12 -O3 warns of reads beyond w unless it sees so)
  V mass = ops::constant(T(0));
  for (int i = 0; i < n; ++i) mass = mass + ops::abs(w[i]);
  return {ops::constant(moment_accuracy + inversion_rounding<T>() / sqrt(T(2 * n))), tiny_weight_share<T>() * mass};
}

// Node i's relative errors from its sensitivities, weight and node scale (the node on [0, ∞), the
// largest |node| on the line), into the rule's largest so far (scalar or lanes).
template <class V>
FLUIDBED_HOST_DEVICE void add_node_error(V& nodes, V& weights, const NodeSensitivity<V>& s, const V& weight,
                                         const V& node_scale, const RuleErrorTerms<V>& terms) {
  using ops = lane_ops<V>;
  using T = typename ops::scalar;
  const V per_node = T(1) / (ops::abs(weight) * node_scale);  // one division for 1/(w x) and 1/w
  const V per_weight = per_node * node_scale;
  nodes = ops::larger_error(nodes, terms.perturbation * s.node * per_node);
  weights = ops::larger_error(weights, (terms.perturbation * s.weight + terms.tiny_weight) * per_weight);
}

// The rounding of the realizability decisions as a relative perturbation of each moment (see
// passed_decisions_error and failed_decision_error): ε. Measured over random 4–10-atom size
// distributions in double and 3–5-atom ones in float (log-normal sizes around 100 µm, σ_ln 0.45 and
// 1.3), whose exact moments are realizable with every atom, so that each reduced status is a
// decision of the rounding: every such failing coefficient lay within 0.45 ε U of zero (its error
// >= 2.2 with ε), the median within 0.06 ε U; a set lowered by 0.1 % in one moment beyond a
// three-atom boundary gives 7e-12 in double.
template <class T>
FLUIDBED_HOST_DEVICE constexpr T decision_rounding() {
  return std::numeric_limits<T>::epsilon();
}

// One step of the monic orthogonal polynomials of a recurrence (coefficients lowest first):
// p_{level+1} = (x − α_level) p_level − β_level p_{level−1} from previous = p_{level−1} and
// current = p_level, which become p_level and p_{level+1} (level < N).
template <class T, int N>
FLUIDBED_HOST_DEVICE void advance_orthogonal_polynomial(const Recurrence<T, N>& r, int level, T (&previous)[N + 1],
                                                        T (&current)[N + 1]) {
  const T beta = level > 0 ? r.beta[level] : T(0);
  T next[N + 1] = {};
  for (int k = 0; k <= level; ++k) {
    next[k + 1] += current[k];
    next[k] -= r.alpha[level] * current[k] + beta * previous[k];
  }
  for (int k = 0; k <= N; ++k) {
    previous[k] = current[k];
    current[k] = next[k];
  }
}

// p_{degree − 1} in previous and p_{degree} in current (degree <= N; α_0 … α_{degree−1},
// β_1 … β_{degree−1} used).
template <class T, int N>
FLUIDBED_HOST_DEVICE void orthogonal_polynomials(const Recurrence<T, N>& r, int degree, T (&previous)[N + 1],
                                                 T (&current)[N + 1]) {
  for (int k = 0; k <= N; ++k) previous[k] = current[k] = T(0);
  current[0] = T(1);
  for (int level = 0; level < degree; ++level) advance_orthogonal_polynomial(r, level, previous, current);
}

// Σ_k |c_k m_{k + shift}| for c the coefficients of q², q of degree `degree` (lowest first).
template <class T, int M>
FLUIDBED_HOST_DEVICE T square_sensitivity(const T (&q)[M], int degree, std::span<const T> m, int shift) {
  using std::abs;
  T sum = T(0);
  for (int k = 0; k <= 2 * degree; ++k) {
    T c = T(0);
    for (int a = k > degree ? k - degree : 0; a <= k && a <= degree; ++a) c += q[a] * q[k - a];
    sum += abs(c * m[std::size_t(k + shift)]);
  }
  return sum;
}

// The decisions an n-node rule passed on [0, ∞): ζ_d > 0, d = 1 … 2n − 1. Each is the sign of a
// minimum over monic polynomials (see failed_decision_error), V_2k = m_0 β_1 ⋯ β_k = ∫ p_k² dμ and
// V_2k+1 = ∫ q_k² x dμ (q_k orthogonal for x dμ, whose recurrence is α'_k = ζ_2k+1 + ζ_2k+2,
// β'_k = ζ_2k ζ_2k+1), moved by relative moment changes δ by at most δ U_d, U_d the sum of the
// absolute coefficients of p_k² (or x q_k²) against the moments. Their roots are positive, so
// those coefficients alternate and U_2k = ∫ p_k(−x)² dμ, U_2k+1 = ∫ x q_k(−x)² dμ: polynomials of
// degree <= 2n − 1, integrated exactly by the rule. Returned: the largest perturbation U_d/|V_d|,
// from the rule (x, w) and its recurrence (α_0 … α_{n−1}, β_1 … β_{n−1}), all in scaled units;
// O(n²), scalar or lanes (as lane_ops).
template <class V, int N>
FLUIDBED_HOST_DEVICE V passed_decisions_error(const V* x, const V* w, const V* alpha, const V* beta, int n,
                                              const V& perturbation) {
  using ops = lane_ops<V>;
  using T = typename ops::scalar;
  n = n < N ? n : N;
  // Every entry set, so that GCC 12 -O3 sees no read of an unset one (as rule_error_terms).
  V zeta[2 * N], spread[2 * N];  // zeta[d − 1] = ζ_d, spread[d − 1] = U_d
  for (int d = 0; d < 2 * N; ++d) zeta[d] = spread[d] = ops::constant(T(0));
  zeta[0] = alpha[0];
  for (int k = 1; k < n; ++k) {
    zeta[2 * k - 1] = beta[k] / zeta[2 * k - 2];
    zeta[2 * k] = alpha[k] - zeta[2 * k - 1];
  }
  for (int j = 0; j < n; ++j) {
    V p_previous = ops::constant(T(0)), p = ops::constant(T(1));  // p_k(−x_j)
    V q_previous = ops::constant(T(0)), q = ops::constant(T(1));  // q_k(−x_j)
    for (int k = 0; k < n; ++k) {
      if (k > 0) spread[2 * k - 1] = spread[2 * k - 1] + w[j] * p * p;
      spread[2 * k] = spread[2 * k] + w[j] * x[j] * q * q;
      if (k + 1 == n) break;
      const V p_recalled = k > 0 ? V(beta[k] * p_previous) : ops::constant(T(0));
      const V q_recalled = k > 0 ? V(zeta[2 * k - 1] * zeta[2 * k] * q_previous) : ops::constant(T(0));
      const V p_next = (T(0) - x[j] - alpha[k]) * p - p_recalled;
      const V q_next = (T(0) - x[j] - (zeta[2 * k] + zeta[2 * k + 1])) * q - q_recalled;
      p_previous = p;
      p = p_next;
      q_previous = q;
      q = q_next;
    }
  }
  V mass = ops::constant(T(0));
  for (int j = 0; j < n; ++j) mass = mass + w[j];
  V value = mass, largest = ops::constant(T(0));  // V_d = m_0 ζ_1 ⋯ ζ_d
  for (int d = 0; d < 2 * n - 1; ++d) {
    value = value * zeta[d];
    largest = ops::larger_error(largest, perturbation * spread[d] / ops::abs(value));
  }
  return largest;
}

// The decisions an n-node rule passed on the real line, β_k > 0, k = 1 … n − 1: V_k = m_0 β_1 ⋯ β_k
// = min ∫ q² dμ, moved by at most δ Σ_i |c_i m_i| (c the coefficients of p_k²), the moments of
// either sign: from the coefficients (p_k by one recurrence step each), O(n³) for the squares'
// coefficients. The largest perturbation U_k/|V_k| (0 for one node).
template <class T, int N>
FLUIDBED_HOST_DEVICE T real_line_passed_decisions_error(std::span<const T> m, const Recurrence<T, N>& r, int n,
                                                        const T& perturbation) {
  using std::abs;
  T largest = T(0), value = m[0];
  T previous[N + 1], p[N + 1];  // p_{k−1}, p_k
  orthogonal_polynomials(r, 0, previous, p);
  for (int k = 1; k < n; ++k) {
    advance_orthogonal_polynomial(r, k - 1, previous, p);
    value *= r.beta[k];
    largest = lane_ops<T>::larger_error(largest, perturbation * square_sensitivity(p, k, m, 0) / abs(value));
  }
  return largest;
}

// The estimate for a rule of n = q.size >= 1 nodes, its 2n moments m and their recurrence r (α_0 …
// α_{n−1}, β_1 … β_{n−1} used), all in the exactly scaled units of the inversion (nodes and moments
// O(1)); moment_accuracy as estimated_error(). The count: the decisions the rule passed.
template <class T, int N>
FLUIDBED_HOST_DEVICE RuleError<T> scaled_rule_error(std::span<const T> m, const Quadrature<T, N>& q,
                                                    const Recurrence<T, N>& r, Support support,
                                                    const T& moment_accuracy) {
  using std::abs;
  using std::sqrt;
  const int n = q.size;
  FLUIDBED_EXPECTS(n >= 1 && n <= N && m.size() == std::size_t(2 * n));  // the callers' counts
  const bool positive = support == Support::positive_half_line;
  T p[N + 1] = {};  // P(x) = Π_j (x − x_j), lowest coefficient first (general path only)
  T largest = T(0);
  if (!positive) {
    p[0] = T(1);
    for (int j = 0; j < n; ++j) {
      p[j + 1] = p[j];
      for (int k = j; k > 0; --k) p[k] = p[k - 1] - q.nodes[j] * p[k];
      p[0] = -q.nodes[j] * p[0];
      largest = abs(q.nodes[j]) > largest ? abs(q.nodes[j]) : largest;
    }
  }
  const RuleErrorTerms<T> terms = rule_error_terms<N>(q.weights.data(), n, moment_accuracy);
  NodeSensitivity<T> s[N];
  if (positive)
    positive_sensitivities(q.nodes.data(), q.weights.data(), n, s);
  else
    for (int i = 0; i < n; ++i) s[i] = general_node_sensitivity(m, q, p, i);
  RuleError<T> error{T(0), T(0)};
  for (int i = 0; i < n; ++i)
    add_node_error(error.nodes, error.weights, s[i], q.weights[i], positive ? T(abs(q.nodes[i])) : largest, terms);
  const T perturbation = moment_accuracy + decision_rounding<T>();
  error.count = positive ? passed_decisions_error<T, N>(q.nodes.data(), q.weights.data(), r.alpha.data(),
                                                        r.beta.data(), n, perturbation)
                         : real_line_passed_decisions_error(m, r, n, perturbation);
  return error;
}

// How near the realizability decision that ended a reduced rule of n = r.size nodes lies to its
// threshold: the relative error of the coefficient that failed (j = first_failing_index), from the
// moments' accuracy and the rounding, relative to that coefficient (the count error of a reduced
// rule is the larger of this and passed_decisions_error()). Each failing test is the sign
// of a ratio of Hankel determinants, a minimum over monic polynomials q of degree n:
//   ζ_2n ([0, ∞)) or β_n (real line):  V = m_0 β_1 ⋯ β_n = H_2n/H_2n−2 = min ∫ q² dμ,  at q = p_n;
//   ζ_2n+1 ([0, ∞)):                   V = −p_{n+1}(0)/p_n(0) m_0 β_1 ⋯ β_n = H_2n+1/H_2n−1
//                                        = min ∫ q² x dμ,  at the kernel polynomial
//                                        q_n = (p_{n+1} − p_{n+1}(0)/p_n(0) p_n)/x
// (Chihara (1978), An Introduction to Orthogonal Polynomials, Gordon and Breach, ch. I). A
// minimum moves to first order only through the functional (the minimiser is stationary), so a
// relative change δ of each moment moves V by at most δ Σ_k |c_k m_k| (c the coefficients of q²,
// the moments shifted by one for x dμ). Returned: (moment_accuracy + decision_rounding) times that
// sum over |V|; >= 1: the set may be realizable with more nodes within the error. +∞ where V is 0
// or not finite, or the failure is a non-finite α (real line). Scaled moments and recurrence
// (levels beyond r.size as Wheeler computed them).
template <class T, int N>
FLUIDBED_HOST_DEVICE T failed_decision_error(std::span<const T> m, const Recurrence<T, N>& r, int failing_index,
                                             Support support, const T& moment_accuracy) {
  using std::abs;
  using std::isfinite;
  const T infinity = std::numeric_limits<T>::infinity();
  const int n = r.size;
  const bool odd = support == Support::positive_half_line && failing_index == 2 * n + 1;
  if (n < 1 || n >= N || (support == Support::real_line && !(r.beta[n] <= T(0)))) return infinity;
  T previous[N + 1], p[N + 1];  // p_{n−1}, p_n
  orthogonal_polynomials(r, n, previous, p);
  T value = m[0];
  for (int k = 1; k <= n; ++k) value *= r.beta[k];
  T sensitivity;
  if (odd) {
    advance_orthogonal_polynomial(r, n, previous, p);  // previous = p_n, p = p_{n+1}
    const T ratio = p[0] / previous[0];                // p_{n+1}(0)/p_n(0)
    T kernel[N + 1] = {};
    for (int k = 0; k <= n; ++k) kernel[k] = p[k + 1] - ratio * previous[k + 1];
    value *= -ratio;
    sensitivity = square_sensitivity(kernel, n, m, 1);
  } else {
    sensitivity = square_sensitivity(p, n, m, 0);
  }
  const T error = (moment_accuracy + decision_rounding<T>()) * sensitivity / abs(value);
  return isfinite(error) ? error : infinity;
}

// failed_decision_error() of a reduced set m_0 … m_{2N'−1} in the caller's units, its analysis
// redone as invert() makes it (Wheeler's recurrence on the exactly scaled moments).
template <class T, int N>
FLUIDBED_HOST_DEVICE T failed_decision_error(std::span<const T> m, Support support, const T& moment_accuracy) {
  const ScaledAnalysis<T, N> a = analyse<T, N>(m, support);
  Recurrence<T, N> r = a.recurrence;
  r.size = a.scan.realizable_moments / 2;
  return failed_decision_error(a.moments.view(), r, a.scan.first_failing_index, support, moment_accuracy);
}

}  // namespace detail

// The estimated relative error of `rule`, inverted from `moments` (its 2n moments m_0 …
// m_{2n−1}, n = rule.size, in the caller's units), given that each moment is known to a
// relative `moment_accuracy` (0: exact as given, so only the inversion's rounding counts).
// invert() returns the same estimate in InversionResult::error when InversionOptions asks for
// it, except beyond first order (see the header comment). The count: the decisions the rule
// passed (a full rule of these moments). Infinite where the rule has no digit to estimate (a zero
// weight, coincident nodes, or a moment count that is not 2n); zeros for an empty rule.
template <class T, int N>
FLUIDBED_HOST_DEVICE RuleError<T> estimated_error(std::span<const T> moments, const Quadrature<T, N>& rule,
                                                  Support support = Support::positive_half_line,
                                                  T moment_accuracy = T(0)) {
  const T infinity = std::numeric_limits<T>::infinity();
  const int n = rule.size;
  if (n == 0) return {T(0), T(0)};
  if (n < 0 || n > N || moments.size() != std::size_t(2 * n)) return {infinity, infinity};
  // In the moments' exact power-of-two scales, as the inversion runs.
  const detail::ScaledMoments<T, N> scaled = detail::scaled_moments<T, N>(moments);
  Quadrature<T, N> q = rule;
  detail::scale_rule(q, -scaled.scaling.length_exponent, -scaled.scaling.weight_exponent);
  const Recurrence<T, N> r = wheeler_unscaled<T, N>(scaled.view());
  return detail::scaled_rule_error(scaled.view(), q, r, support, moment_accuracy);
}

}  // namespace fluidbed::moments
