// Properties every drag law of the run-time family must have, checked over whole
// domains, plus the independent mpmath reference values (tests/reference/).
#include <doctest/doctest.h>

#include <boost/math/differentiation/autodiff.hpp>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "fluidbed/drag/any_drag_law.hpp"
#include "reference_table.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;

namespace {

const Fluid<double> air{.density = 1.2, .viscosity = 1.8e-5};
const Fluid<double> water{.density = 998.0, .viscosity = 1.0e-3};

DragState<double> state(double voidage, double slip, const Fluid<double>& fluid = air, double diameter = 5e-4) {
  return {.voidage = voidage, .slip = slip, .fluid = fluid, .diameter = diameter};
}

const std::vector<double> voidages{1e-3, 0.05, 0.2, 0.35, 0.4,   0.5,        0.6,         0.7, 0.79,
                                   0.81, 0.85, 0.9, 0.99, 0.995, 1.0 - 1e-9, 1.0 - 1e-15, 1.0};
const std::vector<double> slips{0.0, 1e-12, 1e-6, 1e-3, 0.05, 0.5, 2.0, 30.0, 1e3};

// Voidages where a law as published is discontinuous or has a kink (documented in its header).
bool is_switch_point(std::string_view law, double voidage) {
  return (law.starts_with("Gidaspow") && voidage == 0.8) || (law == "SyamlalOBrien" && voidage == 0.85) ||
         (law == "KochHill" && (voidage == 0.6 || voidage == 0.9));
}

}  // namespace

TEST_CASE("every law is finite, non-negative, and positive below ε = 1, for every slip including zero") {
  for (const AnyDragLaw& law : all_drag_laws) {
    const std::string name(name_of(law));
    for (const Fluid<double>& fluid : {air, water})
      for (double eps : voidages)
        for (double w : slips) {
          const auto s = state(eps, w, fluid);
          const auto beta = evaluate(law, s);
          const auto with = evaluate_with_derivatives(law, s);
          INFO(name << " eps=" << eps << " w=" << w);
          CHECK(std::isfinite(beta.classical()));
          CHECK(std::isfinite(beta.pressure_gradient()));
          if (eps < 1.0)
            CHECK(beta.classical() > 0.0);
          else
            CHECK(beta.classical() == 0.0);
          // Derivatives: never NaN; ±∞ only where the true derivative is infinite.
          for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient}) {
            const DragDerivatives<double> d = with.in(b);
            CHECK(test::same_arithmetic(d.value, beta.in(b)));
            CHECK(std::isfinite(d.d_voidage));  // even at ε = 1, where √φ-type terms have infinite slopes
            CHECK(!std::isnan(d.d_slip));
            CHECK(std::isfinite(with.force_slip_derivative(b)));
            if (eps < 1.0) CHECK(with.force_slip_derivative(b) > 0.0);  // more slip, more drag force
          }
        }
  }
}

TEST_CASE("the two buoyancy conventions differ by exactly ε (seed 000 eq. 3.19)") {
  for (const AnyDragLaw& law : all_drag_laws)
    for (double eps : {0.3, 0.55, 0.8, 0.97})
      for (double w : {0.0, 0.01, 0.7}) {
        const auto beta = evaluate(law, state(eps, w));
        INFO(name_of(law) << " eps=" << eps << " w=" << w);
        CHECK(beta.pressure_gradient() == doctest::Approx(eps * beta.classical()).epsilon(1e-15));
        CHECK(beta.in(Buoyancy::classical) == beta.classical());
        CHECK(beta.in(Buoyancy::pressure_gradient) == beta.pressure_gradient());
      }
}

