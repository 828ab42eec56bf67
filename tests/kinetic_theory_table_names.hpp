// Test helper: the kinetic-theory closures named as the mpmath tables in tests/reference/ name
// them (ktgf_*.csv, scalar_types_reference.csv: "carnahan_starling", "shear_viscosity:gidaspow"),
// found through the library's registries (kinetic_theory/registry.hpp) and evaluated for any
// scalar (float, double, long double, or a Dual of them).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "fluidbed/kinetic_theory.hpp"

namespace fluidbed::test {

using kinetic_theory::GranularMaterial;

// |a − b|/|b|, 0 when a == b (also for a = b = 0 or ±∞).
inline double relative_difference(double a, double b) {
  if (a == b) return 0;
  return std::abs(a - b) / std::max(std::abs(b), std::numeric_limits<double>::min());
}

// A table's name and the library's (name()) for the same closure.
struct TableName {
  std::string table, library;
};

// The one-class radial distributions.
inline const std::vector<TableName> radial_distribution_names{
    {"carnahan_starling", "CarnahanStarling"},
    {"percus_yevick", "PercusYevick"},
    {"lun_savage", "LunSavage"},
    {"sinclair_jackson", "SinclairJackson"},
    {"ogawa", "Ogawa"},
    {"gidaspow", "GidaspowRadialDistribution"},
    {"ma_ahmadi", "MaAhmadi"},
    {"lathouwers_bellan", "LathouwersBellan"},
    {"song_stratt_mason", "SongStrattMason"},
    {"tobochnik_chapin", "TobochnikChapin"}};

// The laws law(φ, Θ, g0, material), as "function:author".
inline const std::vector<TableName> constitutive_names{
    {"granular_pressure:lun", "LunPressure"},
    {"granular_pressure:syamlal_rogers_obrien", "SyamlalRogersOBrienPressure"},
    {"granular_pressure:ma_ahmadi", "AhmadiMaPressure"},
    {"shear_viscosity:gidaspow", "GidaspowViscosity"},
    {"shear_viscosity:syamlal", "SyamlalViscosity"},
    {"shear_viscosity:hrenya_sinclair", "HrenyaSinclairViscosity"},
    {"bulk_viscosity:lun", "LunBulkViscosity"},
    {"conductivity:gidaspow", "GidaspowConductivity"},
    {"conductivity:syamlal", "SyamlalConductivity"},
    {"conductivity:hrenya_sinclair", "HrenyaSinclairConductivity"},
    {"dissipation:lun", "LunDissipation"},
    {"shear_viscosity:enskog", "EnskogViscosity"},
    {"conductivity:enskog", "EnskogConductivity"}};

inline std::string library_name(const std::vector<TableName>& names, const std::string& table) {
  for (const TableName& n : names)
    if (n.table == table) return n.library;
  throw std::invalid_argument("no closure named " + table + " in the tables");
}

// f(law) for the law called `name` in the first of the registries that has it; throws if none has.
template <class Result, class F, class... Registry>
Result visit_by_name(std::string_view name, const F& f, std::type_identity<Registry>...) {
  std::optional<Result> result;
  const auto try_registry = [&](auto registry) {
    using R = typename decltype(registry)::type;
    if (result) return;
    if (const auto law = R::find(name)) result = std::visit(f, *law);
  };
  (try_registry(std::type_identity<Registry>{}), ...);
  if (!result) throw std::invalid_argument("no registered closure " + std::string(name));
  return *result;
}

// The one-class RDF `name` (the tables' name) with packing limit `max_packing` where it has one.
template <class S>
S radial_distribution(const std::string& name, const S& phi, double max_packing) {
  const auto evaluate = [&](auto law) -> S {
    if constexpr (requires { law.max_packing = max_packing; }) law.max_packing = max_packing;
    return law(phi);
  };
  return visit_by_name<S>(library_name(radial_distribution_names, name), evaluate,
                          std::type_identity<kinetic_theory::RadialDistributions>{});
}

// The g0 of a constitutive row's variant "<author>:<rdf>": carnahan_starling, or ogawa
// with φ_max = 0.63 (tests/reference/README.md).
template <class S>
S row_radial_distribution(const std::string& rdf, const S& phi) {
  return radial_distribution(rdf, phi, 0.63);
}

// The law(φ, Θ, g0, material) of the tables' function and author, or its kinetic or
// collisional part (author "<author>_kinetic", "<author>_collisional"); `length` is the
// Hrenya–Sinclair L where it applies.
template <class S, class T>
S constitutive(const std::string& function, const std::string& author, const S& phi, const S& theta, const S& g0,
               const GranularMaterial<T>& m, double length) {
  std::string law_author = author, part;
  for (const std::string suffix : {"_kinetic", "_collisional"})
    if (author.ends_with(suffix)) {
      law_author = author.substr(0, author.size() - suffix.size());
      part = suffix.substr(1);
    }
  const auto evaluate = [&](auto law) -> S {
    if constexpr (requires { law.length_scale = length; }) law.length_scale = length;
    if constexpr (requires { law.kinetic(phi, theta, g0, m); }) {
      if (part == "kinetic") return law.kinetic(phi, theta, g0, m);
      if (part == "collisional") return law.collisional(phi, theta, g0, m);
    }
    if (!part.empty()) throw std::invalid_argument(std::string(law.name()) + " has no part " + part);
    return law(phi, theta, g0, m);
  };
  using namespace kinetic_theory;
  return visit_by_name<S>(library_name(constitutive_names, function + ":" + law_author), evaluate,
                          std::type_identity<GranularPressures>{}, std::type_identity<ShearViscosities>{},
                          std::type_identity<BulkViscosities>{}, std::type_identity<Conductivities>{},
                          std::type_identity<Dissipations>{});
}

// The author and the RDF of a variant "<author>:<rdf>".
inline std::pair<std::string, std::string> split_variant(const std::string& variant) {
  const auto colon = variant.find(':');
  if (colon == std::string::npos) return {variant, ""};
  return {variant.substr(0, colon), variant.substr(colon + 1)};
}

}  // namespace fluidbed::test
