// fluidbed — the DQMOM source solve (dqmom.hpp) over structure-of-arrays fields, with SIMD lanes
// across cells.
//
// Every cell has the same node count N (DQMOM transports a fixed number of nodes). Cells are taken
// in blocks of `lanes`; within a block every step of the Hermite solve (Lagrange coefficients,
// their squares, the two sums per node; dqmom.hpp's header) is an operation on Eigen arrays of the
// lanes, SIMD at the default flags, and no X⁻¹ is stored. The results are the per-cell System's to rounding
// (the same operations, in a different order where the per-cell path forms X⁻¹ first; tested
// within 8 ε κ). Cells whose nodes are closer than the merge gap, or invalid, are handed to the
// per-cell System (its merge rule and statuses). No allocation; host only (a device code calls
// the per-cell System, one thread per cell); needs Eigen 3.4 (its Array is the lane type).
#pragma once

#include "eigen_core.hpp"  // first: Eigen's Core without its own warnings

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

#include "dqmom.hpp"

FLUIDBED_EIGEN_CODE_BEGIN

namespace fluidbed::moments::dqmom {

// Fields of `cells` cells (the size of `status`): node i of cell c at nodes[i][c], and so on.
template <class T, int N>
struct SourceBatch {
  std::array<std::span<const T>, N> nodes{};
  std::array<std::span<const T>, N> weights{};             // used only for merged nodes
  std::array<std::span<const T>, 2 * N> moment_sources{};  // s_k, k = 0 … 2N − 1
  std::array<std::span<T>, N> weight_sources{};            // c^a
  std::array<std::span<T>, N> weighted_node_sources{};     // c^ξ
  std::span<SourceStatus> status;
  std::span<T> condition;  // κ_∞ per cell, or empty: not computed (saves about a third)
};

namespace detail {

// Per node c of one block of W cells (x in scaled units): the slope ℓ_c'(x_c) and the coefficients
// of ℓ_c². Every quantity is a lane array of W cells (Eigen::Array: SIMD at the default flags,
// which plain loops over lanes are not: GCC leaves them scalar).
template <class T, int N, int W>
struct LagrangeSquares {
  using Lane = Eigen::Array<T, W, 1>;
  std::array<std::array<Lane, N>, N> gap_inverse;  // 1/(x_c − x_j)

  explicit LagrangeSquares(const std::array<Lane, N>& x) {
    for (int c = 0; c < N; ++c)
      for (int j = c + 1; j < N; ++j) {  // one division per pair, the other sign for (j, c)
        gap_inverse[c][j] = (x[c] - x[j]).inverse();
        gap_inverse[j][c] = -gap_inverse[c][j];
      }
  }

