// fluidbed — the C interface's evaluations over arrays (fluidbed_c.h), in double and (the _f
// functions) in float: each the bindings' shared kernel (bindings/common/kernels.hpp) run through
// `guarded`.
#include <cstddef>
#include <string>

#include "closure_handle.hpp"
#include "kernels.hpp"

using namespace fluidbed::c_api;

namespace {

using fluidbed::moments::InversionStatus;
static_assert(FLUIDBED_INVERSION_OK == int(InversionStatus::ok) &&
                  FLUIDBED_INVERSION_REDUCED == int(InversionStatus::reduced) &&
                  FLUIDBED_INVERSION_ZERO_MASS == int(InversionStatus::zero_mass) &&
                  FLUIDBED_INVERSION_NOT_REALIZABLE == int(InversionStatus::not_realizable) &&
                  FLUIDBED_INVERSION_INVALID_INPUT == int(InversionStatus::invalid_input) &&
                  FLUIDBED_INVERSION_EIGEN_FAILURE == int(InversionStatus::eigen_failure) &&
                  FLUIDBED_INVERSION_INACCURATE == int(InversionStatus::inaccurate),
              "fluidbed_inversion_status follows moments::InversionStatus");

fluidbed::drag::Buoyancy buoyancy_of(fluidbed_buoyancy convention) {
  switch (convention) {
    case FLUIDBED_BUOYANCY_CLASSICAL: return fluidbed::drag::Buoyancy::classical;
    case FLUIDBED_BUOYANCY_PRESSURE_GRADIENT: return fluidbed::drag::Buoyancy::pressure_gradient;
    default: break;
  }
  throw InvalidArgument("fluidbed: unknown fluidbed_buoyancy " + std::to_string(static_cast<int>(convention)));
}

static_assert(FLUIDBED_DQMOM_OK == int(fluidbed::moments::dqmom::SourceStatus::ok) &&
                  FLUIDBED_DQMOM_MERGED_NODES == int(fluidbed::moments::dqmom::SourceStatus::merged_nodes) &&
                  FLUIDBED_DQMOM_INVALID_INPUT == int(fluidbed::moments::dqmom::SourceStatus::invalid_input),
              "fluidbed_dqmom_status follows moments::dqmom::SourceStatus");

fluidbed::moments::dqmom::Weights weights_of(fluidbed_dqmom_weights kind) {
  switch (kind) {
    case FLUIDBED_DQMOM_VOLUME_FRACTION: return fluidbed::moments::dqmom::Weights::volume_fraction;
    case FLUIDBED_DQMOM_NUMBER_DENSITY: return fluidbed::moments::dqmom::Weights::number_density;
    default: break;
  }
  throw InvalidArgument("fluidbed: unknown fluidbed_dqmom_weights " + std::to_string(static_cast<int>(kind)));
}

fluidbed::moments::Support support_of(fluidbed_support support) {
  switch (support) {
    case FLUIDBED_SUPPORT_POSITIVE_HALF_LINE: return fluidbed::moments::Support::positive_half_line;
    case FLUIDBED_SUPPORT_REAL_LINE: return fluidbed::moments::Support::real_line;
    default: break;
  }
  throw InvalidArgument("fluidbed: unknown fluidbed_support " + std::to_string(static_cast<int>(support)));
}

using fluidbed::moments::CorrectionStatus;
static_assert(FLUIDBED_CORRECTION_UNCHANGED == int(CorrectionStatus::unchanged) &&
                  FLUIDBED_CORRECTION_MCGRAW == int(CorrectionStatus::mcgraw) &&
                  FLUIDBED_CORRECTION_LOGNORMAL == int(CorrectionStatus::lognormal) &&
                  FLUIDBED_CORRECTION_MONODISPERSE == int(CorrectionStatus::monodisperse) &&
                  FLUIDBED_CORRECTION_ZERO_MASS == int(CorrectionStatus::zero_mass) &&
                  FLUIDBED_CORRECTION_FAILED == int(CorrectionStatus::failed),
              "fluidbed_correction_status follows moments::CorrectionStatus");
static_assert(FLUIDBED_MAX_NODES == fluidbed::bindings::max_nodes &&
                  FLUIDBED_MAX_CLASSES == fluidbed::bindings::max_classes,
              "the C interface's limits are the bindings'");

template <class T>
fluidbed_status drag_in(const fluidbed_closure* law, fluidbed_buoyancy convention, size_t n, const T* voidage,
                        const T* slip, const T* density, const T* viscosity, const T* diameter, T* beta, T* d_voidage,
                        T* d_slip, T* d_force_d_slip, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::drag(closure_of(law, "drag"), buoyancy_of(convention), n, voidage, slip, density, viscosity,
                             diameter, beta, d_voidage, d_slip, d_force_d_slip);
  });
}

