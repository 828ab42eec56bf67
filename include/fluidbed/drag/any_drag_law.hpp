// fluidbed — run-time selection over the whole drag family.
//
// Every law shares one calling shape (drag_law.hpp), so a host can pick one at compile
// time (use the type) or at run time: AnyDragLaw is a std::variant of the family, and
// make_drag_law(name) returns the law of that name (the names are those of `name()`).
// The polydisperse Beetstra law (beetstra_polydisperse.hpp) takes a mixture, not one state, and so
// is not a member of this monodisperse family.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <variant>

#include "../core/registry.hpp"
#include "beetstra.hpp"
#include "di_felice.hpp"
#include "drag_law.hpp"
#include "ergun.hpp"
#include "gidaspow.hpp"
#include "koch_hill.hpp"
#include "mazzei_lettieri.hpp"
#include "syamlal_obrien.hpp"
#include "tang.hpp"
#include "tenneti.hpp"
#include "van_der_hoef.hpp"
#include "wen_yu.hpp"

namespace fluidbed::drag {

struct DragFamily {
  static constexpr std::string_view what = "drag law";
  static constexpr std::string_view convention =
      "β [kg m⁻³ s⁻¹] per unit volume of suspension: the drag on the particles per unit volume is β (u_f − "
      "v_p). Each law is written in its native buoyancy convention, classical (−φ ρ_f g) or pressure-gradient "
      "(−φ ∇p), and gives both, β_pg = ε β_cl. Re = ρ_f ε w d/μ_f with w = |u_f − v_p| the interstitial slip, "
      "unless a law says otherwise (Syamlal–O'Brien: ρ_f w d/μ_f; Koch–Hill: Hill's Re/2).";
};

// The registry of the family: every law, each preset included (registry.hpp). Extend it
// with a law of your own: `using MyDragLaws = DragLaws::with<MyLaw>;`.
using DragLaws =
    Registry<DragFamily, Ergun, ConstantExponentDrag, GidaspowSwitched, GidaspowBlended, GidaspowLeboreiro,
             DiFelice<single_particle::DallavalleCoefficient>, DiFelice<single_particle::SchillerNaumannCoefficient>,
             MazzeiLettieri, VanDerHoef, Beetstra, Tang, Tenneti, KochHill, SyamlalOBrien>;

using AnyDragLaw = DragLaws::Variant;

// One instance of every law of the family, each preset included.
inline constexpr std::array all_drag_laws = DragLaws::all();

inline constexpr std::string_view name_of(const AnyDragLaw& law) { return DragLaws::name_of(law); }

// The law called `name`, or nothing.
inline constexpr std::optional<AnyDragLaw> find_drag_law(std::string_view name) { return DragLaws::find(name); }

// The law called `name`; throws std::invalid_argument listing the known names.
inline AnyDragLaw make_drag_law(std::string_view name) { return DragLaws::make(name); }

// β of a run-time-selected law: the hot path, or with `fluidbed::checked` the law's `checked`.
template <class T, ErrorPolicy Policy = Unchecked>
DragCoefficient<T> evaluate(const AnyDragLaw& law, const DragState<T>& state, Policy = {}) {
  return std::visit(
      [&](const auto& l) {
        if constexpr (std::same_as<Policy, Checked>)
          return l.checked(state);
        else
          return l(state);
      },
      law);
}

// β and its derivatives of a run-time-selected law (with `fluidbed::checked`: checked_with_derivatives).
template <class T, ErrorPolicy Policy = Unchecked>
DragCoefficientWithDerivatives<T> evaluate_with_derivatives(const AnyDragLaw& law, const DragState<T>& state,
                                                            Policy = {}) {
  return std::visit(
      [&](const auto& l) {
        if constexpr (std::same_as<Policy, Checked>)
          return l.checked_with_derivatives(state);
        else
          return l.with_derivatives(state);
      },
      law);
}

}  // namespace fluidbed::drag
