// fluidbed — the van der Hoef / Beetstra lattice-Boltzmann drag family: Stokes flow
// (2005), finite Reynolds number (2007), and the polydisperse correction for a species of
// a mixture.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <sstream>
#include <string>
#include <string_view>

#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../properties.hpp"
#include "dimensionless_force.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

namespace detail {

// van der Hoef et al. (2005) fit of their Stokes-flow lattice-Boltzmann data for random
// monodisperse arrays, in the drag-only normalisation (dimensionless_force.hpp):
//   F0(φ) = 10 φ/(1 − φ)² + (1 − φ)² (1 + 1.5 √φ).
// F0(0) = 1 (Stokes drag of an isolated sphere). It is also the Stokes term of Beetstra
// et al. (2007) and Tang et al. (2015), and exactly the A term of seed 002 eq. (19):
// A (1 − ε)/(18 ε²) = F0 (an algebraic identity; checked to 10 digits for 0.01 ≤ φ ≤ 0.6).
template <class S>
FLUIDBED_HOST_DEVICE S van_der_hoef_stokes_force(const S& phi) {
  using std::sqrt;
  using T = value_type_of<S>;
  const S eps = 1 - phi;
  return 10 * phi / (eps * eps) + eps * eps * (1 + T(1.5) * sqrt(phi));
}

}  // namespace detail

// van der Hoef, M.A., Beetstra, R., Kuipers, J.A.M. (2005), "Lattice-Boltzmann simulations
// of low-Reynolds-number flow past mono- and bidisperse arrays of spheres: results for the
// permeability and drag force", J. Fluid Mech. 528, 233–254, doi:10.1017/S0022112004003295:
//
//   β_pressure_gradient = 18 μ_f ε φ F0(φ) / d²,
//   F0(φ) = 10 φ/ε² + ε² (1 + 1.5 √φ)          (φ = 1 − ε; drag-only normalisation)
//
// Native convention: pressure_gradient. No Reynolds number: creeping (Stokes) flow, β is
// independent of the slip. Seed 002: the Stokes part of eq. (19), A = 180 + 18 ε⁴ (1 +
// 1.5 √φ)/φ, equals 18 ε² F0/φ exactly. Limits: β/(18 μ_f φ/d²) → 1 as ε → 1 (isolated
// sphere); β = 0 at ε = 1.
// Validity: the fitted data, random arrays 0.1 ≤ φ ≤ 0.6, and Re ≲ 1 (at Re = 1 the
// inertial correction of Beetstra 2007 adds 0.3 % at φ = 0.4 and 4 % at φ = 0.05).
struct VanDerHoef2005 : DragLaw<VanDerHoef2005> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;

  constexpr std::string_view name() const { return "VanDerHoef2005"; }
  constexpr std::string_view reference() const {
    return "van der Hoef, M.A., Beetstra, R., Kuipers, J.A.M. (2005) J. Fluid Mech. 528, 233-254, "
           "doi:10.1017/S0022112004003295";
  }
  constexpr ValidityRange validity() const { return {0.4, 0.9, 0.0, 1.0}; }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& /*slip*/, const Fluid<T>& fluid,
                                     const T& diameter) const {
    return beta_from_drag_force(detail::van_der_hoef_stokes_force(S(1 - voidage)), voidage, fluid.viscosity,
                                diameter);
  }
};

