// Settling and homogeneous expansion: Richardson–Zaki exponents, terminal velocities,
// the equilibrium voidage of every drag law, minimum fluidization. Reference values come
// from the independent mpmath generator (tests/reference/settling_reference.py), from an
// independent double-precision evaluation of seed 000's formulas made when the thesis was read
// (printed digits, half a unit), from seed 000 Table 4.4, from exact limits, and from the
// identity Mazzei–Lettieri ≡ Richardson–Zaki.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "../examples/seed000_table_4_4.hpp"
#include "fluidbed/core/dual.hpp"
#include "fluidbed/drag/any_drag_law.hpp"
#include "fluidbed/drag/mazzei_lettieri.hpp"
#include "fluidbed/fluidization.hpp"
#include "fluidbed/settling.hpp"
#include "fluidbed/single_particle.hpp"
#include "reference_table.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using namespace fluidbed::settling;

namespace {

const Fluid<double> water{.density = 998.0, .viscosity = 1.0e-3};
const Fluid<double> air_example{.density = 1.18, .viscosity = 1.81e-5};  // seed 000 §4.3.3 gas example
const Particles<double> fcc_example{.density = 1210.0, .diameter = 137e-6};
constexpr double g = 9.81;

const drag::ConstantExponentDrag wen_yu = drag::ConstantExponentDrag::wen_yu_1966();

// The particles of `system` (1-based) of seed 000 Table 4.3, with system 3 at 5.21 mm.
const seed000::System& system_of(int number) { return seed000::table_4_3.at(static_cast<std::size_t>(number - 1)); }

double relative_difference(double a, double b) { return std::abs(a - b) / std::abs(b); }

// The diameter at which particles of density ρ_p in `fluid` have the Archimedes number Ar.
double diameter_for_archimedes(double ar, const Fluid<double>& fluid, double particle_density) {
  return std::cbrt(ar * fluid.viscosity * fluid.viscosity / (fluid.density * (particle_density - fluid.density) * g));
}

}  // namespace

// ============================================================================ reference CSV

TEST_CASE("every settling quantity agrees with the independent mpmath reference (settling_reference.csv)") {
  const test::ReferenceTable table("settling_reference.csv");
  REQUIRE(table.size() > 100);
  std::set<std::string> seen;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string quantity = table.text(row, "quantity");
    const double p1 = table.number(row, "param1");
    const double p2 = table.number(row, "param2");
    const double p3 = table.number(row, "param3");
    const double p4 = table.number(row, "param4");
    const double expected = table.number(row, "value");
    seen.insert(quantity);
    INFO(quantity << " (" << p1 << ", " << p2 << ", " << p3 << ", " << p4 << ")");
    const Fluid<double> fluid{.density = p1, .viscosity = p2};
    const Particles<double> particles{.density = p3, .diameter = p4};
    // Closed forms to 1e-13, root solves to 1e-11 (relative).
    if (quantity == "rz_exponent_mazzei")
      CHECK(settling::MazzeiExponent{}(p1) == doctest::Approx(expected).epsilon(1e-14));
    else if (quantity == "rz_exponent_rowe1987")
      CHECK(settling::RoweExponent{}(p1) == doctest::Approx(expected).epsilon(1e-14));
    else if (quantity == "rz_exponent_garside_aldibouni1977")
      CHECK(settling::GarsideAlDibouniExponent{}(p1) == doctest::Approx(expected).epsilon(1e-14));
    else if (quantity == "rz_exponent_khan_richardson1989")
      CHECK(settling::KhanRichardsonExponent{p2}(p1) == doctest::Approx(expected).epsilon(1e-14));
    else if (quantity == "rz_exponent_richardson_zaki1954")
      CHECK(settling::RichardsonZaki1954Exponent{p2}(p1) == doctest::Approx(expected).epsilon(1e-14));
    else if (quantity == "terminal_velocity_stokes")
      CHECK(single_particle::StokesTerminalVelocity{}(fluid, particles) == doctest::Approx(expected).epsilon(1e-13));
    else if (quantity == "terminal_velocity_newton")
      CHECK(single_particle::NewtonTerminalVelocity{}(fluid, particles) == doctest::Approx(expected).epsilon(1e-13));
    else if (quantity == "terminal_velocity_dallavalle")
      CHECK(single_particle::DallavalleTerminalVelocity{}(fluid, particles) ==
            doctest::Approx(expected).epsilon(1e-13));
    else if (quantity == "terminal_velocity_schillernaumann")
      CHECK(single_particle::SchillerNaumannTerminalVelocity{}(fluid, particles) ==
            doctest::Approx(expected).epsilon(1e-12));
    else if (quantity == "umf_ergun")
      CHECK(fluidization::ErgunMinimumFluidization{0.4}(fluid, particles) == doctest::Approx(expected).epsilon(1e-13));
    else if (quantity == "umf_wenyu1966")
      CHECK(fluidization::WenYuMinimumFluidization{}(fluid, particles) == doctest::Approx(expected).epsilon(1e-13));
    else if (quantity == "remf_ergun")
      CHECK(fluidization::ErgunMinimumFluidization{p2}.reynolds(p1) == doctest::Approx(expected).epsilon(1e-13));
    else if (quantity == "remf_wenyu1966")
      CHECK(fluidization::WenYuMinimumFluidization{}.reynolds(p1) == doctest::Approx(expected).epsilon(1e-13));
    else if (quantity.starts_with("expansion_")) {
      const seed000::System& system = system_of(static_cast<int>(p1));
      const std::string law_name = quantity.substr(std::string("expansion_").size());
      std::optional<double> voidage;
      if (law_name == "RichardsonZaki") {
        voidage = fluidization::richardson_zaki_equilibrium_voidage(p2, system.fluid, system.particles);
      } else {
        const auto law = drag::find_drag_law(law_name);
        REQUIRE(law.has_value());
        voidage = fluidization::equilibrium_voidage(*law, p2, system.fluid, system.particles);
      }
      REQUIRE(voidage.has_value());
      CHECK(*voidage == doctest::Approx(expected).epsilon(1e-12));
    } else {
      FAIL("unknown quantity " << quantity);
    }
  }
  for (const char* quantity :
       {"rz_exponent_mazzei", "rz_exponent_rowe1987", "rz_exponent_garside_aldibouni1977",
        "rz_exponent_khan_richardson1989", "rz_exponent_richardson_zaki1954", "terminal_velocity_stokes",
        "terminal_velocity_newton", "terminal_velocity_dallavalle", "terminal_velocity_schillernaumann",
        "expansion_RichardsonZaki", "expansion_MazzeiLettieri", "expansion_WenYu1966", "expansion_Ergun", "umf_ergun",
        "umf_wenyu1966", "remf_ergun", "remf_wenyu1966"}) {
    INFO(quantity);
    CHECK(seen.count(quantity) == 1);
  }
}

