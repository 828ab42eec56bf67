// The per-class closures of the multi-fluid (DQMOM) model (polydisperse/class_closures.hpp).
// References, all independent of the code under test: seed 000 Ch. 6's worked values (drag of
// one class, eqs. 6.12–6.13; Syamlal's drag of its binary layers, eqs. 6.14–6.16) evaluated with
// mpmath at 40 digits when the thesis was read; exact identities (one class is the monodisperse
// law; classes of one diameter add up to it; ζ_ik = ζ_ki and invariance under relabelling);
// derivatives against central finite differences and against a dual-number evaluation of the
// formula written out here.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "fluidbed/drag.hpp"
#include "fluidbed/polydisperse.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using polydisperse::ClassClosures;
using polydisperse::MultiFluidState;

namespace {

constexpr double machine_epsilon = std::numeric_limits<double>::epsilon();

constexpr std::size_t N = 4;
using State = MultiFluidState<double, N>;
using drag::Buoyancy;

const Fluid<double> air{.density = 1.16, .viscosity = 1.75e-5};  // illustrative gas (seed 000 gives none)

// One class as the test writes it: φ_i, ξ_i, ρ_i and the slip w_i = |u − v_i|, with u = 0 and
// v_i = (0, 0, −w_i) (so that the slip is w_i exactly), or v_i given.
struct Class {
  double fraction, diameter, density, slip;
};

State make_state(const std::vector<Class>& classes, const Fluid<double>& fluid = air) {
  State s{};
  s.classes = classes.size();
  s.fluid = fluid;
  s.fluid_velocity = {0, 0, 0};
  for (std::size_t i = 0; i < classes.size(); ++i) {
    s.volume_fractions[i] = classes[i].fraction;
    s.diameters[i] = classes[i].diameter;
    s.densities[i] = classes[i].density;
    s.velocities[i] = {0, 0, -classes[i].slip};
  }
  return s;
}

double relative(double a, double b) {
  if (a == b) return 0;
  return std::abs(a - b) / std::max(std::abs(b), std::numeric_limits<double>::min());
}

// The three-class state of the derivative tests: unequal diameters, densities, slips, and a
// relative velocity in every direction.
State three_classes() {
  State s = make_state({{0.12, 80e-6, 2500, 0.21}, {0.2, 150e-6, 2600, 0.13}, {0.09, 300e-6, 1500, 0.05}});
  s.fluid_velocity = {0.01, -0.02, 0.3};
  s.velocities[0] = {0.05, 0.0, 0.12};
  s.velocities[1] = {-0.03, 0.04, 0.2};
  s.velocities[2] = {0.0, 0.01, 0.26};
  return s;
}

}  // namespace

