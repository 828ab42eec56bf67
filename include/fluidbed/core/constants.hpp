// fluidbed — mathematical constants in any scalar type.
//
// std::numbers' variable templates accept the built-in floating types only; these functions
// also serve Boost.Multiprecision and automatic-differentiation types. Each is a 36-digit
// long double literal rounded once to T (to 64 bits, then to T for float and double), so that
// a long double evaluation gets every digit of its type and a float one stays in float.
#pragma once

#include "config.hpp"

namespace fluidbed::numbers {

template <class T>
FLUIDBED_HOST_DEVICE constexpr T pi() {
  return T(3.14159265358979323846264338327950288L);
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T sqrt_pi() {
  return T(1.77245385090551602729816748334114518L);
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T sqrt2() {
  return T(1.41421356237309504880168872420969808L);
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T sqrt3() {
  return T(1.73205080756887729352744634150587237L);
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T ln10() {
  return T(2.30258509299404568401799145468436421L);
}

}  // namespace fluidbed::numbers
