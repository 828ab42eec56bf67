// fluidbed — realizability of a moment set: how many nodes it supports, where it fails.
//
// A moment set m_0 … m_{2n−1} is the moment sequence of a positive measure with n points of
// increase on [0, ∞) iff its Stieltjes coefficients ζ_1 … ζ_{2n−1} are all > 0, and on the
// real line iff β_1 … β_{n−1} > 0 (equivalently, positive Hankel determinants H_0 … ;
// Shohat & Tamarkin (1943), The Problem of Moments, AMS; seed 003 eq. 0.22). The signs are
// read from the recurrence (recurrence.hpp), which is computed on exactly scaled moments, so
// the test involves no absolute threshold and no units.
#pragma once

#include <array>
#include <cmath>

#include "../core/config.hpp"
#include "jacobi_eigen.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

enum class InversionStatus {
  ok,              // all n requested nodes
  reduced,         // fewer nodes: the set is realizable (strictly) only with quadrature.size nodes
  zero_mass,       // m_0 = 0 and every moment 0: an empty cell, no nodes
  not_realizable,  // not even one node: m_0 < 0, or moments of an empty cell nonzero, or the mean
                   // outside the support
  invalid_input,   // a moment is NaN or infinite
  eigen_failure,   // the QL iteration did not converge (never observed); no nodes
};

template <class T, int N>
struct InversionResult {
  Quadrature<T, N> quadrature;  // nodes ascending, weights; quadrature.size nodes
  InversionStatus status = InversionStatus::invalid_input;
  int realizable_nodes = 0;      // nodes the set supports (= quadrature.size unless eigen_failure)
  // The first coefficient that fails: j for ζ_j <= 0 ([0, ∞), 1-based) or k for β_k <= 0 (real
  // line), with its value in the caller's units; 0 and 0 when every tested coefficient passes.
  int first_failing_index = 0;
  T failing_value = T(0);
  // How far inside moment space the retained coefficients lie, relative: min_j ζ_j/ζ_1 over
  // j = 1 … 2 size − 1 ([0, ∞)), or min_k β_k/(m_2/m_0) over k = 1 … size − 1 (real line); 1
  // for a single node. Near 0: close to the boundary (a nearly degenerate set).
  T boundary_distance = T(0);
};

namespace detail {

// Realizability of a scaled recurrence (r.size levels computed) on the support: trims
// r.size to the realizable node count and fills the diagnostics.
template <class T, int N>
FLUIDBED_HOST_DEVICE void assess(Recurrence<T, N>& r, int requested, Support support, MomentScaling s,
                                 InversionResult<T, N>& out) {
  using std::ldexp;
  if (support == Support::positive_half_line) {
    const std::array<T, 2 * N> zeta = stieltjes_coefficients(r);
    // ζ_1 … ζ_{2 size − 1} exist; an early recurrence stop means ζ_{2 size} (= β_size/ζ_{2 size−1}) failed.
    int failing = 0;
    for (int j = 1; j <= 2 * r.size - 1; ++j)
      if (!(zeta[j - 1] > T(0))) {
        failing = j;
        break;
      }
    if (failing == 0 && r.size < requested) {
      failing = 2 * r.size;
      out.failing_value = ldexp(r.beta[r.size] / zeta[2 * r.size - 2], s.length_exponent);
    } else if (failing != 0) {
      out.failing_value = ldexp(zeta[failing - 1], s.length_exponent);
    }
    if (failing != 0) r.size = failing / 2;
    out.first_failing_index = failing;
    T distance(r.size > 0 ? 1 : 0);
    for (int j = 2; j <= 2 * r.size - 1; ++j) distance = zeta[j - 1] / zeta[0] < distance ? zeta[j - 1] / zeta[0] : distance;
    out.boundary_distance = distance;
  } else {
    if (r.size < requested) {
      out.first_failing_index = r.size;
      out.failing_value = ldexp(r.beta[r.size], 2 * s.length_exponent);
    }
    const T second = r.beta[0] * (r.alpha[0] * r.alpha[0]) + (r.size > 1 ? r.beta[0] * r.beta[1] : T(0));
    T distance(r.size > 0 ? 1 : 0);
    for (int k = 1; k < r.size; ++k) {
      const T relative = r.beta[k] * r.beta[0] / second;
      distance = relative < distance ? relative : distance;
    }
    out.boundary_distance = distance;
  }
}

}  // namespace detail
}  // namespace fluidbed::moments
