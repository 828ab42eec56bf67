// fluidbed — the DQMOM source solve (dqmom.hpp) over structure-of-arrays fields, with SIMD lanes
// across cells.
//
// Every cell has the same node count N (DQMOM transports a fixed number of nodes). Cells are taken
// in blocks of `lanes`; within a block every step of the Hermite solve (Lagrange coefficients,
// their squares, the two sums per node; dqmom.hpp's header) is a loop over the lanes, which the
// compiler vectorises, and no X⁻¹ is stored. The results are the per-cell System's to rounding
// (the same operations, in a different order where the per-cell path forms X⁻¹ first; tested
// within 8 ε κ). Cells whose nodes are closer than the merge gap, or invalid, are handed to the
// per-cell System (its merge rule and statuses). No allocation; host only (a device code calls
// the per-cell System, one thread per cell).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

#include "dqmom.hpp"

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

// The Hermite solve of one block of `lanes` cells with distinct valid nodes (x in scaled units,
// s scaled), writing α, β and, when wanted, ‖X̃⁻¹‖_∞ and ‖X̃‖_∞.
template <class T, int N, int W, bool with_condition>
void hermite_block(const std::array<std::array<T, W>, N>& x, const std::array<std::array<T, W>, 2 * N>& s,
                   std::array<std::array<T, W>, N>& alpha, std::array<std::array<T, W>, N>& beta,
                   std::array<T, W>& condition) {
  std::array<T, W> inverse_norm{};
  for (int c = 0; c < N; ++c) {
    std::array<std::array<T, W>, N> lagrange{};
    std::array<T, W> slope{};
    for (int l = 0; l < W; ++l) lagrange[0][l] = T(1);
    int degree = 0;
    for (int j = 0; j < N; ++j) {
      if (j == c) continue;
      std::array<T, W> inverse;
      for (int l = 0; l < W; ++l) {
        inverse[l] = T(1) / (x[c][l] - x[j][l]);
        slope[l] += inverse[l];
      }
      for (int m = degree + 1; m > 0; --m)
        for (int l = 0; l < W; ++l) lagrange[m][l] = (lagrange[m - 1][l] - x[j][l] * lagrange[m][l]) * inverse[l];
      for (int l = 0; l < W; ++l) lagrange[0][l] = -x[j][l] * lagrange[0][l] * inverse[l];
      ++degree;
    }
    std::array<std::array<T, W>, 2 * N> square{};
    for (int p = 0; p < N; ++p)
      for (int q = 0; q < N; ++q)
        for (int l = 0; l < W; ++l) square[p + q][l] += lagrange[p][l] * lagrange[q][l];
    std::array<T, W> of_square{}, b{}, alpha_norm{}, node_norm{};
    for (int k = 0; k < 2 * N; ++k)
      for (int l = 0; l < W; ++l) {
        const T beta_row = (k > 0 ? square[k - 1][l] : T(0)) - x[c][l] * square[k][l];
        b[l] += beta_row * s[k][l];
        of_square[l] += square[k][l] * s[k][l];
        if constexpr (with_condition) {
          const T alpha_row = square[k][l] - T(2) * slope[l] * beta_row;
          alpha_norm[l] += std::abs(alpha_row);
          node_norm[l] += std::abs(beta_row + x[c][l] * alpha_row);
        }
      }
    for (int l = 0; l < W; ++l) {
      beta[c][l] = b[l];
      alpha[c][l] = of_square[l] - T(2) * slope[l] * b[l];
      if constexpr (with_condition) inverse_norm[l] = std::max({inverse_norm[l], alpha_norm[l], node_norm[l]});
    }
  }
  if constexpr (with_condition) {
    std::array<T, W> matrix_norm{};
    for (int k = 0; k < 2 * N; ++k) {
      std::array<T, W> row{};
      for (int c = 0; c < N; ++c)
        for (int l = 0; l < W; ++l) {
          T power(1);  // x^(k−1)
          for (int m = 1; m < k; ++m) power *= x[c][l];
          row[l] += std::abs(T(1 - k) * power * (k > 0 ? x[c][l] : T(1))) + T(k) * power;
        }
      for (int l = 0; l < W; ++l) matrix_norm[l] = std::max(matrix_norm[l], row[l]);
    }
    for (int l = 0; l < W; ++l) condition[l] = matrix_norm[l] * inverse_norm[l];
  }
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
  const std::size_t cells = batch.status.size();
  const T gap = merge_gap<T>(options);
  for (std::size_t first = 0; first < cells; first += W) {
    const int lanes = int(std::min<std::size_t>(W, cells - first));
    // Gather (padding lanes: distinct nodes 1 … N, weights 1), check, scale: loops over lanes.
    std::array<std::array<T, W>, N> node{}, x{};
    std::array<std::array<T, W>, 2 * N> s{};
    std::array<T, W> largest{}, scale{};
    std::array<int, W> valid{};
    for (int l = 0; l < W; ++l) valid[l] = 1;
    for (int i = 0; i < N; ++i)
      for (int l = 0; l < W; ++l) {
        const T xi = l < lanes ? batch.nodes[i][first + std::size_t(l)] : T(i + 1) / T(N);
        const T wi = l < lanes ? batch.weights[i][first + std::size_t(l)] : T(1);
        node[i][l] = xi;
        valid[l] &= int(xi > T(0)) & int(xi < std::numeric_limits<T>::infinity()) & int(wi >= T(0)) &
                    int(wi < std::numeric_limits<T>::infinity());
        largest[l] = std::max(largest[l], xi);
      }
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < i; ++j)
        for (int l = 0; l < W; ++l)
          valid[l] &= int(std::abs(node[i][l] - node[j][l]) > gap * std::max(node[i][l], node[j][l]));
    for (int l = 0; l < W; ++l) scale[l] = valid[l] ? power_of_two_near(largest[l]) : T(1);
    for (int i = 0; i < N; ++i)
      for (int l = 0; l < W; ++l) x[i][l] = valid[l] ? node[i][l] / scale[l] : T(i + 1) / T(N);
    std::array<T, W> unit{};
    for (int l = 0; l < W; ++l) unit[l] = T(1);
    for (int k = 0; k < 2 * N; ++k)
      for (int l = 0; l < W; ++l) {
        s[k][l] = valid[l] && l < lanes ? batch.moment_sources[k][first + std::size_t(l)] / unit[l] : T(0);
        unit[l] *= scale[l];
      }
    std::array<std::array<T, W>, N> alpha, beta;
    std::array<T, W> condition{};
    hermite_block<T, N, W, with_condition>(x, s, alpha, beta, condition);
    for (int l = 0; l < lanes; ++l) {
      const std::size_t cell = first + std::size_t(l);
      if (!valid[l]) {
        solve_one(batch, cell, options);
        continue;
      }
      for (int i = 0; i < N; ++i) {
        batch.weight_sources[i][cell] = alpha[i][l];
        batch.weighted_node_sources[i][cell] = (beta[i][l] + x[i][l] * alpha[i][l]) * scale[l];
      }
      batch.status[cell] = SourceStatus::ok;
      if constexpr (with_condition) batch.condition[cell] = condition[l];
    }
  }
}

}  // namespace detail

// Solves every cell of the batch (see the header comment). Every span must hold status.size()
// cells (condition: that many, or none).
template <class T, int N>
void solve_batched(const SourceBatch<T, N>& batch, const Options& options = {}) {
  constexpr int lanes = 64 / int(sizeof(T)) > 2 ? 64 / int(sizeof(T)) : 2;  // one 512-bit register
  if (batch.condition.empty())
    detail::solve_blocks<T, N, lanes, false>(batch, options);
  else
    detail::solve_blocks<T, N, lanes, true>(batch, options);
}

}  // namespace fluidbed::moments::dqmom
