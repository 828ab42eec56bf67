/* fluidbed — the library's closures from C, and from whatever calls C (Fortran through
 * iso_c_binding, Python, a host solver written in C or in an older C++).
 *
 * A closure is chosen once by its run-time name (the names are unique across the library; the
 * catalogue below lists them) and then evaluated over arrays of cells: one array per argument,
 * the layout CFD fields use (structure of arrays), each of n elements, in SI units. Every
 * evaluation validates every cell as the C++ library's checked entry points do and stops at the
 * first invalid one.
 *
 * Errors: every function that can fail returns a fluidbed_status and, when `error` is not NULL,
 * writes the status, the index of the first cell that failed (outputs are then written only
 * below it) and the C++ library's message ("fluidbed::SyamlalOBrien: argument 'voidage' = 1.5 is
 * out of domain (must lie in (0, 1])"). No exception crosses this interface, nothing is global
 * but constant tables, and a closure handle may be evaluated from several threads at once
 * (setting its parameters may not race with evaluating it).
 *
 * Values are bit for bit those of the C++ calls: the value of law.checked(...), the derivatives
 * of law.checked_with_derivatives(...). */
#ifndef FLUIDBED_C_H
#define FLUIDBED_C_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FLUIDBED_C_API_VERSION 1

/* The library exports these functions only. */
#if defined(FLUIDBED_C_BUILDING) && defined(__GNUC__)
#define FLUIDBED_C_API __attribute__((visibility("default")))
#else
#define FLUIDBED_C_API
#endif

/* ---- Errors ---------------------------------------------------------------------------- */

typedef enum fluidbed_status {
  FLUIDBED_OK = 0,
  FLUIDBED_UNKNOWN_NAME = 1,      /* no closure (of the family asked for) by that name */
  FLUIDBED_UNKNOWN_PARAMETER = 2, /* the closure has no parameter by that name */
  FLUIDBED_DOMAIN_ERROR = 3,      /* an argument or parameter outside its domain, or a result that is
                                     not finite: the checked C++ API's std::domain_error */
  FLUIDBED_INVALID_ARGUMENT = 4,  /* a NULL array or handle, a closure of another family, an unknown
                                     enumerator */
  FLUIDBED_INTERNAL_ERROR = 5,    /* anything else (out of memory) */
  FLUIDBED_STATUS_MAX_ENUM = 0x7fffffff  /* (every enumeration of this header spans int: any int a
                                            caller passes is a value of the type, checked inside) */
} fluidbed_status;

#define FLUIDBED_MESSAGE_SIZE 512

typedef struct fluidbed_error {
  fluidbed_status status;
  size_t index;                         /* the first cell that failed; 0 where no cell is involved */
  char message[FLUIDBED_MESSAGE_SIZE];  /* always terminated; "" on success */
} fluidbed_error;

/* The status's name ("FLUIDBED_DOMAIN_ERROR"). */
FLUIDBED_C_API const char* fluidbed_status_name(fluidbed_status status);

/* ---- Families and the catalogue -------------------------------------------------------- */

/* One family per registry of the C++ library (fluidbed::Registries), in its order. */
typedef enum fluidbed_family {
  FLUIDBED_SPHERE_DRAG_COEFFICIENT = 0,   /* C_D·Re of one sphere, of Re */
  FLUIDBED_TERMINAL_VELOCITY = 1,         /* Re_t of Ar, one sphere */
  FLUIDBED_RICHARDSON_ZAKI_EXPONENT = 2,  /* n of Re_t or of Ar */
  FLUIDBED_MINIMUM_FLUIDIZATION = 3,      /* Re_mf of Ar */
  FLUIDBED_DRAG_LAW = 4,                  /* β of (ε, w, ρ_f, μ_f, d) */
  FLUIDBED_ELASTIC_MODULUS = 5,
  FLUIDBED_RADIAL_DISTRIBUTION = 6,
  FLUIDBED_MIXTURE_RADIAL_DISTRIBUTION = 7,
  FLUIDBED_GRANULAR_PRESSURE = 8,
  FLUIDBED_SHEAR_VISCOSITY = 9,
  FLUIDBED_BULK_VISCOSITY = 10,
  FLUIDBED_CONDUCTIVITY = 11,
  FLUIDBED_DISSIPATION = 12,
  FLUIDBED_FRICTIONAL_PRESSURE = 13,
  FLUIDBED_FRICTIONAL_VISCOSITY = 14,
  FLUIDBED_FRICTIONAL_STRESS = 15,
  FLUIDBED_GAS_EXCHANGE_SOURCE = 16,
  FLUIDBED_SOLID_SOLID_DRAG = 17,
  FLUIDBED_WALL_BOUNDARY_CONDITION = 18, /* by name and parameters only: no array evaluation yet */
  FLUIDBED_FAMILY_COUNT = 19,
  FLUIDBED_FAMILY_MAX_ENUM = 0x7fffffff
} fluidbed_family;

