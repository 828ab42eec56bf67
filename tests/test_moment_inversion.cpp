// Moment inversion core: exact references, scale invariance, PD against Wheeler, statuses.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <boost/math/special_functions/gamma.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "fluidbed/moments/adaptive.hpp"
#include "fluidbed/moments/inversion.hpp"

using namespace fluidbed::moments;

namespace {

// Moments of a measure from exact recurrence ratios m_{k+1} = m_k · ratio(k), accumulated in
// long double and rounded once to double (the moments of gamma/Laguerre-type measures).
template <int Count, class Ratio>
std::array<double, Count> moments_by_ratio(long double m0, Ratio ratio) {
  std::array<double, Count> m{};
  long double value = m0;
  for (int k = 0; k < Count; ++k) {
    m[k] = double(value);
    value *= ratio(k);
  }
  return m;
}

constexpr RecurrenceAlgorithm algorithms[] = {RecurrenceAlgorithm::wheeler, RecurrenceAlgorithm::product_difference};

std::string name(RecurrenceAlgorithm a) { return a == RecurrenceAlgorithm::wheeler ? "Wheeler" : "PD"; }

}  // namespace

TEST_CASE("three atoms at 1, 2, 5: both algorithms give the exact recurrence and recover the atoms") {
  // Atoms (1, 0.2), (2, 0.5), (5, 0.3); their α, β and ζ to the digits below are checked at 60
  // digits by moments_reference.py (case three_atoms).
  const std::array<double, 6> m{1, 2.7, 9.7, 41.7, 195.7, 953.7};
  for (RecurrenceAlgorithm a : algorithms) {
    INFO(name(a));
    const auto r = recurrence<double, 3>(std::span<const double>(m), a);
    REQUIRE(r.size == 3);
    CHECK(r.alpha[1] == doctest::Approx(3.7356846473).epsilon(1e-10));
    CHECK(r.alpha[2] == doctest::Approx(1.5643153527).epsilon(1e-10));
    CHECK(r.beta[1] == doctest::Approx(2.41).epsilon(1e-14));
    CHECK(r.beta[2] == doctest::Approx(0.743788846611).epsilon(1e-11));
    const auto zeta = stieltjes_coefficients(r);
    const double expected_zeta[] = {2.7, 0.892592592593, 2.84309205471, 0.261612649994, 1.3027027027};
    for (int j = 0; j < 5; ++j) CHECK(zeta[j] == doctest::Approx(expected_zeta[j]).epsilon(1e-11));
    const auto q = invert<3>(m, {.algorithm = a});
    REQUIRE(q.status == InversionStatus::ok);
    // The decimal moments are rounded to binary; that rounding alone moves the nodes by ~1e-13.
    const double x[] = {1, 2, 5}, w[] = {0.2, 0.5, 0.3};
    for (int i = 0; i < 3; ++i) {
      CHECK(q.quadrature.nodes[i] == doctest::Approx(x[i]).epsilon(5e-13));
      CHECK(q.quadrature.weights[i] == doctest::Approx(w[i]).epsilon(5e-13));
    }
  }
}

