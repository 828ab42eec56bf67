// fluidbed — transport within one particle class of a multi-fluid model (Lathouwers & Bellan
// 2001; seed 004): the particles' self-diffusivity, the in-phase diffusion coefficients of the
// class's species mass fractions, enthalpy and mean particle mass, the source of the mean
// particle mass, the per-class exchange of granular energy with the gas and by mass transfer,
// and the segregation index of a binary mixture.
//
// Conventions (granular_state.hpp): SI units; α_i the volume fraction of class i, φ = Σ_k α_k
// the total solids fraction, Θ_i the granular temperature of class i [m² s⁻²]; Γ_i the mass
// source of class i [kg m⁻³ s⁻¹], the right-hand side of its continuity equation
// ∂(α_iρ_i)/∂t + ∇·(α_iρ_i u_i) = Γ_i (negative where the class loses mass, e.g. by pyrolysis;
// the gas gains −Σ_i Γ_i). Energy terms are signed as right-hand-side terms of the class's
// granular energy balance (3/2)[∂(α_iρ_iΘ_i)/∂t + ∇·(α_iρ_iu_iΘ_i)] = … (seed 004).
// These are relations, not closures of a family (no alternatives): each function takes an
// error policy last, fluidbed::unchecked (the default hot path, preconditions asserted in
// debug builds) or fluidbed::checked (throws std::domain_error naming the argument).
// Reference for the in-phase transport: Lathouwers, D. & Bellan, J. (2001) Int. J. Multiphase
// Flow 27, 2155–2187 (seed 004).
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>

#include "../core/config.hpp"
#include "../core/constants.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "gas_exchange.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

namespace detail {

// d > 0, ρ > 0 and the like.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> positive_argument(const char* name, const T& x) {
  return {name, x, domains::positive<T>()};
}

// The total solids fraction a diffusivity divides by: φ ∈ (0, 1).
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> diffusing_solid_fraction(const T& phi) {
  return {"solid_fraction", phi, domains::open(T(0), T(1))};
}

// α_i ∈ [0, φ]: a class is part of the solids.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Argument<T> class_fraction(const T& alpha, const T& phi) {
  return {"class_fraction", alpha, domains::closed(T(0), phi),
          "must lie in [0, solid_fraction]: a class is part of the solids"};
}

}  // namespace detail

// ---- Self-diffusion ---------------------------------------------------------------------------

// The particles' self-diffusivity of kinetic theory [m² s⁻¹] (seed 000 eq. 6.24, after Gidaspow
// (1994), Multiphase Flow and Fluidization, Academic Press):
//   D = √Θ d / (3 √π φ),
// a fluctuation speed times a mean free path ∝ d/φ. Θ = 10⁻⁴ m² s⁻², d = 200 µm, φ = 0.5 give
// 7.52253e-7 m²/s (seed 000: "about 10⁻⁶"). Preconditions: Θ ≥ 0, d > 0, φ ∈ (0, 1).
// For class i of a mixture, pass Θ_i, d_i and the TOTAL solids fraction φ = Σ_k α_k, not α_i:
// the free path of a particle of class i ends at a collision with a particle of any class, so
// it is set by all the solids around it. With α_i, a trace class in a dense bed would diffuse as
// in a dilute suspension (and D would diverge as α_i → 0), and relabelling one powder as two
// identical classes would change its diffusivity (tested: it does not).
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S self_diffusivity(const S& granular_temperature, const S& diameter, const S& solid_fraction,
                                        Policy policy = {}) {
  using std::sqrt;
  using T = value_type_of<S>;
  check_domain(policy, "kinetic_theory::self_diffusivity",
               arguments(detail::granular_temperature(value_of(granular_temperature)),
                         detail::positive_argument("diameter", value_of(diameter)),
                         detail::diffusing_solid_fraction(value_of(solid_fraction))));
  return sqrt(granular_temperature) * diameter / (3 * numbers::sqrt_pi<T>() * solid_fraction);
}

// D with ∂D/∂φ = −D/φ and ∂D/∂Θ = D/(2Θ) (+∞ at Θ = 0, where D has a vertical tangent).
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE ValueAndDerivatives<T> self_diffusivity_with_derivatives(const T& granular_temperature,
                                                                              const T& diameter,
                                                                              const T& solid_fraction,
                                                                              Policy policy = {}) {
  using D = Dual<T, 2>;
  const D value = self_diffusivity(D::variable(granular_temperature, 1), D(diameter),
                                   D::variable(solid_fraction, 0), policy);
  return {value.value, value.derivative[0], value.derivative[1]};
}

