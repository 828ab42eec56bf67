// Cost of one drag evaluation per cell, for every law of the family, with and without
// derivatives, reported in ns per evaluation and as a ratio to Wen–Yu measured in the
// same run (the ratio is what carries across machines).
//
// Each benchmark sweeps a fixed batch of cell states spanning dense to dilute beds and
// creeping to inertial slip, so that branchy laws pay for their branches as in a CFD
// field. Statically dispatched (the law's type is known inside the loop), as a host that
// picks its law at compile time would call it.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "fluidbed/drag/any_drag_law.hpp"
#include "ratio_reporter.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;

namespace {

constexpr int cells = 4096;

std::vector<DragState<double>> cell_states() {
  std::vector<DragState<double>> states;
  states.reserve(cells);
  for (int i = 0; i < cells; ++i) {
    const double voidage = 0.38 + 0.6 * ((i * 37) % cells) / double(cells);
    const double slip = 1e-4 * std::pow(1e4, ((i * 101) % cells) / double(cells));  // 1e-4 .. 1 m/s
    states.push_back({voidage, slip, {1.2, 1.8e-5}, 5e-4});
  }
  return states;
}

const std::vector<DragState<double>> states = cell_states();

template <class Law>
void value(benchmark::State& run, Law law) {
  for (auto _ : run) {
    double sum = 0;
    for (const auto& s : states) sum += law(s).pressure_gradient();
    benchmark::DoNotOptimize(sum);
  }
  run.SetItemsProcessed(run.iterations() * cells);
}

template <class Law>
void with_derivatives(benchmark::State& run, Law law) {
  for (auto _ : run) {
    double sum = 0;
    for (const auto& s : states) {
      const auto d = law.with_derivatives(s).pressure_gradient();
      sum += d.value + d.d_voidage + d.d_slip;
    }
    benchmark::DoNotOptimize(sum);
  }
  run.SetItemsProcessed(run.iterations() * cells);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> laws;
  for (const AnyDragLaw& law : all_drag_laws)
    std::visit(
        [&laws](const auto& l) {
          const std::string name(l.name());
          laws.push_back(name);
          benchmark::RegisterBenchmark(("value/" + name).c_str(), [l](benchmark::State& s) { value(s, l); });
          benchmark::RegisterBenchmark(("with_derivatives/" + name).c_str(),
                                       [l](benchmark::State& s) { with_derivatives(s, l); });
        },
        law);
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_table(
      "law", laws, {"value", "with_derivatives"}, [](const std::string&) { return std::string("value/WenYu1966"); },
      "value/WenYu1966");
  benchmark::Shutdown();
}
