// fluidbed — the C++20 side of the OpenFOAM plugin's interface (fluidbed_drag_bridge.h): the drag
// registry evaluated over whole arrays, one dispatch on the law per array, not per cell.
#include "fluidbed_drag_bridge.h"

#include <exception>
#include <string>
#include <variant>

#include "fluidbed/drag.hpp"
#include "fluidbed_bridge_parameters.hpp"

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

extern "C" int fluidbed_drag_law_set(fluidbed_drag_law* law, const char* key, double value, char* message,
                                     size_t message_size) {
  return std::visit(
      [&](auto& l) { return fluidbed::openfoam::set_dictionary_parameter(l, key, value, message, message_size); },
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
          const auto beta_at = [&](double voidage) {
            const fluidbed::drag::DragState<double> state{
                voidage, slip[i], {fluid_density[i], fluid_viscosity[i]}, diameter[i]};
            return l.checked(state).pressure_gradient();
          };
          for (; i < n; ++i) {
            // The law forms phi back as 1 - voidage, and 1 - (1 - phi) keeps only the digits of phi
            // above 2^-53: at phi = 1e-6 ten of its sixteen. beta is phi times a function h smooth
            // in phi (every law's beta vanishes like phi), so beta at the phi the law sees, phi',
            // times phi/phi' is phi h(phi'), within |h'/h| |phi - phi'| <= |h'/h| 2^-53 of
            // phi h(phi): a few ulp. (Without particles phi' = 0 and beta = 0.)
            const double phi = particle_fraction[i];
            const double voidage = 1.0 - phi;
            const double seen = 1.0 - voidage;  // exact (Sterbenz: voidage in [1/2, 2] for phi <= 1/2)
            const double beta_seen = beta_at(voidage);
            beta[i] = (seen > 0 && seen != phi && phi < 0.5) ? beta_seen * (phi / seen) : beta_seen;
          }
        },
        law->law);
  } catch (const std::exception& e) {
    write_message(e.what(), message, message_size);
  }
  return i;
}
