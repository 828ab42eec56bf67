// DQMOM source terms (moments/dqmom.hpp, work in progress): exact identities of the system
// (seed 000 eq. 5.63): pure growth for every ν, the two-node closed forms of seed 000 App. D
// (eqs D.14–D.17, with the −2ξ³ row the seed misprints as −2ξ²), the two-node diffusion sources
// of eq. 6.22, and the recovery of random sources from the moments they imply.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>
#include <span>

#include "fluidbed/moments/dqmom.hpp"

using namespace fluidbed::moments;

namespace {

constexpr std::array<double, 5> sizes{75e-6, 103e-6, 240e-6, 355e-6, 165e-6};  // m (seed 000 Table 6.4 and more)
constexpr std::array<double, 5> fractions{0.131, 0.169, 0.190, 0.110, 0.05};

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

// The left-hand side of the system: the moment sources implied by (c^a, c^ξ).
template <int N>
std::array<double, 2 * N> implied(std::span<const double> xi, const dqmom::Sources<double, N>& c) {
  std::array<double, 2 * N> s{};
  const int n = int(xi.size());
  for (int k = 0; k < 2 * n; ++k)
    for (int i = 0; i < n; ++i)
      s[k] += (1 - k) * std::pow(xi[i], k) * c.weight[i] + k * std::pow(xi[i], k - 1) * c.weighted_node[i];
  return s;
}

}  // namespace

TEST_CASE("DQMOM pure growth: c^phi = 3 phi G/xi and c^xi = 4 phi G (volume), c^w = 0 and c^xi = w G (number)") {
  for (int n = 1; n <= 5; ++n) {
    INFO("nodes " << n);
    std::array<double, 5> growth{};
    for (int i = 0; i < n; ++i) growth[i] = 1e-7 * (1 + i);  // m/s
    const std::span<const double> xi(sizes.data(), n), phi(fractions.data(), n), g(growth.data(), n);
    const auto s = dqmom::growth_sources<double, 5>(dqmom::Weights::volume_fraction, phi, xi, g);
    const auto c = dqmom::solve<double, 5>(xi, std::span<const double>(s.data(), 2 * n));
    REQUIRE(c.size == n);
    const auto sn = dqmom::growth_sources<double, 5>(dqmom::Weights::number_density, phi, xi, g);
    const auto cn = dqmom::solve<double, 5>(xi, std::span<const double>(sn.data(), 2 * n));
    for (int i = 0; i < n; ++i) {
      // (tolerance: the measured error of this solve, ~1e-16 · 10^(2ν); its conditioning is still to
      // be studied against a high-precision solve)
      const double tolerance = 1e-15 * std::pow(10.0, 2 * n);
      CHECK(relative(c.weight[i], 3 * phi[i] * g[i] / xi[i]) < tolerance);
      CHECK(relative(c.weighted_node[i], 4 * phi[i] * g[i]) < tolerance);
      CHECK(std::abs(cn.weight[i]) < tolerance * phi[i] * g[i] / xi[i]);
      CHECK(relative(cn.weighted_node[i], phi[i] * g[i]) < tolerance);
    }
  }
}

TEST_CASE("DQMOM two nodes: the closed forms of seed 000 App. D (D.14-D.17) and the diffusion sources of eq. 6.22") {
  const double x1 = 75e-6, x2 = 103e-6;
  const std::array<double, 2> xi{x1, x2};
  const std::array<double, 4> S{1e-3, 2e-7, 3e-11, 5e-15};  // 𝒮_0 … 𝒮_3, any
  const auto c = dqmom::solve<double, 2>(std::span<const double>(xi), std::span<const double>(S));
  const double d3 = std::pow(x1 - x2, 3);
  const double c1_phi = (x2 * x2 * (3 * x1 - x2) * S[0] - 6 * x1 * x2 * S[1] + 3 * (x1 + x2) * S[2] - 2 * S[3]) / d3;
  const double c2_phi = (x1 * x1 * (3 * x2 - x1) * S[0] - 6 * x1 * x2 * S[1] + 3 * (x1 + x2) * S[2] - 2 * S[3]) / -d3;
  const double c1_xi = (2 * x1 * x1 * x2 * x2 * S[0] - x2 * (4 * x1 * x1 + x1 * x2 + x2 * x2) * S[1] +
                        2 * (x1 * x1 + x1 * x2 + x2 * x2) * S[2] - (x1 + x2) * S[3]) /
                       d3;
  const double c2_xi = (2 * x1 * x1 * x2 * x2 * S[0] - x1 * (4 * x2 * x2 + x1 * x2 + x1 * x1) * S[1] +
                        2 * (x1 * x1 + x1 * x2 + x2 * x2) * S[2] - (x1 + x2) * S[3]) /
                       -d3;
  CHECK(relative(c.weight[0], c1_phi) < 1e-10);
  CHECK(relative(c.weight[1], c2_phi) < 1e-10);
  CHECK(relative(c.weighted_node[0], c1_xi) < 1e-10);
  CHECK(relative(c.weighted_node[1], c2_xi) < 1e-10);
  // Diffusion: 𝒞_i = 𝒟 φ_i |∇ξ_i|², eq. 6.22 with i ≠ j.
  const std::array<double, 2> diffusion{7.5e-7 * 0.262 * 1e-6, 7.5e-7 * 0.338 * 4e-6};
  const auto sd = dqmom::diffusion_sources<double, 2>(std::span<const double>(xi), std::span<const double>(diffusion));
  const auto cd = dqmom::solve<double, 2>(std::span<const double>(xi), std::span<const double>(sd));
  const double gap2 = (x1 - x2) * (x1 - x2);
  CHECK(relative(cd.weight[0], 6 * (diffusion[1] - diffusion[0]) / gap2) < 1e-10);
  CHECK(relative(cd.weight[1], 6 * (diffusion[0] - diffusion[1]) / gap2) < 1e-10);
  CHECK(relative(cd.weighted_node[0], (2 * diffusion[1] * (x2 + 2 * x1) - 2 * diffusion[0] * (x1 + 2 * x2)) / gap2) <
        1e-10);
  CHECK(relative(cd.weighted_node[1], (2 * diffusion[0] * (x1 + 2 * x2) - 2 * diffusion[1] * (x2 + 2 * x1)) / gap2) <
        1e-10);
}

TEST_CASE("DQMOM: random sources are recovered from the moment sources they imply, 1 to 5 nodes in SI units") {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int n = 1; n <= 5; ++n)
    for (int trial = 0; trial < 20; ++trial) {
      INFO("nodes " << n << ", trial " << trial);
      const std::span<const double> xi(sizes.data(), n);
      dqmom::Sources<double, 5> c;
      c.size = n;
      for (int i = 0; i < n; ++i) c.weight[i] = unit(random), c.weighted_node[i] = 1e-4 * unit(random);
      const auto s = implied<5>(xi, c);
      const auto back = dqmom::solve<double, 5>(xi, std::span<const double>(s.data(), 2 * n));
      // The sources of all nodes are O(1) and O(1e-4): compare at those scales (tolerance as above).
      const double tolerance = 1e-15 * std::pow(10.0, 2 * n);
      for (int i = 0; i < n; ++i) {
        CHECK(std::abs(back.weight[i] - c.weight[i]) < tolerance);
        CHECK(std::abs(back.weighted_node[i] - c.weighted_node[i]) < 1e-4 * tolerance);
      }
    }
}
