// fluidbed — DQMOM: the source terms of a transported quadrature, and the pieces of moment
// transport built on a quadrature (moment-specific velocities, growth and diffusion sources,
// initialisation from moments).
//
// DQMOM (Marchisio & Fox (2005), J. Aerosol Sci. 36, 43–73, doi:10.1016/j.jaerosci.2004.07.009;
// Mazzei (2008), PhD thesis, UCL (seed 000), §5.7 and App. D) transports the ν weights a_i and weighted nodes
// a_i ξ_i of a quadrature, with sources c_i^a and c_i^ξ chosen so that 2ν moments
// M_k = Σ a_i ξ_i^k evolve as the population balance says:
//   Σ_i (1 − k) ξ_i^k c_i^a + k ξ_i^(k−1) c_i^ξ = s_k,   k = 0 … 2ν − 1          (thesis eq. 5.63)
// The weights are either volume fractions φ_i (the thesis: the volume-density function of a
// diameter ξ) or number densities w_i (Marchisio & Fox). The matrix X of this system is the same
// for both; the growth part of the right-hand side is not (Weights below), and the two must never
// be mixed. The thesis prints the k = 3 row of the two-node matrix (eq. D.8) as −2ξ_i² where
// (1 − k)ξ^k gives −2ξ_i³; its solution (D.9–D.17) is right (tested). Niemi (2012, seed 001)
// prints the general matrix (eqs 71–72) with the k = 2 row of the c^ξ block as 2ξ_i² (it is
// 2ξ_i, k ξ^(k−1)) and the last row of the c^a block as −2(1 − ν)ξ^(2ν−1) (it is
// (1 − k)ξ^k = 2(1 − ν)ξ^(2ν−1) at k = 2ν − 1); both printed rows are tested not to hold.
//
// Structured solve. With α_i = c_i^a and β_i = c_i^ξ − ξ_i c_i^a the rows read L(x^k) = s_k for
// the functional L(p) = Σ_i α_i p(ξ_i) + β_i p'(ξ_i): (α, β) are the Hermite weights of L at the
// nodes, L applied to the Hermite basis of degree 2ν − 1,
//   h_i = [1 − 2 ℓ_i'(ξ_i)(x − ξ_i)] ℓ_i²,   ĥ_i = (x − ξ_i) ℓ_i²,   ℓ_i the Lagrange basis.
// Two ways in:
//  * moment sources s_k (any kernel of moments: aggregation, breakage, nucleation, given as
//    the numbers s_0 … s_{2ν−1}): α_i = L(ℓ_i²) − 2 ℓ_i'(ξ_i) β_i and β_i = L((x − ξ_i) ℓ_i²)
//    from the coefficients of ℓ_i² — the rows of X⁻¹, O(ν³) without pivoting, where a dense LU
//    takes (2/3)(2ν)³;
//  * sources as point functionals (PointSource: a weight times p, p' or p'' at a point): then
//    α_i = Σ w h_i^(d)(x), β_i = Σ w ĥ_i^(d)(x), with no monomial in sight. Growth (p and p' at
//    the nodes), diffusion (p'' at the nodes), nucleation (p at the nucleus size) and the birth
//    and death of aggregation between nodes (p at (ξ_i³ + ξ_j³)^(1/3) and at ξ_i) are of this
//    form; their sources come out to rounding whatever the conditioning of X (tested: pure growth
//    gives c^a = 3φG/ξ and c^ξ = 4φG to a few ulp for ν = 1 … 8).
// Both solve in units of L = the power of two at or below the largest node (exact scaling:
// s̃_k = s_k/L^k, c^ξ = L c̃^ξ), so that results do not depend on the length unit (SI or µm).
//
// Conditioning. det X = (−1)^(ν(ν−1)/2) Π_{i<j} (ξ_i − ξ_j)⁴ (tested): X is singular exactly where
// two nodes coincide, and for two nodes a relative gap δ apart the entries of X⁻¹ grow as δ⁻³.
// Sources gives κ_∞ = ‖X̃‖_∞ ‖X̃⁻¹‖_∞ of the scaled matrix actually solved: a moment-source
// solve loses about log10(κ) digits (the reference table of tests/reference/dqmom_reference.py
// measures it).
//
// Coincident nodes: nodes whose relative gap is below Options::merge_gap (default
// (1000 ε_machine)^(1/3): 6.1e-5 in double, where the δ⁻³ growth would amplify rounding about
// 1000-fold) are merged into one node at their weight-averaged position, the system of the ν'
// distinct nodes is solved with the first 2ν' rows (moments 0 … 2ν' − 1 exact; a rank-deficient
// X cannot honour more), and each merged node's sources are shared among its members in
// proportion to their weights, with one common growth rate (c^ξ − ξ c^a)/a: the members move
// together, and stay within the gap. The alternative the thesis quotes from Marchisio & Fox —
// perturbing the nodes inside X only — gives sources of order δ⁻³ that depend on the arbitrary
// perturbation and drive the nodes apart. For sources consistent with a quadrature of fewer
// nodes (growth, diffusion with equal gradients) the merged result is the limit of the unmerged
// one as the gap closes (tested). status says when a merge happened.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include "../core/config.hpp"
#include "inversion.hpp"

