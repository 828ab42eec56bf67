// fluidbed — the checked entry points' exceptions (host only).
//
// The hot path (per-cell calls) states its preconditions and asserts them in debug builds
// only (domain.hpp). The checked entry points validate the same domains with these helpers,
// which throw std::domain_error with the function, the argument's name and its offending value:
//   fluidbed::<function>: argument '<argument>' = <value> is out of domain (<requirement>)
// Every helper rejects NaN and ±∞. require_finite_result checks a result the same way.
// Numbers are written with 17 significant digits (std::to_chars), without <sstream>.
//
// The only header of the library that throws (tests/check_layering.py checks it). The family
// bases' checked members, which call these helpers, are host functions beside the
// FLUIDBED_HOST_DEVICE hot paths of the same closures; device code instantiates the hot paths
// only, and nvcc reports a host function reached from device code, so the CUDA build of every
// registry's closures (tests/cuda/, every warning an error) shows that no device path reaches
// this header's code.
#pragma once

#include "config.hpp"  // first: its C++20 check precedes any C++20-only header

#include <charconv>
#include <concepts>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "domain.hpp"
#include "parameters.hpp"

namespace fluidbed {

namespace detail {

// x as text: integers exactly, floating-point numbers with 17 significant digits ("%.17g"),
// any other scalar (Boost.Multiprecision) through long double.
template <class T>
std::string number_text(const T& x) {
  if constexpr (std::integral<T>) {
    return std::to_string(x);
  } else if constexpr (std::floating_point<T>) {
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, 17).ptr;
    return std::string(buffer, end);
  } else {
    return number_text(static_cast<long double>(x));
  }
}

// The wording of an interval in a message: "must be finite", "must be finite and > 0",
// "must lie in (0, 1]".
template <class T>
std::string requirement_text(const Interval<T>& domain) {
  const bool unbounded_below = domain.lower == -std::numeric_limits<T>::infinity();
  const bool unbounded_above = domain.upper == std::numeric_limits<T>::infinity();
  if (unbounded_below && unbounded_above) return "must be finite";
  if (unbounded_above) return std::string("must be finite and ") + (domain.lower_closed ? ">= " : "> ") + number_text(domain.lower);
  if (unbounded_below) return std::string("must be finite and ") + (domain.upper_closed ? "<= " : "< ") + number_text(domain.upper);
  return std::string("must lie in ") + (domain.lower_closed ? '[' : '(') + number_text(domain.lower) + ", " +
         number_text(domain.upper) + (domain.upper_closed ? ']' : ')');
}

template <class T>
[[noreturn]] void throw_domain_error(std::string_view function, std::string_view argument, const T& value,
                                     std::string_view requirement) {
  throw std::domain_error("fluidbed::" + std::string(function) + ": argument '" + std::string(argument) +
                          "' = " + number_text(value) + " is out of domain (" + std::string(requirement) + ")");
}

// A registry's make() of a name it does not list (registry.hpp).
[[noreturn]] inline void throw_unknown_closure(std::string_view what, std::string_view name, std::string_view known) {
  throw std::invalid_argument("fluidbed: unknown " + std::string(what) + " '" + std::string(name) +
                              "'; known: " + std::string(known));
}

template <class T>
bool is_finite_number(const T& x) {
  return x - x == T(0);
}

}  // namespace detail

// Throws std::domain_error naming the first argument outside its interval: the checked form
// of the hot path's FLUIDBED_EXPECTS(within(list)).
template <class T, std::size_t N>
void require_within(std::string_view function, const Arguments<T, N>& list) {
  for (const Argument<T>& argument : list)
    if (!argument.domain.contains(argument.value))
      detail::throw_domain_error(function, argument.name, argument.value,
                                 argument.requirement == nullptr ? detail::requirement_text(argument.domain)
                                                                : std::string(argument.requirement));
}

// Throws unless x lies in `domain` (one argument).
template <class T>
void require_in(std::string_view function, std::string_view argument, const T& x, const Interval<T>& domain) {
  if (!domain.contains(x)) detail::throw_domain_error(function, argument, x, detail::requirement_text(domain));
}

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
  throw std::domain_error("fluidbed::" + std::string(function) + ": result '" + std::string(result) + "' = " +
                          detail::number_text(value) + " is not finite for " + std::string(describe_arguments()) +
                          " (arguments in the domain, result out of the range of the floating type)");
}

