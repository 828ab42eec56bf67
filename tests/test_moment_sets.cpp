// Moment-set helpers: moments of quadratures and sieve analyses (seed 000 App. E), mean
// diameters, VDF ↔ NDF moments, log-normal sets. References: the mpmath oracle
// (moments_reference.csv), figures the generator checks at 60 digits, and exact rationals.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "fluidbed/moments/inversion.hpp"
#include "fluidbed/moments/moment_set.hpp"
#include "moment_reference.hpp"

using namespace fluidbed::moments;
using fluidbed::test::MomentReference;

namespace {

// A 45–150 µm sieve cut (the oracle's sieve_psd): apertures in µm and mass fractions.
const std::array<double, 8> sieve_edges{45, 53, 63, 75, 90, 106, 125, 150};
const std::array<double, 7> sieve_fractions{0.05, 0.10, 0.20, 0.30, 0.20, 0.10, 0.05};
const SieveAnalysis<double> sieve{sieve_edges, sieve_fractions};

// One bin [100, 200] µm (the oracle's sieve_one_bin).
const std::array<double, 2> bin_edges{100, 200};
const std::array<double, 1> bin_fraction{1};

}  // namespace

TEST_CASE("moments of a quadrature: three atoms at 1, 2, 5, and a round trip through invert") {
  const std::array<double, 3> x{1, 2, 5}, w{0.2, 0.5, 0.3};
  std::array<double, 6> m{};
  moments_from_quadrature<double>(x, w, m);
  const double expected[] = {1, 2.7, 9.7, 41.7, 195.7, 953.7};
  for (int k = 0; k < 6; ++k) CHECK(m[k] == doctest::Approx(expected[k]).epsilon(1e-15));
  const auto r = invert<3>(m);
  REQUIRE(r.status == InversionStatus::ok);
  std::array<double, 6> again{};
  moments_from_quadrature(r.quadrature, std::span<double>(again));
  for (int k = 0; k < 6; ++k) CHECK(again[k] == doctest::Approx(m[k]).epsilon(1e-13));
  CHECK(quadrature_moment(r.quadrature, -1) == doctest::Approx(0.2 + 0.25 + 0.06).epsilon(1e-13));
}

TEST_CASE("sieve moments, one bin 100 to 200 µm: exact rationals and the oracle") {
  const SieveAnalysis<double> one{bin_edges, bin_fraction};
  const double exact[] = {0.6, 90, 14000, 2250000, 372000000, 63000000000};
  for (int k = 0; k < 6; ++k) CHECK(sieve_moment(one, 0.4, k) == doctest::Approx(exact[k]).epsilon(4e-16));
  const auto& oracle = MomentReference::instance().moments("sieve_one_bin");
  std::array<double, 8> m{};
  sieve_moments(one, 0.4, std::span<double>(m));
  for (int k = 0; k < 8; ++k) CHECK(m[k] == doctest::Approx(oracle[std::size_t(k)]).epsilon(4e-16));
  CHECK(d43<double>(m) == 150.0);
  // d32 = M_0/M_{−1} = 100/ln 2 (the logarithmic limit of E.7 at k = −1).
  CHECK(d32(one) == doctest::Approx(MomentReference::instance().values("sieve_one_bin", 0, "d32")[0]).epsilon(1e-15));
  CHECK(d32(one) == doctest::Approx(100 / std::log(2.0)).epsilon(1e-15));
  // d10 = M_{−2}/M_{−3} = [(1/100 − 1/200)/100] / [(1/100² − 1/200²)/200] = 400/3.
  CHECK(d10(one) == doctest::Approx(400.0 / 3).epsilon(1e-15));
}

TEST_CASE("sieve moments of a 45–150 µm cut: M_0 … M_7, d43, d32, variance and Geldart's d_sv") {
  const auto& oracle = MomentReference::instance().moments("sieve_psd");
  std::array<double, 8> m{};
  sieve_moments(sieve, 0.4, std::span<double>(m));
  for (int k = 0; k < 8; ++k) {
    INFO("k = " << k);
    CHECK(m[k] == doctest::Approx(oracle[std::size_t(k)]).epsilon(1e-15));
  }
  CHECK(d43<double>(m) == doctest::Approx(84.825).epsilon(1e-15));
  CHECK(d32(sieve) == doctest::Approx(MomentReference::instance().values("sieve_psd", 0, "d32")[0]).epsilon(1e-14));
  CHECK(d32(sieve) == doctest::Approx(79.48364158).epsilon(1e-10));
  // M_{−1} itself: 0.007548723084 (from the oracle's exact logarithmic bin integrals).
  CHECK(sieve_moment(sieve, 0.4, -1) == doctest::Approx(0.007548723084).epsilon(1e-10));
  CHECK(variance<double>(m) == doctest::Approx(474.3860417).epsilon(1e-10));
  // Geldart (seed 000 eq. 6.1, arithmetic bin means): 0.25% above M_0/M_{−1}.
  CHECK(geldart_sauter_diameter(sieve) == doctest::Approx(79.68309071).epsilon(1e-10));
  CHECK(solid_fraction<double>(m) == doctest::Approx(0.6).epsilon(1e-15));
}

