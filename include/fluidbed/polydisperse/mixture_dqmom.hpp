// fluidbed — Niemi's solids-mixture DQMOM: the algebraic class velocities and the
// volume-fraction consistency correction (seed 001 Ch. 5).
//
// Niemi, T. (2012), "Particle size distribution in CFD simulation of gas-particle flows", MSc
// thesis, Aalto University (seed 001), transports one solids "mixture" phase (α_s, v_s) with
// the usual two-fluid equations and n size classes q (volume fractions α_q, diameters d_q) whose
// momentum equations are replaced by an algebraic local-equilibrium balance. Two pieces of that
// model live here:
//
// 1. The class velocities (seed 001 eq. 112; eq. 115 for two classes, eq. 116 for three),
//
//      K_gq (v_g − v_q) + Σ_{p≠q} K'_pq (v_p − v_q) = (α_q/α_s) K_gs (v_g − v_s),   q = 1 … n,
//
//    solved for v_q given the gas velocity v_g and the mixture velocity v_s. It comes from
//    eliminating ∇p between the class momentum equation (eq. 90) and the mixture one (eq. 104)
//    with ρ_q = ρ_s (gravity drops out), local equilibrium ∂v_qs/∂t ≈ 0 (eq. 109), equal
//    convective accelerations (eq. 110), p_q ≈ (α_q/α_s) p_s (eq. 111) and the stresses dropped.
//    Seed 001's intermediate eq. 108 prints (α_q/α_s) Σ_q K_gq (v_g − v_q) inside the
//    α_q (…) bracket; redoing the elimination gives (1/α_s) Σ_q K_gq (v_g − v_q) there (the
//    printed factor would make the right-hand side α_q²/α_s K_gs (v_g − v_s)), and eq. 112 above
//    is the one consistent with the elimination; it is what is solved here. The model does not
//    enforce v_s = Σ_q α_q v_q/α_s (eq. 97): the solution generally violates it (by 1.8 cm/s in a
//    binary bed at v_g − v_s = 2.2 m/s), which is why the correction of piece 2 exists.
//
//    The coefficients, all in the pressure-gradient convention (the model's momentum equations
//    carry the buoyancy −α ∇p, eqs. 90 and 104; drag/drag_law.hpp):
//      K_gs = β(ε, |v_g − v_s|, d_s)           the mixture drag, ε = 1 − α_s, d_s the local
//                                              Sauter diameter α_s / Σ_q (α_q/d_q);
//      K_gq = (α_q/α_s) β(ε, |v_g − v_q|, d_q)  the class's share of the drag of a suspension of
//                                              d_q particles at the total voidage (for Ergun
//                                              150 α_q α_s μ_g/(ε d_q²) + 1.75 ρ_g α_q |v_g − v_q|/d_q,
//                                              for Wen–Yu ¾ C_D α_q ε ρ_g |v_g − v_q| ε^−2.65/d_q
//                                              with Re = ε ρ_g |v_g − v_q| d_q/μ_g, and
//                                              Gidaspow's switch on the total α_s);
//      K'_pq = Syamlal's solid–solid drag (kinetic_theory/solid_solid_drag.hpp; seed 001
//              eq. 91) with g_pq = g0(α_s) of a one-class radial distribution, C_f and e_pq.
//    β is any drag law of the library (drag/); the thesis uses Gidaspow (seed 001 eq. 45 and
//    Table 1) but states neither the per-class form of K_gq nor e_pq, C_f and g_pq for eq. 91.
//    The preset niemi_force_balance takes Gidaspow switched at α_s = 0.2, e_pq = 0.9 (Table 1's
//    e_ss), C_f = 0 and g_pq = g0(α_s) of eq. 24 (Ogawa, α_max = 0.63, Table 1). With these the
//    thesis's relaxation study of §6.6 (eq. 134, whose prefactor 1/α_q must be 1/(α_q ρ_q))
//    comes out within a few per cent of the printed values: 0.32 ms and 0.21 mm for 416 µm in
//    the dense bottom (thesis ≈ 0.30 ms, 0.20 mm), 26 ms for 255 µm in the dilute region
//    (thesis ≈ 25 ms).
//
//    Nonlinearity and Newton's method. K_gq depends on |v_g − v_q| and K'_pq = c_pq |v_p − v_q|
//    on the relative speed, so the balance is nonlinear; in 3-D it is a vector equation in which
//    the K's depend on the norms. Each equation is divided by α_q (K_gq and K'_pq are
//    proportional to α_q), so that a class with α_q = 0 gets the velocity of a tracer of its
//    size; the right-hand side per unit α_q, f = K_gs (v_g − v_s)/α_s, is the same for every
//    class. With w_q = v_g − v_q, u_pq = v_p − v_q, A_q = β_q/α_s and k_pq = K'_pq/(α_p α_q):
//
//      r_q = A_q(|w_q|) w_q + Σ_{p≠q} α_p k_pq(|u_pq|) u_pq − f,
//
//    with the analytic Jacobian (blocks of size 1 or 3; ŵ = w/|w|, û = u/|u|)
//
//      ∂r_q/∂v_q = −G_q − Σ_{p≠q} α_p P_pq,    ∂r_q/∂v_p = α_p P_pq,
//      G_q  = A_q (I − ŵŵᵀ) + (A_q + |w| dA_q/d|w|) ŵŵᵀ   (A_q I at w = 0),
//      P_pq = k_pq I + |u| dk_pq/d|u| ûûᵀ                   (= c|u| (I + ûûᵀ) for Syamlal; 0 at u = 0),
//
//    the derivatives in the speeds coming from the laws' with_derivatives (A + |w| dA/d|w| is
//    the drag law's force_slip_derivative, finite at zero slip). In 1-D the blocks are the
//    scalars A + |w| dA/d|w| and 2c|u|. The system is the gradient of a strictly convex
//    function wherever the drag forces β(w) w and K'(u) u increase with the speeds (true of every
//    law here), so its solution is unique. Newton is damped by halving the step until
//    ‖r‖² decreases (Armijo, 1e-4).
//
//    The start. f(u) = c|u| u has zero derivative at u = 0, so Newton started from v_q = v_s
//    (all u_pq = 0, the "kink" of |v_p − v_q|) sees no solid–solid coupling in its first step and
//    overshoots by the ratio K'/K_gq (10–10⁴); damped as here it needs 4–6 iterations instead of
//    3 in the thesis's cases. Seed 001 warm-starts from the previous time step instead. Without a warm start (initial_guess
//    empty) the start here is the solution of the linear system with the coefficients frozen:
//      A_q at |v_g − v_s|, k_pq = 0            → v⁽⁰⁾ (each class alone with the gas),
//      k_pq at r₀ = |v_p⁽⁰⁾ − v_q⁽⁰⁾|          → v⁽¹⁾, relative speeds r₁ (too small: K' frozen too high),
//      k_pq at √(r₀ r₁)                        → the start,
//    the geometric mean being exact for a pair dominated by K' = c|u| (r₁ = r*²/r₀). The start
//    has v_p ≠ v_q unless the classes are identical, in which case it is the exact solution.
//    With a warm start (the previous step's velocities) Newton starts there.
//
//    Convergence: max_q ‖r_q‖/s_q ≤ tolerance, s_q = A_q|w_q| + Σ_p α_p k_pq |u_pq| + |f| the sum of
//    the magnitudes of the terms of equation q (relative residual). The unknowns are v_q − v_s
//    (the balance involves velocity differences only), so that large absolute velocities cost no
//    accuracy. The default tolerance 64 ε_T (1.4e-14 in double, 7.6e-6 in float, 6.9e-18 in x87
//    long double) is met in 3 iterations from the frozen-coefficient start in the thesis's
//    cases (from v_q = v_s: 4–6), and in at most 5 for random cells of 1–8 classes, α_s from
//    1e-4 to 0.6, slips from −6 to +10 m/s; the residual reached is ~1 ε_T, so float, double,
//    long double and Boost.Multiprecision are all supported. A law with a jump in the slip (Schiller–Naumann at Re = 1000) can
//    stop Newton at the jump: status not_converged. No allocation: MaxClasses (a template
//    argument) bounds n, and the Jacobian (3 MaxClasses)² lives on the stack.
//
//    3-D. The balance is isotropic and its solution unique, so it is symmetric about the axis
//    v_g − v_s: v_q = v_s + s_q (v_g − v_s)/|v_g − v_s|, s_q the 1-D solution along that axis.
//    The n scalar equations per cell that the thesis counts are therefore the whole problem;
//    the vector form solved here (3n unknowns, the Jacobian above) gives the same answer from
//    the frozen-coefficient start, which lies on the axis, and matters for warm starts off it.
//
// 2. The volume-fraction consistency correction (seed 001 §5.3, eqs. 117–122). After a time
//    step the class fractions α̃_q, transported with their own velocities, no longer sum to the
//    transported mixture fraction α_s. The correction
//      (a) normalises each cell:         α_q = α̃_q α_s / Σ_q α̃_q           (eq. 120, so eq. 121 holds),
//      (b) scales each class globally:   α_q ← C_q α_q,  C_q = V_q^true / V_q,
//          V_q = Σ_cells α_q V_cell the current total after (a), V_q^true the class's true volume
//          (eq. 122: the thesis defines C_q = V_q/Ṽ_q with V_q "after the correction" and Ṽ_q
//          "the original, real volume", the inverse of the factor that restores the totals; the
//          factor here is the one that does, and reproduces the thesis's Figure 8),
//      (c) normalises again (eq. 120), and repeats (b)–(c) "a couple of times".
//    This is iterative proportional fitting (Deming & Stephan (1940), Ann. Math. Statist. 11,
//    427–444, doi:10.1214/aoms/1177731829) of the cells × classes table to the row sums α_s V_cell
//    and the column sums V_q^true: it converges (linearly) when the two sets of sums agree,
//    Σ_q V_q^true = Σ_cells α_s V_cell (the mixture and the class equations both conservative), and
//    cannot meet a tolerance below their mismatch otherwise (ConsistencyResult reports it). The
//    thesis notes that step (b) moves volume between distant cells, which is unphysical but small
//    (|C_q − 1| ≲ 1e-5 per step in its simulations).
#pragma once

