// fluidbed — run-time selection of a closure by name, one registry per family, extensible.
//
// A family's registry is a type list of its closures, Registry<Family, Law...>. From that
// one list come the std::variant a host stores (`Variant`), one instance of every closure
// (`all()`, each preset of a parameterised law included), and lookup by name (`find`,
// `make`). A user adds a law of their own without editing the library:
//
//   using MyDragLaws = fluidbed::drag::DragLaws::with<MyLaw>;
//   auto law = MyDragLaws::make("MyLaw");            // a MyDragLaws::Variant
//
// Whatever enumerates closures (tests, fuzzers, benchmarks, the catalogue, bindings)
// iterates the registries: for_each_type visits every type, all() every instance.
//
// A law type provides name() (unique across the library), and optionally a static
// `registered()` returning a std::array of its instances (presets); without it the
// registry holds one default-constructed instance. Family provides `static constexpr
// std::string_view what`, the kind of closure in an error message ("drag law"), and
// `convention`, what the family's closures return (quantity, units, sign) and the definitions
// of their arguments, which the generated catalogue (docs/catalogue.md) prints.
#pragma once

#include "config.hpp"  // first: its C++20 check precedes any C++20-only header

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>

#include "errors.hpp"

namespace fluidbed {

namespace detail {

template <class Law>
constexpr auto registered_instances() {
  if constexpr (requires { Law::registered(); })
    return Law::registered();
  else
    return std::array<Law, 1>{Law{}};
}

}  // namespace detail

template <class Family, class... Laws>
struct Registry {
  static_assert(sizeof...(Laws) > 0, "a registry lists at least one closure");

  using Variant = std::variant<Laws...>;
  // The family's tag: what its closures are (`what`) and their `convention`.
  using family = Family;
  // This registry with more closures: a user's own laws beside the library's.
  template <class... More>
  using with = Registry<Family, Laws..., More...>;

  static constexpr std::size_t size = (detail::registered_instances<Laws>().size() + ...);

  // One instance of every closure, presets included, in the order of the type list, each as
  // its own type: a std::tuple that compile-time code (a device kernel, a benchmark) walks
  // with std::apply, seeing every kernel without a std::visit.
  static constexpr auto instances() { return std::tuple_cat(detail::registered_instances<Laws>()...); }

  // The same instances as Variants, for run-time selection.
  static constexpr std::array<Variant, size> all() {
    return std::apply([](const auto&... law) { return std::array<Variant, size>{Variant{law}...}; }, instances());
  }

  // Calls f(std::type_identity<Law>{}) for every type of the list.
  template <class F>
  static constexpr void for_each_type(F&& f) {
    (f(std::type_identity<Laws>{}), ...);
  }

  static constexpr std::string_view name_of(const Variant& law) {
    return std::visit([](const auto& l) -> std::string_view { return l.name(); }, law);
  }

  // The closure called `name`, or nothing.
  static constexpr std::optional<Variant> find(std::string_view name) {
    for (const Variant& law : all())
      if (name_of(law) == name) return law;
    return std::nullopt;
  }

  // The closure called `name`; throws std::invalid_argument listing the known names.
  static Variant make(std::string_view name) {
    if (auto law = find(name)) return *law;
    std::string known;
    for (const Variant& law : all()) known += (known.empty() ? "" : ", ") + std::string(name_of(law));
    detail::throw_unknown_closure(Family::what, name, known);
  }

  // True if no two instances share a name (a registry test; names are unique library-wide).
  static constexpr bool names_are_unique() {
    const auto instances = all();
    for (std::size_t i = 0; i < size; ++i)
      for (std::size_t j = i + 1; j < size; ++j)
        if (name_of(instances[i]) == name_of(instances[j])) return false;
    return true;
  }
};

}  // namespace fluidbed
