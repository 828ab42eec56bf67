// fluidbed — the elastic force of a fluidized suspension: the part of the drag that comes
// from voidage gradients (seed 000 §3.5).
//
// A particle in a voidage gradient feels the drag of the voidage a small distance upstream,
// ε̃ = ε − θ ∂ε/∂x with θ = (2/3) d (eqs. 3.84–3.86). To first order the extra force per unit
// volume of suspension is E ∂ε/∂x, E the elastic modulus [Pa] (eqs. 3.87–3.89, 3.98):
//
//   E = −[4(1 − ε)/(π d²)] (∂F/∂ε) at fixed superficial slip u_s − v_p,
//
// F the drag on one particle. Writing ∂F/∂ε = H F (eq. 3.108) and n F = |n f_d| (the drag per
// unit volume, n = 6(1 − ε)/(π d³)) gives the one form every model here shares:
//
//   E = −(2/3) d H |n f_d|,      n f_e = −(2/3) d H (∇ε · n_d) n f_d        (3.115, 3.116)
//
// with n_d the unit vector of the drag (parallel to the slip). H < 0, so a voidage rising
// along the drag direction increases the drag. The models differ only in H:
//
//   Foscolo–Gibilaro / Jean–Fan   H = −4.8/ε (the ε^−4.8 drag of Richardson–Zaki form)
//   Mazzei–Lettieri               H = C n_e (D − 2)/ε at Re* (eq. 3.109, Table 3.1)
//
// and, at homogeneous equilibrium, in which drag they multiply: the classical-buoyancy drag
// |n f_d| = (1 − ε)(ρ_p − ρ_f) g (eq. 3.21) gives Jean–Fan's E_j = 3.2 d (1 − ε) Δρ g/ε (eq. 3.95)
// and E_r^e (eq. 3.111); the pressure-gradient drag ε(1 − ε)Δρ g (eq. 3.19) gives
// Foscolo–Gibilaro's E_f = 3.2 d (1 − ε) Δρ g (eq. 3.75). E_f and E_j are one model in the two
// buoyancy conventions (E_j = E_f/ε is exactly the factor of eq. 3.19); seed 000 compares them
// as separate stability criteria (S_f and S_j, stability.hpp).
//
// Every function asserts its documented preconditions in debug builds; each has a `_checked`
// form (the moduli at equilibrium through equilibrium_modulus_checked) that validates them and
// throws std::domain_error naming the argument and its value.
#pragma once

#include <cmath>
#include <limits>
#include <string_view>
#include <type_traits>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../core/vector3.hpp"
#include "../drag/drag_law.hpp"
#include "../drag/mazzei_lettieri.hpp"
#include "../properties.hpp"
#include "../settling/richardson_zaki.hpp"
#include "../settling/terminal_velocity_closed_forms.hpp"

