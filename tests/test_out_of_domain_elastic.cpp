// Out-of-domain input for every checked entry point of elastic/ and interaction/: the moduli
// (.checked, .checked_with_derivatives), the functions of a state and the elastic force, the
// other interaction forces and the stability of homogeneous fluidization (fluidbed::checked; see
// test_out_of_domain.hpp for what each table entry checks), in float, double and long double.
#include <doctest/doctest.h>

#include <array>
#include <string>
#include <variant>

#include "fluidbed/elastic.hpp"
#include "fluidbed/interaction.hpp"
#include "test_out_of_domain.hpp"
#include "test_scalar_types.hpp"

namespace {

using namespace fluidbed;
using namespace fluidbed::elastic;
using namespace fluidbed::interaction;
using namespace fluidbed::test;

// Calls f(model, its name) for every model of the registry.
template <class F>
void for_each_model(const F& f) {
  for (const AnyElasticModulus& model : ElasticModuli::all())
    std::visit([&](const auto& m) { f(m, std::string(m.name())); }, model);
}

// ρ_f, μ_f, ρ_p, d, g of FCC in air. The particles must be heavier than the fluid: equal
// (1.25) and lighter (1) densities are out of domain, as zero and negative ones.
const std::vector<ArgumentCase> fluidized_system{
    {"fluid.density", 1.25, not_positive},
    {"fluid.viscosity", 1.8e-5, not_positive},
    {"particles.density", 1210.0, and_non_finite({{0.0, "0"}, {-1.0, "-1"}, {1.25, "1.25"}, {1.0, "1"}})},
    {"particles.diameter", 1e-4, not_positive},
    {"gravity", 9.81, not_positive},
};

// The three components of a vector argument, each of which must be finite.
std::vector<ArgumentCase> vector_argument(const std::string& name, const Vector3<double>& valid) {
  std::vector<ArgumentCase> components;
  for (std::size_t i = 0; i < 3; ++i)
    components.push_back({name + "[" + std::to_string(i) + "]", valid[i], non_finite});
  return components;
}

template <class T>
Vector3<T> vector_of(const ValuesOf<T>& v, std::size_t at) {
  return {v[at], v[at + 1], v[at + 2]};
}

template <class T>
T sum_of(const Vector3<T>& v) {
  return v[0] + v[1] + v[2];
}

// The suspension of homogeneous_suspension(FCC in air) with each field an argument.
const HomogeneousSuspension<double> fcc = homogeneous_suspension<double>({1.25, 1.8e-5}, {1210.0, 1e-4});
const std::vector<ArgumentCase> suspension_fields =
    concatenated(fluidized_system, {
                                       {"suspension.terminal_velocity", fcc.terminal_velocity, not_positive},
                                       {"suspension.terminal_reynolds", fcc.terminal_reynolds, not_positive},
                                       {"suspension.exponent", fcc.exponent, not_positive},
                                   });

template <class T>
HomogeneousSuspension<T> suspension_of(const ValuesOf<T>& v) {
  return {fluid_of(v, 0), particles_of(v, 0), v[4], v[5], v[6], v[7]};
}

}  // namespace

TEST_CASE_TEMPLATE("out of domain: elastic moduli at equilibrium, Table 3.1 functions and H", T,
                   FLUIDBED_SCALAR_TYPES) {
  const std::vector<ArgumentCase> equilibrium =
      concatenated({{"voidage", 0.5, outside_voidage, {1.0}}},
                   concatenated(fluidized_system, {{"terminal_reynolds", 4.0, negative, {0.0}}}));
  const auto state_of = [](const ValuesOf<T>& v) {
    return EquilibriumState<T>{v[0], fluid_of(v, 1), particles_of(v, 1), v[6], v[5]};
  };
  for_each_model([&](const auto& model, const std::string& name) {
    check_entry_point<T>(name + ".checked", equilibrium, [&](const ValuesOf<T>& v) { return model.checked(state_of(v)); });
    check_entry_point<T>(name + ".checked_with_derivatives", equilibrium, [&](const ValuesOf<T>& v) {
      const auto e = model.checked_with_derivatives(state_of(v));
      return e.value + e.d_voidage;
    });
    const std::string expected = "fluidbed::" + name + ": argument 'voidage' = 2";
    CHECK_THROWS_WITH_AS(model.checked(state_of({T(2), T(1.25L), T(1.8e-5L), T(1210), T(1e-4L), T(9.81L), T(4)})),
                         doctest::Contains(expected.c_str()), std::domain_error);
    check_entry_point<T>("voidage_sensitivity " + name,
                         {{"voidage", 0.5, outside_voidage, {1.0}}, {"re_star", 4.0, negative, {0.0}}},
                         [&](const ValuesOf<T>& v) { return voidage_sensitivity(model, v[0], v[1], fluidbed::checked); });
  });
  check_entry_point<T>("mazzei_lettieri_functions",
                       {{"voidage", 0.5, outside_voidage, {1.0}}, {"re_star", 4.0, negative, {0.0}}},
                       [](const ValuesOf<T>& v) {
                         const auto f = mazzei_lettieri_functions(v[0], v[1], fluidbed::checked);
                         return f.exponent + f.reynolds_factor + f.drag_factor + f.voidage_sensitivity;
                       });
  CHECK(mazzei_lettieri_functions(0.5, 0.0, fluidbed::checked).exponent_slope == -inf);  // N(0), documented
}

