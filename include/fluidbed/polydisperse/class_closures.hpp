// fluidbed — the per-class closures of the multi-fluid (DQMOM) model, one call per cell: the
// gas–particle drag β_i of every solids class and the solid–solid drag ζ_ik of every pair.
//
// Model (seed 000 Ch. 6, eqs. 6.8–6.16). Classes i = 1 … ν, each with volume fraction φ_i, diameter
// ξ_i, material density ρ_i and velocity v_i, have their own momentum equation; the interaction
// terms per unit volume of suspension are, for class i,
//   buoyancy        −φ_i ∇p                (pressure-gradient convention, eq. 6.11)
//   gas drag        β_i (u − v_i)          (eq. 6.12)
//   solid drag      Σ_k ζ_ik (v_k − v_i)   (eqs. 6.14–6.15), ζ_ik = ζ_ki, ζ_ii unused (0).
// The voidage is ε = 1 − Σ_i φ_i: it is computed here, not passed, so that the state cannot be
// inconsistent and ∂/∂φ_m are the derivatives an implicit solver that eliminates ε needs.
//
// Gas–particle drag: the standard per-class extension of a monodisperse law. Any DragLaw is
// evaluated per class at the mixture voidage ε, the class slip w_i = |u − v_i| and the class
// diameter ξ_i (Re_i = ρ_f ε w_i ξ_i/μ_f, seed 000 eq. 6.13), and scaled by φ_i/(1 − ε):
//   β_i = φ_i B_i,   B_i = β_law(ε, w_i, ξ_i)/(1 − ε),
// in either buoyancy convention (the scale is common to both, so β_i,pg = ε β_i,cl class by class,
// seed 000 eq. 3.19 applied per class). With drag::MazzeiLettieri this is exactly seed 000
// eqs. 6.12–6.13, β_i,pg = ¾ C_D(Re_i) ρ_f w_i ε φ_i/ξ_i · ε^(−ψ_e(ε, Re_i)) (Dallavalle C_D; ψ_e
// of Mazzei & Lettieri 2007): ε β_ML,cl φ_i/(1 − ε), the monodisperse (1 − ε) replaced by φ_i.
// One class reproduces the law; classes of one diameter and one slip add up to the law.
// Conventions for a mixture. Per class, the factor ε between the two conventions is the
// per-class extension's own definition, not an identity: eliminating ∇p with the gas momentum
// balance gives β_i,cl (u − v_i) = β_i,pg (u − v_i) + (φ_i/ε) Σ_j β_j,pg (u − v_j), which couples
// the classes; the two agree only when β_i/φ_i is the same for every class (one diameter, one
// slip). Seed 000's model (eqs. 6.11–6.12) is the pressure-gradient one; a host with classical
// buoyancy −φ_i ρ_f g per class and the classical β_i has a different, equally per-class closure.
// At ε = 1 in T (Σ φ_i below half an ulp of 1, the empty cell included) β_law/(1 − ε) is 0/0: the
// law is evaluated at the largest T below 1 instead, a shift no larger than the rounding of ε.
//
// Solid–solid drag: Syamlal (1987), kinetic_theory::SyamlalSolidSolidDrag (the standard ¾ form;
// seed 000 eq. 6.15 prints a prefactor π times larger, a misprint), with restitution e (one value
// for every pair, as seed 000 §6.5: 0.97) and friction C_f (0.15 there), and g_ik from a mixture
// radial distribution (kinetic_theory::Lebowitz by default; seed 000 eq. 6.16 sums φ/ξ over the
// pair only, the standard form over all classes: the same for two classes).
//
// Entry points of ClassClosures (the family shape): closures(state) → ClassCoefficients,
// closures.with_derivatives(state) → ClassCoefficientsWithDerivatives (∂β_i/∂w_i, ∂β_i/∂φ_m,
// ∂ζ_ik/∂φ_m, ∂ζ_ik/∂|v_k − v_i|), closures.checked(state) and closures.checked_with_derivatives(state)
// (std::domain_error naming the argument and its value). No allocation, O(ν²) work per cell
// (O(ν³) with derivatives), thread-safe.
//
// References: Mazzei, L., Lettieri, P. (2007), Chem. Eng. Sci. 62, 6129–6142,
// doi:10.1016/j.ces.2007.06.028 (the drag); Syamlal, M. (1987), DOE/MC/21353-2373 (the solid–solid
// drag); Lebowitz, J.L. (1964), Phys. Rev. 133, A895–A899, doi:10.1103/PhysRev.133.A895 (g_ik); the
// model: Mazzei, L. (2008), PhD thesis, UCL, Ch. 6 (seed 000).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../core/vector3.hpp"
#include "../drag/drag_law.hpp"
#include "../drag/mazzei_lettieri.hpp"
#include "../kinetic_theory/mixture_radial_distribution.hpp"
#include "../kinetic_theory/solid_solid_drag.hpp"
#include "../properties.hpp"

