// fluidbed — linear stability of homogeneous fluidization and the minimum bubbling point
// (seed 000 §4.6.1, Tables 4.5 and 4.6).
//
// One-dimensional two-fluid model, x upward, particle stresses neglected, interaction force =
// buoyancy + drag + elastic force. Linearising about the homogeneous state (ε̄, particles at
// rest, u_s = u_t ε̄^n_e) gives for the voidage perturbation ε̂ (eq. 4.33):
//
//   ∂²ε̂/∂t² − u_d² ∂²ε̂/∂x² + K (∂ε̂/∂t + u_k ∂ε̂/∂x) = 0
//
//   u_k = u_t n_e (1 − ε) ε^(n_e − 1)     kinematic wave speed (eq. 4.27)
//   u_d = √(E^e/ρ_p)                      dynamic wave speed (eq. 4.31), E^e the equilibrium
//                                         modulus of the model (elastic_modulus.hpp)
//   K   = (ρ_p − ρ_f) g C (2 − D)/(ρ_p u_s)  damping of the Mazzei–Lettieri drag, C and D at
//                                         (ε, Re_t) (eq. 4.31 with A of eq. 4.26)
//
// Seed eq. 4.26 prints A and B without the factor C(ε, Re_t); the finite-difference
// linearisation of the drag (tests/reference/stability_reference.py) and the H of eq. 3.109
// both contain it. C cancels in u_k = (1 − ε) A/B, so the threshold is unaffected, but the
// printed K, and every growth rate, would be too large by 1/C. K here includes C.
//
// The homogeneous state is stable iff u_d > u_k. The stability functions
// S = 1 − u_d/u_k are negative while stable (eqs. 3.76, 4.37, 4.36):
//   S_f = 1 − [(3.2/n_e²)(d g/u_t²)(Δρ/ρ_p) ε^(2(1−n_e))/(1 − ε)]^½        Foscolo–Gibilaro
//   S_j = 1 − [(3.2/n_e²)(d g/u_t²)(Δρ/ρ_p) ε^(1−2n_e)/(1 − ε)]^½          Jean–Fan
//   S_r = 1 − [−(2H/(3n_e²))(d g/u_t²)(Δρ/ρ_p) ε^(2(1−n_e))/(1 − ε)]^½     Mazzei–Lettieri
// with u_t Dallavalle's terminal velocity and n_e = n_e(Re_t) (seed eq. 3.24), as seed 000
// uses them (Table 4.6 is reproduced with exactly these).
//
// The criteria take the elastic modulus of the model (elastic_modulus.hpp: FoscoloGibilaroModulus,
// JeanFanModulus, MazzeiLettieriModulus, one of your own, or an ElasticModuli::Variant).
// Preconditions: ε ∈ (0, 1] and a suspension as homogeneous_suspension builds it (ρ_f, μ_f, d,
// g > 0, ρ_p > ρ_f, u_t, Re_t, n_e > 0: domain(suspension)); wave numbers and velocities > 0.
// Every function takes an error policy as last argument: fluidbed::unchecked (default; asserted
// in debug builds) or fluidbed::checked (std::domain_error naming the argument and its value);
// minimum_bubbling_point always validates.
//
// S is negative in the packed range, positive in a middle band (bubbling) and negative again
// as ε → 1, where u_d/u_k ∝ (1 − ε)^−½: there are two roots. The lower one is the minimum
// bubbling voidage ε_mb; the upper one (re-stabilisation, near ε ≈ 0.99–0.9999) is reported
// separately. For fine powders S may stay negative everywhere (Table 4.6 powder 10 with
// Jean–Fan and Mazzei–Lettieri): no transition is predicted.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../core/domain.hpp"
#include "../core/errors.hpp"
#include "../core/root_finding.hpp"
#include "../properties.hpp"
#include "../settling/richardson_zaki.hpp"
#include "../single_particle/settling_system.hpp"
#include "../single_particle/terminal_velocity_closed_forms.hpp"
#include "elastic_modulus.hpp"

