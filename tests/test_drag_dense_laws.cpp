// The particle-resolved-simulation drag laws (van der Hoef, Beetstra, Tang, Tenneti,
// Koch–Hill) and Syamlal–O'Brien: published and independently checked values, exact
// limits and identities, switch continuity, positivity, and derivatives.
//
// Sources of expected values: an independent double-precision Python evaluation of the
// published formulas (seed 002 eqs. 18, 19, 46, 47 and Sec. II-III, Beetstra et al. 2007) made
// when seed 002 was read, to the digits printed; a re-evaluation of the drag laws exactly as
// OpenFOAM, MFiX 25.2.1 and waLBerla write them (not published data: a cross-check of the
// conventions, to the digits printed); exact limits; and the mpmath generator's polydisperse
// table (tests/reference/drag_reference.py).
#include <doctest/doctest.h>

#include <array>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "fluidbed/drag/beetstra_polydisperse.hpp"
#include "fluidbed/drag/koch_hill.hpp"
#include "fluidbed/drag/syamlal_obrien.hpp"
#include "fluidbed/fluidization/syamlal_obrien_calibration.hpp"
#include "fluidbed/drag/tang.hpp"
#include "fluidbed/drag/tenneti.hpp"
#include "reference_table.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;

namespace {

constexpr double diameter = 5e-4;
const Fluid<double> air{.density = 1.2, .viscosity = 1.8e-5};
const Fluid<double> water{.density = 998.0, .viscosity = 1.0e-3};

DragState<double> state(double voidage, double slip, const Fluid<double>& fluid = air, double d = diameter) {
  return {.voidage = voidage, .slip = slip, .fluid = fluid, .diameter = d};
}

// The slip that gives Re = ρ_f ε w d / μ_f.
DragState<double> at_reynolds(double voidage, double re, const Fluid<double>& fluid = air) {
  return state(voidage, re * fluid.viscosity / (fluid.density * voidage * diameter), fluid);
}

// Drag-only F = β_pg d²/(18 μ_f ε φ) and total F_tot = F/ε (dimensionless_force.hpp).
double drag_force(double beta_pg, const DragState<double>& s) {
  return beta_pg * s.diameter * s.diameter / (18.0 * s.fluid.viscosity * s.voidage * (1.0 - s.voidage));
}
double total_force(double beta_pg, const DragState<double>& s) { return drag_force(beta_pg, s) / s.voidage; }

// |x − expected| <= half a unit in the last printed digit.
void check_printed(double x, double expected, double half_unit) {
  INFO("got " << x << ", expected " << expected << " +- " << half_unit);
  CHECK(std::abs(x - expected) <= half_unit * (1.0 + 1e-12));
}

}  // namespace

// ------------------------------------------------------------------------ van der Hoef 2005
TEST_CASE("VanDerHoef: Stokes fit F0(φ) and A of seed 002 eq. (19) (the independent evaluation)") {
  struct Row {
    double phi, a, f0;
  };
  for (const Row& r :
       {Row{0.01, 2168.433741, 1.2291454051}, Row{0.10, 354.116800, 2.4287846369}, Row{0.20, 241.593123, 4.1943250517},
        Row{0.30, 206.241737, 7.0150250594}, Row{0.40, 191.364721, 11.8126370984}, Row{0.50, 184.636485, 20.5151650429},
        Row{0.60, 181.660335, 37.8459032006}}) {
    for (double w : {0.0, 0.3, 30.0}) {  // creeping flow: β does not depend on the slip
      const auto s = state(1.0 - r.phi, w);
      const double beta = VanDerHoef{}(s).pressure_gradient();
      INFO("phi=" << r.phi << " w=" << w);
      CHECK(drag_force(beta, s) == doctest::Approx(r.f0).epsilon(1e-10));
      // Ergun form at Re = 0: β d² ε/(μ φ) = A φ.
      check_printed(beta * diameter * diameter * s.voidage / (air.viscosity * r.phi * r.phi), r.a, 5e-7);
    }
  }
  // Isolated sphere: F0 → 1, i.e. β_classical/(18 μ φ/d²) → 1 as ε → 1; β = 0 at ε = 1.
  const auto dilute = state(1.0 - 1e-12, 0.0);
  const double phi = 1.0 - dilute.voidage;
  CHECK(VanDerHoef{}(dilute).classical() / (18.0 * air.viscosity * phi / (diameter * diameter)) ==
        doctest::Approx(1.0).epsilon(1e-5));
  CHECK(VanDerHoef{}(state(1.0, 0.5)).pressure_gradient() == 0.0);
}

