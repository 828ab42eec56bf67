// Elastic modulus and elastic force (seed 000 §3.5), the other interaction forces (§3.3,
// interaction/) and the family's calling shape (ElasticModulus, ElasticModuli).
// References: the independent mpmath generator tests/reference/stability_reference.py
// (elastic_functions_reference.csv, elastic_state_reference.csv), an E_r^e/E_j table from an
// independent double-precision evaluation of eqs. 3.95 and 3.111 made when the thesis was read,
// exact limits (eq. 3.112, 4.38) and exact identities (eqs. 3.9, 3.13–3.14, 3.20).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

#include "fluidbed/core/dual.hpp"
#include "fluidbed/drag/mazzei_lettieri.hpp"
#include "fluidbed/elastic.hpp"
#include "fluidbed/interaction.hpp"
#include "reference_table.hpp"
#include "same_arithmetic.hpp"
#include "test_out_of_domain.hpp"

using namespace fluidbed;
using namespace fluidbed::elastic;
using namespace fluidbed::interaction;

namespace {

constexpr double g = 9.81;
const Fluid<double> air{.density = 1.205, .viscosity = 1.81e-5};
const Particles<double> fcc{.density = 1210.0, .diameter = 137e-6};  // Table 4.5 powder 1

double relative_difference(double a, double b) { return std::abs(a - b) / std::abs(b); }

// FCC in air at equilibrium at this voidage and terminal Reynolds number.
EquilibriumState<double> fcc_at(double voidage, double terminal_reynolds = 4.0) {
  return {voidage, air, fcc, terminal_reynolds, g};
}

// The state (ε, w) of FCC particles in a fluid.
drag::DragState<double> state_of(double voidage, double slip, const Fluid<double>& fluid = air,
                                 double diameter = fcc.diameter) {
  return {voidage, slip, fluid, diameter};
}

// F̂ = π d³/(6(1 − ε)) β w, the drag on one particle (eq. 3.114), from the library's drag.
template <class S>
S drag_per_particle(const S& voidage, const S& slip, const Fluid<double>& fluid, double diameter) {
  const double pi = 3.14159265358979323846;
  return pi * diameter * diameter * diameter / 6.0 * drag::MazzeiLettieri{}.native_beta(voidage, slip, fluid, diameter) *
         slip / (1.0 - voidage);
}

// A user's own model: half of Jean–Fan's modulus.
struct HalfJeanFan : ElasticModulus<HalfJeanFan> {
  constexpr std::string_view name() const { return "HalfJeanFan"; }
  constexpr std::string_view reference() const { return "test"; }
  constexpr Validity<0> validity() const { return {}; }  // no stated range
  template <class S>
  S sensitivity(const S& voidage, const S& re_star) const {
    return JeanFanModulus{}.sensitivity(voidage, re_star) / 2;
  }
  template <class S, class T>
  S modulus_at_equilibrium(const S& voidage, const EquilibriumState<T>& s) const {
    return JeanFanModulus{}.modulus_at_equilibrium(voidage, s) / 2;
  }
};

}  // namespace

// ============================================================================ Table 3.1 functions

TEST_CASE("the functions n_e, N, C, D, H of Table 3.1 agree with the mpmath reference") {
  const test::ReferenceTable table("elastic_functions_reference.csv");
  REQUIRE(table.size() == 99);
  double worst = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const double voidage = table.number(row, "voidage"), re_star = table.number(row, "re_star");
    INFO("voidage " << voidage << ", Re* " << re_star);
    const auto f = mazzei_lettieri_functions(voidage, re_star);
    for (const auto& entry : {std::pair{"n_e", f.exponent}, std::pair{"N", f.exponent_slope},
                              std::pair{"C", f.reynolds_factor}, std::pair{"D", f.drag_factor},
                              std::pair{"H", f.voidage_sensitivity}}) {
      // named copies, not a structured binding: clang before 16 cannot capture one (INFO does)
      const char* column = entry.first;
      const double value = entry.second;
      INFO(column);
      const double expected = table.number(row, column);
      const double error = expected == 0 ? std::abs(value) : relative_difference(value, expected);
      CHECK(error < 2e-14);
      worst = std::max(worst, error);
    }
  }
  MESSAGE("worst relative error of the Table 3.1 functions: " << worst);
}

