// fluidbed — the calling shape shared by every drag law.
//
// A drag law is a small value type (its parameters) deriving from DragLaw<Law>. It
// supplies one generic kernel, `native_beta(voidage, slip, fluid, diameter)`, written
// in the law's native buoyancy convention and templated on the scalar type so that the
// same code yields the value (S = T) and exact partial derivatives (S = Dual<T, 2>).
// DragLaw<Law> turns the kernel into the three public entry points:
//
//   law(state)                    hot path, value             -> DragCoefficient<T>
//   law.with_derivatives(state)   hot path, ∂β/∂ε and ∂β/∂w   -> DragCoefficientWithDerivatives<T>
//   law.checked(state)            validates the state, then law(state), and throws
//                                 std::domain_error unless the result is finite
//   law.checked_with_derivatives(state)   the same with law.with_derivatives(state)
//
// Convention. β [kg m⁻³ s⁻¹] is per unit suspension volume: the drag on the particles
// per unit volume is β (u_f − v_p). Its value depends on the buoyancy the host code
// uses (seed 000 §3.4.2, eq. 3.19):
//   classical          buoyancy −φ ρ_f g  (the seed's and most correlations' papers)
//   pressure_gradient  buoyancy −φ ∇p     (OpenFOAM, MFiX model A, Fluent)
//   β_pressure_gradient = ε · β_classical.
// A result never exposes a bare number: the caller must name the convention.
#pragma once

#include <limits>
#include <string>
#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../properties.hpp"

namespace fluidbed::drag {

enum class Buoyancy {
  classical,          // −φ ρ_f g
  pressure_gradient,  // −φ ∇p
};

// The local state a drag law needs. slip is the interstitial slip speed |u_f − v_p|.
template <class T>
struct DragState {
  T voidage;       // ε, fluid volume fraction, in (0, 1]
  T slip;          // w [m s⁻¹], >= 0
  Fluid<T> fluid;  // ρ_f, μ_f
  T diameter;      // d [m]
};

// Where a law was fitted or derived; outside it the law is still finite and positive,
// but it is an extrapolation.
struct ValidityRange {
  double voidage_min, voidage_max;    // ε
  double reynolds_min, reynolds_max;  // Re = ρ_f ε w d / μ_f
};

// β in one convention, convertible to the other; the caller names the convention.
template <class T>
class DragCoefficient {
 public:
  FLUIDBED_HOST_DEVICE constexpr DragCoefficient(Buoyancy native, T beta_native, T voidage)
      : native_(native), beta_(beta_native), voidage_(voidage) {}

  // β for a momentum equation with classical buoyancy −φ ρ_f g.
  FLUIDBED_HOST_DEVICE constexpr T classical() const {
    return native_ == Buoyancy::classical ? beta_ : beta_ / voidage_;
  }
  // β for a momentum equation with buoyancy −φ ∇p (= ε β_classical).
  FLUIDBED_HOST_DEVICE constexpr T pressure_gradient() const {
    return native_ == Buoyancy::pressure_gradient ? beta_ : voidage_ * beta_;
  }
  FLUIDBED_HOST_DEVICE constexpr T in(Buoyancy convention) const {
    return convention == Buoyancy::classical ? classical() : pressure_gradient();
  }
  FLUIDBED_HOST_DEVICE constexpr Buoyancy native_convention() const { return native_; }

 private:
  Buoyancy native_;
  T beta_;
  T voidage_;
};

// β and its partial derivatives at fixed fluid properties and diameter.
template <class T>
struct DragDerivatives {
  T value;      // β [kg m⁻³ s⁻¹]
  T d_voidage;  // ∂β/∂ε at fixed w
  T d_slip;     // ∂β/∂w at fixed ε
};

// β with derivatives, in one convention, convertible to the other.
//
// At w = 0, ∂β/∂w is +∞ for laws whose C_D·Re contains a fractional power of Re
// (Schiller–Naumann Re^0.687, Dallavalle √Re): that is the true derivative. What an
// implicit solver linearises is the drag force per unit volume, βw, whose derivative
// `force_slip_derivative` is finite everywhere (it equals β at w = 0).
template <class T>
class DragCoefficientWithDerivatives {
 public:
  FLUIDBED_HOST_DEVICE constexpr DragCoefficientWithDerivatives(Buoyancy native, DragDerivatives<T> beta_native,
                                                                T voidage, T slip)
      : native_(native), beta_(beta_native), voidage_(voidage), slip_(slip) {}

