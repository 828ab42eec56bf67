// Wall boundary conditions of the solids phase (kinetic_theory/walls.hpp): Johnson–Jackson's
// partial-slip wall and Jenkins–Louge's small-friction flat wall. References: the mpmath
// generator tests/reference/wall_reference.py (wall_reference.csv, which also checks the codes'
// own arrangements of the formulas), exact limits (free slip, Coulomb saturation, OpenFOAM's
// reference temperature (2/3)ψu²/(1 − e_w²) at which the wall flux vanishes) and finite
// differences.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "fluidbed/kinetic_theory.hpp"
#include "reference_table.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

namespace {

// |got − expected| relative to |expected| + scale.
double scaled_error(double got, double expected, double scale) {
  return got == expected ? 0.0 : std::abs(got - expected) / (std::abs(expected) + scale);
}

template <class S>
const S& quantity_of(const WallConditions<S>& w, const std::string& quantity) {
  if (quantity == "shear") return w.shear;
  if (quantity == "slip_coefficient") return w.slip_coefficient;
  if (quantity == "energy_flux") return w.energy_flux;
  if (quantity == "generation") return w.generation;
  if (quantity == "dissipation") return w.dissipation;
  REQUIRE(quantity == "dissipation_coefficient");
  return w.dissipation_coefficient;
}

struct Row {
  std::string law, quantity;
  double specularity, wall_restitution, max_packing, wall_friction, slip_floor;
  double phi, theta, slip, g0;
  GranularMaterial<double> material;
  double value, d_phi, d_theta, d_slip;
};

Row row_of(const test::ReferenceTable& t, std::size_t r) {
  return {t.text(r, "law"),
          t.text(r, "quantity"),
          t.number(r, "specularity"),
          t.number(r, "wall_restitution"),
          t.number(r, "max_packing"),
          t.number(r, "wall_friction"),
          t.number(r, "slip_floor"),
          t.number(r, "solid_fraction"),
          t.number(r, "granular_temperature"),
          t.number(r, "wall_slip"),
          t.number(r, "g0"),
          {5e-4, t.number(r, "particle_density"), t.number(r, "restitution")},
          t.number(r, "value"),
          t.number(r, "d_solid_fraction"),
          t.number(r, "d_granular_temperature"),
          t.number(r, "d_wall_slip")};
}

// The row's law as the registry's variant.
WallBoundaryConditions::Variant law_of(const Row& row) {
  if (row.law == "johnson_jackson") return JohnsonJacksonWall{row.specularity, row.wall_restitution, row.max_packing};
  REQUIRE(row.law == "jenkins_louge");
  return JenkinsLougeWall{row.wall_friction, row.wall_restitution, row.slip_floor};
}

const GranularMaterial<double> glass{5e-4, 2480, 0.9};  // seed 001 Table 1: glass, e = 0.9
const SinclairJackson sinclair_jackson{0.63};

}  // namespace

TEST_CASE("wall laws agree with the mpmath reference, values and derivatives") {
  const test::ReferenceTable table("wall_reference.csv");
  REQUIRE(table.size() == 2880);
  double worst_value = 0, worst_derivative = 0, worst_g0 = 0;
  for (std::size_t r = 0; r < table.size(); ++r) {
    const Row row = row_of(table, r);
    INFO(row.law << " " << row.quantity << " row " << r + 2);
    const auto law = law_of(row);
    std::visit(
        [&](const auto& l) {
          const double value = quantity_of(l(row.phi, row.theta, row.g0, row.slip, row.material), row.quantity);
          const WallDerivatives<double> d =
              quantity_of(l.with_derivatives(row.phi, row.theta, sinclair_jackson, row.slip, row.material), row.quantity);
          worst_g0 = std::max(worst_g0, scaled_error(sinclair_jackson(row.phi), row.g0, 0.0));
          const double scale = 1e-300;
          worst_value = std::max(worst_value, scaled_error(value, row.value, scale));
          worst_value = std::max(worst_value, scaled_error(d.value, row.value, scale));
          // Derivatives: relative to the largest of the row's derivatives (a component that is
          // 0 analytically comes out of mpmath.diff as a residue of that size).
          const double size = std::abs(row.d_phi) + std::abs(row.d_theta) + std::abs(row.d_slip) + 1e-300;
          const double e = std::max({std::abs(d.d_solid_fraction - row.d_phi), std::abs(d.d_granular_temperature - row.d_theta),
                                     std::abs(d.d_wall_slip - row.d_slip)}) /
                           size;
          worst_derivative = std::max(worst_derivative, e);
          CHECK(scaled_error(value, row.value, scale) < 1e-13);
          CHECK(e < 1e-12);
        },
        law);
  }
  MESSAGE("wall laws vs mpmath: worst value " << worst_value << ", derivative " << worst_derivative << ", g0 "
                                              << worst_g0);
  CHECK(worst_g0 < 1e-14);
}

