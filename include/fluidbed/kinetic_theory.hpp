// fluidbed — kinetic theory of granular flow: radial distribution functions (one class and
// mixtures), granular pressure, shear and bulk viscosity, conductivity, dissipation, gas
// exchange, friction, solid–solid drag, algebraic granular temperature, the transport within
// a class of a mixture (self-diffusion, in-phase fluxes, per-class energy exchange), the per-cell
// ConstitutiveSet, and one registry per kind of function (kinetic_theory/registry.hpp).
// Conventions: kinetic_theory/granular_state.hpp.
#pragma once

#include "kinetic_theory/algebraic_temperature.hpp"
#include "kinetic_theory/class_transport.hpp"
#include "kinetic_theory/conductivity.hpp"
#include "kinetic_theory/constitutive_set.hpp"
#include "kinetic_theory/dissipation.hpp"
#include "kinetic_theory/friction.hpp"
#include "kinetic_theory/gas_exchange.hpp"
#include "kinetic_theory/granular_pressure.hpp"
#include "kinetic_theory/granular_state.hpp"
#include "kinetic_theory/mixture_radial_distribution.hpp"
#include "kinetic_theory/radial_distribution.hpp"
#include "kinetic_theory/registry.hpp"
#include "kinetic_theory/solid_solid_drag.hpp"
#include "kinetic_theory/unequal_temperature_mixture.hpp"
#include "kinetic_theory/viscosity.hpp"
#include "kinetic_theory/walls.hpp"
