// The public realizability test: counts, the failing coefficient, ζ against the 60-digit
// oracle, and the seed-003 diagnostics (log-convexity, Hankel–Hadamard determinants) that show
// the printed moment sets of seed 003 Tables 1–2 log-convex yet not realizable; the Hankel
// determinants at the boundary of moment space, where a ζ is 0 or ∞, against exact ones.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "fluidbed/moments/inversion.hpp"
#include "fluidbed/moments/realizability.hpp"
#include "moment_reference.hpp"

using namespace fluidbed::moments;
using fluidbed::test::MomentReference;

namespace {

constexpr int capacity = 10;

// As tests/test_moment_oracle.cpp: the oracle's conditioning is the first-order error of one
// moment rounded to double; measured ζ errors are <= 13 × node_condition over every case.
double tolerance(double condition, int n) { return 8.0 * 2 * n * condition + 8e-16; }

RealizabilityReport<double, capacity> report(const std::vector<double>& m, std::size_t count,
                                             Support support = Support::positive_half_line) {
  return realizability<double, capacity>(std::span<const double>(m.data(), count), support);
}

}  // namespace

TEST_CASE("realizable oracle cases: status ok, every ζ within the conditioned tolerance") {
  const auto& oracle = MomentReference::instance();
  int checked = 0;
  for (const std::string name : {"legendre01", "laguerre_a", "lognormal_si", "gamma_si", "beta25", "three_atoms",
                                 "four_class", "four_class_si", "sieve_psd", "sieve_one_bin", "hermite_shifted"}) {
    const auto& m = oracle.moments(name);
    for (int n = 1; 2 * std::size_t(n) <= m.size() && n <= capacity; ++n) {
      const auto r = report(m, std::size_t(2 * n));
      const auto& zeta = oracle.values(name, n, "zeta");
      const double condition = oracle.values(name, n, "node_condition")[0];
      INFO(name << " N=" << n);
      REQUIRE(r.status == InversionStatus::ok);
      CHECK(r.realizable_moments == 2 * n);
      CHECK(r.realizable_nodes == n);
      CHECK(r.first_failing_index == 0);
      REQUIRE(r.zeta_count == 2 * n - 1);
      for (int j = 1; j <= 2 * n - 1; ++j)
        CHECK(std::abs(r.zeta[j - 1] - zeta[std::size_t(j)]) <= tolerance(condition, n) * std::abs(zeta[std::size_t(j)]));
      CHECK(r.hankel_positive);
      CHECK(r.hankel_count == 2 * n);
      CHECK(r.boundary_distance > 0);
      ++checked;
    }
  }
  CHECK(checked == 75);
}

TEST_CASE("uniform 0 to 1: the exact ζ, odd counts, and m_3 := 0 fails at ζ_3 = −8/3") {
  // ζ_{2k} = k/(2(2k + 1)), ζ_{2k+1} = (k + 1)/(2(2k + 1)).
  std::vector<double> m(9);
  for (std::size_t k = 0; k < m.size(); ++k) m[k] = 1.0 / double(k + 1);
  for (std::size_t count = 1; count <= 9; ++count) {
    const auto r = report(m, count);
    INFO("count " << count);
    CHECK(r.status == InversionStatus::ok);
    CHECK(r.realizable_moments == int(count));
    CHECK(r.realizable_nodes == int(count) / 2);
    REQUIRE(r.zeta_count == int(count) - 1);  // an odd count tests ζ_{2n} too (Gauss–Radau's need)
    for (int j = 1; j <= r.zeta_count; ++j) {
      const int k = j / 2;
      const double exact = j % 2 == 0 ? k / (2.0 * (2 * k + 1)) : (k + 1) / (2.0 * (2 * k + 1));
      CHECK(r.zeta[j - 1] == doctest::Approx(exact).epsilon(1e-11));
    }
  }
  m[3] = 0;
  const auto r = report(m, 6);
  CHECK(r.status == InversionStatus::reduced);
  CHECK(r.first_failing_index == 3);
  CHECK(r.failing_value == doctest::Approx(-8.0 / 3).epsilon(1e-14));
  CHECK(r.realizable_moments == 3);  // m_0, m_1, m_2: an odd prefix
  CHECK(r.realizable_nodes == 1);
  CHECK(r.recurrence.size == 1);
  CHECK(r.recurrence.alpha[0] == 0.5);
  CHECK(r.recurrence.beta[0] == 1.0);
  // log-convexity fails at ln m_3 = −∞: reported as not log-convex, no differences.
  CHECK_FALSE(r.log_convex);
  CHECK(r.log_second_difference_count == 0);
}

