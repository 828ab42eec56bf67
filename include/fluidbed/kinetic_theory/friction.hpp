// fluidbed — frictional stress of dense granular flow: a pressure p_f [Pa] and a viscosity
// μ_f [Pa s], per unit volume of suspension, ADDED to the kinetic-theory p_s and μ_s
// (Johnson & Jackson 1987: Σ = Σ_f + Σ_c; seeds 001 and 004) inside the sign convention of
// granular_state.hpp. Seed 004 writes Σ_f tension-positive (−p I + 2μS) next to a
// pressure-positive Σ_c; summed literally friction would act with the wrong sign.
//
// Frictional pressures are 0 below the onset fraction φ_min and grow steeply towards
// packing. Frictional viscosities divide by a strain rate: each law documents its floor.
// The friction angle is in radians. Preconditions (asserted in debug builds; law.checked(…)
// throws std::domain_error): φ ∈ [0, 1), Θ ≥ 0, d > 0, p_f ≥ 0, ∇·u finite, D':D' ≥ 0,
// 0 <= φ_min < φ_max <= 1, 0 < packing_margin < φ_max, friction angle in (0, π/2), strain-rate
// floor > 0, coefficients and exponents ≥ 0. The pressures have the shape g(φ)
// (SolidFractionLaw, granular_state.hpp); the viscosity and the Srivastava–Sundaresan stress
// their own, with with_derivatives members.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string_view>

#include "../core/constants.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// The default strain-rate floor s [s⁻¹] of the frictional viscosities.
inline constexpr double default_strain_rate_floor = 1e-6;

