// Adaptive inversion: boundary sets with round-off come out with the right number of nodes,
// in any unit; genuine sets keep all their nodes; Gauss–Radau against the 60-digit oracle.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "fluidbed/moments/adaptive.hpp"
#include "fluidbed/moments/moment_set.hpp"
#include "moment_reference.hpp"

using namespace fluidbed::moments;
using fluidbed::test::MomentReference;

namespace {

constexpr int capacity = 8;

template <class T = double>
std::vector<T> moments_of(const std::vector<T>& x, const std::vector<T>& w, int count) {
  std::vector<T> m(static_cast<std::size_t>(count));
  moments_from_quadrature<T>(x, w, m);
  return m;
}

template <class T = double>
AdaptiveInversionResult<T, capacity> adaptive(const std::vector<T>& m, const AdaptiveOptions<T>& options = {}) {
  return invert_adaptive<T, capacity>(std::span<const T>(m), options);
}

// Every returned node and weight is finite.
template <class T, int N>
bool finite(const Quadrature<T, N>& q) {
  for (int i = 0; i < q.size; ++i)
    if (!std::isfinite(q.nodes[i]) || !std::isfinite(q.weights[i])) return false;
  return true;
}

}  // namespace

TEST_CASE("a single atom in SI units (weight 3.125e12 at 2e-6 m): one node, for any number of moments") {
  const std::vector<double> dirac{3.125e12, 6.25e6, 12.5, 2.5e-5, 5e-11, 1e-16, 2e-22, 4e-28};
  for (int count : {2, 4, 6, 8, 3, 5, 7}) {
    INFO(count << " moments");
    const auto r = adaptive(std::vector<double>(dirac.begin(), dirac.begin() + count));
    REQUIRE(r.quadrature.size == 1);
    CHECK(r.quadrature.nodes[0] == doctest::Approx(2e-6).epsilon(1e-15));
    CHECK(r.quadrature.weights[0] == 3.125e12);
    CHECK(r.status == (count / 2 == 1 ? InversionStatus::ok : InversionStatus::reduced));
    CHECK(r.moments_used == 2);
  }
}

TEST_CASE("coincident atoms merge into one node with the summed weight, in µm and in m") {
  for (double unit : {1.0, 1e-6}) {
    for (int count : {4, 6, 8}) {
      INFO("unit " << unit << ", " << count << " moments");
      const auto r = adaptive(moments_of({137 * unit, 137 * unit}, {0.25, 0.35}, count));
      REQUIRE(r.quadrature.size == 1);
      CHECK(r.quadrature.nodes[0] == doctest::Approx(137 * unit).epsilon(1e-14));
      CHECK(r.quadrature.weights[0] == doctest::Approx(0.6).epsilon(1e-15));
      CHECK(r.status == InversionStatus::reduced);
    }
  }
}

TEST_CASE("two atoms given 6, 8, 10 moments: two nodes, the atoms") {
  for (double unit : {1.0, 1e-6, 1e-3}) {
    for (int count : {4, 6, 8, 10}) {
      INFO("unit " << unit << ", " << count << " moments");
      const auto r = adaptive(moments_of({75 * unit, 355 * unit}, {0.262, 0.338}, count));
      REQUIRE(r.quadrature.size == 2);
      CHECK(r.quadrature.nodes[0] == doctest::Approx(75 * unit).epsilon(1e-12));
      CHECK(r.quadrature.nodes[1] == doctest::Approx(355 * unit).epsilon(1e-12));
      CHECK(r.quadrature.weights[0] == doctest::Approx(0.262).epsilon(1e-12));
      CHECK(r.status == (count == 4 ? InversionStatus::ok : InversionStatus::reduced));
      if (count > 4) CHECK(r.reduced_by != ReductionRule::none);
    }
  }
}

