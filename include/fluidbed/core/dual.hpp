// fluidbed — forward-mode dual numbers: exact first derivatives of a generic formula.
//
// Every closure is written once, as a template on its scalar type S. Evaluated with
// S = T it gives the value; with S = Dual<T, N> it gives the value and N partial
// derivatives exact to rounding, with no hand-derived (and hand-mistyped) derivative
// formulas to maintain. Boost.Math's autodiff does the same for host code, but its
// types are neither constexpr nor usable in device code and are several times slower
// per cell; this type is deliberately minimal (the operations closures use) and the
// tests check it against Boost.Math autodiff and finite differences.
//
// Zero convention. Closures are evaluated at exact limits (zero slip, ε = 1) where a
// factor with an infinite slope (Re^0.687, √φ) meets a factor that is identically
// zero along that direction. The chain rule then multiplies ∞ by an exact 0. Here a
// product with an exact zero operand is zero, so a derivative is NaN only where the
// formula itself is; it may be ±∞ where the true derivative is.
#pragma once

#include <cmath>
#include <compare>
#include <concepts>
#include <limits>
#include <numbers>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "constants.hpp"

// Dual's operations are a few instructions each around what the plain arithmetic does: always
// inlined, as that arithmetic is. Left to its heuristics GCC calls operator* and sqrt out of
// line, passing the 24-byte Dual<double, 2> through memory, and a law with derivatives then
// costs 4 times its value instead of 2.
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDACC__) && !defined(__HIPCC__)
#define FLUIDBED_DUAL_INLINE [[gnu::always_inline]] inline
#else
#define FLUIDBED_DUAL_INLINE inline
#endif

namespace fluidbed {

template <class T, int N>
struct Dual {
  T value{};
  T derivative[N]{};

  constexpr Dual() = default;
  FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual(const T& constant) : value(constant) {}  // NOLINT: constants mix freely