TEST_CASE("seed 003 printed sets: log-convex, yet not realizable — ζ and Hankel determinants") {
  // The 8-moment sets of seed 003 Table 1 (powders A, B) and Table 2 (the mixture) as printed;
  // ln M second differences to the printed 6 figures (checked by moments_reference.py), every
  // Hankel determinant against the generator's det() at 60 digits.
  struct Expected {
    std::string name;
    int failing;
    std::vector<double> second_differences;
  };
  const std::vector<Expected> cases{
      {"seed003_A_printed", 4, {0.0218947, 0.0256566, 0.0169777, 0.0186836, 0.0172602, 0.0170393}},
      {"seed003_B_printed", 4, {0.0333478, 0.0410639, 0.03404, 0.0351392, 0.0353529, 0.0312906}},
      {"seed003_mix_printed", 6, {0.229071, 0.134185, 0.0709952, 0.0469622, 0.0344053, 0.0354173}},
  };
  const auto& oracle = MomentReference::instance();
  for (const Expected& c : cases) {
    INFO(c.name);
    const auto& m = oracle.moments(c.name);
    const auto& zeta = oracle.values(c.name, 4, "zeta");
    REQUIRE(int(oracle.values(c.name, 4, "first_unrealizable_zeta_index")[0]) == c.failing);
    const auto r = report(m, 8);
    CHECK(r.status == InversionStatus::reduced);
    CHECK(r.first_failing_index == c.failing);
    CHECK(r.realizable_moments == c.failing);
    CHECK(r.realizable_nodes == c.failing / 2);
    CHECK(r.failing_value == doctest::Approx(zeta[std::size_t(c.failing)]).epsilon(1e-9));
    REQUIRE(r.zeta_count >= c.failing);
    for (int j = 1; j <= c.failing; ++j) CHECK(r.zeta[j - 1] == doctest::Approx(zeta[std::size_t(j)]).epsilon(1e-9));
    // Seed 003 check 1 passes: ln M_k is convex.
    CHECK(r.log_convex);
    REQUIRE(r.log_second_difference_count == 6);
    for (int k = 0; k < 6; ++k)
      CHECK(r.log_second_differences[k] == doctest::Approx(c.second_differences[std::size_t(k)]).epsilon(2e-5));
    // Check 2 fails: the Hankel determinant H_failing is negative. Every one of the 8 is
    // reported, also beyond the failing one.
    REQUIRE(r.hankel_count == 8);
    CHECK_FALSE(r.hankel_positive);
    CHECK(r.hankel_sign[c.failing] == -1);
    const auto& hankel = oracle.values(c.name, 0, "hankel");
    for (int k = 0; k < 8; ++k) {
      INFO("H_" << k << " = " << hankel[std::size_t(k)]);
      CHECK(r.hankel_sign[k] == (hankel[std::size_t(k)] > 0 ? 1 : -1));
      CHECK(r.log_abs_hankel[k] == doctest::Approx(std::log(std::abs(hankel[std::size_t(k)]))).epsilon(1e-12));
    }
    // The reduced recurrence is the oracle's.
    const auto& alpha = oracle.values(c.name, r.realizable_nodes, "alpha");
    for (int k = 0; k < r.recurrence.size; ++k) CHECK(r.recurrence.alpha[k] == doctest::Approx(alpha[std::size_t(k)]).epsilon(1e-10));
  }
}

