// DQMOM (moments/dqmom.hpp, dqmom_batched.hpp): exact identities of the source system (Mazzei 2008
// thesis eq. 5.63): pure growth for every ν in both weight conventions, det X, the two-node closed
// forms of App. D (D.14–D.17, with the −2ξ³ row the thesis misprints as −2ξ²), the two-node
// diffusion sources of eq. 6.22, the recovery of random sources within the reported conditioning,
// exact power-of-two scale invariance, the coincident-node rule at its limit, fractional orders,
// and the transport pieces (moment velocities, upwind fluxes, initialisation from moments, nodes
// of vanishing weights). The high-precision reference table is test_dqmom_reference.cpp's.
#include <doctest/doctest.h>

#include "fluidbed/moments/eigen_core.hpp"  // first: Eigen without its own warnings

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "fluidbed/core/vector3.hpp"
#include "fluidbed/kinetic_theory/class_transport.hpp"
#include "fluidbed/moments/dqmom.hpp"
#include "fluidbed/moments/dqmom_batched.hpp"

using namespace fluidbed::moments;

namespace {

// Sizes of the thesis's Table 6.8 (75 … 355 µm) and more, with their volume fractions.
constexpr std::array<double, 8> sizes{75e-6, 103e-6, 240e-6, 355e-6, 165e-6, 60e-6, 420e-6, 130e-6};  // m
constexpr std::array<double, 8> fractions{0.131, 0.169, 0.190, 0.110, 0.05, 0.03, 0.02, 0.04};
constexpr double eps = std::numeric_limits<double>::epsilon();

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

template <class T>
std::span<const T> first(const auto& array, int n) {
  return std::span<const T>(array.data(), std::size_t(n));
}

// The left-hand side of the system: the moment sources implied by (c^a, c^ξ), orders 0 … L − 1.
template <int N>
std::array<double, 2 * N> implied(std::span<const double> xi, const dqmom::Sources<double, N>& c, int orders) {
  std::array<double, 2 * N> s{};
  for (int k = 0; k < orders; ++k)
    for (std::size_t i = 0; i < xi.size(); ++i)
      s[k] += (1 - k) * std::pow(xi[i], k) * c.weight[i] + k * std::pow(xi[i], k - 1) * c.weighted_node[i];
  return s;
}

}  // namespace

TEST_CASE("DQMOM pure growth: c^phi = 3 phi G/xi, c^xi = 4 phi G (volume), c^w = 0, c^xi = w G (number), nu = 1..8") {
  for (int n = 1; n <= 8; ++n) {
    INFO("nodes " << n);
    std::array<double, 8> growth{};
    for (int i = 0; i < n; ++i) growth[i] = 1e-7 * (1 + i) * (i % 2 ? -1 : 1);  // m/s, shrinking and growing
    const auto xi = first<double>(sizes, n), phi = first<double>(fractions, n), g = first<double>(growth, n);
    const dqmom::System<double, 8> system(xi, phi);
    REQUIRE(system.size() == n);
    // As point functionals: exact to rounding whatever the conditioning.
    const auto volume = dqmom::growth_terms<double, 8>(dqmom::Weights::volume_fraction, phi, xi, g);
    const auto number = dqmom::growth_terms<double, 8>(dqmom::Weights::number_density, phi, xi, g);
    const auto cv = system.solve(first<dqmom::PointSource<double>>(volume, 2 * n));
    const auto cn = system.solve(first<dqmom::PointSource<double>>(number, 2 * n));
    REQUIRE(cv.status == dqmom::SourceStatus::ok);
    // As moment sources (QMOM's S_k of eq. 5.101): within the measured conditioning.
    std::array<double, 16> orders{};
    for (int k = 0; k < 16; ++k) orders[k] = k;
    const auto s = dqmom::growth_moment_sources(dqmom::Weights::volume_fraction, phi, xi, g, orders);
    const auto cm = system.solve(first<double>(s, 2 * n));
    CHECK(cm.condition == system.condition());
    for (int i = 0; i < n; ++i) {
      CHECK(relative(cv.weight[i], 3 * phi[i] * g[i] / xi[i]) < 8 * eps);
      CHECK(relative(cv.weighted_node[i], 4 * phi[i] * g[i]) < 8 * eps);
      CHECK(std::abs(cn.weight[i]) < 8 * eps * phi[i] * std::abs(g[i]) / xi[i]);
      CHECK(relative(cn.weighted_node[i], phi[i] * g[i]) < 8 * eps);
      // The nodes' growth rates differ in sign and size by up to 16: scale by the largest.
      CHECK(std::abs(cm.weight[i] - cv.weight[i]) < 32 * eps * system.condition() * 3 * 0.19 * 8e-7 / 60e-6);
      CHECK(std::abs(cm.weighted_node[i] - cv.weighted_node[i]) < 32 * eps * system.condition() * 4 * 0.19 * 8e-7);
    }
  }
}