namespace fluidbed::elastic {

// References (as seed 000's bibliography gives them; DOIs omitted where not confirmed):
//   Foscolo & Gibilaro (1987), "Fluid dynamic stability of fluidized suspensions: the particle
//     bed model", Chem. Eng. Sci. 42, 1489; the criterion: Foscolo & Gibilaro (1984), Chem.
//     Eng. Sci. 39, 1667;
//   Jean & Fan (1992), "On the model equations of Gibilaro and Foscolo with corrected buoyancy
//     force", Powder Technol. 72, 201;
//   Mazzei, Lettieri, Elson & Colman (2006), Chem. Eng. Sci. 61, 1958, and Mazzei (2008), PhD
//     thesis, UCL, §3.5.3 (seed 000), which derives E_r from the Mazzei–Lettieri (2007) drag.
enum class ElasticModel { foscolo_gibilaro, jean_fan, mazzei_lettieri };

constexpr std::string_view name(ElasticModel model) {
  switch (model) {
    case ElasticModel::foscolo_gibilaro: return "FoscoloGibilaro";
    case ElasticModel::jean_fan: return "JeanFan";
    case ElasticModel::mazzei_lettieri: return "MazzeiLettieri";
  }
  return "";
}

// The functions of seed 000 Table 3.1 at (ε, Re*), Re* = Re/ε^n_e(Re*) the terminal Reynolds
// number Richardson–Zaki assigns to the state (eq. 3.53; = Re_t at equilibrium):
//   n_e = (4.8 + 2.4 x)/(1 + x), x = 0.175 Re*^¾                       (3.24/3.54)
//   N   = dn_e/dRe* = −0.315 Re*^−¼/(1 + x)²; Re* N = −1.8 x/(1 + x)²  (3.103)
//   C   = 1/(1 + Re* N ln ε)        ∈ (0, 1], 1 at ε = 1                (3.105)
//   D   = 4.8 Re*^−½/(0.63 + 4.8 Re*^−½) = 4.8/(0.63 √Re* + 4.8)        (3.107)
//   H   = C n_e (D − 2)/ε           → −4.8/ε as Re* → 0 and ∞           (3.109, 4.38)
// Every function is finite for Re* in [0, ∞) and ε in (0, 1] except N, which is −∞ at
// Re* = 0 (only the product Re* N enters C). S may be fluidbed::Dual for derivatives.
// Preconditions: ε ∈ (0, 1], Re* ≥ 0.
template <class S>
struct MazzeiLettieriFunctions {
  S exponent;        // n_e
  S exponent_slope;  // N
  S reynolds_factor;  // C
  S drag_factor;      // D
  S voidage_sensitivity;  // H = (∂F/∂ε)/F at fixed superficial slip
};

namespace detail {

// The hot-path preconditions of a state (ε, w) with fluid and diameter: those of a drag law.
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr bool valid_slip_state(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                                     const T& diameter) {
  return value_of(voidage) > 0 && value_of(voidage) <= 1 && value_of(slip) >= 0 && fluid.density > T(0) &&
         fluid.viscosity > T(0) && diameter > T(0);
}

// The Table 3.1 algebra from x = 0.175 Re*^¾, √Re*, ln ε and ε; N is left to the caller
// (it needs Re* itself). Shared by mazzei_lettieri_functions and the one-solve hot path
// mazzei_lettieri_drag_and_sensitivity, which has x and √Re* from the Re* solve.
template <class S>
FLUIDBED_HOST_DEVICE MazzeiLettieriFunctions<S> table_3_1_functions(const S& voidage, const S& log_voidage,
                                                                    const S& scaled_power, const S& root_re_star) {
  using T = value_type_of<S>;
  const S one_plus_x = 1 + scaled_power;
  MazzeiLettieriFunctions<S> f;
  f.exponent = settling::detail::exponent_of_scaled_power(scaled_power);
  f.exponent_slope = T(-1.8L) * scaled_power / (one_plus_x * one_plus_x);  // Re* N, divided by Re* by the caller
  f.reynolds_factor = 1 / (1 + f.exponent_slope * log_voidage);
  f.drag_factor = T(4.8L) / (T(0.63L) * root_re_star + T(4.8L));
  f.voidage_sensitivity = f.reynolds_factor * f.exponent * (f.drag_factor - 2) / voidage;
  return f;
}

}  // namespace detail

template <class S>
FLUIDBED_HOST_DEVICE MazzeiLettieriFunctions<S> mazzei_lettieri_functions(const S& voidage, const S& re_star) {
  using std::log;
  using std::sqrt;
  using T = value_type_of<S>;
  FLUIDBED_EXPECTS(voidage > 0 && voidage <= 1 && !(re_star < 0));
  MazzeiLettieriFunctions<S> f = detail::table_3_1_functions(
      voidage, S(log(voidage)), settling::detail::scaled_power(re_star), S(sqrt(re_star)));
  f.exponent_slope = value_of(re_star) > 0 ? f.exponent_slope / re_star : S(-std::numeric_limits<T>::infinity());
  return f;
}

// H of the Foscolo–Gibilaro and Jean–Fan moduli: −4.8/ε, the Re* → 0 and ∞ limit of the
// Mazzei–Lettieri H (eq. 4.38). Their drag is ∝ ε^−4.8 at fixed superficial slip
// (eqs. 3.90–3.94), whence the 4.8. Precondition: ε ∈ (0, 1].
template <class S>
FLUIDBED_HOST_DEVICE S constant_exponent_sensitivity(const S& voidage) {
  FLUIDBED_EXPECTS(voidage > 0 && voidage <= 1);
  return value_type_of<S>(-4.8L) / voidage;
}

// H of a model at (ε, Re*); Re* is ignored by Foscolo–Gibilaro and Jean–Fan. Preconditions:
// ε ∈ (0, 1], Re* ≥ 0.
template <class S>
FLUIDBED_HOST_DEVICE S voidage_sensitivity(ElasticModel model, const S& voidage, const S& re_star) {
  if (model == ElasticModel::mazzei_lettieri) return mazzei_lettieri_functions(voidage, re_star).voidage_sensitivity;
  return constant_exponent_sensitivity(voidage);
}

// ---------------------------------------------------------------- moduli at equilibrium

// E = −(2/3) d (1 − ε)(ρ_p − ρ_f) g H: the modulus with the drag of a homogeneous suspension
// in equilibrium (classical buoyancy, eq. 3.21), the form eqs. 3.95 and 3.111 take.
// Preconditions (of every modulus at equilibrium): ε ∈ (0, 1], ρ_f, μ_f, d, g > 0 and
// ρ_p > ρ_f (see validate_modulus_inputs).
template <class S, class T>
FLUIDBED_HOST_DEVICE S modulus_from_sensitivity(const S& voidage, const S& sensitivity, const Fluid<T>& fluid,
                                                const Particles<T>& particles, const T& gravity) {
  FLUIDBED_EXPECTS(voidage > 0 && voidage <= 1 && settling::detail::valid_settling_inputs(fluid, particles, gravity));
  const T weight = T(2) / T(3) * particles.diameter * (particles.density - fluid.density) * gravity;
  return -weight * (1 - voidage) * sensitivity;
}

// Foscolo–Gibilaro, eq. 3.75: E_f = 3.2 d (1 − ε)(ρ_p − ρ_f) g [Pa]. Native buoyancy:
// pressure-gradient (the Particle Bed Model's drag carries the factor ε of eq. 3.19). Derived
// for 1-D fluidization, every ε in (0, 1) and Re_t; 0 at ε = 1.
template <class S, class T>
FLUIDBED_HOST_DEVICE S foscolo_gibilaro_modulus(const S& voidage, const Fluid<T>& fluid, const Particles<T>& particles,
                                                const T& gravity = standard_gravity_as<T>()) {
  return modulus_from_sensitivity(voidage, S(T(-4.8L)), fluid, particles, gravity);
}

// Jean–Fan, eq. 3.95: E_j = E_f/ε = 3.2 d (1 − ε)(ρ_p − ρ_f) g/ε [Pa]. Native buoyancy:
// classical. Same range as Foscolo–Gibilaro.
template <class S, class T>
FLUIDBED_HOST_DEVICE S jean_fan_modulus(const S& voidage, const Fluid<T>& fluid, const Particles<T>& particles,
                                        const T& gravity = standard_gravity_as<T>()) {
  return modulus_from_sensitivity(voidage, constant_exponent_sensitivity(voidage), fluid, particles, gravity);
}

// Mazzei–Lettieri at equilibrium, eq. 3.111: E_r^e = −(2/3) d (1 − ε)(ρ_p − ρ_f) g H(ε, Re_t)
// [Pa], Re_t = ρ_f u_t d/μ_f with Dallavalle's u_t (at equilibrium Re* = Re_t). Native buoyancy:
// classical. Every ε in (0, 1], Re_t >= 0; equals E_j as Re_t → 0 and ∞ (eq. 3.112).
template <class S, class T>
FLUIDBED_HOST_DEVICE S mazzei_lettieri_equilibrium_modulus(const S& voidage, const Fluid<T>& fluid,
                                                           const Particles<T>& particles, const T& terminal_reynolds,
                                                           const T& gravity = standard_gravity_as<T>()) {
  const S h = mazzei_lettieri_functions(voidage, S(terminal_reynolds)).voidage_sensitivity;
  return modulus_from_sensitivity(voidage, h, fluid, particles, gravity);
}

// The equilibrium modulus of a model [Pa]; Re_t is used by Mazzei–Lettieri only.
template <class S, class T>
FLUIDBED_HOST_DEVICE S equilibrium_modulus(ElasticModel model, const S& voidage, const Fluid<T>& fluid,
                                           const Particles<T>& particles, const T& terminal_reynolds,
                                           const T& gravity = standard_gravity_as<T>()) {
  switch (model) {
    case ElasticModel::foscolo_gibilaro: return foscolo_gibilaro_modulus(voidage, fluid, particles, gravity);
    case ElasticModel::jean_fan: return jean_fan_modulus(voidage, fluid, particles, gravity);
    case ElasticModel::mazzei_lettieri: break;
  }
  return mazzei_lettieri_equilibrium_modulus(voidage, fluid, particles, terminal_reynolds, gravity);
}

// ---------------------------------------------------------------- off equilibrium

// Re* of a state (eq. 3.53), through the Mazzei–Lettieri drag's solver. S may be Dual in
// (ε, w): the derivatives follow from the implicit function theorem. Preconditions (of every
// function of a state (ε, w) below): those of a drag law, ε ∈ (0, 1], w ≥ 0, ρ_f, μ_f, d > 0.
template <class S, class T>
FLUIDBED_HOST_DEVICE S effective_reynolds(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) {
  FLUIDBED_EXPECTS(detail::valid_slip_state(voidage, slip, fluid, diameter));
  return drag::MazzeiLettieri::effective_reynolds(voidage, particle_reynolds(fluid, diameter, voidage, slip));
}

// H(ε, Re*) of the Mazzei–Lettieri model at a state (ε, w): the sensitivity the 3-D elastic
// force needs off equilibrium.
template <class S, class T>
FLUIDBED_HOST_DEVICE S mazzei_lettieri_sensitivity(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                                   const T& diameter) {
  return mazzei_lettieri_functions(voidage, effective_reynolds(voidage, slip, fluid, diameter)).voidage_sensitivity;
}

// β (classical) and H of the Mazzei–Lettieri model at a state (ε, w) with one solve for Re*:
// what a CFD code needs per cell for the drag and its elastic force.
template <class T>
struct DragAndSensitivity {
  T beta;         // β_classical [kg m⁻³ s⁻¹]
  T sensitivity;  // H
};

template <class T>
FLUIDBED_HOST_DEVICE DragAndSensitivity<T> mazzei_lettieri_drag_and_sensitivity(const T& voidage, const T& slip,
                                                                                const Fluid<T>& fluid,
                                                                                const T& diameter) {
  FLUIDBED_EXPECTS(detail::valid_slip_state(voidage, slip, fluid, diameter));
  const drag::MazzeiLettieri law;
  const T re = particle_reynolds(fluid, diameter, voidage, slip);
  if (!(re > T(0)) || voidage == T(1))
    return {law.native_beta(voidage, slip, fluid, diameter), mazzei_lettieri_sensitivity(voidage, slip, fluid, diameter)};
  const auto state = drag::MazzeiLettieri::solve_state(re, voidage);
  const T root_re_star = state.root_reynolds * state.inverse_root_power;
  return {drag::MazzeiLettieri::beta_of_state(state, voidage, fluid, diameter),
          detail::table_3_1_functions(voidage, state.log_voidage, state.scaled_power, root_re_star).voidage_sensitivity};
}

// Mazzei–Lettieri modulus off equilibrium, eq. 3.110: E_r = −[4(1 − ε)/(π d²)] H F̂ with F̂ the
// drag on one particle (eq. 3.99), i.e. E_r = −(2/3) d H β w with β the Mazzei–Lettieri drag
// coefficient (classical buoyancy) and w the interstitial slip [Pa]. 0 at w = 0 and at ε = 1.
template <class S, class T>
FLUIDBED_HOST_DEVICE S mazzei_lettieri_modulus(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                               const T& diameter) {
  const S beta = drag::MazzeiLettieri{}.native_beta(voidage, slip, fluid, diameter);
  const S h = mazzei_lettieri_sensitivity(voidage, slip, fluid, diameter);
  return -(T(2) / T(3)) * diameter * h * beta * slip;
}

// ---------------------------------------------------------------- forces

// The elastic force per unit volume of suspension in 3-D, eq. 3.116:
//   n f_e = −(2/3) d H (∇ε · n_d) n f_d,   n_d = n f_d/|n f_d|,
// given the drag force density n f_d [N m⁻³] in the convention the host code uses (the
// elastic force is a component of the drag, so it comes out in the same convention), ∇ε
// [m⁻¹], H (voidage_sensitivity) and d [m]. Zero when the drag is zero (the force is
// linear in |n f_d|, so the direction is not needed there). Preconditions: d > 0, every
// component and H finite.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> elastic_force(const Vector3<T>& drag_force, const Vector3<T>& voidage_gradient,
                                              const T& sensitivity, const T& diameter) {
  using std::sqrt;
  FLUIDBED_EXPECTS(diameter > T(0));
  const T magnitude = sqrt(dot(drag_force, drag_force));
  if (!(magnitude > T(0))) return {T(0), T(0), T(0)};
  const T factor = -(T(2) / T(3)) * diameter * sensitivity * dot(voidage_gradient, drag_force) / magnitude;
  return scaled(factor, drag_force);
}

