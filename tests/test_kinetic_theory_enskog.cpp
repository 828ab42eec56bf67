// Seed 002's remaining kinetic theory: the radial distributions of Song, Stratt & Mason and of
// Tobochnik & Chapin (seed 002 eq. 77 with Table III) and the Enskog shear viscosity and
// conductivity of elastic hard spheres (seed 002 eqs 72-76). The mpmath rows of
// tests/reference/ktgf_reference.csv are compared by test_kinetic_theory.cpp (every row, value
// and derivatives) and test_scalar_types_kinetic_theory.cpp; here: the seed's worked y^ES table
// evaluated independently (8 significant digits), exact limits and identities, and the laws in a
// ConstitutiveSet.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "fluidbed/kinetic_theory.hpp"
#include "kinetic_theory_table_names.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;
using fluidbed::test::relative_difference;

namespace {

// The state of seed 002's worked KTGF values: ρ_s = 2500, d = 500 µm, Θ = 0.01.
const GranularMaterial<double> glass{500e-6, 2500.0, 0.9};
constexpr double theta = 0.01;

// μ_id and κ_id of seed 002 eq. 72 written as the seed prints them, (5/96) π ρ_s d √(Θ/π) and
// (75/384) π ρ_s d √(Θ/π).
double mu_ideal(double t, const GranularMaterial<double>& m) {
  return 5.0 / 96.0 * std::numbers::pi * m.density * m.diameter * std::sqrt(t / std::numbers::pi);
}
double kappa_ideal(double t, const GranularMaterial<double>& m) {
  return 75.0 / 384.0 * std::numbers::pi * m.density * m.diameter * std::sqrt(t / std::numbers::pi);
}

}  // namespace

TEST_CASE("seed 002 eq. 77: y^ES = 4 phi g0 of Table III's fits, the worked table (8 significant digits)") {
  // φ, y_CS, y_MA (Table III's c_3 = 0.070554), y_SSM, y_TC: seed 002 eq. 77 with Table III,
  // evaluated independently in double precision.
  struct Row {
    double phi, cs, ma, ssm, tc;
  };
  constexpr std::array rows{Row{0.05, 0.2274384, 0.22748042, 0.22748816, 0.22748267},
                            Row{0.1, 0.521262, 0.52149514, 0.52166316, 0.52163853},
                            Row{0.2, 1.40625, 1.4045136, 1.4097992, 1.4096665},
                            Row{0.3, 2.9737609, 2.947995, 2.990319, 2.9895958},
                            Row{0.4, 5.9259259, 5.8274315, 6.0175958, 6.006947},
                            Row{0.5, 12.0, 12.170865, 12.811366, 12.604627},
                            Row{0.55, 17.503429, 19.286397, 20.467147, 19.438463},
                            Row{0.6, 26.25, 37.997256, 40.986892, 33.541314},
                            Row{0.63, 34.078929, 91.859721, 104.71102, 52.991715}};
  for (const Row& r : rows) {
    INFO("phi = " << r.phi);
    const double y = 4 * r.phi;
    CHECK(relative_difference(y * CarnahanStarling{}(r.phi), r.cs) < 5e-8);
    CHECK(relative_difference(y * SongStrattMason{}(r.phi), r.ssm) < 5e-8);
    CHECK(relative_difference(y * TobochnikChapin{}(r.phi), r.tc) < 5e-8);
    // The library's Ma–Ahmadi has the published 4.515439 where Table III gives 64 × 0.070554 =
    // 4.515456: about 1e-6 apart.
    CHECK(relative_difference(y * MaAhmadi{}(r.phi), r.ma) < 2e-6);
  }
  // The four fits agree within 0.3 % at φ ≤ 0.2 and part near packing (at 0.63: 34, 92, 105, 53).
  for (const double phi : {0.05, 0.1, 0.2}) {
    const double cs = CarnahanStarling{}(phi);
    for (const double g : {MaAhmadi{}(phi), SongStrattMason{}(phi), TobochnikChapin{}(phi)})
      CHECK(relative_difference(g, cs) < 3e-3);
  }
}

