// fluidbed — moment inversion: 2n moments to an n-node Gauss quadrature, with diagnostics.
//
// The pipeline, per cell, allocation-free and usable in device code:
//   1. validate (finite moments, m_0 > 0);
//   2. scale by exact powers of two (recurrence.hpp): the result does not depend on units;
//   3. recurrence by Wheeler's algorithm (default) or product-difference;
//   4. realizability: the number of nodes the set supports on the chosen support, from the
//      signs of the Stieltjes coefficients ζ_j ([0, ∞)) or of β_k (real line);
//   5. nodes and weights of that many nodes (jacobi_eigen.hpp), in scaled units: closed
//      forms for n <= 2, a fixed-cost solver for n = 3, else QL carrying the first
//      eigenvector row;
//   6. unscale nodes and weights exactly.
// Never NaN without a status, never an exception or abort: problems are returned as data.
//
// Node counts. invert<T, N>(span) takes any even number 2n of moments, 2 <= 2n <= 2N: N is the
// compile-time capacity (the storage), n the runtime node count. Any other count (empty, odd,
// above 2N) is invalid_input with no node, at every optimisation level: never a moment dropped,
// never an access beyond the storage. invert<N>(std::array) is the fixed-n = N form. In double precision more than ~10–12 nodes are meaningless for
// size distributions (the map from moments to nodes loses about a decade per node; see
// tests/reference/moments_reference.py's conditioning), so a capacity of 10–16 serves every
// runtime use.
#pragma once

#include <array>
#include <cmath>
#include <span>

#include "../core/config.hpp"
#include "accuracy.hpp"
#include "jacobi_eigen.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

enum class EigenSolver {
  automatic,    // closed forms for n <= 2, the fixed-cost three-node solver for n = 3 (within
                // detail::three_node_spread_limit, jacobi_eigen.hpp), QL otherwise
  golub_welsch  // QL for every n (the reference path for the others)
};

struct InversionOptions {
  RecurrenceAlgorithm algorithm = RecurrenceAlgorithm::wheeler;
  EigenSolver solver = EigenSolver::automatic;
  Support support = Support::positive_half_line;
  // The error estimate of the rule (accuracy.hpp) in InversionResult::error. Off by default: at
  // n = 3 it costs about as much as the inversion.
  bool estimate_error = false;
  // How accurate the caller's moments are, relative (each moment; 0: exact as given), for the
  // estimate.
  double moment_accuracy = 0;
  // > 0: a rule whose estimated node or weight error exceeds it is returned with status
  // inaccurate (the estimate is then made whatever estimate_error says).
  double required_accuracy = 0;
};

namespace detail {

template <class T, int N>
FLUIDBED_HOST_DEVICE void unscale(Quadrature<T, N>& q, MomentScaling s) {
  const T length = power_of_two<T>(s.length_exponent);
  const T weight = power_of_two<T>(s.weight_exponent);
  for (int i = 0; i < q.size; ++i) {
    q.nodes[i] = times_power_of_two(q.nodes[i], length, s.length_exponent);
    q.weights[i] = times_power_of_two(q.weights[i], weight, s.weight_exponent);
  }
}

// Whether every node and weight of q is finite.
template <class T, int N>
FLUIDBED_HOST_DEVICE bool finite_rule(const Quadrature<T, N>& q) {
  return finite_prefix(q.nodes, q.weights, q.size);
}

}  // namespace detail

