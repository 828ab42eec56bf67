// Niemi's solids-mixture DQMOM (polydisperse/mixture_dqmom.hpp; seed 001 Ch. 5).
//
// The class velocities of seed 001 eq. 112 (eqs. 115/116 for two and three classes): four cells
// (binary bottom, binary dilute, binary dense on Gidaspow's Ergun branch, three classes of the
// thesis's Table 3), against an independent solution with the closures written out from their
// formulas (mpmath 1.3 at 40 digits, findroot; the script is at the end of this file) and against
// the same solution rounded as it was tabulated when the library's seed 001 reference values were
// collected; the residual of eq. 112 evaluated here from the laws directly; the identities the
// equations imply (identical classes, a class split in two, a tracer class, permutations, 3-D
// symmetry and rotations); the analytic Jacobian against finite differences; statuses and the
// error policy. Gas: air as FLUENT's defaults (ρ_g = 1.225 kg/m³, μ_g = 1.7894e-5 Pa s; the
// thesis gives no gas properties), glass beads of 2480 kg/m³ (seed 001 §6.4).
//
// The consistency correction of seed 001 §5.3 (eqs. 120–122): the thesis's Figure 8 example step
// by step against the exact rational values of the procedure (Python fractions, quoted below),
// the figure's rounded numbers, the relative errors after each normalisation, the tolerance stop,
// cell volumes, incompatible totals and invalid input.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "cpp_bin_float_50.hpp"
#include "fluidbed/polydisperse/mixture_dqmom.hpp"

using namespace fluidbed;
using namespace fluidbed::polydisperse;

