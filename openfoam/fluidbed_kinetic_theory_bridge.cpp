// fluidbed — the C++20 side of the OpenFOAM plugin's kinetic-theory interface
// (fluidbed_kinetic_theory_bridge.h): fluidbed's kinetic-theory registries evaluated over whole
// arrays, one dispatch on the law per array, not per cell; derivatives from the laws'
// with_derivatives (dual numbers), never finite differences.
#include "fluidbed_kinetic_theory_bridge.h"

#include <algorithm>
#include <array>
#include <cfenv>
#include <cmath>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "fluidbed/kinetic_theory/registry.hpp"
#include "fluidbed_bridge_parameters.hpp"

namespace kt = fluidbed::kinetic_theory;

namespace {

// The registries, in the order of fluidbed_kt_kind.
using Registries = std::tuple<kt::RadialDistributions, kt::GranularPressures, kt::ShearViscosities,
                              kt::Conductivities, kt::FrictionalPressures, kt::FrictionalViscosities,
                              kt::FrictionalStresses>;

template <class>
struct VariantsOf;
template <class... Registry>
struct VariantsOf<std::tuple<Registry...>> {
  using type = std::variant<typename Registry::Variant...>;
};

// A law of any of the registries; its index is its fluidbed_kt_kind.
using AnyLaw = VariantsOf<Registries>::type;

template <std::size_t... kind>
AnyLaw make_law(std::size_t wanted, std::string_view name, std::index_sequence<kind...>) {
  AnyLaw law;
  const bool made = ((wanted == kind && (law.template emplace<kind>(std::tuple_element_t<kind, Registries>::make(name)),
                                         true)) ||
                     ...);
  if (!made) throw std::invalid_argument("fluidbed: unknown kind of kinetic-theory law " + std::to_string(wanted));
  return law;
}

// The parameters the solver gives every evaluation (alphaMax, alphaMinFriction): not dictionary
// entries.
constexpr std::array<std::string_view, 2> from_solver{"max_packing", "min_fraction"};

// The solver's packing limit and onset of friction, set on a copy of the law where it has them
// (MaAhmadi's fitted packing limit is not a parameter and stays).
template <class Law>
Law with_limits(Law law, double max_packing, double min_fraction) {
  if constexpr (requires { law.critical_state_pressure; })
    law.critical_state_pressure = with_limits(law.critical_state_pressure, max_packing, min_fraction);
  if constexpr (requires { law.max_packing = 0.0; }) law.max_packing = max_packing;
  if constexpr (requires { law.min_fraction = 0.0; }) law.min_fraction = min_fraction;
  return law;
}

}  // namespace

struct fluidbed_kt_law {
  AnyLaw law;
  std::string name;  // name() is a view, not necessarily terminated
};

namespace {

// The kinds, as the registries' error messages name them, in the order of fluidbed_kt_kind.
constexpr std::array<std::string_view, std::tuple_size_v<Registries>> kind_names{
    "radial distribution", "granular pressure", "shear viscosity",     "granular conductivity",
    "frictional pressure", "frictional viscosity", "frictional stress"};

// Calls cell(law, i) for i in [0, n) with the law of registry `kind`; returns n, or the index of
// the state whose evaluation threw, with the exception's text in `message`.
template <std::size_t kind, class Cell>
size_t over_cells(const fluidbed_kt_law* law, size_t n, char* message, size_t message_size, const Cell& cell) {
  size_t i = 0;
  try {
    if (law->law.index() != kind) throw std::invalid_argument("fluidbed: " + law->name + " is not a " +
                                                              std::string(kind_names[kind]));
    std::visit(
        [&](const auto& l) {
          for (; i < n; ++i) cell(l, i);
        },
        std::get<kind>(law->law));
  } catch (const std::exception& e) {
    fluidbed::openfoam::write_message(e.what(), message, message_size);
  }
  return i;
}

// Holds the floating-point environment with every trap disabled while it lives; restores it
// (traps and flags) on leaving, exceptions included.
class HeldFloatingPointTraps {
 public:
  HeldFloatingPointTraps() { std::feholdexcept(&saved_); }
  ~HeldFloatingPointTraps() { std::fesetenv(&saved_); }
  HeldFloatingPointTraps(const HeldFloatingPointTraps&) = delete;
  HeldFloatingPointTraps& operator=(const HeldFloatingPointTraps&) = delete;

 private:
  std::fenv_t saved_;
};

}  // namespace

extern "C" fluidbed_kt_law* fluidbed_kt_law_create(fluidbed_kt_kind kind, const char* name, char* message,
                                                   size_t message_size) {
  try {
    AnyLaw law = make_law(static_cast<std::size_t>(kind), name,
                          std::make_index_sequence<std::tuple_size_v<Registries>>{});
    std::string law_name(std::visit([](const auto& v) { return std::visit([](const auto& l) { return l.name(); }, v); }, law));
    return new fluidbed_kt_law{law, std::move(law_name)};
  } catch (const std::exception& e) {
    fluidbed::openfoam::write_message(e.what(), message, message_size);
    return nullptr;
  }
}

extern "C" void fluidbed_kt_law_destroy(fluidbed_kt_law* law) { delete law; }

extern "C" const char* fluidbed_kt_law_name(const fluidbed_kt_law* law) { return law->name.c_str(); }

extern "C" int fluidbed_kt_law_set(fluidbed_kt_law* law, const char* key, double value, char* message,
                                   size_t message_size) {
  return std::visit(
      [&](auto& v) {
        return std::visit(
            [&](auto& l) {
              return fluidbed::openfoam::set_dictionary_parameter(l, key, value, message, message_size, from_solver);
            },
            v);
      },
      law->law);
}