// Beetstra, R., van der Hoef, M.A., Kuipers, J.A.M. (2007), "Drag force of intermediate
// Reynolds number flow past mono- and bidisperse arrays of spheres", AIChE J. 53, 489–501,
// doi:10.1002/aic.11065:
//
//   F(φ, Re) = F0(φ) + 0.413 Re/(24 ε²) · [1/ε + 3 ε φ + 8.4 Re^−0.343]
//                                       / [1 + 10^(3φ) Re^(−(1 + 4φ)/2)]
//   β_pressure_gradient = 18 μ_f ε φ F / d²,    Re = ρ_f ε w d / μ_f (superficial slip),
//
// F0 the van der Hoef (2005) Stokes term above. Native convention: pressure_gradient.
//
// Seed 002 eq. (19) is misprinted: it writes the Ergun-form B as
// 0.31 (1/ε + 3εφ) + 8.4 Re^−0.343, leaving 8.4 Re^−0.343 outside the factor 0.31 (=
// 18 · 0.413/24 rounded). The published form, used here and by OpenFOAM and MFiX, has
// 0.413/24 multiplying all three terms; the misprint changes β by up to +89 % (φ = 0.1,
// Re = 100). The exact 0.413/24 is used, not the rounded 0.31.
//
// Evaluated form. Multiplying numerator and denominator by Re^p, p = (1 + 4φ)/2,
//   F = F0 + 0.413/(24 ε²) · [Re (1/ε + 3εφ) + 8.4 Re^0.657] · Re^p / (Re^p + 10^(3φ)),
// which has no negative power of Re: F(φ, 0) = F0 exactly (the van der Hoef 2005 law),
// and F → F0 continuously as Re → 0 (the inertial term is O(Re^(1.157 + 2φ))).
// Validity: the fitted LB data, 0.1 ≤ φ ≤ 0.6 and Re ≤ 1000, "within 8 %" (seed 002
// §II.D). It is a fit for arrays, not for isolated spheres: as φ → 0 it is 16 % above
// Schiller–Naumann at Re = 100 and 68 % above at Re = 1000 (F(0, Re) = 5.27 and 30.8
// against 4.55 and 18.3).
struct Beetstra2007 : DragLaw<Beetstra2007> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;

  constexpr std::string_view name() const { return "Beetstra2007"; }
  constexpr std::string_view reference() const {
    return "Beetstra, R., van der Hoef, M.A., Kuipers, J.A.M. (2007) AIChE J. 53, 489-501, doi:10.1002/aic.11065";
  }
  constexpr ValidityRange validity() const { return {0.4, 0.9, 0.0, 1000.0}; }

  // F(φ, Re), drag-only normalisation, Re = ρ_f ε w d / μ_f.
  template <class S>
  FLUIDBED_HOST_DEVICE static S dimensionless_force(const S& phi, const S& re) {
    using std::pow;
    using T = value_type_of<S>;
    const S eps = 1 - phi;
    const S re_p = pow(re, S(T(0.5) + 2 * phi));
    const S inertial =
        (re * (1 / eps + 3 * eps * phi) + T(8.4L) * pow(re, T(0.657L))) * (re_p / (re_p + pow(T(10), 3 * phi)));
    return detail::van_der_hoef_stokes_force(phi) + T(0.413L) / 24 / (eps * eps) * inertial;
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid, const T& diameter) const {
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    return beta_from_drag_force(dimensionless_force(S(1 - voidage), re), voidage, fluid.viscosity, diameter);
  }
};

// ------------------------------------------------------------------------------ polydisperse

// One particle species of a mixture.
template <class T>
struct Species {
  T volume_fraction;  // φ_i, the species' solids volume fraction (>= 0)
  T diameter;         // d_i [m]
};

// The state for the drag on species i of a mixture. The voidage is ε = 1 − Σ_j φ_j, so
// `mixture` lists every solids species of the cell.
template <class T>
struct PolydisperseDragState {
  std::span<const Species<T>> mixture;
  std::size_t species;  // i, index into mixture
  T slip;               // w_i = |u_f − v_i| [m s⁻¹], interstitial slip of species i
  Fluid<T> fluid;
};

// The moments of a mixture the correction needs.
template <class T>
struct MixtureMoments {
  T solids_fraction;  // φ = Σ_j φ_j
  T sauter_diameter;  // <d> = 1 / Σ_j (x_j / d_j), x_j = φ_j / φ
};

template <class T>
FLUIDBED_HOST_DEVICE constexpr MixtureMoments<T> mixture_moments(std::span<const Species<T>> mixture) {
  T phi(0);
  T surface(0);  // Σ φ_j / d_j
  for (const Species<T>& s : mixture) {
    phi += s.volume_fraction;
    surface += s.volume_fraction / s.diameter;
  }
  return {phi, phi / surface};
}

namespace detail {

// The state as text, for the messages of the checked entry point: every species, the species
// asked for, its slip and the fluid.
template <class T>
std::string describe_state(const PolydisperseDragState<T>& s) {
  std::ostringstream text;
  text.precision(17);
  text << "state {mixture = {";
  for (std::size_t j = 0; j < s.mixture.size(); ++j)
    text << (j ? ", " : "") << "{" << s.mixture[j].volume_fraction << ", " << s.mixture[j].diameter << "}";
  text << "}, species = " << s.species << ", slip = " << s.slip << ", fluid.density = " << s.fluid.density
       << ", fluid.viscosity = " << s.fluid.viscosity << "}";
  return text.str();
}

}  // namespace detail

