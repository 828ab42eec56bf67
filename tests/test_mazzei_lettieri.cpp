// Mazzei–Lettieri drag: the seed's Table 3.1 values, its limits and identities.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "fluidbed/drag/mazzei_lettieri.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;
using ML = MazzeiLettieri;

namespace {
const Fluid<double> water{.density = 998.0, .viscosity = 1.0e-3};
}

TEST_CASE("Re*, φ and ψ_e reproduce a table evaluated independently from seed 000 Table 3.1") {
  // An independent double-precision evaluation of Table 3.1 made when the thesis was read.
  struct Row {
    double eps, re, re_star, phi, psi;
  };
  const Row rows[] = {
      {0.40, 0.01, 0.637028, 12.1195, 2.722734},  {0.40, 1, 20.4616, 6.49767, 2.042413},
      {0.40, 10, 121.375, 5.80248, 1.918917},     {0.40, 100, 967.206, 7.47347, 2.195110},
      {0.40, 1000, 9138.18, 10.1146, 2.525378},   {0.50, 0.01, 0.252658, 6.9926, 2.805829},
      {0.50, 1, 11.6419, 4.76739, 2.253199},      {0.50, 10, 72.1118, 4.02571, 2.009243},
      {0.50, 100, 570.416, 4.55884, 2.188668},    {0.50, 1000, 5358.02, 5.68143, 2.506254},
      {0.70, 0.01, 0.0544921, 2.76323, 2.849651}, {0.70, 1, 4.15091, 2.55302, 2.627816},
      {0.70, 10, 30.5688, 2.22764, 2.245587},     {0.70, 100, 252.647, 2.20494, 2.216866},
      {0.70, 1000, 2387.17, 2.42289, 2.481145},   {0.90, 0.01, 0.0165484, 1.35039, 2.851079},
      {0.90, 1, 1.57737, 1.35467, 2.881134},      {0.90, 10, 14.3789, 1.30472, 2.524522},
      {0.90, 100, 132.985, 1.27263, 2.288210},    {0.90, 1000, 1296.13, 1.29725, 2.470038},
  };
  for (const Row& r : rows) {
    INFO("eps=" << r.eps << " Re=" << r.re);
    CHECK(ML::effective_reynolds(r.eps, r.re) == doctest::Approx(r.re_star).epsilon(6e-6));
    CHECK(ML::voidage_function(r.eps, r.re) == doctest::Approx(r.phi).epsilon(6e-6));
    CHECK(ML::equivalent_exponent(r.eps, r.re) == doctest::Approx(r.psi).epsilon(1e-6));
  }
}

TEST_CASE("Re* solves Re* = Re/ε^n_e(Re*) to rounding, inside the bracket Re ε^-2.4 .. Re ε^-4.8") {
  for (double eps : {1e-3, 0.05, 0.3, 0.6, 0.9, 0.999, 1.0})
    for (double re : {1e-12, 1e-6, 1e-2, 1.0, 31.6, 1e3, 1e6, 1e10}) {
      const double re_star = ML::effective_reynolds(eps, re);
      const double n = 2.4 + 2.4 / (1 + 0.175 * std::pow(re_star, 0.75));  // seed 000 eq. 3.24
      INFO("eps=" << eps << " Re=" << re);
      CHECK(re_star * std::pow(eps, n) == doctest::Approx(re).epsilon(4e-15 * (1 + 5 * std::abs(std::log(eps)))));
      CHECK(re_star >= re * std::pow(eps, -2.4) * (1 - 1e-15));
      CHECK(re_star <= re * std::pow(eps, -4.8) * (1 + 1e-15));
    }
}

TEST_CASE("the regularised form equals Table 3.1's β = ¾ C_D ρ w (1-ε)/d ε^-ψ_e wherever both are defined") {
  const double d = 253e-6;
  for (double eps : {0.38, 0.5, 0.75, 0.95})
    for (double w : {1e-5, 1e-3, 0.05, 1.0}) {
      const DragState<double> s{.voidage = eps, .slip = w, .fluid = water, .diameter = d};
      const double re = particle_reynolds(water, d, eps, w);
      const double cd = std::pow(0.63 + 4.8 / std::sqrt(re), 2);
      const double table_3_1 =
          0.75 * cd * water.density * w * (1 - eps) / d * std::pow(eps, -ML::equivalent_exponent(eps, re));
      CHECK(ML{}(s).classical() == doctest::Approx(table_3_1).epsilon(1e-12));
    }
}