/* What the family's closures are ("drag law"), and their convention: the quantity, its units
 * and sign, the definitions of the arguments. NULL for a value that is not a family. */
FLUIDBED_C_API const char* fluidbed_family_what(fluidbed_family family);
FLUIDBED_C_API const char* fluidbed_family_convention(fluidbed_family family);

/* The closures of the library, presets included: their number, and the name of the index-th
 * (NULL beyond the last). */
FLUIDBED_C_API size_t fluidbed_closure_count(void);
FLUIDBED_C_API const char* fluidbed_closure_name_at(size_t index);

/* ---- Closures ---------------------------------------------------------------------------- */

typedef struct fluidbed_closure fluidbed_closure;

/* The closure called `name`, with its registered parameters, in *closure (to be destroyed by
 * fluidbed_closure_destroy); FLUIDBED_UNKNOWN_NAME, with the known names in the message, where
 * there is none. */
FLUIDBED_C_API fluidbed_status fluidbed_closure_create(const char* name, fluidbed_closure** closure, fluidbed_error* error);

/* A copy of `closure`, its parameters included; NULL where out of memory. */
FLUIDBED_C_API fluidbed_closure* fluidbed_closure_copy(const fluidbed_closure* closure);

FLUIDBED_C_API void fluidbed_closure_destroy(fluidbed_closure* closure);

FLUIDBED_C_API fluidbed_family fluidbed_closure_family(const fluidbed_closure* closure);

/* The closure's run-time name and its reference (authors, year, journal, DOI); valid while the
 * closure lives. */
FLUIDBED_C_API const char* fluidbed_closure_name(const fluidbed_closure* closure);
FLUIDBED_C_API const char* fluidbed_closure_reference(const fluidbed_closure* closure);

/* The ranges the closure was fitted or derived for: their number, and the index-th quantity's
 * name and bounds (FLUIDBED_INVALID_ARGUMENT beyond the last). Outside them the closure still
 * returns its formula's value. */
FLUIDBED_C_API size_t fluidbed_closure_validity_count(const fluidbed_closure* closure);
FLUIDBED_C_API fluidbed_status fluidbed_closure_validity(const fluidbed_closure* closure, size_t index, const char** quantity,
                                          double* min, double* max, fluidbed_error* error);

/* The closure's parameters (snake_case names, angles in radians): their number, the index-th
 * name (NULL beyond the last), a value by name, and setting one, validated at once:
 * FLUIDBED_UNKNOWN_PARAMETER (listing the closure's parameters) or FLUIDBED_DOMAIN_ERROR (the
 * closure unchanged). */
FLUIDBED_C_API size_t fluidbed_closure_parameter_count(const fluidbed_closure* closure);
FLUIDBED_C_API const char* fluidbed_closure_parameter_name(const fluidbed_closure* closure, size_t index);
FLUIDBED_C_API fluidbed_status fluidbed_closure_get_parameter(const fluidbed_closure* closure, const char* name, double* value,
                                               fluidbed_error* error);
FLUIDBED_C_API fluidbed_status fluidbed_closure_set_parameter(fluidbed_closure* closure, const char* name, double value,
                                               fluidbed_error* error);

/* ---- Drag laws (FLUIDBED_DRAG_LAW) ------------------------------------------------------------ */

/* The buoyancy convention of the host's momentum equations: classical, −φ ρ_f g (the papers'),
 * or pressure gradient, −φ ∇p (OpenFOAM, MFiX model A, Fluent). For the same physics
 * β_pressure_gradient = ε β_classical. */
typedef enum fluidbed_buoyancy {
  FLUIDBED_BUOYANCY_CLASSICAL = 0,
  FLUIDBED_BUOYANCY_PRESSURE_GRADIENT = 1,
  FLUIDBED_BUOYANCY_MAX_ENUM = 0x7fffffff
} fluidbed_buoyancy;

/* beta[i] [kg m^-3 s^-1], the drag coefficient per unit volume of suspension in `convention`,
 * at voidage[i] = ε ∈ (0, 1], slip[i] = |u_f − v_p| >= 0 [m/s], fluid_density[i] [kg/m^3],
 * fluid_viscosity[i] [Pa s] and diameter[i] [m]; the drag force on the particles per unit volume
 * is β (u_f − v_p). If not NULL: d_voidage[i] = ∂β/∂ε at fixed w, d_slip[i] = ∂β/∂w at fixed ε
 * (+∞ at w = 0 for the laws with a fractional power of Re: the true derivative), and
 * d_force_d_slip[i] = ∂(β w)/∂w, finite everywhere (β at w = 0), what an implicit solver
 * linearises. */
