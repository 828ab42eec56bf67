// Out-of-domain input for every checked entry point of kinetic_theory/: evaluate_checked of
// every radial distribution, closure, frictional law, gas-exchange source, mixture form and
// the solid–solid drag, gas_damping_checked, the algebraic granular temperature and the
// ConstitutiveSet (see test_out_of_domain.hpp for what each table entry checks). The laws'
// own parameters (packing limits, length scales, friction angles, …) are arguments too.
#include <doctest/doctest.h>

#include <array>
#include <span>
#include <string>

#include "fluidbed/kinetic_theory.hpp"
#include "test_out_of_domain.hpp"

namespace {

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;
using namespace fluidbed::test;

const Argument solid_fraction{"solid_fraction", 0.3, outside_solid_fraction, {0.0}};
const Argument granular_temperature{"granular_temperature", 0.01, negative, {0.0}};
const Argument g0{"g0", 2.0, not_positive};
const std::vector<Argument> material{
    {"material.diameter", 5e-4, not_positive},
    {"material.density", 2500.0, not_positive},
    {"material.restitution", 0.9, outside_closed_unit, {0.0, 1.0}},
};
const std::vector<Argument> strain_rate{
    {"rate.divergence", 0.5, non_finite, {0.0, -1.0}},
    {"rate.deviatoric_contraction", 2.0, negative, {0.0}},
};
// φ_max = 0.625 is also the out-of-domain margin (a margin must lie below φ_max).
const std::vector<Argument> packing{
    {"max_packing", 0.625, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {1.5, "1.5"}}), {1.0}},
    {"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {0.625, "0.625"}})},
};
const std::vector<Argument> johnson_jackson_parameters{
    {"min_fraction", 0.5, and_non_finite({{-0.5, "-0.5"}, {0.625, "0.625"}, {1.5, "1.5"}}), {0.0}},
    {"max_packing", 0.625, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {1.5, "1.5"}})},
    {"coefficient", 0.05, negative, {0.0}},
    {"numerator_exponent", 2.0, negative, {0.0}},
    {"denominator_exponent", 5.0, negative, {0.0}},
    {"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {0.625, "0.625"}})},
};
const std::vector<Argument> yield_parameters{
    {"friction_angle", 0.5, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}, {2.0, "2"}})},
    {"strain_rate_floor", 1e-6, not_positive},
};
const Argument temperature_floor{"temperature_floor", 1e-6, not_positive};

GranularMaterial<double> material_of(const Values& v, std::size_t at) { return {v[at], v[at + 1], v[at + 2]}; }
StrainRate<double> rate_of(const Values& v, std::size_t at) { return {v[at], v[at + 1]}; }
JohnsonJacksonPressure johnson_jackson_of(const Values& v, std::size_t at) {
  return {v[at], v[at + 1], v[at + 2], v[at + 3], v[at + 4], v[at + 5]};
}

// A closure law(φ, Θ, g0, material) built by make(values), the law's parameters (if any)
// being the arguments after the material.
template <class Make>
void check_closure(const std::string& label, const std::vector<Argument>& parameters, const Make& make) {
  check_entry_point(label, concatenated(concatenated({solid_fraction, granular_temperature, g0}, material), parameters),
                    [&](const Values& v) { return evaluate_checked(make(v), v[0], v[1], v[2], material_of(v, 3)); });
}

// A one-class g0(φ) built by make(values), its parameters after φ.
template <class Make>
void check_radial_distribution(const std::string& label, const std::vector<Argument>& parameters, const Make& make) {
  const Argument phi{"solid_fraction", 0.3, outside_solid_fraction, {0.0, 0.7}};  // 0.7: beyond packing, continued
  check_entry_point(label, concatenated({phi}, parameters),
                    [&](const Values& v) { return evaluate_checked(make(v), v[0]); });
}

}  // namespace

TEST_CASE("out of domain: one-class radial distribution functions and their packing parameters") {
  check_radial_distribution("CarnahanStarling", {}, [](const Values&) { return CarnahanStarling{}; });
  check_radial_distribution("PercusYevick", {}, [](const Values&) { return PercusYevick{}; });
  check_radial_distribution("LunSavage", packing, [](const Values& v) { return LunSavage{v[1], v[2]}; });
  check_radial_distribution("Ogawa", packing, [](const Values& v) { return Ogawa(v[1], v[2]); });
  check_radial_distribution("SinclairJackson", packing, [](const Values& v) { return SinclairJackson(v[1], v[2]); });
  check_radial_distribution("Gidaspow", packing,
                            [](const Values& v) { return GidaspowRadialDistribution(v[1], v[2]); });
  check_radial_distribution("MaAhmadi", {{"packing_margin", 0.01, and_non_finite({{0.0, "0"}, {-0.5, "-0.5"}})}},
                            [](const Values& v) { return MaAhmadi{v[1]}; });
  check_radial_distribution("LathouwersBellan", packing, [](const Values& v) { return LathouwersBellan{v[1], v[2]}; });
}