namespace fluidbed::polydisperse {

template <class Drag = drag::MazzeiLettieri, class RadialDistribution = kinetic_theory::Lebowitz>
struct ClassClosures;

// The state of one cell of a multi-fluid model with at most N solids classes, of which the first
// `classes` are used (the rest are ignored).
template <class T, std::size_t N>
struct MultiFluidState {
  std::size_t classes;                   // ν, 1 ≤ ν ≤ N
  std::array<T, N> volume_fractions;     // φ_i ≥ 0 per unit suspension volume, Σ φ_i < 1
  std::array<T, N> diameters;            // ξ_i > 0 [m], also where φ_i = 0 (a DQMOM node)
  std::array<T, N> densities;            // ρ_i > 0 [kg m⁻³], material density
  std::array<Vector3<T>, N> velocities;  // v_i [m s⁻¹]
  Fluid<T> fluid;                        // ρ_f, μ_f
  Vector3<T> fluid_velocity;             // u [m s⁻¹], the gas's (phase-averaged) velocity
};

// ε = 1 − Σ_i φ_i over the state's classes.
template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE constexpr T voidage(const MultiFluidState<T, N>& s) {
  T total(0);
  for (std::size_t i = 0; i < s.classes && i < N; ++i) total += s.volume_fractions[i];
  return T(1) - total;
}

// β_i with its derivatives, in one convention.
template <class T, std::size_t N>
struct GasParticleDerivatives {
  T value{};                     // β_i [kg m⁻³ s⁻¹]
  T d_slip{};                    // ∂β_i/∂w_i at fixed fractions (+∞ at w_i = 0 for laws with √Re, as drag/)
  std::array<T, N> d_fractions{};  // ∂β_i/∂φ_m at fixed slips, ε = 1 − Σ φ (0 for m ≥ ν)
};

// β_i with derivatives in either convention (drag::DragCoefficientWithDerivatives for a class of
// the mixture): the conversion uses β_pg = ε β_cl and ∂ε/∂φ_m = −1.
template <class T, std::size_t N>
class GasParticleCoefficientWithDerivatives {
 public:
  FLUIDBED_HOST_DEVICE constexpr GasParticleCoefficientWithDerivatives(drag::Buoyancy native,
                                                                       const GasParticleDerivatives<T, N>& beta,
                                                                       T voidage, T slip, std::size_t classes)
      : native_(native), beta_(beta), voidage_(voidage), slip_(slip), classes_(classes) {}