TEST_CASE("sieve moments: narrow bins lose nothing to cancellation, for every order") {
  // ⟨ξ^p⟩ over [1, 1 + h] = 1 + p h/2 + p(p − 1) h²/6 + O(h³), any real p; E.7 as printed
  // (b^{p+1} − a^{p+1})/((p + 1)(b − a)) would lose ~|log2 h| = 30 bits here.
  const double h = std::ldexp(1.0, -30);
  const std::array<double, 2> edges{1, 1 + h};
  const SieveAnalysis<double> narrow{edges, bin_fraction};
  for (int p = -4; p <= 9; ++p) {
    const long double hl = h;
    const long double expected = 1 + p * hl / 2 + p * (p - 1) * hl * hl / 6;
    INFO("p = " << p);
    CHECK(std::abs(sieve_moment(narrow, 0.0, p) - double(expected)) <= 4 * std::numeric_limits<double>::epsilon());
  }
}

TEST_CASE("number-based sieve data: the NDF uniform within each bin") {
  // One bin [100, 200] with a uniform NDF: μ_j ∝ ⟨ξ^j⟩, so d10 = ⟨ξ⟩ = 150,
  // d32 = ⟨ξ³⟩/⟨ξ²⟩ = (3/4)(200⁴ − 100⁴)/(200³ − 100³) = 1125/7,
  // d43 = ⟨ξ⁴⟩/⟨ξ³⟩ = (4/5)(200⁵ − 100⁵)/(200⁴ − 100⁴) = 496/3, and M_0 = 1 − ε.
  const SieveAnalysis<double> counted{bin_edges, bin_fraction, SizeBasis::number};
  CHECK(d10(counted) == doctest::Approx(150).epsilon(1e-15));
  CHECK(d32(counted) == doctest::Approx(1125.0 / 7).epsilon(1e-15));
  std::array<double, 2> m{};
  sieve_moments(counted, 0.4, std::span<double>(m));
  CHECK(m[0] == doctest::Approx(0.6).epsilon(1e-15));
  CHECK(d43<double>(m) == doctest::Approx(496.0 / 3).epsilon(1e-15));
  // Number fractions of a narrow-bin distribution give the volume-based moments of the same
  // distribution: ν_i ∝ ω_i/ξ_i³ at the bin centres, up to second order in the bin width.
  std::array<double, 201> edges{};
  std::array<double, 200> volume{}, number{};
  for (std::size_t i = 0; i < edges.size(); ++i) edges[i] = 50 + 0.5 * double(i);
  for (std::size_t i = 0; i < volume.size(); ++i) {
    const double centre = (edges[i] + edges[i + 1]) / 2;
    volume[i] = std::exp(-std::pow((centre - 100) / 15, 2));
    number[i] = volume[i] / (centre * centre * centre);
  }
  const SieveAnalysis<double> by_volume{edges, volume}, by_number{edges, number, SizeBasis::number};
  for (int k = -1; k <= 4; ++k)
    CHECK(sieve_moment(by_number, 0.4, k) == doctest::Approx(sieve_moment(by_volume, 0.4, k)).epsilon(1e-4));
}