namespace fluidbed::moments::dqmom {

// What the weights are: volume fractions φ_i of a diameter-distributed phase (the thesis) or
// number densities w_i (Marchisio & Fox). Only growth sources differ (growth_moment_sources).
enum class Weights { volume_fraction, number_density };

enum class SourceStatus {
  ok,              // every node distinct: the full system solved
  merged_nodes,    // nodes closer than Options::merge_gap were merged (see the header comment)
  invalid_input,   // node count outside 1 … N, a node not finite and positive, a weight negative
};

// The sources of the weights (c_i^a) and of the weighted nodes (c_i^ξ).
template <class T, int N>
struct Sources {
  std::array<T, N> weight{};
  std::array<T, N> weighted_node{};
  int size = 0;             // ν, 0 on invalid input
  int distinct_nodes = 0;   // ν' after merging (= size when status is ok)
  T condition = T(0);       // κ_∞ of the scaled matrix solved (1 for one node)
  SourceStatus status = SourceStatus::invalid_input;
};

struct Options {
  // Relative gap |ξ_i − ξ_j| / max(ξ_i, ξ_j) below which two nodes are merged; negative: the
  // default (1000 ε_machine)^(1/3) of the type.
  double merge_gap = -1;
};

// A source written as a point functional: weight · p^(derivative)(point) for p(x) = x^k gives
// its contribution to s_k. derivative is 0, 1 or 2.
template <class T>
struct PointSource {
  T point;
  T weight;
  int derivative = 0;
};

namespace detail {

// ℓ(x), ℓ'(x), ℓ''(x) of a Lagrange basis polynomial Π_{j≠i}(x − x_j)/(x_i − x_j), by multiplying
// in one linear factor at a time (exact at the nodes, where logarithmic derivatives are not).
template <class T>
struct Jet {
  T value, first, second;
};

template <class T, int N>
FLUIDBED_HOST_DEVICE Jet<T> lagrange_jet(const std::array<T, N>& x, int n, int i, const T& at) {
  Jet<T> p{T(1), T(0), T(0)};
  for (int j = 0; j < n; ++j) {
    if (j == i) continue;
    const T inverse = T(1) / (x[i] - x[j]);
    const T factor = (at - x[j]) * inverse;
    p = {p.value * factor, p.first * factor + p.value * inverse, p.second * factor + T(2) * p.first * inverse};
  }
  return p;
}

// The power of two at or below x > 0, within a factor 2 (x's exponent: scaling by it costs no
// rounding). For
// float and double by masking the bits, which vectorises; frexp otherwise.
template <class T>
FLUIDBED_HOST_DEVICE T power_of_two_near(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) & 0x7ff0000000000000ull);
  } else if constexpr (std::is_same_v<T, float>) {
    return std::bit_cast<float>(std::bit_cast<std::uint32_t>(x) & 0x7f800000u);
  } else {
    int exponent = 0;
    (void)std::frexp(x, &exponent);  // x = f 2^exponent, f in [0.5, 1)
    return std::ldexp(T(1), exponent - 1);
  }
}

// The default merge gap (1000 ε)^(1/3), by Newton's iteration at compile time (a variable, so
// that no build evaluates it at run time).
template <class T>
constexpr T cube_root_of_1000_epsilon() {
  const double target = 1000 * double(std::numeric_limits<T>::epsilon());
  double root = 1e-3;
  for (int i = 0; i < 60; ++i) root -= (root * root * root - target) / (3 * root * root);
  return T(root);
}
template <class T>
inline constexpr T default_merge_gap = cube_root_of_1000_epsilon<T>();

template <class T>
FLUIDBED_HOST_DEVICE T merge_gap(const Options& options) {
  return options.merge_gap < 0 ? default_merge_gap<T> : T(options.merge_gap);
}

}  // namespace detail

