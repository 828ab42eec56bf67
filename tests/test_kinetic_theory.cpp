// Kinetic theory of granular flow, one solids class: radial distribution functions,
// pressure, viscosities, conductivity, dissipation, algebraic granular temperature.
// References: the independent mpmath generator tests/reference/ktgf_reference.py
// (ktgf_reference.csv: values and mpmath.diff derivatives), an independent double-precision
// evaluation of the seeds' formulas made when seeds 001 and 004 were read (6 significant
// figures, or double-precision digits for seed 001's closures; each quoted where used), exact
// limits and identities, and finite differences of the library's own values for the derivatives.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "kinetic_theory_table_names.hpp"
#include "reference_table.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;
using D2 = Dual<double, 2>;

using fluidbed::test::relative_difference;

namespace {

// The state of the independent evaluation of seed 004's closures: d = 500 µm, ρ_s = 2500,
// e = 0.9, Θ = 0.01.
const GranularMaterial<double> state_material{500e-6, 2500.0, 0.9};
constexpr double state_theta = 0.01;

}  // namespace

TEST_CASE("radial distribution functions and their slopes agree with the mpmath reference") {
  const test::ReferenceTable table("ktgf_reference.csv");
  int rows = 0;
  double worst_value = 0, worst_slope = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    if (table.text(row, "function") != "radial_distribution") continue;
    ++rows;
    const std::string name = table.text(row, "variant");
    const double phi = table.number(row, "solid_fraction"), max_packing = table.number(row, "extra");
    INFO(name << " phi = " << phi << " phi_max = " << max_packing);
    const D2 g = test::radial_distribution(name, D2::variable(phi, 0), max_packing);
    const double value = table.number(row, "value"), slope = table.number(row, "d_solid_fraction");
    worst_value = std::max(worst_value, relative_difference(g.value, value));
    worst_slope = std::max(worst_slope, relative_difference(g.derivative[0], slope));
    CHECK(relative_difference(g.value, value) < 1e-13);
    CHECK(relative_difference(g.derivative[0], slope) < 1e-12);
    CHECK(test::same_arithmetic(test::radial_distribution(name, phi, max_packing), g.value));
  }
  CHECK(rows >= 114);
  MESSAGE("RDF rows " << rows << ": worst relative value error " << worst_value << ", slope " << worst_slope);
}

TEST_CASE("pressure, viscosities, conductivity and dissipation agree with the mpmath reference") {
  const test::ReferenceTable table("ktgf_reference.csv");
  int rows = 0;
  double worst_value = 0, worst_derivative = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string function = table.text(row, "function");
    if (function == "radial_distribution" || function == "algebraic_granular_temperature") continue;
    ++rows;
    const auto variant = test::split_variant(table.text(row, "variant"));
    const std::string &author = variant.first, &rdf = variant.second;  // clang < 16 captures no structured binding
    const double phi = table.number(row, "solid_fraction"), theta = table.number(row, "granular_temperature");
    const GranularMaterial<double> m{table.number(row, "diameter"), table.number(row, "particle_density"),
                                     table.number(row, "restitution")};
    const double extra = table.number(row, "extra");
    INFO(function << " " << author << ":" << rdf << " phi = " << phi << " theta = " << theta << " e = " << m.restitution
                  << " extra = " << extra);
    const D2 phi_d = D2::variable(phi, 0), theta_d = D2::variable(theta, 1);
    const D2 r =
        test::constitutive(function, author, phi_d, theta_d, test::row_radial_distribution(rdf, phi_d), m, extra);
    const double value = table.number(row, "value");
    const double error = relative_difference(r.value, value);
    // Derivative scales: value/φ and value/Θ (the derivatives' natural sizes).
    const double e_phi = std::abs(r.derivative[0] - table.number(row, "d_solid_fraction")) /
                         (std::abs(table.number(row, "d_solid_fraction")) + std::abs(value) / phi);
    const double e_theta = std::abs(r.derivative[1] - table.number(row, "d_granular_temperature")) /
                           (std::abs(table.number(row, "d_granular_temperature")) + std::abs(value) / theta);
    worst_value = std::max(worst_value, error);
    worst_derivative = std::max({worst_derivative, e_phi, e_theta});
    CHECK(error < 1e-13);
    CHECK(e_phi < 1e-12);
    CHECK(e_theta < 1e-12);
    // The plain-double path is the same arithmetic (same_arithmetic.hpp).
    const double plain =
        test::constitutive(function, author, phi, theta, test::row_radial_distribution(rdf, phi), m, extra);
    CHECK(test::same_arithmetic(plain, r.value));
  }
  CHECK(rows >= 1680);
  MESSAGE("constitutive rows " << rows << ": worst relative value error " << worst_value << ", derivative "
                               << worst_derivative);
}