// The 1-D form of eq. 3.74: n f_e = E (∇ε · e) e, e the upward unit vector (opposite to
// gravity), E an equilibrium modulus. It equals eq. 3.116 only when the drag is vertical; kept
// to compare with the literature that uses it. Preconditions: `upward` a unit vector, every
// component and E finite.
template <class T>
FLUIDBED_HOST_DEVICE Vector3<T> elastic_force_vertical(const T& modulus, const Vector3<T>& voidage_gradient,
                                                       const Vector3<T>& upward) {
  return scaled(modulus * dot(voidage_gradient, upward), upward);
}

// ---------------------------------------------------------------- checked

namespace detail {

// The moduli at equilibrium balance the drag against the buoyant weight (1 − ε)(ρ_p − ρ_f) g
// of a bed fluidized upwards (eqs. 3.21, 3.75, 3.95, 3.111: at equilibrium F̂ = (π d³/6)Δρ g,
// with u_t > 0 in the bond u_s = u_t ε^n_e). For ρ_p <= ρ_f there is no such bed: the formulas
// would give E <= 0, a modulus of the wrong sign, not the inverse-fluidization physics (which
// needs the drag and gravity reversed). So ρ_p > ρ_f is required, as for the terminal velocity
// the moduli go with (settling::detail::validate_settling, shared). The off-equilibrium
// Mazzei–Lettieri modulus (eq. 3.110) uses the actual drag and has no such restriction.
template <class T>
void validate_modulus_inputs(std::string_view function, const T& voidage, const Fluid<T>& fluid,
                             const Particles<T>& particles, const T& gravity) {
  require_in_half_open(function, "voidage", voidage, T(0), T(1));
  settling::detail::validate_settling(function, fluid, particles, gravity);
}

// ε ∈ (0, 1] and Re* ≥ 0, the arguments of Table 3.1.
template <class T>
void validate_table_3_1_state(std::string_view function, const T& voidage, const T& re_star) {
  require_in_half_open(function, "voidage", voidage, T(0), T(1));
  require_non_negative(function, "re_star", re_star);
}

}  // namespace detail