TEST_CASE("DQMOM: det X = (-1)^(nu(nu-1)/2) prod (xi_i - xi_j)^4 for nu = 1..5") {
  for (int n = 1; n <= 5; ++n) {
    Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> x(2 * n, 2 * n);
    std::array<long double, 5> xi{};
    for (int i = 0; i < n; ++i) xi[i] = sizes[i] / 256e-6L;  // O(1) units
    for (int k = 0; k < 2 * n; ++k)
      for (int i = 0; i < n; ++i) {
        x(k, i) = (1 - k) * std::pow(xi[i], (long double)k);
        x(k, n + i) = k == 0 ? 0.0L : k * std::pow(xi[i], (long double)(k - 1));
      }
    long double expected = (n * (n - 1) / 2) % 2 ? -1 : 1;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) expected *= std::pow(xi[i] - xi[j], 4.0L);
    CHECK(double(std::abs(x.fullPivLu().determinant() / expected - 1)) < 1e-12);
  }
}

TEST_CASE("DQMOM two nodes: the closed forms of the thesis's App. D (D.14-D.17) and the diffusion sources of eq. 6.22") {
  const double x1 = 75e-6, x2 = 103e-6;
  const std::array<double, 2> xi{x1, x2};
  const std::array<double, 4> S{1e-3, 2e-7, 3e-11, 5e-15};  // 𝒮_0 … 𝒮_3, any
  const auto c = dqmom::solve<double, 2>(std::span<const double>(xi), std::span<const double>(S));
  REQUIRE(c.status == dqmom::SourceStatus::ok);
  const double d3 = std::pow(x1 - x2, 3);
  const double c1_phi = (x2 * x2 * (3 * x1 - x2) * S[0] - 6 * x1 * x2 * S[1] + 3 * (x1 + x2) * S[2] - 2 * S[3]) / d3;
  const double c2_phi = (x1 * x1 * (3 * x2 - x1) * S[0] - 6 * x1 * x2 * S[1] + 3 * (x1 + x2) * S[2] - 2 * S[3]) / -d3;
  const double c1_xi = (2 * x1 * x1 * x2 * x2 * S[0] - x2 * (4 * x1 * x1 + x1 * x2 + x2 * x2) * S[1] +
                        2 * (x1 * x1 + x1 * x2 + x2 * x2) * S[2] - (x1 + x2) * S[3]) /
                       d3;
  const double c2_xi = (2 * x1 * x1 * x2 * x2 * S[0] - x1 * (4 * x2 * x2 + x1 * x2 + x1 * x1) * S[1] +
                        2 * (x1 * x1 + x1 * x2 + x2 * x2) * S[2] - (x1 + x2) * S[3]) /
                       -d3;
  CHECK(relative(c.weight[0], c1_phi) < 1e-12);
  CHECK(relative(c.weight[1], c2_phi) < 1e-12);
  CHECK(relative(c.weighted_node[0], c1_xi) < 1e-12);
  CHECK(relative(c.weighted_node[1], c2_xi) < 1e-12);
  // The printed row −2ξ² for k = 3 (D.8) would not reproduce 𝒮_3 with these sources.
  const double printed_row = -2 * x1 * x1 * c.weight[0] - 2 * x2 * x2 * c.weight[1] + 3 * x1 * x1 * c.weighted_node[0] +
                             3 * x2 * x2 * c.weighted_node[1];
  CHECK(relative(printed_row, S[3]) > 1);
  // Diffusion: 𝒞_i = 𝒟 φ_i |∇ξ_i|², eq. 6.22 with i ≠ j, as moments and as point functionals.
  const std::array<double, 2> phi{0.262, 0.338}, diffusion{7.5e-7 * 0.262 * 1e-6, 7.5e-7 * 0.338 * 4e-6};
  const dqmom::System<double, 2> system{std::span<const double>(xi), std::span<const double>(phi)};
  const auto sd = dqmom::diffusion_sources<double, 2>(std::span<const double>(xi), std::span<const double>(diffusion));
  const auto terms = dqmom::diffusion_terms<double, 2>(std::span<const double>(xi), std::span<const double>(diffusion));
  const double gap2 = (x1 - x2) * (x1 - x2);
  const std::array<double, 2> expected_phi{6 * (diffusion[1] - diffusion[0]) / gap2, 6 * (diffusion[0] - diffusion[1]) / gap2};
  const std::array<double, 2> expected_xi{(2 * diffusion[1] * (x2 + 2 * x1) - 2 * diffusion[0] * (x1 + 2 * x2)) / gap2,
                                          (2 * diffusion[0] * (x1 + 2 * x2) - 2 * diffusion[1] * (x2 + 2 * x1)) / gap2};
  for (const auto& cd : {system.solve(std::span<const double>(sd)),
                         system.solve(std::span<const dqmom::PointSource<double>>(terms))})
    for (int i = 0; i < 2; ++i) {
      CHECK(relative(cd.weight[i], expected_phi[i]) < 1e-12);
      CHECK(relative(cd.weighted_node[i], expected_xi[i]) < 1e-12);
    }
}

