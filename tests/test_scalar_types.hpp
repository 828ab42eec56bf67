// Test helper for the scalar-type tests (tests/test_scalar_types_*.cpp): every family's
// closures are evaluated in float, double and long double and compared with the mpmath table
// tests/reference/scalar_types_reference.csv (written by scalar_types_reference.py), whose
// inputs every one of the three types represents exactly and whose values have 25 digits. A
// result then differs from the table only by the rounding inside the closure, so the
// tolerances are multiples of the type's epsilon: the same multiple for the three types.
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
#include <vector>

namespace fluidbed::test {

// The types every family is tested in, for TEST_CASE_TEMPLATE.
#define FLUIDBED_SCALAR_TYPES float, double, long double

// One row of the table: a closure of a family at inputs p[0..7], its value and up to two
// partial derivatives (the meaning of each per family: scalar_types_reference.py).
struct ScalarTypeRow {
  std::string closure;
  std::array<long double, 8> p;
  long double value;
  std::optional<long double> d1, d2;

  // Input i in T: exact, the generator asserts that every input has at most 24 bits.
  template <class T>
  T in(std::size_t i) const {
    return T(p.at(i));
  }
};

// The rows of one family, read once (long double: the values have 25 significant digits).
inline const std::vector<ScalarTypeRow>& scalar_type_rows(const std::string& family) {
  static const std::map<std::string, std::vector<ScalarTypeRow>> table = [] {
    const std::string path = std::string(FLUIDBED_REFERENCE_DIR) + "/scalar_types_reference.csv";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open reference table " + path);
    std::map<std::string, std::vector<ScalarTypeRow>> rows;
    std::string line;
    std::getline(in, line);  // header: family,closure,p1..p8,value,d1,d2
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::stringstream stream(line);
      std::string cell;
      while (std::getline(stream, cell, ',')) cells.push_back(cell);
      while (cells.size() < 13) cells.emplace_back();  // empty trailing derivatives
      ScalarTypeRow row;
      row.closure = cells[1];
      for (std::size_t i = 0; i < 8; ++i) row.p[i] = std::stold(cells[2 + i]);
      row.value = std::stold(cells[10]);
      if (!cells[11].empty()) row.d1 = std::stold(cells[11]);
      if (!cells[12].empty()) row.d2 = std::stold(cells[12]);
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

// |got − expected| in units of ε_T·scale (scale = |expected| by default: a relative error).
// The worst of these over a test is what its tolerance bounds; tests report it.
template <class T>
long double error_in_epsilons(const T& got, long double expected, long double scale) {
  if (static_cast<long double>(got) == expected) return 0;
  return std::abs(static_cast<long double>(got) - expected) /
         (static_cast<long double>(std::numeric_limits<T>::epsilon()) *
          std::max(scale, std::numeric_limits<long double>::min()));
}

template <class T>
long double error_in_epsilons(const T& got, long double expected) {
  return error_in_epsilons(got, expected, std::abs(expected));
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