// equilibrium_modulus with every argument validated (std::domain_error naming the argument
// and value); the checked form of the three moduli at equilibrium.
template <class T>
T equilibrium_modulus_checked(ElasticModel model, const T& voidage, const Fluid<T>& fluid,
                              const Particles<T>& particles, const T& terminal_reynolds,
                              const T& gravity = standard_gravity_as<T>()) {
  detail::validate_modulus_inputs("equilibrium_modulus", voidage, fluid, particles, gravity);
  require_non_negative("equilibrium_modulus", "terminal_reynolds", terminal_reynolds);
  return equilibrium_modulus(model, voidage, fluid, particles, terminal_reynolds, gravity);
}

template <class T>
MazzeiLettieriFunctions<T> mazzei_lettieri_functions_checked(const T& voidage, const T& re_star) {
  detail::validate_table_3_1_state("mazzei_lettieri_functions", voidage, re_star);
  return mazzei_lettieri_functions(voidage, re_star);
}

template <class T>
T voidage_sensitivity_checked(ElasticModel model, const T& voidage, const T& re_star) {
  detail::validate_table_3_1_state("voidage_sensitivity", voidage, re_star);
  return voidage_sensitivity(model, voidage, re_star);
}

// The functions of a state (ε, w), validated as a drag law's state (drag::validate).
template <class T>
T effective_reynolds_checked(const T& voidage, const T& slip, const Fluid<T>& fluid, const T& diameter) {
  drag::validate("effective_reynolds", drag::DragState<T>{voidage, slip, fluid, diameter});
  return effective_reynolds(voidage, slip, fluid, diameter);
}

