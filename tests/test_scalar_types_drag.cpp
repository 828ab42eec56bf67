// The drag family in float, double and long double: every law of all_drag_laws (so that a law
// added to the run-time family is tested here too), the polydisperse Beetstra law and the
// single-sphere C_D·Re, against the mpmath table of scalar_types_reference.py (inputs exact in
// the three types, 25-digit values); the value of with_derivatives equals the plain value in
// each type; the derivatives agree with mpmath's; switch points compare in the argument's type.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <span>
#include <string>

#include "fluidbed/drag.hpp"
#include "same_arithmetic.hpp"
#include "test_scalar_types.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;

namespace {

// Every β and derivative here is a few dozen roundings of its exact inputs: within 16 ε of the
// type (the worst measured, 1.6, is reported by each test), times 1 + κ for β and its derivatives,
// κ = |ε ∂β/∂ε/β| the condition of β in the voidage. A constant a law compares or combines
// with ε (Gidaspow's blend takes ε − 0.8) is not exact in T; its rounding acts as a relative
// perturbation of ε of order ε_T, which κ amplifies (κ = 75 in the blend at ε = 0.8125).
constexpr long double tolerance = 16;

long double voidage_condition(const test::ScalarTypeRow& row) {
  return row.d1 && row.value != 0 ? std::abs(row.p[0] * *row.d1 / row.value) : 0;
}

template <class T>
DragState<T> state_of(const test::ScalarTypeRow& row) {
  return {row.in<T>(0), row.in<T>(1), Fluid<T>{row.in<T>(2), row.in<T>(3)}, row.in<T>(4)};
}

}  // namespace

TEST_CASE_TEMPLATE("every law of all_drag_laws: beta and its derivatives agree with mpmath to 16 eps of the type", T,
                   FLUIDBED_SCALAR_TYPES) {
  test::WorstError value_error, derivative_error;
  for (const AnyDragLaw& law : all_drag_laws) {
    const std::string name(name_of(law));
    const auto rows = test::scalar_type_rows("drag", name);
    REQUIRE_MESSAGE(rows.size() >= 40, name << " has no rows: add it to tests/reference/scalar_types_reference.py");
    for (const test::ScalarTypeRow& row : rows) {
      const DragState<T> s = state_of<T>(row);
      INFO(name << " voidage " << double(s.voidage) << " slip " << double(s.slip) << " density "
                << double(s.fluid.density));
      const DragCoefficient<T> beta = evaluate(law, s);
      const DragCoefficientWithDerivatives<T> with = evaluate_with_derivatives(law, s);
      const DragDerivatives<T> d = with.classical();
      REQUIRE(std::isfinite(beta.classical()));
      const long double condition = 1 + voidage_condition(row);
      const long double e = test::error_in_epsilons(beta.classical(), row.value) / condition;
      CHECK(e <= tolerance);
      value_error.record(e, name);
      CHECK(test::same_arithmetic(d.value, beta.classical()));
      CHECK(
          beta.pressure_gradient() ==
          doctest::Approx(double(s.voidage * beta.classical())).epsilon(4 * double(std::numeric_limits<T>::epsilon())));
      // ∂β/∂ε on the scale β/ε, ∂β/∂w on the scale β/w (each may pass through zero)
      if (row.d1) {
        const long double de =
            test::error_in_epsilons(d.d_voidage, *row.d1, std::max(std::abs(*row.d1), std::abs(row.value) / row.p[0])) /
            condition;
        CHECK(de <= tolerance);
        derivative_error.record(de, name + " d/d voidage");
      }
      if (row.d2) {
        const long double dw =
            test::error_in_epsilons(d.d_slip, *row.d2, std::max(std::abs(*row.d2), std::abs(row.value) / row.p[1])) /
            condition;
        CHECK(dw <= tolerance);
        derivative_error.record(dw, name + " d/d slip");
      }
      CHECK_NOTHROW(evaluate(law, s, fluidbed::checked));
    }
  }
  MESSAGE("worst beta " << double(value_error.epsilons) << " eps (1 + kappa) (" << value_error.where << "), derivative "
                        << double(derivative_error.epsilons) << " eps (1 + kappa) (" << derivative_error.where << ")");
}

