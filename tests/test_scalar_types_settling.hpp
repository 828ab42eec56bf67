// The row test of the settling family against the mpmath table of scalar_types_reference.py, for
// every scalar type (inputs exact in every type, 55-digit values): the Richardson–Zaki exponents
// and law, the terminal Reynolds numbers and velocities, minimum fluidization, and the
// equilibrium voidage, voidage ratio and equivalent exponent of every law of all_drag_laws (a
// law added to the run-time family is tested here too). Every quantity of the table has a
// function here and every function rows in the table. Defined here, invoked for the built-in
// types by test_scalar_types_settling.cpp and for cpp_bin_float_50 by
// test_scalar_types_50_digits_settling.cpp.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "fluidbed/drag/any_drag_law.hpp"
#include "fluidbed/fluidization.hpp"
#include "fluidbed/settling.hpp"
#include "fluidbed/single_particle.hpp"
#include "test_scalar_types.hpp"

namespace fluidbed::test::settling_rows {

// Closed forms are a few roundings of their exact inputs; the solvers (Halley for Re_t,
// TOMS 748 for the equilibrium voidage and Schiller–Naumann's Re_t) stop at the precision of
// T and their roots move by the residual's rounding over its slope; the voidage ratio chains
// three of them. The worst measured is reported; the tolerance is 16 ε of the type, and
// 32 ε for the chained voidage ratio and the equivalent exponent (−ln(β/β₁)/ln ε, whose
// rounding ln ε amplifies by 1/|ln ε| = 7.5 at ε = 0.875); 4 times these in cpp_bin_float_50
// (test::tolerance_factor).
template <class T>
constexpr long double tolerance = 16 * test::tolerance_factor<T>;
template <class T>
constexpr long double chained_tolerance = 32 * test::tolerance_factor<T>;

template <class T>
Fluid<T> fluid_of(const test::ScalarTypeRow& row, std::size_t at) {
  return {row.in<T>(at), row.in<T>(at + 1)};
}

template <class T>
Particles<T> particles_of(const test::ScalarTypeRow& row, std::size_t at) {
  return {row.in<T>(at + 2), row.in<T>(at + 3)};
}

template <class T>
T required(const std::optional<T>& value) {
  REQUIRE(value.has_value());
  return *value;
}

// Every quantity of the table's settling rows, as a function of the row in T (a law's parameters,
// the row's inputs in double, exact: every law parameter is a double).
template <class T>
std::map<std::string, std::function<T(const test::ScalarTypeRow&)>> settling_quantities() {
  using Row = test::ScalarTypeRow;
  std::map<std::string, std::function<T(const Row&)>> q{
      {"rz_exponent_mazzei", [](const Row& r) { return settling::MazzeiExponent{}(r.in<T>(0)); }},
      {"rz_exponent_mazzei_derivative",
       [](const Row& r) { return settling::MazzeiExponent{}.with_derivatives(r.in<T>(0)).d_argument; }},
      {"rz_exponent_rowe1987", [](const Row& r) { return settling::RoweExponent{}(r.in<T>(0)); }},
      {"rz_exponent_garside_aldibouni1977",
       [](const Row& r) { return settling::GarsideAlDibouniExponent{}(r.in<T>(0)); }},
      {"rz_exponent_khan_richardson1989",
       [](const Row& r) { return settling::KhanRichardsonExponent{r.in<double>(1)}(r.in<T>(0)); }},
      {"rz_exponent_richardson_zaki1954",
       [](const Row& r) { return settling::RichardsonZaki1954Exponent{r.in<double>(1)}(r.in<T>(0)); }},
      {"richardson_zaki_velocity",
       [](const Row& r) { return settling::richardson_zaki_velocity(r.in<T>(0), r.in<T>(1), r.in<T>(2)); }},
      {"richardson_zaki_voidage",
       [](const Row& r) { return settling::richardson_zaki_voidage(r.in<T>(0), r.in<T>(1), r.in<T>(2)); }},
      {"richardson_zaki_terminal_reynolds",
       [](const Row& r) { return settling::richardson_zaki_terminal_reynolds(r.in<T>(0), r.in<T>(1)); }},
      {"terminal_reynolds_stokes",
       [](const Row& r) { return single_particle::StokesTerminalVelocity{}.reynolds(r.in<T>(0)); }},
      {"terminal_reynolds_newton",
       [](const Row& r) { return single_particle::NewtonTerminalVelocity{}.reynolds(r.in<T>(0)); }},
      {"terminal_reynolds_dallavalle",
       [](const Row& r) { return single_particle::DallavalleTerminalVelocity{}.reynolds(r.in<T>(0)); }},
      {"terminal_reynolds_schiller_naumann",
       [](const Row& r) { return single_particle::SchillerNaumannTerminalVelocity{}.reynolds(r.in<T>(0)); }},
      {"terminal_velocity_stokes",
       [](const Row& r) {
         return single_particle::StokesTerminalVelocity{}(fluid_of<T>(r, 0), particles_of<T>(r, 0));
       }},
      {"terminal_velocity_newton",
       [](const Row& r) {
         return single_particle::NewtonTerminalVelocity{}(fluid_of<T>(r, 0), particles_of<T>(r, 0));
       }},
      {"terminal_velocity_dallavalle",
       [](const Row& r) {
         return single_particle::DallavalleTerminalVelocity{}(fluid_of<T>(r, 0), particles_of<T>(r, 0));
       }},
      {"terminal_velocity_schiller_naumann",
       [](const Row& r) {
         return single_particle::SchillerNaumannTerminalVelocity{}(fluid_of<T>(r, 0), particles_of<T>(r, 0));
       }},
      {"minimum_fluidization_velocity_ergun",
       [](const Row& r) {
         return fluidization::ErgunMinimumFluidization{r.in<double>(4), r.in<double>(5)}(fluid_of<T>(r, 0),
                                                                                         particles_of<T>(r, 0));
       }},
      {"minimum_fluidization_reynolds_ergun",
       [](const Row& r) {
         return fluidization::ErgunMinimumFluidization{r.in<double>(1), r.in<double>(2)}.reynolds(r.in<T>(0));
       }},
      {"minimum_fluidization_velocity_wen_yu",
       [](const Row& r) { return fluidization::WenYuMinimumFluidization{}(fluid_of<T>(r, 0), particles_of<T>(r, 0)); }},
      {"minimum_fluidization_reynolds_wen_yu",
       [](const Row& r) { return fluidization::WenYuMinimumFluidization{}.reynolds(r.in<T>(0)); }},
      {"equilibrium_voidage_RichardsonZaki",
       [](const Row& r) {
         return required(
             fluidization::richardson_zaki_equilibrium_voidage(r.in<T>(0), fluid_of<T>(r, 1), particles_of<T>(r, 1)));
       }},
      {"bed_height", [](const Row& r) { return fluidization::bed_height(r.in<T>(0), r.in<T>(1), r.in<T>(2)); }},
  };
  for (const drag::AnyDragLaw& law : drag::all_drag_laws) {
    const std::string name(drag::name_of(law));
    q["equilibrium_voidage_" + name] = [law](const Row& r) {
      return required(fluidization::equilibrium_voidage(law, r.in<T>(0), fluid_of<T>(r, 1), particles_of<T>(r, 1)));
    };
    q["voidage_ratio_" + name] = [law](const Row& r) {
      return required(fluidization::voidage_ratio(law, r.in<T>(0), r.in<T>(1)));
    };
    q["equivalent_exponent_" + name] = [law](const Row& r) {
      return fluidization::equivalent_exponent(law, r.in<T>(0), r.in<T>(1));
    };
  }
  return q;
}

inline bool chained(const std::string& quantity) {
  return quantity.starts_with("voidage_ratio_") || quantity.starts_with("equivalent_exponent_");
}

}  // namespace fluidbed::test::settling_rows