// ============================================================================ exponents

TEST_CASE("eq. 3.24: independently evaluated values, and the limits 4.8 / 2.4") {
  // The independent evaluation of eq. 3.24; tolerances: half a unit in the last printed digit.
  CHECK(settling::MazzeiExponent{}(1e-6) == doctest::Approx(4.79999).epsilon(1e-6));
  CHECK(settling::MazzeiExponent{}(0.1) == doctest::Approx(4.727566).epsilon(2.5e-7));
  CHECK(settling::MazzeiExponent{}(1.0) == doctest::Approx(4.442553191).epsilon(1e-10));
  CHECK(settling::MazzeiExponent{}(10.0) == doctest::Approx(3.609618).epsilon(2.5e-7));
  CHECK(settling::MazzeiExponent{}(100.0) == doctest::Approx(2.767310).epsilon(2.5e-7));
  CHECK(settling::MazzeiExponent{}(1000.0) == doctest::Approx(2.474720).epsilon(2.5e-7));
  CHECK(settling::MazzeiExponent{}(1e4) == doctest::Approx(2.413636).epsilon(2.5e-7));
  CHECK(settling::MazzeiExponent{}(1e8) == doctest::Approx(2.400014).epsilon(2.5e-7));
  CHECK(settling::MazzeiExponent{}(0.0) == 4.8);
  CHECK(settling::MazzeiExponent{}(1e40) == doctest::Approx(2.4).epsilon(1e-15));
  // As printed: (4.8 + 2.4·0.175 Re^¾)/(1 + 0.175 Re^¾).
  for (double re : {1e-3, 0.7, 13.0, 4e3}) {
    const double x = 0.175 * std::pow(re, 0.75);
    CHECK(settling::MazzeiExponent{}(re) == doctest::Approx((4.8 + 2.4 * x) / (1 + x)).epsilon(1e-15));
  }
}

TEST_CASE("dn/dRe_t of eq. 3.24 equals a central difference, the closed form and the dual-number derivative") {
  for (double re : {1e-4, 0.05, 1.0, 10.2, 300.0, 1e5}) {
    const double h = 1e-4 * re;
    const double fd = (settling::MazzeiExponent{}(re + h) - settling::MazzeiExponent{}(re - h)) / (2 * h);
    const auto with = settling::MazzeiExponent{}.with_derivatives(re);
    const double slope = with.d_argument;
    // The former richardson_zaki_exponent_mazzei_derivative: −0.315 Re_t^−¼/(1 + 0.175 Re_t^¾)² (eq. 3.103).
    const double one_plus_x = 1 + 0.175 * std::pow(re, 0.75);
    const double closed_form = -0.315 * std::pow(re, -0.25) / (one_plus_x * one_plus_x);
    INFO("Re_t = " << re);
    CHECK(fluidbed::test::same_arithmetic(with.value, settling::MazzeiExponent{}(re)));
    CHECK(slope < 0.0);
    CHECK(slope == doctest::Approx(fd).epsilon(1e-7));
    CHECK(slope == closed_form);  // bit for bit: the same expression, the same rounding
    const auto dual = settling::MazzeiExponent{}(Dual<double, 1>::variable(re, 0));
    CHECK(fluidbed::test::same_arithmetic(dual.value, settling::MazzeiExponent{}(re)));
    CHECK(dual.derivative[0] == doctest::Approx(slope).epsilon(1e-13));
  }
  // |Re_t N| = 1.8 x/(1 + x)² <= 0.45 (eq. 3.103), the maximum at x = 0.175 Re_t^¾ = 1.
  const double re_peak = std::pow(1 / 0.175, 4.0 / 3.0);
  CHECK(re_peak * settling::MazzeiExponent{}.with_derivatives(re_peak).d_argument ==
        doctest::Approx(-0.45).epsilon(1e-14));
  CHECK(settling::MazzeiExponent{}.with_derivatives(0.0).d_argument == -std::numeric_limits<double>::infinity());
}