TEST_CASE("sieve moments: fractions are normalised, the pan, and the checked entry point") {
  const std::array<double, 7> doubled{0.1, 0.2, 0.4, 0.6, 0.4, 0.2, 0.1};
  const SieveAnalysis<double> twice{sieve_edges, doubled};
  for (int k = -1; k < 8; ++k) CHECK(sieve_moment(twice, 0.4, k) == doctest::Approx(sieve_moment(sieve, 0.4, k)).epsilon(1e-15));
  // A pan (lower edge 0): positive orders are finite, negative ones infinite (a uniform VDF
  // down to ξ = 0 holds infinitely many particles).
  const std::array<double, 3> pan_edges{0, 45, 53};
  const std::array<double, 2> pan_fractions{0.1, 0.9};
  const SieveAnalysis<double> pan{pan_edges, pan_fractions};
  CHECK(sieve_moment(pan, 0.4, 1) == doctest::Approx(0.6 * (0.1 * 22.5 + 0.9 * 49)).epsilon(1e-15));
  CHECK(std::isinf(sieve_moment(pan, 0.4, -1)));
  CHECK(std::isinf(sieve_moment(pan, 0.4, -2)));
  CHECK(sieve_moment(sieve, 0.4, 3, fluidbed::checked) == sieve_moment(sieve, 0.4, 3));
  CHECK(sieve_moment(pan, 0.4, 2, fluidbed::checked) == sieve_moment(pan, 0.4, 2));
  CHECK_THROWS_AS(sieve_moment(pan, 0.4, -1, fluidbed::checked), std::domain_error);
  CHECK_THROWS_AS(sieve_moment(sieve, 0.0, 1, fluidbed::checked), std::domain_error);
  CHECK_THROWS_AS(sieve_moment(sieve, 1.5, 1, fluidbed::checked), std::domain_error);
  const std::array<double, 3> decreasing{45, 40, 53};
  CHECK_THROWS_AS(sieve_moment(SieveAnalysis<double>{decreasing, pan_fractions}, 0.4, 1, fluidbed::checked), std::domain_error);
  const std::array<double, 2> negative{0.5, -0.1};
  CHECK_THROWS_AS(sieve_moment(SieveAnalysis<double>{pan_edges, negative}, 0.4, 1, fluidbed::checked), std::domain_error);
  CHECK_THROWS_AS(sieve_moment(SieveAnalysis<double>{bin_edges, pan_fractions}, 0.4, 1, fluidbed::checked), std::domain_error);
  const std::array<double, 2> zero{0, 0};
  CHECK_THROWS_AS(sieve_moment(SieveAnalysis<double>{pan_edges, zero}, 0.4, 1, fluidbed::checked), std::domain_error);
  const std::array<double, 3> nan_edge{45, std::nan(""), 53};
  CHECK_THROWS_AS(sieve_moment(SieveAnalysis<double>{nan_edge, pan_fractions}, 0.4, 1, fluidbed::checked), std::domain_error);
  // Valid arguments whose moment is not representable (found by fuzz/moment_inversion_fuzzer):
  // M_−3 = (1 − ε)⟨ξ^−3⟩ = (1 − ε)(a^−2 b^−1 + a^−1 b^−2)/2 over one bin [a, b], and a^−2 = 1e320
  // for a = 1e-160: +∞ in double. Named by k, the order asked for.
  const std::array<double, 2> wide{1e-160, 5e27};
  const std::array<double, 1> one{1};
  CHECK(std::isinf(sieve_moment(SieveAnalysis<double>{wide, one}, 0.5, -3)));
  CHECK_THROWS_WITH_AS(sieve_moment(SieveAnalysis<double>{wide, one}, 0.5, -3, fluidbed::checked),
                       doctest::Contains("argument 'k' = -3"), std::domain_error);
  // Below the range a moment underflows to 0, as any product does: M_12 of a bin at 1e-30 m is
  // ~1e-360 (documented; the checked and the hot path agree).
  const std::array<double, 2> tiny{1e-30, 2e-30};
  CHECK(sieve_moment(SieveAnalysis<double>{tiny, one}, 0.5, 12, fluidbed::checked) == 0);
  // The fuzzer's case in float: edges 1e-31 and 5e27, k = −3: a^−2 = 1e62, +∞ in float.
  const std::array<float, 2> wide_float{1e-31f, 5e27f};
  const std::array<float, 1> one_float{1};
  CHECK_THROWS_AS(sieve_moment(SieveAnalysis<float>{wide_float, one_float}, 0.5f, -3, fluidbed::checked), std::domain_error);
}

TEST_CASE("Sauter diameters of the published 2-node quadratures (seed 000 Table 6.2): A 88.56 µm, B 272.3 µm") {
  Quadrature<double, 2> a{{75, 103}, {0.262, 0.338}, 2};
  Quadrature<double, 2> b{{240, 355}, {0.380, 0.220}, 2};
  CHECK(d32(a) == doctest::Approx(88.56).epsilon(5e-5));
  CHECK(d32(b) == doctest::Approx(272.3).epsilon(2e-4));
  CHECK(d32(a) == doctest::Approx(MomentReference::instance().values("seed003_A_N2", 0, "d32")[0]).epsilon(1e-15));
  CHECK(d32(b) == doctest::Approx(MomentReference::instance().values("seed003_B_N2", 0, "d32")[0]).epsilon(1e-15));
  // d10 = Σφ/ξ² / Σφ/ξ³ and the generic d_pq: d43 = M_1/M_0.
  CHECK(d10(a) == doctest::Approx((0.262 / 75 / 75 + 0.338 / 103 / 103) / (0.262 / 75 / 75 / 75 + 0.338 / 103 / 103 / 103))
                      .epsilon(1e-15));
  CHECK(mean_diameter<double>(4, 3, [&](int k) { return quadrature_moment(a, k); }) ==
        doctest::Approx(MomentReference::instance().values("seed003_A_N2", 0, "d43")[0]).epsilon(1e-15));
  // d_pq with p − q = 2: d31 = (μ_3/μ_1)^{1/2} = (M_0/M_{−2})^{1/2}.
  CHECK(mean_diameter<double>(3, 1, [&](int k) { return quadrature_moment(a, k); }) ==
        doctest::Approx(std::sqrt(0.6 / (0.262 / 75 / 75 + 0.338 / 103 / 103))).epsilon(1e-15));
}

