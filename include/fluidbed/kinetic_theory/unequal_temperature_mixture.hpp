// fluidbed — kinetic theory of a granular mixture whose classes have their own granular
// temperatures: the collisional pressure, viscosities, conductivities, energy exchange,
// solid–solid drag and segregation force of every class of a cell, with their derivatives in
// every class's volume fraction and granular temperature.
//
// Model: Lathouwers, D. & Bellan, J. (2001), "Modeling of dense gas–solid reactive mixtures
// applied to biomass pyrolysis in a fluidized bed", Int. J. Multiphase Flow 27(12), 2155–2187,
// as presented in seed 004 (slides "Constitutive
// particle-phase equations", "Granular pressure and transport coefficients"). Class i has
// envelope volume fraction α_i, diameter d_i, envelope density ρ_i, granular temperature
// Θ_i = ⟨C_i²⟩/3 and velocity u_i; every pair has the restitution coefficient e. With
//   n_i = α_i/(π d_i³/6),  m_i = ρ_i π d_i³/6,  M_i = m_i/(m_i + m_k),  σ_ik = (d_i + d_k)/2
// (the contact distance: the only reading of the slide's σ_ik that reproduces the one-class
// theory), h_ik a mixture radial distribution (default ModifiedMansoori{0.64}, seed 004's) and
//   c_ik = n_i n_k m_i M_k (1 + e) h_ik       (symmetric: m_i M_k is the reduced mass),
//   F_ik = c_ik σ_ik²,  Σ_ik = Θ_i + Θ_k,
// the pair terms are
//   p_ik      = (π/3) c_ik σ_ik³ Σ_ik
//   μ_i^ik    = (√(2π)/15) c_ik M_k σ_ik⁴ Σ_ik^(3/2)/Θ_i     μ_i^kk = (√(2π)/15) c_ik M_i σ_ik⁴ Σ_ik^(3/2)/Θ_k
//   κ_i^ik    = (√(2π)/3) c_ik σ_ik⁴ Σ_ik^(1/2) M_k Θ_k/Θ_i   κ_i^kk = (√(2π)/3) c_ik σ_ik⁴ Σ_ik^(1/2) M_i Θ_i/Θ_k
//   −γ_ik     = 2√(2π) F_ik Σ_ik^(1/2) [2(M_i Θ_i − M_k Θ_k) + M_k (1 − e) Σ_ik]
//   β_ik      = (4/3)√(2π) F_ik Σ_ik^(1/2)            (solid–solid drag coefficient)
//   s_ik      = (π/3) F_ik σ_ik Σ_ik = p_ik           (segregation-force coefficient)
// and the class quantities (library conventions, granular_state.hpp: pressure-positive, the
// dissipation a positive sink, everything per unit volume of suspension):
//   pressure        p_i = n_i m_i Θ_i + Σ_k p_ik      (the streaming part is isotropic: the
//                   velocity distribution is Maxwellian)
//   stress          τ_i = Σ_j [2 μ_ij D_j + (λ_ij − ⅔ μ_ij)(∇·u_j) I],  D_j = ½(∇u_j + ∇u_jᵀ),
//                   μ_ij = δ_ij Σ_k μ_i^ik + μ_i^jj,   λ_ij = (5/3) μ_ij
//   heat flux       q_i = −Σ_j κ_ij ∇Θ_j,             κ_ij = δ_ij Σ_k κ_i^ik + κ_i^jj
//   dissipation     γ_i = Σ_k (−γ_ik)                 (sink of class i's granular energy:
//                   inelastic loss plus transfer to the other classes)
//   collisional force on class i
//                   φ_i = Σ_k [β_ik (u_k − u_i) + s_ik ∇ln(n_i/n_k)]
// The granular energy balance of class i is then
//   (3/2)[∂(α_iρ_iΘ_i)/∂t + ∇·(α_iρ_iΘ_i u_i)] = (−p_i I + τ_i):∇u_i + ∇·(Σ_j κ_ij ∇Θ_j) − γ_i + J_i.
// Sign corrections to the slides (each tested): the slides write the stress pressure-positive
// but the frictional stress tension-positive, and print q_i without the minus sign that makes
// conduction run down the gradient (their Θ equation contains −∇·q_i); the exchange γ_i is a
// source there (≤ 0 for one class), a sink here as in the one-class ConstitutiveSet. The
// slides' h_ik prints its third term 8 r² ξ/(1 − x)², dimensionally wrong: ModifiedMansoori has
// the Mansoori et al. (1971) form.
//
// Limits (tested): one class gives exactly Lun's collisional pressure, Gidaspow's collisional
// viscosity and conductivity, Lun's bulk viscosity and dissipation at the same g0; classes at
// equipartition (m_i Θ_i equal) give the Enskog mixture pressure and only the inelastic part of
// the exchange; Σ_i γ_i = 0 at e = 1; identical classes split from one change nothing;
// β_ik = β_ki and s_ik = s_ki, so φ_ik = −φ_ki. There is no streaming (kinetic) viscosity or
// conductivity: unlike Gidaspow's, μ and κ vanish as α → 0 (the Maxwellian assumption).
//
// Domain: α_i ≥ 0 with Σ α_i < 1 (and the radial distribution's own), Θ_i > 0 for every class
// (μ_i^ik and κ_i^ik divide by Θ_i: the theory has no cold-class limit, so hosts floor Θ_i),
// d_i, ρ_i > 0, e ∈ [0, 1]. Validity: the theory assumes binary collisions, Maxwellian
// velocity distributions, small drift |u_i − u_k| ≪ Σ_ik^(1/2), and neglects products of
// gradients with (1 − e); validity() gives the radial distribution's range of Σ α_i.
//
// Entry points of UnequalTemperatureMixture: mixture(state) → ClassKineticValues<T, N>,
// mixture.with_derivatives(state) → the same with ∂/∂α_m and ∂/∂Θ_m of every entry,
// mixture.checked / checked_with_derivatives (std::domain_error naming the argument and its
// value), mixture.pair_terms(state, i, k) for the terms of one pair, collisional_force and
// stress_power (the production term of each class's granular energy balance).
// No allocation, O(N²) square roots per cell (the pairs are symmetric), thread-safe.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "../core/registry.hpp"
#include "../core/vector3.hpp"
#include "granular_state.hpp"
#include "mixture_radial_distribution.hpp"