TEST_CASE("alternative exponents: limits and the published forms") {
  // Rowe (1987): 4.7 and 0.41/0.175.
  CHECK(settling::RoweExponent{}(0.0) == 4.7);
  CHECK(settling::RoweExponent{}(1e40) == doctest::Approx(0.41 / 0.175).epsilon(1e-14));
  CHECK(0.41 / 0.175 == doctest::Approx(2.343).epsilon(1e-4));
  // Garside & Al-Dibouni (1977): 5.1 and 2.7, and (5.1 − n)/(n − 2.7) = 0.1 Re_t^0.9.
  CHECK(settling::GarsideAlDibouniExponent{}(0.0) == doctest::Approx(5.1).epsilon(1e-15));
  CHECK(settling::GarsideAlDibouniExponent{}(1e40) == doctest::Approx(2.7).epsilon(1e-15));
  for (double re : {0.3, 7.0, 250.0}) {
    const double n = settling::GarsideAlDibouniExponent{}(re);
    CHECK((5.1 - n) / (n - 2.7) == doctest::Approx(0.1 * std::pow(re, 0.9)).epsilon(1e-13));
  }
  // Khan & Richardson (1989): 4.8 and 2.4 in the Ar limits (also with a wall term), and
  // (4.8 − n)/(n − 2.4) = 0.043 Ar^0.57 (1 − 2.4 (d/D)^0.27).
  for (double wall : {0.0, 0.01, 0.03}) {
    CHECK(settling::KhanRichardsonExponent{wall}(0.0) == 4.8);
    CHECK(settling::KhanRichardsonExponent{wall}(1e60) == doctest::Approx(2.4).epsilon(1e-12));
    for (double ar : {0.5, 300.0, 2e5}) {
      const double n = settling::KhanRichardsonExponent{wall}(ar);
      CHECK((4.8 - n) / (n - 2.4) ==
            doctest::Approx(0.043 * std::pow(ar, 0.57) * (1 - 2.4 * std::pow(wall, 0.27))).epsilon(1e-12));
    }
  }
  // Richardson & Zaki (1954): 4.65 (+ 19.5 d/D) below Re_t = 0.2, 2.39 from 500 on, and
  // each branch as published.
  CHECK(settling::RichardsonZaki1954Exponent{}(0.0) == 4.65);
  CHECK(settling::RichardsonZaki1954Exponent{0.05}(0.1999) == doctest::Approx(4.65 + 19.5 * 0.05).epsilon(1e-15));
  CHECK(settling::RichardsonZaki1954Exponent{}(0.2) == doctest::Approx(4.35 * std::pow(0.2, -0.03)).epsilon(1e-15));
  CHECK(settling::RichardsonZaki1954Exponent{0.02}(1.0) == doctest::Approx(4.45 + 18 * 0.02).epsilon(1e-15));
  CHECK(settling::RichardsonZaki1954Exponent{0.1}(200.0) ==
        doctest::Approx(4.45 * std::pow(200.0, -0.1)).epsilon(1e-15));
  CHECK(settling::RichardsonZaki1954Exponent{0.1}(500.0) == 2.39);
  CHECK(settling::RichardsonZaki1954Exponent{}(1e9) == 2.39);
  // The documented jumps at d/D = 0.
  CHECK(settling::RichardsonZaki1954Exponent{}(0.2) -
            settling::RichardsonZaki1954Exponent{}(std::nextafter(0.2, 0.0)) ==
        doctest::Approx(-0.0848).epsilon(1e-3));
  CHECK(settling::RichardsonZaki1954Exponent{}(1.0) -
            settling::RichardsonZaki1954Exponent{}(std::nextafter(1.0, 0.0)) ==
        doctest::Approx(0.10).epsilon(1e-9));
  // Every correlation decreases with Re_t (Ar) between its limits.
  double previous[5] = {9, 9, 9, 9, 9};
  for (double re = 1e-3; re < 1e6; re *= 1.3) {
    const double now[5] = {settling::MazzeiExponent{}(re), settling::RoweExponent{}(re),
                           settling::GarsideAlDibouniExponent{}(re), settling::KhanRichardsonExponent{}(re),
                           settling::RichardsonZaki1954Exponent{}(re)};
    for (int i = 0; i < 4; ++i) CHECK(now[i] < previous[i]);
    if (std::abs(re - 1.0) > 0.3) CHECK(now[4] <= previous[4]);  // except the +0.1 jump at Re_t = 1
    std::copy(now, now + 5, previous);
  }
}

TEST_CASE("the Richardson–Zaki law, its inverse, and Re_t from (Re, ε)") {
  CHECK(settling::richardson_zaki_velocity(0.5, 0.6, 3.0) == doctest::Approx(0.5 * 0.216).epsilon(1e-15));
  for (double eps : {0.35, 0.6, 0.93})
    for (double n : {2.4, 3.3, 4.8})
      CHECK(settling::richardson_zaki_voidage(settling::richardson_zaki_velocity(0.2, eps, n), 0.2, n) ==
            doctest::Approx(eps).epsilon(1e-14));
  CHECK(settling::richardson_zaki_voidage(0.2, 0.2, 3.0) == 1.0);
  // Re = Re_t ε^n(Re_t), solved for Re_t.
  for (double re : {1e-6, 0.03, 1.0, 40.0, 2e3, 1e6})
    for (double eps : {0.05, 0.4, 0.7, 0.99, 1.0}) {
      const double re_t = settling::richardson_zaki_terminal_reynolds(re, eps);
      INFO("Re = " << re << " eps = " << eps);
      CHECK(re_t * std::pow(eps, settling::MazzeiExponent{}(re_t)) == doctest::Approx(re).epsilon(1e-13));
      CHECK(re_t >= re * std::pow(eps, -2.4) * (1 - 1e-14));
      CHECK(re_t <= re * std::pow(eps, -4.8) * (1 + 1e-14));
    }
  CHECK(settling::richardson_zaki_terminal_reynolds(3.0, 1.0) == 3.0);
  CHECK(settling::richardson_zaki_terminal_reynolds(0.0, 0.5) == 0.0);
  // It is the Re* of the Mazzei–Lettieri law (seed 000 eq. 3.53).
  for (double re : {0.01, 1.0, 100.0})
    for (double eps : {0.4, 0.7, 0.9})
      CHECK(settling::richardson_zaki_terminal_reynolds(re, eps) ==
            doctest::Approx(drag::MazzeiLettieri::effective_reynolds(eps, re)).epsilon(1e-13));
}

// ============================================================================ terminal velocity

TEST_CASE("Dallavalle terminal velocity: the seed's checked systems") {
  const auto check = [](const Fluid<double>& fluid, const Particles<double>& particles, double u_t, double re_t,
                        double n, double tolerance) {
    const double terminal = single_particle::DallavalleTerminalVelocity{}(fluid, particles);
    const double reynolds = terminal_reynolds(fluid, particles.diameter, terminal);
    CHECK(terminal == doctest::Approx(u_t).epsilon(tolerance));
    CHECK(reynolds == doctest::Approx(re_t).epsilon(tolerance));
    CHECK(settling::MazzeiExponent{}(reynolds) == doctest::Approx(n).epsilon(tolerance));
  };
  // Table 4.3 systems 1–3 (system 3 at 5.21 mm: the printed 521 µm cannot reproduce Table 4.4), values of
  // the independent evaluation.
  check(system_of(1).fluid, system_of(1).particles, 0.033827, 8.5411396, 3.6805, 2e-5);
  CHECK(terminal_reynolds(water, 253e-6, single_particle::DallavalleTerminalVelocity{}(water, {2780.0, 253e-6})) ==
        doctest::Approx(8.5411396).epsilon(1e-8));
  CHECK(archimedes(water, {2780.0, 253e-6}) == doctest::Approx(282.5328).epsilon(2e-7));
  check(system_of(2).fluid, system_of(2).particles, 0.051804, 19.42, 3.3164, 2e-4);
  check(system_of(3).fluid, system_of(3).particles, 0.4120, 2157, 2.4426, 2e-4);
  // §4.3.3: the gas example and the Richardson & Zaki (1954) liquid (ρ_f = 2170 as printed).
  check(air_example, fcc_example, 0.4467, 3.99, 4.006, 3e-4);
  check({2170.0, 1.61e-3}, {2620.0, 230e-6}, 6.034e-3, 1.87, 4.275, 3e-3);
  // The §4.6.3 stability system.
  check({1.19, 1.82e-5}, {2500.0, 71.5e-6}, 0.29866, 1.3962, 4.3595, 3e-5);
}