TEST_CASE("Hankel determinants where a ζ is 0 or ∞: finite and exact, never 0·∞ (issue 13)") {
  // The set {1, 0, 1e-8, 0} on [0, ∞): ζ_1 = 0 and ζ_2 = +∞. H_2 = m_0 m_2 − m_1² = 1e-8
  // and H_3 = m_1 m_3 − m_2² = −1e-16 came back with sign 0 and a NaN logarithm, as the product
  // ζ_2 · (H_1/H_{−1}) = ∞ · 0 of the ζ route. Also N(0, 1) (every odd moment 0), a set with
  // ζ_3 = 0 and ζ_4 = ∞ (m_1 m_3 = m_2²) and uniform moments with m_3 := 0 (ζ_3 < 0); each
  // determinant against det() at 60 digits (moments_reference.py), on both supports.
  const auto& oracle = MomentReference::instance();
  for (const std::string name : {"hankel_zero_mean", "hankel_normal01", "hankel_zeta3_zero", "hankel_uniform_m3_zero"})
    for (const Support support : {Support::positive_half_line, Support::real_line}) {
      const auto& m = oracle.moments(name);
      const auto& hankel = oracle.values(name, 0, "hankel");
      INFO(name << (support == Support::real_line ? " on the real line" : " on [0, inf)"));
      const auto r = report(m, m.size(), support);
      REQUIRE(r.hankel_count == int(m.size()));
      bool tested_positive = true;
      for (std::size_t k = 0; k < m.size(); ++k) {
        INFO("H_" << k << " = " << hankel[k]);
        const int sign = hankel[k] > 0 ? 1 : (hankel[k] < 0 ? -1 : 0);
        CHECK(r.hankel_sign[k] == sign);
        if (sign == 0)
          CHECK(r.log_abs_hankel[k] == -std::numeric_limits<double>::infinity());
        else
          CHECK(r.log_abs_hankel[k] == doctest::Approx(std::log(std::abs(hankel[k]))).epsilon(1e-14));
        if (support == Support::positive_half_line || k % 2 == 0) tested_positive = tested_positive && sign > 0;
      }
      CHECK(r.hankel_positive == tested_positive);
    }
  // The numbers, spelled out.
  const auto r = report({1, 0, 1e-8, 0}, 4);
  CHECK(r.status == InversionStatus::not_realizable);
  CHECK(r.first_failing_index == 1);
  REQUIRE(r.hankel_count == 4);
  CHECK(r.hankel_sign[2] == 1);
  CHECK(std::exp(r.log_abs_hankel[2]) == doctest::Approx(1e-8).epsilon(1e-14));
  CHECK(r.hankel_sign[3] == -1);
  CHECK(std::exp(r.log_abs_hankel[3]) == doctest::Approx(1e-16).epsilon(1e-14));
}

TEST_CASE("random Jacobi matrices: realizable on the line, failing on 0 to ∞ at the oracle's ζ") {
  const auto& oracle = MomentReference::instance();
  int failing_cases = 0;
  for (int i = 0; i < 20; ++i) {
    const std::string name = std::string("random_jacobi_") + (i < 10 ? "0" : "") + std::to_string(i);
    const auto& m = oracle.moments(name);
    const int n = int(m.size() / 2);
    const int first = int(oracle.values(name, n, "first_unrealizable_zeta_index")[0]);
    INFO(name);
    const auto line = report(m, m.size(), Support::real_line);
    CHECK(line.status == InversionStatus::ok);
    CHECK(line.realizable_nodes == n);
    CHECK(line.hankel_positive);  // a = 0 determinants only on the line
    const auto plus = report(m, m.size());
    CHECK(plus.first_failing_index == first);
    if (first > 0) {
      ++failing_cases;
      CHECK(plus.status == InversionStatus::reduced);
      CHECK(plus.realizable_moments == first);
      CHECK(plus.failing_value < 0);
      CHECK_FALSE(plus.hankel_positive);
    }
  }
  CHECK(failing_cases == 3);
}

