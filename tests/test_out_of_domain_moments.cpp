// Out-of-domain input for the moment routines. The inversions report problems as data, not
// exceptions (inversion.hpp: "never NaN without a status"): NaN or ±∞ in any moment is
// invalid_input with no node, a zero or negative moment a status (not_realizable or reduced)
// with finite nodes and positive weights, for every entry point — per cell, adaptive,
// Gauss–Radau, Eigen backend, realizability, correction and batched. The sieve moments have a
// checked entry point that throws, tested like the closures (test_out_of_domain.hpp).
#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "fluidbed/moments.hpp"
#include "fluidbed/moments/eigen_backend.hpp"
#include "test_out_of_domain.hpp"

namespace {

using namespace fluidbed::moments;
using namespace fluidbed::test;

constexpr int nodes = 3;
using Moments = std::array<double, 2 * nodes>;

// The VDF moments of a log-normal powder in SI units (README), realizable with three nodes.
constexpr Moments powder{0.6, 6.2762e-5, 7.1833e-9, 8.9958e-13, 1.2327e-16, 1.8481e-20};

// What an entry point made of a moment set: whether it reported the input invalid, how many
// nodes it returned, and whether they and their weights are finite (weights > 0).
struct Outcome {
  bool invalid_input;
  bool realizable;  // the whole set accepted (status ok)
  int size;
  bool finite;
};

template <int N>
Outcome outcome_of(const InversionResult<double, N>& r) {
  bool finite = true;
  for (int i = 0; i < r.quadrature.size; ++i)
    finite = finite && std::isfinite(r.quadrature.nodes[i]) && std::isfinite(r.quadrature.weights[i]) &&
             r.quadrature.weights[i] > 0;
  const bool finite_diagnostics = std::isfinite(r.failing_value) && std::isfinite(r.boundary_distance);
  return {r.status == InversionStatus::invalid_input, r.status == InversionStatus::ok, r.quadrature.size,
          finite && finite_diagnostics};
}

struct EntryPoint {
  std::string name;
  std::function<Outcome(const Moments&)> run;
};

std::span<const double> view(const Moments& m, std::size_t size = 2 * nodes) { return {m.data(), size}; }

const std::vector<EntryPoint> inversions{
    {"invert (Wheeler)", [](const Moments& m) { return outcome_of(invert<nodes>(m)); }},
    {"invert (product-difference)",
     [](const Moments& m) {
       return outcome_of(invert<nodes>(m, {.algorithm = RecurrenceAlgorithm::product_difference}));
     }},
    {"invert (Golub-Welsch)",
     [](const Moments& m) { return outcome_of(invert<nodes>(m, {.solver = EigenSolver::golub_welsch})); }},
    {"invert (real line)",
     [](const Moments& m) { return outcome_of(invert<nodes>(m, {.support = Support::real_line})); }},
    {"invert_eigen", [](const Moments& m) { return outcome_of(invert_eigen<nodes>(m)); }},
    {"invert_adaptive", [](const Moments& m) { return outcome_of<nodes>(invert_adaptive<nodes>(m)); }},
    {"invert_adaptive (Radau, 5 moments)",
     [](const Moments& m) {
       AdaptiveOptions<double> options;
       options.radau = true;
       return outcome_of<nodes>(invert_adaptive<double, nodes>(view(m, 5), options));
     }},
    {"gauss_radau (5 moments)",
     [](const Moments& m) { return outcome_of(gauss_radau<double, nodes>(view(m, 5), 0.0)); }},
    {"realizability",
     [](const Moments& m) {
       const RealizabilityReport<double, nodes> r = realizability<double, nodes>(view(m));
       return Outcome{r.status == InversionStatus::invalid_input, r.status == InversionStatus::ok, r.realizable_nodes,
                      std::isfinite(r.failing_value) && std::isfinite(r.boundary_distance)};
     }},
};

// The moment set with moment k replaced by `value`.
Moments with(std::size_t k, double value) {
  Moments m = powder;
  m[k] = value;
  return m;
}

}  // namespace

TEST_CASE("out of domain: NaN and infinite moments are invalid_input for every inversion, at every index") {
  for (const EntryPoint& entry : inversions) {
    INFO("entry point: ", entry.name);
    const Outcome valid = entry.run(powder);
    CHECK(valid.realizable);
    CHECK(valid.finite);
    const std::size_t used = entry.name.find("5 moments") != std::string::npos ? 5 : 2 * nodes;
    for (std::size_t k = 0; k < used; ++k)
      for (const Bad& bad : non_finite) {
        INFO("moment ", k, " = ", bad.shown);
        const Outcome o = entry.run(with(k, bad.value));
        CHECK(o.invalid_input);
        CHECK(o.size == 0);
      }
  }
}

TEST_CASE("out of domain: zero and negative moments are a status with finite nodes, at every index") {
  for (const EntryPoint& entry : inversions) {
    INFO("entry point: ", entry.name);
    const bool real_line = entry.name.find("real line") != std::string::npos;
    const std::size_t used = entry.name.find("5 moments") != std::string::npos ? 5 : 2 * nodes;
    for (std::size_t k = 0; k < used; ++k)
      for (const double factor : {0.0, -1.0}) {
        // On the real line odd moments may have either sign: only m_0 and the even ones are tested.
        if (real_line && k % 2 == 1) continue;
        INFO("moment ", k, " times ", factor);
        const Outcome o = entry.run(with(k, factor * powder[k]));
        CHECK(!o.invalid_input);
        CHECK(!o.realizable);
        CHECK(o.size < nodes);
        CHECK(o.finite);
      }
  }
}

