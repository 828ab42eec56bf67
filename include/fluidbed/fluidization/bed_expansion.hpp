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
#include <type_traits>
#include <variant>

#include "../core/errors.hpp"
#include "../core/root_finding.hpp"
#include "../drag/drag_law.hpp"
#include "../properties.hpp"
#include "../settling/richardson_zaki.hpp"
#include "../single_particle/drag_coefficient.hpp"
#include "../single_particle/terminal_velocity_closed_forms.hpp"

namespace fluidbed::fluidization {

// One drag law with the DragLaw calling shape (β from law(state).classical(), ∂β/∂ε from
// law.with_derivatives(state)).
template <class Law, class T>
concept SingleDragLawFor = requires(const Law& law, const drag::DragState<T>& state) {
  { law(state).classical() } -> std::convertible_to<T>;
  { law.with_derivatives(state).classical().d_voidage } -> std::convertible_to<T>;
};

namespace detail {

template <class Law, class T>
struct is_variant_of_drag_laws : std::false_type {};
template <class... Laws, class T>
struct is_variant_of_drag_laws<std::variant<Laws...>, T> : std::bool_constant<(SingleDragLawFor<Laws, T> && ...)> {};

template <class Law>
inline constexpr bool is_variant = false;
template <class... Laws>
inline constexpr bool is_variant<std::variant<Laws...>> = true;

}  // namespace detail

// What the equilibrium solvers accept: one drag law, or a std::variant of drag laws (any
// registry's Variant: drag::AnyDragLaw, or the Variant of a user's DragLaws::with<MyLaw>).
template <class Law, class T>
concept DragLawFor = SingleDragLawFor<Law, T> || detail::is_variant_of_drag_laws<Law, T>::value;

namespace detail {

// β_classical and ∂β_classical/∂ε of one law or of a variant of laws.
template <class Law, class F>
decltype(auto) with_law(const Law& law, F&& f) {
  if constexpr (is_variant<Law>)
    return std::visit(f, law);
  else
    return f(law);
}
template <class Law, class T>
T classical_beta(const Law& law, const drag::DragState<T>& state) {
  return with_law(law, [&](const auto& l) -> T { return l(state).classical(); });
}
template <class Law, class T>
T classical_beta_voidage_slope(const Law& law, const drag::DragState<T>& state) {
  return with_law(law, [&](const auto& l) -> T { return l.with_derivatives(state).classical().d_voidage; });
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

// The domain of the equilibrium solvers, declared once: the settling system's, then u_s > 0.
template <class T>
constexpr Arguments<T, 6> equilibrium_domain(const T& superficial_velocity, const Fluid<T>& fluid,
                                             const Particles<T>& particles, const T& gravity) {
  return join(single_particle::settling_domain(fluid, particles, gravity),
              arguments(Argument<T>{"superficial_velocity", superficial_velocity, domains::positive<T>()}));
}

// Under fluidbed::checked, no homogeneous bed is an error; otherwise it is the empty result.
template <ErrorPolicy Policy, class T>
void check_bed_exists(Policy, std::string_view function, const std::optional<T>& voidage,
                      const T& superficial_velocity) {
  if constexpr (std::same_as<Policy, Checked>)
    if (!voidage)
      fluidbed::detail::throw_domain_error(
          function, "superficial_velocity", superficial_velocity,
          "at or above the single-particle terminal velocity: no homogeneous bed, the particles are carried out");
}

// The lowest root of the equilibrium residual, or nothing (see equilibrium_voidage).
template <class Law, class T>
std::optional<T> lowest_equilibrium_voidage(const Law& law, const T& superficial_velocity, const Fluid<T>& fluid,
                                            const Particles<T>& particles, const T& gravity) {
  const EquilibriumResidual<Law, T> residual{law, superficial_velocity, fluid, particles.diameter,
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

}  // namespace detail

// ----------------------------------------------------------------------------- any drag law

// The voidage at which `law` holds a homogeneous bed in equilibrium at the superficial
// velocity u_s (seed 000 eq. 3.28), or nothing when u_s is at or above the law's own
// single-particle terminal velocity (the limit of eq. 3.28 as ε → 1): then there is no
// homogeneous bed, the particles are carried out.
//
// `law` is any type with the DragLaw calling shape (law(DragState<T>).classical() and
// law.with_derivatives(state)), or a std::variant of such laws (drag::AnyDragLaw, any
// registry's Variant). The relation is
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
// Domain: u_s > 0, ρ_f, μ_f, d, g > 0, ρ_p > ρ_f. With fluidbed::checked, an argument out
// of it, and the absence of a homogeneous bed, throw std::domain_error (the result is then
// never empty).
template <class Law, class T, ErrorPolicy Policy = Unchecked>
requires DragLawFor<Law, T> std::optional<T> equilibrium_voidage(const Law& law, const T& superficial_velocity,
                                                                 const Fluid<T>& fluid, const Particles<T>& particles,
                                                                 const T& gravity, Policy policy = {}) {
  constexpr std::string_view function = "equilibrium_voidage";
  check_domain(policy, function, detail::equilibrium_domain(superficial_velocity, fluid, particles, gravity));
  const std::optional<T> voidage =
      detail::lowest_equilibrium_voidage(law, superficial_velocity, fluid, particles, gravity);
  detail::check_bed_exists(policy, function, voidage, superficial_velocity);
  return voidage;
}

// The same at standard gravity.
template <class Law, class T, ErrorPolicy Policy = Unchecked>
requires DragLawFor<Law, T> std::optional<T> equilibrium_voidage(const Law& law, const T& superficial_velocity,
                                                                 const Fluid<T>& fluid, const Particles<T>& particles,
                                                                 Policy policy = {}) {
  return equilibrium_voidage(law, superficial_velocity, fluid, particles, standard_gravity_as<T>(), policy);
}

// ----------------------------------------------------------------------------- Richardson–Zaki

// The Richardson–Zaki expansion ε = (u_s/u_t)^(1/n) with Dallavalle's u_t and n from
// seed 000 eq. 3.24 at Re_t: the ε_R&Z column of seed 000 Table 4.4 (only Dallavalle's u_t
// reproduces it), and exactly the expansion of the Mazzei–Lettieri drag. Nothing when u_s >= u_t.
// Domain and policy as equilibrium_voidage's.
template <class T, ErrorPolicy Policy = Unchecked>
std::optional<T> richardson_zaki_equilibrium_voidage(const T& superficial_velocity, const Fluid<T>& fluid,
                                                     const Particles<T>& particles, const T& gravity,
                                                     Policy policy = {}) {
  constexpr std::string_view function = "richardson_zaki_equilibrium_voidage";
  check_domain(policy, function, detail::equilibrium_domain(superficial_velocity, fluid, particles, gravity));
  const T terminal = single_particle::DallavalleTerminalVelocity{}(fluid, particles, gravity);
  std::optional<T> voidage;
  if (superficial_velocity < terminal) {
    const T exponent = settling::MazzeiExponent{}(terminal_reynolds(fluid, particles.diameter, terminal));
    voidage = settling::richardson_zaki_voidage(superficial_velocity, terminal, exponent);
  }
  detail::check_bed_exists(policy, function, voidage, superficial_velocity);
  return voidage;
}

// The same at standard gravity.
template <class T, ErrorPolicy Policy = Unchecked>
std::optional<T> richardson_zaki_equilibrium_voidage(const T& superficial_velocity, const Fluid<T>& fluid,
                                                     const Particles<T>& particles, Policy policy = {}) {
  return richardson_zaki_equilibrium_voidage(superficial_velocity, fluid, particles, standard_gravity_as<T>(), policy);
}

// ----------------------------------------------------------------------------- comparisons

// ε_law / ε_R&Z at the equilibrium Reynolds number Re = ρ_f u_s d/μ_f and the
// Richardson–Zaki voidage ε_R&Z, as plotted in seed 000 Figs 3.1–3.5:
//   1. Re_t from Re = Re_t ε_R&Z^n(Re_t)           (settling::richardson_zaki_terminal_reynolds);
//   2. Ar = ¾ C_D(Re_t) Re_t², Dallavalle's C_D   (the system whose R–Z bed that is);
//   3. ε_law from eq. 3.28 at (Re, Ar)            (equilibrium_voidage).
// The equilibrium depends on (Re, Ar) alone for any law built from ρ_f, μ_f, d and w, so
// step 3 runs in the units ρ_f = μ_f = d = 1, ρ_p − ρ_f = 1, g = Ar, u_s = Re. Nothing
// when the law has no homogeneous bed there (its single-particle u_t is below u_s; e.g.
// Ergun, at high Re and ε_R&Z, would need ε > 1), under either policy. The ratio is 1 for
// Mazzei–Lettieri. Domain: Re > 0, ε_R&Z ∈ (0, 1).
template <class Law, class T, ErrorPolicy Policy = Unchecked>
requires DragLawFor<Law, T> std::optional<T> voidage_ratio(const Law& law, const T& reynolds,
                                                           const T& richardson_zaki_voidage, Policy policy = {}) {
  check_domain(policy, "voidage_ratio",
               arguments(Argument<T>{"reynolds", reynolds, domains::positive<T>()},
                         Argument<T>{"richardson_zaki_voidage", richardson_zaki_voidage, domains::open(T(0), T(1))}));
  const T re_t = settling::richardson_zaki_terminal_reynolds(reynolds, richardson_zaki_voidage);
  const T ar = T(0.75) * single_particle::DallavalleCoefficient::cd_times_re(re_t) * re_t;
  const Fluid<T> unit_fluid{.density = T(1), .viscosity = T(1)};
  const Particles<T> unit_particles{.density = T(2), .diameter = T(1)};
  const std::optional<T> voidage = equilibrium_voidage(law, reynolds, unit_fluid, unit_particles, ar);
  if (!voidage) return std::nullopt;
  return *voidage / richardson_zaki_voidage;
}

// The "equivalent exponent" of a law (seed 000 eq. 3.64): writing its β as
//   β_classical = ¾ C_D(Re) ρ_f w (1 − ε)/d · φ(ε, Re)   (eq. 3.61),
//   ψ_e(ε, Re) = −ln φ / ln ε,
// the voidage exponent a Wen–Yu-type law would need to give the same β. C_D is that of
// `Coefficient`, Dallavalle's by default as in eqs. 3.55–3.65; with
// single_particle::SchillerNaumannCoefficient a ConstantExponentDrag gives its α exactly. Re is the
// multiphase Reynolds number ρ_f ε w d/μ_f; ψ_e depends on (ε, Re) alone and is evaluated
// in the units ρ_f = μ_f = d = 1. At ε = 1 it is 0/0 (φ = 1): excluded.
// Domain: ε ∈ (0, 1), Re >= 0.
template <class Coefficient = single_particle::DallavalleCoefficient, class Law, class T,
          ErrorPolicy Policy = Unchecked>
requires DragLawFor<Law, T> T equivalent_exponent(const Law& law, const T& voidage, const T& reynolds,
                                                  Policy policy = {}) {
  using std::log;
  check_domain(policy, "equivalent_exponent",
               arguments(Argument<T>{"voidage", voidage, domains::open(T(0), T(1))},
                         Argument<T>{"reynolds", reynolds, domains::non_negative<T>()}));
  const Fluid<T> unit_fluid{.density = T(1), .viscosity = T(1)};
  const T beta = detail::classical_beta(law, drag::DragState<T>{voidage, reynolds / voidage, unit_fluid, T(1)});
  const T single =
      single_particle::unhindered_beta(Coefficient::cd_times_re(reynolds), voidage, unit_fluid.viscosity, T(1));
  return -log(beta / single) / log(voidage);
}

// ----------------------------------------------------------------------------- bed height

// h = h₀ (1 − ε₀)/(1 − ε): the height of a bed of fixed solids inventory at voidage ε,
// given its height h₀ at ε₀ (solids volume conservation; seed 000 §4.3.3, eq. 4.5).
// Domain: h₀ > 0, ε₀, ε ∈ (0, 1).
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr T bed_height(const T& initial_height, const T& initial_voidage, const T& voidage,
                                            Policy policy = {}) {
  check_domain(policy, "bed_height",
               arguments(Argument<T>{"initial_height", initial_height, domains::positive<T>()},
                         Argument<T>{"initial_voidage", initial_voidage, domains::open(T(0), T(1))},
                         Argument<T>{"voidage", voidage, domains::open(T(0), T(1))}));
  return initial_height * (1 - initial_voidage) / (1 - voidage);
}

// ----------------------------------------------------------------------------- response time

// A homogeneous bed that expands after a step in the superficial velocity u₁ → u₂ > u₁ at
// t = 0, from equilibrium (u₁, h₁) to equilibrium (u₂, h₂ > h₁) (seed 000 §4.3.3 and §4.5.2,
// eqs. 4.1 and 4.9–4.13). Suited to stable (liquid-fluidized) beds, where the new equilibrium
// is homogeneous.
template <class T>
struct ExpansionStep {
  T initial_height;    // h₁ [m]
  T initial_velocity;  // u₁ [m s⁻¹], superficial
  T final_height;      // h₂ [m]
  T final_velocity;    // u₂ [m s⁻¹], superficial
};

namespace detail {

// The domain of a step, declared once: h₁ > 0, u₁ >= 0, h₂ > h₁, u₂ > u₁ (an expansion).
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 4> expansion_step_domain(const ExpansionStep<T>& step) {
  return {{{"initial_height", step.initial_height, domains::positive<T>()},
           {"initial_velocity", step.initial_velocity, domains::non_negative<T>()},
           {"final_height", step.final_height, domains::greater_than(step.initial_height),
            "must be finite and > initial_height: an expanding bed"},
           {"final_velocity", step.final_velocity, domains::greater_than(step.initial_velocity),
            "must be finite and > initial_velocity: a step up in the fluid flux"}}};
}

}  // namespace detail

// The time constant of the expansion, τ = (h₂ − h₁)/(u₂ − u₁) (seed 000 eq. 4.2): the time
// the bed would take to reach h₂ if it kept its initial rate of rise h'(0) = u₂ − u₁
// (eq. 4.13; the rate of rise equals the step in fluid flux only at t = 0, when the bed
// still has its two-region structure). From minimum fluidization, (u₁, h₁) = (u_mf, h_mf)
// (eq. 4.2); with u₁ = 0 and h₁ the initial height h₀ it is eq. 4.3, τ ≈ (h − h₀)/u, the
// approximation for u_mf ≪ u.
// Domain: h₁ > 0, u₁ >= 0, h₂ > h₁, u₂ > u₁ (std::domain_error under fluidbed::checked).
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr T expansion_time_constant(const ExpansionStep<T>& step, Policy policy = {}) {
  check_domain(policy, "expansion_time_constant", detail::expansion_step_domain(step));
  return (step.final_height - step.initial_height) / (step.final_velocity - step.initial_velocity);
}

// The response time t_e = 3τ of seed 000 eq. 4.2: h(t_e) − h₁ = (1 − e⁻³)(h₂ − h₁), 95.0 %
// of the expansion. Seed 000's examples: the Richardson & Zaki (1954) system (u_mf 1.30·10⁻⁴,
// u 4.70·10⁻⁴ m s⁻¹, h 0.30 → 0.39 m) takes t_e ≈ 800 s (eq. 4.4), its gas-fluidized bed
// (u_mf 8.73·10⁻³, u 5.77·10⁻² m s⁻¹, h 0.30 → 0.45 m) about 9 s (eq. 4.5).
// Domain as expansion_time_constant's.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr T expansion_response_time(const ExpansionStep<T>& step, Policy policy = {}) {
  check_domain(policy, "expansion_response_time", detail::expansion_step_domain(step));
  return 3 * expansion_time_constant(step);
}

// The bed height during the expansion (seed 000 eq. 4.1):
//
//   h(t) = h₂ − (h₂ − h₁) exp(−t/τ),   τ = (h₂ − h₁)/(u₂ − u₁),
//
// h(0) = h₁, h'(0) = u₂ − u₁, h → h₂. Seed 000 Fig. 4.13 finds it in close agreement with
// its CFD expansion profile. Domain: the step's, and t >= 0.
template <class T, ErrorPolicy Policy = Unchecked>
T expanding_bed_height(const ExpansionStep<T>& step, const T& time, Policy policy = {}) {
  using std::exp;
  check_domain(policy, "expanding_bed_height",
               join(detail::expansion_step_domain(step),
                    arguments(Argument<T>{"time", time, domains::non_negative<T>()})));
  return step.final_height - (step.final_height - step.initial_height) * exp(-time / expansion_time_constant(step));
}

}  // namespace fluidbed::fluidization