TEST_CASE("H is finite at Re* = 0 and equals the Jean-Fan -4.8/eps there and at both limits (eq. 4.38)") {
  for (const double voidage : {0.36, 0.5, 0.9, 1.0}) {
    CHECK(mazzei_lettieri_functions(voidage, 0.0).voidage_sensitivity == doctest::Approx(-4.8 / voidage).epsilon(1e-15));
    CHECK(std::isinf(mazzei_lettieri_functions(voidage, 0.0).exponent_slope));
    CHECK(relative_difference(mazzei_lettieri_functions(voidage, 1e-12).voidage_sensitivity, -4.8 / voidage) < 1e-6);
    CHECK(relative_difference(mazzei_lettieri_functions(voidage, 1e16).voidage_sensitivity, -4.8 / voidage) < 1e-3);
    CHECK(voidage_sensitivity(JeanFanModulus{}, voidage, 100.0) == -4.8 / voidage);
  }
}

TEST_CASE("E_r^e over E_j: an independently evaluated table and the limits of eq. 3.112") {
  // E_r^e/E_j = H/(−4.8/ε) at ε = 0.5 and 0.9 (eqs. 3.95, 3.111), from an independent
  // double-precision evaluation made when the thesis was read, to its 5 printed digits.
  const double re[] = {1e-10, 1e-3, 1, 10, 100, 1e4, 1e12};
  const double at_half[] = {1.00000, 1.00241, 0.89187, 0.74135, 0.77793, 0.96329, 1.00000};
  const double at_nine_tenths[] = {1.00000, 1.00345, 1.00867, 0.92855, 0.88206, 0.96904, 1.00000};
  for (int i = 0; i < 7; ++i) {
    INFO("Re_t = " << re[i]);
    for (const auto& [voidage, expected] : {std::pair{0.5, at_half[i]}, std::pair{0.9, at_nine_tenths[i]}}) {
      const double ratio = MazzeiLettieriModulus{}(fcc_at(voidage, re[i])) / JeanFanModulus{}(fcc_at(voidage));
      CHECK(std::abs(ratio - expected) <= 0.5e-5);
    }
  }
}

// ============================================================================ moduli

TEST_CASE("the equilibrium moduli: eqs. 3.75 and 3.95 and their relation E_j = E_f / eps") {
  const double weight = (fcc.density - air.density) * g * fcc.diameter;
  for (const double voidage : {0.4, 0.6, 0.9, 1.0}) {
    const double e_f = FoscoloGibilaroModulus{}(fcc_at(voidage));
    CHECK(e_f == doctest::Approx(3.2 * (1 - voidage) * weight).epsilon(1e-15));
    CHECK(JeanFanModulus{}(fcc_at(voidage)) == doctest::Approx(e_f / voidage).epsilon(1e-15));
  }
  CHECK(FoscoloGibilaroModulus{}(fcc_at(1.0)) == 0.0);
  CHECK(JeanFanModulus{}(fcc_at(1.0)) == 0.0);
  CHECK(MazzeiLettieriModulus{}(fcc_at(1.0)) == 0.0);
}

TEST_CASE("Mazzei-Lettieri modulus off equilibrium agrees with the mpmath reference, and dF/deps = H F") {
  const test::ReferenceTable table("elastic_state_reference.csv");
  REQUIRE(table.size() == 75);
  double worst_modulus = 0, worst_derivative = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const Fluid<double> fluid{table.number(row, "fluid_density"), table.number(row, "fluid_viscosity")};
    const double d = table.number(row, "diameter");
    const double voidage = table.number(row, "voidage"), slip = table.number(row, "slip");
    INFO("row " << row << ": voidage " << voidage << ", Re " << table.number(row, "reynolds"));
    CHECK(relative_difference(effective_reynolds(voidage, slip, fluid, d), table.number(row, "re_star")) < 1e-13);
    CHECK(relative_difference(mazzei_lettieri_sensitivity(voidage, slip, fluid, d), table.number(row, "H")) < 1e-13);
    const double modulus = MazzeiLettieriModulus{}(state_of(voidage, slip, fluid, d));
    const double force = drag_per_particle(voidage, slip, fluid, d);
    CHECK(relative_difference(force, table.number(row, "drag_per_particle")) < 1e-13);
    worst_modulus = std::max(worst_modulus, relative_difference(modulus, table.number(row, "modulus")));
    CHECK(relative_difference(modulus, table.number(row, "modulus")) < 1e-13);
    // eq. 3.108 against the oracle's independent numerical derivative at fixed superficial slip
    const double h_times_f = mazzei_lettieri_sensitivity(voidage, slip, fluid, d) * force;
    worst_derivative = std::max(worst_derivative, relative_difference(h_times_f, table.number(row, "dF_dvoidage")));
    CHECK(relative_difference(h_times_f, table.number(row, "dF_dvoidage")) < 1e-12);
  }
  MESSAGE("worst relative error: modulus " << worst_modulus << ", H F against dF/deps " << worst_derivative);
}