TEST_CASE("VDF ↔ NDF moments: M_k = (π/6) μ_{k+3}, and the class number density") {
  // n = 1e9 particles per m³ of diameter 1e-4 m: μ_j = n d^j.
  const double n = 1e9, d = 1e-4;
  std::array<double, 6> mu{};
  for (int j = 0; j < 6; ++j) mu[j] = n * std::pow(d, j + 3);
  std::array<double, 6> vdf{}, back{};
  vdf_from_ndf_moments<double>(mu, vdf);
  CHECK(vdf[0] == doctest::Approx(n * std::numbers::pi * d * d * d / 6).epsilon(1e-15));  // the solids fraction
  ndf_from_vdf_moments<double>(vdf, back);
  for (int j = 0; j < 6; ++j) CHECK(back[j] == doctest::Approx(mu[j]).epsilon(1e-15));
  CHECK(class_number_density(vdf[0], d) == doctest::Approx(n).epsilon(1e-15));
}

TEST_CASE("log-normal moment sets (m_0 = 0.6, median 100 µm, s = 0.3), and the set sharing M_0, M_1, M_2") {
  const double expected[] = {0.6,           62.761671594523,  7183.30417873086,  899581.50003406,
                             123265992.638633, 18481301093.5082, 3031854189938.32, 544215094071385};
  std::array<double, 8> m{};
  lognormal_moments<double>(0.6, {std::log(100.0), 0.09}, m);
  for (int k = 0; k < 8; ++k) CHECK(m[k] == doctest::Approx(expected[k]).epsilon(1e-14));
  for (int k = 0; k + 2 < 8; ++k) CHECK(std::log(m[k]) - 2 * std::log(m[k + 1]) + std::log(m[k + 2]) == doctest::Approx(0.09).epsilon(1e-12));
  const LognormalParameters<double> p = lognormal_matching(m[0], m[1], m[2]);
  CHECK(p.mu == doctest::Approx(std::log(100.0)).epsilon(1e-14));
  CHECK(p.sigma_squared == doctest::Approx(0.09).epsilon(1e-13));
  // The fill from the M_0, M_1, M_2 of the 4-class mixture of seed 000 Table 6.4:
  // s² = 0.270264654551, e^μ = 162.9002485 (moments_reference.py, mcgraw_checks).
  const LognormalParameters<double> mix = lognormal_matching(0.6, 111.882, 27336.546);
  CHECK(mix.sigma_squared == doctest::Approx(0.270264654551).epsilon(1e-11));
  CHECK(std::exp(mix.mu) == doctest::Approx(162.9002485).epsilon(1e-9));
}

TEST_CASE("the helpers run in float, long double and Boost.Multiprecision") {
  using F = boost::multiprecision::cpp_bin_float_50;
  std::array<F, 8> edges{};
  for (std::size_t i = 0; i < 8; ++i) edges[i] = F(sieve_edges[i]);  // integers: exact
  const std::array<F, 7> fractions{F("0.05"), F("0.10"), F("0.20"), F("0.30"), F("0.20"), F("0.10"), F("0.05")};
  const SieveAnalysis<F> precise{edges, fractions};
  // 50 digits: M_5 = 4833551588.085 exactly (a rational with a short decimal expansion), and
  // d32 = 79.483641584000119… (oracle, 17 digits).
  CHECK(abs(sieve_moment(precise, F(4) / 10, 5) - F("4833551588.085")) < F("1e-35"));
  CHECK(abs(d32(precise) - F("79.483641584000119")) < F("1e-14"));
  const std::array<float, 8> ef{45, 53, 63, 75, 90, 106, 125, 150};
  const std::array<float, 7> ff{0.05f, 0.10f, 0.20f, 0.30f, 0.20f, 0.10f, 0.05f};
  CHECK(d32(SieveAnalysis<float>{ef, ff}) == doctest::Approx(79.48364158).epsilon(1e-6));
  const std::array<long double, 2> el{100, 200};
  const std::array<long double, 1> fl{1};
  CHECK(sieve_moment(SieveAnalysis<long double>{el, fl}, 0.4L, 3) == doctest::Approx(2250000).epsilon(1e-17));
}