// ---- In-phase transport (seed 004; Lathouwers & Bellan 2001) ----------------------------------
//
// The velocity fluctuations of class i carry its scalars down their gradients:
//   −∇·(α_iρ_i⟨C_i Y'_iξ⟩) = ∇·(α_iρ_i D_ii ∇Y_iξ)         species mass fractions,
//   −∇·(α_iρ_i⟨C_i h'_i⟩)  = ∇·(α_iρ_i c_p,i D_ii ∇T_i)    enthalpy (as a temperature gradient),
//   ∂(α_iρ_i m̄_i)/∂t + ∇·(α_iρ_i u_i m̄_i) = ∇·(α_iρ_i D_ii ∇m̄_i) + 2 Γ_i m̄_i   mean particle mass,
// with D_ii the class's self-diffusivity (seed 004 leaves it open; self_diffusivity above).

namespace detail {

// α_i ∈ [0, 1), ρ_i > 0, D_ii ≥ 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 3> mass_diffusion_domain(const T& alpha, const T& density,
                                                                     const T& diffusivity) {
  return arguments(Argument<T>{"class_fraction", alpha, domains::closed_open(T(0), T(1))},
                   positive_argument("density", density),
                   Argument<T>{"self_diffusivity", diffusivity, domains::non_negative<T>()});
}

}  // namespace detail

// α_i ρ_i D_ii [kg m⁻¹ s⁻¹], the diffusion coefficient of the species mass fractions and of the
// mean particle mass of class i; ρ_i is the material density. Preconditions: α_i ∈ [0, 1),
// ρ_i > 0, D_ii ≥ 0.
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr S class_mass_diffusion_coefficient(const S& class_fraction, const S& density,
                                                                  const S& self_diffusivity, Policy policy = {}) {
  check_domain(policy, "kinetic_theory::class_mass_diffusion_coefficient",
               detail::mass_diffusion_domain(value_of(class_fraction), value_of(density), value_of(self_diffusivity)));
  return class_fraction * density * self_diffusivity;
}

// α_i ρ_i c_p,i D_ii [W m⁻¹ K⁻¹], the conductivity-like coefficient of the class's enthalpy
// flux, −∇·(α_iρ_i⟨C_i h'_i⟩) = ∇·(α_iρ_i c_p,i D_ii ∇T_i) (the fluctuations' transport of
// sensible heat; collisional conduction is neglected, as in seed 004). Preconditions as
// class_mass_diffusion_coefficient's, and c_p,i > 0 [J kg⁻¹ K⁻¹].
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr S class_enthalpy_diffusion_coefficient(const S& class_fraction, const S& density,
                                                                      const S& heat_capacity,
                                                                      const S& self_diffusivity, Policy policy = {}) {
  check_domain(policy, "kinetic_theory::class_enthalpy_diffusion_coefficient",
               join(detail::mass_diffusion_domain(value_of(class_fraction), value_of(density),
                                                  value_of(self_diffusivity)),
                    arguments(detail::positive_argument("heat_capacity", value_of(heat_capacity)))));
  return heat_capacity * class_mass_diffusion_coefficient(class_fraction, density, self_diffusivity);
}

// A diffusion coefficient of class i from the state, with its partial derivatives: α_i at fixed
// φ, the total φ at fixed α_i, and Θ_i. In a solver whose unknowns are the α_k, the chain rule
// is ∂/∂α_k = δ_ik d_class_fraction + d_solid_fraction (φ = Σ_k α_k).
template <class T>
struct ClassDiffusionDerivatives {
  T value;
  T d_class_fraction;        // ∂/∂α_i at fixed φ, Θ_i
  T d_solid_fraction;        // ∂/∂φ at fixed α_i, Θ_i (through D_ii)
  T d_granular_temperature;  // ∂/∂Θ_i
};