extern "C" size_t fluidbed_kt_radial_distribution(const fluidbed_kt_law* law, double max_packing,
                                                  double min_fraction, double slope_floor, size_t n, const double* phi,
                                                  double* g0, double* g0_slope, char* message, size_t message_size) {
  // The cube-root forms' slope at φ = 0 is 1/0, which a host may trap (OpenFOAM does): it is
  // computed with the floating-point traps held, and a non-finite slope is taken at slope_floor.
  const HeldFloatingPointTraps held;
  return over_cells<FLUIDBED_KT_RADIAL_DISTRIBUTION>(law, n, message, message_size, [&](const auto& l, size_t i) {
    const auto limited = with_limits(l, max_packing, min_fraction);
    g0[i] = limited.checked(phi[i]);
    if (g0_slope == nullptr) return;
    const double slope = limited.checked_with_derivatives(phi[i]).d_solid_fraction;
    g0_slope[i] = std::isfinite(slope) ? slope : limited.checked_with_derivatives(slope_floor).d_solid_fraction;
  });
}

extern "C" size_t fluidbed_kt_granular_pressure(const fluidbed_kt_law* law, size_t n, const double* phi,
                                                const double* g0, const double* g0_slope,
                                                const double* solid_density, double restitution, double* coefficient,
                                                double* slope, char* message, size_t message_size) {
  return over_cells<FLUIDBED_KT_GRANULAR_PRESSURE>(law, n, message, message_size, [&](const auto& l, size_t i) {
    // The pressures do not use the diameter; 1 m only satisfies the material's domain.
    const kt::GranularMaterial<double> material{1.0, solid_density[i], restitution};
    coefficient[i] = l.checked(phi[i], 1.0, g0[i], material);  // p_s is linear in Θ: p_s(Θ = 1) = p_s/Θ
    if (slope != nullptr) {
      // g0 as the solver's radial distribution gives it, to first order about phi[i].
      const auto radial = [&](const auto& x) { return g0[i] + g0_slope[i] * (x - phi[i]); };
      slope[i] = l.with_derivatives(phi[i], 1.0, radial, material).d_solid_fraction;
    }
  });
}

extern "C" size_t fluidbed_kt_shear_viscosity(const fluidbed_kt_law* law, size_t n, const double* phi,
                                              const double* theta, const double* g0, const double* diameter,
                                              const double* solid_density, double restitution,
                                              double* kinematic_viscosity, char* message, size_t message_size) {
  return over_cells<FLUIDBED_KT_SHEAR_VISCOSITY>(law, n, message, message_size, [&](const auto& l, size_t i) {
    const kt::GranularMaterial<double> material{diameter[i], solid_density[i], restitution};
    kinematic_viscosity[i] = l.checked(phi[i], theta[i], g0[i], material) / solid_density[i];
  });
}

extern "C" size_t fluidbed_kt_conductivity(const fluidbed_kt_law* law, size_t n, const double* phi,
                                           const double* theta, const double* g0, const double* diameter,
                                           const double* solid_density, double restitution, double* conductivity,
                                           char* message, size_t message_size) {
  return over_cells<FLUIDBED_KT_CONDUCTIVITY>(law, n, message, message_size, [&](const auto& l, size_t i) {
    conductivity[i] = l.checked(phi[i], theta[i], g0[i], kt::GranularMaterial<double>{diameter[i], solid_density[i],
                                                                                      restitution});
  });
}

extern "C" size_t fluidbed_kt_frictional_pressure(const fluidbed_kt_law* law, double max_packing,
                                                  double min_fraction, size_t n, const double* phi, double* pressure,
                                                  double* slope, char* message, size_t message_size) {
  return over_cells<FLUIDBED_KT_FRICTIONAL_PRESSURE>(law, n, message, message_size, [&](const auto& l, size_t i) {
    const auto r = with_limits(l, max_packing, min_fraction).checked_with_derivatives(phi[i]);
    pressure[i] = r.value;
    if (slope != nullptr) slope[i] = r.d_solid_fraction;
  });
}

extern "C" size_t fluidbed_kt_frictional_viscosity(const fluidbed_kt_law* law, size_t n,
                                                   const double* frictional_pressure, const double* divergence,
                                                   const double* contraction, double* viscosity, char* message,
                                                   size_t message_size) {
  return over_cells<FLUIDBED_KT_FRICTIONAL_VISCOSITY>(law, n, message, message_size, [&](const auto& l, size_t i) {
    viscosity[i] = l.checked(frictional_pressure[i], kt::StrainRate<double>{divergence[i], contraction[i]});
  });
}

extern "C" size_t fluidbed_kt_frictional_stress(const fluidbed_kt_law* law, double max_packing, double min_fraction,
                                                size_t n, const double* phi, const double* theta,
                                                const double* diameter, const double* divergence,
                                                const double* contraction, double* pressure, double* slope,
                                                double* viscosity, char* message, size_t message_size) {
  return over_cells<FLUIDBED_KT_FRICTIONAL_STRESS>(law, n, message, message_size, [&](const auto& l, size_t i) {
    const auto r = with_limits(l, max_packing, min_fraction)
                       .checked_with_derivatives(phi[i], theta[i], diameter[i],
                                                 kt::StrainRate<double>{divergence[i], contraction[i]});
    pressure[i] = r.pressure.value;
    if (slope != nullptr) slope[i] = r.pressure.d_solid_fraction;
    if (viscosity != nullptr) viscosity[i] = r.viscosity.value;
  });
}
