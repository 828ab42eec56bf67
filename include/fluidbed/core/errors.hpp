// fluidbed — argument validation for the checked entry points.
//
// The hot path (per-cell calls) states its preconditions and asserts them in debug
// builds only. The checked entry points call these helpers, which throw
// std::domain_error with the function, the argument's name and its offending value.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fluidbed {

namespace detail {

template <class T>
[[noreturn]] void throw_domain_error(std::string_view function, std::string_view argument,
                                     const T& value, std::string_view requirement) {
  std::ostringstream message;
  message.precision(17);
  message << "fluidbed::" << function << ": argument '" << argument << "' = " << value
          << " is out of domain (" << requirement << ")";
  throw std::domain_error(message.str());
}

template <class T>
bool is_finite_number(const T& x) {
  using std::isfinite;
  return isfinite(x);
}

}  // namespace detail

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
void require_in_half_open(std::string_view function, std::string_view argument, const T& x,
                          const T& lower, const T& upper) {
  if (!detail::is_finite_number(x) || !(x > lower) || !(x <= upper)) {
    std::ostringstream range;
    range.precision(17);
    range << "must lie in (" << lower << ", " << upper << "]";
    detail::throw_domain_error(function, argument, x, range.str());
  }
}

// Throws unless x is finite and lower < x < upper.
template <class T>
void require_in_open(std::string_view function, std::string_view argument, const T& x,
                     const T& lower, const T& upper) {
  if (!detail::is_finite_number(x) || !(x > lower) || !(x < upper)) {
    std::ostringstream range;
    range.precision(17);
    range << "must lie in (" << lower << ", " << upper << ")";
    detail::throw_domain_error(function, argument, x, range.str());
  }
}

}  // namespace fluidbed