TEST_CASE("gas-particle drag: seed 000 eqs. 6.12-6.13 worked example, and the thesis form at other states") {
  // ε = 0.6 from a second class (φ_2 = 0.138, any diameter); class 1: φ = 0.262, ξ = 75 µm, w = 0.15 m/s.
  const State s = make_state({{0.262, 75e-6, 2500, 0.15}, {0.138, 103e-6, 2500, 0.02}});
  const auto c = ClassClosures<>{}(s);
  CHECK(c.voidage() == doctest::Approx(0.6).epsilon(1e-15));
  CHECK(c.slip(0) == 0.15);
  const double eps = c.voidage();
  const double re = particle_reynolds(air, 75e-6, eps, 0.15);  // Re_i = ρ_f ε w_i ξ_i/μ_f (eq. 6.13)
  const double re_star = drag::MazzeiLettieri::effective_reynolds(eps, re);
  const double psi = drag::MazzeiLettieri::equivalent_exponent(eps, re);
  CHECK(relative(re, 0.447429) < 1e-6);
  CHECK(relative(re_star, 3.54641) < 2e-6);
  CHECK(relative(settling::MazzeiExponent{}.exponent(re_star), 4.05261) < 2e-6);
  CHECK(relative(psi, 2.58792) < 2e-6);
  // mpmath, 40 digits: β_1 = 62514.28859700258739 (seed 000's convention, −φ_i ∇p).
  CHECK(relative(c.gas_particle(0).pressure_gradient(), 62514.28859700259) < 1e-12);
  CHECK(relative(c.gas_particle(0).classical(), 62514.28859700259 / eps) < 1e-12);

  // β_i,pg = ¾ C_D(Re_i) ρ_f w_i ε φ_i/ξ_i · ε^(−ψ_e(ε, Re_i)), Dallavalle C_D, at a grid of states.
  for (double phi1 : {0.05, 0.2, 0.35})
    for (double w : {1e-3, 0.15, 3.0})
      for (double d : {50e-6, 500e-6}) {
        const State t = make_state({{phi1, d, 2500, w}, {0.1, 200e-6, 2500, 0.0}, {0.07, 120e-6, 1000, 0.4}});
        const auto r = ClassClosures<>{}(t);
        const double e = r.voidage();
        const double re_i = air.density * e * w * d / air.viscosity;
        const double cd = std::pow(0.63 + 4.8 / std::sqrt(re_i), 2);
        const double thesis = 0.75 * cd * air.density * w * e * phi1 / d *
                              std::pow(e, -drag::MazzeiLettieri::equivalent_exponent(e, re_i));
        INFO("phi1 = " << phi1 << ", w = " << w << ", d = " << d);
        CHECK(relative(r.gas_particle(0).pressure_gradient(), thesis) < 1e-12);
      }
}

TEST_CASE("solid-solid drag: seed 000's binary layer (Syamlal, Lebowitz), standard 3/4 prefactor") {
  // φ = (0.262, 0.338), ξ = (75, 103) µm, ρ = 2500, ε = 0.4, |Δv| = 0.01 m/s, e = 0.97, C_f = 0.15.
  State s = make_state({{0.262, 75e-6, 2500, 0.0}, {0.338, 103e-6, 2500, 0.0}});
  s.velocities[1] = {0.01, 0, 0};
  const ClassClosures<> closures{};  // seed 000 §6.5: e = 0.97, C_f = 0.15
  CHECK(closures.restitution == 0.97);
  CHECK(closures.solid_solid_drag.friction_coefficient == 0.15);
  const auto c = closures(s);
  CHECK(c.voidage() == doctest::Approx(0.4).epsilon(1e-15));
  CHECK(c.relative_speed(0, 1) == 0.01);
  const std::array<double, 2> phi{0.262, 0.338}, xi{75e-6, 103e-6};
  // mpmath: g_12 = 8.012921348314607, ζ_12 = 612894.5109648634 (seed 000 eq. 6.15 as printed: × π).
  CHECK(relative(closures.radial_distribution(std::span<const double>(phi), std::span<const double>(xi), 0, 1),
                 8.012921348314607) < 1e-14);
  CHECK(relative(c.solid_solid(0, 1), 612894.5109648634) < 1e-13);
  CHECK(relative(std::numbers::pi * c.solid_solid(0, 1), 1925464.893072724) < 1e-13);
  CHECK(c.solid_solid(1, 0) == c.solid_solid(0, 1));
  CHECK(c.solid_solid(0, 0) == 0);
  // ζ is linear in |Δv|: ∂ζ/∂|Δv| = ζ/|Δv|.
  const auto d = closures.with_derivatives(s);
  CHECK(relative(d.solid_solid(0, 1).d_relative_speed, 612894.5109648634 / 0.01) < 1e-13);
}