// ------------------------------------------------------------------------ Beetstra 2007
TEST_CASE("Beetstra: published-form F(φ, Re) of the independent evaluation, in air and in water") {
  struct Row {
    double phi, re, f;
  };
  const std::vector<Row> rows{
      {0.05, 0, 1.759224323},    {0.05, 1, 1.835059107},   {0.05, 10, 2.464075375}, {0.05, 100, 6.881903609},
      {0.05, 1000, 38.70226855}, {0.1, 0, 2.428784637},    {0.1, 1, 2.498160296},   {0.1, 10, 3.218069413},
      {0.1, 100, 8.553746301},   {0.1, 1000, 47.74502664}, {0.2, 0, 4.194325052},   {0.2, 1, 4.24900719},
      {0.2, 10, 5.187160872},    {0.2, 100, 12.94777326},  {0.2, 1000, 71.3045398}, {0.3, 0, 7.015025059},
      {0.3, 1, 7.05609444},      {0.3, 10, 8.279361283},   {0.3, 100, 19.68822548}, {0.3, 1000, 106.5084699},
      {0.4, 0, 11.8126371},      {0.4, 1, 11.8432392},     {0.4, 10, 13.46425824},  {0.4, 100, 30.74155255},
      {0.4, 1000, 163.1546827},  {0.5, 0, 20.51516504},    {0.5, 1, 20.5386913},    {0.5, 10, 22.77396859},
      {0.5, 100, 50.41342778},   {0.5, 1000, 263.6488541}, {0.6, 0, 37.8459032},    {0.6, 1, 37.86540146},
      {0.6, 10, 41.19451128},    {0.6, 100, 89.78941537},  {0.6, 1000, 468.4558517}};
  for (const Row& r : rows)
    for (const Fluid<double>& fluid : {air, water}) {
      const auto s = at_reynolds(1.0 - r.phi, r.re, fluid);
      INFO("phi=" << r.phi << " Re=" << r.re);
      CHECK(drag_force(Beetstra{}(s).pressure_gradient(), s) == doctest::Approx(r.f).epsilon(1e-9));
      CHECK(Beetstra::dimensionless_force(r.phi, r.re) == doctest::Approx(r.f).epsilon(1e-9));
    }
  // Seed 002 eq. (19) as printed (8.4 Re^−0.343 outside the factor 0.31) would give 16.14752691 at
  // φ = 0.1, Re = 100.
  CHECK(Beetstra::dimensionless_force(0.1, 100.0) < 9.0);
  // Single-sphere end (φ = 1e-9): the fit is not Schiller–Naumann (1.15, 1.72961, 4.54888, 18.3333).
  const std::array<std::array<double, 2>, 4> dilute{{{1, 1.08093}, {10, 1.62931}, {100, 5.27230}, {1000, 30.78770}}};
  for (const auto& [re, f] : dilute)
    CHECK(Beetstra::dimensionless_force(1e-9, re) == doctest::Approx(f).epsilon(1e-5));
}

TEST_CASE("Beetstra: Ergun-form LHS (seed 002 eqs. 18, 46) and dimensional β (the independent evaluation)") {
  struct Row {
    double eps, re, lhs;
  };
  for (const Row& r : {Row{0.4, 0.5, 109.0066324},  Row{0.4, 10, 118.6401925},  Row{0.4, 100, 258.5935163},
                       Row{0.4, 500, 760.9846083},  Row{0.5, 0.5, 92.34119667}, Row{0.5, 10, 102.4828587},
                       Row{0.5, 100, 226.860425},   Row{0.5, 500, 670.9404822}, Row{0.6, 0.5, 76.59635102},
                       Row{0.6, 10, 87.24839341},   Row{0.6, 100, 199.2052606}, Row{0.6, 500, 597.9717493},
                       Row{0.7, 0.5, 61.98174369},  Row{0.7, 10, 73.02396651},  Row{0.7, 100, 173.6501487},
                       Row{0.7, 500, 531.0426347},  Row{0.8, 0.5, 48.54617954}, Row{0.8, 10, 59.75609325},
                       Row{0.8, 100, 149.1583479},  Row{0.8, 500, 464.4369622}, Row{0.9, 0.5, 35.85116969},
                       Row{0.9, 10, 46.91945204},   Row{0.9, 100, 124.7136211}, Row{0.9, 500, 394.4205619},
                       Row{0.95, 0.5, 29.16287355}, Row{0.95, 10, 40.02890447}, Row{0.95, 100, 111.7965241},
                       Row{0.95, 500, 356.8868095}}) {
    const auto s = at_reynolds(r.eps, r.re);
    const double lhs =
        Beetstra{}(s).pressure_gradient() * diameter * diameter * r.eps / (air.viscosity * (1 - r.eps));
    INFO("eps=" << r.eps << " Re=" << r.re);
    CHECK(lhs == doctest::Approx(r.lhs).epsilon(1e-9));
  }
  // Air at 1.01e5 Pa and 293 K (M = 0.02896 kg/mol), μ = 1.8e-5 Pa s, d = 500 µm.
  const Fluid<double> air_293_k{.density = 1.01e5 * 0.02896 / (8.314 * 293.0), .viscosity = 1.8e-5};
  const std::array<std::array<double, 3>, 4> dimensional{
      {{0.4, 0.5, 12255.452941}, {0.6, 0.5, 4188.344370}, {0.8, 0.5, 1147.828255}, {0.95, 1.0, 227.126998}}};
  for (const auto& [eps, w, beta] : dimensional)
    check_printed(Beetstra{}(state(eps, w, air_293_k)).pressure_gradient(), beta, 5e-7);
  // Seed 002 Sec. II.D conversion round trip at φ = 0.3, Re = 10: β = 2253.310967, β d²/μ = 31.29598565,
  // F_tot = 11.82765898.
  const auto s = at_reynolds(0.7, 10.0);
  const double beta = Beetstra{}(s).pressure_gradient();
  CHECK(beta == doctest::Approx(2253.310967).epsilon(1e-9));
  CHECK(beta * diameter * diameter / air.viscosity == doctest::Approx(31.29598565).epsilon(1e-9));
  CHECK(total_force(beta, s) == doctest::Approx(11.82765898).epsilon(1e-9));
}

