// The 50-digit type of the scalar-type tests (tests/test_scalar_types_50_digits_*.cpp), and its
// name in the test-case names.
#pragma once

#include <doctest/doctest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace fluidbed::test {
using Digits50 = boost::multiprecision::cpp_bin_float_50;
}  // namespace fluidbed::test

DOCTEST_TYPE_TO_STRING_AS("cpp_bin_float_50", fluidbed::test::Digits50);
