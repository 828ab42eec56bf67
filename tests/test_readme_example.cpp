// The README's example, verbatim in the body, so that the documentation cannot rot.
#include <doctest/doctest.h>

#include <cmath>
#include <fluidbed/fluidbed.hpp>

TEST_CASE("README example compiles and gives consistent numbers") {
  using namespace fluidbed::drag;

  const DragState<double> cell{.voidage = 0.55, .slip = 0.12,            // ε, |u_f − v_p| [m/s]
                               .fluid = {.density = 1.2, .viscosity = 1.8e-5},
                               .diameter = 150e-6};
  const auto law = make_drag_law("MazzeiLettieri");                       // or the type itself
  double beta = evaluate(law, cell).pressure_gradient();                 // host uses −φ∇p buoyancy
  auto jac = MazzeiLettieri{}.with_derivatives(cell).pressure_gradient(); // β, ∂β/∂ε, ∂β/∂w

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

TEST_CASE("README moment-inversion example compiles and inverts its log-normal set") {
  using namespace fluidbed::moments;

  const std::array<double, 6> m{0.6, 6.2762e-5, 7.1833e-9, 8.9958e-13, 1.2327e-16, 1.8481e-20};  // SI units
  const auto r = invert<3>(m);                     // Wheeler + Golub–Welsch, scale-invariant

  REQUIRE(r.status == InversionStatus::ok);
  double total = 0;
  for (int i = 0; i < r.quadrature.size; ++i) total += r.quadrature.weights[i];
  CHECK(total == doctest::Approx(0.6).epsilon(1e-14));
  // Near the exact rule of the log-normal these moments are rounded from (M_0 = 0.6, median
  // 100 µm, s = 0.3: nodes 73.46, 125.2, 213.5 µm; case lognormal_si of
  // tests/reference/moments_reference.py): the printed moments carry 5 digits.
  CHECK(r.quadrature.nodes[1] == doctest::Approx(125.2e-6).epsilon(0.01));
}

TEST_CASE("README elastic-force and stability example compiles and gives the quoted numbers") {
  using namespace fluidbed::elastic;

  // per cell: drag and its elastic part (eq. 3.116), one Re* solve for both
  const auto d = mazzei_lettieri_drag_and_sensitivity(0.55, 0.12, {1.2, 1.8e-5}, 150e-6);
  const fluidbed::Vector3<double> slip{0.0, 0.02, 0.12}, grad_eps{0.0, 0.0, 4.0};  // u_f − v_p, ∇ε
  const auto drag = fluidbed::scaled(d.beta, slip);                    // classical buoyancy
  const auto elastic = elastic_force(drag, grad_eps, d.sensitivity, 150e-6);

  // once per material: where does a homogeneous bed of this powder start to bubble?
  const auto bed = homogeneous_suspension<double>({1.205, 1.81e-5}, {1210.0, 137e-6});
  const auto t = minimum_bubbling_point(ElasticModel::mazzei_lettieri, bed);
  if (t.bubbling_voidage) { /* ε_mb = 0.401, u_mb = *t.bubbling_velocity = 1.15 cm/s */ }

  REQUIRE(t.bubbling_voidage.has_value());
  CHECK(*t.bubbling_voidage == doctest::Approx(0.401).epsilon(2e-3));
  CHECK(*t.bubbling_velocity == doctest::Approx(0.0115).epsilon(5e-3));
  CHECK(elastic[2] / drag[2] == doctest::Approx(elastic[1] / drag[1]).epsilon(1e-12));  // along the drag
  CHECK(elastic[2] > 0);  // voidage rising along the drag increases it
}

TEST_CASE("README kinetic-theory example compiles and gives the seed-001 numbers") {
  using namespace fluidbed::kinetic_theory;

  const ConstitutiveSet ktgf{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{}, SyamlalConductivity{}};
  const GranularMaterial<double> glass{.diameter = 279e-6, .density = 2480.0, .restitution = 0.9};
  const auto c = ktgf.with_derivatives(0.3, 0.01, glass);
  const double theta = ktgf.algebraic_granular_temperature(0.3, glass, StrainRate<double>{0.0, 0.5}, 0.0);
  const double p_f = JohnsonJacksonPressure{.min_fraction = 0.61, .max_packing = 0.63}(0.62);

  CHECK(c.pressure.value == doctest::Approx(46.15050170899907).epsilon(1e-12));  // seed 001 §12.4 state A
  CHECK(c.pressure.d_solid_fraction > 0);
  CHECK(theta > 0);
  CHECK(p_f == doctest::Approx(5e4).epsilon(1e-12));
}
