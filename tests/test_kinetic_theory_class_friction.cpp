// The frictional pressure split among solids classes by mass fraction (seed 004, slide
// "Frictional transfer"; kinetic_theory/friction.hpp ClassFrictionalPressures). References: the
// closed form of Johnson–Jackson's p^f at seed 004's constants (Fr = 0.005, exponents 2 and 5,
// φ_max = 0.64; the values are exact decimals, e.g. 0.005·0.08²/0.01⁵ = 320000 Pa), the identities
// Σ p_i^f = p^f(φ_t) and p_1^f = p^f for one class, the derivative written out by hand, and
// central finite differences.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fluidbed/kinetic_theory.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

namespace {

// Seed 004's Johnson–Jackson constants with the onset φ_min.
JohnsonJacksonPressure seed_004_law(double min_fraction) { return {min_fraction, 0.64, 0.005, 2.0, 5.0}; }

double sum(const auto& values) {
  double s = 0;
  for (const double v : values) s += v;
  return s;
}

}  // namespace

TEST_CASE("class frictional pressures: one class gets the law itself, exactly") {
  for (const double min_fraction : {0.5, 0.55, 0.6})
    for (const double phi : {0.3, 0.55, 0.56, 0.6, 0.62, 0.63, 0.635, 0.7}) {
      const JohnsonJacksonPressure law = seed_004_law(min_fraction);
      const ClassFrictionalPressures<JohnsonJacksonPressure> split{law};
      CHECK(split(std::array{phi}, std::array{2500.0})[0] == law(phi));
      const auto d = split.with_derivatives(std::array{phi}, std::array{2500.0});
      CHECK(d.value[0] == law(phi));
      CHECK(d.d_fractions[0][0] == doctest::Approx(law.with_derivatives(phi).d_solid_fraction).epsilon(1e-14));
    }
  const ClassFrictionalPressures<SchaefferPressure> schaeffer{SchaefferPressure{0.5}};
  CHECK(schaeffer(std::array{0.58}, std::array{1000.0})[0] == SchaefferPressure{0.5}(0.58));
}

TEST_CASE("class frictional pressures: seed 004's values, split by mass fraction, sum to the total") {
  struct Row {
    double min_fraction, total_fraction, pressure;  // p^f at seed 004's constants [Pa]
  };
  const Row rows[] = {{0.55, 0.56, 0.152587890625}, {0.55, 0.60, 122.0703125}, {0.55, 0.62, 7656.25},
                      {0.55, 0.63, 320000.0},       {0.60, 0.60, 0.0},          {0.60, 0.62, 625.0},
                      {0.60, 0.63, 45000.0}};
  const std::array<double, 3> densities{2500.0, 1000.0, 7800.0};  // sand, biomass, steel
  for (const Row& row : rows)
    for (const std::array<double, 3>& shares : {std::array{0.5, 0.3, 0.2}, std::array{0.9, 0.1, 0.0}}) {
      INFO("phi_min " << row.min_fraction << ", phi_t " << row.total_fraction);
      std::array<double, 3> fractions{};
      double mass = 0;
      for (std::size_t i = 0; i < 3; ++i) fractions[i] = shares[i] * row.total_fraction, mass += fractions[i] * densities[i];
      const ClassFrictionalPressures<JohnsonJacksonPressure> split{seed_004_law(row.min_fraction)};
      const std::array<double, 3> p = split.checked(fractions, densities);
      const double total = split.total(sum(fractions));
      CHECK(total == doctest::Approx(row.pressure).epsilon(1e-12));
      CHECK(std::abs(sum(p) - total) <= 4 * std::numeric_limits<double>::epsilon() * total);  // to rounding
      for (std::size_t i = 0; i < 3; ++i) {
        CHECK(p[i] >= 0);  // pressure-positive, as every pressure of the library
        CHECK(p[i] == doctest::Approx(fractions[i] * densities[i] / mass * row.pressure).epsilon(1e-12));
      }
    }
}