TEST_CASE("recurrences with exact closed forms: Laguerre (non-integer a), shifted Hermite, gamma in SI units") {
  // Per-coefficient tolerance: the map moments → recurrence loses about a factor 10 per level
  // for these measures (measured; Gautschi 2004 §2.1), from double-rounded moments.
  const auto tolerance = [](int k) { return 4e-15 * std::pow(12.0, k); };
  SUBCASE("generalized Laguerre x^a e^-x, a = 0.37: α_k = 2k + a + 1, β_k = k(k + a)") {
    const double a = 0.37;
    const auto m = moments_by_ratio<16>(std::tgamma(1.0L + a), [&](int k) { return (long double)(k) + 1.0L + a; });
    for (RecurrenceAlgorithm alg : algorithms) {
      const auto r = recurrence<double, 8>(std::span<const double>(m), alg);
      REQUIRE(r.size == 8);
      for (int k = 0; k < 8; ++k) {
        INFO(name(alg) << " k=" << k);
        CHECK(r.alpha[k] == doctest::Approx(2 * k + a + 1).epsilon(tolerance(k)));
        if (k > 0) CHECK(r.beta[k] == doctest::Approx(k * (k + a)).epsilon(tolerance(k)));
      }
    }
  }
  SUBCASE("gamma(2.5, θ = 1e-4 m): α_k = θ(2k + 2.5), β_k = θ² k(k + 1.5), m_0 = 1") {
    const long double theta = 1e-4L;
    const auto m = moments_by_ratio<16>(1.0L, [&](int k) { return theta * ((long double)(k) + 2.5L); });
    for (RecurrenceAlgorithm alg : algorithms) {
      const auto r = recurrence<double, 8>(std::span<const double>(m), alg);
      REQUIRE(r.size == 8);  // textbook PD underflows from n = 5 here (recurrence.hpp)
      for (int k = 0; k < 8; ++k) {
        INFO(name(alg) << " k=" << k);
        CHECK(r.alpha[k] == doctest::Approx(1e-4 * (2 * k + 2.5)).epsilon(tolerance(k)));
        if (k > 0) CHECK(r.beta[k] == doctest::Approx(1e-8 * k * (k + 1.5)).epsilon(tolerance(k)));
      }
    }
  }
  SUBCASE("normal, mean 5.3, σ = 0.7 (Wheeler; PD too, as the mean is not zero)") {
    // m_{k+1} = μ m_k + k σ² m_{k−1}
    std::array<long double, 12> exact{1.0L, 5.3L};
    for (int k = 1; k < 11; ++k) exact[k + 1] = 5.3L * exact[k] + k * 0.49L * exact[k - 1];
    std::array<double, 12> m{};
    std::transform(exact.begin(), exact.end(), m.begin(), [](long double x) { return double(x); });
    for (RecurrenceAlgorithm alg : algorithms) {
      const auto r = recurrence<double, 6>(std::span<const double>(m), alg);
      REQUIRE(r.size == 6);
      for (int k = 0; k < 6; ++k) {
        INFO(name(alg) << " k=" << k);
        // A narrow measure far from 0 is the worst conditioned case: its coefficients are the
        // differences of nearly equal moments.
        CHECK(r.alpha[k] == doctest::Approx(5.3).epsilon(1e-14 * std::pow(60.0, k)));
        if (k > 0) CHECK(r.beta[k] == doctest::Approx(0.49 * k).epsilon(1e-14 * std::pow(60.0, k)));
      }
    }
  }
}

TEST_CASE("Gauss–Legendre on 0 to 1 from m_k = 1/(k+1) (the exact rule, checked by moments_reference.py)") {
  std::array<double, 10> m{};
  for (int k = 0; k < 10; ++k) m[k] = 1.0 / (k + 1);
  const double x[] = {0.046910077030668004, 0.23076534494715845, 0.5, 0.76923465505284155, 0.953089922969332};
  const double w[] = {0.11846344252809454, 0.23931433524968323, 64.0 / 225, 0.23931433524968323, 0.11846344252809454};
  for (RecurrenceAlgorithm alg : algorithms) {
    const auto q = invert<5>(m, {.algorithm = alg});
    REQUIRE(q.status == InversionStatus::ok);
    for (int i = 0; i < 5; ++i) {
      INFO(name(alg) << " i=" << i);
      CHECK(q.quadrature.nodes[i] == doctest::Approx(x[i]).epsilon(2e-10));
      CHECK(q.quadrature.weights[i] == doctest::Approx(w[i]).epsilon(2e-10));
    }
  }
}

TEST_CASE("scale invariance: a change of unit by a power of two gives bit-identical rescaled quadratures") {
  // A lognormal volume distribution, d50 = 100 µm, σ_ln = 0.3, m_0 = 0.6, written in
  // micrometres and in units of 2^-20 m ≈ 0.95 µm... any power-of-two unit change is exact.
  std::array<double, 16> micrometres{};
  for (int k = 0; k < 16; ++k) micrometres[k] = 0.6 * std::exp(k * std::log(100.0) + k * k * 0.09 / 2);
  for (int shift : {-40, -20, -7, 3, 30})
    for (int weight_shift : {-30, 0, 12}) {
      std::array<double, 16> other{};
      for (int k = 0; k < 16; ++k) other[k] = std::ldexp(micrometres[k], weight_shift + k * shift);
      for (RecurrenceAlgorithm alg : algorithms) {
        const auto a = invert<8>(micrometres, {.algorithm = alg});
        const auto b = invert<8>(other, {.algorithm = alg});
        INFO(name(alg) << " length shift 2^" << shift << " weight shift 2^" << weight_shift);
        REQUIRE(a.status == b.status);
        REQUIRE(a.quadrature.size == b.quadrature.size);
        for (int i = 0; i < a.quadrature.size; ++i) {
          CHECK(std::ldexp(a.quadrature.nodes[i], shift) == b.quadrature.nodes[i]);
          CHECK(std::ldexp(a.quadrature.weights[i], weight_shift) == b.quadrature.weights[i]);
        }
      }
    }
}

