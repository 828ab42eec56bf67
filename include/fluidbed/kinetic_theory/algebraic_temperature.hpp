// fluidbed — algebraic (local-equilibrium) granular temperature.
//
// Where convection and diffusion of granular energy are negligible (dense, slowly varying
// flows; seed 003 found no significant difference from the PDE), the balance of
// granular_state.hpp reduces to production = dissipation + gas damping:
//   (−p_s I + τ_s):D − γ − 3βΘ = 0,   τ_s:D = 2μ_s D':D' + λ_s (∇·u)².
// Every kinetic-theory coefficient is a power of Θ times a function of φ:
// p_s = P Θ, μ_s = A √Θ, λ_s = Λ √Θ, γ = B Θ^(3/2) (P, A, Λ, B are the laws at Θ = 1).
// With x = √Θ the balance divided by x is the quadratic
//   B x² + b x − c = 0,   b = P ∇·u + 3β,   c = 2A D':D' + Λ (∇·u)² ≥ 0,
// whose non-negative root is taken, in the form without cancellation:
//   b ≥ 0: x = 2c/(b + √(b² + 4Bc))  (0 when c = 0);   b < 0: x = (−b + √(b² + 4Bc))/(2B).
// No seed prints this; in simple shear without gas (b = 0, D':D' = γ̇²/2) it is Θ = Aγ̇²/B.
// OpenFOAM's "equilibrium" option and MFiX's GT_ALGEBRAIC solve the same quadratic with
// their own constants: in the viscous coefficient K3 MFiX has (3e + 1)/2 where OpenFOAM has
// 1, and MFiX leaves the kinetic pressure out of the ∇·u coefficient.
// Preconditions (asserted in debug builds): as for the laws (φ ∈ [0, 1), g0 > 0, material
// valid), D':D' ≥ 0, β ≥ 0; and B > 0 (e < 1, φ > 0) or b > 0 — with no dissipation and
// b ≤ 0 (compression at e = 1, or φ = 0 without gas) there is no finite root and the result is
// +∞ under shear. With the error policy fluidbed::checked (last argument) the arguments and
// the laws' parameters are validated and std::domain_error is thrown, also for that +∞.
#pragma once

#include <cmath>
#include <concepts>
#include <string_view>

#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// Θ [m² s⁻²] from the four laws (each called as law(φ, Θ, g0, material)), the state,
// the strain-rate invariants and the gas–particle drag coefficient β ≥ 0 (0 without gas).
// Templated on the scalar: a Dual φ (with g0 from it), Dual invariants or a Dual β give
// the sensitivities. A relation, not a closure: the error policy picks the hot path
// (fluidbed::unchecked, the default) or fluidbed::checked, which validates φ, g0 > 0, the
// material, the strain-rate invariants, β ≥ 0 and the four laws' parameters, and that a
// finite Θ exists, throwing std::domain_error naming the argument and its value
// ("kinetic_theory::algebraic_granular_temperature").
template <class S, class T, class Pressure, class ShearViscosity, class BulkViscosity, class Dissipation,
          ErrorPolicy Policy = Unchecked>
FLUIDBED_HOST_DEVICE S algebraic_granular_temperature(const Pressure& pressure, const ShearViscosity& shear_viscosity,
                                                      const BulkViscosity& bulk_viscosity,
                                                      const Dissipation& dissipation, const S& phi, const S& g0,
                                                      const GranularMaterial<T>& m, const StrainRate<S>& rate,
                                                      const S& beta, Policy policy = {}) {
  using std::sqrt;
  constexpr std::string_view function = "kinetic_theory::algebraic_granular_temperature";
  check_domain(policy, function,
               join(join(Arguments<T, 2>{detail::solid_fraction(value_of(phi)),
                                         detail::radial_distribution_value(value_of(g0))},
                         domain(m)),
                    join(domain(detail::plain(rate)),
                         Arguments<T, 1>{{{"beta", value_of(beta), domains::non_negative<T>()}}})));
  if constexpr (std::same_as<Policy, Checked>) {
    detail::require_parameters(function, pressure);
    detail::require_parameters(function, shear_viscosity);
    detail::require_parameters(function, bulk_viscosity);
    detail::require_parameters(function, dissipation);
  }
  const S unit(1);
  const S b = pressure(phi, unit, g0, m) * rate.divergence + 3 * beta;
  const S c = 2 * shear_viscosity(phi, unit, g0, m) * rate.deviatoric_contraction +
              bulk_viscosity(phi, unit, g0, m) * rate.divergence * rate.divergence;
  const S B = dissipation(phi, unit, g0, m);
  S x;
  if (b >= 0)
    x = c == 0 ? S(0) : 2 * c / (b + sqrt(b * b + 4 * B * c));
  else
    x = (sqrt(b * b + 4 * B * c) - b) / (2 * B);
  const S theta = x * x;
  if constexpr (std::same_as<Policy, Checked>)
    if (!fluidbed::detail::is_finite_number(value_of(theta)))
      fluidbed::detail::throw_domain_error(function, "beta", value_of(beta),
                                           "no finite granular temperature: without collisional dissipation (e = 1 or "
                                           "phi = 0) the production needs the sink 3 beta + (p_s/Theta) div u > 0");
  return theta;
}

// Θ with its sensitivities.
template <class T>
struct AlgebraicTemperatureSensitivities {
  T value;                     // Θ [m² s⁻²]
  T d_solid_fraction;          // ∂Θ/∂φ (through g0(φ) too)
  T d_beta;                    // ∂Θ/∂β
  T d_divergence;              // ∂Θ/∂(∇·u)
  T d_deviatoric_contraction;  // ∂Θ/∂(D':D')
};

}  // namespace fluidbed::kinetic_theory
