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
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "fluidbed/drag/any_drag_law.hpp"

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

// Collects ns per evaluation (the fastest repetition of each benchmark: the least
// disturbed by other load), then prints the ratio table.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration) {
        const double ns = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e9 / cells;
        const auto [it, inserted] = ns_per_evaluation_.try_emplace(r.run_name.function_name, ns);
        if (!inserted && ns < it->second) it->second = ns;
      }
  }
  void print_ratios(const std::string& baseline) const {
    const auto base = ns_per_evaluation_.find("value/" + baseline);
    if (base == ns_per_evaluation_.end()) return;
    std::printf("\n%-28s %14s %8s %20s %8s\n", "law", "value ns/cell", "ratio", "with derivatives ns", "ratio");
    for (const auto& [name, ns] : ns_per_evaluation_) {
      if (!name.starts_with("value/")) continue;
      const std::string law = name.substr(6);
      std::printf("%-28s %14.2f %8.2f", law.c_str(), ns, ns / base->second);
      const auto d = ns_per_evaluation_.find("with_derivatives/" + law);
      if (d != ns_per_evaluation_.end()) std::printf(" %20.2f %8.2f", d->second, d->second / base->second);
      std::printf("\n");
    }
    std::printf("(ns per cell evaluation, fastest repetition; ratios are to value/%s in this run)\n",
                baseline.c_str());
  }

 private:
  std::map<std::string, double> ns_per_evaluation_;
};

}  // namespace

int main(int argc, char** argv) {
  for (const AnyDragLaw& law : all_drag_laws)
    std::visit(
        [](const auto& l) {
          const std::string name(l.name());
          benchmark::RegisterBenchmark(("value/" + name).c_str(), [l](benchmark::State& s) { value(s, l); });
          benchmark::RegisterBenchmark(("with_derivatives/" + name).c_str(),
                                       [l](benchmark::State& s) { with_derivatives(s, l); });
        },
        law);
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios("WenYu1966");
  benchmark::Shutdown();
}