  // β_i for classical buoyancy −φ_i ρ_f g.
  FLUIDBED_HOST_DEVICE constexpr GasParticleDerivatives<T, N> classical() const {
    if (native_ == drag::Buoyancy::classical) return beta_;
    const T e = voidage_;  // β_cl = β_pg/ε: ∂β_cl/∂φ_m = (∂β_pg/∂φ_m + β_cl)/ε
    GasParticleDerivatives<T, N> r{beta_.value / e, beta_.d_slip / e, {}};
    for (std::size_t m = 0; m < classes_ && m < N; ++m) r.d_fractions[m] = (beta_.d_fractions[m] + r.value) / e;
    return r;
  }
  // β_i for buoyancy −φ_i ∇p (seed 000 eq. 6.11), = ε β_i,cl.
  FLUIDBED_HOST_DEVICE constexpr GasParticleDerivatives<T, N> pressure_gradient() const {
    if (native_ == drag::Buoyancy::pressure_gradient) return beta_;
    const T e = voidage_;  // β_pg = ε β_cl: ∂β_pg/∂φ_m = ε ∂β_cl/∂φ_m − β_cl
    GasParticleDerivatives<T, N> r{e * beta_.value, e * beta_.d_slip, {}};
    for (std::size_t m = 0; m < classes_ && m < N; ++m) r.d_fractions[m] = e * beta_.d_fractions[m] - beta_.value;
    return r;
  }
  FLUIDBED_HOST_DEVICE constexpr GasParticleDerivatives<T, N> in(drag::Buoyancy convention) const {
    return convention == drag::Buoyancy::classical ? classical() : pressure_gradient();
  }
  // ∂(β_i w_i)/∂w_i in the given convention: finite at w_i = 0, where it equals β_i.
  FLUIDBED_HOST_DEVICE constexpr T force_slip_derivative(drag::Buoyancy convention) const {
    const GasParticleDerivatives<T, N> b = in(convention);
    return slip_ > T(0) ? b.value + slip_ * b.d_slip : b.value;
  }
  FLUIDBED_HOST_DEVICE constexpr drag::DragCoefficient<T> coefficient() const {
    return drag::DragCoefficient<T>(native_, beta_.value, voidage_);
  }

 private:
  drag::Buoyancy native_;
  GasParticleDerivatives<T, N> beta_;
  T voidage_;
  T slip_;
  std::size_t classes_;
};

// ζ_ik with its derivatives.
template <class T, std::size_t N>
struct SolidSolidDerivatives {
  T value{};                       // ζ_ik [kg m⁻³ s⁻¹]
  T d_relative_speed{};            // ∂ζ_ik/∂|v_k − v_i| at fixed fractions
  std::array<T, N> d_fractions{};  // ∂ζ_ik/∂φ_m (through φ_i φ_k and g_ik) at fixed speed (0 for m ≥ ν)
};

template <class T, std::size_t N>
class ClassCoefficientsWithDerivatives;

namespace detail {

// |a − b|.
template <class T>
FLUIDBED_HOST_DEVICE T distance(const Vector3<T>& a, const Vector3<T>& b) {
  using std::sqrt;
  const Vector3<T> d = difference(a, b);
  return sqrt(dot(d, d));
}

// What both sets of coefficients carry besides the coefficients: the drag law's native
// convention, the class count, ε, the slips and the pairs' relative speeds, from the state.
template <class T, std::size_t N>
class ClassKinematics {
 public:
  constexpr ClassKinematics() = default;
  FLUIDBED_HOST_DEVICE ClassKinematics(const MultiFluidState<T, N>& s, drag::Buoyancy native)
      : native_(native), classes_(s.classes), voidage_(polydisperse::voidage(s)) {
    for (std::size_t i = 0; i < s.classes; ++i) {
      slip_[i] = distance(s.fluid_velocity, s.velocities[i]);
      for (std::size_t k = i + 1; k < s.classes; ++k)
        speed_[i][k] = speed_[k][i] = distance(s.velocities[k], s.velocities[i]);
    }
  }

  FLUIDBED_HOST_DEVICE constexpr std::size_t classes() const { return classes_; }
  // ε = 1 − Σ φ_i.
  FLUIDBED_HOST_DEVICE constexpr T voidage() const { return voidage_; }
  // w_i = |u − v_i|.
  FLUIDBED_HOST_DEVICE constexpr T slip(std::size_t i) const { return slip_[i]; }
  // |v_k − v_i|.
  FLUIDBED_HOST_DEVICE constexpr T relative_speed(std::size_t i, std::size_t k) const { return speed_[i][k]; }

