// Transport within a class of a mixture (kinetic_theory/class_transport.hpp): the self-diffusivity
// of seed 000 eq. 6.24, the in-phase diffusion coefficients and the mean-particle-mass source of
// seed 004 (Lathouwers & Bellan 2001), the per-class granular-energy exchange, and seed 004's
// segregation index. References: seed 000's example (Θ = 1e-4 m²/s², d = 200 µm, φ = 0.5:
// "about 1e-6 m²/s"), an independent double-precision evaluation of the seeds' formulas made when
// the seeds were read (quoted to 6 significant figures where used), seed 004's own segregation
// formula, exact solutions and identities.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "fluidbed/kinetic_theory.hpp"
#include "test_out_of_domain.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

namespace {

// |got − expected| within `ulps` units in the last place of T at expected.
template <class T>
bool within_ulps(const T& got, const T& expected, int ulps) {
  return std::abs(got - expected) <= ulps * std::numeric_limits<T>::epsilon() * std::abs(expected);
}

// expected within a relative tolerance (doctest's Approx alone adds an absolute tolerance of
// `epsilon`, which would accept any value of a quantity as small as 1e-5 m²/s).
doctest::Approx approx(double expected, double epsilon) { return doctest::Approx(expected).epsilon(epsilon).scale(0); }

// The message of a checked call begins with the function and the argument.
template <class Call>
void check_message(const std::string& function, const std::string& argument, const Call& call) {
  const std::string expected = "fluidbed::kinetic_theory::" + function + ": argument '" + argument + "'";
  INFO("expected: ", expected);
  CHECK(test::domain_error_message(call).find(expected) == 0);
}

template <class T>
void check_self_diffusivity_identities() {
  // √π · 3/(3√π · 0.5) = 2.
  const T pi = std::numbers::pi_v<T>;
  CHECK(within_ulps(self_diffusivity(pi, T(3), T(0.5)), T(2), 8));
  const auto d = self_diffusivity_with_derivatives(T(0.01), T(500e-6), T(0.3));
  CHECK(within_ulps(d.d_solid_fraction, -d.value / T(0.3), 8));
  CHECK(within_ulps(d.d_granular_temperature, d.value / T(0.02), 8));
}

template <class T>
void check_segregation_limits() {
  CHECK(segregation_index(T(0.4), T(0.2), T(0.4), T(0.2)) == T(0));
  CHECK(segregation_index(T(0.4), T(0), T(0.4), T(0.2)) == T(1));
  CHECK(segregation_index(T(0), T(0.2), T(0.4), T(0.2)) == T(-1));
}

}  // namespace

TEST_CASE("self-diffusivity: seed 000 eq. 6.24 values, identities, float to long double") {
  // The seed's example and two denser states (6 s.f.).
  CHECK(self_diffusivity(1e-4, 200e-6, 0.5) == approx(7.52253e-7, 1e-5));
  CHECK(self_diffusivity(0.01, 500e-6, 0.3) == approx(3.13439e-5, 1e-5));
  CHECK(self_diffusivity(0.01, 500e-6, 0.55) == approx(1.70967e-5, 1e-5));
  CHECK(self_diffusivity(0.0, 500e-6, 0.3) == 0.0);
  check_self_diffusivity_identities<float>();
  check_self_diffusivity_identities<double>();
  check_self_diffusivity_identities<long double>();
}

TEST_CASE("self-diffusivity: derivatives against central differences") {
  const double theta = 0.01, d = 500e-6, phi = 0.3, h = 1e-6;
  const auto value = self_diffusivity_with_derivatives(theta, d, phi);
  CHECK(value.value == self_diffusivity(theta, d, phi));
  const double by_phi = (self_diffusivity(theta, d, phi + h) - self_diffusivity(theta, d, phi - h)) / (2 * h);
  const double by_theta =
      (self_diffusivity(theta + h * theta, d, phi) - self_diffusivity(theta - h * theta, d, phi)) / (2 * h * theta);
  CHECK(value.d_solid_fraction == approx(by_phi, 1e-7));
  CHECK(value.d_granular_temperature == approx(by_theta, 1e-7));
}

