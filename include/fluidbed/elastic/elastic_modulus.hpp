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
// Each model is a value type deriving from ElasticModulus<Model> (below), with name(),
// reference() and validity(), and one kernel per form it has: the modulus at homogeneous
// equilibrium (all three) and at a state (ε, w) off equilibrium (Mazzei–Lettieri only: the
// other two define no drag off equilibrium). The base gives the hot call, .with_derivatives
// (∂E/∂ε, and ∂E/∂w at a state, through Dual on the same kernel), .checked and
// .checked_with_derivatives; ElasticModuli is the family's registry. The functions that are not
// closures (Table 3.1, Re*, H at a state, the forces) take an error policy as last argument:
// fluidbed::unchecked (default: preconditions asserted in debug builds) or fluidbed::checked
// (std::domain_error naming the argument and its value). Each argument's domain is declared
// once (domain(EquilibriumState), drag::domain(DragState), detail::table_3_1_domain).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../core/registry.hpp"
#include "../core/vector3.hpp"
#include "../drag/drag_law.hpp"
#include "../drag/mazzei_lettieri.hpp"
#include "../interaction/vector_arguments.hpp"
#include "../properties.hpp"
#include "../settling/richardson_zaki.hpp"
#include "../single_particle/settling_system.hpp"

namespace fluidbed::elastic {

// References (as seed 000's bibliography gives them; DOIs omitted where not confirmed):
//   Foscolo & Gibilaro (1987), "Fluid dynamic stability of fluidized suspensions: the particle
//     bed model", Chem. Eng. Sci. 42, 1489; the criterion: Foscolo & Gibilaro (1984), Chem.
//     Eng. Sci. 39, 1667;
//   Jean & Fan (1992), "On the model equations of Gibilaro and Foscolo with corrected buoyancy
//     force", Powder Technol. 72, 201;
//   Mazzei, Lettieri, Elson & Colman (2006), Chem. Eng. Sci. 61, 1958, and Mazzei (2008), PhD
//     thesis, UCL, §3.5.3 (seed 000), which derives E_r from the Mazzei–Lettieri (2007) drag.

// The functions of seed 000 Table 3.1 at (ε, Re*), Re* = Re/ε^n_e(Re*) the terminal Reynolds
// number Richardson–Zaki assigns to the state (eq. 3.53; = Re_t at equilibrium):
//   n_e = (4.8 + 2.4 x)/(1 + x), x = 0.175 Re*^¾                       (3.24/3.54)
//   N   = dn_e/dRe* = −0.315 Re*^−¼/(1 + x)²; Re* N = −1.8 x/(1 + x)²  (3.103)
//   C   = 1/(1 + Re* N ln ε)        ∈ (0, 1], 1 at ε = 1                (3.105)
//   D   = 4.8 Re*^−½/(0.63 + 4.8 Re*^−½) = 4.8/(0.63 √Re* + 4.8)        (3.107)
//   H   = C n_e (D − 2)/ε           → −4.8/ε as Re* → 0 and ∞           (3.109, 4.38)
// Every function is finite for Re* in [0, ∞) and ε in (0, 1] except N, which is −∞ at
// Re* = 0 (only the product Re* N enters C). S may be fluidbed::Dual for derivatives.
template <class S>
struct MazzeiLettieriFunctions {
  S exponent;        // n_e
  S exponent_slope;  // N
  S reynolds_factor;  // C
  S drag_factor;      // D
  S voidage_sensitivity;  // H = (∂F/∂ε)/F at fixed superficial slip
};

namespace detail {

// The domain of (ε, Re*), the arguments of Table 3.1 and of H, declared once: ε ∈ (0, 1], Re* ≥ 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 2> table_3_1_domain(const T& voidage, const T& re_star) {
  return {{{"voidage", voidage, domains::half_open(T(0), T(1))}, {"re_star", re_star, domains::non_negative<T>()}}};
}

// The domain of a state (ε, w) with fluid and diameter: a drag law's (drag::domain), the values
// of dual arguments.
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 5> slip_state_domain(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                                                const T& diameter) {
  return drag::domain(drag::DragState<T>{value_of(voidage), value_of(slip), fluid, diameter});
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
  f.exponent = settling::MazzeiExponent::of_scaled_power(scaled_power);
  f.exponent_slope =
      FLUIDBED_DECIMAL(T, -1.8) * scaled_power / (one_plus_x * one_plus_x);  // Re* N, divided by Re* by the caller
  f.reynolds_factor = 1 / (1 + f.exponent_slope * log_voidage);
  f.drag_factor = FLUIDBED_DECIMAL(T, 4.8) / (FLUIDBED_DECIMAL(T, 0.63) * root_re_star + FLUIDBED_DECIMAL(T, 4.8));
  f.voidage_sensitivity = f.reynolds_factor * f.exponent * (f.drag_factor - 2) / voidage;
  return f;
}

}  // namespace detail