namespace detail {

// α_i ∈ [0, φ], φ ∈ (0, 1), Θ_i ≥ 0, d_i > 0, ρ_i > 0: the state of a class's diffusion.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 5> class_diffusion_domain(const T& alpha, const T& phi, const T& theta,
                                                                      const T& diameter, const T& density) {
  return arguments(class_fraction(alpha, phi), diffusing_solid_fraction(phi), granular_temperature(theta),
                   positive_argument("diameter", diameter), positive_argument("density", density));
}

// α_i ρ_i D_ii(Θ_i, d_i, φ) with the three derivatives of ClassDiffusionDerivatives, times
// `factor` (1 for the mass coefficient, c_p,i for the enthalpy one); arguments in their domain.
template <class T>
FLUIDBED_HOST_DEVICE ClassDiffusionDerivatives<T> class_diffusion(const T& class_fraction, const T& solid_fraction,
                                                                  const T& granular_temperature, const T& diameter,
                                                                  const T& density, const T& factor) {
  using D = Dual<T, 3>;
  const D diffusivity =
      self_diffusivity(D::variable(granular_temperature, 2), D(diameter), D::variable(solid_fraction, 1));
  const D coefficient = factor * class_mass_diffusion_coefficient(D::variable(class_fraction, 0), D(density), diffusivity);
  return {coefficient.value, coefficient.derivative[0], coefficient.derivative[1], coefficient.derivative[2]};
}

}  // namespace detail

// α_i ρ_i D_ii with D_ii = self_diffusivity(Θ_i, d_i, φ), φ the total solids fraction, and its
// derivatives. Preconditions: α_i ∈ [0, φ], φ ∈ (0, 1), Θ_i ≥ 0, d_i, ρ_i > 0.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE ClassDiffusionDerivatives<T> class_mass_diffusion_with_derivatives(
    const T& class_fraction, const T& solid_fraction, const T& granular_temperature, const T& diameter,
    const T& density, Policy policy = {}) {
  check_domain(policy, "kinetic_theory::class_mass_diffusion_with_derivatives",
               detail::class_diffusion_domain(class_fraction, solid_fraction, granular_temperature, diameter, density));
  return detail::class_diffusion(class_fraction, solid_fraction, granular_temperature, diameter, density, T(1));
}

// α_i ρ_i c_p,i D_ii and its derivatives, as above; c_p,i > 0.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE ClassDiffusionDerivatives<T> class_enthalpy_diffusion_with_derivatives(
    const T& class_fraction, const T& solid_fraction, const T& granular_temperature, const T& diameter,
    const T& density, const T& heat_capacity, Policy policy = {}) {
  check_domain(policy, "kinetic_theory::class_enthalpy_diffusion_with_derivatives",
               join(detail::class_diffusion_domain(class_fraction, solid_fraction, granular_temperature, diameter,
                                                   density),
                    arguments(detail::positive_argument("heat_capacity", heat_capacity))));
  return detail::class_diffusion(class_fraction, solid_fraction, granular_temperature, diameter, density,
                                 heat_capacity);
}

// The source of the mean particle mass m̄_i [kg] in the conservative equation for α_iρ_i m̄_i
// [kg² m⁻³], per unit volume and time [kg² m⁻³ s⁻¹]:
//   + 2 Γ_i m̄_i.
// Why 2: α_iρ_i = n_i m̄_i with n_i the number density, which mass transfer leaves unchanged
// (particles shrink or grow; none appear or vanish), so D(n_i m̄_i²)/Dt = 2 m̄_i D(n_i m̄_i)/Dt
// = 2 m̄_i Γ_i — one Γ_i m̄_i from the class's mass (continuity) and one from each particle's
// change of mass. Seed 004 (slide "Transport of mean particle mass") prints the source as
// −2 Γ_i m̄_i. Its dimensions are right, its sign is not, with Γ_i the class's mass source as the
// same slides define it (Γ_i = α_iρ_i⟨(1/m_i) dm_i/dt⟩ on the right of the continuity equation):
// particles that lose mass (Γ_i < 0) would then see their mean mass grow. For a uniform class
// whose particles lose mass at the rate dm/dt = −k m, m̄_i = m̄_0 e^{−kt} and
// α_iρ_i m̄_i = n m̄_0² e^{−2kt}, whose rate −2k α_iρ_i m̄_i is +2 Γ_i m̄_i (tested).
// Preconditions: Γ_i finite, m̄_i ≥ 0.
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr S mean_mass_source(const S& mass_source, const S& mean_mass, Policy policy = {}) {
  using T = value_type_of<S>;
  check_domain(policy, "kinetic_theory::mean_mass_source",
               arguments(Argument<T>{"mass_source", value_of(mass_source), domains::finite<T>()},
                         Argument<T>{"mean_mass", value_of(mean_mass), domains::non_negative<T>()}));
  return 2 * mass_source * mean_mass;
}

