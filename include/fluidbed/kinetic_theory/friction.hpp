// fluidbed — frictional stress of dense granular flow: a pressure p_f [Pa] and a viscosity
// μ_f [Pa s], per unit volume of suspension, ADDED to the kinetic-theory p_s and μ_s
// (Johnson & Jackson 1987: Σ = Σ_f + Σ_c; seeds 001 and 004) inside the sign convention of
// granular_state.hpp. Seed 004 writes Σ_f tension-positive (−p I + 2μS) next to a
// pressure-positive Σ_c; summed literally friction would act with the wrong sign.
//
// Frictional pressures are 0 below the onset fraction φ_min and grow steeply towards
// packing. Frictional viscosities divide by a strain rate: each law documents its floor.
// The friction angle is in radians. Preconditions (asserted in debug builds): φ ∈ [0, 1),
// Θ ≥ 0, d > 0, p_f ≥ 0, D':D' ≥ 0, 0 <= φ_min < φ_max <= 1, 0 < packing_margin < φ_max,
// friction angle in (0, π/2), strain-rate floor > 0, coefficients and exponents ≥ 0.
// evaluate_checked(law, args…) validates them and throws std::domain_error.
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "../core/constants.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// The default strain-rate floor s [s⁻¹] of the frictional viscosities.
inline constexpr double default_strain_rate_floor = 1e-6;

namespace detail {

// The parameters the frictional viscosities share: φ_f ∈ (0, π/2) and s > 0 (with s = 0 the
// viscosity is infinite, or 0/0, at rest).
FLUIDBED_HOST_DEVICE constexpr bool valid_yield_parameters(double friction_angle, double strain_rate_floor) {
  return friction_angle > 0 && friction_angle < std::numbers::pi / 2 && strain_rate_floor > 0;
}

inline void validate_yield_parameters(std::string_view function, double friction_angle, double strain_rate_floor) {
  require_in_open(function, "friction_angle", friction_angle, 0.0, std::numbers::pi / 2);
  require_positive(function, "strain_rate_floor", strain_rate_floor);
}

}  // namespace detail

// Johnson & Jackson (1987), J. Fluid Mech. 176, 67–93, in the form of Johnson, Nott &
// Jackson (1990), J. Fluid Mech. 210, 501–535 (seed 001 eq. 36; seed 004, which splits it
// among classes by mass fraction after Anderson & Jackson 1992):
//   p_f = Fr (φ − φ_min)^a / (φ_max − φ)^b   for φ > φ_min,   0 otherwise.
// The factor (φ_max − φ)^(−b) is continued linearly above φ_max − packing_margin (as MFiX's
// PRINCETON model linearises within 0.01 of packing; OpenFOAM instead floors φ_max − φ at
// 0.01, which freezes the denominator and makes ∂p_f/∂φ jump): p_f is finite for every φ,
// continuous with a continuous slope (for a > 1), and ∂p_f/∂φ is its exact derivative.
// Seed 001's letters (…)^n/(…)^p and seed 004's (…)^p/(…)^n are swapped; both mean
// a = 2 (numerator), b = 5 (denominator). Defaults: Fr = 0.05 Pa, a = 2, b = 5 (OpenFOAM
// tutorials, MFiX); seed 004 uses Fr = 0.005 (unit not printed; Pa assumed), φ_min
// 0.55–0.6, φ_max = 0.64.
struct JohnsonJacksonPressure {
  double min_fraction;                // φ_min, onset of friction
  double max_packing;                 // φ_max
  double coefficient = 0.05;          // Fr [Pa]
  double numerator_exponent = 2.0;    // a
  double denominator_exponent = 5.0;  // b
  double packing_margin = 0.01;

