// fluidbed — drag coefficient of a single sphere, C_D(Re).
//
// Each law is written as the product C_D·Re, which is finite at Re = 0 (C_D itself
// diverges there); the suspension laws build β from C_D·Re so that zero slip is never
// 0·∞. Re is the particle Reynolds number of the caller's law: for a suspension law it
// is Re = ρ_f ε w d / μ_f (seed 000 eq. 3.33), for a free particle ρ_f u d / μ_f.
//
// Every coefficient is a value type deriving from SphereDragCoefficient<Law>, which gives
//   law(Re)                       C_D·Re (hot path; Re >= 0 asserted in debug builds)
//   law.drag_coefficient(Re)      C_D = (C_D·Re)/Re, Re > 0
//   law.with_derivatives(Re)      C_D·Re and d(C_D·Re)/dRe (through Dual on the one kernel)
//   law.checked(Re), law.checked_with_derivatives(Re)   throw std::domain_error for Re < 0 or
//                                 non-finite Re, naming the argument
// from the law's static kernel `cd_times_re(Re)`, which the drag laws call directly.
// Registry: DragCoefficients (single_particle/terminal_velocity_closed_forms.hpp lists none
// of these; this header needs the standard library only).
#pragma once

#include <cmath>
#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../core/registry.hpp"

namespace fluidbed::single_particle {

// C_D·Re and its slope in Re.
template <class T>
struct DragCoefficientWithDerivative {
  T value;       // C_D·Re
  T d_reynolds;  // d(C_D·Re)/dRe
};

// The domain of Re, declared once: finite and >= 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 1> reynolds_domain(const T& reynolds) {
  return {{{"reynolds", reynolds, domains::non_negative<T>()}}};
}

// CRTP base: Law provides name(), reference(), validity() and
//   template <class S> static S cd_times_re(const S& re);
template <class Law>
struct SphereDragCoefficient {
  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S operator()(const S& reynolds) const {
    FLUIDBED_EXPECTS(within(reynolds_domain(value_of(reynolds))));
    return Law::cd_times_re(reynolds);
  }

  // C_D = (C_D·Re)/Re. Precondition: Re > 0.
  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S drag_coefficient(const S& reynolds) const {
    FLUIDBED_EXPECTS(reynolds > S(0));
    return Law::cd_times_re(reynolds) / reynolds;
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr DragCoefficientWithDerivative<T> with_derivatives(const T& reynolds) const {
    const Dual<T, 1> product = (*this)(Dual<T, 1>::variable(reynolds, 0));
    return {product.value, product.derivative[0]};
  }

  template <class T>
  T checked(const T& reynolds) const {
    require_within(self().name(), reynolds_domain(reynolds));
    return (*this)(reynolds);
  }

  template <class T>
  DragCoefficientWithDerivative<T> checked_with_derivatives(const T& reynolds) const {
    require_within(self().name(), reynolds_domain(reynolds));
    return with_derivatives(reynolds);
  }

 private:
  FLUIDBED_HOST_DEVICE constexpr const Law& self() const { return static_cast<const Law&>(*this); }
};

// Stokes, G.G. (1851), "On the effect of the internal friction of fluids on the motion of
// pendulums", Trans. Camb. Philos. Soc. 9, 8–106: C_D = 24/Re. Valid for Re << 1.
struct StokesCoefficient : SphereDragCoefficient<StokesCoefficient> {
  static constexpr double reynolds_max = 0.1;
  constexpr std::string_view name() const { return "StokesCoefficient"; }
  constexpr std::string_view reference() const { return "Stokes, G.G. (1851) Trans. Camb. Philos. Soc. 9, 8-106"; }
  constexpr Validity<1> validity() const { return {{{"reynolds", 0.0, reynolds_max}}}; }

  template <class S>
  FLUIDBED_HOST_DEVICE static constexpr S cd_times_re(const S& /*re*/) {
    return S(24);
  }
};

// Schiller & Naumann (1933), Z. Ver. Dtsch. Ing. 77, 318; as printed in seed 000
// eq. 3.35: C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, C_D = 0.44 for Re >= 1000.
// The law jumps by 0.4 % at Re = 1000 (0.438288 → 0.44); kept as published.
// Validity: Re up to about 2·10⁵ (the Newton regime's end).
struct SchillerNaumannCoefficient : SphereDragCoefficient<SchillerNaumannCoefficient> {
  static constexpr double newton_switch_reynolds = 1000.0;
  constexpr std::string_view name() const { return "SchillerNaumannCoefficient"; }
  constexpr std::string_view reference() const {
    return "Schiller, L., Naumann, A. (1933) Z. Ver. Dtsch. Ing. 77, 318-320";
  }
  constexpr Validity<1> validity() const { return {{{"reynolds", 0.0, 2.0e5}}}; }

  template <class S>
  FLUIDBED_HOST_DEVICE static S cd_times_re(const S& re) {
    using std::pow;
    using T = value_type_of<S>;
    if (re < constant_as<S>(newton_switch_reynolds))
      return 24 * (1 + FLUIDBED_DECIMAL(T, 0.15) * pow(re, FLUIDBED_DECIMAL(T, 0.687)));
    return FLUIDBED_DECIMAL(T, 0.44) * re;
  }
};

// Dallavalle (1948), Micromeritics, Pitman; seed 000 eqs. 3.51 and 3.55:
// C_D = (0.63 + 4.8 Re^-1/2)², i.e. C_D·Re = (0.63 √Re + 4.8)². Smooth for all Re;
// C_D·Re → 23.04 as Re → 0 and C_D → 0.3969 as Re → ∞. Validity: Re up to about 10⁴.
struct DallavalleCoefficient : SphereDragCoefficient<DallavalleCoefficient> {
  constexpr std::string_view name() const { return "DallavalleCoefficient"; }
  constexpr std::string_view reference() const {
    return "Dallavalle, J.M. (1948) Micromeritics, 2nd ed., Pitman, New York";
  }
  constexpr Validity<1> validity() const { return {{{"reynolds", 0.0, 1.0e4}}}; }

  template <class S>
  FLUIDBED_HOST_DEVICE static S cd_times_re(const S& re) {
    using std::sqrt;
    using T = value_type_of<S>;
    const S root = FLUIDBED_DECIMAL(T, 0.63) * sqrt(re) + FLUIDBED_DECIMAL(T, 4.8);
    return root * root;
  }
};

struct DragCoefficientFamily {
  static constexpr std::string_view what = "single-sphere drag coefficient";
};

// The single-sphere drag coefficients; extend with `DragCoefficients::with<MyCoefficient>`.
using DragCoefficients =
    Registry<DragCoefficientFamily, StokesCoefficient, SchillerNaumannCoefficient, DallavalleCoefficient>;

// ¾ C_D ρ_f w φ / d written as ¾ (C_D·Re) μ_f φ / (ε d²), with Re = ρ_f ε w d / μ_f:
// β_classical [kg m⁻³ s⁻¹] of a dilute suspension without hindrance, the "ε^0" part shared by
// the Wen–Yu, Di Felice and Mazzei–Lettieri families (seed 000 eq. 3.34) and the reference of
// the equivalent exponent (fluidization/bed_expansion.hpp). Preconditions: ε ∈ (0, 1],
// μ_f, d > 0.
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S unhindered_beta(const S& cd_times_re, const S& voidage, const T& viscosity,
                                                 const T& diameter) {
  return T(0.75) * viscosity / (diameter * diameter) * cd_times_re * (1 - voidage) / voidage;
}

}  // namespace fluidbed::single_particle