TEST_CASE_TEMPLATE("out of domain: functions of a state (voidage, slip): Re*, H, drag and modulus off equilibrium", T,
                   FLUIDBED_SCALAR_TYPES) {
  const std::vector<ArgumentCase> state{
      {"voidage", 0.5, outside_voidage, {1.0}}, {"slip", 0.1, negative, {0.0}},
      {"fluid.density", 1.25, not_positive},    {"fluid.viscosity", 1.8e-5, not_positive},
      {"diameter", 1e-4, not_positive},
  };
  const auto fluid = [](const ValuesOf<T>& v) { return Fluid<T>{v[2], v[3]}; };
  const auto drag_state = [&](const ValuesOf<T>& v) { return drag::DragState<T>{v[0], v[1], fluid(v), v[4]}; };
  check_entry_point<T>("effective_reynolds", state, [&](const ValuesOf<T>& v) {
    return effective_reynolds(v[0], v[1], fluid(v), v[4], fluidbed::checked);
  });
  check_entry_point<T>("mazzei_lettieri_sensitivity", state, [&](const ValuesOf<T>& v) {
    return mazzei_lettieri_sensitivity(v[0], v[1], fluid(v), v[4], fluidbed::checked);
  });
  check_entry_point<T>("mazzei_lettieri_drag_and_sensitivity", state, [&](const ValuesOf<T>& v) {
    const auto d = mazzei_lettieri_drag_and_sensitivity(v[0], v[1], fluid(v), v[4], fluidbed::checked);
    return d.beta + d.sensitivity;
  });
  check_entry_point<T>("MazzeiLettieriModulus.checked", state,
                       [&](const ValuesOf<T>& v) { return MazzeiLettieriModulus{}.checked(drag_state(v)); });
  check_entry_point<T>("MazzeiLettieriModulus.checked_with_derivatives", state, [&](const ValuesOf<T>& v) {
    const auto e = MazzeiLettieriModulus{}.checked_with_derivatives(drag_state(v));
    return e.value + e.d_voidage + e.d_slip;
  });
  const drag::DragState<T> at_rest{T(1), T(0), Fluid<T>{T(1.25L), T(1.8e-5L)}, T(1e-4L)};
  CHECK(MazzeiLettieriModulus{}.checked(at_rest) == 0);  // ε = 1, w = 0
}

TEST_CASE_TEMPLATE("out of domain: elastic force, 3-D and vertical", T, FLUIDBED_SCALAR_TYPES) {
  const std::vector<ArgumentCase> force =
      concatenated(concatenated(vector_argument("drag_force", {0.0, 1.0, 2.0}),
                                vector_argument("voidage_gradient", {0.0, 0.5, 4.0})),
                   {{"sensitivity", -4.8, non_finite}, {"diameter", 1e-4, not_positive}});
  check_entry_point<T>("elastic_force", force, [](const ValuesOf<T>& v) {
    return sum_of(elastic_force(vector_of(v, 0), vector_of(v, 3), v[6], v[7], fluidbed::checked));
  });
  CHECK(elastic_force(Vector3<T>{0, 0, 0}, Vector3<T>{0, 0, 4}, T(-4.8L), T(1e-4L), fluidbed::checked) ==
        Vector3<T>{0, 0, 0});  // no drag, no force
  const std::vector<ArgumentCase> vertical =
      concatenated(concatenated({{"modulus", 0.5, non_finite}}, vector_argument("voidage_gradient", {0.0, 0.5, 4.0})),
                   vector_argument("upward", {0.0, 0.0, 1.0}));
  check_entry_point<T>("elastic_force_vertical", vertical, [](const ValuesOf<T>& v) {
    return sum_of(elastic_force_vertical(v[0], vector_of(v, 1), vector_of(v, 4), fluidbed::checked));
  });
  CHECK_THROWS_WITH_AS(elastic_force_vertical(T(1), Vector3<T>{0, 0, 1}, Vector3<T>{0, 0, 2}, fluidbed::checked),
                       doctest::Contains("'|upward|' = 2"), std::domain_error);
}

