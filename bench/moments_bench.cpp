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
//   wheeler_ql     invert<N>(): Wheeler + closed form (n <= 2) or Golub–Welsch QL
//   pd_ql          invert<N>() with product-difference
//   wheeler_eigen  invert_eigen<N>(): Wheeler + Eigen's tridiagonal solver
//   batched        invert_batched() on structure-of-arrays fields
//
// Every path reads the same 4096 distinct cells and writes every node and weight. The cells
// are lognormal number distributions in SI units (median 20–500 µm, σ_ln 0.15–0.6, number
// density 1e9–1e12 m⁻³), all realizable with N nodes (checked at start-up).
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

// The moments of cell c: m_k = n exp(k μ + k² σ²/2), the parameters spread over their ranges
// by coprime strides so that no two cells coincide.
template <int N>
std::vector<std::array<double, 2 * N>> cell_moments() {
  std::vector<std::array<double, 2 * N>> out(cells);
  for (int c = 0; c < cells; ++c) {
    const double u = ((c * 37) % cells + 0.5) / cells, v = ((c * 101) % cells + 0.5) / cells,
                 w = ((c * 211) % cells + 0.5) / cells;
    const double median = 20e-6 * std::pow(25.0, u), sigma = 0.15 + 0.45 * v, density = 1e9 * std::pow(1e3, w);
    for (int k = 0; k < 2 * N; ++k)
      out[c][k] = density * std::exp(k * std::log(median) + 0.5 * k * k * sigma * sigma);
  }
  return out;
}

// The same cells as fields: moment k of cell c at fields[k][c].
template <int N>
std::vector<std::vector<double>> cell_fields(const std::vector<std::array<double, 2 * N>>& m) {
  std::vector<std::vector<double>> fields(2 * N, std::vector<double>(cells));
  for (int k = 0; k < 2 * N; ++k)
    for (int c = 0; c < cells; ++c) fields[k][c] = m[c][k];
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

template <int N>
struct Fixture {
  std::vector<std::array<double, 2 * N>> moments = cell_moments<N>();
  std::vector<std::vector<double>> fields = cell_fields<N>(moments);
  std::vector<double> nodes = std::vector<double>(std::size_t(N) * cells);  // per-cell paths: cell-major
  std::vector<double> weights = std::vector<double>(std::size_t(N) * cells);
  std::vector<int> sizes = std::vector<int>(cells);
  std::vector<InversionStatus> status = std::vector<InversionStatus>(cells);

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

  void batched(benchmark::State& state) {
    MomentBatch<double, N> in;
    for (int k = 0; k < 2 * N; ++k) in.moments[k] = fields[k];
    QuadratureBatch<double, N> out;
    for (int i = 0; i < N; ++i) {
      out.nodes[i] = std::span<double>(nodes).subspan(std::size_t(i) * cells, cells);  // node-major: nodes[i][c]
      out.weights[i] = std::span<double>(weights).subspan(std::size_t(i) * cells, cells);
    }
    out.sizes = sizes;
    out.status = status;
    if (!invert_batched(in, out)) state.SkipWithError("invert_batched: arrays of different lengths");
    for (auto _ : state) {
      benchmark::DoNotOptimize(invert_batched(in, out));
      benchmark::DoNotOptimize(nodes.data());
      benchmark::DoNotOptimize(weights.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * cells);
  }

  // The cells must all be realizable with N nodes, else the paths would do different work.
  int unrealizable() const {
    int count = 0;
    for (const auto& m : moments) count += invert<N>(m).status != InversionStatus::ok;
    return count;
  }
};

template <int N>
void register_benchmarks() {
  static Fixture<N> f;
  if (const int bad = f.unrealizable(); bad > 0)
    std::printf("warning: %d of the N = %d cells are not realizable with %d nodes\n", bad, N, N);
  const std::string n = std::to_string(N);
  benchmark::RegisterBenchmark(("baseline/" + n).c_str(), [](benchmark::State& s) { f.baseline(s); });
  benchmark::RegisterBenchmark(("wheeler_ql/" + n).c_str(), [](benchmark::State& s) {
    f.per_cell(s, [](const std::array<double, 2 * N>& m) { return invert<N>(m); });
  });
  benchmark::RegisterBenchmark(("pd_ql/" + n).c_str(), [](benchmark::State& s) {
    f.per_cell(s, [](const std::array<double, 2 * N>& m) {
      return invert<N>(m, {.algorithm = RecurrenceAlgorithm::product_difference});
    });
  });
  benchmark::RegisterBenchmark(("wheeler_eigen/" + n).c_str(), [](benchmark::State& s) {
    f.per_cell(s, [](const std::array<double, 2 * N>& m) { return invert_eigen<N>(m); });
  });
  benchmark::RegisterBenchmark(("batched/" + n).c_str(), [](benchmark::State& s) { f.batched(s); });
}

template <int... N>
void register_all(std::integer_sequence<int, N...>) {
  (register_benchmarks<N + 1>(), ...);
}

}  // namespace

int main(int argc, char** argv) {
  register_all(std::make_integer_sequence<int, max_nodes>{});
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::vector<std::string> rows;
  for (int n = 1; n <= max_nodes; ++n) rows.push_back(std::to_string(n));
  reporter.print_table(
      "N (nodes)", rows, {"baseline", "wheeler_ql", "pd_ql", "wheeler_eigen", "batched"},
      [](const std::string& n) { return "baseline/" + n; }, "baseline/N");
  benchmark::Shutdown();
}