TEST_CASE("the algebraic granular temperature in simple shear agrees with the mpmath reference") {
  const test::ReferenceTable table("ktgf_reference.csv");
  int rows = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    if (table.text(row, "function") != "algebraic_granular_temperature") continue;
    ++rows;
    const auto variant = test::split_variant(table.text(row, "variant"));
    const std::string &author = variant.first, &rdf = variant.second;  // clang < 16 captures no structured binding
    const double phi = table.number(row, "solid_fraction"), shear_rate = table.number(row, "extra");
    const GranularMaterial<double> m{table.number(row, "diameter"), table.number(row, "particle_density"),
                                     table.number(row, "restitution")};
    INFO(author << ":" << rdf << " phi = " << phi << " shear rate = " << shear_rate);
    // Simple shear u_x = γ̇ y: ∇·u = 0 and D':D' = γ̇²/2; no gas.
    const auto rate_of = [&](auto scalar) {
      using S = decltype(scalar);
      return StrainRate<S>{S(0.0), S(0.5 * shear_rate * shear_rate)};
    };
    const auto theta_of = [&](const auto& phi_s) {
      using S = std::remove_cvref_t<decltype(phi_s)>;
      const S g0 = test::row_radial_distribution(rdf, phi_s);
      const S beta(0.0);
      if (author == "gidaspow")
        return algebraic_granular_temperature(LunPressure{}, GidaspowViscosity{}, LunBulkViscosity{}, LunDissipation{},
                                              phi_s, g0, m, rate_of(S{}), beta);
      return algebraic_granular_temperature(LunPressure{}, SyamlalViscosity{}, LunBulkViscosity{}, LunDissipation{},
                                            phi_s, g0, m, rate_of(S{}), beta);
    };
    const Dual<double, 1> theta = theta_of(Dual<double, 1>::variable(phi, 0));
    CHECK(relative_difference(theta.value, table.number(row, "value")) < 1e-13);
    CHECK(relative_difference(theta.derivative[0], table.number(row, "d_solid_fraction")) < 1e-11);
  }
  CHECK(rows == 112);
}