  void of(const std::array<Lane, N>& x, int c, Lane& slope, std::array<Lane, 2 * N>& square) const {
    std::array<Lane, N> lagrange;
    lagrange[0] = Lane::Ones();
    slope = Lane::Zero();
    int degree = 0;
    for (int j = 0; j < N; ++j) {
      if (j == c) continue;
      const Lane& inverse = gap_inverse[c][j];
      slope += inverse;
      lagrange[degree + 1] = lagrange[degree] * inverse;
      for (int m = degree; m > 0; --m) lagrange[m] = (lagrange[m - 1] - x[j] * lagrange[m]) * inverse;
      lagrange[0] = -x[j] * lagrange[0] * inverse;
      ++degree;
    }
    for (auto& q : square) q.setZero();
    for (int p = 0; p < N; ++p)
      for (int q = 0; q < N; ++q) square[p + q] += lagrange[p] * lagrange[q];
  }
};

// The Hermite solve of one block: β_c = Σ_k (q_{k−1} − x_c q_k) s̃_k, α_c = Σ_k q_k s̃_k − 2 ℓ_c'(x_c) β_c
// (LagrangeSquares's steps written out: through its member function the compiler stops inlining
// Eigen's lane operations, which then cost 40 % more).
template <class T, int N, int W>
void hermite_block(const std::array<Eigen::Array<T, W, 1>, N>& x, const std::array<Eigen::Array<T, W, 1>, 2 * N>& s,
                   std::array<Eigen::Array<T, W, 1>, N>& alpha, std::array<Eigen::Array<T, W, 1>, N>& beta) {
  using Lane = Eigen::Array<T, W, 1>;
  std::array<std::array<Lane, N>, N> gap_inverse;
  for (int c = 0; c < N; ++c)
    for (int j = c + 1; j < N; ++j) {
      gap_inverse[c][j] = (x[c] - x[j]).inverse();
      gap_inverse[j][c] = -gap_inverse[c][j];
    }
  for (int c = 0; c < N; ++c) {
    std::array<Lane, N> lagrange;
    lagrange[0] = Lane::Ones();
    Lane slope = Lane::Zero();
    int degree = 0;
    for (int j = 0; j < N; ++j) {
      if (j == c) continue;
      const Lane& inverse = gap_inverse[c][j];
      slope += inverse;
      lagrange[degree + 1] = lagrange[degree] * inverse;
      for (int m = degree; m > 0; --m) lagrange[m] = (lagrange[m - 1] - x[j] * lagrange[m]) * inverse;
      lagrange[0] = -x[j] * lagrange[0] * inverse;
      ++degree;
    }
    std::array<Lane, 2 * N> square;
    for (auto& q : square) q.setZero();
    for (int p = 0; p < N; ++p)
      for (int q = 0; q < N; ++q) square[p + q] += lagrange[p] * lagrange[q];
    Lane of_square = square[0] * s[0], b = -x[c] * square[0] * s[0];
    for (int k = 1; k < 2 * N; ++k) {
      b += (square[k - 1] - x[c] * square[k]) * s[k];
      of_square += square[k] * s[k];
    }
    beta[c] = b;
    alpha[c] = of_square - T(2) * slope * b;
  }
}

// κ_∞ = ‖X̃‖_∞‖X̃⁻¹‖_∞ of one block, a pass of its own (one function doing both outgrows the
// compiler's inlining of Eigen's lane operations, which then cost four times as much).
template <class T, int N, int W>
Eigen::Array<T, W, 1> condition_block(const std::array<Eigen::Array<T, W, 1>, N>& x) {
  using Lane = Eigen::Array<T, W, 1>;
  const LagrangeSquares<T, N, W> squares(x);
  Lane inverse_norm = Lane::Zero();
  for (int c = 0; c < N; ++c) {
    Lane slope;
    std::array<Lane, 2 * N> square;
    squares.of(x, c, slope, square);
    Lane alpha_norm = Lane::Zero(), node_norm = Lane::Zero();
    for (int k = 0; k < 2 * N; ++k) {  // rows of X̃⁻¹ for α_c and for c̃^ξ_c = β_c + x_c α_c
      const Lane beta_row = (k > 0 ? square[k - 1] : Lane::Zero()) - x[c] * square[k];
      const Lane alpha_row = square[k] - T(2) * slope * beta_row;
      alpha_norm += alpha_row.abs();
      node_norm += (beta_row + x[c] * alpha_row).abs();
    }
    inverse_norm = inverse_norm.max(alpha_norm).max(node_norm);
  }
  // Row k of X̃ sums |1 − k| x^k + k x^(k−1) over the nodes (x > 0).
  std::array<Lane, 2 * N> row;
  for (auto& r : row) r.setZero();
  for (int c = 0; c < N; ++c) {
    Lane below = Lane::Ones();  // x^(k−1), from k = 1
    row[0] += Lane::Ones();
    for (int k = 1; k < 2 * N; ++k) {
      const Lane power = below * x[c];
      row[k] += T(k > 1 ? k - 1 : 1 - k) * power + T(k) * below;
      below = power;
    }
  }
  Lane matrix_norm = row[0];
  for (int k = 1; k < 2 * N; ++k) matrix_norm = matrix_norm.max(row[k]);
  return matrix_norm * inverse_norm;
}

// One cell through the per-cell System (merged nodes, invalid input).
template <class T, int N>
void solve_one(const SourceBatch<T, N>& batch, std::size_t cell, const Options& options) {
  std::array<T, N> nodes{}, weights{};
  std::array<T, 2 * N> s{};
  for (int i = 0; i < N; ++i) nodes[i] = batch.nodes[i][cell], weights[i] = batch.weights[i][cell];
  for (int k = 0; k < 2 * N; ++k) s[k] = batch.moment_sources[k][cell];
  const System<T, N> system{std::span<const T>(nodes), std::span<const T>(weights), options};
  const Sources<T, N> out = system.solve(std::span<const T>(s));
  for (int i = 0; i < N; ++i) {
    batch.weight_sources[i][cell] = out.weight[i];
    batch.weighted_node_sources[i][cell] = out.weighted_node[i];
  }
  batch.status[cell] = out.status;
  if (!batch.condition.empty()) batch.condition[cell] = out.condition;
}

template <class T, int N, int W, bool with_condition>
void solve_blocks(const SourceBatch<T, N>& batch, const Options& options) {
  using Lane = Eigen::Array<T, W, 1>;
  const std::size_t cells = batch.status.size();
  const T gap = merge_gap<T>(options);
  for (std::size_t first = 0; first < cells; first += W) {
    const int lanes = int(std::min<std::size_t>(W, cells - first));
    // Gather (padding lanes: distinct nodes 1 … N, weights 1), check and scale, cell by cell.
    std::array<Lane, N> x;
    std::array<Lane, 2 * N> s;
    std::array<bool, W> valid{};
    std::array<T, W> scale{};
    for (int l = 0; l < W; ++l) {
      std::array<T, N> node{};
      bool ok = l < lanes;
      T largest(0);
      for (int i = 0; i < N; ++i) {
        node[i] = ok ? batch.nodes[i][first + std::size_t(l)] : T(0);
        const T wi = ok ? batch.weights[i][first + std::size_t(l)] : T(0);
        ok = ok && node[i] > T(0) && node[i] < std::numeric_limits<T>::infinity() && wi >= T(0) &&
             wi < std::numeric_limits<T>::infinity();
        largest = std::max(largest, node[i]);
      }
      for (int i = 0; i < N && ok; ++i)
        for (int j = 0; j < i; ++j) ok = ok && std::abs(node[i] - node[j]) > gap * std::max(node[i], node[j]);
      valid[l] = ok;
      // Powers of two: multiplying by the inverse is exact.
      scale[l] = ok ? power_of_two_near(largest) : T(1);
      const T inverse_scale = T(1) / scale[l];
      for (int i = 0; i < N; ++i) x[i](l) = ok ? node[i] * inverse_scale : T(i + 1) / T(N);
      T unit(1);
      for (int k = 0; k < 2 * N; ++k, unit *= inverse_scale)
        s[k](l) = ok ? batch.moment_sources[k][first + std::size_t(l)] * unit : T(0);
    }
    std::array<Lane, N> alpha, beta;
    hermite_block<T, N, W>(x, s, alpha, beta);
    Lane condition = Lane::Zero();
    if constexpr (with_condition) condition = condition_block<T, N, W>(x);
    for (int l = 0; l < lanes; ++l) {
      const std::size_t cell = first + std::size_t(l);
      if (!valid[l]) {
        solve_one(batch, cell, options);
        continue;
      }
      for (int i = 0; i < N; ++i) {
        batch.weight_sources[i][cell] = alpha[i](l);
        batch.weighted_node_sources[i][cell] = (beta[i](l) + x[i](l) * alpha[i](l)) * scale[l];
      }
      batch.status[cell] = SourceStatus::ok;
      if constexpr (with_condition) batch.condition[cell] = condition(l);
    }
  }
}

}  // namespace detail

// Solves every cell of the batch (see the header comment). Every span must hold status.size()
// cells (condition: that many, or none).
template <class T, int N>
void solve_batched(const SourceBatch<T, N>& batch, const Options& options = {}) {
  // 256 bits: Eigen's lane operations stay inlined (at 512 GCC outlines them, 1.5-2x slower).
  constexpr int lanes = 32 / int(sizeof(T)) > 2 ? 32 / int(sizeof(T)) : 2;
  if (batch.condition.empty())
    detail::solve_blocks<T, N, lanes, false>(batch, options);
  else
    detail::solve_blocks<T, N, lanes, true>(batch, options);
}

}  // namespace fluidbed::moments::dqmom

FLUIDBED_EIGEN_CODE_END
