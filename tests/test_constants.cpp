// core/constants.hpp: each constant at the precision of the scalar type — the nearest float,
// double, long double and cpp_bin_float_50 (which parses 64 digits and rounds them once),
// against Boost.Math's constants, which are correctly rounded in each of these types.
#include <doctest/doctest.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "cpp_bin_float_50.hpp"
#include "fluidbed/core/constants.hpp"

using boost::multiprecision::cpp_bin_float_50;
namespace bmc = boost::math::constants;

TEST_CASE_TEMPLATE("constants: the nearest value of each floating type", T, float, double, long double,
                   cpp_bin_float_50) {
  CHECK(fluidbed::numbers::pi<T>() == bmc::pi<T>());
  CHECK(fluidbed::numbers::sqrt_pi<T>() == bmc::root_pi<T>());
  CHECK(fluidbed::numbers::sqrt2<T>() == bmc::root_two<T>());
  CHECK(fluidbed::numbers::sqrt3<T>() == bmc::root_three<T>());
  CHECK(fluidbed::numbers::ln10<T>() == bmc::ln_ten<T>());
}

TEST_CASE("constants: a long double value in a 50-digit type is 1e-20 off") {
  CHECK(abs(cpp_bin_float_50(fluidbed::numbers::pi<long double>()) - bmc::pi<cpp_bin_float_50>()) > 1e-25);
}
