// The kinetic-theory registries (kinetic_theory/registry.hpp) and the entry points every law
// has from its shape's base (granular_state.hpp): names unique and found, unknown names
// rejected with the list, every registered law finite at a valid state, with_derivatives equal
// to central differences and to the free with_derivatives (or a Dual through the hot path),
// checked equal to the hot path and throwing with the law's own name and the argument.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>

#include "fluidbed/kinetic_theory.hpp"
#include "same_arithmetic.hpp"
#include "test_out_of_domain.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

namespace {

using fluidbed::test::same_arithmetic;

const GranularMaterial<double> material{5e-4, 2500.0, 0.9};
const StrainRate<double> rate{0.5, 2.0};
constexpr double phi = 0.3, theta = 0.01, slip = 0.4, beta = 300.0, gas_viscosity = 1.8e-5;
const Particles<double> small{2500.0, 1e-4}, large{1500.0, 2e-4};

// Calls f(law) for every registered instance of every law of Registry, each as its own type.
template <class Registry, class F>
void for_each_law(const F& f) {
  std::apply([&](const auto&... law) { (f(law), ...); }, Registry::instances());
}

// (f(x + h) − f(x − h))/(2h), h relative to x.
template <class F>
double central_difference(const F& f, double x) {
  const double h = 1e-6 * std::abs(x);
  return (f(x + h) - f(x - h)) / (2 * h);
}

// A derivative against its central difference, on the scale of the value per unit x.
void check_slope(double derivative, double difference, double value, double x) {
  CHECK(std::abs(derivative - difference) <= 1e-6 * (std::abs(difference) + std::abs(value / x)));
}

template <class Registry>
void check_registry(std::size_t expected_size) {
  static_assert(Registry::names_are_unique());
  CHECK(Registry::size == expected_size);
  for (const auto& law : Registry::all()) {
    const std::string_view name = Registry::name_of(law);
    INFO("law ", name);
    REQUIRE(Registry::find(name).has_value());
    CHECK(Registry::name_of(*Registry::find(name)) == name);
    CHECK(Registry::name_of(Registry::make(name)) == name);
  }
  CHECK_FALSE(Registry::find("NoSuchLaw").has_value());
  std::string known;
  for (const auto& law : Registry::all()) known += (known.empty() ? "" : ", ") + std::string(Registry::name_of(law));
  CHECK_THROWS_WITH_AS(Registry::make("NoSuchLaw"), doctest::Contains(("'NoSuchLaw'; known: " + known).c_str()),
                       std::invalid_argument);
}

// A user's own granular pressure, twice Lun's.
struct Doubled : ConstitutiveLaw<Doubled> {
  constexpr std::string_view name() const { return "Doubled"; }
  constexpr std::string_view reference() const { return "a user's law (2026)"; }
  constexpr Validity<0> validity() const { return {}; }
  template <class S, class T>
  S kernel(const S& p, const S& t, const S& g0, const GranularMaterial<T>& m) const {
    return 2 * LunPressure{}.kernel(p, t, g0, m);
  }
};

// The message of a checked entry point names the law and the argument.
template <class Call>
void check_message(const std::string& law_name, const std::string& argument, const Call& call) {
  const std::string expected = "fluidbed::kinetic_theory::" + law_name + ": argument '" + argument + "'";
  INFO("expected: ", expected);
  CHECK(test::domain_error_message(call).find(expected) == 0);
}

}  // namespace

TEST_CASE("kinetic-theory registries: unique names, lookup, unknown names listed") {
  check_registry<RadialDistributions>(10);
  check_registry<MixtureRadialDistributions>(3);
  check_registry<GranularPressures>(3);
  check_registry<ShearViscosities>(4);
  check_registry<BulkViscosities>(1);
  check_registry<Conductivities>(4);
  check_registry<Dissipations>(1);
  check_registry<FrictionalPressures>(2);
  check_registry<FrictionalViscosities>(1);
  check_registry<FrictionalStresses>(1);
  check_registry<GasExchangeSources>(2);
  check_registry<SolidSolidDrags>(1);
  // A law's name is its type's: no two kinds share one (Lun's pressure, bulk viscosity and
  // dissipation were all "Lun").
  CHECK(LunPressure{}.name() == "LunPressure");
  CHECK(LunBulkViscosity{}.name() == "LunBulkViscosity");
  CHECK(LunDissipation{}.name() == "LunDissipation");
  CHECK(GidaspowRadialDistribution{0.63}.name() == "GidaspowRadialDistribution");
  // A user's law joins a kind without editing the library.
  using MyPressures = GranularPressures::with<Doubled>;
  const double doubled =
      std::visit([](const auto& law) { return law(phi, theta, 2.0, material); }, MyPressures::make("Doubled"));
  CHECK(doubled == 2 * LunPressure{}(phi, theta, 2.0, material));
}