FLUIDBED_C_API fluidbed_status fluidbed_drag(const fluidbed_closure* law, fluidbed_buoyancy convention, size_t n,
                              const double* voidage, const double* slip, const double* fluid_density,
                              const double* fluid_viscosity, const double* diameter, double* beta, double* d_voidage,
                              double* d_slip, double* d_force_d_slip, fluidbed_error* error);

/* The same in float: the library evaluated in single precision (not double rounded to float). */
FLUIDBED_C_API fluidbed_status fluidbed_drag_f(const fluidbed_closure* law, fluidbed_buoyancy convention, size_t n,
                                               const float* voidage, const float* slip, const float* fluid_density,
                                               const float* fluid_viscosity, const float* diameter, float* beta,
                                               float* d_voidage, float* d_slip, float* d_force_d_slip,
                                               fluidbed_error* error);

/* ---- Single spheres, settling, fluidization -------------------------------------------------- */

/* FLUIDBED_SPHERE_DRAG_COEFFICIENT: cd_re[i] = C_D·Re at reynolds[i] = Re >= 0 and, if not NULL,
 * d_reynolds[i] = d(C_D·Re)/dRe. */
FLUIDBED_C_API fluidbed_status fluidbed_sphere_drag_coefficient(const fluidbed_closure* law, size_t n, const double* reynolds,
                                                 double* cd_re, double* d_reynolds, fluidbed_error* error);

/* FLUIDBED_TERMINAL_VELOCITY and FLUIDBED_MINIMUM_FLUIDIZATION: the Reynolds number (Re_t or
 * Re_mf) at archimedes[i] = Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f² >= 0 and, if not NULL,
 * d_archimedes[i] = dRe/dAr. */
FLUIDBED_C_API fluidbed_status fluidbed_reynolds_of_archimedes(const fluidbed_closure* law, size_t n, const double* archimedes,
                                                double* reynolds, double* d_archimedes, fluidbed_error* error);

/* FLUIDBED_RICHARDSON_ZAKI_EXPONENT: n at argument[i], the terminal Reynolds number Re_t or the
 * Archimedes number Ar as fluidbed_richardson_zaki_argument names it, and, if not NULL,
 * d_argument[i] = dn/d(argument). */
FLUIDBED_C_API fluidbed_status fluidbed_richardson_zaki_exponent(const fluidbed_closure* law, size_t n, const double* argument,
                                                  double* exponent, double* d_argument, fluidbed_error* error);

/* "terminal_reynolds" or "archimedes"; NULL for a closure of another family. */
FLUIDBED_C_API const char* fluidbed_richardson_zaki_argument(const fluidbed_closure* law);

/* ---- Elastic moduli (FLUIDBED_ELASTIC_MODULUS) -------------------------------------------------- */

/* The elastic modulus E^e [Pa] of a homogeneous bed at equilibrium: voidage[i] = ε ∈ (0, 1], the
 * fluid (density [kg/m^3], viscosity [Pa s]), the particles (density > the fluid's [kg/m^3],
 * diameter [m]), the terminal Reynolds number Re_t = ρ_f u_t d/μ_f >= 0 (read by Mazzei–Lettieri
 * only) and the gravity [m/s^2]; if not NULL, d_voidage[i] = ∂E^e/∂ε. */
FLUIDBED_C_API fluidbed_status fluidbed_elastic_modulus_at_equilibrium(
    const fluidbed_closure* model, size_t n, const double* voidage, const double* fluid_density,
    const double* fluid_viscosity, const double* particle_density, const double* diameter,
    const double* terminal_reynolds, const double* gravity, double* modulus, double* d_voidage,
    fluidbed_error* error);

/* The elastic modulus E [Pa] off equilibrium, at the drag state (ε, w, ρ_f, μ_f, d) of
 * fluidbed_drag, for the models that define one (Mazzei–Lettieri; FLUIDBED_INVALID_ARGUMENT for
 * the others); if not NULL, ∂E/∂ε at fixed w and ∂E/∂w at fixed ε. */
FLUIDBED_C_API fluidbed_status fluidbed_elastic_modulus_at_state(const fluidbed_closure* model, size_t n,
                                                                 const double* voidage, const double* slip,
                                                                 const double* fluid_density,
                                                                 const double* fluid_viscosity, const double* diameter,
                                                                 double* modulus, double* d_voidage, double* d_slip,
                                                                 fluidbed_error* error);

/* ---- Kinetic theory of one class of particles ------------------------------------------------ */