TEST_CASE("terminal velocities: limits of Dallavalle and Schiller–Naumann") {
  const Particles<double> glass{.density = 2500.0, .diameter = 1e-6};
  const double weight = (glass.density - water.density) * g;
  // Dallavalle: C_D·Re → 23.04 for small Ar (not 24), C_D → 0.3969 for large Ar (not 0.44).
  CHECK(single_particle::DallavalleTerminalVelocity{}(water, glass) ==
        doctest::Approx(weight * glass.diameter * glass.diameter / (17.28 * water.viscosity)).epsilon(1e-6));
  // The inertial limit is approached slowly: u_t/u_∞ = 1 − 4.8/(0.63 √Re_t) + O(1/Re_t).
  const Particles<double> boulder{.density = 2500.0, .diameter = 2.0};
  const double u_inertial =
      std::sqrt(4 * g * boulder.diameter * (boulder.density - water.density) / (3 * 0.3969 * water.density));
  const double u_boulder = single_particle::DallavalleTerminalVelocity{}(water, boulder);
  const double re_boulder = terminal_reynolds(water, boulder.diameter, u_boulder);
  CHECK(u_boulder / u_inertial == doctest::Approx(1 - 4.8 / (0.63 * std::sqrt(re_boulder))).epsilon(1e-5));
  CHECK(single_particle::DallavalleTerminalVelocity{}.reynolds(1e30) / std::sqrt(4e30 / (3 * 0.3969)) ==
        doctest::Approx(1.0).epsilon(1e-6));
  CHECK(single_particle::DallavalleTerminalVelocity{}.reynolds(1e-20) == doctest::Approx(1e-20 / 17.28).epsilon(1e-9));
  CHECK(single_particle::DallavalleTerminalVelocity{}.reynolds(0.0) == 0.0);
  // It solves ¾ C_D Re_t² = Ar.
  for (double ar : {1e-8, 0.3, 80.0, 5e4, 3e7}) {
    const double re = single_particle::DallavalleTerminalVelocity{}.reynolds(ar);
    CHECK(0.75 * single_particle::DallavalleCoefficient::cd_times_re(re) * re == doctest::Approx(ar).epsilon(1e-14));
  }
  // Schiller–Naumann: Stokes for small Ar, Newton (exactly) on the 0.44 branch.
  CHECK(single_particle::SchillerNaumannTerminalVelocity{}(water, glass) ==
        doctest::Approx(single_particle::StokesTerminalVelocity{}(water, glass)).epsilon(1e-6));
  CHECK(single_particle::SchillerNaumannTerminalVelocity{}.reynolds(1e-12) ==
        doctest::Approx(1e-12 / 18).epsilon(1e-12));
  CHECK(single_particle::SchillerNaumannTerminalVelocity{}(water, boulder) ==
        doctest::Approx(single_particle::NewtonTerminalVelocity{}(water, boulder)).epsilon(1e-14));
  CHECK(single_particle::NewtonTerminalVelocity{}(water, boulder) ==
        doctest::Approx(std::sqrt(4 * g * 2.0 * 1502.0 / (3 * 0.44 * 998.0))).epsilon(1e-15));
  CHECK(single_particle::SchillerNaumannTerminalVelocity{}.reynolds(0.0) == 0.0);
  for (double ar : {1e-8, 0.3, 80.0, 5e4, 3e5, 3.3e5, 3e7}) {
    const double re = single_particle::SchillerNaumannTerminalVelocity{}.reynolds(ar);
    INFO("Ar = " << ar);
    CHECK(0.75 * single_particle::SchillerNaumannCoefficient::cd_times_re(re) * re ==
          doctest::Approx(ar).epsilon(1e-14));
  }
}

TEST_CASE("Schiller–Naumann terminal velocity across the C_D jump at Re = 1000: no root, Re_t = 1000, monotone") {
  const double ar_below = 0.75 * 24 * (1 + 0.15 * std::pow(1000.0, 0.687)) * 1000;  // 328 716
  const double ar_above = 0.75 * 0.44 * 1e6;                                        // 330 000
  CHECK(ar_below == doctest::Approx(328716.2).epsilon(1e-6));
  for (double ar : {ar_below * (1 + 1e-9), 329000.0, 329500.0, ar_above * (1 - 1e-9)})
    CHECK(single_particle::SchillerNaumannTerminalVelocity{}.reynolds(ar) == doctest::Approx(1000.0).epsilon(1e-12));
  double previous = 0;
  for (double ar = 3.2e5; ar < 3.4e5; ar += 250.0) {
    const double re = single_particle::SchillerNaumannTerminalVelocity{}.reynolds(ar);
    CHECK(re >= previous * (1 - 1e-14));  // flat at 1000 (to rounding) across the gap
    previous = re;
  }
}

// ============================================================================ bed expansion