TEST_CASE("one class is the monodisperse law, value and derivatives, for every law of the registry") {
  for (const drag::AnyDragLaw& any : drag::all_drag_laws)
    std::visit(
        [](const auto& law) {
          using Law = std::remove_cvref_t<decltype(law)>;
          const ClassClosures<Law> closures{law};
          for (double phi : {1e-6, 0.1, 0.4, 0.55})
            for (double w : {0.0, 0.02, 0.7}) {
              const State s = make_state({{phi, 180e-6, 2500, w}});
              const auto c = closures(s);
              const auto d = closures.with_derivatives(s);
              const double eps = c.voidage();
              const drag::DragState<double> mono{eps, w, air, 180e-6};
              const auto beta = law(mono);
              const auto beta_d = law.with_derivatives(mono);
              // The law at ε = fl(1 − φ) is the law of the solids fraction 1 − ε, which differs
              // from φ by the rounding of ε (2.9e-11 relative at φ = 1e-6): the class's β is
              // that of φ itself, β_law φ/(1 − ε); the correction is within 1 ulp of 1 for φ ≥ 0.1.
              const double correction = phi / (1 - eps);
              if (phi >= 0.1) CHECK(std::abs(correction - 1) <= 2.3e-16);
              INFO(law.name() << ": phi = " << phi << ", w = " << w);
              for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
                CHECK(relative(c.gas_particle(0).in(b), correction * beta.in(b)) < 7e-16);
                const auto got = d.gas_particle(0).in(b);
                const drag::DragDerivatives<double> want = beta_d.in(b);
                CHECK(relative(got.value, correction * want.value) < 7e-16);
                // ∂β/∂φ = −∂β/∂ε for one class (again at φ, not at 1 − ε); the scale is the larger of
                // the two terms of the chain rule.
                const double scale = std::abs(want.d_voidage) + want.value / phi;
                CHECK(std::abs(got.d_fractions[0] + want.d_voidage) < (1e-13 + 4 * std::abs(correction - 1)) * scale);
                if (std::isinf(want.d_slip))
                  CHECK(got.d_slip == want.d_slip);
                else
                  // (a few ulp: with FMA contraction, -march=native, the chain rule's last bits move)
                  CHECK(std::abs(got.d_slip - correction * want.d_slip) <= 16 * machine_epsilon * std::abs(want.d_slip));
                CHECK(relative(d.gas_particle(0).force_slip_derivative(b),
                               correction * beta_d.force_slip_derivative(b)) < 1e-14);
              }
            }
        },
        any);
}

TEST_CASE("classes of one diameter and one slip add up to the monodisperse law at the same voidage") {
  for (double w : {0.0, 0.05, 1.2}) {
    const State s = make_state({{0.1, 90e-6, 2500, w}, {0.15, 90e-6, 1200, w}, {0.2, 90e-6, 3000, w}});
    const auto c = ClassClosures<>{}(s);
    const double eps = c.voidage();
    const auto mono = drag::MazzeiLettieri{}(drag::DragState<double>{eps, w, air, 90e-6});
    for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
      double sum = 0;
      for (std::size_t i = 0; i < 3; ++i) sum += c.gas_particle(i).in(b);
      CHECK(relative(sum, mono.in(b)) < 1e-14);
    }
    // Then, and only then, the per-class factor ε is the exact conversion between the conventions:
    // β_i,cl = β_i,pg + (φ_i/ε) Σ_j β_j,pg (∇p eliminated with the gas momentum balance).
    double sum_pg = 0;
    for (std::size_t i = 0; i < 3; ++i) sum_pg += c.gas_particle(i).pressure_gradient();
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(relative(c.gas_particle(i).classical(),
                     c.gas_particle(i).pressure_gradient() + s.volume_fractions[i] / eps * sum_pg) < 1e-14);
  }
  // With unequal diameters the per-class classical β_i is a different closure (documented).
  const State s = make_state({{0.2, 75e-6, 2500, 0.1}, {0.2, 300e-6, 2500, 0.1}});
  const auto c = ClassClosures<>{}(s);
  double sum_pg = 0;
  for (std::size_t i = 0; i < 2; ++i) sum_pg += c.gas_particle(i).pressure_gradient();
  CHECK(relative(c.gas_particle(0).classical(),
                 c.gas_particle(0).pressure_gradient() + 0.2 / c.voidage() * sum_pg) > 0.1);
}