TEST_CASE("limits: ψ_e → 2.80 for Re → 0 and Re → ∞ (eqs. 3.68, 3.71), zero-slip Stokes value, ε = 1") {
  for (double eps : {0.4, 0.7, 0.95}) {
    CHECK(ML::equivalent_exponent(eps, 1e-14) == doctest::Approx(2.8).epsilon(1e-5));
    CHECK(ML::equivalent_exponent(eps, 1e18) == doctest::Approx(2.8).epsilon(1e-5));
    const DragState<double> s{.voidage = eps, .slip = 0.0, .fluid = water, .diameter = 1e-4};
    CHECK(ML{}(s).classical() ==
          doctest::Approx(17.28 * 1e-3 * (1 - eps) / (1e-8 * std::pow(eps, 3.8))).epsilon(1e-14));
  }
  // ψ_e at ε = 1 is the limit of the neighbouring values (0/0 in eq. 3.64).
  for (double re : {1e-3, 1.0, 100.0, 1e5})
    CHECK(ML::equivalent_exponent(1.0, re) == doctest::Approx(ML::equivalent_exponent(1.0 - 1e-7, re)).epsilon(1e-6));
  // The minimum over Re of ψ_e at ε = 0.4 is 1.9079 at Re ≈ 6.1 (the independent evaluation; the thesis
  // says ψ_e drops "to values as low as 1.90" in the intermediate regime).
  double minimum = 10;
  for (double lg = -1; lg < 2; lg += 0.001)
    minimum = std::min(minimum, ML::equivalent_exponent(0.4, std::pow(10.0, lg)));
  CHECK(minimum == doctest::Approx(1.9079).epsilon(1e-4));
}

TEST_CASE("β at seed 000 Table 4.3 system 1, u = 5.28e-3 m/s equals the equilibrium β̂ of eq. 3.28") {
  // β̂ = (ε/u_s)(1 − ε)(ρ_p − ρ_f) g at ε_R&Z = 0.6037180 (the independent evaluation's numbers).
  const DragState<double> s{.voidage = 0.6037180, .slip = 8.7458051e-3, .fluid = water, .diameter = 253e-6};
  CHECK(ML{}(s).classical() == doctest::Approx(7.9210226e5).epsilon(1e-6));
  CHECK(ML::effective_reynolds(0.6037180, 1.3331683) == doctest::Approx(8.5411396).epsilon(1e-6));
}

TEST_CASE("implicit derivative: d ln Re*/d ln Re = C = 1/(1 + Re* N ln ε) (seed eq. 3.105)") {
  using D = Dual<double, 2>;
  for (double eps : {0.3, 0.6, 0.9})
    for (double re : {0.01, 3.0, 300.0}) {
      const D r = ML::effective_reynolds(D(eps), D::variable(re, 0));
      const double re_star = r.value;
      const double x = 0.175 * std::pow(re_star, 0.75);
      const double n_prime = -0.315 * std::pow(re_star, -0.25) / ((1 + x) * (1 + x));  // eq. 3.103 simplified
      const double c = 1 / (1 + re_star * n_prime * std::log(eps));
      CHECK(r.derivative[0] * re / re_star == doctest::Approx(c).epsilon(1e-13));
    }
}