TEST_CASE("seed 000 Table 4.4: every row and column, to the tolerance the data supports") {
  for (const seed000::Row& row : seed000::table_4_4) {
    const seed000::System& system = system_of(row.system);
    const seed000::Tolerance& tol = seed000::tolerance.at(static_cast<std::size_t>(row.system - 1));
    INFO("system " << row.system << ", u = " << row.velocity);
    const auto rz = fluidization::richardson_zaki_equilibrium_voidage(row.velocity, system.fluid, system.particles);
    const auto ml =
        fluidization::equilibrium_voidage(drag::MazzeiLettieri{}, row.velocity, system.fluid, system.particles);
    const auto wy = fluidization::equilibrium_voidage(wen_yu, row.velocity, system.fluid, system.particles);
    const auto ergun = fluidization::equilibrium_voidage(drag::Ergun{}, row.velocity, system.fluid, system.particles);
    REQUIRE(rz.has_value());
    REQUIRE(ml.has_value());
    REQUIRE(wy.has_value());
    REQUIRE(ergun.has_value());
    CHECK(std::abs(*rz - row.richardson_zaki) <= tol.richardson_zaki);
    CHECK(std::abs(*ml - row.richardson_zaki) <= tol.mazzei_lettieri);
    CHECK(std::abs(*wy - row.wen_yu) <= tol.wen_yu);
    CHECK(std::abs(*ergun - row.ergun) <= tol.ergun);
    // The printed ε_M&L is CFD output, 0.0010–0.0062 below the analytic value.
    CHECK(*ml - row.mazzei_lettieri > 0.0);
    CHECK(*ml - row.mazzei_lettieri <= seed000::mazzei_lettieri_cfd_offset_max);
  }
  // System 1's W&Y and Ergun columns are the ones that need more than 0.002 (computed −
  // printed: W&Y −0.0113 at u = 1.5e-2, Ergun +0.0139 at u = 5.28e-3): check that this is
  // still so, so that the wider tolerance is not hiding a regression elsewhere.
  const seed000::System& system_1 = system_of(1);
  CHECK(*fluidization::equilibrium_voidage(wen_yu, 1.50e-2, system_1.fluid, system_1.particles) - 0.802 ==
        doctest::Approx(-0.0113).epsilon(0.01));
  CHECK(*fluidization::equilibrium_voidage(drag::Ergun{}, 5.28e-3, system_1.fluid, system_1.particles) - 0.628 ==
        doctest::Approx(0.0139).epsilon(0.01));
}

TEST_CASE("seed 000 Table 4.3 system 3 as printed (d = 521 µm) has no homogeneous bed: the misprint") {
  const seed000::System& system = system_of(3);
  const Particles<double> printed{.density = system.particles.density, .diameter = seed000::system_3_printed_diameter};
  const double u_t = single_particle::DallavalleTerminalVelocity{}(system.fluid, printed);
  CHECK(u_t == doctest::Approx(0.0661).epsilon(1e-3));
  for (const seed000::Row& row : seed000::table_4_4) {
    if (row.system != 3) continue;
    INFO("u = " << row.velocity);
    CHECK(u_t < row.velocity);
    CHECK(!fluidization::richardson_zaki_equilibrium_voidage(row.velocity, system.fluid, printed).has_value());
    // nor with any of the thesis's three closures
    CHECK(!fluidization::equilibrium_voidage(drag::MazzeiLettieri{}, row.velocity, system.fluid, printed).has_value());
    CHECK(!fluidization::equilibrium_voidage(wen_yu, row.velocity, system.fluid, printed).has_value());
    CHECK(!fluidization::equilibrium_voidage(drag::Ergun{}, row.velocity, system.fluid, printed).has_value());
    CHECK_THROWS_WITH_AS(
        fluidization::equilibrium_voidage(wen_yu, row.velocity, system.fluid, printed, fluidbed::checked).value(),
        doctest::Contains("no homogeneous bed"), std::domain_error);
  }
}

TEST_CASE("gas example of seed 000 §4.3.3: ε_R&Z(5.77e-2) = 0.6000, h = 0.45 m, u_mf(Ergun, 0.4) = 8.731e-3") {
  const double eps = *fluidization::richardson_zaki_equilibrium_voidage(5.77e-2, air_example, fcc_example);
  CHECK(eps == doctest::Approx(0.6000).epsilon(1e-4));
  CHECK(fluidization::bed_height(0.30, 0.4, eps) == doctest::Approx(0.450).epsilon(1e-4));
  CHECK(fluidization::ErgunMinimumFluidization{0.4}(air_example, fcc_example) ==
        doctest::Approx(8.731e-3).epsilon(1e-4));
  // The Richardson & Zaki (1954) liquid of §4.3.3 (eq. 4.4): ε_R&Z(4.70e-4) = 0.5504, h = 0.400 m.
  const double eps_rz = *fluidization::richardson_zaki_equilibrium_voidage(4.70e-4, Fluid<double>{2170.0, 1.61e-3},
                                                                           Particles<double>{2620.0, 230e-6});
  CHECK(eps_rz == doctest::Approx(0.5504).epsilon(2e-4));
  CHECK(fluidization::bed_height(0.30, 0.4, eps_rz) == doctest::Approx(0.400).epsilon(1e-3));
  // §4.6.3: R–Z at 1.55 cm/s gives 0.507 for its stability system.
  CHECK(*fluidization::richardson_zaki_equilibrium_voidage(1.55e-2, Fluid<double>{1.19, 1.82e-5},
                                                           Particles<double>{2500.0, 71.5e-6}) ==
        doctest::Approx(0.507).epsilon(1e-3));
}

TEST_CASE(
    "Mazzei–Lettieri expansion equals Richardson–Zaki (Dallavalle u_t, n(Re_t)) for Re_t 1e-3..1e4, ε 0.4..0.99") {
  const drag::MazzeiLettieri ml;
  const double particle_density = 2500.0;
  const Fluid<double> liquid{.density = 1000.0, .viscosity = 1e-3};
  double worst = 0;
  for (int i = 0; i < 9; ++i) {
    const double re_t = std::pow(10.0, -3.0 + 7.0 * i / 8);  // 1e-3 … 1e4
    const double ar = 0.75 * single_particle::DallavalleCoefficient::cd_times_re(re_t) * re_t;
    const Particles<double> particles{.density = particle_density,
                                      .diameter = diameter_for_archimedes(ar, liquid, particle_density)};
    const double u_t = single_particle::DallavalleTerminalVelocity{}(liquid, particles, g);
    CHECK(terminal_reynolds(liquid, particles.diameter, u_t) == doctest::Approx(re_t).epsilon(1e-12));
    const double n = settling::MazzeiExponent{}(re_t);
    for (int j = 0; j < 9; ++j) {
      const double eps = 0.4 + (0.99 - 0.4) * j / 8;
      const double u = u_t * std::pow(eps, n);
      INFO("Re_t = " << re_t << ", eps = " << eps);
      const auto by_law = fluidization::equilibrium_voidage(ml, u, liquid, particles, g);
      REQUIRE(by_law.has_value());
      CHECK(*by_law == doctest::Approx(eps).epsilon(1e-10));
      CHECK(*fluidization::richardson_zaki_equilibrium_voidage(u, liquid, particles, g) ==
            doctest::Approx(eps).epsilon(1e-13));
      worst = std::max(worst, relative_difference(*by_law, eps));
      // and the seed's Figs 3.1–3.5 ratio is 1 (Fig. 3.5).
      const double re = liquid.density * u * particles.diameter / liquid.viscosity;
      CHECK(*fluidization::voidage_ratio(ml, re, eps) == doctest::Approx(1.0).epsilon(1e-10));
    }
  }
  CHECK(worst <= 1e-10);
}