TEST_CASE("the two buoyancy conventions: beta_pg = eps beta_cl class by class, derivatives converted exactly") {
  const State s = three_classes();
  const auto check_law = [&s](const auto& closures) {
    const auto c = closures(s);
    const auto d = closures.with_derivatives(s);
    const double eps = c.voidage();
    for (std::size_t i = 0; i < s.classes; ++i) {
      CHECK(relative(c.gas_particle(i).pressure_gradient(), eps * c.gas_particle(i).classical()) < 4e-16);
      const auto cl = d.gas_particle(i).classical();
      const auto pg = d.gas_particle(i).pressure_gradient();
      CHECK(relative(pg.d_slip, eps * cl.d_slip) < 4e-16);
      for (std::size_t m = 0; m < s.classes; ++m)  // ∂(ε β_cl)/∂φ_m = ε ∂β_cl/∂φ_m − β_cl
        CHECK(std::abs(pg.d_fractions[m] - (eps * cl.d_fractions[m] - cl.value)) <
              1e-15 * (std::abs(pg.d_fractions[m]) + cl.value));
      CHECK(d.gas_particle(i).coefficient().classical() == c.gas_particle(i).classical());
    }
  };
  check_law(ClassClosures<>{});                       // native classical
  check_law(ClassClosures<drag::Beetstra>{});         // native pressure gradient
  check_law(ClassClosures<drag::GidaspowSwitched>{});  // switched law
}

