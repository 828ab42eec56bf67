// fluidbed — momentum exchange between two solids classes by collisions.
//
// K_pq [kg m⁻³ s⁻¹] per unit volume of suspension: the force per unit volume on class p is
// K_pq (v_q − v_p); K_pq = K_qp. Preconditions (asserted in debug builds): φ_p, φ_q ∈ [0, 1),
// densities and diameters > 0, e ∈ [0, 1], C_f ≥ 0, |Δv| ≥ 0, g_pq > 0 the contact value of the
// pair from a mixture RDF (mixture_radial_distribution.hpp). law.checked(args…) validates them
// and throws std::domain_error naming the argument and its value; law.with_derivatives(args…)
// gives ∂K_pq/∂φ_p, ∂φ_q, ∂g_pq and ∂|Δv|.
#pragma once

#include <string_view>

#include "../core/constants.hpp"
#include "../properties.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// K_pq with its partial derivatives in its scalar arguments.
template <class T>
struct SolidSolidDragDerivatives {
  T value;
  T d_phi_p;
  T d_phi_q;
  T d_contact_rdf;
  T d_relative_speed;
};

// Syamlal (1987), "The particle–particle drag term in a multiparticle model of
// fluidization", DOE/MC/21353-2373 (MFiX drag_ss; seed 001 eq. 91;
// FLUENT):
//   K_pq = 3 (1 + e)(π/2 + C_f π²/8) φ_p ρ_p φ_q ρ_q (d_p + d_q)² g_pq
//          / (2π (ρ_p d_p³ + ρ_q d_q³)) · |v_p − v_q|,
// C_f the coefficient of friction between the classes (0 in MFiX by default; seed 000
// §6.5 uses 0.15). Seed 000 eq. 6.15 prints the prefactor as (3π/4)(1 + e)(1 + C_f π/4):
// π times this one (tested); the codes and seed 001 agree on the form here.
// Validity: derived for binary mixtures of a fluidized bed, no stated range (Validity<0>).
struct SyamlalSolidSolidDrag : KineticTheoryLaw<SyamlalSolidSolidDrag> {
  double friction_coefficient = 0.0;  // C_f

  constexpr explicit SyamlalSolidSolidDrag(double friction_coefficient_ = 0.0)
      : friction_coefficient(friction_coefficient_) {}
  constexpr std::string_view name() const { return "SyamlalSolidSolidDrag"; }
  constexpr std::string_view reference() const {
    return "Syamlal, M. (1987) The particle-particle drag term in a multiparticle model of fluidization, "
           "DOE/MC/21353-2373";
  }
  constexpr Validity<0> validity() const { return {}; }
  constexpr Arguments<double, 1> parameter_domain() const {
    return {{{"friction_coefficient", friction_coefficient, domains::non_negative<double>()}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&SyamlalSolidSolidDrag::friction_coefficient>("friction_coefficient")};
  }
  // φ_p, φ_q ∈ [0, 1), densities and diameters > 0, e ∈ [0, 1], g_pq > 0, |Δv| ≥ 0.
  template <class T>
  FLUIDBED_HOST_DEVICE static constexpr Arguments<T, 9> argument_domain(const T& phi_p, const T& phi_q,
                                                                          const Particles<T>& p,
                                                                          const Particles<T>& q,
                                                                          const T& restitution, const T& contact_rdf,
                                                                          const T& relative_speed) {
    return {{{"phi_p", phi_p, domains::closed_open(T(0), T(1))},
             {"phi_q", phi_q, domains::closed_open(T(0), T(1))},
             {"p.density", p.density, domains::positive<T>()},
             {"p.diameter", p.diameter, domains::positive<T>()},
             {"q.density", q.density, domains::positive<T>()},
             {"q.diameter", q.diameter, domains::positive<T>()},
             {"restitution", restitution, domains::closed(T(0), T(1))},
             {"contact_rdf", contact_rdf, domains::positive<T>()},
             {"relative_speed", relative_speed, domains::non_negative<T>()}}};
  }

  // K_pq with its partial derivatives (g_pq an argument: for ∂/∂φ_m through g_pq, pass duals
  // to the hot path with g_pq from a mixture RDF of the same duals).
  template <class T>
  FLUIDBED_HOST_DEVICE SolidSolidDragDerivatives<T> with_derivatives(const T& phi_p, const T& phi_q,
                                                                     const Particles<T>& p, const Particles<T>& q,
                                                                     const T& restitution, const T& contact_rdf,
                                                                     const T& relative_speed) const {
    using D = Dual<T, 4>;
    const D k = (*this)(D::variable(phi_p, 0), D::variable(phi_q, 1), p, q, restitution, D::variable(contact_rdf, 2),
                        D::variable(relative_speed, 3));
    return {k.value, k.derivative[0], k.derivative[1], k.derivative[2], k.derivative[3]};
  }
  template <class T>
  SolidSolidDragDerivatives<T> checked_with_derivatives(const T& phi_p, const T& phi_q, const Particles<T>& p,
                                                        const Particles<T>& q, const T& restitution,
                                                        const T& contact_rdf, const T& relative_speed) const {
    require_valid(phi_p, phi_q, p, q, restitution, contact_rdf, relative_speed);
    return with_derivatives(phi_p, phi_q, p, q, restitution, contact_rdf, relative_speed);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S kernel(const S& phi_p, const S& phi_q, const Particles<T>& p,
                                          const Particles<T>& q, const T& restitution, const S& contact_rdf,
                                          const S& relative_speed) const {
    const T pi = numbers::pi<T>();
    const T d_sum = p.diameter + q.diameter;
    const T mass_scale =
        p.density * p.diameter * p.diameter * p.diameter + q.density * q.diameter * q.diameter * q.diameter;
    const T prefactor = 3 * (1 + restitution) * (pi / 2 + T(friction_coefficient) * pi * pi / 8) * p.density *
                        q.density * d_sum * d_sum / (2 * pi * mass_scale);
    return prefactor * (phi_p * phi_q) * contact_rdf * relative_speed;
  }
};

}  // namespace fluidbed::kinetic_theory