namespace fluidbed::kinetic_theory {

// The classes of one cell.
template <class T, std::size_t N>
struct GranularClassesState {
  std::array<T, N> fractions;     // α_i, envelope volume fractions (pores counted as solid)
  std::array<T, N> temperatures;  // Θ_i [m² s⁻²], > 0
  std::array<T, N> diameters;     // d_i [m]
  std::array<T, N> densities;     // ρ_i [kg m⁻³], envelope densities (α_i ρ_i = n_i m_i)
  T restitution;                  // e of every pair
};

template <class V, std::size_t N>
using ClassMatrix = std::array<std::array<V, N>, N>;

// The class quantities of one cell (see the header comment for the equations they enter).
template <class V, std::size_t N>
struct ClassKineticValues {
  ClassMatrix<V, N> radial_distribution;  // h_ik
  std::array<V, N> pressure;              // p_i [Pa]
  ClassMatrix<V, N> shear_viscosity;      // μ_ij [Pa s]: class j's strain rate in class i's stress
  ClassMatrix<V, N> bulk_viscosity;       // λ_ij = (5/3) μ_ij [Pa s]
  ClassMatrix<V, N> conductivity;         // κ_ij [kg m⁻¹ s⁻¹]: q_i = −Σ_j κ_ij ∇Θ_j
  std::array<V, N> dissipation;           // γ_i [W m⁻³], a sink (transfer to other classes included)
  ClassMatrix<V, N> drag;                 // β_ik [kg m⁻³ s⁻¹], symmetric, β_ii = 0
  ClassMatrix<V, N> segregation;          // s_ik [Pa], symmetric, s_ii = 0
};

// The terms of one pair (i, k), as the slides write them (γ_ik with the sink sign).
template <class V>
struct ClassPairTerms {
  V radial_distribution;    // h_ik
  V contact_factor;         // F_ik [kg m⁻⁴]
  V pressure;               // p_ik [Pa]
  V viscosity_own;          // μ_i^ik [Pa s], multiplies class i's strain rate
  V viscosity_partner;      // μ_i^kk [Pa s], multiplies class k's strain rate
  V conductivity_own;       // κ_i^ik, multiplies ∇Θ_i
  V conductivity_partner;   // κ_i^kk, multiplies ∇Θ_k
  V energy_sink;            // −γ_ik [W m⁻³]
  V drag;                   // β_ik [kg m⁻³ s⁻¹]
  V segregation;            // s_ik [Pa]
};

// A value with its partial derivatives in every class's volume fraction and temperature.
template <class T, std::size_t N>
struct ClassSensitivity {
  T value;
  std::array<T, N> d_fractions;     // ∂/∂α_m (through h_ik as well)
  std::array<T, N> d_temperatures;  // ∂/∂Θ_m
};

namespace detail {

// The domains of the state, declared once for the assertions and the exceptions.
template <class T>
struct ClassStateDomain {
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> fraction() { return domains::non_negative<T>(); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> temperature() { return domains::positive<T>(); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> length_or_density() { return domains::positive<T>(); }
  FLUIDBED_HOST_DEVICE static constexpr Interval<T> restitution() { return domains::closed(T(0), T(1)); }
};

template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE constexpr bool class_state_within(const GranularClassesState<T, N>& s) {
  using Domain = ClassStateDomain<T>;
  bool ok = Domain::restitution().contains(s.restitution);
  for (std::size_t i = 0; i < N; ++i)
    ok = ok && Domain::fraction().contains(s.fractions[i]) && Domain::temperature().contains(s.temperatures[i]) &&
         Domain::length_or_density().contains(s.diameters[i]) && Domain::length_or_density().contains(s.densities[i]);
  return ok;
}

// Applies `f` to every entry of `v`: the values with derivatives from the Dual evaluation.
template <class U, class V, std::size_t N, class F>
FLUIDBED_HOST_DEVICE ClassKineticValues<U, N> map_class_values(const ClassKineticValues<V, N>& v, F f) {
  ClassKineticValues<U, N> r{};
  for (std::size_t i = 0; i < N; ++i) {
    r.pressure[i] = f(v.pressure[i]);
    r.dissipation[i] = f(v.dissipation[i]);
    for (std::size_t j = 0; j < N; ++j) {
      r.radial_distribution[i][j] = f(v.radial_distribution[i][j]);
      r.shear_viscosity[i][j] = f(v.shear_viscosity[i][j]);
      r.bulk_viscosity[i][j] = f(v.bulk_viscosity[i][j]);
      r.conductivity[i][j] = f(v.conductivity[i][j]);
      r.drag[i][j] = f(v.drag[i][j]);
      r.segregation[i][j] = f(v.segregation[i][j]);
    }
  }
  return r;
}

}  // namespace detail

template <class RadialDistribution = ModifiedMansoori>
struct UnequalTemperatureMixture {
  // By default the law's first registered preset (ModifiedMansoori: φ_max = 0.64, seed 004's).
  RadialDistribution radial_distribution = fluidbed::detail::registered_instances<RadialDistribution>()[0];

