// Cost of the elastic force per cell relative to the drag it is built on, ns per cell and
// the ratio to that drag measured in the same run.
//
//   drag/<law>          the 3-D drag force density β (u_f − v_p) of the law
//   drag_elastic/<law>  the same plus the elastic force of eq. 3.116 from a voidage gradient:
//                       Mazzei–Lettieri with H(ε, Re*) from the same solve for Re*
//                       (mazzei_lettieri_drag_and_sensitivity), Jean–Fan with H = −4.8/ε on
//                       the Wen–Yu drag, its natural partner (both ε^−4.8 at low Re)
//
// 4096 cells spanning dense to dilute beds and creeping to inertial slip, in random
// directions, with random voidage gradients.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "fluidbed/drag/wen_yu.hpp"
#include "fluidbed/drag/mazzei_lettieri.hpp"
#include "fluidbed/elastic/elastic_modulus.hpp"
#include "ratio_reporter.hpp"

using namespace fluidbed;

namespace {

constexpr int cells = 4096;
const Fluid<double> air{1.2, 1.8e-5};
constexpr double diameter = 5e-4;

struct Cell {
  double voidage;
  Vector3<double> slip;      // u_f − v_p [m/s]
  Vector3<double> gradient;  // ∇ε [1/m]
};

std::vector<Cell> make_cells() {
  std::vector<Cell> out(cells);
  for (int i = 0; i < cells; ++i) {
    const double u = ((i * 37) % cells + 0.5) / cells, v = ((i * 101) % cells + 0.5) / cells,
                 w = ((i * 211) % cells + 0.5) / cells;
    const double speed = 1e-4 * std::pow(1e4, v);  // 1e-4 .. 1 m/s
    const double polar = 3.0 * w, azimuth = 6.28 * u;
    const Vector3<double> direction{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                                    std::cos(polar)};
    out[i] = {0.38 + 0.6 * u, scaled(speed, direction), {20.0 * (v - 0.5), 10.0 * (w - 0.3), 50.0 * (u - 0.6)}};
  }
  return out;
}

const std::vector<Cell> field = make_cells();

double magnitude(const Vector3<double>& a) { return std::sqrt(dot(a, a)); }

template <class Law>
void drag_only(benchmark::State& run, Law law) {
  for (auto _ : run) {
    double sum = 0;
    for (const Cell& c : field) {
      const double beta = law.native_beta(c.voidage, magnitude(c.slip), air, diameter);
      const Vector3<double> f = scaled(beta, c.slip);
      sum += f[0] + f[1] + f[2];
    }
    benchmark::DoNotOptimize(sum);
  }
  run.SetItemsProcessed(run.iterations() * cells);
}

void mazzei_lettieri_with_elastic(benchmark::State& run) {
  for (auto _ : run) {
    double sum = 0;
    for (const Cell& c : field) {
      const auto d = elastic::mazzei_lettieri_drag_and_sensitivity(c.voidage, magnitude(c.slip), air, diameter);
      const Vector3<double> f = scaled(d.beta, c.slip);
      const Vector3<double> e = elastic::elastic_force(f, c.gradient, d.sensitivity, diameter);
      sum += f[0] + f[1] + f[2] + e[0] + e[1] + e[2];
    }
    benchmark::DoNotOptimize(sum);
  }
  run.SetItemsProcessed(run.iterations() * cells);
}

void wen_yu_with_jean_fan(benchmark::State& run) {
  const drag::ConstantExponentDrag law = drag::ConstantExponentDrag::wen_yu_1966();
  const elastic::JeanFanModulus jean_fan{};  // H = −4.8/ε, whatever Re*
  for (auto _ : run) {
    double sum = 0;
    for (const Cell& c : field) {
      const double beta = law.native_beta(c.voidage, magnitude(c.slip), air, diameter);
      const Vector3<double> f = scaled(beta, c.slip);
      const Vector3<double> e =
          elastic::elastic_force(f, c.gradient, elastic::voidage_sensitivity(jean_fan, c.voidage, 0.0), diameter);
      sum += f[0] + f[1] + f[2] + e[0] + e[1] + e[2];
    }
    benchmark::DoNotOptimize(sum);
  }
  run.SetItemsProcessed(run.iterations() * cells);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("drag/MazzeiLettieri", [](benchmark::State& s) { drag_only(s, drag::MazzeiLettieri{}); });
  benchmark::RegisterBenchmark("drag_elastic/MazzeiLettieri", mazzei_lettieri_with_elastic);
  benchmark::RegisterBenchmark("drag/WenYu1966",
                               [](benchmark::State& s) { drag_only(s, drag::ConstantExponentDrag::wen_yu_1966()); });
  benchmark::RegisterBenchmark("drag_elastic/WenYu1966", wen_yu_with_jean_fan);
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_table(
      "drag law", {"MazzeiLettieri", "WenYu1966"}, {"drag", "drag_elastic"},
      [](const std::string& row) { return "drag/" + row; }, "the drag alone (drag/<law>)");
  benchmark::Shutdown();
}