// β of one species in both conventions. For a polydisperse mixture the two are NOT
// related by the factor ε species by species (see BeetstraPolydisperse), so both are
// carried and the caller names the one its momentum equations use.
template <class S>
struct PolydisperseBeta {
  S classical;
  S pressure_gradient;
};

template <class T>
class PolydisperseDragCoefficient {
 public:
  FLUIDBED_HOST_DEVICE constexpr explicit PolydisperseDragCoefficient(const PolydisperseBeta<T>& beta) : beta_(beta) {}

  // β_i for buoyancy −φ_i ρ_f g (MFiX model B).
  FLUIDBED_HOST_DEVICE constexpr T classical() const { return beta_.classical; }
  // β_i for buoyancy −φ_i ∇p (MFiX model A, OpenFOAM).
  FLUIDBED_HOST_DEVICE constexpr T pressure_gradient() const { return beta_.pressure_gradient; }
  FLUIDBED_HOST_DEVICE constexpr T in(Buoyancy convention) const {
    return convention == Buoyancy::classical ? classical() : pressure_gradient();
  }

 private:
  PolydisperseBeta<T> beta_;
};

// β_i with ∂β_i/∂ε (at fixed composition x_j = φ_j/φ and diameters) and ∂β_i/∂w_i.
template <class T>
class PolydisperseDragCoefficientWithDerivatives {
 public:
  FLUIDBED_HOST_DEVICE constexpr PolydisperseDragCoefficientWithDerivatives(const DragDerivatives<T>& classical,
                                                                            const DragDerivatives<T>& pressure_gradient,
                                                                            T slip)
      : classical_(classical), pressure_gradient_(pressure_gradient), slip_(slip) {}

  FLUIDBED_HOST_DEVICE constexpr DragDerivatives<T> classical() const { return classical_; }
  FLUIDBED_HOST_DEVICE constexpr DragDerivatives<T> pressure_gradient() const { return pressure_gradient_; }
  FLUIDBED_HOST_DEVICE constexpr DragDerivatives<T> in(Buoyancy convention) const {
    return convention == Buoyancy::classical ? classical_ : pressure_gradient_;
  }
  // ∂(β_i w_i)/∂w_i: finite at w_i = 0, where it equals β_i.
  FLUIDBED_HOST_DEVICE constexpr T force_slip_derivative(Buoyancy convention) const {
    const DragDerivatives<T> b = in(convention);
    return slip_ > T(0) ? b.value + slip_ * b.d_slip : b.value;
  }
  FLUIDBED_HOST_DEVICE constexpr PolydisperseDragCoefficient<T> coefficient() const {
    return PolydisperseDragCoefficient<T>({classical_.value, pressure_gradient_.value});
  }

 private:
  DragDerivatives<T> classical_;
  DragDerivatives<T> pressure_gradient_;
  T slip_;
};