TEST_CASE("the length scale is read from exponents: a real-line set with a tiny mean inverts as the zero-mean one") {
  // N(μ, 1), μ = 1e-300: m_k = E[Z^k] + k μ E[Z^(k−1)] to rounding. The mean alone as length
  // scale (2^−997) put m̃_2 = 2^1994 out of range (invalid_input, found by fuzz/); √(m_2/m_0)
  // does not. Reference: the probabilists' Gauss–Hermite rule, nodes ±√(3 ∓ √6), weights
  // (3 ± √6)/12 (the zeros of He_4 = x⁴ − 6x² + 3 and its Christoffel numbers).
  const double mu = 1e-300;
  const std::array<double, 8> m{1, mu, 1, 3 * mu, 3, 5 * 3 * mu, 15, 7 * 15 * mu};
  const double inner = std::sqrt(3 - std::sqrt(6.0)), outer = std::sqrt(3 + std::sqrt(6.0));
  const std::array<double, 4> x{-outer, -inner, inner, outer};
  const std::array<double, 4> w{(3 - std::sqrt(6.0)) / 12, (3 + std::sqrt(6.0)) / 12, (3 + std::sqrt(6.0)) / 12,
                                (3 - std::sqrt(6.0)) / 12};
  const auto r = invert<4>(m, {.support = Support::real_line});
  REQUIRE(r.status == InversionStatus::ok);
  for (int i = 0; i < 4; ++i) {
    CHECK(r.quadrature.nodes[i] == doctest::Approx(x[i]).epsilon(1e-14));
    CHECK(r.quadrature.weights[i] == doctest::Approx(w[i]).epsilon(1e-14));
  }
  const auto report = realizability<double, 4>(m, Support::real_line);
  CHECK(report.status == InversionStatus::ok);
  CHECK(invert_adaptive<4>(m, {.inversion = {.support = Support::real_line}}).status == InversionStatus::ok);
}

TEST_CASE("two nodes whose half gap squared overflows: the closed form takes hypot, the node stays finite") {
  // Float atoms −1 (weight 1) and 2^66 (weight 2^-140): in scaled units α_1 ≈ 2^66, so
  // h² ≈ 2^130 is beyond float's range while the nodes are not (the fuzzer's case: a corrupted
  // m_3 gave eigen_failure per cell and a rule in the batched lanes).
  const std::array<float, 4> m{1.0f, -1.0f, 1.0f + 0x1p-8f, -1.0f + 0x1p58f};
  const auto r = invert<2>(m, {.support = Support::real_line});
  REQUIRE(r.status == InversionStatus::ok);
  CHECK(r.quadrature.nodes[0] == doctest::Approx(-1.0f).epsilon(1e-6));
  CHECK(r.quadrature.nodes[1] == doctest::Approx(0x1p66f).epsilon(1e-3));
  CHECK(r.quadrature.weights[0] == doctest::Approx(1.0f).epsilon(1e-6));
}