TEST_CASE("Song-Stratt-Mason and Tobochnik-Chapin: g0 -> 1, the virial slope 5/2, the pole, the continuation") {
  for (const double phi : {0.0, 1e-12, 1e-9}) {
    CHECK(std::abs(SongStrattMason{}(phi)-1) <= 2.6 * phi + 1e-16);
    CHECK(std::abs(TobochnikChapin{}(phi)-1) <= 2.6 * phi + 1e-16);
  }
  // The fits reproduce the second virial coefficient only approximately: dg0/dφ(0) = 4 c_1 +
  // b/φ_cp = 1.3192 + 0.76/0.6435 = 2.50024 and 1.0452 + 1/0.6875 = 2.49975 (exact: 5/2).
  using D1 = Dual<double, 1>;
  CHECK(SongStrattMason{}(D1::variable(0.0, 0)).derivative[0] == doctest::Approx(1.3192 + 0.76 / 0.6435).epsilon(1e-14));
  CHECK(TobochnikChapin{}(D1::variable(0.0, 0)).derivative[0] == doctest::Approx(1.0452 + 1 / 0.6875).epsilon(1e-14));
  CHECK(relative_difference(SongStrattMason{}(D1::variable(0.0, 0)).derivative[0], 2.5) < 1e-4);
  CHECK(relative_difference(TobochnikChapin{}(D1::variable(0.0, 0)).derivative[0], 2.5) < 2e-4);
  // Increasing to the pole φ_cp − margin, then finite, continued linearly with the slope there
  // (value and slope continuous), up to φ → 1.
  const auto check = [](const auto& g) {
    INFO(g.name());
    const double cut = g.template max_packing<double>() - default_packing_margin;
    double previous = 0;
    for (double phi = 0; phi < 0.999; phi += 0.0125) {
      const double value = g(phi);
      CHECK(std::isfinite(value));
      CHECK(value > previous);
      previous = value;
    }
    const auto below = g.with_derivatives(cut), above = g.with_derivatives(std::nextafter(cut, 1.0));
    CHECK(relative_difference(above.value, below.value) < 1e-12);
    CHECK(relative_difference(above.d_solid_fraction, below.d_solid_fraction) < 1e-9);
    CHECK(g.validity()[0].max == g.template max_packing<double>());
  };
  check(SongStrattMason{});
  check(TobochnikChapin{});
  CHECK(SongStrattMason::max_packing<double>() == 0.6435);
  CHECK(TobochnikChapin::max_packing<double>() == 0.6875);
}

TEST_CASE("Enskog viscosity and conductivity: seed 002 eqs 75-76, the dilute limit, Enskog >= dilute") {
  // The dilute values of seed 002 eq. 72 at its worked state (evaluated independently).
  CHECK(mu_ideal(theta, glass) == doctest::Approx(0.0115394131).epsilon(5e-10));
  CHECK(kappa_ideal(theta, glass) == doctest::Approx(0.0432727991).epsilon(5e-10));
  // φ → 0: μ^ES → μ_id and κ^ES → κ_id (g0 → 1): 4φ/y = 1/g0 keeps it finite at φ = 0.
  CHECK(relative_difference(EnskogViscosity{}(0.0, theta, 1.0, glass), mu_ideal(theta, glass)) < 1e-15);
  CHECK(relative_difference(EnskogConductivity{}(0.0, theta, 1.0, glass), kappa_ideal(theta, glass)) < 1e-15);
  for (const double phi : {1e-12, 1e-9}) {
    CHECK(relative_difference(EnskogViscosity{}(phi, theta, SongStrattMason{}(phi), glass), mu_ideal(theta, glass)) <
          1e-8);
    CHECK(relative_difference(EnskogConductivity{}(phi, theta, TobochnikChapin{}(phi), glass),
                              kappa_ideal(theta, glass)) < 1e-8);
  }
  // Seed 002 eqs 75-76 written with y = 4 φ g0, as printed, against the library (every
  // registered g0, φ up to packing); e is not used (elastic spheres). Enskog ≥ dilute where g0 is
  // a hard-sphere form, g0 = 1 + a φ + … with a < 16/5: μ/μ_id = 1/g0 + (16/5) φ + 12.18 g0 φ²
  // = 1 + (16/5 − a) φ + O(φ²). Not for the cube-root forms (Ogawa, Sinclair–Jackson, Gidaspow),
  // whose g0 rises like (φ/φ_max)^(1/3): with Ogawa (φ_max = 0.63) μ^ES = 0.77 μ_id at φ = 0.0125.
  const GranularMaterial<double> elastic{glass.diameter, glass.density, 1.0};
  double worst = 0;
  for (const auto& rdf : RadialDistributions::all()) {
    const double slope_at_0 =
        std::visit([](const auto& g) { return g(Dual<double, 1>::variable(0.0, 0)).derivative[0]; }, rdf);
    const bool hard_sphere = slope_at_0 < 3.2;
    INFO(RadialDistributions::name_of(rdf) << ", dg0/dphi(0) = " << slope_at_0);
    for (double phi = 0.0125; phi < 0.64; phi += 0.0125) {
      const double g0 = std::visit([&](const auto& g) { return g(phi); }, rdf);
      const double y = 4 * phi * g0;
      const double mu = 4 * mu_ideal(theta, glass) * phi * (1 / y + 0.8 + 0.7614 * y);
      const double kappa = 4 * kappa_ideal(theta, glass) * phi * (1 / y + 1.2 + 0.7574 * y);
      const double ours_mu = EnskogViscosity{}(phi, theta, g0, glass);
      const double ours_kappa = EnskogConductivity{}(phi, theta, g0, glass);
      worst = std::max({worst, relative_difference(ours_mu, mu), relative_difference(ours_kappa, kappa)});
      CHECK(relative_difference(ours_mu, mu) < 1e-14);
      CHECK(relative_difference(ours_kappa, kappa) < 1e-14);
      if (hard_sphere) {
        CHECK(ours_mu > mu_ideal(theta, glass));
        CHECK(ours_kappa > kappa_ideal(theta, glass));
      }
      CHECK(EnskogViscosity{}(phi, theta, g0, elastic) == ours_mu);
      CHECK(EnskogConductivity{}(phi, theta, g0, elastic) == ours_kappa);
    }
  }
  MESSAGE("Enskog against seed 002 eqs 75-76 written with y: worst relative difference " << worst);
}