// The arguments of a list as text, "name = value, name = value", for the messages of
// require_finite_result.
template <class T, std::size_t N>
std::string describe(const Arguments<T, N>& list) {
  std::string text;
  for (const Argument<T>& argument : list)
    text += (text.empty() ? "" : ", ") + std::string(argument.name) + " = " + detail::number_text(argument.value);
  return text;
}

// Error policies, for the functions that are not closures of a family (relations, solvers,
// the bed-expansion and stability helpers): one entry point whose last argument picks what
// happens to arguments outside their domain, in the manner of Boost.Math's policies,
//   bed_height(h0, e0, e)                       hot path: asserted in debug builds;
//   bed_height(h0, e0, e, fluidbed::checked)    throws std::domain_error.
// (Closures have the member .checked(...) instead, from their family's base.)
struct Unchecked {};
struct Checked {};
inline constexpr Unchecked unchecked{};
inline constexpr Checked checked{};

template <class Policy>
concept ErrorPolicy = std::same_as<Policy, Unchecked> || std::same_as<Policy, Checked>;

// The domain check of an entry point under `Policy`. The names (here and in check_result) are
// taken as given (a C string, a string_view) and read only on the checked path: the hot path
// runs in device code, where nvcc compiles a std::string_view made from a C string to undefined
// behaviour (core/domain.hpp, Argument).
template <ErrorPolicy Policy, class Name, class T, std::size_t N>
constexpr void check_domain(Policy, const Name& function, const Arguments<T, N>& list) {
  if constexpr (std::same_as<Policy, Checked>)
    require_within(function, list);
  else
    FLUIDBED_EXPECTS(within(list));
}

// The result check of an entry point under `Policy`: the checked path throws unless the
// result is finite (require_finite_result); the hot path returns it as it is.
template <ErrorPolicy Policy, class Name, class Result, class T, class DescribeArguments>
constexpr void check_result(Policy, const Name& function, const Result& result, const T& value,
                            const DescribeArguments& describe_arguments) {
  if constexpr (std::same_as<Policy, Checked>) require_finite_result(function, result, value, describe_arguments);
}

// The name of element `index` of an array argument, e.g. indexed_argument("fractions", 2)
// is "fractions[2]".
inline std::string indexed_argument(std::string_view array, std::size_t index) {
  return std::string(array) + '[' + std::to_string(index) + ']';
}

// Throws unless x is finite (any sign).
template <class T>
void require_finite(std::string_view function, std::string_view argument, const T& x) {
  require_in(function, argument, x, domains::finite<T>());
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
  require_in(function, argument, x, domains::positive<T>());
}

// Throws unless x is finite and x >= 0.
template <class T>
void require_non_negative(std::string_view function, std::string_view argument, const T& x) {
  require_in(function, argument, x, domains::non_negative<T>());
}

// Throws unless x is finite and lower < x <= upper.
template <class T>
void require_in_half_open(std::string_view function, std::string_view argument, const T& x, const T& lower,
                          const T& upper) {
  require_in(function, argument, x, domains::half_open(lower, upper));
}

// Throws unless x is finite and lower < x < upper.
template <class T>
void require_in_open(std::string_view function, std::string_view argument, const T& x, const T& lower, const T& upper) {
  require_in(function, argument, x, domains::open(lower, upper));
}

// The names of a closure type's parameters, comma-separated ("none" without any), for messages.
template <class Law>
std::string parameter_names() {
  std::string names;
  for (const auto& p : parameters_of<Law>()) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names.empty() ? "none" : names;
}

// Sets `law`'s parameter `name` to `value` and validates the law's parameters at once: throws
// std::invalid_argument where the law has no such parameter (naming those it has), and
// std::domain_error, as the checked entry points do, where the value leaves the parameters'
// domain; `law` is unchanged when it throws.
template <class Law>
void set_parameter_checked(Law& law, std::string_view name, double value) {
  Law changed = law;
  if (!set_parameter(changed, name, value))
    throw std::invalid_argument("fluidbed: " + std::string(law.name()) + " has no parameter '" + std::string(name) +
                                "'; its parameters: " + parameter_names<Law>());
  require_within(changed.name(), parameter_domain_in_double(changed));
  law = changed;
}

}  // namespace fluidbed