TEST_CASE("equilibrium voidage: eq. 3.28 holds at the root, for every law of the run-time family") {
  const Particles<double> sand{.density = 2650.0, .diameter = 4e-4};
  for (const drag::AnyDragLaw& law : drag::all_drag_laws) {
    double previous = 0;
    for (double u : {2e-4, 1e-3, 4e-3, 1.5e-2, 3e-2}) {
      INFO(drag::name_of(law) << " u = " << u);
      const auto eps = fluidization::equilibrium_voidage(law, u, water, sand);
      REQUIRE(eps.has_value());
      CHECK(*eps > previous);  // the bed expands with u
      previous = *eps;
      const double w = u / *eps;
      const double drag_force =
          drag::evaluate(law, drag::DragState<double>{*eps, w, water, sand.diameter}).classical() * w;
      const double weight = (1 - *eps) * (sand.density - water.density) * g;
      if (std::abs(*eps - 0.8) > 1e-9) CHECK(drag_force == doctest::Approx(weight).epsilon(1e-10));
    }
  }
}

TEST_CASE("no homogeneous bed at or above the law's own single-particle terminal velocity") {
  const Particles<double> sand{.density = 2650.0, .diameter = 4e-4};
  const auto bounds = [&](const auto& law, double u_t) {
    const auto below = fluidization::equilibrium_voidage(law, u_t * (1 - 1e-6), water, sand);
    REQUIRE(below.has_value());
    CHECK(*below > 0.9999);
    CHECK(!fluidization::equilibrium_voidage(law, u_t * (1 + 1e-12), water, sand).has_value());
    CHECK(!fluidization::equilibrium_voidage(law, 2 * u_t, water, sand).has_value());
  };
  // Wen–Yu tends to the Schiller–Naumann sphere, Mazzei–Lettieri to Dallavalle's, and
  // Ergun to 1.75 ρ_f u²/d = (ρ_p − ρ_f) g.
  bounds(wen_yu, single_particle::SchillerNaumannTerminalVelocity{}(water, sand));
  bounds(drag::MazzeiLettieri{}, single_particle::DallavalleTerminalVelocity{}(water, sand));
  bounds(drag::Ergun{}, std::sqrt((sand.density - water.density) * g * sand.diameter / (1.75 * water.density)));
  CHECK(!fluidization::richardson_zaki_equilibrium_voidage(single_particle::DallavalleTerminalVelocity{}(water, sand),
                                                           water, sand)
             .has_value());
}

TEST_CASE("a law discontinuous in ε: Gidaspow's switch can hold the bed at its jump, ε = 0.8") {
  // System 3 at u = 0.162: Ergun alone puts the bed at 0.879, Wen–Yu (α = 2.65) at 0.649;
  // switched at 0.8, the balance changes sign at the jump and has no root.
  const seed000::System& system = system_of(3);
  const auto eps = fluidization::equilibrium_voidage(drag::GidaspowSwitched{}, 0.162, system.fluid, system.particles);
  REQUIRE(eps.has_value());
  CHECK(*eps == doctest::Approx(0.8).epsilon(1e-12));
  CHECK(*fluidization::equilibrium_voidage(drag::Ergun{}, 0.162, system.fluid, system.particles) > 0.8);
  CHECK(*fluidization::equilibrium_voidage(drag::ConstantExponentDrag::wen_yu_gidaspow(), 0.162, system.fluid,
                                           system.particles) < 0.8);
}

TEST_CASE("typed laws and drag::AnyDragLaw give the same voidage, long double and float agree") {
  const seed000::System& system = system_of(2);
  for (double u : {9.05e-3, 2.85e-2}) {
    CHECK(*fluidization::equilibrium_voidage(drag::Ergun{}, u, system.fluid, system.particles) ==
          *fluidization::equilibrium_voidage(drag::AnyDragLaw{drag::Ergun{}}, u, system.fluid, system.particles));
    CHECK(*fluidization::equilibrium_voidage(wen_yu, u, system.fluid, system.particles) ==
          *fluidization::equilibrium_voidage(drag::make_drag_law("WenYu1966"), u, system.fluid, system.particles));
    const double in_double = *fluidization::equilibrium_voidage(wen_yu, u, system.fluid, system.particles);
    const Fluid<long double> fluid_l{system.fluid.density, system.fluid.viscosity};
    const Particles<long double> particles_l{system.particles.density, system.particles.diameter};
    const long double in_long =
        *fluidization::equilibrium_voidage(wen_yu, static_cast<long double>(u), fluid_l, particles_l);
    CHECK(static_cast<double>(in_long) == doctest::Approx(in_double).epsilon(1e-13));
    const Fluid<float> fluid_f{static_cast<float>(system.fluid.density), static_cast<float>(system.fluid.viscosity)};
    const Particles<float> particles_f{static_cast<float>(system.particles.density),
                                       static_cast<float>(system.particles.diameter)};
    CHECK(*fluidization::equilibrium_voidage(wen_yu, static_cast<float>(u), fluid_f, particles_f) ==
          doctest::Approx(in_double).epsilon(1e-5));
    CHECK(single_particle::SchillerNaumannTerminalVelocity{}(fluid_f, particles_f) ==
          doctest::Approx(single_particle::SchillerNaumannTerminalVelocity{}(system.fluid, system.particles))
              .epsilon(1e-5));
  }
}

