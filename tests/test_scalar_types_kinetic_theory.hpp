// The row tests of the kinetic-theory family against the mpmath table of
// scalar_types_reference.py, for every scalar type (inputs exact in every type, 55-digit
// values): every one-class radial distribution and every law(φ, Θ, g0, material) of the
// registries (by the tables' names, tests/kinetic_theory_table_names.hpp), with ∂/∂φ and ∂/∂Θ
// through Dual<T, 2>; the frictional pressures and viscosity, the gas exchange, the algebraic
// granular temperature, the mixture radial distributions and the solid–solid drag. Defined here,
// invoked for the built-in types by test_scalar_types_kinetic_theory.cpp and for
// cpp_bin_float_50 by test_scalar_types_50_digits_kinetic_theory.cpp.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <span>
#include <string>

#include "fluidbed/kinetic_theory.hpp"
#include "kinetic_theory_table_names.hpp"
#include "same_arithmetic.hpp"
#include "test_scalar_types.hpp"

namespace fluidbed::test::kinetic_theory_rows {

// Each value is a few dozen roundings of its exact inputs: 16 ε of the type (64 ε in
// cpp_bin_float_50: test::tolerance_factor), times 1 + κ,
// κ = |φ ∂f/∂φ / f| the condition in φ where the table has ∂f/∂φ. A constant the law combines
// with φ (φ − φ_min, φ/φ_max, 1 − φ/φ_max near packing) is not exact in T, and its rounding
// acts as a relative perturbation of φ of order ε_T, which κ amplifies. Derivatives are
// compared on the scale max(|∂f|, |f|/x). The worst measured is reported.
template <class T>
constexpr long double tolerance = 16 * test::tolerance_factor<T>;

inline long double condition(const test::ScalarTypeRow& row) {
  const bool d1_is_phi_derivative = row.closure != "solid_solid_drag:syamlal";  // there d1 is g_pq
  return 1 + (d1_is_phi_derivative && row.d1 && row.value != 0 ? std::abs(row.p[0] * *row.d1 / row.value) : 0);
}

template <class T>
void check_value(const T& got, const test::ScalarTypeRow& row, test::WorstError& worst) {
  REQUIRE(test::is_finite(got));
  const long double e = test::error_in_epsilons(got, row.value) / condition(row);
  CHECK(e <= tolerance<T>);
  worst.record(e, row.closure);
}

template <class T>
void check_derivative(const T& got, const test::Reference& expected, long double value, long double at,
                      const test::ScalarTypeRow& row, test::WorstError& worst) {
  const long double e =
      test::error_in_epsilons(got, expected, std::max(std::abs(expected), std::abs(value / at))) / condition(row);
  CHECK(e <= tolerance<T>);
  worst.record(e, row.closure + " derivative");
}

}  // namespace fluidbed::test::kinetic_theory_rows

TEST_CASE_TEMPLATE_DEFINE("radial distributions and the constitutive laws agree with mpmath with their derivatives", T,
                          scalar_types_kinetic_theory_laws) {
  using namespace fluidbed;
  using namespace fluidbed::kinetic_theory;
  using namespace fluidbed::test::kinetic_theory_rows;
  test::WorstError worst;
  std::set<std::string> seen;
  for (const test::ScalarTypeRow& row : test::scalar_type_rows("kinetic_theory")) {
    const auto parts = test::split_variant(row.closure);
    const std::string &function = parts.first, &variant = parts.second;  // clang < 16 captures no structured binding
    INFO("line " << row.line << ": " << row.closure << " phi " << double(row.p[0]) << " theta " << double(row.p[1]));
    if (function == "radial_distribution") {
      seen.insert(variant);
      const double max_packing = double(row.p[1]);  // the generator's double parameter, exactly
      const Dual<T, 1> g = test::radial_distribution(variant, Dual<T, 1>::variable(row.in<T>(0), 0), max_packing);
      CHECK(test::same_arithmetic(g.value, test::radial_distribution(variant, row.in<T>(0), max_packing)));
      check_value(g.value, row, worst);
      check_derivative(g.derivative[0], *row.d1, row.value, row.p[0], row, worst);
      continue;
    }
    const bool constitutive = std::any_of(test::constitutive_names.begin(), test::constitutive_names.end(),
                                          [&](const test::TableName& n) { return n.table == row.closure; });
    if (!constitutive) continue;  // the other closures have their own test below
    seen.insert(row.closure);
    const GranularMaterial<T> m{row.in<T>(3), row.in<T>(4), row.in<T>(2)};
    const double length = double(row.p[5]);
    const auto law = [&](const auto& phi, const auto& theta) {
      return test::constitutive(function, variant, phi, theta, CarnahanStarling{}(phi), m, length);
    };
    const T value = law(row.in<T>(0), row.in<T>(1));
    const ValueAndDerivatives<T> with = kinetic_theory::with_derivatives(law, row.in<T>(0), row.in<T>(1));
    CHECK(test::same_arithmetic(with.value, value));
    check_value(value, row, worst);
    check_derivative(with.d_solid_fraction, *row.d1, row.value, row.p[0], row, worst);
    if (row.d2) check_derivative(with.d_granular_temperature, *row.d2, row.value, row.p[1], row, worst);
  }
  for (const test::TableName& name : test::radial_distribution_names)
    CHECK_MESSAGE(seen.count(name.table) == 1, name.table << ": no rows");
  for (const test::TableName& name : test::constitutive_names)
    CHECK_MESSAGE(seen.count(name.table) == 1, name.table << ": no rows");
  MESSAGE("worst " << double(worst.epsilons) << " eps (1 + kappa) (" << worst.where << ")");
}

