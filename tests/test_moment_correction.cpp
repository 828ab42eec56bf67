// Correction of corrupted moment sets (seed 003; McGraw 2006): single McGraw iterations on a
// corrupted mixture, the log-normal and monodisperse fallbacks, sets that must stay untouched,
// and corrected sets that are realizable. The expected McGraw steps (k*, ln c, the corrected
// moment) and log-normal fills are recomputed at 60 digits by an independent implementation in
// tests/reference/moments_reference.py (mcgraw_checks).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "fluidbed/moments/correction.hpp"
#include "fluidbed/moments/moment_set.hpp"
#include "moment_reference.hpp"

using namespace fluidbed::moments;
using fluidbed::test::MomentReference;

namespace {

constexpr int capacity = 4;

// The 4-class mixture of seed 000 Table 6.4 (75, 103, 240, 355 µm; volume fractions 0.131,
// 0.169, 0.190, 0.110), moments computed exactly.
const std::array<double, 8> mixture{0.6,
                                    111.882,
                                    27336.546,
                                    7787772.738,
                                    2400593489.514,
                                    773763737732.442,
                                    256707038452879.03,
                                    8.6898018074014352e16};

std::array<double, 8> corrupted(int k, double factor) {
  std::array<double, 8> m = mixture;
  m[std::size_t(k)] *= factor;
  return m;
}

template <std::size_t L>
CorrectionResult<double, capacity> correct(const std::array<double, L>& m, const CorrectionOptions<double>& o = {}) {
  return correct_moments<double, capacity>(std::span<const double>(m), o);
}

template <std::size_t L>
CorrectionResult<double, capacity> mcgraw(const std::array<double, L>& m, const CorrectionOptions<double>& o = {}) {
  return mcgraw_correct<double, capacity>(std::span<const double>(m), o);
}

}  // namespace

TEST_CASE("one McGraw iteration on the corrupted 4-class mixture: k* and ln c") {
  struct Case {
    int k;
    double factor, ln_c, corrected;
  };
  const Case cases[] = {
      {3, 0.7, 0.355644081, 7779748.745},  {5, 0.6, 0.511517369, 7.742991704e11}, {7, 0.5, 0.701890012, 8.766108364e16},
      {2, 0.8, 0.214713110, 27107.05557},  {4, 1.6, -0.469470149, 2401874500},   {1, 1.3, -0.234822071, 115.0063033},
  };
  for (const Case& c : cases) {
    INFO("M_" << c.k << " × " << c.factor);
    const auto m = corrupted(c.k, c.factor);
    const auto r = mcgraw(m);
    CHECK(r.status == CorrectionStatus::mcgraw);
    CHECK(r.iterations == 1);  // convex after one step
    for (int k = 0; k < 8; ++k) {
      CHECK(r.changed[k] == (k == c.k));
      if (k != c.k) CHECK(r.moments[k] == m[std::size_t(k)]);
    }
    CHECK(std::log(r.ratio[c.k]) == doctest::Approx(c.ln_c).epsilon(1e-8));
    CHECK(r.moments[c.k] == doctest::Approx(c.corrected).epsilon(1e-9));
    CHECK(r.moments[0] == 0.6);  // the volume fraction is never a candidate
  }
}

TEST_CASE("the full correction: McGraw where it restores realizability, the log-normal fill otherwise") {
  // M_7 × 0.5: McGraw's one iteration gives a realizable set.
  const auto seventh = correct(corrupted(7, 0.5));
  CHECK(seventh.status == CorrectionStatus::mcgraw);
  CHECK(seventh.iterations == 1);
  CHECK(seventh.realizable_moments == 8);
  CHECK(seventh.moments[7] == doctest::Approx(8.766108364e16).epsilon(1e-9));
  // M_3 × 0.7 and M_5 × 0.6: convex after McGraw but not realizable → the log-normal sharing
  // the exact M_0, M_1, M_2.
  const double fill[] = {8751883.082, 3671417912, 2.018090257e12, 1.453522628e15, 1.371757858e18};
  for (const auto& corruption : {std::pair{3, 0.7}, std::pair{5, 0.6}, std::pair{4, 1.6}}) {
    const int k = corruption.first;
    const double factor = corruption.second;
    INFO("M_" << k << " × " << factor);
    const auto r = correct(corrupted(k, factor));
    CHECK(r.status == CorrectionStatus::lognormal);
    CHECK(r.iterations == 1);
    CHECK(r.realizable_moments == 8);
    for (int j = 0; j < 3; ++j) {
      CHECK(r.moments[j] == mixture[std::size_t(j)]);  // exactly
      CHECK_FALSE(r.changed[j]);
      CHECK(r.ratio[j] == 1.0);
    }
    for (int j = 3; j < 8; ++j) {
      CHECK(r.changed[j]);
      CHECK(r.moments[j] == doctest::Approx(fill[j - 3]).epsilon(1e-9));
      CHECK(r.ratio[j] == doctest::Approx(fill[j - 3] / corrupted(k, factor)[std::size_t(j)]).epsilon(1e-9));
    }
  }
  // M_1 × 1.3: McGraw restores M_1 to 115.0063033; the fill starts from that value (the
  // corrupted 145.4 would have M_0 M_2 < M_1²).
  const auto first = correct(corrupted(1, 1.3));
  CHECK(first.status == CorrectionStatus::lognormal);
  CHECK(first.moments[1] == doctest::Approx(115.0063033).epsilon(1e-9));
  CHECK(first.changed[1]);
  CHECK_FALSE(first.changed[2]);
  CHECK(first.realizable_moments == 8);
}

