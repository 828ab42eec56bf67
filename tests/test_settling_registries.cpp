// The one calling shape of the single-particle, settling and fluidization closures: their
// registries (unique names, lookup, a user's own closure), the checked entry points' messages
// (naming the closure and the argument), and with_derivatives against a central finite
// difference of the hot path.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fluidbed/core/closure.hpp"
#include "fluidbed/drag/any_drag_law.hpp"
#include "fluidbed/fluidization.hpp"
#include "fluidbed/settling.hpp"
#include "fluidbed/single_particle.hpp"
#include "test_out_of_domain.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;

namespace {

const Fluid<double> water{.density = 998.0, .viscosity = 1.0e-3};
const Particles<double> sand{.density = 2650.0, .diameter = 0.5e-3};
const Particles<double> bubble{.density = 1.2, .diameter = 1e-3};

using fluidization::MinimumFluidizations;
using settling::RichardsonZakiExponents;
using single_particle::DragCoefficients;
using single_particle::TerminalVelocities;

static_assert(DragCoefficients::names_are_unique());
static_assert(TerminalVelocities::names_are_unique());
static_assert(RichardsonZakiExponents::names_are_unique());
static_assert(MinimumFluidizations::names_are_unique());

// Every name of a registry, in order.
template <class Registry>
std::vector<std::string> names_of() {
  std::vector<std::string> names;
  for (const auto& law : Registry::all()) names.emplace_back(Registry::name_of(law));
  return names;
}

// Lookup of every name returns that law, and make() of an unknown name throws listing every name.
template <class Registry>
void check_lookup(const char* family) {
  INFO("registry of ", family);
  const std::vector<std::string> names = names_of<Registry>();
  for (const std::string& name : names) {
    const auto found = Registry::find(name);
    REQUIRE(found.has_value());
    CHECK(Registry::name_of(*found) == name);
    CHECK(Registry::name_of(Registry::make(name)) == name);
  }
  CHECK(!Registry::find("NoSuchLaw").has_value());
  try {
    (void)Registry::make("NoSuchLaw");
    FAIL("make of an unknown name did not throw");
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    CHECK(message.find(std::string("unknown ") + family + " 'NoSuchLaw'") != std::string::npos);
    for (const std::string& name : names) CHECK(message.find(name) != std::string::npos);
  }
  Registry::for_each_type([](auto type) {
    using Law = typename decltype(type)::type;
    static_assert(Closure<Law>, "every registered law has name(), reference() and validity()");
    CHECK(!Law{}.reference().empty());
  });
}

double central_difference(const auto& f, double x) {
  const double h = 1e-6 * std::max(x, 1.0);
  return (f(x + h) - f(x - h)) / (2 * h);
}

// Every correlation Re(Ar) of a registry: with_derivatives gives the value of the hot path and
// a dRe/dAr equal to a central difference, at each Ar of `grid`.
template <class Registry>
void check_archimedes_correlations(std::initializer_list<double> grid) {
  for (const auto& any : Registry::all())
    std::visit(
        [&](const auto& law) {
          for (const double ar : grid) {
            INFO(law.name(), " at Ar = ", ar);
            const auto with = law.with_derivatives(ar);
            CHECK(fluidbed::test::same_arithmetic(with.value, law.reynolds(ar)));
            const auto re_of = [&](double a) { return law.reynolds(a); };
            CHECK(with.d_archimedes == doctest::Approx(central_difference(re_of, ar)).epsilon(1e-6));
          }
        },
        any);
}

// A user's own Richardson–Zaki exponent: a constant n.
struct ConstantExponent : settling::RichardsonZakiExponent<ConstantExponent> {
  static constexpr const char* argument = "terminal_reynolds";
  constexpr std::string_view name() const { return "ConstantExponent"; }
  constexpr std::string_view reference() const { return "a test"; }
  constexpr Validity<0> validity() const { return {}; }
  template <class S>
  S exponent(const S& /*terminal_reynolds*/) const {
    return S(3.0);
  }
};

}  // namespace

TEST_CASE("registries of single_particle, settling and fluidization: lookup, unknown names, metadata") {
  check_lookup<DragCoefficients>("single-sphere drag coefficient");
  check_lookup<TerminalVelocities>("terminal velocity");
  check_lookup<RichardsonZakiExponents>("Richardson-Zaki exponent");
  check_lookup<MinimumFluidizations>("minimum fluidization correlation");
}

