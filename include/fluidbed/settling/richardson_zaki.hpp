// fluidbed — the Richardson–Zaki law of homogeneous expansion and correlations for its
// exponent n.
//
//   u_s = u_t ε^n                                            (seed 000 eq. 3.22)
//
// u_s: superficial fluid velocity (fluidization) or sedimentation velocity of the
// suspension; u_t: unhindered terminal velocity of one particle; ε: voidage.
// Reynolds and Archimedes numbers (properties.hpp):
//   Re_t = ρ_f u_t d / μ_f                                   (seed 000 eq. 3.23)
//   Ar   = ρ_f (ρ_p − ρ_f) g d³ / μ_f²
// wall_ratio is d/D, the particle over the column diameter (0: no wall effect).
//
// The correlations differ mainly in their viscous / inertial limits (seed 000 §3.4.3):
//   richardson_zaki_exponent_mazzei            4.80 / 2.40  (seed 000 eq. 3.24; the library's default)
//   richardson_zaki_exponent_1954              4.65 / 2.39  (d/D = 0)
//   richardson_zaki_exponent_rowe              4.70 / 2.343 (seed 000 quotes 2.35)
//   richardson_zaki_exponent_khan_richardson   4.80 / 2.40  (a function of Ar; d/D < 0.0391)
//   richardson_zaki_exponent_garside_al_dibouni 5.10 / 2.70
// The per-cell functions are templated on the scalar S (Dual numbers included) and
// have `_checked` versions that throw std::domain_error naming the argument.
#pragma once

#include <cmath>
#include <limits>
#include <sstream>
#include <string_view>
#include <type_traits>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"

