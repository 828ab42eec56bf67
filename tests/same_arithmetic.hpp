// Comparing two code paths that evaluate the same expression: the plain value and the value
// part of a dual number, a law and its one-species form, per-cell and batched inversion.
// Without floating-point contraction they perform the same operations and agree to the bit.
// GCC contracts a·b + c into a fused multiply-add by default (-ffp-contract=fast, its GNU
// modes) wherever the target has FMA (e.g. -march=native on x86-64-v3 and later), and may
// contract the two paths differently: they then agree only to rounding.
#pragma once

#include <cmath>
#include <limits>

namespace fluidbed::test {

#if defined(__FMA__) || defined(__ARM_FEATURE_FMA) || defined(__FP_FAST_FMA)
inline constexpr bool exact_agreement = false;
#else
inline constexpr bool exact_agreement = true;
#endif

// a == b to the bit without contraction; within 64 ε relative with it (the value of a
// closure passes through at most a few dozen roundings, each of which contraction may skip).
template <class T>
bool same_arithmetic(T a, T b) {
  if (exact_agreement || a == b) return a == b;
  using std::abs;  // and Boost.Multiprecision's by argument-dependent lookup
  const T larger = abs(a) > abs(b) ? T(abs(a)) : T(abs(b));
  return T(abs(a - b)) <= T(64) * std::numeric_limits<T>::epsilon() * larger;
}

}  // namespace fluidbed::test