TEST_CASE("out of domain: corrupted sets are corrected or reported as failed, never NaN") {
  using Correct = std::function<CorrectionResult<double, nodes>(std::span<const double>)>;
  const std::vector<std::pair<std::string, Correct>> corrections{
      {"correct_moments", [](std::span<const double> m) { return correct_moments<double, nodes>(m); }},
      {"mcgraw_correct", [](std::span<const double> m) { return mcgraw_correct<double, nodes>(m); }},
  };
  for (const auto& entry : corrections) {
    const std::string& name = entry.first;  // (clang 14 lambdas, as INFO's, cannot capture a structured binding)
    const Correct& correct = entry.second;
    INFO("entry point: ", name);
    CHECK(correct(view(powder)).status == CorrectionStatus::unchanged);
    for (std::size_t k = 0; k < powder.size(); ++k) {
      for (const Bad& bad : non_finite) {
        INFO("moment ", k, " = ", bad.shown);
        CHECK(correct(view(with(k, bad.value))).status == CorrectionStatus::failed);
      }
      for (const double factor : {0.0, -1.0}) {
        INFO("moment ", k, " times ", factor);
        const Moments corrupted = with(k, factor * powder[k]);
        const CorrectionResult<double, nodes> r = correct(view(corrupted));
        if (k <= 1) {  // m_0 <= 0 or m_1 <= 0: nothing to correct from
          CHECK(r.status == CorrectionStatus::failed);
          continue;
        }
        for (int i = 0; i < r.size; ++i) CHECK(std::isfinite(r.moments[std::size_t(i)]));
        if (name == "correct_moments") {  // a set with at least one node (an atom for the monodisperse fallback)
          const Outcome inverted = outcome_of(invert<nodes>(r.moments));
          CHECK(inverted.size >= 1);
          CHECK(inverted.finite);
        }
      }
    }
  }
}

TEST_CASE("out of domain: batched inversion gives each bad cell the per-cell status") {
  // One cell per (moment, bad value), between valid cells.
  std::vector<Moments> cells{powder};
  for (std::size_t k = 0; k < powder.size(); ++k) {
    for (const Bad& bad : non_finite) cells.push_back(with(k, bad.value));
    for (const double factor : {0.0, -1.0}) cells.push_back(with(k, factor * powder[k]));
    cells.push_back(powder);
  }
  const std::size_t count = cells.size();
  std::vector<std::vector<double>> fields(2 * nodes, std::vector<double>(count)), x(nodes, std::vector<double>(count)),
      w(nodes, std::vector<double>(count));
  for (std::size_t c = 0; c < count; ++c)
    for (std::size_t k = 0; k < 2 * nodes; ++k) fields[k][c] = cells[c][k];
  MomentBatch<double, nodes> in;
  for (std::size_t k = 0; k < 2 * nodes; ++k) in.moments[k] = fields[k];
  std::vector<int> sizes(count);
  std::vector<InversionStatus> status(count);
  QuadratureBatch<double, nodes> out;
  for (std::size_t i = 0; i < nodes; ++i) {
    out.nodes[i] = x[i];
    out.weights[i] = w[i];
  }
  out.sizes = sizes;
  out.status = status;
  REQUIRE(invert_batched(in, out));
  for (std::size_t c = 0; c < count; ++c) {
    INFO("cell ", c);
    const InversionResult<double, nodes> single = invert<nodes>(cells[c]);
    CHECK(status[c] == single.status);
    CHECK(sizes[c] == single.quadrature.size);
    for (int i = 0; i < sizes[c]; ++i) CHECK((std::isfinite(x[std::size_t(i)][c]) && w[std::size_t(i)][c] > 0));
  }
}

TEST_CASE("out of domain: sieve moments, checked") {
  // Three bins 45–63–90–150 µm (in m).
  const auto sieve_moment_of = [](const Values& v) {
    const std::array<double, 4> edges{v[0], v[1], v[2], v[3]};
    const std::array<double, 3> fractions{v[4], v[5], v[6]};
    return sieve_moment(SieveAnalysis<double>{edges, fractions}, v[7], 3, fluidbed::checked);
  };
  const std::vector<ArgumentCase> arguments{
      {"edges[0]", 45e-6, negative, {0.0}},
      {"edges[1]", 63e-6, and_non_finite({{0.0, "0"}, {-1.0, "-1"}})},  // not increasing
      {"edges[2]", 90e-6, and_non_finite({{0.0, "0"}, {-1.0, "-1"}})},
      {"edges[3]", 150e-6, and_non_finite({{0.0, "0"}, {-1.0, "-1"}})},
      {"fractions[0]", 0.25, negative, {0.0}},
      {"fractions[1]", 0.5, negative, {0.0}},
      {"fractions[2]", 0.25, negative, {0.0}},
      {"voidage", 0.5, outside_voidage, {1.0}},
  };
  check_entry_point("sieve_moment", arguments, sieve_moment_of);
  CHECK_THROWS_WITH_AS(sieve_moment(SieveAnalysis<double>{std::array{0.0, 1e-4}, std::array{1.0}}, 0.5, -1, fluidbed::checked),
                       doctest::Contains("'edges[0] (negative order k)' = 0"), std::domain_error);
}