 protected:
  drag::Buoyancy native_ = drag::Buoyancy::classical;
  std::size_t classes_ = 0;
  T voidage_{};
  std::array<T, N> slip_{};
  std::array<std::array<T, N>, N> speed_{};
};

}  // namespace detail

// The coefficients of one cell. The gas–particle β_i are given only through
// drag::DragCoefficient, whose caller names the convention.
template <class T, std::size_t N>
class ClassCoefficients : public detail::ClassKinematics<T, N> {
 public:
  constexpr ClassCoefficients() = default;

  // β_i: the force of the gas on class i per unit suspension volume is β_i (u − v_i).
  FLUIDBED_HOST_DEVICE constexpr drag::DragCoefficient<T> gas_particle(std::size_t i) const {
    return drag::DragCoefficient<T>(this->native_, beta_[i], this->voidage_);
  }
  // ζ_ik = ζ_ki: the force of class k on class i per unit suspension volume is ζ_ik (v_k − v_i).
  FLUIDBED_HOST_DEVICE constexpr T solid_solid(std::size_t i, std::size_t k) const { return zeta_[i][k]; }

 private:
  template <class, class>
  friend struct ClassClosures;
  friend class ClassCoefficientsWithDerivatives<T, N>;

  FLUIDBED_HOST_DEVICE constexpr explicit ClassCoefficients(const detail::ClassKinematics<T, N>& kinematics)
      : detail::ClassKinematics<T, N>(kinematics) {}

  std::array<T, N> beta_{};  // native convention
  std::array<std::array<T, N>, N> zeta_{};
};

// The coefficients of one cell with their derivatives.
template <class T, std::size_t N>
class ClassCoefficientsWithDerivatives : public detail::ClassKinematics<T, N> {
 public:
  constexpr ClassCoefficientsWithDerivatives() = default;

  FLUIDBED_HOST_DEVICE constexpr GasParticleCoefficientWithDerivatives<T, N> gas_particle(std::size_t i) const {
    return GasParticleCoefficientWithDerivatives<T, N>(this->native_, beta_[i], this->voidage_, this->slip_[i],
                                                       this->classes_);
  }
  FLUIDBED_HOST_DEVICE constexpr const SolidSolidDerivatives<T, N>& solid_solid(std::size_t i, std::size_t k) const {
    return zeta_[i][k];
  }
  // The values alone.
  FLUIDBED_HOST_DEVICE constexpr ClassCoefficients<T, N> coefficients() const {
    ClassCoefficients<T, N> r(*this);
    for (std::size_t i = 0; i < N; ++i) {
      r.beta_[i] = beta_[i].value;
      for (std::size_t k = 0; k < N; ++k) r.zeta_[i][k] = zeta_[i][k].value;
    }
    return r;
  }

 private:
  template <class, class>
  friend struct ClassClosures;

  FLUIDBED_HOST_DEVICE constexpr explicit ClassCoefficientsWithDerivatives(
      const detail::ClassKinematics<T, N>& kinematics)
      : detail::ClassKinematics<T, N>(kinematics) {}

