// Counts and span sizes: every moments entry point that takes a span, a count or a sized rule
// returns its status (or an empty result, false, NaN) for a count it does not take — empty,
// odd, above the capacity, too few moments, mismatched span sizes — and never reads or writes
// beyond its storage, never aborts, never drops a moment silently, at every optimisation level
// (the suite also runs in Release -O3 and under AddressSanitizer). The exact cases of issue 13:
// invert<double, 3> given 7 or 8 moments wrote past its storage (a stack-buffer-overflow in a
// Release build, an abort in Debug), and given 5 it dropped m_4 and returned ok with 2 nodes.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fluidbed/moments.hpp"

using namespace fluidbed::moments;

namespace {

constexpr int capacity = 3;

// The first 9 VDF moments of a log-normal powder in SI units (m_0 = 0.6, median 100 µm,
// s = 0.3; tests/reference/moments_reference.py case lognormal_si): realizable to any order,
// so that any prefix of them is a valid set of that count.
std::vector<double> powder(std::size_t count) {
  std::vector<double> m(count);
  for (std::size_t k = 0; k < count; ++k)
    m[k] = 0.6 * std::exp(double(k) * std::log(1e-4) + double(k * k) * 0.09 / 2);
  return m;
}

// What invert() promises for a count it does not take: invalid_input, no node, no diagnostic.
template <int N>
void check_refused(const InversionResult<double, N>& r) {
  CHECK(r.status == InversionStatus::invalid_input);
  CHECK(r.quadrature.size == 0);
  CHECK(r.realizable_nodes == 0);
  CHECK(r.first_failing_index == 0);
  CHECK(r.failing_value == 0);
}

bool all_nan(std::span<const double> values) {
  for (const double x : values)
    if (!std::isnan(x)) return false;
  return true;
}

}  // namespace

TEST_CASE("issue 13: invert<double, 3> given 7, 8 or 5 moments is invalid_input, in every build") {
  for (const std::size_t count : {7, 8, 5}) {
    INFO(count << " moments");
    const std::vector<double> m = powder(count);
    check_refused(invert<double, capacity>(std::span<const double>(m)));
    check_refused(invert_eigen<double, capacity>(std::span<const double>(m)));
  }
  // The prefixes of the same set with an even count up to the capacity invert fully.
  for (const std::size_t count : {2, 4, 6}) {
    const std::vector<double> m = powder(count);
    const InversionResult<double, capacity> r = invert<double, capacity>(std::span<const double>(m));
    CHECK(r.status == InversionStatus::ok);
    CHECK(r.quadrature.size == int(count / 2));
  }
}

TEST_CASE("invert and invert_eigen: every count but 2, 4, … 2N is invalid_input, with every option") {
  const std::vector<double> m = powder(2 * capacity + 3);
  for (const RecurrenceAlgorithm algorithm : {RecurrenceAlgorithm::wheeler, RecurrenceAlgorithm::product_difference})
    for (const EigenSolver solver : {EigenSolver::automatic, EigenSolver::golub_welsch})
      for (const Support support : {Support::positive_half_line, Support::real_line})
        for (std::size_t count = 0; count <= m.size(); ++count) {
          const InversionOptions options{.algorithm = algorithm, .solver = solver, .support = support};
          const std::span<const double> set(m.data(), count);
          INFO(count << " moments");
          const bool taken = count >= 2 && count <= 2 * capacity && count % 2 == 0;
          const InversionResult<double, capacity> r = invert<double, capacity>(set, options);
          const InversionResult<double, capacity> e = invert_eigen<double, capacity>(set, options);
          if (taken) {
            CHECK(r.status == InversionStatus::ok);
            CHECK(e.status == InversionStatus::ok);
          } else {
            check_refused(r);
            check_refused(e);
          }
        }
  // Capacity 1: only 2 moments.
  const std::vector<double> three = powder(3);
  check_refused(invert<double, 1>(std::span<const double>(three)));
  check_refused(invert<double, 1>(std::span<const double>(three.data(), 1)));
  CHECK(invert<double, 1>(std::span<const double>(three.data(), 2)).status == InversionStatus::ok);
}

