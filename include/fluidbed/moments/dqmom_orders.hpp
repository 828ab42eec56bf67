// fluidbed — the DQMOM source system for any 2ν moment orders, integer or fractional (needs Eigen
// 3.4; host only).
//
// The thesis (Mazzei (2008), PhD thesis, UCL, §5.7) and Marchisio & Fox (2005), J. Aerosol Sci.
// 36, 43–73, doi:10.1016/j.jaerosci.2004.07.009, allow any 2ν independent real orders p, the
// orders 0 and 1 always among them (they carry the weights and the weighted nodes):
//   Σ_i (1 − p) ξ_i^p c_i^a + p ξ_i^(p−1) c_i^ξ = s_p.
// Without the polynomial structure of the integer orders there is no Hermite shortcut
// (dqmom.hpp): the 2ν × 2ν matrix is factorised by Eigen's PartialPivLU, in units of L (the power of
// two nearest the largest node; s̃_p = s_p / L^p, c^ξ = L c̃^ξ), with κ_∞ of the scaled matrix
// reported. Coincident nodes are merged as in dqmom.hpp; the merged system keeps the first 2ν'
// orders of the list, so list them by priority: 0 and 1 first (required), then the others.
#pragma once

#include "eigen_core.hpp"  // first: Eigen's Core without its own warnings

#include <Eigen/LU>

#include <array>
#include <cmath>
#include <span>

#include "dqmom.hpp"

FLUIDBED_EIGEN_CODE_BEGIN

namespace fluidbed::moments::dqmom {

// Sources for moment orders `orders` (2ν distinct finite reals, orders[0] = 0, orders[1] = 1) and
// moment sources s (s[j] for orders[j]); invalid_input otherwise.
template <class T, int N>
Sources<T, N> solve_orders(std::span<const T> nodes, std::span<const T> weights, std::span<const T> orders,
                           std::span<const T> s, const Options& options = {}) {
  const detail::MergedNodes<T, N> merged(nodes, weights, options);
  const int n = merged.size;
  if (n == 0 || int(orders.size()) != 2 * n || int(s.size()) != 2 * n || orders[0] != T(0) || orders[1] != T(1))
    return Sources<T, N>{};
  for (int j = 0; j < 2 * n; ++j) {
    if (!std::isfinite(orders[j])) return Sources<T, N>{};
    for (int k = 0; k < j; ++k)
      if (orders[j] == orders[k]) return Sources<T, N>{};
  }
  const int m = merged.distinct;
  using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, 2 * N, 2 * N>;
  using Vector = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, 2 * N, 1>;
  Matrix x(2 * m, 2 * m);
  Vector rhs(2 * m);
  for (int j = 0; j < 2 * m; ++j) {
    const T p = orders[j];
    rhs(j) = s[j] / std::pow(merged.scale, p);
    for (int c = 0; c < m; ++c) {
      x(j, c) = (T(1) - p) * std::pow(merged.center[c], p);
      x(j, m + c) = p == T(0) ? T(0) : p * std::pow(merged.center[c], p - T(1));
    }
  }
  const Eigen::PartialPivLU<Matrix> lu(x);
  const Vector c = lu.solve(rhs);
  const Matrix inverse = lu.inverse();
  const T condition = x.cwiseAbs().rowwise().sum().maxCoeff() * inverse.cwiseAbs().rowwise().sum().maxCoeff();
  Sources<T, N> out = merged.header(condition);
  std::array<T, N> alpha{}, beta{};
  for (int k = 0; k < m; ++k) {
    alpha[k] = c(k);
    beta[k] = c(m + k) - merged.center[k] * c(k);
  }
  merged.distribute(alpha, beta, out);
  return out;
}

}  // namespace fluidbed::moments::dqmom

FLUIDBED_EIGEN_CODE_END