TEST_CASE("derivatives equal central finite differences over the domain") {
  // Relative step h; the O(h²) truncation and O(ε_mach/h) rounding set the tolerance.
  const double h = 1e-6;
  for (const AnyDragLaw& law : all_drag_laws) {
    const std::string name(name_of(law));
    for (const Fluid<double>& fluid : {air, water})
      for (double eps : {0.37, 0.45, 0.6, 0.75, 0.9, 0.97})
        for (double w : {1e-4, 0.02, 0.4, 5.0}) {
          if (is_switch_point(name, eps)) continue;
          const auto f = [&](double e, double s) { return evaluate(law, state(e, s, fluid)).classical(); };
          const double re = particle_reynolds(fluid, 5e-4, eps, w);
          if (std::abs(re - 1000.0) < 5.0) continue;  // Schiller–Naumann switch
          const auto d = evaluate_with_derivatives(law, state(eps, w, fluid)).classical();
          const double fd_eps = (f(eps * (1 + h), w) - f(eps * (1 - h), w)) / (2 * h * eps);
          const double fd_w = (f(eps, w * (1 + h)) - f(eps, w * (1 - h))) / (2 * h * w);
          INFO(name << " eps=" << eps << " w=" << w);
          CHECK(d.d_voidage == doctest::Approx(fd_eps).epsilon(1e-6).scale(d.value));
          CHECK(d.d_slip * w == doctest::Approx(fd_w * w).epsilon(1e-6).scale(d.value));
        }
  }
}

TEST_CASE("derivatives equal Boost.Math autodiff (an independent AD implementation)") {
  using boost::math::differentiation::make_fvar;
  using F = boost::math::differentiation::autodiff_fvar<double, 1>;
  const auto check = [](const auto& law) {
    for (double eps : {0.41, 0.63, 0.88, 0.99})
      for (double w : {0.003, 0.3, 3.0}) {
        const auto d = law.with_derivatives(state(eps, w)).classical();
        const F by_eps = law.native_beta(make_fvar<double, 1>(eps), F(w), air, 5e-4);
        const F by_slip = law.native_beta(F(eps), make_fvar<double, 1>(w), air, 5e-4);
        const double to_classical = law.native_buoyancy == Buoyancy::classical ? 1.0 : 1.0 / eps;
        const double value = by_eps.derivative(0) * to_classical;
        const double d_eps = law.native_buoyancy == Buoyancy::classical
                                 ? by_eps.derivative(1)
                                 : (by_eps.derivative(1) - by_eps.derivative(0) / eps) / eps;
        INFO(law.name() << " eps=" << eps << " w=" << w);
        CHECK(d.value == doctest::Approx(value).epsilon(1e-14));
        CHECK(d.d_voidage == doctest::Approx(d_eps).epsilon(1e-12));
        CHECK(d.d_slip == doctest::Approx(by_slip.derivative(1) * to_classical).epsilon(1e-12));
      }
  };
  for (const AnyDragLaw& law : all_drag_laws)
    std::visit(
        [&](const auto& l) {
          // Mazzei–Lettieri's implicit Re* needs the value of its argument; it is
          // checked against finite differences and the implicit-function identity.
          if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(l)>, MazzeiLettieri>) check(l);
        },
        law);
}

TEST_CASE("β agrees with the independent mpmath reference (tests/reference/drag_reference.py)") {
  const test::ReferenceTable table("drag_reference.csv");
  REQUIRE(table.size() > 100);
  std::set<std::string> seen;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string name = table.text(row, "law");
    const auto law = find_drag_law(name);
    INFO("law " << name << " is in the reference table but not in the run-time family");
    REQUIRE(law.has_value());
    seen.insert(name);
    const auto s =
        state(table.number(row, "voidage"), table.number(row, "slip"),
              {.density = table.number(row, "fluid_density"), .viscosity = table.number(row, "fluid_viscosity")},
              table.number(row, "diameter"));
    const auto beta = evaluate(*law, s);
    INFO(name << " eps=" << s.voidage << " w=" << s.slip);
    CHECK(beta.classical() == doctest::Approx(table.number(row, "beta_classical")).epsilon(1e-12));
    CHECK(beta.pressure_gradient() == doctest::Approx(table.number(row, "beta_pressure_gradient")).epsilon(1e-12));
  }
  // Every law of the family has independent reference values.
  for (const AnyDragLaw& law : all_drag_laws) {
    INFO(name_of(law));
    CHECK(seen.count(std::string(name_of(law))) == 1);
  }
}

