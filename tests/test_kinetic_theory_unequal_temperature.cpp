// The kinetic theory of a mixture with unequal granular temperatures (Lathouwers & Bellan
// 2001, seed 004). References: the seed 004 binary sand–biomass example and one-class
// reduction, evaluated in double precision from the slides' formulas when the seeds were
// read (6 significant figures); exact identities of the theory (one class, equipartition,
// e = 1, splitting a class, symmetry); the misprints of the slides. The mpmath comparison with
// derivatives is test_kinetic_theory_unequal_temperature_reference.cpp.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <span>
#include <string>
#include <variant>

#include "fluidbed/kinetic_theory.hpp"
#include "kinetic_theory_table_names.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;
using fluidbed::test::relative_difference;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// Seed 004's binary example: sand (class 0) and biomass (class 1), 500 µm each, α̂ = 0.45.
GranularClassesState<double, 2> sand_and_biomass(double biomass_diameter = 500e-6) {
  return {{0.30, 0.15}, {0.01, 0.02}, {500e-6, biomass_diameter}, {2500.0, 500.0}, 0.9};
}

// The value at 6 significant figures, as the reference prints it.
void check_printed(double value, double printed) { CHECK(relative_difference(value, printed) < 5e-6); }

}  // namespace

TEST_CASE("unequal-temperature mixture reproduces the seed 004 binary example") {
  const UnequalTemperatureMixture mixture;
  const auto s = sand_and_biomass();
  const auto ss = mixture.pair_terms(s, 0, 0), sb = mixture.pair_terms(s, 0, 1);
  check_printed(ss.radial_distribution, 14.8968);
  check_printed(sb.radial_distribution, 14.8968);
  check_printed(ss.contact_factor, 1.21627e7);
  check_printed(ss.pressure, 127.368);
  check_printed(ss.viscosity_own, 0.0718596);
  check_printed(ss.viscosity_partner, 0.0718596);
  check_printed(ss.conductivity_own, 0.179649);
  check_printed(ss.conductivity_partner, 0.179649);
  check_printed(ss.energy_sink, 8623.15);  // the slides' γ_ss = −8623.15 W/m³, a source
  check_printed(ss.drag, 5.74877e6);
  check_printed(sb.contact_factor, 2.02712e6);
  check_printed(sb.pressure, 31.8420);
  check_printed(sb.viscosity_own, 0.00733414);
  check_printed(sb.viscosity_partner, 0.0183353);
  check_printed(sb.conductivity_own, 0.0244471);
  check_printed(sb.conductivity_partner, 0.0305589);
  check_printed(sb.energy_sink, 18482.0);
  check_printed(sb.drag, 1.17346e6);

  const auto unequal = sand_and_biomass(1000e-6);
  check_printed(mixture.pair_terms(unequal, 0, 0).radial_distribution, 12.4380);
  check_printed(mixture.pair_terms(unequal, 0, 1).radial_distribution, 16.6555);
  check_printed(mixture.pair_terms(unequal, 1, 1).radial_distribution, 26.8821);

  // The assembled quantities are the sums of the pair terms.
  const auto v = mixture(s);
  CHECK(relative_difference(v.pressure[0], 0.30 * 2500 * 0.01 + ss.pressure + sb.pressure) < 4 * eps);
  CHECK(relative_difference(v.shear_viscosity[0][0], ss.viscosity_own + ss.viscosity_partner + sb.viscosity_own) <
        4 * eps);
  CHECK(v.shear_viscosity[0][1] == sb.viscosity_partner);
  CHECK(relative_difference(v.bulk_viscosity[0][1], 5.0 / 3 * sb.viscosity_partner) < 2 * eps);
  CHECK(v.conductivity[0][1] == sb.conductivity_partner);
  CHECK(relative_difference(v.dissipation[0], ss.energy_sink + sb.energy_sink) < 4 * eps);
  CHECK(v.drag[0][0] == 0);
  CHECK(v.drag[0][1] == sb.drag);
}