template <class T>
T mazzei_lettieri_sensitivity_checked(const T& voidage, const T& slip, const Fluid<T>& fluid, const T& diameter) {
  drag::validate("mazzei_lettieri_sensitivity", drag::DragState<T>{voidage, slip, fluid, diameter});
  return mazzei_lettieri_sensitivity(voidage, slip, fluid, diameter);
}

template <class T>
DragAndSensitivity<T> mazzei_lettieri_drag_and_sensitivity_checked(const T& voidage, const T& slip,
                                                                   const Fluid<T>& fluid, const T& diameter) {
  drag::validate("mazzei_lettieri_drag_and_sensitivity", drag::DragState<T>{voidage, slip, fluid, diameter});
  return mazzei_lettieri_drag_and_sensitivity(voidage, slip, fluid, diameter);
}

template <class T>
T mazzei_lettieri_modulus_checked(const T& voidage, const T& slip, const Fluid<T>& fluid, const T& diameter) {
  drag::validate("mazzei_lettieri_modulus", drag::DragState<T>{voidage, slip, fluid, diameter});
  return mazzei_lettieri_modulus(voidage, slip, fluid, diameter);
}

template <class T>
Vector3<T> elastic_force_checked(const Vector3<T>& drag_force, const Vector3<T>& voidage_gradient, const T& sensitivity,
                                 const T& diameter) {
  constexpr std::string_view function = "elastic_force";
  require_finite_elements(function, "drag_force", drag_force);
  require_finite_elements(function, "voidage_gradient", voidage_gradient);
  require_finite(function, "sensitivity", sensitivity);
  require_positive(function, "diameter", diameter);
  return elastic_force(drag_force, voidage_gradient, sensitivity, diameter);
}

// `upward` must be a unit vector to within 1e-6 (its length is named in the message).
template <class T>
Vector3<T> elastic_force_vertical_checked(const T& modulus, const Vector3<T>& voidage_gradient,
                                          const Vector3<T>& upward) {
  using std::abs;
  using std::sqrt;
  constexpr std::string_view function = "elastic_force_vertical";
  require_finite(function, "modulus", modulus);
  require_finite_elements(function, "voidage_gradient", voidage_gradient);
  require_finite_elements(function, "upward", upward);
  require_in_closed(function, "|upward|", sqrt(dot(upward, upward)), T(1) - T(1e-6), T(1) + T(1e-6));
  return elastic_force_vertical(modulus, voidage_gradient, upward);
}

}  // namespace fluidbed::elastic
