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
#include <limits>
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

// The status and rule of 2n moments, n <= N (defined below).
template <class T, int N>
FLUIDBED_HOST_DEVICE InversionResult<T, N> invert(std::span<const T> m, const InversionOptions& options = {});

namespace detail {

// Whether the options ask for the error estimate (for itself, or for the status).
FLUIDBED_HOST_DEVICE inline bool wants_estimate(const InversionOptions& options) {
  return options.estimate_error || options.required_accuracy > 0;
}

// Whether an estimate misses the options' required accuracy (the status is then inaccurate).
template <class T>
FLUIDBED_HOST_DEVICE bool misses_requirement(const RuleError<T>& error, const InversionOptions& options) {
  return options.required_accuracy > 0 && !meets(error, T(options.required_accuracy));
}

template <class T, int N>
FLUIDBED_HOST_DEVICE void unscale(Quadrature<T, N>& q, MomentScaling s) {
  scale_rule(q, s.length_exponent, s.weight_exponent);
}

// Above this, the first-order estimate's own second-order terms exceed 1 % of it.
template <class T>
FLUIDBED_HOST_DEVICE constexpr T first_order_limit() {
  return T(0.01);
}

// Whether an estimate needs the vertex rules of add_vertex_changes(): on [0, ∞), with a caller's
// moment accuracy, an estimate beyond first order.
template <class T>
FLUIDBED_HOST_DEVICE bool beyond_first_order(const RuleError<T>& error, const InversionOptions& options) {
  return options.support == Support::positive_half_line && options.moment_accuracy > 0 &&
         (error.nodes > first_order_limit<T>() || error.weights > first_order_limit<T>());
}

// Beyond first order (where beyond_first_order()): the rules of the two moment sets
// m_k (1 ± δ (−1)^(k+1)), δ = moment_accuracy, are computed by invert(), and the estimate raised to
// the largest relative change of a node or a weight between them and the rule q of m (2n
// moments, n = q.size, in the caller's units). On [0, ∞) these two sign patterns are the first-order
// worst case of every node at once (the coefficients of H̃_i alternate in sign, accuracy.hpp), so
// the two rules bound each node's range without linearisation: for seed 003's powder A (Table 1,
// two nodes, δ = 1.04e-3) the nodes reach 70–89 and 101–163 µm, where first order says 84.5 and
// 119.7 µm ± 26 % and the rules of the printed digits span 72–89 and 102–158 µm. +∞ where either
// set has no rule of n nodes: within the moments' accuracy the set may not be realizable with them.
template <class T, int N>
FLUIDBED_HOST_DEVICE void add_vertex_changes(std::span<const T> m, const Quadrature<T, N>& q,
                                             const InversionOptions& options, RuleError<T>& error) {
  using std::abs;
  const T infinity = std::numeric_limits<T>::infinity();
  const T delta = T(options.moment_accuracy);
  const InversionOptions plain{.algorithm = options.algorithm, .solver = options.solver, .support = options.support};
  for (int direction = 1; direction >= -1; direction -= 2) {
    const T sign = T(direction);
    std::array<T, 2 * N> vertex{};
    for (std::size_t k = 0; k < m.size() && k < vertex.size(); ++k)
      vertex[k] = m[k] * (T(1) + (k % 2 == 1 ? sign : -sign) * delta);
    const InversionResult<T, N> moved = invert<T, N>(std::span<const T>(vertex.data(), m.size()), plain);
    if (moved.status != InversionStatus::ok) {
      error.nodes = error.weights = infinity;
      return;
    }
    for (int i = 0; i < q.size; ++i) {
      const T node_change = abs(moved.quadrature.nodes[i] - q.nodes[i]) / abs(q.nodes[i]);
      const T weight_change = abs(moved.quadrature.weights[i] - q.weights[i]) / abs(q.weights[i]);
      error.nodes = lane_ops<T>::larger_error(error.nodes, node_change);
      error.weights = lane_ops<T>::larger_error(error.weights, weight_change);
    }
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
  if (wants_estimate(options))
    out.error = scaled_rule_error(scaled.view().first(std::size_t(2 * r.size)), out.quadrature,
                                  r, options.support, T(options.moment_accuracy));
  unscale(out.quadrature, s);
  if (!finite_rule(out.quadrature)) {
    out.quadrature = {};
    out.error = {};
    out.status = InversionStatus::invalid_input;
    return out;
  }
  if (wants_estimate(options) && beyond_first_order(out.error, options))
    add_vertex_changes(m.first(std::size_t(2 * r.size)), out.quadrature, options, out.error);
  out.status = r.size == requested ? InversionStatus::ok : InversionStatus::reduced;
  if (out.status == InversionStatus::reduced && wants_estimate(options))
    out.error.count = lane_ops<T>::larger_error(
        out.error.count,
        failed_decision_error(scaled.view(), r, out.first_failing_index, options.support, T(options.moment_accuracy)));
  if (misses_requirement(out.error, options)) out.status = InversionStatus::inaccurate;
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
FLUIDBED_HOST_DEVICE InversionResult<T, N> invert(std::span<const T> m, const InversionOptions& options) {
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