TEST_CASE("one class of the unequal-temperature mixture is Lun, Gidaspow and Lun exactly") {
  const UnequalTemperatureMixture mixture;
  const LathouwersBellan one_class_rdf{0.64};
  for (const double phi : {1e-6, 0.05, 0.30, 0.55, 0.62})
    for (const double theta : {1e-6, 0.01, 3.0}) {
      CAPTURE(phi);
      CAPTURE(theta);
      const GranularMaterial<double> m{500e-6, 2500.0, 0.9};
      const GranularClassesState<double, 1> s{{phi}, {theta}, {m.diameter}, {m.density}, m.restitution};
      const auto v = mixture(s);
      const double g0 = one_class_rdf(phi);
      CHECK(relative_difference(v.radial_distribution[0][0], g0) < 8 * eps);
      CHECK(relative_difference(v.pressure[0], LunPressure{}(phi, theta, g0, m)) < 16 * eps);
      CHECK(relative_difference(v.shear_viscosity[0][0], GidaspowViscosity{}.collisional(phi, theta, g0, m)) <
            16 * eps);
      CHECK(relative_difference(v.bulk_viscosity[0][0], LunBulkViscosity{}(phi, theta, g0, m)) < 16 * eps);
      CHECK(relative_difference(v.conductivity[0][0], GidaspowConductivity{}.collisional(phi, theta, g0, m)) <
            16 * eps);
      CHECK(relative_difference(v.dissipation[0], LunDissipation{}(phi, theta, g0, m)) < 16 * eps);
    }
  // Seed 004's monodisperse table (6 significant figures).
  const GranularClassesState<double, 1> s{{0.55}, {0.01}, {500e-6}, {2500.0}, 0.9};
  const auto v = mixture(s);
  check_printed(v.radial_distribution[0][0], 103.218);
  check_printed(v.pressure[0] - 0.55 * 2500 * 0.01, 2966.23);
  check_printed(v.shear_viscosity[0][0], 3.34704);
  check_printed(v.bulk_viscosity[0][0], 5.57839);
  check_printed(v.conductivity[0][0], 8.36759);
  check_printed(v.dissipation[0], 200822);
  check_printed(mixture.pair_terms(s, 0, 0).contact_factor, 2.83254e8);
}

TEST_CASE("a class split into identical halves changes nothing") {
  const UnequalTemperatureMixture mixture;
  const GranularClassesState<double, 1> whole{{0.4}, {0.02}, {300e-6}, {2600.0}, 0.85};
  const GranularClassesState<double, 2> halves{{0.1, 0.3}, {0.02, 0.02}, {300e-6, 300e-6}, {2600.0, 2600.0}, 0.85};
  const auto w = mixture(whole);
  const auto h = mixture(halves);
  CHECK(relative_difference(h.pressure[0] + h.pressure[1], w.pressure[0]) < 8 * eps);
  // Each half carries its share: p_i/α_i, and every row sum of μ_ij and κ_ij per unit α_i.
  CHECK(relative_difference(h.pressure[0] / 0.1, w.pressure[0] / 0.4) < 8 * eps);
  for (std::size_t i = 0; i < 2; ++i) {
    const double share = halves.fractions[i] / 0.4;
    CHECK(relative_difference(h.shear_viscosity[i][0] + h.shear_viscosity[i][1], share * w.shear_viscosity[0][0]) <
          16 * eps);
    CHECK(relative_difference(h.conductivity[i][0] + h.conductivity[i][1], share * w.conductivity[0][0]) < 16 * eps);
    CHECK(relative_difference(h.dissipation[i], share * w.dissipation[0]) < 16 * eps);
  }
}