TEST_CASE("Re* over every finite state: the Newton (n → 2.4) and Stokes (n → 4.8) asymptotes of eq. 3.24") {
  // Where 0.175 Re*^¾ ≫ 1, eq. 3.24 gives n = 2.4 to rounding, so ln Re* = ln Re − 2.4 ln ε; where
  // it is ≪ 1, n = 4.8 and ln Re* = ln Re − 4.8 ln ε. The Halley step of the solver once formed
  // (0.175 Re*^¾)⁴, which overflowed (and gave NaN) beyond ln Re* ≈ 239 in double, 32 in float.
  using settling::solve_richardson_zaki_terminal_reynolds;
  const auto log_re_star = [](auto re, auto eps) {
    return solve_richardson_zaki_terminal_reynolds(re, eps).log_terminal_reynolds;
  };
  struct Case {
    double re, eps, n;
  };
  const double huge = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  for (const Case c : {Case{1e300, 0.01, 2.4}, Case{1e300, 1e-100, 2.4}, Case{1e10, 1e-300, 2.4}, Case{huge, tiny, 2.4},
                       Case{1e-300, 0.5, 4.8}, Case{1e-300, 1e-30, 4.8}, Case{tiny, 0.9, 4.8}}) {
    INFO("Re=" << c.re << " eps=" << c.eps);
    const double asymptote = std::log(c.re) - c.n * std::log(c.eps);
    CHECK(log_re_star(c.re, c.eps) == doctest::Approx(asymptote).epsilon(1e-14));
  }
  CHECK(settling::richardson_zaki_terminal_reynolds(1e300, 0.01) == doctest::Approx(1e300 * std::pow(0.01, -2.4)));
  CHECK(settling::richardson_zaki_terminal_reynolds(1e300, 1e-100) == std::numeric_limits<double>::infinity());
  CHECK_THROWS_WITH_AS(
      settling::richardson_zaki_terminal_reynolds(1e300, 1e-100, fluidbed::checked),
      doctest::Contains("result 'terminal_reynolds' = inf is not finite for reynolds = 1.0000000000000001e+300"),
      std::domain_error);
  CHECK(settling::richardson_zaki_terminal_reynolds(1e300, 0.01, fluidbed::checked) ==
        settling::richardson_zaki_terminal_reynolds(1e300, 0.01));
  CHECK(log_re_star(1e30f, 0.5f) == doctest::Approx(std::log(1e30) - 2.4 * std::log(0.5)).epsilon(1e-6));
  CHECK(settling::richardson_zaki_terminal_reynolds(1e30f, 0.5f) ==
        doctest::Approx(1e30 * std::pow(0.5, -2.4)).epsilon(1e-5));
  CHECK(settling::richardson_zaki_terminal_reynolds(3e38f, 1e-30f) == std::numeric_limits<float>::infinity());
}

TEST_CASE("Re* where n(Re*) is a step of height 2.4 |ln ε| (ε ≪ 1): the root of eq. 3.53 to rounding, no cycling") {
  // ε = 2.3e-9, Re = 2.1e-37: Halley's iteration alone cycles here between the two flat parts of
  // n; the safeguarded one must still return the root of x + n(eˣ) ln ε = ln Re.
  for (const auto& state : {std::pair{2.1322746435998335e-37, 2.3217596236941965e-09},
                            std::pair{6.3912104805310214e-91, 6.3937804997894256e-37},
                            std::pair{2.9973843420186996e-133, 1.834351405783779e-54}}) {
    const double re = state.first, eps = state.second;  // named copies: clang < 16 captures no structured binding
    const auto r = settling::solve_richardson_zaki_terminal_reynolds(re, eps);
    const double x = r.log_terminal_reynolds, log_eps = std::log(eps);
    const double n = 2.4 + 2.4 / (1 + 0.175 * std::exp(0.75 * x));  // seed 000 eq. 3.24
    INFO("Re=" << re << " eps=" << eps << " ln Re*=" << x);
    // To rounding of its terms, of size |ln Re| and n |ln ε|.
    CHECK(std::abs(x + n * log_eps - std::log(re)) <= 1e-15 * (std::abs(std::log(re)) + n * std::abs(log_eps)));
    CHECK(r.scaled_power == doctest::Approx(0.175 * std::exp(0.75 * x)).epsilon(1e-13));
  }
}