namespace {

constexpr double glass = 2480;  // kg/m³
template <class T>
constexpr Fluid<T> air() {
  return {T(1.225L), T(1.7894e-5L)};
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

// One cell of the table: inputs, the independent solution (17 significant digits) and the
// values as tabulated (rounded; the tolerance of each is half a unit of its last digit).
struct Case {
  const char* name;
  int n;
  std::array<double, 3> alpha, diameter;
  double gas_velocity, solids_velocity;
  // mpmath, 40 digits, rounded to 17
  double sauter, mixture_drag;
  std::array<double, 3> velocity;
  double flux_mismatch;  // Σ α_q v_q/α_s − v_s
  // as tabulated
  double sauter_um, mixture_drag_tabulated, mixture_drag_half_unit;
  std::array<double, 3> velocity_tabulated;  // 8 decimals
  double flux_tabulated, flux_half_unit;
};

const Case cases[] = {
    {"binary bottom", 2, {0.117, 0.033, 0}, {255e-6, 416e-6, 0}, 4.0, 1.8,
     2.7873246098060854e-4, 2629.1107052199385, {1.8302165784961068, 1.7741159858691989, 0}, 0.017874448118187025,
     278.7325, 2629.1107, 5e-5, {1.83021658, 1.77411599, 0}, 1.787e-2, 5e-6},
    {"binary dilute", 2, {0.0078, 0.0022, 0}, {255e-6, 416e-6, 0}, 2.5, 0.5,
     2.7873246098060854e-4, 119.99701223600917, {0.5485492612379355, 0.32558711521866691, 0}, -5.0241088630358884e-4,
     278.7325, 119.99701, 5e-6, {0.54854926, 0.32558712, 0}, -5.02e-4, 5e-7},
    {"binary dense (Ergun branch)", 2, {0.234, 0.066, 0}, {255e-6, 416e-6, 0}, 1.0, 0.2,
     2.7873246098060854e-4, 6287.7487476129723, {0.2156940971436865, 0.19517285485863491, 0}, 0.011179423840975149,
     278.7325, 6287.7487, 5e-5, {0.21569410, 0.19517285, 0}, 1.118e-2, 5e-6},
    {"three classes (seed 001 Table 3 fractions x 0.15)", 3, {0.04155, 0.10035, 0.0081}, {206e-6, 336e-6, 541e-6},
     4.0, 1.8, 2.9107448219348156e-4, 2457.2173360869143,
     {1.8843731317647228, 1.8259023420417068, 1.77983574265348}, 0.039611154428017951,
     291.0745, 2457.2173, 5e-5, {1.88437313, 1.82590234, 1.77983574}, 3.961e-2, 5e-6},
};

MixtureCell<double> cell_of(const Case& c, std::span<const double> alpha, std::span<const double> diameter) {
  return {alpha, diameter, glass, air<double>(), c.gas_velocity, c.solids_velocity};
}

// The relative residual of eq. 112 in its printed (unscaled) form, evaluated from the library's
// laws directly: max_q |LHS_q − RHS_q| / (|K_gq (v_g − v_q)| + Σ_p |K'_pq (v_p − v_q)| + |RHS_q|).
double eq112_residual(std::span<const double> alpha, std::span<const double> d, double vg, double vs,
                      std::span<const double> v) {
  const drag::GidaspowSwitched gidaspow;
  const kinetic_theory::SyamlalSolidSolidDrag syamlal{0.0};
  double alpha_s = 0, inverse = 0;
  for (std::size_t q = 0; q < alpha.size(); ++q) {
    alpha_s += alpha[q];
    inverse += alpha[q] / d[q];
  }
  const double eps = 1 - alpha_s, g0 = kinetic_theory::Ogawa{0.63}(alpha_s);
  const double kgs = gidaspow(drag::DragState<double>{eps, std::abs(vg - vs), air<double>(), alpha_s / inverse})
                         .pressure_gradient();
  double worst = 0;
  for (std::size_t q = 0; q < alpha.size(); ++q) {
    const double kgq = alpha[q] / alpha_s *
                       gidaspow(drag::DragState<double>{eps, std::abs(vg - v[q]), air<double>(), d[q]})
                           .pressure_gradient();
    double lhs = kgq * (vg - v[q]), scale = std::abs(lhs);
    for (std::size_t p = 0; p < alpha.size(); ++p) {
      if (p == q) continue;
      const double k = syamlal(alpha[p], alpha[q], Particles<double>{glass, d[p]}, Particles<double>{glass, d[q]},
                               0.9, g0, std::abs(v[p] - v[q]));
      lhs += k * (v[p] - v[q]);
      scale += std::abs(k * (v[p] - v[q]));
    }
    const double rhs = alpha[q] / alpha_s * kgs * (vg - vs);
    worst = std::max(worst, std::abs(lhs - rhs) / (scale + std::abs(rhs)));
  }
  return worst;
}

template <class T, int N>
std::vector<double> velocities_of(const ForceBalanceResult<T, T, N>& r) {
  return std::vector<double>(r.velocities.begin(), r.velocities.begin() + r.size);
}

}  // namespace

TEST_CASE("mixture force balance: the four cells of eqs. 115/116 against an independent 40-digit solution") {
  for (const Case& c : cases) {
    INFO(std::string(c.name));
    const std::span<const double> alpha(c.alpha.data(), c.n), d(c.diameter.data(), c.n);
    const auto r = solve_force_balance<4>(niemi_force_balance, cell_of(c, alpha, d));
    REQUIRE(r.status == ForceBalanceStatus::converged);
    REQUIRE(r.size == c.n);
    MESSAGE(std::string(c.name) << ": " << r.iterations << " Newton iterations from the frozen-coefficient start, residual "
                   << r.residual);
    CHECK(r.iterations <= 4);
    CHECK(r.residual <= ForceBalanceOptions<double>{}.tolerance);
    CHECK(relative(r.sauter_diameter, c.sauter) < 1e-15);
    CHECK(relative(r.mixture_drag, c.mixture_drag) < 1e-14);
    double flux = 0;
    for (int q = 0; q < c.n; ++q) {
      CHECK(relative(r.velocities[q], c.velocity[q]) < 1e-13);
      flux += c.alpha[q] * r.velocities[q];
    }
    flux = flux / r.solids_fraction - c.solids_velocity;
    // Eq. 97 does not hold: the volume-weighted class velocity is not v_s.
    CHECK(relative(flux, c.flux_mismatch) < 1e-11);
    CHECK(std::abs(flux) > 1e-4);

    // As tabulated (rounded): d_SMD in µm to 4 decimals, K_gs, v_q to 8 decimals, the mismatch.
    CHECK(std::abs(r.sauter_diameter * 1e6 - c.sauter_um) <= 5e-5);
    CHECK(std::abs(r.mixture_drag - c.mixture_drag_tabulated) <= c.mixture_drag_half_unit);
    for (int q = 0; q < c.n; ++q) CHECK(std::abs(r.velocities[q] - c.velocity_tabulated[q]) <= 5e-9);
    CHECK(std::abs(flux - c.flux_tabulated) <= c.flux_half_unit);

    // The residual of eq. 112 as printed, from the laws directly.
    const auto v = velocities_of(r);
    CHECK(eq112_residual(alpha, d, c.gas_velocity, c.solids_velocity, v) <= 1e-10);
    CHECK(eq112_residual(alpha, d, c.gas_velocity, c.solids_velocity, v) <= 1e-14);
  }
}

TEST_CASE("mixture force balance: the preset's closures (K'_12, g0, Gidaspow branch and convention)") {
  const auto& model = niemi_force_balance;
  // Binary bottom, |Δv| = 0.1 m/s: K'_12 = 18243.04613 with C_f = 0 and 19675.85162 with C_f = 0.1
  // (evaluated independently at 40 digits) with g_12 = g0(α_s = 0.15) of seed 001 eq. 24,
  // α_max = 0.63.
  const Particles<double> small{glass, 255e-6}, large{glass, 416e-6};
  const double g0 = model.radial_distribution(0.15);
  CHECK(g0 == doctest::Approx(2.630181450574105).epsilon(1e-14));
  const double k12 = model.solid_solid_drag(0.117, 0.033, small, large, model.restitution, g0, 0.1);
  CHECK(std::abs(k12 - 18243.04613) <= 5e-6);
  const kinetic_theory::SyamlalSolidSolidDrag with_friction{0.1};
  CHECK(std::abs(with_friction(0.117, 0.033, small, large, model.restitution, g0, 0.1) - 19675.85162) <= 5e-6);
  // No other one-class contact value of the library gives it (within 5 %).
  const double others[] = {kinetic_theory::CarnahanStarling{}(0.15), kinetic_theory::PercusYevick{}(0.15),
                           kinetic_theory::LunSavage{0.63}(0.15), kinetic_theory::MaAhmadi{}(0.15),
                           kinetic_theory::GidaspowRadialDistribution{0.63}(0.15)};
  for (double g : others) CHECK(std::abs(g / g0 - 1) > 0.05);

  // K_gs of the dense cell (α_s = 0.3 >= 0.2) is Ergun's, of the others Wen–Yu's, in the
  // pressure-gradient convention: seed 001 eqs. 41/42 as printed (α_s(1 − α_g) μ_g/α_g, α_g^−2.65).
  for (const Case& c : cases) {
    const std::span<const double> alpha(c.alpha.data(), c.n), d(c.diameter.data(), c.n);
    const auto r = solve_force_balance<4>(model, cell_of(c, alpha, d));
    const double as = r.solids_fraction, ag = 1 - as, w = c.gas_velocity - c.solids_velocity, ds = r.sauter_diameter;
    const double mu = 1.7894e-5, rho = 1.225;
    double expected;
    if (as >= 0.2) {
      expected = 150 * as * (1 - ag) * mu / (ag * ds * ds) + 1.75 * rho * as * w / ds;
    } else {
      const double re = ag * rho * w * ds / mu, cd = 24 / re * (1 + 0.15 * std::pow(re, 0.687));
      expected = 0.75 * cd * as * ag * rho * w / ds * std::pow(ag, -2.65);
    }
    CHECK(relative(r.mixture_drag, expected) < 1e-13);
  }
}

namespace {

// Gidaspow's β in the classical convention (β_pg/ε) passed off as a pressure-gradient one: what a
// host gets by feeding the other convention into eq. 112.
struct GidaspowClassicalAsPressureGradient : drag::DragLaw<GidaspowClassicalAsPressureGradient> {
  static constexpr drag::Buoyancy native_buoyancy = drag::Buoyancy::pressure_gradient;
  constexpr std::string_view name() const { return "GidaspowClassicalAsPressureGradient"; }
  constexpr std::string_view reference() const { return "test only"; }
  constexpr drag::ValidityRange validity() const { return {0.36, 1.0, 0.0, 1.0e5}; }
  template <class S, class T>
  S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    return drag::GidaspowSwitched{}.native_beta(voidage, slip, fluid, diameter) / voidage;
  }
};

}  // namespace

TEST_CASE("mixture force balance: only the pressure-gradient Gidaspow with K_gq = (alpha_q/alpha_s) beta(d_q) "
          "reproduces the table") {
  const Case& c = cases[0];
  const std::span<const double> alpha(c.alpha.data(), 2), d(c.diameter.data(), 2);
  const MixtureForceBalance<GidaspowClassicalAsPressureGradient> classical{
      {}, kinetic_theory::Ogawa{0.63}, kinetic_theory::SyamlalSolidSolidDrag{0.0}, 0.9};
  const auto r = solve_force_balance<2>(classical, cell_of(c, alpha, d));
  REQUIRE(r.status == ForceBalanceStatus::converged);
  // Independent 40-digit solution with both K's divided by α_g: 1.830784004, 1.770034922.
  CHECK(std::abs(r.velocities[0] - 1.830784004) < 1e-9);
  CHECK(std::abs(r.velocities[1] - 1.770034922) < 1e-9);
  CHECK(std::abs(r.velocities[0] - c.velocity_tabulated[0]) > 5e-4);
}

