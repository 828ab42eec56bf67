// fluidbed — the C++20 side of the OpenFOAM plugin's interface (fluidbed_drag_bridge.h): the drag
// registry evaluated over whole arrays, one dispatch on the law per array, not per cell.
#include "fluidbed_drag_bridge.h"

#include <array>
#include <concepts>
#include <exception>
#include <string>
#include <string_view>
#include <variant>

#include "fluidbed/drag.hpp"
#include "fluidbed_bridge_message.hpp"

struct fluidbed_drag_law {
  fluidbed::drag::AnyDragLaw law;
  std::string name;  // name() is a view, not necessarily terminated
};

using fluidbed::openfoam::write_message;

namespace {

// The parameters a dictionary may set, by key (the names of the laws' accessors).
constexpr std::array<std::string_view, 3> parameter_keys{"exponent", "c1", "d1"};

// Whether the law has the parameter `key`; where it has and `value` is not null, sets it. The
// laws hold their parameters privately: a changed one is a law built anew.
template <class Law>
bool parameter(Law& law, std::string_view key, const double* value) {
  using fluidbed::drag::ConstantExponentDrag;
  using fluidbed::drag::SyamlalOBrien;
  if constexpr (std::same_as<Law, ConstantExponentDrag>) {
    if (key != "exponent") return false;
    if (value != nullptr) law = ConstantExponentDrag(*value, law.name(), law.reference());
    return true;
  } else if constexpr (std::same_as<Law, SyamlalOBrien>) {
    if (key != "c1" && key != "d1") return false;
    if (value != nullptr) law = key == "c1" ? SyamlalOBrien(*value, law.d1()) : SyamlalOBrien(law.c1(), *value);
    return true;
  } else {
    return false;
  }
}

}  // namespace

extern "C" fluidbed_drag_law* fluidbed_drag_law_create(const char* name, char* message, size_t message_size) {
  try {
    const fluidbed::drag::AnyDragLaw law = fluidbed::drag::DragLaws::make(name);
    return new fluidbed_drag_law{law, std::string(fluidbed::drag::name_of(law))};
  } catch (const std::exception& e) {
    write_message(e.what(), message, message_size);
    return nullptr;
  }
}

extern "C" void fluidbed_drag_law_destroy(fluidbed_drag_law* law) { delete law; }

extern "C" int fluidbed_drag_law_set(fluidbed_drag_law* law, const char* key, double value, char* message,
                                     size_t message_size) {
  return std::visit(
      [&](auto& l) {
        if (parameter(l, key, &value)) return 1;
        std::string known;
        for (const std::string_view k : parameter_keys)
          if (parameter(l, k, nullptr)) known += (known.empty() ? "" : ", ") + std::string(k);
        write_message(fluidbed::openfoam::unknown_parameter(law->name, key, known), message, message_size);
        return 0;
      },
      law->law);
}

extern "C" const char* fluidbed_drag_law_name(const fluidbed_drag_law* law) { return law->name.c_str(); }

extern "C" size_t fluidbed_drag_law_pressure_gradient_beta(const fluidbed_drag_law* law, size_t n,
                                                           const double* particle_fraction, const double* slip,
                                                           const double* fluid_density, const double* fluid_viscosity,
                                                           const double* diameter, double* beta, char* message,
                                                           size_t message_size) {
  size_t i = 0;
  try {
    std::visit(
        [&](const auto& l) {
          const auto beta_as = [&](auto one) {
            using T = decltype(one);
            const fluidbed::drag::DragState<T> state{one - T(particle_fraction[i]),
                                                     T(slip[i]),
                                                     {T(fluid_density[i]), T(fluid_viscosity[i])},
                                                     T(diameter[i])};
            return static_cast<double>(l.checked(state).pressure_gradient());
          };
          for (; i < n; ++i) {
            // The law forms phi back as 1 - voidage. In double, 1 - phi rounds by up to 2^-54, which
            // is more than 2^-50 of phi below phi = 1/16: there the law runs in long double, where
            // (x86: 64 significand bits) the rounding is 2^-65, 3e-14 of phi at phi = 1e-6.
            const bool small = particle_fraction[i] > 0 && particle_fraction[i] < 0.0625;
            beta[i] = small ? beta_as(1.0L) : beta_as(1.0);
          }
        },
        law->law);
  } catch (const std::exception& e) {
    write_message(e.what(), message, message_size);
  }
  return i;
}