namespace detail {

// A cell's nodes in units of L (the power of two at or below the largest), grouped into merged nodes.
template <class T, int N>
struct MergedNodes {
  int size = 0, distinct = 0;  // ν (0 on invalid input) and ν'
  T scale = T(1);
  std::array<T, N> node{}, weight{};   // scaled nodes, weights as given
  std::array<int, N> cluster{};        // node i belongs to merged node cluster[i]
  std::array<T, N> center{}, total{};  // merged nodes (scaled) and their total weights
  std::array<int, N> members{};

  FLUIDBED_HOST_DEVICE MergedNodes(std::span<const T> nodes, std::span<const T> weights, const Options& options) {
    const int n = int(nodes.size());
    if (n < 1 || n > N || int(weights.size()) != n) return;
    T largest(0);
    for (int i = 0; i < n; ++i) {
      if (!(nodes[i] > T(0)) || !(nodes[i] < std::numeric_limits<T>::infinity()) || !(weights[i] >= T(0)) ||
          !(weights[i] < std::numeric_limits<T>::infinity()))
        return;
      largest = nodes[i] > largest ? nodes[i] : largest;
    }
    size = n;
    scale = power_of_two_near(largest);
    for (int i = 0; i < n; ++i) node[i] = nodes[i] / scale, weight[i] = weights[i];
    merge(merge_gap<T>(options));
  }

  // Groups nodes whose sorted neighbours are within the relative gap; each group's centre is its
  // weight-averaged node (plain average when its weights are all zero).
  FLUIDBED_HOST_DEVICE void merge(const T& gap) {
    std::array<int, N> order{};
    for (int i = 0; i < size; ++i) order[i] = i;
    for (int i = 1; i < size; ++i)
      for (int j = i; j > 0 && node[order[j]] < node[order[j - 1]]; --j) {
        const int swap = order[j];
        order[j] = order[j - 1];
        order[j - 1] = swap;
      }
    std::array<T, N> sum{}, plain{};
    for (int r = 0; r < size; ++r) {
      const int i = order[r];
      if (r == 0 || node[i] - node[order[r - 1]] > gap * node[i]) ++distinct;
      const int c = distinct - 1;
      cluster[i] = c;
      total[c] += weight[i];
      sum[c] += weight[i] * node[i];
      plain[c] += node[i];
      ++members[c];
    }
    // A node alone keeps its exact value: (a x)/a may be an ulp off x, and the point functionals
    // at the nodes rely on the Lagrange basis vanishing exactly at the other nodes (an ulp off, the
    // large slopes of the basis of spread nodes turn it into errors of 1e-10 at 7 nodes).
    for (int c = 0; c < distinct; ++c)
      center[c] = members[c] == 1 ? plain[c] : total[c] > T(0) ? sum[c] / total[c] : plain[c] / T(members[c]);
  }

  FLUIDBED_HOST_DEVICE Sources<T, N> header(const T& condition) const {
    Sources<T, N> out;
    out.size = size;
    out.distinct_nodes = distinct;
    out.condition = condition;
    out.status = size == 0 ? SourceStatus::invalid_input
                 : distinct == size ? SourceStatus::ok
                                    : SourceStatus::merged_nodes;
    return out;
  }

  // From the merged nodes' (α, β) in scaled units to every node's (c^a, c^ξ) in the caller's:
  // c^a_i = share α_c, c^ξ_i = L (share β_c + x_i c^a_i), so that every member of a merged node
  // has the relative weight change α_c/a_c and the growth rate β_c/a_c.
  FLUIDBED_HOST_DEVICE void distribute(const std::array<T, N>& alpha, const std::array<T, N>& beta,
                                       Sources<T, N>& out) const {
    for (int i = 0; i < size; ++i) {
      const int c = cluster[i];
      const T share = members[c] == 1 ? T(1) : total[c] > T(0) ? weight[i] / total[c] : T(1) / T(members[c]);
      out.weight[i] = share * alpha[c];
      out.weighted_node[i] = (share * beta[c] + node[i] * out.weight[i]) * scale;
    }
  }
};

}  // namespace detail

// The DQMOM system of one cell's nodes (orders 0 … 2ν − 1): merges coincident nodes, scales, and
// holds X⁻¹ (in the scaled units) for any number of right-hand sides. `weights` (the
// quadrature's a_i, >= 0) are used only to place and share merged nodes. No allocation; host and
// device.
template <class T, int N>
class System {
 public:
  FLUIDBED_HOST_DEVICE System(std::span<const T> nodes, std::span<const T> weights, const Options& options = {})
      : nodes_(nodes, weights, options) {
    if (nodes_.size > 0) invert();
  }

  FLUIDBED_HOST_DEVICE int size() const { return nodes_.size; }
  FLUIDBED_HOST_DEVICE int distinct_nodes() const { return nodes_.distinct; }
  FLUIDBED_HOST_DEVICE T condition() const { return condition_; }