TEST_CASE("at equipartition the unequal-temperature mixture is the Enskog mixture") {
  // Equal temperatures in the sense of the kinetic theory of mixtures: equal mean energy per
  // particle, T = m_i Θ_i (equipartition, Jenkins & Mancini 1989). Then the collisional
  // pressure is the hard-sphere mixture's (π/3)(1 + e) T Σ_ik n_i n_k σ_ik³ h_ik, and the
  // exchange only dissipates: the elastic transfer 2(M_i Θ_i − M_k Θ_k) vanishes.
  const UnequalTemperatureMixture mixture{Mansoori{}};
  const std::array<double, 3> d{200e-6, 350e-6, 600e-6}, rho{2500.0, 1200.0, 7800.0}, alpha{0.12, 0.08, 0.15};
  const double energy = 2e-12;  // T [J]
  GranularClassesState<double, 3> s{alpha, {}, d, rho, 0.8};
  std::array<double, 3> n{}, mass{};
  for (std::size_t i = 0; i < 3; ++i) {
    mass[i] = rho[i] * std::numbers::pi * d[i] * d[i] * d[i] / 6;
    n[i] = alpha[i] * rho[i] / mass[i];
    s.temperatures[i] = energy / mass[i];
  }
  const auto v = mixture(s);
  double total = 0, enskog = 0, dissipation = 0, inelastic = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    total += v.pressure[i];
    enskog += n[i] * energy;
    dissipation += v.dissipation[i];
    for (std::size_t k = 0; k < 3; ++k) {
      const double sigma = (d[i] + d[k]) / 2;
      enskog += std::numbers::pi / 3 * (1 + s.restitution) * energy * n[i] * n[k] * sigma * sigma * sigma *
                v.radial_distribution[i][k];
      // The inelastic part alone: 2√(2π) F_ik Σ^(1/2) M_k (1 − e) Σ_ik.
      const auto t = mixture.pair_terms(s, i, k);
      const double sum = s.temperatures[i] + s.temperatures[k];
      inelastic += 2 * std::sqrt(2 * std::numbers::pi) * t.contact_factor * std::sqrt(sum) * mass[k] /
                   (mass[i] + mass[k]) * (1 - s.restitution) * sum;
      CHECK(relative_difference(t.energy_sink, 2 * std::sqrt(2 * std::numbers::pi) * t.contact_factor * std::sqrt(sum) *
                                                   mass[k] / (mass[i] + mass[k]) * (1 - s.restitution) * sum) <
            1e-12);
    }
  }
  CHECK(relative_difference(total, enskog) < 16 * eps);
  CHECK(relative_difference(dissipation, inelastic) < 16 * eps);
}

TEST_CASE("collisions conserve granular energy as e tends to 1") {
  const UnequalTemperatureMixture mixture;
  GranularClassesState<double, 4> s{
      {0.05, 0.2, 0.1, 0.15}, {1e-3, 0.4, 2e-2, 5e-5}, {80e-6, 250e-6, 1e-3, 400e-6}, {1500.0, 2500.0, 900.0, 7000.0}, 1.0};
  auto v = mixture(s);
  double total = 0, magnitude = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    total += v.dissipation[i];
    magnitude += std::abs(v.dissipation[i]);
  }
  CHECK(magnitude > 0);  // energy does move between the classes
  CHECK(std::abs(total) < 16 * eps * magnitude);
  // The net loss is (1 − e)-proportional: halving 1 − e halves it.
  s.restitution = 0.98;
  const auto loss = [&] {
    const auto w = mixture(s);
    return w.dissipation[0] + w.dissipation[1] + w.dissipation[2] + w.dissipation[3];
  };
  const double loss_002 = loss();
  s.restitution = 0.99;
  const double loss_001 = loss();
  CHECK(loss_002 > 0);
  // (1 + e)(1 − e) scaling: the contact factor carries 1 + e.
  CHECK(relative_difference(loss_001 / loss_002, (1.99 * 0.01) / (1.98 * 0.02)) < 1e-12);
  // The hotter class gives energy to the colder one at e = 1 (mass-weighted temperatures).
  s.restitution = 1.0;
  v = mixture(s);
  CHECK(v.dissipation[1] > 0);
}

TEST_CASE("the solid-solid interaction is antisymmetric and vanishes between identical classes") {
  const UnequalTemperatureMixture mixture;
  const GranularClassesState<double, 3> s{{0.1, 0.2, 0.15}, {0.01, 0.03, 0.002}, {150e-6, 600e-6, 300e-6},
                                          {2500.0, 1800.0, 2500.0}, 0.9};
  const auto v = mixture(s);
  const std::array<Vector3<double>, 3> u{{{0.1, 0.0, -0.2}, {0.3, 0.1, 0.0}, {-0.1, 0.05, 0.2}}};
  const std::array<Vector3<double>, 3> grad_ln_n{{{1.0, -2.0, 0.5}, {0.0, 3.0, -1.0}, {2.0, 0.5, 0.0}}};
  Vector3<double> sum{0, 0, 0}, scale{0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto f = collisional_force(v, i, u, grad_ln_n);
    for (int c = 0; c < 3; ++c) {
      sum[c] += f[c];
      scale[c] += std::abs(f[c]);
    }
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(v.drag[i][k] == v.drag[k][i]);
      CHECK(v.segregation[i][k] == v.segregation[k][i]);
    }
  }
  for (int c = 0; c < 3; ++c) CHECK(std::abs(sum[c]) < 8 * eps * scale[c]);
  // Identical classes, moving together with proportional number densities: no force.
  const GranularClassesState<double, 2> twins{{0.1, 0.25}, {0.01, 0.01}, {300e-6, 300e-6}, {2500.0, 2500.0}, 0.9};
  const auto w = mixture(twins);
  const std::array<Vector3<double>, 2> same_u{{{0.2, 0.1, 0.0}, {0.2, 0.1, 0.0}}};
  const std::array<Vector3<double>, 2> same_gradient{{{3.0, -1.0, 2.0}, {3.0, -1.0, 2.0}}};
  CHECK(w.drag[0][1] > 0);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto f = collisional_force(w, i, same_u, same_gradient);
    for (int c = 0; c < 3; ++c) CHECK(f[c] == 0);
  }
}