TEST_CASE("β at extreme Re*: finite where representable, equal to the Newton limit; float as double") {
  // With Re* → ∞, (0.63 √Re* + 4.8)² → 0.3969 Re* and n → 2.4, so eq. 3.65 tends to Newton's
  // regime, β_classical = ¾ · 0.3969 ρ_f w (1 − ε) ε^−2.8 / d (C_D = 0.63², Dallavalle).
  // μ_f = 1e-298 puts ln Re* between 670 and 1300: where the Halley step overflowed, and (for
  // ε <= 1e-10) where Re*, E² and the product (√Re E²)² leave the range of double.
  for (double eps : {1e-100, 1e-10, 0.01, 0.3, 0.9}) {
    const DragState<double> s{.voidage = eps, .slip = 1.0, .fluid = {1e3, 1e-298}, .diameter = 1e-3};
    const double newton = 0.75 * 0.3969 * 1e3 * 1.0 * (1 - eps) * std::pow(eps, -2.8) / 1e-3;
    INFO("eps=" << eps);
    CHECK(ML{}(s).classical() == doctest::Approx(newton).epsilon(1e-13));
    CHECK(ML{}.with_derivatives(s).classical().value == ML{}(s).classical());
  }
  // Not representable: +∞, not NaN; at ε = 1 exactly 0 even where μ_f/d² overflows.
  CHECK(ML{}(DragState<double>{1e-300, 1.0, {1e3, 1e-298}, 1e-3}).classical() ==
        std::numeric_limits<double>::infinity());
  CHECK(ML{}(DragState<double>{1.0, 1.0, {1e3, 1e300}, 1e-10}).classical() == 0.0);
  // Float beyond ln Re* = 32 (Re* ≈ 5e14), once NaN: agrees with double, derivatives finite.
  const DragState<float> sf{0.1f, 1e4f, {2e4f, 1e-6f}, 0.1f};
  const DragState<double> sd{0.1f, 1e4f, {2e4f, 1e-6f}, 0.1f};
  CHECK(double(ML{}(sf).classical()) == doctest::Approx(ML{}(sd).classical()).epsilon(1e-5));
  const DragDerivatives<float> d = ML{}.with_derivatives(sf).classical();
  CHECK(d.value == ML{}(sf).classical());
  CHECK((std::isfinite(d.d_voidage) && std::isfinite(d.d_slip)));
}

TEST_CASE("a state inside the domain whose Re overflows: no assertion in the hot path, a status from checked") {
  // ε, w, ρ_f, μ_f and d are finite and valid, but ρ_f ε w d/μ_f = +∞ in double (found by the
  // drag fuzzer, fuzz/corpus/drag_fuzzer/overflowing_reynolds_mazzei_lettieri).
  const DragState<double> state{0.5, 1e300, {1e10, 1e-300}, 1.0};
  REQUIRE(std::isinf(particle_reynolds(state.fluid, state.diameter, state.voidage, state.slip)));
  const double beta = ML{}(state).classical();
  CHECK_FALSE(std::isfinite(beta));
  CHECK_FALSE(std::isfinite(ML{}.with_derivatives(state).classical().value));
  CHECK_THROWS_WITH_AS(ML{}.checked(state), doctest::Contains("is not finite for state {voidage = 0.5"),
                       std::domain_error);
}

TEST_CASE("with_derivatives equals the chain rule through eq. 3.65 with Re* as a dual number (seed eq. 3.105)") {
  // An independent route to the same derivatives: β = ¾ μ_f (1 − ε)/d² (0.63 √Re* + 4.8)² ε^(1 − n_e(Re*))
  // with Re* and n_e(Re*) dual numbers (effective_reynolds: a Newton step in Dual from the root),
  // against with_derivatives' closed form of the implicit-function theorem, over Re 1e-9 … 1e7.
  using D = Dual<double, 2>;
  for (double eps : {0.36, 0.5, 0.7, 0.9, 0.999})
    for (double re = 1e-9; re < 2e7; re *= 7.3) {
      const double d = 1e-3, w = re * water.viscosity / (water.density * eps * d);
      const D voidage = D::variable(eps, 0), slip = D::variable(w, 1);
      const D re_dual = particle_reynolds(water, d, voidage, slip);
      const D re_star = ML::effective_reynolds(voidage, re_dual);
      const D root = 0.63 * sqrt(re_star) + 4.8;
      const D beta = 0.75 * water.viscosity / (d * d) * (1 - voidage) * root * root *
                     pow(voidage, 1 - settling::MazzeiExponent{}.exponent(re_star));
      const DragDerivatives<double> r = ML{}.with_derivatives(DragState<double>{eps, w, water, d}).classical();
      INFO("eps=" << eps << " Re=" << re);
      CHECK(r.value == doctest::Approx(beta.value).epsilon(1e-13));
      CHECK(r.d_voidage == doctest::Approx(beta.derivative[0]).epsilon(1e-12).scale(beta.value / eps));
      CHECK(r.d_slip == doctest::Approx(beta.derivative[1]).epsilon(1e-12).scale(beta.value / w));
    }
}