  std::array<GasParticleDerivatives<T, N>, N> beta_{};  // native convention
  std::array<std::array<SolidSolidDerivatives<T, N>, N>, N> zeta_{};
};

namespace detail {

// The domains of the state's arguments, declared once for the hot path's assertion and the
// checked path's exceptions: φ_i ≥ 0, ξ_i, ρ_i, ρ_f, μ_f > 0, Σ φ_i ∈ [0, 1) (ε ∈ (0, 1]), every
// velocity component finite, 1 ≤ ν ≤ N.
template <class T>
struct StateDomain {
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> volume_fraction() { return domains::non_negative<T>(); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> positive() { return domains::positive<T>(); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> total_fraction() { return domains::closed_open(T(0), T(1)); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> velocity() { return domains::finite<T>(); }
};

template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE constexpr bool within(const MultiFluidState<T, N>& s) {
  using Domain = StateDomain<T>;
  if (s.classes < 1 || s.classes > N) return false;
  if (!Domain::positive().contains(s.fluid.density) || !Domain::positive().contains(s.fluid.viscosity)) return false;
  for (int c = 0; c < 3; ++c)
    if (!Domain::velocity().contains(s.fluid_velocity[c])) return false;
  T total(0);
  for (std::size_t i = 0; i < s.classes; ++i) {
    if (!Domain::volume_fraction().contains(s.volume_fractions[i]) || !Domain::positive().contains(s.diameters[i]) ||
        !Domain::positive().contains(s.densities[i]))
      return false;
    for (int c = 0; c < 3; ++c)
      if (!Domain::velocity().contains(s.velocities[i][c])) return false;
    total += s.volume_fractions[i];
  }
  return Domain::total_fraction().contains(total);
}

// Throws as the checked entry points do, naming the first argument out of its domain.
template <class T, std::size_t N>
void require_within(std::string_view function, const MultiFluidState<T, N>& s) {
  using Domain = StateDomain<T>;
  if (s.classes < 1 || s.classes > N)
    fluidbed::detail::throw_domain_error(function, "classes", s.classes,
                                         "must lie in [1, N], N = " + std::to_string(N));
  require_in(function, "fluid.density", s.fluid.density, Domain::positive());
  require_in(function, "fluid.viscosity", s.fluid.viscosity, Domain::positive());
  require_finite_elements(function, "fluid_velocity", s.fluid_velocity);
  T total(0);
  for (std::size_t i = 0; i < s.classes; ++i) {
    require_in(function, indexed_argument("volume_fractions", i), s.volume_fractions[i], Domain::volume_fraction());
    require_in(function, indexed_argument("diameters", i), s.diameters[i], Domain::positive());
    require_in(function, indexed_argument("densities", i), s.densities[i], Domain::positive());
    require_finite_elements(function, indexed_argument("velocities", i), s.velocities[i]);
    total += s.volume_fractions[i];
  }
  require_in(function, "sum of volume_fractions", total, Domain::total_fraction());
}

// The state as text, for the messages of require_finite_result.
template <class T, std::size_t N>
std::string describe_state(const MultiFluidState<T, N>& s) {
  using fluidbed::detail::number_text;
  const auto list = [&s](const std::array<T, N>& values) {
    std::string text = "{";
    for (std::size_t i = 0; i < s.classes; ++i) text += (i ? ", " : "") + number_text(values[i]);
    return text + "}";
  };
  const auto vector = [](const Vector3<T>& v) {
    return "{" + number_text(v[0]) + ", " + number_text(v[1]) + ", " + number_text(v[2]) + "}";
  };
  std::string velocities = "{";
  for (std::size_t i = 0; i < s.classes; ++i) velocities += (i ? ", " : "") + vector(s.velocities[i]);
  return "state {classes = " + number_text(s.classes) + ", volume_fractions = " + list(s.volume_fractions) +
         ", diameters = " + list(s.diameters) + ", densities = " + list(s.densities) +
         ", velocities = " + velocities + "}, fluid.density = " + number_text(s.fluid.density) +
         ", fluid.viscosity = " + number_text(s.fluid.viscosity) + ", fluid_velocity = " + vector(s.fluid_velocity) +
         "}";
}

// The voidage at which the per-class law is evaluated: ε, or the largest T below 1 where ε = 1
// (β_law/(1 − ε) is 0/0 there).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T law_voidage(const T& voidage) {
  return voidage < T(1) ? voidage : T(1) - std::numeric_limits<T>::epsilon() / 2;
}

}  // namespace detail

// The per-class closures of seed 000 Ch. 6 as one value type: a monodisperse drag law extended
// per class, a mixture radial distribution and Syamlal's solid–solid drag with restitution e and
// friction C_f. ClassClosures<>{} is seed 000 §6.5's set: Mazzei–Lettieri drag, Lebowitz g_ik,
// e = 0.97, C_f = 0.15. Drag: any drag::DragLaw; RadialDistribution: any
// kinetic_theory::MixtureRadialDistribution (Lebowitz, Mansoori, ModifiedMansoori).
template <class Drag, class RadialDistribution>
struct ClassClosures {
  Drag drag_law{};
  RadialDistribution radial_distribution{};
  kinetic_theory::SyamlalSolidSolidDrag solid_solid_drag{0.15};  // C_f (seed 000 §6.5)
  double restitution = 0.97;                                       // e, every pair (seed 000 §6.5)

