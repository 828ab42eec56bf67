// fluidbed — how many digits an n-node Gauss rule has: a first-order estimate of the relative
// error of its nodes and weights, from the rule and the moments it came from.
//
// Sensitivity. The rule (x_i, w_i) reproduces m_k = Σ_i w_i x_i^k, k = 0 … 2n−1, so a change
// δm of the moments moves it by the solution of the confluent Vandermonde system
//   δm_k = Σ_i (x_i^k δw_i + k w_i x_i^(k−1) δx_i).
// For any polynomial h of degree <= 2n−1 with coefficients h_k, Σ_k h_k δm_k = Σ_i (h(x_i) δw_i
// + w_i h'(x_i) δx_i), so the Hermite basis polynomials invert it in O(n²) per node: with
// P(x) = Π_j (x − x_j) and Q_i(x) = P(x)/(x − x_i),
//   H̃_i = P Q_i / Q_i(x_i)²                       (H̃_i(x_j) = 0, H̃_i'(x_j) = δ_ij):
//       w_i δx_i = Σ_k h̃_ik δm_k,
//   H_i = Q_i² / Q_i(x_i)² − 2 Q_i'(x_i)/Q_i(x_i) · H̃_i   (H_i(x_j) = δ_ij, H_i'(x_j) = 0):
//       δw_i = Σ_k h_ik δm_k
// (Hermite interpolation; e.g. Gautschi (2004), Orthogonal Polynomials: Computation and
// Approximation, Oxford, §2.1, for the conditioning of the moment map it measures).
//
// Estimate. Two sources, added:
//   - the caller's moments, each off by up to a relative δ (transport, measurement, printed
//     digits): the worst case δ Σ_k |h_k m_k|, a bound to first order;
//   - the rounding of the inversion itself (scaling, Wheeler's recurrence, the eigen-solver):
//     it acts on the rule like a random relative perturbation of the moments of a fraction of
//     an ulp, estimated as κ ε (Σ_k (h_k m_k)²)^(1/2) with κ = 1/16. κ was measured, not
//     derived: over random 2…8-atom size distributions (log-normal sizes around 100 µm,
//     σ_ln 0.45 and 1.3) the double inversion's error against a 50-digit inversion of the same
//     moments has a median of about ε/13 times the root-sum-square, independent of the
//     conditioning from 1e-15 to 1; κ = 1/16 makes the estimate about that median (96 % of
//     cells within a factor 10, none below 0.09 of the error; κ = 1/32 would bracket 98 % but
//     fall below the error of most cells). With floating-point contraction (FMA) the inversion
//     errs about half as much: the estimate is then about twice the median error (90–92 % of
//     cells within a factor 10).
// The error of one inversion is one draw: perturbing a cell's moments by one ulp moves its
// measured error by 0.40 decades (standard deviation of log10; p1–p99 of 2 decades) around
// that cell's mean, so no estimate from the rule can bracket more than about 98 % of cells
// within a factor 10; this one is, at the median, that cell mean.
//
// Units: node errors are relative to the node on [0, ∞) and to the largest |node| on the real
// line (a velocity node near zero has no relative error of its own); weight errors to the
// weight. First order: an estimate above about 0.1 means no correct digit, not its size.
#pragma once

#include <cmath>
#include <limits>
#include <span>

#include "../core/config.hpp"
#include "jacobi_eigen.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

namespace detail {

// The rounding of the inversion as a relative perturbation of each moment, root-sum-square
// (κ ε above).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T inversion_rounding() {
  return std::numeric_limits<T>::epsilon() / T(16);
}

// The larger of two error estimates, infinite where the new one is not a number (a zero weight
// or coincident nodes divide by zero).
template <class T>
FLUIDBED_HOST_DEVICE T larger_error(const T& so_far, const T& next) {
  if (!(next <= std::numeric_limits<T>::max())) return std::numeric_limits<T>::infinity();
  return next > so_far ? next : so_far;
}

// Whether both estimated errors are within a required relative accuracy.
template <class T>
FLUIDBED_HOST_DEVICE bool meets(const RuleError<T>& error, const T& required) {
  return error.nodes <= required && error.weights <= required;
}