TEST_CASE("Beetstra is VanDerHoef at Re = 0 exactly, and tends to it continuously") {
  for (double eps : {0.35, 0.5, 0.75, 0.95, 1.0 - 1e-9}) {
    INFO("eps=" << eps);
    CHECK(Beetstra{}(state(eps, 0.0)).pressure_gradient() == VanDerHoef{}(state(eps, 0.0)).pressure_gradient());
    double previous = std::numeric_limits<double>::infinity();
    for (double re : {1e-2, 1e-4, 1e-6, 1e-8}) {
      const double excess = Beetstra{}(at_reynolds(eps, re)).pressure_gradient() /
                                VanDerHoef{}(state(eps, 0.0)).pressure_gradient() -
                            1.0;
      if (re == 1e-2) CHECK(excess > 0.0);
      CHECK(excess >= 0.0);
      CHECK(excess <= previous);
      previous = excess;
    }
    CHECK(previous < 1e-10);
  }
}

// ------------------------------------------------------------------------ the codes, re-evaluated
TEST_CASE("conventions agree with a re-evaluation of the codes' formulas (not published data)") {
  // Air ρ = 1.2, μ = 1.8e-5, d = 500 µm, w = 0.5 m/s; β_pg at φ = 0.05, 0.2, 0.4, 0.55.
  const std::array<double, 4> voidages{0.95, 0.8, 0.6, 0.45};
  struct Expected {
    double value, half_unit;
  };
  const auto check_row = [&](const auto& law, const std::array<Expected, 4>& expected) {
    for (std::size_t k = 0; k < 4; ++k) {
      INFO(law.name() << " eps=" << voidages[k]);
      check_printed(law(state(voidages[k], 0.5)).pressure_gradient(), expected[k].value, expected[k].half_unit);
    }
  };
  check_row(Beetstra{}, {{{173.5, 0.05}, {1148, 0.5}, {4188, 0.5}, {9377, 0.5}}});
  check_row(Tang{}, {{{199, 0.5}, {1244, 0.5}, {4601, 0.5}, {1.079e4, 5}}});
  check_row(Tenneti{}, {{{169.1, 0.05}, {1119, 0.5}, {4138, 0.5}, {9240, 0.5}}});
  check_row(KochHill{}, {{{157.7, 0.05}, {1182, 0.5}, {3876, 0.5}, {9492, 0.5}}});
  check_row(SyamlalOBrien{}, {{{175.7, 0.05}, {1131, 0.5}, {3221, 0.5}, {5648, 0.5}}});

  // Tenneti's three code conventions at φ = 0.4 (tenneti.hpp): MFiX 25.2.1 = this/ε = 6897,
  // OpenFOAM 18 μ φ [F_iso + ε² (F_φ + F_φRe)]/d² = 3540, this law (waLBerla) 4138.
  const auto s = state(0.6, 0.5);
  const double beta = Tenneti{}(s).pressure_gradient();
  check_printed(beta / s.voidage, 6897, 0.5);
  const double re = particle_reynolds(air, diameter, s.voidage, s.slip);
  const double isolated = 1.0 + 0.15 * std::pow(re, 0.687);
  const double rest = total_force(beta, s) - isolated / std::pow(s.voidage, 3);
  check_printed(18 * air.viscosity * 0.4 * (isolated + s.voidage * s.voidage * rest) / (diameter * diameter), 3540,
                0.5);
}