  FLUIDBED_HOST_DEVICE constexpr DragDerivatives<T> classical() const {
    if (native_ == Buoyancy::classical) return beta_;
    const T e = voidage_;  // β_cl = β_pg / ε
    return {beta_.value / e, (beta_.d_voidage - beta_.value / e) / e, beta_.d_slip / e};
  }
  FLUIDBED_HOST_DEVICE constexpr DragDerivatives<T> pressure_gradient() const {
    if (native_ == Buoyancy::pressure_gradient) return beta_;
    const T e = voidage_;  // β_pg = ε β_cl
    return {e * beta_.value, beta_.value + e * beta_.d_voidage, e * beta_.d_slip};
  }
  FLUIDBED_HOST_DEVICE constexpr DragDerivatives<T> in(Buoyancy convention) const {
    return convention == Buoyancy::classical ? classical() : pressure_gradient();
  }
  // ∂(β w)/∂w in the given convention: finite at w = 0, where it equals β.
  FLUIDBED_HOST_DEVICE constexpr T force_slip_derivative(Buoyancy convention) const {
    const DragDerivatives<T> b = in(convention);
    return slip_ > T(0) ? b.value + slip_ * b.d_slip : b.value;
  }
  FLUIDBED_HOST_DEVICE constexpr DragCoefficient<T> coefficient() const {
    return DragCoefficient<T>(native_, beta_.value, voidage_);
  }

 private:
  Buoyancy native_;
  DragDerivatives<T> beta_;
  T voidage_;
  T slip_;
};

// The domain of a state, declared once: ε ∈ (0, 1], w >= 0, ρ_f, μ_f, d > 0, all finite. The
// hot path asserts it (debug builds), the checked entry points throw on it.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 5> domain(const DragState<T>& s) {
  return {{{"voidage", s.voidage, domains::half_open(T(0), T(1))},
           {"slip", s.slip, domains::non_negative<T>()},
           {"fluid.density", s.fluid.density, domains::positive<T>()},
           {"fluid.viscosity", s.fluid.viscosity, domains::positive<T>()},
           {"diameter", s.diameter, domains::positive<T>()}}};
}

// Validates a state, then the law's parameters where it has any (parameter_domain), for the
// checked entry points; `function` names the caller.
template <class T, class Law>
void validate(std::string_view function, const DragState<T>& s, const Law& law) {
  require_within(function, join(domain(s), parameter_domain_of<T>(law)));
}

namespace detail {

// The state as text, for the messages of the checked entry points.
template <class T>
std::string describe_state(const DragState<T>& s) {
  return "state {" + describe(domain(s)) + "}";
}

// The names the checked entry points give the results they check, per convention.
struct ResultNames {
  std::string_view value, d_voidage, d_slip, force_slip_derivative;
};

constexpr ResultNames result_names(Buoyancy convention) {
  return convention == Buoyancy::classical
             ? ResultNames{"beta.classical", "d beta.classical/d voidage", "d beta.classical/d slip",
                           "d (beta.classical slip)/d slip"}
             : ResultNames{"beta.pressure_gradient", "d beta.pressure_gradient/d voidage",
                           "d beta.pressure_gradient/d slip", "d (beta.pressure_gradient slip)/d slip"};
}

inline constexpr Buoyancy conventions[] = {Buoyancy::classical, Buoyancy::pressure_gradient};

// For the checked entry points: throws std::domain_error (require_finite_result) unless β is
// finite in both conventions (β_classical = β_pg/ε can overflow where β_pg does not). Any
// coefficient type with in(Buoyancy) (one law, or one species of a mixture); the state is
// described by describe_arguments() on failure.
template <class Coefficient, class DescribeArguments>
void validate_result(std::string_view function, const Coefficient& beta, const DescribeArguments& describe_arguments) {
  for (Buoyancy b : conventions) require_finite_result(function, result_names(b).value, beta.in(b), describe_arguments);
}

// The same for β with derivatives: β, ∂β/∂ε, ∂β/∂w and ∂(βw)/∂w finite in both conventions,
// except ∂β/∂w = +∞ at w = 0, the true derivative of the laws whose C_D·Re has a fractional
// power of Re (DragCoefficientWithDerivatives).
template <class T>
void validate_result(std::string_view function, const DragState<T>& s, const DragCoefficientWithDerivatives<T>& beta) {
  const auto describe = [&s] { return describe_state(s); };
  validate_result(function, beta.coefficient(), describe);
  for (Buoyancy b : conventions) {
    const DragDerivatives<T> d = beta.in(b);
    const ResultNames names = result_names(b);
    require_finite_result(function, names.d_voidage, d.d_voidage, describe);
    if (!(s.slip == T(0) && d.d_slip == std::numeric_limits<T>::infinity()))
      require_finite_result(function, names.d_slip, d.d_slip, describe);
    require_finite_result(function, names.force_slip_derivative, beta.force_slip_derivative(b), describe);
  }
}

}  // namespace detail