/* FLUIDBED_RADIAL_DISTRIBUTION (g0, dimensionless) and FLUIDBED_FRICTIONAL_PRESSURE (p_f [Pa] per
 * unit volume of suspension): value[i] at the solids volume fraction solid_fraction[i] = φ ∈ [0, 1)
 * and, if not NULL, d_solid_fraction[i] = d/dφ. */
FLUIDBED_C_API fluidbed_status fluidbed_of_solid_fraction(const fluidbed_closure* law, size_t n,
                                                          const double* solid_fraction, double* value,
                                                          double* d_solid_fraction, fluidbed_error* error);

/* FLUIDBED_GRANULAR_PRESSURE (p_s [Pa]), FLUIDBED_SHEAR_VISCOSITY (μ_s [Pa s]), FLUIDBED_BULK_VISCOSITY
 * (λ_s [Pa s]), FLUIDBED_CONDUCTIVITY (κ_s [kg m^-1 s^-1]) and FLUIDBED_DISSIPATION (γ [W m^-3]), all
 * per unit volume of suspension: value[i] = law(φ, Θ, g0(φ), material) at φ = solid_fraction[i],
 * the granular temperature Θ = granular_temperature[i] = <C^2>/3 >= 0 [m^2 s^-2], g0 the radial
 * distribution `radial` (a FLUIDBED_RADIAL_DISTRIBUTION closure) and the material {diameter[i] [m],
 * solid_density[i] [kg m^-3], restitution[i] ∈ [0, 1]}. If not NULL, d_solid_fraction[i] = ∂/∂φ at
 * fixed Θ, g0's slope included, and d_granular_temperature[i] = ∂/∂Θ at fixed φ. */
FLUIDBED_C_API fluidbed_status fluidbed_constitutive(const fluidbed_closure* law, const fluidbed_closure* radial,
                                                     size_t n, const double* solid_fraction,
                                                     const double* granular_temperature, const double* diameter,
                                                     const double* solid_density, const double* restitution,
                                                     double* value, double* d_solid_fraction,
                                                     double* d_granular_temperature, fluidbed_error* error);

/* The same in float. */
FLUIDBED_C_API fluidbed_status fluidbed_constitutive_f(const fluidbed_closure* law, const fluidbed_closure* radial,
                                                       size_t n, const float* solid_fraction,
                                                       const float* granular_temperature, const float* diameter,
                                                       const float* solid_density, const float* restitution,
                                                       float* value, float* d_solid_fraction,
                                                       float* d_granular_temperature, fluidbed_error* error);

/* FLUIDBED_FRICTIONAL_VISCOSITY: μ_f [Pa s] per unit volume of suspension at the frictional
 * pressure frictional_pressure[i] = p_f >= 0 [Pa] and the rate of strain, divergence[i] = ∇·u
 * [s^-1] and contraction[i] = D':D' >= 0 [s^-2] (D' the deviatoric rate of strain); if not NULL,
 * d_frictional_pressure[i] = ∂μ_f/∂p_f. */
FLUIDBED_C_API fluidbed_status fluidbed_frictional_viscosity(const fluidbed_closure* law, size_t n,
                                                             const double* frictional_pressure,
                                                             const double* divergence, const double* contraction,
                                                             double* viscosity, double* d_frictional_pressure,
                                                             fluidbed_error* error);

/* FLUIDBED_FRICTIONAL_STRESS: the frictional pressure p_f [Pa] and viscosity μ_f [Pa s] per unit
 * volume of suspension as one law of (φ, Θ, d, rate of strain); if not NULL, d_pressure[i] =
 * ∂p_f/∂φ and d_viscosity[i] = ∂μ_f/∂φ, at fixed Θ and rate of strain. */
FLUIDBED_C_API fluidbed_status fluidbed_frictional_stress(const fluidbed_closure* law, size_t n,
                                                          const double* solid_fraction,
                                                          const double* granular_temperature,
                                                          const double* diameter, const double* divergence,
                                                          const double* contraction, double* pressure,
                                                          double* viscosity, double* d_pressure, double* d_viscosity,
                                                          fluidbed_error* error);

/* ---- Kinetic theory of several classes --------------------------------------------------------- */

/* The largest number of solids classes the mixture functions take (MFiX's default number of
 * solids phases). */
#define FLUIDBED_MAX_CLASSES 10

/* FLUIDBED_MIXTURE_RADIAL_DISTRIBUTION: value[c] = g_ik, the contact value between a particle of
 * class i and one of class k (0-based, below class_count, 1 to FLUIDBED_MAX_CLASSES), of cell c
 * whose class m has the solids volume fraction fractions[m n + c] = φ_m >= 0 (Σ φ_m < 1) and the
 * diameter diameters[m n + c] = d_m > 0 [m]; if not NULL, d_fractions[m n + c] = ∂g_ik/∂φ_m. */