namespace fluidbed::elastic {

// A homogeneous suspension and the single-particle data its stability depends on.
template <class T>
struct HomogeneousSuspension {
  Fluid<T> fluid;
  Particles<T> particles;
  T gravity = standard_gravity_as<T>();
  T terminal_velocity;  // u_t [m s⁻¹], Dallavalle
  T terminal_reynolds;  // Re_t = ρ_f u_t d/μ_f
  T exponent;           // n_e(Re_t), seed eq. 3.24
};

// The domain of a suspension, declared once: a settling system (single_particle::settling_domain)
// and its single-particle data, which a hand-built suspension may get wrong.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 8> domain(const HomogeneousSuspension<T>& s) {
  return join(single_particle::settling_domain(s.fluid, s.particles, s.gravity),
              arguments(Argument<T>{"suspension.terminal_velocity", s.terminal_velocity, domains::positive<T>()},
                        Argument<T>{"suspension.terminal_reynolds", s.terminal_reynolds, domains::positive<T>()},
                        Argument<T>{"suspension.exponent", s.exponent, domains::positive<T>()}));
}

namespace detail {

// A suspension at a voidage ε ∈ (0, 1] (the value of a dual voidage).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 9> suspension_state_domain(const HomogeneousSuspension<T>& s,
                                                                       const S& voidage) {
  return join(domain(s), arguments(Argument<T>{"voidage", value_of(voidage), domains::half_open(T(0), T(1))}));
}

}  // namespace detail

// The suspension as seed 000 §4.6 sets it up: Dallavalle u_t (eq. 3.51) and n_e(Re_t) of
// eq. 3.24. Preconditions: positive properties, ρ_p > ρ_f (a fluidized, not a floating, bed).
template <class T, ErrorPolicy Policy = Unchecked>
HomogeneousSuspension<T> homogeneous_suspension(const Fluid<T>& fluid, const Particles<T>& particles,
                                                const T& gravity, Policy policy = {}) {
  check_domain(policy, "homogeneous_suspension", single_particle::settling_domain(fluid, particles, gravity));
  HomogeneousSuspension<T> s{fluid, particles, gravity, T(0), T(0), T(0)};
  s.terminal_velocity = single_particle::DallavalleTerminalVelocity{}(fluid, particles, gravity);
  s.terminal_reynolds = terminal_reynolds(fluid, particles.diameter, s.terminal_velocity);
  s.exponent = settling::MazzeiExponent{}(s.terminal_reynolds);
  return s;
}

// The same at standard gravity.
template <class T, ErrorPolicy Policy = Unchecked>
HomogeneousSuspension<T> homogeneous_suspension(const Fluid<T>& fluid, const Particles<T>& particles,
                                                Policy policy = {}) {
  return homogeneous_suspension(fluid, particles, standard_gravity_as<T>(), policy);
}

// The equilibrium modulus E^e(ε) of a model for this suspension [Pa]: `model` any elastic
// modulus or a variant of them. S may be Dual in ε.
template <class Model, class S, class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S equilibrium_modulus(const Model& model, const HomogeneousSuspension<T>& s, const S& voidage,
                                           Policy policy = {}) {
  check_domain(policy, "equilibrium_modulus", detail::suspension_state_domain(s, voidage));
  const EquilibriumState<T> state{value_of(voidage), s.fluid, s.particles, s.terminal_reynolds, s.gravity};
  if constexpr (detail::is_variant<Model>)
    return std::visit([&](const auto& m) { return m.modulus_at_equilibrium(voidage, state); }, model);
  else
    return model.modulus_at_equilibrium(voidage, state);
}

// u_k = u_t n_e (1 − ε) ε^(n_e − 1) = (1 − ε) du_s/dε along Richardson–Zaki (eq. 4.27) [m s⁻¹].
template <class S, class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S kinematic_wave_speed(const HomogeneousSuspension<T>& s, const S& voidage, Policy policy = {}) {
  using std::pow;
  check_domain(policy, "kinematic_wave_speed", detail::suspension_state_domain(s, voidage));
  return s.terminal_velocity * s.exponent * (1 - voidage) * pow(voidage, s.exponent - T(1));
}

// u_d = √(E^e/ρ_p) (eq. 4.31) [m s⁻¹].
template <class Model, class S, class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S dynamic_wave_speed(const Model& model, const HomogeneousSuspension<T>& s, const S& voidage,
                                          Policy policy = {}) {
  using std::sqrt;
  check_domain(policy, "dynamic_wave_speed", detail::suspension_state_domain(s, voidage));
  return sqrt(equilibrium_modulus(model, s, voidage) / s.particles.density);
}