TEST_CASE("recurrence, wheeler_unscaled, product_difference_unscaled: an empty recurrence for another count") {
  const std::vector<double> m = powder(2 * capacity + 2);
  for (std::size_t count = 0; count <= m.size(); ++count) {
    INFO(count << " moments");
    const std::span<const double> set(m.data(), count);
    const bool taken = count >= 2 && count <= 2 * capacity && count % 2 == 0;
    const int expected = taken ? int(count / 2) : 0;
    CHECK(recurrence<double, capacity>(set).size == expected);
    CHECK(recurrence<double, capacity>(set, RecurrenceAlgorithm::product_difference).size == expected);
    CHECK(wheeler_unscaled<double, capacity>(set).size == expected);
    std::array<double, 2 * capacity> zeta;
    zeta.fill(-1);
    CHECK(product_difference_unscaled<double, capacity>(set, &zeta).size == expected);
    if (!taken)
      for (const double z : zeta) CHECK(z == 0);
  }
  // m_0 not > 0 and finite: no recurrence either (recurrence() scales by m_0).
  for (const double m0 : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    std::vector<double> bad = powder(4);
    bad[0] = m0;
    CHECK(recurrence<double, capacity>(std::span<const double>(bad)).size == 0);
  }
}

TEST_CASE("realizability: 1 … 2N moments, another count invalid_input with nothing filled") {
  const std::vector<double> m = powder(2 * capacity + 2);
  for (std::size_t count = 0; count <= m.size(); ++count) {
    INFO(count << " moments");
    for (const Support support : {Support::positive_half_line, Support::real_line}) {
      const RealizabilityReport<double, capacity> r =
          realizability<double, capacity>(std::span<const double>(m.data(), count), support);
      if (count >= 1 && count <= 2 * capacity) {
        CHECK(r.status == InversionStatus::ok);
        CHECK(r.realizable_moments == int(count));
        CHECK(r.hankel_count == int(count));
      } else {
        CHECK(r.status == InversionStatus::invalid_input);
        CHECK(r.realizable_moments == 0);
        CHECK(r.zeta_count == 0);
        CHECK(r.hankel_count == 0);
      }
    }
  }
}

TEST_CASE("invert_adaptive: 2 … 2N moments (odd ones too), another count invalid_input") {
  const std::vector<double> m = powder(2 * capacity + 2);
  for (const bool radau : {false, true})
    for (std::size_t count = 0; count <= m.size(); ++count) {
      INFO(count << " moments, Radau " << radau);
      AdaptiveOptions<double> options;
      options.radau = radau;
      const AdaptiveInversionResult<double, capacity> r =
          invert_adaptive<double, capacity>(std::span<const double>(m.data(), count), options);
      if (count >= 2 && count <= 2 * capacity) {
        CHECK(r.quadrature.size >= 1);
        CHECK(r.moments_used <= int(count));
        // An odd count without Radau drops its last moment, and says so.
        if (count % 2 == 1 && !radau) CHECK(r.moments_used == int(count) - 1);
      } else {
        CHECK(r.status == InversionStatus::invalid_input);
        CHECK(r.quadrature.size == 0);
        CHECK(r.moments_used == 0);
      }
    }
}

TEST_CASE("gauss_radau: an odd count 3 … 2N − 1, another count invalid_input") {
  const std::vector<double> m = powder(2 * capacity + 2);
  for (std::size_t count = 0; count <= m.size(); ++count) {
    INFO(count << " moments");
    const InversionResult<double, capacity> r =
        gauss_radau<double, capacity>(std::span<const double>(m.data(), count), 0.0);
    if (count >= 3 && count <= 2 * capacity - 1 && count % 2 == 1) {
      CHECK(r.status == InversionStatus::ok);
      CHECK(r.quadrature.size == int(count / 2) + 1);
    } else {
      check_refused(r);
    }
  }
}

TEST_CASE("correct_moments, mcgraw_correct: 1 … 2N moments, another count failed with size 0") {
  const std::vector<double> m = powder(2 * capacity + 2);
  for (std::size_t count = 0; count <= m.size(); ++count) {
    INFO(count << " moments");
    const std::span<const double> set(m.data(), count);
    for (const CorrectionResult<double, capacity>& r :
         {correct_moments<double, capacity>(set), mcgraw_correct<double, capacity>(set)}) {
      if (count >= 1 && count <= 2 * capacity) {
        CHECK(r.status == CorrectionStatus::unchanged);
        CHECK(r.size == int(count));
      } else {
        CHECK(r.status == CorrectionStatus::failed);
        CHECK(r.size == 0);
      }
    }
  }
}

