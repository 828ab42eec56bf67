// The elastic family in float, double and long double: the Mazzei–Lettieri functions of Table
// 3.1, the moduli at equilibrium and off it, the forces, and the linear stability analysis up
// to the minimum bubbling point, against the mpmath table of scalar_types_reference.py
// (inputs exact in the three types, 25-digit values) or, for the force products, against the
// documented formula evaluated in long double.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <variant>

#include "fluidbed/elastic.hpp"
#include "fluidbed/interaction.hpp"
#include "same_arithmetic.hpp"
#include "test_scalar_types.hpp"

using namespace fluidbed;
using namespace fluidbed::elastic;
using namespace fluidbed::interaction;

namespace {

// Closed forms are a few dozen roundings of their exact inputs; the Re* solve stops at the
// precision of T. The worst measured is reported; the tolerance is 16 ε of the type, times
// the condition of the subtraction S = 1 − u_d/u_k for a value of S: 1 + |1 − S|/|S| (S = −0.046
// at the maximum of powder 10's S_j: u_d/u_k = 1.046 is 23 times larger than S).
constexpr long double tolerance = 16;

long double subtraction_condition(long double stability) { return 1 + std::abs(1 - stability) / std::abs(stability); }

// The models by the names of the reference table.
const std::map<std::string, AnyElasticModulus> models = {{"foscolo_gibilaro", FoscoloGibilaroModulus{}},
                                                         {"jean_fan", JeanFanModulus{}},
                                                         {"mazzei_lettieri", MazzeiLettieriModulus{}}};

template <class T>
Fluid<T> fluid_of(const test::ScalarTypeRow& row, std::size_t at) {
  return {row.in<T>(at), row.in<T>(at + 1)};
}

template <class T>
HomogeneousSuspension<T> suspension_of(const test::ScalarTypeRow& row) {
  return homogeneous_suspension(fluid_of<T>(row, 0), Particles<T>{row.in<T>(2), row.in<T>(3)});
}

}  // namespace

TEST_CASE_TEMPLATE("Table 3.1 functions and the moduli and the functions of a state agree with mpmath", T,
                   FLUIDBED_SCALAR_TYPES) {
  test::WorstError worst;
  int compared = 0;
  for (const test::ScalarTypeRow& row : test::scalar_type_rows("elastic")) {
    INFO(row.closure << " (" << double(row.p[0]) << ", " << double(row.p[1]) << ")");
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
      if (c == "table_3_1_H")
        CHECK(voidage_sensitivity(MazzeiLettieriModulus{}, row.in<T>(0), row.in<T>(1)) == value);
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
        CHECK(test::error_in_epsilons(both.sensitivity, row.value) <= tolerance);
        const T beta = drag::MazzeiLettieri{}(drag::DragState<T>{voidage, slip, fluid, diameter}).classical();
        CHECK(test::error_in_epsilons(both.beta, static_cast<long double>(beta)) <= tolerance);
      }
      if (c == "mazzei_lettieri_modulus")
        value = MazzeiLettieriModulus{}(drag::DragState<T>{voidage, slip, fluid, diameter});
    }
    REQUIRE_MESSAGE(std::isfinite(value), "no function, or a non-finite value, for " << c);
    const long double e = test::error_in_epsilons(value, row.value);
    CHECK(e <= tolerance);
    worst.record(e, c);
    ++compared;
  }
  CHECK(compared == 222);
  MESSAGE("worst " << double(worst.epsilons) << " eps (" << worst.where << ")");
}

