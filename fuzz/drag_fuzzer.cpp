// libFuzzer target for the drag family (include/fluidbed/drag/).
//
// The first byte picks what the input drives:
//   plausible state   every law of the run-time family (all_drag_laws, through AnyDragLaw and
//                     evaluate*) on a physically plausible cell, in double and float: the hot
//                     path's contract (drag_law.hpp, README "Conventions"): β finite and >= 0,
//                     > 0 for ε < 1 and 0 at ε = 1; the conventions differ by ε; derivatives:
//                     value equal to β, ∂β/∂ε finite, ∂β/∂w never NaN (+∞ only at w = 0),
//                     ∂(βw)/∂w finite and > 0 below ε = 1; `checked` accepts the state and agrees;
//   garbage state     raw doubles into `checked` and `checked_with_derivatives` (through
//                     evaluate*_checked): they throw std::domain_error exactly when a documented
//                     precondition fails or, in the domain, when the hot path's result is not
//                     finite (β overflowing, say), and otherwise return the hot path's finite β;
//   polydisperse      BeetstraPolydisperse on a plausible mixture (hot path, derivatives, checked,
//                     and the documented identity: the species' β sum to the monodisperse law at
//                     the Sauter diameter), and on a garbage mixture (checked);
//   free functions    the single-particle C_D·Re, the dimensionless forces and the other static
//                     helpers of the laws, with the bounds their comments state;
//   calibration       fluidization::syamlal_obrien_from_minimum_fluidization (throws or reproduces u_mf);
//   lookup            make_drag_law / find_drag_law on arbitrary names.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "fluidbed/drag.hpp"
#include "fluidbed/fluidization/syamlal_obrien_calibration.hpp"
#include "fuzz_input.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;
using fluidbed::fuzz::close;
using fluidbed::fuzz::Input;
using fluidbed::fuzz::is_finite;

namespace {

template <class T>
const char* type_name() {
  return std::is_same_v<T, float> ? "float" : "double";
}

// ------------------------------------------------------------------------------------- decoding

// The voidages where a law switches branch (headers of gidaspow, syamlal_obrien, koch_hill,
// tenneti, beetstra): where off-by-one comparisons and one-sided formulas show.
constexpr double kSwitchVoidages[] = {0.8, 0.85, 0.6, 0.9, 0.99, 1.0 - 0.0953, 0.4, 0.36, 0.5, 0.47791};

// The plausible ranges of a cell: wider than any fluidized bed (gas to liquid metal, 0.1 µm to
// 10 cm, creeping to supersonic slip), down to ε = 1e-3, the tests' lowest voidage
// (tests/test_drag_family.cpp). Narrower in float, whose range the derivatives at tiny slips
// (∂β/∂w ∝ w^−½) and μ/d² at tiny diameters would exceed.
template <class T>
struct Ranges {
  static constexpr bool wide = std::is_same_v<T, double>;
  static constexpr double voidage_min = wide ? 1e-3 : 0.2;
  static constexpr double slip_min = wide ? 1e-12 : 1e-6, slip_max = wide ? 1e3 : 1e2;
  static constexpr double density_min = wide ? 1e-2 : 0.1, density_max = 2e4;
  static constexpr double viscosity_min = 1e-6, viscosity_max = wide ? 10 : 1;
  static constexpr double diameter_min = wide ? 1e-7 : 1e-6, diameter_max = 0.1;
};

template <class T>
DragState<T> plausible_state(Input& in) {
  using R = Ranges<T>;
  T voidage;
  switch (in.byte() % 8) {
    case 0:
      voidage = T(1);
      break;
    case 1:  // the dilute limit
      voidage = T(1 - in.log_uniform(1e-16, 1e-2));
      break;
    case 2: {
      const T at = T(kSwitchVoidages[in.byte() % std::size(kSwitchVoidages)]);
      const int side = in.integer(-1, 1);  // the switch point or its neighbour on either side
      voidage = side == 0 ? at : std::nextafter(at, side < 0 ? T(0) : T(1));
      break;
    }
    case 3:  // denser than any packing
      voidage = T(in.log_uniform(R::voidage_min, 0.3));
      break;
    default:
      voidage = T(in.uniform(0.3, 1));
      break;
  }
  const T slip = in.byte() % 4 == 0 ? T(0) : T(in.log_uniform(R::slip_min, R::slip_max));
  const Fluid<T> fluid{.density = T(in.log_uniform(R::density_min, R::density_max)),
                       .viscosity = T(in.log_uniform(R::viscosity_min, R::viscosity_max))};
  return {.voidage = voidage,
          .slip = slip,
          .fluid = fluid,
          .diameter = T(in.log_uniform(R::diameter_min, R::diameter_max))};
}

// -------------------------------------------------------------------------------------- reports

template <class T>
std::string text(const DragState<T>& s) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer,
                "%s state {voidage %.17g, slip %.17g, density %.17g, viscosity %.17g, "
                "diameter %.17g}",
                type_name<T>(), double(s.voidage), double(s.slip), double(s.fluid.density), double(s.fluid.viscosity),
                double(s.diameter));
  return buffer;
}

