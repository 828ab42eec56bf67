// fluidbed — Gauss nodes and weights from the recurrence (the Jacobi matrix).
//
// Golub & Welsch (1969), Math. Comp. 23, 221–230, doi:10.1090/S0025-5718-69-99647-1;
// seed 000 eqs. 5.82–5.85 and 5.92: the nodes are the eigenvalues of
// J = tridiag(√β_k; α_k; √β_k) and the weights m_0 v_{0,i}², v_{0,i} the first component of
// the i-th unit eigenvector. Only that first row is needed, so the QL iteration below carries
// one row of the eigenvector matrix instead of all n² entries.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "../core/config.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

// Nodes (ascending) and weights of a Gauss rule with `size` <= N points.
template <class T, int N>
struct Quadrature {
  std::array<T, N> nodes{};
  std::array<T, N> weights{};
  int size = 0;
};

namespace detail {

// Multiplies the nodes by 2^length_exponent and the weights by 2^weight_exponent, exactly where
// the results are normal numbers: a rule from the scaled units of the inversion to the caller's
// (unscale, inversion.hpp) and back (estimated_error, accuracy.hpp).
template <class T, int N>
FLUIDBED_HOST_DEVICE void scale_rule(Quadrature<T, N>& q, int length_exponent, int weight_exponent) {
  const T length = power_of_two<T>(length_exponent);
  const T weight = power_of_two<T>(weight_exponent);
  for (int i = 0; i < q.size; ++i) {
    q.nodes[i] = times_power_of_two(q.nodes[i], length, length_exponent);
    q.weights[i] = times_power_of_two(q.weights[i], weight, weight_exponent);
  }
}

// Orders the first n nodes ascending, carrying their weights (insertion sort: n is small).
template <class T, int N>
FLUIDBED_HOST_DEVICE void sort_nodes(Quadrature<T, N>& q) {
  for (int i = 1; i < q.size; ++i)
    for (int j = i; j > 0 && q.nodes[j] < q.nodes[j - 1]; --j) {
      const T x = q.nodes[j];
      q.nodes[j] = q.nodes[j - 1];
      q.nodes[j - 1] = x;
      const T w = q.weights[j];
      q.weights[j] = q.weights[j - 1];
      q.weights[j - 1] = w;
    }
}

}  // namespace detail

// Closed forms for n = 1 and 2 (r.size <= 2). For n = 2 the nodes are x = α_0 + y with
// y² − 2hy − β_1 = 0, h = (α_1 − α_0)/2: the root away from α_0, y_far = h + sign(h)√(h² + β_1),
// has no cancellation, and the other follows from y_near y_far = −β_1 (Vieta). (The textbook
// c ∓ √(h² + β_1), c = (α_0 + α_1)/2, cancels for the node near α_0 when the other is far: off
// by ε|x_far|, 2.8e-10 at 0.1 beside −5.9e6, found by fuzz/.) The weights in the Christoffel
// form w_i = m_0 β_1/(β_1 + y_i²), on those y, have no cancellation either (the textbook
// (m_0 x_2 − m_1)/(x_2 − x_1) loses the small weight of a skewed pair). An empty rule (size 0)
// for a recurrence of another size (> 2, or beyond N).
template <class T, int N>
FLUIDBED_HOST_DEVICE Quadrature<T, N> gauss_closed_form(const Recurrence<T, N>& r) {
  using std::hypot;
  using std::isfinite;
  using std::sqrt;
  Quadrature<T, N> q;
  if (r.size > 2 || !detail::size_in_storage(r)) return q;
  q.size = r.size;
  if (r.size == 1) {
    q.nodes[0] = r.alpha[0];
    q.weights[0] = r.beta[0];
  } else if (r.size == 2) {
    const T h = (r.alpha[1] - r.alpha[0]) / T(2);
    T radius = sqrt(h * h + r.beta[1]);
    if (!isfinite(radius)) radius = hypot(h, sqrt(r.beta[1]));  // h² beyond the range, the root not
    const T far = h < T(0) ? h - radius : h + radius;
    const T near = -r.beta[1] / far;
    const T y[2] = {h < T(0) ? far : near, h < T(0) ? near : far};  // ascending
    for (int i = 0; i < 2; ++i) {
      q.nodes[i] = r.alpha[0] + y[i];
      q.weights[i] = r.beta[0] * r.beta[1] / (r.beta[1] + y[i] * y[i]);
    }
  }
  return q;
}