TEST_CASE("statuses: empty cell, NaN, infinity, negative mass, negative mean, Dirac, zero mean on the real line") {
  const auto check = [](const std::array<double, 4>& m, InversionStatus status, int size, Support support) {
    const auto r = invert<2>(m, {.support = support});
    CHECK(r.status == status);
    CHECK(r.quadrature.size == size);
    for (int i = 0; i < r.quadrature.size; ++i) {
      CHECK(std::isfinite(r.quadrature.nodes[i]));
      CHECK(std::isfinite(r.quadrature.weights[i]));
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Support plus = Support::positive_half_line, line = Support::real_line;
  check({0, 0, 0, 0}, InversionStatus::zero_mass, 0, plus);
  check({0, 1e-9, 0, 0}, InversionStatus::not_realizable, 0, plus);
  check({1, nan, 2, 3}, InversionStatus::invalid_input, 0, plus);
  check({1, 2, inf, 3}, InversionStatus::invalid_input, 0, plus);
  check({-1, 2, 4, 8}, InversionStatus::not_realizable, 0, plus);
  check({1, -2, 4, -8}, InversionStatus::not_realizable, 0, plus);
  check({1, -2, 4, -8}, InversionStatus::reduced, 1, line);  // a Dirac at −2 on the line
  check({1, 1, 1, 1}, InversionStatus::reduced, 1, plus);  // a Dirac at 1, exact in binary
  // A subnormal m_0 with ordinary higher moments: the mean, hence the node, overflows; reported
  // as invalid (it once came out as a node at +∞).
  check({4.9e-324, 4.3e-4, 3.6e-7, 1.0e-10}, InversionStatus::invalid_input, 0, line);
  check({4.9e-324, 4.3e-4, 3.6e-7, 1.0e-10}, InversionStatus::invalid_input, 0, plus);
  check({1, 0, 1, 0}, InversionStatus::not_realizable, 0, plus);  // zero mean is not on (0, ∞)
  check({1, 0, 1, 0}, InversionStatus::ok, 2, line);              // ±1, weights 1/2
  // A Dirac whose moments are exact in decimal, not in binary (2e-6 m, weight 3.125e12) sits on the
  // boundary of moment space: ζ_2 = variance/mean is 0 only up to rounding, and its sign (so
  // the plain invert()'s node count) may change with the compiler's FMA contraction. The
  // adaptive inversion, with its relative boundary tolerance, is the entry point for that.
  const std::array<double, 4> dirac_moments{3.125e12, 6.25e6, 12.5, 2.5e-5};
  const auto dirac = invert_adaptive<2>(dirac_moments);
  CHECK(dirac.status == InversionStatus::reduced);
  REQUIRE(dirac.quadrature.size == 1);
  CHECK(dirac.quadrature.nodes[0] == doctest::Approx(2e-6).epsilon(1e-15));
  CHECK(dirac.quadrature.weights[0] == 3.125e12);
}

TEST_CASE("the first failing Stieltjes coefficient is reported with its value") {
  // Uniform [0, 1] moments with m_3 := 0: ζ = 1/2, 1/6, −8/3.
  const std::array<double, 6> m{1, 0.5, 1.0 / 3, 0, 0.2, 1.0 / 6};
  for (RecurrenceAlgorithm alg : algorithms) {
    const auto r = invert<3>(m, {.algorithm = alg});
    INFO(name(alg));
    CHECK(r.status == InversionStatus::reduced);
    CHECK(r.realizable_nodes == 1);
    CHECK(r.first_failing_index == 3);
    CHECK(r.failing_value == doctest::Approx(-8.0 / 3).epsilon(1e-14));
    CHECK(r.quadrature.nodes[0] == 0.5);
  }
}

TEST_CASE("the same code runs in long double and Boost.Multiprecision (50 digits)") {
  using boost::multiprecision::cpp_bin_float_50;
  using F = cpp_bin_float_50;
  const F a = F(37) / 100;
  std::array<F, 20> m{};
  m[0] = boost::math::tgamma(a + 1);
  for (int k = 1; k < 20; ++k) m[k] = m[k - 1] * (k + a);
  for (RecurrenceAlgorithm alg : algorithms) {
    const auto r = recurrence<F, 10>(std::span<const F>(m), alg);
    REQUIRE(r.size == 10);
    for (int k = 0; k < 10; ++k) {
      INFO(name(alg) << " k=" << k);
      CHECK(abs(r.alpha[k] / (2 * k + a + 1) - 1) < F(1e-35));
      if (k > 0) CHECK(abs(r.beta[k] / (k * (k + a)) - 1) < F(1e-35));
    }
    const auto q = invert<10>(m, {.algorithm = alg});
    REQUIRE(q.status == InversionStatus::ok);
    F total = 0;
    for (int i = 0; i < 10; ++i) total += q.quadrature.weights[i] * pow(q.quadrature.nodes[i], 19);
    CHECK(abs(total / m[19] - 1) < F(1e-30));  // the rule reproduces the highest moment
  }
  // long double: Gauss–Legendre N = 5 nodes to long double precision
  std::array<long double, 10> u{};
  for (int k = 0; k < 10; ++k) u[k] = 1.0L / (k + 1);
  const auto q = invert<5>(u);
  CHECK(std::abs(q.quadrature.nodes[0] - 0.046910077030668003601186560850303517L) < 1e-14L);
}

// Found by fuzz/moment_inversion_fuzzer: eight moments whose three-node prefix on the real
// line spreads its nodes over 1e3 … 5e18; the closed-form three-node solver overflowed there
// and returned NaN weights under status reduced. The QL takes over: a finite rule, or a status.
TEST_CASE("a three-node rule whose nodes spread beyond the closed form's range is finite or has a failure status") {
  const std::array<double, 8> m{0.26173474688316289,    -259.66282338420916,   257607.3045337277,
                                -255568060.42219979,    253544962169.06024,    251537881914546.22,
                                2.495466928116103e+17, -2.475712690178978e+20};
  const auto r = invert<4>(m, {.support = Support::real_line});
  REQUIRE(r.status == InversionStatus::reduced);
  REQUIRE(r.quadrature.size == 3);
  double total = 0;
  for (int i = 0; i < 3; ++i) {
    CHECK(std::isfinite(r.quadrature.nodes[i]));
    CHECK(r.quadrature.weights[i] >= 0);
    total += r.quadrature.weights[i];
  }
  CHECK(total == doctest::Approx(m[0]).epsilon(1e-12));
}

// Found by fuzz/moment_inversion_fuzzer: product-difference stopped at the first ζ_j <= 0,
// which the real line allows, and cut the rule there. N(1/2, 1): ζ = 1/2, 2, −3/2, −4/3, 11/6
// (ζ_2 = β_1/ζ_1, ζ_{2k+1} = α_k − ζ_{2k} with α_k = 1/2, β_k = k), and the three-node rule is
// Gauss–Hermite shifted by 1/2: nodes 1/2 and 1/2 ± √3, weights 2/3 and 1/6.
TEST_CASE("product-difference on the real line goes on past a negative ζ: N(1/2, 1), three nodes") {
  const std::array<double, 6> m{1, 0.5, 1.25, 1.625, 4.5625, 8.78125};  // exact in binary
  for (RecurrenceAlgorithm alg : algorithms) {
    INFO(name(alg));
    const auto r = invert<3>(m, {.algorithm = alg, .support = Support::real_line});
    REQUIRE(r.status == InversionStatus::ok);
    REQUIRE(r.quadrature.size == 3);
    const double root3 = std::sqrt(3.0);
    const std::array<double, 3> nodes{0.5 - root3, 0.5, 0.5 + root3}, weights{1.0 / 6, 2.0 / 3, 1.0 / 6};
    for (int i = 0; i < 3; ++i) {
      CHECK(r.quadrature.nodes[i] == doctest::Approx(nodes[i]).epsilon(1e-14));
      CHECK(r.quadrature.weights[i] == doctest::Approx(weights[i]).epsilon(1e-14));
    }
    CHECK(r.boundary_distance == doctest::Approx(1 / 1.25).epsilon(1e-14));  // β_1/(m_2/m_0)
  }
  // On [0, ∞) the same set fails at ζ_3 = −3/2 with either algorithm.
  for (RecurrenceAlgorithm alg : algorithms) {
    INFO(name(alg));
    const auto r = invert<3>(m, {.algorithm = alg});
    CHECK(r.status == InversionStatus::reduced);
    CHECK(r.quadrature.size == 1);
    CHECK(r.first_failing_index == 3);
    CHECK(r.failing_value == doctest::Approx(-1.5).epsilon(1e-14));
  }
}

// PD's limit (recurrence.hpp): an exact ζ_{2k+1} = 0 makes β_{k+1} = ζ_{2k+1} ζ_{2k+2} = 0·∞.
// N(1, 1) has ζ_3 = α_1 − β_1/α_0 = 0: PD keeps the two levels it has (nodes 0 and 2, weights
// 1/2: Gauss–Hermite shifted by 1) and reports the undefined β_2 as NaN; Wheeler gives all three
// (1 and 1 ± √3). Likewise a zero mean (ζ_1 = 0) leaves PD one node.
TEST_CASE("product-difference on the real line stops with a status at an exact ζ = 0: N(1, 1), N(0, 1)") {
  const std::array<double, 6> m{1, 1, 2, 4, 10, 26};
  const auto pd = invert<3>(m, {.algorithm = RecurrenceAlgorithm::product_difference, .support = Support::real_line});
  CHECK(pd.status == InversionStatus::reduced);
  REQUIRE(pd.quadrature.size == 2);
  CHECK(pd.quadrature.nodes[0] == doctest::Approx(0).scale(1).epsilon(1e-15));
  CHECK(pd.quadrature.nodes[1] == doctest::Approx(2).epsilon(1e-15));
  CHECK(pd.quadrature.weights[0] == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(pd.first_failing_index == 2);
  CHECK(std::isnan(pd.failing_value));
  const auto wheeler = invert<3>(m, {.support = Support::real_line});
  REQUIRE(wheeler.status == InversionStatus::ok);
  CHECK(wheeler.quadrature.nodes[2] == doctest::Approx(1 + std::sqrt(3.0)).epsilon(1e-15));

  const std::array<double, 4> normal{1, 0, 1, 0};
  const auto zero_mean =
      invert<2>(normal, {.algorithm = RecurrenceAlgorithm::product_difference, .support = Support::real_line});
  CHECK(zero_mean.status == InversionStatus::reduced);
  REQUIRE(zero_mean.quadrature.size == 1);
  CHECK(zero_mean.quadrature.nodes[0] == 0);
  CHECK(zero_mean.boundary_distance == 1);
  CHECK(std::isnan(zero_mean.failing_value));
}

// Found by fuzz/moment_inversion_fuzzer: a set whose scaled moments span ~1e-86 … 1e256 (a
// huge m_0 with a geometric tail). PD renormalised its first column by the largest entry and so
// pushed m_1 below the range: ζ_1 = α_0 came out 0, a node at 0 where m_1 ≠ 0. Whatever the node
// count, a Gauss rule reproduces m_0 and m_1 (Σw = m_0, Σwx = m_0 α_0 = m_1).
TEST_CASE("product-difference keeps ζ_1 = m_1/m_0 when its column spans more than the range") {
  const std::array<double, 6> m{2.9214909123913038e+170, 5.3181319439445191e-06, 6.2454715945679317e-11,
                                7.3360137638125056e-16,  8.6187390541864121e-21, 1.0127818810528304e-25};
  for (Support support : {Support::positive_half_line, Support::real_line}) {
    const auto r = invert<3>(m, {.algorithm = RecurrenceAlgorithm::product_difference, .support = support});
    INFO("real line " << (support == Support::real_line));
    REQUIRE((r.status == InversionStatus::ok || r.status == InversionStatus::reduced));
    long double sum = 0, first = 0;
    for (int i = 0; i < r.quadrature.size; ++i) {
      sum += r.quadrature.weights[i];
      first += (long double)r.quadrature.weights[i] * r.quadrature.nodes[i];
    }
    CHECK(double(sum) == doctest::Approx(m[0]).epsilon(1e-14));
    CHECK(double(first) == doctest::Approx(m[1]).epsilon(1e-14));
  }
}

// Found by fuzz/moment_inversion_fuzzer: on the real line a one-node rule tests no β, and the
// boundary distance min β_k/(m_2/m_0) was 0/0 for a Dirac at 0 (particles at rest), where the
// contract says 1 for a single node.
TEST_CASE("a Dirac at 0 on the real line: one node at 0, boundary distance 1, never NaN") {
  const std::array<double, 2> one{0.4, 0};
  const auto single = invert<1>(one, {.support = Support::real_line});
  CHECK(single.status == InversionStatus::ok);
  CHECK(single.boundary_distance == 1);
  const std::array<double, 4> rest{0.4, 0, 0, 0};
  for (RecurrenceAlgorithm alg : algorithms) {
    INFO(name(alg));
    const auto r = invert<2>(rest, {.algorithm = alg, .support = Support::real_line});
    CHECK(r.status == InversionStatus::reduced);
    REQUIRE(r.quadrature.size == 1);
    CHECK(r.quadrature.nodes[0] == 0);
    CHECK(r.quadrature.weights[0] == 0.4);
    CHECK(r.boundary_distance == 1);
  }
}