#include "../core/config.hpp"  // first: its C++20 check precedes any C++20-only header

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "../core/domain.hpp"
#include "../core/errors.hpp"
#include "../core/parameters.hpp"
#include "../core/vector3.hpp"
#include "../drag/drag_law.hpp"
#include "../drag/gidaspow.hpp"
#include "../kinetic_theory/radial_distribution.hpp"
#include "../kinetic_theory/solid_solid_drag.hpp"
#include "../properties.hpp"

namespace fluidbed::polydisperse {

// ------------------------------------------------------------------------------------------
// 1. The class velocities of the mixture model (seed 001 eq. 112)
// ------------------------------------------------------------------------------------------

// The closures of the balance: the gas–solid drag law β (any law of drag/, used in the
// pressure-gradient convention), the one-class radial distribution evaluated at α_s for g_pq,
// Syamlal's solid–solid drag (its friction coefficient C_f) and the restitution coefficient e_pq
// between the classes.
template <class GasDrag = drag::GidaspowSwitched, class RadialDistribution = kinetic_theory::Ogawa>
struct MixtureForceBalance {
  GasDrag gas_drag;
  RadialDistribution radial_distribution;
  kinetic_theory::SyamlalSolidSolidDrag solid_solid_drag;
  double restitution;  // e_pq ∈ [0, 1]
};

// The settings of seed 001: Gidaspow's drag switched at α_s = 0.2 (eq. 45), K'_pq of eq. 91
// with e_pq = 0.9 (Table 1's e_ss), C_f = 0 and g_pq = g0(α_s) of eq. 24 (Ogawa et al., FLUENT's
// "Lun et al.", α_max = 0.63). The thesis does not state e_pq, C_f or g_pq; these are
// consistent with its relaxation times of §6.6 (top of this file).
inline constexpr auto niemi_force_balance = MixtureForceBalance<>{
    drag::GidaspowSwitched{}, kinetic_theory::Ogawa{0.63}, kinetic_theory::SyamlalSolidSolidDrag{0.0}, 0.9};

// One cell's state. Velocity is T (1-D: the vertical components) or Vector3<T> (3-D).
// fractions[q] = α_q ∈ [0, 1) with α_s = Σ_q α_q ∈ (0, 1), diameters[q] = d_q > 0 [m], one
// solids density ρ_s > 0 for every class (the model assumes ρ_q = ρ_s), the gas (ρ_g, μ_g > 0).
// initial_guess: empty (the frozen-coefficient start) or n velocities (a warm start, e.g. the
// previous time step's v_q).
template <class T, class Velocity = T>
struct MixtureCell {
  std::span<const T> fractions;
  std::span<const T> diameters;
  T solids_density;
  Fluid<T> gas;
  Velocity gas_velocity;
  Velocity solids_velocity;
  std::span<const Velocity> initial_guess{};
};

enum class ForceBalanceStatus {
  converged,      // max_q ‖r_q‖/s_q <= tolerance
  not_converged,  // iteration cap, a line search that found no decrease, or a singular Jacobian:
                  // the velocities are the last iterate, `residual` says how good they are
  invalid_input,  // a size, a fraction, a diameter, a property, a velocity or a parameter out of
                  // its domain: nothing computed (velocities 0, NaN diagnostics)
};

template <class T>
struct ForceBalanceOptions {
  T tolerance = T(64) * std::numeric_limits<T>::epsilon();  // on max_q ‖r_q‖/s_q
  int max_iterations = 50;                                     // Newton iterations
};

template <class T, class Velocity, int MaxClasses>
struct ForceBalanceResult {
  std::array<Velocity, MaxClasses> velocities{};  // v_q, q < size
  int size = 0;
  ForceBalanceStatus status = ForceBalanceStatus::invalid_input;
  int iterations = 0;  // Newton iterations (Jacobian solves) after the start
  T residual = std::numeric_limits<T>::quiet_NaN();         // max_q ‖r_q‖/s_q at `velocities`
  T solids_fraction = std::numeric_limits<T>::quiet_NaN();  // α_s = Σ_q α_q
  T sauter_diameter = std::numeric_limits<T>::quiet_NaN();  // d_s = α_s / Σ_q (α_q/d_q) [m]
  T contact_rdf = std::numeric_limits<T>::quiet_NaN();      // g_pq = g0(α_s)
  T mixture_drag = std::numeric_limits<T>::quiet_NaN();     // K_gs [kg m⁻³ s⁻¹], pressure-gradient convention
};

namespace detail {

// 1 for a scalar velocity (any floating type, Boost.Multiprecision included), 3 for Vector3<T>.
template <class Velocity>
struct VelocityDimension : std::integral_constant<int, 1> {};
template <class T>
struct VelocityDimension<Vector3<T>> : std::integral_constant<int, 3> {};

template <class T, int D>
using Components = std::array<T, D>;

template <class T>
FLUIDBED_HOST_DEVICE constexpr Components<T, 1> components(const T& v) {
  return {v};
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr Components<T, 3> components(const Vector3<T>& v) {
  return v;
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr T velocity_from(const Components<T, 1>& c, const T*) {
  return c[0];
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr Vector3<T> velocity_from(const Components<T, 3>& c, const Vector3<T>*) {
  return c;
}

template <class T, int D>
FLUIDBED_HOST_DEVICE T norm(const Components<T, D>& a) {
  using std::abs;
  using std::sqrt;
  if constexpr (D == 1) {
    return abs(a[0]);
  } else {
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  }
}

template <class T>
FLUIDBED_HOST_DEVICE bool finite(const T& x) {
  return x - x == T(0);
}

// Gaussian elimination with partial pivoting of the m × m matrix a (row-major, leading
// dimension m) for `rhs` right-hand sides b[i·rhs + j], in place. False for a zero or non-finite
// pivot.
template <class T, std::size_t MM, std::size_t MR>
FLUIDBED_HOST_DEVICE bool solve_in_place(std::array<T, MM>& a, std::array<T, MR>& b, int m, int rhs) {
  using std::abs;
  for (int k = 0; k < m; ++k) {
    int pivot = k;
    T largest = abs(a[k * m + k]);
    for (int i = k + 1; i < m; ++i)
      if (abs(a[i * m + k]) > largest) {
        largest = abs(a[i * m + k]);
        pivot = i;
      }
    if (!(largest > T(0)) || !finite(largest)) return false;
    if (pivot != k) {
      for (int j = 0; j < m; ++j) {
        const T t = a[k * m + j];
        a[k * m + j] = a[pivot * m + j];
        a[pivot * m + j] = t;
      }
      for (int j = 0; j < rhs; ++j) {
        const T t = b[k * rhs + j];
        b[k * rhs + j] = b[pivot * rhs + j];
        b[pivot * rhs + j] = t;
      }
    }
    for (int i = k + 1; i < m; ++i) {
      const T factor = a[i * m + k] / a[k * m + k];
      if (factor == T(0)) continue;
      for (int j = k + 1; j < m; ++j) a[i * m + j] -= factor * a[k * m + j];
      for (int j = 0; j < rhs; ++j) b[i * rhs + j] -= factor * b[k * rhs + j];
    }
  }
  for (int i = m - 1; i >= 0; --i)
    for (int j = 0; j < rhs; ++j) {
      T sum = b[i * rhs + j];
      for (int l = i + 1; l < m; ++l) sum -= a[i * m + l] * b[l * rhs + j];
      b[i * rhs + j] = sum / a[i * m + i];
    }
  return true;
}

// The balance of one cell, per unit α_q, with the coefficients that do not depend on the class
// velocities evaluated once.
template <class T, int D, int N, class Model>
struct ForceBalanceSystem {
  static constexpr int M = D * N;
  using Vec = Components<T, D>;

  const Model& model;
  int n = 0;
  std::array<T, N> fraction{};  // α_q
  std::array<T, N> diameter{};  // d_q
  T solids_density{};
  Fluid<T> gas{};
  Vec solids_velocity{};  // v_s
  Vec gas_velocity{};     // v_g − v_s: the unknowns are x_q = v_q − v_s
  T solids_fraction{};    // α_s
  T voidage{};            // ε = 1 − α_s
  T sauter_diameter{};    // d_s
  T contact_rdf{};        // g0(α_s)
  T mixture_slip{};       // |v_g − v_s|
  T mixture_drag{};       // K_gs
  Vec force{};            // f = K_gs (v_g − v_s)/α_s
  T force_norm{};

  // A_q = β(ε, |w|, d_q)/α_s and A_q + |w| dA_q/d|w|.
  struct GasTerm {
    T coefficient, force_derivative;
  };
  FLUIDBED_HOST_DEVICE T gas_coefficient(int q, const T& slip) const {
    return model.gas_drag(drag::DragState<T>{voidage, slip, gas, diameter[q]}).pressure_gradient() /
           solids_fraction;
  }
  FLUIDBED_HOST_DEVICE GasTerm gas_term(int q, const T& slip) const {
    const auto b = model.gas_drag.with_derivatives(drag::DragState<T>{voidage, slip, gas, diameter[q]});
    return {b.pressure_gradient().value / solids_fraction,
            b.force_slip_derivative(drag::Buoyancy::pressure_gradient) / solids_fraction};
  }

  // k_pq = K'_pq/(α_p α_q) and dk_pq/d|u|: Syamlal's K' is proportional to α_p α_q, so it is
  // 4 K'(½, ½) exactly (a factor 4 is exact in binary).
  struct PairTerm {
    T coefficient, speed_derivative;
  };
  FLUIDBED_HOST_DEVICE T pair_coefficient(int p, int q, const T& speed) const {
    return 4 * model.solid_solid_drag(T(0.5), T(0.5), Particles<T>{solids_density, diameter[p]},
                                      Particles<T>{solids_density, diameter[q]}, T(model.restitution), contact_rdf,
                                      speed);
  }
  FLUIDBED_HOST_DEVICE PairTerm pair_term(int p, int q, const T& speed) const {
    const auto k = model.solid_solid_drag.with_derivatives(T(0.5), T(0.5), Particles<T>{solids_density, diameter[p]},
                                                           Particles<T>{solids_density, diameter[q]},
                                                           T(model.restitution), contact_rdf, speed);
    return {4 * k.value, 4 * k.d_relative_speed};
  }

  FLUIDBED_HOST_DEVICE Vec velocity(const std::array<T, M>& x, int q) const {
    Vec v;
    for (int i = 0; i < D; ++i) v[i] = x[q * D + i];
    return v;
  }

  // r (per unit α_q) at x, and max_q ‖r_q‖/s_q; returns ‖r‖² (NaN if anything is not finite).
  FLUIDBED_HOST_DEVICE T residual(const std::array<T, M>& x, std::array<T, M>& r, T& relative) const {
    std::array<T, N> scale{};
    for (int q = 0; q < n; ++q) {
      Vec w;
      for (int i = 0; i < D; ++i) w[i] = gas_velocity[i] - x[q * D + i];
      const T slip = norm<T, D>(w);
      const T a = gas_coefficient(q, slip);
      for (int i = 0; i < D; ++i) r[q * D + i] = a * w[i] - force[i];
      scale[q] = a * slip + force_norm;
    }
    for (int q = 0; q < n; ++q)
      for (int p = q + 1; p < n; ++p) {
        Vec u;  // v_p − v_q
        for (int i = 0; i < D; ++i) u[i] = x[p * D + i] - x[q * D + i];
        const T speed = norm<T, D>(u);
        const T k = pair_coefficient(p, q, speed);
        for (int i = 0; i < D; ++i) {
          r[q * D + i] += fraction[p] * k * u[i];
          r[p * D + i] -= fraction[q] * k * u[i];
        }
        scale[q] += fraction[p] * k * speed;
        scale[p] += fraction[q] * k * speed;
      }
    T squared(0);
    relative = T(0);
    bool finite_terms = true;
    for (int q = 0; q < n; ++q) {
      Vec rq;
      for (int i = 0; i < D; ++i) rq[i] = r[q * D + i];
      const T size = norm<T, D>(rq);
      squared += size * size;
      const T e = size == T(0) ? T(0) : size / scale[q];
      finite_terms = finite_terms && finite(e);
      if (e > relative) relative = e;
    }
    if (!finite_terms || !finite(squared)) {
      relative = std::numeric_limits<T>::quiet_NaN();
      return relative;
    }
    return squared;
  }

  // J = ∂r/∂x at x (row-major, m × m with m = nD).
  FLUIDBED_HOST_DEVICE void jacobian(const std::array<T, M>& x, std::array<T, M * M>& j) const {
    const int m = n * D;
    for (int i = 0; i < m * m; ++i) j[i] = T(0);
    // −G_q on the diagonal blocks.
    for (int q = 0; q < n; ++q) {
      Vec w;
      for (int i = 0; i < D; ++i) w[i] = gas_velocity[i] - x[q * D + i];
      const T slip = norm<T, D>(w);
      const GasTerm g = gas_term(q, slip);
      for (int a = 0; a < D; ++a) {
        j[(q * D + a) * m + q * D + a] -= g.coefficient;
        if (slip > T(0))
          for (int b = 0; b < D; ++b)
            j[(q * D + a) * m + q * D + b] -= (g.force_derivative - g.coefficient) * (w[a] / slip) * (w[b] / slip);
      }
    }
    // P_pq = k I + |u| dk/d|u| ûûᵀ: +α_p P in block (q, p), −α_p P in (q, q); the same with p, q swapped.
    for (int q = 0; q < n; ++q)
      for (int p = q + 1; p < n; ++p) {
        Vec u;
        for (int i = 0; i < D; ++i) u[i] = x[p * D + i] - x[q * D + i];
        const T speed = norm<T, D>(u);
        const PairTerm k = pair_term(p, q, speed);
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) {
            T pab = a == b ? k.coefficient : T(0);
            if (speed > T(0)) pab += k.speed_derivative * u[a] * u[b] / speed;
            j[(q * D + a) * m + p * D + b] += fraction[p] * pab;
            j[(q * D + a) * m + q * D + b] -= fraction[p] * pab;
            j[(p * D + a) * m + q * D + b] += fraction[q] * pab;
            j[(p * D + a) * m + p * D + b] -= fraction[q] * pab;
          }
      }
  }

  // The solution of the balance with A_q frozen at |v_g − v_s| and k_pq frozen at `speed(p, q)`
  // (a linear system, the same n × n matrix for every component).
  template <class Speed>
  FLUIDBED_HOST_DEVICE bool frozen_solution(const std::array<T, N>& a, const Speed& speed,
                                            std::array<T, M>& x) const {
    std::array<T, N * N> matrix{};
    std::array<T, N * D> rhs{};
    for (int q = 0; q < n; ++q) {
      matrix[q * n + q] = a[q];
      for (int i = 0; i < D; ++i) rhs[q * D + i] = a[q] * gas_velocity[i] - force[i];
    }
    for (int q = 0; q < n; ++q)
      for (int p = q + 1; p < n; ++p) {
        const T k = pair_coefficient(p, q, speed(p, q));
        matrix[q * n + q] += fraction[p] * k;
        matrix[q * n + p] -= fraction[p] * k;
        matrix[p * n + p] += fraction[q] * k;
        matrix[p * n + q] -= fraction[q] * k;
      }
    if (!solve_in_place(matrix, rhs, n, D)) return false;
    for (int i = 0; i < n * D; ++i) x[i] = rhs[i];
    return true;
  }

  FLUIDBED_HOST_DEVICE bool cold_start(std::array<T, M>& x) const {
    using std::sqrt;
    std::array<T, N> a{};
    for (int q = 0; q < n; ++q) a[q] = gas_coefficient(q, mixture_slip);
    std::array<T, M> x0{}, x1{};
    const auto relative_speed = [](const std::array<T, M>& v, int p, int q) {
      Vec u;
      for (int i = 0; i < D; ++i) u[i] = v[p * D + i] - v[q * D + i];
      return norm<T, D>(u);
    };
    if (!frozen_solution(a, [](int, int) { return T(0); }, x0)) return false;
    if (!frozen_solution(a, [&](int p, int q) { return relative_speed(x0, p, q); }, x1)) return false;
    return frozen_solution(
        a, [&](int p, int q) { return sqrt(relative_speed(x0, p, q) * relative_speed(x1, p, q)); }, x);
  }
};

// The system of a valid cell (check_cell): α_s, d_s, g0(α_s), K_gs and f evaluated once. The
// unknowns are the class velocities relative to the mixture, x_q = v_q − v_s (the balance depends
// on velocity differences only), so that the round-off of large absolute velocities does not set
// a floor under the residual.
template <int MaxClasses, class T, class Velocity, class Model>
ForceBalanceSystem<T, VelocityDimension<Velocity>::value, MaxClasses, Model> make_force_balance_system(
    const Model& model, const MixtureCell<T, Velocity>& cell) {
  constexpr int D = VelocityDimension<Velocity>::value;
  ForceBalanceSystem<T, D, MaxClasses, Model> system{model};
  system.n = int(cell.fractions.size());
  system.solids_density = cell.solids_density;
  system.gas = cell.gas;
  system.solids_velocity = components(cell.solids_velocity);
  system.gas_velocity = components(cell.gas_velocity);
  for (int i = 0; i < D; ++i) system.gas_velocity[i] -= system.solids_velocity[i];
  T alpha_s(0), inverse_diameter_sum(0);
  for (int q = 0; q < system.n; ++q) {
    system.fraction[q] = cell.fractions[q];
    system.diameter[q] = cell.diameters[q];
    alpha_s += cell.fractions[q];
    inverse_diameter_sum += cell.fractions[q] / cell.diameters[q];
  }
  system.solids_fraction = alpha_s;
  system.voidage = 1 - alpha_s;
  system.sauter_diameter = alpha_s / inverse_diameter_sum;
  system.contact_rdf = model.radial_distribution(alpha_s);
  system.mixture_slip = norm<T, D>(system.gas_velocity);
  system.mixture_drag =
      model.gas_drag(drag::DragState<T>{system.voidage, system.mixture_slip, cell.gas, system.sauter_diameter})
          .pressure_gradient();
  for (int i = 0; i < D; ++i) system.force[i] = system.mixture_drag * system.gas_velocity[i] / alpha_s;
  system.force_norm = system.mixture_drag * system.mixture_slip / alpha_s;
  return system;
}

inline constexpr std::string_view force_balance_function = "polydisperse::solve_force_balance";

// The domain of a cell and of the model, declared once: under Checked the first violation throws
// std::domain_error naming it; under Unchecked the function returns false.
template <ErrorPolicy Policy, int MaxClasses, class T, class Velocity, class Model>
bool check_cell(Policy, const MixtureCell<T, Velocity>& cell, const Model& model) {
  constexpr bool throws = std::same_as<Policy, Checked>;
  constexpr std::size_t whole = std::size_t(-1);  // not an element of an array argument
  const auto fail = [](std::string_view argument, std::size_t index, const auto& value, std::string_view requirement) {
    if constexpr (throws)
      fluidbed::detail::throw_domain_error(force_balance_function,
                                           index == whole ? std::string(argument) : indexed_argument(argument, index),
                                           value, requirement);
    return false;
  };
  const std::size_t n = cell.fractions.size();
  if (n < 1 || n > std::size_t(MaxClasses))
    return fail("fractions.size()", whole, n, "must lie in [1, MaxClasses]");
  if (cell.diameters.size() != n) return fail("diameters.size()", whole, cell.diameters.size(), "must equal fractions.size()");
  if (!cell.initial_guess.empty() && cell.initial_guess.size() != n)
    return fail("initial_guess.size()", whole, cell.initial_guess.size(), "must be 0 or fractions.size()");
  T total(0);
  for (std::size_t q = 0; q < n; ++q) {
    if (!domains::closed_open(T(0), T(1)).contains(cell.fractions[q]))
      return fail("fractions", q, cell.fractions[q], "must lie in [0, 1)");
    if (!domains::positive<T>().contains(cell.diameters[q]))
      return fail("diameters", q, cell.diameters[q], "must be finite and > 0");
    total += cell.fractions[q];
  }
  if (!domains::open(T(0), T(1)).contains(total))
    return fail("sum of fractions", whole, total, "must lie in (0, 1): some solids, some gas");
  if (!domains::positive<T>().contains(cell.solids_density))
    return fail("solids_density", whole, cell.solids_density, "must be finite and > 0");
  if (!domains::positive<T>().contains(cell.gas.density))
    return fail("gas.density", whole, cell.gas.density, "must be finite and > 0");
  if (!domains::positive<T>().contains(cell.gas.viscosity))
    return fail("gas.viscosity", whole, cell.gas.viscosity, "must be finite and > 0");
  const auto gas_velocity = components(cell.gas_velocity);
  const auto solids_velocity = components(cell.solids_velocity);
  for (std::size_t i = 0; i < gas_velocity.size(); ++i) {
    if (!finite(gas_velocity[i])) return fail("gas_velocity", i, gas_velocity[i], "must be finite");
    if (!finite(solids_velocity[i])) return fail("solids_velocity", i, solids_velocity[i], "must be finite");
  }
  for (std::size_t q = 0; q < cell.initial_guess.size(); ++q)
    for (const T& c : components(cell.initial_guess[q]))
      if (!finite(c)) return fail("initial_guess", q, c, "must be finite");
  if (!domains::closed(0.0, 1.0).contains(model.restitution))
    return fail("restitution", whole, model.restitution, "must lie in [0, 1]");
  if constexpr (throws) {
    fluidbed::require_within(model.gas_drag.name(), parameter_domain_in_double(model.gas_drag));
    fluidbed::require_within(model.radial_distribution.name(), parameter_domain_in_double(model.radial_distribution));
    fluidbed::require_within(model.solid_solid_drag.name(), parameter_domain_in_double(model.solid_solid_drag));
    return true;
  } else {
    return fluidbed::within(parameter_domain_in_double(model.gas_drag)) &&
           fluidbed::within(parameter_domain_in_double(model.radial_distribution)) &&
           fluidbed::within(parameter_domain_in_double(model.solid_solid_drag));
  }
}

}  // namespace detail

// Solves seed 001 eq. 112 for the class velocities v_q of one cell (see the top of this file for
// the coefficients, the start and the convergence test). MaxClasses bounds the number of
// classes n = cell.fractions.size(); Velocity = T solves the 1-D (vertical) balance, Vector3<T>
// the 3-D one. The error policy picks the hot path (fluidbed::unchecked: an argument out of its
// domain gives status invalid_input) or fluidbed::checked (it throws std::domain_error naming the
// argument and its value; the solve's own outcome is still a status).
template <int MaxClasses, class T, class Velocity, class GasDrag, class RadialDistribution,
          ErrorPolicy Policy = Unchecked>
ForceBalanceResult<T, Velocity, MaxClasses> solve_force_balance(
    const MixtureForceBalance<GasDrag, RadialDistribution>& model, const MixtureCell<T, Velocity>& cell,
    const ForceBalanceOptions<T>& options = {}, Policy policy = {}) {
  static_assert(MaxClasses >= 1, "MaxClasses must be at least 1");
  constexpr int D = detail::VelocityDimension<Velocity>::value;
  using System = detail::ForceBalanceSystem<T, D, MaxClasses, MixtureForceBalance<GasDrag, RadialDistribution>>;
  constexpr int M = System::M;
  using Vec = typename System::Vec;

  ForceBalanceResult<T, Velocity, MaxClasses> result;
  if (!detail::check_cell<Policy, MaxClasses>(policy, cell, model)) return result;
  const int n = int(cell.fractions.size());
  result.size = n;

  const System system = detail::make_force_balance_system<MaxClasses>(model, cell);
  result.solids_fraction = system.solids_fraction;
  result.sauter_diameter = system.sauter_diameter;
  result.contact_rdf = system.contact_rdf;
  result.mixture_drag = system.mixture_drag;
  const Vec& vs = system.solids_velocity;

  // The start.
  std::array<T, M> x{};
  bool started = true;
  if (!cell.initial_guess.empty()) {
    for (int q = 0; q < n; ++q) {
      const Vec v = detail::components(cell.initial_guess[q]);
      for (int i = 0; i < D; ++i) x[q * D + i] = v[i] - vs[i];
    }
  } else {
    started = system.cold_start(x);
  }
  const auto finish = [&](ForceBalanceStatus status, const T& relative) {
    for (int q = 0; q < n; ++q) {
      Vec v = system.velocity(x, q);
      for (int i = 0; i < D; ++i) v[i] += vs[i];
      result.velocities[q] = detail::velocity_from(v, &cell.gas_velocity);
    }
    result.status = status;
    result.residual = relative;
    return result;
  };
  if (!started) return finish(ForceBalanceStatus::not_converged, std::numeric_limits<T>::quiet_NaN());

  std::array<T, M> r{};
  T relative(0);
  T merit = system.residual(x, r, relative);
  if (!detail::finite(merit)) return finish(ForceBalanceStatus::not_converged, relative);
  if (relative <= options.tolerance) return finish(ForceBalanceStatus::converged, relative);

  const int m = n * D;
  std::array<T, M * M> jacobian{};
  std::array<T, M> step{}, trial{}, r_trial{};
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    system.jacobian(x, jacobian);
    for (int i = 0; i < m; ++i) step[i] = -r[i];
    if (!detail::solve_in_place(jacobian, step, m, 1)) return finish(ForceBalanceStatus::not_converged, relative);
    result.iterations = iteration;
    // Damped step: halve λ until ‖r‖² decreases by the Armijo fraction 1e-4 of its slope −2‖r‖²
    // along the Newton direction. A full step that meets the tolerance is taken even where
    // round-off keeps ‖r‖² from decreasing.
    T lambda(1);
    bool accepted = false;
    T trial_relative(0);
    for (int halving = 0; halving < 40 && !accepted; ++halving, lambda /= 2) {
      for (int i = 0; i < m; ++i) trial[i] = x[i] + lambda * step[i];
      const T trial_merit = system.residual(trial, r_trial, trial_relative);
      accepted = detail::finite(trial_merit) && (trial_merit <= (1 - T(2e-4) * lambda) * merit ||
                                                 (halving == 0 && trial_relative <= options.tolerance));
      if (accepted) {
        x = trial;
        r = r_trial;
        merit = trial_merit;
        relative = trial_relative;
      }
    }
    if (!accepted) return finish(ForceBalanceStatus::not_converged, relative);
    if (relative <= options.tolerance) return finish(ForceBalanceStatus::converged, relative);
  }
  return finish(ForceBalanceStatus::not_converged, relative);
}

// ------------------------------------------------------------------------------------------
// 2. The volume-fraction consistency correction (seed 001 §5.3, eqs. 117–122)
// ------------------------------------------------------------------------------------------
//
// Layout: class-major. fractions[q · cells + c] is α_q of cell c (each class's field contiguous,
// as a CFD code stores one field per phase); cells = mixture_fractions.size(), and
// fractions.size() must be classes · cells. cell_volumes: V_c > 0 per cell, or empty for equal
// cells (V_c = 1, so totals are sums of fractions). No allocation.

// Eq. 120 in every cell: α_q ← α_q α_s/Σ_q α_q. A cell with Σ_q α_q = 0 is left unchanged (all
// its class fractions 0; if α_s > 0 there it keeps Σ_q α_q ≠ α_s): returns the number of such
// cells with α_s > 0. Preconditions (asserted in debug builds): fractions.size() = classes ·
// mixture_fractions.size(), fractions >= 0.
template <class T>
FLUIDBED_HOST_DEVICE int normalise_class_fractions(std::span<T> fractions, int classes,
                                                   std::span<const T> mixture_fractions) {
  const std::size_t cells = mixture_fractions.size();
  FLUIDBED_EXPECTS(classes >= 1 && fractions.size() == std::size_t(classes) * cells);
  int unnormalisable = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    T sum(0);
    for (int q = 0; q < classes; ++q) sum += fractions[q * cells + c];
    if (sum > T(0)) {
      const T factor = mixture_fractions[c] / sum;
      for (int q = 0; q < classes; ++q) fractions[q * cells + c] *= factor;
    } else if (mixture_fractions[c] > T(0)) {
      ++unnormalisable;
    }
  }
  return unnormalisable;
}

// The class volumes V_q = Σ_c α_q,c V_c into volumes[0 … classes − 1] (cell_volumes empty: V_c = 1).
template <class T>
FLUIDBED_HOST_DEVICE void class_volumes(std::span<const T> fractions, int classes, std::span<const T> cell_volumes,
                                        std::span<T> volumes) {
  FLUIDBED_EXPECTS(classes >= 1 && volumes.size() >= std::size_t(classes) &&
                   fractions.size() % std::size_t(classes) == 0);
  const std::size_t cells = fractions.size() / std::size_t(classes);
  FLUIDBED_EXPECTS(cell_volumes.empty() || cell_volumes.size() == cells);
  for (int q = 0; q < classes; ++q) {
    T sum(0);
    for (std::size_t c = 0; c < cells; ++c)
      sum += cell_volumes.empty() ? fractions[q * cells + c] : fractions[q * cells + c] * cell_volumes[c];
    volumes[q] = sum;
  }
}

enum class ConsistencyStatus {
  tolerance_met,    // max_q |V_q/V_q^true − 1| <= tolerance after the last normalisation
  iteration_limit,  // max_iterations corrections done without meeting the tolerance (always, for
                    // tolerance 0 and inexact totals: the thesis's fixed count of iterations)
  invalid_input,    // sizes, a negative or non-finite fraction or volume, α_s ∉ [0, 1]: nothing changed
};

template <class T>
struct ConsistencyOptions {
  int max_iterations = 3;  // global corrections, each followed by eq. 120 ("2–3 in practice")
  T tolerance = T(0);      // on max_q |V_q/V_q^true − 1|; 0: always max_iterations corrections
};

template <class T>
struct ConsistencyResult {
  ConsistencyStatus status = ConsistencyStatus::invalid_input;
  int iterations = 0;  // global corrections done
  T relative_error = std::numeric_limits<T>::quiet_NaN();  // max_q |V_q/V_q^true − 1| at the end
  // Σ_q V_q^true / Σ_c α_s,c V_c − 1: the tolerance cannot be met below about this
  T mixture_mismatch = std::numeric_limits<T>::quiet_NaN();
  int unnormalisable_cells = 0;  // cells with α_s > 0 and no class fraction (left unchanged)
};

namespace detail {

inline constexpr std::string_view consistency_function = "polydisperse::correct_class_fractions";

template <ErrorPolicy Policy, int MaxClasses, class T>
bool check_consistency_input(Policy, std::span<const T> fractions, int classes, std::span<const T> mixture,
                             std::span<const T> cell_volumes, std::span<const T> true_volumes,
                             const ConsistencyOptions<T>& options) {
  constexpr bool throws = std::same_as<Policy, Checked>;
  const auto fail = [](std::string_view argument, const auto& value, std::string_view requirement) {
    if constexpr (throws) fluidbed::detail::throw_domain_error(consistency_function, argument, value, requirement);
    return false;
  };
  const std::size_t cells = mixture.size();
  if (classes < 1 || classes > MaxClasses) return fail("classes", classes, "must lie in [1, MaxClasses]");
  if (fractions.size() != std::size_t(classes) * cells)
    return fail("fractions.size()", fractions.size(), "must equal classes * mixture_fractions.size()");
  if (!cell_volumes.empty() && cell_volumes.size() != cells)
    return fail("cell_volumes.size()", cell_volumes.size(), "must be 0 or mixture_fractions.size()");
  if (!true_volumes.empty() && true_volumes.size() != std::size_t(classes))
    return fail("true_volumes.size()", true_volumes.size(), "must be 0 or classes");
  if (options.max_iterations < 0) return fail("max_iterations", options.max_iterations, "must be >= 0");
  if (!domains::non_negative<T>().contains(options.tolerance))
    return fail("tolerance", options.tolerance, "must be finite and >= 0");
  for (const T& a : fractions)
    if (!domains::non_negative<T>().contains(a)) return fail("fractions", a, "must be finite and >= 0");
  for (const T& a : mixture)
    if (!domains::closed(T(0), T(1)).contains(a)) return fail("mixture_fractions", a, "must lie in [0, 1]");
  for (const T& v : cell_volumes)
    if (!domains::positive<T>().contains(v)) return fail("cell_volumes", v, "must be finite and > 0");
  for (const T& v : true_volumes)
    if (!domains::non_negative<T>().contains(v)) return fail("true_volumes", v, "must be finite and >= 0");
  return true;
}

// max_q |V_q/V_q^true − 1| (|V_q| where V_q^true = 0).
template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE T max_relative_error(const std::array<T, N>& volumes, const std::array<T, N>& targets,
                                          int classes) {
  using std::abs;
  T largest(0);
  for (int q = 0; q < classes; ++q) {
    const T e = targets[q] > T(0) ? abs(volumes[q] / targets[q] - 1) : abs(volumes[q]);
    if (e > largest) largest = e;
  }
  return largest;
}

}  // namespace detail

// Seed 001's consistency correction (eqs. 120–122, see the top of this file) of the class
// fractions in place: eq. 120 in every cell, then up to options.max_iterations times the global
// factors C_q = V_q^true/V_q and eq. 120 again, stopping early once max_q |V_q/V_q^true − 1| <=
// options.tolerance. true_volumes: V_q^true per class, or empty for the class volumes of the
// fractions as given (the transported α̃_q, which conservative class equations keep at the true
// volumes). A class whose current volume is 0 is not scaled. MaxClasses bounds `classes`. Error
// policy: unchecked gives status invalid_input (nothing changed), checked throws
// std::domain_error, for input out of its domain.
template <int MaxClasses, class T, ErrorPolicy Policy = Unchecked>
ConsistencyResult<T> correct_class_fractions(std::span<T> fractions, int classes,
                                             std::span<const T> mixture_fractions, std::span<const T> cell_volumes,
                                             std::span<const T> true_volumes, const ConsistencyOptions<T>& options = {},
                                             Policy policy = {}) {
  ConsistencyResult<T> result;
  if (!detail::check_consistency_input<Policy, MaxClasses, T>(policy, fractions, classes, mixture_fractions,
                                                               cell_volumes, true_volumes, options))
    return result;
  const std::size_t cells = mixture_fractions.size();
  const std::span<const T> view(fractions.data(), fractions.size());

  std::array<T, MaxClasses> targets{}, volumes{};
  if (true_volumes.empty())
    class_volumes<T>(view, classes, cell_volumes, std::span<T>(targets.data(), std::size_t(classes)));
  else
    for (int q = 0; q < classes; ++q) targets[q] = true_volumes[q];
  T mixture_volume(0), target_sum(0);
  for (std::size_t c = 0; c < cells; ++c)
    mixture_volume += cell_volumes.empty() ? mixture_fractions[c] : mixture_fractions[c] * cell_volumes[c];
  for (int q = 0; q < classes; ++q) target_sum += targets[q];
  result.mixture_mismatch = mixture_volume > T(0) ? target_sum / mixture_volume - 1 : target_sum;

  result.unnormalisable_cells = normalise_class_fractions<T>(fractions, classes, mixture_fractions);
  const std::span<T> volume_span(volumes.data(), std::size_t(classes));
  class_volumes<T>(view, classes, cell_volumes, volume_span);
  result.relative_error = detail::max_relative_error(volumes, targets, classes);
  while (result.relative_error > options.tolerance && result.iterations < options.max_iterations) {
    for (int q = 0; q < classes; ++q) {
      if (!(volumes[q] > T(0))) continue;
      const T factor = targets[q] / volumes[q];  // C_q
      for (std::size_t c = 0; c < cells; ++c) fractions[q * cells + c] *= factor;
    }
    result.unnormalisable_cells = normalise_class_fractions<T>(fractions, classes, mixture_fractions);
    class_volumes<T>(view, classes, cell_volumes, volume_span);
    result.relative_error = detail::max_relative_error(volumes, targets, classes);
    ++result.iterations;
  }
  result.status = result.relative_error <= options.tolerance ? ConsistencyStatus::tolerance_met
                                                             : ConsistencyStatus::iteration_limit;
  return result;
}

}  // namespace fluidbed::polydisperse