TEST_CASE("below minimum fluidization the law's voidage is below ε_mf, Ergun at u_mf(ε_mf) gives ε_mf") {
  const Particles<double> sand{.density = 2650.0, .diameter = 4e-4};
  for (double eps_mf : {0.38, 0.4, 0.45}) {
    const double u_mf = fluidization::ErgunMinimumFluidization{eps_mf}(water, sand);
    CHECK(*fluidization::equilibrium_voidage(drag::Ergun{}, u_mf, water, sand) ==
          doctest::Approx(eps_mf).epsilon(1e-12));
    CHECK(*fluidization::equilibrium_voidage(drag::Ergun{}, 0.5 * u_mf, water, sand) < eps_mf);
  }
  // Far below u_mf the root lies below the first scan point 1/64 and is still found.
  const double tiny = *fluidization::equilibrium_voidage(drag::Ergun{}, 1e-9, water, sand);
  CHECK(tiny < 1.0 / 64);
  const double re = water.density * 1e-9 * sand.diameter / water.viscosity;
  CHECK(150 * (1 - tiny) * re / std::pow(tiny, 3) + 1.75 * re * re / std::pow(tiny, 3) ==
        doctest::Approx(archimedes(water, sand)).epsilon(1e-10));
}

TEST_CASE("voidage ratio ε_law/ε_R&Z (seed 000 Figs 3.1–3.3): independently evaluated values") {
  // Figs 3.1–3.3 give these ratios only as curves; the values come from an independent
  // double-precision evaluation of their construction (§3.4.4.1) made when the thesis was read.
  const std::vector<double> re{1e-3, 1.0, 10.0, 100.0, 1e3, 1e5};
  const auto check = [&](const auto& law, double eps_rz, const std::vector<double>& expected) {
    for (std::size_t i = 0; i < re.size(); ++i) {
      INFO("eps_RZ = " << eps_rz << ", Re = " << re[i]);
      const auto ratio = fluidization::voidage_ratio(law, re[i], eps_rz);
      if (expected[i] * eps_rz >= 1.0) {
        CHECK(!ratio.has_value());  // the construction gives ε > 1: no bed
      } else {
        REQUIRE(ratio.has_value());
        CHECK(*ratio == doctest::Approx(expected[i]).epsilon(6e-5));
      }
    }
  };
  check(drag::Ergun{}, 0.4, {0.9957, 1.1336, 1.0845, 0.9872, 0.9974, 1.0359});
  check(drag::Ergun{}, 0.6, {1.0680, 1.0642, 1.0569, 1.0991, 1.2215, 1.3166});
  check(drag::Ergun{}, 0.8, {1.0192, 0.9950, 1.0015, 1.1522, 1.3959, 1.5591});
  check(wen_yu, 0.4, {0.9860, 1.1209, 1.1386, 1.0754, 0.9648, 0.9989});
  check(wen_yu, 0.8, {1.0015, 0.9827, 0.9927, 0.9957, 0.9425, 1.0093});
  check(drag::DiFelice<single_particle::SchillerNaumannCoefficient>{}, 0.4,
        {0.9860, 1.0794, 1.0207, 0.9564, 0.9225, 0.9986});
  check(drag::DiFelice<single_particle::DallavalleCoefficient>{}, 0.4,
        {0.9789, 1.0954, 1.0471, 0.9849, 0.9926, 0.9869});
}

TEST_CASE("equivalent exponent ψ_e (eq. 3.64)") {
  // A constant-exponent law measured against its own C_D has ψ_e = α.
  for (double eps : {0.35, 0.6, 0.95})
    for (double re : {0.0, 0.5, 80.0, 5e3})
      CHECK(fluidization::equivalent_exponent<single_particle::SchillerNaumannCoefficient>(wen_yu, eps, re) ==
            doctest::Approx(2.70).epsilon(1e-13));
  // Mazzei–Lettieri against Dallavalle's C_D: ψ_e of the independent evaluation of Table 3.1.
  const drag::MazzeiLettieri ml;
  CHECK(fluidization::equivalent_exponent(ml, 0.40, 1.0) == doctest::Approx(2.042413).epsilon(1e-6));
  CHECK(fluidization::equivalent_exponent(ml, 0.50, 0.01) == doctest::Approx(2.805829).epsilon(1e-6));
  CHECK(fluidization::equivalent_exponent(ml, 0.70, 100.0) == doctest::Approx(2.216866).epsilon(1e-6));
  CHECK(fluidization::equivalent_exponent(ml, 0.90, 1.0) == doctest::Approx(2.881134).epsilon(1e-6));
  CHECK(fluidization::equivalent_exponent(ml, 0.40, 10.0) == doctest::Approx(1.918917).epsilon(1e-6));
  for (double eps : {0.4, 0.77, 0.98})
    for (double re : {1e-3, 3.0, 400.0})
      CHECK(fluidization::equivalent_exponent(ml, eps, re) ==
            doctest::Approx(drag::MazzeiLettieri::equivalent_exponent(eps, re)).epsilon(1e-12));
}

// ============================================================================ minimum fluidization

TEST_CASE("minimum fluidization: Ergun quadratic, its limits and sphericity, Wen & Yu") {
  // The root satisfies the quadratic, with no cancellation for tiny Ar.
  for (double ar : {1e-12, 1e-3, 10.0, 1e4, 1e9})
    for (double eps : {0.38, 0.45})
      for (double phi : {1.0, 0.7}) {
        const double re = fluidization::ErgunMinimumFluidization{eps, phi}.reynolds(ar);
        const double e3 = eps * eps * eps;
        CHECK(150 * (1 - eps) * re / (e3 * phi * phi) + 1.75 * re * re / (e3 * phi) ==
              doctest::Approx(ar).epsilon(1e-14));
      }
  CHECK(fluidization::ErgunMinimumFluidization{0.4}.reynolds(1e-12) ==
        doctest::Approx(1e-12 * 0.064 / (150 * 0.6)).epsilon(1e-12));
  CHECK(fluidization::ErgunMinimumFluidization{0.4}.reynolds(1e20) ==
        doctest::Approx(std::sqrt(1e20 * 0.064 / 1.75)).epsilon(1e-6));
  // Sphericity enters through the surface–volume diameter φ_s d only.
  const Particles<double> sand{.density = 2650.0, .diameter = 4e-4};
  CHECK(fluidization::ErgunMinimumFluidization{0.42, 0.8}(water, sand) ==
        doctest::Approx(fluidization::ErgunMinimumFluidization{0.42}(water, {sand.density, 0.8 * sand.diameter}))
            .epsilon(1e-13));
  // Wen & Yu (1966): √(33.7² + 0.0408 Ar) − 33.7, and its small-Ar limit Ar/1651.
  for (double ar : {0.1, 50.0, 1e5, 1e8})
    CHECK(fluidization::WenYuMinimumFluidization{}.reynolds(ar) ==
          doctest::Approx(std::sqrt(33.7 * 33.7 + 0.0408 * ar) - 33.7).epsilon(1e-9));
  CHECK(fluidization::WenYuMinimumFluidization{}.reynolds(1e-14) ==
        doctest::Approx(1e-14 * 0.0408 / 67.4).epsilon(1e-13));
  CHECK(fluidization::WenYuMinimumFluidization{}(air_example, fcc_example) <
        fluidization::ErgunMinimumFluidization{0.4}(air_example, fcc_example));
}