TEST_CASE("single-particle C_D·Re agrees with the mpmath reference and the seed's values") {
  const test::ReferenceTable table("cd_reference.csv");
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string name = table.text(row, "law");
    const double re = table.number(row, "reynolds");
    const double expected = table.number(row, "cd_times_re");
    INFO(name << " Re=" << re);
    if (name == "Stokes")
      CHECK(single_particle::StokesCoefficient::cd_times_re(re) == expected);
    else if (name == "SchillerNaumann")
      CHECK(single_particle::SchillerNaumannCoefficient::cd_times_re(re) == doctest::Approx(expected).epsilon(1e-14));
    else if (name == "Dallavalle")
      CHECK(single_particle::DallavalleCoefficient::cd_times_re(re) == doctest::Approx(expected).epsilon(1e-14));
    else
      FAIL("unknown coefficient " << name);
  }
  // An independent double-precision evaluation of seed 000 eqs. 3.35 and 3.55 made when the
  // thesis was read: C_D(1) = 27.6, C_D(10) = 4.151066, C_D(100) = 1.091731, the 0.4 % jump at
  // Re = 1000; Dallavalle C_D(10) = 4.6134455.
  CHECK(single_particle::SchillerNaumannCoefficient{}.drag_coefficient(1.0) == doctest::Approx(27.6).epsilon(1e-12));
  CHECK(single_particle::SchillerNaumannCoefficient{}.drag_coefficient(10.0) ==
        doctest::Approx(4.151066).epsilon(1e-6));
  CHECK(single_particle::SchillerNaumannCoefficient{}.drag_coefficient(100.0) ==
        doctest::Approx(1.091731).epsilon(1e-6));
  CHECK(single_particle::SchillerNaumannCoefficient{}.drag_coefficient(std::nextafter(1000.0, 0.0)) ==
        doctest::Approx(0.438288).epsilon(1e-6));
  CHECK(single_particle::SchillerNaumannCoefficient{}.drag_coefficient(1000.0) == 0.44);
  CHECK(single_particle::DallavalleCoefficient{}.drag_coefficient(10.0) == doctest::Approx(4.6134455).epsilon(1e-7));
  CHECK(single_particle::DallavalleCoefficient::cd_times_re(0.0) == doctest::Approx(23.04));
  CHECK(single_particle::DallavalleCoefficient{}.drag_coefficient(1e16) == doctest::Approx(0.3969).epsilon(1e-6));
}

TEST_CASE("names: unique, found by run-time lookup, unknown names rejected with the list") {
  std::set<std::string> names;
  for (const AnyDragLaw& law : all_drag_laws) {
    const std::string name(name_of(law));
    CHECK(names.insert(name).second);
    CHECK(name_of(make_drag_law(name)) == name);
    CHECK(!std::visit([](const auto& l) { return std::string(l.reference()); }, law).empty());
  }
  CHECK_THROWS_WITH_AS(make_drag_law("WenYu"), doctest::Contains("unknown drag law 'WenYu'; known: Ergun"), std::invalid_argument);
  CHECK(!find_drag_law("wenyu").has_value());
}

