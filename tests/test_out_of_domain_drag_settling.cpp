// Out-of-domain input for every checked entry point of drag/ and settling/: zero and negative
// sizes, densities and viscosities, ε outside (0, 1], NaN and ±∞ in each argument in turn
// must throw std::domain_error naming the argument and the value; the valid boundary values
// (ε = 1, zero slip, Re = 0) must not, and must give finite results. In float, double and long
// double.
#include <doctest/doctest.h>

#include <array>
#include <limits>
#include <span>
#include <variant>

#include "fluidbed/drag.hpp"
#include "fluidbed/fluidization.hpp"
#include "fluidbed/settling.hpp"
#include "fluidbed/single_particle.hpp"
#include "test_out_of_domain.hpp"
#include "test_scalar_types.hpp"

namespace {

using namespace fluidbed;
using namespace fluidbed::test;

// ρ_f, μ_f, ρ_p, d, g of a water–glass system (ρ_p > ρ_f; 1000 is shown exactly).
const std::vector<ArgumentCase> settling_system{
    {"fluid.density", 1000.0, not_positive},
    {"fluid.viscosity", 1e-3, not_positive},
    {"particles.density", 2500.0, and_non_finite({{0.0, "0"}, {-1.0, "-1"}, {1000.0, "1000"}, {500.0, "500"}})},
    {"particles.diameter", 1e-3, not_positive},
    {"gravity", 9.81, not_positive},
};

// The arguments of a drag law's state.
const std::vector<ArgumentCase> drag_state{
    {"voidage", 0.5, outside_voidage, {1.0}},  {"slip", 0.1, negative, {0.0}},   {"fluid.density", 1.25, not_positive},
    {"fluid.viscosity", 1.8e-5, not_positive}, {"diameter", 1e-4, not_positive},
};

template <class T>
drag::DragState<T> drag_state_of(const ValuesOf<T>& v) {
  return {v[0], v[1], {v[2], v[3]}, v[4]};
}

}  // namespace

TEST_CASE_TEMPLATE("out of domain: every drag law, value and derivatives, by type and through AnyDragLaw", T,
                   FLUIDBED_SCALAR_TYPES) {
  for (const drag::AnyDragLaw& any : drag::all_drag_laws) {
    const std::string name(drag::name_of(any));
    std::visit(
        [&](const auto& law) {
          check_entry_point<T>(name + ".checked", drag_state,
                               [&](const ValuesOf<T>& v) { return law.checked(drag_state_of(v)).classical(); });
          check_entry_point<T>(name + ".checked_with_derivatives", drag_state, [&](const ValuesOf<T>& v) {
            const auto d = law.checked_with_derivatives(drag_state_of(v));
            return d.classical().value + d.pressure_gradient().d_voidage +
                   d.force_slip_derivative(drag::Buoyancy::classical);
          });
        },
        any);
    check_entry_point<T>("evaluate_checked " + name, drag_state, [&](const ValuesOf<T>& v) {
      return drag::evaluate(any, drag_state_of(v), fluidbed::checked).pressure_gradient();
    });
    check_entry_point<T>("evaluate_with_derivatives_checked " + name, drag_state, [&](const ValuesOf<T>& v) {
      return drag::evaluate_with_derivatives(any, drag_state_of(v), fluidbed::checked).pressure_gradient().value;
    });
    // ε = 1 and zero slip together: β = 0, ∂(βw)/∂w finite.
    const drag::DragState<T> clear{1.0, 0.0, {1.25, 1.8e-5}, 1e-4};
    CHECK(drag::evaluate(any, clear, fluidbed::checked).classical() == 0.0);
    CHECK(std::isfinite(
        drag::evaluate_with_derivatives(any, clear, fluidbed::checked).force_slip_derivative(drag::Buoyancy::pressure_gradient)));
  }
}