TEST_CASE("real line: zero-mean sets, a Dirac at a negative position, the a = 0 Hankel determinants") {
  // N(0, 1): 1, 0, 1, 0, 3, 0 → H_0 = 1, H_2 = 1, H_4 = det[[1,0,1],[0,1,0],[1,0,3]] = 2.
  const std::vector<double> normal{1, 0, 1, 0, 3, 0};
  const auto r = report(normal, 6, Support::real_line);
  CHECK(r.status == InversionStatus::ok);
  CHECK(r.realizable_nodes == 3);
  CHECK(r.recurrence.beta[1] == 1);
  CHECK(r.recurrence.beta[2] == 2);
  REQUIRE(r.hankel_count == 6);
  CHECK(r.hankel_sign[0] == 1);
  CHECK(r.hankel_sign[2] == 1);
  CHECK(r.hankel_sign[4] == 1);
  CHECK(r.hankel_sign[1] == 0);  // a = 1: not a condition on the line
  CHECK(r.log_abs_hankel[4] == doctest::Approx(std::log(2.0)).epsilon(1e-15));
  CHECK(r.hankel_positive);
  CHECK(r.boundary_distance == doctest::Approx(1.0));
  // On [0, ∞) a zero mean is not realizable at all: ζ_1 = 0.
  const auto plus = report(normal, 6);
  CHECK(plus.status == InversionStatus::not_realizable);
  CHECK(plus.first_failing_index == 1);
  CHECK(plus.failing_value == 0);
  CHECK(plus.realizable_moments == 1);
  // A Dirac at −2: the line supports one node, β_1 = 0 fails.
  const std::vector<double> dirac{1, -2, 4, -8};
  const auto d = report(dirac, 4, Support::real_line);
  CHECK(d.status == InversionStatus::reduced);
  CHECK(d.realizable_nodes == 1);
  CHECK(d.first_failing_index == 1);
  CHECK(d.failing_value == 0);
  CHECK(d.recurrence.alpha[0] == -2);
  // A Dirac at 0 (particles at rest): one node, no β tested, boundary distance 1 — it was
  // 0/0 = NaN, m_2/m_0 being 0 (found by fuzz/moment_inversion_fuzzer).
  const std::vector<double> rest{0.4, 0, 0, 0};
  for (std::size_t count : {2, 3, 4}) {
    INFO("count " << count);
    const auto a = report(rest, count, Support::real_line);
    CHECK(a.realizable_nodes == 1);
    CHECK(a.boundary_distance == 1);
  }
}