  // Sources for moment sources s_0 … s_{2ν−1} (orders 0 … 2ν − 1).
  FLUIDBED_HOST_DEVICE Sources<T, N> solve(std::span<const T> s) const {
    const int n = nodes_.distinct;
    if (nodes_.size == 0 || int(s.size()) != 2 * nodes_.size) return Sources<T, N>{};
    Sources<T, N> out = nodes_.header(condition_);
    std::array<T, 2 * N> scaled{};
    T unit(1);
    for (int k = 0; k < 2 * n; ++k, unit *= nodes_.scale) scaled[k] = s[k] / unit;
    std::array<T, N> alpha{}, beta{};
    for (int c = 0; c < n; ++c)
      for (int k = 0; k < 2 * n; ++k) {
        alpha[c] += alpha_row_[c][k] * scaled[k];
        beta[c] += beta_row_[c][k] * scaled[k];
      }
    nodes_.distribute(alpha, beta, out);
    return out;
  }

  // Sources for a sum of point functionals.
  FLUIDBED_HOST_DEVICE Sources<T, N> solve(std::span<const PointSource<T>> terms) const {
    if (nodes_.size == 0) return Sources<T, N>{};
    Sources<T, N> out = nodes_.header(condition_);
    const auto& x = nodes_.center;
    std::array<T, N> alpha{}, beta{};
    for (const auto& term : terms) {
      if (term.derivative < 0 || term.derivative > 2) return Sources<T, N>{};
      const T at = term.point / nodes_.scale;
      // s̃_k = s_k / L^k makes w p^(d)(x) into (w / L^d) p^(d)(x / L).
      T weight = term.weight;
      for (int d = 0; d < term.derivative; ++d) weight /= nodes_.scale;
      for (int c = 0; c < nodes_.distinct; ++c) {
        // h_c = (1 − 2 ℓ_c'(x_c)(x − x_c)) ℓ_c², ĥ_c = (x − x_c) ℓ_c² and their derivatives.
        const auto l = detail::lagrange_jet<T, N>(x, nodes_.distinct, c, at);
        const T offset = at - x[c];
        const T factor = T(1) - T(2) * slope_[c] * offset;
        const T square = l.value * l.value, square_first = T(2) * l.value * l.first,
                square_second = T(2) * (l.first * l.first + l.value * l.second);
        T h, hhat;
        if (term.derivative == 0) {
          h = factor * square;
          hhat = offset * square;
        } else if (term.derivative == 1) {
          h = -T(2) * slope_[c] * square + factor * square_first;
          hhat = square + offset * square_first;
        } else {
          h = -T(4) * slope_[c] * square_first + factor * square_second;
          hhat = T(2) * square_first + offset * square_second;
        }
        alpha[c] += weight * h;
        beta[c] += weight * hhat;
      }
    }
    nodes_.distribute(alpha, beta, out);
    return out;
  }

 private:
  detail::MergedNodes<T, N> nodes_;
  T condition_ = T(0);
  std::array<T, N> slope_{};                                      // ℓ_c'(x_c)
  std::array<std::array<T, 2 * N>, N> alpha_row_{}, beta_row_{};  // rows of X̃⁻¹ for α and β

  // Rows of X̃⁻¹ from the coefficients q of ℓ_c²: β_c = Σ_k (q_{k−1} − x_c q_k) s̃_k and
  // α_c = Σ_k q_k s̃_k − 2 ℓ_c'(x_c) β_c; then κ_∞ (rows of c̃^ξ = β + x α).
  FLUIDBED_HOST_DEVICE void invert() {
    const int n = nodes_.distinct;
    const auto& x = nodes_.center;
    T inverse_norm(0);
    for (int c = 0; c < n; ++c) {
      // One coefficient more than ℓ_c needs (degree n − 1 <= N − 1): GCC 12 at -O2 cannot see that
      // the loop below never runs for N = 1 and reports its index 1 as out of bounds.
      std::array<T, N + 1> lagrange{};
      lagrange[0] = T(1);
      T slope(0);
      int degree = 0;
      for (int j = 0; j < n; ++j) {
        if (j == c) continue;
        const T inverse = T(1) / (x[c] - x[j]);
        slope += inverse;
        for (int m = degree + 1; m > 0; --m) lagrange[m] = (lagrange[m - 1] - x[j] * lagrange[m]) * inverse;
        lagrange[0] = -x[j] * lagrange[0] * inverse;
        ++degree;
      }
      std::array<T, 2 * N> square{};
      for (int p = 0; p <= degree; ++p)
        for (int q = 0; q <= degree; ++q) square[p + q] += lagrange[p] * lagrange[q];
      slope_[c] = slope;
      T alpha_norm(0), node_norm(0);
      for (int k = 0; k < 2 * n; ++k) {
        const T beta = (k > 0 ? square[k - 1] : T(0)) - x[c] * square[k];
        beta_row_[c][k] = beta;
        alpha_row_[c][k] = square[k] - T(2) * slope * beta;
        alpha_norm += std::abs(alpha_row_[c][k]);
        node_norm += std::abs(beta + x[c] * alpha_row_[c][k]);
      }
      inverse_norm = alpha_norm > inverse_norm ? alpha_norm : inverse_norm;
      inverse_norm = node_norm > inverse_norm ? node_norm : inverse_norm;
    }
    T matrix_norm(0);
    for (int k = 0; k < 2 * n; ++k) {
      T row(0);
      for (int c = 0; c < n; ++c) {
        T power(1);  // x_c^(k−1)
        for (int m = 1; m < k; ++m) power *= x[c];
        row += std::abs(T(1 - k) * power * (k > 0 ? x[c] : T(1))) + T(k) * power;
      }
      matrix_norm = row > matrix_norm ? row : matrix_norm;
    }
    condition_ = matrix_norm * inverse_norm;
  }
};

