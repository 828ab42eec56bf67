// fluidbed — the C++20 side of the OpenFOAM plugin's interface (fluidbed_drag_bridge.h): the drag
// registry evaluated over whole arrays, one dispatch on the law per array, not per cell.
#include "fluidbed_drag_bridge.h"

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
