// Test helper for the scalar-type tests (tests/test_scalar_types_*.cpp): every family's
// closures are evaluated in float, double, long double and cpp_bin_float_50 and compared with
// the mpmath table tests/reference/scalar_types_reference.csv (written by
// scalar_types_reference.py), whose inputs every one of these types represents exactly and whose
// values have 55 significant digits. A result then differs from the table only by the rounding
// inside the closure, so the tolerances are multiples of the type's epsilon: the same multiple
// for the built-in types, 4 times it for the 50-digit one (tolerance_factor). The row tests of a
// family are defined once in test_scalar_types_<family>.hpp and invoked for the built-in types in
// test_scalar_types_<family>.cpp and for cpp_bin_float_50 in
// test_scalar_types_50_digits_<family>.cpp (files of their own, each compiling in about the time
// of the three built-in types together, so that two cores build them side by side).
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace fluidbed::test {

// The built-in types every family is tested in, for TEST_CASE_TEMPLATE_INVOKE (the 50-digit
// type has test files of its own).
#define FLUIDBED_SCALAR_TYPES float, double, long double

// The type a comparison in T is made in: long double for the built-in types (the table's value
// is then rounded once, to 64 bits), T itself for a wider type.
template <class T>
using Wide = std::conditional_t<std::is_floating_point_v<T>, long double, T>;

// A number of the table: its decimal text and that text in long double, which the tolerances
// and conditions are computed from (as a long double, implicitly).
struct Reference {
  long double approximation;
  std::string decimal;

  operator long double() const { return approximation; }  // NOLINT(google-explicit-constructor)

  // In T: the long double for a built-in type, the decimal parsed in T for a wider one.
  template <class T>
  T in() const {
    if constexpr (std::is_floating_point_v<T>)
      return T(approximation);
    else
      return T(decimal);
  }
};

// The multiple of the built-in types' tolerances that a type is allowed: 4 for a Boost.Multiprecision
// type, whose pow, exp and log are not correctly rounded (Boost 1.74, cpp_bin_float_50: pow(x, y)
// is off by up to about |y ln x| + 5 ε, 10 ε for pow(100, 0.75), where the built-in types' are
// within an ulp). A coefficient good to long double's 19 digits only is still 1e30 ε off.
template <class T>
inline constexpr long double tolerance_factor = std::is_floating_point_v<T> ? 1 : 4;

// One row of the table: a closure of a family at inputs p[0..7], its value and up to two
// partial derivatives (the meaning of each per family: scalar_types_reference.py).
struct ScalarTypeRow {
  std::size_t line;  // in the table, for the messages of a failing row
  std::string closure;
  std::array<long double, 8> p;
  Reference value;
  std::optional<Reference> d1, d2;

  // Input i in T: exact, the generator asserts that every input is a double (most have at most
  // 24 bits) and prints it exactly.
  template <class T>
  T in(std::size_t i) const {
    return T(p.at(i));
  }
};

inline const std::vector<ScalarTypeRow>& scalar_type_rows(const std::string& family) {
  static const std::map<std::string, std::vector<ScalarTypeRow>> table = [] {
    const std::string path = std::string(FLUIDBED_REFERENCE_DIR) + "/scalar_types_reference.csv";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open reference table " + path);
    std::map<std::string, std::vector<ScalarTypeRow>> rows;
    std::string line;
    std::getline(in, line);  // header: family,closure,p1..p8,value,d1,d2
    for (std::size_t number = 2; std::getline(in, line); ++number) {
      std::vector<std::string> cells;
      std::stringstream stream(line);
      std::string cell;
      while (std::getline(stream, cell, ',')) cells.push_back(cell);
      while (cells.size() < 13) cells.emplace_back();  // empty trailing derivatives
      ScalarTypeRow row;
      row.line = number;
      row.closure = cells[1];
      for (std::size_t i = 0; i < 8; ++i) row.p[i] = std::stold(cells[2 + i]);
      const auto reference = [](const std::string& text) { return Reference{std::stold(text), text}; };
      row.value = reference(cells[10]);
      if (!cells[11].empty()) row.d1 = reference(cells[11]);
      if (!cells[12].empty()) row.d2 = reference(cells[12]);
      rows[cells[0]].push_back(row);
    }
    return rows;
  }();
  return table.at(family);
}

// The rows of `family` whose closure is `closure`.
inline std::vector<ScalarTypeRow> scalar_type_rows(const std::string& family, const std::string& closure) {
  std::vector<ScalarTypeRow> selected;
  for (const ScalarTypeRow& row : scalar_type_rows(family))
    if (row.closure == closure) selected.push_back(row);
  return selected;
}

// |got − expected| in units of ε_T·scale (scale = |expected| by default: a relative error),
// computed in Wide<T>. The worst of these over a test is what its tolerance bounds; tests report it.
template <class T>
long double error_in_epsilons(const T& got, const Wide<T>& expected, const Wide<T>& scale) {
  using W = Wide<T>;
  using std::abs;
  const W difference = abs(W(got) - expected);
  if (difference == 0) return 0;
  const W floor = std::numeric_limits<W>::min();
  return static_cast<long double>(
      W(difference / (W(std::numeric_limits<T>::epsilon()) * (scale > floor ? scale : floor))));
}

template <class T>
long double error_in_epsilons(const T& got, const Wide<T>& expected) {
  using std::abs;
  return error_in_epsilons(got, expected, Wide<T>(abs(expected)));
}

// Against a number of the table, read in Wide<T>; the scale needs no more than long double.
template <class T>
long double error_in_epsilons(const T& got, const Reference& expected, long double scale) {
  return error_in_epsilons(got, expected.in<Wide<T>>(), Wide<T>(scale));
}

template <class T>
long double error_in_epsilons(const T& got, const Reference& expected) {
  const Wide<T> wide = expected.in<Wide<T>>();
  using std::abs;
  return error_in_epsilons(got, wide, Wide<T>(abs(wide)));
}

// std::isfinite for the built-in types, found by argument-dependent lookup for the others.
template <class T>
bool is_finite(const T& x) {
  using std::isfinite;
  return isfinite(x);
}

// The worst error of a test, and where it was, for its closing MESSAGE.
struct WorstError {
  long double epsilons = 0;
  std::string where;

  void record(long double e, const std::string& at) {
    if (e > epsilons) {
      epsilons = e;
      where = at;
    }
  }
};

}  // namespace fluidbed::test