  constexpr std::string_view name() const { return "JohnsonJackson"; }
  constexpr std::string_view reference() const {
    return "Johnson, P.C. & Jackson, R. (1987) J. Fluid Mech. 176, 67-93; Johnson, P.C., Nott, P. & Jackson, R. "
           "(1990) J. Fluid Mech. 210, 501-535";
  }
  void validate(std::string_view function) const {
    detail::validate_packing(function, max_packing, packing_margin);
    require_in_closed_open(function, "min_fraction", min_fraction, 0.0, max_packing);
    require_non_negative(function, "coefficient", coefficient);
    require_non_negative(function, "numerator_exponent", numerator_exponent);
    require_non_negative(function, "denominator_exponent", denominator_exponent);
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S operator()(const S& phi) const {
    using std::pow;
    FLUIDBED_EXPECTS(detail::valid_solid_fraction(phi) && detail::valid_packing(max_packing, packing_margin) &&
                     min_fraction >= 0 && min_fraction < max_packing);
    using T = value_type_of<S>;
    const T onset = T(min_fraction), packing = T(max_packing);
    if (!(phi > onset)) return S(0);
    const S gap_factor = detail::continued_linearly_above(phi, packing - T(packing_margin), [&](const auto& x) {
      return pow(packing - x, T(-denominator_exponent));
    });
    return T(coefficient) * pow(phi - onset, T(numerator_exponent)) * gap_factor;
  }
};

// Schaeffer (1987), J. Differential Equations 66, 19–50, doi:10.1016/0022-0396(87)90038-6,
// as in MFiX and OpenFOAM: p_f = A (φ − φ_min)^n for φ > φ_min, 0 otherwise, with
// A = 10²⁴ Pa (10²⁵ barye in MFiX's CGS) and n = 10. Finite at every φ (no packing
// singularity): it is a penalty that keeps φ near φ_min.
struct SchaefferPressure {
  double min_fraction;        // φ_min
  double coefficient = 1e24;  // A [Pa]
  double exponent = 10.0;     // n

  constexpr std::string_view name() const { return "Schaeffer"; }
  constexpr std::string_view reference() const { return detail::references::schaeffer_1987; }
  void validate(std::string_view function) const {
    require_in_closed_open(function, "min_fraction", min_fraction, 0.0, 1.0);
    require_non_negative(function, "coefficient", coefficient);
    require_non_negative(function, "exponent", exponent);
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S operator()(const S& phi) const {
    using std::pow;
    FLUIDBED_EXPECTS(detail::valid_solid_fraction(phi) && min_fraction >= 0 && min_fraction < 1);
    using T = value_type_of<S>;
    const T onset = T(min_fraction);
    if (!(phi > onset)) return S(0);
    return T(coefficient) * pow(phi - onset, T(exponent));
  }
};

// Schaeffer's (1987) frictional viscosity, the Coulomb yield condition written as a
// viscosity (seed 001 eq. 38, seed 004):
//   μ_f = p_f sin φ_f / (2 √(I_2D + s²)),   I_2D = ½ D':D',
// s = strain_rate_floor (default 10⁻⁶ s⁻¹; OpenFOAM adds a small number to √I_2D, MFiX
// caps μ_f at 100 Pa s). In simple shear √I_2D = γ̇/2, so the shear stress is p_f sin φ_f.
// Seed 001 eq. 37 (μ = p sin φ, "Johnson–Jackson") lacks the 1/strain rate: it is a stress.
// Seed 004's I_2 is not said to be deviatoric; with D:D instead of D':D' μ_f changes.
struct SchaefferViscosity {
  double friction_angle;                                 // φ_f [rad]
  double strain_rate_floor = default_strain_rate_floor;  // s [s⁻¹]

