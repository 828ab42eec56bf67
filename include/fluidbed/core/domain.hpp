// fluidbed — argument domains, declared once per closure.
//
// A closure states the domain of each of its arguments once, as a list of Argument values
// (name, value, Interval). Both entry points derive their checks from that one list:
//   hot path      FLUIDBED_EXPECTS(within(domain))   asserted in debug builds, free in release,
//                                                    no exceptions: usable in device code;
//   checked path  require_within(function, domain)   (errors.hpp) throws std::domain_error
//                                                    naming the first argument outside.
// An interval excludes NaN and ±∞ whatever its bounds: every argument must be finite.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <string_view>

#include "config.hpp"

namespace fluidbed {

// The finite numbers between lower and upper, each end open or closed; a bound may be ±∞.
template <class T>
struct Interval {
  T lower;
  T upper;
  bool lower_closed;
  bool upper_closed;

  FLUIDBED_HOST_DEVICE constexpr bool contains(const T& x) const {
    const bool above = lower_closed ? x >= lower : x > lower;
    const bool below = upper_closed ? x <= upper : x < upper;
    // x − x is 0 for finite x and NaN for NaN and ±∞.
    return above && below && x - x == T(0);
  }
};

// The intervals the closures use, by what they say.
namespace domains {

template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> finite() {
  return {-std::numeric_limits<T>::infinity(), std::numeric_limits<T>::infinity(), false, false};
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> positive() {
  return {T(0), std::numeric_limits<T>::infinity(), false, false};
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> non_negative() {
  return {T(0), std::numeric_limits<T>::infinity(), true, false};
}
template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> greater_than(const T& lower) {
  return {lower, std::numeric_limits<T>::infinity(), false, false};
}
// lower < x < upper
template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> open(const T& lower, const T& upper) {
  return {lower, upper, false, false};
}
// lower <= x <= upper
template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> closed(const T& lower, const T& upper) {
  return {lower, upper, true, true};
}
// lower < x <= upper, e.g. a voidage ε ∈ (0, 1]
template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> half_open(const T& lower, const T& upper) {
  return {lower, upper, false, true};
}
// lower <= x < upper, e.g. a solids fraction φ ∈ [0, 1)
template <class T>
FLUIDBED_HOST_DEVICE constexpr Interval<T> closed_open(const T& lower, const T& upper) {
  return {lower, upper, true, false};
}

}  // namespace domains

// One argument of a call, with the interval it must lie in. `requirement`, when given,
// replaces the interval's own wording in the checked path's message (for a bound that is
// another argument, e.g. "must be finite and > fluid.density: heavier-than-fluid particles
// only").
// The texts are C strings, not std::string_view: the hot path builds these lists for its
// debug-build assertions in device code too, and nvcc compiles std::string_view's constructor
// from a C string (std::char_traits::length, __builtin_strlen) in device code to undefined
// behaviour without a diagnostic, which empties the whole kernel (seen on an H100: every kernel
// of tests/cuda wrote nothing in a debug build).
template <class T>
struct Argument {
  const char* name;
  T value;
  Interval<T> domain;
  const char* requirement = nullptr;
};

template <class T, std::size_t N>
using Arguments = std::array<Argument<T>, N>;

// The arguments of a call as one list (all of one scalar type).
template <class T, class... Rest>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 1 + sizeof...(Rest)> arguments(const Argument<T>& first,
                                                                          const Rest&... rest) {
  return {first, rest...};
}

// Two lists as one (a state's arguments followed by a material's, …).
template <class T, std::size_t M, std::size_t N>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, M + N> join(const Arguments<T, M>& a, const Arguments<T, N>& b) {
  // An empty list (a law without parameters) is returned as it is: no loop `i < 0`, which nvcc
  // reports as a pointless comparison.
  if constexpr (N == 0) {
    return a;
  } else if constexpr (M == 0) {
    return b;
  } else {
    Arguments<T, M + N> all{};
    for (std::size_t i = 0; i < M; ++i) all[i] = a[i];
    for (std::size_t i = 0; i < N; ++i) all[M + i] = b[i];
    return all;
  }
}

// True if every argument lies in its interval: the hot path's precondition.
template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE constexpr bool within(const Arguments<T, N>& list) {
  if constexpr (N > 0)  // (nvcc warns of i < 0 for an empty list, a closure without parameters)
    for (std::size_t i = 0; i < N; ++i)
      if (!list[i].domain.contains(list[i].value)) return false;
  return true;
}

}  // namespace fluidbed