TEST_CASE("dF/deps = H F against a double-precision central difference of the library's drag at fixed u_s - v") {
  for (const double voidage : {0.42, 0.6, 0.85}) {
    for (const double superficial_slip : {1e-4, 1e-2, 0.5}) {
      INFO("voidage " << voidage << ", superficial slip " << superficial_slip);
      const auto force_at = [&](double e) { return drag_per_particle(e, superficial_slip / e, air, fcc.diameter); };
      const double step = 1e-5;
      const double difference = (force_at(voidage + step) - force_at(voidage - step)) / (2 * step);
      const double h = mazzei_lettieri_sensitivity(voidage, superficial_slip / voidage, air, fcc.diameter);
      CHECK(relative_difference(h * force_at(voidage), difference) < 1e-7);
      // and the exact derivative through the dual numbers
      using D = Dual<double, 1>;
      const D e = D::variable(voidage, 0);
      const D f = drag_per_particle(e, D(superficial_slip) / e, air, fcc.diameter);
      CHECK(relative_difference(h * f.value, f.derivative[0]) < 1e-12);
    }
  }
}

TEST_CASE("with_derivatives: the moduli's derivatives through dual numbers match central differences") {
  const double step = 1e-6;
  for (const double voidage : {0.4, 0.55, 0.8, 0.95}) {
    INFO("voidage " << voidage);
    const auto check = [&](const auto& model, auto state_at) {
      INFO(model.name());
      const auto exact = model.with_derivatives(state_at(voidage));
      const double difference = (model(state_at(voidage + step)) - model(state_at(voidage - step))) / (2 * step);
      CHECK(relative_difference(exact.d_voidage, difference) < 1e-7);
      CHECK(test::same_arithmetic(exact.value, model(state_at(voidage))));
      // the checked form returns the same
      const auto checked = model.checked_with_derivatives(state_at(voidage));
      CHECK((checked.value == exact.value && checked.d_voidage == exact.d_voidage));
    };
    const auto at_equilibrium = [](double e) { return fcc_at(e, 4.06); };
    check(FoscoloGibilaroModulus{}, at_equilibrium);
    check(JeanFanModulus{}, at_equilibrium);
    check(MazzeiLettieriModulus{}, at_equilibrium);
    check(MazzeiLettieriModulus{}, [](double e) { return state_of(e, 0.05); });
    // the old derivative: one dual number through the kernel
    const Dual<double, 1> dual = MazzeiLettieriModulus{}.modulus_at_equilibrium(Dual<double, 1>::variable(voidage, 0),
                                                                                fcc_at(voidage, 4.06));
    CHECK(MazzeiLettieriModulus{}.with_derivatives(fcc_at(voidage, 4.06)).d_voidage == dual.derivative[0]);
  }
  // and in the slip, off equilibrium
  const ModulusWithDerivatives<double> e_r = MazzeiLettieriModulus{}.with_derivatives(state_of(0.6, 0.05));
  const double difference = (MazzeiLettieriModulus{}(state_of(0.6, 0.05 + 1e-8)) -
                             MazzeiLettieriModulus{}(state_of(0.6, 0.05 - 1e-8))) /
                            2e-8;
  CHECK(relative_difference(e_r.d_slip, difference) < 1e-6);
  CHECK(MazzeiLettieriModulus{}.checked_with_derivatives(state_of(0.6, 0.05)).d_slip == e_r.d_slip);
}

