// Seed 000 (Mazzei, PhD thesis, UCL 2008), Tables 4.5 and 4.6: fifteen Geldart A powders
// (Xie & Geldart 1995, powders 1–10; Lettieri 1999 and Lettieri et al. 2001, powders 11–15)
// and their minimum bubbling voidage, measured and predicted by the Foscolo–Gibilaro,
// Jean–Fan and Mazzei–Lettieri stability criteria. Used by examples/minimum_bubbling_table_4_6.cpp.
#pragma once

#include <array>
#include <cmath>

#include "fluidbed/properties.hpp"

namespace seed000 {

struct Powder {
  int number;
  const char* material;
  fluidbed::Particles<double> particles;
  bool nitrogen;  // fluidized by N₂ (powders 11–15) rather than air
};

// Table 4.5 (sizes and densities; F₄₅, c.v. and the Geldart group omitted).
inline constexpr std::array<Powder, 15> table_4_5{{
    {1, "FCC", {1210.0, 137e-6}, false},      {2, "FCC", {1220.0, 130e-6}, false},
    {3, "FCC", {1230.0, 115e-6}, false},      {4, "FCC", {1240.0, 110e-6}, false},
    {5, "FCC", {1260.0, 94e-6}, false},       {6, "FCC", {1300.0, 71e-6}, false},
    {7, "FCC", {1310.0, 68e-6}, false},       {8, "FCC", {1310.0, 63e-6}, false},
    {9, "FCC", {1350.0, 47e-6}, false},       {10, "FCC", {1420.0, 26e-6}, false},
    {11, "Silica", {880.0, 109e-6}, true},    {12, "FCC", {1420.0, 71e-6}, true},
    {13, "Ballotini", {2550.0, 62e-6}, true}, {14, "FCC", {1420.0, 57e-6}, true},
    {15, "FCC", {1420.0, 49e-6}, true},
}};

struct BubblingRow {
  int powder;
  double temperature;  // °C
  double experiment, foscolo_gibilaro, jean_fan, mazzei_lettieri;  // ε_mb
};

// Table 4.6 as printed.
inline constexpr std::array<BubblingRow, 24> table_4_6{{
    {1, 20, 0.418, 0.359, 0.421, 0.401},   {2, 20, 0.441, 0.369, 0.431, 0.413},
    {3, 20, 0.449, 0.397, 0.456, 0.440},   {4, 20, 0.454, 0.406, 0.465, 0.450},
    {5, 20, 0.481, 0.440, 0.497, 0.485},   {6, 20, 0.482, 0.503, 0.556, 0.549},
    {7, 20, 0.495, 0.512, 0.565, 0.559},   {8, 20, 0.539, 0.532, 0.583, 0.578},
    {9, 20, 0.581, 0.606, 0.654, 0.652},   {10, 20, 0.646, 0.855, 0.896, 0.902},
    {11, 20, 0.448, 0.456, 0.513, 0.500},  {12, 20, 0.553, 0.483, 0.536, 0.529},
    {13, 20, 0.514, 0.430, 0.485, 0.477},  {14, 20, 0.583, 0.537, 0.588, 0.584},
    {15, 20, 0.542, 0.578, 0.626, 0.624},  {12, 100, 0.579, 0.512, 0.563, 0.559},
    {12, 200, 0.593, 0.543, 0.592, 0.590}, {12, 300, 0.595, 0.568, 0.616, 0.615},
    {12, 400, 0.607, 0.588, 0.635, 0.635}, {12, 500, 0.608, 0.609, 0.655, 0.656},
    {12, 600, 0.611, 0.629, 0.674, 0.675}, {13, 100, 0.509, 0.452, 0.505, 0.500},
    {13, 200, 0.507, 0.480, 0.532, 0.529}, {13, 300, 0.563, 0.503, 0.553, 0.551},
}};

// The gas. The thesis does not print its properties; these reproduce the 20 °C rows of
// Table 4.6 within 0.0012 (examples/minimum_bubbling_table_4_6 prints them): air ρ = 1.205 kg/m³, μ = 1.81e-5 Pa s for powders 1–10 and for 13
// (with N₂ powder 13 comes out 0.004–0.005 low), N₂ ρ = 1.165, μ = 1.76e-5 at 20 °C for
// 11, 12, 14, 15, and above 20 °C N₂ as an ideal gas at 101325 Pa with Sutherland's
// viscosity (μ₀ = 1.663e-5 Pa s at 273.15 K, S = 107 K), which matches 100 °C and drifts low
// above (by −0.022 at 600 °C): the thesis's high-temperature properties are unknown.
inline fluidbed::Fluid<double> gas_of(const Powder& powder, double temperature_celsius) {
  if (!powder.nitrogen || powder.number == 13) {
    if (temperature_celsius == 20) return {1.205, 1.81e-5};
  } else if (temperature_celsius == 20) {
    return {1.165, 1.76e-5};
  }
  const double t = temperature_celsius + 273.15;
  const double density = 101325.0 * 0.0280134 / (8.314462618 * t);
  const double viscosity = 1.663e-5 * std::pow(t / 273.15, 1.5) * (273.15 + 107.0) / (t + 107.0);
  return {density, viscosity};
}

}  // namespace seed000
