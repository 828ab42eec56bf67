// The settling family in float, double and long double: the row test of
// test_scalar_types_settling.hpp against the mpmath table, and the switches and the calibrated
// Syamlal–O'Brien law in each type.
#include "test_scalar_types_settling.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <utility>

#include "fluidbed/drag/syamlal_obrien.hpp"
#include "fluidbed/fluidization.hpp"
#include "fluidbed/settling.hpp"

using namespace fluidbed;
using namespace fluidbed::settling;
using namespace fluidbed::test::settling_rows;

TEST_CASE_TEMPLATE_INVOKE(scalar_types_settling, FLUIDBED_SCALAR_TYPES);

// Richardson & Zaki (1954) switch at Re_t = 0.2, 1, 200 and 500: each band includes its lower
// end, in every type (0.2L lies below the double 0.2: compared with it, a long double
// Re_t = 0.2 took the band below).
TEST_CASE_TEMPLATE("Richardson-Zaki 1954: each band starts at its switch in the argument's type", T,
                   FLUIDBED_SCALAR_TYPES) {
  const double wall = 0;
  CHECK(settling::RichardsonZaki1954Exponent{wall}(T(0.2L)) == T(4.35L) * std::pow(T(0.2L), T(-0.03L)));
  CHECK(settling::RichardsonZaki1954Exponent{wall}(std::nextafter(T(0.2L), T(0))) == T(4.65L));
  CHECK(settling::RichardsonZaki1954Exponent{wall}(T(1)) == T(4.45L));
  CHECK(settling::RichardsonZaki1954Exponent{wall}(T(500)) == T(2.39L));
}

// Syamlal–O'Brien calibrated from a minimum fluidization state (u_mf, ε_mf) holds the bed at
// ε_mf at u_mf (its documented property), below and above the switch at ε = 0.85; the
// parameters c1, d1 are computed in T.
TEST_CASE_TEMPLATE("Syamlal-O'Brien calibrated from minimum fluidization holds the bed at that voidage", T,
                   FLUIDBED_SCALAR_TYPES) {
  const Fluid<T> water{T(1000), T(9.765625e-4L)};
  const Particles<T> sand{T(2500), T(2.44140625e-4L)};
  for (const auto& state : {std::pair{T(0.4375L), T(0.001953125L)}, std::pair{T(0.875L), T(0.015625L)}}) {
    const T voidage = state.first, velocity = state.second;  // clang < 16 captures no structured binding
    const drag::SyamlalOBrien law =
        fluidization::syamlal_obrien_from_minimum_fluidization(velocity, voidage, water, sand);
    INFO("eps_mf " << double(voidage) << ": c1 " << law.c1() << ", d1 " << law.d1());
    const T equilibrium = required(fluidization::equilibrium_voidage(law, velocity, water, sand));
    CHECK(test::error_in_epsilons(equilibrium, static_cast<long double>(voidage)) <= chained_tolerance<T>);
  }
}