TEST_CASE("mixture force balance: float and long double") {
  const Case& c = cases[0];
  {
    const std::array<float, 2> alpha{0.117f, 0.033f}, d{255e-6f, 416e-6f};
    const MixtureCell<float> cell{alpha, d, 2480.0f, air<float>(), 4.0f, 1.8f};
    const auto r = solve_force_balance<2>(niemi_force_balance, cell);
    REQUIRE(r.status == ForceBalanceStatus::converged);
    CHECK(r.residual <= 64 * std::numeric_limits<float>::epsilon());
    for (int q = 0; q < 2; ++q) CHECK(std::abs(r.velocities[q] - c.velocity[q]) < 1e-6);
  }
  {
    const std::array<long double, 2> alpha{0.117L, 0.033L}, d{255e-6L, 416e-6L};
    const MixtureCell<long double> cell{alpha, d, 2480.0L, air<long double>(), 4.0L, 1.8L};
    const auto r = solve_force_balance<2>(niemi_force_balance, cell);
    REQUIRE(r.status == ForceBalanceStatus::converged);
    CHECK(r.residual <= 64 * std::numeric_limits<long double>::epsilon());
    // 21 digits of the independent solution.
    const long double expected[] = {1.83021657849610676537L, 1.77411598586919885244L};
    const long double tolerance = std::numeric_limits<long double>::epsilon() <
                                          std::numeric_limits<double>::epsilon()
                                      ? 1e-16L
                                      : 1e-13L;
    for (int q = 0; q < 2; ++q)
      CHECK(std::abs(r.velocities[q] - expected[q]) / expected[q] < tolerance);
    CHECK(std::abs(r.mixture_drag - 2629.11070521993847399L) / 2629.11070521993847399L < tolerance);
  }
}

TEST_CASE("mixture force balance: 50 digits (Boost.Multiprecision)") {
  using F = boost::multiprecision::cpp_bin_float_50;
  const std::array<F, 2> alpha{F("0.117"), F("0.033")}, d{F("255e-6"), F("416e-6")};
  const MixtureCell<F> cell{alpha, d, F(2480), Fluid<F>{F("1.225"), F("1.7894e-5")}, F(4), F("1.8")};
  const auto r = solve_force_balance<2>(niemi_force_balance, cell);
  REQUIRE(r.status == ForceBalanceStatus::converged);
  CHECK(r.residual <= F("1e-45"));
  // The closures' run-time parameters (e = 0.9, α_max = 0.63) are doubles, so the solution agrees
  // with the 40-digit one to their precision, ~1e-17.
  const F expected[] = {F("1.83021657849610676537"), F("1.77411598586919885244")};
  for (int q = 0; q < 2; ++q) CHECK(abs(r.velocities[q] - expected[q]) / expected[q] < F("1e-16"));
}

TEST_CASE("mixture force balance: identities of eq. 112") {
  const Case& bottom = cases[0];
  const std::span<const double> alpha2(bottom.alpha.data(), 2), d2(bottom.diameter.data(), 2);
  const auto binary = solve_force_balance<4>(niemi_force_balance, cell_of(bottom, alpha2, d2));
  REQUIRE(binary.status == ForceBalanceStatus::converged);

  SUBCASE("identical classes move with the mixture: v_q = v_s (and then eq. 97 holds), from the start") {
    // All K'(v_p − v_q) vanish and K_gq = (α_q/α_s) K_gs when every d_q = d_s.
    const std::array<double, 3> alpha{0.05, 0.07, 0.03}, d{300e-6, 300e-6, 300e-6};
    for (double vg : {4.0, -1.0, 1.8}) {
      const MixtureCell<double> cell{alpha, d, glass, air<double>(), vg, 1.8};
      const auto r = solve_force_balance<3>(niemi_force_balance, cell);
      REQUIRE(r.status == ForceBalanceStatus::converged);
      CHECK(r.iterations == 0);
      for (int q = 0; q < 3; ++q) CHECK(std::abs(r.velocities[q] - 1.8) <= 1e-14 * (1 + std::abs(vg - 1.8)));
    }
  }
  SUBCASE("a class split into two identical halves: the same velocities") {
    // K_gq and K'_pq are proportional to α_q, and α_s, d_s, g0 are unchanged.
    const std::array<double, 3> alpha{0.117, 0.0165, 0.0165}, d{255e-6, 416e-6, 416e-6};
    const auto r = solve_force_balance<4>(niemi_force_balance, cell_of(bottom, alpha, d));
    REQUIRE(r.status == ForceBalanceStatus::converged);
    CHECK(relative(r.velocities[0], binary.velocities[0]) < 1e-14);
    CHECK(relative(r.velocities[1], binary.velocities[1]) < 1e-14);
    CHECK(relative(r.velocities[2], binary.velocities[1]) < 1e-14);
  }
  SUBCASE("a class with alpha_q = 0 is a tracer: the others unchanged, its own velocity the limit") {
    const std::array<double, 3> alpha{0.117, 0.033, 0.0}, d{255e-6, 416e-6, 330e-6};
    const auto r = solve_force_balance<4>(niemi_force_balance, cell_of(bottom, alpha, d));
    REQUIRE(r.status == ForceBalanceStatus::converged);
    CHECK(relative(r.velocities[0], binary.velocities[0]) < 1e-14);
    CHECK(relative(r.velocities[1], binary.velocities[1]) < 1e-14);
    CHECK(relative(r.velocities[2], 1.793814683711509) < 1e-13);  // independent 40-digit solution
    const std::array<double, 3> trace{0.117, 0.033, 1e-9};
    const auto near = solve_force_balance<4>(niemi_force_balance, cell_of(bottom, trace, d));
    CHECK(std::abs(near.velocities[2] - r.velocities[2]) < 1e-7);
  }
  SUBCASE("permuting the classes permutes the solution") {
    const Case& c = cases[3];
    std::array<int, 3> order{0, 1, 2};
    do {
      std::array<double, 3> alpha{}, d{};
      for (int q = 0; q < 3; ++q) {
        alpha[q] = c.alpha[order[q]];
        d[q] = c.diameter[order[q]];
      }
      const auto r = solve_force_balance<3>(niemi_force_balance, cell_of(c, alpha, d));
      REQUIRE(r.status == ForceBalanceStatus::converged);
      for (int q = 0; q < 3; ++q) CHECK(relative(r.velocities[q], c.velocity[order[q]]) < 1e-13);
    } while (std::next_permutation(order.begin(), order.end()));
  }
  SUBCASE("Galilean invariance: a uniform shift of v_g and v_s shifts every v_q") {
    for (double shift : {-30.0, 25.0, 1000.0}) {
      const MixtureCell<double> cell{alpha2, d2, glass, air<double>(), 4.0 + shift, 1.8 + shift};
      const auto r = solve_force_balance<4>(niemi_force_balance, cell);
      REQUIRE(r.status == ForceBalanceStatus::converged);
      for (int q = 0; q < 2; ++q)
        CHECK(std::abs((r.velocities[q] - shift) - bottom.velocity[q]) < 1e-13 * (1 + std::abs(shift)));
    }
  }
}