TEST_CASE("the 4-class mixture of seed 000 Table 6.4 in µm and in m: four nodes from 8, 10, 12, 14, 16 moments") {
  const auto& oracle = MomentReference::instance();
  for (const std::string name : {"four_class", "four_class_si"}) {
    const double unit = name == "four_class" ? 1.0 : 1e-6;
    const std::vector<double> x{75 * unit, 103 * unit, 240 * unit, 355 * unit}, w{0.131, 0.169, 0.190, 0.110};
    for (int count = 8; count <= 16; count += 2) {
      INFO(name << ", " << count << " moments");
      const auto m = count == 8 ? oracle.moments(name) : moments_of(x, w, count);
      const auto r = adaptive(m);
      REQUIRE(r.quadrature.size == 4);
      CHECK(r.moments_used == 8);
      CHECK(r.status == (count == 8 ? InversionStatus::ok : InversionStatus::reduced));
      for (int i = 0; i < 4; ++i) {
        CHECK(r.quadrature.nodes[i] == doctest::Approx(x[std::size_t(i)]).epsilon(1e-9));
        CHECK(r.quadrature.weights[i] == doctest::Approx(w[std::size_t(i)]).epsilon(1e-9));
      }
    }
  }
}

TEST_CASE("genuine (non-degenerate) oracle sets keep every node: adaptive = invert") {
  const auto& oracle = MomentReference::instance();
  for (const std::string name : {"legendre01", "lognormal_si", "gamma_si", "sieve_psd", "sieve_one_bin", "three_atoms",
                                 "seed003_A_N4", "seed003_B_N4", "seed003_mix_N4"}) {
    const auto& m = oracle.moments(name);
    const int n = std::min(int(m.size() / 2), 4);
    INFO(name << " N=" << n);
    const auto plain = invert<double, capacity>(std::span<const double>(m.data(), std::size_t(2 * n)));
    const auto r = invert_adaptive<double, capacity>(std::span<const double>(m.data(), std::size_t(2 * n)));
    CHECK(r.status == InversionStatus::ok);
    CHECK(r.reduced_by == ReductionRule::none);
    REQUIRE(r.quadrature.size == n);
    for (int i = 0; i < n; ++i) {
      CHECK(r.quadrature.nodes[i] == plain.quadrature.nodes[i]);
      CHECK(r.quadrature.weights[i] == plain.quadrature.weights[i]);
    }
    CHECK(r.boundary_distance == plain.boundary_distance);
  }
}

TEST_CASE("random well-separated atoms (5% apart), 1 to 4 of them, given more moments than atoms") {
  // A deterministic ensemble (the generator's raw output is specified by the standard; the
  // mapping to [0, 1) is written out). Units from 1e-7 to 1e2.
  std::mt19937_64 engine(2024);
  const auto uniform = [&] { return double(engine() >> 11) * 0x1p-53; };
  int sets = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int k = 1 + int(uniform() * 4);
    const int n = k + 1 + int(uniform() * (6 - k));
    const double unit = std::pow(10.0, -7 + 9 * uniform());
    std::vector<double> x, w;
    while (int(x.size()) < k) {
      const double c = 10 + 400 * uniform();
      if (std::all_of(x.begin(), x.end(), [&](double y) { return std::abs(y - c) >= 0.05 * std::max(y, c); })) {
        x.push_back(c);
        w.push_back(0.05 + uniform());
      }
    }
    std::vector<double> scaled = x;
    for (double& v : scaled) v *= unit;
    const auto r = adaptive(moments_of(scaled, w, 2 * n));
    INFO("trial " << trial << ": " << k << " atoms, " << 2 * n << " moments, unit " << unit);
    REQUIRE(r.quadrature.size == k);
    std::sort(x.begin(), x.end());
    for (int i = 0; i < k; ++i) CHECK(r.quadrature.nodes[i] == doctest::Approx(x[std::size_t(i)] * unit).epsilon(1e-6));
    ++sets;
  }
  CHECK(sets == 400);
}

