// fluidbed — the domain of a call with vector arguments (forces of interaction/ and elastic/):
// its scalar arguments as an Arguments list (core/domain.hpp), and its vectors, each of whose
// components must be finite, named "<vector>[i]" in the checked path's message.
#pragma once

#include <concepts>
#include <cstddef>
#include <string_view>

#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/errors.hpp"
#include "../core/vector3.hpp"

namespace fluidbed::interaction {

// A vector argument: every component must be finite.
template <class T>
struct FiniteVector {
  const char* name;  // a C string, as Argument's name (core/domain.hpp)
  const Vector3<T>& value;

  FLUIDBED_HOST_DEVICE constexpr bool holds() const {
    // x − x is 0 for finite x and NaN for NaN and ±∞.
    return value[0] - value[0] == T(0) && value[1] - value[1] == T(0) && value[2] - value[2] == T(0);
  }
};

// The domain check of a force under `Policy` (core/errors.hpp), the vectors first (a length
// computed from a vector is then finite), then the scalars: what fluidbed::check_domain is for
// scalar arguments. Shared by the forces of interaction/ and elastic/.
template <ErrorPolicy Policy, class Name, class T, std::size_t N, class... Vectors>
constexpr void check_force_domain(Policy policy, const Name& function, const Arguments<T, N>& scalars,
                                  const Vectors&... vectors) {
  if constexpr (std::same_as<Policy, Checked>)
    (require_finite_elements(function, vectors.name, vectors.value), ...);
  else
    FLUIDBED_EXPECTS((vectors.holds() && ...));
  fluidbed::check_domain(policy, function, scalars);
}

}  // namespace fluidbed::interaction