template <class T>
fluidbed_status constitutive_in(const fluidbed_closure* law, const fluidbed_closure* radial, size_t n, const T* phi,
                                const T* theta, const T* diameter, const T* density, const T* restitution, T* value,
                                T* d_phi, T* d_theta, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::constitutive(closure_of(law, "constitutive"), closure_of(radial, "constitutive"), n, phi, theta,
                                     diameter, density, restitution, value, d_phi, d_theta);
  });
}

}  // namespace

extern "C" fluidbed_status fluidbed_drag(const fluidbed_closure* law, fluidbed_buoyancy convention, size_t n,
                                         const double* voidage, const double* slip, const double* fluid_density,
                                         const double* fluid_viscosity, const double* diameter, double* beta,
                                         double* d_voidage, double* d_slip, double* d_force_d_slip,
                                         fluidbed_error* error) {
  return drag_in(law, convention, n, voidage, slip, fluid_density, fluid_viscosity, diameter, beta, d_voidage, d_slip,
                 d_force_d_slip, error);
}

extern "C" fluidbed_status fluidbed_drag_f(const fluidbed_closure* law, fluidbed_buoyancy convention, size_t n,
                                           const float* voidage, const float* slip, const float* fluid_density,
                                           const float* fluid_viscosity, const float* diameter, float* beta,
                                           float* d_voidage, float* d_slip, float* d_force_d_slip,
                                           fluidbed_error* error) {
  return drag_in(law, convention, n, voidage, slip, fluid_density, fluid_viscosity, diameter, beta, d_voidage, d_slip,
                 d_force_d_slip, error);
}

extern "C" fluidbed_status fluidbed_sphere_drag_coefficient(const fluidbed_closure* law, size_t n,
                                                            const double* reynolds, double* cd_re, double* d_reynolds,
                                                            fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::sphere_drag_coefficient(closure_of(law, "sphere_drag_coefficient"), n, reynolds, cd_re,
                                                d_reynolds);
  });
}

extern "C" fluidbed_status fluidbed_reynolds_of_archimedes(const fluidbed_closure* law, size_t n,
                                                           const double* archimedes, double* reynolds,
                                                           double* d_archimedes, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::reynolds_of_archimedes(closure_of(law, "reynolds_of_archimedes"), n, archimedes, reynolds,
                                               d_archimedes);
  });
}

extern "C" fluidbed_status fluidbed_richardson_zaki_exponent(const fluidbed_closure* law, size_t n,
                                                             const double* argument, double* exponent,
                                                             double* d_argument, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::richardson_zaki_exponent(closure_of(law, "richardson_zaki_exponent"), n, argument, exponent,
                                                 d_argument);
  });
}

extern "C" const char* fluidbed_richardson_zaki_argument(const fluidbed_closure* law) {
  // The laws' `argument` is a literal: static storage, terminated.
  const std::string_view argument = law == nullptr ? std::string_view{} : fluidbed::bindings::richardson_zaki_argument(*law);
  return argument.empty() ? nullptr : argument.data();
}

extern "C" fluidbed_status fluidbed_of_solid_fraction(const fluidbed_closure* law, size_t n,
                                                      const double* solid_fraction, double* value,
                                                      double* d_solid_fraction, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::of_solid_fraction(closure_of(law, "of_solid_fraction"), n, solid_fraction, value,
                                          d_solid_fraction);
  });
}