constexpr Buoyancy kConventions[] = {Buoyancy::classical, Buoyancy::pressure_gradient};

const char* name(Buoyancy b) { return b == Buoyancy::classical ? "classical" : "pressure_gradient"; }

// β of with_derivatives against the hot path's: bit for bit in double (tests/test_drag_family.cpp).
// In float the plain path runs partly in double (double literals promote it) while the dual path
// runs in float, whose cancellations (Gidaspow's ½ + atan/π far from ε = 0.8) then show: 1e-4, the
// tolerance of the tests' float-against-double comparison.
template <class T>
bool same_value(const T& dual, const T& plain) {
  return std::is_same_v<T, double> ? dual == plain : close(dual, plain, T(1e-4), plain);
}

// --------------------------------------------------------------------------- one law, one state

template <class T, class Law>
void check_hot_path(const Law& law, const DragState<T>& s) {
  const std::string_view law_name = law.name();
  const int name_length = int(law_name.size());
  const char* name_data = law_name.data();
  const DragCoefficient<T> beta = law(s);
  const T eps = std::numeric_limits<T>::epsilon();
  for (Buoyancy b : kConventions) {
    const T value = beta.in(b);
    FUZZ_CHECK(is_finite(value) && value >= T(0), "%.*s: beta %s = %.17g (finite, >= 0); %s", name_length, name_data,
               name(b), double(value), text(s).c_str());
    FUZZ_CHECK(s.voidage < T(1) ? value > T(0) : value == T(0),
               "%.*s: beta %s = %.17g (> 0 below voidage 1, 0 at 1); %s", name_length, name_data, name(b),
               double(value), text(s).c_str());
  }
  FUZZ_CHECK(close(beta.pressure_gradient(), s.voidage * beta.classical(), T(4) * eps, beta.pressure_gradient()),
             "%.*s: beta pressure_gradient %.17g != voidage * classical %.17g; %s", name_length, name_data,
             double(beta.pressure_gradient()), double(s.voidage * beta.classical()), text(s).c_str());

  const DragCoefficientWithDerivatives<T> with = law.with_derivatives(s);
  for (Buoyancy b : kConventions) {
    const DragDerivatives<T> d = with.in(b);
    FUZZ_CHECK(same_value(d.value, beta.in(b)) && with.coefficient().in(b) == d.value,
               "%.*s: with_derivatives value %.17g != beta %.17g (%s); %s", name_length, name_data, double(d.value),
               double(beta.in(b)), name(b), text(s).c_str());
    FUZZ_CHECK(is_finite(d.d_voidage), "%.*s: d beta/d voidage = %.17g (%s); %s", name_length, name_data,
               double(d.d_voidage), name(b), text(s).c_str());
    FUZZ_CHECK(is_finite(d.d_slip) || (s.slip == T(0) && d.d_slip == std::numeric_limits<T>::infinity()),
               "%.*s: d beta/d slip = %.17g (%s; finite, or +inf at zero slip); %s", name_length, name_data,
               double(d.d_slip), name(b), text(s).c_str());
    // More slip, more drag force (tests/test_drag_family.cpp) — checked from ε = 0.01: at ε <~ 1.2e-3
    // Di Felice's χ(Re) falls fast enough near Re = 3 for βw to decrease (an extrapolation far
    // below any packing, reported).
    const T force = with.force_slip_derivative(b);
    const bool increasing = s.voidage < T(1) && s.voidage >= T(0.01);
    FUZZ_CHECK(is_finite(force) && (!increasing || force > T(0)) && (s.voidage < T(1) || force >= T(0)),
               "%.*s: d(beta w)/dw = %.17g (%s; finite, > 0 for 0.01 <= voidage < 1); %s", name_length, name_data,
               double(force), name(b), text(s).c_str());
  }
  (void)law.within_validity(s);
  const DragCoefficient<T> checked = law.checked(s);  // a state inside the domain: no exception
  FUZZ_CHECK(checked.classical() == beta.classical(), "%.*s: checked %.17g != hot path %.17g; %s", name_length,
             name_data, double(checked.classical()), double(beta.classical()), text(s).c_str());
}

