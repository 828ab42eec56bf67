// core/constants.hpp: each constant at the precision of the scalar type — the nearest float,
// double, long double and cpp_bin_float_50 (which parses 64 digits and rounds them once),
// against Boost.Math's constants, which are correctly rounded in each of these types; and a
// published decimal (FLUIDBED_DECIMAL) against the quotient of two integers in 50 digits.
#include <doctest/doctest.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <type_traits>

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

// The decimal n/m rounded once: in cpp_bin_float_50 the quotient of the integers, which Boost
// rounds correctly (a long double literal would be 1e-20 off); within an ulp in the built-in
// types (rounded to 64 bits, then to T).
TEST_CASE_TEMPLATE("constants: a published decimal is the decimal rounded to each floating type", T, float, double,
                   long double, cpp_bin_float_50) {
  const auto check = [](const T& got, int numerator, int denominator) {
    const cpp_bin_float_50 exact = cpp_bin_float_50(numerator) / denominator;
    INFO(numerator << "/" << denominator);
    if constexpr (std::is_same_v<T, cpp_bin_float_50>)
      CHECK(got == exact);
    else
      CHECK(abs(cpp_bin_float_50(got) - exact) <= std::numeric_limits<T>::epsilon() * exact);
  };
  check(FLUIDBED_DECIMAL(T, 0.175), 175, 1000);
  check(FLUIDBED_DECIMAL(T, 4.8), 48, 10);
  check(FLUIDBED_DECIMAL(T, 9.81), 981, 100);
  check(FLUIDBED_DECIMAL(T, 4.515439), 4515439, 1000000);
  check(FLUIDBED_DECIMAL(T, 0.00001), 1, 100000);
}
