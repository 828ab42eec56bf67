// The Haider–Levenspiel (1989) terminal velocity against its independent mpmath reference
// (tests/reference/haider_levenspiel_reference.py evaluates the paper's d*, u* form for a
// dimensional system; the library evaluates the reduced Re_t = Ar/(18 + c√Ar)), in float, double
// and long double at inputs exact in all three. Everything else the law must satisfy (name,
// lookup, checked messages, derivatives against finite differences, its catalogue entry) is
// tested by the registry-driven tests, which found it in TerminalVelocities.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "fluidbed/single_particle/terminal_velocity.hpp"
#include "reference_table.hpp"
#include "same_arithmetic.hpp"

using fluidbed::single_particle::HaiderLevenspielTerminalVelocity;

TEST_CASE_TEMPLATE("Haider-Levenspiel: Re_t and dRe_t/dAr agree with mpmath to a few eps of the type", T, float,
                   double, long double) {
  const fluidbed::test::ReferenceTable table("haider_levenspiel_reference.csv");
  REQUIRE(table.size() == 66);
  const T eps = std::numeric_limits<T>::epsilon();
  for (std::size_t row = 0; row < table.size(); ++row) {
    const HaiderLevenspielTerminalVelocity law(table.number(row, "sphericity"));
    // Every input is a power of two (or 0): exact in T through stold.
    const T archimedes = T(std::stold(table.text(row, "archimedes")));
    const T expected = T(std::stold(table.text(row, "terminal_reynolds")));
    const T expected_slope = T(std::stold(table.text(row, "d_terminal_reynolds_d_archimedes")));
    INFO("sphericity ", table.text(row, "sphericity"), ", Ar = ", table.text(row, "archimedes"));
    const auto result = law.with_derivatives(archimedes);
    CHECK(fluidbed::test::same_arithmetic(law.reynolds(archimedes), result.value));
    CHECK(std::abs(result.value - expected) <= 4 * eps * expected);
    CHECK(std::abs(result.d_archimedes - expected_slope) <= 8 * eps * expected_slope);
  }
}

TEST_CASE("Haider-Levenspiel: a sphericity outside the fit's 0.5-1 is refused by the checked path") {
  CHECK_THROWS_WITH_AS(HaiderLevenspielTerminalVelocity(0.4).checked_reynolds(10.0),
                       doctest::Contains("fluidbed::HaiderLevenspielTerminalVelocity: argument 'sphericity' = 0.4"),
                       std::domain_error);
  CHECK_NOTHROW(HaiderLevenspielTerminalVelocity(0.5L).checked_reynolds(10.0));
}