template <class T>
void plausible_states(Input& in) {
  const DragState<T> s = plausible_state<T>(in);
  for (const AnyDragLaw& law : all_drag_laws) {
    std::visit([&](const auto& l) { check_hot_path(l, s); }, law);
    // The run-time dispatch returns what the law itself does.
    const DragCoefficient<T> direct = std::visit([&](const auto& l) { return l(s); }, law);
    FUZZ_CHECK(evaluate(law, s).classical() == direct.classical() &&
                   same_value(evaluate_with_derivatives(law, s).classical().value, direct.classical()) &&
                   evaluate(law, s, fluidbed::checked).classical() == direct.classical(),
               "evaluate*(%s) differs from the law's own call; %s", std::string(name_of(law)).c_str(), text(s).c_str());
  }
  // The constant-exponent family with any exponent a user may construct.
  check_hot_path(ConstantExponentDrag(in.uniform(0, 6), "fuzzed", "-"), s);
  check_hot_path(SyamlalOBrien::continuous_at_switch(in.uniform(1.3, 4)), s);
}

// ------------------------------------------------------------------------------------- checked

// The domain of DragState the headers document: ε ∈ (0, 1], w >= 0, ρ_f, μ_f, d > 0, all finite.
template <class T>
bool in_domain(const DragState<T>& s) {
  const auto positive = [](T x) { return is_finite(x) && x > T(0); };
  return is_finite(s.voidage) && s.voidage > T(0) && s.voidage <= T(1) && is_finite(s.slip) && s.slip >= T(0) &&
         positive(s.fluid.density) && positive(s.fluid.viscosity) && positive(s.diameter);
}

// Whether the hot path's result is finite: β in both conventions, and with derivatives also
// ∂β/∂ε, ∂β/∂w (but for the documented +∞ at w = 0) and ∂(βw)/∂w. In the domain, `checked` and
// `checked_with_derivatives` throw exactly when it is not (drag_law.hpp).
template <class T>
bool representable(const DragCoefficient<T>& beta) {
  return is_finite(beta.classical()) && is_finite(beta.pressure_gradient());
}

template <class T>
bool representable(const DragCoefficientWithDerivatives<T>& beta, const T& slip) {
  return std::all_of(std::begin(kConventions), std::end(kConventions), [&](Buoyancy b) {
    const DragDerivatives<T> d = beta.in(b);
    return is_finite(d.value) && is_finite(d.d_voidage) &&
           (is_finite(d.d_slip) || (slip == T(0) && d.d_slip == std::numeric_limits<T>::infinity())) &&
           is_finite(beta.force_slip_derivative(b));
  });
}