  constexpr std::string_view name() const { return "ClassClosures"; }
  constexpr std::string_view reference() const {
    return "Mazzei, L. (2008) PhD thesis, University College London, Ch. 6 (eqs. 6.11-6.16); per class the drag "
           "law's reference (Mazzei, L., Lettieri, P. (2007) Chem. Eng. Sci. 62, 6129-6142, "
           "doi:10.1016/j.ces.2007.06.028 by default), Syamlal, M. (1987) DOE/MC/21353-2373, and the radial "
           "distribution's (Lebowitz, J.L. (1964) Phys. Rev. 133, A895-A899, doi:10.1103/PhysRev.133.A895 by "
           "default)";
  }
  // No range of its own: the per-class extension was not fitted to polydisperse data (seed 002
  // §VI(i): monodisperse laws used per class are off by up to a factor 5 at a diameter ratio
  // 1:4); the component laws' validity() applies.
  constexpr Validity<0> validity() const { return {}; }
  // e ∈ [0, 1]; the friction coefficient's domain is solid_solid_drag's.
  constexpr Arguments<double, 1> parameter_domain() const {
    return {{{"restitution", restitution, domains::closed(0.0, 1.0)}}};
  }

  // Hot path. Preconditions (asserted in debug builds): 1 ≤ ν ≤ N, φ_i ≥ 0, Σ φ_i < 1, ξ_i, ρ_i,
  // ρ_f, μ_f > 0, every velocity component finite, every law's parameters in their domain.
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassCoefficients<T, N> operator()(const MultiFluidState<T, N>& s) const {
    FLUIDBED_EXPECTS(detail::within(s) && parameters_within<T>());
    ClassCoefficients<T, N> r(detail::ClassKinematics<T, N>(s, Drag::native_buoyancy));
    const T law_voidage = detail::law_voidage(r.voidage());
    const T solids = T(1) - law_voidage;
    for (std::size_t i = 0; i < s.classes; ++i) {
      const T beta = drag_law(drag::DragState<T>{law_voidage, r.slip(i), s.fluid, s.diameters[i]})
                         .in(Drag::native_buoyancy);
      r.beta_[i] = s.volume_fractions[i] * (beta / solids);
    }
    const std::span<const T> fractions(s.volume_fractions.data(), s.classes);
    const std::span<const T> diameters(s.diameters.data(), s.classes);
    for (std::size_t i = 0; i < s.classes; ++i)
      for (std::size_t k = i + 1; k < s.classes; ++k)
        r.zeta_[i][k] = r.zeta_[k][i] = pair_drag(fractions, diameters, s.densities, i, k, r.relative_speed(i, k));
    return r;
  }