FLUIDBED_C_API fluidbed_status fluidbed_mixture_radial_distribution(const fluidbed_closure* law, size_t n,
                                                                    size_t class_count, size_t i, size_t k,
                                                                    const double* fractions, const double* diameters,
                                                                    double* value, double* d_fractions,
                                                                    fluidbed_error* error);

/* FLUIDBED_SOLID_SOLID_DRAG: the momentum exchange coefficient K_pq [kg m^-3 s^-1] between classes
 * p and q per unit volume of suspension (the force per unit volume on class p is K_pq (v_q − v_p);
 * K_pq = K_qp) at their volume fractions phi_p[i], phi_q[i] ∈ [0, 1), their particles' densities
 * [kg m^-3] and diameters [m] (> 0), the restitution coefficient of their collisions ∈ [0, 1], their
 * contact value g_pq = contact_rdf[i] > 0 (fluidbed_mixture_radial_distribution) and their relative
 * speed |v_p − v_q| = relative_speed[i] >= 0 [m/s]; if not NULL, its derivatives in phi_p, phi_q,
 * g_pq and the relative speed. */
FLUIDBED_C_API fluidbed_status fluidbed_solid_solid_drag(const fluidbed_closure* law, size_t n, const double* phi_p,
                                                         const double* phi_q, const double* density_p,
                                                         const double* diameter_p, const double* density_q,
                                                         const double* diameter_q, const double* restitution,
                                                         const double* contact_rdf, const double* relative_speed,
                                                         double* coefficient, double* d_phi_p, double* d_phi_q,
                                                         double* d_contact_rdf, double* d_relative_speed,
                                                         fluidbed_error* error);

/* FLUIDBED_GAS_EXCHANGE_SOURCE: the production of granular energy by the gas, source[i] [W m^-3]
 * (positive, a term on the right-hand side of the granular energy balance), at the solids volume
 * fraction solid_fraction[i] = φ, the granular temperature Θ [m^2 s^-2], the slip speed
 * |u_g − u_s| = slip[i] [m/s] and the material {diameter [m], solid_density [kg m^-3],
 * restitution}. Each source reads its own further arguments, and those of the other may be NULL:
 * KochSanganiSource the radial distribution `radial` (for g0(φ)) and gas_viscosity[i] [Pa s];
 * DragFluctuationSource the drag coefficient beta[i] [kg m^-3 s^-1] of the host's momentum
 * equation. If not NULL, the derivatives ∂/∂φ (through g0 as well), ∂/∂Θ, ∂/∂β (0 for
 * Koch–Sangani) and ∂/∂w. (The gas's damping of the fluctuations, −3 β Θ, is not a closure.) */
FLUIDBED_C_API fluidbed_status fluidbed_gas_exchange_source(
    const fluidbed_closure* law, const fluidbed_closure* radial, size_t n, const double* solid_fraction,
    const double* granular_temperature, const double* slip, const double* beta, const double* gas_viscosity,
    const double* diameter, const double* solid_density, const double* restitution, double* source,
    double* d_solid_fraction, double* d_granular_temperature, double* d_beta, double* d_slip,
    fluidbed_error* error);

/* ---- Kinetic theory of classes with their own granular temperatures -------------------------- */

/* The kinetic theory of Lathouwers & Bellan (2001) (docs/closures/kinetic_theory.md; the C++
 * kinetic_theory::UnequalTemperatureMixture) over n cells of class_count classes (1 to
 * FLUIDBED_MAX_CLASSES), with h_ik the mixture radial distribution `radial` (a
 * FLUIDBED_MIXTURE_RADIAL_DISTRIBUTION closure with its parameters: "Lebowitz", "Mansoori" or
 * "ModifiedMansoori", the latter seed 004's, max_packing 0.64 as registered). Class m of cell c has
 * the envelope volume fraction fractions[m n + c] = α_m >= 0 (Σ α_m < 1), the granular temperature
 * temperatures[m n + c] = Θ_m = <C_m^2>/3 > 0 [m^2 s^-2], the diameter diameters[m n + c] > 0 [m]
 * and the envelope density densities[m n + c] > 0 [kg m^-3]; every pair of cell c has the
 * restitution restitution[c] ∈ [0, 1]. Writes, per unit volume of suspension (N = class_count):
 *   pressure[i n + c]                     p_i [Pa]
 *   shear_viscosity[(i N + k) n + c]      μ_ik [Pa s]: class k's strain rate in class i's stress
 *   bulk_viscosity[(i N + k) n + c]       λ_ik = (5/3) μ_ik [Pa s]
 *   conductivity[(i N + k) n + c]         κ_ik [kg m^-1 s^-1]: q_i = −Σ_k κ_ik ∇Θ_k
 *   dissipation[i n + c]                  γ_i [W m^-3], a sink (inelastic loss and transfer to
 *                                         the other classes)
 *   drag[(i N + k) n + c]                 β_ik [kg m^-3 s^-1], symmetric, β_ii = 0 (force on class i
 *                                         Σ_k β_ik (u_k − u_i))
 *   segregation[(i N + k) n + c]          s_ik [Pa], symmetric, s_ii = 0 (force on class i
 *                                         Σ_k s_ik ∇ln(n_i/n_k))
 *   radial_distribution[(i N + k) n + c]  h_ik
 * the matrices row-major per cell. Any output may be NULL (not wanted). Every cell is validated as
 * mixture.checked does (FLUIDBED_DOMAIN_ERROR naming the argument, e.g. 'state.temperatures[1]',
 * and the failing cell); a class count out of range, a NULL input or a closure of another family
 * is FLUIDBED_INVALID_ARGUMENT. The values of mixture.checked, bit for bit. */