namespace detail {

// The pipeline with the eigen step as a parameter: solve(recurrence, quadrature) fills the
// quadrature of a scaled recurrence and returns false on failure (eigen_backend.hpp passes
// Eigen's solver). Counts and statuses as invert().
template <class T, int N, class Solve>
FLUIDBED_HOST_DEVICE InversionResult<T, N> invert_with(std::span<const T> m, const InversionOptions& options,
                                                        Solve&& solve) {
  InversionResult<T, N> out;  // invalid_input
  if (!count_within(m.size(), 2, 2 * N, Parity::even)) return out;
  const int requested = int(m.size() / 2);
  out.status = input_status(m);
  if (out.status != InversionStatus::ok) {
    if (out.status == InversionStatus::not_realizable) out.failing_value = m[0];
    return out;
  }
  const ScaledMoments<T, N> scaled = scaled_moments<T, N>(m);
  if (!scaled_moments_in_range(m, scaled.view())) {
    out.status = InversionStatus::invalid_input;
    return out;
  }
  out.status = InversionStatus::not_realizable;
  Recurrence<T, N> r = options.algorithm == RecurrenceAlgorithm::wheeler
                           ? wheeler_unscaled<T, N>(scaled.view())
                           : product_difference_unscaled<T, N>(scaled.view());
  const MomentScaling s = scaled.scaling;
  assess(r, requested, options.support, s, out);
  out.realizable_nodes = r.size;
  if (r.size == 0) return out;  // not_realizable (e.g. a negative mean on [0, ∞))
  // A rule that cannot be represented is a status, never a NaN or an infinity under ok: a
  // spread of nodes beyond the floating-point range in scaled units (eigen_failure), or a node
  // or weight beyond it in the caller's (invalid_input: the set spans more than the range).
  if (!solve(static_cast<const Recurrence<T, N>&>(r), out.quadrature) || !finite_rule(out.quadrature)) {
    out.quadrature = {};
    out.status = InversionStatus::eigen_failure;
    return out;
  }
  const bool estimate = options.estimate_error || options.required_accuracy > 0;
  if (estimate)
    out.error = scaled_rule_error(scaled.view().first(std::size_t(2 * r.size)), out.quadrature, options.support,
                                  T(options.moment_accuracy));
  unscale(out.quadrature, s);
  if (!finite_rule(out.quadrature)) {
    out.quadrature = {};
    out.error = {};
    out.status = InversionStatus::invalid_input;
    return out;
  }
  out.status = r.size == requested ? InversionStatus::ok : InversionStatus::reduced;
  if (options.required_accuracy > 0 && !meets(out.error, T(options.required_accuracy)))
    out.status = InversionStatus::inaccurate;
  return out;
}

}  // namespace detail

// The Gauss quadrature of the first n nodes, n = m.size()/2 <= N (2n moments m_0 … m_{2n−1}).
// No preconditions: a count other than 2, 4, … 2N is invalid_input (see above), and so is
// everything else the data can be a status.
namespace detail {

// invert()'s eigen step (see EigenSolver): the quadrature of a scaled recurrence into q, false on
// failure.
template <class T, int N>
FLUIDBED_HOST_DEVICE bool solve_recurrence(const Recurrence<T, N>& r, Quadrature<T, N>& q, EigenSolver solver) {
  if (solver == EigenSolver::automatic) {
    if (r.size <= 2) {
      q = gauss_closed_form(r);
      return true;
    }
    if constexpr (N >= 3)
      if (r.size == 3 && gauss_three_nodes_within_limit(r, q) && finite_rule(q))
        return true;  // else beyond the spread limit, or a β underflowed in the adjugate: the QL
  }
  return gauss_golub_welsch(r, q);
}

}  // namespace detail

template <class T, int N>
FLUIDBED_HOST_DEVICE InversionResult<T, N> invert(std::span<const T> m, const InversionOptions& options = {}) {
  return detail::invert_with<T, N>(m, options, [&options](const Recurrence<T, N>& r, Quadrature<T, N>& q) {
    return detail::solve_recurrence(r, q, options.solver);
  });
}

// Fixed n = N at compile time: exactly 2N moments.
template <int N, class T>
FLUIDBED_HOST_DEVICE InversionResult<T, N> invert(const std::array<T, 2 * N>& m, const InversionOptions& options = {}) {
  return invert<T, N>(std::span<const T>(m.data(), m.size()), options);
}

}  // namespace fluidbed::moments
