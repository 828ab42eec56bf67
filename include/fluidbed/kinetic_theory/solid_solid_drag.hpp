// fluidbed — momentum exchange between two solids classes by collisions.
//
// K_pq [kg m⁻³ s⁻¹] per unit volume of suspension: the force per unit volume on class p is
// K_pq (v_q − v_p); K_pq = K_qp. Preconditions: φ_p, φ_q ≥ 0, densities and diameters > 0,
// e ∈ [0, 1], C_f ≥ 0, |Δv| ≥ 0, g_pq the contact value of the pair from a mixture RDF
// (mixture_radial_distribution.hpp).
#pragma once

#include <numbers>
#include <string_view>

#include "../properties.hpp"
#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// Syamlal (1987), "The particle–particle drag term in a multiparticle model of
// fluidization", DOE/MC/21353-2373 (MFiX drag_ss; seed 001 eq. 91;
// FLUENT):
//   K_pq = 3 (1 + e)(π/2 + C_f π²/8) φ_p ρ_p φ_q ρ_q (d_p + d_q)² g_pq
//          / (2π (ρ_p d_p³ + ρ_q d_q³)) · |v_p − v_q|,
// C_f the coefficient of friction between the classes (0 in MFiX by default; seed 000
// §6.5 uses 0.15). Seed 000 eq. 6.15 prints the prefactor as (3π/4)(1 + e)(1 + C_f π/4):
// π times this one (tested); the codes and seed 001 agree on the form here.
struct SyamlalSolidSolidDrag {
  double friction_coefficient = 0.0;  // C_f

  constexpr std::string_view name() const { return "Syamlal"; }
  constexpr std::string_view reference() const {
    return "Syamlal, M. (1987) The particle-particle drag term in a multiparticle model of fluidization, "
           "DOE/MC/21353-2373";
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S operator()(const S& phi_p, const S& phi_q, const Particles<T>& p,
                                              const Particles<T>& q, const T& restitution, const S& contact_rdf,
                                              const S& relative_speed) const {
    constexpr double pi = std::numbers::pi;
    const T d_sum = p.diameter + q.diameter;
    const T mass_scale =
        p.density * p.diameter * p.diameter * p.diameter + q.density * q.diameter * q.diameter * q.diameter;
    const T prefactor = 3.0 * (1.0 + restitution) * (pi / 2.0 + friction_coefficient * pi * pi / 8.0) * p.density *
                        q.density * d_sum * d_sum / (2.0 * pi * mass_scale);
    return prefactor * (phi_p * phi_q) * contact_rdf * relative_speed;
  }
};

}  // namespace fluidbed::kinetic_theory