TEST_CASE("mixture force balance: random cells (1 to 8 classes, alpha_s 1e-4 to 0.6, up- and downflow)") {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0, 1);
  int worst = 0;
  double worst_residual = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 1 + int(u(rng) * 8);
    const double alpha_s = std::pow(10.0, -4 + 3.78 * u(rng));
    std::vector<double> alpha(n), d(n), weight(n);
    double sum = 0;
    for (int q = 0; q < n; ++q) sum += (weight[q] = u(rng) + 0.01);
    for (int q = 0; q < n; ++q) {
      alpha[q] = alpha_s * weight[q] / sum;
      d[q] = std::pow(10.0, -4.3 + 1.3 * u(rng));  // 50 µm … 1 mm
    }
    const double vs = 20 * (u(rng) - 0.5), vg = vs + 15 * (u(rng) - 0.3);
    const MixtureCell<double> cell{alpha, d, glass, air<double>(), vg, vs};
    const auto r = solve_force_balance<8>(niemi_force_balance, cell);
    REQUIRE(r.status == ForceBalanceStatus::converged);
    worst = std::max(worst, r.iterations);
    const double residual = eq112_residual(alpha, d, vg, vs, velocities_of(r));
    worst_residual = std::max(worst_residual, residual);
    CHECK(residual <= 1e-10);
  }
  MESSAGE("2000 random cells: at most " << worst << " Newton iterations, eq. 112 residual at most " << worst_residual);
  CHECK(worst <= 6);
}

namespace {

using V3 = Vector3<double>;

V3 rotate(const std::array<double, 9>& r, const V3& v) {
  return {r[0] * v[0] + r[1] * v[1] + r[2] * v[2], r[3] * v[0] + r[4] * v[1] + r[5] * v[2],
          r[6] * v[0] + r[7] * v[1] + r[8] * v[2]};
}

// A rotation from a random unit quaternion.
std::array<double, 9> random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  double a = normal(rng), b = normal(rng), c = normal(rng), d = normal(rng);
  const double s = std::sqrt(a * a + b * b + c * c + d * d);
  a /= s, b /= s, c /= s, d /= s;
  return {a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c),
          2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b),
          2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d};
}

