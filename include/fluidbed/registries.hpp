// fluidbed — every family's registry in one list, for the code that enumerates every closure
// of the library: bindings, the catalogue check, the tests. A family added to the library adds
// its registry here (a user's own registries are lists of the same kind).
#pragma once

#include <type_traits>

#include "drag.hpp"
#include "elastic/elastic_modulus.hpp"
#include "fluidization/minimum_fluidization.hpp"
#include "kinetic_theory.hpp"
#include "settling/richardson_zaki.hpp"
#include "single_particle/drag_coefficient.hpp"
#include "single_particle/terminal_velocity.hpp"

namespace fluidbed {

template <class... Registry>
struct RegistryList {
  // Calls f(std::type_identity<Registry>{}) for every registry of the list.
  template <class F>
  static constexpr void for_each(F&& f) {
    (f(std::type_identity<Registry>{}), ...);
  }
};

using Registries = RegistryList<
    single_particle::DragCoefficients, single_particle::TerminalVelocities, settling::RichardsonZakiExponents,
    fluidization::MinimumFluidizations, drag::DragLaws, elastic::ElasticModuli, kinetic_theory::RadialDistributions,
    kinetic_theory::MixtureRadialDistributions, kinetic_theory::GranularPressures, kinetic_theory::ShearViscosities,
    kinetic_theory::BulkViscosities, kinetic_theory::Conductivities, kinetic_theory::Dissipations,
    kinetic_theory::FrictionalPressures, kinetic_theory::FrictionalViscosities, kinetic_theory::FrictionalStresses,
    kinetic_theory::GasExchangeSources, kinetic_theory::SolidSolidDrags, kinetic_theory::WallBoundaryConditions>;

}  // namespace fluidbed
