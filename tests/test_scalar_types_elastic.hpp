// The row tests of the elastic family against the mpmath table of scalar_types_reference.py, for
// every scalar type (inputs exact in every type, 55-digit values): the Mazzei–Lettieri
// functions of Table 3.1, the moduli at equilibrium and off it, and the linear stability
// analysis up to the minimum bubbling point. Defined here, invoked for the built-in types by
// test_scalar_types_elastic.cpp and for cpp_bin_float_50 by test_scalar_types_50_digits_elastic.cpp.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <variant>

#include "fluidbed/elastic.hpp"
#include "test_scalar_types.hpp"

namespace fluidbed::test::elastic_rows {

// Closed forms are a few dozen roundings of their exact inputs; the Re* solve stops at the
// precision of T. The worst measured is reported; the tolerance is 16 ε of the type (64 ε in
// cpp_bin_float_50: test::tolerance_factor), times
// the condition of the subtraction S = 1 − u_d/u_k for a value of S: 1 + |1 − S|/|S| (S = −0.046
// at the maximum of powder 10's S_j: u_d/u_k = 1.046 is 23 times larger than S).
template <class T>
constexpr long double tolerance = 16 * test::tolerance_factor<T>;

inline long double subtraction_condition(long double stability) {
  return 1 + std::abs(1 - stability) / std::abs(stability);
}

// The models by the names of the reference table.
const std::map<std::string, elastic::AnyElasticModulus> models = {
    {"foscolo_gibilaro", elastic::FoscoloGibilaroModulus{}},
    {"jean_fan", elastic::JeanFanModulus{}},
    {"mazzei_lettieri", elastic::MazzeiLettieriModulus{}}};

template <class T>
Fluid<T> fluid_of(const test::ScalarTypeRow& row, std::size_t at) {
  return {row.in<T>(at), row.in<T>(at + 1)};
}

template <class T>
elastic::HomogeneousSuspension<T> suspension_of(const test::ScalarTypeRow& row) {
  return elastic::homogeneous_suspension(fluid_of<T>(row, 0), Particles<T>{row.in<T>(2), row.in<T>(3)});
}

}  // namespace fluidbed::test::elastic_rows

TEST_CASE_TEMPLATE_DEFINE("Table 3.1 functions and the moduli and the functions of a state agree with mpmath", T,
                          scalar_types_elastic) {
  using namespace fluidbed;
  using namespace fluidbed::elastic;
  using namespace fluidbed::test::elastic_rows;
  test::WorstError worst;
  int compared = 0;
  for (const test::ScalarTypeRow& row : test::scalar_type_rows("elastic")) {
    INFO("line " << row.line << ": " << row.closure << " (" << double(row.p[0]) << ", " << double(row.p[1]) << ")");
    const std::string& c = row.closure;
    T value = std::numeric_limits<T>::quiet_NaN();
    if (c.starts_with("table_3_1_")) {
      const MazzeiLettieriFunctions<T> f = mazzei_lettieri_functions(row.in<T>(0), row.in<T>(1));
      const std::map<std::string, T> by_name = {{"table_3_1_n_e", f.exponent},
                                                {"table_3_1_N", f.exponent_slope},
                                                {"table_3_1_C", f.reynolds_factor},
                                                {"table_3_1_D", f.drag_factor},
                                                {"table_3_1_H", f.voidage_sensitivity}};
      value = by_name.at(c);
      if (c == "table_3_1_H") CHECK(voidage_sensitivity(MazzeiLettieriModulus{}, row.in<T>(0), row.in<T>(1)) == value);
    } else if (c.starts_with("modulus_")) {
      const EquilibriumState<T> state{row.in<T>(0), fluid_of<T>(row, 1), Particles<T>{row.in<T>(3), row.in<T>(4)},
                                      row.in<T>(5)};
      value = std::visit([&](const auto& model) { return model(state); },
                         models.at(c.substr(std::string("modulus_").size())));
    } else {
      const T voidage = row.in<T>(0), slip = row.in<T>(1), diameter = row.in<T>(4);
      const Fluid<T> fluid = fluid_of<T>(row, 2);
      if (c == "effective_reynolds") value = effective_reynolds(voidage, slip, fluid, diameter);
      if (c == "mazzei_lettieri_sensitivity") {
        value = mazzei_lettieri_sensitivity(voidage, slip, fluid, diameter);
        // the one-solve hot path gives the same H and the law's β
        const DragAndSensitivity<T> both = mazzei_lettieri_drag_and_sensitivity(voidage, slip, fluid, diameter);
        CHECK(test::error_in_epsilons(both.sensitivity, row.value) <= tolerance<T>);
        const T beta = drag::MazzeiLettieri{}(drag::DragState<T>{voidage, slip, fluid, diameter}).classical();
        CHECK(test::error_in_epsilons(both.beta, test::Wide<T>(beta)) <= tolerance<T>);
      }
      if (c == "mazzei_lettieri_modulus")
        value = MazzeiLettieriModulus{}(drag::DragState<T>{voidage, slip, fluid, diameter});
    }
    REQUIRE_MESSAGE(test::is_finite(value), "no function, or a non-finite value, for " << c);
    const long double e = test::error_in_epsilons(value, row.value);
    CHECK(e <= tolerance<T>);
    worst.record(e, c);
    ++compared;
  }
  CHECK(compared == 222);
  MESSAGE("worst " << double(worst.epsilons) << " eps (" << worst.where << ")");
}

