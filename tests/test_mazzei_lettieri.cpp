// Mazzei–Lettieri drag: the seed's Table 3.1 values, its limits and identities.
#include <doctest/doctest.h>

#include <cmath>

#include "fluidbed/drag/mazzei_lettieri.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;
using ML = MazzeiLettieri;

namespace {
const Fluid<double> water{.density = 998.0, .viscosity = 1.0e-3};
}

TEST_CASE("Re*, φ and ψ_e reproduce seed 000 note §6.4's independently checked table") {
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
      const double table_3_1 = 0.75 * cd * water.density * w * (1 - eps) / d * std::pow(eps, -ML::equivalent_exponent(eps, re));
      CHECK(ML{}(s).classical() == doctest::Approx(table_3_1).epsilon(1e-12));
    }
}

TEST_CASE("limits: ψ_e → 2.80 for Re → 0 and Re → ∞ (eqs. 3.68, 3.71), zero-slip Stokes value, ε = 1") {
  for (double eps : {0.4, 0.7, 0.95}) {
    CHECK(ML::equivalent_exponent(eps, 1e-14) == doctest::Approx(2.8).epsilon(1e-5));
    CHECK(ML::equivalent_exponent(eps, 1e18) == doctest::Approx(2.8).epsilon(1e-5));
    const DragState<double> s{.voidage = eps, .slip = 0.0, .fluid = water, .diameter = 1e-4};
    CHECK(ML{}(s).classical() == doctest::Approx(17.28 * 1e-3 * (1 - eps) / (1e-8 * std::pow(eps, 3.8))).epsilon(1e-14));
  }
  // ψ_e at ε = 1 is the limit of the neighbouring values (0/0 in eq. 3.64).
  for (double re : {1e-3, 1.0, 100.0, 1e5})
    CHECK(ML::equivalent_exponent(1.0, re) == doctest::Approx(ML::equivalent_exponent(1.0 - 1e-7, re)).epsilon(1e-6));
  // Thesis: the minimum over Re of ψ_e at ε = 0.4 is 1.9079 at Re ≈ 6.1 (note §6.4).
  double minimum = 10;
  for (double lg = -1; lg < 2; lg += 0.001) minimum = std::min(minimum, ML::equivalent_exponent(0.4, std::pow(10.0, lg)));
  CHECK(minimum == doctest::Approx(1.9079).epsilon(1e-4));
}

TEST_CASE("β at seed 000 Table 4.3 system 1, u = 5.28e-3 m/s equals the equilibrium β̂ (note §6.5)") {
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
