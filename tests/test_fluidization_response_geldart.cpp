// The response time of an expanding bed (seed 000 eqs. 4.1–4.5) and Geldart's powder groups
// (Geldart 1973; seed 001 §2.3): the seeds' worked numbers, exact identities of eq. 4.1, and
// representative powders on either side of each boundary.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "fluidbed/fluidization/bed_expansion.hpp"
#include "fluidbed/fluidization/geldart.hpp"

using namespace fluidbed;
using fluidization::ExpansionStep;
using fluidization::GeldartGroup;

TEST_CASE("expansion response time: seed 000 eqs. 4.4 and 4.5") {
  // Eq. 4.4, the Richardson & Zaki (1954) system from minimum fluidization: 3 (0.39 − 0.30)/(4.70e-4 −
  // 1.30e-4) = 794.1 s, "≈ 800 s" in the seed.
  const ExpansionStep<double> liquid{0.30, 1.30e-4, 0.39, 4.70e-4};
  CHECK(fluidization::expansion_time_constant(liquid) == doctest::Approx(0.09 / 3.40e-4).epsilon(1e-14));
  CHECK(fluidization::expansion_response_time(liquid) == doctest::Approx(794.1176470588235).epsilon(1e-14));
  CHECK(std::abs(fluidization::expansion_response_time(liquid) - 800.0) < 10.0);
  // Eq. 4.5, the gas-fluidized bed of the time-step study: 3 (0.45 − 0.30)/(5.77e-2 − 8.73e-3) = 9.19 s, "≈ 9 s".
  const ExpansionStep<double> gas{0.30, 8.73e-3, 0.45, 5.77e-2};
  CHECK(fluidization::expansion_response_time(gas) == doctest::Approx(0.45 / 4.897e-2).epsilon(1e-14));
  CHECK(std::abs(fluidization::expansion_response_time(gas) - 9.0) < 0.25);
  // Eq. 4.3: from rest (u₁ = 0, h₁ = h₀), τ = (h − h₀)/u, the approximation for u_mf ≪ u: 1.7 % above eq.
  // 4.2's τ for the gas bed, where u_mf/u = 0.15.
  const ExpansionStep<double> from_rest{0.30, 0.0, 0.45, 5.77e-2};
  CHECK(fluidization::expansion_time_constant(from_rest) == doctest::Approx(0.15 / 5.77e-2).epsilon(1e-15));
  CHECK(fluidization::expansion_time_constant(from_rest) < fluidization::expansion_time_constant(gas));
}

TEST_CASE("expanding bed height: eq. 4.1 starts at h1 with slope u2 - u1, covers 95 % in 3 tau, tends to h2") {
  const ExpansionStep<double> step{0.454, 5.28e-3, 0.908, 1.50e-2};  // seed 000 §4.5.2's velocities
  const double tau = fluidization::expansion_time_constant(step);
  CHECK(fluidization::expanding_bed_height(step, 0.0) == 0.454);
  // h'(0) = u₂ − u₁ (eq. 4.13), by a forward difference over a small t.
  const double h = 1e-3;
  const double slope =
      (fluidization::expanding_bed_height(step, 2 * h) - fluidization::expanding_bed_height(step, 0.0)) / (2 * h);
  CHECK(slope == doctest::Approx(1.50e-2 - 5.28e-3).epsilon(1e-4));
  // After τ: 1 − 1/e of the expansion; after t_e = 3τ: 1 − e⁻³ = 95.02 % ("95 % of the variation").
  const auto fraction_done = [&](double t) { return (fluidization::expanding_bed_height(step, t) - 0.454) / 0.454; };
  CHECK(fraction_done(tau) == doctest::Approx(1 - std::exp(-1.0)).epsilon(1e-14));
  CHECK(fraction_done(fluidization::expansion_response_time(step)) == doctest::Approx(0.950212931632136).epsilon(1e-14));
  CHECK(fluidization::expanding_bed_height(step, 1e6) == 0.908);
  // Each t: h₂ − h decays by e^(−Δt/τ) over Δt.
  const double gap_10 = 0.908 - fluidization::expanding_bed_height(step, 10.0);
  const double gap_30 = 0.908 - fluidization::expanding_bed_height(step, 30.0);
  CHECK(gap_30 / gap_10 == doctest::Approx(std::exp(-20.0 / tau)).epsilon(1e-12));
}

TEST_CASE("expansion response time in float and long double, and the checked entry points") {
  const ExpansionStep<float> f{0.30f, 1.30e-4f, 0.39f, 4.70e-4f};
  const ExpansionStep<long double> l{0.30L, 1.30e-4L, 0.39L, 4.70e-4L};
  CHECK(double(fluidization::expansion_response_time(f)) == doctest::Approx(794.1176470588235).epsilon(1e-5));
  CHECK(double(fluidization::expansion_response_time(l)) == doctest::Approx(794.1176470588235).epsilon(1e-15));
  CHECK(double(fluidization::expanding_bed_height(f, 100.0f)) ==
        doctest::Approx(0.39 - 0.09 * std::exp(-100.0 / 264.7058823529412)).epsilon(1e-5));
  // A contraction (h₂ < h₁, u₂ < u₁) is not this law's: the checked path names the argument.
  const ExpansionStep<double> contraction{0.908, 1.50e-2, 0.363, 2.72e-3};
  CHECK_THROWS_WITH_AS(fluidization::expansion_response_time(contraction, fluidbed::checked),
                       doctest::Contains("'final_height' = 0.36299999999999999"), std::domain_error);
  CHECK_THROWS_WITH_AS(fluidization::expanding_bed_height(ExpansionStep<double>{0.3, 0.0, 0.45, 0.05}, -1.0,
                                                          fluidbed::checked),
                       doctest::Contains("'time' = -1"), std::domain_error);
}

