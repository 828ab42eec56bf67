// fluidbed — momentum exchange between two solids classes by collisions.
//
// K_pq [kg m⁻³ s⁻¹] per unit volume of suspension: the force per unit volume on class p is
// K_pq (v_q − v_p); K_pq = K_qp. Preconditions (asserted in debug builds): φ_p, φ_q ∈ [0, 1),
// densities and diameters > 0, e ∈ [0, 1], C_f ≥ 0, |Δv| ≥ 0, g_pq > 0 the contact value of the
// pair from a mixture RDF (mixture_radial_distribution.hpp). evaluate_checked(law, args…)
// validates them and throws std::domain_error naming the argument and its value.
#pragma once

#include <string>
#include <string_view>

#include "../core/constants.hpp"
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
  void validate(std::string_view function) const {
    require_non_negative(function, "friction_coefficient", friction_coefficient);
  }
  template <class S, class T>
  FLUIDBED_HOST_DEVICE constexpr S operator()(const S& phi_p, const S& phi_q, const Particles<T>& p,
                                              const Particles<T>& q, const T& restitution, const S& contact_rdf,
                                              const S& relative_speed) const {
    const T pi = numbers::pi<T>();
    FLUIDBED_EXPECTS(detail::valid_solid_fraction(phi_p) && detail::valid_solid_fraction(phi_q));
    FLUIDBED_EXPECTS(p.density > T(0) && p.diameter > T(0) && q.density > T(0) && q.diameter > T(0));
    FLUIDBED_EXPECTS(restitution >= T(0) && restitution <= T(1) && friction_coefficient >= 0);
    FLUIDBED_EXPECTS(value_of(contact_rdf) > 0 && value_of(relative_speed) >= 0);
    const T d_sum = p.diameter + q.diameter;
    const T mass_scale =
        p.density * p.diameter * p.diameter * p.diameter + q.density * q.diameter * q.diameter * q.diameter;
    const T prefactor = 3 * (1 + restitution) * (pi / 2 + T(friction_coefficient) * pi * pi / 8) * p.density *
                        q.density * d_sum * d_sum / (2 * pi * mass_scale);
    return prefactor * (phi_p * phi_q) * contact_rdf * relative_speed;
  }
};

// Checked entry point: validates every argument and C_f, throwing std::domain_error naming
// the argument and its value, then evaluates K_pq.
template <class T>
T evaluate_checked(const SyamlalSolidSolidDrag& law, const T& phi_p, const T& phi_q, const Particles<T>& p,
                   const Particles<T>& q, const T& restitution, const T& contact_rdf, const T& relative_speed) {
  const std::string function = detail::checked_function_name(law);
  require_in_closed_open(function, "phi_p", phi_p, T(0), T(1));
  require_in_closed_open(function, "phi_q", phi_q, T(0), T(1));
  require_positive(function, "p.density", p.density);
  require_positive(function, "p.diameter", p.diameter);
  require_positive(function, "q.density", q.density);
  require_positive(function, "q.diameter", q.diameter);
  require_in_closed(function, "restitution", restitution, T(0), T(1));
  require_positive(function, "contact_rdf", contact_rdf);
  require_non_negative(function, "relative_speed", relative_speed);
  law.validate(function);
  return law(phi_p, phi_q, p, q, restitution, contact_rdf, relative_speed);
}

}  // namespace fluidbed::kinetic_theory