// One-call forms: the system of `nodes` (and `weights`, which only place and share merged
// nodes; without them merged nodes share equally) solved for moment sources s_0 … s_{2ν−1}.
template <class T, int N>
FLUIDBED_HOST_DEVICE Sources<T, N> solve(std::span<const T> nodes, std::span<const T> weights, std::span<const T> s,
                                         const Options& options = {}) {
  return System<T, N>(nodes, weights, options).solve(s);
}
template <class T, int N>
FLUIDBED_HOST_DEVICE Sources<T, N> solve(std::span<const T> nodes, std::span<const T> s, const Options& options = {}) {
  std::array<T, N> equal{};
  for (auto& w : equal) w = T(1);
  const std::size_t n = nodes.size() <= std::size_t(N) ? nodes.size() : 0;
  return System<T, N>(nodes, std::span<const T>(equal.data(), n), options).solve(s);
}

// Number-density sources (c^w, c^ξ of w_i and w_i ξ_i) as the sources of the volume fraction
// φ_i = k_v ξ_i³ w_i and of φ_i ξ_i, for a diameter ξ (k_v = π/6 for spheres):
//   c^φ = k_v (3 ξ² c^ξ − 2 ξ³ c^w),   c^{φξ} = k_v (4 ξ³ c^ξ − 3 ξ⁴ c^w)
// (Niemi (2012), MSc thesis, Aalto University (seed 001), eqs 77–78, which print the last terms
// with the volume fraction α_q where the weight's source a_q belongs: from φ = k_v (wξ)³/w² by the
// chain rule; tested through the growth identities of the two forms).
template <class T, int N>
FLUIDBED_HOST_DEVICE Sources<T, N> volume_sources_from_number(const Sources<T, N>& number, std::span<const T> nodes,
                                                              const T& shape_factor) {
  Sources<T, N> out = number;
  for (int i = 0; i < number.size && i < int(nodes.size()); ++i) {
    const T x = nodes[i], x2 = x * x, x3 = x2 * x;
    out.weight[i] = shape_factor * (T(3) * x2 * number.weighted_node[i] - T(2) * x3 * number.weight[i]);
    out.weighted_node[i] = shape_factor * (T(4) * x3 * number.weighted_node[i] - T(3) * x3 * x * number.weight[i]);
  }
  return out;
}