TEST_CASE("names are unique across these registries and the drag laws, and say what the closure computes") {
  std::vector<std::string> all;
  for (const auto& names :
       {names_of<DragCoefficients>(), names_of<TerminalVelocities>(), names_of<RichardsonZakiExponents>(),
        names_of<MinimumFluidizations>(), names_of<drag::DragLaws>()})
    all.insert(all.end(), names.begin(), names.end());
  CHECK(std::set<std::string>(all.begin(), all.end()).size() == all.size());
  // The naming rule: authors, then what the closure computes (a new law added to a registry
  // follows it without an edit here).
  const auto all_end_with = [](const std::vector<std::string>& names, const std::string& suffix) {
    for (const std::string& name : names) {
      INFO(name, " should end with ", suffix);
      CHECK((name.size() > suffix.size() && name.ends_with(suffix)));
    }
  };
  all_end_with(names_of<DragCoefficients>(), "Coefficient");
  all_end_with(names_of<TerminalVelocities>(), "TerminalVelocity");
  all_end_with(names_of<RichardsonZakiExponents>(), "Exponent");
  all_end_with(names_of<MinimumFluidizations>(), "MinimumFluidization");
  // The seed's forms are all there.
  for (const char* name : {"StokesTerminalVelocity", "NewtonTerminalVelocity", "DallavalleTerminalVelocity",
                           "SchillerNaumannTerminalVelocity"})
    CHECK(TerminalVelocities::find(name).has_value());
  for (const char* name : {"MazzeiExponent", "RichardsonZaki1954Exponent", "RoweExponent", "KhanRichardsonExponent",
                           "GarsideAlDibouniExponent"})
    CHECK(RichardsonZakiExponents::find(name).has_value());
}

TEST_CASE("a user's own law extends a registry") {
  using MyExponents = RichardsonZakiExponents::with<ConstantExponent>;
  static_assert(MyExponents::names_are_unique());
  const MyExponents::Variant law = MyExponents::make("ConstantExponent");
  CHECK(std::visit([](const auto& l) { return l(10.0); }, law) == 3.0);
  CHECK(std::visit([](const auto& l) { return l.checked(10.0); }, law) == 3.0);
  CHECK(std::get<ConstantExponent>(law).with_derivatives(10.0).d_argument == 0.0);
  CHECK_THROWS_WITH_AS(ConstantExponent{}.checked(-1.0), doctest::Contains("'terminal_reynolds' = -1"),
                       std::domain_error);
}

