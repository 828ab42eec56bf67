// fluidbed — mathematical constants in any scalar type.
//
// std::numbers' variable templates accept the built-in floating types only; these functions
// also serve Boost.Multiprecision and automatic-differentiation types. For a built-in type each
// is a 36-digit long double literal rounded once to T (to 64 bits, then to T for float and
// double), so that a long double evaluation gets every digit of its type and a float one stays
// in float. A Boost.Multiprecision number is given 64 digits, so that a 50-digit evaluation
// gets a 50-digit π, not long double's.
//
// A closure's published decimal coefficient or switch point is written once, as
// FLUIDBED_DECIMAL(T, 0.175): for a built-in T it is T(0.175L), the decimal rounded once to 64
// bits and then to T, bit for bit what a long double literal gives; a Boost.Multiprecision T
// parses the digits "0.175", so that a 50-digit evaluation gets the coefficient the paper
// printed, not its 19-digit approximation. Dyadic decimals (0.5, 0.75) and integers are exact
// in every type and are written plainly.
#pragma once

#include "config.hpp"

namespace fluidbed::numbers {

namespace detail {

// `digits` (64 significant digits for a constant of mathematics, the published digits for a
// closure's coefficient) for a Boost.Multiprecision number (recognised by its
// backend_type, without including Boost), else `rounded`. (Other wrappers, autodiff types
// among them, may accept a string in overload resolution without parsing one.)
template <class T>
FLUIDBED_HOST_DEVICE constexpr T constant(long double rounded, const char* digits) {
  if constexpr (requires { typename T::backend_type; })
    return T(digits);
  else
    return T(rounded);
}

}  // namespace detail

template <class T>
FLUIDBED_HOST_DEVICE constexpr T pi() {
  return detail::constant<T>(3.14159265358979323846264338327950288L,
                             "3.141592653589793238462643383279502884197169399375105820974944592");
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T sqrt_pi() {
  return detail::constant<T>(1.77245385090551602729816748334114518L,
                             "1.772453850905516027298167483341145182797549456122387128213807790");
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T sqrt2() {
  return detail::constant<T>(1.41421356237309504880168872420969808L,
                             "1.414213562373095048801688724209698078569671875376948073176679738");
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T sqrt3() {
  return detail::constant<T>(1.73205080756887729352744634150587237L,
                             "1.732050807568877293527446341505872366942805253810380628055806979");
}

template <class T>
FLUIDBED_HOST_DEVICE constexpr T ln10() {
  return detail::constant<T>(2.30258509299404568401799145468436421L,
                             "2.302585092994045684017991454684364207601101488628772976033327901");
}

}  // namespace fluidbed::numbers

// The decimal `literal` (as written, without suffix) in T: see the header comment.
#define FLUIDBED_DECIMAL(T, literal) (::fluidbed::numbers::detail::constant<T>(literal##L, #literal))