// Sources for any 2ν moment orders, integer or fractional (the thesis §5.7 and Marchisio & Fox
// allow any 2ν independent real orders; 0 and 1 carry the weights and weighted nodes):
//   Σ_i (1 − p) ξ_i^p c_i^a + p ξ_i^(p−1) c_i^ξ = s_p   for p = orders[j], s_p = s[j].
// orders must be 2ν distinct finite reals with orders[0] = 0 and orders[1] = 1 (invalid_input
// otherwise); merged nodes keep the first 2ν' orders, so list the others by priority. Without the
// polynomial structure there is no Hermite shortcut: the scaled matrix (units of L as above,
// s̃_p = s_p / L^p) is solved by Gaussian elimination with partial pivoting (2ν <= 2N; written out
// rather than Eigen's PartialPivLU, whose blocked kernels draw GCC 12's false -Wmaybe-uninitialized
// and -Warray-bounds at -march=native into a host's -Werror build), and κ_∞ comes from X̃⁻¹
// column by column.
template <class T, int N>
FLUIDBED_HOST_DEVICE Sources<T, N> solve_orders(std::span<const T> nodes, std::span<const T> weights,
                                                std::span<const T> orders, std::span<const T> s,
                                                const Options& options = {}) {
  const detail::MergedNodes<T, N> merged(nodes, weights, options);
  const int n = merged.size;
  if (n == 0 || int(orders.size()) != 2 * n || int(s.size()) != 2 * n || orders[0] != T(0) || orders[1] != T(1))
    return Sources<T, N>{};
  for (int j = 0; j < 2 * n; ++j) {
    if (!(std::abs(orders[j]) < std::numeric_limits<T>::infinity())) return Sources<T, N>{};
    for (int k = 0; k < j; ++k)
      if (orders[j] == orders[k]) return Sources<T, N>{};
  }
  const int m = merged.distinct, size = 2 * m;
  std::array<std::array<T, 2 * N>, 2 * N> lu{};
  std::array<T, 2 * N> rhs{}, matrix_rows{};
  for (int j = 0; j < size; ++j) {
    const T p = orders[j];
    rhs[j] = s[j] / std::pow(merged.scale, p);
    for (int c = 0; c < m; ++c) {
      lu[j][c] = (T(1) - p) * std::pow(merged.center[c], p);
      lu[j][m + c] = p == T(0) ? T(0) : p * std::pow(merged.center[c], p - T(1));
      matrix_rows[j] += std::abs(lu[j][c]) + std::abs(lu[j][m + c]);
    }
  }
  // LU with row pivoting, then forward and back substitution for any right-hand side.
  std::array<int, 2 * N> pivot{};
  for (int k = 0; k < size; ++k) {
    int best = k;
    for (int r = k + 1; r < size; ++r)
      if (std::abs(lu[r][k]) > std::abs(lu[best][k])) best = r;
    pivot[k] = best;
    if (best != k)
      for (int c = 0; c < size; ++c) {
        const T swap = lu[k][c];
        lu[k][c] = lu[best][c];
        lu[best][c] = swap;
      }
    for (int r = k + 1; r < size; ++r) {
      lu[r][k] /= lu[k][k];
      for (int c = k + 1; c < size; ++c) lu[r][c] -= lu[r][k] * lu[k][c];
    }
  }
  auto substitute = [&](std::array<T, 2 * N> b) {
    for (int k = 0; k < size; ++k) {
      const T swap = b[k];
      b[k] = b[pivot[k]];
      b[pivot[k]] = swap;
    }
    for (int r = 0; r < size; ++r)
      for (int c = 0; c < r; ++c) b[r] -= lu[r][c] * b[c];
    for (int r = size - 1; r >= 0; --r) {
      for (int c = r + 1; c < size; ++c) b[r] -= lu[r][c] * b[c];
      b[r] /= lu[r][r];
    }
    return b;
  };
  const std::array<T, 2 * N> c = substitute(rhs);
  std::array<T, 2 * N> inverse_rows{};
  for (int j = 0; j < size; ++j) {
    std::array<T, 2 * N> unit{};
    unit[j] = T(1);
    const std::array<T, 2 * N> column = substitute(unit);
    for (int r = 0; r < size; ++r) inverse_rows[r] += std::abs(column[r]);
  }
  T matrix_norm(0), inverse_norm(0);
  for (int r = 0; r < size; ++r) {
    matrix_norm = matrix_rows[r] > matrix_norm ? matrix_rows[r] : matrix_norm;
    inverse_norm = inverse_rows[r] > inverse_norm ? inverse_rows[r] : inverse_norm;
  }
  Sources<T, N> out = merged.header(matrix_norm * inverse_norm);
  std::array<T, N> alpha{}, beta{};
  for (int k = 0; k < m; ++k) {
    alpha[k] = c[k];
    beta[k] = c[m + k] - merged.center[k] * c[k];
  }
  merged.distribute(alpha, beta, out);
  return out;
}

// ---- Right-hand sides --------------------------------------------------------------------------

// Growth at rates ξ̇_i = growth_rate[i] [m/s] as point functionals: the thesis's
// (3 + k) Σ φ_i ξ_i^(k−1) ξ̇_i for volume fractions of diameters (eq. 5.63; 3φξ̇/ξ · p(ξ) +
// φξ̇ · p'(ξ)), or Marchisio & Fox's k Σ w_i ξ_i^(k−1) ξ̇_i for number densities (w ξ̇ · p'(ξ)).
// Solved, they give c^a = 3φξ̇/ξ, c^ξ = 4φξ̇ (volume) and c^a = 0, c^ξ = w ξ̇ (number) for any ν.
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<PointSource<T>, 2 * N> growth_terms(Weights form, std::span<const T> weights,
                                                                  std::span<const T> nodes,
                                                                  std::span<const T> growth_rate) {
  std::array<PointSource<T>, 2 * N> terms{};
  for (std::size_t i = 0; i < nodes.size() && i < std::size_t(N); ++i) {
    const T rate = weights[i] * growth_rate[i];
    terms[2 * i] = {nodes[i], form == Weights::volume_fraction ? T(3) * rate / nodes[i] : T(0), 0};
    terms[2 * i + 1] = {nodes[i], rate, 1};
  }
  return terms;
}

