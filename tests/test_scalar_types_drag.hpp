// The row tests of the drag family against the mpmath table of scalar_types_reference.py, for
// every scalar type: every law of all_drag_laws (so that a law added to the run-time family is
// tested here too), the polydisperse Beetstra law and the single-sphere C_D·Re (inputs exact in
// every type, 55-digit values); the value of with_derivatives equals the plain value in each
// type; the derivatives agree with mpmath's. Defined here, invoked for the built-in types by
// test_scalar_types_drag.cpp and for cpp_bin_float_50 by test_scalar_types_50_digits_drag.cpp.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>

#include "fluidbed/drag.hpp"
#include "same_arithmetic.hpp"
#include "test_scalar_types.hpp"

namespace fluidbed::test::drag_rows {

// Every β and derivative here is a few dozen roundings of its exact inputs: within 16 ε of the
// type (64 ε in cpp_bin_float_50: test::tolerance_factor; the worst measured, 1.6, is reported by
// each test), times 1 + κ for β and its derivatives, κ = |ε ∂β/∂ε/β| the condition of β in the
// voidage. A constant a law compares or combines with ε (Gidaspow's blend takes ε − 0.8) is not
// exact in T; its rounding acts as a relative perturbation of ε of order ε_T, which κ amplifies
// (κ = 75 in the blend at ε = 0.8125).
template <class T>
constexpr long double tolerance = 16 * test::tolerance_factor<T>;

inline long double voidage_condition(const ScalarTypeRow& row) {
  return row.d1 && row.value != 0 ? std::abs(row.p[0] * *row.d1 / row.value) : 0;
}

template <class T>
drag::DragState<T> state_of(const ScalarTypeRow& row) {
  return {row.in<T>(0), row.in<T>(1), Fluid<T>{row.in<T>(2), row.in<T>(3)}, row.in<T>(4)};
}

}  // namespace fluidbed::test::drag_rows

TEST_CASE_TEMPLATE_DEFINE(
    "every law of all_drag_laws: beta and its derivatives agree with mpmath to a few eps of the type", T,
    scalar_types_drag_laws) {
  using namespace fluidbed;
  using namespace fluidbed::drag;
  using namespace fluidbed::test::drag_rows;
  test::WorstError value_error, derivative_error;
  for (const AnyDragLaw& law : all_drag_laws) {
    const std::string name(name_of(law));
    const auto rows = test::scalar_type_rows("drag", name);
    REQUIRE_MESSAGE(rows.size() >= 40, name << " has no rows: add it to tests/reference/scalar_types_reference.py");
    for (const test::ScalarTypeRow& row : rows) {
      const DragState<T> s = state_of<T>(row);
      INFO("line " << row.line << ": " << name << " voidage " << double(s.voidage) << " slip " << double(s.slip)
                   << " density " << double(s.fluid.density));
      const DragCoefficient<T> beta = evaluate(law, s);
      const DragCoefficientWithDerivatives<T> with = evaluate_with_derivatives(law, s);
      const DragDerivatives<T> d = with.classical();
      REQUIRE(test::is_finite(beta.classical()));
      const long double condition = 1 + voidage_condition(row);
      const long double e = test::error_in_epsilons(beta.classical(), row.value) / condition;
      CHECK(e <= tolerance<T>);
      value_error.record(e, name);
      CHECK(test::same_arithmetic(d.value, beta.classical()));
      CHECK(test::error_in_epsilons(beta.pressure_gradient(), test::Wide<T>(s.voidage * beta.classical())) <= 4);
      // ∂β/∂ε on the scale β/ε, ∂β/∂w on the scale β/w (each may pass through zero)
      if (row.d1) {
        const long double de =
            test::error_in_epsilons(d.d_voidage, *row.d1, std::max(std::abs(*row.d1), std::abs(row.value) / row.p[0])) /
            condition;
        CHECK(de <= tolerance<T>);
        derivative_error.record(de, name + " d/d voidage");
      }
      if (row.d2) {
        const long double dw =
            test::error_in_epsilons(d.d_slip, *row.d2, std::max(std::abs(*row.d2), std::abs(row.value) / row.p[1])) /
            condition;
        CHECK(dw <= tolerance<T>);
        derivative_error.record(dw, name + " d/d slip");
      }
      CHECK_NOTHROW(evaluate(law, s, fluidbed::checked));
    }
  }
  MESSAGE("worst beta " << double(value_error.epsilons) << " eps (1 + kappa) (" << value_error.where << "), derivative "
                        << double(derivative_error.epsilons) << " eps (1 + kappa) (" << derivative_error.where << ")");
}