FLUIDBED_C_API fluidbed_status fluidbed_unequal_temperature_mixture(
    const fluidbed_closure* radial, size_t n, size_t class_count, const double* fractions,
    const double* temperatures, const double* diameters, const double* densities, const double* restitution,
    double* pressure, double* shear_viscosity, double* bulk_viscosity, double* conductivity, double* dissipation,
    double* drag, double* segregation, double* radial_distribution, fluidbed_error* error);

/* The same with the derivatives: each output X (laid out as above, S = its size: N n for p and γ,
 * N^2 n for the matrices) is followed by d_X_d_fractions and d_X_d_temperatures, of size N S, which
 * hold ∂X/∂α_m and ∂X/∂Θ_m laid out as X, m after m: ∂X[e n + c]/∂α_m at
 * d_X_d_fractions[m S + e n + c] (e = i, or i N + k). Every pointer may be NULL (not wanted); the
 * derivatives are those of mixture.checked_with_derivatives, bit for bit (∂/∂α_m through h_ik as
 * well). */
FLUIDBED_C_API fluidbed_status fluidbed_unequal_temperature_mixture_with_derivatives(
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
    fluidbed_error* error);

/* ---- Moment inversion ------------------------------------------------------------------------- */

/* The support of the distributions: [0, ∞) (sizes, masses) or the real line (velocities). */
typedef enum fluidbed_support {
  FLUIDBED_SUPPORT_POSITIVE_HALF_LINE = 0,
  FLUIDBED_SUPPORT_REAL_LINE = 1,
  FLUIDBED_SUPPORT_MAX_ENUM = 0x7fffffff
} fluidbed_support;

/* The largest node count of the moment functions (2 FLUIDBED_MAX_NODES moments). */
#define FLUIDBED_MAX_NODES 8

/* A cell's outcome (the C++ library's moments::InversionStatus). */
typedef enum fluidbed_inversion_status {
  FLUIDBED_INVERSION_OK = 0,              /* all N nodes */
  FLUIDBED_INVERSION_REDUCED = 1,         /* fewer nodes: the set is realizable only with sizes[c] nodes */
  FLUIDBED_INVERSION_ZERO_MASS = 2,       /* every moment 0: an empty cell, no nodes */
  FLUIDBED_INVERSION_NOT_REALIZABLE = 3,  /* not even one node */
  FLUIDBED_INVERSION_INVALID_INPUT = 4,   /* a moment NaN or infinite, or the set beyond the floating-point range */
  FLUIDBED_INVERSION_EIGEN_FAILURE = 5,   /* the eigen-solver did not converge (never observed for sizes) */
  FLUIDBED_INVERSION_INACCURATE = 6,      /* a rule (returned, as for ok or reduced) whose estimated error exceeds
                                             the required accuracy (fluidbed_invert_moments_with_accuracy) */
  FLUIDBED_INVERSION_MAX_ENUM = 0x7fffffff
} fluidbed_inversion_status;

/* Inverts n cells, 2 node_count moments each (node_count from 1 to FLUIDBED_MAX_NODES), to
 * node_count-node Gauss rules, as a CFD code stores the fields: moment k of cell c at
 * moments[k n + c]; writes node i of cell c at nodes[i n + c] (ascending in i) and its weight at
 * weights[i n + c] (0 for i >= sizes[c]), the node count sizes[c] and the cell's status[c] (a
 * fluidbed_inversion_status). The results and statuses are those of the C++
 * moments::invert_batched, bit for bit. A cell that cannot be inverted has its status and the
 * function still returns FLUIDBED_OK; only a node count out of range or a NULL array is an error
 * (FLUIDBED_INVALID_ARGUMENT). */