TEST_CASE("derivatives: against a dual-number evaluation of the formula and central finite differences") {
  const State s = three_classes();
  const ClassClosures<drag::MazzeiLettieri, kinetic_theory::ModifiedMansoori> closures{
      .radial_distribution = kinetic_theory::ModifiedMansoori{0.64}};
  const auto d = closures.with_derivatives(s);
  const auto c = closures(s);
  const std::size_t nu = s.classes;

  // β_i,cl = φ_i β_ML,cl(ε, w_i)/(1 − ε), ε = 1 − Σ φ, all in dual numbers of (φ_0 … φ_3, w_i).
  using D = Dual<double, int(N) + 1>;
  for (std::size_t i = 0; i < nu; ++i) {
    std::array<D, N> phi{};
    D eps(1.0);
    for (std::size_t m = 0; m < nu; ++m) {
      phi[m] = D::variable(s.volume_fractions[m], int(m));
      eps = eps - phi[m];
    }
    const D w = D::variable(c.slip(i), int(N));
    const D beta = phi[i] * drag::MazzeiLettieri{}.native_beta(eps, w, air, s.diameters[i]) / (1 - eps);
    const auto got = d.gas_particle(i).classical();
    CHECK(relative(got.value, beta.value) < 1e-14);
    CHECK(relative(got.d_slip, beta.derivative[N]) < 1e-12);
    for (std::size_t m = 0; m < nu; ++m)
      CHECK(std::abs(got.d_fractions[m] - beta.derivative[m]) < 1e-12 * (std::abs(beta.derivative[m]) + beta.value));
  }

  // Finite differences in φ_m (other fractions and every velocity fixed).
  const double h = 1e-7;
  for (std::size_t m = 0; m < nu; ++m) {
    State up = s, down = s;
    up.volume_fractions[m] += h;
    down.volume_fractions[m] -= h;
    const auto cu = closures(up), cd = closures(down);
    for (std::size_t i = 0; i < nu; ++i) {
      for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
        const double fd = (cu.gas_particle(i).in(b) - cd.gas_particle(i).in(b)) / (2 * h);
        const double scale = c.gas_particle(i).in(b) / s.volume_fractions[i];
        INFO("d beta_" << i << "/d phi_" << m);
        CHECK(std::abs(d.gas_particle(i).in(b).d_fractions[m] - fd) < 1e-6 * scale);
      }
      for (std::size_t k = 0; k < nu; ++k) {
        if (k == i) continue;
        const double fd = (cu.solid_solid(i, k) - cd.solid_solid(i, k)) / (2 * h);
        INFO("d zeta_" << i << k << "/d phi_" << m);
        CHECK(std::abs(d.solid_solid(i, k).d_fractions[m] - fd) < 1e-6 * c.solid_solid(i, k) / 0.09);
      }
    }
  }
  // Finite differences in the slip w_i (v_i moved along u − v_i) and in |v_k − v_i| (v_k moved along v_k − v_i).
  for (std::size_t i = 0; i < nu; ++i) {
    const double w = c.slip(i);
    State up = s, down = s;
    for (int a = 0; a < 3; ++a) {
      const double direction = (s.fluid_velocity[a] - s.velocities[i][a]) / w;
      up.velocities[i][a] -= h * direction;
      down.velocities[i][a] += h * direction;
    }
    for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
      const double fd = (closures(up).gas_particle(i).in(b) - closures(down).gas_particle(i).in(b)) / (2 * h);
      CHECK(relative(d.gas_particle(i).in(b).d_slip, fd) < 1e-6);
    }
    for (std::size_t k = i + 1; k < nu; ++k) {
      const double speed = c.relative_speed(i, k);
      State ku = s, kd = s;
      for (int a = 0; a < 3; ++a) {
        const double direction = (s.velocities[k][a] - s.velocities[i][a]) / speed;
        ku.velocities[k][a] += h * direction;
        kd.velocities[k][a] -= h * direction;
      }
      const double fd = (closures(ku).solid_solid(i, k) - closures(kd).solid_solid(i, k)) / (2 * h);
      CHECK(relative(d.solid_solid(i, k).d_relative_speed, fd) < 1e-6);
      CHECK(d.solid_solid(k, i).d_relative_speed == d.solid_solid(i, k).d_relative_speed);
    }
  }
  // The values of with_derivatives are those of the hot path (ζ through dual numbers: to a few ulp
  // where FMA contraction, -march=native, rounds the two paths differently).
  const auto values = d.coefficients();
  for (std::size_t i = 0; i < nu; ++i) {
    CHECK(values.gas_particle(i).classical() == c.gas_particle(i).classical());
    for (std::size_t k = 0; k < nu; ++k)
      CHECK(std::abs(values.solid_solid(i, k) - c.solid_solid(i, k)) <= 4 * machine_epsilon * c.solid_solid(i, k));
  }
}

