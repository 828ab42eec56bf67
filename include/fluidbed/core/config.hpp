// fluidbed — configuration: host/device annotation and debug-only precondition checks.
#pragma once

#include <cassert>
#include <cmath>
#include <limits>

// C++20 is required (concepts, std::span, designated initializers, std::remove_cvref_t, …): say
// so first, instead of hundreds of errors from the first C++20 construct. MSVC reports its
// language level in _MSVC_LANG unless /Zc:__cplusplus is given.
#if defined(_MSVC_LANG) && _MSVC_LANG > __cplusplus
#define FLUIDBED_CPLUSPLUS _MSVC_LANG
#else
#define FLUIDBED_CPLUSPLUS __cplusplus
#endif
#if FLUIDBED_CPLUSPLUS < 202002L
#error "fluidbed needs C++20: compile with -std=c++20 (or /std:c++20); with CMake, link fluidbed::fluidbed, which sets it"
#endif
#undef FLUIDBED_CPLUSPLUS

// -ffast-math (through -ffinite-math-only) lets the compiler assume no value is NaN or ±∞,
// which folds away the checks that turn such inputs into exceptions and statuses (checked
// entry points, moment-inversion statuses, batched lane guards) and the infinities returned
// on purpose: unsupported (docs/README.md). Define FLUIDBED_ACCEPT_FAST_MATH to build anyway
// and take on the responsibility that no NaN or ±∞ ever reaches the library.
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__ && !defined(FLUIDBED_ACCEPT_FAST_MATH)
#error "fluidbed: -ffast-math/-ffinite-math-only is unsupported (its NaN and infinity checks would be folded away)"
#endif

// Every per-cell function is usable from CUDA/HIP device code when the headers are
// compiled by a device compiler; on the host the macro expands to nothing.
#if defined(__CUDACC__) || defined(__HIPCC__)
#define FLUIDBED_HOST_DEVICE __host__ __device__
#else
#define FLUIDBED_HOST_DEVICE
#endif

// Hot-path preconditions: checked with assert() in debug builds, free in release builds.
// The checked entry points (`*_checked`) validate the same conditions and throw. Under
// NDEBUG the condition stays an unevaluated operand, so a parameter that only appears in a
// precondition is still "used" (no -Wunused-parameter in a release build of the host).
#ifdef NDEBUG
#define FLUIDBED_EXPECTS(condition) static_cast<void>(sizeof(!(condition)))
#else
#define FLUIDBED_EXPECTS(condition) assert(condition)
#endif

namespace fluidbed::detail {

// Whether x is a normal floating-point number (not 0, subnormal, ±∞ or NaN), written with
// comparisons. Not std::isnormal: nvcc compiles std::isnormal in device code to `false`, without
// a diagnostic (seen on an H100: every device inversion reported invalid_input).
template <class T>
FLUIDBED_HOST_DEVICE constexpr bool is_normal(const T& x) {
  using std::abs;
  const T magnitude = abs(x);
  return magnitude >= std::numeric_limits<T>::min() && magnitude <= std::numeric_limits<T>::max();
}

}  // namespace fluidbed::detail