FLUIDBED_C_API fluidbed_status fluidbed_invert_moments(int node_count, fluidbed_support support, size_t n,
                                                       const double* moments, double* nodes, double* weights,
                                                       int* sizes, int* status, fluidbed_error* error);

/* fluidbed_invert_moments with the error estimate of each rule (the C++ moments::InversionOptions'
 * moment_accuracy and required_accuracy; docs/closures/moments.md, "How many digits a rule has"):
 * moment_accuracy >= 0, the relative accuracy of each of the caller's moments (0: exact as given),
 * and required_accuracy >= 0, both finite (else FLUIDBED_DOMAIN_ERROR naming it, nothing written).
 * Each of the three error arrays may be NULL; given, node_errors[c] and weight_errors[c] receive
 * the cell's estimated largest relative node error (relative to the node on [0, ∞), to the largest
 * |node| on the real line) and weight error (relative to the weight): −1 where the cell has no
 * rule, +∞ where the rule has no digit; count_errors[c] the largest error, relative to its
 * threshold, of the realizability decisions that set the cell's node count (>= 1: the count lies
 * within the error, the set may be realizable with another count), −1 where the cell has no rule.
 * required_accuracy > 0: a rule whose estimated node or weight error
 * exceeds it has the status FLUIDBED_INVERSION_INACCURATE, its nodes and weights still written
 * (the estimate is then made even with every error array NULL; required_accuracy 0 and all NULL:
 * no estimate, the results of fluidbed_invert_moments). The C++ moments::invert_batched with these
 * options, bit for bit. */
FLUIDBED_C_API fluidbed_status fluidbed_invert_moments_with_accuracy(
    int node_count, fluidbed_support support, size_t n, const double* moments, double moment_accuracy,
    double required_accuracy, double* nodes, double* weights, int* sizes, int* status, double* node_errors,
    double* weight_errors, double* count_errors, fluidbed_error* error);

/* The realizability of n cells' moment sets m_0 … m_{moment_count−1} (moment_count from 1 to
 * 2 FLUIDBED_MAX_NODES; moment k of cell c at moments[k n + c]) on the support, by the signs of
 * the recurrence's coefficients (no threshold): the cell's status[c] (a fluidbed_inversion_status:
 * ok when the whole set is realizable, reduced when only a prefix is) and the length R of the
 * realizable prefix m_0 … m_{R−1}, realizable_moments[c] (the Gauss rule then has R/2 nodes); if
 * not NULL, first_failing_index[c], j for the first ζ_j <= 0 on [0, ∞) or k for the first β_k <= 0
 * on the real line (0 where none fails), and failing_value[c], that coefficient in the caller's
 * units (m_0 itself when m_0 <= 0). The C++ moments::realizability, bit for bit. As with the
 * inversion, a cell's outcome is its status, never an error. */
FLUIDBED_C_API fluidbed_status fluidbed_moment_realizability(fluidbed_support support, int moment_count, size_t n,
                                                             const double* moments, int* status,
                                                             int* realizable_moments, int* first_failing_index,
                                                             double* failing_value, fluidbed_error* error);

/* A cell's outcome of the correction (the C++ library's moments::CorrectionStatus). */
typedef enum fluidbed_correction_status {
  FLUIDBED_CORRECTION_UNCHANGED = 0,     /* realizable as given, or on the boundary within round-off */
  FLUIDBED_CORRECTION_MCGRAW = 1,        /* made realizable by McGraw's iterations */
  FLUIDBED_CORRECTION_LOGNORMAL = 2,     /* replaced above m_2 by the log-normal sharing m_0, m_1, m_2 */
  FLUIDBED_CORRECTION_MONODISPERSE = 3,  /* m_0 m_2 < m_1^2: replaced by m_0 r^k, r = m_1/m_0 */
  FLUIDBED_CORRECTION_ZERO_MASS = 4,     /* every moment 0: nothing to correct */
  FLUIDBED_CORRECTION_FAILED = 5,        /* NaN or ±∞, m_0 <= 0 or m_1 <= 0, or no correction
                                            representable: the moments returned as given */
  FLUIDBED_CORRECTION_MAX_ENUM = 0x7fffffff
} fluidbed_correction_status;

/* The correction's options (the C++ moments::CorrectionOptions<double>):
 * protected_moments >= 1, the moments m_0 … m_{protected_moments−1} McGraw never changes;
 * max_iterations >= 0 of McGraw's; degenerate_tolerance >= 0, the relative distance from the
 * boundary of moment space (|ζ_j| <= tolerance ζ_1) within which a set is left unchanged. */
typedef struct fluidbed_correction_options {
  int protected_moments;
  int max_iterations;
  double degenerate_tolerance;
} fluidbed_correction_options;

