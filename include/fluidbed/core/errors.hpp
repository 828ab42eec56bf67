// fluidbed — argument validation for the checked entry points.
//
// The hot path (per-cell calls) states its preconditions and asserts them in debug
// builds only. The checked entry points call these helpers, which throw
// std::domain_error with the function, the argument's name and its offending value:
//   fluidbed::<function>: argument '<argument>' = <value> is out of domain (<requirement>)
// Every helper rejects NaN and ±∞. require_finite_result checks a result the same way.
#pragma once

#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fluidbed {

namespace detail {

template <class T>
[[noreturn]] void throw_domain_error(std::string_view function, std::string_view argument, const T& value,
                                     std::string_view requirement) {
  std::ostringstream message;
  message.precision(17);
  message << "fluidbed::" << function << ": argument '" << argument << "' = " << value << " is out of domain ("
          << requirement << ")";
  throw std::domain_error(message.str());
}

template <class T>
bool is_finite_number(const T& x) {
  using std::isfinite;
  return isfinite(x);
}

// Throws unless x is finite and inside the interval from lower to upper, each end open or
// closed; the message writes the interval in the usual bracket notation.
template <class T>
void require_in_interval(std::string_view function, std::string_view argument, const T& x, const T& lower,
                         bool lower_closed, const T& upper, bool upper_closed) {
  const bool above = lower_closed ? x >= lower : x > lower;
  const bool below = upper_closed ? x <= upper : x < upper;
  if (is_finite_number(x) && above && below) return;
  std::ostringstream range;
  range.precision(17);
  range << "must lie in " << (lower_closed ? '[' : '(') << lower << ", " << upper << (upper_closed ? ']' : ')');
  throw_domain_error(function, argument, x, range.str());
}

}  // namespace detail

// For the checked entry points, after the evaluation: throws std::domain_error unless the
// result `value` is finite. Arguments that pass validation can still have a result the
// floating type cannot represent (an overflow to ∞, or NaN where it meets an exact 0); the
// checked contract is then a status, never a silent ∞ or NaN. `describe_arguments()` returns
// the arguments as text; it is called on failure only, so that success builds no string:
//   fluidbed::<function>: result '<result>' = <value> is not finite for <arguments> (...)
template <class T, class DescribeArguments>
void require_finite_result(std::string_view function, std::string_view result, const T& value,
                           const DescribeArguments& describe_arguments) {
  if (detail::is_finite_number(value)) return;
  std::ostringstream message;
  message.precision(17);
  message << "fluidbed::" << function << ": result '" << result << "' = " << value << " is not finite for "
          << describe_arguments() << " (arguments in the domain, result out of the range of the floating type)";
  throw std::domain_error(message.str());
}

// The name of element `index` of an array argument, e.g. indexed_argument("fractions", 2)
// is "fractions[2]".
inline std::string indexed_argument(std::string_view array, std::size_t index) {
  return std::string(array) + '[' + std::to_string(index) + ']';
}

// Throws unless x is finite (any sign).
template <class T>
void require_finite(std::string_view function, std::string_view argument, const T& x) {
  if (!detail::is_finite_number(x)) detail::throw_domain_error(function, argument, x, "must be finite");
}

// Throws unless every element of `values` (an array, a span, a Vector3) is finite, naming the
// first that is not, e.g. "gravity[2]".
template <class Range>
void require_finite_elements(std::string_view function, std::string_view argument, const Range& values) {
  std::size_t index = 0;
  for (const auto& x : values) {
    if (!detail::is_finite_number(x))
      detail::throw_domain_error(function, indexed_argument(argument, index), x, "must be finite");
    ++index;
  }
}

// Throws unless x is finite and x > 0.
template <class T>
void require_positive(std::string_view function, std::string_view argument, const T& x) {
  if (!detail::is_finite_number(x) || !(x > 0))
    detail::throw_domain_error(function, argument, x, "must be finite and > 0");
}

// Throws unless x is finite and x >= 0.
template <class T>
void require_non_negative(std::string_view function, std::string_view argument, const T& x) {
  if (!detail::is_finite_number(x) || !(x >= 0))
    detail::throw_domain_error(function, argument, x, "must be finite and >= 0");
}

// Throws unless x is finite and lower < x <= upper.
template <class T>
void require_in_half_open(std::string_view function, std::string_view argument, const T& x, const T& lower,
                          const T& upper) {
  detail::require_in_interval(function, argument, x, lower, false, upper, true);
}

// Throws unless x is finite and lower <= x < upper.
template <class T>
void require_in_closed_open(std::string_view function, std::string_view argument, const T& x, const T& lower,
                            const T& upper) {
  detail::require_in_interval(function, argument, x, lower, true, upper, false);
}

// Throws unless x is finite and lower < x < upper.
template <class T>
void require_in_open(std::string_view function, std::string_view argument, const T& x, const T& lower, const T& upper) {
  detail::require_in_interval(function, argument, x, lower, false, upper, false);
}

// Throws unless x is finite and lower <= x <= upper.
template <class T>
void require_in_closed(std::string_view function, std::string_view argument, const T& x, const T& lower,
                       const T& upper) {
  detail::require_in_interval(function, argument, x, lower, true, upper, true);
}

}  // namespace fluidbed
