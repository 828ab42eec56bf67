// Kinetic theory beyond the collisional set: frictional stress (Johnson–Jackson, Schaeffer,
// Srivastava–Sundaresan), gas–particle exchange of granular energy and the algebraic
// granular temperature with strain and gas. References: the mpmath generator
// tests/reference/ktgf_reference.py (ktgf_friction_reference.csv,
// ktgf_exchange_reference.csv), an independent double-precision evaluation of seed 001's and
// seed 004's friction, exchange and algebraic-Θ formulas made when the seeds were read (each
// quoted where used), and exact identities.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "kinetic_theory_table_names.hpp"
#include "reference_table.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

using fluidbed::test::relative_difference;

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// |got − expected| relative to |expected| + scale.
double scaled_error(double got, double expected, double scale) {
  return got == expected ? 0.0 : std::abs(got - expected) / (std::abs(expected) + scale);
}

}  // namespace

TEST_CASE("frictional pressures and viscosities agree with the mpmath reference") {
  using D4 = Dual<double, 4>;  // φ, Θ, ∇·u, D':D'
  const test::ReferenceTable table("ktgf_friction_reference.csv");
  double worst_value = 0, worst_derivative = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string function = table.text(row, "function"), variant = table.text(row, "variant");
    const D4 phi = D4::variable(table.number(row, "solid_fraction"), 0);
    const D4 theta = D4::variable(table.number(row, "granular_temperature"), 1);
    const StrainRate<D4> rate{D4::variable(table.number(row, "divergence"), 2),
                              D4::variable(table.number(row, "deviatoric_contraction"), 3)};
    const double min_fraction = table.number(row, "min_fraction"), max_packing = table.number(row, "max_packing");
    const double coefficient = table.number(row, "coefficient");
    const double angle = radians(table.number(row, "friction_angle_deg"));
    const JohnsonJacksonPressure johnson_jackson{min_fraction, max_packing, coefficient,
                                                 table.number(row, "numerator_exponent"),
                                                 table.number(row, "denominator_exponent")};
    const SchaefferPressure schaeffer{min_fraction, coefficient, table.number(row, "numerator_exponent")};
    INFO(function << " " << variant << " row " << row + 2);
    D4 r;
    if (variant == "srivastava_sundaresan") {
      const auto stress = SrivastavaSundaresan{johnson_jackson, angle}(phi, theta, table.number(row, "diameter"), rate);
      r = function == "frictional_pressure" ? stress.pressure : stress.viscosity;
    } else if (function == "frictional_pressure") {
      r = variant == "johnson_jackson" ? johnson_jackson(phi) : schaeffer(phi);
    } else {
      REQUIRE(function == "frictional_viscosity");
      const D4 pressure = variant == "schaeffer:johnson_jackson" ? johnson_jackson(phi) : schaeffer(phi);
      r = SchaefferViscosity{angle}(pressure, rate);
    }
    const double value = table.number(row, "value");
    worst_value = std::max(worst_value, relative_difference(r.value, value));
    CHECK(relative_difference(r.value, value) < 1e-13);
    const char* columns[] = {"d_solid_fraction", "d_granular_temperature", "d_divergence", "d_deviatoric_contraction"};
    for (int c = 0; c < 4; ++c) {
      const double error = scaled_error(r.derivative[c], table.number(row, columns[c]), 1e-9 * std::abs(value));
      worst_derivative = std::max(worst_derivative, error);
      CHECK(error < 1e-11);
    }
  }
  CHECK(table.size() >= 1000);
  MESSAGE("friction rows " << table.size() << ": worst value " << worst_value << ", derivative " << worst_derivative);
}