TEST_CASE("scaling helpers: an empty set, m_0 <= 0, a short output span") {
  CHECK(scaling_of(std::span<const double>()).weight_exponent == 0);
  CHECK(scaling_of(std::span<const double>()).length_exponent == 0);
  for (const double m0 : {0.0, -2.0, std::numeric_limits<double>::infinity()}) {
    const std::array<double, 3> m{m0, 4.0, 64.0};
    const MomentScaling s = scaling_of(std::span<const double>(m));
    CHECK(s.weight_exponent == 0);
    CHECK(s.length_exponent == 0);
  }
  const std::vector<double> m = powder(4);
  const MomentScaling s = scaling_of(std::span<const double>(m));
  std::array<double, 4> exact{};
  CHECK(scale_moments(std::span<const double>(m), s, std::span<double>(exact)));
  std::array<double, 6> longer{};
  longer.fill(7);
  CHECK(scale_moments(std::span<const double>(m), s, std::span<double>(longer)));
  for (std::size_t k = 0; k < 4; ++k) CHECK(longer[k] == exact[k]);
  CHECK(longer[4] == 7);  // beyond the input: untouched
  std::array<double, 3> shorter{};
  CHECK_FALSE(scale_moments(std::span<const double>(m), s, std::span<double>(shorter)));
  CHECK(all_nan(shorter));
}

TEST_CASE("recurrences and rules whose size is not within 0 … N: no rule, nothing read beyond the storage") {
  Recurrence<double, capacity> r;
  r.alpha = {1.0, 2.0, 3.0};
  r.beta = {1.0, 0.5, 0.25};
  for (const int size : {-1, capacity + 1, 1000}) {
    INFO("size " << size);
    r.size = size;
    Recurrence<double, capacity> unscaled = r;
    unscale(unscaled, MomentScaling{3, -2});
    CHECK(unscaled.alpha == r.alpha);  // left unchanged
    CHECK(unscaled.beta == r.beta);
    for (const double z : stieltjes_coefficients(r)) CHECK(z == 0);
    CHECK(gauss_closed_form(r).size == 0);
    Quadrature<double, capacity> q;
    q.size = 2;
    CHECK_FALSE(gauss_golub_welsch(r, q));
    CHECK(q.size == 0);
    q.size = 2;
    CHECK_FALSE(gauss_eigen_tridiagonal(r, q));
    CHECK(q.size == 0);
    CHECK(gauss_three_nodes(r).size == 0);
  }
  // Sizes a solver does not take: the closed forms beyond 2 nodes, the three-node solver
  // other than 3 (and gauss_closed_form at capacity 1 asked for 2 nodes).
  r.size = 3;
  CHECK(gauss_closed_form(r).size == 0);
  r.size = 2;
  CHECK(gauss_three_nodes(r).size == 0);
  Recurrence<double, 1> small;
  small.size = 2;
  CHECK(gauss_closed_form(small).size == 0);
}

TEST_CASE("moment-set helpers: mismatched spans give false and NaN, too few moments NaN") {
  const std::array<double, 3> x{1, 2, 5}, w{0.2, 0.5, 0.3};
  std::array<double, 4> m{};
  CHECK(moments_from_quadrature<double>(x, w, m));
  CHECK(m[1] == doctest::Approx(2.7));
  CHECK_FALSE(moments_from_quadrature<double>(x, std::span<const double>(w).first(2), m));
  CHECK(all_nan(m));
  Quadrature<double, capacity> q;
  q.size = capacity + 1;
  CHECK_FALSE(moments_from_quadrature(q, std::span<double>(m)));
  CHECK(all_nan(m));
  CHECK(std::isnan(quadrature_moment(q, 1)));
  CHECK(std::isnan(d32(q)));
  CHECK(std::isnan(d10(q)));

  const std::array<double, 1> one{0.6};
  const std::array<double, 2> two{0.6, 6e-5};
  CHECK(std::isnan(d43(std::span<const double>())));
  CHECK(std::isnan(d43<double>(one)));
  CHECK(d43<double>(two) == doctest::Approx(1e-4));
  CHECK(std::isnan(variance<double>(two)));
  CHECK(std::isnan(solid_fraction(std::span<const double>())));
  CHECK(solid_fraction<double>(one) == 0.6);

  std::array<double, 3> vdf{}, ndf{};
  const std::array<double, 2> short_input{1, 2};
  CHECK_FALSE(vdf_from_ndf_moments<double>(short_input, vdf));
  CHECK(all_nan(vdf));
  CHECK_FALSE(ndf_from_vdf_moments<double>(std::span<const double>(vdf), std::span<double>(ndf).first(2)));
  CHECK(all_nan(std::span<const double>(ndf).first(2)));
  CHECK(ndf[2] == 0);  // beyond the output span: untouched
}