  // Hot path with derivatives (same preconditions): ∂β_i/∂w_i, ∂β_i/∂φ_m, ∂ζ_ik/∂φ_m and
  // ∂ζ_ik/∂|v_k − v_i|. β_i's from the law's own with_derivatives (∂/∂ε, ∂/∂w) by the chain rule
  //   ∂β_i/∂φ_m = δ_im B_i − φ_i ∂B_i/∂ε,  ∂B_i/∂ε = (∂β_law/∂ε + B_i)/(1 − ε);
  // ζ_ik's from one dual-number evaluation of g_ik and K_ik per pair. Where φ_i = 0, β_i = 0,
  // ∂β_i/∂w_i = 0 and ∂β_i/∂φ_i = B_i (the dual numbers' convention 0·∞ = 0, core/dual.hpp).
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassCoefficientsWithDerivatives<T, N> with_derivatives(const MultiFluidState<T, N>& s) const {
    FLUIDBED_EXPECTS(detail::within(s) && parameters_within<T>());
    using fluidbed::detail::times;
    ClassCoefficientsWithDerivatives<T, N> r(detail::ClassKinematics<T, N>(s, Drag::native_buoyancy));
    const T law_voidage = detail::law_voidage(r.voidage());
    const T solids = T(1) - law_voidage;
    for (std::size_t i = 0; i < s.classes; ++i) {
      const drag::DragDerivatives<T> law =
          drag_law.with_derivatives(drag::DragState<T>{law_voidage, r.slip(i), s.fluid, s.diameters[i]})
              .in(Drag::native_buoyancy);
      const T per_fraction = law.value / solids;                       // B_i
      const T per_fraction_d_voidage = (law.d_voidage + per_fraction) / solids;  // ∂B_i/∂ε
      const T phi = s.volume_fractions[i];
      GasParticleDerivatives<T, N>& b = r.beta_[i];
      b.value = phi * per_fraction;
      b.d_slip = times(phi, law.d_slip / solids);
      for (std::size_t m = 0; m < s.classes; ++m)
        b.d_fractions[m] = (m == i ? per_fraction : T(0)) - times(phi, per_fraction_d_voidage);
    }
    using D = Dual<T, int(N) + 1>;  // ∂/∂φ_0 … ∂/∂φ_(N−1), ∂/∂|Δv|
    std::array<D, N> dual_fractions{};
    for (std::size_t m = 0; m < s.classes; ++m) dual_fractions[m] = D::variable(s.volume_fractions[m], int(m));
    const std::span<const D> fractions(dual_fractions.data(), s.classes);
    const std::span<const T> diameters(s.diameters.data(), s.classes);
    for (std::size_t i = 0; i < s.classes; ++i)
      for (std::size_t k = i + 1; k < s.classes; ++k) {
        const D zeta = pair_drag(fractions, diameters, s.densities, i, k, D::variable(r.relative_speed(i, k), int(N)));
        SolidSolidDerivatives<T, N>& z = r.zeta_[i][k];
        z.value = zeta.value;
        z.d_relative_speed = zeta.derivative[N];
        for (std::size_t m = 0; m < s.classes; ++m) z.d_fractions[m] = zeta.derivative[m];
        r.zeta_[k][i] = z;
      }
    return r;
  }

  // Checked entry point: throws std::domain_error naming the first argument or parameter out of
  // its domain and its value ("fluidbed::polydisperse::ClassClosures: argument 'volume_fractions[1]'
  // = -0.5 is out of domain (must be finite and >= 0)"), and, for a state inside the domain, naming
  // a β_i (either convention) or ζ_ik that is not finite in T, and the state.
  template <class T, std::size_t N>
  ClassCoefficients<T, N> checked(const MultiFluidState<T, N>& s) const {
    const std::string function = function_name();
    require_valid<T>(function, s);
    const ClassCoefficients<T, N> r = (*this)(s);
    const auto describe = [&s] { return detail::describe_state(s); };
    for (std::size_t i = 0; i < s.classes; ++i) {
      const drag::DragCoefficient<T> beta = r.gas_particle(i);
      require_finite_result(function, indexed_argument("beta.classical", i), beta.classical(), describe);
      require_finite_result(function, indexed_argument("beta.pressure_gradient", i), beta.pressure_gradient(),
                            describe);
      for (std::size_t k = i + 1; k < s.classes; ++k)
        require_finite_result(function, pair_name("zeta", i, k), r.solid_solid(i, k), describe);
    }
    return r;
  }

