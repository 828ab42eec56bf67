// The metadata of every closure of the library, read through the registries (registries.hpp) as
// plain values, family by family: what tests/test_registries.cpp checks against the hand-written
// docs/closures/*.md and what docs/catalogue/generate_catalogue.cpp prints as docs/catalogue.md.
#pragma once

#include <regex>
#include <string>
#include <variant>
#include <vector>

#include "fluidbed/registries.hpp"

namespace fluidbed::test {

struct ClosureMetadata {
  std::string name;
  std::string reference;
  std::vector<ValidityInterval> validity;
};

struct FamilyMetadata {
  std::string what;
  std::string convention;
  std::vector<ClosureMetadata> closures;  // every instance of the registry, presets included
};

// The Family tag of a registry (what and convention).
template <class Registry>
struct family_of;
template <class Family, class... Laws>
struct family_of<Registry<Family, Laws...>> {
  using type = Family;
};

template <class Law>
std::vector<ValidityInterval> validity_of(const Law& law) {
  const auto v = law.validity();
  if constexpr (requires { v.voidage_min; })  // a drag law's box (drag::ValidityRange)
    return {{"voidage", v.voidage_min, v.voidage_max}, {"reynolds", v.reynolds_min, v.reynolds_max}};
  else
    return {v.begin(), v.end()};
}

inline std::vector<FamilyMetadata> every_family() {
  std::vector<FamilyMetadata> families;
  Registries::for_each([&](auto registry) {
    using Registry = typename decltype(registry)::type;
    using Family = typename family_of<Registry>::type;
    FamilyMetadata family{std::string(Family::what), std::string(Family::convention), {}};
    for (const auto& law : Registry::all())
      std::visit(
          [&](const auto& l) {
            family.closures.push_back({std::string(l.name()), std::string(l.reference()), validity_of(l)});
          },
          law);
    families.push_back(family);
  });
  return families;
}

// The DOIs a reference string cites, written "doi:10.xxxx/yyy" (a trailing ',', ';' or ')' is
// punctuation, not part of the DOI).
inline std::vector<std::string> dois_of(const std::string& reference) {
  static const std::regex doi(R"(doi:(\S+?)[,;)]?(\s|$))");
  std::vector<std::string> found;
  for (std::sregex_iterator it(reference.begin(), reference.end(), doi), end; it != end; ++it)
    found.push_back((*it)[1].str());
  return found;
}

}  // namespace fluidbed::test