// ------------------------------------------------------------------------ Tang 2015
TEST_CASE("Tang: van der Hoef at Re = 0, as published for Re <= 1000, positive beyond") {
  // Published F, transcribed independently of the header.
  const auto published = [](double phi, double re) {
    const double e = 1.0 - phi;
    return 10 * phi / (e * e) + e * e * (1 + 1.5 * std::sqrt(phi)) +
           (0.11 * phi * (1 + phi) - 0.00456 / std::pow(e, 4)) * re +
           (0.169 * e + 0.0644 / std::pow(e, 4)) * std::pow(re, 0.657);
  };
  for (double phi : {0.01, 0.1, 0.3, 0.5, 0.55, 0.6, 0.65, 0.8}) {
    const double eps = 1.0 - phi;
    INFO("phi=" << phi);
    CHECK(Tang{}(state(eps, 0.0)).pressure_gradient() == VanDerHoef{}(state(eps, 0.0)).pressure_gradient());
    for (double re : {1e-3, 0.1, 1.0, 10.0, 100.0, 500.0, 999.0, 1000.0}) {
      INFO("Re=" << re);
      CHECK(drag_force(Tang{}(at_reynolds(eps, re)).pressure_gradient(), at_reynolds(eps, re)) ==
            doctest::Approx(published(phi, re)).epsilon(1e-13));
    }
    // Beyond Re = 1000 the Re-dependent part grows in proportion to Re; F stays continuous.
    const double f0 = Tang::dimensionless_force(phi, 0.0);
    const double at_switch = Tang::dimensionless_force(phi, 1000.0);
    CHECK(Tang::dimensionless_force(phi, std::nextafter(1000.0, 2000.0)) ==
          doctest::Approx(at_switch).epsilon(1e-13));
    for (double re : {1001.0, 2000.0, 1e4, 1e6, 1e9}) {
      INFO("Re=" << re);
      const double f = Tang::dimensionless_force(phi, re);
      CHECK(f - f0 == doctest::Approx(re / 1000.0 * (at_switch - f0)).epsilon(1e-12));
      CHECK(f > at_switch);
    }
  }
  // Why the extension: the published Re-linear coefficient changes sign at φ = 0.52209 and the
  // published F is negative at φ = 0.6, Re = 10⁵ (it crosses zero at Re ≈ 3.49·10⁴).
  const auto linear = [](double phi) { return 0.11 * phi * (1 + phi) - 0.00456 / std::pow(1 - phi, 4); };
  CHECK(linear(0.5220) > 0.0);
  CHECK(linear(0.5222) < 0.0);
  CHECK(published(0.6, 1e5) < 0.0);
  CHECK(published(0.6, 3.4e4) > 0.0);
  CHECK(Tang{}(at_reynolds(0.4, 1e5)).pressure_gradient() > 0.0);
}

// ------------------------------------------------------------------------ Tenneti 2011
TEST_CASE("Tenneti: isolated-sphere limit F_tot → 1 + 0.15 Re^0.687 and the Hill normalisation") {
  for (double re : {0.0, 0.5, 10.0, 100.0, 300.0}) {
    const double isolated = 1.0 + 0.15 * std::pow(re, 0.687);
    INFO("Re=" << re);
    CHECK(Tenneti::dimensionless_force(0.0, re) == doctest::Approx(isolated).epsilon(1e-15));
    // F_φ ∝ φ^(1/3): at φ = 1e-15 the correction is 0.48·10⁻⁵.
    CHECK(Tenneti::dimensionless_force(1e-15, re) == doctest::Approx(isolated).epsilon(1e-5));
    for (double eps : {0.45, 0.8}) {
      const auto s = at_reynolds(eps, re);
      CHECK(total_force(Tenneti{}(s).pressure_gradient(), s) ==
            doctest::Approx(Tenneti::dimensionless_force(1.0 - eps, re)).epsilon(1e-14));
    }
  }
  // The Stokes limit is finite: F_tot(φ, 0) = 1/ε³ + 5.81 φ/ε³ + 0.48 φ^(1/3)/ε⁴.
  const double phi = 0.3, e = 0.7;
  CHECK(Tenneti::dimensionless_force(phi, 0.0) ==
        doctest::Approx(1 / std::pow(e, 3) + 5.81 * phi / std::pow(e, 3) + 0.48 * std::cbrt(phi) / std::pow(e, 4)));
}

// ------------------------------------------------------------------------ Koch–Hill
TEST_CASE("KochHill: dense Stokes limit 10φ/ε³ (the independent evaluation) and dilute limits") {
  // F0 = 10φ/ε³ for φ >= 0.4: 40 at ε = 0.5, 259.2592593 at ε = 0.3 (A_o = 180).
  for (const auto& [eps, f] : {std::array<double, 2>{0.5, 40.0}, std::array<double, 2>{0.3, 259.2592593}}) {
    const auto s = state(eps, 0.0);
    CHECK(total_force(KochHill{}(s).pressure_gradient(), s) == doctest::Approx(f).epsilon(1e-9));
    CHECK(18 * eps * eps * eps * f / (1 - eps) == doctest::Approx(180.0).epsilon(1e-9));
  }
  // φ <= 0.01: isolated sphere 1 + 3 Re_h/8 at low Re; the Stokes limit jumps to F0(0.01) = 1.2787573 above.
  CHECK(KochHill::dimensionless_force(0.005, 0.0) == 1.0);
  CHECK(KochHill::dimensionless_force(0.005, 0.2) == doctest::Approx(1.0 + 0.375 * 0.1).epsilon(1e-15));
  CHECK(KochHill::dimensionless_force(0.01, 0.0) == 1.0);
  CHECK(KochHill::dimensionless_force(0.01 + 1e-12, 0.0) == doctest::Approx(1.2787573398).epsilon(1e-9));
  // ε = 1: F = 1 at Re = 0 and 1 + 0.03667 Re_h beyond (the transition is at Re_h = 0).
  CHECK(KochHill::dimensionless_force(0.0, 0.0) == 1.0);
  CHECK(KochHill::dimensionless_force(0.0, 10.0) == doctest::Approx(1.0 + 0.03667 * 5.0).epsilon(1e-15));
}