TEST_CASE("g(phi): radial distributions and frictional pressures, finite, with_derivatives, checked") {
  const auto check = [](const auto& law, double x) {
    INFO(law.name(), " at phi = ", x);
    const double value = law(x);
    CHECK(std::isfinite(value));
    const ValueAndSlope<double> d = law.with_derivatives(x);
    CHECK(same_arithmetic(d.value, value));
    check_slope(d.d_solid_fraction, central_difference([&](double p) { return law(p); }, x), value, x);
    const ValueAndDerivatives<double> old =
        with_derivatives([&](const auto& p, const auto&) { return law(p); }, x, theta);
    CHECK(d.d_solid_fraction == doctest::Approx(old.d_solid_fraction).epsilon(1e-15));
    CHECK(law.checked(x) == value);
    CHECK(law.checked_with_derivatives(x).d_solid_fraction == d.d_solid_fraction);
    check_message(std::string(law.name()), "solid_fraction", [&] { law.checked(-0.5); });
    check_message(std::string(law.name()), "solid_fraction", [&] { law.checked_with_derivatives(1.0); });
  };
  for_each_law<RadialDistributions>([&](const auto& law) { check(law, phi); });
  for_each_law<FrictionalPressures>([&](const auto& law) { check(law, 0.615); });
  check_message("LunSavage", "packing_margin", [] { LunSavage{0.63, 0.7}.checked(phi); });
}

TEST_CASE("law(phi, Theta, g0, material): finite, with_derivatives through g0(phi), checked") {
  const auto check = [](const auto& law) {
    for (const double x : {0.05, phi, 0.55}) {
      const auto rdf = Ogawa{0.63};
      INFO(law.name(), " at phi = ", x);
      const double value = law(x, theta, rdf(x), material);
      CHECK(std::isfinite(value));
      CHECK(value >= 0);
      const ValueAndDerivatives<double> d = law.with_derivatives(x, theta, rdf, material);
      CHECK(same_arithmetic(d.value, value));
      const ValueAndDerivatives<double> old =
          with_derivatives([&](const auto& p, const auto& t) { return law(p, t, rdf(p), material); }, x, theta);
      CHECK(d.d_solid_fraction == old.d_solid_fraction);
      CHECK(d.d_granular_temperature == old.d_granular_temperature);
      check_slope(d.d_solid_fraction,
                  central_difference([&](double p) { return law(p, theta, rdf(p), material); }, x), value, x);
      check_slope(d.d_granular_temperature,
                  central_difference([&](double t) { return law(x, t, rdf(x), material); }, theta), value, theta);
      CHECK(law.checked(x, theta, rdf(x), material) == value);
      const ValueAndDerivatives<double> checked = law.checked_with_derivatives(x, theta, rdf, material);
      CHECK(checked.d_solid_fraction == d.d_solid_fraction);
    }
    const std::string name(law.name());
    check_message(name, "solid_fraction", [&] { law.checked(-0.5, theta, 2.0, material); });
    check_message(name, "granular_temperature", [&] { law.checked(phi, -1.0, 2.0, material); });
    check_message(name, "g0", [&] { law.checked(phi, theta, 0.0, material); });
    const GranularMaterial<double> elastic_beyond{5e-4, 2500.0, 1.5};
    check_message(name, "material.restitution", [&] { law.checked(phi, theta, 2.0, elastic_beyond); });
    // The radial distribution's own checks come first, with its name.
    check_message("Ogawa", "max_packing", [&] { law.checked_with_derivatives(phi, theta, Ogawa{1.5}, material); });
  };
  for_each_law<GranularPressures>(check);
  for_each_law<ShearViscosities>(check);
  for_each_law<BulkViscosities>(check);
  for_each_law<Conductivities>(check);
  for_each_law<Dissipations>(check);
  check_message("HrenyaSinclairViscosity", "length_scale",
                [] { HrenyaSinclairViscosity(0.0).checked(phi, theta, 2.0, material); });
}