TEST_CASE("wall laws in float, double and long double") {
  const test::ReferenceTable table("wall_reference.csv");
  const auto check_type = [&]<class T>(T, double tolerance) {
    double worst = 0;
    for (std::size_t r = 0; r < table.size(); r += 7) {
      const Row row = row_of(table, r);
      const GranularMaterial<T> m{T(row.material.diameter), T(row.material.density), T(row.material.restitution)};
      std::visit(
          [&](const auto& l) {
            const WallConditions<T> w = l(T(row.phi), T(row.theta), T(row.g0), T(row.slip), m);
            const double got = static_cast<double>(quantity_of(w, row.quantity));
            worst = std::max(worst, scaled_error(got, row.value, 1e-30));
            const auto d = l.with_derivatives(T(row.phi), T(row.theta), sinclair_jackson, T(row.slip), m);
            CHECK(std::isfinite(static_cast<double>(quantity_of(d, row.quantity).d_granular_temperature)));
          },
          law_of(row));
    }
    CHECK(worst < tolerance);
    return worst;
  };
  MESSAGE("float " << check_type(0.0f, 2e-5) << ", double " << check_type(0.0, 1e-13) << ", long double "
                   << check_type(0.0L, 1e-13));
}

TEST_CASE("free-slip limit: specularity 0 or no friction gives no shear and no generation") {
  for (const double phi : {0.001, 0.05, 0.3})
    for (const double slip : {0.0, 0.3, 3.0}) {
      const double theta = 0.02, g0 = sinclair_jackson(phi);
      const auto jj = JohnsonJacksonWall{0.0, 0.2, 0.63}(phi, theta, g0, slip, glass);
      CHECK(jj.shear == 0);
      CHECK(jj.slip_coefficient == 0);
      CHECK(jj.generation == 0);
      CHECK(jj.dissipation > 0);
      CHECK(jj.energy_flux == -jj.dissipation);  // the wall only cools the bed
      CHECK(slip_length(jj.slip_coefficient, 0.1) == std::numeric_limits<double>::infinity());
      CHECK(velocity_robin(jj, 0.1).coefficient == 0);  // zero gradient: free slip
      const auto jl = JenkinsLougeWall{0.0, 0.9}(phi, theta, g0, slip, glass);
      CHECK(jl.shear == 0);
      CHECK(jl.generation == 0);
      CHECK(jl.energy_flux < 0);
      // and the shear and generation vanish continuously as ψ → 0
      const auto small = JohnsonJacksonWall{1e-12, 0.2, 0.63}(phi, theta, g0, slip, glass);
      CHECK(small.shear <= 1e-9 * (1 + slip));
    }
  // An elastic wall (e_w = 1) dissipates nothing.
  const auto elastic = JohnsonJacksonWall{0.01, 1.0, 0.63}(0.1, 0.02, sinclair_jackson(0.1), 1.0, glass);
  CHECK(elastic.dissipation == 0);
  CHECK(elastic.energy_flux > 0);
}

