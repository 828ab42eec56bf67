// fluidbed — Gauss nodes and weights from the recurrence (the Jacobi matrix).
//
// Golub & Welsch (1969), Math. Comp. 23, 221–230, doi:10.1090/S0025-5718-69-99647-1;
// seed 000 eqs. 5.82–5.85 and 5.92: the nodes are the eigenvalues of
// J = tridiag(√β_k; α_k; √β_k) and the weights m_0 v_{0,i}², v_{0,i} the first component of
// the i-th unit eigenvector. Only that first row is needed, so the QL iteration below carries
// one row of the eigenvector matrix instead of all n² entries.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "../core/config.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

// Nodes (ascending) and weights of a Gauss rule with `size` <= N points.
template <class T, int N>
struct Quadrature {
  std::array<T, N> nodes{};
  std::array<T, N> weights{};
  int size = 0;
};

namespace detail {

// Orders the first n nodes ascending, carrying their weights (insertion sort: n is small).
template <class T, int N>
FLUIDBED_HOST_DEVICE void sort_nodes(Quadrature<T, N>& q) {
  for (int i = 1; i < q.size; ++i)
    for (int j = i; j > 0 && q.nodes[j] < q.nodes[j - 1]; --j) {
      const T x = q.nodes[j];
      q.nodes[j] = q.nodes[j - 1];
      q.nodes[j - 1] = x;
      const T w = q.weights[j];
      q.weights[j] = q.weights[j - 1];
      q.weights[j - 1] = w;
    }
}

}  // namespace detail

// Closed forms for n = 1 and 2 (r.size <= 2). For n = 2, with c = (α_0 + α_1)/2,
// h = (α_1 − α_0)/2 and ρ = √(h² + β_1): x = c ∓ ρ, and the weights in the Christoffel form
// w_i = m_0 β_1 / (β_1 + (x_i − α_0)²), which has no cancellation (the textbook
// (m_0 x_2 − m_1)/(x_2 − x_1) loses the small weight of a skewed pair).
template <class T, int N>
FLUIDBED_HOST_DEVICE Quadrature<T, N> gauss_closed_form(const Recurrence<T, N>& r) {
  using std::sqrt;
  FLUIDBED_EXPECTS(r.size >= 0 && r.size <= 2);
  Quadrature<T, N> q;
  q.size = r.size;
  if (r.size == 1) {
    q.nodes[0] = r.alpha[0];
    q.weights[0] = r.beta[0];
  } else if (r.size == 2) {
    const T centre = (r.alpha[0] + r.alpha[1]) / T(2);
    const T half_gap = (r.alpha[1] - r.alpha[0]) / T(2);
    const T radius = sqrt(half_gap * half_gap + r.beta[1]);
    q.nodes[0] = centre - radius;
    q.nodes[1] = centre + radius;
    for (int i = 0; i < 2; ++i) {
      const T d = q.nodes[i] - r.alpha[0];
      q.weights[i] = r.beta[0] * r.beta[1] / (r.beta[1] + d * d);
    }
  }
  return q;
}

// Implicit QL with Wilkinson shifts on the symmetric tridiagonal J (the algorithm of
// EISPACK tql2: Bowdler, Martin, Reinsch & Wilkinson (1968), Numer. Math. 11, 293–306),
// accumulating only the first row of the eigenvector matrix. Deflation is relative
// (|e_m| <= ε_mach (|d_m| + |d_{m+1}|)), so the result does not depend on units. Returns
// false if some eigenvalue needed more than 30 iterations (never observed; the quadrature
// is then left with size 0). Expects the recurrence in units where its entries are O(1) or
// at least far from overflow (inversion.hpp passes the scaled one): sqrt(f² + g²) is used
// for the rotations instead of hypot.
template <class T, int N>
FLUIDBED_HOST_DEVICE bool gauss_golub_welsch(const Recurrence<T, N>& r, Quadrature<T, N>& q) {
  using std::abs;
  using std::sqrt;
  const int n = r.size;
  FLUIDBED_EXPECTS(n >= 0 && n <= N);
  T d[N]{};
  T e[N]{};
  T z[N]{};
  for (int i = 0; i < n; ++i) {
    d[i] = r.alpha[i];
    e[i] = i + 1 < n ? sqrt(r.beta[i + 1]) : T(0);
  }
  if (n > 0) z[0] = T(1);
  const T eps = std::numeric_limits<T>::epsilon();
  for (int l = 0; l < n; ++l) {
    for (int iteration = 0;; ++iteration) {
      int m = l;
      while (m < n - 1 && abs(e[m]) > eps * (abs(d[m]) + abs(d[m + 1]))) ++m;
      if (m == l) break;
      if (iteration == 30) {
        q.size = 0;
        return false;
      }
      // Wilkinson shift from the leading 2×2 block, then the chase from m up to l.
      T g = (d[l + 1] - d[l]) / (T(2) * e[l]);
      T radius = sqrt(g * g + T(1));
      g = d[m] - d[l] + e[l] / (g + (g < T(0) ? -radius : radius));
      T s(1), c(1), p(0);
      int i = m - 1;
      for (; i >= l; --i) {
        const T f = s * e[i];
        const T b = c * e[i];
        radius = sqrt(f * f + g * g);
        e[i + 1] = radius;
        if (radius == T(0)) {  // underflow: split the matrix here and restart
          d[i + 1] -= p;
          e[m] = T(0);
          break;
        }
        s = f / radius;
        c = g / radius;
        g = d[i + 1] - p;
        radius = (d[i] - g) * s + T(2) * c * b;
        p = s * radius;
        d[i + 1] = g + p;
        g = c * radius - b;
        const T top = z[i + 1];  // the plane rotation, on the first eigenvector row only
        z[i + 1] = s * z[i] + c * top;
        z[i] = c * z[i] - s * top;
      }
      if (radius == T(0) && i >= l) continue;
      d[l] -= p;
      e[l] = g;
      e[m] = T(0);
    }
  }
  q.size = n;
  for (int i = 0; i < n; ++i) {
    q.nodes[i] = d[i];
    q.weights[i] = r.beta[0] * z[i] * z[i];
  }
  detail::sort_nodes(q);
  return true;
}

}  // namespace fluidbed::moments