TEST_CASE("sets that must stay untouched: a log-normal (median 100 µm, s = 0.3), realizable sets, boundary sets") {
  const double lognormal[] = {0.6,           62.761671594523,  7183.30417873086,  899581.50003406,
                              123265992.638633, 18481301093.5082, 3031854189938.32, 544215094071385};
  std::array<double, 8> m{};
  std::copy(std::begin(lognormal), std::end(lognormal), m.begin());
  for (const auto& r : {correct(m), mcgraw(m)}) {
    CHECK(r.status == CorrectionStatus::unchanged);
    CHECK(r.iterations == 0);
    for (int k = 0; k < 8; ++k) {
      CHECK(r.moments[k] == m[std::size_t(k)]);
      CHECK(r.ratio[k] == 1.0);
      CHECK_FALSE(r.changed[k]);
    }
  }
  // Realizable sets of the oracle (4-class in µm and m, sieve PSD, seed-003 quadratures).
  for (const std::string name : {"four_class", "four_class_si", "sieve_psd", "seed003_A_N4", "seed003_mix_N4"}) {
    const auto& reference = MomentReference::instance().moments(name);
    const auto r = correct_moments<double, capacity>(std::span<const double>(reference.data(), 8));
    INFO(name);
    CHECK(r.status == CorrectionStatus::unchanged);
  }
  // Boundary sets (fewer atoms than nodes, exact up to rounding): valid, left alone.
  const std::array<double, 6> dirac{3.125e12, 6.25e6, 12.5, 2.5e-5, 5e-11, 1e-16};
  CHECK(correct(dirac).status == CorrectionStatus::unchanged);
  for (double unit : {1.0, 1e-6}) {
    std::array<double, 8> two{}, four_in_ten{};
    moments_from_quadrature<double>(std::array<double, 2>{75 * unit, 355 * unit}, std::array<double, 2>{0.262, 0.338}, two);
    INFO("unit " << unit);
    CHECK(correct(two).status == CorrectionStatus::unchanged);
    const std::array<double, 3> x{75 * unit, 103 * unit, 240 * unit}, w{0.2, 0.2, 0.2};
    moments_from_quadrature<double>(x, w, four_in_ten);
    CHECK(correct(four_in_ten).status == CorrectionStatus::unchanged);
  }
}

TEST_CASE("seed 003 printed sets: log-convex, so McGraw stops at once, the log-normal fill") {
  const auto& a = MomentReference::instance().moments("seed003_A_printed");
  const auto r = correct_moments<double, capacity>(std::span<const double>(a.data(), 8));
  CHECK(r.iterations == 0);
  CHECK(r.status == CorrectionStatus::lognormal);
  CHECK(r.realizable_moments == 8);
  const double fill[] = {480190, 4.65784e7, 4.61812e9, 4.68009e11, 4.84788e13};
  for (int k = 3; k < 8; ++k) CHECK(r.moments[k] == doctest::Approx(fill[k - 3]).epsilon(1e-5));
  for (const std::string name : {"seed003_B_printed", "seed003_mix_printed"}) {
    const auto& m = MomentReference::instance().moments(name);
    const auto c = correct_moments<double, capacity>(std::span<const double>(m.data(), 8));
    INFO(name);
    CHECK(c.status == CorrectionStatus::lognormal);
    CHECK(c.realizable_moments == 8);
  }
}