TEST_CASE("friction: Schaeffer's viscosity and Srivastava-Sundaresan's stress, with_derivatives and checked") {
  for_each_law<FrictionalViscosities>([](const auto& law) {
    const double p_f = 120.0;
    const double value = law(p_f, rate);
    CHECK(std::isfinite(value));
    const auto d = law.with_derivatives(p_f, rate);
    CHECK(same_arithmetic(d.value, value));
    check_slope(d.d_frictional_pressure, central_difference([&](double p) { return law(p, rate); }, p_f), value, p_f);
    CHECK(d.d_divergence == 0);
    check_slope(d.d_deviatoric_contraction,
                central_difference(
                    [&](double c) { return law(p_f, StrainRate<double>{rate.divergence, c}); },
                    rate.deviatoric_contraction),
                value, rate.deviatoric_contraction);
    CHECK(law.checked(p_f, rate) == value);
    CHECK(law.checked_with_derivatives(p_f, rate).d_frictional_pressure == d.d_frictional_pressure);
    check_message(std::string(law.name()), "frictional_pressure", [&] { law.checked(-1.0, rate); });
    check_message(std::string(law.name()), "rate.deviatoric_contraction",
                  [&] { law.checked(p_f, StrainRate<double>{0.0, -1.0}); });
  });
  for_each_law<FrictionalStresses>([](const auto& law) {
    const double x = 0.6, d = 2e-4;
    const auto stress = law(x, theta, d, rate);
    CHECK(std::isfinite(stress.pressure));
    CHECK(std::isfinite(stress.viscosity));
    const auto derivatives = law.with_derivatives(x, theta, d, rate);
    const double div = rate.divergence, c = rate.deviatoric_contraction;
    const auto check_part = [&](bool pressure, const FrictionDerivatives<double>& got) {
      const auto f = [&](double p, double t, double v, double w) {
        const auto s = law(p, t, d, StrainRate<double>{v, w});
        return pressure ? s.pressure : s.viscosity;
      };
      CHECK(same_arithmetic(got.value, f(x, theta, div, c)));
      check_slope(got.d_solid_fraction, central_difference([&](double v) { return f(v, theta, div, c); }, x),
                  got.value, x);
      check_slope(got.d_granular_temperature, central_difference([&](double v) { return f(x, v, div, c); }, theta),
                  got.value, theta);
      check_slope(got.d_divergence, central_difference([&](double v) { return f(x, theta, v, c); }, div), got.value,
                  div);
      check_slope(got.d_deviatoric_contraction, central_difference([&](double v) { return f(x, theta, div, v); }, c),
                  got.value, c);
    };
    check_part(true, derivatives.pressure);
    check_part(false, derivatives.viscosity);
    CHECK(law.checked(x, theta, d, rate).pressure == stress.pressure);
    CHECK(same_arithmetic(law.checked_with_derivatives(x, theta, d, rate).viscosity.value, stress.viscosity));
    check_message(std::string(law.name()), "diameter", [&] { law.checked(x, theta, 0.0, rate); });
  });
}

TEST_CASE("gas exchange sources: finite, with_derivatives, checked") {
  const auto rdf = CarnahanStarling{};
  const KochSanganiSource koch_sangani = std::get<KochSanganiSource>(GasExchangeSources::make("KochSanganiSource"));
  const auto koch = [&](double p, double t, double w) {
    return koch_sangani(p, t, rdf(p), w, gas_viscosity, material);
  };
  const double j = koch(phi, theta, slip);
  CHECK(std::isfinite(j));
  const GasExchangeDerivatives<double> k =
      koch_sangani.with_derivatives(phi, theta, rdf, slip, gas_viscosity, material);
  CHECK(same_arithmetic(k.value, j));
  check_slope(k.d_solid_fraction, central_difference([&](double v) { return koch(v, theta, slip); }, phi), j, phi);
  check_slope(k.d_granular_temperature, central_difference([&](double v) { return koch(phi, v, slip); }, theta), j,
              theta);
  CHECK(k.d_beta == 0);
  check_slope(k.d_slip, central_difference([&](double v) { return koch(phi, theta, v); }, slip), j, slip);
  CHECK(koch_sangani.checked(phi, theta, rdf(phi), slip, gas_viscosity, material) == j);
  CHECK(koch_sangani.checked_with_derivatives(phi, theta, rdf, slip, gas_viscosity, material).d_slip == k.d_slip);
  check_message("KochSanganiSource", "gas_viscosity",
                [&] { koch_sangani.checked(phi, theta, 2.0, slip, 0.0, material); });

  const DragFluctuationSource drag_source =
      std::get<DragFluctuationSource>(GasExchangeSources::make("DragFluctuationSource"));
  const auto source = [&](double p, double t, double b, double w) { return drag_source(p, t, b, w, material); };
  const double s = source(phi, theta, beta, slip);
  CHECK(std::isfinite(s));
  const GasExchangeDerivatives<double> g = drag_source.with_derivatives(phi, theta, beta, slip, material);
  CHECK(same_arithmetic(g.value, s));
  check_slope(g.d_solid_fraction, central_difference([&](double v) { return source(v, theta, beta, slip); }, phi), s,
              phi);
  check_slope(g.d_granular_temperature,
              central_difference([&](double v) { return source(phi, v, beta, slip); }, theta), s, theta);
  check_slope(g.d_beta, central_difference([&](double v) { return source(phi, theta, v, slip); }, beta), s, beta);
  check_slope(g.d_slip, central_difference([&](double v) { return source(phi, theta, beta, v); }, slip), s, slip);
  CHECK(drag_source.checked(phi, theta, beta, slip, material) == s);
  CHECK(drag_source.checked_with_derivatives(phi, theta, beta, slip, material).d_beta == g.d_beta);
  check_message("DragFluctuationSource", "solid_fraction",
                [&] { drag_source.checked(0.0, theta, beta, slip, material); });
  // The sink is a single function: one entry point and an error policy.
  CHECK(gas_damping(beta, theta, fluidbed::checked) == gas_damping(beta, theta));
  check_message("gas_damping", "beta", [] { gas_damping(-1.0, theta, fluidbed::checked); });
}

