// fluidbed — batched moment inversion: many cells at once, structure of arrays, vectorized
// across cells.
//
// A CFD code stores moment k of every cell in one field array; invert_batched() reads those
// 2N arrays (moments[k][c]) and writes nodes[i][c], weights[i][c], the node count and the
// status of every cell. The per-cell pipeline of inversion.hpp is re-expressed over *lanes*:
// a lane value holds one quantity for L consecutive cells (an Eigen fixed-size array, so
// every arithmetic operation, square root included, is a SIMD operation at the default
// flags — compilers do not vectorize std::sqrt while math-errno is on), and every step runs
// the same operations on all lanes:
//   1. exact power-of-two scaling, the exponents read from the moments' exponent fields;
//   2. Wheeler's recurrence: detail::wheeler_levels, the kernel wheeler_unscaled() runs per cell;
//   3. realizability (every β_k > 0; on [0, ∞) every ζ_j > 0) as a per-cell mask;
//   4. nodes and weights: the closed forms of jacobi_eigen.hpp for n <= 2, its fixed-cost
//      three-node solver for n = 3, the Golub–Welsch QL on lanes for n >= 4;
//   5. with InversionOptions asking for it, the error estimate of accuracy.hpp on [0, ∞);
//   6. exact unscaling.
// A cell whose mask fails anywhere (empty, non-finite, not fully realizable, scale factors
// out of range, non-finite result) is inverted again by the per-cell pipeline, so that its
// status, node count and every special case are exactly those of invert(); a rule it reduces to
// 4 … N − 1 nodes is then solved on lanes with others of that count (ReducedRuleQueues), any
// other by invert() itself. Only such cells pay for a branch; the lanes never branch on data.
//
// Host only: the lanes are Eigen arrays. On a GPU, call invert() per thread (the
// structure-of-arrays layout is then the coalesced one).
//
// Eigen is what makes the lanes SIMD at the default flags: Eigen::Array's sqrt, min and
// division are packet operations on every target Eigen supports, where a loop of std::sqrt is
// not vectorized while math-errno is on, and the alternatives (intrinsics per architecture,
// std::experimental::simd) are less portable. This header and eigen_backend.hpp are the only
// ones that need Eigen.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <span>

#include "../core/config.hpp"
#include "eigen_core.hpp"
#include "inversion.hpp"
#include "jacobi_eigen.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

FLUIDBED_EIGEN_CODE_BEGIN