extern "C" fluidbed_status fluidbed_constitutive(const fluidbed_closure* law, const fluidbed_closure* radial,
                                                 size_t n, const double* solid_fraction,
                                                 const double* granular_temperature, const double* diameter,
                                                 const double* solid_density, const double* restitution,
                                                 double* value, double* d_solid_fraction,
                                                 double* d_granular_temperature, fluidbed_error* error) {
  return constitutive_in(law, radial, n, solid_fraction, granular_temperature, diameter, solid_density, restitution,
                         value, d_solid_fraction, d_granular_temperature, error);
}

extern "C" fluidbed_status fluidbed_constitutive_f(const fluidbed_closure* law, const fluidbed_closure* radial,
                                                   size_t n, const float* solid_fraction,
                                                   const float* granular_temperature, const float* diameter,
                                                   const float* solid_density, const float* restitution, float* value,
                                                   float* d_solid_fraction, float* d_granular_temperature,
                                                   fluidbed_error* error) {
  return constitutive_in(law, radial, n, solid_fraction, granular_temperature, diameter, solid_density, restitution,
                         value, d_solid_fraction, d_granular_temperature, error);
}

extern "C" fluidbed_status fluidbed_frictional_viscosity(const fluidbed_closure* law, size_t n,
                                                         const double* frictional_pressure, const double* divergence,
                                                         const double* contraction, double* viscosity,
                                                         double* d_frictional_pressure, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::frictional_viscosity(closure_of(law, "frictional_viscosity"), n, frictional_pressure,
                                             divergence, contraction, viscosity, d_frictional_pressure);
  });
}

extern "C" fluidbed_status fluidbed_frictional_stress(const fluidbed_closure* law, size_t n,
                                                      const double* solid_fraction,
                                                      const double* granular_temperature, const double* diameter,
                                                      const double* divergence, const double* contraction,
                                                      double* pressure, double* viscosity, double* d_pressure,
                                                      double* d_viscosity, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::frictional_stress(closure_of(law, "frictional_stress"), n, solid_fraction,
                                          granular_temperature, diameter, divergence, contraction, pressure,
                                          viscosity, d_pressure, d_viscosity);
  });
}

extern "C" fluidbed_status fluidbed_invert_moments(int node_count, fluidbed_support support, size_t n,
                                                   const double* moments, double* nodes, double* weights, int* sizes,
                                                   int* status, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::invert_moments(node_count, {.support = support_of(support)}, n, moments, nodes, weights, sizes,
                                       status);
  });
}

extern "C" fluidbed_status fluidbed_invert_moments_with_accuracy(int node_count, fluidbed_support support, size_t n,
                                                                 const double* moments, double moment_accuracy,
                                                                 double required_accuracy, double* nodes,
                                                                 double* weights, int* sizes, int* status,
                                                                 double* node_errors, double* weight_errors,
                                                                 double* count_errors, fluidbed_error* error) {
  return guarded(error, [&] {
    const bool stored = node_errors != nullptr || weight_errors != nullptr || count_errors != nullptr;
    const fluidbed::moments::InversionOptions options{.support = support_of(support),
                                                      .estimate_error = stored,
                                                      .moment_accuracy = moment_accuracy,
                                                      .required_accuracy = required_accuracy};
    fluidbed::bindings::invert_moments(node_count, options, n, moments, nodes, weights, sizes, status, node_errors,
                                       weight_errors, count_errors);
  });
}

extern "C" fluidbed_status fluidbed_moment_realizability(fluidbed_support support, int moment_count, size_t n,
                                                         const double* moments, int* status, int* realizable_moments,
                                                         int* first_failing_index, double* failing_value,
                                                         fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::moment_realizability(support_of(support), moment_count, n, moments, status, realizable_moments,
                                             first_failing_index, failing_value);
  });
}

extern "C" fluidbed_correction_options fluidbed_correction_default_options(void) {
  const fluidbed::moments::CorrectionOptions<double> defaults;
  return {defaults.protected_moments, defaults.max_iterations, defaults.degenerate_tolerance};
}