// Preconditions: ε ∈ (0, 1], Re* ≥ 0 (detail::table_3_1_domain).
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE MazzeiLettieriFunctions<S> mazzei_lettieri_functions(const S& voidage, const S& re_star,
                                                                          Policy policy = {}) {
  using std::log;
  using std::sqrt;
  using T = value_type_of<S>;
  check_domain(policy, "mazzei_lettieri_functions", detail::table_3_1_domain(value_of(voidage), value_of(re_star)));
  MazzeiLettieriFunctions<S> f = detail::table_3_1_functions(
      voidage, S(log(voidage)), settling::MazzeiExponent::scaled_power(re_star), S(sqrt(re_star)));
  f.exponent_slope = value_of(re_star) > 0 ? f.exponent_slope / re_star : S(-std::numeric_limits<T>::infinity());
  return f;
}

// ---------------------------------------------------------------- a state (ε, w) off equilibrium

// Re* of a state (ε, w) (eq. 3.53), through the Mazzei–Lettieri drag's solver. S may be Dual in
// (ε, w): the derivatives follow from the implicit function theorem. Preconditions (of every
// function of a state (ε, w) below): those of a drag law (drag::domain), ε ∈ (0, 1], w ≥ 0,
// ρ_f, μ_f, d > 0.
template <class S, class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S effective_reynolds(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter,
                                          Policy policy = {}) {
  check_domain(policy, "effective_reynolds", detail::slip_state_domain(voidage, slip, fluid, diameter));
  return drag::MazzeiLettieri::effective_reynolds(voidage, particle_reynolds(fluid, diameter, voidage, slip));
}

// H(ε, Re*) of the Mazzei–Lettieri model at a state (ε, w): the sensitivity the 3-D elastic
// force needs off equilibrium.
template <class S, class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S mazzei_lettieri_sensitivity(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                                   const T& diameter, Policy policy = {}) {
  check_domain(policy, "mazzei_lettieri_sensitivity", detail::slip_state_domain(voidage, slip, fluid, diameter));
  return mazzei_lettieri_functions(voidage, effective_reynolds(voidage, slip, fluid, diameter)).voidage_sensitivity;
}

// ---------------------------------------------------------------- the moduli

// A homogeneous suspension in equilibrium, the state of every modulus at equilibrium. The
// particles must be heavier than the fluid: the moduli balance the drag against the buoyant
// weight (1 − ε)(ρ_p − ρ_f) g of a bed fluidized upwards (eqs. 3.21, 3.75, 3.95, 3.111: at
// equilibrium F̂ = (π d³/6)Δρ g, with u_t > 0 in the bond u_s = u_t ε^n_e). For ρ_p <= ρ_f
// there is no such bed: the formulas would give E <= 0, a modulus of the wrong sign, not the
// inverse-fluidization physics (which needs the drag and gravity reversed). The
// off-equilibrium Mazzei–Lettieri modulus (eq. 3.110) uses the actual drag and has no such
// restriction.
template <class T>
struct EquilibriumState {
  T voidage;               // ε
  Fluid<T> fluid;          // ρ_f, μ_f
  Particles<T> particles;  // ρ_p, d
  T terminal_reynolds;     // Re_t = ρ_f u_t d/μ_f (Dallavalle's u_t); read by Mazzei–Lettieri only
  T gravity = standard_gravity_as<T>();  // g [m s⁻²]
};

// The domain of an equilibrium state, declared once: ε ∈ (0, 1], a settling system (ρ_f, μ_f,
// d, g > 0, ρ_p > ρ_f, single_particle::settling_domain) and Re_t ≥ 0, all finite.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 7> domain(const EquilibriumState<T>& s) {
  return join(join(arguments(Argument<T>{"voidage", s.voidage, domains::half_open(T(0), T(1))}),
                   single_particle::settling_domain(s.fluid, s.particles, s.gravity)),
              arguments(Argument<T>{"terminal_reynolds", s.terminal_reynolds, domains::non_negative<T>()}));
}