TEST_CASE("friction: published numbers, onset, the continuation near packing and Coulomb's shear stress") {
  // Seed 001 eq. 36 with its Table 1 values (Fr = 0.05, a = 2, b = 5, φ_min = 0.61, φ_max = 0.63),
  // evaluated independently.
  const JohnsonJacksonPressure seed001{0.61, 0.63};
  CHECK(seed001(0.61) == 0.0);
  CHECK(seed001(0.615) == doctest::Approx(1646.090535).epsilon(1e-9));
  CHECK(seed001(0.62) == doctest::Approx(50000.0).epsilon(1e-12));  // φ_c itself: the formula
  // Beyond φ_c the printed formula (3.6e6 at 0.625) is replaced by the tangent: smaller,
  // finite up to and beyond φ_max, with a continuous slope at φ_c.
  CHECK(seed001(0.625) < 3.6e6);
  CHECK(std::isfinite(seed001(0.63)));
  CHECK(std::isfinite(seed001(0.7)));
  using D1 = Dual<double, 1>;
  const double c = 0.62;
  CHECK(relative_difference(seed001(D1::variable(std::nextafter(c, 1.0), 0)).derivative[0],
                            seed001(D1::variable(c, 0)).derivative[0]) < 1e-12);
  // Seed 004's friction slide: Fr = 0.005, φ_min = 0.55, φ_max = 0.64 (evaluated independently).
  const JohnsonJacksonPressure seed004{0.55, 0.64, 0.005};
  CHECK(seed004(0.56) == doctest::Approx(0.152588).epsilon(5e-6));
  CHECK(seed004(0.60) == doctest::Approx(122.070).epsilon(5e-6));
  CHECK(seed004(0.62) == doctest::Approx(7656.25).epsilon(5e-6));
  CHECK(seed004(0.63) == doctest::Approx(320000).epsilon(5e-6));
  // Schaeffer's viscosity in simple shear γ̇ (D':D' = γ̇²/2): μ = p sin φ_f/γ̇, i.e. the shear
  // stress is p sin φ_f (51.5891 at 0.60, γ̇ = 1, φ_f = 25°, evaluated independently).
  const SchaefferViscosity coulomb{radians(25)};
  for (double shear_rate : {1.0, 10.0}) {
    const StrainRate<double> shear{0.0, 0.5 * shear_rate * shear_rate};
    CHECK(coulomb(seed004(0.60), shear) == doctest::Approx(51.5891 / shear_rate).epsilon(5e-6));
  }
  // Seed 001 eq. 38 evaluated independently: p = 68.2570812281924 (Lun p_s at 0.62), φ_f = 30°,
  // I_2D = 25.
  CHECK(SchaefferViscosity{radians(30)}(68.2570812281924, StrainRate<double>{0.0, 50.0}) ==
        doctest::Approx(3.4128540614096194).epsilon(1e-12));
  // At rest the floor keeps μ finite; below the onset everything is 0.
  CHECK(std::isfinite(coulomb(seed004(0.60), StrainRate<double>{0.0, 0.0})));
  CHECK(SchaefferPressure{0.6}(0.59) == 0.0);
  CHECK(SchaefferPressure{0.6}(0.61) == doctest::Approx(1e24 * std::pow(0.01, 10)).epsilon(1e-13));
}

TEST_CASE("Srivastava-Sundaresan: critical state at zero dilatation, continuity across it, no NaN") {
  const SrivastavaSundaresan model{JohnsonJacksonPressure{0.5, 0.63}, radians(28.5)};
  const double phi = 0.6, d = 2e-4;
  const double critical = JohnsonJacksonPressure{0.5, 0.63}(phi);
  for (double theta : {0.0, 1e-3}) {
    const StrainRate<double> rest_shape{0.0, 2.0};
    const auto s = model(phi, theta, d, rest_shape);
    const double zeta = std::sqrt(2.0 + theta / (d * d) + 1e-12);
    CHECK(s.pressure == doctest::Approx(critical).epsilon(1e-15));
    CHECK(s.viscosity ==
          doctest::Approx(std::numbers::sqrt2 * critical * std::sin(radians(28.5)) / (2 * zeta)).epsilon(1e-14));
    // Continuous across ∇·u = 0 although n switches between 1.03 and √3/(2 sin φ_f).
    const auto below = model(phi, theta, d, StrainRate<double>{-1e-9, 2.0});
    const auto above = model(phi, theta, d, StrainRate<double>{1e-9, 2.0});
    CHECK(relative_difference(below.pressure, above.pressure) < 1e-8);
    CHECK(relative_difference(below.viscosity, above.viscosity) < 1e-8);
  }
  // Compaction raises the pressure, dilation lowers it; strong dilation takes it to 0.
  CHECK(model(phi, 0.0, d, StrainRate<double>{-1.0, 2.0}).pressure > critical);
  CHECK(model(phi, 0.0, d, StrainRate<double>{1.0, 2.0}).pressure < critical);
  const auto torn = model(phi, 0.0, d, StrainRate<double>{100.0, 0.01});
  CHECK(torn.pressure == 0.0);
  CHECK(torn.viscosity == 0.0);
  // Everything at rest and Θ = 0: finite, derivatives not NaN.
  using D4 = Dual<double, 4>;
  const auto still =
      model(D4::variable(phi, 0), D4::variable(0.0, 1), d, StrainRate<D4>{D4::variable(0.0, 2), D4::variable(0.0, 3)});
  CHECK(std::isfinite(still.pressure.value));
  CHECK(std::isfinite(still.viscosity.value));
  for (int i = 0; i < 4; ++i) {
    CHECK_FALSE(std::isnan(still.pressure.derivative[i]));
    CHECK_FALSE(std::isnan(still.viscosity.derivative[i]));
  }
}