extern "C" fluidbed_status fluidbed_correct_moments(int moment_count, size_t n, const double* moments,
                                                    const fluidbed_correction_options* options, double* corrected,
                                                    int* status, int* realizable_moments, fluidbed_error* error) {
  return guarded(error, [&] {
    const fluidbed_correction_options o = options != nullptr ? *options : fluidbed_correction_default_options();
    const fluidbed::moments::CorrectionOptions<double> cpp{o.protected_moments, o.max_iterations,
                                                           o.degenerate_tolerance};
    fluidbed::bindings::correct_moments(moment_count, n, moments, cpp, corrected, status, realizable_moments);
  });
}

extern "C" fluidbed_status fluidbed_dqmom_sources(int node_count, size_t n, const double* nodes, const double* weights,
                                                  const double* moment_sources, double* weight_sources,
                                                  double* weighted_node_sources, int* status, double* condition,
                                                  fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::dqmom_sources(node_count, n, nodes, weights, moment_sources, weight_sources,
                                      weighted_node_sources, status, condition);
  });
}

extern "C" fluidbed_status fluidbed_dqmom_growth_diffusion_sources(
    int node_count, fluidbed_dqmom_weights weights_kind, size_t n, const double* nodes, const double* weights,
    const double* growth_rate, const double* diffusion_intensity, double* weight_sources,
    double* weighted_node_sources, int* status, double* condition, fluidbed_error* error) {
  return guarded(error, [&] {
    const auto form = weights_of(weights_kind);
    fluidbed::bindings::dqmom_growth_diffusion_sources(node_count, form, n, nodes, weights, growth_rate,
                                                       diffusion_intensity, weight_sources, weighted_node_sources,
                                                       status, condition);
  });
}

extern "C" fluidbed_status fluidbed_mixture_radial_distribution(const fluidbed_closure* law, size_t n,
                                                                size_t class_count, size_t i, size_t k,
                                                                const double* fractions, const double* diameters,
                                                                double* value, double* d_fractions,
                                                                fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::mixture_radial_distribution(closure_of(law, "mixture_radial_distribution"), n, class_count, i,
                                                    k, fractions, diameters, value, d_fractions);
  });
}

extern "C" fluidbed_status fluidbed_solid_solid_drag(const fluidbed_closure* law, size_t n, const double* phi_p,
                                                     const double* phi_q, const double* density_p,
                                                     const double* diameter_p, const double* density_q,
                                                     const double* diameter_q, const double* restitution,
                                                     const double* contact_rdf, const double* relative_speed,
                                                     double* coefficient, double* d_phi_p, double* d_phi_q,
                                                     double* d_contact_rdf, double* d_relative_speed,
                                                     fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::solid_solid_drag(closure_of(law, "solid_solid_drag"), n, phi_p, phi_q, density_p, diameter_p,
                                         density_q, diameter_q, restitution, contact_rdf, relative_speed, coefficient,
                                         d_phi_p, d_phi_q, d_contact_rdf, d_relative_speed);
  });
}

extern "C" fluidbed_status fluidbed_gas_exchange_source(
    const fluidbed_closure* law, const fluidbed_closure* radial, size_t n, const double* solid_fraction,
    const double* granular_temperature, const double* slip, const double* beta, const double* gas_viscosity,
    const double* diameter, const double* solid_density, const double* restitution, double* source,
    double* d_solid_fraction, double* d_granular_temperature, double* d_beta, double* d_slip, fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::gas_exchange_source(closure_of(law, "gas_exchange_source"), radial, n, solid_fraction,
                                            granular_temperature, slip, beta, gas_viscosity, diameter, solid_density,
                                            restitution, source, d_solid_fraction, d_granular_temperature, d_beta,
                                            d_slip);
  });
}

extern "C" fluidbed_status fluidbed_elastic_modulus_at_equilibrium(
    const fluidbed_closure* model, size_t n, const double* voidage, const double* fluid_density,
    const double* fluid_viscosity, const double* particle_density, const double* diameter,
    const double* terminal_reynolds, const double* gravity, double* modulus, double* d_voidage,
    fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::elastic_modulus_at_equilibrium(closure_of(model, "elastic_modulus_at_equilibrium"), n, voidage,
                                                       fluid_density, fluid_viscosity, particle_density, diameter,
                                                       terminal_reynolds, gravity, modulus, d_voidage);
  });
}