TEST_CASE("checked entry points name the closure and the argument") {
  for (const auto& any : DragCoefficients::all())
    std::visit(
        [](const auto& law) {
          const std::string message = test::domain_error_message([&] { (void)law.checked(-1.0); });
          INFO(message);
          CHECK(message.find("fluidbed::" + std::string(law.name()) + ": argument 'reynolds' = -1") == 0);
          CHECK_THROWS_AS((void)law.checked_with_derivatives(test::nan), std::domain_error);
          CHECK(law.checked(2.0) == law(2.0));
        },
        any);
  for (const auto& any : TerminalVelocities::all())
    std::visit(
        [](const auto& law) {
          const std::string name(law.name());
          CHECK(test::domain_error_message([&] {
                  (void)law.checked_reynolds(-1.0);
                }).find("fluidbed::" + name + ": argument 'archimedes' = -1") == 0);
          CHECK(test::domain_error_message([&] {
                  (void)law.checked(water, bubble);
                }).find("fluidbed::" + name + ": argument 'particles.density' = 1.2") == 0);
          CHECK_THROWS_AS((void)law.checked_with_derivatives(test::inf), std::domain_error);
          CHECK(law.checked(water, sand) == law(water, sand));
        },
        any);
  for (const auto& any : RichardsonZakiExponents::all())
    std::visit(
        [](const auto& law) {
          const std::string message = test::domain_error_message([&] { (void)law.checked(-1.0); });
          INFO(message);
          CHECK(message.find("fluidbed::" + std::string(law.name()) + ": argument '" + std::string(law.argument) +
                             "' = -1") == 0);
          CHECK(law.checked(50.0) == law(50.0));
        },
        any);
  for (const auto& any : MinimumFluidizations::all())
    std::visit(
        [](const auto& law) {
          CHECK(test::domain_error_message([&] {
                  (void)law.checked_reynolds(-1.0);
                }).find("fluidbed::" + std::string(law.name()) + ": argument 'archimedes' = -1") == 0);
          CHECK(law.checked(water, sand) == law(water, sand));
        },
        any);
  // The parameters' domains, declared once with the law.
  CHECK_THROWS_WITH_AS((void)settling::RichardsonZaki1954Exponent(-0.5).checked(1.0),
                       doctest::Contains("fluidbed::RichardsonZaki1954Exponent: argument 'wall_ratio' = -0.5"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS((void)fluidization::ErgunMinimumFluidization(0.4, 0.0).checked_reynolds(10.0),
                       doctest::Contains("fluidbed::ErgunMinimumFluidization: argument 'sphericity' = 0"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS((void)fluidization::ErgunMinimumFluidization(1.0).checked(water, sand),
                       doctest::Contains("argument 'voidage' = 1"), std::domain_error);
}

TEST_CASE("with_derivatives: the hot path's value and a central finite difference") {
  for (const auto& any : DragCoefficients::all())
    std::visit(
        [](const auto& law) {
          for (const double re : {0.05, 3.0, 150.0, 2500.0}) {
            INFO(law.name(), " at Re = ", re);
            const auto with = law.with_derivatives(re);
            CHECK(fluidbed::test::same_arithmetic(with.value, law(re)));
            CHECK(with.d_reynolds == doctest::Approx(central_difference(law, re)).epsilon(1e-6));
          }
        },
        any);
  // Ar = 3e5 stays off the Schiller–Naumann gap (328 716 < Ar < 330 000).
  check_archimedes_correlations<TerminalVelocities>({0.5, 40.0, 3.0e3, 3.0e5, 1.0e8});
  // At Ar = 0 the viscous limits: 1/18 (Stokes, Schiller–Naumann), 1/17.28 (Dallavalle).
  CHECK(single_particle::StokesTerminalVelocity{}.with_derivatives(0.0).d_archimedes == 1.0 / 18);
  CHECK(single_particle::SchillerNaumannTerminalVelocity{}.with_derivatives(0.0).d_archimedes == 1.0 / 18);
  CHECK(single_particle::DallavalleTerminalVelocity{}.with_derivatives(0.0).d_archimedes == 1.0 / 17.28);
  for (const auto& any : RichardsonZakiExponents::all())
    std::visit(
        [](const auto& law) {
          // Off the switches of the 1954 correlation (0.2, 1, 200, 500).
          for (const double x : {0.05, 0.6, 7.0, 350.0, 4.0e4}) {
            INFO(law.name(), " at ", law.argument, " = ", x);
            const auto with = law.with_derivatives(x);
            CHECK(fluidbed::test::same_arithmetic(with.value, law(x)));
            CHECK(with.d_argument == doctest::Approx(central_difference(law, x)).epsilon(1e-6));
          }
        },
        any);
  // With a wall ratio: the parameter enters the kernel, not the derivative's variable.
  const settling::KhanRichardsonExponent walled(0.02);
  CHECK(walled.with_derivatives(500.0).d_argument == doctest::Approx(central_difference(walled, 500.0)).epsilon(1e-6));
  check_archimedes_correlations<MinimumFluidizations>({1e-3, 10.0, 1.0e4, 1.0e7});
}

TEST_CASE("the equilibrium solvers take any variant of drag laws, not only AnyDragLaw") {
  using Pair = std::variant<drag::Ergun, drag::MazzeiLettieri>;
  const double u = 5e-3;
  CHECK(*fluidization::equilibrium_voidage(Pair{drag::MazzeiLettieri{}}, u, water, sand) ==
        *fluidization::equilibrium_voidage(drag::MazzeiLettieri{}, u, water, sand));
  CHECK(*fluidization::voidage_ratio(Pair{drag::Ergun{}}, 0.5, 0.5) ==
        *fluidization::voidage_ratio(drag::Ergun{}, 0.5, 0.5));
  CHECK(fluidization::equivalent_exponent(Pair{drag::Ergun{}}, 0.5, 1.0) ==
        fluidization::equivalent_exponent(drag::Ergun{}, 0.5, 1.0));
}
