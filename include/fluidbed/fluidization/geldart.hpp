// fluidbed — Geldart's classification of powders by how they fluidize in a gas.
//
// Geldart, D. (1973), "Types of gas fluidization", Powder Technol. 7, 285–292,
// doi:10.1016/0032-5910(73)80037-3; the groups as seed 001 §2.3 describes them:
//   C  cohesive, very fine: channels or lifts as a plug (flour, starch);
//   A  aeratable: the bed expands homogeneously between u_mf and the minimum bubbling
//      velocity u_mb > u_mf; small bubbles of a maximum size (FCC catalyst);
//   B  sand-like: bubbles from u_mf on, growing without a clear maximum;
//   D  spoutable, large or dense: slow bubbles, spouting (gravel, coffee beans).
// Seed 001 states only ranges (A: ρ_p <= 1400 kg m⁻³; B: 1400 <= ρ_p <= 4000 kg m⁻³ and
// 40 <= d <= 500 µm) and its diagram (Fig. 3) is missing; the groups are regions of the
// (ρ_p − ρ_g, d) plane, bounded by lines, and those are used here.
#pragma once

#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/constants.hpp"
#include "../core/domain.hpp"
#include "../core/errors.hpp"

namespace fluidbed::fluidization {

enum class GeldartGroup { C, A, B, D };

constexpr std::string_view name(GeldartGroup group) {
  switch (group) {
    case GeldartGroup::C:
      return "C";
    case GeldartGroup::A:
      return "A";
    case GeldartGroup::B:
      return "B";
    case GeldartGroup::D:
      return "D";
  }
  return "";
}

// The boundaries, in SI units, with Δρ = ρ_p − ρ_g and d the mean (surface–volume, Sauter)
// diameter:
//   C/A  d = 30 µm. Geldart (1973) draws this boundary but gives no formula for it; on his
//        chart it lies between about 20 and 30 µm over the densities of common powders (seed
//        001 gives no number). A line, not a criterion: cohesion also depends on humidity,
//        shape, charge and the fines content, so powders of 20–40 µm can fall either side.
//   A/B  Δρ d = 0.225 kg m⁻², Geldart's (1973) boundary, (ρ_p − ρ_g) d = 225 with ρ in g cm⁻³
//        and d in µm: where the minimum bubbling velocity meets u_mf (u_mb/u_mf = 1), from
//        his data in air. The data scatter about the line; ±20 % in d is this library's
//        reading of that scatter, not a number of the paper.
//   B/D  Δρ d² = 10⁻³ kg m⁻¹, Geldart's (1973) boundary, (ρ_p − ρ_g) d² = 10⁶ with ρ in g cm⁻³
//        and d in µm: where bubbles become slower than the interstitial gas (d ≈ 620 µm for
//        sand); a gradual transition rather than a sharp line.
// A powder exactly on a boundary belongs to the coarser group (C/A at 30 µm: A).
// Validity: air (or gases of like density and viscosity) near ambient conditions, Δρ from
// about 100 to 10⁴ kg m⁻³ (the chart's range); at elevated pressure or temperature the
// boundaries shift (the gas properties enter u_mf and u_mb), which these lines ignore. Below
// Δρ ≈ 50 kg m⁻³ (where the A/B and B/D lines cross, at d = 4.4 mm) the classification is an
// extrapolation of the chart.
struct GeldartBoundaries {
  template <class T>  // C/A: d [m]
  static constexpr T cohesive_diameter() {
    return FLUIDBED_DECIMAL(T, 30e-6);
  }
  template <class T>  // A/B: Δρ d [kg m⁻²]
  static constexpr T aeratable_density_diameter() {
    return FLUIDBED_DECIMAL(T, 0.225);
  }
  template <class T>  // B/D: Δρ d² [kg m⁻¹]
  static constexpr T spoutable_density_diameter_squared() {
    return FLUIDBED_DECIMAL(T, 1e-3);
  }
};

// The Geldart group of a powder of particle density ρ_p, mean diameter d in a gas of density
// ρ_g (boundaries and validity: GeldartBoundaries). Domain: d > 0, ρ_g > 0, ρ_p > ρ_g, all
// finite; with fluidbed::checked, std::domain_error naming the argument otherwise. Works in
// float, double, long double and Boost.Multiprecision (the boundaries as decimals in T).
template <class T, ErrorPolicy Policy = Unchecked>
constexpr GeldartGroup geldart_group(const T& particle_density, const T& gas_density, const T& diameter,
                                     Policy policy = {}) {
  check_domain(policy, "geldart_group",
               arguments(Argument<T>{"gas_density", gas_density, domains::positive<T>()},
                         Argument<T>{"particle_density", particle_density, domains::greater_than(gas_density),
                                     "must be finite and > gas_density: heavier-than-gas particles only"},
                         Argument<T>{"diameter", diameter, domains::positive<T>()}));
  const T excess_density = particle_density - gas_density;
  if (diameter < GeldartBoundaries::cohesive_diameter<T>()) return GeldartGroup::C;
  if (excess_density * diameter * diameter >= GeldartBoundaries::spoutable_density_diameter_squared<T>())
    return GeldartGroup::D;
  if (excess_density * diameter >= GeldartBoundaries::aeratable_density_diameter<T>()) return GeldartGroup::B;
  return GeldartGroup::A;
}

}  // namespace fluidbed::fluidization