TEST_CASE("Enskog against Gidaspow at e = 1: only the constant of the y term differs (seed 002 footnote 3)") {
  // Gidaspow's forms (seed 002 eqs 82-83) at e = 1 are Enskog's with c_1 = c_2 = 1:
  // 4/25 (1 + 12/π) = 0.7712 and 9/25 (1 + 32/(9π)) = 0.7674. The seed's printed 0.7614 and
  // 0.7574 (from c_2 = 1.016: 0.761530, and the factor 1.025: 0.757499) differ by these constants
  // times 16 μ_id g0 φ² (resp. κ_id).
  const GranularMaterial<double> elastic{glass.diameter, glass.density, 1.0};
  const double pi = std::numbers::pi;
  const double gidaspow_mu = 4.0 / 25 * (1 + 12 / pi), gidaspow_kappa = 9.0 / 25 * (1 + 32 / (9 * pi));
  CHECK(4.0 / 25 * (1 + 12 / (pi * 1.016)) == doctest::Approx(0.761530).epsilon(1e-6));
  CHECK(9.0 / 25 * (1 + 32 / (9 * pi * 1.025)) == doctest::Approx(0.757499).epsilon(1e-6));
  for (const double phi : {0.05, 0.3, 0.5}) {
    const double g0 = SongStrattMason{}(phi);
    const double mu_difference = EnskogViscosity{}(phi, theta, g0, elastic) - GidaspowViscosity{}(phi, theta, g0, elastic);
    const double kappa_difference =
        EnskogConductivity{}(phi, theta, g0, elastic) - GidaspowConductivity{}(phi, theta, g0, elastic);
    CHECK(mu_difference == doctest::Approx(16 * mu_ideal(theta, glass) * g0 * phi * phi * (0.7614 - gidaspow_mu))
                               .epsilon(1e-11));
    CHECK(kappa_difference ==
          doctest::Approx(16 * kappa_ideal(theta, glass) * g0 * phi * phi * (0.7574 - gidaspow_kappa)).epsilon(1e-11));
  }
}

TEST_CASE("Enskog laws in a ConstitutiveSet: derivatives in phi through g0 and in Theta, mu/(2 Theta)") {
  const ConstitutiveSet set{SongStrattMason{}, LunPressure{}, EnskogViscosity{}, EnskogConductivity{}};
  for (const double phi : {0.0, 0.1, 0.3, 0.55, 0.64}) {
    INFO("phi = " << phi);
    const auto v = set.checked_with_derivatives(phi, theta, glass);
    CHECK(v.radial_distribution.value == SongStrattMason{}(phi));
    CHECK(v.shear_viscosity.value == EnskogViscosity{}(phi, theta, SongStrattMason{}(phi), glass));
    CHECK(v.shear_viscosity.d_granular_temperature ==
          doctest::Approx(v.shear_viscosity.value / (2 * theta)).epsilon(1e-14));
    CHECK(v.conductivity.d_granular_temperature == doctest::Approx(v.conductivity.value / (2 * theta)).epsilon(1e-14));
    // ∂μ/∂φ = μ_id (−g0'/g0² + 16/5 + 16 c (g0' φ² + 2 g0 φ)), with g0' from the law.
    const auto g = SongStrattMason{}.with_derivatives(phi);
    const double slope = mu_ideal(theta, glass) * (-g.d_solid_fraction / (g.value * g.value) + 3.2 +
                                                   16 * 0.7614 * (g.d_solid_fraction * phi * phi + 2 * g.value * phi));
    CHECK(v.shear_viscosity.d_solid_fraction == doctest::Approx(slope).epsilon(1e-13));
  }
  // Θ = 0: the value is 0, ∂/∂Θ is +∞ (∝ √Θ), as every other transport coefficient.
  const auto zero = set.with_derivatives(0.3, 0.0, glass);
  CHECK(zero.shear_viscosity.value == 0);
  CHECK(zero.conductivity.d_granular_temperature == std::numeric_limits<double>::infinity());
  // Run-time selection by name.
  CHECK(ShearViscosities::find("EnskogViscosity").has_value());
  CHECK(Conductivities::find("EnskogConductivity").has_value());
  CHECK(RadialDistributions::find("SongStrattMason").has_value());
  CHECK(RadialDistributions::find("TobochnikChapin").has_value());
}
