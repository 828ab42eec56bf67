// The kinetic-theory family in float, double and long double: the row tests of
// test_scalar_types_kinetic_theory.hpp against the mpmath table, and a ConstitutiveSet's values
// and derivatives in each type.
#include "test_scalar_types_kinetic_theory.hpp"

#include <doctest/doctest.h>

#include <cmath>

#include "fluidbed/kinetic_theory.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

TEST_CASE_TEMPLATE_INVOKE(scalar_types_kinetic_theory_laws, FLUIDBED_SCALAR_TYPES);

TEST_CASE_TEMPLATE_INVOKE(scalar_types_kinetic_theory_others, FLUIDBED_SCALAR_TYPES);

TEST_CASE_TEMPLATE("a ConstitutiveSet gives its laws' values and their derivatives in each type", T,
                   FLUIDBED_SCALAR_TYPES) {
  const ConstitutiveSet<CarnahanStarling, LunPressure, SyamlalViscosity, SyamlalConductivity> set{};
  const GranularMaterial<T> m{T(4.8828125e-4L), T(2500), T(0.875L)};
  const StrainRate<T> rate{T(0.25L), T(2)};
  for (const T phi : {T(0), T(0.125L), T(0.5L)})
    for (const T theta : {T(0), T(0.0625L)}) {
      INFO("phi " << double(phi) << " theta " << double(theta));
      const ConstitutiveValues<T> v = set(phi, theta, m);
      const T g0 = CarnahanStarling{}(phi);
      CHECK(test::same_arithmetic(v.radial_distribution, g0));
      CHECK(test::same_arithmetic(v.pressure, LunPressure{}(phi, theta, g0, m)));
      CHECK(test::same_arithmetic(v.shear_viscosity, SyamlalViscosity{}(phi, theta, g0, m)));
      CHECK(test::same_arithmetic(v.bulk_viscosity, LunBulkViscosity{}(phi, theta, g0, m)));
      CHECK(test::same_arithmetic(v.conductivity, SyamlalConductivity{}(phi, theta, g0, m)));
      CHECK(test::same_arithmetic(v.dissipation, LunDissipation{}(phi, theta, g0, m)));
      const auto d = set.with_derivatives(phi, theta, m);
      CHECK(test::same_arithmetic(d.pressure.value, v.pressure));
      CHECK(test::same_arithmetic(d.conductivity.value, v.conductivity));
      CHECK(std::isfinite(d.pressure.d_solid_fraction));
      CHECK(std::isfinite(d.dissipation.d_granular_temperature));
      CHECK(test::same_arithmetic(set.checked(phi, theta, m).pressure, v.pressure));
      if (phi > 0) {
        const T theta_algebraic = set.algebraic_granular_temperature(phi, m, rate, T(0));
        CHECK(std::isfinite(theta_algebraic));
        CHECK(test::same_arithmetic(set.algebraic_granular_temperature(phi, m, rate, T(0), fluidbed::checked),
                                    theta_algebraic));
        const auto sensitivities = set.algebraic_granular_temperature_with_sensitivities(phi, m, rate, T(0));
        CHECK(test::same_arithmetic(sensitivities.value, theta_algebraic));
        CHECK(std::isfinite(sensitivities.d_solid_fraction));
      }
    }
}