TEST_CASE("DQMOM: random sources are recovered from the moment sources they imply within eps * condition, nu = 1..8") {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(-1, 1);
  double worst = 0;
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 20; ++trial) {
      INFO("nodes " << n << ", trial " << trial);
      const auto xi = first<double>(sizes, n);
      dqmom::Sources<double, 8> c;
      for (int i = 0; i < n; ++i) c.weight[i] = unit(random), c.weighted_node[i] = 1e-4 * unit(random);
      const auto s = implied<8>(xi, c, 2 * n);
      const auto back = dqmom::solve<double, 8>(xi, first<double>(s, 2 * n));
      REQUIRE(back.status == dqmom::SourceStatus::ok);
      // The unknowns are O(1) and O(1e-4) (c^ξ in m: O(L) in the scaled units).
      for (int i = 0; i < n; ++i) {
        const double error = std::max(std::abs(back.weight[i] - c.weight[i]),
                                      std::abs(back.weighted_node[i] - c.weighted_node[i]) / 1e-4);
        worst = std::max(worst, error / (eps * back.condition));
        CHECK(error < 4 * eps * back.condition);
      }
    }
  MESSAGE("largest error / (eps condition): " << worst);
}

TEST_CASE("DQMOM: scaling the nodes by a power of two scales the sources exactly (no unit dependence)") {
  const int n = 4;
  const auto xi = first<double>(sizes, n), phi = first<double>(fractions, n);
  const std::array<double, 8> s{1e-3, 2e-7, 3e-11, 5e-15, -1e-18, 2e-22, 7e-26, 1e-30};
  std::array<double, 8> xi_scaled{}, s_scaled{};
  const double factor = std::ldexp(1.0, 20);  // ~1e6: m to about µm
  for (int i = 0; i < n; ++i) xi_scaled[i] = xi[i] * factor;
  for (int k = 0; k < 2 * n; ++k) s_scaled[k] = s[k] * std::pow(factor, k);
  const auto c = dqmom::solve<double, 8>(xi, phi, first<double>(s, 2 * n));
  const auto cs = dqmom::solve<double, 8>(first<double>(xi_scaled, n), phi, first<double>(s_scaled, 2 * n));
  CHECK(c.condition == cs.condition);
  for (int i = 0; i < n; ++i) {
    CHECK(cs.weight[i] == c.weight[i]);
    CHECK(cs.weighted_node[i] == c.weighted_node[i] * factor);
  }
}