TEST_CASE("the weight rule and the node rule, each with its documented relative threshold") {
  // A weight of 1e-7 m_0 (below ε^{1/3} = 6.06e-6): dropped; the 1-node rule keeps m_0, m_1.
  const auto light = moments_of({100, 200}, {1, 1e-7}, 4);
  const auto r = adaptive(light);
  CHECK(r.reduced_by == ReductionRule::small_weight);
  REQUIRE(r.quadrature.size == 1);
  CHECK(r.quadrature.nodes[0] == doctest::Approx(light[1] / light[0]).epsilon(1e-15));
  AdaptiveOptions<double> permissive;
  permissive.min_weight_fraction = permissive.min_node_separation = 1e-9;
  const auto kept = adaptive(light, permissive);
  CHECK(kept.status == InversionStatus::ok);
  REQUIRE(kept.quadrature.size == 2);
  CHECK(kept.quadrature.weights[1] == doctest::Approx(1e-7).epsilon(1e-6));
  // Two equal atoms 4e-6 apart (relative): ζ_2/ζ_1 = 4e-12 < τ = ε^{2/3}, the second level is
  // round-off (it would give a node 3e-5 away holding 0.4% of the weight): merged.
  const auto close = moments_of({100, 100 * (1 + 4e-6)}, {0.3, 0.3}, 4);
  const auto merged = adaptive(close);
  CHECK(merged.reduced_by == ReductionRule::near_boundary);
  CHECK(merged.status == InversionStatus::reduced);
  CHECK(merged.realizable_nodes == 2);  // the sign test alone passes
  REQUIRE(merged.quadrature.size == 1);
  CHECK(merged.quadrature.weights[0] == doctest::Approx(0.6).epsilon(1e-15));
  CHECK(merged.quadrature.nodes[0] == doctest::Approx(100 * (1 + 2e-6)).epsilon(1e-15));
  // Atoms 5e-4 apart are resolved (ζ_2/ζ_1 = 6e-8) and kept by default; a user who wants
  // classes within 0.1% merged sets e_abs = 1e-3: the node rule.
  const auto pair = moments_of({100, 100.05}, {0.3, 0.3}, 4);
  const auto resolved = adaptive(pair);
  REQUIRE(resolved.quadrature.size == 2);
  CHECK(resolved.quadrature.nodes[1] == doctest::Approx(100.05).epsilon(1e-8));  // conditioning ~ε/d²
  AdaptiveOptions<double> coarse;
  coarse.min_node_separation = 1e-3;
  const auto joined = adaptive(pair, coarse);
  CHECK(joined.reduced_by == ReductionRule::close_nodes);
  REQUIRE(joined.quadrature.size == 1);
  CHECK(joined.quadrature.nodes[0] == doctest::Approx(100.025).epsilon(1e-15));
  // The defaults are ε^{1/3} of the type.
  CHECK(default_degeneracy_threshold<double>() == doctest::Approx(6.0554544523933395e-6).epsilon(1e-15));
  CHECK(default_degeneracy_threshold<float>() == doctest::Approx(4.921566e-3f).epsilon(1e-6));
  CHECK(default_boundary_tolerance<double>() == doctest::Approx(3.6668e-11).epsilon(1e-4));
}

