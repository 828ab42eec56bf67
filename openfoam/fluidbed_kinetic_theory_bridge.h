/* fluidbed — the narrow C interface between the OpenFOAM plugin's kinetic-theory sub-models
 * (OpenFOAM's headers, C++11 for v1912) and fluidbed's kinetic-theory registries (C++20): plain
 * types, whole arrays, no exceptions. Every quantity is fluidbed's, per unit volume of suspension,
 * in SI units (fluidbed/kinetic_theory/registry.hpp states each family's convention); the
 * OpenFOAM side converts to OpenFOAM's conventions (kinematic viscosities, coefficients of Θ).
 *
 * Each evaluation validates every state with the law's checked entry point and returns n when all
 * are valid, else the index of the first invalid one, with `message` (of `message_size` bytes,
 * always terminated) naming the argument, its value and the law; outputs are then written only
 * below that index. Output pointers documented as optional may be NULL. */
#ifndef FLUIDBED_KINETIC_THEORY_BRIDGE_H
#define FLUIDBED_KINETIC_THEORY_BRIDGE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The registries a law is chosen from. */
typedef enum fluidbed_kt_kind {
  FLUIDBED_KT_RADIAL_DISTRIBUTION,  /* kinetic_theory::RadialDistributions */
  FLUIDBED_KT_GRANULAR_PRESSURE,    /* GranularPressures */
  FLUIDBED_KT_SHEAR_VISCOSITY,      /* ShearViscosities */
  FLUIDBED_KT_CONDUCTIVITY,         /* Conductivities */
  FLUIDBED_KT_FRICTIONAL_PRESSURE,  /* FrictionalPressures */
  FLUIDBED_KT_FRICTIONAL_VISCOSITY, /* FrictionalViscosities */
  FLUIDBED_KT_FRICTIONAL_STRESS     /* FrictionalStresses */
} fluidbed_kt_kind;

typedef struct fluidbed_kt_law fluidbed_kt_law;

/* The law of registry `kind` called `name`, with its registered parameters, or NULL when there is
 * none; then `message` lists the registry's names. */
fluidbed_kt_law* fluidbed_kt_law_create(fluidbed_kt_kind kind, const char* name, char* message, size_t message_size);

void fluidbed_kt_law_destroy(fluidbed_kt_law* law);

/* The law's run-time name (valid while the law lives). */
const char* fluidbed_kt_law_name(const fluidbed_kt_law* law);

/* Sets the law's parameter `key`: the library's parameter name in camelCase (packingMargin,
 * lengthScale, frictionCoefficient, coefficient, numeratorExponent, denominatorExponent,
 * exponent, frictionAngle in degrees as OpenFOAM writes angles, strainRateFloor). maxPacking and
 * minFraction are not set here: every evaluation takes them from the solver. Returns 1, or 0 when
 * the law has no such parameter, with `message` listing those it has, or when the value is outside
 * the parameter's domain, with the library's checked message. */
int fluidbed_kt_law_set(fluidbed_kt_law* law, const char* key, double value, char* message, size_t message_size);

/* In every evaluation below, max_packing and min_fraction (OpenFOAM's alphaMax and
 * alphaMinFriction) replace the law's φ_max and onset of friction where it has them. */

/* Radial distribution: g0[i] = g0(phi[i]) and, if g0_slope is not NULL, g0_slope[i] = dg0/dφ, or
 * where that is not finite (the cube-root forms at φ = 0: +∞, a division by zero computed with
 * the floating-point traps held) the slope at slope_floor. */
size_t fluidbed_kt_radial_distribution(const fluidbed_kt_law* law, double max_packing, double min_fraction,
                                       double slope_floor, size_t n, const double* phi, double* g0, double* g0_slope,
                                       char* message, size_t message_size);

/* Granular pressure per unit granular temperature: coefficient[i] = p_s/Θ [kg m^-3] at
 * (phi[i], g0[i], rho_s[i], restitution) and, if slope is not NULL, slope[i] = its total
 * derivative in φ with g0 varying as g0_slope[i] (dg0/dφ of the solver's radial distribution).
 * Every granular pressure of fluidbed is linear in Θ. */
size_t fluidbed_kt_granular_pressure(const fluidbed_kt_law* law, size_t n, const double* phi, const double* g0,
                                     const double* g0_slope, const double* solid_density, double restitution,
                                     double* coefficient, double* slope, char* message, size_t message_size);

/* Shear viscosity per unit volume of suspension mu_s [Pa s] divided by solid_density[i] (OpenFOAM's
 * kinematic nu of the particles), at (phi, Theta, g0, d, rho_s, restitution). */
size_t fluidbed_kt_shear_viscosity(const fluidbed_kt_law* law, size_t n, const double* phi, const double* theta,
                                   const double* g0, const double* diameter, const double* solid_density,
                                   double restitution, double* kinematic_viscosity, char* message,
                                   size_t message_size);

/* Conductivity of granular energy kappa_s [kg m^-1 s^-1] at (phi, Theta, g0, d, rho_s, restitution). */
size_t fluidbed_kt_conductivity(const fluidbed_kt_law* law, size_t n, const double* phi, const double* theta,
                                const double* g0, const double* diameter, const double* solid_density,
                                double restitution, double* conductivity, char* message, size_t message_size);

/* Frictional pressure p_f [Pa] at phi[i] and, if slope is not NULL, dp_f/dφ. */
size_t fluidbed_kt_frictional_pressure(const fluidbed_kt_law* law, double max_packing, double min_fraction, size_t n,
                                       const double* phi, double* pressure, double* slope, char* message,
                                       size_t message_size);

/* Frictional viscosity mu_f [Pa s] at the frictional pressure p_f[i] and the strain rate
 * (divergence[i] = tr D, contraction[i] = D':D'). */
size_t fluidbed_kt_frictional_viscosity(const fluidbed_kt_law* law, size_t n, const double* frictional_pressure,
                                        const double* divergence, const double* contraction, double* viscosity,
                                        char* message, size_t message_size);

/* Frictional stress laws of (φ, Θ, d, strain rate): p_f [Pa], if slope is not NULL dp_f/dφ at fixed
 * Θ and strain rate, and if viscosity is not NULL mu_f [Pa s]. */
size_t fluidbed_kt_frictional_stress(const fluidbed_kt_law* law, double max_packing, double min_fraction, size_t n,
                                     const double* phi, const double* theta, const double* diameter,
                                     const double* divergence, const double* contraction, double* pressure,
                                     double* slope, double* viscosity, char* message, size_t message_size);

#ifdef __cplusplus
}
#endif

#endif
