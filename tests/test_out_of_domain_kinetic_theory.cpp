// Out-of-domain input for every checked entry point of kinetic_theory/: law.checked of every
// radial distribution, closure, frictional law, gas-exchange source, mixture form and the
// solid–solid drag, gas_damping and the algebraic granular temperature under fluidbed::checked,
// and the ConstitutiveSet (see test_out_of_domain.hpp for what each table entry checks). The laws'
// own parameters (packing limits, length scales, friction angles, …) are arguments too. In
// float, double and long double (a law's parameters are double members in every type).
#include <doctest/doctest.h>

#include <array>
#include <span>
#include <string>

#include "fluidbed/kinetic_theory.hpp"
#include "test_out_of_domain.hpp"
#include "test_scalar_types.hpp"

namespace {

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;
using namespace fluidbed::test;

const ArgumentCase solid_fraction{"solid_fraction", 0.3, outside_solid_fraction, {0.0}};
const ArgumentCase granular_temperature{"granular_temperature", 0.01, negative, {0.0}};
const ArgumentCase g0{"g0", 2.0, not_positive};
const std::vector<ArgumentCase> material{
    {"material.diameter", 5e-4, not_positive},
    {"material.density", 2500.0, not_positive},
    {"material.restitution", 0.9, outside_closed_unit, {0.0, 1.0}},
};
const std::vector<ArgumentCase> strain_rate{
    {"rate.divergence", 0.5, non_finite, {0.0, -1.0}},
    {"rate.deviatoric_contraction", 2.0, negative, {0.0}},
};
// φ_max = 0.625 is also the out-of-domain margin (a margin must lie below φ_max).
const std::vector<ArgumentCase> packing{
    {"max_packing", 0.625, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {1.5, "1.5"}}), {1.0}},
    {"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {0.625, "0.625"}})},
};
const std::vector<ArgumentCase> johnson_jackson_parameters{
    {"min_fraction", 0.5, and_non_finite({{-0.5, "-0.5"}, {0.625, "0.625"}, {1.5, "1.5"}}), {0.0}},
    {"max_packing", 0.625, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {1.5, "1.5"}})},
    {"coefficient", 0.05, negative, {0.0}},
    {"numerator_exponent", 2.0, negative, {0.0}},
    {"denominator_exponent", 5.0, negative, {0.0}},
    {"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {0.625, "0.625"}})},
};
const std::vector<ArgumentCase> yield_parameters{
    {"friction_angle", 0.5, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {2.0, "2"}})},
    {"strain_rate_floor", 1e-6, not_positive},
};
const ArgumentCase temperature_floor{"temperature_floor", 1e-6, not_positive};

template <class T>
GranularMaterial<T> material_of(const ValuesOf<T>& v, std::size_t at) {
  return {v[at], v[at + 1], v[at + 2]};
}
template <class T>
StrainRate<T> rate_of(const ValuesOf<T>& v, std::size_t at) {
  return {v[at], v[at + 1]};
}
template <class T>
JohnsonJacksonPressure johnson_jackson_of(const ValuesOf<T>& v, std::size_t at) {
  return {parameter(v, at),     parameter(v, at + 1), parameter(v, at + 2),
          parameter(v, at + 3), parameter(v, at + 4), parameter(v, at + 5)};
}

// A closure law(φ, Θ, g0, material) built by make(values), the law's parameters (if any)
// being the arguments after the material.
template <class T, class Make>
void check_closure(const std::string& label, const std::vector<ArgumentCase>& parameters, const Make& make) {
  check_entry_point<T>(
      label, concatenated(concatenated({solid_fraction, granular_temperature, g0}, material), parameters),
      [&](const ValuesOf<T>& v) { return make(v).checked(v[0], v[1], v[2], material_of(v, 3)); });
}

// A one-class g0(φ) built by make(values), its parameters after φ.
template <class T, class Make>
void check_radial_distribution(const std::string& label, const std::vector<ArgumentCase>& parameters, const Make& make) {
  const ArgumentCase phi{"solid_fraction", 0.3, outside_solid_fraction, {0.0, 0.7}};  // 0.7: beyond packing, continued
  check_entry_point<T>(label, concatenated({phi}, parameters),
                       [&](const ValuesOf<T>& v) { return make(v).checked(v[0]); });
}

}  // namespace

