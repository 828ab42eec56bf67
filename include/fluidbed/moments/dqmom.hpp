// fluidbed — DQMOM source terms: the linear system that turns moment sources into sources of the
// transported quadrature (work in progress, issue 17: the system, its structured solve, the
// growth and diffusion right-hand sides; conditioning, coincident nodes, kernels of moments and
// batching still to come).
//
// DQMOM (Marchisio & Fox (2005), J. Aerosol Sci. 36, 43–73, doi:10.1016/j.jaerosci.2004.07.009;
// seed 000 §5.7 and App. D) transports the ν weights a_i and weighted nodes a_i ξ_i of a
// quadrature with sources c_i^a and c_i^ξ chosen so that 2ν moments M_k = Σ a_i ξ_i^k evolve as the
// population balance says:
//   Σ_i (1 − k) ξ_i^k c_i^a + k ξ_i^(k−1) c_i^ξ = s_k,   k = 0 … 2ν − 1          (seed 000 eq. 5.63)
// The weights are either volume fractions φ_i (seed 000: the volume-density function, ξ a
// diameter) or number densities w_i (Marchisio & Fox); the matrix is the same, the growth part of
// the right-hand side is not (growth_sources below), and the two must never be mixed.
//
// Structured solve. With α_i = c_i^a and β_i = c_i^ξ − ξ_i c_i^a the rows read
// L(x^k) = s_k for the functional L(p) = Σ_i α_i p(ξ_i) + β_i p'(ξ_i): (α, β) are the Hermite
// weights of L at the nodes, L applied to the Hermite basis polynomials
//   h_i = [1 − 2 ℓ_i'(ξ_i)(x − ξ_i)] ℓ_i²,   ĥ_i = (x − ξ_i) ℓ_i²,   ℓ_i the Lagrange basis,
// so that α_i = L(ℓ_i²) − 2 ℓ_i'(ξ_i) β_i and β_i = L((x − ξ_i) ℓ_i²), each from the coefficients
// of ℓ_i² (degree 2ν − 2) and the s_k: O(ν³) operations without pivoting, where a dense LU of the
// 2ν × 2ν matrix takes about (2ν)³ · 2/3 and a copy. det X = (−1)^(ν(ν−1)/2) Π_{i<j} (ξ_i − ξ_j)⁴:
// the system is singular exactly where two nodes coincide (the divisions by ξ_i − ξ_j here).
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "../core/config.hpp"

namespace fluidbed::moments::dqmom {

// The sources of the weights (c_i^a) and of the weighted nodes (c_i^ξ) of `size` nodes.
template <class T, int N>
struct Sources {
  std::array<T, N> weight{};
  std::array<T, N> weighted_node{};
  int size = 0;
};

// Solves the DQMOM system for the nodes ξ_0 … ξ_{ν−1} (distinct; ν = nodes.size() <= N) and the
// right-hand side s_0 … s_{2ν−1}. Returns size 0 for sizes that do not match.
template <class T, int N>
FLUIDBED_HOST_DEVICE Sources<T, N> solve(std::span<const T> nodes, std::span<const T> s) {
  Sources<T, N> out;
  const int n = int(nodes.size());
  if (n < 1 || n > N || int(s.size()) != 2 * n) return out;
  for (int i = 0; i < n; ++i) {
    // ℓ_i = Π_{j≠i} (x − ξ_j)/(ξ_i − ξ_j), built by multiplying in one factor at a time, then
    // squared; the slope ℓ_i'(ξ_i) = Σ_{j≠i} 1/(ξ_i − ξ_j).
    std::array<T, N> lagrange{};
    lagrange[0] = T(1);
    T slope(0);
    int degree = 0;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const T inverse = T(1) / (nodes[i] - nodes[j]);
      slope += inverse;
      for (int m = degree + 1; m > 0; --m) lagrange[m] = (lagrange[m - 1] - nodes[j] * lagrange[m]) * inverse;
      lagrange[0] = -nodes[j] * lagrange[0] * inverse;
      ++degree;
    }
    // L(ℓ_i²) and L(x ℓ_i²) from the coefficients of ℓ_i².
    T of_square(0), of_x_square(0);
    for (int p = 0; p <= degree; ++p)
      for (int q = 0; q <= degree; ++q) {
        const T c = lagrange[p] * lagrange[q];
        of_square += c * s[p + q];
        of_x_square += c * s[p + q + 1];
      }
    const T beta = of_x_square - nodes[i] * of_square;
    const T alpha = of_square - 2 * slope * beta;
    out.weight[i] = alpha;
    out.weighted_node[i] = beta + nodes[i] * alpha;
  }
  out.size = n;
  return out;
}

// What the weights are: seed 000's volume fractions of a diameter-distributed phase, or
// Marchisio & Fox's number densities.
enum class Weights { volume_fraction, number_density };

// The growth part of the right-hand side, for ξ̇_i = growth_rate[i] the rate of change of node
// i's size: (3 + k) Σ_i φ_i ξ_i^(k−1) ξ̇_i for volume fractions of diameters (seed 000 eq. 5.63),
// k Σ_i w_i ξ_i^(k−1) ξ̇_i for number densities (Marchisio & Fox 2005), k = 0 … 2ν − 1.
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<T, 2 * N> growth_sources(Weights form, std::span<const T> weights,
                                                         std::span<const T> nodes, std::span<const T> growth_rate) {
  std::array<T, 2 * N> s{};
  const int n = int(nodes.size());
  for (int k = 0; k < 2 * n; ++k) {
    const T factor = form == Weights::volume_fraction ? T(3 + k) : T(k);
    T sum(0);
    for (int i = 0; i < n; ++i) {
      T power(1);  // ξ_i^(k−1)
      for (int m = 1; m < k; ++m) power *= nodes[i];
      if (k == 0) power = T(1) / nodes[i];
      sum += weights[i] * power * growth_rate[i];
    }
    s[k] = factor * sum;
  }
  return s;
}

// The diffusion-induced right-hand side of seed 000 §6.5.4 for any ν:
// s_k = k(k − 1) Σ_i ξ_i^(k−2) C_i, C_i = 𝒟 φ_i |∇ξ_i|² (eqs 6.18–6.23; at ν = 2 the solution is
// eq. 6.22).
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<T, 2 * N> diffusion_sources(std::span<const T> nodes, std::span<const T> c) {
  std::array<T, 2 * N> s{};
  const int n = int(nodes.size());
  for (int k = 2; k < 2 * n; ++k) {
    T sum(0);
    for (int i = 0; i < n; ++i) {
      T power(1);  // ξ_i^(k−2)
      for (int m = 2; m < k; ++m) power *= nodes[i];
      sum += power * c[i];
    }
    s[k] = T(k * (k - 1)) * sum;
  }
  return s;
}

}  // namespace fluidbed::moments::dqmom
