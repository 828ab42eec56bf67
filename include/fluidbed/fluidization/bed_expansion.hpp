// fluidbed — homogeneous expansion of a fluidized bed: the equilibrium voidage a drag
// law predicts, the Richardson–Zaki expansion it should match, and how to compare them.
//
// At homogeneous equilibrium, with the particles at rest and the fluid at superficial
// velocity u_s (interstitial slip w = u_s/ε), the drag carries the buoyant weight of the
// particles (seed 000 eqs. 3.26–3.28, classical buoyancy):
//
//   β_classical(ε, u_s/ε) · u_s/ε = (1 − ε)(ρ_p − ρ_f) g.                       (3.28)
//
// The multiphase Reynolds number at equilibrium is Re = ρ_f ε w d/μ_f = ρ_f u_s d/μ_f, the
// same for every voidage and every law, and Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f².
#pragma once

#include <cmath>
#include <concepts>
#include <optional>
#include <string_view>

#include "../core/root_finding.hpp"
#include "../drag/any_drag_law.hpp"
#include "../drag/drag_law.hpp"
#include "../drag/single_particle.hpp"
#include "../properties.hpp"
#include "richardson_zaki.hpp"
#include "terminal_velocity.hpp"

namespace fluidbed::settling {

// What the equilibrium solvers accept: a law with the DragLaw calling shape (β from
// law(state).classical(), ∂β/∂ε from law.with_derivatives(state)), or drag::AnyDragLaw.
template <class Law, class T>
concept DragLawFor = std::same_as<Law, drag::AnyDragLaw> || requires(const Law& law, const drag::DragState<T>& state) {
  { law(state).classical() } -> std::convertible_to<T>;
  { law.with_derivatives(state).classical().d_voidage } -> std::convertible_to<T>;
};

namespace detail {

// β_classical and ∂β_classical/∂ε of a law with the DragLaw calling shape, or of a
// run-time-selected drag::AnyDragLaw.
template <class Law, class T>
T classical_beta(const Law& law, const drag::DragState<T>& state) {
  return law(state).classical();
}
template <class T>
T classical_beta(const drag::AnyDragLaw& law, const drag::DragState<T>& state) {
  return drag::evaluate(law, state).classical();
}
template <class Law, class T>
T classical_beta_voidage_slope(const Law& law, const drag::DragState<T>& state) {
  return law.with_derivatives(state).classical().d_voidage;
}
template <class T>
T classical_beta_voidage_slope(const drag::AnyDragLaw& law, const drag::DragState<T>& state) {
  return drag::evaluate_with_derivatives(law, state).classical().d_voidage;
}

// The equilibrium relation (3.28) divided by (1 − ε)(ρ_p − ρ_f) g, minus one:
//
//   G(ε) = β_classical(ε, u_s/ε) u_s / (ε (1 − ε) (ρ_p − ρ_f) g) − 1,
//
// which removes the trivial root ε = 1 (β vanishes with the solids fraction). At ε = 1 it
// takes its limit: β(1, w) = 0 for every w, so β(ε, u_s/ε)/(1 − ε) → −∂β/∂ε(1, u_s), the
// single-particle drag; G(1) < 0 exactly when u_s is below the law's own single-particle
// terminal velocity. G → +∞ as ε → 0.
template <class Law, class T>
struct EquilibriumResidual {
  const Law& law;
  T superficial_velocity;
  Fluid<T> fluid;
  T diameter;
  T weight;  // (ρ_p − ρ_f) g