TEST_CASE("DQMOM coincident nodes: merged below the gap, the limit of the unmerged solve, lower moments exact") {
  // Three nodes, the last two a relative gap δ apart, growing at rates that are smooth in ξ.
  auto case_at = [](double gap, const dqmom::Options& options) {
    const std::array<double, 3> xi{100e-6, 200e-6, 200e-6 * (1 + gap)}, phi{0.2, 0.1, 0.3};
    std::array<double, 3> g{};
    for (int i = 0; i < 3; ++i) g[i] = 1e-7 * std::sqrt(xi[i] / 1e-4);
    const dqmom::System<double, 3> system{std::span<const double>(xi), std::span<const double>(phi), options};
    const auto terms =
        dqmom::growth_terms<double, 3>(dqmom::Weights::volume_fraction, std::span<const double>(phi),
                                       std::span<const double>(xi), std::span<const double>(g));
    return std::pair{system.solve(std::span<const dqmom::PointSource<double>>(terms)), xi};
  };
  const auto [unmerged, xi_far] = case_at(1e-3, {});
  const auto [merged, xi_near] = case_at(1e-6, {});
  CHECK(unmerged.status == dqmom::SourceStatus::ok);
  REQUIRE(merged.status == dqmom::SourceStatus::merged_nodes);
  CHECK(merged.distinct_nodes == 2);
  // Growth is consistent with two nodes: the merged sources are the limit of the unmerged ones
  // (which differ from it by O(δ) = 1e-3).
  for (int i = 0; i < 3; ++i) {
    CHECK(relative(merged.weight[i], unmerged.weight[i]) < 3e-3);
    CHECK(relative(merged.weighted_node[i], unmerged.weighted_node[i]) < 3e-3);
  }
  // The merged members share one growth rate and one relative weight change.
  const std::array<double, 3> phi{0.2, 0.1, 0.3};
  CHECK(relative(merged.weight[1] / phi[1], merged.weight[2] / phi[2]) < 1e-14);
  CHECK(relative((merged.weighted_node[1] - xi_near[1] * merged.weight[1]) / phi[1],
                 (merged.weighted_node[2] - xi_near[2] * merged.weight[2]) / phi[2]) < 1e-12);
  // Arbitrary moment sources: moments 0 … 2ν' − 1 = 3 are honoured, the sources stay bounded;
  // without merging (gap 0) the same sources are of order δ⁻³ larger.
  const std::array<double, 6> s{1e-3, 2e-7, 3e-11, 5e-15, -1e-18, 2e-22};
  const std::array<double, 3> weights{0.2, 0.1, 0.3};
  const auto bounded = dqmom::solve<double, 3>(std::span<const double>(xi_near), std::span<const double>(weights),
                                               std::span<const double>(s));
  const auto implied_moments = implied<3>(std::span<const double>(xi_near), bounded, 4);
  for (int k = 0; k < 4; ++k) CHECK(relative(implied_moments[k], s[k]) < 1e-10);
  const auto exploding = dqmom::solve<double, 3>(std::span<const double>(xi_near), std::span<const double>(weights),
                                                 std::span<const double>(s), dqmom::Options{.merge_gap = 0});
  CHECK(exploding.status == dqmom::SourceStatus::ok);
  CHECK(std::abs(exploding.weight[1]) > 1e6 * std::abs(bounded.weight[1]));
}

TEST_CASE("DQMOM any orders: fractional orders give the growth identity, integer orders agree with the Hermite solve") {
  const int n = 3;
  const auto xi = first<double>(sizes, n), phi = first<double>(fractions, n);
  const std::array<double, 3> g{1e-7, -2e-7, 3e-7};
  const std::array<double, 6> orders{0, 1, 1.0 / 3, 2.0 / 3, 4.0 / 3, 5.0 / 3};
  const auto s = dqmom::growth_moment_sources(dqmom::Weights::volume_fraction, phi, xi, std::span<const double>(g), orders);
  const auto c = dqmom::solve_orders<double, 3>(xi, phi, std::span<const double>(orders), std::span<const double>(s));
  REQUIRE(c.status == dqmom::SourceStatus::ok);
  for (int i = 0; i < n; ++i) {
    CHECK(relative(c.weight[i], 3 * phi[i] * g[i] / xi[i]) < 1e3 * eps * c.condition);
    CHECK(relative(c.weighted_node[i], 4 * phi[i] * g[i]) < 1e3 * eps * c.condition);
  }
  const std::array<double, 6> integer{0, 1, 2, 3, 4, 5}, random_s{1e-3, 2e-7, 3e-11, 5e-15, -1e-18, 2e-22};
  const auto dense = dqmom::solve_orders<double, 3>(xi, phi, std::span<const double>(integer), std::span<const double>(random_s));
  const auto hermite = dqmom::solve<double, 3>(xi, phi, std::span<const double>(random_s));
  CHECK(relative(dense.condition, hermite.condition) < 1e-6);
  for (int i = 0; i < n; ++i) {
    CHECK(std::abs(dense.weight[i] - hermite.weight[i]) < 4 * eps * hermite.condition * std::abs(hermite.weight[0]));
    CHECK(std::abs(dense.weighted_node[i] - hermite.weighted_node[i]) <
          4 * eps * hermite.condition * std::abs(hermite.weighted_node[0]));
  }
  // 0 and 1 must come first, orders distinct and finite.
  const std::array<double, 6> swapped{1, 0, 2, 3, 4, 5}, repeated{0, 1, 2, 2, 4, 5};
  for (const auto& bad : {swapped, repeated})
    CHECK(dqmom::solve_orders<double, 3>(xi, phi, std::span<const double>(bad), std::span<const double>(random_s)).status ==
          dqmom::SourceStatus::invalid_input);
}