TEST_CASE_TEMPLATE_DEFINE("the single-sphere C_D Re of Stokes and Schiller-Naumann and Dallavalle agrees with mpmath",
                          T, scalar_types_single_sphere) {
  using namespace fluidbed;
  using namespace fluidbed::drag;
  using namespace fluidbed::test::drag_rows;
  test::WorstError worst;
  for (const std::string name : {"Stokes", "SchillerNaumann", "Dallavalle"}) {
    const auto rows = test::scalar_type_rows("drag", name);
    REQUIRE(rows.size() == 6);
    for (const test::ScalarTypeRow& row : rows) {
      const T re = row.in<T>(0);
      const T cd_re = name == "Stokes"            ? single_particle::StokesCoefficient::cd_times_re(re)
                      : name == "SchillerNaumann" ? single_particle::SchillerNaumannCoefficient::cd_times_re(re)
                                                  : single_particle::DallavalleCoefficient::cd_times_re(re);
      INFO("line " << row.line << ": " << name << " Re " << double(re));
      const long double e = test::error_in_epsilons(cd_re, row.value);
      CHECK(e <= tolerance<T>);
      worst.record(e, name);
    }
  }
  MESSAGE("worst " << double(worst.epsilons) << " eps (" << worst.where << ")");
}

TEST_CASE_TEMPLATE_DEFINE(
    "polydisperse Beetstra in both conventions and with both cubic coefficients agrees with mpmath", T,
    scalar_types_beetstra) {
  using namespace fluidbed;
  using namespace fluidbed::drag;
  using namespace fluidbed::test::drag_rows;
  const auto rows = test::scalar_type_rows("drag", "BeetstraPolydisperse");
  REQUIRE(rows.size() == 12);
  test::WorstError worst;
  for (const test::ScalarTypeRow& row : rows) {
    const std::array<Species<T>, 2> mixture{Species<T>{row.in<T>(0), row.in<T>(2)},
                                            Species<T>{row.in<T>(1), row.in<T>(3)}};
    const PolydisperseDragState<T> s{std::span<const Species<T>>(mixture), 0, row.in<T>(4),
                                     Fluid<T>{row.in<T>(5), row.in<T>(6)}};
    const BeetstraPolydisperse law =
        row.p[7] == 0 ? BeetstraPolydisperse::without_cubic_term() : BeetstraPolydisperse::published();
    const auto beta = law(s);
    const auto with = law.with_derivatives(s);
    INFO("line " << row.line << ": "
                 << "phi " << double(row.p[0]) << "+" << double(row.p[1]) << " slip " << double(row.p[4]));
    const long double classical = test::error_in_epsilons(beta.classical(), row.value);
    const long double pressure_gradient = test::error_in_epsilons(beta.pressure_gradient(), *row.d1);
    CHECK(classical <= tolerance<T>);
    CHECK(pressure_gradient <= tolerance<T>);
    CHECK(test::same_arithmetic(with.classical().value, beta.classical()));
    CHECK(test::same_arithmetic(with.pressure_gradient().value, beta.pressure_gradient()));
    CHECK(test::is_finite(with.classical().d_voidage));
    CHECK_NOTHROW(law.checked(s));
    worst.record(std::max(classical, pressure_gradient), "");
  }
  MESSAGE("worst " << double(worst.epsilons) << " eps");
}
