// Boost's 50-digit type for the tests that take it as a template argument, and its name in their
// test-case names ("<cpp_bin_float_50>"): every translation unit that names it in a test case
// includes this header, so that the name is the same in all of them.
#pragma once

#include <doctest/doctest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

DOCTEST_TYPE_TO_STRING_AS("cpp_bin_float_50", boost::multiprecision::cpp_bin_float_50);
