// Test helper: the kinetic-theory closures by the names the mpmath tables in
// tests/reference/ use (ktgf_*.csv, scalar_types_reference.csv), evaluated for any scalar
// (float, double, long double, or a Dual of them).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "fluidbed/kinetic_theory.hpp"

namespace fluidbed::test {

using kinetic_theory::GranularMaterial;

// |a − b|/|b|, 0 when a == b (also for a = b = 0 or ±∞).
inline double relative_difference(double a, double b) {
  if (a == b) return 0;
  return std::abs(a - b) / std::max(std::abs(b), std::numeric_limits<double>::min());
}

// The one-class RDF `name` with packing parameter `max_packing` (ignored where fixed).
template <class S>
S radial_distribution(const std::string& name, const S& phi, double max_packing) {
  using namespace kinetic_theory;
  if (name == "carnahan_starling") return CarnahanStarling{}(phi);
  if (name == "percus_yevick") return PercusYevick{}(phi);
  if (name == "lun_savage") return LunSavage{max_packing}(phi);
  if (name == "sinclair_jackson") return SinclairJackson{max_packing}(phi);
  if (name == "ogawa") return Ogawa{max_packing}(phi);
  if (name == "gidaspow") return GidaspowRadialDistribution{max_packing}(phi);
  if (name == "ma_ahmadi") return MaAhmadi{}(phi);
  if (name == "lathouwers_bellan") return LathouwersBellan{max_packing}(phi);
  throw std::invalid_argument("no radial distribution " + name);
}

// The g0 of a constitutive row's variant "<author>:<rdf>": carnahan_starling, or ogawa
// with φ_max = 0.63 (tests/reference/README.md).
template <class S>
S row_radial_distribution(const std::string& rdf, const S& phi) {
  return radial_distribution(rdf, phi, 0.63);
}

// The names radial_distribution dispatches: every one-class form of the library.
inline constexpr std::array radial_distribution_names{"carnahan_starling", "percus_yevick", "lun_savage",
                                                      "sinclair_jackson",  "ogawa",         "gidaspow",
                                                      "ma_ahmadi",         "lathouwers_bellan"};

// The "function:author" names constitutive dispatches: every law(φ, Θ, g0, material) of the
// library (the kinetic and collisional parts of a transport coefficient are not listed).
inline constexpr std::array constitutive_names{
    "granular_pressure:lun",    "granular_pressure:syamlal_rogers_obrien", "granular_pressure:ma_ahmadi",
    "shear_viscosity:gidaspow", "shear_viscosity:syamlal",                "shear_viscosity:hrenya_sinclair",
    "bulk_viscosity:lun",       "conductivity:gidaspow",                  "conductivity:syamlal",
    "conductivity:hrenya_sinclair", "dissipation:lun"};

// Constitutive function `function` of author `author` (the part of the variant before
// ':'); `extra` is the Hrenya–Sinclair length L where it applies.
template <class S, class T>
S constitutive(const std::string& function, const std::string& author, const S& phi, const S& theta, const S& g0,
               const GranularMaterial<T>& m, double extra) {
  using namespace kinetic_theory;
  if (function == "granular_pressure") {
    if (author == "lun") return LunPressure{}(phi, theta, g0, m);
    if (author == "syamlal_rogers_obrien") return SyamlalRogersOBrienPressure{}(phi, theta, g0, m);
    if (author == "ma_ahmadi") return AhmadiMaPressure{}(phi, theta, g0, m);
  } else if (function == "shear_viscosity") {
    if (author == "gidaspow") return GidaspowViscosity{}(phi, theta, g0, m);
    if (author == "gidaspow_kinetic") return GidaspowViscosity{}.kinetic(phi, theta, g0, m);
    if (author == "gidaspow_collisional") return GidaspowViscosity{}.collisional(phi, theta, g0, m);
    if (author == "syamlal") return SyamlalViscosity{}(phi, theta, g0, m);
    if (author == "syamlal_kinetic") return SyamlalViscosity{}.kinetic(phi, theta, g0, m);
    if (author == "hrenya_sinclair") return HrenyaSinclairViscosity(extra)(phi, theta, g0, m);
    if (author == "hrenya_sinclair_kinetic") return HrenyaSinclairViscosity(extra).kinetic(phi, theta, g0, m);
  } else if (function == "bulk_viscosity") {
    if (author == "lun") return LunBulkViscosity{}(phi, theta, g0, m);
  } else if (function == "conductivity") {
    if (author == "gidaspow") return GidaspowConductivity{}(phi, theta, g0, m);
    if (author == "gidaspow_kinetic") return GidaspowConductivity{}.kinetic(phi, theta, g0, m);
    if (author == "gidaspow_collisional") return GidaspowConductivity{}.collisional(phi, theta, g0, m);
    if (author == "syamlal") return SyamlalConductivity{}(phi, theta, g0, m);
    if (author == "hrenya_sinclair") return HrenyaSinclairConductivity(extra)(phi, theta, g0, m);
  } else if (function == "dissipation") {
    if (author == "lun") return LunDissipation{}(phi, theta, g0, m);
  }
  throw std::invalid_argument("no constitutive function " + function + " " + author);
}

// The author and the RDF of a variant "<author>:<rdf>".
inline std::pair<std::string, std::string> split_variant(const std::string& variant) {
  const auto colon = variant.find(':');
  if (colon == std::string::npos) return {variant, ""};
  return {variant.substr(0, colon), variant.substr(colon + 1)};
}

}  // namespace fluidbed::test
