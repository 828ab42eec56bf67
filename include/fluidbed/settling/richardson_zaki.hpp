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
// The exponent correlations are value types deriving from RichardsonZakiExponent<Law>;
// they differ mainly in their viscous / inertial limits (seed 000 §3.4.3):
//   MazzeiExponent              4.80 / 2.40  (seed 000 eq. 3.24; the library's default)
//   RichardsonZaki1954Exponent  4.65 / 2.39  (d/D = 0)
//   RoweExponent                4.70 / 2.343 (seed 000 quotes 2.35)
//   KhanRichardsonExponent      4.80 / 2.40  (a function of Ar; d/D < 0.0391)
//   GarsideAlDibouniExponent    5.10 / 2.70
// Registry: RichardsonZakiExponents. The relations (richardson_zaki_velocity, _voidage,
// _terminal_reynolds) take an error policy as their last argument: fluidbed::checked throws
// std::domain_error naming the argument, the default asserts in debug builds.
#pragma once

#include <cmath>
#include <limits>
#include <string_view>
#include <type_traits>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../core/registry.hpp"

namespace fluidbed::settling {

// ----------------------------------------------------------------------------- exponents

// n and dn/dx, x the law's argument (`Law::argument`: Re_t, or Ar for Khan–Richardson).
template <class T>
struct ExponentWithDerivative {
  T value;       // n
  T d_argument;  // dn/dx
};

// CRTP base of the exponent correlations. Law provides name(), reference(), validity(),
//   static constexpr std::string_view argument;   "terminal_reynolds" (Re_t) or "archimedes" (Ar)
//   template <class S> S exponent(const S& x) const;   the kernel, S = T or Dual<T, 1>
// and, if it has parameters (d/D), `template <class T> Arguments<T, N> parameter_domain() const`.
// The base gives
//   law(x)                          n (hot path; x >= 0 and the parameters asserted in debug builds)
//   law.with_derivatives(x)         n and dn/dx, through Dual on the kernel (or the law's
//                                   `static S slope(x)` where its source gives dn/dx in closed form)
//   law.checked(x), law.checked_with_derivatives(x)   throw std::domain_error naming the
//                                   first argument outside its domain.
// A host holding a RichardsonZakiExponents::Variant reads `argument` to know which number to pass.
template <class Law>
struct RichardsonZakiExponent {
  // The domain of a call, declared once: x finite and >= 0, then the law's parameters.
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr auto domain(const T& x) const {
    const Arguments<T, 1> own{{{Law::argument, x, domains::non_negative<T>()}}};
    return join(own, parameter_domain_of<T>(self()));
  }

  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S operator()(const S& x) const {
    FLUIDBED_EXPECTS(within(domain(value_of(x))));
    return self().exponent(x);
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr ExponentWithDerivative<T> with_derivatives(const T& x) const {
    if constexpr (requires { Law::slope(x); }) {  // a law whose source gives dn/dx in closed form
      FLUIDBED_EXPECTS(within(domain(x)));
      return {self().exponent(x), Law::slope(x)};
    } else {
      const Dual<T, 1> n = (*this)(Dual<T, 1>::variable(x, 0));
      return {n.value, n.derivative[0]};
    }
  }

  template <class T>
  T checked(const T& x) const {
    require_within(self().name(), domain(x));
    return (*this)(x);
  }

  template <class T>
  ExponentWithDerivative<T> checked_with_derivatives(const T& x) const {
    require_within(self().name(), domain(x));
    return with_derivatives(x);
  }

 private:
  FLUIDBED_HOST_DEVICE constexpr const Law& self() const { return static_cast<const Law&>(*this); }
};

// Mazzei (2008), seed 000 eq. 3.24; Mazzei & Lettieri (2007), Chem. Eng. Sci. 62,
// 6129–6142, doi:10.1016/j.ces.2007.06.028:
//
//   n = (4.8 + 2.4 · 0.175 Re_t^¾) / (1 + 0.175 Re_t^¾) = 2.4 + 2.4 / (1 + 0.175 Re_t^¾).
//
// Rowe's (1987) form with the limits 4.8 (Re_t → 0) and 2.4 (Re_t → ∞) of Khan &
// Richardson (1989) and Gibilaro (2001). Together with Dallavalle's terminal velocity it is
// the expansion law the Mazzei–Lettieri drag reproduces exactly (seed 000 §3.4.5).
// dn/dRe_t = −0.315 Re_t^−¼ / (1 + 0.175 Re_t^¾)² (seed 000 eq. 3.103, the function N of
// Table 3.1 in simplified form), −∞ at Re_t = 0: `slope`, which with_derivatives returns.
// Values: n(1) = 4.442553191, n(10) = 3.609618, n(100) = 2.767310.
// Validity: every Re_t >= 0, by construction between the two limits.
struct MazzeiExponent : RichardsonZakiExponent<MazzeiExponent> {
  static constexpr const char* argument = "terminal_reynolds";
  constexpr std::string_view name() const { return "MazzeiExponent"; }
  constexpr std::string_view reference() const {
    return "Mazzei, L., Lettieri, P. (2007) Chem. Eng. Sci. 62, 6129-6142, doi:10.1016/j.ces.2007.06.028";
  }
  constexpr Validity<1> validity() const {
    return {{{"terminal_reynolds", 0.0, std::numeric_limits<double>::infinity()}}};
  }