// The growth source of moment orders `orders` (any real orders: QMOM's S_k, thesis eq. 5.101):
// (3 + k) Σ φ_i ξ_i^(k−1) ξ̇_i (volume fractions) or k Σ w_i ξ_i^(k−1) ξ̇_i (number densities).
template <class T, std::size_t L>
FLUIDBED_HOST_DEVICE std::array<T, L> growth_moment_sources(Weights form, std::span<const T> weights,
                                                            std::span<const T> nodes, std::span<const T> growth_rate,
                                                            const std::array<T, L>& orders) {
  std::array<T, L> s{};
  for (std::size_t k = 0; k < L; ++k) {
    const T factor = form == Weights::volume_fraction ? T(3) + orders[k] : orders[k];
    for (std::size_t i = 0; i < nodes.size(); ++i)
      s[k] += factor * weights[i] * std::pow(nodes[i], orders[k] - T(1)) * growth_rate[i];
  }
  return s;
}

// Diffusion-induced sources (thesis §6.5.4, eqs 6.18–6.23): a Fickian flux −∇·(𝒟∇f) in the
// population balance gives 𝒮_k = k(k − 1) Σ_i ξ_i^(k−2) 𝒞_i, 𝒞_i = 𝒟 φ_i |∇ξ_i|²
// (diffusion_intensity) — the point functionals 𝒞_i p''(ξ_i). At ν = 2 the solution is the
// thesis's eq. 6.22 (tested). They vanish iff every ∇ξ_i = 0.
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<PointSource<T>, N> diffusion_terms(std::span<const T> nodes,
                                                                 std::span<const T> intensity) {
  std::array<PointSource<T>, N> terms{};
  for (std::size_t i = 0; i < nodes.size() && i < std::size_t(N); ++i) terms[i] = {nodes[i], intensity[i], 2};
  return terms;
}

// The same sources as moments s_0 … s_{2ν−1}.
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<T, 2 * N> diffusion_sources(std::span<const T> nodes, std::span<const T> intensity) {
  std::array<T, 2 * N> s{};
  const int n = int(nodes.size());
  for (int k = 2; k < 2 * n; ++k)
    for (int i = 0; i < n; ++i) s[k] += T(k * (k - 1)) * std::pow(nodes[i], T(k - 2)) * intensity[i];
  return s;
}

// 𝒞_i = 𝒟 φ_i |∇ξ_i|² [m² s⁻¹ · m² m⁻²] (thesis eq. 6.23), from the squared gradient of the node.
template <class T>
FLUIDBED_HOST_DEVICE constexpr T diffusion_intensity(const T& diffusivity, const T& weight,
                                                     const T& node_gradient_squared) {
  return diffusivity * weight * node_gradient_squared;
}

// The particles' self-diffusivity 𝒟 of kinetic theory (thesis eq. 6.24), the physical diffusivity
// these sources are usually given, is fluidbed::kinetic_theory::self_diffusivity
// (kinetic_theory/class_transport.hpp; a higher layer than moments/, so not included here).

// The numerical diffusivity of first-order upwinding, 𝒟_n = u Δx / 2 [m²/s] (thesis eq. 6.25, after
// Ferziger & Perić (2002), Computational Methods for Fluid Dynamics, Springer): the leading
// truncation error of the upwind flux at speed u [m/s] on cells of size Δx [m].
template <class T>
FLUIDBED_HOST_DEVICE constexpr T upwind_numerical_diffusivity(const T& speed, const T& cell_size) {
  return (speed < T(0) ? -speed : speed) * cell_size / T(2);
}

// ---- Moment transport on a quadrature ----------------------------------------------------------