TEST_CASE("gas exchange and the algebraic granular temperature agree with the mpmath reference") {
  using D6 = Dual<double, 6>;  // φ, Θ, β, w, ∇·u, D':D'
  const test::ReferenceTable table("ktgf_exchange_reference.csv");
  double worst_value = 0, worst_derivative = 0;
  int algebraic_rows = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string function = table.text(row, "function");
    const auto [author, rdf] = test::split_variant(table.text(row, "variant"));
    const D6 phi = D6::variable(table.number(row, "solid_fraction"), 0);
    const D6 theta = D6::variable(table.number(row, "granular_temperature"), 1);
    const D6 beta = D6::variable(table.number(row, "beta"), 2), slip = D6::variable(table.number(row, "slip"), 3);
    const StrainRate<D6> rate{D6::variable(table.number(row, "divergence"), 4),
                              D6::variable(table.number(row, "deviatoric_contraction"), 5)};
    const GranularMaterial<double> m{table.number(row, "diameter"), table.number(row, "particle_density"),
                                     table.number(row, "restitution")};
    INFO(function << " " << table.text(row, "variant") << " row " << row + 2);
    D6 r;
    if (function == "fluctuating_energy_sink") {
      r = gas_damping(beta, theta);
    } else if (function == "fluctuating_energy_source") {
      if (author == "koch_sangani")
        r = KochSanganiSource{}(phi, theta, test::row_radial_distribution(rdf, phi), slip,
                                table.number(row, "gas_viscosity"), m);
      else
        r = DragFluctuationSource{}(phi, theta, beta, slip, m);
    } else {
      REQUIRE(function == "algebraic_granular_temperature");
      ++algebraic_rows;
      const D6 g0 = test::row_radial_distribution(rdf, phi);
      r = author == "gidaspow" ? algebraic_granular_temperature(LunPressure{}, GidaspowViscosity{}, LunBulkViscosity{},
                                                                LunDissipation{}, phi, g0, m, rate, beta)
                               : algebraic_granular_temperature(LunPressure{}, SyamlalViscosity{}, LunBulkViscosity{},
                                                                LunDissipation{}, phi, g0, m, rate, beta);
    }
    const double value = table.number(row, "value");
    worst_value = std::max(worst_value, relative_difference(r.value, value));
    CHECK(relative_difference(r.value, value) < 1e-13);
    const char* columns[] = {"d_solid_fraction", "d_granular_temperature", "d_beta",
                             "d_slip",           "d_divergence",           "d_deviatoric_contraction"};
    for (int c = 0; c < 6; ++c) {
      const double error = scaled_error(r.derivative[c], table.number(row, columns[c]), 1e-9 * std::abs(value));
      worst_derivative = std::max(worst_derivative, error);
      CHECK(error < 1e-11);
    }
  }
  CHECK(algebraic_rows >= 100);
  MESSAGE("exchange rows " << table.size() << ": worst value " << worst_value << ", derivative " << worst_derivative);
}

