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
//   mixture-values/<N> UnequalTemperatureMixture (seed 004's h_ik, ModifiedMansoori 0.64) for N
//                      = 1…4 classes per cell: p_i, μ_ij, λ_ij, κ_ij, γ_i, β_ik, s_ik
//   mixture-derivatives/<N>  the same with ∂/∂α_m and ∂/∂Θ_m of each (one Dual<2N> pass)
// The mixture rows are compared with the one-class set of the same theory, LathouwersBellan
// (its g0 at φ_max 0.64, Lun pressure, Gidaspow μ and κ: what one class of the mixture reduces
// to), values with values and derivatives with derivatives.
//
// Sets: Gidaspow (Ogawa g0, φ_max 0.63, Lun pressure, Gidaspow μ and κ), Fluent (seed 001's
// choice: Ogawa g0, Syamlal μ and κ), HrenyaSinclair (Carnahan–Starling g0).
// 4096 cells with φ from 10⁻⁴ to 0.62 and Θ from 10⁻⁶ to 0.1 m² s⁻²; a mixture cell splits the
// cell's φ (up to 0.6) among its classes in unequal shares, with Θ_i spread over two decades
// around the cell's Θ, d_i from 100 to 800 µm and ρ_i from 900 to 7800 kg m⁻³.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
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

template <std::size_t N>
std::vector<GranularClassesState<double, N>> make_mixture_cells() {
  std::vector<GranularClassesState<double, N>> out(cells);
  for (int c = 0; c < cells; ++c) {
    const Cell& cell = field[c];
    auto& s = out[c];
    const auto weight = [c](std::size_t i) { return 1.0 + double((c * 13 + 7 * int(i)) % 5); };  // 1 … 5
    double weights = 0;
    for (std::size_t i = 0; i < N; ++i) weights += weight(i);
    for (std::size_t i = 0; i < N; ++i) {
      const double u = double((c * 29 + 11 * int(i)) % 97) / 96;
      s.fractions[i] = std::min(cell.solid_fraction, 0.6) * weight(i) / weights;
      s.temperatures[i] = cell.granular_temperature * std::pow(10.0, 2 * u - 1);
      s.diameters[i] = 100e-6 + 700e-6 * double(i + 1) / double(N + 1);
      s.densities[i] = 900.0 + 6900.0 * u;
    }
    s.restitution = 0.9;
  }
  return out;
}

template <std::size_t N>
void register_mixture() {
  const UnequalTemperatureMixture mixture;
  const auto states = std::make_shared<const std::vector<GranularClassesState<double, N>>>(make_mixture_cells<N>());
  const std::string classes = std::to_string(N);
  benchmark::RegisterBenchmark(("mixture-values/" + classes).c_str(), [=](benchmark::State& run) {
    for (auto _ : run) {
      double sum = 0;
      for (const auto& s : *states) {
        const auto r = mixture(s);
        sum += r.pressure[N - 1] + r.shear_viscosity[0][N - 1] + r.conductivity[N - 1][0] + r.dissipation[0] +
               r.drag[0][N - 1];
      }
      benchmark::DoNotOptimize(sum);
    }
    run.SetItemsProcessed(run.iterations() * cells);
  });
  benchmark::RegisterBenchmark(("mixture-derivatives/" + classes).c_str(), [=](benchmark::State& run) {
    for (auto _ : run) {
      double sum = 0;
      for (const auto& s : *states) {
        const auto r = mixture.with_derivatives(s);
        sum += r.pressure[N - 1].d_fractions[0] + r.shear_viscosity[0][N - 1].d_temperatures[N - 1] +
               r.conductivity[N - 1][0].value + r.dissipation[0].d_temperatures[0] + r.drag[0][N - 1].d_fractions[0];
      }
      benchmark::DoNotOptimize(sum);
    }
    run.SetItemsProcessed(run.iterations() * cells);
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
  register_set("LathouwersBellan",
               ConstitutiveSet{LathouwersBellan{0.64}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}});
  register_mixture<1>();
  register_mixture<2>();
  register_mixture<3>();
  register_mixture<4>();
  register_radial_distributions();
  benchmark::Initialize(&argc, argv);
  fluidbed::bench::RatioReporter reporter(cells);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_table(
      "KTGF set", {"Gidaspow", "Fluent", "HrenyaSinclair"}, {"values", "derivatives", "full"},
      [](const std::string&) { return std::string("drag/WenYu1966"); }, "the Wen-Yu drag (drag/WenYu1966)");
  const std::vector<std::string> class_counts{"1", "2", "3", "4"};
  reporter.print_table(
      "classes", class_counts, {"mixture-values"}, [](const std::string&) { return std::string("values/LathouwersBellan"); },
      "the one-class set values/LathouwersBellan");
  reporter.print_table(
      "classes", class_counts, {"mixture-derivatives"},
      [](const std::string&) { return std::string("derivatives/LathouwersBellan"); },
      "the one-class set derivatives/LathouwersBellan");
  benchmark::Shutdown();
}