TEST_CASE("seed-004 closures evaluated independently, through the ConstitutiveSet (d = 500 um, Theta = 0.01)") {
  // The independent evaluation (6 significant figures), Ogawa φ_max = 0.63 and Carnahan–Starling.
  const ConstitutiveSet ogawa{Ogawa{0.63}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
  const ConstitutiveSet cs{CarnahanStarling{}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
  const auto a = ogawa(0.3, state_theta, state_material);
  CHECK(a.radial_distribution == doctest::Approx(4.56406).epsilon(5e-6));
  CHECK(a.pressure == doctest::Approx(46.5227).epsilon(5e-6));
  CHECK(a.shear_viscosity == doctest::Approx(0.0692993).epsilon(5e-6));
  CHECK(a.bulk_viscosity == doctest::Approx(0.0733873).epsilon(5e-6));
  CHECK(a.conductivity == doctest::Approx(0.279639).epsilon(5e-6));
  CHECK(a.dissipation == doctest::Approx(2641.94).epsilon(5e-6));
  const auto b = cs(0.55, state_theta, state_material);
  CHECK(b.radial_distribution == doctest::Approx(7.95610).epsilon(5e-6));
  CHECK(b.pressure == doctest::Approx(242.389).epsilon(5e-6));
  CHECK(b.shear_viscosity == doctest::Approx(0.347369).epsilon(5e-6));
  CHECK(b.bulk_viscosity == doctest::Approx(0.429985).epsilon(5e-6));
  CHECK(b.conductivity == doctest::Approx(1.33483).epsilon(5e-6));
  CHECK(b.dissipation == doctest::Approx(15479.5).epsilon(5e-6));
  // dp_s/dφ (the independent evaluation), the Jacobian entry of seed 002 eq. 95.
  CHECK(ogawa.with_derivatives(0.3, state_theta, state_material).pressure.d_solid_fraction ==
        doctest::Approx(439.683).epsilon(5e-6));
  CHECK(cs.with_derivatives(0.55, state_theta, state_material).pressure.d_solid_fraction ==
        doctest::Approx(2222.99).epsilon(5e-6));
  // Seed 001's closures evaluated independently at state A (α_s = 0.3, Θ = 0.01, d = 279 µm,
  // ρ_s = 2480, e = 0.9, its glass beads): FLUENT's
  // per-phase Syamlal kinetic viscosity 0.026951793486765043 = ours/φ, conductivity
  // (Syamlal) 0.10915277022284721.
  const GranularMaterial<double> glass{279e-6, 2480.0, 0.9};
  const ConstitutiveSet fluent{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{}, SyamlalConductivity{}};
  CHECK(SyamlalViscosity{}.kinetic(0.3, 0.01, Ogawa{0.63}(0.3), glass) / 0.3 ==
        doctest::Approx(0.026951793486765043).epsilon(1e-12));
  CHECK(fluent(0.3, 0.01, glass).conductivity == doctest::Approx(0.10915277022284721).epsilon(1e-12));
  CHECK(fluent(0.3, 0.01, glass).pressure == doctest::Approx(46.15050170899907).epsilon(1e-12));
}

TEST_CASE("each seed misprint is caught: the printed form differs from the library") {
  const double g_ogawa_03 = Ogawa{0.63}(0.3), g_ogawa_055 = Ogawa{0.63}(0.55);
  const GranularMaterial<double>& m = state_material;
  const double e = m.restitution, rho = m.density, d = m.diameter, theta = state_theta;
  SUBCASE("M1: seed 001 eq. 27, Gidaspow kinetic viscosity with (3 - e) for (1 + e)") {
    // Seed 001's state A, evaluated independently: corrected 0.04662042742594844, as printed
    // 0.04218038671871525.
    const GranularMaterial<double> glass{279e-6, 2480.0, 0.9};
    const double ours = GidaspowViscosity{}.kinetic(0.3, 0.01, g_ogawa_03, glass) / 0.3;  // per phase
    CHECK(ours == doctest::Approx(0.04662042742594844).epsilon(1e-12));
    CHECK(relative_difference(ours, 0.04218038671871525) > 0.09);
  }
  SUBCASE("M2: seed 002 eq. 79, (1 + e) g0 under the root and a factor 2 dropped") {
    const double bracket = 1 + 0.8 * (1 + e) * g_ogawa_055 * 0.55;
    const double printed = 5.0 / 96.0 * std::numbers::pi * rho * d *
                               std::sqrt(theta / (std::numbers::pi * (1 + e) * g_ogawa_055)) * bracket * bracket +
                           GidaspowViscosity{}.collisional(0.55, theta, g_ogawa_055, m);
    const double ours = GidaspowViscosity{}(0.55, theta, g_ogawa_055, m);
    CHECK(printed == doctest::Approx(1.42937).epsilon(5e-6));  // eq. 79 as printed, evaluated independently
    CHECK(ours == doctest::Approx(0.945340).epsilon(5e-6));
  }
  SUBCASE("M3: seed 001 eq. 34, dissipation with (1 + e^2) for (1 - e^2)") {
    const double ours = LunDissipation{}(0.3, theta, g_ogawa_03, m);
    const double printed = ours * (1 + e * e) / (1 - e * e);
    CHECK(ours == doctest::Approx(2641.94).epsilon(5e-6));
    CHECK(printed == doctest::Approx(25168.0).epsilon(5e-6));  // eq. 34 as printed, evaluated independently
    const GranularMaterial<double> elastic{d, rho, 1.0};
    CHECK(LunDissipation{}(0.3, theta, CarnahanStarling{}(0.3), elastic) == 0.0);
  }
  SUBCASE("M4: seed 002 eq. 54, excess compressibility with (1 - e)/2 for (1 + e)/2") {
    const double phi = 0.3, g0 = CarnahanStarling{}(phi), y_es = 4 * g0 * phi;
    const double ideal = phi * rho * theta;
    const double correct = ideal * (1 + (1 + e) / 2 * y_es), printed = ideal * (1 + (1 - e) / 2 * y_es);
    const double ours = LunPressure{}(phi, theta, g0, m);
    CHECK(relative_difference(ours, correct) < 1e-15);
    CHECK(relative_difference(ours, printed) > 0.5);
  }
  SUBCASE("M5: seed 004 h_ik, third term 8 r^2 xi/(1 - x)^2 for 8 r^2 xi^2/(1 - x)^3") {
    // Monodisperse, d = 500 µm, α_max = 0.64: corrected 3.77695, printed 3.47708 (evaluated independently).
    CHECK(LathouwersBellan{0.64}(0.3) == doctest::Approx(3.77695).epsilon(5e-6));
    const double x = 0.3 / 0.64, r = d / 4, xi = 0.3 / d;
    const double printed = 1 / (1 - x) + 6 * r * xi / ((1 - x) * (1 - x)) + 8 * r * r * xi / ((1 - x) * (1 - x));
    CHECK(printed == doctest::Approx(3.47708).epsilon(5e-6));
  }
}

TEST_CASE("limits: g0 -> 1 as phi -> 0, dissipation -> 0 as e -> 1, the dilute viscosity and conductivity") {
  for (double phi : {1e-9, 1e-12, 0.0}) {
    CHECK(std::abs(CarnahanStarling{}(phi)-1) <= 2.5 * phi + 1e-16);
    CHECK(std::abs(PercusYevick{}(phi)-1) <= 2.5 * phi + 1e-16);
    CHECK(std::abs(MaAhmadi{}(phi)-1) <= 2.5 * phi + 1e-16);
    CHECK(std::abs(LathouwersBellan{0.64}(phi)-1) <= 3.1 * phi + 1e-16);
    CHECK(std::abs(LunSavage{0.64}(phi)-1) <= 2.5 * phi + 1e-16);
    // The cube-root forms approach 1 only like (φ/φ_max)^(1/3).
    const double cube_root = std::cbrt(phi / 0.63);
    CHECK(std::abs(Ogawa{0.63}(phi)-1 - cube_root) <= 2 * cube_root * cube_root + 1e-16);
    CHECK(std::abs(SinclairJackson{0.63}(phi)-1 - cube_root) <= 2 * cube_root * cube_root + 1e-16);
    CHECK(std::abs(GidaspowRadialDistribution{0.63}(phi)-0.6 * (1 + cube_root)) <= 2 * cube_root * cube_root + 1e-16);
  }
  // The initial slope of the hard-sphere forms is the second virial coefficient 5/2.
  for (double slope :
       {CarnahanStarling{}(D2::variable(0.0, 0)).derivative[0], PercusYevick{}(D2::variable(0.0, 0)).derivative[0],
        MaAhmadi{}(D2::variable(0.0, 0)).derivative[0]})
    CHECK(slope == doctest::Approx(2.5).epsilon(1e-15));
  CHECK(Ogawa{0.63}(D2::variable(0.0, 0)).derivative[0] == std::numeric_limits<double>::infinity());

  // Dissipation: 0 at e = 1 exactly, ∝ (1 − e²) near it.
  for (double e : {1.0, 1.0 - 1e-12, 0.999}) {
    const GranularMaterial<double> m{500e-6, 2500.0, e};
    const double gamma = LunDissipation{}(0.3, 0.01, CarnahanStarling{}(0.3), m);
    const double reference = LunDissipation{}(0.3, 0.01, CarnahanStarling{}(0.3), state_material) / (1 - 0.81);
    CHECK(gamma == doctest::Approx(reference * (1 - e * e)).epsilon(1e-9));
  }
  // φ → 0 with g0 → 1: Gidaspow's kinetic viscosity and conductivity tend to 2μ_dil/(1 + e)
  // and 2κ_dil/(1 + e) (0.0121468 and 0.0455503, evaluated independently), Syamlal's to 0.
  const double mu_dilute = 5.0 / 96.0 * 2500 * 500e-6 * std::sqrt(std::numbers::pi * 0.01);
  CHECK(mu_dilute == doctest::Approx(0.0115394).epsilon(5e-6));
  CHECK(GidaspowViscosity{}(0.0, 0.01, CarnahanStarling{}(0.0), state_material) ==
        doctest::Approx(2 * mu_dilute / 1.9).epsilon(1e-15));
  CHECK(GidaspowViscosity{}(0.0, 0.01, CarnahanStarling{}(0.0), state_material) ==
        doctest::Approx(0.0121468).epsilon(5e-6));
  CHECK(GidaspowConductivity{}(0.0, 0.01, CarnahanStarling{}(0.0), state_material) ==
        doctest::Approx(0.0455503).epsilon(5e-6));
  CHECK(SyamlalViscosity{}(0.0, 0.01, 1.0, state_material) == 0.0);
  CHECK(SyamlalConductivity{}(0.0, 0.01, 1.0, state_material) == 0.0);
  CHECK(LunPressure{}(1e-12, 0.01, 1.0, state_material) == doctest::Approx(1e-12 * 2500 * 0.01).epsilon(1e-11));
}

TEST_CASE("at Theta = 0 and phi = 0 values are finite and derivatives are never NaN") {
  const ConstitutiveSet gidaspow{Ogawa{0.63}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
  const ConstitutiveSet syamlal{CarnahanStarling{}, SyamlalRogersOBrienPressure{}, SyamlalViscosity{},
                                SyamlalConductivity{}};
  const ConstitutiveSet hrenya{LathouwersBellan{0.64}, AhmadiMaPressure{}, HrenyaSinclairViscosity(0.05),
                               HrenyaSinclairConductivity(0.05)};
  const auto check_all = [](const auto& set, double phi, double theta) {
    INFO("phi = " << phi << " theta = " << theta);
    const auto r = set.with_derivatives(phi, theta, state_material);
    for (const auto& v :
         {r.radial_distribution, r.pressure, r.shear_viscosity, r.bulk_viscosity, r.conductivity, r.dissipation}) {
      CHECK(std::isfinite(v.value));
      CHECK(v.value >= 0);
      CHECK_FALSE(std::isnan(v.d_solid_fraction));
      CHECK_FALSE(std::isnan(v.d_granular_temperature));
    }
    if (theta == 0) {
      CHECK(r.pressure.value == 0);
      CHECK(r.shear_viscosity.value == 0);
      CHECK(r.dissipation.d_granular_temperature == 0);
      // μ ∝ √Θ: the true ∂μ/∂Θ is +∞ at Θ = 0 (documented), never NaN (at φ = 0 Syamlal's
      // μ is identically 0 and so is its derivative).
      if (phi > 0) CHECK(r.shear_viscosity.d_granular_temperature == std::numeric_limits<double>::infinity());
    }
  };
  for (double phi : {0.0, 1e-8, 0.3, 0.62, 0.7, 0.95})
    for (double theta : {0.0, 1e-12, 0.01}) {
      check_all(gidaspow, phi, theta);
      check_all(syamlal, phi, theta);
      check_all(hrenya, phi, theta);
    }
}

TEST_CASE("derivatives equal central differences across the domain, through the continuation beyond packing") {
  const char* rdfs[] = {"carnahan_starling", "percus_yevick", "lun_savage",       "sinclair_jackson", "ogawa",
                        "gidaspow",          "ma_ahmadi",     "lathouwers_bellan"};
  const char* laws[][2] = {{"granular_pressure", "lun"},           {"granular_pressure", "ma_ahmadi"},
                           {"shear_viscosity", "gidaspow"},        {"shear_viscosity", "syamlal"},
                           {"shear_viscosity", "hrenya_sinclair"}, {"bulk_viscosity", "lun"},
                           {"conductivity", "gidaspow"},           {"conductivity", "syamlal"},
                           {"conductivity", "hrenya_sinclair"},    {"dissipation", "lun"}};
  double worst = 0;
  for (const char* rdf : rdfs)
    for (const auto& law : laws)
      for (double phi : {0.001, 0.05, 0.2, 0.4, 0.55, 0.6, 0.615, 0.625, 0.66, 0.8})
        for (double theta : {1e-5, 0.05}) {
          INFO(rdf << " " << law[0] << " " << law[1] << " phi = " << phi << " theta = " << theta);
          const auto f = [&](const auto& p, const auto& t) {
            return test::constitutive(law[0], law[1], p, t, test::radial_distribution(rdf, p, 0.63), state_material,
                                      0.05);
          };
          const D2 r = f(D2::variable(phi, 0), D2::variable(theta, 1));
          const double h_phi = 1e-6 * phi, h_theta = 1e-6 * theta;
          const double fd_phi = (f(phi + h_phi, theta) - f(phi - h_phi, theta)) / (2 * h_phi);
          const double fd_theta = (f(phi, theta + h_theta) - f(phi, theta - h_theta)) / (2 * h_theta);
          const double e_phi = std::abs(r.derivative[0] - fd_phi) / (std::abs(fd_phi) + std::abs(r.value) / phi);
          const double e_theta =
              std::abs(r.derivative[1] - fd_theta) / (std::abs(fd_theta) + std::abs(r.value) / theta);
          worst = std::max({worst, e_phi, e_theta});
          CHECK(e_phi < 1e-7);
          CHECK(e_theta < 1e-7);
        }
  MESSAGE("worst relative difference, Dual vs central difference: " << worst);
}

TEST_CASE("the continuation beyond packing is continuous with a continuous slope, increasing and finite") {
  // linear: the whole g0 is the continued factor (for Ma–Ahmadi only the denominator is,
  // times the polynomial).
  const auto check_c1 = [](const auto& rdf, double max_packing, bool linear = true) {
    const double c = max_packing - default_packing_margin;
    INFO(rdf.name() << " phi_c = " << c);
    const D2 below = rdf(D2::variable(std::nextafter(c, 0.0), 0)), at = rdf(D2::variable(c, 0));
    const D2 above = rdf(D2::variable(std::nextafter(c, 1.0), 0));
    CHECK(relative_difference(above.value, at.value) < 1e-13);
    CHECK(relative_difference(below.value, at.value) < 1e-13);
    CHECK(relative_difference(above.derivative[0], at.derivative[0]) < 1e-12);
    // Beyond: the tangent line, finite and increasing up to φ → 1, slope constant.
    double previous = at.value;
    for (double phi = c + 0.01; phi < 1; phi += 0.01) {
      const D2 g = rdf(D2::variable(phi, 0));
      CHECK(std::isfinite(g.value));
      CHECK(g.value > previous);
      if (linear) CHECK(relative_difference(g.derivative[0], at.derivative[0]) < 1e-15);
      CHECK(g.derivative[0] >= at.derivative[0]);
      previous = g.value;
    }
  };
  check_c1(LunSavage{0.64}, 0.64);
  check_c1(Ogawa{0.63}, 0.63);
  check_c1(SinclairJackson{0.6}, 0.6);
  check_c1(GidaspowRadialDistribution{0.64}, 0.64);
  check_c1(MaAhmadi{}, MaAhmadi::max_packing<double>(), false);
  // Lathouwers–Bellan continues each factor; their sum has a continuous slope too.
  const LathouwersBellan lb{0.64};
  const double c = 0.63;
  CHECK(relative_difference(lb(D2::variable(std::nextafter(c, 1.0), 0)).derivative[0],
                            lb(D2::variable(c, 0)).derivative[0]) < 1e-12);
  // A custom margin moves the continuation point.
  CHECK(Ogawa{0.63, 0.001}(0.625) == doctest::Approx(1.0 / (1.0 - std::cbrt(0.625 / 0.63))).epsilon(1e-15));
  CHECK(Ogawa{0.63}(0.625) < 1.0 / (1.0 - std::cbrt(0.625 / 0.63)));
}

TEST_CASE("Theta dependence is exactly a power of Theta: Theta dF/dTheta = k F") {
  const ConstitutiveSet set{MaAhmadi{}, LunPressure{}, HrenyaSinclairViscosity(0.01), GidaspowConductivity{}};
  for (double phi : {0.01, 0.3, 0.6})
    for (double theta : {1e-6, 0.02, 3.0}) {
      const auto r = set.with_derivatives(phi, theta, state_material);
      CHECK(theta * r.pressure.d_granular_temperature == doctest::Approx(r.pressure.value).epsilon(1e-14));
      CHECK(theta * r.shear_viscosity.d_granular_temperature ==
            doctest::Approx(0.5 * r.shear_viscosity.value).epsilon(1e-14));
      CHECK(theta * r.conductivity.d_granular_temperature ==
            doctest::Approx(0.5 * r.conductivity.value).epsilon(1e-14));
      CHECK(theta * r.dissipation.d_granular_temperature == doctest::Approx(1.5 * r.dissipation.value).epsilon(1e-14));
      CHECK(r.radial_distribution.d_granular_temperature == 0);
    }
}

TEST_CASE("strain-rate invariants from a velocity gradient") {
  // Simple shear u_x = γ̇ y: ∇·u = 0, D':D' = γ̇²/2, I_2D = D':D'/2 = γ̇²/4 (seed 001 eq. 39).
  const std::array<std::array<double, 3>, 3> shear{{{0, 0, 0}, {2.0, 0, 0}, {0, 0, 0}}};
  const auto s = strain_rate_of(shear);
  CHECK(s.divergence == 0);
  CHECK(s.deviatoric_contraction == doctest::Approx(2.0).epsilon(1e-15));
  // Seed 001 eq. 39 for D = [[1, .2, 0], [.2, −.5, .3], [0, .3, .1]] gives I_2D = 0.7.
  const std::array<std::array<double, 3>, 3> d{{{1, 0.2, 0}, {0.2, -0.5, 0.3}, {0, 0.3, 0.1}}};
  const auto t = strain_rate_of(d);
  CHECK(t.divergence == doctest::Approx(0.6).epsilon(1e-15));
  CHECK(0.5 * t.deviatoric_contraction == doctest::Approx(0.7).epsilon(1e-14));
}

TEST_CASE("the checked entry point names the offending argument") {
  const ConstitutiveSet set{CarnahanStarling{}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
  const auto message_of = [&](double phi, double theta, GranularMaterial<double> m) -> std::string {
    try {
      set.checked(phi, theta, m);
    } catch (const std::domain_error& error) {
      return error.what();
    }
    return "";
  };
  CHECK(message_of(0.3, 0.01, state_material).empty());
  CHECK(message_of(-0.1, 0.01, state_material).find("'solid_fraction' = -0.1") != std::string::npos);
  CHECK(message_of(1.0, 0.01, state_material).find("solid_fraction") != std::string::npos);
  CHECK(message_of(std::nan(""), 0.01, state_material).find("solid_fraction") != std::string::npos);
  CHECK(message_of(0.3, -1, state_material).find("'granular_temperature' = -1") != std::string::npos);
  CHECK(message_of(0.3, std::numeric_limits<double>::infinity(), state_material).find("granular_temperature") !=
        std::string::npos);
  CHECK(message_of(0.3, 0.01, {0.0, 2500, 0.9}).find("material.diameter") != std::string::npos);
  CHECK(message_of(0.3, 0.01, {5e-4, -1, 0.9}).find("material.density") != std::string::npos);
  CHECK(message_of(0.3, 0.01, {5e-4, 2500, 1.1}).find("material.restitution") != std::string::npos);
  CHECK(set.checked(0.3, 0.01, state_material).pressure == set(0.3, 0.01, state_material).pressure);
}