TEST_CASE("zero slip, zero relative speed, empty classes and the empty cell give finite values, never NaN") {
  const ClassClosures<> closures{};
  const auto all_finite = [](const auto& d, std::size_t nu) {
    for (std::size_t i = 0; i < nu; ++i) {
      for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
        const auto g = d.gas_particle(i).in(b);
        CHECK(std::isfinite(g.value));
        CHECK(!std::isnan(g.d_slip));
        CHECK(std::isfinite(d.gas_particle(i).force_slip_derivative(b)));
        for (std::size_t m = 0; m < nu; ++m) CHECK(std::isfinite(g.d_fractions[m]));
      }
      for (std::size_t k = 0; k < nu; ++k) {
        CHECK(std::isfinite(d.solid_solid(i, k).value));
        CHECK(std::isfinite(d.solid_solid(i, k).d_relative_speed));
        for (std::size_t m = 0; m < nu; ++m) CHECK(std::isfinite(d.solid_solid(i, k).d_fractions[m]));
      }
    }
  };

  SUBCASE("every class moving with the gas") {
    const State s = make_state({{0.2, 75e-6, 2500, 0.0}, {0.25, 150e-6, 2500, 0.0}, {0.0, 300e-6, 2500, 0.0}});
    const auto d = closures.checked_with_derivatives(s);
    all_finite(d, 3);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto b = d.gas_particle(i).classical();
      CHECK(b.value > 0);
      CHECK(b.d_slip == std::numeric_limits<double>::infinity());  // √Re in Dallavalle's C_D: the true slope
      CHECK(d.gas_particle(i).force_slip_derivative(Buoyancy::classical) == b.value);
      // The Stokes limit of Mazzei–Lettieri per class: B_i → 17.28 μ_f/(ξ_i² ε^3.8).
      const double eps = d.voidage();
      CHECK(relative(b.value, 17.28 * air.viscosity * s.volume_fractions[i] /
                                  (s.diameters[i] * s.diameters[i] * std::pow(eps, 3.8))) < 1e-14);
    }
    CHECK(d.solid_solid(0, 1).value == 0);
    CHECK(d.solid_solid(0, 1).d_relative_speed > 0);
  }
  SUBCASE("a class with phi_i = 0 has zero coefficients and the derivative of its own beta is B_i") {
    const State s = make_state({{0.2, 75e-6, 2500, 0.1}, {0.0, 75e-6, 2500, 0.1}, {0.1, 200e-6, 2000, 0.0}});
    const auto d = closures.checked_with_derivatives(s);
    all_finite(d, 3);
    const auto b = d.gas_particle(1).classical();
    CHECK(b.value == 0);
    CHECK(b.d_slip == 0);
    CHECK(b.d_fractions[0] == 0);
    // Class 0 has class 1's diameter and slip: B_1 = β_0/φ_0.
    CHECK(relative(b.d_fractions[1], d.gas_particle(0).classical().value / 0.2) < 1e-15);
    CHECK(d.solid_solid(0, 1).value == 0);
    CHECK(d.solid_solid(1, 2).value == 0);
    CHECK(d.solid_solid(1, 2).d_fractions[1] > 0);  // |v_2 − v_1| = 0.1
    CHECK(d.solid_solid(0, 1).d_fractions[1] == 0);  // v_0 = v_1
    // Also at zero slip (0·∞ in ∂β/∂w is 0).
    const State z = make_state({{0.2, 75e-6, 2500, 0.0}, {0.0, 75e-6, 2500, 0.0}});
    const auto dz = closures.with_derivatives(z);
    all_finite(dz, 2);
    CHECK(dz.gas_particle(1).classical().d_slip == 0);
  }
  SUBCASE("the empty cell: eps = 1") {
    const State s = make_state({{0.0, 75e-6, 2500, 0.3}, {0.0, 150e-6, 2500, 0.1}});
    const auto d = closures.checked_with_derivatives(s);
    CHECK(d.voidage() == 1);
    all_finite(d, 2);
    const double slips[] = {0.3, 0.1};
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(d.gas_particle(i).classical().value == 0);
      CHECK(d.gas_particle(i).pressure_gradient().value == 0);
      // ∂β_i/∂φ_i = B_i(ε → 1): the dilute limit of β_i/φ_i.
      const State dilute = make_state({{1e-9, s.diameters[i], 2500, slips[i]}});
      const double limit = closures(dilute).gas_particle(0).classical() / 1e-9;
      CHECK(relative(d.gas_particle(i).classical().d_fractions[i], limit) < 1e-8);
    }
  }
}