  T operator()(const T& voidage) const {
    const T& u = superficial_velocity;
    if (voidage == T(1))
      return -classical_beta_voidage_slope(law, drag::DragState<T>{T(1), u, fluid, diameter}) * u / weight - 1;
    const T slip = u / voidage;
    return classical_beta(law, drag::DragState<T>{voidage, slip, fluid, diameter}) * slip / ((1 - voidage) * weight) -
           1;
  }
};

template <class T>
[[noreturn]] void throw_no_homogeneous_bed(std::string_view function, const T& superficial_velocity) {
  fluidbed::detail::throw_domain_error(
      function, "superficial_velocity", superficial_velocity,
      "at or above the single-particle terminal velocity: no homogeneous bed, the particles are carried out");
}

}  // namespace detail

// ----------------------------------------------------------------------------- any drag law

// The voidage at which `law` holds a homogeneous bed in equilibrium at the superficial
// velocity u_s (seed 000 eq. 3.28), or nothing when u_s is at or above the law's own
// single-particle terminal velocity (the limit of eq. 3.28 as ε → 1): then there is no
// homogeneous bed, the particles are carried out.
//
// `law` is any type with the DragLaw calling shape (law(DragState<T>).classical() and
// law.with_derivatives(state)), or a run-time-selected drag::AnyDragLaw. The relation is
// divided by (1 − ε) to remove the trivial root ε = 1 and solved with Boost.Math toms748
// on a bracket in (0, 1]. Every law of the library gives a residual that decreases with ε
// and so a single root; for a law with several, the lowest is returned: the scan on
// ε = k/64 brackets the first sign change (roots closer together than 1/64 may be passed
// over). A law discontinuous in ε (drag::GidaspowSwitched at ε = 0.8) may change sign at
// its jump without a root; the jump is then returned, the only voidage where the bed can
// sit. At a fixed u_s the Reynolds number is fixed, so Reynolds switches (the
// Schiller–Naumann one at Re = 1000) are never crossed.
// Below minimum fluidization the returned voidage is lower than the packed bed's: the law
// balances the weight only in a bed denser than the real one, which stays fixed.
// Nothing is also returned if the law balances the weight at no voidage above 2⁻⁷⁰
// (G > 0 somewhere near ε = 0 holds for every law of the library).
// Preconditions: u_s > 0, ρ_f, μ_f, d, g > 0, ρ_p > ρ_f.
template <class Law, class T>
requires DragLawFor<Law, T> std::optional<T> equilibrium_voidage(const Law& law, const T& superficial_velocity,
                                                                 const Fluid<T>& fluid, const Particles<T>& particles,
                                                                 const T& gravity = standard_gravity_as<T>()) {
  FLUIDBED_EXPECTS(superficial_velocity > T(0) && detail::valid_settling_inputs(fluid, particles, gravity));
  const detail::EquilibriumResidual<Law, T> residual{law, superficial_velocity, fluid, particles.diameter,
                                                     (particles.density - fluid.density) * gravity};
  const T at_one = residual(T(1));
  if (!(at_one < T(0))) return std::nullopt;  // u_s >= the law's single-particle u_t
  // Bracket the lowest root: scan ε = k/64 upwards for the first sign change, or, if G
  // is already <= 0 at 1/64, halve towards ε = 0, where G → +∞.
  constexpr int scan_intervals = 64;
  constexpr int max_halvings = 64;
  T lower = T(1) / scan_intervals;
  T at_lower = residual(lower);
  T upper = T(1);
  T at_upper = at_one;
  if (at_lower > T(0)) {
    for (int k = 2; k < scan_intervals; ++k) {
      const T next = T(k) / scan_intervals;
      const T at_next = residual(next);
      if (!(at_next > T(0))) {
        upper = next;
        at_upper = at_next;
        break;
      }
      lower = next;
      at_lower = at_next;
    }
  } else {
    for (int halving = 0; !(at_lower > T(0)); ++halving) {
      if (halving == max_halvings) return std::nullopt;  // the law balances the weight nowhere
      upper = lower;
      at_upper = at_lower;
      lower /= 2;
      at_lower = residual(lower);
    }
  }
  if (at_upper == T(0)) return upper;
  return fluidbed::detail::bracketed_root(residual, lower, upper, at_lower, at_upper);
}

// As equilibrium_voidage, validating its arguments; throws std::domain_error when there
// is no homogeneous bed.
template <class Law, class T>
requires DragLawFor<Law, T> T equilibrium_voidage_checked(const Law& law, const T& superficial_velocity,
                                                          const Fluid<T>& fluid, const Particles<T>& particles,
                                                          const T& gravity = standard_gravity_as<T>()) {
  constexpr std::string_view function = "equilibrium_voidage";
  detail::validate_settling(function, fluid, particles, gravity);
  require_positive(function, "superficial_velocity", superficial_velocity);
  const std::optional<T> voidage = equilibrium_voidage(law, superficial_velocity, fluid, particles, gravity);
  if (!voidage) detail::throw_no_homogeneous_bed(function, superficial_velocity);
  return *voidage;
}

// ----------------------------------------------------------------------------- Richardson–Zaki

// The Richardson–Zaki expansion ε = (u_s/u_t)^(1/n) with Dallavalle's u_t and n from
// seed 000 eq. 3.24 at Re_t: the ε_R&Z column of seed 000 Table 4.4 (only Dallavalle's u_t
// reproduces it), and exactly the expansion of the Mazzei–Lettieri drag. Nothing when u_s >= u_t.
// Preconditions: u_s > 0, ρ_f, μ_f, d, g > 0, ρ_p > ρ_f.
template <class T>
std::optional<T> richardson_zaki_equilibrium_voidage(const T& superficial_velocity, const Fluid<T>& fluid,
                                                     const Particles<T>& particles,
                                                     const T& gravity = standard_gravity_as<T>()) {
  FLUIDBED_EXPECTS(superficial_velocity > T(0));
  const T terminal = terminal_velocity_dallavalle(fluid, particles, gravity);
  if (!(superficial_velocity < terminal)) return std::nullopt;
  const T exponent = richardson_zaki_exponent_mazzei(terminal_reynolds(fluid, particles.diameter, terminal));
  return richardson_zaki_voidage(superficial_velocity, terminal, exponent);
}

template <class T>
T richardson_zaki_equilibrium_voidage_checked(const T& superficial_velocity, const Fluid<T>& fluid,
                                              const Particles<T>& particles,
                                              const T& gravity = standard_gravity_as<T>()) {
  constexpr std::string_view function = "richardson_zaki_equilibrium_voidage";
  detail::validate_settling(function, fluid, particles, gravity);
  require_positive(function, "superficial_velocity", superficial_velocity);
  const std::optional<T> voidage = richardson_zaki_equilibrium_voidage(superficial_velocity, fluid, particles, gravity);
  if (!voidage) detail::throw_no_homogeneous_bed(function, superficial_velocity);
  return *voidage;
}

// ----------------------------------------------------------------------------- comparisons

// ε_law / ε_R&Z at the equilibrium Reynolds number Re = ρ_f u_s d/μ_f and the
// Richardson–Zaki voidage ε_R&Z, as plotted in seed 000 Figs 3.1–3.5:
//   1. Re_t from Re = Re_t ε_R&Z^n(Re_t)           (richardson_zaki_terminal_reynolds);
//   2. Ar = ¾ C_D(Re_t) Re_t², Dallavalle's C_D   (the system whose R–Z bed that is);
//   3. ε_law from eq. 3.28 at (Re, Ar)            (equilibrium_voidage).
// The equilibrium depends on (Re, Ar) alone for any law built from ρ_f, μ_f, d and w, so
// step 3 runs in the units ρ_f = μ_f = d = 1, ρ_p − ρ_f = 1, g = Ar, u_s = Re. Nothing
// when the law has no homogeneous bed there (its single-particle u_t is below u_s; e.g.
// Ergun, at high Re and ε_R&Z, would need ε > 1). The ratio is 1 for Mazzei–Lettieri.
// Preconditions: Re > 0, ε_R&Z ∈ (0, 1).
template <class Law, class T>
requires DragLawFor<Law, T> std::optional<T> voidage_ratio(const Law& law, const T& reynolds,
                                                           const T& richardson_zaki_voidage) {
  FLUIDBED_EXPECTS(reynolds > T(0) && richardson_zaki_voidage > T(0) && richardson_zaki_voidage < T(1));
  const T re_t = richardson_zaki_terminal_reynolds(reynolds, richardson_zaki_voidage);
  const T ar = T(0.75) * drag::DallavalleCoefficient::cd_times_re(re_t) * re_t;
  const Fluid<T> unit_fluid{.density = T(1), .viscosity = T(1)};
  const Particles<T> unit_particles{.density = T(2), .diameter = T(1)};
  const std::optional<T> voidage = equilibrium_voidage(law, reynolds, unit_fluid, unit_particles, ar);
  if (!voidage) return std::nullopt;
  return *voidage / richardson_zaki_voidage;
}

// As voidage_ratio, validating its arguments (std::domain_error naming the argument and its value).
template <class Law, class T>
requires DragLawFor<Law, T> std::optional<T> voidage_ratio_checked(const Law& law, const T& reynolds,
                                                                   const T& richardson_zaki_voidage) {
  constexpr std::string_view function = "voidage_ratio";
  require_positive(function, "reynolds", reynolds);
  require_in_open(function, "richardson_zaki_voidage", richardson_zaki_voidage, T(0), T(1));
  return voidage_ratio(law, reynolds, richardson_zaki_voidage);
}

// The "equivalent exponent" of a law (seed 000 eq. 3.64): writing its β as
//   β_classical = ¾ C_D(Re) ρ_f w (1 − ε)/d · φ(ε, Re)   (eq. 3.61),
//   ψ_e(ε, Re) = −ln φ / ln ε,
// the voidage exponent a Wen–Yu-type law would need to give the same β. C_D is that of
// `Coefficient`, Dallavalle's by default as in eqs. 3.55–3.65; with
// drag::SchillerNaumannCoefficient a ConstantExponentDrag gives its α exactly. Re is the
// multiphase Reynolds number ρ_f ε w d/μ_f; ψ_e depends on (ε, Re) alone and is evaluated
// in the units ρ_f = μ_f = d = 1. At ε = 1 it is 0/0 (φ = 1): excluded.
// Preconditions: ε ∈ (0, 1), Re >= 0.
template <class Coefficient = drag::DallavalleCoefficient, class Law, class T>
requires DragLawFor<Law, T> T equivalent_exponent(const Law& law, const T& voidage, const T& reynolds) {
  using std::log;
  FLUIDBED_EXPECTS(voidage > T(0) && voidage < T(1) && !(reynolds < T(0)));
  const Fluid<T> unit_fluid{.density = T(1), .viscosity = T(1)};
  const T beta = detail::classical_beta(law, drag::DragState<T>{voidage, reynolds / voidage, unit_fluid, T(1)});
  const T single =
      drag::detail::single_particle_beta(Coefficient::cd_times_re(reynolds), voidage, unit_fluid.viscosity, T(1));
  return -log(beta / single) / log(voidage);
}

// As equivalent_exponent, validating its arguments (std::domain_error naming the argument and its value).
template <class Coefficient = drag::DallavalleCoefficient, class Law, class T>
requires DragLawFor<Law, T> T equivalent_exponent_checked(const Law& law, const T& voidage, const T& reynolds) {
  constexpr std::string_view function = "equivalent_exponent";
  require_in_open(function, "voidage", voidage, T(0), T(1));
  require_non_negative(function, "reynolds", reynolds);
  return equivalent_exponent<Coefficient>(law, voidage, reynolds);
}

// ----------------------------------------------------------------------------- bed height

// h = h₀ (1 − ε₀)/(1 − ε): the height of a bed of fixed solids inventory at voidage ε,
// given its height h₀ at ε₀ (solids volume conservation; seed 000 §4.3.3, eq. 4.5).
// Preconditions: h₀ > 0, ε₀, ε ∈ (0, 1).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T bed_height(const T& initial_height, const T& initial_voidage, const T& voidage) {
  FLUIDBED_EXPECTS(initial_height > T(0) && initial_voidage > T(0) && initial_voidage < T(1) && voidage > T(0) &&
                   voidage < T(1));
  return initial_height * (1 - initial_voidage) / (1 - voidage);
}

template <class T>
T bed_height_checked(const T& initial_height, const T& initial_voidage, const T& voidage) {
  require_positive("bed_height", "initial_height", initial_height);
  require_in_open("bed_height", "initial_voidage", initial_voidage, T(0), T(1));
  require_in_open("bed_height", "voidage", voidage, T(0), T(1));
  return bed_height(initial_height, initial_voidage, voidage);
}

}  // namespace fluidbed::settling