TEST_CASE_TEMPLATE("derivatives of the equilibrium moduli through Dual<T> match central differences", T,
                   FLUIDBED_SCALAR_TYPES) {
  const Fluid<T> air{T(1.25L), T(1.52587890625e-5L)};
  const Particles<T> particles{T(1250), T(1.220703125e-4L)};
  const auto state_at = [&](const T& voidage) { return EquilibriumState<T>{voidage, air, particles, T(3)}; };
  for (const T voidage : {T(0.4L), T(0.6L), T(0.95L)})
    for (const AnyElasticModulus& any : ElasticModuli::all())
      std::visit(
          [&](const auto& model) {
            const auto e = model.with_derivatives(state_at(voidage));
            CHECK(test::same_arithmetic(e.value, model(state_at(voidage))));
            // dE/dε against a central difference with h = ε_T^(1/3) (error ~ h² ≈ ε_T^(2/3))
            const T h = std::cbrt(std::numeric_limits<T>::epsilon());
            const T difference = (model(state_at(voidage + h)) - model(state_at(voidage - h))) / (2 * h);
            INFO("model " << model.name() << " voidage " << double(voidage));
            CHECK(std::isfinite(e.d_voidage));
            CHECK(double(e.d_voidage) == doctest::Approx(double(difference)).epsilon(100 * double(h * h)));
          },
          any);
}

TEST_CASE_TEMPLATE("the interaction forces and the elastic force are their documented products to 4 eps", T,
                   FLUIDBED_SCALAR_TYPES) {
  using L = long double;
  const T phi = T(0.375L), rho_f = T(1.25L), rho_p = T(2500), mu = T(1.52587890625e-5L);
  const Vector3<T> g{T(0), T(0), T(-9.8125L)}, a{T(0.5L), T(-1.25L), T(2)}, b{T(-0.75L), T(0.25L), T(1)};
  const auto check = [](const Vector3<T>& got, const std::array<L, 3>& expected) {
    for (std::size_t i = 0; i < 3; ++i) {
      INFO("component " << i);
      CHECK(test::error_in_epsilons(got[i], expected[i],
                                    std::abs(expected[0]) + std::abs(expected[1]) + std::abs(expected[2])) <= 4);
    }
  };
  const L p = L(phi);
  check(classical_buoyancy(phi, rho_f, g), {0, 0, L(-p * L(rho_f) * L(g[2]))});
  check(pressure_gradient_buoyancy(phi, a), {-p * L(a[0]), -p * L(a[1]), -p * L(a[2])});
  check(stress_buoyancy(phi, a), {p * L(a[0]), p * L(a[1]), p * L(a[2])});
  const L suspension = (1 - p) * L(rho_f) + p * L(rho_p);
  check(homogeneous_buoyancy(phi, rho_f, rho_p, g), {0, 0, -p * suspension * L(g[2])});
  check(local_fluid_acceleration_force(phi, rho_f, a),
        {p * L(rho_f) * L(a[0]), p * L(rho_f) * L(a[1]), p * L(rho_f) * L(a[2])});
  const L vm = L(0.5) * p * L(rho_f);
  check(virtual_mass_force(phi, rho_f, a, b),
        {vm * (L(a[0]) - L(b[0])), vm * (L(a[1]) - L(b[1])), vm * (L(a[2]) - L(b[2]))});
  const L lift = -L(0.5) * p * L(rho_f);  // −C_l φ ρ_f (a × b)
  check(lift_force(phi, rho_f, a, b),
        {lift * (L(a[1]) * L(b[2]) - L(a[2]) * L(b[1])), lift * (L(a[2]) * L(b[0]) - L(a[0]) * L(b[2])),
         lift * (L(a[0]) * L(b[1]) - L(a[1]) * L(b[0]))});
  const L faxen = L(0.75) * p * L(mu);
  check(faxen_force(phi, mu, a), {faxen * L(a[0]), faxen * L(a[1]), faxen * L(a[2])});
  // n f_e = −(2/3) d H (∇ε · n_d) n f_d: along the drag, E ∂ε/∂x with E = −(2/3) d H |n f_d|
  const T d = T(4.8828125e-4L), h = T(-7.5L);
  const L along = -L(2) / 3 * L(d) * L(h) * (L(a[0]) * L(b[0]) + L(a[1]) * L(b[1]) + L(a[2]) * L(b[2])) /
                  std::sqrt(L(a[0]) * L(a[0]) + L(a[1]) * L(a[1]) + L(a[2]) * L(a[2]));
  check(elastic_force(a, b, h, d), {along * L(a[0]), along * L(a[1]), along * L(a[2])});
  const Vector3<T> up{T(0), T(0), T(1)};
  check(elastic_force_vertical(T(3.5L), b, up), {0, 0, L(T(3.5L)) * L(b[2])});
  CHECK_NOTHROW(elastic_force_vertical(T(3.5L), b, up, fluidbed::checked));
}