TEST_CASE("the checked entry point rejects out-of-domain states, naming the argument and value") {
  const auto law = make_drag_law("Ergun");
  const auto bad = [&](DragState<double> s, const char* expected) {
    CHECK_THROWS_WITH_AS(evaluate(law, s, fluidbed::checked), doctest::Contains(expected), std::domain_error);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  bad(state(0.0, 0.1), "'voidage' = 0");
  bad(state(1.5, 0.1), "'voidage' = 1.5");
  bad(state(nan, 0.1), "'voidage' = nan");
  bad(state(0.5, -0.1), "'slip' = -0.1");
  bad(state(0.5, inf), "'slip' = inf");
  bad(state(0.5, 0.1, {.density = -1.0, .viscosity = 1e-3}), "'fluid.density' = -1");
  bad(state(0.5, 0.1, {.density = 1.0, .viscosity = 0.0}), "'fluid.viscosity' = 0");
  bad(state(0.5, 0.1, air, nan), "'diameter' = nan");
  CHECK_THROWS_WITH(evaluate(law, state(0.0, 0.1), fluidbed::checked), doctest::Contains("fluidbed::Ergun"));
  CHECK(evaluate(law, state(0.5, 0.1), fluidbed::checked).classical() == evaluate(law, state(0.5, 0.1)).classical());
}

TEST_CASE("Wen–Yu as CFD codes call it (Gidaspow) is numerically the Lewis α = 2.65 law") {
  const auto cfd = ConstantExponentDrag::wen_yu_gidaspow();
  const auto lewis = ConstantExponentDrag::lewis();
  for (double eps : {0.4, 0.8, 0.95})
    for (double w : {0.0, 0.1, 10.0}) CHECK(cfd(state(eps, w)).classical() == lewis(state(eps, w)).classical());
  // and Wen & Yu's own 1966 exponent is 2.70 (seed 000 §3.4.4.2), not the CFD default.
  CHECK(ConstantExponentDrag::wen_yu_1966().exponent() == 2.70);
}

TEST_CASE("constant-exponent laws: Stokes limit is 18 μ φ/(d² ε^(α+1)) (seed 000 eq. 3.36)") {
  for (const auto& law :
       {ConstantExponentDrag::lewis(), ConstantExponentDrag::wen_yu_1966(), ConstantExponentDrag::kmiec()})
    for (double eps : {0.4, 0.7, 0.95}) {
      const double expected = 18 * air.viscosity * (1 - eps) / (5e-4 * 5e-4 * std::pow(eps, law.exponent() + 1));
      CHECK(law(state(eps, 0.0)).classical() == doctest::Approx(expected).epsilon(1e-14));
    }
}

TEST_CASE("Gidaspow: documented jump at ε = 0.8, blend continuous and centred there") {
  const GidaspowSwitched switched;
  const GidaspowBlended blended;
  for (double w : {0.0, 0.05, 0.5, 5.0}) {
    const double below = switched(state(std::nextafter(0.8, 0.0), w)).pressure_gradient();
    const double at = switched(state(0.8, w)).pressure_gradient();
    CHECK(below == doctest::Approx(Ergun{}(state(std::nextafter(0.8, 0.0), w)).pressure_gradient()).epsilon(1e-15));
    CHECK(at == ConstantExponentDrag::wen_yu_gidaspow()(state(0.8, w)).pressure_gradient());
    if (w > 0.1) CHECK(std::abs(at / below - 1.0) > 0.05);  // a real discontinuity (Wen–Yu/Ergun ≠ 1 at 0.8)
    // The blend is the mean of the two laws at 0.8 and continuous through it.
    CHECK(blended(state(0.8, w)).pressure_gradient() ==
          doctest::Approx(0.5 * (Ergun{}(state(0.8, w)).pressure_gradient() + at)).epsilon(1e-14));
    const double left = blended(state(0.8 - 1e-9, w)).pressure_gradient();
    const double right = blended(state(0.8 + 1e-9, w)).pressure_gradient();
    CHECK(std::abs(right - left) < 1e-6 * left);
  }
  CHECK(GidaspowBlended::blending_weight(0.75) == doctest::Approx(0.0242).epsilon(1e-2));
}

TEST_CASE("GidaspowLeboreiro: exactly Ergun and Wen-Yu outside its window, C1 through it") {
  const GidaspowLeboreiro law;  // ε_s = 0.54 (Leboreiro et al.'s φ_s = 0.46), δ = 0.02
  const auto ergun = [](double e, double w) { return Ergun{}.with_derivatives(state(e, w)).pressure_gradient(); };
  const auto wen_yu = [](double e, double w) {
    return ConstantExponentDrag::wen_yu_gidaspow().with_derivatives(state(e, w)).pressure_gradient();
  };
  const auto beta = [&](double e, double w) { return law.with_derivatives(state(e, w)).pressure_gradient(); };
  for (double w : {0.0, 0.05, 0.5, 5.0}) {
    INFO("w=" << w);
    // Outside the window the law is one of the two, to rounding (a few ulp: FMA contraction at
    // -march=native, and Wen–Yu's pressure-gradient slope formed from the classical one here).
    const auto same = [](const DragDerivatives<double>& a, const DragDerivatives<double>& b) {
      CHECK(a.value == doctest::Approx(b.value).epsilon(1e-14));
      CHECK(a.d_voidage == doctest::Approx(b.d_voidage).epsilon(1e-14));
      CHECK((a.d_slip == b.d_slip || a.d_slip == doctest::Approx(b.d_slip).epsilon(1e-14)));  // +∞ at w = 0
    };
    for (double e : {0.4, 0.5, 0.519}) same(beta(e, w), ergun(e, w));  // below ε_s − δ: Ergun
    for (double e : {0.5600001, 0.7, 0.8, 0.95}) same(beta(e, w), wen_yu(e, w));  // above: Wen–Yu (Gidaspow's)
    // At ε_s the Hermite weight is ½: the mean of the two laws.
    CHECK(beta(0.54, w).value == doctest::Approx(0.5 * (ergun(0.54, w).value + wen_yu(0.54, w).value)).epsilon(1e-14));
    // Inside, with t = (ε − 0.52)/0.04, s = 3t² − 2t³, s' = 6t(1 − t)/0.04:
    // ∂β/∂ε = (1 − s) E' + s Y' + s' (Y − E).
    for (double e : {0.525, 0.54, 0.555}) {
      const double t = (e - 0.52) / 0.04, s = t * t * (3 - 2 * t), slope = 6 * t * (1 - t) / 0.04;
      const auto E = ergun(e, w), Y = wen_yu(e, w);
      CHECK(beta(e, w).value == doctest::Approx((1 - s) * E.value + s * Y.value).epsilon(1e-13));
      CHECK(beta(e, w).d_voidage ==
            doctest::Approx((1 - s) * E.d_voidage + s * Y.d_voidage + slope * (Y.value - E.value)).epsilon(1e-12));
    }
    // Continuity of β and ∂β/∂ε at both window edges (s' vanishes there).
    for (double edge : {0.52, 0.56}) {
      const auto left = beta(edge - 1e-9, w), right = beta(edge + 1e-9, w);
      CHECK(right.value == doctest::Approx(left.value).epsilon(1e-7));
      CHECK(right.d_voidage == doctest::Approx(left.d_voidage).epsilon(1e-6));
    }
  }
  // The jump it removes: at φ = 0.46 and w = 0, Ergun/Wen-Yu = 150 φ ε^1.65/18 = 1.387 (both pressure-gradient).
  const double ratio_at_switch = ergun(0.54, 0.0).value / wen_yu(0.54, 0.0).value;
  CHECK(ratio_at_switch == doctest::Approx(150 * 0.46 * std::pow(0.54, 1.65) / 18).epsilon(1e-13));
  CHECK(ratio_at_switch == doctest::Approx(1.3868).epsilon(1e-4));
  // Switch voidage and width are the caller's: at 0.8 with a narrow window it is GidaspowSwitched
  // outside 0.8 ± 1e-4.
  const GidaspowLeboreiro at_gidaspow{0.8, 1e-4};
  for (double w : {0.0, 0.5})
    for (double e : {0.79, 0.7999, 0.8001, 0.81})
      CHECK(at_gidaspow(state(e, w)).classical() == GidaspowSwitched{}(state(e, w)).classical());
  CHECK(get_parameter(law, "switch_voidage") == 0.54);
  CHECK(get_parameter(law, "half_width") == 0.02);
  // The checked entry points name a parameter out of its domain.
  CHECK_THROWS_WITH_AS(GidaspowLeboreiro(0.54, 0.0).checked(state(0.5, 0.1)), doctest::Contains("'half_width' = 0"),
                       std::domain_error);
  CHECK_THROWS_WITH_AS(GidaspowLeboreiro(1.0, 0.02).checked(state(0.5, 0.1)),
                       doctest::Contains("'switch_voidage' = 1"), std::domain_error);
}

TEST_CASE("Di Felice: χ minimum 3.05 (α_d = 2.05) exactly at Re = 10^1.5, 3.7 at both limits") {
  using Law = DiFelice<>;
  const double re_min = std::pow(10.0, 1.5);
  CHECK(Law::exponent(re_min) == doctest::Approx(3.05).epsilon(1e-15));
  CHECK(Law::exponent(re_min * 1.01) > Law::exponent(re_min));
  CHECK(Law::exponent(re_min / 1.01) > Law::exponent(re_min));
  CHECK(Law::exponent(0.0) == 3.7);
  CHECK(Law::exponent(1e-8) == doctest::Approx(3.7).epsilon(1e-12));
  CHECK(Law::exponent(1e12) == doctest::Approx(3.7).epsilon(1e-12));
  // Seed 000 eq. 3.48, evaluated independently: α_d(28) = 2.05091, α_d(1) = α_d(1000) = 2.488976.
  CHECK(Law::exponent(28.0) - 1.0 == doctest::Approx(2.05091).epsilon(1e-5));
  CHECK(Law::exponent(1.0) - 1.0 == doctest::Approx(2.488976).epsilon(1e-6));
  CHECK(Law::exponent(1000.0) == doctest::Approx(Law::exponent(1.0)).epsilon(1e-14));
}

TEST_CASE("every law evaluates in float and long double, agreeing with double") {
  for (const AnyDragLaw& law : all_drag_laws)
    std::visit(
        [](const auto& l) {
          for (double eps : {0.45, 0.7, 0.95})
            for (double w : {0.0, 0.01, 0.2, 5.0}) {
              const double reference = l(state(eps, w)).classical();
              const DragState<float> sf{float(eps), float(w), {1.2f, 1.8e-5f}, 5e-4f};
              const DragState<long double> sl{eps, w, {1.2L, 1.8e-5L}, 5e-4L};
              INFO(l.name() << " eps=" << eps << " w=" << w);
              CHECK(double(l(sf).classical()) == doctest::Approx(reference).epsilon(1e-4));
              CHECK(double(l(sl).classical()) == doctest::Approx(reference).epsilon(1e-13));
            }
        },
        law);
}

TEST_CASE("float at a switch voidage: value and derivative paths take the same branch") {
  // The plain path once compared a float ε with the double constant (0.85f > 0.85) and the dual
  // path with the constant rounded to float (0.85f <= 0.85f): with_derivatives then evaluated the
  // other branch, 0.05 % to 0.1 % off for Syamlal–O'Brien's B, 11 % to 73 % for Gidaspow's switch.
  // Both now compare with the switch point in T; what is left between them is float rounding.
  for (const AnyDragLaw& law : all_drag_laws)
    std::visit(
        [](const auto& l) {
          for (double at : {0.8, 0.85, 0.6, 0.9, 0.99, 1.0 - 0.0953})
            for (float eps : {std::nextafter(float(at), 0.0f), float(at), std::nextafter(float(at), 1.0f)})
              for (float w : {0.0f, 0.05f, 2.0f, 300.0f}) {
                const DragState<float> s{eps, w, {998.0f, 1e-3f}, 3e-3f};
                INFO(l.name() << " eps=" << eps << " w=" << w);
                for (Buoyancy b : {Buoyancy::classical, Buoyancy::pressure_gradient})
                  CHECK(double(l.with_derivatives(s).in(b).value) == doctest::Approx(double(l(s).in(b))).epsilon(1e-5));
              }
        },
        law);
  CHECK(SyamlalOBrien::switch_voidage<float>() == 0.85f);
  CHECK(GidaspowSwitched::switch_voidage<value_type_of<Dual<float, 2>>>() == 0.8f);
}

TEST_CASE("every law states a reference and a validity range that contains states and excludes others") {
  for (const AnyDragLaw& law : all_drag_laws)
    std::visit(
        [](const auto& l) {
          const ValidityRange v = l.validity();
          INFO(l.name());
          CHECK(!l.reference().empty());
          CHECK(v.voidage_min < v.voidage_max);
          CHECK(v.reynolds_min < v.reynolds_max);
          const double eps = 0.5 * (v.voidage_min + v.voidage_max);
          const double re = v.reynolds_max < 1e300 ? 0.5 * (v.reynolds_min + v.reynolds_max) : 10.0;
          const double w = re * air.viscosity / (air.density * eps * 5e-4);
          CHECK(l.within_validity(state(eps, w)));
          if (v.voidage_min > 0.01) CHECK(!l.within_validity(state(0.5 * v.voidage_min, w)));
        },
        law);
}