// E^e and dE^e/dε at fixed fluid, particles, Re_t and g.
template <class T>
struct EquilibriumModulusWithDerivatives {
  T value;      // E^e [Pa]
  T d_voidage;  // ∂E^e/∂ε
};

// E off equilibrium and its partial derivatives at fixed fluid properties and diameter.
template <class T>
struct ModulusWithDerivatives {
  T value;      // E [Pa]
  T d_voidage;  // ∂E/∂ε at fixed w
  T d_slip;     // ∂E/∂w at fixed ε
};

namespace detail {

// E = −(2/3) d (1 − ε)(ρ_p − ρ_f) g H: the modulus with the drag of a homogeneous suspension
// in equilibrium (classical buoyancy, eq. 3.21), the form eqs. 3.95 and 3.111 take.
template <class S, class T>
FLUIDBED_HOST_DEVICE S modulus_from_sensitivity(const S& voidage, const S& sensitivity, const Fluid<T>& fluid,
                                                const Particles<T>& particles, const T& gravity) {
  const T weight = T(2) / T(3) * particles.diameter * (particles.density - fluid.density) * gravity;
  return -weight * (1 - voidage) * sensitivity;
}

// H = −4.8/ε of Foscolo–Gibilaro and Jean–Fan, the Re* → 0 and ∞ limit of the Mazzei–Lettieri
// H (eq. 4.38).
template <class S>
FLUIDBED_HOST_DEVICE constexpr S constant_exponent_sensitivity(const S& voidage) {
  return FLUIDBED_DECIMAL(value_type_of<S>, -4.8) / voidage;
}

// "state {name = value, …}", for the messages of the checked entry points.
template <class T, std::size_t N>
std::string state_text(const Arguments<T, N>& list) {
  return "state {" + describe(list) + "}";
}

}  // namespace detail

// A model with a modulus at a state (ε, w) off equilibrium (a concept, not a requires-expression
// in the base, so that clang checks it once Model is complete).
template <class Model, class T>
concept DefinedOffEquilibrium = requires(const Model& m, const T& x, const Fluid<T>& f) { m.modulus_at_state(x, x, f, x); };

