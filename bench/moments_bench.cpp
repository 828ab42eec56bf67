// Cost of one moment inversion (2N moments to an N-node Gauss rule) per cell, N = 1 … 8, for
// the library's paths and for a baseline written the way generic CFD codes do it; ns per
// cell and the ratio to that baseline at the same N, measured in the same run.
//
//   baseline       OpenQBMM / UIN style: per cell, the moments copied into a dynamic
//                  Eigen::VectorXd, Wheeler's table as a dense (n+1)×(2n+1) MatrixXd on the
//                  raw moments, the Jacobi matrix as a dense n×n MatrixXd, Eigen's dense
//                  SelfAdjointEigenSolver<MatrixXd> (Householder tridiagonalization, then QR
//                  accumulating every eigenvector), weights from row 0 of the eigenvectors
//                  (OpenQBMM's per-cell univariateMomentSet and its dense EigenMatrix, a
//                  JAMA/EISPACK tred2 + tql2 with every eigenvector; Uintah's CQMOM likewise
//                  solves a dense Jacobi matrix)
//   wheeler_ql     invert<N>(): Wheeler + closed form (n <= 2), three-node solver (n = 3) or
//                  Golub–Welsch QL
//   pd_ql          invert<N>() with product-difference
//   with_error     invert<N>() with the error estimate of the rule (estimate_error, accuracy.hpp)
//   wheeler_eigen  invert_eigen<N>(): Wheeler + Eigen's tridiagonal solver
//   batched        invert_batched() on structure-of-arrays fields
//   batched_with_error  the same with the error estimate (InversionOptions::estimate_error)
//   batched_float  the same in float (the moments rounded to float)
//   stream         the streaming limit of the batched path: read the 2N moment fields and write
//                  the N node and N weight fields (a copy), nothing computed
//
// Every path reads the same 4096 distinct cells and writes every node and weight. Two sets of
// cells in SI units (number density 1e9–1e12 m⁻³):
//   lognormal  log-normal number distributions, median 20–500 µm, σ_ln 0.15–0.6;
//   atoms      N atoms per cell, diameters log-uniform over 10 µm – 1 mm (σ_ln ≈ 1.3 per cell),
//              number fractions uniform over 0.05–1.05: the wide distributions of polydisperse
//              beds, where the nodes come close and the QL sweeps more.
// The count of cells that are not realizable with N nodes in double is printed at start-up (the
// paths then take the reduced rule; all are realizable in exact arithmetic).
#include <benchmark/benchmark.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fluidbed/moments/batched.hpp"
#include "fluidbed/moments/eigen_backend.hpp"
#include "fluidbed/moments/inversion.hpp"
#include "ratio_reporter.hpp"

using namespace fluidbed::moments;

