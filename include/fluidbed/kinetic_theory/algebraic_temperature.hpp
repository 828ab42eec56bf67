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
// No seed prints this (seed-004 note §2.12 derives the simple-shear case Θ = Aγ̇²/B);
// OpenFOAM's "equilibrium" option and MFiX's GT_ALGEBRAIC solve the same quadratic with
// their own constants (anchors note §2.16, where MFiX's differs by a factor in K3).
// Preconditions: as for the laws; B > 0 (e < 1) or b > 0 — with no dissipation and
// compression (b < 0, e = 1) there is no finite root and the result is +∞.
#pragma once

#include <cmath>

#include "granular_state.hpp"

namespace fluidbed::kinetic_theory {

// Θ [m² s⁻²] from the four laws (each called as law(φ, Θ, g0, material)), the state,
// the strain-rate invariants and the gas–particle drag coefficient β ≥ 0 (0 without gas).
// Templated on the scalar: a Dual φ (with g0 from it), Dual invariants or a Dual β give
// the sensitivities.
template <class S, class T, class Pressure, class ShearViscosity, class BulkViscosity, class Dissipation>
FLUIDBED_HOST_DEVICE S algebraic_granular_temperature(const Pressure& pressure, const ShearViscosity& shear_viscosity,
                                                      const BulkViscosity& bulk_viscosity,
                                                      const Dissipation& dissipation, const S& phi, const S& g0,
                                                      const GranularMaterial<T>& m, const StrainRate<S>& rate,
                                                      const S& beta) {
  using std::sqrt;
  const S unit(1.0);
  const S b = pressure(phi, unit, g0, m) * rate.divergence + 3.0 * beta;
  const S c = 2.0 * shear_viscosity(phi, unit, g0, m) * rate.deviatoric_contraction +
              bulk_viscosity(phi, unit, g0, m) * rate.divergence * rate.divergence;
  const S B = dissipation(phi, unit, g0, m);
  S x;
  if (b >= 0)
    x = c == 0 ? S(0) : 2.0 * c / (b + sqrt(b * b + 4.0 * B * c));
  else
    x = (sqrt(b * b + 4.0 * B * c) - b) / (2.0 * B);
  return x * x;
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