TEST_CASE("symmetry: zeta_ik = zeta_ki, and relabelling the classes relabels every coefficient") {
  const ClassClosures<drag::MazzeiLettieri, kinetic_theory::Mansoori> closures{};
  const State s = three_classes();
  const std::size_t order[] = {2, 0, 1};  // class j of the relabelled state is class order[j] of s
  State t = s;
  for (std::size_t j = 0; j < 3; ++j) {
    t.volume_fractions[j] = s.volume_fractions[order[j]];
    t.diameters[j] = s.diameters[order[j]];
    t.densities[j] = s.densities[order[j]];
    t.velocities[j] = s.velocities[order[j]];
  }
  const auto c = closures.with_derivatives(s), r = closures.with_derivatives(t);
  for (std::size_t j = 0; j < 3; ++j) {
    const auto a = r.gas_particle(j).classical(), b = c.gas_particle(order[j]).classical();
    CHECK(relative(a.value, b.value) < 1e-15);
    CHECK(relative(a.d_slip, b.d_slip) < 1e-15);
    for (std::size_t m = 0; m < 3; ++m)
      CHECK(std::abs(a.d_fractions[m] - b.d_fractions[order[m]]) <
            1e-14 * (std::abs(b.d_fractions[order[m]]) + b.value));
    for (std::size_t l = 0; l < 3; ++l) {
      CHECK(c.solid_solid(j, l).value == c.solid_solid(l, j).value);
      CHECK(c.solid_solid(j, l).d_fractions == c.solid_solid(l, j).d_fractions);
      const auto x = r.solid_solid(j, l), y = c.solid_solid(order[j], order[l]);
      CHECK(relative(x.value, y.value) < 1e-14);
      CHECK(relative(x.d_relative_speed, y.d_relative_speed) < 1e-14);
      for (std::size_t m = 0; m < 3; ++m)
        CHECK(std::abs(x.d_fractions[m] - y.d_fractions[order[m]]) <= 1e-14 * std::abs(y.d_fractions[order[m]]));
    }
  }
}

namespace {

// The worked examples in T: β_1 of the drag example and ζ_12 of the binary layer.
template <class T>
std::array<T, 2> worked_examples() {
  const Fluid<T> gas{FLUIDBED_DECIMAL(T, 1.16), FLUIDBED_DECIMAL(T, 1.75e-5)};
  MultiFluidState<T, 3> s{};
  s.classes = 2;
  s.fluid = gas;
  s.volume_fractions = {FLUIDBED_DECIMAL(T, 0.262), FLUIDBED_DECIMAL(T, 0.138), T(0)};
  s.diameters = {FLUIDBED_DECIMAL(T, 75e-6), FLUIDBED_DECIMAL(T, 103e-6), T(1)};
  s.densities = {T(2500), T(2500), T(1)};
  s.velocities[0] = {T(0), T(0), -FLUIDBED_DECIMAL(T, 0.15)};
  s.velocities[1] = {T(0), T(0), T(0)};
  const T beta = ClassClosures<>{}(s).gas_particle(0).pressure_gradient();
  s.volume_fractions[1] = FLUIDBED_DECIMAL(T, 0.338);
  s.velocities[0] = {T(0), T(0), T(0)};
  s.velocities[1] = {FLUIDBED_DECIMAL(T, 0.01), T(0), T(0)};
  const auto d = ClassClosures<>{}.with_derivatives(s);
  CHECK(fluidbed::test::same_arithmetic(d.solid_solid(0, 1).value, ClassClosures<>{}(s).solid_solid(0, 1)));
  return {beta, d.solid_solid(0, 1).value};
}

}  // namespace

TEST_CASE("float, double and long double: the worked examples to the accuracy of the type") {
  // mpmath, 40 digits.
  const long double beta = 62514.28859700258739L, zeta = 612894.5109648633740L;
  const auto f = worked_examples<float>();
  const auto d = worked_examples<double>();
  const auto l = worked_examples<long double>();
  static_assert(std::is_same_v<decltype(f), const std::array<float, 2>>);
  // A few ulp of each type (measured: float 7.0e-8 and 1.2e-7, double 2.6e-16 and 5.3e-16).
  CHECK(std::abs(f[0] - beta) / beta < 4 * std::numeric_limits<float>::epsilon());
  CHECK(std::abs(f[1] - zeta) / zeta < 4 * std::numeric_limits<float>::epsilon());
  CHECK(std::abs(d[0] - beta) / beta < 8 * std::numeric_limits<double>::epsilon());
  CHECK(std::abs(d[1] - zeta) / zeta < 8 * std::numeric_limits<double>::epsilon());
  // β: a few ulp of long double (measured 4.0e-19, 7 ulp). ζ: to the precision of the run-time
  // parameters e = 0.97 and C_f = 0.15, double members as every law's parameters (measured
  // 1.7e-17; (1 + e) alone carries up to 2.8e-17).
  const long double precision = std::numeric_limits<long double>::epsilon();
  CHECK(std::abs(l[0] - beta) / beta < 32 * precision);
  CHECK(std::abs(l[1] - zeta) / zeta < 6e-17L);
}

