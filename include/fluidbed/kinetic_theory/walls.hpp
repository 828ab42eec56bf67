// fluidbed — wall boundary conditions of the solids phase, per wall face: the shear the wall
// exerts on the particles and the flux of granular energy through the wall, from the state of
// the solids at the face. Each law returns a WallConditions (below) and, with_derivatives, its
// exact partial derivatives in φ, Θ and the slip, for implicit use.
//
// Conventions (every law of this header)
// * State at the wall face: φ (`solid_fraction`), Θ (`granular_temperature`), g0 = g0(φ) (the
//   host's radial distribution, as elsewhere in kinetic_theory/), and the slip speed
//   u = |u_s − u_wall| ≥ 0 (`wall_slip`) [m s⁻¹], the magnitude of the tangential velocity
//   of the solids relative to the wall (any normal component is the host's no-penetration
//   condition). Material as in granular_state.hpp.
// * n is the unit normal pointing OUT of the bed, into the wall.
// * shear |τ_w| ≥ 0 [Pa]: the magnitude of the wall's tangential traction on the solids,
//   which opposes the slip: traction = −k u_slip, k = slip_coefficient [kg m⁻² s⁻¹] (Pa per
//   m s⁻¹). The momentum condition is μ_s ∂u_t/∂n = −k u_t, i.e. the Robin/partial-slip form
//   u_t + ℓ ∂u_t/∂n = 0 with the slip length ℓ = μ_s/k (velocity_robin, slip_length), μ_s the
//   solids shear viscosity per unit volume of suspension that the host's momentum equation
//   applies at the face.
// * energy_flux q_w [W m⁻²] is the flux of granular energy INTO the bed through the wall:
//   positive when the wall heats the particles (generation by slip wins), negative when it
//   cools them. It is q_w = generation − dissipation, each ≥ 0, and the condition on Θ is
//   κ_s ∂Θ/∂n = q_w (κ_s the conductivity, per unit volume of suspension, of the balance in
//   granular_state.hpp). dissipation = A Θ with A = dissipation_coefficient [kg m⁻² s⁻¹], so
//   the Robin form is ∂Θ/∂n = (generation − A Θ)/κ_s (temperature_robin).
// * Derivatives in Θ are exact for Θ > 0; at Θ = 0 the laws are ∝ √Θ and their Θ-slope is
//   infinite. Preconditions (asserted in debug builds; law.checked(…) throws
//   std::domain_error naming the argument): φ ∈ [0, 1), Θ ≥ 0, g0 > 0, u ≥ 0, material as in
//   granular_state.hpp, and each law's parameters as its parameter_domain says.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <string_view>

#include "../core/constants.hpp"
#include "../core/registry.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// What a wall law gives for one face (S a scalar, a Dual, or WallDerivatives<T>).
template <class S>
struct WallConditions {
  S shear;                    // |τ_w| [Pa], opposing the slip
  S slip_coefficient;         // k = |τ_w|/u [kg m⁻² s⁻¹]; traction on the solids = −k u_slip
  S energy_flux;              // q_w = generation − dissipation [W m⁻²], > 0 into the bed
  S generation;               // ≥ 0 [W m⁻²]
  S dissipation;              // ≥ 0 [W m⁻²]
  S dissipation_coefficient;  // A = dissipation/Θ [kg m⁻² s⁻¹]
};

// One quantity of WallConditions with its partial derivatives in the face's state.
template <class T>
struct WallDerivatives {
  T value;
  T d_solid_fraction;        // ∂/∂φ at fixed Θ, u (through g0(φ) as well)
  T d_granular_temperature;  // ∂/∂Θ
  T d_wall_slip;             // ∂/∂u
};

// A Robin condition on a face value x (a tangential velocity component, Θ):
//   ∂x/∂n = source − coefficient · x,   n out of the bed,
// coefficient [m⁻¹] ≥ 0 (OpenFOAM's partial-slip and mixed conditions call it c and impose it
// through the value fraction c/(c + 1/Δ), Δ the face-to-cell distance), source [unit of x per m].
// coefficient = 0 is the free-slip (zero-gradient) limit; the slip length is 1/coefficient.
template <class S>
struct RobinCondition {
  S coefficient;
  S source;
};