/* The library's defaults: 1, 20, and the cube root of double's machine epsilon. */
FLUIDBED_C_API fluidbed_correction_options fluidbed_correction_default_options(void);

/* Corrects n cells' size moment sets (on [0, ∞); moment_count from 1 to 2 FLUIDBED_MAX_NODES,
 * moment k of cell c at moments[k n + c]) made unrealizable by their transport: McGraw's (2006)
 * iterations toward a smooth ln m_k, the realizability test, and the log-normal sharing m_0, m_1,
 * m_2 as the fallback (docs/closures/moments.md).
 * Writes the corrected set to corrected (laid out as moments; it may be the moments array itself),
 * the cell's status[c] (a fluidbed_correction_status) and, if not NULL, realizable_moments[c] of
 * the returned set. options NULL: the defaults; options outside their domain:
 * FLUIDBED_DOMAIN_ERROR, nothing written. The C++ moments::correct_moments, bit for bit. */
FLUIDBED_C_API fluidbed_status fluidbed_correct_moments(int moment_count, size_t n, const double* moments,
                                                        const fluidbed_correction_options* options,
                                                        double* corrected, int* status, int* realizable_moments,
                                                        fluidbed_error* error);

/* A cell's outcome of the DQMOM source solve (the C++ library's moments::dqmom::SourceStatus). */
typedef enum fluidbed_dqmom_status {
  FLUIDBED_DQMOM_OK = 0,             /* every node distinct: the full system solved */
  FLUIDBED_DQMOM_MERGED_NODES = 1,   /* nodes closer than (1000 eps)^(1/3) relative were merged (docs/closures/dqmom.md) */
  FLUIDBED_DQMOM_INVALID_INPUT = 2,  /* a node not finite and positive, or a weight negative or not finite */
  FLUIDBED_DQMOM_MAX_ENUM = 0x7fffffff
} fluidbed_dqmom_status;

/* What the DQMOM weights are (the C++ moments::dqmom::Weights): volume fractions of a
 * diameter-distributed phase (seed 000) or number densities (Marchisio & Fox 2005). */
typedef enum fluidbed_dqmom_weights {
  FLUIDBED_DQMOM_VOLUME_FRACTION = 0,
  FLUIDBED_DQMOM_NUMBER_DENSITY = 1,
  FLUIDBED_DQMOM_WEIGHTS_MAX_ENUM = 0x7fffffff
} fluidbed_dqmom_weights;

/* DQMOM source terms of n cells of node_count nodes each (1 to FLUIDBED_MAX_NODES): the sources
 * c^a of the weights and c^xi of the weighted nodes that make the moments M_k = sum a_i xi_i^k,
 * k = 0 ... 2 node_count - 1, change at the rates moment_sources (any kernel of moments:
 * aggregation, breakage, nucleation, ...). Node i of cell c at nodes[i n + c], its weight at
 * weights[i n + c], moment source k at moment_sources[k n + c]; writes weight_sources[i n + c],
 * weighted_node_sources[i n + c], the cell's status[c] (a fluidbed_dqmom_status) and, if not NULL,
 * the condition number of the system solved, condition[c] (about log10 of it digits are lost).
 * The C++ moments::dqmom::solve_batched, bit for bit. A cell's outcome is its status, never an
 * error; a node count out of range or a NULL array is FLUIDBED_INVALID_ARGUMENT. */
FLUIDBED_C_API fluidbed_status fluidbed_dqmom_sources(int node_count, size_t n, const double* nodes,
                                                      const double* weights, const double* moment_sources,
                                                      double* weight_sources, double* weighted_node_sources,
                                                      int* status, double* condition, fluidbed_error* error);

/* DQMOM source terms of growth (node i of cell c growing at growth_rate[i n + c], m/s) and of
 * diffusion (the diffusion-induced sources of seed 000 eqs 6.18-6.23, intensity
 * C_i = D phi_i |grad xi_i|^2 at diffusion_intensity[i n + c]), solved as point functionals: exact to
 * rounding whatever the conditioning (docs/closures/dqmom.md). Either array may be NULL (no such
 * source). weights_kind says what the weights are (growth differs: 3 phi G/xi and 4 phi G for
 * volume fractions, 0 and w G for number densities). Layout and outputs as fluidbed_dqmom_sources;
 * the C++ moments::dqmom::System with growth_terms and diffusion_terms, bit for bit. */
FLUIDBED_C_API fluidbed_status fluidbed_dqmom_growth_diffusion_sources(
    int node_count, fluidbed_dqmom_weights weights_kind, size_t n, const double* nodes, const double* weights,
    const double* growth_rate, const double* diffusion_intensity, double* weight_sources,
    double* weighted_node_sources, int* status, double* condition, fluidbed_error* error);

#ifdef __cplusplus
}
#endif

#endif