template <class T>
void garbage_states(Input& in) {
  DragState<T> s{};
  // Each field garbage, or plausible, so that the other fields' checks are reached too.
  const DragState<T> fallback = plausible_state<T>(in);
  const std::uint8_t which = in.byte();
  s.voidage = which & 1 ? in.garbage<T>() : fallback.voidage;
  s.slip = which & 2 ? in.garbage<T>() : fallback.slip;
  s.fluid.density = which & 4 ? in.garbage<T>() : fallback.fluid.density;
  s.fluid.viscosity = which & 8 ? in.garbage<T>() : fallback.fluid.viscosity;
  s.diameter = which & 16 ? in.garbage<T>() : fallback.diameter;
  const bool valid = in_domain(s);
  for (const AnyDragLaw& law : all_drag_laws) {
    const std::string law_name(name_of(law));
    // The hot path only inside its domain (its preconditions are asserted).
    const bool finite = valid && representable(evaluate(law, s));
    try {
      const DragCoefficient<T> beta = evaluate(law, s, fluidbed::checked);
      FUZZ_CHECK(finite, "%s: checked accepted %s %s", law_name.c_str(),
                 valid ? "a non-finite beta at an in-domain" : "an out-of-domain", text(s).c_str());
      for (Buoyancy b : kConventions)
        FUZZ_CHECK(beta.in(b) >= T(0) && beta.in(b) == evaluate(law, s).in(b),
                   "%s: checked returned beta %s = %.17g, hot path %.17g, for %s", law_name.c_str(), name(b),
                   double(beta.in(b)), double(evaluate(law, s).in(b)), text(s).c_str());
    } catch (const std::domain_error&) {
      FUZZ_CHECK(!finite, "%s: checked threw for an in-domain %s with a finite beta", law_name.c_str(),
                 text(s).c_str());
    }
    // Out of the domain the derivative entry point runs the validation of `checked`, fuzzed just
    // above (drag_law.hpp); in the domain, its check of the results.
    if (!valid) continue;
    const bool finite_derivatives = representable(evaluate_with_derivatives(law, s), s.slip);
    try {
      (void)evaluate_with_derivatives(law, s, fluidbed::checked);
      FUZZ_CHECK(finite_derivatives, "%s: checked_with_derivatives accepted a non-finite result at %s",
                 law_name.c_str(), text(s).c_str());
    } catch (const std::domain_error&) {
      FUZZ_CHECK(!finite_derivatives, "%s: checked_with_derivatives threw for an in-domain %s with finite results",
                 law_name.c_str(), text(s).c_str());
    }
  }
}

// -------------------------------------------------------------------------------- polydisperse

template <class T>
struct Mixture {
  std::array<Species<T>, 8> species{};
  std::size_t count = 1;
};

template <class T>
std::string text(const PolydisperseDragState<T>& s) {
  std::string out = "mixture {";
  char buffer[120];
  for (const Species<T>& sp : s.mixture) {
    std::snprintf(buffer, sizeof buffer, "{%.17g, %.17g} ", double(sp.volume_fraction), double(sp.diameter));
    out += buffer;
  }
  std::snprintf(buffer, sizeof buffer, "}, species %zu, slip %.17g, fluid {%.17g, %.17g}", s.species, double(s.slip),
                double(s.fluid.density), double(s.fluid.viscosity));
  return out + buffer;
}