  constexpr std::string_view name() const { return "UnequalTemperatureMixture"; }
  constexpr std::string_view reference() const {
    return "Lathouwers, D. & Bellan, J. (2001) Int. J. Multiphase Flow 27, 2155-2187";
  }
  constexpr auto validity() const { return radial_distribution.validity(); }

  // Hot path. Preconditions (asserted in debug builds): the header's domain.
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassKineticValues<T, N> operator()(const GranularClassesState<T, N>& s) const {
    return evaluate<T>(s.fractions, s.temperatures, s);
  }

  // Every entry with ∂/∂α_m and ∂/∂Θ_m, m = 0 … N − 1, from one Dual evaluation.
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassKineticValues<ClassSensitivity<T, N>, N> with_derivatives(
      const GranularClassesState<T, N>& s) const {
    const DualState<T, N> x(s);
    return detail::map_class_values<ClassSensitivity<T, N>>(evaluate(x.fractions, x.temperatures, s),
                                                            &DualState<T, N>::split);
  }

  // The terms of the pair (i, k) (hot path, i, k < N).
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassPairTerms<T> pair_terms(const GranularClassesState<T, N>& s, std::size_t i,
                                                    std::size_t k) const {
    FLUIDBED_EXPECTS(detail::class_state_within(s) && i < N && k < N);
    return pair(s.fractions, s.temperatures, s, i, k);
  }