extern "C" fluidbed_status fluidbed_elastic_modulus_at_state(const fluidbed_closure* model, size_t n,
                                                             const double* voidage, const double* slip,
                                                             const double* fluid_density,
                                                             const double* fluid_viscosity, const double* diameter,
                                                             double* modulus, double* d_voidage, double* d_slip,
                                                             fluidbed_error* error) {
  return guarded(error, [&] {
    fluidbed::bindings::elastic_modulus_at_state(closure_of(model, "elastic_modulus_at_state"), n, voidage, slip,
                                                 fluid_density, fluid_viscosity, diameter, modulus, d_voidage, d_slip);
  });
}

extern "C" fluidbed_status fluidbed_unequal_temperature_mixture(
    const fluidbed_closure* radial, size_t n, size_t class_count, const double* fractions,
    const double* temperatures, const double* diameters, const double* densities, const double* restitution,
    double* pressure, double* shear_viscosity, double* bulk_viscosity, double* conductivity, double* dissipation,
    double* drag, double* segregation, double* radial_distribution, fluidbed_error* error) {
  return fluidbed_unequal_temperature_mixture_with_derivatives(
      radial, n, class_count, fractions, temperatures, diameters, densities, restitution, pressure, nullptr, nullptr,
      shear_viscosity, nullptr, nullptr, bulk_viscosity, nullptr, nullptr, conductivity, nullptr, nullptr, dissipation,
      nullptr, nullptr, drag, nullptr, nullptr, segregation, nullptr, nullptr, radial_distribution, nullptr, nullptr,
      error);
}

extern "C" fluidbed_status fluidbed_unequal_temperature_mixture_with_derivatives(
    const fluidbed_closure* radial, size_t n, size_t class_count, const double* fractions,
    const double* temperatures, const double* diameters, const double* densities, const double* restitution,
    double* pressure, double* d_pressure_d_fractions, double* d_pressure_d_temperatures, double* shear_viscosity,
    double* d_shear_viscosity_d_fractions, double* d_shear_viscosity_d_temperatures, double* bulk_viscosity,
    double* d_bulk_viscosity_d_fractions, double* d_bulk_viscosity_d_temperatures, double* conductivity,
    double* d_conductivity_d_fractions, double* d_conductivity_d_temperatures, double* dissipation,
    double* d_dissipation_d_fractions, double* d_dissipation_d_temperatures, double* drag,
    double* d_drag_d_fractions, double* d_drag_d_temperatures, double* segregation,
    double* d_segregation_d_fractions, double* d_segregation_d_temperatures, double* radial_distribution,
    double* d_radial_distribution_d_fractions, double* d_radial_distribution_d_temperatures,
    fluidbed_error* error) {
  using fluidbed::bindings::ClassOutputs;
  return guarded(error, [&] {
    ClassOutputs<double> out{};
    out[fluidbed::bindings::class_pressure] = {pressure, d_pressure_d_fractions, d_pressure_d_temperatures};
    out[fluidbed::bindings::class_shear_viscosity] = {shear_viscosity, d_shear_viscosity_d_fractions,
                                                      d_shear_viscosity_d_temperatures};
    out[fluidbed::bindings::class_bulk_viscosity] = {bulk_viscosity, d_bulk_viscosity_d_fractions,
                                                     d_bulk_viscosity_d_temperatures};
    out[fluidbed::bindings::class_conductivity] = {conductivity, d_conductivity_d_fractions,
                                                   d_conductivity_d_temperatures};
    out[fluidbed::bindings::class_dissipation] = {dissipation, d_dissipation_d_fractions, d_dissipation_d_temperatures};
    out[fluidbed::bindings::class_drag] = {drag, d_drag_d_fractions, d_drag_d_temperatures};
    out[fluidbed::bindings::class_segregation] = {segregation, d_segregation_d_fractions, d_segregation_d_temperatures};
    out[fluidbed::bindings::class_radial_distribution] = {radial_distribution, d_radial_distribution_d_fractions,
                                                          d_radial_distribution_d_temperatures};
    fluidbed::bindings::unequal_temperature_mixture(closure_of(radial, "unequal_temperature_mixture"), n, class_count,
                                                    fractions, temperatures, diameters, densities, restitution, out);
  });
}