TEST_CASE("checked entry points: std::domain_error naming the argument and its value") {
  const ClassClosures<> closures{};
  const State good = three_classes();
  CHECK(closures.checked(good).gas_particle(1).classical() == closures(good).gas_particle(1).classical());
  CHECK(closures.checked_with_derivatives(good).solid_solid(0, 2).value == closures(good).solid_solid(0, 2));

  const auto message = [](const auto& closures_, const State& s) -> std::string {
    try {
      closures_.checked(s);
    } catch (const std::domain_error& e) {
      std::string text = e.what();
      try {
        closures_.checked_with_derivatives(s);
      } catch (const std::domain_error& e2) {
        CHECK(std::string(e2.what()) == text);
        return text;
      }
      FAIL("checked_with_derivatives did not throw: " << text);
    }
    FAIL("checked did not throw");
    return "";
  };
  const auto expect = [&](const auto& closures_, const State& s, const std::string& argument,
                          const std::string& value) {
    const std::string text = message(closures_, s);
    INFO(text);
    CHECK(text.find("fluidbed::polydisperse::ClassClosures: argument '" + argument + "' = " + value) == 0);
  };
  State s = good;
  s.classes = 0;
  expect(closures, s, "classes", "0");
  s.classes = N + 1;
  expect(closures, s, "classes", "5");
  s = good;
  s.volume_fractions[1] = -0.5;
  expect(closures, s, "volume_fractions[1]", "-0.5");
  s = good;
  s.volume_fractions[2] = std::numeric_limits<double>::quiet_NaN();
  expect(closures, s, "volume_fractions[2]", "nan");
  s = good;
  s.volume_fractions = {0.5, 0.3, 0.2, 0.0};
  expect(closures, s, "sum of volume_fractions", "1");
  s = good;
  s.diameters[0] = 0;
  expect(closures, s, "diameters[0]", "0");
  s = good;
  s.densities[2] = -2500;
  expect(closures, s, "densities[2]", "-2500");
  s = good;
  s.velocities[1][2] = std::numeric_limits<double>::infinity();
  expect(closures, s, "velocities[1][2]", "inf");
  s = good;
  s.fluid_velocity[0] = std::numeric_limits<double>::quiet_NaN();
  expect(closures, s, "fluid_velocity[0]", "nan");
  s = good;
  s.fluid.viscosity = 0;
  expect(closures, s, "fluid.viscosity", "0");
  s = good;
  s.fluid.density = -1;
  expect(closures, s, "fluid.density", "-1");

  expect(ClassClosures<>{.restitution = 1.5}, good, "restitution", "1.5");
  expect(ClassClosures<>{.solid_solid_drag = kinetic_theory::SyamlalSolidSolidDrag{-0.1}}, good,
         "friction_coefficient", "-0.10000000000000001");
  expect(ClassClosures<drag::MazzeiLettieri, kinetic_theory::ModifiedMansoori>{
             .radial_distribution = kinetic_theory::ModifiedMansoori{1.2}},
         good, "max_packing", "1.2");

  // Classes beyond ν are not read.
  s = good;
  s.volume_fractions[3] = -7;
  s.diameters[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK(closures.checked(s).classes() == 3);
}