namespace fluidbed::settling {

namespace detail {

// The wall factor 1 − 2.4 (d/D)^0.27 of Khan & Richardson (1989).
template <class S>
FLUIDBED_HOST_DEVICE S khan_richardson_wall_factor(const S& wall_ratio) {
  using std::pow;
  using T = value_type_of<S>;
  return 1 - T(2.4L) * pow(wall_ratio, T(0.27L));
}

// y = 0.175 Re_t^¾, the variable in which eq. 3.24 reads n = 2.4 + 2.4/(1 + y).
template <class S>
FLUIDBED_HOST_DEVICE S scaled_power(const S& terminal_reynolds) {
  using std::pow;
  using T = value_type_of<S>;
  return T(0.175L) * pow(terminal_reynolds, T(0.75));
}

// Eq. 3.24 written in y = 0.175 Re_t^¾.
template <class S>
FLUIDBED_HOST_DEVICE S exponent_of_scaled_power(const S& y) {
  using T = value_type_of<S>;
  return T(2.4L) + T(2.4L) / (1 + y);
}

}  // namespace detail

// ----------------------------------------------------------------------------- exponents

// Mazzei (2008), seed 000 eq. 3.24; Mazzei & Lettieri (2007), Chem. Eng. Sci. 62,
// 6129–6142, doi:10.1016/j.ces.2007.06.028:
//
//   n = (4.8 + 2.4 · 0.175 Re_t^¾) / (1 + 0.175 Re_t^¾) = 2.4 + 2.4 / (1 + 0.175 Re_t^¾).
//
// Rowe's (1987) form with the limits 4.8 (Re_t → 0) and 2.4 (Re_t → ∞) of Khan &
// Richardson (1989) and Gibilaro (2001). Together with Dallavalle's terminal velocity it is
// the expansion law the Mazzei–Lettieri drag reproduces exactly (seed 000 §3.4.5).
// Precondition: Re_t >= 0. Values: n(1) = 4.442553191, n(10) = 3.609618, n(100) = 2.767310.
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_exponent_mazzei(const S& terminal_reynolds) {
  FLUIDBED_EXPECTS(!(terminal_reynolds < S(0)));
  return detail::exponent_of_scaled_power(detail::scaled_power(terminal_reynolds));
}

// dn/dRe_t of eq. 3.24 = −0.315 Re_t^−¼ / (1 + 0.175 Re_t^¾)² (0.315 = ¾ · 0.175 · 2.4;
// seed 000 eq. 3.103, the function N of Table 3.1 in simplified form). −∞ at Re_t = 0.
// Precondition: Re_t >= 0.
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_exponent_mazzei_derivative(const S& terminal_reynolds) {
  using std::pow;
  using T = value_type_of<S>;
  FLUIDBED_EXPECTS(!(terminal_reynolds < S(0)));
  const S one_plus_x = 1 + detail::scaled_power(terminal_reynolds);
  return T(-0.315L) * pow(terminal_reynolds, T(-0.25)) / (one_plus_x * one_plus_x);
}

// Richardson, J.F., Zaki, W.N. (1954), "Sedimentation and fluidisation: Part I",
// Trans. Inst. Chem. Eng. 32, 35–53 (reprinted Chem. Eng. Res. Des. 75 (1997) S82–S100,
// doi:10.1016/S0263-8762(97)80006-8), with the wall term d/D:
//
//   Re_t < 0.2          n = 4.65 + 19.5 d/D
//   0.2 <= Re_t < 1     n = (4.35 + 17.5 d/D) Re_t^−0.03
//   1   <= Re_t < 200   n = (4.45 + 18 d/D) Re_t^−0.1
//   200 <= Re_t < 500   n = 4.45 Re_t^−0.1
//   500 <= Re_t         n = 2.39
//
// Re_t is that of a particle in an unbounded fluid. Piecewise and discontinuous as
// published: at d/D = 0 the jumps are −0.085 at Re_t = 0.2, +0.10 at 1, 0 at 200 and
// −0.0004 at 500 (the wall terms add their own). Fitted for 0 <= d/D <~ 0.1.
// Preconditions: Re_t >= 0, 0 <= d/D < 1.
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_exponent_1954(const S& terminal_reynolds,
                                                     const std::type_identity_t<S>& wall_ratio = S(0)) {
  using std::pow;
  using T = value_type_of<S>;
  FLUIDBED_EXPECTS(!(terminal_reynolds < S(0)) && !(wall_ratio < S(0)) && wall_ratio < S(1));
  if (terminal_reynolds < constant_as<S>(0.2L)) return T(4.65L) + T(19.5) * wall_ratio;
  if (terminal_reynolds < 1) return (T(4.35L) + T(17.5) * wall_ratio) * pow(terminal_reynolds, T(-0.03L));
  if (terminal_reynolds < 200) return (T(4.45L) + 18 * wall_ratio) * pow(terminal_reynolds, T(-0.1L));
  if (terminal_reynolds < 500) return T(4.45L) * pow(terminal_reynolds, T(-0.1L));
  return S(T(2.39L));
}

// Rowe, P.N. (1987), "A convenient empirical equation for estimation of the
// Richardson–Zaki exponent", Chem. Eng. Sci. 42, 2795–2796:
//
//   n = (4.7 + 0.41 Re_t^¾) / (1 + 0.175 Re_t^¾),
//
// a smooth fit of the 1954 correlation without wall effect; limits 4.7 and
// 0.41/0.175 = 2.342857 (seed 000 §3.4.3 quotes 2.35). Precondition: Re_t >= 0.
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_exponent_rowe(const S& terminal_reynolds) {
  using std::pow;
  using T = value_type_of<S>;
  FLUIDBED_EXPECTS(!(terminal_reynolds < S(0)));
  const S x = pow(terminal_reynolds, T(0.75));
  return (T(4.7L) + T(0.41L) * x) / (1 + T(0.175L) * x);
}

// Khan, A.R., Richardson, J.F. (1989), "Fluid-particle interactions and flow
// characteristics of fluidized beds and settling suspensions of spherical particles",
// Chem. Eng. Commun. 78, 111–130:
//
//   (4.8 − n)/(n − 2.4) = X,   X = 0.043 Ar^0.57 [1 − 2.4 (d/D)^0.27],
//   i.e. n = 2.4 + 2.4/(1 + X),
//
// a function of Ar (not of Re_t). Limits 4.8 (Ar → 0) and 2.4 (Ar → ∞). The wall factor
// is positive only for d/D < (1/2.4)^(1/0.27) = 0.0391; beyond, X < 0, n grows with Ar
// and has a pole at X = −1: the correlation has left its data, and such d/D are out of
// domain. Preconditions: Ar >= 0, d/D >= 0 with 1 − 2.4 (d/D)^0.27 > 0.
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_exponent_khan_richardson(const S& archimedes,
                                                                const std::type_identity_t<S>& wall_ratio = S(0)) {
  using std::pow;
  const S wall_factor = detail::khan_richardson_wall_factor(S(wall_ratio));
  using T = value_type_of<S>;
  FLUIDBED_EXPECTS(!(archimedes < S(0)) && !(wall_ratio < S(0)) && wall_factor > S(0));
  return T(2.4L) + T(2.4L) / (1 + T(0.043L) * pow(archimedes, T(0.57L)) * wall_factor);
}

// Garside, J., Al-Dibouni, M.R. (1977), "Velocity-voidage relationships for
// fluidization and sedimentation in solid-liquid systems", Ind. Eng. Chem. Process Des.
// Dev. 16, 206–214, doi:10.1021/i260062a008:
//
//   (5.1 − n)/(n − 2.7) = 0.1 Re_t^0.9,   i.e. n = 2.7 + 2.4/(1 + 0.1 Re_t^0.9);
//
// limits 5.1 and 2.7. Precondition: Re_t >= 0.
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_exponent_garside_al_dibouni(const S& terminal_reynolds) {
  using std::pow;
  using T = value_type_of<S>;
  FLUIDBED_EXPECTS(!(terminal_reynolds < S(0)));
  return T(2.7L) + T(2.4L) / (1 + T(0.1L) * pow(terminal_reynolds, T(0.9L)));
}

// ----------------------------------------------------------------------------- the law

// u_s = u_t ε^n (seed 000 eq. 3.22). Preconditions: u_t >= 0, ε ∈ (0, 1], n > 0.
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_velocity(const S& terminal_velocity, const std::type_identity_t<S>& voidage,
                                                const std::type_identity_t<S>& exponent) {
  using std::pow;
  FLUIDBED_EXPECTS(voidage > S(0) && voidage <= S(1) && exponent > S(0));
  return terminal_velocity * pow(voidage, exponent);
}

// ε = (u_s/u_t)^(1/n), the inverse of eq. 3.22. Preconditions: 0 < u_s <= u_t, n > 0
// (u_s > u_t would give ε > 1: the particles are carried out, there is no bed).
template <class S>
FLUIDBED_HOST_DEVICE S richardson_zaki_voidage(const S& superficial_velocity,
                                               const std::type_identity_t<S>& terminal_velocity,
                                               const std::type_identity_t<S>& exponent) {
  using std::pow;
  FLUIDBED_EXPECTS(superficial_velocity > S(0) && superficial_velocity <= terminal_velocity && exponent > S(0));
  return pow(superficial_velocity / terminal_velocity, 1 / exponent);
}

namespace detail {

// The converged relation Re = Re_t ε^n(Re_t) of eq. 3.24: ln Re_t, y = 0.175 Re_t^¾ (so
// n = 2.4 + 2.4/(1 + y)) and ln ε — all a per-cell caller (the Mazzei–Lettieri drag)
// needs, with no further transcendental function.
template <class T>
struct TerminalReynoldsSolution {
  T log_terminal_reynolds, scaled_power, log_voidage;
};

// Halley's method on g(x) = x + n(eˣ) ln ε − ln Re, x = ln Re_t, from the middle of the
// bracket [ln Re − 2.4 ln ε, ln Re − 4.8 ln ε] (n = 3.6). With y = 0.175 e^(0.75x),
// r = 1/(1 + y) and L = ln ε:
//   n = 2.4 + 2.4 r,  y r = 1 − r,  dy/dx = 0.75 y,
//   g   = x + 2.4 L − ln Re + 2.4 L r
//   g'  = 1 − 1.8 L y r²                 = 1 − 1.8 L r (1 − r)          (≥ 1: the root is unique)
//   g'' = −1.35 L y (1 − y) r³           = −1.35 L r (1 − r)(2r − 1)
// and the Halley step 2 g g'/(2 g'² − g g''): one exp and two divisions per step, no pow.
// Written in r ∈ [0, 1], every term is bounded by a multiple of |L| and of the distance to
// the root, whatever Re and ε: written in p = 1 + y (g = G/p, S₁ = p² g', S₂ = p³ g''), it squares
// S₁ ≈ y², which overflows once ln Re_t >~ 239 (double) or 32 (float) and turns the step
// into ∞/∞. Here y may overflow to +∞ (Re_t beyond the range of T) and r is then 0: n = 2.4
// exactly and g is linear.
// Safeguard. For |L| >~ 20 (ε <~ 1e-9) n(eˣ) is a step of height 2.4 |L| a few units of x
// wide, and Halley's (or Newton's) iteration can cycle across it. g is increasing, so the
// iteration keeps a bracket [low, high] of the root (g(low) <= 0 <= g(high)) and bisects
// it whenever a step would leave it or fails to halve the step before (rtsafe of Press et
// al., Numerical Recipes, 3rd ed. §9.4); on a fluidized bed's states no step does. It stops
// only after a Halley step, whose size bounds the error (a bisection's does not).
// Convergence is cubic: a step of size s leaves an error below 0.02 s³ on ε ∈ [0.01, 1],
// Re ∈ [1e-10, 1e10], hence the stop at s ≤ 4 ∛ε_machine; 2.3 steps on average over a
// fluidized bed's states, at most 4.
// Preconditions: Re > 0, ε ∈ (0, 1], both finite.
template <class T>
FLUIDBED_HOST_DEVICE TerminalReynoldsSolution<T> solve_terminal_reynolds(const T& reynolds, const T& voidage) {
  using std::abs;
  using std::cbrt;
  using std::exp;
  using std::log;
  const T log_voidage = log(voidage);
  const T log_re = log(reynolds);
  const T stop = T(4) * cbrt(std::numeric_limits<T>::epsilon());
  // The bracket, widened by 1 so that a root at one of its ends (n = 4.8 or 2.4 to rounding)
  // lies strictly inside it: a step that lands on an end is then one that cycles.
  T low = log_re - T(2.4L) * log_voidage - 1;
  T high = log_re - T(4.8L) * log_voidage + 1;
  T x = log_re - T(3.6L) * log_voidage;
  T previous = high - low;  // the size of the last step taken
  T y{};
  for (int iteration = 0; iteration < 100; ++iteration) {
    y = T(0.175L) * exp(T(0.75) * x);
    const T r = T(1) / (T(1) + y);
    const T r_q = r * (T(1) - r);  // y r² = y/(1 + y)², from r so that y = ∞ gives 0
    const T g = x + T(2.4L) * log_voidage - log_re + T(2.4L) * log_voidage * r;
    const T d1 = T(1) - T(1.8L) * log_voidage * r_q;
    const T d2 = T(-1.35L) * log_voidage * r_q * (T(2) * r - T(1));
    const T step = T(2) * g * d1 / (T(2) * d1 * d1 - g * d2);
    if (abs(step) <= stop) {
      x -= step;
      const T z = T(0.75) * step;
      y *= T(1) - z + T(0.5) * z * z;  // y at the updated x, to O(step³) ~ ε_machine
      break;
    }
    // A step this large starts far enough from the root for the sign of g to be exact.
    (g < T(0) ? low : high) = x;
    const T next = x - step;
    const T taken = next > low && next < high && abs(step) <= T(0.5) * previous ? next : T(0.5) * (low + high);
    previous = abs(x - taken);
    x = taken;
  }
  return {x, y, log_voidage};
}

}  // namespace detail

// The terminal Reynolds number Re_t for which Richardson–Zaki with the exponent of
// eq. 3.24 puts a bed fluidized at the superficial Reynolds number Re = ρ_f u_s d/μ_f at
// the voidage ε:  Re = Re_t ε^n(Re_t)  (seed 000 §3.4.4.1, the procedure behind
// Figs 3.1–3.5; the same relation defines Re* of eq. 3.53, the Mazzei–Lettieri drag's).
// Re_t = Re at ε = 1 and Re_t = 0 at Re = 0; +∞ where Re_t exceeds the range of T (ln Re_t,
// which the solver returns, is finite for every finite Re and ε). Preconditions: Re >= 0 finite,
// ε ∈ (0, 1].
template <class T>
FLUIDBED_HOST_DEVICE T richardson_zaki_terminal_reynolds(const T& reynolds, const T& voidage) {
  using std::exp;
  FLUIDBED_EXPECTS(!(reynolds < T(0)) && voidage > T(0) && voidage <= T(1));
  if (voidage == T(1) || reynolds == T(0)) return reynolds;
  return exp(detail::solve_terminal_reynolds(reynolds, voidage).log_terminal_reynolds);
}

// ----------------------------------------------------------------------------- checked

template <class T>
T richardson_zaki_exponent_mazzei_checked(const T& terminal_reynolds) {
  require_non_negative("richardson_zaki_exponent_mazzei", "terminal_reynolds", terminal_reynolds);
  return richardson_zaki_exponent_mazzei(terminal_reynolds);
}

template <class T>
T richardson_zaki_exponent_mazzei_derivative_checked(const T& terminal_reynolds) {
  require_non_negative("richardson_zaki_exponent_mazzei_derivative", "terminal_reynolds", terminal_reynolds);
  return richardson_zaki_exponent_mazzei_derivative(terminal_reynolds);
}

template <class T>
T richardson_zaki_exponent_1954_checked(const T& terminal_reynolds, const std::type_identity_t<T>& wall_ratio = T(0)) {
  require_non_negative("richardson_zaki_exponent_1954", "terminal_reynolds", terminal_reynolds);
  require_in_closed_open("richardson_zaki_exponent_1954", "wall_ratio", wall_ratio, T(0), T(1));
  return richardson_zaki_exponent_1954(terminal_reynolds, wall_ratio);
}

template <class T>
T richardson_zaki_exponent_rowe_checked(const T& terminal_reynolds) {
  require_non_negative("richardson_zaki_exponent_rowe", "terminal_reynolds", terminal_reynolds);
  return richardson_zaki_exponent_rowe(terminal_reynolds);
}

template <class T>
T richardson_zaki_exponent_khan_richardson_checked(const T& archimedes,
                                                   const std::type_identity_t<T>& wall_ratio = T(0)) {
  constexpr std::string_view function = "richardson_zaki_exponent_khan_richardson";
  require_non_negative(function, "archimedes", archimedes);
  require_non_negative(function, "wall_ratio", wall_ratio);
  if (!(detail::khan_richardson_wall_factor(T(wall_ratio)) > T(0)))
    fluidbed::detail::throw_domain_error(function, "wall_ratio", wall_ratio,
                                         "must be < (1/2.4)^(1/0.27) = 0.0391, where 1 - 2.4 (d/D)^0.27 > 0");
  return richardson_zaki_exponent_khan_richardson(archimedes, wall_ratio);
}

template <class T>
T richardson_zaki_exponent_garside_al_dibouni_checked(const T& terminal_reynolds) {
  require_non_negative("richardson_zaki_exponent_garside_al_dibouni", "terminal_reynolds", terminal_reynolds);
  return richardson_zaki_exponent_garside_al_dibouni(terminal_reynolds);
}

template <class T>
T richardson_zaki_velocity_checked(const T& terminal_velocity, const std::type_identity_t<T>& voidage,
                                   const std::type_identity_t<T>& exponent) {
  require_non_negative("richardson_zaki_velocity", "terminal_velocity", terminal_velocity);
  require_in_half_open("richardson_zaki_velocity", "voidage", voidage, T(0), T(1));
  require_positive("richardson_zaki_velocity", "exponent", exponent);
  return richardson_zaki_velocity(terminal_velocity, voidage, exponent);
}

template <class T>
T richardson_zaki_voidage_checked(const T& superficial_velocity, const std::type_identity_t<T>& terminal_velocity,
                                  const std::type_identity_t<T>& exponent) {
  require_positive("richardson_zaki_voidage", "terminal_velocity", terminal_velocity);
  require_in_half_open("richardson_zaki_voidage", "superficial_velocity", superficial_velocity, T(0),
                       terminal_velocity);
  require_positive("richardson_zaki_voidage", "exponent", exponent);
  return richardson_zaki_voidage(superficial_velocity, terminal_velocity, exponent);
}

// Also throws std::domain_error where Re_t exceeds the range of T (e.g. Re = 1e300, ε = 1e-100).
template <class T>
T richardson_zaki_terminal_reynolds_checked(const T& reynolds, const T& voidage) {
  constexpr std::string_view function = "richardson_zaki_terminal_reynolds";
  require_non_negative(function, "reynolds", reynolds);
  require_in_half_open(function, "voidage", voidage, T(0), T(1));
  const T terminal_reynolds = richardson_zaki_terminal_reynolds(reynolds, voidage);
  require_finite_result(function, "terminal_reynolds", terminal_reynolds, [&] {
    std::ostringstream text;
    text.precision(17);
    text << "reynolds = " << reynolds << ", voidage = " << voidage;
    return text.str();
  });
  return terminal_reynolds;
}

}  // namespace fluidbed::settling