TEST_CASE("M_0 M_2 < M_1²: no log-normal exists, the monodisperse set keeps M_0, M_1") {
  // Four moments (no McGraw): 1, 2, 3, 8 → 1, 2, 4, 8, an atom at d43 = 2.
  const std::array<double, 4> m{1, 2, 3, 8};
  const auto r = correct(m);
  CHECK(r.status == CorrectionStatus::monodisperse);
  const double expected[] = {1, 2, 4, 8};
  for (int k = 0; k < 4; ++k) CHECK(r.moments[k] == doctest::Approx(expected[k]).epsilon(1e-15));
  CHECK(r.changed[2]);
  CHECK(r.ratio[2] == doctest::Approx(4.0 / 3).epsilon(1e-15));
  CHECK_FALSE(r.changed[1]);
  CHECK(r.ratio[1] == 1.0);
  CHECK(r.realizable_moments == 2);  // an atom: the boundary of moment space
  // With six moments McGraw finds the corrupted M_2 itself: one iteration makes ln m_k linear
  // (d = 0), i.e. the same atom, accepted as a boundary set.
  const auto six = correct(std::array<double, 6>{1, 2, 3, 8, 16, 32});
  CHECK(six.status == CorrectionStatus::mcgraw);
  CHECK(six.iterations == 1);
  CHECK(six.moments[2] == doctest::Approx(4).epsilon(1e-14));
  for (int k = 0; k < 6; ++k) CHECK(six.changed[k] == (k == 2));
  // Four moments that are not realizable: no McGraw (seed 003: six or more), straight to the fill.
  const std::array<double, 4> four{1, 2, 5, 9};  // M_1 M_3 = 18 < M_2² = 25
  const auto f = correct(four);
  CHECK(f.iterations == 0);
  CHECK(f.status == CorrectionStatus::lognormal);
  CHECK(f.moments[3] == doctest::Approx(2 * 2 * 2 * std::pow(5.0 / 4, 3)).epsilon(1e-14));  // M_0 r³ q³
  CHECK(f.realizable_moments == 4);
}

TEST_CASE("protected moments: with M_0 … M_2 protected McGraw moves M_3 … M_7 only") {
  CorrectionOptions<double> options;
  options.protected_moments = 3;
  const auto r = mcgraw(corrupted(1, 1.3), options);
  for (int k = 0; k < 3; ++k) CHECK_FALSE(r.changed[k]);
  CHECK(r.iterations >= 1);
  const auto full = correct(corrupted(1, 1.3), options);
  CHECK(full.moments[1] == doctest::Approx(111.882 * 1.3).epsilon(1e-15));  // kept, corrupted or not
  CHECK(full.realizable_moments >= 2);
}

TEST_CASE("degenerate and invalid inputs: a status, the moments returned as given, never a NaN") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto check = [](const std::array<double, 6>& m, CorrectionStatus status) {
    const auto r = correct(m);
    CHECK(r.status == status);
    for (int k = 0; k < 6; ++k) {
      if (std::isnan(m[std::size_t(k)])) continue;
      CHECK(r.moments[k] == m[std::size_t(k)]);
      CHECK(r.ratio[k] == 1.0);
    }
  };
  check({1, nan, 2, 3, 4, 5}, CorrectionStatus::failed);
  check({0, 0, 0, 0, 0, 0}, CorrectionStatus::zero_mass);
  check({0, 1e-9, 0, 0, 0, 0}, CorrectionStatus::failed);
  check({-1, 2, 4, 8, 16, 32}, CorrectionStatus::failed);
  check({1, 0, 1, 0, 3, 0}, CorrectionStatus::failed);  // zero mean: no size scale
  check({1, -2, 4, -8, 16, -32}, CorrectionStatus::failed);
  // A negative higher moment: no logarithms, so no McGraw; the fill from M_0, M_1, M_2.
  const auto r = correct(std::array<double, 6>{1, 2, 5, 9, -1, 40});
  CHECK(r.status == CorrectionStatus::lognormal);
  CHECK(r.iterations == 0);
  CHECK(r.realizable_moments == 6);
  for (int k = 0; k < 6; ++k) CHECK(std::isfinite(r.moments[k]));
}

