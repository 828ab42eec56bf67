// Test helper for the out-of-domain tests (tests/test_out_of_domain_*.cpp): every checked
// entry point is described once, as its arguments (name in the message, a valid value, the
// out-of-domain values, the valid boundary values) and a call on a flat list of values, and
// check_entry_point tries every argument with every bad value, in the scalar type T (double by
// default; every value below is exact in float, so the messages read the same in each type).
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluidbed/properties.hpp"

namespace fluidbed::test {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
inline constexpr double inf = std::numeric_limits<double>::infinity();

// An out-of-domain value and how the library's message prints it (values chosen to print
// exactly at the message's 17 significant digits).
struct Bad {
  double value;
  const char* shown;
};

// `extra` and the three non-finite values, which every argument rejects.
inline std::vector<Bad> and_non_finite(std::initializer_list<Bad> extra) {
  std::vector<Bad> all(extra);
  all.insert(all.end(), {{nan, "nan"}, {inf, "inf"}, {-inf, "-inf"}});
  return all;
}

inline const std::vector<Bad> non_finite = and_non_finite({});
inline const std::vector<Bad> not_positive = and_non_finite({{0.0, "0"}, {-1.0, "-1"}});  // sizes, densities, …
inline const std::vector<Bad> negative = and_non_finite({{-1.0, "-1"}, {-0.5, "-0.5"}});
inline const std::vector<Bad> outside_voidage = and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {1.5, "1.5"}});  // (0, 1]
inline const std::vector<Bad> outside_solid_fraction = and_non_finite({{-0.5, "-0.5"}, {1.0, "1"}, {1.5, "1.5"}});
inline const std::vector<Bad> outside_open_unit =
    and_non_finite({{0.0, "0"}, {1.0, "1"}, {-0.5, "-0.5"}, {1.5, "1.5"}});
inline const std::vector<Bad> outside_closed_unit = and_non_finite({{-0.5, "-0.5"}, {1.5, "1.5"}});

// One argument of a checked entry point.
struct ArgumentCase {
  std::string name;                // as the message names it, e.g. "fluid.density"
  double valid;                    // a value inside the domain
  std::vector<Bad> invalid;        // each must be rejected, naming this argument and the value
  std::vector<double> edges = {};  // valid boundary values (ε = 1, zero slip, …): accepted, finite result
};

// The arguments' values, in the order of the entry point's `arguments`, in the scalar type T.
template <class T>
using ValuesOf = std::vector<T>;
using Values = ValuesOf<double>;

// A law's parameter: a double member whatever the scalar type of the state.
template <class T>
double parameter(const ValuesOf<T>& v, std::size_t at) {
  return double(v[at]);
}

// `head` followed by `tail`: the arguments of an entry point assembled from shared groups.
inline std::vector<ArgumentCase> concatenated(std::vector<ArgumentCase> head, const std::vector<ArgumentCase>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

// A fluid from values[at], values[at + 1] (ρ_f, μ_f) and particles from the next two (ρ_p, d).
template <class T>
Fluid<T> fluid_of(const ValuesOf<T>& values, std::size_t at) {
  return {values[at], values[at + 1]};
}
template <class T>
Particles<T> particles_of(const ValuesOf<T>& values, std::size_t at) {
  return {values[at + 2], values[at + 3]};
}

// With every argument valid, and with each edge value in turn, the call returns a finite
// value; with each invalid value in turn it throws std::domain_error whose message contains
// "'<name>' = <value>". `call` maps the values (in the order of `arguments`, in T) to a number.
template <class T = double, class Call>
void check_entry_point(const std::string& label, const std::vector<ArgumentCase>& arguments, const Call& call) {
  INFO("entry point: ", label);
  ValuesOf<T> valid;
  for (const ArgumentCase& a : arguments) valid.push_back(T(a.valid));
  T result = std::numeric_limits<T>::quiet_NaN();
  CHECK_NOTHROW(result = call(valid));
  CHECK(std::isfinite(result));
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    for (const Bad& bad : arguments[i].invalid) {
      ValuesOf<T> values = valid;
      values[i] = T(bad.value);
      const std::string expected = "'" + arguments[i].name + "' = " + bad.shown;
      INFO("expected in the message: ", expected);
      CHECK_THROWS_WITH_AS(call(values), doctest::Contains(expected.c_str()), std::domain_error);
    }
    for (const double edge : arguments[i].edges) {
      ValuesOf<T> values = valid;
      values[i] = T(edge);
      INFO("valid edge of ", arguments[i].name, ": ", edge);
      T at_edge = std::numeric_limits<T>::quiet_NaN();
      CHECK_NOTHROW(at_edge = call(values));
      CHECK(std::isfinite(at_edge));
    }
  }
}

// The message of what `call` throws as std::domain_error ("" if nothing is thrown).
template <class Call>
std::string domain_error_message(const Call& call) {
  try {
    call();
  } catch (const std::domain_error& error) {
    return error.what();
  }
  return "";
}

}  // namespace fluidbed::test