  // The same with ∂/∂α_m and ∂/∂Θ_m of each term.
  template <class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassPairTerms<ClassSensitivity<T, N>> pair_terms_with_derivatives(
      const GranularClassesState<T, N>& s, std::size_t i, std::size_t k) const {
    FLUIDBED_EXPECTS(detail::class_state_within(s) && i < N && k < N);
    const DualState<T, N> x(s);
    const auto t = pair(x.fractions, x.temperatures, s, i, k);
    const auto split = &DualState<T, N>::split;
    return {split(t.radial_distribution), split(t.contact_factor),       split(t.pressure),
            split(t.viscosity_own),       split(t.viscosity_partner),    split(t.conductivity_own),
            split(t.conductivity_partner), split(t.energy_sink),         split(t.drag),
            split(t.segregation)};
  }

  // Validates the state and the radial distribution's parameters (std::domain_error naming the
  // argument, e.g. 'state.temperatures[1]', and its value), then evaluates.
  template <class T, std::size_t N>
  ClassKineticValues<T, N> checked(const GranularClassesState<T, N>& s) const {
    require_valid(s);
    return (*this)(s);
  }
  template <class T, std::size_t N>
  ClassKineticValues<ClassSensitivity<T, N>, N> checked_with_derivatives(const GranularClassesState<T, N>& s) const {
    require_valid(s);
    return with_derivatives(s);
  }

  template <class T, std::size_t N>
  void require_valid(const GranularClassesState<T, N>& s) const {
    using Domain = detail::ClassStateDomain<T>;
    const std::string function = "kinetic_theory::UnequalTemperatureMixture";
    for (std::size_t i = 0; i < N; ++i) {
      require_in(function, indexed_argument("state.fractions", i), s.fractions[i], Domain::fraction());
      require_in(function, indexed_argument("state.temperatures", i), s.temperatures[i], Domain::temperature());
      require_in(function, indexed_argument("state.diameters", i), s.diameters[i], Domain::length_or_density());
      require_in(function, indexed_argument("state.densities", i), s.densities[i], Domain::length_or_density());
    }
    require_in(function, "state.restitution", s.restitution, Domain::restitution());
    radial_distribution.require_valid(std::span<const T>(s.fractions), std::span<const T>(s.diameters), 0, 0);
  }

 private:
  // The fractions and temperatures as the 2N variables of a Dual evaluation.
  template <class T, std::size_t N>
  struct DualState {
    using D = Dual<T, int(2 * N)>;
    std::array<D, N> fractions{}, temperatures{};
    FLUIDBED_HOST_DEVICE explicit DualState(const GranularClassesState<T, N>& s) {
      for (std::size_t m = 0; m < N; ++m) {
        fractions[m] = D::variable(s.fractions[m], int(m));
        temperatures[m] = D::variable(s.temperatures[m], int(N + m));
      }
    }
    FLUIDBED_HOST_DEVICE static ClassSensitivity<T, N> split(const D& x) {
      ClassSensitivity<T, N> r{x.value, {}, {}};
      for (std::size_t m = 0; m < N; ++m) {
        r.d_fractions[m] = x.derivative[m];
        r.d_temperatures[m] = x.derivative[N + m];
      }
      return r;
    }
  };

  // What the pair (i, k) shares with (k, i): the symmetric factors of the header's equations.
  template <class S>
  struct SymmetricPair {
    S radial_distribution, contact_factor, pressure, viscosity, conductivity, drag;
    S transfer;  // 2(M_i Θ_i − M_k Θ_k): the elastic part of −γ_ik/rate, −that of −γ_ki
    S loss;      // (1 − e)(Θ_i + Θ_k): the inelastic part, weighted by M_k for i and M_i for k
    S rate;      // 2√(2π) F_ik (Θ_i + Θ_k)^(1/2)
    value_type_of<S> share_i, share_k;  // M_i, M_k
  };