TEST_CASE("Mazzei-Lettieri modulus: zero at zero slip and at eps = 1, never NaN") {
  CHECK(MazzeiLettieriModulus{}(state_of(0.6, 0.0)) == 0.0);
  CHECK(MazzeiLettieriModulus{}(state_of(1.0, 0.3)) == 0.0);
  for (const double voidage : {1e-3, 0.3, 0.999999})
    for (const double slip : {0.0, 1e-12, 1.0, 1e3}) {
      const double e = MazzeiLettieriModulus{}(state_of(voidage, slip));
      CHECK(std::isfinite(e));
      CHECK(e >= 0.0);
    }
}

TEST_CASE("the checked equilibrium modulus names the argument and the value") {
  const std::string bad_voidage = test::domain_error_message([] { JeanFanModulus{}.checked(fcc_at(1.5)); });
  CHECK(bad_voidage.find("JeanFanModulus") != std::string::npos);
  CHECK(bad_voidage.find("voidage") != std::string::npos);
  CHECK(bad_voidage.find("1.5") != std::string::npos);
  CHECK_THROWS_AS(FoscoloGibilaroModulus{}.checked(fcc_at(0.0)), std::domain_error);
  CHECK_THROWS_AS(MazzeiLettieriModulus{}.checked(fcc_at(std::nan(""))), std::domain_error);
  CHECK_THROWS_AS(MazzeiLettieriModulus{}.checked(fcc_at(0.5, -1.0)), std::domain_error);
  CHECK_THROWS_AS(JeanFanModulus{}.checked(EquilibriumState<double>{0.5, air, Particles<double>{1210.0, -1e-4}, 4.0}),
                  std::domain_error);
  CHECK(MazzeiLettieriModulus{}.checked(fcc_at(0.5)) == MazzeiLettieriModulus{}(fcc_at(0.5)));
}

// ============================================================================ the family's shape

