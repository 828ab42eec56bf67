// Cost of one drag evaluation per cell, for every law of the family, with and without
// derivatives, reported in ns per evaluation and as ratios measured in the same run (the
// ratios are what carry across machines): the value to Wen–Yu's value, and the value with
// derivatives to the same law's value.
//
// Each benchmark sweeps a fixed batch of cell states, so that branchy laws (and the
// iterative Re* of Mazzei–Lettieri) pay for their branches as in a CFD field, over two sets:
//   fluidized  air, d = 0.5 mm, ε 0.38–0.98, slip 1e-4–1 m/s (Re 1e-5–33): a gas-fluidized bed
//   wide       ε 0.36–0.999, Re 1e-9–1e7 from air and water, d 10 µm–10 mm and the slip that
//              gives the Re: every regime a host's field may reach
// in an order that looks random but is fixed (coprime strides through the ranges).
// Statically dispatched (the law's type is known inside the loop), as a host that picks its
// law at compile time would call it.
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

// The fraction (i · stride mod cells)/cells: a coprime stride visits every fraction once.
double spread(int i, int stride) { return ((i * stride) % cells) / double(cells); }

std::vector<DragState<double>> fluidized_states() {
  std::vector<DragState<double>> states;
  states.reserve(cells);
  for (int i = 0; i < cells; ++i) {
    const double voidage = 0.38 + 0.6 * spread(i, 37);
    const double slip = 1e-4 * std::pow(1e4, spread(i, 101));  // 1e-4 .. 1 m/s
    states.push_back({voidage, slip, {1.2, 1.8e-5}, 5e-4});
  }
  return states;
}

std::vector<DragState<double>> wide_states() {
  const Fluid<double> fluids[] = {{1.2, 1.8e-5}, {998.0, 1.0e-3}};  // air, water
  std::vector<DragState<double>> states;
  states.reserve(cells);
  for (int i = 0; i < cells; ++i) {
    const double voidage = 0.36 + 0.639 * spread(i, 37);
    const double reynolds = 1e-9 * std::pow(1e16, spread(i, 101));  // Re = ρ_f ε w d/μ_f, 1e-9 .. 1e7
    const double diameter = 1e-5 * std::pow(1e3, spread(i, 1009));   // 10 µm .. 10 mm
    const Fluid<double>& fluid = fluids[(i * 7 / 3) % 2];
    const double slip = reynolds * fluid.viscosity / (fluid.density * voidage * diameter);
    states.push_back({voidage, slip, fluid, diameter});
  }
  return states;
}

const std::vector<DragState<double>> fluidized = fluidized_states();
const std::vector<DragState<double>> wide = wide_states();

template <class Law>
void value(benchmark::State& run, Law law, const std::vector<DragState<double>>& states) {
  for (auto _ : run) {
    double sum = 0;
    for (const auto& s : states) sum += law(s).pressure_gradient();
    benchmark::DoNotOptimize(sum);
  }
  run.SetItemsProcessed(run.iterations() * cells);
}

template <class Law>
void with_derivatives(benchmark::State& run, Law law, const std::vector<DragState<double>>& states) {
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

struct StateSet {
  std::string prefix;  // "" for the fluidized set (the benchmarks' historical names), "wide/"
  const std::vector<DragState<double>>* states;
};

const StateSet state_sets[] = {{"", &fluidized}, {"wide/", &wide}};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> laws;
  for (const AnyDragLaw& law : all_drag_laws) laws.emplace_back(name_of(law));
  for (const StateSet& set : state_sets)
    for (const AnyDragLaw& law : all_drag_laws)
      std::visit(
          [&set](const auto& l) {
            const std::string name(l.name());
            const std::vector<DragState<double>>& states = *set.states;
            benchmark::RegisterBenchmark((set.prefix + "value/" + name).c_str(),
                                         [l, &states](benchmark::State& s) { value(s, l, states); });
            benchmark::RegisterBenchmark((set.prefix + "with_derivatives/" + name).c_str(),
                                         [l, &states](benchmark::State& s) { with_derivatives(s, l, states); });
          },
          law);
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (const StateSet& set : state_sets) {
    const std::string value_column = set.prefix + "value";
    std::printf("\n%s states\n", set.prefix.empty() ? "fluidized" : "wide");
    reporter.print_table(
        "law",
        laws,
        {{value_column, [&](const std::string&) { return value_column + "/WenYu1966"; }},
         {set.prefix + "with_derivatives", [&](const std::string& law) { return value_column + "/" + law; }}},
        "value/WenYu1966 (value) and to the law's own value (with_derivatives), on the same states");
  }
  benchmark::Shutdown();
}