  template <class S, class T, std::size_t N>
  FLUIDBED_HOST_DEVICE SymmetricPair<S> symmetric_pair(const std::array<S, N>& fractions,
                                                       const std::array<S, N>& temperatures,
                                                       const GranularClassesState<T, N>& s, std::size_t i,
                                                       std::size_t k) const {
    using std::sqrt;
    const T sqrt_2pi = numbers::sqrt2<T>() * numbers::sqrt_pi<T>();
    const T pi = numbers::pi<T>();
    // Masses through ρ d³ (the common π/6 cancels in M_i); n_i m_i = α_i ρ_i.
    const T mass_i = s.densities[i] * s.diameters[i] * s.diameters[i] * s.diameters[i];
    const T mass_k = s.densities[k] * s.diameters[k] * s.diameters[k] * s.diameters[k];
    const T share_i = mass_i / (mass_i + mass_k), share_k = mass_k / (mass_i + mass_k);
    const T sigma = (s.diameters[i] + s.diameters[k]) / 2;
    const T particle_volume_k = pi / 6 * s.diameters[k] * s.diameters[k] * s.diameters[k];
    const S h = radial_distribution(std::span<const S>(fractions), std::span<const T>(s.diameters), i, k);
    // F_ik = n_i n_k m_i M_k (1 + e) h σ² with n_i m_i = α_i ρ_i.
    const S contact = fractions[i] * s.densities[i] * (fractions[k] / particle_volume_k) *
                      (share_k * (1 + s.restitution) * sigma * sigma) * h;
    const S sum = temperatures[i] + temperatures[k];
    const S root = sqrt(sum);
    const S pressure = (pi / 3 * sigma) * contact * sum;
    return {h,
            contact,
            pressure,
            (sqrt_2pi / 15 * sigma * sigma) * contact * sum * root,
            (sqrt_2pi / 3 * sigma * sigma) * contact * root,
            (4 * sqrt_2pi / 3) * contact * root,
            2 * (share_i * temperatures[i] - share_k * temperatures[k]),
            (1 - s.restitution) * sum,
            2 * sqrt_2pi * contact * root,
            share_i,
            share_k};
  }

  // The terms of (i, k) from the shared factors; those of (k, i) are the same call with the
  // roles of M_i, Θ_i and M_k, Θ_k exchanged.
  template <class S>
  FLUIDBED_HOST_DEVICE static ClassPairTerms<S> terms_of(const SymmetricPair<S>& p, const S& theta_i,
                                                         const S& theta_k) {
    return {p.radial_distribution,
            p.contact_factor,
            p.pressure,
            p.share_k * p.viscosity / theta_i,
            p.share_i * p.viscosity / theta_k,
            p.conductivity * (p.share_k * theta_k / theta_i),
            p.conductivity * (p.share_i * theta_i / theta_k),
            p.rate * (p.transfer + p.share_k * p.loss),
            p.drag,
            p.pressure};
  }

  template <class S>
  FLUIDBED_HOST_DEVICE static SymmetricPair<S> mirrored(SymmetricPair<S> p) {
    p.transfer = -p.transfer;
    const auto share_i = p.share_i;
    p.share_i = p.share_k;
    p.share_k = share_i;
    return p;
  }

  template <class S, class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassPairTerms<S> pair(const std::array<S, N>& fractions, const std::array<S, N>& temperatures,
                                              const GranularClassesState<T, N>& s, std::size_t i,
                                              std::size_t k) const {
    return terms_of(symmetric_pair(fractions, temperatures, s, i, k), temperatures[i], temperatures[k]);
  }

  // Adds the terms of the pair (i, k) to class i's quantities.
  template <class S, std::size_t N>
  FLUIDBED_HOST_DEVICE static void accumulate(ClassKineticValues<S, N>& r, const ClassPairTerms<S>& t, std::size_t i,
                                              std::size_t k) {
    r.radial_distribution[i][k] = t.radial_distribution;
    r.pressure[i] = r.pressure[i] + t.pressure;
    r.shear_viscosity[i][i] = r.shear_viscosity[i][i] + t.viscosity_own;
    r.shear_viscosity[i][k] = r.shear_viscosity[i][k] + t.viscosity_partner;
    r.conductivity[i][i] = r.conductivity[i][i] + t.conductivity_own;
    r.conductivity[i][k] = r.conductivity[i][k] + t.conductivity_partner;
    r.dissipation[i] = r.dissipation[i] + t.energy_sink;
    r.drag[i][k] = i == k ? S(0) : t.drag;
    r.segregation[i][k] = i == k ? S(0) : t.segregation;
  }