// K = (ρ_p − ρ_f) g C (2 − D)/(ρ_p u_s), u_s = u_t ε^n_e [s⁻¹]: the relaxation rate of the
// particle velocity under the Mazzei–Lettieri drag (eq. 4.31 with the C that eq. 4.26 omits).
template <class S, class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S damping(const HomogeneousSuspension<T>& s, const S& voidage, Policy policy = {}) {
  using std::pow;
  check_domain(policy, "damping", detail::suspension_state_domain(s, voidage));
  const auto f = mazzei_lettieri_functions(voidage, S(s.terminal_reynolds));
  const S superficial = s.terminal_velocity * pow(voidage, s.exponent);
  return (s.particles.density - s.fluid.density) * s.gravity * f.reynolds_factor * (2 - f.drag_factor) /
         (s.particles.density * superficial);
}

// S = 1 − u_d/u_k: S_f, S_j or S_r (eqs. 3.76, 4.37, 4.36) as `model` is FoscoloGibilaroModulus,
// JeanFanModulus or MazzeiLettieriModulus; the state is stable while S < 0. −∞ at ε = 1, the
// limit: both speeds vanish there, u_d/u_k ∝ (1 − ε)^−½.
template <class Model, class S, class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S stability_function(const Model& model, const HomogeneousSuspension<T>& s, const S& voidage,
                                          Policy policy = {}) {
  check_domain(policy, "stability_function", detail::suspension_state_domain(s, voidage));
  if (voidage == 1) return S(-std::numeric_limits<T>::infinity());
  return 1 - dynamic_wave_speed(model, s, voidage) / kinematic_wave_speed(s, voidage);
}

// ---------------------------------------------------------------- waves (eqs. 4.34–4.35)

template <class T>
struct WaveSpeeds {
  T kinematic;  // u_k [m s⁻¹]
  T dynamic;    // u_d [m s⁻¹]
  T damping;    // K [s⁻¹]
};

template <class Model, class T, ErrorPolicy Policy = Unchecked>
WaveSpeeds<T> wave_speeds(const Model& model, const HomogeneousSuspension<T>& s, const T& voidage, Policy policy = {}) {
  check_domain(policy, "wave_speeds", detail::suspension_state_domain(s, voidage));
  return {kinematic_wave_speed(s, voidage), dynamic_wave_speed(model, s, voidage), damping(s, voidage)};
}

namespace detail {

// The domain of the wave quantities with a wavenumber or a wave velocity (`name`) > 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 4> wave_domain(const WaveSpeeds<T>& w, const char* name,
                                                           const T& value) {
  return arguments(Argument<T>{"waves.kinematic", w.kinematic, domains::non_negative<T>()},
                   Argument<T>{"waves.dynamic", w.dynamic, domains::non_negative<T>()},
                   Argument<T>{"waves.damping", w.damping, domains::non_negative<T>()},
                   Argument<T>{name, value, domains::positive<T>()});
}

}  // namespace detail

// A voidage wave ε̂ = ε̂_a exp[a t + i k (x − ν t)] (eq. 4.34).
template <class T>
struct Wave {
  T growth_rate;  // a [s⁻¹]; the wave grows if a > 0
  T velocity;     // ν [m s⁻¹]
};

// The wave of wavenumber k > 0 [m⁻¹]: with ε̂ ∝ exp(σ t + i k x), eq. 4.33 gives
// σ² + K σ + u_d² k² + i K u_k k = 0; the root with the larger real part (the least damped)
// is σ = [−K + √(K² − 4 u_d² k² − 4 i K u_k k)]/2, so a = Re σ and ν = −Im σ/k. Long waves
// travel at u_k, short ones at u_d; every k decays iff u_d > u_k.
template <class T, ErrorPolicy Policy = Unchecked>
Wave<T> wave_of_wavenumber(const WaveSpeeds<T>& w, const T& wavenumber, Policy policy = {}) {
  check_domain(policy, "wave_of_wavenumber", detail::wave_domain(w, "wavenumber", wavenumber));
  const std::complex<T> discriminant(w.damping * w.damping - T(4) * w.dynamic * w.dynamic * wavenumber * wavenumber,
                                     -T(4) * w.damping * w.kinematic * wavenumber);
  const std::complex<T> sigma = (-w.damping + std::sqrt(discriminant)) / T(2);
  return {sigma.real(), -sigma.imag() / wavenumber};
}