TEST_CASE("KochHill: the transition discriminant stays positive and every switch is continuous") {
  // F3² − 4 F1 (F0 − F2) >= 0.23 F3² on (0.01, 1) (documented minimum at φ ≈ 0.387).
  double smallest = std::numeric_limits<double>::infinity();
  for (int k = 1; k < 99000; ++k) {
    const double phi = 0.01 + k * 1e-5;
    const double f3 = KochHill::f3(phi);
    smallest =
        std::min(smallest, (f3 * f3 - 4.0 * KochHill::f1(phi) * (KochHill::f0(phi) - KochHill::f2(phi))) / (f3 * f3));
    REQUIRE(KochHill::transition_reynolds(phi) > 0.0);
  }
  CHECK(smallest > 0.2);
  CHECK(smallest < 0.24);
  // Continuous across the branch switch Re_T (dense) and Re_T1 (dilute).
  for (double phi : {0.002, 0.01, 0.02, 0.09, 0.2, 0.387, 0.39, 0.5, 0.7}) {
    const double re_t = 2.0 * KochHill::transition_reynolds(phi);
    INFO("phi=" << phi << " Re_T=" << re_t);
    CHECK(KochHill::dimensionless_force(phi, re_t * (1 - 1e-12)) ==
          doctest::Approx(KochHill::dimensionless_force(phi, re_t * (1 + 1e-12))).epsilon(1e-10));
  }
  // Continuous at φ = 0.4 (blend weight 1 there), for every Re.
  for (double re : {0.0, 1.0, 5.0, 50.0, 500.0}) {
    INFO("Re=" << re);
    CHECK(KochHill::dimensionless_force(std::nextafter(0.4, 0.0), re) ==
          doctest::Approx(KochHill::dimensionless_force(0.4, re)).epsilon(1e-12));
  }
}

// ------------------------------------------------------------------------ Syamlal–O'Brien
TEST_CASE("SyamlalOBrien: velocity ratio limits, Garside–Al-Dibouni identity, published form") {
  const SyamlalOBrien law;
  CHECK(law.velocity_ratio(1.0, 0.0) == 1.0);
  for (double eps : {0.4, 0.6, 0.85, 0.9, 0.99}) {
    const double a = std::pow(eps, 4.14);
    const double b = eps <= 0.85 ? 0.8 * std::pow(eps, 1.28) : std::pow(eps, 2.65);
    INFO("eps=" << eps);
    CHECK(law.velocity_ratio(eps, 0.0) == doctest::Approx(a).epsilon(1e-15));
    CHECK(law.velocity_ratio(eps, 1e14) == doctest::Approx(b).epsilon(1e-9));
    for (double re_s : {1e-3, 1.0, 30.0, 1e3, 1e6}) {
      // V_r (1 + 0.06 Re_t) = A + 0.06 B Re_t with Re_t = Re_s/V_r.
      const double vr = law.velocity_ratio(eps, re_s);
      const double re_t = re_s / vr;
      CHECK(vr * (1 + 0.06 * re_t) == doctest::Approx(a + 0.06 * b * re_t).epsilon(1e-13));
      if (re_s <= 1e3) {  // the published closed form (cancels digits at large Re_s)
        const double x = 0.06 * re_s;
        CHECK(vr ==
              doctest::Approx(0.5 * (a - x + std::sqrt(x * x + 0.12 * re_s * (2 * b - a) + a * a))).epsilon(1e-12));
      }
    }
    // Stokes limit β = 17.28 μ φ ε^−3.14/d² (V_r = A); published form ¾ C_D φ ε ρ w/(V_r² d) with
    // Re_s = ρ w d/μ (no ε) at finite slip.
    CHECK(law(state(eps, 0.0)).pressure_gradient() ==
          doctest::Approx(17.28 * air.viscosity * (1 - eps) * std::pow(eps, -3.14) / (diameter * diameter))
              .epsilon(1e-13));
    const double w = 0.7;
    const double re_s = air.density * w * diameter / air.viscosity;
    const double vr = law.velocity_ratio(eps, re_s);
    const double cd = std::pow(0.63 + 4.8 / std::sqrt(re_s / vr), 2);
    CHECK(law(state(eps, w)).pressure_gradient() ==
          doctest::Approx(0.75 * cd * (1 - eps) * eps * air.density * w / (vr * vr * diameter)).epsilon(1e-13));
  }
}