// Found by fuzz/moment_inversion_fuzzer: the fallback M_k = M_0 r^k q^{k(k−1)/2} and McGraw's
// factor c = exp(ln c) were applied without checking that the result is representable, and gave
// +∞, 0 or NaN moments under status lognormal or mcgraw. A correction is now reported only with
// finite positive moments; otherwise status failed and the moments exactly as given.
TEST_CASE("corrections beyond the floating-point range: status failed and the moments as given") {
  const auto as_given = [](const auto& r, std::span<const double> m) {
    CHECK(r.status == CorrectionStatus::failed);
    CHECK(r.iterations == 0);
    for (std::size_t k = 0; k < m.size(); ++k) {
      CHECK(r.moments[k] == m[k]);
      CHECK(r.ratio[k] == 1.0);
      CHECK_FALSE(r.changed[k]);
    }
  };
  // Not realizable (M_1 M_3 = 1 < M_2² = 1e400): the log-normal through M_0 … M_2 has
  // q = M_0 M_2/M_1² = 1e200, so M_3 = M_0 r³ q³ = 1e600 overflows.
  const std::array<double, 4> broad{1, 1, 1e200, 1};
  as_given(correct(broad), broad);
  // r = M_1/M_0 = 1e-600 underflows to 0, q = M_0 M_2/M_1² overflows: the fill would be NaN.
  const std::array<double, 4> spanning{1e300, 1e-300, 1, 1};
  as_given(correct(spanning), spanning);

  // The mixture in metres with M_2 corrupted to 8e-323: ln c for M_2 is ~ +720, and
  // c = e^720 overflows. McGraw alone fails; the full correction hands the set as given to the
  // fill, here monodisperse (M_0 M_2 < M_1²): M_k = M_0 r^k, r = M_1/M_0.
  std::array<double, 8> si{};
  for (std::size_t k = 0; k < 8; ++k) si[k] = mixture[k] * std::pow(1e-6, double(k));
  si[2] = 8e-323;
  as_given(mcgraw(si), si);
  const auto full = correct(si);
  CHECK(full.status == CorrectionStatus::monodisperse);
  const double r = si[1] / si[0];
  CHECK(full.moments[0] == si[0]);
  CHECK(full.moments[1] == si[1]);
  for (int k = 2; k < 8; ++k) CHECK(full.moments[k] == doctest::Approx(si[0] * std::pow(r, k)).epsilon(1e-14));

  // A sub-micron set in float whose moments above M_7 underflowed to 0 (found by the fuzzer):
  // the log-normal through M_0 … M_2 has finite positive moments (M_12 ~ 3e20), but scaled by
  // M_0 and the length √(M_2/M_0) ~ 5e-7 they overflow — no inversion could use them.
  const std::array<float, 13> sub_micron{1.0006985e-06f,
                                         7.4380165e-14f,
                                         2.7475065e-19f,
                                         2.0093646e-24f,
                                         2.1968288e-29f,
                                         3.1969341e-34f,
                                         5.8094808e-39f,
                                         1.2611686e-43f,
                                         0,
                                         0,
                                         0,
                                         0,
                                         0};
  const auto f = correct_moments<float, 8>(std::span<const float>(sub_micron));
  CHECK(f.status == CorrectionStatus::failed);
  for (std::size_t k = 0; k < sub_micron.size(); ++k) CHECK(f.moments[k] == sub_micron[k]);
}

TEST_CASE("randomly corrupted realizable sets always come back realizable (or at the boundary)") {
  std::mt19937_64 engine(17);
  const auto uniform = [&] { return double(engine() >> 11) * 0x1p-53; };
  const auto& reference = MomentReference::instance();
  const std::string names[] = {"four_class", "four_class_si", "sieve_psd", "lognormal_si", "seed003_B_N4"};
  int corrected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto& exact = reference.moments(names[trial % 5]);
    std::array<double, 8> m{};
    std::copy(exact.begin(), exact.begin() + 8, m.begin());
    const int k = 1 + int(uniform() * 7);
    m[std::size_t(k)] *= std::exp(std::log(0.3) + uniform() * std::log(10.0));  // × 0.3 … 3
    const auto r = correct(m);
    INFO(names[trial % 5] << ": M_" << k << " × " << m[std::size_t(k)] / exact[std::size_t(k)]);
    REQUIRE(r.status != CorrectionStatus::failed);
    CHECK(r.moments[0] == m[0]);
    if (r.status == CorrectionStatus::mcgraw || r.status == CorrectionStatus::lognormal) {
      CHECK(r.realizable_moments == 8);
      ++corrected;
    }
    for (int j = 0; j < 8; ++j) CHECK(std::isfinite(r.moments[j]));
  }
  CHECK(corrected > 150);
}

TEST_CASE("the correction runs in long double and Boost.Multiprecision (50 digits)") {
  using F = boost::multiprecision::cpp_bin_float_50;
  std::array<F, 8> m{};
  const char* exact[] = {"0.6", "111.882", "27336.546", "7787772.738", "2400593489.514", "773763737732.442",
                         "256707038452879.03", "86898018074014352"};
  for (int k = 0; k < 8; ++k) m[std::size_t(k)] = F(exact[k]);
  m[3] *= F("0.7");
  const auto r = correct_moments<F, capacity>(std::span<const F>(m));
  CHECK(r.status == CorrectionStatus::lognormal);
  CHECK(r.iterations == 1);
  CHECK(abs(r.moments[3] / F("8751883.082") - 1) < F("1e-10"));
  const auto step = mcgraw_correct<F, capacity>(std::span<const F>(m));
  CHECK(abs(log(step.ratio[3]) - F("0.355644081")) < F("1e-9"));
  std::array<long double, 8> l{};
  for (int k = 0; k < 8; ++k) l[std::size_t(k)] = static_cast<long double>(mixture[std::size_t(k)]);
  l[7] *= 0.5L;
  const auto lr = correct_moments<long double, capacity>(std::span<const long double>(l));
  CHECK(lr.status == CorrectionStatus::mcgraw);
  CHECK(lr.moments[7] == doctest::Approx(8.766108364e16).epsilon(1e-9));
}
