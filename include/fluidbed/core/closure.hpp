// fluidbed — what every closure of every family says about itself.
//
// Each closure is a small value type (its parameters) with
//   name()        unique across the library: the type's name, or a preset's name;
//   reference()   authors, year, journal, DOI of the primary source;
//   validity()    the ranges it was fitted or derived for (std::array of ValidityInterval);
// and its family's entry points: the hot-path call, with_derivatives, checked (family bases:
// drag/drag_law.hpp, settling/, elastic/, kinetic_theory/). A registry (registry.hpp) lists
// the closures of a family; the catalogue, the tests and the bindings read these members.
#pragma once

#include "config.hpp"  // first: its C++20 check precedes any C++20-only header

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>

#include "domain.hpp"
#include "parameters.hpp"

namespace fluidbed {

// One quantity's range over which a closure was fitted or derived. Outside it the closure
// still returns its formula's value (finite where documented): an extrapolation.
struct ValidityInterval {
  std::string_view quantity;  // e.g. "voidage", "Re_t"
  double min;
  double max;
};

template <std::size_t N>
using Validity = std::array<ValidityInterval, N>;

// The domain of a closure's own parameters (a packing limit, a wall ratio) in T:
// `law.parameter_domain<T>()` where the closure has parameters, else an empty list, so that a
// family's base joins it to its arguments' domain whatever law it serves.
template <class T, class Law>
FLUIDBED_HOST_DEVICE constexpr auto parameter_domain_of(const Law& law) {
  if constexpr (requires { law.template parameter_domain<T>(); })
    return law.template parameter_domain<T>();
  else
    return Arguments<T, 0>{};
}

// The metadata members every closure has.
template <class Law>
concept Closure = requires(const Law& law) {
  { law.name() } -> std::convertible_to<std::string_view>;
  { law.reference() } -> std::convertible_to<std::string_view>;
  law.validity();
};

}  // namespace fluidbed
