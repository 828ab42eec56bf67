// Cost of crossing into the C interface: a drag law over a field of cells (structure of arrays,
// as a host stores it) through fluidbed_drag, against the C++ loop a host would write over the
// same arrays with the same checked calls, in the same run; per cell, and as a ratio. A million
// cells spread from dense to dilute beds and from creeping to inertial slip. (The Python
// package's cost against the same C interface is bench/bindings_python.py.)
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "fluidbed/drag.hpp"
#include "fluidbed_c.h"
#include "ratio_reporter.hpp"

using namespace fluidbed;

namespace {

constexpr int cells = 1 << 20;

struct Field {
  std::vector<double> voidage, slip, density, viscosity, diameter;
};

Field make_field() {
  Field f;
  for (int i = 0; i < cells; ++i) {
    const double u = ((i * 7919L) % cells) / double(cells), v = ((i * 104729L) % cells) / double(cells);
    f.voidage.push_back(0.36 + 0.639 * u);
    f.slip.push_back(1e-5 * std::pow(1e6, v));  // 1e-5 .. 10 m/s
    f.density.push_back(1.2);
    f.viscosity.push_back(1.8e-5);
    f.diameter.push_back(3e-4);
  }
  return f;
}

const Field field = make_field();

// The C++ loop: the law's checked call per cell, writing β in the pressure-gradient convention.
void cpp_loop(benchmark::State& run, const std::string& name) {
  const drag::DragLaws::Variant law = drag::DragLaws::make(name);
  std::vector<double> beta(cells);
  for (auto _ : run) {
    std::visit(
        [&](const auto& l) {
          for (int i = 0; i < cells; ++i)
            beta[i] = l.checked(drag::DragState<double>{field.voidage[i], field.slip[i],
                                                        {field.density[i], field.viscosity[i]}, field.diameter[i]})
                          .pressure_gradient();
        },
        law);
    benchmark::DoNotOptimize(beta.data());
  }
}

void c_interface(benchmark::State& run, const std::string& name) {
  fluidbed_closure* law = nullptr;
  fluidbed_closure_create(name.c_str(), &law, nullptr);
  std::vector<double> beta(cells);
  for (auto _ : run) {
    if (fluidbed_drag(law, FLUIDBED_BUOYANCY_PRESSURE_GRADIENT, cells, field.voidage.data(), field.slip.data(),
                      field.density.data(), field.viscosity.data(), field.diameter.data(), beta.data(), nullptr,
                      nullptr, nullptr, nullptr) != FLUIDBED_OK)
      run.SkipWithError("fluidbed_drag failed");
    benchmark::DoNotOptimize(beta.data());
  }
  fluidbed_closure_destroy(law);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> laws{"WenYu1966", "MazzeiLettieri", "Beetstra"};
  for (const std::string& law : laws) {
    benchmark::RegisterBenchmark(("cpp_loop/" + law).c_str(), [law](benchmark::State& s) { cpp_loop(s, law); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("c_interface/" + law).c_str(), [law](benchmark::State& s) { c_interface(s, law); })
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_table(
      "law", laws, {"cpp_loop", "c_interface"}, [](const std::string& law) { return "cpp_loop/" + law; },
      "the C++ loop over the same arrays");
}