TEST_CASE("Gauss–Radau with node 0 of uniform 0 to 1 from 11 moments: the oracle's 6-point rule") {
  const auto& oracle = MomentReference::instance();
  const auto& m = oracle.moments("radau_legendre01");
  REQUIRE(m.size() == 11);
  const auto& nodes = oracle.values("radau_legendre01", 6, "node");
  const auto& weights = oracle.values("radau_legendre01", 6, "weight");
  // Tolerance as in test_moment_oracle.cpp: 8 · 2n · conditioning.
  const double node_tolerance = 8 * 12 * oracle.values("radau_legendre01", 6, "node_condition")[0];
  const double weight_tolerance = 8 * 12 * oracle.values("radau_legendre01", 6, "weight_condition")[0];
  AdaptiveOptions<double> options;
  options.radau = true;
  const auto r = adaptive(m, options);
  const auto direct = gauss_radau<double, capacity>(std::span<const double>(m), 0.0);
  for (const InversionResult<double, capacity>* q : {static_cast<const InversionResult<double, capacity>*>(&r), &direct}) {
    CHECK(q->status == InversionStatus::ok);
    REQUIRE(q->quadrature.size == 6);
    CHECK(q->quadrature.nodes[0] == 0.0);  // the fixed node, exactly
    CHECK(q->quadrature.weights[0] == doctest::Approx(1.0 / 36).epsilon(weight_tolerance * 36));
    for (int i = 0; i < 6; ++i) {
      CHECK(std::abs(q->quadrature.nodes[i] - nodes[std::size_t(i)]) <= node_tolerance);
      CHECK(std::abs(q->quadrature.weights[i] - weights[std::size_t(i)]) <= weight_tolerance);
    }
  }
  CHECK(r.radau);
  CHECK(r.moments_used == 11);
  CHECK(r.realizable_nodes == 6);
  // Exact to degree 10 (the forward moments), not 11.
  std::array<double, 12> back{};
  moments_from_quadrature(r.quadrature, std::span<double>(back));
  for (int k = 0; k < 11; ++k) CHECK(back[k] == doctest::Approx(m[std::size_t(k)]).epsilon(1e-9));
  CHECK(std::abs(back[11] - 1.0 / 12) > 1e-7);  // the rule's error at degree 11: 3.9e-7
  // Without radau the 11th moment is dropped: the 5-point Gauss rule.
  const auto gauss = adaptive(m);
  CHECK(gauss.status == InversionStatus::ok);
  CHECK(gauss.quadrature.size == 5);
  CHECK(gauss.moments_used == 10);
  CHECK_FALSE(gauss.radau);
}

TEST_CASE("Gauss–Radau at the lower sieve aperture uses the odd moment, where it fails, Gauss") {
  // A 45–150 µm sieve cut (the oracle's sieve_psd), 7 moments, node fixed at the 45 µm
  // aperture: 4 nodes reproducing M_0 … M_6.
  const std::array<double, 8> edges{45, 53, 63, 75, 90, 106, 125, 150};
  const std::array<double, 7> fractions{0.05, 0.10, 0.20, 0.30, 0.20, 0.10, 0.05};
  std::vector<double> m(7);
  sieve_moments(SieveAnalysis<double>{edges, fractions}, 0.4, std::span<double>(m));
  AdaptiveOptions<double> options;
  options.radau = true;
  options.fixed_node = 45;
  const auto r = adaptive(m, options);
  CHECK(r.status == InversionStatus::ok);
  CHECK(r.radau);
  REQUIRE(r.quadrature.size == 4);
  CHECK(r.quadrature.nodes[0] == 45.0);
  std::vector<double> back(7);
  moments_from_quadrature(r.quadrature, std::span<double>(back));
  for (int k = 0; k < 7; ++k) CHECK(back[std::size_t(k)] == doctest::Approx(m[std::size_t(k)]).epsilon(1e-11));
  // Uniform [0, 1], 3 moments, node fixed at 0.6: the 2-point rule has its other node at −1/3,
  // outside [0, ∞) — the Gauss rule (1 node at 1/2) is returned instead.
  AdaptiveOptions<double> inside;
  inside.radau = true;
  inside.fixed_node = 0.6;
  const auto g = adaptive({1, 0.5, 1.0 / 3}, inside);
  CHECK(g.reduced_by == ReductionRule::radau_invalid);
  CHECK(g.status == InversionStatus::reduced);
  CHECK_FALSE(g.radau);
  REQUIRE(g.quadrature.size == 1);
  CHECK(g.quadrature.nodes[0] == 0.5);
  const auto direct = gauss_radau<double, capacity>(std::span<const double>(std::array<double, 3>{1, 0.5, 1.0 / 3}), 0.6);
  CHECK(direct.status == InversionStatus::not_realizable);
  CHECK(direct.quadrature.size == 0);
  // An odd realizable prefix: uniform moments with m_3 := 0 fail at ζ_3, so m_0, m_1, m_2 are
  // realizable: Radau at 0 gives 2 nodes where Gauss gives 1.
  const std::vector<double> broken{1, 0.5, 1.0 / 3, 0, 0.2, 1.0 / 6};
  const auto radau = adaptive(broken, [] {
    AdaptiveOptions<double> o;
    o.radau = true;
    return o;
  }());
  CHECK(radau.reduced_by == ReductionRule::realizability);
  CHECK(radau.first_failing_index == 3);
  CHECK(radau.failing_value == doctest::Approx(-8.0 / 3).epsilon(1e-14));
  REQUIRE(radau.quadrature.size == 2);
  CHECK(radau.moments_used == 3);
  CHECK(radau.quadrature.nodes[0] == 0.0);
  CHECK(radau.quadrature.nodes[1] == doctest::Approx(2.0 / 3).epsilon(1e-15));  // (m_2 − 0)/m_1
  CHECK(radau.quadrature.weights[1] == doctest::Approx(0.75).epsilon(1e-15));
  CHECK(adaptive(broken).quadrature.size == 1);
}