template <class T>
void polydisperse(Input& in) {
  Mixture<T> mix;
  mix.count = std::size_t(in.integer(1, 8));
  const bool garbage = in.byte() % 4 == 0;
  const double solids = in.uniform(1e-4, 0.65);
  double weights[8], total = 0;
  for (std::size_t j = 0; j < mix.count; ++j) {
    weights[j] = in.byte() % 6 == 0 ? 0.0 : in.uniform(0.01, 1);
    total += weights[j];
    mix.species[j].diameter = T(in.log_uniform(1e-6, 1e-2));
  }
  if (total == 0) weights[0] = total = 1;
  for (std::size_t j = 0; j < mix.count; ++j) mix.species[j].volume_fraction = T(solids * weights[j] / total);
  const DragState<T> cell = plausible_state<T>(in);
  PolydisperseDragState<T> s{.mixture = std::span<const Species<T>>(mix.species.data(), mix.count),
                             .species = std::size_t(in.integer(0, int(mix.count) - 1)),
                             .slip = cell.slip,
                             .fluid = cell.fluid};
  const BeetstraPolydisperse law =
      in.boolean() ? BeetstraPolydisperse::published() : BeetstraPolydisperse::without_cubic_term();
  if (garbage) {  // checked: throws std::domain_error, or a finite β
    for (std::size_t j = 0; j < mix.count; ++j)
      if (in.boolean()) mix.species[j] = {in.garbage<T>(), in.garbage<T>()};
    if (in.boolean()) s.slip = in.garbage<T>();
    if (in.boolean()) s.fluid = {in.garbage<T>(), in.garbage<T>()};
    if (in.byte() % 8 == 0) s.species = std::size_t(in.integer(0, 255));
    try {
      const PolydisperseDragCoefficient<T> beta = law.checked(s);
      for (Buoyancy b : kConventions)
        FUZZ_CHECK(is_finite(beta.in(b)) && beta.in(b) >= T(0), "%s: checked returned beta %s = %.17g for %s",
                   std::string(law.name()).c_str(), name(b), double(beta.in(b)), text(s).c_str());
    } catch (const std::domain_error&) {
    }
    return;
  }
  const PolydisperseDragCoefficient<T> beta = law(s);
  const PolydisperseDragCoefficientWithDerivatives<T> with = law.with_derivatives(s);
  const PolydisperseDragCoefficient<T> checked = law.checked(s);
  for (Buoyancy b : kConventions) {
    const DragDerivatives<T> d = with.in(b);
    FUZZ_CHECK(is_finite(beta.in(b)) && beta.in(b) >= T(0) && d.value == beta.in(b) && checked.in(b) == beta.in(b),
               "%s: beta %s = %.17g, with_derivatives %.17g, checked %.17g; %s", std::string(law.name()).c_str(),
               name(b), double(beta.in(b)), double(d.value), double(checked.in(b)), text(s).c_str());
    FUZZ_CHECK(is_finite(d.d_voidage) && !std::isnan(d.d_slip) && is_finite(with.force_slip_derivative(b)),
               "%s: derivatives %.17g, %.17g, force %.17g (%s); %s", std::string(law.name()).c_str(),
               double(d.d_voidage), double(d.d_slip), double(with.force_slip_derivative(b)), name(b), text(s).c_str());
  }
  // Documented identity (beetstra.hpp): at equal slips the species' drags sum to the
  // monodisperse Beetstra law at the Sauter diameter — model A always, model B without y³.
  PolydisperseBeta<T> sum{T(0), T(0)};
  for (std::size_t i = 0; i < mix.count; ++i) {
    s.species = i;
    const PolydisperseDragCoefficient<T> b = law(s);
    sum.classical += b.classical();
    sum.pressure_gradient += b.pressure_gradient();
  }
  const MixtureMoments<T> moments = mixture_moments(s.mixture);
  const DragCoefficient<T> mono =
      Beetstra{}(DragState<T>{T(1) - moments.solid_fraction, s.slip, s.fluid, moments.sauter_diameter});
  const T tolerance = T(64) * T(mix.count) * std::numeric_limits<T>::epsilon();
  FUZZ_CHECK(close(sum.pressure_gradient, mono.pressure_gradient(), tolerance, mono.pressure_gradient()),
             "BeetstraPolydisperse: species sum %.17g != monodisperse %.17g (pressure_gradient), %zu species",
             double(sum.pressure_gradient), double(mono.pressure_gradient()), mix.count);
  if (law.cubic_coefficient() == 0.0)
    FUZZ_CHECK(close(sum.classical, mono.classical(), tolerance, mono.classical()),
               "BeetstraPolydisperseNoCubic: species sum %.17g != monodisperse %.17g (classical), %zu species",
               double(sum.classical), double(mono.classical()), mix.count);
}

// ------------------------------------------------------------------------------ free functions