TEST_CASE("bed height from voidage") {
  CHECK(fluidization::bed_height(0.30, 0.4, 0.6) == doctest::Approx(0.45).epsilon(1e-15));
  CHECK(fluidization::bed_height(fluidization::bed_height(0.3, 0.4, 0.7), 0.7, 0.4) ==
        doctest::Approx(0.3).epsilon(1e-15));
  CHECK(fluidization::bed_height(1.0, 0.5, 0.5, fluidbed::checked) == 1.0);
}

// ============================================================================ checked entry points

TEST_CASE("checked entry points throw std::domain_error naming the argument and its value") {
  const Particles<double> sand{.density = 2650.0, .diameter = 4e-4};
  const Particles<double> bubble{.density = 1.2, .diameter = 4e-4};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(single_particle::DallavalleTerminalVelocity{}.checked(water, bubble),
                       doctest::Contains("'particles.density' = 1.2"), std::domain_error);
  CHECK_THROWS_WITH_AS(single_particle::SchillerNaumannTerminalVelocity{}.checked(water, {998.0, 1e-3}),
                       doctest::Contains("heavier-than-fluid"), std::domain_error);
  CHECK_THROWS_WITH_AS(single_particle::StokesTerminalVelocity{}.checked(water, {2650.0, -1e-3}),
                       doctest::Contains("'particles.diameter' = -0.001"), std::domain_error);
  CHECK_THROWS_WITH_AS(single_particle::NewtonTerminalVelocity{}.checked({nan, 1e-3}, sand),
                       doctest::Contains("'fluid.density' = nan"), std::domain_error);
  CHECK_THROWS_WITH_AS(single_particle::NewtonTerminalVelocity{}.checked(water, sand, 0.0),
                       doctest::Contains("'gravity' = 0"), std::domain_error);
  CHECK(single_particle::DallavalleTerminalVelocity{}.checked(water, sand) ==
        single_particle::DallavalleTerminalVelocity{}(water, sand));

  CHECK_THROWS_WITH_AS(fluidization::equilibrium_voidage(drag::Ergun{}, 10.0, water, sand, fluidbed::checked).value(),
                       doctest::Contains("'superficial_velocity' = 10"), std::domain_error);
  CHECK_THROWS_WITH_AS(fluidization::equilibrium_voidage(drag::Ergun{}, -1e-3, water, sand, fluidbed::checked).value(),
                       doctest::Contains("'superficial_velocity' = -0.001"), std::domain_error);
  CHECK_THROWS_AS(fluidization::equilibrium_voidage(drag::Ergun{}, 1e-3, water, bubble, fluidbed::checked).value(),
                  std::domain_error);
  CHECK(fluidization::equilibrium_voidage(drag::Ergun{}, 1e-2, water, sand, fluidbed::checked).value() ==
        *fluidization::equilibrium_voidage(drag::Ergun{}, 1e-2, water, sand));
  CHECK_THROWS_WITH_AS(fluidization::richardson_zaki_equilibrium_voidage(10.0, water, sand, fluidbed::checked).value(),
                       doctest::Contains("no homogeneous bed"), std::domain_error);

  CHECK_THROWS_WITH_AS(settling::MazzeiExponent{}.checked(-1.0), doctest::Contains("'terminal_reynolds' = -1"),
                       std::domain_error);
  CHECK_THROWS_AS((void)settling::MazzeiExponent{}.checked_with_derivatives(nan), std::domain_error);
  CHECK_THROWS_AS(settling::RoweExponent{}.checked(-2.0), std::domain_error);
  CHECK_THROWS_AS(settling::GarsideAlDibouniExponent{}.checked(nan), std::domain_error);
  CHECK_THROWS_WITH_AS(settling::RichardsonZaki1954Exponent{1.0}.checked(5.0), doctest::Contains("'wall_ratio' = 1"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(settling::KhanRichardsonExponent{0.05}.checked(100.0), doctest::Contains("'wall_ratio' = 0.05"),
                       std::domain_error);
  CHECK(settling::KhanRichardsonExponent{0.03}.checked(100.0) == settling::KhanRichardsonExponent{0.03}(100.0));
  CHECK_THROWS_WITH_AS(settling::richardson_zaki_voidage(0.375, 0.25, 3.0, fluidbed::checked),
                       doctest::Contains("'superficial_velocity' = 0.375"), std::domain_error);
  CHECK_THROWS_AS(settling::richardson_zaki_velocity(0.3, 1.2, 3.0, fluidbed::checked), std::domain_error);
  CHECK_THROWS_WITH_AS(settling::richardson_zaki_terminal_reynolds(1.0, 0.0, fluidbed::checked),
                       doctest::Contains("'voidage' = 0"), std::domain_error);
  CHECK_THROWS_WITH_AS(fluidization::ErgunMinimumFluidization(0.4, 1.5).checked(water, sand),
                       doctest::Contains("'sphericity' = 1.5"), std::domain_error);
  CHECK_THROWS_AS(fluidization::WenYuMinimumFluidization{}.checked(water, bubble), std::domain_error);
  CHECK_THROWS_WITH_AS(fluidization::bed_height(0.3, 0.4, 1.0, fluidbed::checked), doctest::Contains("'voidage' = 1"),
                       std::domain_error);
}
