// The elastic family in float, double and long double: the row tests of
// test_scalar_types_elastic.hpp against the mpmath table, the derivatives of the moduli, the
// force products (against the documented formula evaluated in long double) and the stability
// search over the whole interval.
#include "test_scalar_types_elastic.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <variant>

#include "fluidbed/elastic.hpp"
#include "fluidbed/interaction.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using namespace fluidbed::elastic;
using namespace fluidbed::interaction;

TEST_CASE_TEMPLATE_INVOKE(scalar_types_elastic, FLUIDBED_SCALAR_TYPES);

TEST_CASE_TEMPLATE("derivatives of the equilibrium moduli through Dual<T> match central differences", T,
                   FLUIDBED_SCALAR_TYPES) {
  const Fluid<T> air{T(1.25L), T(1.52587890625e-5L)};
  const Particles<T> particles{T(1250), T(1.220703125e-4L)};
  const auto state_at = [&](const T& voidage) { return EquilibriumState<T>{voidage, air, particles, T(3)}; };
  for (const T voidage : {T(0.4L), T(0.6L), T(0.95L)})
    for (const AnyElasticModulus& any : ElasticModuli::all())
      std::visit(
          [&](const auto& model) {
            const auto e = model.with_derivatives(state_at(voidage));
            CHECK(test::same_arithmetic(e.value, model(state_at(voidage))));
            // dE/dε against a central difference with h = ε_T^(1/3) (error ~ h² ≈ ε_T^(2/3))
            const T h = std::cbrt(std::numeric_limits<T>::epsilon());
            const T difference = (model(state_at(voidage + h)) - model(state_at(voidage - h))) / (2 * h);
            INFO("model " << model.name() << " voidage " << double(voidage));
            CHECK(std::isfinite(e.d_voidage));
            CHECK(double(e.d_voidage) == doctest::Approx(double(difference)).epsilon(100 * double(h * h)));
          },
          any);
}

TEST_CASE_TEMPLATE("the interaction forces and the elastic force are their documented products to 4 eps", T,
                   FLUIDBED_SCALAR_TYPES) {
  using L = long double;
  const T phi = T(0.375L), rho_f = T(1.25L), rho_p = T(2500), mu = T(1.52587890625e-5L);
  const Vector3<T> g{T(0), T(0), T(-9.8125L)}, a{T(0.5L), T(-1.25L), T(2)}, b{T(-0.75L), T(0.25L), T(1)};
  const auto check = [](const Vector3<T>& got, const std::array<L, 3>& expected) {
    for (std::size_t i = 0; i < 3; ++i) {
      INFO("component " << i);
      CHECK(test::error_in_epsilons(got[i], expected[i],
                                    std::abs(expected[0]) + std::abs(expected[1]) + std::abs(expected[2])) <= 4);
    }
  };
  const L p = L(phi);
  check(classical_buoyancy(phi, rho_f, g), {0, 0, L(-p * L(rho_f) * L(g[2]))});
  check(pressure_gradient_buoyancy(phi, a), {-p * L(a[0]), -p * L(a[1]), -p * L(a[2])});
  check(stress_buoyancy(phi, a), {p * L(a[0]), p * L(a[1]), p * L(a[2])});
  const L suspension = (1 - p) * L(rho_f) + p * L(rho_p);
  check(homogeneous_buoyancy(phi, rho_f, rho_p, g), {0, 0, -p * suspension * L(g[2])});
  check(local_fluid_acceleration_force(phi, rho_f, a),
        {p * L(rho_f) * L(a[0]), p * L(rho_f) * L(a[1]), p * L(rho_f) * L(a[2])});
  const L vm = L(0.5) * p * L(rho_f);
  check(virtual_mass_force(phi, rho_f, a, b),
        {vm * (L(a[0]) - L(b[0])), vm * (L(a[1]) - L(b[1])), vm * (L(a[2]) - L(b[2]))});
  const L lift = -L(0.5) * p * L(rho_f);  // −C_l φ ρ_f (a × b)
  check(lift_force(phi, rho_f, a, b),
        {lift * (L(a[1]) * L(b[2]) - L(a[2]) * L(b[1])), lift * (L(a[2]) * L(b[0]) - L(a[0]) * L(b[2])),
         lift * (L(a[0]) * L(b[1]) - L(a[1]) * L(b[0]))});
  const L faxen = L(0.75) * p * L(mu);
  check(faxen_force(phi, mu, a), {faxen * L(a[0]), faxen * L(a[1]), faxen * L(a[2])});
  // n f_e = −(2/3) d H (∇ε · n_d) n f_d: along the drag, E ∂ε/∂x with E = −(2/3) d H |n f_d|
  const T d = T(4.8828125e-4L), h = T(-7.5L);
  const L along = -L(2) / 3 * L(d) * L(h) * (L(a[0]) * L(b[0]) + L(a[1]) * L(b[1]) + L(a[2]) * L(b[2])) /
                  std::sqrt(L(a[0]) * L(a[0]) + L(a[1]) * L(a[1]) + L(a[2]) * L(a[2]));
  check(elastic_force(a, b, h, d), {along * L(a[0]), along * L(a[1]), along * L(a[2])});
  const Vector3<T> up{T(0), T(0), T(1)};
  check(elastic_force_vertical(T(3.5L), b, up), {0, 0, L(T(3.5L)) * L(b[2])});
  CHECK_NOTHROW(elastic_force_vertical(T(3.5L), b, up, fluidbed::checked));
}