double distance(const V3& a, const V3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

TEST_CASE("mixture force balance in 3-D: the 1-D solution along v_g - v_s, rotations, off-axis warm starts") {
  for (const Case& c : cases) {
    INFO(std::string(c.name));
    const std::span<const double> alpha(c.alpha.data(), c.n), d(c.diameter.data(), c.n);
    // Along the vertical axis: the 1-D solution.
    const MixtureCell<double, V3> vertical{alpha, d, glass, air<double>(), {0, 0, c.gas_velocity},
                                           {0, 0, c.solids_velocity}};
    const auto r = solve_force_balance<4>(niemi_force_balance, vertical);
    REQUIRE(r.status == ForceBalanceStatus::converged);
    for (int q = 0; q < c.n; ++q) {
      CHECK(r.velocities[q][0] == 0.0);
      CHECK(r.velocities[q][1] == 0.0);
      CHECK(relative(r.velocities[q][2], c.velocity[q]) < 1e-14);
    }
    CHECK(relative(r.mixture_drag, c.mixture_drag) < 1e-14);

    // Any orientation: v_q = v_s + s_q (v_g − v_s)/|v_g − v_s|, s_q = v_q(1-D) − v_s(1-D), and the
    // solution turns with the input.
    std::mt19937 rng(12345);
    for (int trial = 0; trial < 5; ++trial) {
      const auto rotation = random_rotation(rng);
      const V3 offset{0.3 * trial - 0.5, 0.2, -0.1 * trial};  // v_s off the origin too
      const V3 vs0 = rotate(rotation, {0, 0, c.solids_velocity}), vg0 = rotate(rotation, {0, 0, c.gas_velocity});
      const V3 vs{vs0[0] + offset[0], vs0[1] + offset[1], vs0[2] + offset[2]};
      const V3 vg{vg0[0] + offset[0], vg0[1] + offset[1], vg0[2] + offset[2]};
      const MixtureCell<double, V3> cell{alpha, d, glass, air<double>(), vg, vs};
      const auto turned = solve_force_balance<4>(niemi_force_balance, cell);
      REQUIRE(turned.status == ForceBalanceStatus::converged);
      for (int q = 0; q < c.n; ++q) {
        const V3 e0 = rotate(rotation, r.velocities[q]);
        const V3 expected{e0[0] + offset[0], e0[1] + offset[1], e0[2] + offset[2]};
        CHECK(distance(turned.velocities[q], expected) < 1e-13 * (c.gas_velocity - c.solids_velocity));
      }

      // A warm start off the axis (lateral 0.3 m/s per class) converges to the same solution.
      std::array<V3, 3> guess{};
      for (int q = 0; q < c.n; ++q) {
        const V3 lateral = rotate(rotation, {0.3 * (q + 1), -0.2 * q, 0.05});
        for (int i = 0; i < 3; ++i) guess[q][i] = turned.velocities[q][i] + lateral[i];
      }
      MixtureCell<double, V3> warm = cell;
      warm.initial_guess = std::span<const V3>(guess.data(), c.n);
      const auto w = solve_force_balance<4>(niemi_force_balance, warm);
      REQUIRE(w.status == ForceBalanceStatus::converged);
      CHECK(w.iterations <= 12);
      for (int q = 0; q < c.n; ++q)
        CHECK(distance(w.velocities[q], turned.velocities[q]) < 1e-12 * (c.gas_velocity - c.solids_velocity));
      if (trial == 0) MESSAGE(std::string(c.name) << ": off-axis warm start, " << w.iterations << " Newton iterations");
    }
  }
}

TEST_CASE("mixture force balance: the analytic Jacobian equals central differences (1-D and 3-D, off the axis)") {
  const Case& c = cases[3];
  const std::span<const double> alpha(c.alpha.data(), 3), d(c.diameter.data(), 3);
  {
    const MixtureCell<double, V3> cell{alpha, d, glass, air<double>(), {0.4, -0.3, 4.0}, {0.1, 0.2, 1.8}};
    const auto system = polydisperse::detail::make_force_balance_system<3>(niemi_force_balance, cell);
    constexpr int M = 9;
    // A point with every slip and relative velocity oblique.
    std::array<double, M> x{0.35, -0.1, 0.05, 0.2, -0.45, 0.02, -0.15, 0.3, -0.07};
    std::array<double, M * M> j{};
    system.jacobian(x, j);
    double worst = 0;
    for (int k = 0; k < M; ++k) {
      const double h = 1e-6;
      std::array<double, M> xp = x, xm = x, rp{}, rm{};
      xp[k] += h;
      xm[k] -= h;
      double unused;
      system.residual(xp, rp, unused);
      system.residual(xm, rm, unused);
      for (int i = 0; i < M; ++i) {
        const double fd = (rp[i] - rm[i]) / (2 * h);
        worst = std::max(worst, std::abs(j[i * M + k] - fd) / (1 + std::abs(j[i * M + k])));
      }
    }
    CHECK(worst < 1e-6);
  }
  {
    const MixtureCell<double> cell{alpha, d, glass, air<double>(), 4.0, 1.8};
    const auto system = polydisperse::detail::make_force_balance_system<3>(niemi_force_balance, cell);
    std::array<double, 3> x{0.1, 0.03, -0.02};
    std::array<double, 9> j{};
    system.jacobian(x, j);
    for (int k = 0; k < 3; ++k) {
      const double h = 1e-7;
      std::array<double, 3> xp = x, xm = x, rp{}, rm{};
      xp[k] += h;
      xm[k] -= h;
      double unused;
      system.residual(xp, rp, unused);
      system.residual(xm, rm, unused);
      for (int i = 0; i < 3; ++i) CHECK(j[i * 3 + k] == doctest::Approx((rp[i] - rm[i]) / (2 * h)).epsilon(1e-6));
    }
  }
}

TEST_CASE("mixture force balance: warm starts, the start on the kink, statuses") {
  const Case& c = cases[0];
  const std::span<const double> alpha(c.alpha.data(), 2), d(c.diameter.data(), 2);
  const auto cold = solve_force_balance<2>(niemi_force_balance, cell_of(c, alpha, d));
  REQUIRE(cold.status == ForceBalanceStatus::converged);

  // From the solution: no iteration.
  MixtureCell<double> warm = cell_of(c, alpha, d);
  warm.initial_guess = std::span<const double>(cold.velocities.data(), 2);
  const auto again = solve_force_balance<2>(niemi_force_balance, warm);
  CHECK(again.status == ForceBalanceStatus::converged);
  CHECK(again.iterations == 0);

  // From v_q = v_s (the kink of |v_p − v_q|): still converges, with more iterations.
  for (const Case& k : cases) {
    const std::array<double, 3> at_mixture{k.solids_velocity, k.solids_velocity, k.solids_velocity};
    MixtureCell<double> kink = cell_of(k, std::span<const double>(k.alpha.data(), k.n),
                                       std::span<const double>(k.diameter.data(), k.n));
    kink.initial_guess = std::span<const double>(at_mixture.data(), k.n);
    const auto r = solve_force_balance<3>(niemi_force_balance, kink);
    REQUIRE(r.status == ForceBalanceStatus::converged);
    for (int q = 0; q < k.n; ++q) CHECK(relative(r.velocities[q], k.velocity[q]) < 1e-13);
    MESSAGE(std::string(k.name) << ": from v_q = v_s, " << r.iterations << " Newton iterations");
    CHECK(r.iterations <= 8);
  }

  // The iteration cap: the start is returned with status not_converged.
  ForceBalanceOptions<double> none;
  none.max_iterations = 0;
  const auto capped = solve_force_balance<2>(niemi_force_balance, cell_of(c, alpha, d), none);
  CHECK(capped.status == ForceBalanceStatus::not_converged);
  CHECK(capped.residual > none.tolerance);
  CHECK(std::isfinite(capped.velocities[0]));
  // The frozen-coefficient start: within 1 % of the slip v_g − v_s (0.44 %, 0.46 % here).
  for (int q = 0; q < 2; ++q)
    CHECK(std::abs(capped.velocities[q] - c.velocity[q]) < 0.01 * (c.gas_velocity - c.solids_velocity));
}

TEST_CASE("mixture force balance: invalid input (status on the hot path, std::domain_error when checked)") {
  const std::array<double, 3> alpha{0.117, 0.033, 0.01}, d{255e-6, 416e-6, 300e-6};
  const auto valid = [&] { return MixtureCell<double>{std::span<const double>(alpha.data(), 2),
                                                      std::span<const double>(d.data(), 2), glass, air<double>(), 4.0,
                                                      1.8}; };
  const auto expect_invalid = [&](const MixtureCell<double>& cell, const std::string& argument) {
    INFO("argument " << argument);
    const auto r = solve_force_balance<2>(niemi_force_balance, cell);
    CHECK(r.status == ForceBalanceStatus::invalid_input);
    CHECK(r.size == 0);
    try {
      solve_force_balance<2>(niemi_force_balance, cell, {}, fluidbed::checked);
      FAIL("no exception");
    } catch (const std::domain_error& e) {
      CHECK(std::string(e.what()).find(argument) != std::string::npos);
    }
  };
  CHECK(solve_force_balance<2>(niemi_force_balance, valid(), {}, fluidbed::checked).status ==
        ForceBalanceStatus::converged);

  auto cell = valid();
  cell.fractions = std::span<const double>(alpha.data(), 3);  // more classes than MaxClasses = 2
  cell.diameters = std::span<const double>(d.data(), 3);
  expect_invalid(cell, "fractions.size()");
  cell = valid();
  cell.fractions = {};
  expect_invalid(cell, "fractions.size()");
  cell = valid();
  cell.diameters = std::span<const double>(d.data(), 1);
  expect_invalid(cell, "diameters.size()");
  const std::array<double, 2> negative{0.117, -0.01}, dense{0.6, 0.45}, zero_d{255e-6, 0.0};
  cell = valid();
  cell.fractions = negative;
  expect_invalid(cell, "fractions[1]");
  cell = valid();
  cell.fractions = dense;  // α_s = 1.05
  expect_invalid(cell, "sum of fractions");
  cell = valid();
  cell.diameters = zero_d;
  expect_invalid(cell, "diameters[1]");
  cell = valid();
  cell.gas_velocity = std::nan("");
  expect_invalid(cell, "gas_velocity");
  cell = valid();
  cell.gas.viscosity = -1;
  expect_invalid(cell, "gas.viscosity");
  cell = valid();
  const std::array<double, 1> short_guess{1.8};
  cell.initial_guess = short_guess;
  expect_invalid(cell, "initial_guess.size()");

  auto model = niemi_force_balance;
  model.restitution = 1.5;
  CHECK(solve_force_balance<2>(model, valid()).status == ForceBalanceStatus::invalid_input);
  CHECK_THROWS_AS((solve_force_balance<2>(model, valid(), {}, fluidbed::checked)), std::domain_error);
  model = niemi_force_balance;
  model.solid_solid_drag.friction_coefficient = -0.1;
  CHECK(solve_force_balance<2>(model, valid()).status == ForceBalanceStatus::invalid_input);
  CHECK_THROWS_AS((solve_force_balance<2>(model, valid(), {}, fluidbed::checked)), std::domain_error);
}

// ------------------------------------------------------------------------------------------
// The consistency correction: seed 001 Figure 8 (3 equal cells, 2 classes, % units there,
// fractions here). Exact values of the procedure (Python fractions):
//   after the fluxes, normalised: cell c, class q: α̃_q α_s/Σα̃, e.g. 25·28/30 = 70/3;
//   class totals 982/15 = 65.4666…, 668/15 = 44.5333…; C_1 = 975/982, C_2 = 675/668;
//   after k corrections and normalisations (k = 1 … 4) the relative errors V_q/V_q^true − 1 are
//   k = 1:  9.670111454640502e-4, −1.3967938767814058e-3
//   k = 2:  1.3039309315222733e-4, −1.883455789976617e-4
//   k = 3:  1.7585014201678687e-5, −2.5400576069091437e-5
//   k = 4:  2.371590063101434e-6,  −3.425630091146516e-6
// ------------------------------------------------------------------------------------------

namespace {

// Class-major: α_1 of cells 1–3, then α_2 of cells 1–3 (fractions, the figure's % / 100).
constexpr std::array<double, 6> initial{0.20, 0.25, 0.20, 0.10, 0.15, 0.20};
constexpr std::array<double, 3> initial_mixture{0.30, 0.40, 0.40};
// The figure's face fluxes (α_1, α_2, α_s): between cells 1 and 2 "5↑ 5↓ 2↓", between 2 and 3
// "0↑ 10↓ 7↓" (%; ↑ into the upper cell).
std::array<double, 6> after_fluxes() {
  std::array<double, 6> a = initial;
  a[0] += 0.05, a[1] -= 0.05;  // class 1 up from cell 2 to cell 1
  a[3] -= 0.05, a[4] += 0.05;  // class 2 down from cell 1 to cell 2
  a[4] -= 0.10, a[5] += 0.10;  // class 2 down from cell 2 to cell 3
  return a;
}
std::array<double, 3> mixture_after_fluxes() {
  std::array<double, 3> s = initial_mixture;
  s[0] -= 0.02, s[1] += 0.02 - 0.07, s[2] += 0.07;
  return s;
}

}  // namespace

TEST_CASE("consistency correction: seed 001 Figure 8 step by step") {
  std::array<double, 6> a = after_fluxes();
  const std::array<double, 3> s = mixture_after_fluxes();
  // The figure's "fluxes applied" column: (25, 5, 28), (20, 10, 35), (20, 30, 47).
  const std::array<double, 6> printed_fluxed{25, 20, 20, 5, 10, 30};
  for (int i = 0; i < 6; ++i) CHECK(a[i] * 100 == doctest::Approx(printed_fluxed[i]).epsilon(1e-14));
  CHECK(s[0] * 100 == doctest::Approx(28).epsilon(1e-14));
  CHECK(s[1] * 100 == doctest::Approx(35).epsilon(1e-14));
  CHECK(s[2] * 100 == doctest::Approx(47).epsilon(1e-14));
  std::array<double, 2> truth{};
  class_volumes<double>(a, 2, {}, truth);
  CHECK(truth[0] == doctest::Approx(0.65).epsilon(1e-15));  // conservative fluxes keep the totals
  CHECK(truth[1] == doctest::Approx(0.45).epsilon(1e-15));

  // Eq. 120: 23.33/4.67, 23.33/11.67, 18.8/28.2 (exact 70/3, 14/3, 70/3, 35/3, 18.8, 28.2).
  CHECK(normalise_class_fractions<double>(a, 2, s) == 0);
  const std::array<double, 6> normalised{70.0 / 3, 70.0 / 3, 18.8, 14.0 / 3, 35.0 / 3, 28.2};
  for (int i = 0; i < 6; ++i) CHECK(a[i] * 100 == doctest::Approx(normalised[i]).epsilon(1e-14));
  const std::array<double, 6> printed_normalised{23.33, 23.33, 18.8, 4.67, 11.67, 28.2};
  for (int i = 0; i < 6; ++i) CHECK(std::abs(a[i] * 100 - printed_normalised[i]) <= 0.005);
  std::array<double, 2> volumes{};
  class_volumes<double>(a, 2, {}, volumes);
  CHECK(volumes[0] * 100 == doctest::Approx(982.0 / 15).epsilon(1e-14));  // printed 65.47
  CHECK(volumes[1] * 100 == doctest::Approx(668.0 / 15).epsilon(1e-14));  // printed 44.53

  // C_q = V_q^true/V_q = 65/65.47 = 0.992872 and 45/44.53 = 1.010479 (exact 975/982, 675/668).
  const double c1 = truth[0] / volumes[0], c2 = truth[1] / volumes[1];
  CHECK(c1 == doctest::Approx(975.0 / 982).epsilon(1e-14));
  CHECK(c2 == doctest::Approx(675.0 / 668).epsilon(1e-14));
  CHECK(std::abs(c1 - 0.992872) <= 5e-7);
  CHECK(std::abs(c2 - 1.010479) <= 5e-7);
  // The thesis's literal C_q = V_q/Ṽ_q (current over true) is the inverse: it would move the
  // totals away, to 65.47²/65 = 65.94.
  CHECK(volumes[0] * volumes[0] / truth[0] * 100 > 65.9);

  // "Corrected": 23.17/4.72, 23.17/11.79, 18.67/28.5, totals 65/45 exactly.
  std::array<double, 6> corrected = a;
  for (int i = 0; i < 3; ++i) corrected[i] *= c1, corrected[3 + i] *= c2;
  const std::array<double, 6> printed_corrected{23.17, 23.17, 18.67, 4.72, 11.79, 28.5};
  for (int i = 0; i < 6; ++i) CHECK(std::abs(corrected[i] * 100 - printed_corrected[i]) <= 0.005);
  class_volumes<double>(corrected, 2, {}, volumes);
  CHECK(volumes[0] == doctest::Approx(0.65).epsilon(1e-15));
  CHECK(volumes[1] == doctest::Approx(0.45).epsilon(1e-15));
}

TEST_CASE("consistency correction: seed 001 Figure 8's last column is one iteration for the totals and cell 1, "
          "two for cells 2 and 3") {
  const std::array<double, 3> s = mixture_after_fluxes();
  ConsistencyOptions<double> one;
  one.max_iterations = 1;
  std::array<double, 6> a = after_fluxes();
  auto r = correct_class_fractions<2, double>(a, 2, s, {}, {}, one);
  CHECK(r.status == ConsistencyStatus::iteration_limit);
  CHECK(r.iterations == 1);
  CHECK(std::abs(r.mixture_mismatch) < 1e-15);
  // Exact values after one iteration (Python fractions).
  const std::array<double, 6> first{23.264571931570284, 23.19621460734183, 18.602069185543048,
                                    4.735428068429714,  11.80378539265817, 28.397930814456952};
  for (int i = 0; i < 6; ++i) CHECK(a[i] * 100 == doctest::Approx(first[i]).epsilon(1e-14));
  std::array<double, 2> volumes{};
  class_volumes<double>(a, 2, {}, volumes);
  // Printed: cell 1 23.26/4.74 and totals 65.06/44.94 — the first iteration's …
  CHECK(std::abs(a[0] * 100 - 23.26) <= 0.005);
  CHECK(std::abs(a[3] * 100 - 4.74) <= 0.005);
  CHECK(std::abs(volumes[0] * 100 - 65.06) <= 0.005);
  CHECK(std::abs(volumes[1] * 100 - 44.94) <= 0.005);
  // … but cells 2 and 3 after one iteration are 23.20/11.80 and 18.60/28.40, not the printed ones.
  CHECK(std::abs(a[1] * 100 - 23.20) <= 0.005);
  CHECK(std::abs(a[2] * 100 - 18.60) <= 0.005);
  CHECK(std::abs(a[1] * 100 - 23.18) > 0.01);

  ConsistencyOptions<double> two;
  two.max_iterations = 2;
  a = after_fluxes();
  r = correct_class_fractions<2, double>(a, 2, s, {}, {}, two);
  CHECK(r.iterations == 2);
  const std::array<double, 6> second{23.25526211452187, 23.177711591954246, 18.575501844578778,
                                     4.7447378854781315, 11.822288408045752, 28.424498155421222};
  for (int i = 0; i < 6; ++i) CHECK(a[i] * 100 == doctest::Approx(second[i]).epsilon(1e-14));
  // The printed cells 2 and 3, 23.18/11.82 and 18.58/28.42, are the second iteration's (cell 1
  // rounds to the printed 23.26/4.74 after either; the totals, 65.01/44.99, do not).
  const std::array<double, 6> printed{23.26, 23.18, 18.58, 4.74, 11.82, 28.42};
  for (int i = 0; i < 6; ++i) CHECK(std::abs(a[i] * 100 - printed[i]) <= 0.005);
  class_volumes<double>(a, 2, {}, volumes);
  CHECK(std::abs(volumes[0] * 100 - 65.06) > 0.04);
  // Eq. 121 in every cell after every normalisation.
  for (int c = 0; c < 3; ++c) CHECK(a[c] + a[3 + c] == doctest::Approx(s[c]).epsilon(1e-15));
}

TEST_CASE("consistency correction: relative errors after each normalisation, and the tolerance stop") {
  const std::array<double, 3> s = mixture_after_fluxes();
  const std::array<double, 2> truth{0.65, 0.45};
  const double exact[4][2] = {{9.670111454640502e-4, -1.3967938767814058e-3},
                              {1.3039309315222733e-4, -1.883455789976617e-4},
                              {1.7585014201678687e-5, -2.5400576069091437e-5},
                              {2.371590063101434e-6, -3.425630091146516e-6}};
  // As quoted to two digits: 9.7e-4/−1.4e-3, 1.3e-4/−1.9e-4, 1.8e-5/−2.5e-5, 2.4e-6/−3.4e-6.
  const double quoted[4][2] = {{9.7e-4, -1.4e-3}, {1.3e-4, -1.9e-4}, {1.8e-5, -2.5e-5}, {2.4e-6, -3.4e-6}};
  for (int k = 1; k <= 4; ++k) {
    INFO("iterations " << k);
    ConsistencyOptions<double> options;
    options.max_iterations = k;
    std::array<double, 6> a = after_fluxes();
    const auto r = correct_class_fractions<2, double>(a, 2, s, {}, truth, options);
    CHECK(r.iterations == k);
    std::array<double, 2> volumes{};
    class_volumes<double>(a, 2, {}, volumes);
    for (int q = 0; q < 2; ++q) {
      const double error = volumes[q] / truth[q] - 1;
      // The double evaluation of a relative error ~1e-3 … 1e-6 from totals ~0.5: ~1e-16/|error|.
      CHECK(std::abs(error - exact[k - 1][q]) <= 1e-13);
      CHECK(std::abs(error - quoted[k - 1][q]) <= 0.051 * std::abs(quoted[k - 1][q]));
    }
    CHECK(r.relative_error == doctest::Approx(std::max(std::abs(exact[k - 1][0]), std::abs(exact[k - 1][1])))
                                  .epsilon(1e-9));
  }
  // Stop at a tolerance: 1e-5 needs four iterations (2.54e-5 after three).
  ConsistencyOptions<double> tolerant;
  tolerant.max_iterations = 20;
  tolerant.tolerance = 1e-5;
  std::array<double, 6> a = after_fluxes();
  const auto r = correct_class_fractions<2, double>(a, 2, s, {}, {}, tolerant);
  CHECK(r.status == ConsistencyStatus::tolerance_met);
  CHECK(r.iterations == 4);
  // The default: three iterations, as the thesis does ("2–3 in practice").
  a = after_fluxes();
  const auto d = correct_class_fractions<2, double>(a, 2, s, {}, {});
  CHECK(d.status == ConsistencyStatus::iteration_limit);
  CHECK(d.iterations == 3);
  // Convergence to round-off.
  tolerant.tolerance = 1e-14;
  tolerant.max_iterations = 100;
  a = after_fluxes();
  const auto tight = correct_class_fractions<2, double>(a, 2, s, {}, {}, tolerant);
  CHECK(tight.status == ConsistencyStatus::tolerance_met);
  MESSAGE("Figure 8 to 1e-14: " << tight.iterations << " iterations");
}

TEST_CASE("consistency correction: unequal cells, many classes, incompatible totals, invalid input") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr int classes = 5, cells = 40;
  std::vector<double> a(classes * cells), s(cells), volume(cells);
  for (int c = 0; c < cells; ++c) {
    volume[c] = 0.5 + 2 * u(rng);
    s[c] = 0.05 + 0.5 * u(rng);
    double sum = 0;
    for (int q = 0; q < classes; ++q) sum += (a[q * cells + c] = u(rng));
    for (int q = 0; q < classes; ++q) a[q * cells + c] *= s[c] / sum;  // consistent before the "fluxes"
  }
  std::array<double, classes> truth{};
  class_volumes<double>(a, classes, volume, truth);
  // Perturb the class fractions as transport with different velocities would (volume-conserving
  // exchanges between neighbouring cells), leaving α_s.
  for (int q = 0; q < classes; ++q)
    for (int c = 0; c + 1 < cells; ++c) {
      const double moved = 0.1 * (u(rng) - 0.5) * std::min(a[q * cells + c], a[q * cells + c + 1]);
      a[q * cells + c] -= moved / volume[c];
      a[q * cells + c + 1] += moved / volume[c + 1];
    }
  ConsistencyOptions<double> options;
  options.max_iterations = 200;
  options.tolerance = 1e-13;
  const auto r = correct_class_fractions<8, double>(a, classes, s, volume, {}, options);
  CHECK(r.status == ConsistencyStatus::tolerance_met);
  CHECK(std::abs(r.mixture_mismatch) < 1e-14);
  std::array<double, classes> after{};
  class_volumes<double>(a, classes, volume, after);
  for (int q = 0; q < classes; ++q) CHECK(after[q] == doctest::Approx(truth[q]).epsilon(1e-13));
  for (int c = 0; c < cells; ++c) {
    double sum = 0;
    for (int q = 0; q < classes; ++q) sum += a[q * cells + c];
    CHECK(sum == doctest::Approx(s[c]).epsilon(1e-14));
  }
  MESSAGE("5 classes x 40 cells to 1e-13: " << r.iterations << " iterations");

  // Class totals that do not add up to the mixture's: the tolerance cannot be met, the mismatch says why.
  const std::array<double, 3> mixture = mixture_after_fluxes();
  const std::array<double, 2> off{0.66, 0.45};
  std::array<double, 6> f = after_fluxes();
  options.max_iterations = 50;
  options.tolerance = 1e-6;
  const auto bad = correct_class_fractions<2, double>(f, 2, mixture, {}, off, options);
  CHECK(bad.status == ConsistencyStatus::iteration_limit);
  CHECK(bad.mixture_mismatch == doctest::Approx(0.01 / 1.10).epsilon(1e-12));
  CHECK(bad.relative_error > 1e-3);

  // Invalid input: nothing changed; checked throws.
  std::array<double, 6> g = after_fluxes();
  g[4] = -0.01;
  const std::array<double, 6> before = g;
  CHECK(correct_class_fractions<2, double>(g, 2, mixture, {}, {}).status == ConsistencyStatus::invalid_input);
  CHECK(g == before);
  CHECK_THROWS_AS((correct_class_fractions<2, double>(g, 2, mixture, {}, {}, {}, fluidbed::checked)), std::domain_error);
  g = after_fluxes();
  CHECK(correct_class_fractions<2, double>(std::span<double>(g.data(), 5), 2, mixture, {}, {}).status ==
        ConsistencyStatus::invalid_input);
  CHECK(correct_class_fractions<1, double>(g, 2, mixture, {}, {}).status == ConsistencyStatus::invalid_input);
  const std::array<double, 3> bad_volume{1, 0, 1};
  CHECK(correct_class_fractions<2, double>(g, 2, mixture, bad_volume, {}).status == ConsistencyStatus::invalid_input);
  // A cell with solids but no class fraction is reported and left as it is.
  g = after_fluxes();
  g[2] = g[5] = 0;
  const auto empty = correct_class_fractions<2, double>(g, 2, mixture, {}, {});
  CHECK(empty.unnormalisable_cells == 1);
  CHECK(g[2] == 0.0);
  CHECK(g[5] == 0.0);
}

