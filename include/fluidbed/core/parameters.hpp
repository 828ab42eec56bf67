// fluidbed — a closure's run-time parameters by name, for whatever sets them from outside C++
// (the C interface, Python, the OpenFOAM plugin's dictionaries), so that no binding keeps its
// own list of which law has which parameter.
//
// A closure with parameters lists them once, by the names its parameter_domain gives them:
//
//   static constexpr auto parameters() {
//     return std::array{parameter<&LunSavage::max_packing>("max_packing"),
//                       parameter<&LunSavage::packing_margin>("packing_margin")};
//   }
//
// (private members too: the list is written inside the class; a law holding another law's
// parameters lists them with nested_parameters). A closure without parameters lists none.
// Setting a parameter does not validate it: the closure's checked entry points validate its
// parameters with its arguments at every call, and set_parameter_checked (core/errors.hpp)
// validates at once. Names are snake_case; angles are in radians, as everywhere in the library.
#pragma once

#include "config.hpp"  // first: its C++20 check precedes any C++20-only header

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

#include "domain.hpp"

namespace fluidbed {

// One parameter of closure type Law: its name and where it lives in a Law.
template <class Law>
struct Parameter {
  std::string_view name;
  double& (*place)(Law&);
};

namespace detail {

template <class Member>
struct member_traits;
template <class Type, class Class>
struct member_traits<Type Class::*> {
  using owner = Class;
  using type = Type;
};

}  // namespace detail

// The parameter that is the double data member `Member` (written &Law::member), of Law or, for a
// member of a base class, of the Law given.
template <auto Member, class Law = typename detail::member_traits<decltype(Member)>::owner>
constexpr Parameter<Law> parameter(std::string_view name) {
  return {name, [](Law& law) -> double& { return law.*Member; }};
}

// The parameters of a closure type, or an empty list.
template <class Law>
constexpr auto parameters_of() {
  if constexpr (requires { Law::parameters(); })
    return Law::parameters();
  else
    return std::array<Parameter<Law>, 0>{};
}

// The parameters of the closure held in the data member `Member` (written &Outer::member), as
// parameters of Outer under the same names.
template <auto Member>
constexpr auto nested_parameters() {
  using Outer = typename detail::member_traits<decltype(Member)>::owner;
  using Inner = typename detail::member_traits<decltype(Member)>::type;
  constexpr std::size_t count = parameters_of<Inner>().size();
  return []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<Parameter<Outer>, count>{Parameter<Outer>{
        parameters_of<Inner>()[I].name,
        [](Outer& outer) -> double& { return parameters_of<Inner>()[I].place(outer.*Member); }}...};
  }(std::make_index_sequence<count>{});
}

// Two lists of one closure's parameters as one.
template <class Law, std::size_t M, std::size_t N>
constexpr std::array<Parameter<Law>, M + N> join_parameters(const std::array<Parameter<Law>, M>& a,
                                                            const std::array<Parameter<Law>, N>& b) {
  std::array<Parameter<Law>, M + N> all{};
  for (std::size_t i = 0; i < M; ++i) all[i] = a[i];
  for (std::size_t i = 0; i < N; ++i) all[M + i] = b[i];
  return all;
}

// The value of `law`'s parameter `name`, or nothing where it has no such parameter.
template <class Law>
constexpr std::optional<double> get_parameter(const Law& law, std::string_view name) {
  Law copy = law;
  for (const auto& p : parameters_of<Law>())
    if (p.name == name) return p.place(copy);
  return std::nullopt;
}

// Sets `law`'s parameter `name` to `value`; false (and `law` unchanged) where it has no such
// parameter. Not validated here (see above; core/errors.hpp's set_parameter_checked validates).
template <class Law>
constexpr bool set_parameter(Law& law, std::string_view name, double value) {
  for (const auto& p : parameters_of<Law>())
    if (p.name == name) {
      p.place(law) = value;
      return true;
    }
  return false;
}

}  // namespace fluidbed

namespace fluidbed {

// The domain of a closure's parameters in double, whichever way it declares it (the drag and
// settling laws as a template on the scalar type, the kinetic-theory laws in double), or an
// empty list: for validating parameters set by name.
template <class Law>
constexpr auto parameter_domain_in_double(const Law& law) {
  if constexpr (requires { law.template parameter_domain<double>(); })
    return law.template parameter_domain<double>();
  else if constexpr (requires { law.parameter_domain(); })
    return law.parameter_domain();
  else
    return Arguments<double, 0>{};
}

}  // namespace fluidbed