TEST_CASE_TEMPLATE_INVOKE(scalar_types_stability, FLUIDBED_SCALAR_TYPES);

// Regression (issue 13): with a fixed upper limit 1 − 1e-15, which is 1 in float, S was −∞
// there and every sample NaN; the search never returned (Release) or asserted (Debug). The
// limit is now 1 − 4ε_T and every iteration bounded.
TEST_CASE_TEMPLATE("minimum bubbling point and the waves are finite for every model over the whole interval", T,
                   FLUIDBED_SCALAR_TYPES) {
  const Fluid<T> air{T(1.205L), T(1.81e-5L)};
  for (const Particles<T> particles :
       {Particles<T>{T(1210), T(137e-6L)}, Particles<T>{T(1420), T(26e-6L)}, Particles<T>{T(2500), T(1e-3L)}}) {
    const HomogeneousSuspension<T> s = homogeneous_suspension(air, particles, fluidbed::checked);
    for (const AnyElasticModulus& model : ElasticModuli::all()) {
      INFO("d = " << double(particles.diameter) << ", model " << ElasticModuli::name_of(model));
      const StabilityTransition<T> t = minimum_bubbling_point(model, s);
      CHECK(std::isfinite(t.maximum_voidage));
      CHECK(std::isfinite(t.maximum_stability));
      CHECK(t.maximum_voidage < T(1));
      if (t.bubbling_voidage) CHECK(std::abs(stability_function(model, s, *t.bubbling_voidage)) < T(1e-3L));
      // the maximum: dS/dε = 0 there (to rounding), and S no larger one step away on either side
      const T step = std::sqrt(std::numeric_limits<T>::epsilon()) * t.maximum_voidage;
      CHECK(stability_function(model, s, t.maximum_voidage) >= stability_function(model, s, t.maximum_voidage - step));
      CHECK(stability_function(model, s, t.maximum_voidage) >= stability_function(model, s, t.maximum_voidage + step));
      const WaveSpeeds<T> w = wave_speeds(model, s, T(0.5L), fluidbed::checked);
      const Wave<T> wave = wave_of_wavenumber(w, T(30), fluidbed::checked);
      CHECK(std::isfinite(wave.growth_rate));
      CHECK(std::isfinite(wave.velocity));
      CHECK(double(growth_rate_of_wave_velocity(w, wave.velocity, fluidbed::checked)) ==
            doctest::Approx(double(wave.growth_rate))
                .scale(double(w.damping))
                .epsilon(1e3 * double(std::numeric_limits<T>::epsilon())));
      CHECK(std::isfinite(squared_wavenumber_of_wave_velocity(w, wave.velocity, fluidbed::checked)));
      CHECK(stability_function(model, s, T(1), fluidbed::checked) == -std::numeric_limits<T>::infinity());  // at 1
    }
  }
}