// 2 Γ_i m̄_i with ∂/∂Γ_i = 2 m̄_i and ∂/∂m̄_i = 2 Γ_i (the latter for an implicit source).
template <class T>
struct MeanMassSourceDerivatives {
  T value;
  T d_mass_source;
  T d_mean_mass;
};

template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr MeanMassSourceDerivatives<T> mean_mass_source_with_derivatives(const T& mass_source,
                                                                                              const T& mean_mass,
                                                                                              Policy policy = {}) {
  using D = Dual<T, 2>;
  const D source = mean_mass_source(D::variable(mass_source, 0), D::variable(mean_mass, 1), policy);
  return {source.value, source.derivative[0], source.derivative[1]};
}

// ---- Granular energy of a class: exchange with the gas and by mass transfer -------------------

// The granular energy a class gains with the mass it gains [W m⁻³]:
//   α_iρ_i⟨(dm_i/dt)(C_i²/2)/m_i⟩ = (3/2) Γ_i Θ_i
// (seed 004, slide "Gas-particles exchange terms 2", neglecting the correlation of dm_i/dt with
// C_i², so ⟨C_i²⟩ = 3Θ_i). It is the energy the gained or lost mass carries: with the left side
// (3/2)∂(α_iρ_iΘ_i)/∂t and ∂(α_iρ_i)/∂t = Γ_i, it leaves Θ_i unchanged — mass transfer alone
// neither heats nor cools the fluctuations. Preconditions: Γ_i finite, Θ_i ≥ 0.
template <class S, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr S mass_transfer_energy(const S& mass_source, const S& granular_temperature,
                                                      Policy policy = {}) {
  using T = value_type_of<S>;
  check_domain(policy, "kinetic_theory::mass_transfer_energy",
               arguments(Argument<T>{"mass_source", value_of(mass_source), domains::finite<T>()},
                         detail::granular_temperature(value_of(granular_temperature))));
  return T(1.5) * mass_source * granular_temperature;
}

// The two exchange terms of class i's granular energy balance, right-hand-side signs, with the
// derivatives of their sum. Each class's terms depend on its own state only (the Jacobian over
// classes is diagonal).
template <class T>
struct ClassEnergyExchange {
  T gas_damping;             // −3 β_i Θ_i  (gas_damping, gas_exchange.hpp)
  T mass_transfer;           // (3/2) Γ_i Θ_i  (mass_transfer_energy)
  T d_granular_temperature;  // ∂(sum)/∂Θ_i = −3 β_i + (3/2) Γ_i
  T d_beta;                  // ∂(sum)/∂β_i = −3 Θ_i
  T d_mass_source;           // ∂(sum)/∂Γ_i = (3/2) Θ_i

  FLUIDBED_HOST_DEVICE constexpr T total() const { return gas_damping + mass_transfer; }
};

namespace detail {

// β_i ≥ 0, Γ_i finite, Θ_i ≥ 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 3> class_exchange_domain(const T& beta, const T& mass_source,
                                                                     const T& theta) {
  return arguments(Argument<T>{"beta", beta, domains::non_negative<T>()},
                   Argument<T>{"mass_source", mass_source, domains::finite<T>()}, granular_temperature(theta));
}

// The terms of one class whose arguments are known to be in their domain.
template <class T>
FLUIDBED_HOST_DEVICE constexpr ClassEnergyExchange<T> class_energy_exchange_terms(const T& beta,
                                                                                  const T& mass_source,
                                                                                  const T& theta) {
  using D = Dual<T, 3>;
  const D damping = gas_damping(D::variable(beta, 0), D::variable(theta, 2));
  const D transfer = mass_transfer_energy(D::variable(mass_source, 1), D::variable(theta, 2));
  const D sum = damping + transfer;
  return {damping.value, transfer.value, sum.derivative[2], sum.derivative[0], sum.derivative[1]};
}

}  // namespace detail