// The coefficients p_kr = a_r ξ_r^k / Σ_s a_s ξ_s^k of the moment-specific velocity
// v̂_k = Σ_r p_kr v_r of moment order k (Mazzei, Marchisio & Lettieri (2012) AIChE J. 58,
// 3054–3069, doi:10.1002/aic.13714 (seed 003), eqs 0.8–0.10; thesis eqs 5.97–5.99): Σ_r p_kr = 1, so that the host
// forms v̂_k from the class velocities of any vector type. For a moment with no mass
// (Σ a_r ξ_r^k = 0) they are the weight fractions a_r/Σa_s, and all zero without any weight.
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<T, N> moment_velocity_coefficients(std::span<const T> weights,
                                                                   std::span<const T> nodes, const T& order) {
  std::array<T, N> p{};
  T moment(0), total(0);
  const std::size_t n = nodes.size() <= std::size_t(N) ? nodes.size() : 0;
  for (std::size_t r = 0; r < n; ++r) {
    p[r] = weights[r] * std::pow(nodes[r], order);
    moment += p[r];
    total += weights[r];
  }
  for (std::size_t r = 0; r < n; ++r)
    p[r] = moment > T(0) ? p[r] / moment : total > T(0) ? weights[r] / total : T(0);
  return p;
}

// v̂_k for one velocity component (velocities[r] the class velocity of node r).
template <class T, int N>
FLUIDBED_HOST_DEVICE T moment_velocity(std::span<const T> weights, std::span<const T> nodes,
                                       std::span<const T> velocities, const T& order) {
  const auto p = moment_velocity_coefficients<T, N>(weights, nodes, order);
  T v(0);
  for (std::size_t r = 0; r < velocities.size() && r < std::size_t(N); ++r) v += p[r] * velocities[r];
  return v;
}

// The advective flux of moment k through a face with unit normal velocity components
// normal_velocity[r] = v_r · n, node by node upwind: Σ_r a_r ξ_r^k (v_r·n) taken from the
// `upstream` side of each node (upwind_side[r] = the quadrature whose node r flows in). Node-wise
// upwinding keeps a moment set realizable for Courant numbers <= 1, which per-moment upwinding
// with v̂_k does not (Desjardins, Fox & Villedieu (2008) J. Comput. Phys. 227, 2514–2539,
// doi:10.1016/j.jcp.2007.10.026).
template <class T>
FLUIDBED_HOST_DEVICE T upwind_moment_flux(std::span<const T> left_weights, std::span<const T> left_nodes,
                                          std::span<const T> right_weights, std::span<const T> right_nodes,
                                          std::span<const T> normal_velocity, const T& order) {
  T flux(0);
  for (std::size_t r = 0; r < normal_velocity.size(); ++r) {
    const T u = normal_velocity[r];
    flux += u >= T(0) ? left_weights[r] * std::pow(left_nodes[r], order) * u
                      : right_weights[r] * std::pow(right_nodes[r], order) * u;
  }
  return flux;
}

// ---- The transported state ---------------------------------------------------------------------

// A cell's DQMOM state: the weights a_i and weighted nodes a_i ξ_i that are transported.
template <class T, int N>
struct State {
  std::array<T, N> weight{};
  std::array<T, N> weighted_node{};
  int size = 0;
};

// The state of the quadrature of moments M_0 … M_{2ν−1} (initialisation, thesis eqs D.6, D.20–D.21):
// the library's inversion (inversion.hpp), whose status says whether the moments gave ν nodes.
template <class T, int N>
FLUIDBED_HOST_DEVICE State<T, N> state_from_moments(std::span<const T> moments, InversionStatus* status = nullptr,
                                                    const InversionOptions& options = {}) {
  const auto rule = invert<T, N>(moments, options);
  if (status != nullptr) *status = rule.status;
  State<T, N> state;
  state.size = rule.quadrature.size;
  for (int i = 0; i < state.size; ++i) {
    state.weight[i] = rule.quadrature.weights[i];
    state.weighted_node[i] = rule.quadrature.weights[i] * rule.quadrature.nodes[i];
  }
  return state;
}

// The node ξ_i = (a_i ξ_i)/a_i of a transported state. A weight that has vanished leaves its node
// undefined (0/0, and transported rounding makes the ratio arbitrary when a_i is tiny): below
// `vanishing` times the cell's total weight the node keeps `fallback` (the previous step's node
// or the initial one, which is what the thesis's initial conditions with zero weights and set
// nodes assume). A negative ratio is also replaced.
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<T, N> nodes_of(const State<T, N>& state, const std::array<T, N>& fallback,
                                               const T& vanishing = T(1e-12)) {
  T total(0);
  for (int i = 0; i < state.size; ++i) total += state.weight[i] > T(0) ? state.weight[i] : T(0);
  std::array<T, N> nodes = fallback;
  for (int i = 0; i < state.size; ++i) {
    if (!(state.weight[i] > vanishing * total)) continue;
    const T node = state.weighted_node[i] / state.weight[i];
    if (node > T(0)) nodes[i] = node;
  }
  return nodes;
}

}  // namespace fluidbed::moments::dqmom