TEST_CASE("out of domain: pressures, viscosities, conductivities and dissipation") {
  check_closure("LunPressure", {}, [](const Values&) { return LunPressure{}; });
  check_closure("SyamlalRogersOBrienPressure", {}, [](const Values&) { return SyamlalRogersOBrienPressure{}; });
  check_closure("AhmadiMaPressure", {{"friction_coefficient", 0.25, negative, {0.0}}},
                [](const Values& v) { return AhmadiMaPressure{v[6]}; });
  check_closure("GidaspowViscosity", {}, [](const Values&) { return GidaspowViscosity{}; });
  check_closure("SyamlalViscosity", {}, [](const Values&) { return SyamlalViscosity{}; });
  const std::vector<Argument> length{{"length_scale", 0.05, not_positive}};
  check_closure("HrenyaSinclairViscosity", length, [](const Values& v) { return HrenyaSinclairViscosity(v[6]); });
  check_closure("LunBulkViscosity", {}, [](const Values&) { return LunBulkViscosity{}; });
  check_closure("GidaspowConductivity", {}, [](const Values&) { return GidaspowConductivity{}; });
  check_closure("SyamlalConductivity", {}, [](const Values&) { return SyamlalConductivity{}; });
  check_closure("HrenyaSinclairConductivity", length, [](const Values& v) { return HrenyaSinclairConductivity(v[6]); });
  check_closure("LunDissipation", {}, [](const Values&) { return LunDissipation{}; });
}

TEST_CASE("out of domain: frictional pressures and viscosities") {
  const Argument dense{"solid_fraction", 0.62, outside_solid_fraction, {0.0, 0.7}};
  check_entry_point("JohnsonJacksonPressure", concatenated({dense}, johnson_jackson_parameters),
                    [](const Values& v) { return evaluate_checked(johnson_jackson_of(v, 1), v[0]); });
  check_entry_point("SchaefferPressure",
                    {dense,
                     {"min_fraction", 0.5, outside_solid_fraction, {0.0}},
                     {"coefficient", 1e24, negative, {0.0}},
                     {"exponent", 10.0, negative, {0.0}}},
                    [](const Values& v) {
                      return evaluate_checked(SchaefferPressure{v[1], v[2], v[3]}, v[0]);
                    });
  check_entry_point(
      "SchaefferViscosity",
      concatenated(concatenated({{"frictional_pressure", 100.0, negative, {0.0}}}, strain_rate), yield_parameters),
      [](const Values& v) {
        return evaluate_checked(SchaefferViscosity{v[3], v[4]}, v[0], rate_of(v, 1));
      });
  const std::vector<Argument> srivastava_sundaresan = concatenated(
      concatenated(concatenated({dense, granular_temperature, {"diameter", 5e-4, not_positive}}, strain_rate),
                   johnson_jackson_parameters),
      yield_parameters);
  check_entry_point("SrivastavaSundaresan", srivastava_sundaresan, [](const Values& v) {
    const SrivastavaSundaresan law{johnson_jackson_of(v, 5), v[11], v[12]};
    const FrictionalStress<double> stress = evaluate_checked(law, v[0], v[1], v[2], rate_of(v, 3));
    return stress.pressure + stress.viscosity;
  });
}

TEST_CASE("out of domain: exchange of granular energy with the gas") {
  check_entry_point("gas_damping", {{"beta", 10.0, negative, {0.0}}, granular_temperature},
                    [](const Values& v) { return gas_damping_checked(v[0], v[1]); });
  check_entry_point("KochSanganiSource",
                    concatenated({solid_fraction,
                                  granular_temperature,
                                  g0,
                                  {"slip", 0.5, negative, {0.0}},
                                  {"gas_viscosity", 1.8e-5, not_positive}},
                                 concatenated(material, {temperature_floor})),
                    [](const Values& v) {
                      return evaluate_checked(KochSanganiSource{v[8]}, v[0], v[1], v[2], v[3], v[4], material_of(v, 5));
                    });
  check_entry_point("DragFluctuationSource",
                    concatenated({{"solid_fraction", 0.3, outside_open_unit},
                                  granular_temperature,
                                  {"beta", 100.0, negative, {0.0}},
                                  {"slip", 0.5, negative, {0.0}}},
                                 concatenated(material, {temperature_floor})),
                    [](const Values& v) {
                      return evaluate_checked(DragFluctuationSource{v[7]}, v[0], v[1], v[2], v[3], material_of(v, 4));
                    });
}

