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

// The kinds of function: what the registries' error messages name, and the conventions the
// catalogue states (docs/closures/kinetic_theory.md).
struct RadialDistributionFamily {
  static constexpr std::string_view what = "radial distribution";
  static constexpr std::string_view convention =
      "The radial distribution function at contact g0(φ) of one class, dimensionless, φ ∈ [0, 1) the solids "
      "volume fraction; the forms with a packing limit φ_max are continued linearly above φ_max − "
      "packing_margin.";
};
struct MixtureRadialDistributionFamily {
  static constexpr std::string_view what = "mixture radial distribution";
  static constexpr std::string_view convention =
      "The contact value g_ik between a particle of class i and one of class k, dimensionless, from the "
      "classes' solids volume fractions φ_m (Σφ_m < 1) and diameters d_m [m].";
};
struct GranularPressureFamily {
  static constexpr std::string_view what = "granular pressure";
  static constexpr std::string_view convention =
      "The granular pressure p_s ≥ 0 [Pa] per unit volume of suspension, law(φ, Θ, g0, material): φ the solids "
      "volume fraction, Θ = ⟨C²⟩/3 [m² s⁻²] the granular temperature, g0 the radial distribution, material {d, "
      "ρ_s, e}.";
};
struct ShearViscosityFamily {
  static constexpr std::string_view what = "shear viscosity";
  static constexpr std::string_view convention =
      "The shear viscosity μ_s ≥ 0 [Pa s] per unit volume of suspension (FLUENT's, per unit volume of solids, "
      "is μ_s/φ), law(φ, Θ, g0, material); τ_s = 2μ_s D + (λ_s − (2/3)μ_s)(∇·u_s) I.";
};
struct BulkViscosityFamily {
  static constexpr std::string_view what = "bulk viscosity";
  static constexpr std::string_view convention =
      "The bulk viscosity λ_s ≥ 0 [Pa s] per unit volume of suspension, law(φ, Θ, g0, material); τ_s = 2μ_s D + "
      "(λ_s − (2/3)μ_s)(∇·u_s) I.";
};
struct ConductivityFamily {
  static constexpr std::string_view what = "granular conductivity";
  static constexpr std::string_view convention =
      "The conductivity of granular energy κ_s ≥ 0 [kg m⁻¹ s⁻¹] per unit volume of suspension, law(φ, Θ, g0, "
      "material), entering the granular energy balance as ∇·(κ_s∇Θ).";
};
struct DissipationFamily {
  static constexpr std::string_view what = "collisional dissipation";
  static constexpr std::string_view convention =
      "The collisional dissipation rate γ ≥ 0 [W m⁻³] per unit volume of suspension, law(φ, Θ, g0, material), "
      "entering the granular energy balance as −γ.";
};
struct FrictionalPressureFamily {
  static constexpr std::string_view what = "frictional pressure";
  static constexpr std::string_view convention =
      "The frictional pressure p_f(φ) ≥ 0 [Pa] per unit volume of suspension, added to the kinetic-theory p_s.";
};
struct FrictionalViscosityFamily {
  static constexpr std::string_view what = "frictional viscosity";
  static constexpr std::string_view convention =
      "The frictional viscosity μ_f(p_f, strain rate) [Pa s] per unit volume of suspension, added to the "
      "kinetic-theory μ_s; the strain rate as ∇·u and D':D', D' the deviatoric rate of strain; friction angles "
      "in radians.";
};
struct FrictionalStressFamily {
  static constexpr std::string_view what = "frictional stress";
  static constexpr std::string_view convention =
      "The frictional pressure p_f [Pa] and viscosity μ_f [Pa s] per unit volume of suspension as one law of "
      "(φ, Θ, d, strain rate), added to the kinetic-theory p_s and μ_s; friction angles in radians.";
};
struct GasExchangeFamily {
  static constexpr std::string_view what = "gas exchange source";
  static constexpr std::string_view convention =
      "The exchange of granular energy with the gas J [W m⁻³] per unit volume of suspension, signed as a "
      "right-hand-side term of the granular energy balance; β is the host's interphase drag coefficient in the "
      "buoyancy convention of its momentum equation, w = |u_g − u_s|. Each source takes its own arguments.";
};
struct SolidSolidDragFamily {
  static constexpr std::string_view what = "solid-solid drag";
  static constexpr std::string_view convention =
      "The solid–solid drag coefficient K_pq = K_qp [kg m⁻³ s⁻¹] per unit volume of suspension: the force on "
      "class p is K_pq (v_q − v_p); from φ_p, φ_q, the two classes' particles, e, the pair's contact value g_pq "
      "and |v_p − v_q|.";
};

}  // namespace detail

// g0(φ), one class.
using RadialDistributions =
    Registry<detail::RadialDistributionFamily, CarnahanStarling, PercusYevick, LunSavage, Ogawa, SinclairJackson,
             GidaspowRadialDistribution, MaAhmadi, LathouwersBellan, SongStrattMason, TobochnikChapin>;
// g_ik(fractions, diameters, i, k), several classes.
using MixtureRadialDistributions =
    Registry<detail::MixtureRadialDistributionFamily, Lebowitz, Mansoori, ModifiedMansoori>;
// law(φ, Θ, g0, material), by the quantity it gives.
using GranularPressures =
    Registry<detail::GranularPressureFamily, LunPressure, SyamlalRogersOBrienPressure, AhmadiMaPressure>;
using ShearViscosities =
    Registry<detail::ShearViscosityFamily, GidaspowViscosity, SyamlalViscosity, HrenyaSinclairViscosity,
             EnskogViscosity>;
using BulkViscosities = Registry<detail::BulkViscosityFamily, LunBulkViscosity>;
using Conductivities = Registry<detail::ConductivityFamily, GidaspowConductivity, SyamlalConductivity,
                                HrenyaSinclairConductivity, EnskogConductivity>;
using Dissipations = Registry<detail::DissipationFamily, LunDissipation>;
// Friction: p_f(φ); μ_f(p_f, strain rate); {p_f, μ_f}(φ, Θ, d, strain rate).
using FrictionalPressures = Registry<detail::FrictionalPressureFamily, JohnsonJacksonPressure, SchaefferPressure>;
using FrictionalViscosities = Registry<detail::FrictionalViscosityFamily, SchaefferViscosity>;
using FrictionalStresses = Registry<detail::FrictionalStressFamily, SrivastavaSundaresan>;
// Sources of granular energy from the gas (gas_damping, the sink, is a single function).
using GasExchangeSources = Registry<detail::GasExchangeFamily, KochSanganiSource, DragFluctuationSource>;
using SolidSolidDrags = Registry<detail::SolidSolidDragFamily, SyamlalSolidSolidDrag>;

}  // namespace fluidbed::kinetic_theory
