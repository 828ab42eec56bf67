// The states of README.md's examples, and what the numbers they print must satisfy: published
// values where there are any (Table 4.6's minimum bubbling point, the log-normal's exact rule,
// the Lun pressure), physical signs and identities otherwise. The snippets themselves are compiled
// as written and their output compared with the README by the ctests build.readme_snippets_*
// (tests/build_checks/check_readme_snippets.py).
#include <doctest/doctest.h>

#include <cmath>
#include <fluidbed/fluidbed.hpp>

TEST_CASE("README drag example: conventions, signs and the force derivative") {
  using namespace fluidbed::drag;

  const DragState<double> cell{.voidage = 0.55, .slip = 0.12,            // ε, |u_f − v_p| [m/s]
                               .fluid = {.density = 1.2, .viscosity = 1.8e-5},
                               .diameter = 150e-6};
  const auto law = make_drag_law("MazzeiLettieri");
  const double beta = evaluate(law, cell).pressure_gradient();
  const auto jac = MazzeiLettieri{}.with_derivatives(cell).pressure_gradient();

  CHECK(jac.value == beta);
  CHECK(beta == doctest::Approx(0.55 * MazzeiLettieri{}(cell).classical()).epsilon(1e-15));
  CHECK(jac.d_voidage < 0);  // denser beds drag more
  // β itself may fall with slip here (ψ_e drops from 2.8 as Re grows), but the drag
  // force βw must rise with it.
  CHECK(std::isfinite(jac.d_slip));
  CHECK(MazzeiLettieri{}.with_derivatives(cell).force_slip_derivative(Buoyancy::pressure_gradient) > 0);
}

TEST_CASE("laws without transcendental functions evaluate at compile time") {
  using namespace fluidbed::drag;
  constexpr DragState<double> cell{0.5, 0.1, {1.2, 1.8e-5}, 5e-4};
  constexpr double beta = Ergun{}(cell).pressure_gradient();
  static_assert(beta > 0);
  CHECK(beta == doctest::Approx(150 * 0.25 * 1.8e-5 / (0.5 * 25e-8) + 1.75 * 0.5 * 1.2 * 0.1 / 5e-4));
}

TEST_CASE("README moment-inversion example: the rule of its log-normal set") {
  using namespace fluidbed::moments;

  const std::array<double, 6> m{0.6, 6.2762e-5, 7.1833e-9, 8.9958e-13, 1.2327e-16, 1.8481e-20};  // SI units
  const auto r = invert<3>(m);

  REQUIRE(r.status == InversionStatus::ok);
  double total = 0;
  for (int i = 0; i < r.quadrature.size; ++i) total += r.quadrature.weights[i];
  CHECK(total == doctest::Approx(0.6).epsilon(1e-14));
  // Near the exact rule of the log-normal these moments are rounded from (M_0 = 0.6, median
  // 100 µm, s = 0.3: nodes 73.46, 125.2, 213.5 µm; case lognormal_si of
  // tests/reference/moments_reference.py): the printed moments carry 5 digits.
  CHECK(r.quadrature.nodes[1] == doctest::Approx(125.2e-6).epsilon(0.01));
}

TEST_CASE("README elastic-force and stability example: Table 4.6 and the force along the drag") {
  using namespace fluidbed::elastic;

  const auto d = mazzei_lettieri_drag_and_sensitivity(0.55, 0.12, {1.2, 1.8e-5}, 150e-6);
  const fluidbed::Vector3<double> slip{0.0, 0.02, 0.12}, grad_eps{0.0, 0.0, 4.0};
  const auto drag = fluidbed::scaled(d.beta, slip);
  const auto elastic = elastic_force(drag, grad_eps, d.sensitivity, 150e-6);
  const auto bed = homogeneous_suspension<double>({1.205, 1.81e-5}, {1210.0, 137e-6});
  const auto t = minimum_bubbling_point(MazzeiLettieriModulus{}, bed);

  // Powder 1 of seed 000 Table 4.6: ε_mb = 0.401 and u_mb = 1.15 cm/s for the Mazzei–Lettieri model.
  REQUIRE(t.bubbling_voidage.has_value());
  CHECK(*t.bubbling_voidage == doctest::Approx(0.401).epsilon(2e-3));
  CHECK(*t.bubbling_velocity == doctest::Approx(0.0115).epsilon(5e-3));
  CHECK(elastic[2] / drag[2] == doctest::Approx(elastic[1] / drag[1]).epsilon(1e-12));  // along the drag
  CHECK(elastic[2] > 0);  // voidage rising along the drag increases it
}

TEST_CASE("README kinetic-theory example: the Lun pressure and a finite equilibrium temperature") {
  using namespace fluidbed::kinetic_theory;

  const ConstitutiveSet ktgf{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{}, SyamlalConductivity{}};
  const GranularMaterial<double> glass{.diameter = 279e-6, .density = 2480.0, .restitution = 0.9};
  const auto c = ktgf.with_derivatives(0.3, 0.01, glass);
  const double theta = ktgf.algebraic_granular_temperature(0.3, glass, StrainRate<double>{0.0, 50.0}, 0.0);
  const double p_f = JohnsonJacksonPressure{0.61, 0.63}(0.62);

  // Lun et al. (1984), seed 001 eq. 21: ρ_s φ Θ [1 + 2(1 + e) φ g0] with Ogawa's g0 = 1/(1 − (φ/0.63)^(1/3))
  // (seed 001 eq. 24), evaluated by hand: 46.15050170899908 Pa.
  CHECK(c.pressure.value == doctest::Approx(46.15050170899908).epsilon(1e-12));
  CHECK(c.pressure.d_solid_fraction > 0);
  CHECK(theta > 0);
  CHECK(p_f == doctest::Approx(5e4).epsilon(1e-12));
}