namespace {

constexpr int cells = 4096;
constexpr int max_nodes = 8;

enum class Cells { lognormal, atoms };

const char* name(Cells set) { return set == Cells::lognormal ? "lognormal" : "atoms"; }

// A fraction in (0, 1) for cell c, spread by a coprime stride so that no two cells coincide.
double spread(int c, int stride) { return ((c * stride) % cells + 0.5) / cells; }

// The moments of cell c of a set (see the header comment): m_k = n exp(k μ + k² σ²/2) for the
// log-normal cells, Σ_i n_i d_i^k (in long double, then rounded) for the atoms.
template <int N>
std::vector<std::array<double, 2 * N>> cell_moments(Cells set) {
  std::vector<std::array<double, 2 * N>> out(cells);
  for (int c = 0; c < cells; ++c) {
    const double density = 1e9 * std::pow(1e3, spread(c, 211));
    if (set == Cells::lognormal) {
      const double median = 20e-6 * std::pow(25.0, spread(c, 37)), sigma = 0.15 + 0.45 * spread(c, 101);
      for (int k = 0; k < 2 * N; ++k)
        out[c][k] = density * std::exp(k * std::log(median) + 0.5 * k * k * sigma * sigma);
      continue;
    }
    long double sum[2 * N] = {};
    for (int i = 0; i < N; ++i) {
      const int atom = c * N + i;
      const long double size = 1e-5L * std::pow(100.0L, (long double)spread(atom % cells, 37 + 2 * i) );
      const long double number = density * (0.05L + spread((atom * 7 + 3) % cells, 101 + 2 * i));
      for (int k = 0; k < 2 * N; ++k) sum[k] += number * std::pow(size, (long double)k);
    }
    for (int k = 0; k < 2 * N; ++k) out[c][k] = double(sum[k]);
  }
  return out;
}

// The same cells as fields: moment k of cell c at fields[k][c].
template <class T, int N>
std::vector<std::vector<T>> cell_fields(const std::vector<std::array<double, 2 * N>>& m) {
  std::vector<std::vector<T>> fields(2 * N, std::vector<T>(cells));
  for (int k = 0; k < 2 * N; ++k)
    for (int c = 0; c < cells; ++c) fields[k][c] = T(m[c][k]);
  return fields;
}

// See the header comment. Stops at the first b_k <= 0, as such codes do.
int baseline_invert(const double* moments, int count, double* nodes, double* weights) {
  const Eigen::VectorXd m = Eigen::Map<const Eigen::VectorXd>(moments, count);
  const int n = int(m.size() / 2);
  Eigen::MatrixXd sigma = Eigen::MatrixXd::Zero(n + 1, 2 * n + 1);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(n), b = Eigen::VectorXd::Zero(n);
  for (int l = 0; l < 2 * n; ++l) sigma(1, l) = m(l);
  a(0) = m(1) / m(0);
  b(0) = m(0);
  int size = n;
  for (int k = 1; k < n; ++k) {
    for (int l = k; l < 2 * n - k; ++l)
      sigma(k + 1, l) = sigma(k, l + 1) - a(k - 1) * sigma(k, l) - b(k - 1) * sigma(k - 1, l);
    a(k) = sigma(k + 1, k + 1) / sigma(k + 1, k) - sigma(k, k) / sigma(k, k - 1);
    b(k) = sigma(k + 1, k) / sigma(k, k - 1);
    if (!(b(k) > 0)) {
      size = k;
      break;
    }
  }
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(size, size);
  for (int i = 0; i < size; ++i) {
    jacobi(i, i) = a(i);
    if (i + 1 < size) jacobi(i, i + 1) = jacobi(i + 1, i) = std::sqrt(b(i + 1));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
  const Eigen::VectorXd x = solver.eigenvalues();
  const Eigen::VectorXd w = m(0) * solver.eigenvectors().row(0).transpose().array().square();
  for (int i = 0; i < size; ++i) {
    nodes[i] = x(i);
    weights[i] = w(i);
  }
  return size;
}

// Output fields of a batch in T, node-major (nodes[i][c]).
template <class T, int N>
struct BatchFields {
  std::vector<std::vector<T>> moments;
  std::vector<T> nodes = std::vector<T>(std::size_t(N) * cells), weights = nodes;
  std::vector<int> sizes = std::vector<int>(cells);
  std::vector<InversionStatus> status = std::vector<InversionStatus>(cells);
  MomentBatch<T, N> in;
  QuadratureBatch<T, N> out;

  explicit BatchFields(const std::vector<std::array<double, 2 * N>>& m) : moments(cell_fields<T, N>(m)) {
    for (int k = 0; k < 2 * N; ++k) in.moments[k] = moments[k];
    for (int i = 0; i < N; ++i) {
      out.nodes[i] = std::span<T>(nodes).subspan(std::size_t(i) * cells, cells);
      out.weights[i] = std::span<T>(weights).subspan(std::size_t(i) * cells, cells);
    }
    out.sizes = sizes;
    out.status = status;
  }

  // invert_batched() with `options` (the default: none, the plain batched path).
  void batched(benchmark::State& state, const InversionOptions& options = {}) {
    if (!invert_batched(in, out, options)) state.SkipWithError("invert_batched: arrays of different lengths");
    for (auto _ : state) {
      benchmark::DoNotOptimize(invert_batched(in, out, options));
      benchmark::DoNotOptimize(nodes.data());
      benchmark::DoNotOptimize(weights.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * cells);
  }

  // The memory traffic of batched() alone.
  void stream(benchmark::State& state) {
    for (auto _ : state) {
      for (int i = 0; i < N; ++i) {
        const T* x = in.moments[i].data();
        const T* w = in.moments[N + i].data();
        T* nodes_i = out.nodes[i].data();
        T* weights_i = out.weights[i].data();
        for (int c = 0; c < cells; ++c) {
          nodes_i[c] = x[c];
          weights_i[c] = w[c];
        }
      }
      benchmark::DoNotOptimize(nodes.data());
      benchmark::DoNotOptimize(weights.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * cells);
  }
};

template <int N>
struct Fixture {
  explicit Fixture(Cells set) : moments(cell_moments<N>(set)), fields(moments), float_fields(moments) {}

  std::vector<std::array<double, 2 * N>> moments;
  BatchFields<double, N> fields;
  BatchFields<float, N> float_fields;
  std::vector<double> nodes = std::vector<double>(std::size_t(N) * cells);  // per-cell paths: cell-major
  std::vector<double> weights = std::vector<double>(std::size_t(N) * cells);

  template <class Invert>
  void per_cell(benchmark::State& state, Invert invert) {
    for (auto _ : state) {
      for (int c = 0; c < cells; ++c) {
        const InversionResult<double, N> r = invert(moments[c]);
        for (int i = 0; i < N; ++i) {
          nodes[std::size_t(c) * N + i] = r.quadrature.nodes[i];
          weights[std::size_t(c) * N + i] = r.quadrature.weights[i];
        }
      }
      benchmark::DoNotOptimize(nodes.data());
      benchmark::DoNotOptimize(weights.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * cells);
  }

  void baseline(benchmark::State& state) {
    for (auto _ : state) {
      for (int c = 0; c < cells; ++c)
        baseline_invert(moments[c].data(), 2 * N, &nodes[std::size_t(c) * N], &weights[std::size_t(c) * N]);
      benchmark::DoNotOptimize(nodes.data());
      benchmark::DoNotOptimize(weights.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * cells);
  }

  // Cells not realizable with N nodes in double (the paths then do different work).
  int unrealizable() const {
    int count = 0;
    for (const auto& m : moments) count += invert<N>(m).status != InversionStatus::ok;
    return count;
  }
};

template <int N>
void register_benchmarks(Cells set) {
  auto* f = new Fixture<N>(set);  // lives as long as the registered benchmarks
  const std::string row = std::string(name(set)) + "/" + std::to_string(N);
  if (const int bad = f->unrealizable(); bad > 0)
    std::printf("%s: %d of the %d cells are not realizable with %d nodes in double\n", row.c_str(), bad, cells, N);
  benchmark::RegisterBenchmark(("baseline/" + row).c_str(), [f](benchmark::State& s) { f->baseline(s); });
  benchmark::RegisterBenchmark(("wheeler_ql/" + row).c_str(), [f](benchmark::State& s) {
    f->per_cell(s, [](const std::array<double, 2 * N>& m) { return invert<N>(m); });
  });
  benchmark::RegisterBenchmark(("with_error/" + row).c_str(), [f](benchmark::State& s) {
    f->per_cell(s, [](const std::array<double, 2 * N>& m) { return invert<N>(m, {.estimate_error = true}); });
  });
  benchmark::RegisterBenchmark(("pd_ql/" + row).c_str(), [f](benchmark::State& s) {
    f->per_cell(s, [](const std::array<double, 2 * N>& m) {
      return invert<N>(m, {.algorithm = RecurrenceAlgorithm::product_difference});
    });
  });
  benchmark::RegisterBenchmark(("wheeler_eigen/" + row).c_str(), [f](benchmark::State& s) {
    f->per_cell(s, [](const std::array<double, 2 * N>& m) { return invert_eigen<N>(m); });
  });
  benchmark::RegisterBenchmark(("batched/" + row).c_str(), [f](benchmark::State& s) { f->fields.batched(s); });
  benchmark::RegisterBenchmark(("batched_with_error/" + row).c_str(),
                               [f](benchmark::State& s) { f->fields.batched(s, {.estimate_error = true}); });
  benchmark::RegisterBenchmark(("batched_float/" + row).c_str(),
                               [f](benchmark::State& s) { f->float_fields.batched(s); });
  benchmark::RegisterBenchmark(("stream/" + row).c_str(), [f](benchmark::State& s) { f->fields.stream(s); });
}

template <int... N>
void register_all(std::integer_sequence<int, N...>) {
  for (Cells set : {Cells::lognormal, Cells::atoms}) (register_benchmarks<N + 1>(set), ...);
}

}  // namespace

int main(int argc, char** argv) {
  register_all(std::make_integer_sequence<int, max_nodes>{});
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::vector<std::string> rows;
  for (Cells set : {Cells::lognormal, Cells::atoms})
    for (int n = 1; n <= max_nodes; ++n) rows.push_back(std::string(name(set)) + "/" + std::to_string(n));
  reporter.print_table(
      "cells/N (nodes)", rows, {"baseline", "wheeler_ql", "pd_ql", "wheeler_eigen", "batched", "stream"},
      [](const std::string& row) { return "baseline/" + row; }, "baseline/cells/N");
  reporter.print_table(
      "cells/N (nodes)", rows, {"wheeler_ql", "with_error"}, [](const std::string& row) { return "wheeler_ql/" + row; },
      "wheeler_ql/cells/N (the cost of the error estimate)");
  reporter.print_table(
      "cells/N (nodes)", rows, {"batched", "batched_with_error"},
      [](const std::string& row) { return "batched/" + row; }, "batched/cells/N (the cost of the error estimate)");
  reporter.print_table(
      "cells/N (nodes)", rows, {"batched", "batched_float"}, [](const std::string& row) { return "batched/" + row; },
      "the double batched/cells/N");
  benchmark::Shutdown();
}