TEST_CASE_TEMPLATE("out of domain: buoyancy and the other interaction forces", T, FLUIDBED_SCALAR_TYPES) {
  const ArgumentCase solid_fraction{"solid_fraction", 0.5, outside_solid_fraction, {0.0}};
  const ArgumentCase fluid_density{"fluid_density", 1.25, not_positive};
  const ArgumentCase coefficient{"coefficient", 0.5, negative, {0.0}};
  const auto gravity = vector_argument("gravity", {0.0, 0.0, -9.81});
  check_entry_point<T>(
      "classical_buoyancy", concatenated({solid_fraction, fluid_density}, gravity),
      [](const ValuesOf<T>& v) { return sum_of(classical_buoyancy(v[0], v[1], vector_of(v, 2), fluidbed::checked)); });
  check_entry_point<T>("stress_buoyancy",
                       concatenated({solid_fraction}, vector_argument("fluid_stress_divergence", {0.0, 0.0, -12.0})),
                       [](const ValuesOf<T>& v) { return sum_of(stress_buoyancy(v[0], vector_of(v, 1), fluidbed::checked)); });
  check_entry_point<T>(
      "pressure_gradient_buoyancy",
      concatenated({solid_fraction}, vector_argument("pressure_gradient", {0.0, 0.0, -12.0})),
      [](const ValuesOf<T>& v) { return sum_of(pressure_gradient_buoyancy(v[0], vector_of(v, 1), fluidbed::checked)); });
  check_entry_point<T>(
      "homogeneous_buoyancy",
      concatenated({solid_fraction, fluid_density, {"particle_density", 1210.0, not_positive}}, gravity),
      [](const ValuesOf<T>& v) { return sum_of(homogeneous_buoyancy(v[0], v[1], v[2], vector_of(v, 3), fluidbed::checked)); });
  check_entry_point<T>(
      "local_fluid_acceleration_force",
      concatenated({solid_fraction, fluid_density}, vector_argument("fluid_acceleration", {0.0, 1.0, 2.0})),
      [](const ValuesOf<T>& v) { return sum_of(local_fluid_acceleration_force(v[0], v[1], vector_of(v, 2), fluidbed::checked)); });
  check_entry_point<T>("virtual_mass_force",
                       concatenated(concatenated(concatenated({solid_fraction, fluid_density},
                                                              vector_argument("fluid_acceleration", {0.0, 1.0, 2.0})),
                                                 vector_argument("particle_acceleration", {0.5, 0.0, 1.0})),
                                    {coefficient}),
                       [](const ValuesOf<T>& v) {
                         return sum_of(virtual_mass_force(v[0], v[1], vector_of(v, 2), vector_of(v, 5), v[8], fluidbed::checked));
                       });
  check_entry_point<T>("lift_force",
                       concatenated(concatenated(concatenated({solid_fraction, fluid_density},
                                                              vector_argument("fluid_vorticity", {0.0, 1.0, 2.0})),
                                                 vector_argument("slip_velocity", {0.5, 0.0, 1.0})),
                                    {coefficient}),
                       [](const ValuesOf<T>& v) {
                         return sum_of(lift_force(v[0], v[1], vector_of(v, 2), vector_of(v, 5), v[8], fluidbed::checked));
                       });
  check_entry_point<T>(
      "faxen_force",
      concatenated(concatenated({solid_fraction, {"fluid_viscosity", 1.8e-5, not_positive}},
                                vector_argument("fluid_velocity_laplacian", {0.0, 1.0, 2.0})),
                   {coefficient}),
      [](const ValuesOf<T>& v) { return sum_of(faxen_force(v[0], v[1], vector_of(v, 2), v[5], fluidbed::checked)); });
}