TEST_CASE_TEMPLATE_DEFINE("every settling function and the equilibrium of every drag law agree with mpmath", T,
                          scalar_types_settling) {
  using namespace fluidbed;
  using namespace fluidbed::test::settling_rows;
  const auto quantities = settling_quantities<T>();
  std::set<std::string> seen;
  test::WorstError worst, worst_chained;
  for (const test::ScalarTypeRow& row : test::scalar_type_rows("settling")) {
    INFO("line " << row.line << ": " << row.closure << " (" << double(row.p[0]) << ", " << double(row.p[1]) << ", "
                 << double(row.p[2]) << ", " << double(row.p[3]) << ")");
    const auto quantity = quantities.find(row.closure);
    REQUIRE_MESSAGE(quantity != quantities.end(), "no function for the reference quantity " << row.closure);
    seen.insert(row.closure);
    const T value = quantity->second(row);
    REQUIRE(test::is_finite(value));
    const long double e = test::error_in_epsilons(value, row.value);
    CHECK(e <= (chained(row.closure) ? chained_tolerance<T> : tolerance<T>));
    (chained(row.closure) ? worst_chained : worst).record(e, row.closure);
  }
  for (const auto& quantity : quantities)
    CHECK_MESSAGE(seen.count(quantity.first) == 1, quantity.first << " has no rows");
  MESSAGE("worst " << double(worst.epsilons) << " eps (" << worst.where << "), chained "
                   << double(worst_chained.epsilons) << " eps (" << worst_chained.where << ")");
}