// Eq. 4.35, a wave of velocity ν: a = K (u_k − ν)/(2ν).
template <class T, ErrorPolicy Policy = Unchecked>
T growth_rate_of_wave_velocity(const WaveSpeeds<T>& w, const T& velocity, Policy policy = {}) {
  check_domain(policy, "growth_rate_of_wave_velocity", detail::wave_domain(w, "velocity", velocity));
  return w.damping * (w.kinematic - velocity) / (T(2) * velocity);
}

// Eq. 4.35, a wave of velocity ν: k² = [K²/(4ν²)] (u_k² − ν²)/(ν² − u_d²). Negative where no
// wave of that velocity exists (ν outside the interval between u_d and u_k).
template <class T, ErrorPolicy Policy = Unchecked>
T squared_wavenumber_of_wave_velocity(const WaveSpeeds<T>& w, const T& velocity, Policy policy = {}) {
  check_domain(policy, "squared_wavenumber_of_wave_velocity", detail::wave_domain(w, "velocity", velocity));
  const T v2 = velocity * velocity;
  return w.damping * w.damping / (T(4) * v2) * (w.kinematic * w.kinematic - v2) / (v2 - w.dynamic * w.dynamic);
}

// ---------------------------------------------------------------- minimum bubbling point

// Where the stability function is searched: lower <= ε <= upper. The default lower bound is
// below any packed bed (Foscolo–Gibilaro puts the transition of the coarser FCC powders of
// Table 4.6 near ε = 0.36); upper = 1 searches up to the largest voidage below 1 that the
// search resolves in T (detail::largest_searched_voidage).
template <class T>
struct VoidageInterval {
  T lower = FLUIDBED_DECIMAL(T, 0.3);
  T upper = T(1);
};

enum class TransitionStatus {
  transition,              // S < 0 at the lower bound and changes sign: bubbling_voidage is set
  no_transition,           // S < 0 on the whole interval: homogeneous at every voidage
  unstable_at_lower_bound  // S >= 0 already at the lower bound: the transition lies below it
};

template <class T>
struct StabilityTransition {
  TransitionStatus status = TransitionStatus::no_transition;
  std::optional<T> bubbling_voidage;         // ε_mb, the lowest root of S
  std::optional<T> bubbling_velocity;        // u_mb = u_t ε_mb^n_e [m s⁻¹] (Richardson–Zaki expansion)
  std::optional<T> restabilisation_voidage;  // the upper root (S from + to −), if within the interval
  T maximum_voidage = T(0);                  // where S is largest on the interval
  T maximum_stability = T(0);                // that largest S
};

namespace detail {

// S is sampled on the variable u = −ln(1 − ε), which spreads the whole range, up to the
// re-stabilisation root close to 1, over a uniform grid.
template <class T>
T voidage_of_log_gap(const T& u) {
  using std::expm1;
  return -expm1(-u);
}

template <class T>
T log_gap_of_voidage(const T& voidage) {
  using std::log1p;
  return -log1p(-voidage);
}

// The largest voidage the search reaches, 1 − 4ε_T (ε_T = std::numeric_limits<T>::epsilon()):
// 1 − 8.9e-16 in double, 1 − 4.8e-7 in float, 1 − 4.3e-19 in x87 long double. S is finite
// there (ε = 1 itself is its −∞ limit), and a re-stabilisation root closer to 1 than that is
// not resolved in T. A fixed 1 − 1e-15 would be 1 in float: S = −∞ and the samples NaN.
template <class T>
T largest_searched_voidage() {
  return T(1) - T(4) * std::numeric_limits<T>::epsilon();
}

// dS/dε, exact (one dual-number evaluation of S).
template <class Model, class T>
T stability_slope(const Model& model, const HomogeneousSuspension<T>& s, const T& voidage) {
  return stability_function(model, s, Dual<T, 1>::variable(voidage, 0)).derivative[0];
}

}  // namespace detail