namespace detail {

// The start of a QL sweep at level l (tql2's form of the Wilkinson shift from the leading 2×2
// block): g = d_m − d_l + e_l/(h + sign(h)√(h² + 1)), h = (d_{l+1} − d_l)/(2 e_l), on a scalar or
// a lane of cells. Shared by gauss_golub_welsch and its lanes in batched.hpp.
template <class V>
FLUIDBED_HOST_DEVICE V ql_sweep_start(const V& d_l, const V& d_next, const V& e_l, const V& d_m) {
  using ops = lane_ops<V>;
  using T = typename ops::scalar;
  const V h = (d_next - d_l) / (T(2) * e_l);
  return d_m - d_l + e_l / (h + ops::sign(h) * ops::sqrt(h * h + T(1)));
}

// The rest of one plane rotation of the QL chase at rows i, i + 1, once its sine s and cosine c
// are known (b = c_previous·e_i): the diagonal pair, the running p and g, and the first row of
// the eigenvector matrix. Shared likewise.
template <class V>
FLUIDBED_HOST_DEVICE void ql_rotate(const V& s, const V& c, const V& b, V& p, V& g, V& d_i, V& d_next, V& z_i,
                                    V& z_next) {
  using T = typename lane_ops<V>::scalar;
  g = d_next - p;
  const V r = (d_i - g) * s + T(2) * c * b;
  p = s * r;
  d_next = g + p;
  g = c * r - b;
  const V top = z_next;
  z_next = s * z_i + c * top;
  z_i = c * z_i - s * top;
}

}  // namespace detail

// Implicit QL with Wilkinson shifts on the symmetric tridiagonal J (the algorithm of
// EISPACK tql2: Bowdler, Martin, Reinsch & Wilkinson (1968), Numer. Math. 11, 293–306),
// accumulating only the first row of the eigenvector matrix. Deflation is relative
// (|e_m| <= ε_mach (|d_m| + |d_{m+1}|)), so the result does not depend on units. Returns
// false if some eigenvalue needed more than 30 iterations (never observed; the quadrature
// is then left with size 0). Expects the recurrence in units where its entries are O(1) or
// at least far from overflow (inversion.hpp passes the scaled one): sqrt(f² + g²) is used
// for the rotations instead of hypot. Returns false (q.size = 0) for a size not within 0 … N.
template <class T, int N>
FLUIDBED_HOST_DEVICE bool gauss_golub_welsch(const Recurrence<T, N>& r, Quadrature<T, N>& q) {
  using std::abs;
  using std::sqrt;
  const int n = r.size;
  if (!detail::size_in_storage(r)) {
    q.size = 0;
    return false;
  }
  T d[N]{};
  T e[N]{};
  T z[N]{};
  for (int i = 0; i < n; ++i) {
    d[i] = r.alpha[i];
    e[i] = i + 1 < n ? sqrt(r.beta[i + 1]) : T(0);
  }
  if (n > 0) z[0] = T(1);
  const T eps = std::numeric_limits<T>::epsilon();
  for (int l = 0; l < n; ++l) {
    for (int iteration = 0;; ++iteration) {
      int m = l;
      while (m < n - 1 && abs(e[m]) > eps * (abs(d[m]) + abs(d[m + 1]))) ++m;
      if (m == l) break;
      if (iteration == 30) {
        q.size = 0;
        return false;
      }
      // Wilkinson shift from the leading 2×2 block, then the chase from m up to l.
      T g = detail::ql_sweep_start(d[l], d[l + 1], e[l], d[m]);
      T s(1), c(1), p(0), radius(1);
      int i = m - 1;
      for (; i >= l; --i) {
        const T f = s * e[i];
        const T b = c * e[i];
        radius = sqrt(f * f + g * g);
        e[i + 1] = radius;
        if (radius == T(0)) {  // underflow: split the matrix here and restart
          d[i + 1] -= p;
          e[m] = T(0);
          break;
        }
        s = f / radius;
        c = g / radius;
        detail::ql_rotate(s, c, b, p, g, d[i], d[i + 1], z[i], z[i + 1]);
      }
      if (radius == T(0) && i >= l) continue;
      d[l] -= p;
      e[l] = g;
      e[m] = T(0);
    }
  }
  q.size = n;
  for (int i = 0; i < n; ++i) {
    q.nodes[i] = d[i];
    q.weights[i] = r.beta[0] * z[i] * z[i];
  }
  detail::sort_nodes(q);
  return true;
}