TEST_CASE("DQMOM invalid input: counts, non-positive or non-finite nodes, negative weights") {
  const std::array<double, 2> s2{1, 1}, good{1e-4, 2e-4}, w{1, 1};
  const std::array<double, 4> s4{1, 1, 1, 1};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(dqmom::solve<double, 2>(std::span<const double>(), std::span<const double>()).size == 0);
  CHECK(dqmom::solve<double, 2>(std::span<const double>(good), std::span<const double>(s2)).size == 0);  // 2 s for 2 nodes
  for (const auto& bad : {std::array<double, 2>{-1e-4, 2e-4}, std::array<double, 2>{0, 2e-4}, std::array<double, 2>{nan, 2e-4}}) {
    const auto c = dqmom::solve<double, 2>(std::span<const double>(bad), std::span<const double>(w), std::span<const double>(s4));
    CHECK(c.status == dqmom::SourceStatus::invalid_input);
    CHECK(c.size == 0);
  }
  const std::array<double, 2> negative_weight{1, -1};
  CHECK(dqmom::solve<double, 2>(std::span<const double>(good), std::span<const double>(negative_weight),
                                std::span<const double>(s4))
            .status == dqmom::SourceStatus::invalid_input);
  const std::array<dqmom::PointSource<double>, 1> third_derivative{{{1e-4, 1, 3}}};
  CHECK(dqmom::System<double, 2>(std::span<const double>(good), std::span<const double>(w))
            .solve(std::span<const dqmom::PointSource<double>>(third_derivative))
            .status == dqmom::SourceStatus::invalid_input);
}

TEST_CASE("DQMOM in float and long double: the growth identity and the two-node closed form") {
  auto check = [](auto zero) {
    using T = decltype(zero);
    const std::array<T, 3> xi{T(75e-6), T(103e-6), T(240e-6)}, phi{T(0.131), T(0.169), T(0.19)}, g{T(1e-7), T(2e-7), T(-1e-7)};
    const dqmom::System<T, 3> system{std::span<const T>(xi), std::span<const T>(phi)};
    const auto terms = dqmom::growth_terms<T, 3>(dqmom::Weights::volume_fraction, std::span<const T>(phi),
                                                 std::span<const T>(xi), std::span<const T>(g));
    const auto c = system.solve(std::span<const dqmom::PointSource<T>>(terms));
    const T tolerance = 8 * std::numeric_limits<T>::epsilon();
    for (int i = 0; i < 3; ++i) {
      CHECK(std::abs(c.weight[i] / (3 * phi[i] * g[i] / xi[i]) - 1) < tolerance);
      CHECK(std::abs(c.weighted_node[i] / (4 * phi[i] * g[i]) - 1) < tolerance);
    }
  };
  check(0.0f);
  check(0.0L);
}

TEST_CASE("DQMOM diffusivities: the thesis's eq. 6.24 and 6.25 examples") {
  // The self-diffusivity of eq. 6.24 lives in kinetic_theory/ (class_transport.hpp).
  CHECK(fluidbed::kinetic_theory::self_diffusivity(1e-4, 200e-6, 0.5) == doctest::Approx(7.52e-7).epsilon(1e-3));
  CHECK(fluidbed::kinetic_theory::self_diffusivity(1e-4, 200e-6, 0.5) ==
        doctest::Approx(std::sqrt(1e-4) * 200e-6 / (3 * std::sqrt(M_PI) * 0.5)));
  CHECK(dqmom::upwind_numerical_diffusivity(0.10, 5e-3) == doctest::Approx(2.5e-4));
  CHECK(dqmom::upwind_numerical_diffusivity(-0.10, 5e-3) == doctest::Approx(2.5e-4));
  CHECK(dqmom::diffusion_intensity(2.5e-4, 0.3, 4e-4) == doctest::Approx(3e-8));
}