TEST_CASE("no-slip trend: the slip length falls as specularity or friction grows") {
  const double phi = 0.3, theta = 0.05, slip = 0.5, g0 = sinclair_jackson(phi), mu_s = 0.05;
  double previous = std::numeric_limits<double>::infinity();
  for (const double psi : {0.0, 0.001, 0.01, 0.1, 0.5, 1.0}) {
    const auto w = JohnsonJacksonWall{psi, 0.9, 0.63}(phi, theta, g0, slip, glass);
    const double length = slip_length(w.slip_coefficient, mu_s);
    CHECK(length <= previous);
    if (psi > 0) CHECK(length < previous);
    previous = length;
  }
  // Johnson–Jackson's k is linear in ψ: the slip length is 1/ψ times that of ψ = 1.
  const auto diffuse = JohnsonJacksonWall{1.0, 0.9, 0.63}(phi, theta, g0, slip, glass);
  const auto riser = JohnsonJacksonWall{0.001, 0.9, 0.63}(phi, theta, g0, slip, glass);
  CHECK(slip_length(riser.slip_coefficient, mu_s) == doctest::Approx(1000 * slip_length(diffuse.slip_coefficient, mu_s)));
  // Jenkins–Louge: k ∝ μ_w, so large friction drives the slip length to 0 (towards no slip).
  previous = std::numeric_limits<double>::infinity();
  for (const double mu : {0.01, 0.1, 1.0, 10.0, 1000.0}) {
    const auto w = JenkinsLougeWall{mu, 0.9}(phi, theta, g0, slip, glass);
    const double length = slip_length(w.slip_coefficient, mu_s);
    CHECK(length < previous);
    previous = length;
  }
  CHECK(previous < 1e-6);
  // Coulomb: the shear saturates at μ_w N for u ≫ u_0 and is continuous through u = 0.
  const JenkinsLougeWall coulomb{0.2, 0.9};
  const double normal_stress = LunPressure{}(phi, theta, g0, glass);
  CHECK(coulomb(phi, theta, g0, 1.0, glass).shear == doctest::Approx(0.2 * normal_stress).epsilon(1e-12));
  CHECK(coulomb(phi, theta, g0, 0.0, glass).shear == 0);
  CHECK(std::isfinite(coulomb(phi, theta, g0, 0.0, glass).slip_coefficient));
  CHECK(coulomb(phi, theta, g0, 1e-9, glass).shear < 1e-3 * 0.2 * normal_stress);
}

TEST_CASE("energy flux sign: into the bed above OpenFOAM's reference temperature, out below") {
  for (const auto& [psi, e_w] : {std::pair{0.001, 0.2}, std::pair{0.01, 0.9}, std::pair{1.0, 0.5}}) {
    const JohnsonJacksonWall wall{psi, e_w, 0.63};
    const double phi = 0.1, g0 = sinclair_jackson(phi), slip = 2.0;
    const double reference = 2.0 / 3.0 * psi * slip * slip / (1 - e_w * e_w);  // Θ_ref, q_w = 0 there
    const auto at = wall(phi, reference, g0, slip, glass);
    CHECK(std::abs(at.energy_flux) < 1e-13 * at.generation);
    CHECK(wall(phi, 0.5 * reference, g0, slip, glass).energy_flux > 0);  // a cold bed is heated by slip
    CHECK(wall(phi, 2.0 * reference, g0, slip, glass).energy_flux < 0);  // a hot bed is cooled
    // the Robin form gives the same reference temperature and the same flux
    const double kappa = 0.7;
    const RobinCondition<double> robin = temperature_robin(at, kappa);
    CHECK(robin.source / robin.coefficient == doctest::Approx(reference).epsilon(1e-13));
    const auto w = wall(phi, 0.02, g0, slip, glass);
    const RobinCondition<double> r = temperature_robin(w, kappa);
    CHECK(kappa * (r.source - r.coefficient * 0.02) == doctest::Approx(w.energy_flux).epsilon(1e-13));
  }
  // Jenkins–Louge: the slip drops out; the sign is that of 21 μ_w²(1 + e_w) − 6(1 − e_w).
  const double phi = 0.2, theta = 0.03, g0 = sinclair_jackson(phi);
  CHECK(JenkinsLougeWall{0.1, 0.9}(phi, theta, g0, 3.0, glass).energy_flux ==
        doctest::Approx(JenkinsLougeWall{0.1, 0.9}(phi, theta, g0, 0.1, glass).energy_flux).epsilon(1e-14));
  CHECK(JenkinsLougeWall{0.1, 0.2}(phi, theta, g0, 1.0, glass).energy_flux < 0);  // 0.252 < 4.8
  CHECK(JenkinsLougeWall{0.5, 0.9}(phi, theta, g0, 1.0, glass).energy_flux > 0);  // 9.975 > 0.6
}