namespace detail {

// Halley steps that take a guess within 2^−8 of a simple root to the last of `digits` bits:
// each step about triples the correct bits (double: 2; 50 decimal digits: 3).
constexpr int halley_steps(int digits) {
  int steps = 0;
  for (int bits = 8; bits < digits + 2; bits *= 3) ++steps;
  return steps;
}

}  // namespace detail

// Where the three-node solver below is as accurate as the QL: while the spread of the nodes,
// √p = √(tr B²/6), is within three_node_spread_limit of their rms √(m_2/m_0) = √(α_0² + β_1).
// Measured on 300 000 random three-atom sets per precision (nodes and weights log-uniform over
// up to 16 decades, both supports) against a long-double QL of the same recurrence: both solvers
// err by ~ε·(√p/rms)·rms in the nodes up to ratios ~3e5 (float) and ~3e7 (double); beyond, the
// eigenvector of the extreme node (from the adjugate) no longer resolves the other two and the
// closed form breaks down (nodes off by 1e6 rms in float at 3e5, where the QL is off by 0.5).
// A margin > 0 selects the closed form; the limit, 1e3, keeps two decades from the breakdown
// in float and lets log-normal size distributions up to σ_ln = 1.5 through (ratio 0.37 at
// σ_ln = 0.3, 14 at 1, 964 at 1.5; 4e5 at 2, which goes to the QL).
namespace detail {

template <class T>
FLUIDBED_HOST_DEVICE T three_node_spread_limit() {
  return T(1000);
}

// limit² (α_0² + β_1) − p for a three-node recurrence (p = tr(B²)/6, as the solver below forms
// it), on a scalar or a lane of cells: > 0 where the solver suits.
template <class V>
FLUIDBED_HOST_DEVICE V three_node_spread_margin(const V& p, const V& alpha0, const V& beta1) {
  using T = typename lane_ops<V>::scalar;
  const T limit = three_node_spread_limit<T>();
  return limit * limit * (alpha0 * alpha0 + beta1) - p;
}

}  // namespace detail