TEST_CASE_TEMPLATE_DEFINE("stability functions and wave speeds and the minimum bubbling point agree with mpmath", T,
                          scalar_types_stability) {
  using namespace fluidbed;
  using namespace fluidbed::elastic;
  using namespace fluidbed::test::elastic_rows;
  test::WorstError worst, worst_argmax;
  int compared = 0;
  for (const test::ScalarTypeRow& row : test::scalar_type_rows("stability")) {
    const std::string& c = row.closure;
    INFO("line " << row.line << ": " << c << " (d = " << double(row.p[3]) << ", voidage " << double(row.p[4]) << ")");
    const HomogeneousSuspension<T> s = suspension_of<T>(row);
    const T voidage = row.in<T>(4);
    const auto model_of = [&](const std::string& prefix) -> const AnyElasticModulus& {
      return models.at(c.substr(prefix.size()));
    };
    T value = std::numeric_limits<T>::quiet_NaN();
    if (c == "suspension_terminal_velocity") value = s.terminal_velocity;
    if (c == "suspension_terminal_reynolds") value = s.terminal_reynolds;
    if (c == "suspension_exponent") value = s.exponent;
    if (c == "kinematic_wave_speed") value = kinematic_wave_speed(s, voidage);
    if (c == "damping") value = damping(s, voidage);
    if (c.starts_with("stability_")) value = stability_function(model_of("stability_"), s, voidage);
    if (c.starts_with("dynamic_wave_speed_")) value = dynamic_wave_speed(model_of("dynamic_wave_speed_"), s, voidage);
    if (c.starts_with("restabilisation_")) {
      const StabilityTransition<T> t = minimum_bubbling_point(model_of("restabilisation_"), s);
      REQUIRE(t.restabilisation_voidage.has_value());
      value = *t.restabilisation_voidage;
    }
    const bool bubbling = c.starts_with("bubbling_"), no_bubbling = c.starts_with("no_bubbling_");
    if (bubbling || no_bubbling) {
      const StabilityTransition<T> t = minimum_bubbling_point(model_of(bubbling ? "bubbling_" : "no_bubbling_"), s);
      CHECK(t.status == (bubbling ? TransitionStatus::transition : TransitionStatus::no_transition));
      value = bubbling ? t.bubbling_voidage.value_or(T(0)) : t.maximum_stability;
      // the maximum of S: located from dS/dε = 0, to a few ε of T
      const long double argmax = test::error_in_epsilons(t.maximum_voidage, *row.d1);
      CHECK(argmax <= tolerance<T>);
      worst_argmax.record(argmax, c);
      CHECK(test::error_in_epsilons(t.maximum_stability, *row.d2) / subtraction_condition(*row.d2) <= tolerance<T>);
    }
    REQUIRE_MESSAGE(test::is_finite(value), "no function, or a non-finite value, for " << c);
    const bool is_stability = c.starts_with("stability_") || no_bubbling;
    const long double e =
        test::error_in_epsilons(value, row.value) / (is_stability ? subtraction_condition(row.value) : 1);
    CHECK(e <= tolerance<T>);
    worst.record(e, c);
    ++compared;
  }
  CHECK(compared == 80);
  MESSAGE("worst " << double(worst.epsilons) << " eps (S: times its condition) (" << worst.where << "), argmax of S "
                   << double(worst_argmax.epsilons) << " eps (" << worst_argmax.where << ")");
}
