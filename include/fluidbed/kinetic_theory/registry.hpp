// fluidbed — run-time selection of the kinetic-theory closures: one registry per kind of
// function (core/registry.hpp), each listing the library's laws of that kind. Laws with
// parameters are registered with the values their comments give (packing limits, Hrenya and
// Sinclair's L, friction onsets and angles); a host picks a law by name and sets its own
// parameters on the copy. A user adds a law of their own with `Registry::with<MyLaw>` (e.g.
//   using MyViscosities = ShearViscosities::with<MyViscosity>;)
// The laws of one registry share one calling shape, except GasExchangeSources, whose two
// sources take different arguments (gas_exchange.hpp).
#pragma once

#include <string_view>

#include "../core/registry.hpp"
#include "conductivity.hpp"
#include "dissipation.hpp"
#include "friction.hpp"
#include "gas_exchange.hpp"
#include "granular_pressure.hpp"
#include "mixture_radial_distribution.hpp"
#include "radial_distribution.hpp"
#include "solid_solid_drag.hpp"
#include "viscosity.hpp"

namespace fluidbed::kinetic_theory {

namespace detail {

// The kinds of function, as the registries' error messages name them.
template <const char* kind>
struct Kind {
  static constexpr std::string_view what = kind;
};
inline constexpr char radial_distribution_kind[] = "radial distribution";
inline constexpr char mixture_radial_distribution_kind[] = "mixture radial distribution";
inline constexpr char granular_pressure_kind[] = "granular pressure";
inline constexpr char shear_viscosity_kind[] = "shear viscosity";
inline constexpr char bulk_viscosity_kind[] = "bulk viscosity";
inline constexpr char conductivity_kind[] = "granular conductivity";
inline constexpr char dissipation_kind[] = "collisional dissipation";
inline constexpr char frictional_pressure_kind[] = "frictional pressure";
inline constexpr char frictional_viscosity_kind[] = "frictional viscosity";
inline constexpr char frictional_stress_kind[] = "frictional stress";
inline constexpr char gas_exchange_kind[] = "gas exchange source";
inline constexpr char solid_solid_drag_kind[] = "solid-solid drag";

}  // namespace detail

// g0(φ), one class.
using RadialDistributions =
    Registry<detail::Kind<detail::radial_distribution_kind>, CarnahanStarling, PercusYevick, LunSavage, Ogawa,
             SinclairJackson, GidaspowRadialDistribution, MaAhmadi, LathouwersBellan>;
// g_ik(fractions, diameters, i, k), several classes.
using MixtureRadialDistributions =
    Registry<detail::Kind<detail::mixture_radial_distribution_kind>, Lebowitz, Mansoori, ModifiedMansoori>;
// law(φ, Θ, g0, material), by the quantity it gives.
using GranularPressures = Registry<detail::Kind<detail::granular_pressure_kind>, LunPressure,
                                   SyamlalRogersOBrienPressure, AhmadiMaPressure>;
using ShearViscosities =
    Registry<detail::Kind<detail::shear_viscosity_kind>, GidaspowViscosity, SyamlalViscosity, HrenyaSinclairViscosity>;
using BulkViscosities = Registry<detail::Kind<detail::bulk_viscosity_kind>, LunBulkViscosity>;
using Conductivities = Registry<detail::Kind<detail::conductivity_kind>, GidaspowConductivity, SyamlalConductivity,
                                HrenyaSinclairConductivity>;
using Dissipations = Registry<detail::Kind<detail::dissipation_kind>, LunDissipation>;
// Friction: p_f(φ); μ_f(p_f, strain rate); {p_f, μ_f}(φ, Θ, d, strain rate).
using FrictionalPressures =
    Registry<detail::Kind<detail::frictional_pressure_kind>, JohnsonJacksonPressure, SchaefferPressure>;
using FrictionalViscosities = Registry<detail::Kind<detail::frictional_viscosity_kind>, SchaefferViscosity>;
using FrictionalStresses = Registry<detail::Kind<detail::frictional_stress_kind>, SrivastavaSundaresan>;
// Sources of granular energy from the gas (gas_damping, the sink, is a single function).
using GasExchangeSources =
    Registry<detail::Kind<detail::gas_exchange_kind>, KochSanganiSource, DragFluctuationSource>;
using SolidSolidDrags = Registry<detail::Kind<detail::solid_solid_drag_kind>, SyamlalSolidSolidDrag>;

}  // namespace fluidbed::kinetic_theory