  // y = 0.175 Re_t^¾, the variable in which eq. 3.24 reads n = 2.4 + 2.4/(1 + y).
  template <class S>
  FLUIDBED_HOST_DEVICE static S scaled_power(const S& terminal_reynolds) {
    using std::pow;
    using T = value_type_of<S>;
    return FLUIDBED_DECIMAL(T, 0.175) * pow(terminal_reynolds, T(0.75));
  }

  // Eq. 3.24 written in y = 0.175 Re_t^¾ (what a caller that has y already needs: the
  // Mazzei–Lettieri drag and elastic modulus).
  template <class S>
  FLUIDBED_HOST_DEVICE static S of_scaled_power(const S& y) {
    using T = value_type_of<S>;
    return FLUIDBED_DECIMAL(T, 2.4) + FLUIDBED_DECIMAL(T, 2.4) / (1 + y);
  }

  // The kernel, without the hot path's assertion: also defined at Re_t = +∞ (n = 2.4), for the
  // callers whose Re_t may overflow the type (the Mazzei–Lettieri drag's Re* at extreme states).
  template <class S>
  FLUIDBED_HOST_DEVICE S exponent(const S& terminal_reynolds) const {
    return of_scaled_power(scaled_power(terminal_reynolds));
  }

  // dn/dRe_t in the closed form of seed 000 eq. 3.103, −0.315 Re_t^−¼/(1 + 0.175 Re_t^¾)²
  // (0.315 = ¾ · 0.175 · 2.4): what with_derivatives returns, and, without its assertion, the
  // slope the Mazzei–Lettieri drag's Newton step for Re* takes. −∞ at Re_t = 0, 0 at +∞.
  template <class S>
  FLUIDBED_HOST_DEVICE static S slope(const S& terminal_reynolds) {
    using std::pow;
    using T = value_type_of<S>;
    const S one_plus_x = 1 + scaled_power(terminal_reynolds);
    return FLUIDBED_DECIMAL(T, -0.315) * pow(terminal_reynolds, T(-0.25)) / (one_plus_x * one_plus_x);
  }
};

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
// Parameter: d/D ∈ [0, 1) (default 0).
struct RichardsonZaki1954Exponent : RichardsonZakiExponent<RichardsonZaki1954Exponent> {
  static constexpr const char* argument = "terminal_reynolds";
  double wall_ratio;  // d/D

  constexpr explicit RichardsonZaki1954Exponent(double wall_ratio = 0) : wall_ratio(wall_ratio) {}