TEST_CASE("degenerate and invalid inputs: statuses, never a NaN node or weight") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto check = [](const std::vector<double>& m, InversionStatus status, int nodes,
                        Support support = Support::positive_half_line) {
    AdaptiveOptions<double> options;
    options.inversion.support = support;
    const auto r = adaptive(m, options);
    CHECK(r.status == status);
    CHECK(r.quadrature.size == nodes);
    CHECK(finite(r.quadrature));
    return r;
  };
  check({1, nan, 2, 3}, InversionStatus::invalid_input, 0);
  check({0, 0, 0, 0}, InversionStatus::zero_mass, 0);
  CHECK(check({0, 1e-9, 0, 0}, InversionStatus::not_realizable, 0).failing_value == 0);
  CHECK(check({-1, 2, 4, 8}, InversionStatus::not_realizable, 0).failing_value == -1);
  check({1, 0, 1, 0}, InversionStatus::not_realizable, 0);  // zero mean on [0, ∞)
  const auto pair = check({1, 0, 1, 0}, InversionStatus::ok, 2, Support::real_line);
  CHECK(pair.quadrature.nodes[0] == -1);
  CHECK(pair.quadrature.nodes[1] == 1);
  const auto left = check({1, -2, 4, -8, 16, -32}, InversionStatus::reduced, 1, Support::real_line);
  CHECK(left.quadrature.nodes[0] == -2);
  CHECK(left.reduced_by == ReductionRule::realizability);
  const auto negative_mean = check({1, -2, 4, -8}, InversionStatus::not_realizable, 0);  // on [0, ∞)
  CHECK(negative_mean.first_failing_index == 1);
  CHECK(negative_mean.failing_value == -2);  // in the caller's units
}

TEST_CASE("float and long double: the degenerate examples come out right with ε^{1/3} of the type") {
  const std::vector<float> dirac{3.125e12f, 6.25e6f, 12.5f, 2.5e-5f, 5e-11f, 1e-16f};
  const auto f = adaptive<float>(dirac);
  REQUIRE(f.quadrature.size == 1);
  CHECK(f.quadrature.nodes[0] == doctest::Approx(2e-6).epsilon(1e-6));
  const auto mixture = adaptive<float>(moments_of<float>({75, 103, 240, 355}, {0.131f, 0.169f, 0.190f, 0.110f}, 10));
  REQUIRE(mixture.quadrature.size == 4);
  CHECK(mixture.quadrature.nodes[2] == doctest::Approx(240).epsilon(1e-3));
  const auto l = adaptive<long double>(moments_of<long double>({75e-6L, 355e-6L, 355e-6L}, {0.2L, 0.3L, 0.1L}, 12));
  REQUIRE(l.quadrature.size == 2);
  CHECK(l.quadrature.weights[1] == doctest::Approx(0.4).epsilon(1e-15));
}