TEST_CASE("SyamlalOBrien: continuity at ε = 0.85 needs c1 = 0.85^(d1 − 1.28)") {
  const auto continuous = SyamlalOBrien::continuous_at_switch(2.65);
  CHECK(continuous.c1() == doctest::Approx(0.8003941914).epsilon(1e-10));
  const double above = std::nextafter(0.85, 1.0);
  for (double w : {0.0, 0.5, 50.0}) {
    INFO("w=" << w);
    CHECK(continuous(state(above, w)).pressure_gradient() ==
          doctest::Approx(continuous(state(0.85, w)).pressure_gradient()).epsilon(1e-12));
    // The defaults (0.8, 2.65) mismatch B by 0.049 %: β jumps by up to twice that (β ∝ V_r⁻², V_r → B).
    const double jump =
        SyamlalOBrien{}(state(above, w)).pressure_gradient() / SyamlalOBrien{}(state(0.85, w)).pressure_gradient() - 1;
    CHECK(std::abs(jump) < 1e-3);
    if (w > 10) CHECK(std::abs(jump) > 1e-4);
  }
}

TEST_CASE("SyamlalOBrien: calibration from minimum fluidization recovers the law that produced u_mf") {
  const Fluid<double> fluid{.density = 1.2, .viscosity = 1.8e-5};
  const Particles<double> particles{.density = 2500.0, .diameter = 5e-4};
  const double g = 9.81;
  struct Case {
    SyamlalOBrien truth;
    double eps_mf;
  };
  for (const Case& c :
       {Case{SyamlalOBrien::continuous_at_switch(3.1), 0.42}, Case{SyamlalOBrien::continuous_at_switch(2.4), 0.6},
        Case{SyamlalOBrien::continuous_at_switch(2.9), 0.9}}) {
    const SyamlalOBrien& truth = c.truth;
    const double eps_mf = c.eps_mf;
    // u_mf from the force balance β w = φ ε (ρ_p − ρ_f) g, solved numerically with the law itself.
    const auto residual = [&](double w) {
      const auto s = state(eps_mf, w, fluid, particles.diameter);
      return truth(s).pressure_gradient() * w - (1 - eps_mf) * eps_mf * (particles.density - fluid.density) * g;
    };
    std::uintmax_t iterations = 200;
    const auto [lo, hi] = boost::math::tools::toms748_solve(residual, 1e-8, 1e3,
                                                            boost::math::tools::eps_tolerance<double>(52), iterations);
    const double u_mf = eps_mf * 0.5 * (lo + hi);
    const auto calibrated = fluidization::syamlal_obrien_from_minimum_fluidization(u_mf, eps_mf, fluid, particles, g);
    INFO("eps_mf=" << eps_mf << " u_mf=" << u_mf);
    CHECK(calibrated.c1() == doctest::Approx(truth.c1()).epsilon(1e-9));
    CHECK(calibrated.d1() == doctest::Approx(truth.d1()).epsilon(1e-9));
  }
  // The defaults' d1 is what continuity gives for c1 = 0.8: 1.28 + ln 0.8/ln 0.85 = 2.653.
  CHECK(1.28 + std::log(0.8) / std::log(0.85) == doctest::Approx(2.653).epsilon(1e-3));
  CHECK_THROWS_WITH_AS(fluidization::syamlal_obrien_from_minimum_fluidization(1e-6, 0.42, fluid, particles, g),
                       doctest::Contains("'minimum_fluidization_velocity'"), std::domain_error);
  CHECK_THROWS_WITH_AS(fluidization::syamlal_obrien_from_minimum_fluidization(0.2, 1.0, fluid, particles, g),
                       doctest::Contains("'minimum_fluidization_voidage' = 1"), std::domain_error);
  CHECK_THROWS_WITH_AS(
      fluidization::syamlal_obrien_from_minimum_fluidization(0.2, 0.42, fluid, {.density = 1.0, .diameter = 5e-4}, g),
      doctest::Contains("'particles.density' = 1"), std::domain_error);
}

// ------------------------------------------------------------------------ polydisperse
namespace {

std::vector<Species<double>> mixture(std::vector<double> fractions, std::vector<double> diameters) {
  std::vector<Species<double>> m;
  for (std::size_t j = 0; j < fractions.size(); ++j) m.push_back({fractions[j], diameters[j]});
  return m;
}

PolydisperseDragState<double> species_state(const std::vector<Species<double>>& m, std::size_t i, double slip,
                                            const Fluid<double>& fluid = air) {
  return {.mixture = m, .species = i, .slip = slip, .fluid = fluid};
}

}  // namespace