TEST_CASE("degenerate and invalid inputs: a defined report with a status, never a NaN without one") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(report({1, nan, 2, 3}, 4).status == InversionStatus::invalid_input);
  CHECK(report({1, 2, inf, 3}, 4).status == InversionStatus::invalid_input);
  CHECK(report({0, 0, 0, 0}, 4).status == InversionStatus::zero_mass);
  const auto empty_but = report({0, 1e-9, 0, 0}, 4);
  CHECK(empty_but.status == InversionStatus::not_realizable);
  CHECK(empty_but.first_failing_index == 0);
  CHECK(empty_but.failing_value == 0);
  const auto negative = report({-1, 2, 4, 8}, 4);
  CHECK(negative.status == InversionStatus::not_realizable);
  CHECK(negative.failing_value == -1);
  CHECK(negative.realizable_moments == 0);
  const auto negative_mean = report({1, -2, 4, -8}, 4);
  CHECK(negative_mean.status == InversionStatus::not_realizable);
  CHECK(negative_mean.first_failing_index == 1);
  CHECK(negative_mean.failing_value == -2);
  // A single m_0 > 0: realizable, no node.
  const auto alone = report({0.6}, 1);
  CHECK(alone.status == InversionStatus::ok);
  CHECK(alone.realizable_moments == 1);
  CHECK(alone.realizable_nodes == 0);
  CHECK(alone.recurrence.beta[0] == 0.6);
  // A Dirac at 2e-6 m with weight 3.125e12 (moments exact in decimal, not in binary): ζ_2 = 0 up to rounding. Its sign,
  // hence the count, depends on the rounding (FMA contraction makes it positive): the sign test
  // cannot decide at the boundary, adaptive.hpp does (test_adaptive.cpp).
  const auto atom = report({3.125e12, 6.25e6, 12.5, 2.5e-5, 5e-11, 1e-16}, 6);
  CHECK(atom.status == InversionStatus::reduced);
  CHECK(atom.realizable_nodes >= 1);
  REQUIRE(atom.zeta_count >= 2);
  CHECK(std::abs(atom.zeta[1]) <= 8 * std::numeric_limits<double>::epsilon() * atom.zeta[0]);
  CHECK(atom.recurrence.alpha[0] == doctest::Approx(2e-6).epsilon(1e-15));
  REQUIRE(atom.log_second_difference_count == 4);  // Δ² = 0 up to rounding
  for (int k = 0; k < 4; ++k) CHECK(std::abs(atom.log_second_differences[k]) <= 4 * std::numeric_limits<double>::epsilon());
}

TEST_CASE("units: the same mixture in µm and in m gives the same report, ζ scaled by 1e-6") {
  const auto& oracle = MomentReference::instance();
  const auto um = report(oracle.moments("four_class"), 8);
  const auto si = report(oracle.moments("four_class_si"), 8);
  REQUIRE(um.status == InversionStatus::ok);
  REQUIRE(si.status == InversionStatus::ok);
  const double condition = oracle.values("four_class", 4, "node_condition")[0];
  for (int j = 1; j <= 7; ++j) CHECK(si.zeta[j - 1] == doctest::Approx(um.zeta[j - 1] * 1e-6).epsilon(tolerance(condition, 4)));
  for (int k = 0; k < 6; ++k) CHECK(si.log_second_differences[k] == doctest::Approx(um.log_second_differences[k]).epsilon(1e-12));
  CHECK(si.boundary_distance == doctest::Approx(um.boundary_distance).epsilon(tolerance(condition, 4)));
  // ln H_k differs by exactly the change of unit: H_{2i} ∝ L^{i(i+1)}, H_{2i+1} ∝ L^{(i+1)²}.
  for (int k = 0; k < 8; ++k) {
    const int i = k / 2;
    const int power = k % 2 == 0 ? i * (i + 1) : (i + 1) * (i + 1);
    CHECK(si.log_abs_hankel[k] == doctest::Approx(um.log_abs_hankel[k] + power * std::log(1e-6)).epsilon(1e-9));
  }
}

TEST_CASE("a log-normal (m_0 = 0.6, median 100, s = 0.3): second differences exactly s² = 0.09, in 50 digits") {
  using F = boost::multiprecision::cpp_bin_float_50;
  std::array<F, 8> m{};
  for (int k = 0; k < 8; ++k) m[k] = F("0.6") * exp(k * log(F(100)) + k * k * F("0.045"));
  const auto r = realizability<F, 4>(std::span<const F>(m));
  CHECK(r.status == InversionStatus::ok);
  CHECK(r.log_convex);
  for (int k = 0; k < 6; ++k) CHECK(abs(r.log_second_differences[k] - F("0.09")) < F("1e-45"));
  CHECK(r.hankel_positive);
  CHECK(abs(r.zeta[0] - F(100) * exp(F("0.045"))) < F("1e-45"));
}