TEST_CASE("Moment-specific velocities v_k = sum phi xi^k v / M_k and node-wise upwind fluxes") {
  const std::array<double, 2> phi{0.36, 0.24}, xi{102e-6, 314e-6};
  const std::array<fluidbed::Vector3<double>, 2> v{{{0, 0, 0.01}, {0, 0, -0.02}}};
  for (double k : {0.0, 1.0, 2.0, 3.0, 1.5}) {
    const auto p = dqmom::moment_velocity_coefficients<double, 2>(std::span<const double>(phi), std::span<const double>(xi), k);
    const auto vk = fluidbed::scaled(p[0], v[0]);
    const double a = phi[0] * std::pow(xi[0], k), b = phi[1] * std::pow(xi[1], k);
    CHECK(p[0] + p[1] == doctest::Approx(1).epsilon(1e-15));
    CHECK(vk[2] + p[1] * v[1][2] == doctest::Approx((a * 0.01 - b * 0.02) / (a + b)));
  }
  // All nodes at one velocity: every moment moves with it (Σ_r p_kr = 1).
  const std::array<double, 2> same{0.05, 0.05};
  for (double k = 0; k < 4; ++k)
    CHECK(dqmom::moment_velocity<double, 2>(std::span<const double>(phi), std::span<const double>(xi),
                                            std::span<const double>(same), k) == doctest::Approx(0.05).epsilon(1e-15));
  // No mass: zero velocity.
  const std::array<double, 2> none{0, 0}, speeds{0.01, 0.03};
  CHECK(dqmom::moment_velocity<double, 2>(std::span<const double>(none), std::span<const double>(xi),
                                          std::span<const double>(speeds), 2.0) == 0);
  // Upwind: node 0 flows right (from the left cell), node 1 left (from the right cell).
  const std::array<double, 2> right_phi{0.1, 0.5}, right_xi{110e-6, 300e-6}, normal{0.01, -0.02};
  const double flux = dqmom::upwind_moment_flux(std::span<const double>(phi), std::span<const double>(xi),
                                                std::span<const double>(right_phi), std::span<const double>(right_xi),
                                                std::span<const double>(normal), 3.0);
  CHECK(flux == doctest::Approx(0.36 * std::pow(102e-6, 3) * 0.01 - 0.5 * std::pow(300e-6, 3) * 0.02));
}

TEST_CASE("DQMOM state from moments (a 3-atom measure) and nodes of vanishing weights") {
  const std::array<double, 3> xi{75e-6, 103e-6, 240e-6}, phi{0.262, 0.338, 0.1};
  std::array<double, 6> m{};
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 3; ++i) m[k] += phi[i] * std::pow(xi[i], k);
  InversionStatus status{};
  const auto state = dqmom::state_from_moments<double, 3>(std::span<const double>(m), &status);
  REQUIRE(status == InversionStatus::ok);
  REQUIRE(state.size == 3);
  for (int i = 0; i < 3; ++i) {
    CHECK(relative(state.weight[i], phi[i]) < 1e-10);
    CHECK(relative(state.weighted_node[i], phi[i] * xi[i]) < 1e-10);
  }
  // A weight that vanished keeps the fallback node; the others are a ξ / a.
  dqmom::State<double, 3> faded = state;
  faded.weight[1] = 1e-20;
  faded.weighted_node[1] = 3e-20;  // ratio 3 m: meaningless
  const auto nodes = dqmom::nodes_of<double, 3>(faded, std::array<double, 3>{1, 103e-6, 1});
  CHECK(nodes[1] == 103e-6);
  CHECK(relative(nodes[0], xi[0]) < 1e-10);
  CHECK(relative(nodes[2], xi[2]) < 1e-10);
}

TEST_CASE("DQMOM batched: every cell as the per-cell System (within 8 eps condition), merged and invalid cells included") {
  constexpr int n = 4, count = 203;  // not a multiple of the lanes
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0, 1), sign(-1, 1);
  std::vector<std::vector<double>> nodes(n, std::vector<double>(count)), weights(n, std::vector<double>(count)),
      s(2 * n, std::vector<double>(count)), a(n, std::vector<double>(count)), b(n, std::vector<double>(count));
  std::vector<dqmom::SourceStatus> status(count);
  std::vector<double> condition(count);
  for (int c = 0; c < count; ++c) {
    for (int i = 0; i < n; ++i) nodes[i][c] = 20e-6 * std::pow(100.0, unit(random)), weights[i][c] = unit(random);
    if (c % 17 == 3) nodes[2][c] = nodes[1][c] * (1 + 1e-9);  // merged
    if (c % 29 == 5) nodes[0][c] = -nodes[0][c];             // invalid
    for (int k = 0; k < 2 * n; ++k) s[k][c] = sign(random) * std::pow(300e-6, k);
  }
  dqmom::SourceBatch<double, n> batch;
  for (int i = 0; i < n; ++i) {
    batch.nodes[i] = nodes[i];
    batch.weights[i] = weights[i];
    batch.weight_sources[i] = a[i];
    batch.weighted_node_sources[i] = b[i];
  }
  for (int k = 0; k < 2 * n; ++k) batch.moment_sources[k] = s[k];
  batch.status = status;
  batch.condition = condition;
  dqmom::solve_batched(batch);
  int merged = 0, invalid = 0;
  for (int c = 0; c < count; ++c) {
    INFO("cell " << c);
    std::array<double, n> x{}, w{};
    std::array<double, 2 * n> sc{};
    for (int i = 0; i < n; ++i) x[i] = nodes[i][c], w[i] = weights[i][c];
    for (int k = 0; k < 2 * n; ++k) sc[k] = s[k][c];
    const auto one = dqmom::solve<double, n>(std::span<const double>(x), std::span<const double>(w), std::span<const double>(sc));
    REQUIRE(status[c] == one.status);
    merged += one.status == dqmom::SourceStatus::merged_nodes;
    invalid += one.status == dqmom::SourceStatus::invalid_input;
    if (one.status == dqmom::SourceStatus::invalid_input) continue;
    CHECK(relative(condition[c], one.condition) < 1e-12);
    double largest_a = 0, largest_b = 0;
    for (int i = 0; i < n; ++i) largest_a = std::max(largest_a, std::abs(one.weight[i])), largest_b = std::max(largest_b, std::abs(one.weighted_node[i]));
    for (int i = 0; i < n; ++i) {
      CHECK(std::abs(a[i][c] - one.weight[i]) <= 8 * eps * one.condition * largest_a);
      CHECK(std::abs(b[i][c] - one.weighted_node[i]) <= 8 * eps * one.condition * largest_b);
    }
  }
  CHECK(merged == 12);
  CHECK(invalid == 7);
  // Without the condition field the sources are the same.
  std::vector<std::vector<double>> a2 = a;
  for (int i = 0; i < n; ++i) batch.weight_sources[i] = a2[i];
  batch.condition = {};
  dqmom::solve_batched(batch);
  CHECK(a2 == a);
}

