// fluidbed — the C interface's evaluations of the one-class kinetic theory (fluidbed_c.h) over
// arrays: radial distributions and frictional pressures of φ, the constitutive laws of (φ, Θ,
// g0, material) with a radial distribution of the caller's choice, the frictional viscosity and
// the frictional stress; one dispatch per array, each cell through the checked entry points.
#include <cstddef>
#include <string>
#include <type_traits>
#include <variant>

#include "closure_handle.hpp"

using namespace fluidbed::c_api;
namespace kt = fluidbed::kinetic_theory;

namespace {

constexpr std::size_t radial_distribution = FLUIDBED_RADIAL_DISTRIBUTION;
constexpr std::size_t frictional_pressure = FLUIDBED_FRICTIONAL_PRESSURE;
constexpr std::size_t frictional_viscosity = FLUIDBED_FRICTIONAL_VISCOSITY;
constexpr std::size_t frictional_stress = FLUIDBED_FRICTIONAL_STRESS;

// The families of law(φ, Θ, g0, material).
constexpr bool is_constitutive(std::size_t family) {
  return family == FLUIDBED_GRANULAR_PRESSURE || family == FLUIDBED_SHEAR_VISCOSITY ||
         family == FLUIDBED_BULK_VISCOSITY || family == FLUIDBED_CONDUCTIVITY || family == FLUIDBED_DISSIPATION;
}

template <class Variant>
void of_solid_fraction(const Variant& closure, std::size_t n, const double* phi, double* value, double* slope) {
  std::visit(
      [&](const auto& l) {
        for_each_cell(n, [&](std::size_t i) {
          value[i] = l.checked(phi[i]);
          if (slope != nullptr) slope[i] = l.checked_with_derivatives(phi[i]).d_solid_fraction;
        });
      },
      closure);
}

}  // namespace

extern "C" fluidbed_status fluidbed_of_solid_fraction(const fluidbed_closure* law, size_t n,
                                                      const double* solid_fraction, double* value,
                                                      double* d_solid_fraction, fluidbed_error* error) {
  return guarded(error, [&] {
    require_arrays(n, "fluidbed_of_solid_fraction", solid_fraction, value);
    if (law != nullptr && law->closure.index() == frictional_pressure)
      of_solid_fraction(closure_of<frictional_pressure>(law, ""), n, solid_fraction, value, d_solid_fraction);
    else
      of_solid_fraction(closure_of<radial_distribution>(law, "fluidbed_of_solid_fraction"), n, solid_fraction, value,
                        d_solid_fraction);
  });
}

extern "C" fluidbed_status fluidbed_constitutive(const fluidbed_closure* law, const fluidbed_closure* radial,
                                                 size_t n, const double* solid_fraction,
                                                 const double* granular_temperature, const double* diameter,
                                                 const double* solid_density, const double* restitution,
                                                 double* value, double* d_solid_fraction,
                                                 double* d_granular_temperature, fluidbed_error* error) {
  return guarded(error, [&] {
    if (law == nullptr || !is_constitutive(law->closure.index()))
      throw InvalidArgument("fluidbed: fluidbed_constitutive: " + (law == nullptr ? std::string("the closure is NULL")
                                                                                : law->name + " is not a law of (phi, "
                                                                                              "Theta, g0, material)"));
    const auto& rdf = closure_of<radial_distribution>(radial, "fluidbed_constitutive");
    require_arrays(n, "fluidbed_constitutive", solid_fraction, granular_temperature, diameter, solid_density,
                   restitution, value);
    const bool derivatives = d_solid_fraction != nullptr || d_granular_temperature != nullptr;
    std::visit(
        [&](const auto& g0) {
          visit_closure(law->closure, [&]<class Law>(const Law& l) {
            if constexpr (std::is_base_of_v<kt::ConstitutiveLaw<Law>, Law>) {
              for_each_cell(n, [&](std::size_t i) {
                const double phi = solid_fraction[i], theta = granular_temperature[i];
                const kt::GranularMaterial<double> material{diameter[i], solid_density[i], restitution[i]};
                value[i] = l.checked(phi, theta, g0.checked(phi), material);
                if (!derivatives) return;
                const auto d = l.checked_with_derivatives(phi, theta, g0, material);
                if (d_solid_fraction != nullptr) d_solid_fraction[i] = d.d_solid_fraction;
                if (d_granular_temperature != nullptr) d_granular_temperature[i] = d.d_granular_temperature;
              });
            }
          });
        },
        rdf);
  });
}

extern "C" fluidbed_status fluidbed_frictional_viscosity(const fluidbed_closure* law, size_t n,
                                                         const double* frictional_pressure_,
                                                         const double* divergence, const double* contraction,
                                                         double* viscosity, double* d_frictional_pressure,
                                                         fluidbed_error* error) {
  return guarded(error, [&] {
    const auto& closure = closure_of<frictional_viscosity>(law, "fluidbed_frictional_viscosity");
    require_arrays(n, "fluidbed_frictional_viscosity", frictional_pressure_, divergence, contraction, viscosity);
    std::visit(
        [&](const auto& l) {
          for_each_cell(n, [&](std::size_t i) {
            const kt::StrainRate<double> rate{divergence[i], contraction[i]};
            viscosity[i] = l.checked(frictional_pressure_[i], rate);
            if (d_frictional_pressure != nullptr)
              d_frictional_pressure[i] = l.checked_with_derivatives(frictional_pressure_[i], rate).d_frictional_pressure;
          });
        },
        closure);
  });
}

extern "C" fluidbed_status fluidbed_frictional_stress(const fluidbed_closure* law, size_t n,
                                                      const double* solid_fraction,
                                                      const double* granular_temperature, const double* diameter,
                                                      const double* divergence, const double* contraction,
                                                      double* pressure, double* viscosity, double* d_pressure,
                                                      double* d_viscosity, fluidbed_error* error) {
  return guarded(error, [&] {
    const auto& closure = closure_of<frictional_stress>(law, "fluidbed_frictional_stress");
    require_arrays(n, "fluidbed_frictional_stress", solid_fraction, granular_temperature, diameter, divergence,
                   contraction, pressure, viscosity);
    std::visit(
        [&](const auto& l) {
          for_each_cell(n, [&](std::size_t i) {
            const kt::StrainRate<double> rate{divergence[i], contraction[i]};
            const auto stress = l.checked(solid_fraction[i], granular_temperature[i], diameter[i], rate);
            pressure[i] = stress.pressure;
            viscosity[i] = stress.viscosity;
            if (d_pressure == nullptr && d_viscosity == nullptr) return;
            const auto d = l.checked_with_derivatives(solid_fraction[i], granular_temperature[i], diameter[i], rate);
            if (d_pressure != nullptr) d_pressure[i] = d.pressure.d_solid_fraction;
            if (d_viscosity != nullptr) d_viscosity[i] = d.viscosity.d_solid_fraction;
          });
        },
        closure);
  });
}