// The minimum bubbling point of a model: the lowest root of S in the interval, the
// superficial velocity there, the re-stabilisation root, and the maximum of S. S is sampled
// on 2000 points uniform in −ln(1 − ε). Its maximum is located as the root of the exact
// dS/dε (dual numbers) between the neighbours of the largest sample, by TOMS 748 to the
// precision of T; a value-only search (Brent) could not place it better than √ε_T relative,
// since S is flat to second order there. Every root of S bracketed by the samples (or by the
// maximum, so that a positive band narrower than the sampling is still found) is refined by
// TOMS 748 to the precision of T. Every iteration is bounded (fluidbed::detail::root_iteration_limit).
// Works in float, double and long double, up to detail::largest_searched_voidage<T>().
// Throws std::domain_error unless 0 < lower < upper <= 1 and the suspension is valid
// (domain(suspension)), and if S is not finite at a sample (a suspension whose wave speeds
// leave the range of T). `model` any elastic modulus (for a variant of them, see below).
template <class Model, class T>
StabilityTransition<T> minimum_bubbling_point(const Model& model, const HomogeneousSuspension<T>& s,
                                              const VoidageInterval<T>& interval = {}) {
  using std::pow;
  constexpr std::string_view function = "minimum_bubbling_point";
  require_within(function, domain(s));
  require_in_open(function, "interval.lower", interval.lower, T(0), T(1));
  require_in_half_open(function, "interval.upper", interval.upper, interval.lower, T(1));
  const T stability_limit = std::min(interval.upper, detail::largest_searched_voidage<T>());
  const auto stability = [&](const T& voidage) { return stability_function(model, s, voidage); };
  const auto slope = [&](const T& voidage) { return detail::stability_slope(model, s, voidage); };
  constexpr int samples = 2000;
  const T u_low = detail::log_gap_of_voidage(interval.lower), u_high = detail::log_gap_of_voidage(stability_limit);
  std::vector<T> voidage(samples), value(samples);
  for (int i = 0; i < samples; ++i) {
    voidage[i] = i + 1 == samples ? stability_limit
                                  : detail::voidage_of_log_gap(u_low + (u_high - u_low) * T(i) / T(samples - 1));
    value[i] = stability(voidage[i]);
    require_finite_result(function, "stability function", value[i],
                          [&] { return "the suspension at voidage " + fluidbed::detail::number_text(voidage[i]); });
  }
  const int peak = int(std::max_element(value.begin(), value.end()) - value.begin());
  StabilityTransition<T> out;
  out.maximum_voidage = voidage[peak];  // the largest sample: the maximum where it lies at an end of the interval
  out.maximum_stability = value[peak];
  if (peak > 0 && peak + 1 < samples) {
    const T left = voidage[peak - 1], right = voidage[peak + 1];
    const T slope_left = slope(left), slope_right = slope(right);
    if (slope_left > T(0) && slope_right < T(0)) {
      out.maximum_voidage = fluidbed::detail::bracketed_root(slope, left, right, slope_left, slope_right);
      out.maximum_stability = stability(out.maximum_voidage);
    }
  }
  const auto root = [&](const T& a, const T& b) {
    return fluidbed::detail::bracketed_root(stability, a, b, stability(a), stability(b));
  };
  // Brackets: between samples of opposite sign, or, when no sample is positive (a band
  // narrower than the sampling), between the maximum and its neighbouring samples.
  const bool positive_sample = value[peak] >= T(0);
  const int below_peak = std::clamp(
      int(std::lower_bound(voidage.begin(), voidage.end(), out.maximum_voidage) - voidage.begin()) - 1, 0, samples - 2);
  if (value[0] >= T(0)) {
    out.status = TransitionStatus::unstable_at_lower_bound;
  } else if (out.maximum_stability > T(0)) {
    out.status = TransitionStatus::transition;
    int i = 0;
    while (positive_sample && value[i + 1] < T(0)) ++i;  // stops at the first sign change, at the latest at the peak
    out.bubbling_voidage =
        positive_sample ? root(voidage[i], voidage[i + 1]) : root(voidage[below_peak], out.maximum_voidage);
    out.bubbling_velocity = s.terminal_velocity * pow(*out.bubbling_voidage, s.exponent);
  }
  if (out.maximum_stability > T(0) && value[samples - 1] < T(0)) {
    int j = samples - 1;
    while (positive_sample && value[j - 1] < T(0)) --j;  // the last sign change, at the earliest at the peak
    out.restabilisation_voidage =
        positive_sample ? root(voidage[j - 1], voidage[j]) : root(out.maximum_voidage, voidage[below_peak + 1]);
  }
  return out;
}

// The same for a model chosen at run time (an ElasticModuli::Variant), visited once.
template <class... Models, class T>
StabilityTransition<T> minimum_bubbling_point(const std::variant<Models...>& model, const HomogeneousSuspension<T>& s,
                                              const VoidageInterval<T>& interval = {}) {
  return std::visit([&](const auto& m) { return minimum_bubbling_point(m, s, interval); }, model);
}

}  // namespace fluidbed::elastic