// The independent reference solution (mpmath 1.3, 40 digits), for the record:
//
//   from mpmath import mp, mpf, cbrt, pi, findroot
//   mp.dps = 40
//   rg, mu, rho = mpf('1.225'), mpf('1.7894e-5'), mpf(2480)
//   def cd(re): return 24/re*(1 + mpf('0.15')*re**mpf('0.687')) if re <= 1000 else mpf('0.44')
//   def gidaspow(a_s, w, d):                       # seed 001 eqs. 41, 42, 45 as printed
//       ag = 1 - a_s
//       if ag < mpf('0.8'): return 150*a_s**2*mu/(ag*d*d) + mpf('1.75')*rg*a_s*w/d
//       return mpf('0.75')*cd(ag*rg*w*d/mu)*a_s*ag*rg*w/d*ag**mpf('-2.65')
//   def g0(a): return 1/(1 - cbrt(a/mpf('0.63')))  # eq. 24
//   def kpq(ap, aq, dp, dq, g, w, cf=0, e=mpf('0.9')):  # eq. 91
//       return 3*(1+e)*(pi/2 + cf*pi**2/8)*ap*rho*aq*rho*(dp+dq)**2*g/(2*pi*(rho*dp**3 + rho*dq**3))*w
//   def solve(al, d, vg, vs):                      # eq. 112
//       n, As = len(al), sum(al); ds = As/sum(a/x for a, x in zip(al, d))
//       Kgs = gidaspow(As, abs(vg - vs), ds)
//       def F(*v):
//           return [al[q]/As*gidaspow(As, abs(vg - v[q]), d[q])*(vg - v[q])
//                   + sum(kpq(al[p], al[q], d[p], d[q], g0(As), abs(v[p] - v[q]))*(v[p] - v[q])
//                         for p in range(n) if p != q)
//                   - al[q]/As*Kgs*(vg - vs) for q in range(n)]
//       return ds, Kgs, findroot(F, [vs + mpf(q)/100 for q in range(n)])