// CRTP base of the elastic moduli. Model provides name(), reference(), validity() and
//   template <class S> S sensitivity(const S& voidage, const S& re_star) const;   H(ε, Re*)
//   template <class S, class T> S modulus_at_equilibrium(const S& voidage, const EquilibriumState<T>&) const;
// (the state's other fields than its voidage), and, if it is defined off equilibrium,
//   template <class S, class T> S modulus_at_state(const S& voidage, const S& slip, const Fluid<T>&, const T& diameter) const;
// The base gives, at equilibrium and (with modulus_at_state) at a drag::DragState:
//   model(state)                          hot path, E [Pa]; the domain asserted in debug builds
//   model.with_derivatives(state)         E with ∂E/∂ε (and ∂E/∂w at a state), through Dual
//   model.checked(state)                  throws std::domain_error naming the argument outside
//                                         its domain, or the result if it is not finite
//   model.checked_with_derivatives(state) the same for the value and its derivatives
template <class Model>
struct ElasticModulus {
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr T operator()(const EquilibriumState<T>& s) const {
    FLUIDBED_EXPECTS(within(domain(s)));
    return self().modulus_at_equilibrium(s.voidage, s);
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr EquilibriumModulusWithDerivatives<T> with_derivatives(
      const EquilibriumState<T>& s) const {
    FLUIDBED_EXPECTS(within(domain(s)));
    const Dual<T, 1> e = self().modulus_at_equilibrium(Dual<T, 1>::variable(s.voidage, 0), s);
    return {e.value, e.derivative[0]};
  }

  template <class T>
  T checked(const EquilibriumState<T>& s) const {
    require_within(self().name(), domain(s));
    const T e = (*this)(s);
    require_finite_result(self().name(), "modulus", e, [&s] { return detail::state_text(domain(s)); });
    return e;
  }

  template <class T>
  EquilibriumModulusWithDerivatives<T> checked_with_derivatives(const EquilibriumState<T>& s) const {
    require_within(self().name(), domain(s));
    const EquilibriumModulusWithDerivatives<T> e = with_derivatives(s);
    const auto describe_state = [&s] { return detail::state_text(domain(s)); };
    require_finite_result(self().name(), "modulus", e.value, describe_state);
    require_finite_result(self().name(), "d modulus/d voidage", e.d_voidage, describe_state);
    return e;
  }

  // Off equilibrium, at a state (ε, w) of the drag law's domain (drag::domain).
  template <class T>
    requires DefinedOffEquilibrium<Model, T>
  FLUIDBED_HOST_DEVICE constexpr T operator()(const drag::DragState<T>& s) const {
    FLUIDBED_EXPECTS(within(drag::domain(s)));
    return self().modulus_at_state(s.voidage, s.slip, s.fluid, s.diameter);
  }

  template <class T>
    requires DefinedOffEquilibrium<Model, T>
  FLUIDBED_HOST_DEVICE constexpr ModulusWithDerivatives<T> with_derivatives(const drag::DragState<T>& s) const {
    FLUIDBED_EXPECTS(within(drag::domain(s)));
    using D = Dual<T, 2>;
    const D e = self().modulus_at_state(D::variable(s.voidage, 0), D::variable(s.slip, 1), s.fluid, s.diameter);
    return {e.value, e.derivative[0], e.derivative[1]};
  }

  template <class T>
    requires DefinedOffEquilibrium<Model, T>
  T checked(const drag::DragState<T>& s) const {
    require_within(self().name(), drag::domain(s));
    const T e = (*this)(s);
    require_finite_result(self().name(), "modulus", e, [&s] { return detail::state_text(drag::domain(s)); });
    return e;
  }

  template <class T>
    requires DefinedOffEquilibrium<Model, T>
  ModulusWithDerivatives<T> checked_with_derivatives(const drag::DragState<T>& s) const {
    require_within(self().name(), drag::domain(s));
    const ModulusWithDerivatives<T> e = with_derivatives(s);
    const auto describe_state = [&s] { return detail::state_text(drag::domain(s)); };
    require_finite_result(self().name(), "modulus", e.value, describe_state);
    require_finite_result(self().name(), "d modulus/d voidage", e.d_voidage, describe_state);
    require_finite_result(self().name(), "d modulus/d slip", e.d_slip, describe_state);
    return e;
  }

 private:
  FLUIDBED_HOST_DEVICE constexpr const Model& self() const { return static_cast<const Model&>(*this); }
};

// The range every model was derived for: 1-D fluidization, every ε in (0, 1] and Re_t.
inline constexpr Validity<2> fluidization_validity{
    {{"voidage", 0.0, 1.0}, {"terminal_reynolds", 0.0, std::numeric_limits<double>::infinity()}}};

// Foscolo–Gibilaro, eq. 3.75: E_f = 3.2 d (1 − ε)(ρ_p − ρ_f) g [Pa]. Native buoyancy:
// pressure-gradient (the Particle Bed Model's drag carries the factor ε of eq. 3.19). Derived
// for 1-D fluidization, every ε in (0, 1) and Re_t; 0 at ε = 1. H = −4.8/ε, as Jean–Fan's: the
// drag is ∝ ε^−4.8 at fixed superficial slip (eqs. 3.90–3.94), whence the 4.8.
struct FoscoloGibilaroModulus : ElasticModulus<FoscoloGibilaroModulus> {
  constexpr std::string_view name() const { return "FoscoloGibilaroModulus"; }
  constexpr std::string_view reference() const {
    return "Foscolo, P.U., Gibilaro, L.G. (1987) Chem. Eng. Sci. 42, 1489; the criterion: Foscolo, P.U., "
           "Gibilaro, L.G. (1984) Chem. Eng. Sci. 39, 1667";
  }
  constexpr Validity<2> validity() const { return fluidization_validity; }

  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S sensitivity(const S& voidage, const S&) const {
    return detail::constant_exponent_sensitivity(voidage);
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S modulus_at_equilibrium(const S& voidage, const EquilibriumState<T>& s) const {
    return detail::modulus_from_sensitivity(voidage, S(FLUIDBED_DECIMAL(T, -4.8)), s.fluid, s.particles, s.gravity);
  }
};

// Jean–Fan, eq. 3.95: E_j = E_f/ε = 3.2 d (1 − ε)(ρ_p − ρ_f) g/ε [Pa]. Native buoyancy:
// classical. Same range and H as Foscolo–Gibilaro.
struct JeanFanModulus : ElasticModulus<JeanFanModulus> {
  constexpr std::string_view name() const { return "JeanFanModulus"; }
  constexpr std::string_view reference() const {
    return "Jean, R.-H., Fan, L.-S. (1992) On the model equations of Gibilaro and Foscolo with corrected buoyancy "
           "force, Powder Technol. 72, 201";
  }
  constexpr Validity<2> validity() const { return fluidization_validity; }

  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S sensitivity(const S& voidage, const S&) const {
    return detail::constant_exponent_sensitivity(voidage);
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S modulus_at_equilibrium(const S& voidage, const EquilibriumState<T>& s) const {
    return detail::modulus_from_sensitivity(voidage, detail::constant_exponent_sensitivity(voidage), s.fluid,
                                            s.particles, s.gravity);
  }
};

// Mazzei–Lettieri. At equilibrium, eq. 3.111: E_r^e = −(2/3) d (1 − ε)(ρ_p − ρ_f) g H(ε, Re_t)
// [Pa], Re_t = ρ_f u_t d/μ_f with Dallavalle's u_t (at equilibrium Re* = Re_t); every ε in
// (0, 1], Re_t >= 0; equals E_j as Re_t → 0 and ∞ (eq. 3.112). Off equilibrium, eq. 3.110:
// E_r = −[4(1 − ε)/(π d²)] H F̂ with F̂ the drag on one particle (eq. 3.99), i.e.
// E_r = −(2/3) d H β w with β the Mazzei–Lettieri drag coefficient (classical buoyancy) and w the
// interstitial slip [Pa]; 0 at w = 0 and at ε = 1. Native buoyancy: classical. H of Table 3.1.
struct MazzeiLettieriModulus : ElasticModulus<MazzeiLettieriModulus> {
  constexpr std::string_view name() const { return "MazzeiLettieriModulus"; }
  constexpr std::string_view reference() const {
    return "Mazzei, L., Lettieri, P., Elson, T., Colman, D. (2006) Chem. Eng. Sci. 61, 1958; Mazzei, L. (2008) "
           "PhD thesis, University College London, section 3.5.3";
  }
  constexpr Validity<2> validity() const { return fluidization_validity; }