// Beetstra et al. (2007) polydisperse drag on species i of a mixture (same reference as
// Beetstra2007, with its erratum; MFiX attributes the correction to van der Hoef et al. 2005):
//
//   <d> = 1/Σ_j (x_j/d_j)  (Sauter mean),  x_j = φ_j/φ,  y_i = d_i/<d>,
//   Re  = ρ_f ε <d> w_i / μ_f   (mean diameter, species slip),   F = Beetstra2007 F(φ, Re),
//   β_i,pressure_gradient = 18 μ_f ε φ_i F · y_i / d_i²                       (model A)
//   β_i,classical         = 18 μ_f   φ_i F · (ε y_i + φ y_i² + c ε y_i³) / d_i²  (model B)
//
// with c = 0.064. Seed 002 has no polydisperse formula (§VI(i) only says that the drag
// relations in use are wrong by up to a factor 5 for a diameter ratio 1:4); this is the form
// of the independent reference generator (tests/reference/drag_reference.py) and, for the
// factors, of MFiX's comment citing the erratum ("the correction factor differs for model
// A versus model B; the one for model A is found from the one for model B and neglects the
// y³ term"). The primary paper could not be consulted here.
//
// Why the two conventions differ. The normalised TOTAL force on a particle of species i
// (classical convention, pressure-gradient share included) is F_tot · (ε y_i + φ y_i²):
// the drag part grows with the particle's surface, ∝ d_i² (ε y_i), and the mean-pressure-
// gradient part with its volume, ∝ d_i³ (φ y_i²). Subtracting the pressure-gradient share
// φ_i/ε · Σ_j β_j,pg of each species from the total leaves exactly y_i (model A):
//   β_i,cl = β_i,pg + (φ_i/ε) Σ_j β_j,pg  (equal slips),
// which for one species is β_cl = β_pg/ε. For a mixture the conversion couples the
// species, so no single factor converts one convention into the other: both are returned.
//
// A reading that suggests itself, β_i,pg = 18 μ ε φ_i F f_i/d_i² with the model-B factor
// f_i, applies the total-force factor to the drag-only convention; it is not used. Its
// consistency check still holds in the right place: without the y³
// term Σ_i x_i f_i/y_i² = 1 (model B) and Σ_i x_i y_i/y_i² = 1 (model A), so the mixture's
// total drag equals the monodisperse Beetstra law at <d> in either convention. MFiX's
// extra 1/y_i² (it also uses d_i in the Stokes prefactor) double counts; not followed.
//
// The y³ term. 0.064 ε y_i³ is, per the secondary sources (the generator, MFiX), a fit term
// for the finite-Re bidisperse data. It makes the model-B total
// 1 + 0.064 ε Σ x_i y_i times the monodisperse law, i.e. (1 + 0.064 ε) for a single
// species: the published model B does NOT reduce to Beetstra2007 for a monodisperse
// mixture (6.4 % high as ε → 1). MFiX drops it for its first solids phase only.
// without_cubic_term() offers c = 0, whose model B is exactly consistent (and reduces
// to Beetstra2007); the published c = 0.064 is the default. Model A is y_i in both.
//
// Validity: bidisperse LB data with diameter ratios up to 1:4 (seed 002 §VI(i)),
// Re ≤ 1000 for the monodisperse F; φ and Re as Beetstra2007.
class BeetstraPolydisperse {
 public:
  static constexpr double published_cubic_coefficient = 0.064;

  constexpr BeetstraPolydisperse() = default;
  static constexpr BeetstraPolydisperse published() { return BeetstraPolydisperse(published_cubic_coefficient); }
  static constexpr BeetstraPolydisperse without_cubic_term() { return BeetstraPolydisperse(0.0); }

  constexpr double cubic_coefficient() const { return cubic_; }
  constexpr std::string_view name() const {
    return cubic_ == published_cubic_coefficient ? "Beetstra2007Polydisperse" : "Beetstra2007PolydisperseNoCubic";
  }
  constexpr std::string_view reference() const {
    return "Beetstra, R., van der Hoef, M.A., Kuipers, J.A.M. (2007) AIChE J. 53, 489-501, doi:10.1002/aic.11065, "
           "and erratum; van der Hoef, M.A., Beetstra, R., Kuipers, J.A.M. (2005) J. Fluid Mech. 528, 233-254, "
           "doi:10.1017/S0022112004003295";
  }
  constexpr ValidityRange validity() const { return {0.4, 0.9, 0.0, 1000.0}; }

  // Correction factors of species i, y = d_i/<d>: model A (pressure gradient) y;
  // model B (classical) ε y + φ y² + c ε y³.
  template <class S>
  FLUIDBED_HOST_DEVICE constexpr PolydisperseBeta<S> correction(const S& voidage, const S& y) const {
    const S phi = 1 - voidage;
    return {voidage * y * (1 + value_type_of<S>(cubic_) * y * y) + phi * y * y, y};
  }

