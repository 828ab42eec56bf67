/* fluidbed — the narrow C interface between the OpenFOAM plugin (OpenFOAM's headers, in the C++
 * standard OpenFOAM is built with: C++11 for v1912) and fluidbed's drag registry (C++20). OpenFOAM
 * v1912's headers do not compile as C++20 and fluidbed's need it, so the two meet only here: plain
 * types, whole arrays, no exceptions. */
#ifndef FLUIDBED_DRAG_BRIDGE_H
#define FLUIDBED_DRAG_BRIDGE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A drag law of fluidbed::drag::DragLaws, selected by its run-time name. */
typedef struct fluidbed_drag_law fluidbed_drag_law;

/* The law called `name`, or NULL when there is none; then `message` (of `message_size` bytes,
 * always terminated) lists the known names. */
fluidbed_drag_law* fluidbed_drag_law_create(const char* name, char* message, size_t message_size);

void fluidbed_drag_law_destroy(fluidbed_drag_law* law);

/* Sets the law's parameter `key`, the library's parameter name in camelCase (the constant-exponent
 * laws' exponent; SyamlalOBrien's c1, d1). Returns 1, or 0 when the law has no such parameter,
 * with `message` listing those it has, or when the value is outside the parameter's domain, with
 * the library's checked message. */
int fluidbed_drag_law_set(fluidbed_drag_law* law, const char* key, double value, char* message, size_t message_size);

/* The law's run-time name (valid while the law lives). */
const char* fluidbed_drag_law_name(const fluidbed_drag_law* law);

/* beta[i] [kg m^-3 s^-1] for a momentum equation whose buoyancy is -phi grad p (OpenFOAM's
 * two-fluid solvers), per unit volume of suspension, for the n states
 * (particle_fraction[i] = phi in [0, 1), interstitial slip[i] = |u_f - v_p| >= 0, fluid density[i],
 * fluid dynamic viscosity[i], particle diameter[i]), each validated by the law's checked entry point.
 * The particle fraction is passed, not the voidage: the law is evaluated at the voidage 1 - phi,
 * where it sees phi' = 1 - (1 - phi), which has lost the digits of phi below 2^-53, and beta is
 * multiplied by phi/phi' (beta is phi times a function smooth in phi), so that it keeps them.
 * Returns n when every state is valid, else the index of the first invalid one, with `message`
 * naming the offending argument and value; beta is then written only below that index. */
size_t fluidbed_drag_law_pressure_gradient_beta(const fluidbed_drag_law* law, size_t n,
                                                const double* particle_fraction,
                                                const double* slip, const double* fluid_density,
                                                const double* fluid_viscosity, const double* diameter, double* beta,
                                                char* message, size_t message_size);

#ifdef __cplusplus
}
#endif

#endif