TEST_CASE("Jenkins-Louge wall against MFiX's arrangement of Jenkins and Louge's eqs. 2 and 3") {
  // MFiX (calc_grbdry.f F_HW, bc_theta.f THETA_HW_CW, JENKINS option), written as MFiX groups it:
  // F_2 = tan_Phi_w ρ_s φ (1 + 4ηφg0) Θ/u, HW = (3/8)√(3Θ)(1 − e_w) ρ_s φ (1 + 4ηφg0),
  // CW = tan_Phi_w² (1 + e_w)(21/16)√(3Θ) ρ_s φ (1 + 4ηφg0) Θ, η = (1 + e)/2; MFiX has no slip floor,
  // so u ≫ u_0 here.
  for (const double mu : {0.05, 0.1, 0.4})
    for (const double e_w : {0.2, 0.9})
      for (const double phi : {0.01, 0.2, 0.5})
        for (const double theta : {1e-4, 0.03}) {
          const double slip = 0.7, g0 = sinclair_jackson(phi), eta = (1 + glass.restitution) / 2;
          const double density_factor = glass.density * phi * (1 + 4 * eta * phi * g0);
          const double f2 = mu * density_factor * theta / slip;
          const double hw = 3.0 / 8.0 * std::sqrt(3 * theta) * (1 - e_w) * density_factor;
          const double cw = mu * mu * (1 + e_w) * 21.0 / 16.0 * std::sqrt(3 * theta) * density_factor * theta;
          const auto w = JenkinsLougeWall{mu, e_w}(phi, theta, g0, slip, glass);
          CHECK(w.slip_coefficient == doctest::Approx(f2).epsilon(1e-11));  // (u_0/u)² = 2e-12
          CHECK(w.dissipation_coefficient == doctest::Approx(hw).epsilon(1e-14));
          CHECK(w.generation == doctest::Approx(cw).epsilon(1e-14));
          CHECK(w.energy_flux == doctest::Approx(cw - hw * theta).epsilon(1e-13));
        }
}

TEST_CASE("wall derivatives agree with central finite differences") {
  const double phi = 0.25, theta = 0.04, slip = 0.6, h = 1e-6;
  const auto check = [&](const auto& law) {
    const auto d = law.with_derivatives(phi, theta, sinclair_jackson, slip, glass);
    const auto f = [&](double p, double t, double u) { return law(p, t, sinclair_jackson(p), u, glass).energy_flux; };
    const auto s = [&](double p, double t, double u) { return law(p, t, sinclair_jackson(p), u, glass).shear; };
    CHECK(d.energy_flux.d_solid_fraction ==
          doctest::Approx((f(phi + h, theta, slip) - f(phi - h, theta, slip)) / (2 * h)).epsilon(1e-7));
    CHECK(d.energy_flux.d_granular_temperature ==
          doctest::Approx((f(phi, theta + h, slip) - f(phi, theta - h, slip)) / (2 * h)).epsilon(1e-7));
    CHECK(d.shear.d_wall_slip == doctest::Approx((s(phi, theta, slip + h) - s(phi, theta, slip - h)) / (2 * h)).epsilon(1e-7));
    CHECK(d.shear.d_solid_fraction ==
          doctest::Approx((s(phi + h, theta, slip) - s(phi - h, theta, slip)) / (2 * h)).epsilon(1e-7));
  };
  check(JohnsonJacksonWall{0.01, 0.9, 0.63});
  check(JenkinsLougeWall{0.1, 0.9});
  // Robin forms of dual numbers carry derivatives too (for a host that needs ∂c/∂Θ).
  using D = Dual<double, 1>;
  const auto w = JohnsonJacksonWall{0.01, 0.9, 0.63}(D(phi), D::variable(theta, 0), D(sinclair_jackson(phi)), D(slip),
                                                     glass);
  const RobinCondition<D> robin = velocity_robin(w, D(0.05));
  CHECK(robin.coefficient.derivative[0] == doctest::Approx(robin.coefficient.value / (2 * theta)));  // ∝ √Θ
}