// CRTP base: Law provides
//   static constexpr Buoyancy native_buoyancy;
//   std::string_view name() const;        // the name used for run-time lookup
//   std::string_view reference() const;   // authors, year, journal, DOI
//   ValidityRange validity() const;
//   template <class S, class T> S native_beta(S voidage, S slip, const Fluid<T>&, T diameter) const;
template <class Law>
struct DragLaw {
  // Hot path. Preconditions (asserted in debug builds): ε ∈ (0, 1], w >= 0, ρ_f, μ_f, d > 0,
  // all finite, and the law's parameters in their domain (its parameter_domain, if it has one). Result finite and >= 0 (> 0 for ε < 1) wherever β is representable in T;
  // beyond (μ_f/d² or ε^−n overflowing) +∞, or NaN where ∞ meets an exact 0: `checked` reports it.
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr DragCoefficient<T> operator()(const DragState<T>& s) const {
    FLUIDBED_EXPECTS(within(join(domain(s), parameter_domain_of<T>(self()))));
    return DragCoefficient<T>(Law::native_buoyancy, self().native_beta(s.voidage, s.slip, s.fluid, s.diameter),
                              s.voidage);
  }

  // Hot path with ∂β/∂ε and ∂β/∂w (same preconditions).
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr DragCoefficientWithDerivatives<T> with_derivatives(const DragState<T>& s) const {
    FLUIDBED_EXPECTS(within(join(domain(s), parameter_domain_of<T>(self()))));
    using D = Dual<T, 2>;
    const D beta = self().native_beta(D::variable(s.voidage, 0), D::variable(s.slip, 1), s.fluid, s.diameter);
    return DragCoefficientWithDerivatives<T>(Law::native_buoyancy,
                                             DragDerivatives<T>{beta.value, beta.derivative[0], beta.derivative[1]},
                                             s.voidage, s.slip);
  }

  // Checked entry point. Throws std::domain_error naming the argument and its value for a state
  // out of the hot path's domain, and, for a state inside it, naming the result, its value and
  // the state when β is not finite in either convention: a state whose β the floating type
  // cannot represent (μ_f/d² or ε^−n overflowing, e.g. d = 1e-200 m, or ε = 1e-43 in float) gives
  // a status, never ∞ or NaN.
  template <class T>
  DragCoefficient<T> checked(const DragState<T>& s) const {
    validate(self().name(), s, self());
    const DragCoefficient<T> beta = (*this)(s);
    detail::validate_result(self().name(), beta, [&s] { return detail::describe_state(s); });
    return beta;
  }

  // Checked entry point with ∂β/∂ε and ∂β/∂w: the validation of `checked`, and the derivatives
  // must be finite too (∂β/∂w may be the documented +∞ at w = 0).
  template <class T>
  DragCoefficientWithDerivatives<T> checked_with_derivatives(const DragState<T>& s) const {
    validate(self().name(), s, self());
    const DragCoefficientWithDerivatives<T> beta = with_derivatives(s);
    detail::validate_result(self().name(), s, beta);
    return beta;
  }

  // True if the state lies inside the range the law was fitted or derived for.
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr bool within_validity(const DragState<T>& s) const {
    const T re = particle_reynolds(s.fluid, s.diameter, s.voidage, s.slip);
    const ValidityRange v = self().validity();
    return s.voidage >= T(v.voidage_min) && s.voidage <= T(v.voidage_max) && re >= T(v.reynolds_min) &&
           re <= T(v.reynolds_max);
  }

 private:
  FLUIDBED_HOST_DEVICE constexpr const Law& self() const { return static_cast<const Law&>(*this); }
};

}  // namespace fluidbed::drag