template <class T>
void free_functions(Input& in) {
  const T phi = in.byte() % 8 == 0 ? T(0) : T(in.uniform(0, 0.999));
  const T re = in.byte() % 8 == 0 ? T(0) : T(in.log_uniform(1e-12, 1e12));
  const T voidage = T(1) - phi;
  const T eps = std::numeric_limits<T>::epsilon();
  // C_D·Re of a sphere: finite and positive, C_D too for Re > 0.
  for (const T cd_re : {single_particle::StokesCoefficient::cd_times_re(re), single_particle::SchillerNaumannCoefficient::cd_times_re(re),
                        single_particle::DallavalleCoefficient::cd_times_re(re)})
    FUZZ_CHECK(is_finite(cd_re) && cd_re > T(0), "C_D Re(%.17g) = %.17g", double(re), double(cd_re));
  if (re > T(0))
    for (const T cd : {single_particle::StokesCoefficient{}.drag_coefficient(re), single_particle::SchillerNaumannCoefficient{}.drag_coefficient(re),
                       single_particle::DallavalleCoefficient{}.drag_coefficient(re)})
      FUZZ_CHECK(is_finite(cd) && cd > T(0), "C_D(%.17g) = %.17g", double(re), double(cd));
  // Dimensionless forces: finite and positive; Beetstra's inertial part is >= 0 (F >= F0), Tang's
  // extension keeps F positive (tang.hpp).
  const T f0 = drag::detail::van_der_hoef_stokes_force(phi);
  const T beetstra = Beetstra::dimensionless_force(phi, re);
  FUZZ_CHECK(is_finite(f0) && f0 >= T(1) - T(4) * eps && is_finite(beetstra) && beetstra >= f0 * (T(1) - T(4) * eps),
             "F0(%.17g) = %.17g, Beetstra F(Re %.17g) = %.17g", double(phi), double(f0), double(re), double(beetstra));
  const T tang = Tang::dimensionless_force(phi, re), tenneti = Tenneti::dimensionless_force(phi, re);
  FUZZ_CHECK(is_finite(tang) && tang > T(0) && is_finite(tenneti) && tenneti > T(0),
             "phi %.17g, Re %.17g: Tang F = %.17g, Tenneti F = %.17g", double(phi), double(re), double(tang),
             double(tenneti));
  // Koch–Hill: the transition Re is real and >= 0 everywhere (koch_hill.hpp: "no fallback is needed").
  const T transition = KochHill::transition_reynolds(phi), koch_hill = KochHill::dimensionless_force(phi, re);
  FUZZ_CHECK(is_finite(transition) && transition >= T(0) && is_finite(koch_hill) && koch_hill > T(0),
             "Koch-Hill phi %.17g, Re %.17g: transition %.17g, F %.17g", double(phi), double(re), double(transition),
             double(koch_hill));
  if (phi > T(0))
    for (const T f : {KochHill::f0(phi), KochHill::f1(phi), KochHill::f2(phi), KochHill::f3(phi)})
      FUZZ_CHECK(is_finite(f) && f > T(0), "Koch-Hill F_i(%.17g) = %.17g", double(phi), double(f));
  // Di Felice's χ lies in [3.05, 3.7]; Gidaspow's blending weight in [0, 1].
  const T chi = DiFelice<>::exponent(re);
  FUZZ_CHECK(chi >= T(3.05) * (T(1) - T(4) * eps) && chi <= T(3.7) * (T(1) + T(4) * eps), "chi(%.17g) = %.17g",
             double(re), double(chi));
  const T psi = GidaspowBlended::blending_weight(voidage);
  FUZZ_CHECK(psi >= T(0) && psi <= T(1), "blending_weight(%.17g) = %.17g", double(voidage), double(psi));
  // Mazzei–Lettieri: Re ε^−2.4 <= Re* <= Re ε^−4.8 (the bracket of mazzei_lettieri.hpp).
  if (voidage > T(0)) {
    const T re_star = MazzeiLettieri::effective_reynolds(voidage, re);
    const T slack = T(64) * eps;
    FUZZ_CHECK(re_star >= re * std::pow(voidage, T(-2.4)) * (T(1) - slack) &&
                   re_star <= re * std::pow(voidage, T(-4.8)) * (T(1) + slack),
               "Mazzei-Lettieri Re*(voidage %.17g, Re %.17g) = %.17g outside [Re e^-2.4, Re e^-4.8]", double(voidage),
               double(re), double(re_star));
    const T function = MazzeiLettieri::voidage_function(voidage, re);
    const T exponent = MazzeiLettieri::equivalent_exponent(voidage, re);
    FUZZ_CHECK(is_finite(function) && function > T(0) && is_finite(exponent),
               "Mazzei-Lettieri voidage %.17g, Re %.17g: voidage function %.17g, exponent %.17g", double(voidage),
               double(re), double(function), double(exponent));
  }
  // Syamlal–O'Brien: V_r lies between A = ε^4.14 (Re_s → 0) and B (Re_s → ∞).
  if (voidage > T(0)) {
    const SyamlalOBrien law;
    const T ratio = law.velocity_ratio(voidage, re);
    const T a = std::pow(voidage, T(4.14));
    const T b = voidage <= SyamlalOBrien::switch_voidage<T>() ? T(law.c1() * std::pow(voidage, T(1.28)))
                                                            : T(std::pow(voidage, T(law.d1())));
    FUZZ_CHECK(ratio >= std::min(a, b) * (T(1) - T(16) * eps) && ratio <= std::max(a, b) * (T(1) + T(16) * eps),
               "Syamlal-O'Brien V_r(voidage %.17g, Re_s %.17g) = %.17g outside [A %.17g, B %.17g]", double(voidage),
               double(re), double(ratio), double(a), double(b));
  }
  // F → β (dimensionless_force.hpp): finite, >= 0.
  const T viscosity = T(in.log_uniform(1e-6, 10)), diameter = T(in.log_uniform(1e-7, 0.1));
  for (const T b : {beta_from_drag_force(beetstra, voidage, viscosity, diameter),
                    beta_from_total_force(tenneti, voidage, viscosity, diameter)})
    FUZZ_CHECK(is_finite(b) && b >= T(0), "beta from F: %.17g", double(b));
}