TEST_CASE_TEMPLATE("stability functions and wave speeds and the minimum bubbling point agree with mpmath", T,
                   FLUIDBED_SCALAR_TYPES) {
  test::WorstError worst, worst_argmax;
  int compared = 0;
  for (const test::ScalarTypeRow& row : test::scalar_type_rows("stability")) {
    const std::string& c = row.closure;
    INFO(c << " (d = " << double(row.p[3]) << ", voidage " << double(row.p[4]) << ")");
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
      CHECK(argmax <= tolerance);
      worst_argmax.record(argmax, c);
      CHECK(test::error_in_epsilons(t.maximum_stability, *row.d2) / subtraction_condition(*row.d2) <= tolerance);
    }
    REQUIRE_MESSAGE(std::isfinite(value), "no function, or a non-finite value, for " << c);
    const bool is_stability = c.starts_with("stability_") || no_bubbling;
    const long double e =
        test::error_in_epsilons(value, row.value) / (is_stability ? subtraction_condition(row.value) : 1);
    CHECK(e <= tolerance);
    worst.record(e, c);
    ++compared;
  }
  CHECK(compared == 80);
  MESSAGE("worst " << double(worst.epsilons) << " eps (S: times its condition) (" << worst.where << "), argmax of S "
                   << double(worst_argmax.epsilons) << " eps (" << worst_argmax.where << ")");
}

// Regression (issue 13): with a fixed upper limit 1 − 1e-15, which is 1 in float, S was −∞
// there and every sample NaN; the search never returned (Release) or asserted (Debug). The
// limit is now 1 − 4ε_T and every iteration bounded.
TEST_CASE_TEMPLATE("minimum bubbling point and the waves are finite for every model over the whole interval", T,
                   FLUIDBED_SCALAR_TYPES) {
  const Fluid<T> air{T(1.205L), T(1.81e-5L)};
  for (const Particles<T> particles :
       {Particles<T>{T(1210), T(137e-6L)}, Particles<T>{T(1420), T(26e-6L)}, Particles<T>{T(2500), T(1e-3L)}}) {
    const HomogeneousSuspension<T> s = homogeneous_suspension(air, particles, fluidbed::checked);
    for (const AnyElasticModulus& model : ElasticModuli::all()) {
      INFO("d = " << double(particles.diameter) << ", model " << ElasticModuli::name_of(model));
      const StabilityTransition<T> t = minimum_bubbling_point(model, s);
      CHECK(std::isfinite(t.maximum_voidage));
      CHECK(std::isfinite(t.maximum_stability));
      CHECK(t.maximum_voidage < T(1));
      if (t.bubbling_voidage) CHECK(std::abs(stability_function(model, s, *t.bubbling_voidage)) < T(1e-3L));
      // the maximum: dS/dε = 0 there (to rounding), and S no larger one step away on either side
      const T step = std::sqrt(std::numeric_limits<T>::epsilon()) * t.maximum_voidage;
      CHECK(stability_function(model, s, t.maximum_voidage) >= stability_function(model, s, t.maximum_voidage - step));
      CHECK(stability_function(model, s, t.maximum_voidage) >= stability_function(model, s, t.maximum_voidage + step));
      const WaveSpeeds<T> w = wave_speeds(model, s, T(0.5L), fluidbed::checked);
      const Wave<T> wave = wave_of_wavenumber(w, T(30), fluidbed::checked);
      CHECK(std::isfinite(wave.growth_rate));
      CHECK(std::isfinite(wave.velocity));
      CHECK(double(growth_rate_of_wave_velocity(w, wave.velocity, fluidbed::checked)) ==
            doctest::Approx(double(wave.growth_rate))
                .scale(double(w.damping))
                .epsilon(1e3 * double(std::numeric_limits<T>::epsilon())));
      CHECK(std::isfinite(squared_wavenumber_of_wave_velocity(w, wave.velocity, fluidbed::checked)));
      CHECK(stability_function(model, s, T(1), fluidbed::checked) == -std::numeric_limits<T>::infinity());  // at 1
    }
  }
}
