// Every closure's run-time parameters by name (core/parameters.hpp), through the registries:
// each parameter a closure lists is one its parameter domain validates, under the same name
// and in the same order, and every parameter its domain validates is listed (but for constants
// of a fit, below); set and get reach that parameter and no other; set_parameter_checked throws
// the checked entry points' errors and leaves the closure unchanged; a parameter set by name
// changes the closure as its constructor would.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "fluidbed/registries.hpp"

namespace {

using namespace fluidbed;

// Values a parameter domain validates that are not parameters: Ma and Ahmadi's packing limit is
// a constant of their fit (radial_distribution.hpp).
const std::set<std::pair<std::string_view, std::string_view>> constants_of_a_fit{
    {"MaAhmadi", "max_packing"}, {"SongStrattMason", "max_packing"}, {"TobochnikChapin", "max_packing"}};

template <class F>
void for_each_closure(F&& f) {
  Registries::for_each([&](auto registry) {
    std::apply([&](const auto&... law) { (f(law), ...); }, decltype(registry)::type::instances());
  });
}

// The names and values of a closure's parameter domain.
template <class Law>
std::vector<std::pair<std::string_view, double>> domain_values(const Law& law) {
  std::vector<std::pair<std::string_view, double>> values;
  for (const auto& argument : parameter_domain_in_double(law)) values.emplace_back(argument.name, argument.value);
  return values;
}

}  // namespace

TEST_CASE("parameters: every closure lists the parameters its domain validates, by the same names, in order") {
  int closures_with_parameters = 0;
  for_each_closure([&](const auto& law) {
    using Law = std::remove_cvref_t<decltype(law)>;
    CAPTURE(law.name());
    std::vector<std::string_view> listed, validated;
    for (const auto& p : parameters_of<Law>()) listed.push_back(p.name);
    for (const auto& [name, value] : domain_values(law))
      if (!constants_of_a_fit.contains({law.name(), name})) validated.push_back(name);
    CHECK(listed == validated);
    closures_with_parameters += !listed.empty();
  });
  CHECK(closures_with_parameters == 31);
}

TEST_CASE("parameters: set and get reach the named parameter and no other") {
  for_each_closure([](const auto& law) {
    using Law = std::remove_cvref_t<decltype(law)>;
    for (const auto& p : parameters_of<Law>()) {
      CAPTURE(law.name());
      CAPTURE(p.name);
      const double before = *get_parameter(law, p.name);
      const double changed = before / 2 + 0.125;  // differs from before for every registered value
      Law copy = law;
      REQUIRE(set_parameter(copy, p.name, changed));
      CHECK(*get_parameter(copy, p.name) == changed);
      // Every other value of the domain is what it was.
      const auto old_values = domain_values(law), new_values = domain_values(copy);
      REQUIRE(old_values.size() == new_values.size());
      for (std::size_t i = 0; i < old_values.size(); ++i)
        if (old_values[i].first != p.name) CHECK(new_values[i].second == old_values[i].second);
        else CHECK(new_values[i].second == changed);
    }
    Law copy = law;
    CHECK_FALSE(set_parameter(copy, "no_such_parameter", 1.0));
    CHECK_FALSE(get_parameter(law, "no_such_parameter").has_value());
  });
}

TEST_CASE("parameters: set_parameter_checked throws the checked API's errors and leaves the closure as it was") {
  drag::SyamlalOBrien law;
  set_parameter_checked(law, "c1", 0.9);
  CHECK(law.c1() == 0.9);
  CHECK_THROWS_WITH_AS(set_parameter_checked(law, "c1", -1.0),
                       "fluidbed::SyamlalOBrien: argument 'c1' = -1 is out of domain (must be finite and > 0)",
                       std::domain_error);
  CHECK_THROWS_AS(set_parameter_checked(law, "d1", std::numeric_limits<double>::quiet_NaN()), std::domain_error);
  CHECK(law.c1() == 0.9);
  CHECK(law.d1() == 2.65);
  CHECK_THROWS_WITH_AS(set_parameter_checked(law, "exponent", 2.65),
                       "fluidbed: SyamlalOBrien has no parameter 'exponent'; its parameters: c1, d1", std::invalid_argument);
  drag::Ergun ergun;
  CHECK_THROWS_WITH_AS(set_parameter_checked(ergun, "c1", 1.0), "fluidbed: Ergun has no parameter 'c1'; its parameters: none",
                       std::invalid_argument);
  // A domain that depends on another parameter: the packing margin below the packing limit.
  auto radial = kinetic_theory::RadialDistributions::make("LunSavage");
  std::visit([](auto& l) { CHECK_THROWS_AS(set_parameter_checked(l, "packing_margin", 0.7), std::domain_error); },
             radial);
}

TEST_CASE("parameters: a parameter set by name changes the closure as its constructor would") {
  // WenYu1966 (exponent 2.70) with the exponent 2.65 is WenYuGidaspow's formula.
  auto wen_yu_1966 = drag::DragLaws::make("WenYu1966");
  std::visit([](auto& l) { set_parameter_checked(l, "exponent", 2.65); }, wen_yu_1966);
  const drag::DragState<double> state{0.7, 0.3, {1.2, 1.8e-5}, 3e-4};
  const auto beta = [&](const drag::DragLaws::Variant& law) {
    return std::visit([&](const auto& l) { return l.checked(state).pressure_gradient(); }, law);
  };
  CHECK(beta(wen_yu_1966) == beta(drag::DragLaws::make("WenYuGidaspow")));
  CHECK(beta(wen_yu_1966) != beta(drag::DragLaws::make("WenYu1966")));
  // Srivastava–Sundaresan's critical-state pressure is set through its own parameter names.
  kinetic_theory::SrivastavaSundaresan stress = kinetic_theory::SrivastavaSundaresan::registered()[0];
  set_parameter_checked(stress, "coefficient", 0.1);
  set_parameter_checked(stress, "friction_angle", 0.4);
  CHECK(stress.critical_state_pressure.coefficient == 0.1);
  CHECK(stress.friction_angle == 0.4);
  // The lists are constant expressions: a host can build them at compile time.
  static_assert(get_parameter(drag::SyamlalOBrien{}, "d1") == 2.65);
  static_assert(parameters_of<kinetic_theory::SrivastavaSundaresan>().size() == 8);
}
