// The settling family's row tests (test_scalar_types_settling.hpp) in cpp_bin_float_50, with the same
// tolerances in units of the type's epsilon (5.3e-51) as in the built-in types: they hold only
// where every published coefficient is exact to 50 digits.
#include "test_scalar_types_50_digits.hpp"
#include "test_scalar_types_settling.hpp"

TEST_CASE_TEMPLATE_INVOKE(scalar_types_settling, fluidbed::test::Digits50);