namespace detail {

// A state of Duals (φ, Θ, u) split into WallDerivatives.
template <class T>
FLUIDBED_HOST_DEVICE constexpr WallDerivatives<T> split_wall(const Dual<T, 3>& x) {
  return {x.value, x.derivative[0], x.derivative[1], x.derivative[2]};
}

// u ≥ 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> wall_slip(const T& u) {
  return {"wall_slip", u, domains::non_negative<T>()};
}

// e_w ∈ [0, 1].
FLUIDBED_HOST_DEVICE constexpr Argument<double> wall_restitution(double e_w) {
  return {"wall_restitution", e_w, domains::closed(0.0, 1.0)};
}

}  // namespace detail

// The shape law(φ, Θ, g0, u, material) of the wall laws (CRTP). Law provides
// kernel(φ, Θ, g0, u, material) → WallConditions<S>.
template <class Law>
struct WallLaw : KineticTheoryLaw<Law> {
  // φ ∈ [0, 1), Θ ≥ 0, g0 > 0, u ≥ 0, material as domain(GranularMaterial).
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 7> argument_domain(const T& phi, const T& theta, const T& g0,
                                                                          const T& wall_slip,
                                                                          const GranularMaterial<T>& m) {
    return join(Arguments<T, 4>{detail::solid_fraction(phi), detail::granular_temperature(theta),
                                detail::radial_distribution_value(g0), detail::wall_slip(wall_slip)},
                kinetic_theory::domain(m));
  }

  // Every quantity with ∂/∂φ (g0's slope included: `rdf` is the radial distribution, called with
  // the dual φ), ∂/∂Θ and ∂/∂u (hot path).
  template <class T, class RadialDistribution>
  FLUIDBED_HOST_DEVICE WallConditions<WallDerivatives<T>> with_derivatives(const T& phi, const T& theta,
                                                                           const RadialDistribution& rdf,
                                                                           const T& wall_slip,
                                                                           const GranularMaterial<T>& m) const {
    using D = Dual<T, 3>;
    const D p = D::variable(phi, 0);
    const WallConditions<D> w = (*this)(p, D::variable(theta, 1), rdf(p), D::variable(wall_slip, 2), m);
    using detail::split_wall;
    return {split_wall(w.shear),      split_wall(w.slip_coefficient), split_wall(w.energy_flux),
            split_wall(w.generation), split_wall(w.dissipation),      split_wall(w.dissipation_coefficient)};
  }

  // Checked: the radial distribution's argument and parameters (rdf.checked), then this law's.
  template <class T, class RadialDistribution>
  WallConditions<WallDerivatives<T>> checked_with_derivatives(const T& phi, const T& theta,
                                                              const RadialDistribution& rdf, const T& wall_slip,
                                                              const GranularMaterial<T>& m) const {
    this->require_valid(phi, theta, rdf.checked(phi), wall_slip, m);
    return with_derivatives(phi, theta, rdf, wall_slip, m);
  }
};

// Johnson & Jackson (1987), J. Fluid Mech. 176, 67–93, doi:10.1017/S0022112087000570, the
// partial-slip wall of the collisional stress, with the host's g0 (the form FLUENT, MFiX and
// OpenFOAM implement; seed 001 §6.3 uses it without giving a formula):
//   F = (φ/φ_max) ρ_s g0 √Θ,
//   k = (π√3/6) ψ F,                          |τ_w| = k u,
//   generation = (π√3/6) ψ F u² = k u²,       dissipation = (π√3/4)(1 − e_w²) F Θ,
// ψ ∈ [0, 1] the specularity coefficient (0: specular, frictionless wall, free slip; 1: every
// collision diffuse), e_w the particle–wall restitution coefficient. Johnson & Jackson's own
// radial distribution was [1 − (φ/φ_max)^{1/3}]⁻¹; the factor φ g0/φ_max with the host's g0 is
// what the three codes evaluate (read in MFiX's F_2, HW and CW and in OpenFOAM's
// JohnsonJacksonParticleSlip and ...Theta; FLUENT's theory guide writes the same). Code differences (never copied):
// OpenFOAM's ...Theta divides by the conductivity, which in OpenFOAM includes ρ_s, without
// multiplying by ρ_s, so its wall flux is ours/ρ_s as we read it (dimensionally inconsistent);
// recent OpenFOAM ...Slip divides by the kinetic viscosity ν − ν_fric while the momentum
// equation applies ν, so its wall shear is ours × ν/(ν − ν_fric) where friction is active; MFiX
// divides k by its own Lun-type μ_s whatever viscosity the momentum equation uses. Registered
// with seed 001's riser walls: ψ = 0.001, e_w = 0.2 (FLUENT's default), φ_max = 0.63 (seed
// 001 Table 1); its later run used ψ = 0.01, e_w = 0.9. Validity: derived for dense, rapid
// granular flow, no fitted range (Validity<0>).
struct JohnsonJacksonWall : WallLaw<JohnsonJacksonWall> {
  double specularity;       // ψ ∈ [0, 1]
  double wall_restitution;  // e_w ∈ [0, 1]
  double max_packing;       // φ_max ∈ (0, 1]