TEST_CASE("ElasticModuli: unique names, lookup by name, unknown names listed, extension") {
  static_assert(ElasticModuli::names_are_unique());
  static_assert(ElasticModuli::size == 3);
  for (const AnyElasticModulus& model : ElasticModuli::all()) {
    const std::string_view name = ElasticModuli::name_of(model);
    INFO(name);
    REQUIRE(ElasticModuli::find(name).has_value());
    CHECK(ElasticModuli::make(name).index() == model.index());
    std::visit(
        [](const auto& m) {
          CHECK_FALSE(m.reference().empty());
          CHECK(m.validity()[0].quantity == "voidage");
          // every model through the variant equals the model itself
          CHECK(equilibrium_modulus(ElasticModuli::Variant{m}, homogeneous_suspension(air, fcc, g), 0.5) ==
                m(EquilibriumState<double>{0.5, air, fcc, homogeneous_suspension(air, fcc, g).terminal_reynolds, g}));
        },
        model);
  }
  // the elastic Mazzei–Lettieri name differs from the drag law's
  CHECK(ElasticModuli::name_of(MazzeiLettieriModulus{}) != drag::MazzeiLettieri{}.name());
  CHECK_FALSE(ElasticModuli::find("MazzeiLettieri").has_value());
  const std::string unknown = [] {
    try {
      ElasticModuli::make("Bogus");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  CHECK(unknown.find("'Bogus'") != std::string::npos);
  for (const char* known : {"FoscoloGibilaroModulus", "JeanFanModulus", "MazzeiLettieriModulus"})
    CHECK(unknown.find(known) != std::string::npos);
  // a user's own model beside the library's (HalfJeanFan above)
  using Extended = ElasticModuli::with<HalfJeanFan>;
  static_assert(Extended::names_are_unique());
  const auto half = Extended::make("HalfJeanFan");
  CHECK(std::visit([](const auto& m) { return m(fcc_at(0.5)); }, half) == JeanFanModulus{}(fcc_at(0.5)) / 2);
  CHECK(HalfJeanFan{}.with_derivatives(fcc_at(0.5)).d_voidage ==
        JeanFanModulus{}.with_derivatives(fcc_at(0.5)).d_voidage / 2);
}

TEST_CASE("the functions of a state take the error policy: same value, checked throws naming the argument") {
  const double e = 0.6, w = 0.05;
  CHECK(effective_reynolds(e, w, air, fcc.diameter, fluidbed::checked) == effective_reynolds(e, w, air, fcc.diameter));
  CHECK(mazzei_lettieri_sensitivity(e, w, air, fcc.diameter, fluidbed::checked) ==
        mazzei_lettieri_sensitivity(e, w, air, fcc.diameter));
  CHECK(mazzei_lettieri_drag_and_sensitivity(e, w, air, fcc.diameter, fluidbed::checked).beta ==
        mazzei_lettieri_drag_and_sensitivity(e, w, air, fcc.diameter).beta);
  CHECK(mazzei_lettieri_functions(e, 4.0, fluidbed::checked).voidage_sensitivity ==
        mazzei_lettieri_functions(e, 4.0).voidage_sensitivity);
  CHECK_THROWS_WITH_AS(effective_reynolds(e, -1.0, air, fcc.diameter, fluidbed::checked),
                       doctest::Contains("fluidbed::effective_reynolds: argument 'slip' = -1"), std::domain_error);
  CHECK_THROWS_WITH_AS(MazzeiLettieriModulus{}.checked(state_of(2.0, w)),
                       doctest::Contains("fluidbed::MazzeiLettieriModulus: argument 'voidage' = 2"),
                       std::domain_error);
}

// ============================================================================ elastic force

TEST_CASE("3-D elastic force: along the drag, E dEps/dx in 1-D, zero without drag or across it") {
  const double voidage = 0.6, slip = 0.08, d = fcc.diameter;
  const double beta = drag::MazzeiLettieri{}.native_beta(voidage, slip, air, d);
  const double h = mazzei_lettieri_sensitivity(voidage, slip, air, d);
  const double modulus = MazzeiLettieriModulus{}(state_of(voidage, slip, air, d));
  const Vector3<double> up{0, 0, 1};
  const Vector3<double> drag_up{0, 0, beta * slip};
  const Vector3<double> gradient{3.0, -2.0, 5.0};  // m⁻¹
  // 1-D: drag upward, n f_e = E_r ∂ε/∂z e (eqs. 3.113 and 3.74 coincide)
  const Vector3<double> f = elastic_force(drag_up, gradient, h, d);
  CHECK(f[0] == 0.0);
  CHECK(f[1] == 0.0);
  CHECK(relative_difference(f[2], modulus * gradient[2]) < 1e-14);
  const Vector3<double> vertical = elastic_force_vertical(modulus, gradient, up);
  CHECK(relative_difference(vertical[2], f[2]) < 1e-14);
  CHECK(f[2] > 0.0);  // H < 0: voidage rising along the drag increases it
  // No drag, no force (and no 0/0)
  const Vector3<double> none = elastic_force(Vector3<double>{0, 0, 0}, gradient, h, d);
  CHECK((none[0] == 0.0 && none[1] == 0.0 && none[2] == 0.0));
  // A gradient across the drag gives nothing (eq. 3.116), unlike the vertical form of eq. 3.74
  const Vector3<double> sideways_drag{beta * slip, 0, 0};
  const Vector3<double> across = elastic_force(sideways_drag, Vector3<double>{0, 0, 5.0}, h, d);
  CHECK((across[0] == 0.0 && across[1] == 0.0 && across[2] == 0.0));
  CHECK(elastic_force_vertical(modulus, Vector3<double>{0, 0, 5.0}, up)[2] > 0.0);
  // Rotating the frame rotates the force: the force is parallel to the drag with magnitude
  // |(2/3) d H (∇ε·n_d)| |f_d|.
  const Vector3<double> oblique{1.0, 2.0, -2.0};  // |·| = 3
  const Vector3<double> f_oblique = elastic_force(scaled(beta * slip / 3.0, oblique), gradient, h, d);
  const double along = dot(gradient, oblique) / 3.0;
  for (int i = 0; i < 3; ++i)
    CHECK(relative_difference(f_oblique[i], -2.0 / 3.0 * d * h * along * beta * slip * oblique[i] / 3.0) < 1e-14);
}

// ============================================================================ interaction forces

TEST_CASE("buoyancy and local fluid acceleration cancel under a uniform acceleration g (eqs. 3.13-3.14)") {
  const Vector3<double> gravity{0.3, -0.1, -9.81};
  const Vector3<double> b = classical_buoyancy(0.4, 998.0, gravity);
  const Vector3<double> a = local_fluid_acceleration_force(0.4, 998.0, gravity);
  for (int i = 0; i < 3; ++i) CHECK(b[i] + a[i] == 0.0);
  CHECK(b[2] == doctest::Approx(0.4 * 998.0 * 9.81).epsilon(1e-15));  // upward
}

TEST_CASE("the three buoyancies coincide in a homogeneous suspension at equilibrium (eqs. 3.7-3.10, 3.20)") {
  const double phi = 0.45, rho_f = 998.0, rho_p = 2500.0;
  const Vector3<double> gravity{0, 0, -9.81};
  // ∇p = (ε ρ_f + φ ρ_p) g (eq. 3.9); in a homogeneous suspension ∇·S_f = −∇p
  const double mixture = (1 - phi) * rho_f + phi * rho_p;
  const Vector3<double> grad_p = scaled(mixture, gravity);
  const Vector3<double> pressure = pressure_gradient_buoyancy(phi, grad_p);
  const Vector3<double> stress = stress_buoyancy(phi, scaled(-1.0, grad_p));
  const Vector3<double> homogeneous = homogeneous_buoyancy(phi, rho_f, rho_p, gravity);
  for (int i = 0; i < 3; ++i) {
    CHECK(pressure[i] == doctest::Approx(homogeneous[i]).epsilon(1e-15));
    CHECK(stress[i] == doctest::Approx(homogeneous[i]).epsilon(1e-15));
  }
  // eq. 3.20: classical buoyancy + classical drag = pressure-gradient buoyancy + ε · drag = −φ ρ_p g
  const double drag_classical = phi * (rho_p - rho_f) * 9.81;  // eq. 3.21, upward
  const double classical_total = classical_buoyancy(phi, rho_f, gravity)[2] + drag_classical;
  const double pressure_total = homogeneous[2] + (1 - phi) * drag_classical;
  CHECK(classical_total == doctest::Approx(phi * rho_p * 9.81).epsilon(1e-14));
  CHECK(pressure_total == doctest::Approx(phi * rho_p * 9.81).epsilon(1e-14));
}

TEST_CASE("virtual mass, lift and Faxen forces with the dilute coefficients") {
  const double phi = 0.2, rho_f = 1000.0, mu = 1e-3;
  const Vector3<double> vm = virtual_mass_force(phi, rho_f, Vector3<double>{1, 2, 3}, Vector3<double>{0, 2, 5});
  CHECK(vm[0] == doctest::Approx(0.5 * phi * rho_f * 1));
  CHECK(vm[1] == 0.0);
  CHECK(vm[2] == doctest::Approx(0.5 * phi * rho_f * -2));
  // (∇×u) = ω e_z, slip w e_x: (∇×u) × (u − v) = ω w e_y, so the lift is −C_l φ ρ_f ω w e_y
  const double omega = 4.0, w = 0.3;
  const Vector3<double> lift = lift_force(phi, rho_f, Vector3<double>{0, 0, omega}, Vector3<double>{w, 0, 0});
  CHECK(lift[0] == 0.0);
  CHECK(lift[1] == doctest::Approx(-0.5 * phi * rho_f * omega * w));
  CHECK(lift[2] == 0.0);
  const Vector3<double> faxen = faxen_force(phi, mu, Vector3<double>{0, -8.0, 0});
  CHECK(faxen[1] == doctest::Approx(0.75 * phi * mu * -8.0));
  CHECK(dilute_virtual_mass_coefficient == dilute_lift_coefficient);
}

TEST_CASE("drag and H from one solve equal the separate evaluations, at zero slip and at eps = 1 too") {
  for (const double voidage : {0.38, 0.5, 0.75, 0.95, 1.0})
    for (const double slip : {0.0, 1e-6, 1e-3, 0.1, 3.0}) {
      INFO("voidage " << voidage << ", slip " << slip);
      const auto d = mazzei_lettieri_drag_and_sensitivity(voidage, slip, air, fcc.diameter);
      CHECK(d.beta == drag::MazzeiLettieri{}.native_beta(voidage, slip, air, fcc.diameter));
      const double h = mazzei_lettieri_sensitivity(voidage, slip, air, fcc.diameter);
      CHECK(std::abs(d.sensitivity - h) <= 1e-14 * std::abs(h));
    }
}