  // Checked entry point with derivatives: the checks of `checked`, and every derivative finite
  // (∂β_i/∂w_i may be the documented +∞ at w_i = 0).
  template <class T, std::size_t N>
  ClassCoefficientsWithDerivatives<T, N> checked_with_derivatives(const MultiFluidState<T, N>& s) const {
    const std::string function = function_name();
    require_valid<T>(function, s);
    const ClassCoefficientsWithDerivatives<T, N> r = with_derivatives(s);
    const auto describe = [&s] { return detail::describe_state(s); };
    for (std::size_t i = 0; i < s.classes; ++i) {
      const GasParticleCoefficientWithDerivatives<T, N> beta = r.gas_particle(i);
      for (drag::Buoyancy b : {drag::Buoyancy::classical, drag::Buoyancy::pressure_gradient}) {
        const std::string convention = b == drag::Buoyancy::classical ? "classical" : "pressure_gradient";
        const GasParticleDerivatives<T, N> d = beta.in(b);
        require_finite_result(function, indexed_argument("beta." + convention, i), d.value, describe);
        if (!(r.slip(i) == T(0) && d.d_slip == std::numeric_limits<T>::infinity()))
          require_finite_result(function, "d " + indexed_argument("beta." + convention, i) + "/d slip", d.d_slip,
                                describe);
        require_finite_result(function, "d (" + indexed_argument("beta." + convention, i) + " slip)/d slip",
                              beta.force_slip_derivative(b), describe);
        for (std::size_t m = 0; m < s.classes; ++m)
          require_finite_result(function,
                                "d " + indexed_argument("beta." + convention, i) + "/d " +
                                    indexed_argument("volume_fractions", m),
                                d.d_fractions[m], describe);
      }
      for (std::size_t k = i + 1; k < s.classes; ++k) {
        const SolidSolidDerivatives<T, N>& z = r.solid_solid(i, k);
        require_finite_result(function, pair_name("zeta", i, k), z.value, describe);
        require_finite_result(function, "d " + pair_name("zeta", i, k) + "/d relative_speed", z.d_relative_speed,
                              describe);
        for (std::size_t m = 0; m < s.classes; ++m)
          require_finite_result(function,
                                "d " + pair_name("zeta", i, k) + "/d " + indexed_argument("volume_fractions", m),
                                z.d_fractions[m], describe);
      }
    }
    return r;
  }

 private:
  // ζ_ik = K_ik(φ_i, φ_k, g_ik(φ), |Δv|) for a scalar S (T, or a dual number of the fractions).
  template <class S, class T, std::size_t N>
  FLUIDBED_HOST_DEVICE S pair_drag(std::span<const S> fractions, std::span<const T> diameters,
                                   const std::array<T, N>& densities, std::size_t i, std::size_t k,
                                   const S& speed) const {
    const S g = radial_distribution(fractions, diameters, i, k);
    return solid_solid_drag(fractions[i], fractions[k], Particles<T>{densities[i], diameters[i]},
                            Particles<T>{densities[k], diameters[k]}, T(restitution), g, speed);
  }

  // Every law's parameters in their domain: this set's, the drag law's, the radial
  // distribution's and the solid–solid drag's.
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr bool parameters_within() const {
    bool ok = within(parameter_domain()) && within(solid_solid_drag.parameter_domain()) &&
              within(parameter_domain_of<T>(drag_law));
    if constexpr (requires { radial_distribution.parameter_domain(); })
      ok = ok && within(radial_distribution.parameter_domain());
    return ok;
  }

  template <class T, std::size_t N>
  void require_valid(std::string_view function, const MultiFluidState<T, N>& s) const {
    detail::require_within(function, s);
    fluidbed::require_within(function, parameter_domain());
    fluidbed::require_within(function, solid_solid_drag.parameter_domain());
    fluidbed::require_within(function, parameter_domain_of<T>(drag_law));
    if constexpr (requires { radial_distribution.parameter_domain(); })
      fluidbed::require_within(function, radial_distribution.parameter_domain());
  }

  std::string function_name() const { return "polydisperse::" + std::string(name()); }

  static std::string pair_name(std::string_view what, std::size_t i, std::size_t k) {
    return std::string(what) + '[' + std::to_string(i) + "][" + std::to_string(k) + ']';
  }
};

}  // namespace fluidbed::polydisperse