TEST_CASE("self-diffusivity of a class: the total solids fraction, so relabelling one powder as two classes changes nothing") {
  const double theta = 0.01, d = 500e-6, rho = 2500, phi = 0.5;
  const auto whole = class_mass_diffusion_with_derivatives(phi, phi, theta, d, rho);
  const auto first = class_mass_diffusion_with_derivatives(0.2, phi, theta, d, rho);
  const auto second = class_mass_diffusion_with_derivatives(0.3, phi, theta, d, rho);
  CHECK(first.value + second.value == approx(whole.value, 1e-15));
  CHECK(first.d_solid_fraction + second.d_solid_fraction == approx(whole.d_solid_fraction, 1e-15));
  // Each part carries the same diffusivity as the whole: α_i ρ D with D of the whole.
  CHECK(first.value / (0.2 * rho) == approx(self_diffusivity(theta, d, phi), 1e-15));
  // A trace class in a dense bed diffuses as the bed does, not as a dilute suspension.
  const auto trace = class_mass_diffusion_with_derivatives(1e-9, phi, theta, d, rho);
  CHECK(trace.value / (1e-9 * rho) == approx(self_diffusivity(theta, d, phi), 1e-15));
}

TEST_CASE("in-phase diffusion coefficients: values from seed numbers, exact derivatives, enthalpy = c_p times mass") {
  // α = 0.3 of a bed at φ = 0.3 (one class), ρ = 2500, with D = 3.13439e-5 m²/s (Θ = 0.01, d = 500 µm).
  const double alpha = 0.3, rho = 2500, cp = 800, theta = 0.01, d = 500e-6;
  const double expected_mass = alpha * rho * 3.13439e-5;
  CHECK(class_mass_diffusion_coefficient(alpha, rho, 3.13439e-5) == approx(expected_mass, 1e-15));
  CHECK(class_enthalpy_diffusion_coefficient(alpha, rho, cp, 3.13439e-5) ==
        approx(cp * expected_mass, 1e-15));
  const auto mass = class_mass_diffusion_with_derivatives(alpha, 0.3, theta, d, rho);
  CHECK(mass.value == approx(expected_mass, 1e-5));
  CHECK(mass.d_class_fraction == approx(mass.value / alpha, 1e-14));
  CHECK(mass.d_solid_fraction == approx(-mass.value / 0.3, 1e-14));
  CHECK(mass.d_granular_temperature == approx(mass.value / (2 * theta), 1e-14));
  const auto heat = class_enthalpy_diffusion_with_derivatives(alpha, 0.3, theta, d, rho, cp);
  CHECK(heat.value == approx(cp * mass.value, 1e-15));
  CHECK(heat.d_class_fraction == approx(cp * mass.d_class_fraction, 1e-15));
  CHECK(heat.d_solid_fraction == approx(cp * mass.d_solid_fraction, 1e-15));
  CHECK(heat.d_granular_temperature == approx(cp * mass.d_granular_temperature, 1e-15));
}