// The exchange terms of one class: β_i the class's drag coefficient with the gas
// [kg m⁻³ s⁻¹] (seed 004: β_i = α_iρ_i/τ_i,12, in the host's buoyancy convention), Γ_i its mass
// source, Θ_i its granular temperature. Seed 004 also has the gas-fluctuation correlation
// β_i⟨C'_i·u''_g⟩, a source closed separately (gas_exchange.hpp's KochSanganiSource or
// DragFluctuationSource with the class's state); seed 001 eq. 35 and seed 002 eq. 61 are the
// one-class damping −3βΘ; seed 003 eq. 0.16 names the damping S_r^v of class r without a formula.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr ClassEnergyExchange<T> class_energy_exchange(const T& beta, const T& mass_source,
                                                                            const T& granular_temperature,
                                                                            Policy policy = {}) {
  check_domain(policy, "kinetic_theory::class_energy_exchange",
               detail::class_exchange_domain(beta, mass_source, granular_temperature));
  return detail::class_energy_exchange_terms(beta, mass_source, granular_temperature);
}

// The exchange terms of N classes at once; the checked path names the class, e.g. "beta[2]".
template <class T, std::size_t N, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr std::array<ClassEnergyExchange<T>, N> class_energy_exchanges(
    const std::array<T, N>& beta, const std::array<T, N>& mass_source, const std::array<T, N>& granular_temperature,
    Policy = {}) {
  std::array<ClassEnergyExchange<T>, N> terms{};
  for (std::size_t i = 0; i < N; ++i) {
    const auto domain = detail::class_exchange_domain(beta[i], mass_source[i], granular_temperature[i]);
    if constexpr (std::same_as<Policy, Checked>) {
      for (const Argument<T>& argument : domain)
        require_in("kinetic_theory::class_energy_exchanges", indexed_argument(argument.name, i), argument.value,
                   argument.domain);
    } else {
      FLUIDBED_EXPECTS(within(domain));
    }
    terms[i] = detail::class_energy_exchange_terms(beta[i], mass_source[i], granular_temperature[i]);
  }
  return terms;
}

// ---- Segregation of a binary mixture ----------------------------------------------------------

// The segregation index of two classes (seed 004, slide "Results on dynamics and reaction"),
// with each fraction weighted by the inverse of its nominal (well-mixed) fraction:
//   S = (α_1/ᾱ_1 − α_2/ᾱ_2)/(α_1/ᾱ_1 + α_2/ᾱ_2) = (α_1ᾱ_2 − α_2ᾱ_1)/(α_1ᾱ_2 + α_2ᾱ_1).
// S = 0 at the nominal composition, +1 where only class 1 is present, −1 where only class 2.
// Seed 004's S = (0.2 α_sand − 0.4 α_biomass)/(0.2 α_sand + 0.4 α_biomass), for a bed of 2/3
// sand and 1/3 biomass by volume at φ = 0.6, is this with ᾱ_1 = 0.4 (sand), ᾱ_2 = 0.2
// (biomass). Preconditions: α_1, α_2 ≥ 0, not both 0 (S is undefined where neither class is:
// the checked path throws for their sum), ᾱ_1, ᾱ_2 > 0.
template <class T, ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE constexpr T segregation_index(const T& first_fraction, const T& second_fraction,
                                                   const T& first_nominal_fraction,
                                                   const T& second_nominal_fraction, Policy policy = {}) {
  check_domain(policy, "kinetic_theory::segregation_index",
               arguments(Argument<T>{"first_fraction", first_fraction, domains::non_negative<T>()},
                         Argument<T>{"second_fraction", second_fraction, domains::non_negative<T>()},
                         Argument<T>{"first_fraction + second_fraction", first_fraction + second_fraction,
                                     domains::positive<T>(),
                                     "must be > 0: the index is undefined where neither class is present"},
                         detail::positive_argument("first_nominal_fraction", first_nominal_fraction),
                         detail::positive_argument("second_nominal_fraction", second_nominal_fraction)));
  const T first = first_fraction * second_nominal_fraction;
  const T second = second_fraction * first_nominal_fraction;
  return (first - second) / (first + second);
}

}  // namespace fluidbed::kinetic_theory