  constexpr std::string_view name() const { return "Schaeffer"; }
  constexpr std::string_view reference() const { return detail::references::schaeffer_1987; }
  void validate(std::string_view function) const {
    detail::validate_yield_parameters(function, friction_angle, strain_rate_floor);
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S operator()(const S& frictional_pressure, const StrainRate<S>& rate) const {
    using std::sin;
    using std::sqrt;
    FLUIDBED_EXPECTS(value_of(frictional_pressure) >= 0 && value_of(rate.deviatoric_contraction) >= 0 &&
                     detail::valid_yield_parameters(friction_angle, strain_rate_floor));
    using T = value_type_of<S>;
    const T floor = T(strain_rate_floor);
    const S invariant = T(0.5) * rate.deviatoric_contraction + floor * floor;
    return (T(0.5) * sin(T(friction_angle))) * frictional_pressure / sqrt(invariant);
  }
};

template <class S>
struct FrictionalStress {
  S pressure;   // p_f [Pa]
  S viscosity;  // μ_f [Pa s]
};

// Srivastava & Sundaresan (2003), Powder Technol. 129, 72–85,
// doi:10.1016/S0032-5910(02)00132-8 (MFiX PRINCETON, SedFoam): the critical-state pressure
// P_c (Johnson–Jackson form) modified by dilatation, with the granular temperature
// smoothing the strain rate:
//   ζ = √(D':D' + Θ/d² + s²),  n = √3/(2 sin φ_f) if ∇·u ≥ 0 (dilation), 1.03 otherwise,
//   r = max(0, 1 − ∇·u/(n √2 sin φ_f ζ)),
//   p_f = P_c r^(n−1),   μ_f = max(0, √2 p_f sin φ_f (n − (n − 1) r)/(2ζ)).
// (p_f/P_c)^(1/(n−1)) = r is used directly. At ∇·u = 0 both branches give p_f = P_c and
// μ_f = √2 P_c sin φ_f/(2ζ); s (default 10⁻⁶ s⁻¹) keeps ζ > 0 at rest with Θ = 0.
struct SrivastavaSundaresan {
  JohnsonJacksonPressure critical_state_pressure;  // P_c(φ)
  double friction_angle;                           // φ_f [rad]
  double strain_rate_floor = default_strain_rate_floor;

  constexpr std::string_view name() const { return "SrivastavaSundaresan"; }
  constexpr std::string_view reference() const {
    return "Srivastava, A. & Sundaresan, S. (2003) Powder Technol. 129, 72-85, doi:10.1016/S0032-5910(02)00132-8";
  }
  void validate(std::string_view function) const {
    critical_state_pressure.validate(function);
    detail::validate_yield_parameters(function, friction_angle, strain_rate_floor);
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE FrictionalStress<S> operator()(const S& phi, const S& theta, const T& diameter,
                                                      const StrainRate<S>& rate) const {
    using std::pow;
    using std::sin;
    using std::sqrt;
    FLUIDBED_EXPECTS(value_of(theta) >= 0 && diameter > T(0) && value_of(rate.deviatoric_contraction) >= 0 &&
                     detail::valid_yield_parameters(friction_angle, strain_rate_floor));
    const S critical = critical_state_pressure(phi);
    const T sin_angle = sin(T(friction_angle)), floor = T(strain_rate_floor), sqrt2 = numbers::sqrt2<T>();
    const S zeta = sqrt(rate.deviatoric_contraction + theta / (diameter * diameter) + floor * floor);
    const T n = rate.divergence >= 0 ? numbers::sqrt3<T>() / (2 * sin_angle) : T(1.03L);
    // u = 1 − r: written in u, ∂μ_f/∂(∇·u) is exactly 0 at ∇·u = 0, as it is analytically.
    const S u = rate.divergence / ((n * sqrt2 * sin_angle) * zeta);
    if (u >= 1) return {S(0), S(0)};
    const S pressure = critical * pow(1 - u, n - 1);
    const S viscosity = detail::non_negative_part((sqrt2 * sin_angle / 2) * (pressure * (1 + (n - 1) * u)) / zeta);
    return {pressure, viscosity};
  }
};

// Checked entry points of the frictional viscosities (the pressures: evaluate_checked(law, φ),
// granular_state.hpp): validate the arguments and the law's parameters, throwing
// std::domain_error naming the argument and its value, then evaluate.
template <class T>
T evaluate_checked(const SchaefferViscosity& law, const T& frictional_pressure, const StrainRate<T>& rate) {
  const std::string function = detail::checked_function_name(law);
  require_non_negative(function, "frictional_pressure", frictional_pressure);
  validate(function, rate);
  law.validate(function);
  return law(frictional_pressure, rate);
}

template <class T>
FrictionalStress<T> evaluate_checked(const SrivastavaSundaresan& law, const T& phi, const T& theta, const T& diameter,
                                     const StrainRate<T>& rate) {
  const std::string function = detail::checked_function_name(law);
  validate_state(function, phi, theta);
  require_positive(function, "diameter", diameter);
  validate(function, rate);
  law.validate(function);
  return law(phi, theta, diameter, rate);
}

}  // namespace fluidbed::kinetic_theory