// ---------------------------------------------------------------------------------- calibration

// fluidization::syamlal_obrien_from_minimum_fluidization: std::domain_error for invalid input, B <= 0 or
// parameters beyond the range; otherwise finite parameters with which the law reproduces u_mf
// at ε_mf: in the −φ∇p convention β w = φ ε (ρ_p − ρ_f) g, w = u_mf/ε_mf (syamlal_obrien.hpp).
void calibration(Input& in) {
  const bool garbage = in.boolean();
  double velocity = in.log_uniform(1e-5, 1), voidage = in.uniform(0.3, 0.95), gravity = 9.81;
  Fluid<double> fluid{in.log_uniform(1e-2, 2e4), in.log_uniform(1e-6, 10)};
  Particles<double> particles{fluid.density * (1 + in.log_uniform(1e-3, 1e4)), in.log_uniform(1e-7, 0.1)};
  if (garbage) {
    const std::uint8_t which = in.byte();
    if (which & 1) velocity = in.garbage<double>();
    if (which & 2) voidage = in.garbage<double>();
    if (which & 4) fluid = {in.garbage<double>(), in.garbage<double>()};
    if (which & 8) particles = {in.garbage<double>(), in.garbage<double>()};
    if (which & 16) gravity = in.garbage<double>();
  }
  try {
    const SyamlalOBrien law = fluidization::syamlal_obrien_from_minimum_fluidization(velocity, voidage, fluid, particles, gravity);
    FUZZ_CHECK(is_finite(law.c1()) && law.c1() > 0 && is_finite(law.d1()),
               "from_minimum_fluidization(u %.17g, voidage %.17g, fluid {%.17g, %.17g}, particles {%.17g, %.17g}, "
               "g %.17g) returned c1 = %.17g, d1 = %.17g",
               velocity, voidage, fluid.density, fluid.viscosity, particles.density, particles.diameter, gravity,
               law.c1(), law.d1());
    if (garbage) return;
    const double slip = velocity / voidage;
    const double beta = law(DragState<double>{voidage, slip, fluid, particles.diameter}).pressure_gradient();
    const double weight = (1 - voidage) * voidage * (particles.density - fluid.density) * gravity;
    FUZZ_CHECK(close(beta * slip, weight, 1e-8, weight),
               "from_minimum_fluidization(u %.17g, voidage %.17g, fluid {%.17g, %.17g}, particles {%.17g, %.17g}): "
               "beta w = %.17g, weight %.17g (c1 %.17g, d1 %.17g)",
               velocity, voidage, fluid.density, fluid.viscosity, particles.density, particles.diameter, beta * slip,
               weight, law.c1(), law.d1());
  } catch (const std::domain_error&) {
  }
}

// --------------------------------------------------------------------------------------- lookup

void lookup(Input& in) {
  std::string name(std::size_t(in.integer(0, 32)), '\0');
  for (char& c : name) c = char(in.byte());
  if (in.boolean()) name = std::string(name_of(all_drag_laws[in.byte() % all_drag_laws.size()])) + name.substr(0, 2);
  const std::optional<AnyDragLaw> found = find_drag_law(name);
  FUZZ_CHECK(!found || name_of(*found) == name, "find_drag_law(\"%s\") found %s", name.c_str(),
             std::string(name_of(*found)).c_str());
  try {
    const AnyDragLaw law = make_drag_law(name);
    FUZZ_CHECK(found && name_of(law) == name, "make_drag_law(\"%s\") returned %s", name.c_str(),
               std::string(name_of(law)).c_str());
  } catch (const std::invalid_argument&) {
    FUZZ_CHECK(!found, "make_drag_law(\"%s\") threw but find_drag_law found it", name.c_str());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  switch (in.byte() % 12) {
    case 0:
    case 1:
    case 2:
      plausible_states<double>(in);
      break;
    case 3:
      plausible_states<float>(in);
      break;
    case 4:
    case 5:
      garbage_states<double>(in);
      break;
    case 6:
      garbage_states<float>(in);
      break;
    case 7:
      polydisperse<double>(in);
      break;
    case 8:
      free_functions<double>(in);
      break;
    case 9:
      free_functions<float>(in);
      break;
    case 10:
      calibration(in);
      break;
    default:
      lookup(in);
      break;
  }
  return 0;
}