  // The generic kernel: β_i in both conventions as functions of ε and w_i, at fixed
  // composition (x_i = φ_i/φ), species diameter d_i and Sauter mean <d>. Each is x_i times
  // the monodisperse β of diameter d_i, in that convention, with F replaced by F · factor.
  template <class S, class T>
  FLUIDBED_HOST_DEVICE PolydisperseBeta<S> native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                                       const T& sauter_diameter, const T& share,
                                                       const T& diameter) const {
    const S re = particle_reynolds(fluid, sauter_diameter, voidage, slip);
    const S force = Beetstra2007::dimensionless_force(S(1 - voidage), re);
    const PolydisperseBeta<S> f = correction(voidage, S(diameter / sauter_diameter));
    return {share * beta_from_drag_force(force * f.classical, voidage, fluid.viscosity, diameter) / voidage,
            share * beta_from_drag_force(force * f.pressure_gradient, voidage, fluid.viscosity, diameter)};
  }

  // Hot path. Preconditions (asserted in debug builds): species < mixture.size(), every
  // φ_j >= 0 and d_j > 0, 0 < Σ φ_j < 1, w_i >= 0, ρ_f, μ_f > 0. No allocation; O(N).
  template <class T>
  FLUIDBED_HOST_DEVICE PolydisperseDragCoefficient<T> operator()(const PolydisperseDragState<T>& s) const {
    const Prepared<T> p = prepare(s);
    return PolydisperseDragCoefficient<T>(
        native_beta(p.voidage, s.slip, s.fluid, p.moments.sauter_diameter, p.share, p.diameter));
  }

  // Hot path with ∂β_i/∂ε (composition fixed) and ∂β_i/∂w_i (same preconditions).
  template <class T>
  FLUIDBED_HOST_DEVICE PolydisperseDragCoefficientWithDerivatives<T> with_derivatives(
      const PolydisperseDragState<T>& s) const {
    using D = Dual<T, 2>;
    const Prepared<T> p = prepare(s);
    const PolydisperseBeta<D> b = native_beta(D::variable(p.voidage, 0), D::variable(s.slip, 1), s.fluid,
                                              p.moments.sauter_diameter, p.share, p.diameter);
    const auto unpack = [](const D& x) { return DragDerivatives<T>{x.value, x.derivative[0], x.derivative[1]}; };
    return {unpack(b.classical), unpack(b.pressure_gradient), s.slip};
  }

  // Checked entry point: throws std::domain_error naming the argument and its value, and, for a
  // valid state whose β_i is not finite in either convention (a subnormal d_j overflowing
  // φ_j/d_j, say), naming the result, its value and the state: a status, never ∞ or NaN.
  template <class T>
  PolydisperseDragCoefficient<T> checked(const PolydisperseDragState<T>& s) const {
    const std::string_view function = name();
    require_positive(function, "fluid.density", s.fluid.density);
    require_positive(function, "fluid.viscosity", s.fluid.viscosity);
    require_non_negative(function, "slip", s.slip);
    if (s.species >= s.mixture.size())
      fluidbed::detail::throw_domain_error(function, "species", s.species,
                                           "must be < mixture.size() = " + std::to_string(s.mixture.size()));
    for (std::size_t j = 0; j < s.mixture.size(); ++j) {
      const Species<T>& sp = s.mixture[j];
      const auto argument = [j](const char* member) { return "mixture[" + std::to_string(j) + "]." + member; };
      if (!(fluidbed::detail::is_finite_number(sp.volume_fraction) && sp.volume_fraction >= T(0)))
        require_non_negative(function, argument("volume_fraction"), sp.volume_fraction);
      if (!(fluidbed::detail::is_finite_number(sp.diameter) && sp.diameter > T(0)))
        require_positive(function, argument("diameter"), sp.diameter);
    }
    require_in_open(function, "sum of mixture volume fractions", mixture_moments(s.mixture).solids_fraction, T(0),
                    T(1));
    const PolydisperseDragCoefficient<T> beta = (*this)(s);
    detail::validate_result(function, beta, [&s] { return detail::describe_state(s); });
    return beta;
  }

 private:
  constexpr explicit BeetstraPolydisperse(double cubic) : cubic_(cubic) {}

  template <class T>
  struct Prepared {
    MixtureMoments<T> moments;
    T voidage;   // 1 − φ
    T share;     // x_i = φ_i/φ
    T diameter;  // d_i
  };

  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Prepared<T> prepare(const PolydisperseDragState<T>& s) {
    FLUIDBED_EXPECTS(s.species < s.mixture.size() && s.slip >= T(0));
    FLUIDBED_EXPECTS(s.fluid.density > T(0) && s.fluid.viscosity > T(0));
    const MixtureMoments<T> m = mixture_moments(s.mixture);
    FLUIDBED_EXPECTS(m.solids_fraction > T(0) && m.solids_fraction < T(1));
    const Species<T>& i = s.mixture[s.species];
    return {m, T(1) - m.solids_fraction, i.volume_fraction / m.solids_fraction, i.diameter};
  }

  double cubic_ = published_cubic_coefficient;
};

}  // namespace fluidbed::drag