TEST_CASE_TEMPLATE("out of domain: a drag law's parameters (Syamlal-O'Brien c1 > 0 and d1, the constant exponent)", T,
                   FLUIDBED_SCALAR_TYPES) {
  const drag::DragState<T> s{T(0.5), T(0.1), {T(1.25), T(1.8e-5)}, T(1e-4)};
  CHECK_THROWS_WITH_AS(drag::SyamlalOBrien(-1.0, 2.65).checked(s),
                       "fluidbed::SyamlalOBrien: argument 'c1' = -1 is out of domain (must be finite and > 0)",
                       std::domain_error);
  CHECK_THROWS_WITH_AS(drag::SyamlalOBrien(0.0, 2.65).checked_with_derivatives(s), doctest::Contains("argument 'c1' = 0"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(drag::SyamlalOBrien(0.8, std::numeric_limits<double>::quiet_NaN()).checked(s),
                       doctest::Contains("argument 'd1' = nan"), std::domain_error);
  CHECK_THROWS_WITH_AS(drag::ConstantExponentDrag(std::numeric_limits<double>::infinity(), "MyExponentLaw", "").checked(s),
                       doctest::Contains("argument 'exponent' = inf"), std::domain_error);
  CHECK_NOTHROW(drag::SyamlalOBrien(0.8, 2.65).checked(s));
  CHECK_NOTHROW(drag::ConstantExponentDrag(-1.0, "MyExponentLaw", "").checked(s));
  // The state is checked first, then the parameters; the run-time family checks them alike.
  const drag::DragState<T> bad_state{T(0.5), T(-0.1), {T(1.25), T(1.8e-5)}, T(1e-4)};
  CHECK_THROWS_WITH_AS(drag::SyamlalOBrien(-1.0, 2.65).checked(bad_state), doctest::Contains("argument 'slip'"),
                       std::domain_error);
  const drag::AnyDragLaw any = drag::SyamlalOBrien(-1.0, 2.65);
  CHECK_THROWS_WITH_AS(drag::evaluate(any, s, fluidbed::checked), doctest::Contains("argument 'c1'"), std::domain_error);
}

TEST_CASE_TEMPLATE("out of domain: Beetstra polydisperse species of a two-species mixture", T, FLUIDBED_SCALAR_TYPES) {
  const std::vector<ArgumentCase> arguments{
      {"fluid.density", 1.25, not_positive},
      {"fluid.viscosity", 1.8e-5, not_positive},
      {"slip", 0.1, negative, {0.0}},
      {"mixture[0].volume_fraction", 0.25, negative, {0.0}},
      {"mixture[0].diameter", 1e-4, not_positive},
      {"mixture[1].volume_fraction", 0.125, negative},
      {"mixture[1].diameter", 2e-4, not_positive},
  };
  for (const auto law : {drag::BeetstraPolydisperse::published(), drag::BeetstraPolydisperse::without_cubic_term()})
    check_entry_point<T>(std::string(law.name()), arguments, [&](const ValuesOf<T>& v) {
      const std::array<drag::Species<T>, 2> mixture{{{v[3], v[4]}, {v[5], v[6]}}};
      return law.checked(drag::PolydisperseDragState<T>{mixture, 0, v[2], {v[0], v[1]}}).classical();
    });
  const auto law = drag::BeetstraPolydisperse::published();
  const std::array<drag::Species<T>, 2> full{{{0.5, 1e-4}, {0.5, 2e-4}}};
  CHECK_THROWS_WITH_AS(law.checked(drag::PolydisperseDragState<T>{full, 0, 0.1, {1.25, 1.8e-5}}),
                       doctest::Contains("'sum of mixture volume fractions' = 1"), std::domain_error);
  CHECK_THROWS_WITH_AS(law.checked(drag::PolydisperseDragState<T>{full, 2, 0.1, {1.25, 1.8e-5}}),
                       doctest::Contains("'species' = 2"), std::domain_error);
}

TEST_CASE("in the domain, β out of the range of the type: checked throws, naming law, result and state") {
  // Valid arguments whose β the floating type cannot represent: ε^−α overflowing in float at a
  // subnormal ε, μ_f/d² overflowing in double; at ε = 1 the overflow meets φ = 0 (∞·0 = NaN).
  // The hot path gives ∞ or NaN there (documented preconditions hold; the result does not);
  // `checked` must give a status instead.
  const auto throws_for = [](const auto& state, const char* shown) {
    for (const drag::AnyDragLaw& any : drag::all_drag_laws) {
      const std::string name(drag::name_of(any));
      INFO(name, " at ", std::string(shown));
      const std::string value = domain_error_message([&] { (void)drag::evaluate(any, state, fluidbed::checked); });
      CHECK(value.starts_with("fluidbed::" + name + ": result 'beta."));
      CHECK(value.find(shown) != std::string::npos);
      const std::string derivatives =
          domain_error_message([&] { (void)drag::evaluate_with_derivatives(any, state, fluidbed::checked); });
      CHECK(derivatives.starts_with("fluidbed::" + name + ": result '"));
    }
  };
  throws_for(drag::DragState<float>{1e-43f, 1.0f, {1.0f, 1e-5f}, 1e-3f}, "state {voidage = 9.9492190967062012e-44,");
  throws_for(drag::DragState<double>{0.5, 0.1, {1.25, 1.8e-5}, 1e-200}, "diameter = 9.9999999999999998e-201}");
  throws_for(drag::DragState<double>{0.5, 0.1, {1.25, 1e300}, 1e-4}, "fluid.viscosity = 1.0000000000000001e+300");
  // At ε = 1 with μ_f/d² = ∞: NaN (∞·0) from the hot path, except Mazzei–Lettieri's, whose
  // logarithmic fallback gives the exact 0 (mazzei_lettieri.hpp); either a status or a finite β.
  const drag::DragState<double> clear{1.0, 0.1, {1.25, 1e300}, 1e-10};
  for (const drag::AnyDragLaw& any : drag::all_drag_laws) {
    INFO(drag::name_of(any));
    if (std::isfinite(drag::evaluate(any, clear).classical()))
      CHECK(drag::evaluate(any, clear, fluidbed::checked).classical() == drag::evaluate(any, clear).classical());
    else
      CHECK_THROWS_WITH_AS(drag::evaluate(any, clear, fluidbed::checked), doctest::Contains("nan is not finite"),
                           std::domain_error);
  }
  // A subnormal species diameter: φ_j/d_j overflows in the Sauter mean.
  const std::array<drag::Species<double>, 2> mixture{{{0.25, 1e-320}, {0.125, 2e-4}}};
  for (std::size_t i = 0; i < 2; ++i)
    CHECK_THROWS_WITH_AS(drag::BeetstraPolydisperse::published().checked(
                             drag::PolydisperseDragState<double>{mixture, i, 0.1, {1.25, 1.8e-5}}),
                         doctest::Contains("is not finite for state {mixture = {{0.25, 9.9998886718268301e-321}"),
                         std::domain_error);
}

TEST_CASE_TEMPLATE("out of domain: Syamlal-O'Brien calibration from minimum fluidization", T, FLUIDBED_SCALAR_TYPES) {
  check_entry_point<T>("syamlal_obrien_from_minimum_fluidization",
                       concatenated({{"minimum_fluidization_velocity", 5e-3, not_positive},
                                     {"minimum_fluidization_voidage", 0.45, outside_open_unit}},
                                    settling_system),
                       [](const ValuesOf<T>& v) {
                         return fluidization::syamlal_obrien_from_minimum_fluidization(v[0], v[1], fluid_of(v, 2),
                                                                                       particles_of(v, 2), v[6])
                             .c1();
                       });
}

TEST_CASE_TEMPLATE("out of domain: Richardson-Zaki exponents, law and inverse", T, FLUIDBED_SCALAR_TYPES) {
  using namespace settling;
  const std::vector<ArgumentCase> reynolds{{"terminal_reynolds", 10.0, negative, {0.0}}};
  check_entry_point<T>("MazzeiExponent::checked", reynolds,
                       [](const ValuesOf<T>& v) { return settling::MazzeiExponent{}.checked(v[0]); });
  check_entry_point<T>(
      "MazzeiExponent::checked_with_derivatives", {{"terminal_reynolds", 10.0, negative}},
      [](const ValuesOf<T>& v) { return settling::MazzeiExponent{}.checked_with_derivatives(v[0]).d_argument; });
  CHECK(settling::MazzeiExponent{}.checked_with_derivatives(T(0)).d_argument ==
        -std::numeric_limits<T>::infinity());  // documented: −∞ at Re_t = 0
  check_entry_point<T>("RoweExponent::checked", reynolds,
                       [](const ValuesOf<T>& v) { return settling::RoweExponent{}.checked(v[0]); });
  check_entry_point<T>("GarsideAlDibouniExponent::checked", reynolds,
                       [](const ValuesOf<T>& v) { return settling::GarsideAlDibouniExponent{}.checked(v[0]); });
  check_entry_point<T>(
      "RichardsonZaki1954Exponent::checked",
      concatenated(reynolds, {{"wall_ratio", 0.01, outside_solid_fraction, {0.0}}}),
      [](const ValuesOf<T>& v) { return settling::RichardsonZaki1954Exponent{parameter(v, 1)}.checked(v[0]); });
  check_entry_point<T>(
      "KhanRichardsonExponent::checked",
      {{"archimedes", 100.0, negative, {0.0}},
       {"wall_ratio", 0.01, and_non_finite({{-0.5, "-0.5"}, {0.5, "0.5"}, {1.5, "1.5"}}), {0.0}}},
      [](const ValuesOf<T>& v) { return settling::KhanRichardsonExponent{parameter(v, 1)}.checked(v[0]); });
  check_entry_point<T>(
      "richardson_zaki_velocity",
      {{"terminal_velocity", 0.1, negative, {0.0}},
       {"voidage", 0.5, outside_voidage, {1.0}},
       {"exponent", 4.0, not_positive}},
      [](const ValuesOf<T>& v) { return settling::richardson_zaki_velocity(v[0], v[1], v[2], fluidbed::checked); });
  // u_s ∈ (0, u_t] with u_t = 1: the voidage's own interval.
  check_entry_point<T>(
      "richardson_zaki_voidage",
      {{"superficial_velocity", 0.5, outside_voidage, {1.0}},
       {"terminal_velocity", 1.0, not_positive},
       {"exponent", 4.0, not_positive}},
      [](const ValuesOf<T>& v) { return settling::richardson_zaki_voidage(v[0], v[1], v[2], fluidbed::checked); });
  check_entry_point<T>(
      "richardson_zaki_terminal_reynolds",
      {{"reynolds", 10.0, negative, {0.0}}, {"voidage", 0.5, outside_voidage, {1.0}}},
      [](const ValuesOf<T>& v) { return settling::richardson_zaki_terminal_reynolds(v[0], v[1], fluidbed::checked); });
}

TEST_CASE_TEMPLATE("out of domain: terminal Reynolds numbers and terminal velocities", T, FLUIDBED_SCALAR_TYPES) {
  using namespace settling;
  const std::vector<ArgumentCase> archimedes{{"archimedes", 1e4, negative, {0.0}}};
  check_entry_point<T>("StokesTerminalVelocity::checked_reynolds", archimedes, [](const ValuesOf<T>& v) {
    return single_particle::StokesTerminalVelocity{}.checked_reynolds(v[0]);
  });
  check_entry_point<T>("NewtonTerminalVelocity::checked_reynolds", archimedes, [](const ValuesOf<T>& v) {
    return single_particle::NewtonTerminalVelocity{}.checked_reynolds(v[0]);
  });
  check_entry_point<T>("DallavalleTerminalVelocity::checked_reynolds", archimedes, [](const ValuesOf<T>& v) {
    return single_particle::DallavalleTerminalVelocity{}.checked_reynolds(v[0]);
  });
  check_entry_point<T>("SchillerNaumannTerminalVelocity::checked_reynolds", archimedes, [](const ValuesOf<T>& v) {
    return single_particle::SchillerNaumannTerminalVelocity{}.checked_reynolds(v[0]);
  });
  const auto velocity = [](auto checked) {
    return [checked](const ValuesOf<T>& v) { return checked(fluid_of(v, 0), particles_of(v, 0), v[4]); };
  };
  check_entry_point<T>("StokesTerminalVelocity::checked", settling_system, velocity([](auto f, auto p, auto g) {
                         return single_particle::StokesTerminalVelocity{}.checked(f, p, g);
                       }));
  check_entry_point<T>("NewtonTerminalVelocity::checked", settling_system, velocity([](auto f, auto p, auto g) {
                         return single_particle::NewtonTerminalVelocity{}.checked(f, p, g);
                       }));
  check_entry_point<T>("DallavalleTerminalVelocity::checked", settling_system, velocity([](auto f, auto p, auto g) {
                         return single_particle::DallavalleTerminalVelocity{}.checked(f, p, g);
                       }));
  check_entry_point<T>("SchillerNaumannTerminalVelocity::checked", settling_system,
                       velocity([](auto f, auto p, auto g) {
                         return single_particle::SchillerNaumannTerminalVelocity{}.checked(f, p, g);
                       }));
}

TEST_CASE_TEMPLATE("out of domain: minimum fluidization", T, FLUIDBED_SCALAR_TYPES) {
  using namespace settling;
  const std::vector<ArgumentCase> bed{{"voidage", 0.4, outside_open_unit}, {"sphericity", 0.75, outside_voidage, {1.0}}};
  check_entry_point<T>(
      "ErgunMinimumFluidization::checked_reynolds", concatenated({{"archimedes", 1e4, negative, {0.0}}}, bed),
      [](const ValuesOf<T>& v) {
        return fluidization::ErgunMinimumFluidization{parameter(v, 1), parameter(v, 2)}.checked_reynolds(v[0]);
      });
  check_entry_point<T>(
      "WenYuMinimumFluidization::checked_reynolds", {{"archimedes", 1e4, negative, {0.0}}},
      [](const ValuesOf<T>& v) { return fluidization::WenYuMinimumFluidization{}.checked_reynolds(v[0]); });
  check_entry_point<T>("ErgunMinimumFluidization::checked", concatenated(settling_system, bed),
                       [](const ValuesOf<T>& v) {
                         return fluidization::ErgunMinimumFluidization{parameter(v, 5), parameter(v, 6)}.checked(
                             fluid_of(v, 0), particles_of(v, 0), v[4]);
                       });
  check_entry_point<T>("WenYuMinimumFluidization::checked", settling_system, [](const ValuesOf<T>& v) {
    return fluidization::WenYuMinimumFluidization{}.checked(fluid_of(v, 0), particles_of(v, 0), v[4]);
  });
}

TEST_CASE_TEMPLATE("out of domain: bed expansion, voidage ratio, equivalent exponent and bed height", T,
                   FLUIDBED_SCALAR_TYPES) {
  using namespace settling;
  const drag::MazzeiLettieri law;
  const std::vector<ArgumentCase> expansion = concatenated({{"superficial_velocity", 5e-3, not_positive}}, settling_system);
  check_entry_point<T>("equilibrium_voidage", expansion, [&](const ValuesOf<T>& v) {
    return fluidization::equilibrium_voidage(law, v[0], fluid_of(v, 1), particles_of(v, 1), v[5], fluidbed::checked)
        .value();
  });
  check_entry_point<T>("equilibrium_voidage (AnyDragLaw)", expansion, [](const ValuesOf<T>& v) {
    return fluidization::equilibrium_voidage(drag::make_drag_law("WenYu1966"), v[0], fluid_of(v, 1), particles_of(v, 1),
                                             v[5], fluidbed::checked)
        .value();
  });
  check_entry_point<T>("richardson_zaki_equilibrium_voidage", expansion, [](const ValuesOf<T>& v) {
    return fluidization::richardson_zaki_equilibrium_voidage(v[0], fluid_of(v, 1), particles_of(v, 1), v[5],
                                                             fluidbed::checked)
        .value();
  });
  check_entry_point<T>(
      "voidage_ratio", {{"reynolds", 10.0, not_positive}, {"richardson_zaki_voidage", 0.5, outside_open_unit}},
      [&](const ValuesOf<T>& v) { return fluidization::voidage_ratio(law, v[0], v[1], fluidbed::checked).value(); });
  check_entry_point<T>(
      "equivalent_exponent", {{"voidage", 0.5, outside_open_unit}, {"reynolds", 10.0, negative, {0.0}}},
      [&](const ValuesOf<T>& v) { return fluidization::equivalent_exponent(law, v[0], v[1], fluidbed::checked); });
  check_entry_point<T>(
      "bed_height",
      {{"initial_height", 1.0, not_positive},
       {"initial_voidage", 0.4, outside_open_unit},
       {"voidage", 0.5, outside_open_unit}},
      [](const ValuesOf<T>& v) { return fluidization::bed_height(v[0], v[1], v[2], fluidbed::checked); });
  const std::vector<ArgumentCase> step = {
      {"initial_height", 0.25, not_positive},
      {"initial_velocity", 0.125, negative, {0.0}},
      {"final_height", 0.5, and_non_finite({{0.25, "0.25"}, {0.125, "0.125"}})},
      {"final_velocity", 0.5, and_non_finite({{0.125, "0.125"}, {-1.0, "-1"}})}};
  const auto step_of = [](const ValuesOf<T>& v) { return fluidization::ExpansionStep<T>{v[0], v[1], v[2], v[3]}; };
  check_entry_point<T>("expansion_time_constant", step, [&](const ValuesOf<T>& v) {
    return fluidization::expansion_time_constant(step_of(v), fluidbed::checked);
  });
  check_entry_point<T>("expansion_response_time", step, [&](const ValuesOf<T>& v) {
    return fluidization::expansion_response_time(step_of(v), fluidbed::checked);
  });
  check_entry_point<T>("expanding_bed_height", concatenated(step, {{"time", 10.0, negative, {0.0}}}),
                       [&](const ValuesOf<T>& v) {
                         return fluidization::expanding_bed_height(step_of(v), v[4], fluidbed::checked);
                       });
  check_entry_point<T>("geldart_group",
                       {{"particle_density", 2500.0, and_non_finite({{1.25, "1.25"}, {1.0, "1"}, {-1.0, "-1"}})},
                        {"gas_density", 1.25, not_positive},
                        {"diameter", 1e-4, not_positive}},
                       [](const ValuesOf<T>& v) {
                         return T(int(fluidization::geldart_group(v[0], v[1], v[2], fluidbed::checked)));
                       });
}
