// core/constants.hpp: each constant at the precision of the scalar type — the nearest float,
// double and long double, and 64 digits for a type that parses decimal strings (a 50-digit
// Boost.Multiprecision type), against Boost.Math's constants and mpmath-free exact identities.
#include <doctest/doctest.h>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

#include "fluidbed/core/constants.hpp"

using boost::multiprecision::cpp_bin_float_50;
namespace bmc = boost::math::constants;

TEST_CASE_TEMPLATE("constants: the nearest value of each built-in floating type", T, float, double, long double) {
  CHECK(fluidbed::numbers::pi<T>() == bmc::pi<T>());
  CHECK(fluidbed::numbers::sqrt_pi<T>() == bmc::root_pi<T>());
  CHECK(fluidbed::numbers::sqrt2<T>() == bmc::root_two<T>());
  CHECK(fluidbed::numbers::sqrt3<T>() == bmc::root_three<T>());
  CHECK(fluidbed::numbers::ln10<T>() == bmc::ln_ten<T>());
}

TEST_CASE("constants: 50-digit accuracy in a 50-digit type, not long double's 19") {
  using T = cpp_bin_float_50;
  const T tolerance = T(1e-49);
  CHECK(abs(fluidbed::numbers::pi<T>() - bmc::pi<T>()) < tolerance);
  CHECK(abs(fluidbed::numbers::sqrt_pi<T>() - bmc::root_pi<T>()) < tolerance);
  CHECK(abs(fluidbed::numbers::sqrt2<T>() - bmc::root_two<T>()) < tolerance);
  CHECK(abs(fluidbed::numbers::sqrt3<T>() - bmc::root_three<T>()) < tolerance);
  CHECK(abs(fluidbed::numbers::ln10<T>() - bmc::ln_ten<T>()) < tolerance);
  // A long double value would be off by ~1e-20.
  CHECK(abs(T(fluidbed::numbers::pi<long double>()) - bmc::pi<T>()) > T(1e-25));
}