TEST_CASE("checked wall laws name the argument or parameter out of its domain") {
  const JohnsonJacksonWall jj{0.001, 0.2, 0.63};
  const JenkinsLougeWall jl{0.1, 0.9};
  const double g0 = 2.0;
  CHECK_THROWS_WITH_AS(jj.checked(-0.1, 0.01, g0, 1.0, glass), doctest::Contains("'solid_fraction' = -0.1"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(jj.checked(0.1, -0.01, g0, 1.0, glass), doctest::Contains("'granular_temperature'"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(jj.checked(0.1, 0.01, 0.0, 1.0, glass), doctest::Contains("'g0'"), std::domain_error);
  CHECK_THROWS_WITH_AS(jj.checked(0.1, 0.01, g0, -1.0, glass), doctest::Contains("kinetic_theory::JohnsonJacksonWall: argument 'wall_slip' = -1"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(jj.checked(0.1, 0.01, g0, std::nan(""), glass), doctest::Contains("'wall_slip'"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(jj.checked(0.1, 0.01, g0, 1.0, GranularMaterial<double>{5e-4, -1.0, 0.9}),
                       doctest::Contains("'material.density'"), std::domain_error);
  CHECK_THROWS_WITH_AS((JohnsonJacksonWall{1.5, 0.2, 0.63}.checked(0.1, 0.01, g0, 1.0, glass)),
                       doctest::Contains("'specularity' = 1.5"), std::domain_error);
  CHECK_THROWS_WITH_AS((JohnsonJacksonWall{0.001, -0.2, 0.63}.checked(0.1, 0.01, g0, 1.0, glass)),
                       doctest::Contains("'wall_restitution'"), std::domain_error);
  CHECK_THROWS_WITH_AS((JohnsonJacksonWall{0.001, 0.2, 0.0}.checked(0.1, 0.01, g0, 1.0, glass)),
                       doctest::Contains("'max_packing'"), std::domain_error);
  CHECK_THROWS_WITH_AS((JenkinsLougeWall{-0.1, 0.9}.checked(0.1, 0.01, g0, 1.0, glass)),
                       doctest::Contains("kinetic_theory::JenkinsLougeWall: argument 'wall_friction'"), std::domain_error);
  CHECK_THROWS_WITH_AS((JenkinsLougeWall{0.1, 0.9, 0.0}.checked(0.1, 0.01, g0, 1.0, glass)),
                       doctest::Contains("'slip_floor'"), std::domain_error);
  CHECK_THROWS_WITH_AS(jl.checked_with_derivatives(1.0, 0.01, sinclair_jackson, 1.0, glass),
                       doctest::Contains("'solid_fraction' = 1"), std::domain_error);
  CHECK_NOTHROW(jl.checked_with_derivatives(0.3, 0.01, sinclair_jackson, 1.0, glass));
  CHECK_THROWS_WITH_AS(slip_length(1.0, 0.0, fluidbed::checked), doctest::Contains("'shear_viscosity' = 0"),
                       std::domain_error);
  const auto w = jj(0.1, 0.01, g0, 1.0, glass);
  CHECK_THROWS_WITH_AS(velocity_robin(w, -1.0, fluidbed::checked),
                       doctest::Contains("kinetic_theory::velocity_robin: argument 'shear_viscosity'"), std::domain_error);
  CHECK_THROWS_WITH_AS(temperature_robin(w, 0.0, fluidbed::checked), doctest::Contains("'conductivity'"),
                       std::domain_error);
  JohnsonJacksonWall settable = jj;
  CHECK_THROWS_AS(set_parameter_checked(settable, "specularity", 2.0), std::domain_error);
  CHECK(settable.specularity == 0.001);
  set_parameter_checked(settable, "specularity", 0.01);
  CHECK(settable.specularity == 0.01);
}

TEST_CASE("wall boundary conditions are selected by name") {
  CHECK(WallBoundaryConditions::size == 2);
  CHECK(WallBoundaryConditions::names_are_unique());
  const auto jj = WallBoundaryConditions::make("JohnsonJacksonWall");
  const auto& registered = std::get<JohnsonJacksonWall>(jj);
  CHECK(registered.specularity == 0.001);  // seed 001's riser walls
  CHECK(registered.wall_restitution == 0.2);
  CHECK(registered.max_packing == 0.63);
  CHECK(std::holds_alternative<JenkinsLougeWall>(WallBoundaryConditions::make("JenkinsLougeWall")));
  CHECK_THROWS_WITH_AS(WallBoundaryConditions::make("JohnsonJackson"),
                       doctest::Contains("unknown wall boundary condition 'JohnsonJackson'"), std::invalid_argument);
  for (const auto& law : WallBoundaryConditions::all())
    std::visit(
        [](const auto& l) {
          CHECK(!l.reference().empty());
          CHECK(within(l.parameter_domain()));
          const auto w = l(0.1, 0.01, 2.0, 0.5, glass);
          CHECK(w.shear >= 0);
          CHECK(w.generation >= 0);
          CHECK(w.dissipation >= 0);
          CHECK(w.energy_flux == w.generation - w.dissipation);
        },
        law);
}

TEST_CASE("at Θ = 0 the wall laws are 0, and no derivative is NaN") {
  const auto check = [](const auto& law) {
    const auto d = law.with_derivatives(0.1, 0.0, sinclair_jackson, 0.5, glass);
    for (const WallDerivatives<double>& q :
         {d.shear, d.slip_coefficient, d.energy_flux, d.generation, d.dissipation, d.dissipation_coefficient}) {
      CHECK(q.value == 0);
      CHECK(q.d_solid_fraction == 0);
      CHECK(q.d_wall_slip == 0);
      CHECK(!std::isnan(q.d_granular_temperature));  // +∞ where the law is ∝ √Θ (documented)
    }
  };
  check(JohnsonJacksonWall{0.01, 0.9, 0.63});
  check(JenkinsLougeWall{0.1, 0.9});
}