// The estimate for a rule of n = q.size >= 1 nodes and its 2n moments m, both in the exactly
// scaled units of the inversion (nodes and moments O(1)); moment_accuracy as estimated_error().
template <class T, int N>
FLUIDBED_HOST_DEVICE RuleError<T> scaled_rule_error(std::span<const T> m, const Quadrature<T, N>& q, Support support,
                                                    const T& moment_accuracy) {
  using std::abs;
  using std::sqrt;
  const int n = q.size;
  FLUIDBED_EXPECTS(n >= 1 && n <= N && m.size() == std::size_t(2 * n));  // the callers' counts
  T p[N + 1];  // P(x) = Π_j (x − x_j), coefficients lowest first
  p[0] = T(1);
  T largest = T(0);
  for (int j = 0; j < n; ++j) {
    p[j + 1] = p[j];
    for (int k = j; k > 0; --k) p[k] = p[k - 1] - q.nodes[j] * p[k];
    p[0] = -q.nodes[j] * p[0];
    largest = abs(q.nodes[j]) > largest ? abs(q.nodes[j]) : largest;
  }
  const T rounding = inversion_rounding<T>();
  RuleError<T> error{T(0), T(0)};
  for (int i = 0; i < n; ++i) {
    const T x = q.nodes[i];
    T quotient[N];  // Q_i = P/(x − x_i) by synthetic division
    quotient[n - 1] = p[n];
    for (int k = n - 1; k > 0; --k) quotient[k - 1] = p[k] + x * quotient[k];
    T slope = T(0), curvature = T(0);  // P'(x_i) = Q_i(x_i) and Q_i'(x_i), by Horner
    for (int k = n - 1; k >= 0; --k) {
      curvature = curvature * x + slope;
      slope = slope * x + quotient[k];
    }
    T node_part[2 * N] = {}, square_part[2 * N] = {};  // P Q_i and Q_i²
    for (int b = 0; b < n; ++b) {
      for (int a = 0; a < n; ++a) square_part[a + b] += quotient[a] * quotient[b];
      for (int a = 0; a <= n; ++a) node_part[a + b] += p[a] * quotient[b];
    }
    const T inverse_square = T(1) / (slope * slope);
    const T lagrange_slope = T(2) * curvature * slope;  // 2 Q_i'(x_i)/Q_i(x_i), times Q_i(x_i)²
    T node_bound = T(0), node_squares = T(0), weight_bound = T(0), weight_squares = T(0);
    for (int k = 0; k < 2 * n; ++k) {
      const T node_term = node_part[k] * m[std::size_t(k)];
      const T weight_term = (square_part[k] - lagrange_slope * inverse_square * node_part[k]) * m[std::size_t(k)];
      node_bound += abs(node_term);
      node_squares += node_term * node_term;
      weight_bound += abs(weight_term);
      weight_squares += weight_term * weight_term;
    }
    const T per_weight = inverse_square / abs(q.weights[i]);
    const T node_scale = support == Support::positive_half_line ? abs(x) : largest;
    error.nodes = larger_error(error.nodes, (moment_accuracy * node_bound + rounding * sqrt(node_squares)) *
                                                per_weight / node_scale);
    error.weights = larger_error(error.weights,
                                 (moment_accuracy * weight_bound + rounding * sqrt(weight_squares)) * per_weight);
  }
  return error;
}

}  // namespace detail

// The estimated relative error of `rule`, inverted from `moments` (its 2n moments m_0 …
// m_{2n−1}, n = rule.size, in the caller's units), given that each moment is known to a
// relative `moment_accuracy` (0: exact as given, so only the inversion's rounding counts).
// invert() returns the same estimate in InversionResult::error when InversionOptions asks for
// it. Infinite where the rule has no digit to estimate (a zero weight, coincident nodes, or a
// moment count that is not 2n); zeros for an empty rule.
template <class T, int N>
FLUIDBED_HOST_DEVICE RuleError<T> estimated_error(std::span<const T> moments, const Quadrature<T, N>& rule,
                                                  Support support = Support::positive_half_line,
                                                  T moment_accuracy = T(0)) {
  const T infinity = std::numeric_limits<T>::infinity();
  const int n = rule.size;
  if (n == 0) return {T(0), T(0)};
  if (n < 0 || n > N || moments.size() != std::size_t(2 * n)) return {infinity, infinity};
  // In the moments' exact power-of-two scales, as the inversion runs.
  const detail::ScaledMoments<T, N> scaled = detail::scaled_moments<T, N>(moments);
  const MomentScaling s = scaled.scaling;
  const T length = detail::power_of_two<T>(-s.length_exponent), weight = detail::power_of_two<T>(-s.weight_exponent);
  Quadrature<T, N> q = rule;
  for (int i = 0; i < n; ++i) {
    q.nodes[i] = detail::times_power_of_two(rule.nodes[i], length, -s.length_exponent);
    q.weights[i] = detail::times_power_of_two(rule.weights[i], weight, -s.weight_exponent);
  }
  return detail::scaled_rule_error(scaled.view(), q, support, moment_accuracy);
}

}  // namespace fluidbed::moments