namespace fluidbed::moments {

// Read-only view of the moments of a batch of cells: moment k of cell c is moments[k][c]. The
// batch has moments[0].size() cells; every moments[k] must have that size.
template <class T, int N>
struct MomentBatch {
  std::array<std::span<const T>, 2 * N> moments{};
  std::size_t cells() const { return moments[0].size(); }
};

// Where invert_batched() writes: node i of cell c at nodes[i][c] (ascending in i) and its
// weight at weights[i][c], 0 for i >= sizes[c]; sizes[c] and status[c] as in InversionResult.
// Every span must have as many entries as the batch has cells, except node_errors,
// weight_errors and count_errors, each of which may be empty: given, it receives its part of
// InversionResult::error of each cell (−1 where no estimate was asked for or the cell has no
// rule).
template <class T, int N>
struct QuadratureBatch {
  std::array<std::span<T>, N> nodes{};
  std::array<std::span<T>, N> weights{};
  std::span<int> sizes;
  std::span<InversionStatus> status;
  std::span<T> node_errors;
  std::span<T> weight_errors;
  std::span<T> count_errors;
};

namespace detail {

template <class T, int L>
struct lane_ops<Eigen::Array<T, L, 1>> {
  using scalar = T;
  using V = Eigen::Array<T, L, 1>;
  static V sqrt(const V& x) { return x.sqrt(); }
  static V abs(const V& x) { return x.abs(); }
  static V min(const V& x, const scalar& bound) { return x.min(bound); }
  static V constant(const scalar& c) { return V::Constant(c); }
  static V larger_error(const V& so_far, const V& next) {  // as the scalar one: NaN and ∞ give ∞
    const V larger = (next > so_far).select(next, so_far);
    return (next <= std::numeric_limits<T>::max()).select(larger, std::numeric_limits<T>::infinity());
  }
  // No comparison or branch per lane, so that the kernels stay vector code once inlined and
  // unrolled: copysign is bit arithmetic, and the choice is an exact blend of finite values
  // (a·1 + b·0 = a); a lane holding a non-finite value is discarded anyway.
  static V sign(const V& x) {
    V s;
    for (int i = 0; i < L; ++i) s[i] = std::copysign(T(1), x[i]);
    return s;
  }
  static V choose(const V& s, const V& a, const V& b) {
    const V f = (s + T(1)) * T(0.5);
    return a * f + b * (T(1) - f);
  }
};

// GCC and Clang do not inline the hundreds of small Eigen functions of a lane kernel on their
// own; flattening the kernel does, and keeps its values in registers.
#if defined(__GNUC__) || defined(__clang__)
#define FLUIDBED_BATCHED_FLATTEN [[gnu::flatten]]
#else
#define FLUIDBED_BATCHED_FLATTEN
#endif

// Cells per lane value: enough independent SIMD operations per statement to hide the latency
// of divisions and square roots, few enough that a kernel's live lane values stay in the vector
// registers: a quarter of the register file, 64 bytes with SSE (16 registers of 16 bytes: 8
// doubles, 16 floats), 128 with AVX and AVX-512. Measured at N = 8 (4096 log-normal cells,
// g++ 12 -O3): 308 ns per cell with 64-byte lanes against 406 with 128 under SSE2; 156 with 128
// against 207 with 64 under AVX2 and FMA; 134 with 128 against 222 with 64 under AVX-512.
#if defined(EIGEN_VECTORIZE_AVX)
inline constexpr int lane_bytes = 128;
#else
inline constexpr int lane_bytes = 64;
#endif

template <class T>
inline constexpr int batch_lanes = sizeof(T) >= lane_bytes ? 1 : int(lane_bytes / sizeof(T));

template <class T>
using Lanes = Eigen::Array<T, batch_lanes<T>, 1>;

// What the fast path requires of each lane, accumulated without comparisons (see
// lane_ops::sign): every value it uses finite, the realizability coefficients positive, the
// scale factors normal numbers. Any NaN or ±∞ makes `finite` NaN, so the minima may ignore
// NaN; a lane passes if finite = 0, positive > 0 and normal >= the smallest normal number.
template <class V>
struct LaneGuards {
  using T = typename V::Scalar;
  V finite = V::Zero();
  V positive = V::Constant(T(1));
  V normal = V::Constant(T(1));
  void require_finite(const V& x) { finite += x - x; }
  void require_positive(const V& x) {
    require_finite(x);
    positive = positive.min(x);
  }
  void require_normal(const V& x) {
    require_finite(x);
    normal = normal.min(x);
  }
  bool passes(int i) const {
    return finite[i] == T(0) && positive[i] > T(0) && normal[i] >= std::numeric_limits<T>::min();
  }
};

// The Golub–Welsch QL of gauss_golub_welsch (jacobi_eigen.hpp: the same Wilkinson shift from the
// leading 2×2 block, the same relative deflation test, the first eigenvector row only) on every
// lane of cells at once, for a recurrence of N >= 4 levels. A lane's deflation is data-dependent,
// so at each level l the lanes sweep until all have deflated: a lane that deflated earlier takes
// the extra sweeps, orthogonal similarities shifted at its converged eigenvalue, which keep d_l
// to rounding and push e_l further down. The per-cell QL's two shortcuts that branch on data are
// dropped: the chase always starts at the bottom (the per-cell one starts at the first negligible
// e_m), and a zero rotation radius (the per-cell split) gives NaN, as does a lane still not
// deflated after 30 sweeps at a level; the guards then hand the cell to invert(). Each rotation
// takes one division (1/r, then two products) where the per-cell QL takes two. The nodes come
// out ascending (a sorting network of compare-exchanges, no branch), the weights m̃_0 v_0².
template <class V, int N>
FLUIDBED_BATCHED_FLATTEN void gauss_golub_welsch_lanes(const V (&alpha)[N], const V (&beta)[N], V (&nodes)[N],
                                                       V (&weights)[N], LaneGuards<V>& guards) {
  using T = typename V::Scalar;
  using ops = lane_ops<V>;
  constexpr int L = int(V::SizeAtCompileTime);
  constexpr int max_sweeps = 30;
  const T eps = std::numeric_limits<T>::epsilon();
  V d[N], e[N], z[N];  // diagonal, off-diagonal (e_i couples i and i + 1), first eigenvector row
  for (int i = 0; i < N; ++i) {
    d[i] = alpha[i];
    e[i] = i + 1 < N ? V(beta[i + 1].sqrt()) : V::Zero();
    z[i] = i == 0 ? V::Ones() : V::Zero();
  }
  for (int l = 0; l + 1 < N; ++l) {
    for (int sweep = 0;; ++sweep) {
      const auto undeflated = e[l].abs() > eps * (d[l].abs() + d[l + 1].abs());  // false for NaN
      if (!undeflated.any()) break;
      if (sweep == max_sweeps) {
        for (int i = 0; i < L; ++i)
          if (undeflated[i]) guards.finite[i] = std::numeric_limits<T>::quiet_NaN();
        break;
      }
      V g = ql_sweep_start(d[l], d[l + 1], e[l], d[N - 1]);
      V s = V::Ones(), c = V::Ones(), p = V::Zero();
      for (int i = N - 2; i >= l; --i) {
        const V f = s * e[i], b = c * e[i];
        e[i + 1] = (f * f + g * g).sqrt();
        const V inverse = T(1) / e[i + 1];
        s = f * inverse;
        c = g * inverse;
        ql_rotate(s, c, b, p, g, d[i], d[i + 1], z[i], z[i + 1]);
      }
      d[l] -= p;
      e[l] = g;
      e[N - 1].setZero();
    }
  }
  for (int i = 0; i < N; ++i) weights[i] = beta[0] * z[i] * z[i];
  // Odd–even transposition sort (N rounds of compare-exchanges on neighbours).
  for (int round = 0; round < N; ++round)
    for (int i = round % 2; i + 1 < N; i += 2) {
      const V keep = ops::sign(d[i + 1] - d[i]);  // +1: already in order
      const V low = d[i].min(d[i + 1]), high = d[i].max(d[i + 1]);
      const V low_weight = ops::choose(keep, weights[i], weights[i + 1]);
      weights[i + 1] = ops::choose(keep, weights[i + 1], weights[i]);
      weights[i] = low_weight;
      d[i] = low;
      d[i + 1] = high;
    }
  for (int i = 0; i < N; ++i) nodes[i] = d[i];
}

// Exact power-of-two scales of the cells of a lane value: m_k = weight·length^k·m̃_k.
template <class V>
struct LaneScales {
  V weight, inverse_weight, length, inverse_length;
};

// The scales of scaling_of (recurrence.hpp): weight 2^a ≈ m_0, length 2^b ≈ max(|m_1|/m_0,
// √(m_2/m_0)) (m_2 given: `second`), the same powers of two as scaling_of's (the nearest ones,
// read from the exponent fields and the leading fraction bits), so that a cell gives the same
// bits in the lanes as in invert() also where an intermediate is subnormal in scaled units (a
// weight below 2^−126 m_0 in float: with the floor of the exponent the two paths rounded it
// differently, found by fuzz/); other types per cell by scaling_of. The guards require m_0, the
// scales and their inverses to be normal numbers.
template <class V>
LaneScales<V> lane_scales(const V& m0, const V& m1, const V* second, LaneGuards<V>& guards) {
  using T = typename V::Scalar;
  constexpr int L = int(V::SizeAtCompileTime);
  LaneScales<V> s;
  if constexpr (has_binary_layout<T>) {
    using bits = layout_bits<T>;
    constexpr int shift = std::numeric_limits<T>::digits - 1;
    constexpr int bias = std::numeric_limits<T>::max_exponent - 1;
    constexpr int none = -4 * bias;  // no scale from this moment (0 or subnormal)
    // 2^e, or 0 where 2^e is not a normal number (the guards reject the cell then).
    const auto power = [](int e) {
      return e >= 1 - bias && e <= bias ? std::bit_cast<T>(bits(e + bias) << shift) : T(0);
    };
    for (int i = 0; i < L; ++i) {
      const int e0 = nearest_biased_exponent(m0[i]), e1 = nearest_biased_exponent(m1[i]);
      const int e2 = second ? nearest_biased_exponent((*second)[i]) : 0;
      const bool positive_second = second && (*second)[i] > T(0);
      const int from_mean = e1 > 0 ? e1 - e0 : none;
      const int from_second = e2 > 0 && positive_second ? (e2 - e0 + 1) >> 1 : none;
      const int length = from_mean > from_second ? from_mean : from_second;
      const int b = length == none ? 0 : length;
      // A subnormal m_1 or m_2 has no exponent field to read (scaling_of takes it from frexp):
      // such a cell goes to invert() (weight 0 fails the guards).
      const bool subnormal = (m1[i] != T(0) && e1 == 0) || (positive_second && e2 == 0);
      s.weight[i] = subnormal ? T(0) : power(e0 - bias);
      s.inverse_weight[i] = power(bias - e0);
      s.length[i] = power(b);
      s.inverse_length[i] = power(-b);
    }
  } else {
    using std::isfinite;
    for (int i = 0; i < L; ++i) {
      const T m[3] = {m0[i], m1[i], second ? (*second)[i] : T(0)};
      const std::size_t count = second ? 3 : 2;
      bool usable = m0[i] > T(0);
      for (std::size_t k = 0; k < count; ++k) usable = usable && isfinite(m[k]);
      const MomentScaling e = usable ? scaling_of(std::span<const T>(m, count)) : MomentScaling{};
      s.weight[i] = power_of_two<T>(e.weight_exponent);
      s.inverse_weight[i] = power_of_two<T>(-e.weight_exponent);
      s.length[i] = power_of_two<T>(e.length_exponent);
      s.inverse_length[i] = power_of_two<T>(-e.length_exponent);
    }
  }
  for (const V* x : std::initializer_list<const V*>{&m0, &s.weight, &s.inverse_weight, &s.length, &s.inverse_length})
    guards.require_normal(*x);
  return s;
}

// Steps 1–4 of the batched pipeline on one lane value of cells: the recurrence in alpha and beta
// and the nodes and weights in x and w, in scaled units, the guards that tell which lanes they
// are valid for, and the scales that unscale_lanes() takes the rules back to the caller's units
// with.
template <Support support, class V, int N>
FLUIDBED_BATCHED_FLATTEN LaneScales<V> invert_lane_values(const V (&m)[2 * N], V (&alpha)[N], V (&beta)[N],
                                                          V (&x)[N], V (&w)[N], LaneGuards<V>& guards) {
  using T = typename V::Scalar;
  constexpr int L = int(V::SizeAtCompileTime);
  for (int k = 0; k < 2 * N; ++k) guards.require_finite(m[k]);
  // 1. Exact scaling: the factors 2^−(a + k b) by repeated exact products, all normal if the
  // last one is (they are monotonic in k and the first one is checked by lane_scales).
  const LaneScales<V> s = lane_scales(m[0], m[1], N >= 2 ? &m[2 % (2 * N)] : nullptr, guards);
  V scaled[2 * N];
  V factor = s.inverse_weight;
  for (int k = 0; k < 2 * N; ++k) {
    scaled[k] = m[k] * factor;
    if (k + 1 < 2 * N) factor *= s.inverse_length;
  }
  guards.require_normal(factor);
  // m̃_1 a normal number unless m_1 = 0 (detail::scaled_moments_in_range); on [0, ∞) the test
  // of ζ_1 = α_0 = m̃_1/m̃_0 (m̃_0 >= 1) below implies it.
  if constexpr (support == Support::real_line)
    guards.require_normal((m[1] == T(0)).select(V::Constant(T(1)), scaled[1].abs()));
  // 2. Recurrence.
  wheeler_levels<V, N>(scaled, N, alpha, beta);
  // 3. Realizability: every β_k > 0 and finite (the per-cell Wheeler's stop test), and on
  // [0, ∞) every ζ_j > 0 and finite (as scan_coefficients()).
  for (int k = 0; k < N; ++k) guards.require_finite(alpha[k]);
  for (int k = 1; k < N; ++k) guards.require_positive(beta[k]);
  if constexpr (support == Support::positive_half_line) {
    V zeta = alpha[0];  // ζ_1, then ζ_{2k} and ζ_{2k+1}
    guards.require_normal(zeta);  // > 0, and m̃_1 not subnormal
    for (int k = 1; k < N; ++k) {
      const V even = beta[k] / zeta;
      zeta = alpha[k] - even;
      guards.require_positive(even);
      guards.require_positive(zeta);
    }
  }
  // 4. Nodes and weights of the scaled recurrence.
  if constexpr (N == 3) {
    const V spread_margin = gauss_three_nodes(alpha, beta, x, w);
    guards.require_positive(spread_margin);  // else the QL, per cell
  } else if constexpr (N >= 4) {
    gauss_golub_welsch_lanes(alpha, beta, x, w, guards);
  } else {
    for (int k = 0; k < N; ++k) {
      x[k].setZero();
      w[k].setZero();
    }
    for (int i = 0; i < L; ++i) {
      if (!guards.passes(i)) continue;
      Recurrence<T, N> r;
      r.size = N;
      for (int k = 0; k < N; ++k) {
        r.alpha[k] = alpha[k][i];
        r.beta[k] = beta[k][i];
      }
      const Quadrature<T, N> q = gauss_closed_form(r);
      for (int k = 0; k < N; ++k) {
        x[k][i] = q.nodes[k];
        w[k][i] = q.weights[k];
      }
    }
  }
  return s;
}

// Step 5: the rules of a lane value in the caller's units.
template <class V, int N>
void unscale_lanes(V (&x)[N], V (&w)[N], const LaneScales<V>& s, LaneGuards<V>& guards) {
  for (int k = 0; k < N; ++k) {
    x[k] *= s.length;
    w[k] *= s.weight;
    guards.require_finite(x[k]);
    guards.require_finite(w[k]);
  }
}

// Writes the rule and status of cell c.
template <class T, int N>
void store_rule(const QuadratureBatch<T, N>& out, std::size_t c, const Quadrature<T, N>& q, InversionStatus status) {
  out.sizes[c] = q.size;
  out.status[c] = status;
  for (int k = 0; k < N; ++k) {
    out.nodes[k][c] = q.nodes[k];
    out.weights[k][c] = q.weights[k];
  }
}

// The 2N moments of cell c, gathered from the batch's columns.
template <class T, int N>
std::array<T, 2 * N> cell_moments(const MomentBatch<T, N>& in, std::size_t c) {
  std::array<T, 2 * N> cell;
  for (int k = 0; k < 2 * N; ++k) cell[k] = in.moments[k][c];
  return cell;
}

// Cell c's error estimate into the error spans, when they are given.
template <class T, int N>
void store_error(const QuadratureBatch<T, N>& out, std::size_t c, const RuleError<T>& error) {
  if (!out.node_errors.empty()) out.node_errors[c] = error.nodes;
  if (!out.weight_errors.empty()) out.weight_errors[c] = error.weights;
  if (!out.count_errors.empty()) out.count_errors[c] = error.count;
}

// Cell c's estimate (−1 where none was made) stored, and its rule marked inaccurate where the
// estimate misses the options' requirement.
template <class T, int N>
void record_error(const QuadratureBatch<T, N>& out, std::size_t c, const RuleError<T>& error,
                  const InversionOptions& options) {
  if (has_rule(out.status[c]) && misses_requirement(error, options)) out.status[c] = InversionStatus::inaccurate;
  store_error(out, c, error);
}

// Cell c's stored rule.
template <class T, int N>
Quadrature<T, N> stored_rule(const QuadratureBatch<T, N>& out, std::size_t c) {
  Quadrature<T, N> q;
  q.size = out.sizes[c];
  for (int i = 0; i < q.size; ++i) {
    q.nodes[i] = out.nodes[i][c];
    q.weights[i] = out.weights[i][c];
  }
  return q;
}

// Cell c's first-order estimate (from the lanes, or per cell) completed as invert() completes it:
// beyond first order, the vertex rules (add_vertex_changes); then recorded.
template <class T, int N>
void finish_error(const MomentBatch<T, N>& in, const QuadratureBatch<T, N>& out, std::size_t c, RuleError<T> error,
                  const InversionOptions& options) {
  if (has_rule(out.status[c]) && beyond_first_order(error, options)) {
    const std::array<T, 2 * N> cell = cell_moments(in, c);
    add_vertex_changes(std::span<const T>(cell).first(std::size_t(2 * out.sizes[c])), stored_rule(out, c), options,
                       error);
  }
  record_error(out, c, error, options);
}

// Cell c's stored rule estimated per cell, as invert() with the options estimates it (from the
// cell's moments: estimated_error(), and for a reduced rule failed_decision_error()), and recorded.
template <class T, int N>
void estimate_cell_error(const MomentBatch<T, N>& in, const QuadratureBatch<T, N>& out, std::size_t c,
                         const InversionOptions& options) {
  RuleError<T> error;  // −1: not asked for, or no rule
  if (wants_estimate(options) && has_rule(out.status[c])) {
    const std::array<T, 2 * N> cell = cell_moments(in, c);
    error = estimated_error(std::span<const T>(cell).first(std::size_t(2 * out.sizes[c])), stored_rule(out, c),
                            options.support, T(options.moment_accuracy));
    if (out.status[c] == InversionStatus::reduced)
      error.count = lane_ops<T>::larger_error(error.count, failed_decision_error<T, N>(std::span<const T>(cell),
                                                                                       options.support,
                                                                                       T(options.moment_accuracy)));
  }
  finish_error(in, out, c, error, options);
}

// Cell c inverted by invert() alone with the options, its rule, status and estimate stored.
template <class T, int N>
void invert_cell_alone(const MomentBatch<T, N>& in, std::size_t c, const QuadratureBatch<T, N>& out,
                       const InversionOptions& options) {
  const std::array<T, 2 * N> cell = cell_moments(in, c);
  const InversionResult<T, N> result = invert<T, N>(std::span<const T>(cell), options);
  store_rule(out, c, result.quadrature, result.status);
  store_error(out, c, result.error);
}

// Cells the lanes did not validate whose rule invert() reduces to 4 … N − 1 nodes (sets that
// rounding left unrealizable beyond them: a quarter of random 8-atom cells in double). Their
// scaled recurrences wait here, one queue per node count, and are solved on lanes once L of a
// count have gathered, and at the end of the batch, instead of by the per-cell QL.
template <class T, int N>
struct ReducedRuleQueues {
  using V = Lanes<T>;
  static constexpr int L = int(V::SizeAtCompileTime);
  struct Queue {
    V alpha[N], beta[N];
    std::size_t cell[L];
    MomentScaling scaling[L];
    int size = 0;
  };
  Queue queues[N > 5 ? N - 4 : 1];  // queues[k − 4] for k nodes
};

// Solves a queue of K-node recurrences on lanes and stores the rules and their estimates; a cell
// whose lane or unscaled rule is not finite is inverted again by invert(). Empties the queue.
template <int K, class T, int N>
void solve_reduced_queue(typename ReducedRuleQueues<T, N>::Queue& queue, const MomentBatch<T, N>& in,
                         const QuadratureBatch<T, N>& out, const InversionOptions& options) {
  using V = Lanes<T>;
  V alpha[K], beta[K], x[K], w[K];
  for (int k = 0; k < K; ++k) {
    alpha[k] = queue.alpha[k];
    beta[k] = queue.beta[k];
    for (int i = queue.size; i < int(V::SizeAtCompileTime); ++i) {  // padding lanes: a copy of lane 0
      alpha[k][i] = alpha[k][0];
      beta[k][i] = beta[k][0];
    }
  }
  LaneGuards<V> guards;
  gauss_golub_welsch_lanes(alpha, beta, x, w, guards);
  for (int i = 0; i < queue.size; ++i) {
    Quadrature<T, N> q;
    q.size = K;
    for (int k = 0; k < K; ++k) {
      q.nodes[k] = x[k][i];
      q.weights[k] = w[k][i];
    }
    bool valid = guards.passes(i) && finite_rule(q);
    if (valid) {
      unscale(q, queue.scaling[i]);
      valid = finite_rule(q);
    }
    if (valid) {
      store_rule(out, queue.cell[i], q, InversionStatus::reduced);
      estimate_cell_error(in, out, queue.cell[i], options);
    } else {
      invert_cell_alone(in, queue.cell[i], out, options);
    }
  }
  queue.size = 0;
}

// The queue of k nodes, k = K … N − 1, solved (a run-time count to the compile-time K).
template <class T, int N, int K = 4>
void solve_reduced_queue(ReducedRuleQueues<T, N>& queues, int k, const MomentBatch<T, N>& in,
                         const QuadratureBatch<T, N>& out, const InversionOptions& options) {
  if constexpr (K < N) {
    if (k == K)
      solve_reduced_queue<K, T, N>(queues.queues[K - 4], in, out, options);
    else
      solve_reduced_queue<T, N, K + 1>(queues, k, in, out, options);
  }
}

// A cell the lanes did not validate: invert() decides its status, size and rule, except that a
// rule reduced to 4 … N − 1 nodes is queued (its status and size stored now, its nodes and
// estimate when its queue is solved).
template <Support support, class T, int N>
void invert_cell(const MomentBatch<T, N>& in, std::size_t c, ReducedRuleQueues<T, N>& queues,
                 const QuadratureBatch<T, N>& out, const InversionOptions& options) {
  const std::array<T, 2 * N> cell = cell_moments(in, c);
  const std::span<const T> moments(cell);
  Recurrence<T, N> reduced;
  const InversionResult<T, N> result = invert_with<T, N>(
      moments, {.support = support}, [&reduced](const Recurrence<T, N>& r, Quadrature<T, N>& q) {
        if (r.size >= 4 && r.size < N) {  // queued; q holds zeros meanwhile
          reduced = r;
          q.size = r.size;
          return true;
        }
        return solve_recurrence(r, q, EigenSolver::automatic);
      });
  store_rule(out, c, result.quadrature, result.status);
  if (reduced.size == 0 || result.status != InversionStatus::reduced) {
    estimate_cell_error(in, out, c, options);
    return;
  }
  auto& queue = queues.queues[reduced.size - 4];
  const int i = queue.size++;
  for (int k = 0; k < reduced.size; ++k) {
    queue.alpha[k][i] = reduced.alpha[k];
    queue.beta[k][i] = reduced.beta[k];
  }
  queue.cell[i] = c;
  queue.scaling[i] = scaling_of(moments);  // invert_with's (scaled_moments)
  if (queue.size == ReducedRuleQueues<T, N>::L) solve_reduced_queue(queues, reduced.size, in, out, options);
}

// The estimates of the N-node rules of a lane value on [0, ∞), from their recurrences (alpha,
// beta) and rules (x, w) in scaled units, with the same operations as invert() per cell: the same
// bits where the rules are (N <= 2, no contraction).
template <class V, int N, class T = typename V::Scalar>
FLUIDBED_BATCHED_FLATTEN void lane_rule_errors(const V (&alpha)[N], const V (&beta)[N], const V (&x)[N],
                                               const V (&w)[N], const T& moment_accuracy, RuleError<T>* errors) {
  const RuleErrorTerms<V> terms = rule_error_terms<N>(w, N, moment_accuracy);
  V nodes = V::Zero(), weights = V::Zero();
  NodeSensitivity<V> sensitivity[N];
  positive_sensitivities(x, w, N, sensitivity);
  for (int i = 0; i < N; ++i) add_node_error(nodes, weights, sensitivity[i], w[i], V(x[i].abs()), terms);
  const V perturbation = V::Constant(moment_accuracy + decision_rounding<T>());
  const V count = passed_decisions_error<V, N>(x, w, alpha, beta, N, perturbation);
  for (int lane = 0; lane < int(V::SizeAtCompileTime); ++lane) errors[lane] = {nodes[lane], weights[lane], count[lane]};
}

// Inverts `count` <= L cells from cell `first` on: the lane kernel, then invert_cell() for every
// cell it did not validate. The estimates of the validated rules are made on the lanes, before
// unscaling, on [0, ∞), and per cell on the real line (its sensitivities need the moments).
template <Support support, class T, int N>
void invert_lanes(const MomentBatch<T, N>& in, std::size_t first, int count, ReducedRuleQueues<T, N>& queues,
                  const QuadratureBatch<T, N>& out, const InversionOptions& options) {
  using V = Lanes<T>;
  constexpr int L = int(V::SizeAtCompileTime);
  V m[2 * N];
  for (int k = 0; k < 2 * N; ++k) {
    if (count == L) {
      m[k] = Eigen::Map<const V>(in.moments[k].data() + first);
    } else {
      m[k].setZero();  // padding lanes: empty cells, never stored
      for (int i = 0; i < count; ++i) m[k][i] = in.moments[k][first + i];
    }
  }
  V alpha[N], beta[N], x[N], w[N];
  LaneGuards<V> guards;
  const LaneScales<V> scales = invert_lane_values<support>(m, alpha, beta, x, w, guards);
  constexpr bool errors_on_lanes = support == Support::positive_half_line;
  RuleError<T> errors[L];  // −1: not asked for
  if (errors_on_lanes && wants_estimate(options))
    lane_rule_errors(alpha, beta, x, w, T(options.moment_accuracy), errors);
  unscale_lanes(x, w, scales, guards);
  for (int k = 0; k < N; ++k) {
    if (count == L) {
      Eigen::Map<V>(out.nodes[k].data() + first) = x[k];
      Eigen::Map<V>(out.weights[k].data() + first) = w[k];
    } else {
      for (int i = 0; i < count; ++i) {
        out.nodes[k][first + i] = x[k][i];
        out.weights[k][first + i] = w[k][i];
      }
    }
  }
  for (int i = 0; i < count; ++i) {
    const std::size_t c = first + std::size_t(i);
    if (guards.passes(i)) {
      out.sizes[c] = N;
      out.status[c] = InversionStatus::ok;
      if (errors_on_lanes)
        finish_error(in, out, c, errors[i], options);
      else
        estimate_cell_error(in, out, c, options);
    } else {
      invert_cell<support>(in, c, queues, out, options);
    }
  }
}

template <Support support, class T, int N>
void invert_batched(const MomentBatch<T, N>& in, const QuadratureBatch<T, N>& out, const InversionOptions& options) {
  constexpr std::size_t L = std::size_t(batch_lanes<T>);
  const std::size_t cells = in.cells();
  ReducedRuleQueues<T, N> queues;
  for (std::size_t first = 0; first < cells; first += L)
    invert_lanes<support>(in, first, int(cells - first < L ? cells - first : L), queues, out, options);
  for (int k = 4; k < N; ++k)
    if (queues.queues[k - 4].size > 0) solve_reduced_queue(queues, k, in, out, options);
}

// Whether every span of a batch has as many entries as it has cells (the error spans: or none).
template <class T, int N>
bool same_cell_counts(const MomentBatch<T, N>& in, const QuadratureBatch<T, N>& out) {
  const std::size_t cells = in.cells();
  const auto optional_fits = [cells](std::size_t size) { return size == 0 || size == cells; };
  bool same = out.sizes.size() == cells && out.status.size() == cells && optional_fits(out.node_errors.size()) &&
              optional_fits(out.weight_errors.size()) && optional_fits(out.count_errors.size());
  for (const std::span<const T>& moment : in.moments) same = same && moment.size() == cells;
  for (int i = 0; i < N; ++i) same = same && out.nodes[i].size() == cells && out.weights[i].size() == cells;
  return same;
}

}  // namespace detail

// Inverts every cell of the batch: 2N moments per cell to an N-node Gauss rule, with the
// results, statuses and reduced rules of invert<T, N>(moments of the cell, {.support}) — bit for
// bit for N <= 2 (at flags without floating-point contraction), to rounding from N = 3 (the
// three-node solver, and from N = 4 the QL on lanes, whose sweeps differ from the per-cell
// QL's). Allocation-free and thread-safe; distinct threads may invert
// disjoint cell ranges of the same arrays. Returns false, reading and writing nothing, unless
// every span of `in` and `out` has in.cells() entries (an empty batch: true).
template <class T, int N>
[[nodiscard]] bool invert_batched(const MomentBatch<T, N>& in, const QuadratureBatch<T, N>& out,
                                  Support support = Support::positive_half_line) {
  return invert_batched(in, out, InversionOptions{.support = support});
}

// The same with InversionOptions: its support, and the error estimate (estimate_error,
// moment_accuracy, required_accuracy) as invert() makes it, from each cell's rule; algorithm and
// solver are those of the batched path (Wheeler, the solvers above). The estimate of a rule the
// lanes validated is made on the lanes on [0, ∞), before unscaling, and per cell otherwise.
template <class T, int N>
[[nodiscard]] bool invert_batched(const MomentBatch<T, N>& in, const QuadratureBatch<T, N>& out,
                                  const InversionOptions& options) {
  static_assert(N >= 1, "fluidbed::moments::invert_batched: N >= 1 nodes per cell");
  if (!detail::same_cell_counts(in, out)) return false;
  if (options.support == Support::positive_half_line)
    detail::invert_batched<Support::positive_half_line>(in, out, options);
  else
    detail::invert_batched<Support::real_line>(in, out, options);
  return true;
}

}  // namespace fluidbed::moments

FLUIDBED_EIGEN_CODE_END

#undef FLUIDBED_BATCHED_FLATTEN