TEST_CASE("mean particle mass: the source is +2 Gamma m, not seed 004's printed -2 Gamma m") {
  // A uniform class whose particles lose mass at dm/dt = −k m: m̄(t) = m̄0 e^{−kt} at a fixed
  // number density n, α ρ = n m̄, Γ = d(αρ)/dt = −k n m̄, and α ρ m̄ = n m̄(t)².
  const double n = 1e8, m0 = 1e-6, k = 2.0, t = 0.3, h = 1e-6;
  const auto mean_mass = [&](double time) { return m0 * std::exp(-k * time); };
  const auto transported = [&](double time) { return n * mean_mass(time) * mean_mass(time); };
  const double gamma = -k * n * mean_mass(t);
  const double rate = (transported(t + h) - transported(t - h)) / (2 * h);
  CHECK(mean_mass_source(gamma, mean_mass(t)) == approx(rate, 1e-8));
  CHECK(mean_mass_source(gamma, mean_mass(t)) < 0);  // shrinking particles: the mean mass falls
  CHECK(-2 * gamma * mean_mass(t) != approx(rate, 1e-3));  // the printed sign
  const auto with = mean_mass_source_with_derivatives(gamma, mean_mass(t));
  CHECK(with.value == mean_mass_source(gamma, mean_mass(t)));
  CHECK(with.d_mass_source == 2 * mean_mass(t));
  CHECK(with.d_mean_mass == 2 * gamma);
}

TEST_CASE("granular energy of a class: -3 beta Theta and (3/2) Gamma Theta, right-hand-side signs") {
  // Seed 001 eq. 35 with Ergun's K at α_s = 0.3 (air, d = 500 µm, slip 0.5 m/s): −3KΘ = −60.5571.
  const double k_ergun = 2018.57, theta = 0.01;
  const auto one = class_energy_exchange(k_ergun, 0.0, theta);
  CHECK(one.gas_damping == approx(-60.5571, 5e-6));
  CHECK(one.gas_damping == gas_damping(k_ergun, theta));
  CHECK(one.mass_transfer == 0.0);
  // Mass transfer alone leaves Θ unchanged: with α ρ = A e^{−kt}, Γ = −k α ρ and Θ fixed, the
  // left side (3/2) d(α ρ Θ)/dt equals the source.
  const double a0 = 1500, k = 0.7, t = 0.4, h = 1e-6;
  const auto bulk = [&](double time) { return a0 * std::exp(-k * time); };
  const double gamma = -k * bulk(t);
  const double left = 1.5 * theta * (bulk(t + h) - bulk(t - h)) / (2 * h);
  CHECK(mass_transfer_energy(gamma, theta) == approx(left, 1e-8));
  CHECK(mass_transfer_energy(gamma, theta) < 0);
  // Derivatives of the sum.
  const double beta = 330.0;
  const auto both = class_energy_exchange(beta, gamma, theta);
  CHECK(both.total() == approx(-3 * beta * theta + 1.5 * gamma * theta, 1e-15));
  CHECK(both.d_granular_temperature == approx(-3 * beta + 1.5 * gamma, 1e-15));
  CHECK(both.d_beta == -3 * theta);
  CHECK(both.d_mass_source == 1.5 * theta);
}

TEST_CASE("granular energy of N classes: each class its own terms, checked errors name the class") {
  const std::array<double, 3> beta{330.0, 2018.57, 8415.0}, gamma{-0.5, 0.0, 0.25}, theta{0.01, 0.002, 0.0};
  const auto terms = class_energy_exchanges(beta, gamma, theta);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto single = class_energy_exchange(beta[i], gamma[i], theta[i]);
    CHECK(terms[i].gas_damping == single.gas_damping);
    CHECK(terms[i].mass_transfer == single.mass_transfer);
    CHECK(terms[i].d_granular_temperature == single.d_granular_temperature);
  }
  CHECK(terms[0].gas_damping == approx(-9.9, 1e-15));  // seed 001 eq. 35, Ergun at α_s = 0.1
  CHECK(terms[2].total() == 0.0);                                      // Θ = 0: nothing to exchange
  std::array<double, 3> bad = beta;
  bad[1] = -1.0;
  check_message("class_energy_exchanges", "beta[1]", [&] { class_energy_exchanges(bad, gamma, theta, checked); });
  std::array<double, 3> cold = theta;
  cold[2] = -1e-3;
  check_message("class_energy_exchanges", "granular_temperature[2]",
                [&] { class_energy_exchanges(beta, gamma, cold, checked); });
  check_message("class_energy_exchange", "mass_source",
                [] { class_energy_exchange(1.0, std::numeric_limits<double>::quiet_NaN(), 0.01, checked); });
}

