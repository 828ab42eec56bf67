// fluidbed — the Gauss rule of a recurrence by Eigen's symmetric tridiagonal eigen-solver, an
// alternative to the Golub–Welsch QL of jacobi_eigen.hpp (a cross-check, and the solver a
// code that already uses Eigen may prefer).
//
// Eigen::SelfAdjointEigenSolver::computeFromTridiagonal (Eigen 3.4) runs implicit symmetric
// QR steps with Wilkinson shifts on J = tridiag(√β_k; α_k; √β_k) and accumulates the whole
// eigenvector matrix (n² work per rotation, against n for the QL that carries only the first
// row); eigenvalues come out ascending. The weights are m_0 v_{0,i}² (Golub & Welsch (1969),
// Math. Comp. 23, 221, doi:10.1090/S0025-5718-69-99647-1).
//
// Units. Eigen 3.4 deflates a subdiagonal entry when (e_i/ε)² <= |d_i| + |d_{i+1}|, i.e.
// |e_i| <= ε √(|d_i| + |d_{i+1}|): not invariant under a change of units (a length against the
// square root of one), and computeFromTridiagonal, unlike compute(), does not scale the matrix
// first. The QR steps converge so fast that this rarely changes a result (measured: a few
// ulps on a 6-node lognormal rule with sizes from 1e-6 to 1e6), but the solver is given the
// exactly scaled recurrence (entries O(1)), as the QL is: both solvers then see the same
// matrix, and the inversion is exactly unit-invariant (a power-of-two change of units changes
// no bit of the result).
//
// Host only (Eigen's solver is not marked for device code here). Allocation-free: the
// matrices have a fixed maximum size (N×N) and the runtime size n.
#pragma once

#include "eigen_core.hpp"  // first: Eigen's Core without its own warnings

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <span>

#include "../core/config.hpp"
#include "inversion.hpp"
#include "jacobi_eigen.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

FLUIDBED_EIGEN_CODE_BEGIN

namespace fluidbed::moments {

// Nodes (ascending) and weights of the r.size-point Gauss rule of r, by Eigen's tridiagonal
// solver. Returns false (q.size = 0) if Eigen reports no convergence (30 n iterations), or for
// a size not within 0 … N.
template <class T, int N>
bool gauss_eigen_tridiagonal(const Recurrence<T, N>& r, Quadrature<T, N>& q) {
  using std::sqrt;
  // Storage for at least 2×2: with a maximum size of 1 Eigen's vectorized copies trip GCC 12's
  // -Wstringop-overread (a false positive).
  constexpr int capacity = N < 2 ? 2 : N;
  using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, capacity, capacity>;
  using Solver = Eigen::SelfAdjointEigenSolver<Matrix>;
  const int n = r.size;
  q.size = 0;
  if (!detail::size_in_storage(r)) return false;
  if (n == 0) return true;
  typename Solver::RealVectorType diagonal(n);
  typename Solver::SubDiagonalType subdiagonal(n - 1);
  for (int i = 0; i < n; ++i) diagonal(i) = r.alpha[i];
  for (int i = 0; i + 1 < n; ++i) subdiagonal(i) = sqrt(r.beta[i + 1]);
  Solver solver;
  solver.computeFromTridiagonal(diagonal, subdiagonal, Eigen::ComputeEigenvectors);
  if (solver.info() != Eigen::Success) return false;
  q.size = n;
  for (int i = 0; i < n; ++i) {
    const T first = solver.eigenvectors()(0, i);
    q.nodes[i] = solver.eigenvalues()(i);
    q.weights[i] = r.beta[0] * first * first;
  }
  return true;
}


// invert() (inversion.hpp) with the nodes and weights from gauss_eigen_tridiagonal() for every
// node count: the same counts, statuses and diagnostics; options.solver is not used.
template <class T, int N>
InversionResult<T, N> invert_eigen(std::span<const T> m, const InversionOptions& options = {}) {
  return detail::invert_with<T, N>(m, options, [](const Recurrence<T, N>& r, Quadrature<T, N>& q) {
    return gauss_eigen_tridiagonal(r, q);
  });
}

// Fixed n = N at compile time: exactly 2N moments.
template <int N, class T>
InversionResult<T, N> invert_eigen(const std::array<T, 2 * N>& m, const InversionOptions& options = {}) {
  return invert_eigen<T, N>(std::span<const T>(m.data(), m.size()), options);
}

}  // namespace fluidbed::moments

FLUIDBED_EIGEN_CODE_END