TEST_CASE("Beetstra polydisperse: mixture moments and correction factors (the independent evaluation)") {
  struct Row {
    std::vector<double> phi, d;
    double sauter;
    std::array<double, 2> y, f_cubic, f_plain;
    double sum_cubic;
  };
  const std::array<Row, 2> rows{
      Row{{0.2, 0.2}, {5e-4, 2e-3}, 8.0e-4, {0.625, 2.5}, {0.540625, 4.6}, {0.53125, 4.0}, 1.06},
      Row{{0.3, 0.1}, {1e-3, 2e-3}, 1.142857143e-3, {0.875, 1.75}, {0.856975, 2.4808}, {0.83125, 2.275}, 1.042}};
  for (const Row& r : rows) {
    const auto m = mixture(r.phi, r.d);
    const auto moments = mixture_moments<double>(m);
    const double eps = 1.0 - moments.solid_fraction;
    CHECK(moments.sauter_diameter == doctest::Approx(r.sauter).epsilon(1e-9));
    double sum_cubic = 0, sum_plain = 0, sum_pg = 0;
    for (std::size_t i = 0; i < 2; ++i) {
      const double y = r.d[i] / moments.sauter_diameter;
      const double x = r.phi[i] / moments.solid_fraction;
      CHECK(y == doctest::Approx(r.y[i]).epsilon(1e-14));
      const auto cubic = BeetstraPolydisperse::published().correction(eps, y);
      const auto plain = BeetstraPolydisperse::without_cubic_term().correction(eps, y);
      CHECK(cubic.classical == doctest::Approx(r.f_cubic[i]).epsilon(1e-14));
      CHECK(plain.classical == doctest::Approx(r.f_plain[i]).epsilon(1e-14));
      CHECK(cubic.pressure_gradient == y);
      sum_cubic += x * cubic.classical / (y * y);
      sum_plain += x * plain.classical / (y * y);
      sum_pg += x * cubic.pressure_gradient / (y * y);
    }
    CHECK(sum_cubic == doctest::Approx(r.sum_cubic).epsilon(1e-3));  // 1 + 0.064 ε Σ x y
    CHECK(sum_plain == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(sum_pg == doctest::Approx(1.0).epsilon(1e-14));
  }
}

TEST_CASE("Beetstra polydisperse: monodisperse, split and total-drag identities") {
  const auto published = BeetstraPolydisperse::published();
  const auto plain = BeetstraPolydisperse::without_cubic_term();
  CHECK(published.name() == "BeetstraPolydisperse");
  CHECK(BeetstraPolydisperse{}.name() == "BeetstraPolydisperse");
  CHECK(plain.name() == "BeetstraPolydisperseNoCubic");
  for (double w : {0.0, 0.05, 0.5, 5.0}) {
    INFO("w=" << w);
    // Two species of one diameter: a split of the monodisperse law.
    const auto same = mixture({0.1, 0.2}, {diameter, diameter});
    const auto mono = Beetstra{}(state(0.7, w));
    for (std::size_t i = 0; i < 2; ++i) {
      const double x = same[i].volume_fraction / 0.3;
      CHECK(published(species_state(same, i, w)).pressure_gradient() ==
            doctest::Approx(x * mono.pressure_gradient()).epsilon(1e-14));
      CHECK(plain(species_state(same, i, w)).classical() == doctest::Approx(x * mono.classical()).epsilon(1e-14));
      // The published y³ term makes model B (1 + 0.064 ε) times the monodisperse law.
      CHECK(published(species_state(same, i, w)).classical() ==
            doctest::Approx(x * mono.classical() * (1 + 0.064 * 0.7)).epsilon(1e-14));
    }
    // Different diameters: the total drag is the monodisperse law at the Sauter mean diameter
    // (model A always, model B without the y³ term), and model B = model A + φ_i/ε Σ_j model A.
    const auto m = mixture({0.25, 0.05, 0.1}, {3e-4, 1.2e-3, 6e-4});
    const auto moments = mixture_moments<double>(m);
    const double eps = 1 - moments.solid_fraction;
    const auto at_mean = Beetstra{}(state(eps, w, air, moments.sauter_diameter));
    double total_pg = 0, total_cl = 0;
    for (std::size_t i = 0; i < m.size(); ++i) {
      total_pg += published(species_state(m, i, w)).pressure_gradient();
      total_cl += plain(species_state(m, i, w)).classical();
    }
    CHECK(total_pg == doctest::Approx(at_mean.pressure_gradient()).epsilon(1e-13));
    CHECK(total_cl == doctest::Approx(at_mean.classical()).epsilon(1e-13));
    for (std::size_t i = 0; i < m.size(); ++i)
      CHECK(plain(species_state(m, i, w)).classical() ==
            doctest::Approx(plain(species_state(m, i, w)).pressure_gradient() + m[i].volume_fraction / eps * total_pg)
                .epsilon(1e-13));
  }
  // An absent species has no drag.
  const auto m = mixture({0.3, 0.0}, {5e-4, 1e-3});
  CHECK(published(species_state(m, 1, 0.4)).classical() == 0.0);
  // The same operations on the same numbers, but clang -O3 folds one path's pow at compile time
  // and calls libm on the other: equal to an ulp or two, not to the bit.
  CHECK(published(species_state(m, 0, 0.4)).pressure_gradient() ==
        doctest::Approx(Beetstra{}(state(0.7, 0.4)).pressure_gradient()).epsilon(4e-16));
}

TEST_CASE("Beetstra polydisperse agrees with the independent mpmath table (polydisperse_reference.csv)") {
  const test::ReferenceTable table("polydisperse_reference.csv");
  REQUIRE(table.size() > 10);
  for (std::size_t row = 0; row < table.size(); ++row) {
    const auto m = mixture({table.number(row, "phi1"), table.number(row, "phi2")},
                           {table.number(row, "d1"), table.number(row, "d2")});
    const auto s = species_state(
        m, static_cast<std::size_t>(table.number(row, "species")) - 1, table.number(row, "slip"),
        {.density = table.number(row, "fluid_density"), .viscosity = table.number(row, "fluid_viscosity")});
    const auto beta = BeetstraPolydisperse{}(s);
    INFO("case " << table.text(row, "case") << " species " << table.text(row, "species"));
    CHECK(mixture_moments<double>(m).sauter_diameter ==
          doctest::Approx(table.number(row, "sauter_diameter")).epsilon(1e-14));
    CHECK(beta.classical() == doctest::Approx(table.number(row, "beta_classical")).epsilon(1e-12));
    CHECK(beta.pressure_gradient() == doctest::Approx(table.number(row, "beta_pressure_gradient")).epsilon(1e-12));
    CHECK(beta.in(Buoyancy::classical) == beta.classical());
  }
}

TEST_CASE("Beetstra polydisperse: derivatives (ε at fixed composition, species slip) and the checked entry") {
  const BeetstraPolydisperse law;
  const std::vector<double> x{0.5, 0.2, 0.3};
  const std::vector<double> d{3e-4, 1.2e-3, 6e-4};
  const auto at = [&](double eps) {
    std::vector<double> phi;
    for (double xi : x) phi.push_back(xi * (1 - eps));
    return mixture(phi, d);
  };
  const double h = 1e-6;
  for (double eps : {0.45, 0.7, 0.9})
    for (double w : {0.01, 0.3, 3.0})
      for (std::size_t i = 0; i < 3; ++i) {
        const auto m = at(eps);
        const auto with = law.with_derivatives(species_state(m, i, w));
        const auto mp = at(eps * (1 + h));
        const auto mm = at(eps * (1 - h));
        for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
          const DragDerivatives<double> dd = with.in(b);
          const double fd_eps = (law(species_state(mp, i, w)).in(b)-law(species_state(mm, i, w)).in(b)) / (2 * h * eps);
          const double fd_w =
              (law(species_state(m, i, w * (1 + h))).in(b)-law(species_state(m, i, w * (1 - h))).in(b)) / (2 * h * w);
          INFO("eps=" << eps << " w=" << w << " species " << i);
          CHECK(test::same_arithmetic(dd.value, law(species_state(m, i, w)).in(b)));
          CHECK(dd.d_voidage == doctest::Approx(fd_eps).epsilon(1e-6).scale(dd.value));
          CHECK(dd.d_slip * w == doctest::Approx(fd_w * w).epsilon(1e-6).scale(dd.value));
        }
      }
  // Zero slip: finite value and force derivative, no NaN.
  const auto m = at(0.6);
  const auto rest = law.with_derivatives(species_state(m, 1, 0.0));
  for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
    CHECK(!std::isnan(rest.in(b).d_voidage));
    CHECK(!std::isnan(rest.in(b).d_slip));
    CHECK(rest.force_slip_derivative(b) == rest.in(b).value);
    CHECK(rest.coefficient().in(b) == rest.in(b).value);
  }

  const auto bad = [&](const std::vector<Species<double>>& mix, std::size_t i, double w, const char* expected,
                       const Fluid<double>& fluid = air) {
    CHECK_THROWS_WITH_AS(law.checked(species_state(mix, i, w, fluid)), doctest::Contains(expected), std::domain_error);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  bad(mixture({0.2, 0.2}, {5e-4, 1e-3}), 2, 0.1, "'species' = 2");
  bad(mixture({}, {}), 0, 0.1, "'species' = 0");
  bad(mixture({0.2, -0.1}, {5e-4, 1e-3}), 0, 0.1, "'mixture[1].volume_fraction' = -0.1");
  bad(mixture({0.2, 0.2}, {5e-4, nan}), 0, 0.1, "'mixture[1].diameter' = nan");
  bad(mixture({0.6, 0.4}, {5e-4, 1e-3}), 0, 0.1, "'sum of mixture volume fractions' = 1");
  bad(mixture({0.0, 0.0}, {5e-4, 1e-3}), 0, 0.1, "'sum of mixture volume fractions' = 0");
  bad(mixture({0.2, 0.2}, {5e-4, 1e-3}), 0, -1.0, "'slip' = -1");
  bad(mixture({0.2, 0.2}, {5e-4, 1e-3}), 0, 0.1, "'fluid.density' = 0", {.density = 0.0, .viscosity = 1e-5});
  CHECK_THROWS_WITH(law.checked(species_state(mixture({0.2}, {0.0}), 0, 0.1)),
                    doctest::Contains("fluidbed::BeetstraPolydisperse"));
  const auto good = mixture({0.2, 0.2}, {5e-4, 1e-3});
  CHECK(law.checked(species_state(good, 1, 0.1)).classical() == law(species_state(good, 1, 0.1)).classical());
}