TEST_CASE("the slides' misprints are caught") {
  const UnequalTemperatureMixture mixture;
  const auto s = sand_and_biomass();
  const auto v = mixture(s);
  // Heat flux: q_i = −Σ_j κ_ij ∇Θ_j with κ_ij ≥ 0 conducts down the gradient; the slides print
  // q_i = +Σ_k(...), which would carry granular energy from cold to hot: in a uniform
  // gradient the flux must oppose it.
  const double gradient = 1.0;
  for (std::size_t i = 0; i < 2; ++i) {
    double flux = 0;
    for (std::size_t j = 0; j < 2; ++j) {
      CHECK(v.conductivity[i][j] > 0);
      flux -= v.conductivity[i][j] * gradient;
    }
    CHECK(flux * gradient < 0);
  }
  // h_ik: the slides' third term 8 r² ξ/(1 − x)² (r = σ_iσ_k/(σ_i+σ_k) in radii, ξ = (2π/3)Σ n σ²)
  // is not the Mansoori term 8 r² ξ²/(1 − x)³ the one-class limit needs (Carnahan–Starling at
  // x = a): it misses the seed's own h = 14.8968 by far.
  const double x = 0.45 / 0.64, radius = 250e-6, r = radius / 2;
  const double n_total = 0.45 / (std::numbers::pi * 500e-6 * 500e-6 * 500e-6 / 6);
  const double xi = 2 * std::numbers::pi / 3 * n_total * radius * radius;
  const double printed = 1 / (1 - x) + 6 * r * xi / ((1 - x) * (1 - x)) + 8 * r * r * xi / ((1 - x) * (1 - x));
  const double corrected =
      1 / (1 - x) + 6 * r * xi / ((1 - x) * (1 - x)) + 8 * r * r * xi * xi / ((1 - x) * (1 - x) * (1 - x));
  CHECK(relative_difference(corrected, v.radial_distribution[0][1]) < 8 * eps);
  CHECK(relative_difference(printed, v.radial_distribution[0][1]) > 0.1);
}

TEST_CASE("unequal-temperature mixture derivatives, float and long double, and the checked form") {
  const UnequalTemperatureMixture mixture;
  const auto s = sand_and_biomass(800e-6);
  const auto d = mixture.with_derivatives(s);
  const auto v = mixture(s);
  // Values are the hot path's; central differences confirm the derivative mapping (α_m, Θ_m).
  for (std::size_t m = 0; m < 2; ++m) {
    for (const bool temperature : {false, true}) {
      auto up = s, down = s;
      double& x_up = temperature ? up.temperatures[m] : up.fractions[m];
      double& x_down = temperature ? down.temperatures[m] : down.fractions[m];
      const double h = 1e-6 * x_up;
      x_up += h;
      x_down -= h;
      const auto vu = mixture(up), vd = mixture(down);
      for (std::size_t i = 0; i < 2; ++i) {
        const auto& di = d.pressure[i];
        CHECK(di.value == doctest::Approx(v.pressure[i]).epsilon(1e-15));
        const double slope = temperature ? di.d_temperatures[m] : di.d_fractions[m];
        CHECK(slope == doctest::Approx((vu.pressure[i] - vd.pressure[i]) / (2 * h)).epsilon(1e-7));
        const auto& ki = d.conductivity[i][1 - i];
        const double k_slope = temperature ? ki.d_temperatures[m] : ki.d_fractions[m];
        CHECK(k_slope ==
              doctest::Approx((vu.conductivity[i][1 - i] - vd.conductivity[i][1 - i]) / (2 * h)).epsilon(1e-7));
        const auto& gi = d.dissipation[i];
        const double g_slope = temperature ? gi.d_temperatures[m] : gi.d_fractions[m];
        CHECK(g_slope == doctest::Approx((vu.dissipation[i] - vd.dissipation[i]) / (2 * h)).epsilon(1e-6));
      }
    }
  }
  // Float and long double agree with double to their precision.
  const GranularClassesState<float, 2> sf{{0.30f, 0.15f}, {0.01f, 0.02f}, {500e-6f, 800e-6f}, {2500.0f, 500.0f}, 0.9f};
  const GranularClassesState<long double, 2> sl{
      {0.30L, 0.15L}, {0.01L, 0.02L}, {500e-6L, 800e-6L}, {2500.0L, 500.0L}, 0.9L};
  const auto vf = mixture(sf);
  const auto vl = mixture(sl);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(relative_difference(double(vf.pressure[i]), v.pressure[i]) < 1e-5);
    CHECK(relative_difference(double(vl.dissipation[i]), v.dissipation[i]) < 1e-14);
  }
  // Checked: names the argument.
  auto bad = s;
  bad.temperatures[1] = 0;
  const auto message = [&](const auto& state) {
    try {
      (void)mixture.checked(state);
    } catch (const std::domain_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message(bad).find("state.temperatures[1]") != std::string::npos);
  bad = s;
  bad.fractions[0] = 0.9;
  CHECK(message(bad).find("sum of fractions") != std::string::npos);
  bad = s;
  bad.restitution = 1.5;
  CHECK(message(bad).find("state.restitution") != std::string::npos);
  CHECK(message(s).empty());
  CHECK_THROWS_AS((void)mixture.checked_with_derivatives(bad), std::domain_error);
  // An absent class contributes nothing (it keeps its temperature).
  auto absent = s;
  absent.fractions[1] = 0;
  const auto va = mixture(absent);
  CHECK(va.pressure[1] == 0);
  CHECK(va.dissipation[1] == 0);
  CHECK(va.shear_viscosity[0][1] == 0);
  CHECK(mixture.name() == "UnequalTemperatureMixture");
  CHECK(mixture.reference().find("Lathouwers") != std::string_view::npos);
}

