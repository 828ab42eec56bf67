// Cost of the DQMOM source solve (moments/dqmom.hpp) per cell, ν = 2 … 5 and 8 nodes, against a
// baseline written the way generic codes do it, measured in the same run:
//
//   baseline     the 2ν × 2ν matrix X of the thesis's eq. 5.63 built in SI units in a fixed-size
//                Eigen matrix, Eigen's PartialPivLU, solve (what a DQMOM code without structure
//                does; it neither scales nor reports the conditioning)
//   system       System<N> + solve(moment sources): the Hermite rows of X⁻¹ and κ_∞
//   growth       System<N> + solve(growth_terms): point functionals (no moments formed)
//   batched      solve_batched(): the Hermite solve with SIMD lanes across cells, no κ
//   batched_cond solve_batched() with κ_∞ per cell
//
// Two node distributions, 4096 cells each: "narrow" (the Gauss nodes of log-normal size
// distributions, median 50–500 µm, σ_ln 0.15–0.6), and "wide" (ν random sizes log-uniform in
// 20 µm–2 mm, none closer than 1 %). Moment sources are random numbers of the size of the
// moments. Every path reads the same cells and writes every source.
#include <benchmark/benchmark.h>

#include "fluidbed/moments/eigen_core.hpp"  // first: Eigen without its own warnings

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "fluidbed/moments/dqmom.hpp"
#include "fluidbed/moments/dqmom_batched.hpp"
#include "fluidbed/moments/inversion.hpp"
#include "ratio_reporter.hpp"

using namespace fluidbed::moments;

namespace {

constexpr int cells = 4096;

template <int N>
struct Cells {
  std::vector<std::vector<double>> nodes = std::vector<std::vector<double>>(N, std::vector<double>(cells));
  std::vector<std::vector<double>> weights = std::vector<std::vector<double>>(N, std::vector<double>(cells));
  std::vector<std::vector<double>> s = std::vector<std::vector<double>>(2 * N, std::vector<double>(cells));
};

template <int N>
Cells<N> make_cells(bool wide) {
  Cells<N> out;
  std::mt19937_64 random(wide ? 7 : 3);
  std::uniform_real_distribution<double> unit(0, 1), sign(-1, 1);
  for (int c = 0; c < cells; ++c) {
    std::array<double, N> x{}, w{};
    if (wide) {
      for (bool distinct = false; !distinct;) {
        for (int i = 0; i < N; ++i) x[i] = 20e-6 * std::pow(100.0, unit(random)), w[i] = 0.05 + 0.3 * unit(random);
        distinct = true;
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < i; ++j) distinct = distinct && std::abs(x[i] - x[j]) > 0.01 * std::max(x[i], x[j]);
      }
    } else {
      const double median = 50e-6 * std::pow(10.0, unit(random)), sigma = 0.15 + 0.45 * unit(random);
      std::array<double, 2 * N> m{};
      for (int k = 0; k < 2 * N; ++k) m[k] = 0.5 * std::exp(k * std::log(median) + 0.5 * k * k * sigma * sigma);
      const auto rule = invert<N>(m);
      if (rule.status != InversionStatus::ok) std::abort();
      for (int i = 0; i < N; ++i) x[i] = rule.quadrature.nodes[i], w[i] = rule.quadrature.weights[i];
    }
    for (int i = 0; i < N; ++i) out.nodes[i][c] = x[i], out.weights[i][c] = w[i];
    for (int k = 0; k < 2 * N; ++k) {
      double moment = 0;
      for (int i = 0; i < N; ++i) moment += w[i] * std::pow(x[i], k);
      out.s[k][c] = moment * sign(random);
    }
  }
  return out;
}