  // The independent variable number `index` (0-based) at `at`.
  FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE static constexpr Dual variable(const T& at, int index) {
    Dual x(at);
    x.derivative[index] = T(1);
    return x;
  }
};

template <class S>
struct is_dual : std::false_type {};
template <class T, int N>
struct is_dual<Dual<T, N>> : std::true_type {};

// The plain value of a scalar or a dual number.
template <class T>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr const T& value_of(const T& x) { return x; }
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr const T& value_of(const Dual<T, N>& x) { return x.value; }

// The plain floating type of a scalar or a dual number.
template <class S>
using value_type_of = std::remove_cvref_t<decltype(value_of(std::declval<const S&>()))>;

// Constants of the closures. A formula's constant meets its scalar in the scalar's plain
// type T = value_type_of<S>, never in double: `1 - voidage`, `FLUIDBED_DECIMAL(T, 2.4) * x`,
// `pow(x, T(0.75))`. A double literal would turn a float evaluation into a double one
// (float · double is double) and round a long double evaluation's constants to 53 bits
// (double(0.175) is 0.175 − 1.1e-17, 819 ulp of x87 long double). Exact integers and dyadic
// decimals are written as such; every other decimal as FLUIDBED_DECIMAL(T, 0.175)
// (core/constants.hpp): for a built-in T the long double literal 0.175L converted to T, the
// decimal rounded once to T (to 64 bits, then to T: within half an ulp of T but for rare
// double-rounding ties), and for a Boost.Multiprecision T the decimal parsed from its digits,
// exact to the type's precision. A law's run-time parameters (an exponent, a packing limit, a
// wall ratio, a sphericity) are double members and enter as T(parameter): their precision is
// that of double in every T.
//
// A closure's constant that its argument is compared with (a switch point of a piecewise
// law, a bound), in the plain type of S. Dual's comparisons convert a constant to T, while a
// float compared with a double constant directly is compared in double: at ε = 0.85f,
// 0.85f > 0.85 but 0.85f <= float(0.85), and the value (S = float) and the derivatives
// (S = Dual<float, N>) would take different branches. Rounded once to T, both compare the
// same two numbers, and a long double argument is compared with the decimal to 64 bits
// (0.8L < double(0.8): a double switch point would put ε = 0.8L on the wrong side of a switch
// at ε = 0.8). A non-dyadic switch point is therefore FLUIDBED_DECIMAL(value_type_of<S>, 0.8)
// (a law's named switch point: a static member function template returning it); constant_as
// converts a dyadic or integer one given as a number.
template <class S>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr value_type_of<S> constant_as(long double constant) {
  return value_type_of<S>(constant);
}

namespace detail {

// a·b with the convention 0·anything = 0 (see the header comment).
template <class T>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr T times(const T& a, const T& b) {
  return (a == T(0) || b == T(0)) ? T(0) : a * b;
}

// Chain rule for a unary function: value f, local slope f'(x).
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> chain(const T& f, const T& slope, const Dual<T, N>& x) {
  Dual<T, N> r(f);
  for (int i = 0; i < N; ++i) r.derivative[i] = times(slope, x.derivative[i]);
  return r;
}

}  // namespace detail

// f(x) for a function whose value f and slope f'(x) the caller has formed already (a closure
// that reuses the pieces of its value, or solves an implicit relation in T).
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> chain_rule(const T& f, const T& slope, const Dual<T, N>& x) {
  return detail::chain(f, slope, x);
}

// A sub-expression of one input at the cost of one derivative. In a closure of several inputs,
// what depends on x alone can be formed on single_variable(x), a Dual<T, 1> in x, and brought
// back by of_single_variable(y, x): the same value and, by the chain rule, the same N
// derivatives (to rounding) as forming it on x itself, with 1/N of the derivative arithmetic. On
// a plain T both are the identity.
template <class T>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr const T& single_variable(const T& x) {
  return x;
}
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, 1> single_variable(const Dual<T, N>& x) {
  return Dual<T, 1>::variable(x.value, 0);
}
template <class T>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr const T& of_single_variable(const T& y, const T& /*x*/) {
  return y;
}
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> of_single_variable(const Dual<T, 1>& y,
                                                                                   const Dual<T, N>& x) {
  return chain_rule(y.value, y.derivative[0], x);
}

// A plain constant that may be mixed with Dual<T, N> (a literal, or T itself).
template <class U, class T>
concept ConstantFor = std::is_arithmetic_v<U> || std::same_as<U, T>;

// ----------------------------------------------------------------------------- arithmetic
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator-(const Dual<T, N>& x) {
  Dual<T, N> r(-x.value);
  for (int i = 0; i < N; ++i) r.derivative[i] = -x.derivative[i];
  return r;
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator+(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.value + b.value);
  for (int i = 0; i < N; ++i) r.derivative[i] = a.derivative[i] + b.derivative[i];
  return r;
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator-(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.value - b.value);
  for (int i = 0; i < N; ++i) r.derivative[i] = a.derivative[i] - b.derivative[i];
  return r;
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator*(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.value * b.value);
  for (int i = 0; i < N; ++i)
    r.derivative[i] = detail::times(a.derivative[i], b.value) + detail::times(a.value, b.derivative[i]);
  return r;
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator/(const Dual<T, N>& a, const Dual<T, N>& b) {
  const T q = a.value / b.value;
  const T inverse = T(1) / b.value;  // a division per operand, not per derivative
  Dual<T, N> r(q);
  for (int i = 0; i < N; ++i) r.derivative[i] = (a.derivative[i] - detail::times(q, b.derivative[i])) * inverse;
  return r;
}

// With a constant operand: the products and quotients with its zero derivatives are not
// formed (the same results, to the sign of a zero derivative).
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator+(const Dual<T, N>& a, U c) {
  Dual<T, N> r(a);
  r.value = a.value + T(c);
  return r;
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator+(U c, const Dual<T, N>& a) {
  Dual<T, N> r(a);
  r.value = T(c) + a.value;
  return r;
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator-(const Dual<T, N>& a, U c) {
  Dual<T, N> r(a);
  r.value = a.value - T(c);
  return r;
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator-(U c, const Dual<T, N>& a) {
  Dual<T, N> r = -a;
  r.value = T(c) - a.value;
  return r;
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator*(const Dual<T, N>& a, U c) {
  return detail::chain(T(a.value * T(c)), T(c), a);
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator*(U c, const Dual<T, N>& a) {
  return detail::chain(T(T(c) * a.value), T(c), a);
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator/(const Dual<T, N>& a, U c) {
  Dual<T, N> r(T(a.value / T(c)));
  for (int i = 0; i < N; ++i) r.derivative[i] = a.derivative[i] / T(c);
  return r;
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr Dual<T, N> operator/(U c, const Dual<T, N>& a) {
  const T q = T(c) / a.value;
  Dual<T, N> r(q);
  for (int i = 0; i < N; ++i) r.derivative[i] = -detail::times(q, a.derivative[i]) / a.value;
  return r;
}

namespace detail {

// a <=> b, also for a T without operator<=> (Boost.Multiprecision 1.74 has only < and ==).
template <class T>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr auto three_way(const T& a, const T& b) {
  if constexpr (std::three_way_comparable<T>)
    return a <=> b;
  else
    return a < b    ? std::partial_ordering::less
           : b < a  ? std::partial_ordering::greater
           : a == b ? std::partial_ordering::equivalent
                    : std::partial_ordering::unordered;
}

}  // namespace detail

// Comparisons look at the value only (branches of piecewise closures).
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr auto operator<=>(const Dual<T, N>& a, const Dual<T, N>& b) {
  return detail::three_way(a.value, b.value);
}
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr bool operator==(const Dual<T, N>& a, const Dual<T, N>& b) { return a.value == b.value; }
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr auto operator<=>(const Dual<T, N>& a, U c) {
  return detail::three_way(a.value, T(c));
}
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE constexpr bool operator==(const Dual<T, N>& a, U c) { return a.value == T(c); }

// ----------------------------------------------------------------------------- functions
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> sqrt(const Dual<T, N>& x) {
  using std::sqrt;
  const T f = sqrt(x.value);
  return detail::chain(f, T(1) / (T(2) * f), x);
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> cbrt(const Dual<T, N>& x) {
  using std::cbrt;
  const T f = cbrt(x.value);
  return detail::chain(f, T(1) / (T(3) * f * f), x);
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> exp(const Dual<T, N>& x) {
  using std::exp;
  const T f = exp(x.value);
  return detail::chain(f, f, x);
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> log(const Dual<T, N>& x) {
  using std::log;
  return detail::chain(T(log(x.value)), T(1) / x.value, x);
}

template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> atan(const Dual<T, N>& x) {
  using std::atan;
  return detail::chain(T(atan(x.value)), T(1) / (T(1) + x.value * x.value), x);
}

namespace detail {

// p·x^(p−1) given f = x^p: p·f/x, one pow fewer than forming x^(p−1), where that is exact to
// rounding (f and the quotient normal numbers); else formed directly, so that x = 0 gives the
// right 0 or ∞ and an f or a slope beyond the normal range loses no digits.
template <class T>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE T power_slope(const T& x, const T& exponent, const T& f) {
  using std::pow;
  if (exponent == T(0)) return T(0);
  const T slope = exponent * (f / x);
  return is_normal(f) && is_normal(slope) ? slope : T(exponent * T(pow(x, exponent - T(1))));
}

}  // namespace detail

// x^p for a constant exponent.
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> pow(const Dual<T, N>& x, U p) {
  using std::pow;
  const T exponent(p);
  const T f = pow(x.value, exponent);
  return detail::chain(f, detail::power_slope(x.value, exponent, f), x);
}

// a^y for a constant base a > 0 (or a = 0 with y > 0).
template <class T, int N, ConstantFor<T> U>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> pow(U a, const Dual<T, N>& y) {
  using std::log;
  using std::pow;
  const T base(a);
  const T f = pow(base, y.value);
  return detail::chain(f, base > T(0) ? T(f * log(base)) : T(0), y);
}

// x^y with both varying; ∂/∂y uses x^y·ln x, whose limit at x = 0 (y > 0) is 0.
template <class T, int N>
FLUIDBED_DUAL_INLINE FLUIDBED_HOST_DEVICE Dual<T, N> pow(const Dual<T, N>& x, const Dual<T, N>& y) {
  using std::log;
  using std::pow;
  const T f = pow(x.value, y.value);
  const T slope_x = detail::power_slope(x.value, y.value, f);
  const T slope_y = x.value > T(0) ? T(f * log(x.value)) : T(0);
  Dual<T, N> r(f);
  for (int i = 0; i < N; ++i)
    r.derivative[i] = detail::times(slope_x, x.derivative[i]) + detail::times(slope_y, y.derivative[i]);
  return r;
}

}  // namespace fluidbed