  constexpr std::string_view name() const { return "RichardsonZaki1954Exponent"; }
  constexpr std::string_view reference() const {
    return "Richardson, J.F., Zaki, W.N. (1954) Trans. Inst. Chem. Eng. 32, 35-53; reprinted Chem. Eng. Res. "
           "Des. 75 (1997) S82-S100, doi:10.1016/S0263-8762(97)80006-8";
  }
  constexpr Validity<2> validity() const {
    return {{{"terminal_reynolds", 0.0, std::numeric_limits<double>::infinity()}, {"wall_ratio", 0.0, 0.1}}};
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr Arguments<T, 1> parameter_domain() const {
    return {{{"wall_ratio", T(wall_ratio), domains::closed_open(T(0), T(1))}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&RichardsonZaki1954Exponent::wall_ratio>("wall_ratio")};
  }

  template <class S>
  FLUIDBED_HOST_DEVICE S exponent(const S& terminal_reynolds) const {
    using std::pow;
    using T = value_type_of<S>;
    const T d_over_D = T(wall_ratio);
    if (terminal_reynolds < FLUIDBED_DECIMAL(T, 0.2)) return S(FLUIDBED_DECIMAL(T, 4.65) + T(19.5) * d_over_D);
    if (terminal_reynolds < 1)
      return (FLUIDBED_DECIMAL(T, 4.35) + T(17.5) * d_over_D) * pow(terminal_reynolds, FLUIDBED_DECIMAL(T, -0.03));
    if (terminal_reynolds < 200)
      return (FLUIDBED_DECIMAL(T, 4.45) + 18 * d_over_D) * pow(terminal_reynolds, FLUIDBED_DECIMAL(T, -0.1));
    if (terminal_reynolds < 500) return FLUIDBED_DECIMAL(T, 4.45) * pow(terminal_reynolds, FLUIDBED_DECIMAL(T, -0.1));
    return S(FLUIDBED_DECIMAL(T, 2.39));
  }
};

// Rowe, P.N. (1987), "A convenient empirical equation for estimation of the
// Richardson–Zaki exponent", Chem. Eng. Sci. 42, 2795–2796:
//
//   n = (4.7 + 0.41 Re_t^¾) / (1 + 0.175 Re_t^¾),
//
// a smooth fit of the 1954 correlation without wall effect; limits 4.7 and
// 0.41/0.175 = 2.342857 (seed 000 §3.4.3 quotes 2.35).
struct RoweExponent : RichardsonZakiExponent<RoweExponent> {
  static constexpr const char* argument = "terminal_reynolds";
  constexpr std::string_view name() const { return "RoweExponent"; }
  constexpr std::string_view reference() const { return "Rowe, P.N. (1987) Chem. Eng. Sci. 42, 2795-2796"; }
  constexpr Validity<1> validity() const {
    return {{{"terminal_reynolds", 0.0, std::numeric_limits<double>::infinity()}}};
  }

  template <class S>
  FLUIDBED_HOST_DEVICE S exponent(const S& terminal_reynolds) const {
    using std::pow;
    using T = value_type_of<S>;
    const S x = pow(terminal_reynolds, T(0.75));
    return (FLUIDBED_DECIMAL(T, 4.7) + FLUIDBED_DECIMAL(T, 0.41) * x) / (1 + FLUIDBED_DECIMAL(T, 0.175) * x);
  }
};

// Khan, A.R., Richardson, J.F. (1989), "Fluid-particle interactions and flow
// characteristics of fluidized beds and settling suspensions of spherical particles",
// Chem. Eng. Commun. 78, 111–130:
//
//   (4.8 − n)/(n − 2.4) = X,   X = 0.043 Ar^0.57 [1 − 2.4 (d/D)^0.27],
//   i.e. n = 2.4 + 2.4/(1 + X),
//
// a function of Ar (not of Re_t): its `argument` is "archimedes". Limits 4.8 (Ar → 0) and
// 2.4 (Ar → ∞). The wall factor is positive only for d/D < (1/2.4)^(1/0.27) = 0.0391;
// beyond, X < 0, n grows with Ar and has a pole at X = −1: the correlation has left its
// data, and such d/D are out of domain. Parameter: d/D ∈ [0, 0.0391) (default 0).
struct KhanRichardsonExponent : RichardsonZakiExponent<KhanRichardsonExponent> {
  static constexpr const char* argument = "archimedes";
  double wall_ratio;  // d/D

  constexpr explicit KhanRichardsonExponent(double wall_ratio = 0) : wall_ratio(wall_ratio) {}

  constexpr std::string_view name() const { return "KhanRichardsonExponent"; }
  constexpr std::string_view reference() const {
    return "Khan, A.R., Richardson, J.F. (1989) Chem. Eng. Commun. 78, 111-130";
  }
  constexpr Validity<2> validity() const {
    return {{{"archimedes", 0.0, std::numeric_limits<double>::infinity()}, {"wall_ratio", 0.0, 0.0391}}};
  }

  // The wall factor 1 − 2.4 (d/D)^0.27.
  template <class T>
  FLUIDBED_HOST_DEVICE T wall_factor() const {
    using std::pow;
    return 1 - FLUIDBED_DECIMAL(T, 2.4) * pow(T(wall_ratio), FLUIDBED_DECIMAL(T, 0.27));
  }

  // d/D >= 0 with a positive wall factor, i.e. d/D < (1/2.4)^(1/0.27).
  template <class T>
  FLUIDBED_HOST_DEVICE Arguments<T, 1> parameter_domain() const {
    using std::pow;
    const T largest = pow(1 / FLUIDBED_DECIMAL(T, 2.4), 1 / FLUIDBED_DECIMAL(T, 0.27));
    return {{{"wall_ratio", T(wall_ratio), domains::closed_open(T(0), largest),
              "must be >= 0 and < (1/2.4)^(1/0.27) = 0.0391, where 1 - 2.4 (d/D)^0.27 > 0"}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&KhanRichardsonExponent::wall_ratio>("wall_ratio")};
  }

  template <class S>
  FLUIDBED_HOST_DEVICE S exponent(const S& archimedes) const {
    using std::pow;
    using T = value_type_of<S>;
    return FLUIDBED_DECIMAL(T, 2.4) +
           FLUIDBED_DECIMAL(T, 2.4) /
               (1 + FLUIDBED_DECIMAL(T, 0.043) * pow(archimedes, FLUIDBED_DECIMAL(T, 0.57)) * wall_factor<T>());
  }
};

// Garside, J., Al-Dibouni, M.R. (1977), "Velocity-voidage relationships for
// fluidization and sedimentation in solid-liquid systems", Ind. Eng. Chem. Process Des.
// Dev. 16, 206–214, doi:10.1021/i260062a008:
//
//   (5.1 − n)/(n − 2.7) = 0.1 Re_t^0.9,   i.e. n = 2.7 + 2.4/(1 + 0.1 Re_t^0.9);
//
// limits 5.1 and 2.7.
struct GarsideAlDibouniExponent : RichardsonZakiExponent<GarsideAlDibouniExponent> {
  static constexpr const char* argument = "terminal_reynolds";
  constexpr std::string_view name() const { return "GarsideAlDibouniExponent"; }
  constexpr std::string_view reference() const {
    return "Garside, J., Al-Dibouni, M.R. (1977) Ind. Eng. Chem. Process Des. Dev. 16, 206-214, "
           "doi:10.1021/i260062a008";
  }
  constexpr Validity<1> validity() const {
    return {{{"terminal_reynolds", 0.0, std::numeric_limits<double>::infinity()}}};
  }

  template <class S>
  FLUIDBED_HOST_DEVICE S exponent(const S& terminal_reynolds) const {
    using std::pow;
    using T = value_type_of<S>;
    return FLUIDBED_DECIMAL(T, 2.7) +
           FLUIDBED_DECIMAL(T, 2.4) / (1 + FLUIDBED_DECIMAL(T, 0.1) * pow(terminal_reynolds, FLUIDBED_DECIMAL(T, 0.9)));
  }
};

struct RichardsonZakiExponentFamily {
  static constexpr std::string_view what = "Richardson-Zaki exponent";
  static constexpr std::string_view convention =
      "The dimensionless exponent n of the Richardson–Zaki law u_s = u_t ε^n (u_s the superficial fluid or "
      "sedimentation velocity, u_t the unhindered terminal velocity), as a function of Re_t = ρ_f u_t d/μ_f "
      "(Khan–Richardson: of Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f²) and, where a law has one, of the wall ratio d/D.";
};

// The exponent correlations, each at d/D = 0; extend with `RichardsonZakiExponents::with<MyLaw>`.
using RichardsonZakiExponents = Registry<RichardsonZakiExponentFamily, MazzeiExponent, RichardsonZaki1954Exponent,
                                         RoweExponent, KhanRichardsonExponent, GarsideAlDibouniExponent>;

// ----------------------------------------------------------------------------- the law

// u_s = u_t ε^n (seed 000 eq. 3.22). Domain: u_t >= 0, ε ∈ (0, 1], n > 0.
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S richardson_zaki_velocity(const S& terminal_velocity, const std::type_identity_t<S>& voidage,
                                                const std::type_identity_t<S>& exponent, Policy policy = {}) {
  using std::pow;
  using T = value_type_of<S>;
  check_domain(policy, "richardson_zaki_velocity",
               arguments(Argument<T>{"terminal_velocity", value_of(terminal_velocity), domains::non_negative<T>()},
                         Argument<T>{"voidage", value_of(voidage), domains::half_open(T(0), T(1))},
                         Argument<T>{"exponent", value_of(exponent), domains::positive<T>()}));
  return terminal_velocity * pow(voidage, exponent);
}

// ε = (u_s/u_t)^(1/n), the inverse of eq. 3.22. Domain: u_t > 0, 0 < u_s <= u_t, n > 0
// (u_s > u_t would give ε > 1: the particles are carried out, there is no bed).
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S richardson_zaki_voidage(const S& superficial_velocity,
                                               const std::type_identity_t<S>& terminal_velocity,
                                               const std::type_identity_t<S>& exponent, Policy policy = {}) {
  using std::pow;
  using T = value_type_of<S>;
  check_domain(policy, "richardson_zaki_voidage",
               arguments(Argument<T>{"terminal_velocity", value_of(terminal_velocity), domains::positive<T>()},
                         Argument<T>{"superficial_velocity", value_of(superficial_velocity),
                                     domains::half_open(T(0), T(value_of(terminal_velocity)))},
                         Argument<T>{"exponent", value_of(exponent), domains::positive<T>()}));
  return pow(superficial_velocity / terminal_velocity, 1 / exponent);
}

// The converged relation Re = Re_t ε^n(Re_t) of eq. 3.24: ln Re_t, y = 0.175 Re_t^¾ (so
// n = 2.4 + 2.4/(1 + y)) and ln ε — all a per-cell caller (the Mazzei–Lettieri drag)
// needs, with no further transcendental function (also the elastic modulus's, elastic/).
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
// and the Halley step 2 g g'/(2 g'² − g g''), formed in p = 1 + y as
//   2 G S₁ p/(2 S₁² − G S₂),  G = p g = (x + 2.4 L − ln Re) p + 2.4 L,
//   S₁ = p² g' = p² − 1.8 L y,  S₂ = p³ g'' = −1.35 L y (1 − y):
// one exp and one division per step (in r, r and the step are two divisions in series, the
// longest part of the step's latency), no pow. S₁² ~ y⁴ would overflow once ln Re_t >~ 239
// (double) or 32 (float) and turn the step into ∞/∞: y is held below 2^(max_exponent/5),
// where n = 2.4 + 2.4 r is 2.4 to rounding and g linear, so the held step is the step (in double the
// term 2.4 L r < 1e-58 for every ε; in float it reaches the rounding of x only for ε <~ 1e-6).
// y itself may overflow to +∞ (Re_t beyond the range of T).
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
FLUIDBED_HOST_DEVICE TerminalReynoldsSolution<T> solve_richardson_zaki_terminal_reynolds(const T& reynolds,
                                                                                         const T& voidage) {
  using std::abs;
  using std::cbrt;
  using std::exp;
  using std::ldexp;
  using std::log;
  const T log_voidage = log(voidage);
  const T log_re = log(reynolds);
  const T stop = T(4) * cbrt(std::numeric_limits<T>::epsilon());
  // The bracket, widened by 1 so that a root at one of its ends (n = 4.8 or 2.4 to rounding)
  // lies strictly inside it: a step that lands on an end is then one that cycles.
  T low = log_re - FLUIDBED_DECIMAL(T, 2.4) * log_voidage - 1;
  T high = log_re - FLUIDBED_DECIMAL(T, 4.8) * log_voidage + 1;
  T x = log_re - FLUIDBED_DECIMAL(T, 3.6) * log_voidage;
  T previous = high - low;  // the size of the last step taken
  const T y_cap = ldexp(T(1), std::numeric_limits<T>::max_exponent / 5);
  T y{};
  for (int iteration = 0; iteration < 100; ++iteration) {
    y = FLUIDBED_DECIMAL(T, 0.175) * exp(T(0.75) * x);
    const T y_held = y < y_cap ? y : y_cap;
    const T p = T(1) + y_held;
    const T g_p = (x + FLUIDBED_DECIMAL(T, 2.4) * log_voidage - log_re) * p + FLUIDBED_DECIMAL(T, 2.4) * log_voidage;
    const T d1_p2 = p * p - FLUIDBED_DECIMAL(T, 1.8) * log_voidage * y_held;
    const T d2_p3 = FLUIDBED_DECIMAL(T, -1.35) * log_voidage * y_held * (T(1) - y_held);
    const T step = T(2) * g_p * d1_p2 * p / (T(2) * d1_p2 * d1_p2 - g_p * d2_p3);
    if (abs(step) <= stop) {
      x -= step;
      const T z = T(0.75) * step;
      y *= T(1) - z + T(0.5) * z * z;  // y at the updated x, to O(step³) ~ ε_machine
      break;
    }
    // A step this large starts far enough from the root for the sign of g to be exact.
    (g_p < T(0) ? low : high) = x;
    const T next = x - step;
    const T taken = next > low && next < high && abs(step) <= T(0.5) * previous ? next : T(0.5) * (low + high);
    previous = abs(x - taken);
    x = taken;
  }
  return {x, y, log_voidage};
}

// The terminal Reynolds number Re_t for which Richardson–Zaki with the exponent of
// eq. 3.24 puts a bed fluidized at the superficial Reynolds number Re = ρ_f u_s d/μ_f at
// the voidage ε:  Re = Re_t ε^n(Re_t)  (seed 000 §3.4.4.1, the procedure behind
// Figs 3.1–3.5; the same relation defines Re* of eq. 3.53, the Mazzei–Lettieri drag's).
// Re_t = Re at ε = 1 and Re_t = 0 at Re = 0; +∞ where Re_t exceeds the range of T (ln Re_t,
// which solve_richardson_zaki_terminal_reynolds returns, is finite for every finite Re and ε).
// Domain: Re >= 0, ε ∈ (0, 1]. With fluidbed::checked it also throws std::domain_error where
// Re_t exceeds the range of T (e.g. Re = 1e300, ε = 1e-100).
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE T richardson_zaki_terminal_reynolds(const T& reynolds, const T& voidage, Policy policy = {}) {
  using std::exp;
  constexpr std::string_view function = "richardson_zaki_terminal_reynolds";
  const auto domain = arguments(Argument<T>{"reynolds", reynolds, domains::non_negative<T>()},
                                Argument<T>{"voidage", voidage, domains::half_open(T(0), T(1))});
  check_domain(policy, function, domain);
  if (voidage == T(1) || reynolds == T(0)) return reynolds;
  const T terminal_reynolds = exp(solve_richardson_zaki_terminal_reynolds(reynolds, voidage).log_terminal_reynolds);
  check_result(policy, function, "terminal_reynolds", terminal_reynolds, [&] { return describe(domain); });
  return terminal_reynolds;
}

}  // namespace fluidbed::settling
