// The kinetic-theory family's row tests (test_scalar_types_kinetic_theory.hpp) in cpp_bin_float_50, in units of the
// type's epsilon (5.3e-51) with 4 times the built-in types' multiples (test::tolerance_factor):
// they hold only where every published coefficient is exact to 50 digits; one good to long
// double's 19 digits is 1e30 epsilons off.
#include "cpp_bin_float_50.hpp"
#include "test_scalar_types_kinetic_theory.hpp"

TEST_CASE_TEMPLATE_INVOKE(scalar_types_kinetic_theory_laws, boost::multiprecision::cpp_bin_float_50);
TEST_CASE_TEMPLATE_INVOKE(scalar_types_kinetic_theory_others, boost::multiprecision::cpp_bin_float_50);