// Gauss rule of a three-node recurrence (β_1, β_2 > 0) at a fixed operation count: no
// data-dependent iteration, so it vectorizes across cells (V = Eigen array) and is also a
// short-latency per-cell solver (V = T). Works on any units but is meant for the scaled
// recurrence (entries O(1)), as the QL.
//
// With μ = tr J/3 and B = J − μI, the eigenvalues of B solve λ³ − 3pλ − 2q = 0,
// p = tr(B²)/6, q = det(B)/2 (Smith (1961), Commun. ACM 4, 168, doi:10.1145/355578.366316).
// Smith's trigonometric solution is not used: acos/cos do not vectorize, and the
// invariants determine a close pair of eigenvalues only to √ε (Kopp (2008), Int. J. Mod.
// Phys. C 19, 523, doi:10.1142/S0129183108012303). Instead:
//   1. the eigenvalue of largest |λ| is t·√p, where t ∈ [√3, 2] is the largest root of
//      t³ − 3t − 2|r|, r = q/p^(3/2), signed like r; it is at least √3·√p from the other
//      two (their t's are <= 0), hence perfectly conditioned. A quadratic guess exact at
//      |r| = 0 and 1 is within 3e-3 of t, and Halley steps (cubic convergence, error
//      ≈ 0.6 e³ per step) bring it to rounding: two in double, three in 50 digits;
//   2. its eigenvector u is a column of adj(B − λI) = Π(λ_j − λ) u uᵀ; summing the columns
//      with signs (1, s, 1), s = sign(r), adds terms of one sign only, because the
//      eigenvector of the largest eigenvalue of a Jacobi matrix has no sign change and that
//      of the smallest alternates (the oscillation property; Parlett (1998), The Symmetric
//      Eigenvalue Problem, SIAM), so there is no cancellation;
//   3. B restricted to the orthogonal complement of u (an orthonormal pair q1, q2 ⊥ u built
//      from u) is a symmetric 2×2 matrix K; its eigenpairs come in closed form with the
//      eigenvector written in its non-cancelling form, then mapped back by [q1 q2]. This is
//      an exact orthogonal deflation, so a close pair of nodes is resolved to ε‖B‖, as by
//      the QL.
// Weights are m_0 times the squared first eigenvector components. Cost (double): 6 square
// roots and 5 divisions, against 4–5 QL sweeps of 3 square roots and 6 divisions each on one
// dependency chain (measured for size distributions).
// Returns the spread margin (detail::three_node_spread_margin): where it is not > 0 the rule is
// not to be used (invert() and invert_batched() take the QL there).
template <class V>
FLUIDBED_HOST_DEVICE V gauss_three_nodes(const V (&alpha)[3], const V (&beta)[3], V (&nodes)[3], V (&weights)[3]) {
  using ops = detail::lane_ops<V>;
  using T = typename ops::scalar;
  using std::sqrt;
  const T third = T(1) / T(3), sixth = T(1) / T(6), half = T(1) / T(2);
  const T sqrt3 = sqrt(T(3));
  const T curvature = T(5) / T(3) - sqrt3;  // t(ρ) ≈ √3 + ρ/3 + curvature ρ², t(1) = 2
  const V mu = (alpha[0] + alpha[1] + alpha[2]) * third;
  const V d0 = alpha[0] - mu, d1 = alpha[1] - mu, d2 = alpha[2] - mu;
  const V e1 = ops::sqrt(beta[1]), e2 = ops::sqrt(beta[2]);
  const V p = (d0 * d0 + d1 * d1 + d2 * d2 + T(2) * (beta[1] + beta[2])) * sixth;
  const V q = (d0 * (d1 * d2 - beta[2]) - beta[1] * d2) * half;
  const V root_p = ops::sqrt(p);
  const V r = q / (p * root_p);
  const V s = ops::sign(r);
  const V rho = ops::min(ops::abs(r), T(1));
  V t = sqrt3 + rho * (third + curvature * rho);
  for (int step = 0; step < detail::halley_steps(std::numeric_limits<T>::digits); ++step) {
    // Halley on f(t) = t³ − 3t − 2ρ
    const V t2 = t * t;
    const V f = t * (t2 - T(3)) - T(2) * rho;
    const V df = T(3) * (t2 - T(1));
    t = t - T(2) * f * df / (T(2) * df * df - T(6) * f * t);
  }
  const V lambda = s * root_p * t;  // the extreme eigenvalue of B
  // adj(B − λI), g_i = d_i − λ; v = column 0 + s·column 1 + column 2.
  const V g0 = d0 - lambda, g1 = d1 - lambda, g2 = d2 - lambda;
  const V a00 = g1 * g2 - beta[2], a11 = g0 * g2, a22 = g0 * g1 - beta[1];
  const V a01 = -e1 * g2, a02 = e1 * e2, a12 = -g0 * e2;
  const V v0 = a00 + s * a01 + a02, v1 = a01 + s * a11 + a12, v2 = a02 + s * a12 + a22;
  // q1 = (v1, −v0, 0)/ρ_v, q2 = v × q1/‖v‖ = (v0 v2, v1 v2, −ρ_v²)/(ρ_v ‖v‖), ρ_v² = v0² + v1²,
  // with one division: x = 1/(ρ_v² ‖v‖) gives 1/ρ_v = x ρ_v ‖v‖, 1/(ρ_v ‖v‖) = x ρ_v,
  // 1/‖v‖² = (x ρ_v²)².
  const V planar = v0 * v0 + v1 * v1;
  const V norm = ops::sqrt(planar + v2 * v2), root_planar = ops::sqrt(planar);
  const V x = T(1) / (planar * norm);
  const V i1 = x * root_planar * norm, i2 = x * root_planar, inverse_norm = x * planar;
  const V extreme_weight = beta[0] * (v0 * inverse_norm) * (v0 * inverse_norm);
  const V q10 = v1 * i1, q11 = -v0 * i1;
  const V q20 = v0 * v2 * i2, q21 = v1 * v2 * i2, q22 = -planar * i2;
  // K = [q1 q2]ᵀ B [q1 q2] (q12 = 0).
  const V b10 = d0 * q10 + e1 * q11, b11 = e1 * q10 + d1 * q11;
  const V b20 = d0 * q20 + e1 * q21, b21 = e1 * q20 + d1 * q21 + e2 * q22, b22 = e2 * q21 + d2 * q22;
  const V k11 = q10 * b10 + q11 * b11, k12 = q10 * b20 + q11 * b21, k22 = q20 * b20 + q21 * b21 + q22 * b22;
  // 2×2: eigenvalues c ∓ R. With h = (k22 − k11)/2 and g = |h| + R (no cancellation), the
  // eigenvector (g, −σ k12) belongs to c − σR and (σ k12, g) to c + σR, σ = sign(h); both
  // have squared norm g² + k12² = 2Rg.
  const V centre = (k11 + k22) * half, h = (k22 - k11) * half;
  const V radius = ops::sqrt(h * h + k12 * k12);
  const V sh = ops::sign(h);
  const V gap = ops::abs(h) + radius;
  const V first_x = gap * q10 - sh * k12 * q20;  // first component of the eigenvector for c − σR
  const V first_y = sh * k12 * q10 + gap * q20;  // … for c + σR
  const V scale = beta[0] / (T(2) * radius * gap);
  const V weight_x = scale * first_x * first_x, weight_y = scale * first_y * first_y;
  const V low_weight = ops::choose(sh, weight_x, weight_y), high_weight = ops::choose(sh, weight_y, weight_x);
  const V low = mu + (centre - radius), high = mu + (centre + radius), extreme = mu + lambda;
  // The extreme eigenvalue is the largest for s > 0, the smallest for s < 0.
  nodes[0] = ops::choose(s, low, extreme);
  nodes[1] = ops::choose(s, high, low);
  nodes[2] = ops::choose(s, extreme, high);
  weights[0] = ops::choose(s, low_weight, extreme_weight);
  weights[1] = ops::choose(s, high_weight, low_weight);
  weights[2] = ops::choose(s, extreme_weight, high_weight);
  return detail::three_node_spread_margin(p, alpha[0], beta[1]);
}

