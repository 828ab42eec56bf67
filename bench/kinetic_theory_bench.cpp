// Cost of the kinetic-theory closures per cell, ns per cell and the ratio to the Wen–Yu
// drag law measured in the same run (the cheapest closure a two-fluid code calls per cell).
//
//   values/<set>       ConstitutiveSet: g0, p_s, μ_s, λ_s, κ_s, γ (one g0 evaluation)
//   derivatives/<set>  the same with ∂/∂φ and ∂/∂Θ of each (with_derivatives, one Dual pass)
//   full/<set>         derivatives plus the frictional pressure and viscosity
//                      (Johnson–Jackson + Schaeffer, with ∂/∂φ), the gas sink −3βΘ and
//                      the algebraic granular temperature, with β from the Wen–Yu drag:
//                      everything a cell needs
//   drag/WenYu1966     the baseline
//   g0/<name>          every radial distribution of the registry RadialDistributions, with
//                      dg0/dφ (g0.with_derivatives)
//
// Sets: Gidaspow (Ogawa g0, φ_max 0.63, Lun pressure, Gidaspow μ and κ), Fluent (seed 001's
// choice: Ogawa g0, Syamlal μ and κ), HrenyaSinclair (Carnahan–Starling g0).
// 4096 cells with φ from 10⁻⁴ to 0.62 and Θ from 10⁻⁶ to 0.1 m² s⁻².
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "fluidbed/drag/wen_yu.hpp"
#include "fluidbed/kinetic_theory.hpp"
#include "ratio_reporter.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

namespace {

constexpr int cells = 4096;
const Fluid<double> air{1.2, 1.8e-5};
const GranularMaterial<double> glass{5e-4, 2500.0, 0.9};

struct Cell {
  double solid_fraction, granular_temperature, slip;
  StrainRate<double> rate;
};

std::vector<Cell> make_cells() {
  std::vector<Cell> out(cells);
  for (int i = 0; i < cells; ++i) {
    const double u = ((i * 37) % cells + 0.5) / cells, v = ((i * 101) % cells + 0.5) / cells,
                 w = ((i * 211) % cells + 0.5) / cells;
    out[i] = {1e-4 + 0.62 * u, 1e-6 * std::pow(1e5, v), 1e-3 * std::pow(1e3, w), {2.0 * (w - 0.5), 10.0 * v}};
  }
  return out;
}

const std::vector<Cell> field = make_cells();

// Runs `per_cell(cell)` (a double to accumulate) over the field once per iteration.
template <class PerCell>
void over_cells(benchmark::State& run, const PerCell& per_cell) {
  for (auto _ : run) {
    double sum = 0;
    for (const Cell& c : field) sum += per_cell(c);
    benchmark::DoNotOptimize(sum);
  }
  run.SetItemsProcessed(run.iterations() * cells);
}

const drag::ConstantExponentDrag wen_yu = drag::ConstantExponentDrag::wen_yu_1966();

void drag_baseline(benchmark::State& run) {
  over_cells(run,
             [](const Cell& c) { return wen_yu.native_beta(1.0 - c.solid_fraction, c.slip, air, glass.diameter); });
}

template <class Set>
void values(benchmark::State& run, const Set& set) {
  over_cells(run, [&](const Cell& c) {
    const auto r = set(c.solid_fraction, c.granular_temperature, glass);
    return r.pressure + r.shear_viscosity + r.bulk_viscosity + r.conductivity + r.dissipation;
  });
}

template <class Set>
double sum_of_derivatives(const Set& set, const Cell& c) {
  const auto r = set.with_derivatives(c.solid_fraction, c.granular_temperature, glass);
  return r.pressure.d_solid_fraction + r.shear_viscosity.d_granular_temperature + r.conductivity.value +
         r.dissipation.d_granular_temperature + r.bulk_viscosity.d_solid_fraction;
}

template <class Set>
void derivatives(benchmark::State& run, const Set& set) {
  over_cells(run, [&](const Cell& c) { return sum_of_derivatives(set, c); });
}

template <class Set>
void full(benchmark::State& run, const Set& set) {
  using D1 = Dual<double, 1>;
  const JohnsonJacksonPressure frictional_pressure{0.5, 0.63};
  const SchaefferViscosity frictional_viscosity{28.5 * std::numbers::pi / 180.0};
  over_cells(run, [&](const Cell& c) {
    const D1 p_f = frictional_pressure(D1::variable(c.solid_fraction, 0));
    const D1 mu_f = frictional_viscosity(p_f, StrainRate<D1>{D1(c.rate.divergence), D1(c.rate.deviatoric_contraction)});
    const double beta = wen_yu.native_beta(1.0 - c.solid_fraction, c.slip, air, glass.diameter);
    return sum_of_derivatives(set, c) + p_f.derivative[0] + mu_f.value + gas_damping(beta, c.granular_temperature) +
           set.algebraic_granular_temperature(c.solid_fraction, glass, c.rate, beta);
  });
}

template <class Set>
void register_set(const std::string& name, Set set) {
  benchmark::RegisterBenchmark(("values/" + name).c_str(), [set](benchmark::State& s) { values(s, set); });
  benchmark::RegisterBenchmark(("derivatives/" + name).c_str(), [set](benchmark::State& s) { derivatives(s, set); });
  benchmark::RegisterBenchmark(("full/" + name).c_str(), [set](benchmark::State& s) { full(s, set); });
}

// Every registered radial distribution, g0 with its slope.
void register_radial_distributions() {
  std::apply(
      [](const auto&... rdf) {
        (benchmark::RegisterBenchmark(("g0/" + std::string(rdf.name())).c_str(),
                                      [rdf](benchmark::State& s) {
                                        over_cells(s, [&](const Cell& c) {
                                          const auto g = rdf.with_derivatives(c.solid_fraction);
                                          return g.value + g.d_solid_fraction;
                                        });
                                      }),
         ...);
      },
      RadialDistributions::instances());
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("drag/WenYu1966", drag_baseline);
  register_set("Gidaspow", ConstitutiveSet{Ogawa{0.63}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}});
  register_set("Fluent", ConstitutiveSet{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{}, SyamlalConductivity{}});
  register_set("HrenyaSinclair", ConstitutiveSet{CarnahanStarling{}, LunPressure{}, HrenyaSinclairViscosity(0.1),
                                                 HrenyaSinclairConductivity(0.1)});
  register_radial_distributions();
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_table(
      "KTGF set", {"Gidaspow", "Fluent", "HrenyaSinclair"}, {"values", "derivatives", "full"},
      [](const std::string&) { return std::string("drag/WenYu1966"); }, "the Wen-Yu drag (drag/WenYu1966)");
  benchmark::Shutdown();
}
