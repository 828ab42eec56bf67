/* The C interface from a C11 program (ctest c_interface.from_c): a drag law chosen by name,
 * evaluated over three cells of the drag reference table (tests/reference/drag_reference.csv,
 * mpmath) in both conventions, its parameter changed, and an invalid cell reported with its
 * index and the library's message. Exits non-zero on the first failure. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fluidbed_c.h"

static int failures = 0;

static void check(int ok, const char* what) {
  if (!ok) {
    printf("FAILED: %s\n", what);
    ++failures;
  }
}

static int close_to(double value, double expected) { return fabs(value - expected) <= 1e-13 * fabs(expected); }

int main(void) {
  /* Ergun at ε = 0.35, ρ_f = 1.2 kg/m³, μ_f = 1.8e-5 Pa s, d = 0.5 mm, Re = 0, 0.001, 1. */
  const double voidage[3] = {0.35, 0.35, 0.35};
  const double slip[3] = {0.0, 8.5714285714285714e-5, 0.085714285714285714};
  const double density[3] = {1.2, 1.2, 1.2}, viscosity[3] = {1.8e-5, 1.8e-5, 1.8e-5};
  const double diameter[3] = {0.0005, 0.0005, 0.0005};
  const double classical[3] = {37248.979591836735, 37249.648163265306, 37917.551020408163};
  const double pressure_gradient[3] = {13037.142857142857, 13037.376857142857, 13271.142857142857};
  double beta[3], d_force[3];
  fluidbed_error error;
  fluidbed_closure* ergun = NULL;
  int i;

  check(fluidbed_closure_create("Ergun", &ergun, &error) == FLUIDBED_OK, "create Ergun");
  check(fluidbed_closure_family(ergun) == FLUIDBED_DRAG_LAW, "Ergun is a drag law");
  check(fluidbed_drag(ergun, FLUIDBED_BUOYANCY_CLASSICAL, 3, voidage, slip, density, viscosity, diameter, beta, NULL,
                      NULL, d_force, &error) == FLUIDBED_OK,
        "Ergun, classical");
  for (i = 0; i < 3; ++i) check(close_to(beta[i], classical[i]), "classical beta against the reference table");
  check(d_force[0] == beta[0], "d(beta w)/dw = beta at zero slip");
  check(fluidbed_drag(ergun, FLUIDBED_BUOYANCY_PRESSURE_GRADIENT, 3, voidage, slip, density, viscosity, diameter, beta,
                      NULL, NULL, NULL, &error) == FLUIDBED_OK,
        "Ergun, pressure gradient");
  for (i = 0; i < 3; ++i) check(close_to(beta[i], pressure_gradient[i]), "pressure-gradient beta against the table");

  {
    /* An invalid second cell: the status, its index, the checked API's message. */
    const double bad[3] = {0.35, 1.5, 0.35};
    check(fluidbed_drag(ergun, FLUIDBED_BUOYANCY_CLASSICAL, 3, bad, slip, density, viscosity, diameter, beta, NULL, NULL,
                        NULL, &error) == FLUIDBED_DOMAIN_ERROR,
          "voidage 1.5 is a domain error");
    check(error.index == 1, "the failing cell's index");
    check(strstr(error.message, "fluidbed::Ergun: argument 'voidage' = 1.5 is out of domain") == error.message,
          "the checked API's message");
    printf("%s at cell %zu: %s\n", fluidbed_status_name(error.status), error.index, error.message);
  }
  fluidbed_closure_destroy(ergun);

  {
    fluidbed_closure* syamlal = NULL;
    double c1 = 0;
    check(fluidbed_closure_create("SyamlalOBrien", &syamlal, &error) == FLUIDBED_OK, "create SyamlalOBrien");
    check(fluidbed_closure_set_parameter(syamlal, "c1", 0.9, &error) == FLUIDBED_OK, "set c1");
    check(fluidbed_closure_get_parameter(syamlal, "c1", &c1, &error) == FLUIDBED_OK && c1 == 0.9, "get c1");
    check(fluidbed_closure_set_parameter(syamlal, "exponent", 2.65, &error) == FLUIDBED_UNKNOWN_PARAMETER,
          "no parameter 'exponent'");
    printf("%s\n", error.message);
    fluidbed_closure_destroy(syamlal);
  }
  printf("%zu closures; %s\n", fluidbed_closure_count(), failures ? "FAILED" : "all checks passed");
  return failures != 0;
}