TEST_CASE("class frictional pressures: derivatives in every class fraction") {
  const JohnsonJacksonPressure law = seed_004_law(0.55);
  const ClassFrictionalPressures<JohnsonJacksonPressure> split{law};
  const std::array<double, 3> fractions{0.3, 0.2, 0.115}, densities{2500.0, 1000.0, 7800.0};
  const auto d = split.checked_with_derivatives(fractions, densities);
  const double phi_t = sum(fractions), p = law(phi_t), slope = law.with_derivatives(phi_t).d_solid_fraction;
  double mass = 0;
  for (std::size_t i = 0; i < 3; ++i) mass += fractions[i] * densities[i];
  const double h = 1e-7;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t m = 0; m < 3; ++m) {
      INFO("class " << i << ", fraction " << m);
      // ∂p_i/∂φ_m = (ρ_m/M)(δ_im − x_i) p + x_i dp/dφ_t
      const double x = fractions[i] * densities[i] / mass;
      const double by_hand = densities[m] / mass * ((i == m ? 1.0 : 0.0) - x) * p + x * slope;
      CHECK(d.d_fractions[i][m] == doctest::Approx(by_hand).epsilon(1e-13));
      std::array<double, 3> up = fractions, down = fractions;
      up[m] += h, down[m] -= h;
      const double fd = (split(up, densities)[i] - split(down, densities)[i]) / (2 * h);
      CHECK(d.d_fractions[i][m] == doctest::Approx(fd).epsilon(1e-6));
    }
  // Moving solids from one class to another at fixed φ_t moves pressure, not its total.
  for (std::size_t i = 0; i < 3; ++i) {
    double column = 0;
    for (std::size_t k = 0; k < 3; ++k) column += d.d_fractions[k][i] - d.d_fractions[k][0];
    CHECK(std::abs(column) <= 1e-9 * slope);
  }
}

TEST_CASE("class frictional pressures: below the onset and without solids, zero and no NaN") {
  const ClassFrictionalPressures<JohnsonJacksonPressure> split{seed_004_law(0.6)};
  const std::array<double, 2> densities{2500.0, 1000.0};
  for (const auto& fractions : {std::array{0.0, 0.0}, std::array{0.3, 0.2}, std::array{0.0, 0.59}}) {
    const auto d = split.with_derivatives(fractions, densities);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(d.value[i] == 0);
      for (std::size_t m = 0; m < 2; ++m) CHECK(d.d_fractions[i][m] == 0);
    }
  }
}

TEST_CASE("class frictional pressures in float and long double") {
  const ClassFrictionalPressures<JohnsonJacksonPressure> split{seed_004_law(0.55)};
  const auto f = split(std::array{0.3f, 0.32f}, std::array{2500.0f, 1000.0f});
  const auto l = split(std::array{0.3L, 0.32L}, std::array{2500.0L, 1000.0L});
  const auto d = split(std::array{0.3, 0.32}, std::array{2500.0, 1000.0});
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(static_cast<double>(f[i]) == doctest::Approx(d[i]).epsilon(1e-4));
    CHECK(static_cast<double>(l[i]) == doctest::Approx(d[i]).epsilon(1e-13));
  }
}

TEST_CASE("class frictional pressures: checked forms name the argument out of its domain") {
  const ClassFrictionalPressures<JohnsonJacksonPressure> split{seed_004_law(0.55)};
  const std::array<double, 2> densities{2500.0, 1000.0};
  CHECK_THROWS_WITH_AS(split.checked(std::array{0.3, -0.1}, densities),
                       doctest::Contains("kinetic_theory::ClassFrictionalPressures: argument 'fractions[1]' = -0.1"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(split.checked(std::array{0.3, 0.1}, std::array{0.0, 1000.0}),
                       doctest::Contains("'densities[0]' = 0"), std::domain_error);
  CHECK_THROWS_WITH_AS(split.checked_with_derivatives(std::array{0.6, 0.4}, densities),
                       doctest::Contains("'sum of fractions' = 1"), std::domain_error);
  const ClassFrictionalPressures<JohnsonJacksonPressure> bad{JohnsonJacksonPressure{0.7, 0.64}};
  CHECK_THROWS_WITH_AS(bad.checked(std::array{0.3, 0.1}, densities), doctest::Contains("'min_fraction'"),
                       std::domain_error);
  CHECK_NOTHROW(split.checked(std::array{0.3, 0.3}, densities));
}