TEST_CASE("DQMOM conventions: number-density sources as volume-fraction sources (seed 001 eqs 77-78 corrected), seed 001 printed rows") {
  const int n = 3;
  const auto xi = first<double>(sizes, n);
  const double shape = M_PI / 6;
  const std::array<double, 3> w{1e9, 3e8, 2e7}, g{1e-7, -2e-7, 3e-7};  // number densities [m^-3], growth [m/s]
  std::array<double, 3> phi{};
  for (int i = 0; i < n; ++i) phi[i] = shape * std::pow(xi[i], 3) * w[i];
  const dqmom::System<double, 3> number_system{xi, std::span<const double>(w)};
  const auto number_terms = dqmom::growth_terms<double, 3>(dqmom::Weights::number_density, std::span<const double>(w), xi,
                                                           std::span<const double>(g));
  const auto number = number_system.solve(std::span<const dqmom::PointSource<double>>(number_terms));
  const auto volume = dqmom::volume_sources_from_number(number, xi, shape);
  for (int i = 0; i < n; ++i) {
    CHECK(relative(volume.weight[i], 3 * phi[i] * g[i] / xi[i]) < 1e-14);
    CHECK(relative(volume.weighted_node[i], 4 * phi[i] * g[i]) < 1e-14);
  }
  // Any number sources: the chain rule by a small step of w and wξ, against the printed eq. 77,
  // which has the volume fraction where the weight's source c^w belongs.
  dqmom::Sources<double, 3> any;
  any.size = n;
  for (int i = 0; i < n; ++i) any.weight[i] = 1e7 * (i + 1), any.weighted_node[i] = 2e3 * (2 - i);
  const auto converted = dqmom::volume_sources_from_number(any, xi, shape);
  const double dt = 1e-6;
  for (int i = 0; i < n; ++i) {
    const double w1 = w[i] + dt * any.weight[i], wx1 = w[i] * xi[i] + dt * any.weighted_node[i];
    const double phi1 = shape * std::pow(wx1, 3) / (w1 * w1), phi_x1 = shape * std::pow(wx1, 4) / std::pow(w1, 3);
    CHECK(relative(converted.weight[i], (phi1 - phi[i]) / dt) < 1e-5);
    CHECK(relative(converted.weighted_node[i], (phi_x1 - phi[i] * xi[i]) / dt) < 1e-5);
    const double printed = shape * (3 * xi[i] * xi[i] * any.weighted_node[i] - 2 * std::pow(xi[i], 3) * phi[i]);
    CHECK(relative(printed, (phi1 - phi[i]) / dt) > 1e-2);
  }
  // Random sources: Niemi's printed rows (k = 2 of the c^ξ block as 2ξ², the last c^a row with
  // the opposite sign) do not reproduce the moment sources the correct rows do.
  const std::array<double, 6> s{1e-3, 2e-7, 3e-11, 5e-15, -1e-18, 2e-22};
  const auto c = dqmom::solve<double, 3>(xi, std::span<const double>(w), std::span<const double>(s));
  double printed_k2 = 0, printed_last = 0;
  for (int i = 0; i < n; ++i) {
    printed_k2 += -xi[i] * xi[i] * c.weight[i] + 2 * xi[i] * xi[i] * c.weighted_node[i];
    printed_last += -2.0 * (1 - n) * std::pow(xi[i], 5) * c.weight[i] + 5 * std::pow(xi[i], 4) * c.weighted_node[i];
  }
  CHECK(relative(printed_k2, s[2]) > 1e-3);
  CHECK(relative(printed_last, s[5]) > 1e-3);
}