  constexpr JohnsonJacksonWall(double specularity_, double wall_restitution_, double max_packing_)
      : specularity(specularity_), wall_restitution(wall_restitution_), max_packing(max_packing_) {}
  static constexpr std::array<JohnsonJacksonWall, 1> registered() { return {JohnsonJacksonWall{0.001, 0.2, 0.63}}; }
  constexpr std::string_view name() const { return "JohnsonJacksonWall"; }
  constexpr std::string_view reference() const {
    return "Johnson, P.C. & Jackson, R. (1987) J. Fluid Mech. 176, 67-93, doi:10.1017/S0022112087000570";
  }
  constexpr Validity<0> validity() const { return {}; }
  constexpr Arguments<double, 3> parameter_domain() const {
    return {{{"specularity", specularity, domains::closed(0.0, 1.0)},
             detail::wall_restitution(wall_restitution),
             {"max_packing", max_packing, domains::half_open(0.0, 1.0)}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&JohnsonJacksonWall::specularity>("specularity"),
                      parameter<&JohnsonJacksonWall::wall_restitution>("wall_restitution"),
                      parameter<&JohnsonJacksonWall::max_packing>("max_packing")};
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE WallConditions<S> kernel(const S& phi, const S& theta, const S& g0, const S& wall_slip,
                                                const GranularMaterial<T>& m) const {
    using std::sqrt;
    const T root3_pi = numbers::sqrt3<T>() * numbers::pi<T>();
    const T e_w = T(wall_restitution);
    const S collision_flux = (m.density / T(max_packing)) * (phi * g0 * sqrt(theta));  // F
    const S k = (root3_pi * T(specularity) / 6) * collision_flux;
    const S a = (root3_pi * (1 - e_w * e_w) / 4) * collision_flux;
    const S shear = k * wall_slip;
    const S generation = shear * wall_slip;
    const S dissipation = a * theta;
    return {shear, k, generation - dissipation, generation, dissipation, a};
  }
};

// The default slip-speed scale u_0 [m s⁻¹] of JenkinsLougeWall.
inline constexpr double default_wall_slip_floor = 1e-6;

// Jenkins & Louge (1997), Phys. Fluids 9, 2835–2840, doi:10.1063/1.869396, after Jenkins
// (1992), J. Appl. Mech. 59, 120–127: a flat, frictional wall in the
// limit of small friction, where every particle–wall contact slides. Normal stress on the wall
// N = ρ_s φ Θ (1 + 2(1 + e) φ g0) (the pressure of Lun et al. 1984, e the particle–particle
// restitution coefficient); μ_w the particle–wall friction coefficient:
//   |τ_w| = μ_w N u/√(u² + u_0²),             k = μ_w N/√(u² + u_0²),
//   generation = (21/16)√3 μ_w² (1 + e_w) N √Θ,
//   dissipation = (3/8)√3 (1 − e_w) N √Θ,
// as MFiX implements Jenkins & Louge's eqs. (2)–(3) (its JENKINS option, F_2, HW and CW of the
// same names). Checked for issue 18: the paper's text was not available to us; MFiX's source
// (calc_grbdry.f F_HW and bc_theta.f THETA_HW_CW, two versions, both citing "Jenkins and Louge,
// Phys. Fluids 9 (10), 2835", eqs. (2) and (3)) evaluates k = μ_w ρ_s φ(1 + 4ηφg0)Θ/u,
// A = (3/8)√(3Θ)(1 − e_w) ρ_s φ(1 + 4ηφg0), generation = μ_w²(1 + e_w)(21/16)√(3Θ) ρ_s φ(1 + 4ηφg0)Θ
// with η = (1 + e)/2: the forms below term by term (the tests evaluate MFiX's arrangement). In
// the all-sliding limit the tangential restitution β_0 of sticking contacts does not enter.
// The shear is Coulomb's, μ_w N against the slip; in this limit the work of the wall's friction
// on the slip is dissipated in the sliding contacts and the slip drops out of the energy flux,
// which keeps a μ_w² term (the part of the sliding work returned to the fluctuations) and the
// normal inelastic loss. The (1 − e_w) (not 1 − e_w²) and both constants are those of MFiX's
// reading (a Maxwellian average of the same collision model gives the same two terms with
// √(2/π) for (3/8)√3 and (7/2)√(2/π) for (21/16)√3, both 1.2284 times larger: the ratio of the
// two terms, which fixes the sign of q_w, is the same). u_0 = slip_floor (default 10⁻⁶ m s⁻¹)
// smooths the Coulomb sign at u = 0, where MFiX sets k = 0 (free slip) and the exact law is
// singular (k = μ_w N/u): k is finite everywhere, and |τ_w| → μ_w N for u ≫ u_0. Registered
// with μ_w = 0.1 (a small friction, as the limit requires; no seed gives one) and e_w = 0.9
// (seed 001's later run). Validity: small μ_w, no stated range (Validity<0>).
struct JenkinsLougeWall : WallLaw<JenkinsLougeWall> {
  double wall_friction;                             // μ_w ≥ 0
  double wall_restitution;                          // e_w ∈ [0, 1]
  double slip_floor = default_wall_slip_floor;      // u_0 > 0 [m s⁻¹]

  constexpr JenkinsLougeWall(double wall_friction_, double wall_restitution_,
                             double slip_floor_ = default_wall_slip_floor)
      : wall_friction(wall_friction_), wall_restitution(wall_restitution_), slip_floor(slip_floor_) {}
  static constexpr std::array<JenkinsLougeWall, 1> registered() { return {JenkinsLougeWall{0.1, 0.9}}; }
  constexpr std::string_view name() const { return "JenkinsLougeWall"; }
  constexpr std::string_view reference() const {
    return "Jenkins, J.T. & Louge, M.Y. (1997) Phys. Fluids 9, 2835-2840, doi:10.1063/1.869396; Jenkins, J.T. "
           "(1992) J. Appl. Mech. 59, 120-127";
  }
  constexpr Validity<0> validity() const { return {}; }
  constexpr Arguments<double, 3> parameter_domain() const {
    return {{{"wall_friction", wall_friction, domains::non_negative<double>()},
             detail::wall_restitution(wall_restitution),
             {"slip_floor", slip_floor, domains::positive<double>()}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&JenkinsLougeWall::wall_friction>("wall_friction"),
                      parameter<&JenkinsLougeWall::wall_restitution>("wall_restitution"),
                      parameter<&JenkinsLougeWall::slip_floor>("slip_floor")};
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE WallConditions<S> kernel(const S& phi, const S& theta, const S& g0, const S& wall_slip,
                                                const GranularMaterial<T>& m) const {
    using std::sqrt;
    const T mu = T(wall_friction), e_w = T(wall_restitution), floor = T(slip_floor), root3 = numbers::sqrt3<T>();
    // N/Θ and N/√Θ, so that A = dissipation/Θ is formed without dividing by Θ.
    const S density_factor = m.density * phi * (1 + 2 * (1 + m.restitution) * phi * g0);  // N/Θ
    const S sqrt_theta = sqrt(theta);
    const S normal_stress = density_factor * theta;  // N
    const S k = mu * normal_stress / sqrt(wall_slip * wall_slip + floor * floor);
    const S a = (3 * root3 * (1 - e_w) / 8) * density_factor * sqrt_theta;
    const S generation = (21 * root3 * mu * mu * (1 + e_w) / 16) * normal_stress * sqrt_theta;
    const S dissipation = a * theta;
    return {k * wall_slip, k, generation - dissipation, generation, dissipation, a};
  }
};

// The momentum condition as a Robin condition on a tangential velocity component:
//   ∂u_t/∂n = −(k/μ_s) u_t   (coefficient k/μ_s [m⁻¹], source 0),
// μ_s > 0 the solids shear viscosity [Pa s] per unit volume of suspension that the host's
// momentum equation applies at the face (for OpenFOAM, ρ_s times its ν; use the same viscosity
// the momentum flux uses, friction included, or the wall shear is not k u). With fluidbed::checked,
// throws std::domain_error unless μ_s > 0 and k ≥ 0 ("kinetic_theory::velocity_robin").
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr RobinCondition<S> velocity_robin(const WallConditions<S>& wall,
                                                                const S& shear_viscosity, Policy policy = {}) {
  using T = value_type_of<S>;
  check_domain(policy, "kinetic_theory::velocity_robin",
               arguments(Argument<T>{"slip_coefficient", value_of(wall.slip_coefficient), domains::non_negative<T>()},
                         Argument<T>{"shear_viscosity", value_of(shear_viscosity), domains::positive<T>()}));
  return {wall.slip_coefficient / shear_viscosity, S(0)};
}

// The slip length ℓ = μ_s/k [m] of u_t + ℓ ∂u_t/∂n = 0: +∞ for a free-slip wall (k = 0, e.g.
// Johnson–Jackson with ψ = 0; velocity_robin's coefficient 1/ℓ = 0 is then finite), → 0
// towards no slip. With fluidbed::checked, throws unless μ_s > 0 and k ≥ 0
// ("kinetic_theory::slip_length").
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr S slip_length(const S& slip_coefficient, const S& shear_viscosity, Policy policy = {}) {
  using T = value_type_of<S>;
  check_domain(policy, "kinetic_theory::slip_length",
               arguments(Argument<T>{"slip_coefficient", value_of(slip_coefficient), domains::non_negative<T>()},
                         Argument<T>{"shear_viscosity", value_of(shear_viscosity), domains::positive<T>()}));
  if (!(value_of(slip_coefficient) > 0)) return S(std::numeric_limits<T>::infinity());
  return shear_viscosity / slip_coefficient;
}

// The energy condition κ_s ∂Θ/∂n = generation − A Θ as a Robin condition on Θ:
//   coefficient A/κ_s [m⁻¹], source generation/κ_s [m s⁻²];
// Θ_ref = source/coefficient (OpenFOAM's refValue, (2/3) ψ u²/(1 − e_w²) for Johnson–Jackson) is
// the temperature the wall drives Θ to (infinite where A = 0: an elastic, e_w = 1, Johnson–Jackson
// wall only heats). A and generation depend on √Θ themselves: hosts lag them, as OpenFOAM does.
// κ_s > 0 the conductivity [kg m⁻¹ s⁻¹] per unit volume of suspension, of the same balance.
// With fluidbed::checked, throws unless κ_s > 0, A ≥ 0 and generation ≥ 0
// ("kinetic_theory::temperature_robin").
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr RobinCondition<S> temperature_robin(const WallConditions<S>& wall,
                                                                   const S& conductivity, Policy policy = {}) {
  using T = value_type_of<S>;
  check_domain(policy, "kinetic_theory::temperature_robin",
               arguments(Argument<T>{"dissipation_coefficient", value_of(wall.dissipation_coefficient),
                                     domains::non_negative<T>()},
                         Argument<T>{"generation", value_of(wall.generation), domains::non_negative<T>()},
                         Argument<T>{"conductivity", value_of(conductivity), domains::positive<T>()}));
  return {wall.dissipation_coefficient / conductivity, wall.generation / conductivity};
}

namespace detail {

struct WallBoundaryConditionFamily {
  static constexpr std::string_view what = "wall boundary condition";
  static constexpr std::string_view convention =
      "The solids' wall conditions of one face, law(φ, Θ, g0, u, material) → {shear |τ_w| [Pa] against the slip, "
      "slip coefficient k = |τ_w|/u [kg m⁻² s⁻¹], energy flux q_w = generation − dissipation [W m⁻²], positive "
      "INTO the bed, dissipation coefficient A = dissipation/Θ}: u = |u_s − u_wall| the tangential slip speed; "
      "with n out of the bed, μ_s ∂u_t/∂n = −k u_t and κ_s ∂Θ/∂n = q_w.";
};

}  // namespace detail

// Wall boundary conditions of the solids phase, by name (a host copies one and sets its
// parameters: specularity, wall_restitution, max_packing; wall_friction, slip_floor).
using WallBoundaryConditions = Registry<detail::WallBoundaryConditionFamily, JohnsonJacksonWall, JenkinsLougeWall>;

}  // namespace fluidbed::kinetic_theory