TEST_CASE_TEMPLATE("out of domain: one-class radial distribution functions and their packing parameters", T,
                   FLUIDBED_SCALAR_TYPES) {
  check_radial_distribution<T>("CarnahanStarling", {}, [](const auto&) { return CarnahanStarling{}; });
  check_radial_distribution<T>("PercusYevick", {}, [](const auto&) { return PercusYevick{}; });
  check_radial_distribution<T>("LunSavage", packing, [](const ValuesOf<T>& v) {
    return LunSavage{parameter(v, 1), parameter(v, 2)};
  });
  check_radial_distribution<T>("Ogawa", packing, [](const ValuesOf<T>& v) { return Ogawa(v[1], v[2]); });
  check_radial_distribution<T>("SinclairJackson", packing,
                               [](const ValuesOf<T>& v) { return SinclairJackson(v[1], v[2]); });
  check_radial_distribution<T>("GidaspowRadialDistribution", packing,
                               [](const ValuesOf<T>& v) { return GidaspowRadialDistribution(v[1], v[2]); });
  check_radial_distribution<T>("MaAhmadi", {{"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}})}},
                               [](const ValuesOf<T>& v) { return MaAhmadi{parameter(v, 1)}; });
  check_radial_distribution<T>("SongStrattMason",
                               {{"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {0.75, "0.75"}})}},
                               [](const ValuesOf<T>& v) { return SongStrattMason{parameter(v, 1)}; });
  check_radial_distribution<T>("TobochnikChapin",
                               {{"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {0.75, "0.75"}})}},
                               [](const ValuesOf<T>& v) { return TobochnikChapin{parameter(v, 1)}; });
  check_radial_distribution<T>("LathouwersBellan", packing, [](const ValuesOf<T>& v) {
    return LathouwersBellan{parameter(v, 1), parameter(v, 2)};
  });
}

TEST_CASE_TEMPLATE("out of domain: pressures, viscosities, conductivities and dissipation", T, FLUIDBED_SCALAR_TYPES) {
  check_closure<T>("LunPressure", {}, [](const auto&) { return LunPressure{}; });
  check_closure<T>("SyamlalRogersOBrienPressure", {}, [](const auto&) { return SyamlalRogersOBrienPressure{}; });
  check_closure<T>("AhmadiMaPressure", {{"friction_coefficient", 0.25, negative, {0.0}}},
                   [](const ValuesOf<T>& v) { return AhmadiMaPressure{parameter(v, 6)}; });
  check_closure<T>("GidaspowViscosity", {}, [](const auto&) { return GidaspowViscosity{}; });
  check_closure<T>("SyamlalViscosity", {}, [](const auto&) { return SyamlalViscosity{}; });
  const std::vector<ArgumentCase> length{{"length_scale", 0.05, not_positive}};
  check_closure<T>("HrenyaSinclairViscosity", length,
                   [](const ValuesOf<T>& v) { return HrenyaSinclairViscosity(v[6]); });
  check_closure<T>("LunBulkViscosity", {}, [](const auto&) { return LunBulkViscosity{}; });
  check_closure<T>("GidaspowConductivity", {}, [](const auto&) { return GidaspowConductivity{}; });
  check_closure<T>("SyamlalConductivity", {}, [](const auto&) { return SyamlalConductivity{}; });
  check_closure<T>("HrenyaSinclairConductivity", length,
                   [](const ValuesOf<T>& v) { return HrenyaSinclairConductivity(v[6]); });
  check_closure<T>("LunDissipation", {}, [](const auto&) { return LunDissipation{}; });
  check_closure<T>("EnskogViscosity", {}, [](const auto&) { return EnskogViscosity{}; });
  check_closure<T>("EnskogConductivity", {}, [](const auto&) { return EnskogConductivity{}; });
}

TEST_CASE_TEMPLATE("out of domain: frictional pressures and viscosities", T, FLUIDBED_SCALAR_TYPES) {
  const ArgumentCase dense{"solid_fraction", 0.62, outside_solid_fraction, {0.0, 0.7}};
  check_entry_point<T>("JohnsonJacksonPressure", concatenated({dense}, johnson_jackson_parameters),
                       [](const ValuesOf<T>& v) { return johnson_jackson_of(v, 1).checked(v[0]); });
  check_entry_point<T>(
      "SchaefferPressure",
      {dense,
       {"min_fraction", 0.5, outside_solid_fraction, {0.0}},
       {"coefficient", 1e24, negative, {0.0}},
       {"exponent", 10.0, negative, {0.0}}},
      [](const ValuesOf<T>& v) {
        return SchaefferPressure{parameter(v, 1), parameter(v, 2), parameter(v, 3)}.checked(v[0]);
      });
  check_entry_point<T>(
      "SchaefferViscosity",
      concatenated(concatenated({{"frictional_pressure", 100.0, negative, {0.0}}}, strain_rate), yield_parameters),
      [](const ValuesOf<T>& v) {
        return SchaefferViscosity{parameter(v, 3), parameter(v, 4)}.checked(v[0], rate_of(v, 1));
      });
  const std::vector<ArgumentCase> srivastava_sundaresan = concatenated(
      concatenated(concatenated({dense, granular_temperature, {"diameter", 5e-4, not_positive}}, strain_rate),
                   johnson_jackson_parameters),
      yield_parameters);
  check_entry_point<T>("SrivastavaSundaresan", srivastava_sundaresan, [](const ValuesOf<T>& v) {
    const SrivastavaSundaresan law{johnson_jackson_of(v, 5), parameter(v, 11), parameter(v, 12)};
    const FrictionalStress<T> stress = law.checked(v[0], v[1], v[2], rate_of(v, 3));
    return stress.pressure + stress.viscosity;
  });
}

TEST_CASE_TEMPLATE("out of domain: exchange of granular energy with the gas", T, FLUIDBED_SCALAR_TYPES) {
  check_entry_point<T>("gas_damping", {{"beta", 10.0, negative, {0.0}}, granular_temperature},
                       [](const ValuesOf<T>& v) { return gas_damping(v[0], v[1], fluidbed::checked); });
  check_entry_point<T>("KochSanganiSource",
                       concatenated({solid_fraction,
                                     granular_temperature,
                                     g0,
                                     {"slip", 0.5, negative, {0.0}},
                                     {"gas_viscosity", 1.8e-5, not_positive}},
                                    concatenated(material, {temperature_floor})),
                       [](const ValuesOf<T>& v) {
                         return KochSanganiSource{parameter(v, 8)}.checked(v[0], v[1], v[2], v[3], v[4],
                                                                           material_of(v, 5));
                       });
  check_entry_point<T>("DragFluctuationSource",
                       concatenated({{"solid_fraction", 0.3, outside_open_unit},
                                     granular_temperature,
                                     {"beta", 100.0, negative, {0.0}},
                                     {"slip", 0.5, negative, {0.0}}},
                                    concatenated(material, {temperature_floor})),
                       [](const ValuesOf<T>& v) {
                         return DragFluctuationSource{parameter(v, 7)}.checked(v[0], v[1], v[2], v[3],
                                                                               material_of(v, 4));
                       });
}

TEST_CASE_TEMPLATE("out of domain: mixture radial distributions, element by element, and their spans", T,
                   FLUIDBED_SCALAR_TYPES) {
  const std::vector<ArgumentCase> classes{
      {"fractions[0]", 0.25, negative, {0.0}},
      {"fractions[1]", 0.125, negative, {0.0}},
      {"diameters[0]", 1e-4, not_positive},
      {"diameters[1]", 2e-4, not_positive},
  };
  const auto pair_value = [](const auto& law, const ValuesOf<T>& v) {
    const std::array<T, 2> fractions{v[0], v[1]}, diameters{v[2], v[3]};
    return law.checked(std::span<const T>(fractions), std::span<const T>(diameters), 0, 1);
  };
  check_entry_point<T>("Lebowitz", classes, [&](const ValuesOf<T>& v) { return pair_value(Lebowitz{}, v); });
  check_entry_point<T>("Mansoori", classes, [&](const ValuesOf<T>& v) { return pair_value(Mansoori{}, v); });
  check_entry_point<T>("ModifiedMansoori", concatenated(classes, packing), [&](const ValuesOf<T>& v) {
    return pair_value(ModifiedMansoori{parameter(v, 4), parameter(v, 5)}, v);
  });

  const std::array<T, 2> diameters{T(1e-4L), T(2e-4L)};
  const auto message = [&](std::vector<T> fractions, std::size_t size, std::size_t i, std::size_t k) {
    return domain_error_message([&] {
      Mansoori{}.checked(std::span<const T>(fractions), std::span<const T>(diameters.data(), size), i, k);
    });
  };
  CHECK(message({0.5, 0.5}, 2, 0, 1).find("'sum of fractions' = 1 ") != std::string::npos);
  CHECK(message({0.75, 0.5}, 2, 0, 1).find("'sum of fractions' = 1.25") != std::string::npos);
  CHECK(message({0.25, 0.125}, 2, 2, 1).find("'i' = 2") != std::string::npos);
  CHECK(message({0.25, 0.125}, 2, 0, 5).find("'k' = 5") != std::string::npos);
  CHECK(message({0.25, 0.125}, 1, 0, 0).find("'diameters.size()' = 1") != std::string::npos);
  CHECK(message({}, 0, 0, 0).find("'fractions.size()' = 0") != std::string::npos);
}

TEST_CASE_TEMPLATE("out of domain: solid-solid drag", T, FLUIDBED_SCALAR_TYPES) {
  const std::vector<ArgumentCase> arguments{
      {"phi_p", 0.25, outside_solid_fraction, {0.0}},
      {"phi_q", 0.125, outside_solid_fraction, {0.0}},
      {"p.density", 2500.0, not_positive},
      {"p.diameter", 1e-4, not_positive},
      {"q.density", 1500.0, not_positive},
      {"q.diameter", 2e-4, not_positive},
      {"restitution", 0.9, outside_closed_unit, {0.0, 1.0}},
      {"contact_rdf", 2.0, not_positive},
      {"relative_speed", 0.1, negative, {0.0}},
      {"friction_coefficient", 0.15, negative, {0.0}},
  };
  check_entry_point<T>("SyamlalSolidSolidDrag", arguments, [](const ValuesOf<T>& v) {
    return SyamlalSolidSolidDrag{parameter(v, 9)}.checked(v[0], v[1], Particles<T>{v[2], v[3]},
                                                          Particles<T>{v[4], v[5]}, v[6], v[7], v[8]);
  });
}

TEST_CASE_TEMPLATE("out of domain: algebraic granular temperature, free and through a ConstitutiveSet", T,
                   FLUIDBED_SCALAR_TYPES) {
  const ArgumentCase beta{"beta", 10.0, negative, {0.0}};
  const std::vector<ArgumentCase> free =
      concatenated(concatenated({solid_fraction, g0}, material),
                   concatenated(strain_rate, {beta, {"length_scale", 0.05, not_positive}}));
  check_entry_point<T>("algebraic_granular_temperature", free, [](const ValuesOf<T>& v) {
    return algebraic_granular_temperature(LunPressure{}, HrenyaSinclairViscosity(v[8]), LunBulkViscosity{},
                                          LunDissipation{}, v[0], v[1], material_of(v, 2), rate_of(v, 5), v[7],
                                          fluidbed::checked);
  });
  // No dissipation (e = 1) and compression: no finite Θ, reported instead of returned as +∞.
  CHECK_THROWS_WITH_AS(algebraic_granular_temperature(LunPressure{}, GidaspowViscosity{}, LunBulkViscosity{},
                                                      LunDissipation{}, T(0.3L), T(2),
                                                      GranularMaterial<T>{T(5e-4L), T(2500), T(1)},
                                                      StrainRate<T>{T(-100), T(2)}, T(0), fluidbed::checked),
                       doctest::Contains("'beta' = 0"), std::domain_error);

  const auto set_of = [](const ValuesOf<T>& v, std::size_t at) {
    return ConstitutiveSet{Ogawa(v[at], v[at + 1]), LunPressure{}, HrenyaSinclairViscosity(v[at + 2]),
                           HrenyaSinclairConductivity(v[at + 2])};
  };
  const std::vector<ArgumentCase> set_parameters = concatenated(packing, {{"length_scale", 0.05, not_positive}});
  check_entry_point<T>("ConstitutiveSet::checked",
                       concatenated(concatenated({solid_fraction, granular_temperature}, material), set_parameters),
                       [&](const ValuesOf<T>& v) {
                         const auto c = set_of(v, 5).checked(v[0], v[1], material_of(v, 2));
                         return c.radial_distribution + c.pressure + c.shear_viscosity + c.bulk_viscosity +
                                c.conductivity + c.dissipation;
                       });
  check_entry_point<T>(
      "ConstitutiveSet::algebraic_granular_temperature, checked",
      concatenated(concatenated(concatenated({solid_fraction}, material), concatenated(strain_rate, {beta})),
                   set_parameters),
      [&](const ValuesOf<T>& v) {
        return set_of(v, 7).algebraic_granular_temperature(v[0], material_of(v, 1), rate_of(v, 4), v[6],
                                                           fluidbed::checked);
      });
}