TEST_CASE("DQMOM aggregation as point functionals: the same sources as its moments, and no volume created") {
  // Constant kernel b [m³/s] between number densities w_i = φ_i/(k_v ξ_i³); a pair (i, j) makes a
  // particle of diameter (ξ_i³ + ξ_j³)^(1/3). Volume-fraction moments: the birth of volume v_ij at
  // ξ_ij and the death of v_i at ξ_i and v_j at ξ_j, at the rate ½ b w_i w_j.
  const int n = 3;
  const auto xi = first<double>(sizes, n), phi = first<double>(fractions, n);
  const double shape = M_PI / 6, kernel = 1e-12;
  std::vector<dqmom::PointSource<double>> terms;
  std::array<double, 6> s{};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double vi = shape * std::pow(xi[i], 3), vj = shape * std::pow(xi[j], 3);
      const double rate = 0.5 * kernel * (phi[i] / vi) * (phi[j] / vj), born = std::cbrt(std::pow(xi[i], 3) + std::pow(xi[j], 3));
      terms.push_back({born, rate * (vi + vj), 0});
      terms.push_back({xi[i], -rate * vi, 0});
      terms.push_back({xi[j], -rate * vj, 0});
      for (int k = 0; k < 2 * n; ++k)
        s[k] += rate * ((vi + vj) * std::pow(born, k) - vi * std::pow(xi[i], k) - vj * std::pow(xi[j], k));
    }
  const dqmom::System<double, 3> system{xi, phi};
  const auto by_terms = system.solve(std::span<const dqmom::PointSource<double>>(terms));
  const auto by_moments = system.solve(std::span<const double>(s));
  double largest_a = 0, largest_b = 0, total = 0;
  for (int i = 0; i < n; ++i) {
    largest_a = std::max(largest_a, std::abs(by_terms.weight[i]));
    largest_b = std::max(largest_b, std::abs(by_terms.weighted_node[i]));
    total += by_terms.weight[i];
  }
  CHECK(std::abs(total) < 1e-14 * largest_a);  // Σ c^φ = S_0 = 0: volume conserved
  for (int i = 0; i < n; ++i) {
    CHECK(std::abs(by_moments.weight[i] - by_terms.weight[i]) < 4 * eps * system.condition() * largest_a);
    CHECK(std::abs(by_moments.weighted_node[i] - by_terms.weighted_node[i]) < 4 * eps * system.condition() * largest_b);
  }
}

TEST_CASE("DQMOM pure growth as point functionals on random cells, nu = 1..8: a few ulp (the nodes' own values, exactly)") {
  // Weights whose products with the nodes do not round-trip ((a x)/a an ulp off x) and nodes spread
  // by 1.6 per node, where the Lagrange basis has large slopes at the other nodes: a centre an ulp
  // off a node cost 1e-10 here before single nodes kept their exact value.
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst = 0;
  for (int n = 1; n <= 8; ++n)
    for (int trial = 0; trial < 50; ++trial) {
      std::array<double, 8> xi{}, phi{}, g{};
      const double spread = 1 + 0.01 * unit(random);
      for (int i = 0; i < n; ++i)
        xi[i] = 40e-6 * std::pow(1.6, i) * spread, phi[i] = 0.05 + 0.3 * unit(random), g[i] = 1e-7 * (2 * unit(random) - 1);
      const auto x = first<double>(xi, n), w = first<double>(phi, n), rate = first<double>(g, n);
      const dqmom::System<double, 8> system{x, w};
      const auto terms = dqmom::growth_terms<double, 8>(dqmom::Weights::volume_fraction, w, x, rate);
      const auto c = system.solve(first<dqmom::PointSource<double>>(terms, 2 * n));
      for (int i = 0; i < n; ++i) {
        worst = std::max({worst, relative(c.weight[i], 3 * phi[i] * g[i] / xi[i]), relative(c.weighted_node[i], 4 * phi[i] * g[i])});
        CHECK(relative(c.weight[i], 3 * phi[i] * g[i] / xi[i]) < 32 * eps);
        CHECK(relative(c.weighted_node[i], 4 * phi[i] * g[i]) < 32 * eps);
      }
    }
  MESSAGE("largest relative error: " << worst);
}