TEST_CASE_TEMPLATE("the single-sphere C_D Re of Stokes and Schiller-Naumann and Dallavalle agrees with mpmath", T,
                   FLUIDBED_SCALAR_TYPES) {
  test::WorstError worst;
  for (const std::string name : {"Stokes", "SchillerNaumann", "Dallavalle"}) {
    const auto rows = test::scalar_type_rows("drag", name);
    REQUIRE(rows.size() == 6);
    for (const test::ScalarTypeRow& row : rows) {
      const T re = row.in<T>(0);
      const T cd_re = name == "Stokes"            ? single_particle::StokesCoefficient::cd_times_re(re)
                      : name == "SchillerNaumann" ? single_particle::SchillerNaumannCoefficient::cd_times_re(re)
                                                  : single_particle::DallavalleCoefficient::cd_times_re(re);
      INFO(name << " Re " << double(re));
      const long double e = test::error_in_epsilons(cd_re, row.value);
      CHECK(e <= tolerance);
      worst.record(e, name);
    }
  }
  MESSAGE("worst " << double(worst.epsilons) << " eps (" << worst.where << ")");
}

TEST_CASE_TEMPLATE("polydisperse Beetstra in both conventions and with both cubic coefficients agrees with mpmath", T,
                   FLUIDBED_SCALAR_TYPES) {
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
    INFO("phi " << double(row.p[0]) << "+" << double(row.p[1]) << " slip " << double(row.p[4]));
    const long double classical = test::error_in_epsilons(beta.classical(), row.value);
    const long double pressure_gradient = test::error_in_epsilons(beta.pressure_gradient(), *row.d1);
    CHECK(classical <= tolerance);
    CHECK(pressure_gradient <= tolerance);
    CHECK(test::same_arithmetic(with.classical().value, beta.classical()));
    CHECK(test::same_arithmetic(with.pressure_gradient().value, beta.pressure_gradient()));
    CHECK(std::isfinite(with.classical().d_voidage));
    CHECK_NOTHROW(law.checked(s));
    worst.record(std::max(classical, pressure_gradient), "");
  }
  MESSAGE("worst " << double(worst.epsilons) << " eps");
}

// A switch point is compared with the argument in the argument's type: the decimal rounded
// once to T, so that the documented side of a switch holds at the switch itself in every type
// (0.8L lies below the double 0.8 and 0.85L above the double 0.85: compared with double switch
// points, long double arguments equal to the switch took the other branch). At the switch the
// law equals its value one ulp on the documented side and jumps one ulp on the other.
TEST_CASE_TEMPLATE("switch points of the drag laws lie at the decimal in the argument's type", T,
                   FLUIDBED_SCALAR_TYPES) {
  const Fluid<T> air{T(1.25L), T(1.8e-5L)};
  const T d = T(5e-4L);
  const auto jump = [](const T& at_switch, const T& neighbour) { return std::abs(neighbour - at_switch) / at_switch; };
  // Gidaspow: Ergun below ε = 0.8, Wen–Yu from 0.8 on (Wen–Yu/Ergun = 0.89 at Re = 0.1)
  const auto gidaspow = [&](const T& voidage) {
    return GidaspowSwitched{}(DragState<T>{voidage, T(0.005L), air, d}).pressure_gradient();
  };
  const T gidaspow_switch = T(0.8L);
  CHECK(jump(gidaspow(gidaspow_switch), gidaspow(std::nextafter(gidaspow_switch, T(1)))) < 1e-5);
  CHECK(jump(gidaspow(gidaspow_switch), gidaspow(std::nextafter(gidaspow_switch, T(0)))) > 0.05);
  // Syamlal–O'Brien: B = c1 ε^1.28 up to ε = 0.85 inclusive (MFiX's rule), ε^d1 above; at
  // Re_s = 1000, V_r ≈ B and the branches differ by 0.05 % (c1 = 0.8, d1 = 2.65)
  const SyamlalOBrien syamlal;
  const auto ratio = [&](const T& voidage) { return syamlal.velocity_ratio(voidage, T(1000)); };
  const T syamlal_switch = T(0.85L);
  CHECK(jump(ratio(syamlal_switch), ratio(std::nextafter(syamlal_switch, T(0)))) < 1e-5);
  CHECK(jump(ratio(syamlal_switch), ratio(std::nextafter(syamlal_switch, T(1)))) > 2e-4);
  // Schiller–Naumann: the 0.44 branch from Re = 1000 on
  CHECK(single_particle::SchillerNaumannCoefficient::cd_times_re(T(1000)) == T(0.44L) * T(1000));
}