TEST_CASE_TEMPLATE("out of domain: homogeneous suspension, stability function and waves", T, FLUIDBED_SCALAR_TYPES) {
  check_entry_point<T>("homogeneous_suspension", fluidized_system, [](const ValuesOf<T>& v) {
    return homogeneous_suspension(fluid_of(v, 0), particles_of(v, 0), v[4], fluidbed::checked).terminal_velocity;
  });
  const std::vector<ArgumentCase> state = concatenated(suspension_fields, {{"voidage", 0.5, outside_voidage}});
  for_each_model([&](const auto& model, const std::string& name) {
    check_entry_point<T>("stability_function " + name, state, [&](const ValuesOf<T>& v) {
      return stability_function(model, suspension_of(v), v[8], fluidbed::checked);
    });
    // ε = 1 is in the domain: S → −∞ there (both wave speeds vanish, u_d/u_k ∝ (1 − ε)^−½).
    const auto suspension = homogeneous_suspension<T>({T(1.25L), T(1.8e-5L)}, {T(1210), T(1e-4L)});
    CHECK(stability_function(model, suspension, T(1), fluidbed::checked) == -std::numeric_limits<T>::infinity());
    const auto with_voidage = concatenated(suspension_fields, {{"voidage", 0.5, outside_voidage, {1.0}}});
    check_entry_point<T>("wave_speeds " + name, with_voidage, [&](const ValuesOf<T>& v) {
      const WaveSpeeds<T> w = wave_speeds(model, suspension_of(v), v[8], fluidbed::checked);
      return w.kinematic + w.dynamic + w.damping;
    });
    check_entry_point<T>("equilibrium_modulus " + name, with_voidage, [&](const ValuesOf<T>& v) {
      return equilibrium_modulus(model, suspension_of(v), v[8], fluidbed::checked);
    });
    check_entry_point<T>("dynamic_wave_speed " + name, with_voidage, [&](const ValuesOf<T>& v) {
      return dynamic_wave_speed(model, suspension_of(v), v[8], fluidbed::checked);
    });
  });
  const auto with_voidage = concatenated(suspension_fields, {{"voidage", 0.5, outside_voidage, {1.0}}});
  check_entry_point<T>("kinematic_wave_speed", with_voidage, [](const ValuesOf<T>& v) {
    return kinematic_wave_speed(suspension_of(v), v[8], fluidbed::checked);
  });
  check_entry_point<T>("damping", with_voidage,
                       [](const ValuesOf<T>& v) { return damping(suspension_of(v), v[8], fluidbed::checked); });
  const std::vector<ArgumentCase> waves{
      {"waves.kinematic", 0.02, negative, {0.0}},
      {"waves.dynamic", 0.01, negative, {0.0}},
      {"waves.damping", 20.0, negative, {0.0}},
  };
  const auto waves_of = [](const ValuesOf<T>& v) { return WaveSpeeds<T>{v[0], v[1], v[2]}; };
  check_entry_point<T>("wave_of_wavenumber", concatenated(waves, {{"wavenumber", 100.0, not_positive}}),
                       [&](const ValuesOf<T>& v) {
                         const Wave<T> w = wave_of_wavenumber(waves_of(v), v[3], fluidbed::checked);
                         return w.growth_rate + w.velocity;
                       });
  check_entry_point<T>("growth_rate_of_wave_velocity", concatenated(waves, {{"velocity", 0.015, not_positive}}),
                       [&](const ValuesOf<T>& v) { return growth_rate_of_wave_velocity(waves_of(v), v[3], fluidbed::checked); });
  check_entry_point<T>(
      "squared_wavenumber_of_wave_velocity", concatenated(waves, {{"velocity", 0.015, not_positive}}),
      [&](const ValuesOf<T>& v) { return squared_wavenumber_of_wave_velocity(waves_of(v), v[3], fluidbed::checked); });
}

TEST_CASE_TEMPLATE("out of domain: minimum bubbling point validates the suspension and the interval", T,
                   FLUIDBED_SCALAR_TYPES) {
  const std::vector<ArgumentCase> arguments = concatenated(
      suspension_fields, {{"interval.lower", 0.25, outside_open_unit},
                          {"interval.upper", 1.0, and_non_finite({{0.25, "0.25"}, {0.0, "0"}, {1.5, "1.5"}})}});
  check_entry_point<T>("minimum_bubbling_point", arguments, [](const ValuesOf<T>& v) {
    return minimum_bubbling_point(MazzeiLettieriModulus{}, suspension_of(v), VoidageInterval<T>{v[8], v[9]})
        .maximum_stability;
  });
}
