// fluidbed — what the bindings (the C interface, the Python module) share: any closure of any
// registry chosen by its run-time name, with its metadata and its parameters by name, and the
// errors a binding turns into its own (a C status, a Python exception). Internal to the bindings:
// not installed.
#pragma once

#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "fluidbed/registries.hpp"

namespace fluidbed::bindings {

template <class List>
struct ClosuresOf;
template <class... Registry>
struct ClosuresOf<RegistryList<Registry...>> {
  using Variant = std::variant<typename Registry::Variant...>;
  using Registries = std::tuple<Registry...>;
};

// A closure of any registry of fluidbed::Registries: its index is the registry's (the family's)
// place in that list.
using AnyClosure = ClosuresOf<fluidbed::Registries>::Variant;
using RegistryTuple = ClosuresOf<fluidbed::Registries>::Registries;
inline constexpr std::size_t family_count = std::variant_size_v<AnyClosure>;

template <std::size_t family>
using RegistryOf = std::tuple_element_t<family, RegistryTuple>;

// Calls f(law) with the closure's own type.
template <class F>
decltype(auto) visit_closure(const AnyClosure& closure, F&& f) {
  return std::visit([&](const auto& family) -> decltype(auto) { return std::visit(f, family); }, closure);
}
template <class F>
decltype(auto) visit_closure(AnyClosure& closure, F&& f) {
  return std::visit([&](auto& family) -> decltype(auto) { return std::visit(f, family); }, closure);
}

// Failures that are not the library's own (its std::domain_error): a NULL array or a closure of
// another family, an unknown closure or parameter.
struct InvalidArgument : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
struct UnknownName : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
struct UnknownParameter : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// An evaluation stopped at a cell: the cell and what it threw.
struct CellError {
  std::size_t index;
  std::exception_ptr cause;
};

// cell(i) for i in [0, n); what cell i throws becomes a CellError at i.
template <class Cell>
void for_each_cell(std::size_t n, Cell&& cell) {
  for (std::size_t i = 0; i < n; ++i) {
    try {
      cell(i);
    } catch (...) {
      throw CellError{i, std::current_exception()};
    }
  }
}

// A closure with its name and reference as terminated strings (a closure's name() is a view).
struct NamedClosure {
  AnyClosure closure;
  std::string name;
  std::string reference;

  std::size_t family() const { return closure.index(); }
};

// Every closure of the library, presets included, in the registries' order; built once.
inline const std::vector<NamedClosure>& catalogue() {
  static const std::vector<NamedClosure> entries = [] {
    std::vector<NamedClosure> all;
    const auto add = [&]<std::size_t f>(std::integral_constant<std::size_t, f>) {
      for (const auto& law : RegistryOf<f>::all()) {
        const AnyClosure closure(std::in_place_index<f>, law);
        all.push_back({closure, std::string(RegistryOf<f>::name_of(law)),
                       std::string(std::visit([](const auto& l) { return l.reference(); }, law))});
      }
    };
    [&]<std::size_t... f>(std::index_sequence<f...>) {
      (add(std::integral_constant<std::size_t, f>{}), ...);
    }(std::make_index_sequence<family_count>{});
    return all;
  }();
  return entries;
}

// The closure called `name`, with its registered parameters; UnknownName lists the known names.
inline NamedClosure make_closure(std::string_view name) {
  std::string known;
  for (const NamedClosure& entry : catalogue()) {
    if (entry.name == name) return entry;
    known += (known.empty() ? "" : ", ") + entry.name;
  }
  throw UnknownName("fluidbed: unknown closure '" + std::string(name) + "'; known: " + known);
}

// text(std::type_identity<Family>{}) of the family description of registry `family`; empty for
// an index that is not a family's.
template <class Text>
std::string_view family_text(std::size_t family, const Text& text) {
  return [&]<std::size_t... f>(std::index_sequence<f...>) {
    std::string_view found;
    static_cast<void>(
        ((family == f ? (found = text(std::type_identity<typename RegistryOf<f>::family>{}), true) : false) || ...));
    return found;
  }(std::make_index_sequence<family_count>{});
}

// What a family's closures are ("drag law") and their convention.
inline std::string_view family_what(std::size_t family) {
  return family_text(family, []<class Family>(std::type_identity<Family>) { return Family::what; });
}
inline std::string_view family_convention(std::size_t family) {
  return family_text(family, []<class Family>(std::type_identity<Family>) { return Family::convention; });
}

// The closure of family `family`, or InvalidArgument naming what `function` expected.
template <std::size_t family>
const typename RegistryOf<family>::Variant& family_closure(const NamedClosure& closure, std::string_view function) {
  if (closure.family() != family)
    throw InvalidArgument("fluidbed: " + std::string(function) + ": " + closure.name + " is not a " +
                          std::string(RegistryOf<family>::family::what));
  return std::get<family>(closure.closure);
}

// The validity intervals of a closure as (quantity, min, max); a drag law's box as two.
template <class Law>
std::vector<ValidityInterval> validity_of(const Law& law) {
  const auto v = law.validity();
  if constexpr (requires { v.voidage_min; })
    return {{"voidage", v.voidage_min, v.voidage_max}, {"reynolds", v.reynolds_min, v.reynolds_max}};
  else
    return {v.begin(), v.end()};
}
inline std::vector<ValidityInterval> closure_validity(const NamedClosure& closure) {
  return visit_closure(closure.closure, [](const auto& l) { return validity_of(l); });
}

// The names of a closure's parameters (literals: static storage).
inline std::vector<std::string_view> parameter_names_of(const NamedClosure& closure) {
  return visit_closure(closure.closure, []<class Law>(const Law&) {
    std::vector<std::string_view> names;
    for (const auto& p : parameters_of<Law>()) names.push_back(p.name);
    return names;
  });
}

inline double get_parameter(const NamedClosure& closure, std::string_view name) {
  return visit_closure(closure.closure, [&]<class Law>(const Law& law) {
    const auto value = fluidbed::get_parameter(law, name);
    if (!value)
      throw UnknownParameter("fluidbed: " + closure.name + " has no parameter '" + std::string(name) +
                             "'; its parameters: " + parameter_names<Law>());
    return *value;
  });
}

// Sets a parameter, validated at once (std::domain_error, the closure unchanged).
inline void set_parameter(NamedClosure& closure, std::string_view name, double value) {
  visit_closure(closure.closure, [&]<class Law>(Law& law) {
    if (!fluidbed::get_parameter(law, name))
      throw UnknownParameter("fluidbed: " + closure.name + " has no parameter '" + std::string(name) +
                             "'; its parameters: " + parameter_names<Law>());
    set_parameter_checked(law, name, value);
  });
}

}  // namespace fluidbed::bindings