TEST_CASE("gas exchange and algebraic temperature: independently evaluated numbers and identities") {
  const GranularMaterial<double> m{500e-6, 2500.0, 0.9};
  // The Ergun K of seed 001 eq. 41 (the library's Ergun in the pressure-gradient
  // convention, which is FLUENT's K_gs) gives −3KΘ = −60.5571 at α_s = 0.3 (Θ = 0.01,
  // air 1.2 / 1.8e-5, slip 0.5 m/s, d = 500 µm).
  const double k_ergun = 150 * 0.09 * 1.8e-5 / (0.7 * 500e-6 * 500e-6) + 1.75 * 0.3 * 1.2 * 0.5 / 500e-6;
  CHECK(k_ergun == doctest::Approx(2018.57).epsilon(5e-6));
  CHECK(gas_damping(k_ergun, 0.01) == doctest::Approx(-60.5571).epsilon(5e-6));
  // With Stokes drag β = 18 μ φ/d² the drag-based source is Koch–Sangani's with g0 = 1.
  for (double phi : {0.01, 0.2})
    for (double theta : {0.0, 1e-4, 0.1}) {
      const double mu = 1.8e-5, w = 0.3, beta = 18 * mu * phi / (m.diameter * m.diameter);
      CHECK(DragFluctuationSource{}(phi, theta, beta, w, m) ==
            doctest::Approx(KochSanganiSource{}(phi, theta, 1.0, w, mu, m)).epsilon(1e-14));
      CHECK(std::isfinite(KochSanganiSource{}(phi, theta, 1.0, w, mu, m)));
    }
  // Θ with the Ergun sink, simple shear γ̇ = 1 and 10, Gidaspow μ, Lun γ (evaluated independently).
  const ConstitutiveSet ogawa{Ogawa{0.63}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
  const ConstitutiveSet cs{CarnahanStarling{}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
  const double k_055 = 150 * 0.3025 * 1.8e-5 / (0.45 * 500e-6 * 500e-6) + 1.75 * 0.55 * 1.2 * 0.5 / 500e-6;
  CHECK(k_055 == doctest::Approx(8415.00).epsilon(5e-6));
  const StrainRate<double> shear1{0.0, 0.5}, shear10{0.0, 50.0};
  CHECK(ogawa.algebraic_granular_temperature(0.3, m, shear1, k_ergun) == doctest::Approx(1.19314e-8).epsilon(5e-6));
  CHECK(ogawa.algebraic_granular_temperature(0.3, m, shear10, k_ergun) == doctest::Approx(1.68277e-5).epsilon(5e-6));
  CHECK(cs.algebraic_granular_temperature(0.55, m, shear1, k_055) == doctest::Approx(1.62852e-8).epsilon(5e-6));
  CHECK(cs.algebraic_granular_temperature(0.55, m, shear10, 0.0) == doctest::Approx(2.24406e-5).epsilon(5e-6));
  // The root balances production and losses, on both branches of the quadratic.
  for (const StrainRate<double>& rate : {StrainRate<double>{0.5, 3.0}, StrainRate<double>{-0.5, 3.0},
                                         StrainRate<double>{-0.5, 0.0}, StrainRate<double>{0.0, 0.0}})
    for (double beta : {0.0, 500.0}) {
      const double theta = ogawa.algebraic_granular_temperature(0.4, m, rate, beta);
      const auto v = ogawa(0.4, theta, m);
      const double production = -v.pressure * rate.divergence + 2 * v.shear_viscosity * rate.deviatoric_contraction +
                                v.bulk_viscosity * rate.divergence * rate.divergence;
      const double losses = v.dissipation + 3 * beta * theta;
      CHECK(theta >= 0);
      CHECK(production == doctest::Approx(losses).epsilon(1e-12).scale(1e-12));
    }
  // Sensitivities: the Dual result equals central differences.
  const auto s = ogawa.algebraic_granular_temperature_with_sensitivities(0.4, m, StrainRate<double>{-0.2, 3.0}, 300.0);
  const auto theta_at = [&](double phi, double beta, double div, double contraction) {
    return ogawa.algebraic_granular_temperature(phi, m, StrainRate<double>{div, contraction}, beta);
  };
  CHECK(fluidbed::test::same_arithmetic(s.value, theta_at(0.4, 300, -0.2, 3)));  // the dual's value part
  CHECK(
      s.d_solid_fraction ==
      doctest::Approx((theta_at(0.4 + 1e-7, 300, -0.2, 3) - theta_at(0.4 - 1e-7, 300, -0.2, 3)) / 2e-7).epsilon(1e-6));
  CHECK(
      s.d_beta ==
      doctest::Approx((theta_at(0.4, 300 + 1e-4, -0.2, 3) - theta_at(0.4, 300 - 1e-4, -0.2, 3)) / 2e-4).epsilon(1e-6));
  CHECK(
      s.d_divergence ==
      doctest::Approx((theta_at(0.4, 300, -0.2 + 1e-7, 3) - theta_at(0.4, 300, -0.2 - 1e-7, 3)) / 2e-7).epsilon(1e-6));
  CHECK(
      s.d_deviatoric_contraction ==
      doctest::Approx((theta_at(0.4, 300, -0.2, 3 + 1e-6) - theta_at(0.4, 300, -0.2, 3 - 1e-6)) / 2e-6).epsilon(1e-6));
  // Elastic particles under compression have no finite equilibrium (documented: +∞).
  const GranularMaterial<double> elastic{500e-6, 2500.0, 1.0};
  CHECK(ogawa.algebraic_granular_temperature(0.4, elastic, StrainRate<double>{-0.5, 1.0}, 0.0) ==
        std::numeric_limits<double>::infinity());
}