  template <class S, class T, std::size_t N>
  FLUIDBED_HOST_DEVICE ClassKineticValues<S, N> evaluate(const std::array<S, N>& fractions,
                                                         const std::array<S, N>& temperatures,
                                                         const GranularClassesState<T, N>& s) const {
    FLUIDBED_EXPECTS(detail::class_state_within(s));
    ClassKineticValues<S, N> r{};
    for (std::size_t i = 0; i < N; ++i) {
      r.pressure[i] = fractions[i] * s.densities[i] * temperatures[i];
      r.dissipation[i] = S(0);
      for (std::size_t j = 0; j < N; ++j) {
        r.shear_viscosity[i][j] = S(0);
        r.conductivity[i][j] = S(0);
      }
    }
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t k = i; k < N; ++k) {
        const SymmetricPair<S> p = symmetric_pair(fractions, temperatures, s, i, k);
        accumulate(r, terms_of(p, temperatures[i], temperatures[k]), i, k);
        if (k != i) accumulate(r, terms_of(mirrored(p), temperatures[k], temperatures[i]), k, i);
      }
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) r.bulk_viscosity[i][j] = value_type_of<S>(5) / 3 * r.shear_viscosity[i][j];
    return r;
  }
};

UnequalTemperatureMixture() -> UnequalTemperatureMixture<ModifiedMansoori>;
template <class RadialDistribution>
UnequalTemperatureMixture(RadialDistribution) -> UnequalTemperatureMixture<RadialDistribution>;

// The collisional force on class i [N m⁻³], φ_i = Σ_k [β_ik (u_k − u_i) + s_ik ∇ln(n_i/n_k)], from
// the coefficients, the class velocities and the gradients of ln n_k (= ∇α_k/α_k at fixed d_k).
// Σ_i φ_i = 0: the collisions exchange momentum between the classes.
template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE Vector3<T> collisional_force(const ClassKineticValues<T, N>& values, std::size_t i,
                                                  const std::array<Vector3<T>, N>& velocities,
                                                  const std::array<Vector3<T>, N>& log_number_gradients) {
  FLUIDBED_EXPECTS(i < N);
  Vector3<T> force{T(0), T(0), T(0)};
  for (std::size_t k = 0; k < N; ++k)
    for (int c = 0; c < 3; ++c)
      force[c] += values.drag[i][k] * (velocities[k][c] - velocities[i][c]) +
                  values.segregation[i][k] * (log_number_gradients[i][c] - log_number_gradients[k][c]);
  return force;
}

// The production of class i's granular energy by its stress [W m⁻³], (−p_i I + τ_i):∇u_i with
// τ_i = Σ_j [2 μ_ij D_j + (λ_ij − ⅔ μ_ij)(∇·u_j) I], from the class velocity gradients
// gradients[j][a][b] = ∂u_j,b/∂x_a. The cross terms j ≠ i couple class i's energy to the other
// classes' deformation.
template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE T stress_power(const ClassKineticValues<T, N>& values, std::size_t i,
                                    const std::array<std::array<Vector3<T>, 3>, N>& gradients) {
  FLUIDBED_EXPECTS(i < N);
  const auto strain = [](const std::array<Vector3<T>, 3>& g, int a, int b) { return (g[a][b] + g[b][a]) / 2; };
  const auto divergence = [](const std::array<Vector3<T>, 3>& g) { return g[0][0] + g[1][1] + g[2][2]; };
  T power = -values.pressure[i] * divergence(gradients[i]);
  for (std::size_t j = 0; j < N; ++j) {
    T contraction(0);  // D_j : D_i
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) contraction += strain(gradients[j], a, b) * strain(gradients[i], a, b);
    power += 2 * values.shear_viscosity[i][j] * contraction +
             (values.bulk_viscosity[i][j] - T(2) / 3 * values.shear_viscosity[i][j]) * divergence(gradients[j]) *
                 divergence(gradients[i]);
  }
  return power;
}

}  // namespace fluidbed::kinetic_theory