namespace detail {

// The three-node rule of a recurrence with r.size == 3 (β_1, β_2 > 0) into q; false where the
// spread margin is not > 0 (q then not to be used).
template <class T, int N>
FLUIDBED_HOST_DEVICE bool gauss_three_nodes_within_limit(const Recurrence<T, N>& r, Quadrature<T, N>& q) {
  static_assert(N >= 3);
  FLUIDBED_EXPECTS(r.size == 3);  // the callers' branch
  const T alpha[3] = {r.alpha[0], r.alpha[1], r.alpha[2]};
  const T beta[3] = {r.beta[0], r.beta[1], r.beta[2]};
  T x[3], w[3];
  const T margin = gauss_three_nodes(alpha, beta, x, w);
  q.size = 3;
  for (int i = 0; i < 3; ++i) {
    q.nodes[i] = x[i];
    q.weights[i] = w[i];
  }
  return margin > T(0);
}

}  // namespace detail

// The same for one cell: a recurrence with r.size == 3 (β_1, β_2 > 0), whatever the spread.
// invert() uses it only within detail::three_node_spread_limit, the QL beyond. An empty rule
// (size 0) for a recurrence of another size; a capacity N < 3, which holds no three-node rule,
// is refused at compile time.
template <class T, int N>
FLUIDBED_HOST_DEVICE Quadrature<T, N> gauss_three_nodes(const Recurrence<T, N>& r) {
  static_assert(N >= 3, "fluidbed::moments::gauss_three_nodes: a three-node rule needs a Recurrence<T, N> with N >= 3");
  Quadrature<T, N> q;
  if constexpr (N >= 3)  // (only the message above for a smaller N)
    if (r.size == 3) detail::gauss_three_nodes_within_limit(r, q);
  return q;
}

}  // namespace fluidbed::moments