TEST_CASE("sieve analyses: edges not one more than fractions give NaN, false, and the checked form throws with the counts") {
  const std::array<double, 4> edges{45e-6, 63e-6, 90e-6, 150e-6};
  const std::array<double, 3> fractions{0.25, 0.5, 0.25};
  const SieveAnalysis<double> good{edges, fractions};
  CHECK(std::isfinite(sieve_moment(good, 0.4, 3)));
  const std::vector<SieveAnalysis<double>> bad{
      {std::span<const double>(edges).first(3), fractions},   // one edge short: edges[3] would be read
      {edges, std::span<const double>(fractions).first(2)},   // one edge too many
      {edges, std::span<const double>()},                      // no bin
      {std::span<const double>(), std::span<const double>()},  // nothing
  };
  for (const SieveAnalysis<double>& psd : bad) {
    INFO(psd.edges.size() << " edges, " << psd.fractions.size() << " fractions");
    CHECK(std::isnan(sieve_moment(psd, 0.4, 1)));
    std::array<double, 4> m{};
    CHECK_FALSE(sieve_moments(psd, 0.4, std::span<double>(m)));
    CHECK(all_nan(m));
    CHECK(std::isnan(geldart_sauter_diameter(psd)));
    CHECK(std::isnan(d32(psd)));
    CHECK(std::isnan(d10(psd)));
    CHECK_THROWS_AS(sieve_moment(psd, 0.4, 1, fluidbed::checked), std::domain_error);
  }
  CHECK_THROWS_WITH_AS(sieve_moment(bad[0], 0.4, 1, fluidbed::checked),
                       doctest::Contains("'edges.size()' = 3 is out of domain (must be fractions.size() + 1 = 4)"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(sieve_moment(bad[2], 0.4, 1, fluidbed::checked),
                       doctest::Contains("'fractions.size()' = 0 is out of domain (must be >= 1 (a bin))"),
                       std::domain_error);
}

TEST_CASE("invert_batched: spans of different lengths give false and nothing read or written") {
  constexpr int N = 2;
  constexpr std::size_t cells = 20;  // full lanes (8 or 16 doubles) and a partial one
  const std::vector<double> m = powder(2 * N);
  std::vector<std::vector<double>> fields(2 * N, std::vector<double>(cells));
  for (std::size_t k = 0; k < 2 * N; ++k)
    for (std::size_t c = 0; c < cells; ++c) fields[k][c] = m[k];
  std::vector<std::vector<double>> x(N, std::vector<double>(cells, -7.0)), w(x);
  std::vector<int> sizes(cells, -7);
  std::vector<InversionStatus> status(cells, InversionStatus::eigen_failure);
  const auto batch = [&](std::size_t moment_cells, std::size_t node_cells, std::size_t size_cells) {
    MomentBatch<double, N> in;
    for (std::size_t k = 0; k < 2 * N; ++k) in.moments[k] = std::span<const double>(fields[k]).first(k == 2 ? moment_cells : cells);
    QuadratureBatch<double, N> out;
    for (std::size_t i = 0; i < N; ++i) {
      out.nodes[i] = std::span<double>(x[i]).first(i == 1 ? node_cells : cells);
      out.weights[i] = std::span<double>(w[i]);
    }
    out.sizes = std::span<int>(sizes).first(size_cells);
    out.status = std::span<InversionStatus>(status);
    return std::pair{in, out};
  };
  const auto untouched = [&] {
    bool same = true;
    for (std::size_t c = 0; c < cells; ++c) {
      same = same && sizes[c] == -7 && status[c] == InversionStatus::eigen_failure;
      for (std::size_t i = 0; i < N; ++i) same = same && x[i][c] == -7.0 && w[i][c] == -7.0;
    }
    return same;
  };
  for (const std::array<std::size_t, 3>& lengths :
       std::vector<std::array<std::size_t, 3>>{{cells - 1, cells, cells}, {cells, cells - 1, cells}, {cells, cells, 0}}) {
    INFO("moment 2: " << lengths[0] << " cells, node 1: " << lengths[1] << ", sizes: " << lengths[2]);
    const auto mismatched = batch(lengths[0], lengths[1], lengths[2]);
    CHECK_FALSE(invert_batched(mismatched.first, mismatched.second));
    CHECK(untouched());
  }
  const auto matched = batch(cells, cells, cells);
  CHECK(invert_batched(matched.first, matched.second));
  for (std::size_t c = 0; c < cells; ++c) CHECK(status[c] == InversionStatus::ok);
  // An empty batch is a batch: nothing to do.
  CHECK(invert_batched(MomentBatch<double, N>{}, QuadratureBatch<double, N>{}));
}
