// fluidbed — the C++20 sides of the OpenFOAM plugin's C interfaces set a law's parameters from
// OpenFOAM dictionary entries: the library's parameter names (core/parameters.hpp) in
// OpenFOAM's camelCase (packingMargin for packing_margin), angles in degrees as OpenFOAM writes
// them, each value validated at once with the law's parameter domain.
#pragma once

#include <cctype>
#include <cstddef>
#include <exception>
#include <numbers>
#include <span>
#include <string>
#include <string_view>

#include "fluidbed/core/errors.hpp"
#include "fluidbed_bridge_message.hpp"

namespace fluidbed::openfoam {

// packing_margin -> packingMargin
inline std::string camel_case(std::string_view snake) {
  std::string camel;
  for (std::size_t i = 0; i < snake.size(); ++i)
    if (snake[i] == '_' && i + 1 < snake.size())
      camel += static_cast<char>(std::toupper(static_cast<unsigned char>(snake[++i])));
    else
      camel += snake[i];
  return camel;
}

// Sets `law`'s parameter whose camelCase name is `key` (an angle given in degrees). Parameters
// the solver provides at every evaluation (`from_solver`, library names) are not dictionary
// entries. Returns 1, or 0 with `message` naming the law's dictionary parameters where it has no
// such one, or the library's checked message where the value is outside the parameter's domain.
template <class Law>
int set_dictionary_parameter(Law& law, std::string_view key, double value, char* message, std::size_t message_size,
                             std::span<const std::string_view> from_solver = {}) {
  std::string known;
  for (const auto& p : parameters_of<Law>()) {
    bool solver_provided = false;
    for (const std::string_view s : from_solver) solver_provided |= p.name == s;
    if (solver_provided) continue;
    const std::string entry = camel_case(p.name);
    if (entry == key) {
      const bool angle = p.name.ends_with("_angle");
      try {
        set_parameter_checked(law, p.name, angle ? value * std::numbers::pi / 180 : value);
        return 1;
      } catch (const std::exception& e) {
        write_message(e.what(), message, message_size);
        return 0;
      }
    }
    known += (known.empty() ? "" : ", ") + entry;
  }
  write_message(unknown_parameter(law.name(), key, known), message, message_size);
  return 0;
}

}  // namespace fluidbed::openfoam