TEST_CASE("Geldart groups of representative powders in air") {
  const double air = 1.2;
  CHECK(fluidization::geldart_group(1500.0, air, 70e-6) == GeldartGroup::A);   // FCC catalyst
  CHECK(fluidization::geldart_group(2650.0, air, 500e-6) == GeldartGroup::B);  // sand
  CHECK(fluidization::geldart_group(1450.0, air, 20e-6) == GeldartGroup::C);   // flour
  CHECK(fluidization::geldart_group(2500.0, air, 2e-3) == GeldartGroup::D);    // 2 mm grains
  // Seed 001's glass beads (2480 kg m⁻³, 206–541 µm): group B, as the thesis says.
  for (double d : {206e-6, 255e-6, 416e-6, 541e-6}) CHECK(fluidization::geldart_group(2480.0, air, d) == GeldartGroup::B);
  // Sand turns D near 620 µm (Δρ d² = 10⁻³ kg m⁻¹ at Δρ = 2600 kg m⁻³).
  CHECK(fluidization::geldart_group(2601.2, air, 600e-6) == GeldartGroup::B);
  CHECK(fluidization::geldart_group(2601.2, air, 640e-6) == GeldartGroup::D);
  CHECK(fluidization::name(GeldartGroup::A) == "A");
  CHECK(fluidization::name(GeldartGroup::B) == "B");
  CHECK(fluidization::name(GeldartGroup::C) == "C");
  CHECK(fluidization::name(GeldartGroup::D) == "D");
}

TEST_CASE("Geldart groups on and either side of each boundary") {
  // Δρ = 1000 kg m⁻³ exactly (ρ_g = 1): A/B at d = 225 µm, B/D at d = 1 mm, C/A at 30 µm.
  const double rho_p = 1001.0, rho_g = 1.0;
  const double above = 1 + 1e-9, below = 1 - 1e-9;
  CHECK(fluidization::geldart_group(rho_p, rho_g, 30e-6) == GeldartGroup::A);  // on the line: the coarser group
  CHECK(fluidization::geldart_group(rho_p, rho_g, std::nextafter(30e-6, 0.0)) == GeldartGroup::C);
  CHECK(fluidization::geldart_group(rho_p, rho_g, 225e-6 * below) == GeldartGroup::A);
  CHECK(fluidization::geldart_group(rho_p, rho_g, 225e-6 * above) == GeldartGroup::B);
  CHECK(fluidization::geldart_group(rho_p, rho_g, 1e-3 * below) == GeldartGroup::B);
  CHECK(fluidization::geldart_group(rho_p, rho_g, 1e-3 * above) == GeldartGroup::D);
  // The gas density enters only through Δρ = ρ_p − ρ_g: at 20 bar (ρ_g ≈ 24 kg m⁻³) a powder near the
  // A/B line moves across it.
  CHECK(fluidization::geldart_group(1001.0, 1.0, 226e-6) == GeldartGroup::B);
  CHECK(fluidization::geldart_group(1001.0, 24.0, 226e-6) == GeldartGroup::A);
  // Seed 001's group-B ranges (1400–4000 kg m⁻³, 40–500 µm) are loose descriptions, not the
  // boundaries: their corner at 4000 kg m⁻³ and 40 µm is group A on Geldart's A/B line
  // (Δρ d = 0.16 < 0.225 kg m⁻²), and a rectangle read from the seed would call it B.
  CHECK(fluidization::geldart_group(4000.0, 1.2, 40e-6) == GeldartGroup::A);
}

TEST_CASE("Geldart groups in float and long double, and the checked entry point") {
  CHECK(fluidization::geldart_group(1500.0f, 1.2f, 70e-6f) == GeldartGroup::A);
  CHECK(fluidization::geldart_group(2500.0L, 1.2L, 2e-3L) == GeldartGroup::D);
  static_assert(fluidization::geldart_group(2650.0, 1.2, 500e-6) == GeldartGroup::B);
  CHECK_THROWS_WITH_AS(fluidization::geldart_group(1.0, 1.2, 1e-4, fluidbed::checked),
                       doctest::Contains("'particle_density' = 1"), std::domain_error);
  CHECK_THROWS_WITH_AS(fluidization::geldart_group(2500.0, 1.2, 0.0, fluidbed::checked),
                       doctest::Contains("'diameter' = 0"), std::domain_error);
  CHECK_THROWS_WITH_AS(fluidization::geldart_group(2500.0, std::numeric_limits<double>::quiet_NaN(), 1e-4,
                                                   fluidbed::checked),
                       doctest::Contains("'gas_density' = nan"), std::domain_error);
}