TEST_CASE_TEMPLATE_DEFINE("friction and gas exchange and algebraic temperature and mixtures and solid-solid drag agree",
                          T, scalar_types_kinetic_theory_others) {
  using namespace fluidbed;
  using namespace fluidbed::kinetic_theory;
  using namespace fluidbed::test::kinetic_theory_rows;
  test::WorstError worst;
  int compared = 0;
  for (const test::ScalarTypeRow& row : test::scalar_type_rows("kinetic_theory")) {
    const std::string& c = row.closure;
    INFO("line " << row.line << ": " << c << " (" << double(row.p[0]) << ", " << double(row.p[1]) << ", "
                 << double(row.p[2]) << ")");
    const auto p = [&](std::size_t i) { return row.in<T>(i); };
    const auto parameter = [&](std::size_t i) { return double(row.p[i]); };  // a double parameter, exactly
    T value = std::numeric_limits<T>::quiet_NaN();
    if (c == "frictional_pressure:johnson_jackson") {
      const JohnsonJacksonPressure law{parameter(1), parameter(2), parameter(3), parameter(4), parameter(5)};
      const Dual<T, 1> f = law(Dual<T, 1>::variable(p(0), 0));
      value = law(p(0));
      CHECK(test::same_arithmetic(f.value, value));
      check_derivative(f.derivative[0], *row.d1, row.value, row.p[0], row, worst);
    } else if (c == "frictional_pressure:schaeffer") {
      const SchaefferPressure law{parameter(1), parameter(2), parameter(3)};
      const Dual<T, 1> f = law(Dual<T, 1>::variable(p(0), 0));
      value = law(p(0));
      CHECK(test::same_arithmetic(f.value, value));
      check_derivative(f.derivative[0], *row.d1, row.value, row.p[0], row, worst);
    } else if (c == "frictional_stress:srivastava_sundaresan") {
      const SrivastavaSundaresan law{JohnsonJacksonPressure{0.55, 0.63}, parameter(5)};
      const FrictionalStress<T> stress = law(p(0), p(1), p(2), StrainRate<T>{p(3), p(4)});
      value = stress.pressure;
      CHECK(test::error_in_epsilons(stress.viscosity, *row.d2) <= tolerance<T> * condition(row));
    } else if (c == "frictional_viscosity:schaeffer") {
      value = SchaefferViscosity{parameter(2), parameter(3)}(p(0), StrainRate<T>{T(0), p(1)});
    } else if (c == "gas_damping") {
      value = gas_damping(p(0), p(1));
    } else if (c == "koch_sangani") {
      value = KochSanganiSource{}(p(0), p(1), p(2), p(3), p(4), GranularMaterial<T>{p(5), p(6), T(0.875L)});
    } else if (c == "drag_fluctuation") {
      value = DragFluctuationSource{}(p(0), p(1), p(2), p(3), GranularMaterial<T>{p(4), p(5), T(0.875L)});
    } else if (c.starts_with("algebraic_temperature:")) {
      const GranularMaterial<T> m{p(2), p(3), p(1)};
      const StrainRate<T> rate{p(5), p(6)};
      value = c.ends_with("gidaspow")
                  ? algebraic_granular_temperature(LunPressure{}, GidaspowViscosity{}, LunBulkViscosity{},
                                                   LunDissipation{}, p(0), CarnahanStarling{}(p(0)), m, rate, p(4))
                  : algebraic_granular_temperature(LunPressure{}, SyamlalViscosity{}, LunBulkViscosity{},
                                                   LunDissipation{}, p(0), CarnahanStarling{}(p(0)), m, rate, p(4));
    } else if (c.starts_with("mixture:")) {
      const std::array<T, 3> fractions{p(0), p(1), p(2)}, diameters{p(3), p(4), p(5)};
      const std::span<const T> f(fractions), d(diameters);
      const auto i = std::size_t(row.p[6]), k = std::size_t(row.p[7]);
      if (c == "mixture:lebowitz") value = Lebowitz{}(f, d, i, k);
      if (c == "mixture:mansoori") value = Mansoori{}(f, d, i, k);
      if (c == "mixture:modified_mansoori") value = ModifiedMansoori{0.64}(f, d, i, k);
    } else if (c == "solid_solid_drag:syamlal") {
      value = SyamlalSolidSolidDrag{0.15}(p(0), p(1), Particles<T>{p(4), p(2)}, Particles<T>{p(5), p(3)}, p(6),
                                          row.d1->in<T>(), p(7));
    } else {
      continue;  // the radial distributions and the constitutive laws: the test above
    }
    check_value(value, row, worst);
    ++compared;
  }
  CHECK(compared == 65);
  MESSAGE("worst " << double(worst.epsilons) << " eps (" << worst.where << ")");
}