TEST_CASE("out of domain: mixture radial distributions, element by element, and their spans") {
  const std::vector<Argument> classes{
      {"fractions[0]", 0.25, negative, {0.0}},
      {"fractions[1]", 0.125, negative, {0.0}},
      {"diameters[0]", 1e-4, not_positive},
      {"diameters[1]", 2e-4, not_positive},
  };
  const auto pair_value = [](const auto& law, const Values& v) {
    const std::array<double, 2> fractions{v[0], v[1]}, diameters{v[2], v[3]};
    return evaluate_checked(law, std::span<const double>(fractions), std::span<const double>(diameters), 0, 1);
  };
  check_entry_point("Lebowitz", classes, [&](const Values& v) { return pair_value(Lebowitz{}, v); });
  check_entry_point("Mansoori", classes, [&](const Values& v) { return pair_value(Mansoori{}, v); });
  check_entry_point("ModifiedMansoori", concatenated(classes, packing), [&](const Values& v) {
    return pair_value(ModifiedMansoori{v[4], v[5]}, v);
  });

  const std::array<double, 2> diameters{1e-4, 2e-4};
  const auto message = [&](std::vector<double> fractions, std::size_t size, std::size_t i, std::size_t k) {
    return domain_error_message([&] {
      evaluate_checked(Mansoori{}, std::span<const double>(fractions), std::span<const double>(diameters.data(), size),
                       i, k);
    });
  };
  CHECK(message({0.5, 0.5}, 2, 0, 1).find("'sum of fractions' = 1 ") != std::string::npos);
  CHECK(message({0.75, 0.5}, 2, 0, 1).find("'sum of fractions' = 1.25") != std::string::npos);
  CHECK(message({0.25, 0.125}, 2, 2, 1).find("'i' = 2") != std::string::npos);
  CHECK(message({0.25, 0.125}, 2, 0, 5).find("'k' = 5") != std::string::npos);
  CHECK(message({0.25, 0.125}, 1, 0, 0).find("'diameters.size()' = 1") != std::string::npos);
  CHECK(message({}, 0, 0, 0).find("'fractions.size()' = 0") != std::string::npos);
}

TEST_CASE("out of domain: solid-solid drag") {
  const std::vector<Argument> arguments{
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
  check_entry_point("SyamlalSolidSolidDrag", arguments, [](const Values& v) {
    return evaluate_checked(SyamlalSolidSolidDrag{v[9]}, v[0], v[1], Particles<double>{v[2], v[3]},
                            Particles<double>{v[4], v[5]}, v[6], v[7], v[8]);
  });
}

TEST_CASE("out of domain: algebraic granular temperature, free and through a ConstitutiveSet") {
  const Argument beta{"beta", 10.0, negative, {0.0}};
  const std::vector<Argument> free =
      concatenated(concatenated({solid_fraction, g0}, material),
                   concatenated(strain_rate, {beta, {"length_scale", 0.05, not_positive}}));
  check_entry_point("algebraic_granular_temperature", free, [](const Values& v) {
    return algebraic_granular_temperature_checked(LunPressure{}, HrenyaSinclairViscosity(v[8]), LunBulkViscosity{},
                                                  LunDissipation{}, v[0], v[1], material_of(v, 2), rate_of(v, 5), v[7]);
  });
  // No dissipation (e = 1) and compression: no finite Θ, reported instead of returned as +∞.
  CHECK_THROWS_WITH_AS(
      algebraic_granular_temperature_checked(LunPressure{}, GidaspowViscosity{}, LunBulkViscosity{}, LunDissipation{},
                                             0.3, 2.0, {5e-4, 2500.0, 1.0}, StrainRate<double>{-100.0, 2.0}, 0.0),
      doctest::Contains("'beta' = 0"), std::domain_error);

  const auto set_of = [](const Values& v, std::size_t at) {
    return ConstitutiveSet{Ogawa(v[at], v[at + 1]), LunPressure{}, HrenyaSinclairViscosity(v[at + 2]),
                           HrenyaSinclairConductivity(v[at + 2])};
  };
  const std::vector<Argument> set_parameters = concatenated(packing, {{"length_scale", 0.05, not_positive}});
  check_entry_point("ConstitutiveSet::checked",
                    concatenated(concatenated({solid_fraction, granular_temperature}, material), set_parameters),
                    [&](const Values& v) {
                      const auto c = set_of(v, 5).checked(v[0], v[1], material_of(v, 2));
                      return c.radial_distribution + c.pressure + c.shear_viscosity + c.bulk_viscosity +
                             c.conductivity + c.dissipation;
                    });
  check_entry_point(
      "ConstitutiveSet::algebraic_granular_temperature_checked",
      concatenated(concatenated(concatenated({solid_fraction}, material), concatenated(strain_rate, {beta})),
                   set_parameters),
      [&](const Values& v) {
        return set_of(v, 7).algebraic_granular_temperature_checked(v[0], material_of(v, 1), rate_of(v, 4), v[6]);
      });
}