TEST_CASE("mixture radial distributions: finite, with_derivatives in every fraction, checked") {
  const std::array<double, 3> fractions{0.2, 0.1, 0.05}, diameters{1e-4, 2e-4, 3e-4};
  const std::span<const double> d(diameters);
  for_each_law<MixtureRadialDistributions>([&](const auto& law) {
    INFO(law.name());
    const auto at = [&](std::array<double, 3> f) { return law(std::span<const double>(f), d, 0, 2); };
    const double value = at(fractions);
    CHECK(std::isfinite(value));
    const MixtureValueAndDerivatives<double, 3> g = law.with_derivatives(fractions, d, 0, 2);
    CHECK(g.value == value);
    for (std::size_t m = 0; m < 3; ++m) {
      const auto f = [&](double x) {
        std::array<double, 3> moved = fractions;
        moved[m] = x;
        return at(moved);
      };
      check_slope(g.d_fractions[m], central_difference(f, fractions[m]), value, fractions[m]);
    }
    CHECK(law.checked(std::span<const double>(fractions), d, 0, 2) == value);
    CHECK(law.checked_with_derivatives(fractions, d, 0, 2).d_fractions[1] == g.d_fractions[1]);
    const std::array<double, 3> negative{0.2, -0.5, 0.05};
    check_message(std::string(law.name()), "fractions[1]",
                  [&] { law.checked(std::span<const double>(negative), d, 0, 2); });
  });
}

TEST_CASE("solid-solid drag: finite, with_derivatives, checked") {
  for_each_law<SolidSolidDrags>([](const auto& law) {
    const auto k = [&](double p, double q, double g, double w) { return law(p, q, small, large, 0.9, g, w); };
    const double value = k(0.2, 0.1, 2.0, 0.1);
    CHECK(std::isfinite(value));
    const SolidSolidDragDerivatives<double> d = law.with_derivatives(0.2, 0.1, small, large, 0.9, 2.0, 0.1);
    CHECK(same_arithmetic(d.value, value));
    check_slope(d.d_phi_p, central_difference([&](double v) { return k(v, 0.1, 2.0, 0.1); }, 0.2), value, 0.2);
    check_slope(d.d_phi_q, central_difference([&](double v) { return k(0.2, v, 2.0, 0.1); }, 0.1), value, 0.1);
    check_slope(d.d_contact_rdf, central_difference([&](double v) { return k(0.2, 0.1, v, 0.1); }, 2.0), value, 2.0);
    check_slope(d.d_relative_speed, central_difference([&](double v) { return k(0.2, 0.1, 2.0, v); }, 0.1), value, 0.1);
    CHECK(law.checked(0.2, 0.1, small, large, 0.9, 2.0, 0.1) == value);
    CHECK(law.checked_with_derivatives(0.2, 0.1, small, large, 0.9, 2.0, 0.1).d_phi_q == d.d_phi_q);
    check_message(std::string(law.name()), "phi_p", [&] { law.checked(-0.5, 0.1, small, large, 0.9, 2.0, 0.1); });
  });
}

TEST_CASE("a ConstitutiveSet has the same entry points: checked_with_derivatives equals with_derivatives") {
  const ConstitutiveSet set{Ogawa{0.63}, LunPressure{}, HrenyaSinclairViscosity(0.05), SyamlalConductivity{}};
  const auto d = set.with_derivatives(phi, theta, material);
  const auto c = set.checked_with_derivatives(phi, theta, material);
  CHECK(c.pressure.d_solid_fraction == d.pressure.d_solid_fraction);
  CHECK(c.shear_viscosity.d_granular_temperature == d.shear_viscosity.d_granular_temperature);
  CHECK(test::domain_error_message([&] { set.checked_with_derivatives(1.0, theta, material); })
            .find("fluidbed::kinetic_theory::ConstitutiveSet: argument 'solid_fraction' = 1") == 0);
  const ConstitutiveSet bad{Ogawa{0.63}, LunPressure{}, HrenyaSinclairViscosity(-1.0), SyamlalConductivity{}};
  CHECK(test::domain_error_message([&] { bad.checked_with_derivatives(phi, theta, material); })
            .find("'length_scale' = -1") != std::string::npos);
}