// (Eigen's blocked LU draws GCC 12's AVX-512 false positives at -march=native: silenced here only.)
FLUIDBED_EIGEN_CODE_BEGIN
template <int N>
void baseline(benchmark::State& state, bool wide) {
  const auto in = make_cells<N>(wide);
  std::vector<double> out(2 * N * cells);
  for (auto _ : state) {
    for (int c = 0; c < cells; ++c) {
      Eigen::Matrix<double, 2 * N, 2 * N> x;
      Eigen::Matrix<double, 2 * N, 1> s;
      for (int k = 0; k < 2 * N; ++k) {
        s(k) = in.s[k][c];
        for (int i = 0; i < N; ++i) {
          const double xi = in.nodes[i][c];
          x(k, i) = (1 - k) * std::pow(xi, k);
          x(k, N + i) = k * std::pow(xi, k - 1);
        }
      }
      const Eigen::Matrix<double, 2 * N, 1> solution = x.partialPivLu().solve(s);
      for (int j = 0; j < 2 * N; ++j) out[std::size_t(2 * N * c + j)] = solution(j);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}

FLUIDBED_EIGEN_CODE_END

template <int N>
void system_solve(benchmark::State& state, bool wide) {
  const auto in = make_cells<N>(wide);
  std::vector<double> out(2 * N * cells);
  for (auto _ : state) {
    for (int c = 0; c < cells; ++c) {
      std::array<double, N> x{}, w{};
      std::array<double, 2 * N> s{};
      for (int i = 0; i < N; ++i) x[i] = in.nodes[i][c], w[i] = in.weights[i][c];
      for (int k = 0; k < 2 * N; ++k) s[k] = in.s[k][c];
      const dqmom::System<double, N> system{std::span<const double>(x), std::span<const double>(w)};
      const auto r = system.solve(std::span<const double>(s));
      for (int i = 0; i < N; ++i) out[std::size_t(2 * N * c + i)] = r.weight[i], out[std::size_t(2 * N * c + N + i)] = r.weighted_node[i];
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}

template <int N>
void growth(benchmark::State& state, bool wide) {
  const auto in = make_cells<N>(wide);
  std::vector<double> out(2 * N * cells);
  for (auto _ : state) {
    for (int c = 0; c < cells; ++c) {
      std::array<double, N> x{}, w{}, g{};
      for (int i = 0; i < N; ++i) x[i] = in.nodes[i][c], w[i] = in.weights[i][c], g[i] = 1e-7 * x[i] / 1e-4;
      const dqmom::System<double, N> system{std::span<const double>(x), std::span<const double>(w)};
      const auto terms = dqmom::growth_terms<double, N>(dqmom::Weights::volume_fraction, std::span<const double>(w),
                                                        std::span<const double>(x), std::span<const double>(g));
      const auto r = system.solve(std::span<const dqmom::PointSource<double>>(terms));
      for (int i = 0; i < N; ++i) out[std::size_t(2 * N * c + i)] = r.weight[i], out[std::size_t(2 * N * c + N + i)] = r.weighted_node[i];
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}

template <int N>
void batched(benchmark::State& state, bool wide, bool with_condition) {
  const auto in = make_cells<N>(wide);
  std::vector<std::vector<double>> a(N, std::vector<double>(cells)), b(N, std::vector<double>(cells));
  std::vector<dqmom::SourceStatus> status(cells);
  std::vector<double> condition(with_condition ? cells : 0);
  dqmom::SourceBatch<double, N> batch;
  for (int i = 0; i < N; ++i) {
    batch.nodes[i] = in.nodes[i];
    batch.weights[i] = in.weights[i];
    batch.weight_sources[i] = a[i];
    batch.weighted_node_sources[i] = b[i];
  }
  for (int k = 0; k < 2 * N; ++k) batch.moment_sources[k] = in.s[k];
  batch.status = status;
  batch.condition = condition;
  for (auto _ : state) {
    dqmom::solve_batched(batch);
    benchmark::DoNotOptimize(a[0].data());
    benchmark::ClobberMemory();
  }
}

template <int N>
void register_all() {
  for (const bool wide : {false, true}) {
    const std::string row = (wide ? "wide N=" : "narrow N=") + std::to_string(N);
    benchmark::RegisterBenchmark(("baseline/" + row).c_str(), [wide](benchmark::State& s) { baseline<N>(s, wide); });
    benchmark::RegisterBenchmark(("system/" + row).c_str(), [wide](benchmark::State& s) { system_solve<N>(s, wide); });
    benchmark::RegisterBenchmark(("growth/" + row).c_str(), [wide](benchmark::State& s) { growth<N>(s, wide); });
    benchmark::RegisterBenchmark(("batched/" + row).c_str(), [wide](benchmark::State& s) { batched<N>(s, wide, false); });
    benchmark::RegisterBenchmark(("batched_cond/" + row).c_str(),
                                 [wide](benchmark::State& s) { batched<N>(s, wide, true); });
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  register_all<2>();
  register_all<3>();
  register_all<4>();
  register_all<5>();
  register_all<8>();
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::vector<std::string> rows;
  for (const char* kind : {"narrow", "wide"})
    for (int n : {2, 3, 4, 5, 8}) rows.push_back(std::string(kind) + " N=" + std::to_string(n));
  reporter.print_table("cells", rows, {"baseline", "system", "growth", "batched", "batched_cond"},
                       [](const std::string& row) { return "baseline/" + row; },
                       "the dense PartialPivLU baseline at the same N");
  benchmark::Shutdown();
}
