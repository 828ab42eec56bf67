// fluidbed — β from the dimensionless force of particle-resolved simulations.
//
// The lattice-Boltzmann and immersed-boundary correlations (van der Hoef 2005, Beetstra
// 2007, Tang 2015, Hill–Koch–Ladd 2001, Tenneti 2011) report the mean force on a particle
// normalised by the Stokes drag at the superficial slip,
//   F = F_particle / (3π μ_f d ε w),
// and they disagree on what F_particle is (seed 002 §II.D: F_d = ε F_{g→s}):
//
//   drag only        F     = F_drag / (3π μ_f d ε w)     van der Hoef, Beetstra, Tang
//   total force      F_tot = F_total / (3π μ_f d ε w)    Hill–Koch–Ladd, Tenneti
//
// where the total force on a particle in a homogeneous array includes the share of the
// mean pressure gradient that holds the array (its "buoyancy"), F_drag = ε F_total.
// With n = 6φ/(π d³) particles per unit volume and β (u_f − v_p) the drag per unit
// volume in the pressure-gradient convention (buoyancy −φ∇p, drag_law.hpp):
//
//   β_pressure_gradient = 18 μ_f ε φ F / d²  = 18 μ_f ε² φ F_tot / d².
//
// Confusing the two is an error by a factor ε; MFiX 25.2.1, waLBerla and OpenFOAM
// implement Tenneti's correlation in three mutually inconsistent ways (tenneti.hpp).
#pragma once

#include "../core/config.hpp"

namespace fluidbed::drag {

// β_pressure_gradient = 18 μ_f ε φ F / d² from the drag-only force F (φ = 1 − ε).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S beta_from_drag_force(const S& drag_force, const S& voidage, const T& viscosity,
                                                      const T& diameter) {
  return 18 * viscosity / (diameter * diameter) * (voidage * (1 - voidage)) * drag_force;
}

// β_pressure_gradient = 18 μ_f ε² φ F_tot / d² from the total force F_tot, which includes
// the mean-pressure-gradient share (F = ε F_tot).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S beta_from_total_force(const S& total_force, const S& voidage, const T& viscosity,
                                                       const T& diameter) {
  return beta_from_drag_force(voidage * total_force, voidage, viscosity, diameter);
}

}  // namespace fluidbed::drag