namespace detail {

// The parameters the frictional viscosities share: φ_f ∈ (0, π/2) and s > 0 (with s = 0 the
// viscosity is infinite, or 0/0, at rest).
FLUIDBED_HOST_DEVICE constexpr Arguments<double, 2> yield_domain(double friction_angle, double strain_rate_floor) {
  return {{{"friction_angle", friction_angle, domains::open(0.0, std::numbers::pi / 2)},
           {"strain_rate_floor", strain_rate_floor, domains::positive<double>()}}};
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
// 0.55–0.6, φ_max = 0.64. Registered with seed 001's Table 1, φ_min = 0.61, φ_max = 0.63.
// Validity: φ_min to φ_max (dense, enduring contacts).
struct JohnsonJacksonPressure : SolidFractionLaw<JohnsonJacksonPressure> {
  double min_fraction;                // φ_min, onset of friction
  double max_packing;                 // φ_max
  double coefficient = 0.05;          // Fr [Pa]
  double numerator_exponent = 2.0;    // a
  double denominator_exponent = 5.0;  // b
  double packing_margin = 0.01;

  constexpr JohnsonJacksonPressure(double min_fraction_, double max_packing_, double coefficient_ = 0.05,
                                   double numerator_exponent_ = 2.0, double denominator_exponent_ = 5.0,
                                   double packing_margin_ = 0.01)
      : min_fraction(min_fraction_),
        max_packing(max_packing_),
        coefficient(coefficient_),
        numerator_exponent(numerator_exponent_),
        denominator_exponent(denominator_exponent_),
        packing_margin(packing_margin_) {}
  static constexpr std::array<JohnsonJacksonPressure, 1> registered() { return {JohnsonJacksonPressure{0.61, 0.63}}; }
  constexpr std::string_view name() const { return "JohnsonJacksonPressure"; }
  constexpr std::string_view reference() const {
    return "Johnson, P.C. & Jackson, R. (1987) J. Fluid Mech. 176, 67-93; Johnson, P.C., Nott, P. & Jackson, R. "
           "(1990) J. Fluid Mech. 210, 501-535";
  }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", min_fraction, max_packing}}}; }
  constexpr Arguments<double, 6> parameter_domain() const {
    constexpr Interval<double> non_negative = domains::non_negative<double>();
    return join(detail::packing_domain(max_packing, packing_margin),
                Arguments<double, 4>{{{"min_fraction", min_fraction, domains::closed_open(0.0, max_packing)},
                                      {"coefficient", coefficient, non_negative},
                                      {"numerator_exponent", numerator_exponent, non_negative},
                                      {"denominator_exponent", denominator_exponent, non_negative}}});
  }
  static constexpr auto parameters() {
    return std::array{parameter<&JohnsonJacksonPressure::max_packing>("max_packing"),
                      parameter<&JohnsonJacksonPressure::packing_margin>("packing_margin"),
                      parameter<&JohnsonJacksonPressure::min_fraction>("min_fraction"),
                      parameter<&JohnsonJacksonPressure::coefficient>("coefficient"),
                      parameter<&JohnsonJacksonPressure::numerator_exponent>("numerator_exponent"),
                      parameter<&JohnsonJacksonPressure::denominator_exponent>("denominator_exponent")};
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi) const {
    using std::pow;
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
// singularity): it is a penalty that keeps φ near φ_min. Registered with φ_min = 0.5
// (OpenFOAM's alphaMinFriction in its tutorials). Validity: φ above φ_min, no stated bound.
struct SchaefferPressure : SolidFractionLaw<SchaefferPressure> {
  double min_fraction;        // φ_min
  double coefficient = 1e24;  // A [Pa]
  double exponent = 10.0;     // n

  constexpr explicit SchaefferPressure(double min_fraction_, double coefficient_ = 1e24, double exponent_ = 10.0)
      : min_fraction(min_fraction_), coefficient(coefficient_), exponent(exponent_) {}
  static constexpr std::array<SchaefferPressure, 1> registered() { return {SchaefferPressure{0.5}}; }
  constexpr std::string_view name() const { return "SchaefferPressure"; }
  constexpr std::string_view reference() const { return detail::references::schaeffer_1987; }
  constexpr Validity<1> validity() const { return {{{"solid_fraction", min_fraction, 1.0}}}; }
  constexpr Arguments<double, 3> parameter_domain() const {
    return {{{"min_fraction", min_fraction, domains::closed_open(0.0, 1.0)},
             {"coefficient", coefficient, domains::non_negative<double>()},
             {"exponent", exponent, domains::non_negative<double>()}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&SchaefferPressure::min_fraction>("min_fraction"),
                      parameter<&SchaefferPressure::coefficient>("coefficient"),
                      parameter<&SchaefferPressure::exponent>("exponent")};
  }
  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& phi) const {
    using std::pow;
    using T = value_type_of<S>;
    const T onset = T(min_fraction);
    if (!(phi > onset)) return S(0);
    return T(coefficient) * pow(phi - onset, T(exponent));
  }
};

// μ_f of SchaefferViscosity with its partial derivatives in its arguments.
template <class T>
struct SchaefferViscosityDerivatives {
  T value;
  T d_frictional_pressure;
  T d_divergence;  // 0
  T d_deviatoric_contraction;
};

// Schaeffer's (1987) frictional viscosity, the Coulomb yield condition written as a
// viscosity (seed 001 eq. 38, seed 004):
//   μ_f = p_f sin φ_f / (2 √(I_2D + s²)),   I_2D = ½ D':D',
// s = strain_rate_floor (default 10⁻⁶ s⁻¹; OpenFOAM adds a small number to √I_2D, MFiX
// caps μ_f at 100 Pa s). In simple shear √I_2D = γ̇/2, so the shear stress is p_f sin φ_f.
// Seed 001 eq. 37 (μ = p sin φ, "Johnson–Jackson") lacks the 1/strain rate: it is a stress.
// Seed 004's I_2 is not said to be deviatoric; with D:D instead of D':D' μ_f changes.
// Registered with seed 001's φ_f = 30°. Validity: none stated (a yield condition, Validity<0>).
struct SchaefferViscosity : KineticTheoryLaw<SchaefferViscosity> {
  double friction_angle;                                 // φ_f [rad]
  double strain_rate_floor = default_strain_rate_floor;  // s [s⁻¹]

  constexpr explicit SchaefferViscosity(double friction_angle_, double strain_rate_floor_ = default_strain_rate_floor)
      : friction_angle(friction_angle_), strain_rate_floor(strain_rate_floor_) {}
  static constexpr std::array<SchaefferViscosity, 1> registered() {
    return {SchaefferViscosity{std::numbers::pi / 6}};
  }
  constexpr std::string_view name() const { return "SchaefferViscosity"; }
  constexpr std::string_view reference() const { return detail::references::schaeffer_1987; }
  constexpr Validity<0> validity() const { return {}; }
  constexpr Arguments<double, 2> parameter_domain() const {
    return detail::yield_domain(friction_angle, strain_rate_floor);
  }
  static constexpr auto parameters() {
    return std::array{parameter<&SchaefferViscosity::friction_angle>("friction_angle"),
                      parameter<&SchaefferViscosity::strain_rate_floor>("strain_rate_floor")};
  }
  // p_f ≥ 0, the strain rate as domain(StrainRate).
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 3> argument_domain(const T& frictional_pressure,
                                                                          const StrainRate<T>& rate) {
    return join(Arguments<T, 1>{{{"frictional_pressure", frictional_pressure, domains::non_negative<T>()}}},
                kinetic_theory::domain(rate));
  }

  // μ_f with ∂/∂p_f, ∂/∂(∇·u) (0: μ_f does not depend on it) and ∂/∂(D':D'); for ∂μ_f/∂φ pass
  // p_f as a Dual to the hot path.
  template <class T>
  FLUIDBED_HOST_DEVICE SchaefferViscosityDerivatives<T> with_derivatives(const T& frictional_pressure,
                                                                         const StrainRate<T>& rate) const {
    using D = Dual<T, 3>;
    const D mu = (*this)(D::variable(frictional_pressure, 0),
                         StrainRate<D>{D::variable(rate.divergence, 1), D::variable(rate.deviatoric_contraction, 2)});
    return {mu.value, mu.derivative[0], mu.derivative[1], mu.derivative[2]};
  }
  template <class T>
  SchaefferViscosityDerivatives<T> checked_with_derivatives(const T& frictional_pressure,
                                                            const StrainRate<T>& rate) const {
    require_valid(frictional_pressure, rate);
    return with_derivatives(frictional_pressure, rate);
  }

  template <class S>
  FLUIDBED_HOST_DEVICE S kernel(const S& frictional_pressure, const StrainRate<S>& rate) const {
    using std::sin;
    using std::sqrt;
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

// A frictional pressure or viscosity with its partial derivatives in the state (φ, Θ, ∇·u, D':D').
template <class T>
struct FrictionDerivatives {
  T value;
  T d_solid_fraction;
  T d_granular_temperature;
  T d_divergence;
  T d_deviatoric_contraction;
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
// Registered with P_c = JohnsonJacksonPressure{0.5, 0.63} and φ_f = 28.5° (MFiX's PRINCETON
// tutorials). Validity: none stated (Validity<0>).
struct SrivastavaSundaresan : KineticTheoryLaw<SrivastavaSundaresan> {
  JohnsonJacksonPressure critical_state_pressure;  // P_c(φ)
  double friction_angle;                           // φ_f [rad]
  double strain_rate_floor = default_strain_rate_floor;

  constexpr SrivastavaSundaresan(const JohnsonJacksonPressure& critical_state_pressure_, double friction_angle_,
                                 double strain_rate_floor_ = default_strain_rate_floor)
      : critical_state_pressure(critical_state_pressure_),
        friction_angle(friction_angle_),
        strain_rate_floor(strain_rate_floor_) {}
  static constexpr std::array<SrivastavaSundaresan, 1> registered() {
    return {SrivastavaSundaresan{JohnsonJacksonPressure{0.5, 0.63}, 28.5 * std::numbers::pi / 180}};
  }
  constexpr std::string_view name() const { return "SrivastavaSundaresan"; }
  constexpr std::string_view reference() const {
    return "Srivastava, A. & Sundaresan, S. (2003) Powder Technol. 129, 72-85, doi:10.1016/S0032-5910(02)00132-8";
  }
  constexpr Validity<0> validity() const { return {}; }
  constexpr Arguments<double, 8> parameter_domain() const {
    return join(critical_state_pressure.parameter_domain(), detail::yield_domain(friction_angle, strain_rate_floor));
  }
  static constexpr auto parameters() {
    return join_parameters(nested_parameters<&SrivastavaSundaresan::critical_state_pressure>(),
                           std::array{parameter<&SrivastavaSundaresan::friction_angle>("friction_angle"),
                                      parameter<&SrivastavaSundaresan::strain_rate_floor>("strain_rate_floor")});
  }
  // φ ∈ [0, 1), Θ ≥ 0, d > 0, the strain rate as domain(StrainRate).
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 5> argument_domain(const T& phi, const T& theta,
                                                                          const T& diameter,
                                                                          const StrainRate<T>& rate) {
    return join(Arguments<T, 3>{detail::solid_fraction(phi), detail::granular_temperature(theta),
                                {"diameter", diameter, domains::positive<T>()}},
                kinetic_theory::domain(rate));
  }

  // p_f and μ_f, each with ∂/∂φ, ∂/∂Θ, ∂/∂(∇·u) and ∂/∂(D':D').
  template <class T>
  FLUIDBED_HOST_DEVICE FrictionalStress<FrictionDerivatives<T>> with_derivatives(const T& phi, const T& theta,
                                                                                 const T& diameter,
                                                                                 const StrainRate<T>& rate) const {
    using D = Dual<T, 4>;
    const FrictionalStress<D> stress =
        (*this)(D::variable(phi, 0), D::variable(theta, 1), diameter,
                StrainRate<D>{D::variable(rate.divergence, 2), D::variable(rate.deviatoric_contraction, 3)});
    const auto split = [](const D& x) {
      return FrictionDerivatives<T>{x.value, x.derivative[0], x.derivative[1], x.derivative[2], x.derivative[3]};
    };
    return {split(stress.pressure), split(stress.viscosity)};
  }
  template <class T>
  FrictionalStress<FrictionDerivatives<T>> checked_with_derivatives(const T& phi, const T& theta, const T& diameter,
                                                                    const StrainRate<T>& rate) const {
    require_valid(phi, theta, diameter, rate);
    return with_derivatives(phi, theta, diameter, rate);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE FrictionalStress<S> kernel(const S& phi, const S& theta, const T& diameter,
                                                  const StrainRate<S>& rate) const {
    using std::pow;
    using std::sin;
    using std::sqrt;
    const S critical = critical_state_pressure.kernel(phi);
    const T sin_angle = sin(T(friction_angle)), floor = T(strain_rate_floor), sqrt2 = numbers::sqrt2<T>();
    const S zeta = sqrt(rate.deviatoric_contraction + theta / (diameter * diameter) + floor * floor);
    const T n = rate.divergence >= 0 ? numbers::sqrt3<T>() / (2 * sin_angle) : FLUIDBED_DECIMAL(T, 1.03);
    // u = 1 − r: written in u, ∂μ_f/∂(∇·u) is exactly 0 at ∇·u = 0, as it is analytically.
    const S u = rate.divergence / ((n * sqrt2 * sin_angle) * zeta);
    if (u >= 1) return {S(0), S(0)};
    const S pressure = critical * pow(1 - u, n - 1);
    const S viscosity = detail::non_negative_part((sqrt2 * sin_angle / 2) * (pressure * (1 + (n - 1) * u)) / zeta);
    return {pressure, viscosity};
  }
};

// The frictional pressures of N solids classes with their derivatives in every class fraction.
template <class T, std::size_t N>
struct ClassFrictionalPressureDerivatives {
  std::array<T, N> value;                       // p_i^f [Pa]
  std::array<std::array<T, N>, N> d_fractions;  // d_fractions[i][m] = ∂p_i^f/∂φ_m
};

// The mixture's frictional pressure split among N solids classes by mass fraction (seed 004,
// slide "Frictional transfer", after Johnson & Jackson 1987 and Anderson & Jackson 1992):
//   p_i^f = [φ_i ρ_i / Σ_j φ_j ρ_j] p^f(φ_t),   φ_t = Σ_j φ_j,
// p^f the mixture's law of this header (`total`: JohnsonJacksonPressure, SchaefferPressure, …;
// a host holding the FrictionalPressures variant visits it), φ_i the class volume fractions, ρ_i
// their material densities [kg m⁻³]. Pressure-positive, per unit volume of suspension, like
// every pressure of the library; seed 004 writes the frictional stress tension-positive,
// Σ_i^f = −p_i^f I + 2μ_i^f S_i, and p_i^f here is the p_i^f of that −p I. The split sums to
// p^f(φ_t) (to rounding) and one class gets the law itself, exactly. With no solids (every
// φ_i = 0) each p_i^f is 0, not 0/0. Derivatives: ∂p_i^f/∂φ_m = (ρ_m/M)(δ_im − x_i) p^f + x_i
// dp^f/dφ_t, x_i = φ_iρ_i/M, M = Σ_j φ_jρ_j (by dual numbers). Preconditions (asserted in
// debug builds; checked(…) throws std::domain_error naming the argument): φ_i ≥ 0, Σφ_i < 1,
// ρ_i > 0, and the law's own. Validity: the law's, at φ_t.
template <class Pressure>
struct ClassFrictionalPressures {
  Pressure total;  // p^f(φ_t) of the whole solids phase

  static constexpr std::string_view reference() {
    return "seed 004 (slide \"Frictional transfer\"): split by mass fraction; the law's own reference for p^f";
  }
  constexpr auto validity() const { return total.validity(); }

  // Hot path: p_i^f for each class.
  template <class S, class T, std::size_t N>
  FLUIDBED_HOST_DEVICE constexpr std::array<S, N> operator()(const std::array<S, N>& fractions,
                                                             const std::array<T, N>& densities) const {
    static_assert(N >= 1, "at least one solids class");
    S total_fraction(0), total_mass(0);
    for (std::size_t i = 0; i < N; ++i) {
      FLUIDBED_EXPECTS(value_of(fractions[i]) >= 0 && densities[i] > 0);
      total_fraction = total_fraction + fractions[i];  // (Dual has no +=)
      total_mass = total_mass + fractions[i] * densities[i];
    }
    std::array<S, N> split{};
    if (!(value_of(total_mass) > 0)) return split;
    const S pressure = total(total_fraction);
    // (φ_iρ_i/M) p rather than φ_iρ_i (p/M): one class gets exactly 1 · p.
    for (std::size_t i = 0; i < N; ++i) split[i] = (fractions[i] * densities[i] / total_mass) * pressure;
    return split;
  }

  // p_i^f and ∂p_i^f/∂φ_m for every class i and m (hot path).
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassFrictionalPressureDerivatives<T, N> with_derivatives(
      const std::array<T, N>& fractions, const std::array<T, N>& densities) const {
    using D = Dual<T, int(N)>;
    std::array<D, N> dual_fractions{};
    for (std::size_t m = 0; m < N; ++m) dual_fractions[m] = D::variable(fractions[m], int(m));
    const std::array<D, N> split = (*this)(dual_fractions, densities);
    ClassFrictionalPressureDerivatives<T, N> result{};
    for (std::size_t i = 0; i < N; ++i) {
      result.value[i] = split[i].value;
      for (std::size_t m = 0; m < N; ++m) result.d_fractions[i][m] = split[i].derivative[m];
    }
    return result;
  }

  template <class T, std::size_t N>
  std::array<T, N> checked(const std::array<T, N>& fractions, const std::array<T, N>& densities) const {
    require_valid(fractions, densities);
    return (*this)(fractions, densities);
  }
  template <class T, std::size_t N>
  ClassFrictionalPressureDerivatives<T, N> checked_with_derivatives(const std::array<T, N>& fractions,
                                                                    const std::array<T, N>& densities) const {
    require_valid(fractions, densities);
    return with_derivatives(fractions, densities);
  }

  // Throws as `checked` would, without evaluating: each φ_i ≥ 0 and ρ_i > 0, Σφ_i < 1
  // ("kinetic_theory::ClassFrictionalPressures"), then the law's argument and parameters.
  template <class T, std::size_t N>
  void require_valid(const std::array<T, N>& fractions, const std::array<T, N>& densities) const {
    constexpr std::string_view function = "kinetic_theory::ClassFrictionalPressures";
    T total_fraction(0);
    for (std::size_t i = 0; i < N; ++i) {
      require_in(function, indexed_argument("fractions", i), fractions[i], domains::non_negative<T>());
      require_in(function, indexed_argument("densities", i), densities[i], domains::positive<T>());
      total_fraction += fractions[i];
    }
    require_in(function, "sum of fractions", total_fraction, domains::closed_open(T(0), T(1)));
    total.require_valid(total_fraction);
  }
};

}  // namespace fluidbed::kinetic_theory