TEST_CASE("the mixture's radial distribution is chosen at run time from the registry") {
  const auto s = sand_and_biomass(900e-6);
  for (const auto& law : MixtureRadialDistributions::all())
    std::visit(
        [&](const auto& rdf) {
          CAPTURE(rdf.name());
          const UnequalTemperatureMixture mixture{rdf};
          const auto v = mixture(s);
          for (std::size_t i = 0; i < 2; ++i)
            for (std::size_t k = 0; k < 2; ++k)
              CHECK(v.radial_distribution[i][k] ==
                    rdf(std::span<const double>(s.fractions), std::span<const double>(s.diameters), i, k));
        },
        law);
  const auto chosen = MixtureRadialDistributions::make("Mansoori");
  const double h = std::visit([&](const auto& rdf) { return UnequalTemperatureMixture{rdf}(s).radial_distribution[0][1]; },
                              chosen);
  CHECK(h == Mansoori{}(std::span<const double>(s.fractions), std::span<const double>(s.diameters), 0, 1));
}

TEST_CASE("the stress power of a class in simple shear and in compression") {
  const UnequalTemperatureMixture mixture;
  const auto s = sand_and_biomass(700e-6);
  const auto v = mixture(s);
  // Simple shear u_x = γ̇ y of both classes: (−p I + τ_i):∇u_i = (μ_i0 + μ_i1) γ̇², class i's
  // stress responding to both classes' shear.
  const double rate = 3.0;
  std::array<std::array<Vector3<double>, 3>, 2> shear{};
  for (auto& g : shear) g[1][0] = rate;  // ∂u_x/∂y
  for (std::size_t i = 0; i < 2; ++i)
    CHECK(relative_difference(stress_power(v, i, shear),
                              (v.shear_viscosity[i][0] + v.shear_viscosity[i][1]) * rate * rate) < 4 * eps);
  // Only class 1 shears: class 0 is stressed (2 μ_01 D_1) but does not deform, so gains nothing.
  std::array<std::array<Vector3<double>, 3>, 2> other{};
  other[1][1][0] = rate;
  CHECK(stress_power(v, 0, other) == 0);
  // Isotropic compression ∇·u_i = −c of class 0 alone: −p_0 ∇·u_0 + λ_00 (∇·u_0)².
  std::array<std::array<Vector3<double>, 3>, 2> compression{};
  const double c = 0.6;
  for (int a = 0; a < 3; ++a) compression[0][a][a] = -c / 3;
  CHECK(relative_difference(stress_power(v, 0, compression), v.pressure[0] * c + v.bulk_viscosity[0][0] * c * c) <
        8 * eps);
}