TEST_CASE("segregation index: seed 004's values, its printed weights, the limits S = 0 and +-1") {
  // Seed 004: 2/3 sand and 1/3 biomass of φ = 0.6, nominal 0.4 and 0.2.
  CHECK(segregation_index(0.4, 0.2, 0.4, 0.2) == 0.0);
  CHECK(segregation_index(0.3, 0.2, 0.4, 0.2) == approx(-0.142857, 1e-5));
  CHECK(segregation_index(0.4, 0.1, 0.4, 0.2) == approx(0.333333, 1e-5));
  CHECK(segregation_index(0.0, 0.2, 0.4, 0.2) == -1.0);
  // The seed's printed form S = (0.2 α_s − 0.4 α_b)/(0.2 α_s + 0.4 α_b).
  for (const double sand : {0.05, 0.3, 0.45})
    for (const double biomass : {0.0, 0.12, 0.3}) {
      const double printed = (0.2 * sand - 0.4 * biomass) / (0.2 * sand + 0.4 * biomass);
      CHECK(segregation_index(sand, biomass, 0.4, 0.2) == approx(printed, 1e-14));
    }
  // Any nominal composition is S = 0 there; swapping the classes flips the sign.
  CHECK(segregation_index(0.17, 0.31, 0.17, 0.31) == 0.0);
  CHECK(segregation_index(0.2, 0.35, 0.4, 0.2) == -segregation_index(0.35, 0.2, 0.2, 0.4));
  check_segregation_limits<float>();
  check_segregation_limits<double>();
  check_segregation_limits<long double>();
}

TEST_CASE("class transport: checked forms name the argument") {
  check_message("self_diffusivity", "solid_fraction", [] { self_diffusivity(0.01, 5e-4, 0.0, checked); });
  check_message("self_diffusivity", "granular_temperature", [] { self_diffusivity(-0.01, 5e-4, 0.3, checked); });
  check_message("self_diffusivity", "diameter", [] { self_diffusivity(0.01, 0.0, 0.3, checked); });
  CHECK(self_diffusivity(0.01, 5e-4, 0.3, checked) == self_diffusivity(0.01, 5e-4, 0.3));
  check_message("self_diffusivity", "solid_fraction",
                [] { self_diffusivity_with_derivatives(0.01, 5e-4, 1.0, checked); });
  check_message("class_mass_diffusion_with_derivatives", "class_fraction",
                [] { class_mass_diffusion_with_derivatives(0.4, 0.3, 0.01, 5e-4, 2500.0, checked); });
  check_message("class_enthalpy_diffusion_with_derivatives", "heat_capacity",
                [] { class_enthalpy_diffusion_with_derivatives(0.2, 0.3, 0.01, 5e-4, 2500.0, 0.0, checked); });
  check_message("class_mass_diffusion_coefficient", "self_diffusivity",
                [] { class_mass_diffusion_coefficient(0.2, 2500.0, -1e-5, checked); });
  check_message("class_enthalpy_diffusion_coefficient", "density",
                [] { class_enthalpy_diffusion_coefficient(0.2, 0.0, 800.0, 1e-5, checked); });
  check_message("mean_mass_source", "mean_mass", [] { mean_mass_source(-1.0, -1e-6, checked); });
  check_message("mass_transfer_energy", "granular_temperature", [] { mass_transfer_energy(-1.0, -0.1, checked); });
  const std::string neither = test::domain_error_message([] { segregation_index(0.0, 0.0, 0.4, 0.2, checked); });
  CHECK(neither.find("fluidbed::kinetic_theory::segregation_index: argument 'first_fraction + second_fraction'") == 0);
  CHECK(neither.find("neither class is present") != std::string::npos);
  check_message("segregation_index", "second_nominal_fraction", [] { segregation_index(0.3, 0.2, 0.4, 0.0, checked); });
}
