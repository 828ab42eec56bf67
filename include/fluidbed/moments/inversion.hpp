// fluidbed — moment inversion: 2n moments to an n-node Gauss quadrature, with diagnostics.
//
// The pipeline, per cell, allocation-free and usable in device code:
//   1. validate (finite moments, m_0 > 0);
//   2. scale by exact powers of two (recurrence.hpp): the result does not depend on units;
//   3. recurrence by Wheeler's algorithm (default) or product-difference;
//   4. realizability: the number of nodes the set supports on the chosen support, from the
//      signs of the Stieltjes coefficients ζ_j ([0, ∞)) or of β_k (real line);
//   5. nodes and weights of that many nodes: closed form for n <= 2, else QL carrying the
//      first eigenvector row (jacobi_eigen.hpp), in scaled units;
//   6. unscale nodes and weights exactly.
// Never NaN without a status, never an exception or abort: problems are returned as data.
//
// Node counts. invert<T, N>(span) takes any even number 2n <= 2N of moments: N is the
// compile-time capacity (the storage), n the runtime node count. invert<N>(std::array) is
// the fixed-n = N form. In double precision more than ~10–12 nodes are meaningless for
// size distributions (the map from moments to nodes loses about a decade per node; see
// tests/reference/moments_reference.py's conditioning), so a capacity of 10–16 serves every
// runtime use.
#pragma once

#include <array>
#include <cmath>
#include <span>

#include "../core/config.hpp"
#include "jacobi_eigen.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

enum class EigenSolver {
  automatic,    // closed form for n <= 2, Golub–Welsch QL above
  golub_welsch  // QL for every n (the reference path for the closed forms)
};

struct InversionOptions {
  RecurrenceAlgorithm algorithm = RecurrenceAlgorithm::wheeler;
  EigenSolver solver = EigenSolver::automatic;
  Support support = Support::positive_half_line;
};

namespace detail {

template <class T, int N>
FLUIDBED_HOST_DEVICE void unscale(Quadrature<T, N>& q, MomentScaling s) {
  using std::ldexp;
  for (int i = 0; i < q.size; ++i) {
    q.nodes[i] = ldexp(q.nodes[i], s.length_exponent);
    q.weights[i] = ldexp(q.weights[i], s.weight_exponent);
  }
}

}  // namespace detail

// The Gauss quadrature of the first n nodes, n = m.size()/2 <= N (2n moments m_0 … m_{2n−1}).
// Preconditions: m.size() even, 2 <= m.size() <= 2N. Everything else is a status.
template <class T, int N>
FLUIDBED_HOST_DEVICE InversionResult<T, N> invert(std::span<const T> m, const InversionOptions& options = {}) {
  FLUIDBED_EXPECTS(m.size() >= 2 && m.size() <= std::size_t(2 * N) && m.size() % 2 == 0);
  InversionResult<T, N> out;
  const int requested = int(m.size() / 2);
  out.status = detail::input_status(m);
  if (out.status != InversionStatus::ok) {
    if (out.status == InversionStatus::not_realizable) out.failing_value = m[0];
    return out;
  }
  out.status = InversionStatus::not_realizable;
  const MomentScaling s = scaling_of(m);
  T scaled[2 * N];
  scale_moments(m, s, std::span<T>(scaled, m.size()));
  const std::span<const T> view(scaled, m.size());
  Recurrence<T, N> r = options.algorithm == RecurrenceAlgorithm::wheeler ? wheeler_unscaled<T, N>(view)
                                                                         : product_difference_unscaled<T, N>(view);
  detail::assess(r, requested, options.support, s, out);
  out.realizable_nodes = r.size;
  if (r.size == 0) return out;  // not_realizable (e.g. a negative mean on [0, ∞))
  if (options.solver == EigenSolver::automatic && r.size <= 2) {
    out.quadrature = gauss_closed_form(r);
  } else if (!gauss_golub_welsch(r, out.quadrature)) {
    out.status = InversionStatus::eigen_failure;
    return out;
  }
  detail::unscale(out.quadrature, s);
  out.status = r.size == requested ? InversionStatus::ok : InversionStatus::reduced;
  return out;
}

// Fixed n = N at compile time: exactly 2N moments.
template <int N, class T>
FLUIDBED_HOST_DEVICE InversionResult<T, N> invert(const std::array<T, 2 * N>& m, const InversionOptions& options = {}) {
  return invert<T, N>(std::span<const T>(m.data(), m.size()), options);
}

}  // namespace fluidbed::moments