  template <class S>
  FLUIDBED_HOST_DEVICE S sensitivity(const S& voidage, const S& re_star) const {
    return mazzei_lettieri_functions(voidage, re_star).voidage_sensitivity;
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S modulus_at_equilibrium(const S& voidage, const EquilibriumState<T>& s) const {
    return detail::modulus_from_sensitivity(voidage, sensitivity(voidage, S(s.terminal_reynolds)), s.fluid,
                                            s.particles, s.gravity);
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE S modulus_at_state(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                          const T& diameter) const {
    const S beta = drag::MazzeiLettieri{}.native_beta(voidage, slip, fluid, diameter);
    const S h = mazzei_lettieri_sensitivity(voidage, slip, fluid, diameter);
    return -(T(2) / T(3)) * diameter * h * beta * slip;
  }
};

struct ElasticModulusFamily {
  static constexpr std::string_view what = "elastic modulus";
};

// The registry of the family (core/registry.hpp). Extend it with a model of your own:
// `using MyModuli = ElasticModuli::with<MyModulus>;`.
using ElasticModuli = Registry<ElasticModulusFamily, FoscoloGibilaroModulus, JeanFanModulus, MazzeiLettieriModulus>;

using AnyElasticModulus = ElasticModuli::Variant;

namespace detail {

template <class Model>
inline constexpr bool is_variant = false;
template <class... Alternatives>
inline constexpr bool is_variant<std::variant<Alternatives...>> = true;

}  // namespace detail

// H of a model at (ε, Re*) (Re* ignored by Foscolo–Gibilaro and Jean–Fan, whose H is −4.8/ε);
// `model` any elastic modulus, or a variant of them (ElasticModuli::Variant). Preconditions:
// ε ∈ (0, 1], Re* ≥ 0.
template <class Model, class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S voidage_sensitivity(const Model& model, const S& voidage, const S& re_star, Policy policy = {}) {
  check_domain(policy, "voidage_sensitivity", detail::table_3_1_domain(value_of(voidage), value_of(re_star)));
  if constexpr (detail::is_variant<Model>)
    return std::visit([&](const auto& m) { return m.sensitivity(voidage, re_star); }, model);
  else
    return model.sensitivity(voidage, re_star);
}

// β (classical) and H of the Mazzei–Lettieri model at a state (ε, w) with one solve for Re*:
// what a CFD code needs per cell for the drag and its elastic force.
template <class T>
struct DragAndSensitivity {
  T beta;         // β_classical [kg m⁻³ s⁻¹]
  T sensitivity;  // H
};

template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE DragAndSensitivity<T> mazzei_lettieri_drag_and_sensitivity(const T& voidage, const T& slip,
                                                                                const Fluid<T>& fluid,
                                                                                const T& diameter, Policy policy = {}) {
  check_domain(policy, "mazzei_lettieri_drag_and_sensitivity", detail::slip_state_domain(voidage, slip, fluid, diameter));
  const drag::MazzeiLettieri law;
  const T re = particle_reynolds(fluid, diameter, voidage, slip);
  if (!(re > T(0)) || voidage == T(1))
    return {law.native_beta(voidage, slip, fluid, diameter), mazzei_lettieri_sensitivity(voidage, slip, fluid, diameter)};
  const auto state = drag::MazzeiLettieri::solve_state(re, voidage);
  const T root_re_star = state.root_reynolds * state.inverse_root_power;
  return {drag::MazzeiLettieri::beta_of_state(state, voidage, fluid, diameter),
          detail::table_3_1_functions(voidage, state.log_voidage, state.scaled_power, root_re_star).voidage_sensitivity};
}

// ---------------------------------------------------------------- forces

// The elastic force per unit volume of suspension in 3-D, eq. 3.116:
//   n f_e = −(2/3) d H (∇ε · n_d) n f_d,   n_d = n f_d/|n f_d|,
// given the drag force density n f_d [N m⁻³] in the convention the host code uses (the
// elastic force is a component of the drag, so it comes out in the same convention), ∇ε
// [m⁻¹], H (voidage_sensitivity) and d [m]. Zero when the drag is zero (the force is
// linear in |n f_d|, so the direction is not needed there). Preconditions: d > 0, every
// component and H finite.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> elastic_force(const Vector3<T>& drag_force, const Vector3<T>& voidage_gradient,
                                              const T& sensitivity, const T& diameter, Policy policy = {}) {
  using std::sqrt;
  interaction::check_force_domain(policy, "elastic_force",
                                    arguments(Argument<T>{"sensitivity", sensitivity, domains::finite<T>()},
                                              Argument<T>{"diameter", diameter, domains::positive<T>()}),
                                    interaction::FiniteVector<T>{"drag_force", drag_force},
                                    interaction::FiniteVector<T>{"voidage_gradient", voidage_gradient});
  const T magnitude = sqrt(dot(drag_force, drag_force));
  if (!(magnitude > T(0))) return {T(0), T(0), T(0)};
  const T factor = -(T(2) / T(3)) * diameter * sensitivity * dot(voidage_gradient, drag_force) / magnitude;
  return scaled(factor, drag_force);
}

// The 1-D form of eq. 3.74: n f_e = E (∇ε · e) e, e the upward unit vector (opposite to
// gravity), E an equilibrium modulus. It equals eq. 3.116 only when the drag is vertical; kept
// to compare with the literature that uses it. Preconditions: `upward` a unit vector (its
// length |upward| within 1e-6 of 1), every component and E finite.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE Vector3<T> elastic_force_vertical(const T& modulus, const Vector3<T>& voidage_gradient,
                                                       const Vector3<T>& upward, Policy policy = {}) {
  using std::sqrt;
  const T unit = T(1), tolerance = T(1e-6);
  interaction::check_force_domain(
      policy, "elastic_force_vertical",
      arguments(Argument<T>{"modulus", modulus, domains::finite<T>()},
                Argument<T>{"|upward|", sqrt(dot(upward, upward)), domains::closed(unit - tolerance, unit + tolerance)}),
      interaction::FiniteVector<T>{"voidage_gradient", voidage_gradient},
      interaction::FiniteVector<T>{"upward", upward});
  return scaled(modulus * dot(voidage_gradient, upward), upward);
}

}  // namespace fluidbed::elastic
