// fluidbed — the bindings' evaluations over arrays of cells, in the scalar type T (float or
// double): one dispatch on the closure per array, each cell through the closure's checked entry
// points, so that the values are bit for bit those of law.checked(...) in T and the derivatives
// those of law.checked_with_derivatives(...). A cell's failure is thrown as a CellError at its
// index; each binding turns it into its own error (the C interface's status, a Python exception).
// Outputs documented as optional may be null. Internal to the bindings: not installed.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "any_closure.hpp"
#include "fluidbed/kinetic_theory/unequal_temperature_mixture.hpp"
#include "fluidbed/moments/batched.hpp"
#include "fluidbed/moments/correction.hpp"
#include "fluidbed/moments/dqmom.hpp"
#include "fluidbed/moments/dqmom_batched.hpp"
#include "fluidbed/moments/realizability.hpp"

namespace fluidbed::bindings {

// The families, by their place in fluidbed::Registries (the C interface's fluidbed_family).
enum Family : std::size_t {
  sphere_drag_coefficients = 0,
  terminal_velocities = 1,
  richardson_zaki_exponents = 2,
  minimum_fluidizations = 3,
  drag_laws = 4,
  elastic_moduli = 5,
  radial_distributions = 6,
  mixture_radial_distributions = 7,
  granular_pressures = 8,
  shear_viscosities = 9,
  bulk_viscosities = 10,
  conductivities = 11,
  dissipations = 12,
  frictional_pressures = 13,
  frictional_viscosities = 14,
  frictional_stresses = 15,
  gas_exchange_sources = 16,
  solid_solid_drags = 17,
  wall_boundary_conditions = 18,
};
static_assert(std::is_same_v<RegistryOf<drag_laws>, drag::DragLaws> &&
                  std::is_same_v<RegistryOf<frictional_stresses>, kinetic_theory::FrictionalStresses> &&
                  std::is_same_v<RegistryOf<wall_boundary_conditions>, kinetic_theory::WallBoundaryConditions> &&
                  family_count == 19,
              "Family follows the order of fluidbed::Registries");

// Throws InvalidArgument unless every required array is there (any may be null when n is 0).
template <class... Pointer>
void require_arrays(std::size_t n, std::string_view function, const Pointer*... arrays) {
  if (n > 0 && ((arrays == nullptr) || ...))
    throw InvalidArgument("fluidbed: " + std::string(function) + ": an input or required output array is NULL");
}

namespace detail {

// value[i] = law.checked(x[i]) and, if derivative is not null, derivative_of(law, x[i]), for the
// closures of one argument.
template <class T, class Variant, class Value, class Derivative>
void of_one_argument(const Variant& closure, std::size_t n, const T* x, T* value, T* derivative, const Value& value_of,
                     const Derivative& derivative_of) {
  std::visit(
      [&](const auto& law) {
        for_each_cell(n, [&](std::size_t i) {
          value[i] = value_of(law, x[i]);
          if (derivative != nullptr) derivative[i] = derivative_of(law, x[i]);
        });
      },
      closure);
}

}  // namespace detail

// β in `convention` of a drag law and, optionally, ∂β/∂ε, ∂β/∂w and ∂(βw)/∂w.
template <class T>
void drag(const NamedClosure& law, drag::Buoyancy convention, std::size_t n, const T* voidage, const T* slip,
          const T* density, const T* viscosity, const T* diameter, T* beta, T* d_voidage, T* d_slip,
          T* d_force_d_slip) {
  const auto& closure = family_closure<drag_laws>(law, "drag");
  require_arrays(n, "drag", voidage, slip, density, viscosity, diameter, beta);
  const bool derivatives = d_voidage != nullptr || d_slip != nullptr || d_force_d_slip != nullptr;
  std::visit(
      [&](const auto& l) {
        for_each_cell(n, [&](std::size_t i) {
          const drag::DragState<T> state{voidage[i], slip[i], {density[i], viscosity[i]}, diameter[i]};
          beta[i] = l.checked(state).in(convention);
          if (!derivatives) return;
          const auto with = l.checked_with_derivatives(state);
          const auto d = with.in(convention);
          if (d_voidage != nullptr) d_voidage[i] = d.d_voidage;
          if (d_slip != nullptr) d_slip[i] = d.d_slip;
          if (d_force_d_slip != nullptr) d_force_d_slip[i] = with.force_slip_derivative(convention);
        });
      },
      closure);
}

// C_D·Re of a sphere at Re, and d(C_D·Re)/dRe.
template <class T>
void sphere_drag_coefficient(const NamedClosure& law, std::size_t n, const T* reynolds, T* cd_re, T* d_reynolds) {
  const auto& closure = family_closure<sphere_drag_coefficients>(law, "sphere_drag_coefficient");
  require_arrays(n, "sphere_drag_coefficient", reynolds, cd_re);
  detail::of_one_argument(
      closure, n, reynolds, cd_re, d_reynolds, [](const auto& l, T re) { return l.checked(re); },
      [](const auto& l, T re) { return l.checked_with_derivatives(re).d_reynolds; });
}

// Re_t (terminal velocities) or Re_mf (minimum fluidization) at Ar, and dRe/dAr.
template <class T>
void reynolds_of_archimedes(const NamedClosure& law, std::size_t n, const T* archimedes, T* reynolds,
                            T* d_archimedes) {
  require_arrays(n, "reynolds_of_archimedes", archimedes, reynolds);
  const auto value_of = [](const auto& l, T ar) { return l.checked_reynolds(ar); };
  const auto derivative_of = [](const auto& l, T ar) { return l.checked_with_derivatives(ar).d_archimedes; };
  if (law.family() == minimum_fluidizations)
    detail::of_one_argument(std::get<minimum_fluidizations>(law.closure), n, archimedes, reynolds, d_archimedes,
                            value_of, derivative_of);
  else
    detail::of_one_argument(family_closure<terminal_velocities>(law, "reynolds_of_archimedes"), n, archimedes,
                            reynolds, d_archimedes, value_of, derivative_of);
}

// The Richardson–Zaki exponent n at Re_t or Ar (the law's `argument`), and dn/dx.
template <class T>
void richardson_zaki_exponent(const NamedClosure& law, std::size_t n, const T* argument, T* exponent,
                              T* d_argument) {
  const auto& closure = family_closure<richardson_zaki_exponents>(law, "richardson_zaki_exponent");
  require_arrays(n, "richardson_zaki_exponent", argument, exponent);
  detail::of_one_argument(
      closure, n, argument, exponent, d_argument, [](const auto& l, T x) { return l.checked(x); },
      [](const auto& l, T x) { return l.checked_with_derivatives(x).d_argument; });
}

// "terminal_reynolds" or "archimedes"; empty for a closure of another family.
inline std::string_view richardson_zaki_argument(const NamedClosure& law) {
  if (law.family() != richardson_zaki_exponents) return {};
  return std::visit([](const auto& l) { return std::remove_cvref_t<decltype(l)>::argument; },
                    std::get<richardson_zaki_exponents>(law.closure));
}

// g0(φ) of a radial distribution or p_f(φ) of a frictional pressure, and d/dφ.
template <class T>
void of_solid_fraction(const NamedClosure& law, std::size_t n, const T* phi, T* value, T* slope) {
  require_arrays(n, "of_solid_fraction", phi, value);
  const auto value_of = [](const auto& l, T x) { return l.checked(x); };
  const auto slope_of = [](const auto& l, T x) { return l.checked_with_derivatives(x).d_solid_fraction; };
  if (law.family() == frictional_pressures)
    detail::of_one_argument(std::get<frictional_pressures>(law.closure), n, phi, value, slope, value_of, slope_of);
  else
    detail::of_one_argument(family_closure<radial_distributions>(law, "of_solid_fraction"), n, phi, value, slope,
                            value_of, slope_of);
}

inline bool is_constitutive(std::size_t family) {
  return family == granular_pressures || family == shear_viscosities || family == bulk_viscosities ||
         family == conductivities || family == dissipations;
}

// law(φ, Θ, g0(φ), material) with the radial distribution `radial`, and ∂/∂φ (through g0 as
// well) and ∂/∂Θ.
template <class T>
void constitutive(const NamedClosure& law, const NamedClosure& radial, std::size_t n, const T* phi, const T* theta,
                  const T* diameter, const T* solid_density, const T* restitution, T* value, T* d_phi, T* d_theta) {
  if (!is_constitutive(law.family()))
    throw InvalidArgument("fluidbed: constitutive: " + law.name + " is not a law of (phi, Theta, g0, material)");
  const auto& rdf = family_closure<radial_distributions>(radial, "constitutive");
  require_arrays(n, "constitutive", phi, theta, diameter, solid_density, restitution, value);
  const bool derivatives = d_phi != nullptr || d_theta != nullptr;
  std::visit(
      [&](const auto& g0) {
        visit_closure(law.closure, [&]<class Law>(const Law& l) {
          if constexpr (std::is_base_of_v<kinetic_theory::ConstitutiveLaw<Law>, Law>) {
            for_each_cell(n, [&](std::size_t i) {
              const kinetic_theory::GranularMaterial<T> material{diameter[i], solid_density[i], restitution[i]};
              value[i] = l.checked(phi[i], theta[i], g0.checked(phi[i]), material);
              if (!derivatives) return;
              const auto d = l.checked_with_derivatives(phi[i], theta[i], g0, material);
              if (d_phi != nullptr) d_phi[i] = d.d_solid_fraction;
              if (d_theta != nullptr) d_theta[i] = d.d_granular_temperature;
            });
          }
        });
      },
      rdf);
}

// μ_f(p_f, rate of strain) and ∂μ_f/∂p_f.
template <class T>
void frictional_viscosity(const NamedClosure& law, std::size_t n, const T* pressure, const T* divergence,
                          const T* contraction, T* viscosity, T* d_pressure) {
  const auto& closure = family_closure<frictional_viscosities>(law, "frictional_viscosity");
  require_arrays(n, "frictional_viscosity", pressure, divergence, contraction, viscosity);
  std::visit(
      [&](const auto& l) {
        for_each_cell(n, [&](std::size_t i) {
          const kinetic_theory::StrainRate<T> rate{divergence[i], contraction[i]};
          viscosity[i] = l.checked(pressure[i], rate);
          if (d_pressure != nullptr) d_pressure[i] = l.checked_with_derivatives(pressure[i], rate).d_frictional_pressure;
        });
      },
      closure);
}

// p_f and μ_f of a frictional stress law of (φ, Θ, d, rate of strain), and their ∂/∂φ.
template <class T>
void frictional_stress(const NamedClosure& law, std::size_t n, const T* phi, const T* theta, const T* diameter,
                       const T* divergence, const T* contraction, T* pressure, T* viscosity, T* d_pressure,
                       T* d_viscosity) {
  const auto& closure = family_closure<frictional_stresses>(law, "frictional_stress");
  require_arrays(n, "frictional_stress", phi, theta, diameter, divergence, contraction, pressure, viscosity);
  std::visit(
      [&](const auto& l) {
        for_each_cell(n, [&](std::size_t i) {
          const kinetic_theory::StrainRate<T> rate{divergence[i], contraction[i]};
          const auto stress = l.checked(phi[i], theta[i], diameter[i], rate);
          pressure[i] = stress.pressure;
          viscosity[i] = stress.viscosity;
          if (d_pressure == nullptr && d_viscosity == nullptr) return;
          const auto d = l.checked_with_derivatives(phi[i], theta[i], diameter[i], rate);
          if (d_pressure != nullptr) d_pressure[i] = d.pressure.d_solid_fraction;
          if (d_viscosity != nullptr) d_viscosity[i] = d.viscosity.d_solid_fraction;
        });
      },
      closure);
}

// The elastic modulus E^e [Pa] at equilibrium (ε, the fluid, the particles, Re_t, g) and ∂E^e/∂ε.
template <class T>
void elastic_modulus_at_equilibrium(const NamedClosure& model, std::size_t n, const T* voidage, const T* fluid_density,
                                    const T* fluid_viscosity, const T* particle_density, const T* diameter,
                                    const T* terminal_reynolds, const T* gravity, T* modulus, T* d_voidage) {
  const auto& closure = family_closure<elastic_moduli>(model, "elastic_modulus_at_equilibrium");
  require_arrays(n, "elastic_modulus_at_equilibrium", voidage, fluid_density, fluid_viscosity, particle_density,
                 diameter, terminal_reynolds, gravity, modulus);
  std::visit(
      [&](const auto& m) {
        for_each_cell(n, [&](std::size_t i) {
          const elastic::EquilibriumState<T> state{voidage[i], {fluid_density[i], fluid_viscosity[i]},
                                                   {particle_density[i], diameter[i]}, terminal_reynolds[i],
                                                   gravity[i]};
          modulus[i] = m.checked(state);
          if (d_voidage != nullptr) d_voidage[i] = m.checked_with_derivatives(state).d_voidage;
        });
      },
      closure);
}

// The elastic modulus E [Pa] off equilibrium, at a drag state (ε, w, ρ_f, μ_f, d), with ∂E/∂ε and
// ∂E/∂w, for the models that define one (Mazzei–Lettieri); InvalidArgument for the others.
template <class T>
void elastic_modulus_at_state(const NamedClosure& model, std::size_t n, const T* voidage, const T* slip,
                              const T* fluid_density, const T* fluid_viscosity, const T* diameter, T* modulus,
                              T* d_voidage, T* d_slip) {
  const auto& closure = family_closure<elastic_moduli>(model, "elastic_modulus_at_state");
  require_arrays(n, "elastic_modulus_at_state", voidage, slip, fluid_density, fluid_viscosity, diameter, modulus);
  std::visit(
      [&]<class Model>(const Model& m) {
        if constexpr (elastic::DefinedOffEquilibrium<Model, T>) {
          for_each_cell(n, [&](std::size_t i) {
            const drag::DragState<T> state{voidage[i], slip[i], {fluid_density[i], fluid_viscosity[i]}, diameter[i]};
            modulus[i] = m.checked(state);
            if (d_voidage == nullptr && d_slip == nullptr) return;
            const auto d = m.checked_with_derivatives(state);
            if (d_voidage != nullptr) d_voidage[i] = d.d_voidage;
            if (d_slip != nullptr) d_slip[i] = d.d_slip;
          });
        } else {
          throw InvalidArgument("fluidbed: elastic_modulus_at_state: " + model.name +
                                " defines no modulus off equilibrium");
        }
      },
      closure);
}

// The largest number of solids classes of the mixture kernels (MFiX's default number of solids
// phases): ∂g_ik/∂φ_m is computed with a dual number per class, whose size is compiled.
inline constexpr std::size_t max_classes = 10;

namespace detail {

template <std::size_t count>
using Count = std::integral_constant<std::size_t, count>;

// Calls f(Count<count>{}) for a run-time count in [1, max].
template <std::size_t max, class F>
void with_compiled_count(std::size_t count, F&& f) {
  [&]<std::size_t... c>(std::index_sequence<c...>) {
    static_cast<void>(((count == c + 1 ? (f(Count<c + 1>{}), true) : false) || ...));
  }(std::make_index_sequence<max>{});
}

}  // namespace detail

// g_ik of a mixture radial distribution over n cells of class_count classes (fractions[m n + c],
// diameters[m n + c]), and ∂g_ik/∂φ_m at d_fractions[m n + c]. The checked API validates i, k, the
// fractions and the diameters of every cell.
template <class T>
void mixture_radial_distribution(const NamedClosure& law, std::size_t n, std::size_t class_count, std::size_t i,
                                 std::size_t k, const T* fractions, const T* diameters, T* value, T* d_fractions) {
  const auto& closure = family_closure<mixture_radial_distributions>(law, "mixture_radial_distribution");
  if (class_count < 1 || class_count > max_classes)
    throw InvalidArgument("fluidbed: mixture_radial_distribution: " + std::to_string(class_count) +
                          " classes; 1 to " + std::to_string(max_classes) + " are offered");
  require_arrays(n, "mixture_radial_distribution", fractions, diameters, value);
  detail::with_compiled_count<max_classes>(class_count, [&]<std::size_t classes>(detail::Count<classes>) {
    std::visit(
        [&](const auto& l) {
          for_each_cell(n, [&](std::size_t c) {
            std::array<T, classes> phi{}, d{};
            for (std::size_t m = 0; m < classes; ++m) phi[m] = fractions[m * n + c], d[m] = diameters[m * n + c];
            value[c] = l.checked(std::span<const T>(phi), std::span<const T>(d), i, k);
            if (d_fractions == nullptr) return;
            const auto with = l.checked_with_derivatives(phi, std::span<const T>(d), i, k);
            for (std::size_t m = 0; m < classes; ++m) d_fractions[m * n + c] = with.d_fractions[m];
          });
        },
        closure);
  });
}

// K_pq of a solid-solid drag, and its derivatives in φ_p, φ_q, g_pq and |Δv|.
template <class T>
void solid_solid_drag(const NamedClosure& law, std::size_t n, const T* phi_p, const T* phi_q, const T* density_p,
                      const T* diameter_p, const T* density_q, const T* diameter_q, const T* restitution,
                      const T* contact_rdf, const T* relative_speed, T* coefficient, T* d_phi_p, T* d_phi_q,
                      T* d_contact_rdf, T* d_relative_speed) {
  const auto& closure = family_closure<solid_solid_drags>(law, "solid_solid_drag");
  require_arrays(n, "solid_solid_drag", phi_p, phi_q, density_p, diameter_p, density_q, diameter_q, restitution,
                 contact_rdf, relative_speed, coefficient);
  const bool derivatives = d_phi_p != nullptr || d_phi_q != nullptr || d_contact_rdf != nullptr ||
                           d_relative_speed != nullptr;
  std::visit(
      [&](const auto& l) {
        for_each_cell(n, [&](std::size_t c) {
          const Particles<T> p{density_p[c], diameter_p[c]}, q{density_q[c], diameter_q[c]};
          coefficient[c] = l.checked(phi_p[c], phi_q[c], p, q, restitution[c], contact_rdf[c], relative_speed[c]);
          if (!derivatives) return;
          const auto d =
              l.checked_with_derivatives(phi_p[c], phi_q[c], p, q, restitution[c], contact_rdf[c], relative_speed[c]);
          if (d_phi_p != nullptr) d_phi_p[c] = d.d_phi_p;
          if (d_phi_q != nullptr) d_phi_q[c] = d.d_phi_q;
          if (d_contact_rdf != nullptr) d_contact_rdf[c] = d.d_contact_rdf;
          if (d_relative_speed != nullptr) d_relative_speed[c] = d.d_relative_speed;
        });
      },
      closure);
}

// The quantities of kinetic_theory::ClassKineticValues, in the order the bindings pass them.
enum ClassQuantity : std::size_t {
  class_pressure,
  class_shear_viscosity,
  class_bulk_viscosity,
  class_conductivity,
  class_dissipation,
  class_drag,
  class_segregation,
  class_radial_distribution,
  class_quantity_count
};

// Where one quantity of the unequal-temperature mixture goes, each pointer null where it is not
// wanted. Over n cells of N classes: entry e (e = i for p_i and γ_i, e = i N + k for the
// matrices, row-major) of cell c at value[e n + c]; its derivative in α_m at
// d_fractions[m S + e n + c] and in Θ_m at d_temperatures[m S + e n + c], S = (entries) n the
// size of `value`: the derivatives in α_m are laid out as the quantity itself, m after m.
template <class T>
struct ClassOutput {
  T* value = nullptr;
  T* d_fractions = nullptr;
  T* d_temperatures = nullptr;
};
template <class T>
using ClassOutputs = std::array<ClassOutput<T>, class_quantity_count>;

namespace detail {

// f(quantity, entry, entries, x) for every entry x of `v`: the flattening of ClassOutput.
template <class V, std::size_t N, class F>
void for_each_class_entry(const kinetic_theory::ClassKineticValues<V, N>& v, F&& f) {
  for (std::size_t i = 0; i < N; ++i) {
    f(class_pressure, i, N, v.pressure[i]);
    f(class_dissipation, i, N, v.dissipation[i]);
    for (std::size_t k = 0; k < N; ++k) {
      const std::size_t e = i * N + k;
      f(class_shear_viscosity, e, N * N, v.shear_viscosity[i][k]);
      f(class_bulk_viscosity, e, N * N, v.bulk_viscosity[i][k]);
      f(class_conductivity, e, N * N, v.conductivity[i][k]);
      f(class_drag, e, N * N, v.drag[i][k]);
      f(class_segregation, e, N * N, v.segregation[i][k]);
      f(class_radial_distribution, e, N * N, v.radial_distribution[i][k]);
    }
  }
}

}  // namespace detail

// The kinetic theory of class_count classes with their own granular temperatures
// (kinetic_theory::UnequalTemperatureMixture, h_ik the mixture radial distribution `radial` with
// its parameters) over n cells: class m of cell c at fractions[m n + c] (α_m), temperatures[m n + c]
// (Θ_m), diameters[m n + c] and densities[m n + c]; the restitution of cell c at restitution[c].
// Outputs as ClassOutput says; the values from mixture.checked, the derivatives from
// mixture.checked_with_derivatives (evaluated only where one is wanted).
template <class T>
void unequal_temperature_mixture(const NamedClosure& radial, std::size_t n, std::size_t class_count,
                                 const T* fractions, const T* temperatures, const T* diameters, const T* densities,
                                 const T* restitution, const ClassOutputs<T>& out) {
  constexpr std::string_view function = "unequal_temperature_mixture";
  const auto& closure = family_closure<mixture_radial_distributions>(radial, function);
  if (class_count < 1 || class_count > max_classes)
    throw InvalidArgument("fluidbed: unequal_temperature_mixture: " + std::to_string(class_count) +
                          " classes; 1 to " + std::to_string(max_classes) + " are offered");
  require_arrays(n, function, fractions, temperatures, diameters, densities, restitution);
  bool derivatives = false;
  for (const ClassOutput<T>& o : out) derivatives = derivatives || o.d_fractions != nullptr || o.d_temperatures != nullptr;
  detail::with_compiled_count<max_classes>(class_count, [&]<std::size_t N>(detail::Count<N>) {
    std::visit(
        [&](const auto& rdf) {
          const kinetic_theory::UnequalTemperatureMixture mixture{rdf};
          for_each_cell(n, [&](std::size_t c) {
            kinetic_theory::GranularClassesState<T, N> state{};
            for (std::size_t m = 0; m < N; ++m) {
              const std::size_t at = m * n + c;
              state.fractions[m] = fractions[at], state.temperatures[m] = temperatures[at];
              state.diameters[m] = diameters[at], state.densities[m] = densities[at];
            }
            state.restitution = restitution[c];
            detail::for_each_class_entry(mixture.checked(state), [&](ClassQuantity q, std::size_t e, std::size_t,
                                                                     T x) {
              if (out[q].value != nullptr) out[q].value[e * n + c] = x;
            });
            if (!derivatives) return;
            detail::for_each_class_entry(
                mixture.checked_with_derivatives(state),
                [&](ClassQuantity q, std::size_t e, std::size_t entries, const kinetic_theory::ClassSensitivity<T, N>& x) {
                  for (std::size_t m = 0; m < N; ++m) {
                    const std::size_t at = (m * entries + e) * n + c;
                    if (out[q].d_fractions != nullptr) out[q].d_fractions[at] = x.d_fractions[m];
                    if (out[q].d_temperatures != nullptr) out[q].d_temperatures[at] = x.d_temperatures[m];
                  }
                });
          });
        },
        closure);
  });
}

// The gas's production of granular energy and its derivatives in φ, Θ, β and w. Each source reads
// its own arguments: Koch–Sangani the radial distribution and μ_g, the drag-based source β; the
// other's may be null.
template <class T>
void gas_exchange_source(const NamedClosure& law, const NamedClosure* radial, std::size_t n, const T* phi,
                         const T* theta, const T* slip, const T* beta, const T* gas_viscosity, const T* diameter,
                         const T* solid_density, const T* restitution, T* source, T* d_phi, T* d_theta, T* d_beta,
                         T* d_slip) {
  const auto& closure = family_closure<gas_exchange_sources>(law, "gas_exchange_source");
  require_arrays(n, "gas_exchange_source", phi, theta, slip, diameter, solid_density, restitution, source);
  const bool derivatives = d_phi != nullptr || d_theta != nullptr || d_beta != nullptr || d_slip != nullptr;
  const auto require_argument = [&](bool given, std::string_view what) {
    if (!given) throw InvalidArgument("fluidbed: gas_exchange_source: " + law.name + " needs " + std::string(what));
  };
  // Every cell's value_of(material, cell) and, if asked, its derivatives_of(material, cell).
  const auto over_cells = [&](const auto& value_of, const auto& derivatives_of) {
    for_each_cell(n, [&](std::size_t c) {
      const kinetic_theory::GranularMaterial<T> material{diameter[c], solid_density[c], restitution[c]};
      source[c] = value_of(material, c);
      if (!derivatives) return;
      const kinetic_theory::GasExchangeDerivatives<T> d = derivatives_of(material, c);
      if (d_phi != nullptr) d_phi[c] = d.d_solid_fraction;
      if (d_theta != nullptr) d_theta[c] = d.d_granular_temperature;
      if (d_beta != nullptr) d_beta[c] = d.d_beta;
      if (d_slip != nullptr) d_slip[c] = d.d_slip;
    });
  };
  std::visit(
      [&]<class Source>(const Source& s) {
        if constexpr (std::is_same_v<Source, kinetic_theory::KochSanganiSource>) {
          require_argument(radial != nullptr, "a radial distribution");
          require_argument(n == 0 || gas_viscosity != nullptr, "the gas viscosity");
          std::visit(
              [&](const auto& g0) {
                over_cells(
                    [&](const auto& m, std::size_t c) {
                      return s.checked(phi[c], theta[c], g0.checked(phi[c]), slip[c], gas_viscosity[c], m);
                    },
                    [&](const auto& m, std::size_t c) {
                      return s.checked_with_derivatives(phi[c], theta[c], g0, slip[c], gas_viscosity[c], m);
                    });
              },
              family_closure<radial_distributions>(*radial, "gas_exchange_source"));
        } else {
          static_assert(std::is_same_v<Source, kinetic_theory::DragFluctuationSource>, "a source of new arguments");
          require_argument(n == 0 || beta != nullptr, "beta");
          over_cells([&](const auto& m, std::size_t c) { return s.checked(phi[c], theta[c], beta[c], slip[c], m); },
                     [&](const auto& m, std::size_t c) {
                       return s.checked_with_derivatives(phi[c], theta[c], beta[c], slip[c], m);
                     });
        }
      },
      closure);
}

// The largest node count the bindings invert for (fluidbed::moments handles any N; the bindings
// dispatch a run-time count to the compiled ones).
inline constexpr int max_nodes = 8;

namespace detail {

template <class T, int N>
void invert_moments(const moments::InversionOptions& options, std::size_t n, const T* moments_in, T* nodes,
                    T* weights, int* sizes, int* statuses, T* node_errors, T* weight_errors, T* count_errors) {
  moments::MomentBatch<T, N> in;
  for (int k = 0; k < 2 * N; ++k) in.moments[k] = std::span<const T>(moments_in + k * n, n);
  moments::QuadratureBatch<T, N> out;
  for (int i = 0; i < N; ++i) {
    out.nodes[i] = std::span<T>(nodes + i * n, n);
    out.weights[i] = std::span<T>(weights + i * n, n);
  }
  std::vector<moments::InversionStatus> status(n);
  out.sizes = std::span<int>(sizes, n);
  out.status = std::span<moments::InversionStatus>(status);
  if (node_errors != nullptr) out.node_errors = std::span<T>(node_errors, n);
  if (weight_errors != nullptr) out.weight_errors = std::span<T>(weight_errors, n);
  if (count_errors != nullptr) out.count_errors = std::span<T>(count_errors, n);
  if (!moments::invert_batched(in, out, options)) throw InvalidArgument("fluidbed: invert_moments: inconsistent sizes");
  for (std::size_t c = 0; c < n; ++c) statuses[c] = static_cast<int>(status[c]);
}

}  // namespace detail

// The accuracies of the inversion's error estimate, or std::domain_error naming the first out
// of its domain (the C++ library reads them unchecked).
inline void require_valid(const moments::InversionOptions& options) {
  const auto require_accuracy = [](std::string_view name, double accuracy) {
    if (!(accuracy >= 0 && accuracy < std::numeric_limits<double>::infinity()))
      fluidbed::detail::throw_domain_error("moments::invert_batched", name, accuracy, "must be finite and >= 0");
  };
  require_accuracy("moment_accuracy", options.moment_accuracy);
  require_accuracy("required_accuracy", options.required_accuracy);
}

// Inverts n cells' 2N moments each to N-node Gauss rules (moments::invert_batched with
// `options`: the support and the error estimate), structure of arrays: moment k of cell c at
// moments_in[k n + c], node i at nodes[i n + c], its weight at weights[i n + c] (0 for
// i >= sizes[c]), the node count and the per-cell status (moments::InversionStatus as int) of
// every cell. node_errors, weight_errors and count_errors may be null; each given receives
// each cell's estimated largest relative node or weight error, or its node count's error, as
// QuadratureBatch's spans do (−1: no rule, not reduced, or options.estimate_error false and no
// required accuracy; +∞: no digit). A cell that cannot be inverted has its status, never an exception: only a node
// count outside 1 … max_nodes, a missing array or an accuracy out of its domain throws.
template <class T>
void invert_moments(int node_count, const moments::InversionOptions& options, std::size_t n, const T* moments_in,
                    T* nodes, T* weights, int* sizes, int* statuses, T* node_errors = nullptr,
                    T* weight_errors = nullptr, T* count_errors = nullptr) {
  if (node_count < 1 || node_count > max_nodes)
    throw InvalidArgument("fluidbed: invert_moments: " + std::to_string(node_count) + " nodes; 1 to " +
                          std::to_string(max_nodes) + " are offered");
  require_arrays(n, "invert_moments", moments_in, nodes, weights, sizes, statuses);
  require_valid(options);
  detail::with_compiled_count<max_nodes>(std::size_t(node_count), [&]<std::size_t N>(detail::Count<N>) {
    detail::invert_moments<T, int(N)>(options, n, moments_in, nodes, weights, sizes, statuses, node_errors,
                                      weight_errors, count_errors);
  });
}

namespace detail {

// Throws InvalidArgument unless 1 <= moment_count <= 2 max_nodes.
inline void require_moment_count(int moment_count, std::string_view function) {
  if (moment_count < 1 || moment_count > 2 * max_nodes)
    throw InvalidArgument("fluidbed: " + std::string(function) + ": " + std::to_string(moment_count) +
                          " moments; 1 to " + std::to_string(2 * max_nodes) + " are offered");
}

// f(cell's moments as a span, integral_constant N) for each of n cells of moment_count moments
// (moment k of cell c at moments_in[k n + c]), N = ⌈moment_count/2⌉ the compiled node count.
template <class T, class F>
void for_each_moment_set(int moment_count, std::size_t n, const T* moments_in, F&& f) {
  with_compiled_count<max_nodes>(std::size_t(moment_count + 1) / 2, [&]<std::size_t N>(Count<N> nodes) {
    std::array<T, 2 * N> m{};
    for (std::size_t c = 0; c < n; ++c) {
      for (std::size_t k = 0; k < std::size_t(moment_count); ++k) m[k] = moments_in[k * n + c];
      f(c, std::span<const T>(m.data(), std::size_t(moment_count)), nodes);
    }
  });
}

}  // namespace detail

// The realizability of n cells' moment sets (moments::realizability): the status
// (moments::InversionStatus as int), the realizable prefix's length and, optionally, the first
// failing coefficient's index and value. A cell's outcome is its status, never an exception.
template <class T>
void moment_realizability(moments::Support support, int moment_count, std::size_t n, const T* moments_in,
                          int* statuses, int* realizable_moments, int* first_failing_index, T* failing_value) {
  detail::require_moment_count(moment_count, "moment_realizability");
  require_arrays(n, "moment_realizability", moments_in, statuses, realizable_moments);
  const auto assess = [&]<std::size_t N>(std::size_t c, std::span<const T> m, detail::Count<N>) {
    const auto report = moments::realizability<T, int(N)>(m, support);
    statuses[c] = static_cast<int>(report.status);
    realizable_moments[c] = report.realizable_moments;
    if (first_failing_index != nullptr) first_failing_index[c] = report.first_failing_index;
    if (failing_value != nullptr) failing_value[c] = report.failing_value;
  };
  detail::for_each_moment_set(moment_count, n, moments_in, assess);
}

// The options of the correction, or std::domain_error naming the first out of its domain.
template <class T>
void require_valid(const moments::CorrectionOptions<T>& options) {
  constexpr std::string_view function = "moments::correct_moments";
  if (options.protected_moments < 1)
    fluidbed::detail::throw_domain_error(function, "protected_moments", options.protected_moments, "must be >= 1");
  if (options.max_iterations < 0)
    fluidbed::detail::throw_domain_error(function, "max_iterations", options.max_iterations, "must be >= 0");
  if (!(options.degenerate_tolerance >= T(0) && options.degenerate_tolerance < std::numeric_limits<T>::infinity()))
    fluidbed::detail::throw_domain_error(function, "degenerate_tolerance", options.degenerate_tolerance,
                                         "must be finite and >= 0");
}

// The correction of n cells' size moment sets (moments::correct_moments) into `corrected` (laid
// out as moments_in, which it may be), the status (moments::CorrectionStatus as int) and,
// optionally, the realizable prefix of the returned set.
template <class T>
void correct_moments(int moment_count, std::size_t n, const T* moments_in, const moments::CorrectionOptions<T>& options,
                     T* corrected, int* statuses, int* realizable_moments) {
  detail::require_moment_count(moment_count, "correct_moments");
  require_arrays(n, "correct_moments", moments_in, corrected, statuses);
  require_valid(options);
  const auto correct = [&]<std::size_t N>(std::size_t c, std::span<const T> m, detail::Count<N>) {
    const auto result = moments::correct_moments<T, int(N)>(m, options);
    for (std::size_t k = 0; k < m.size(); ++k) corrected[k * n + c] = result.moments[k];
    statuses[c] = static_cast<int>(result.status);
    if (realizable_moments != nullptr) realizable_moments[c] = result.realizable_moments;
  };
  detail::for_each_moment_set(moment_count, n, moments_in, correct);
}


// DQMOM sources of n cells of node_count nodes each (moments::dqmom::solve_batched), structure of
// arrays: node i of cell c at nodes[i n + c], its weight at weights[i n + c], moment source k at
// moment_sources[k n + c] (k = 0 … 2 node_count − 1); writes c^a at weight_sources[i n + c], c^ξ at
// weighted_node_sources[i n + c], the status (moments::dqmom::SourceStatus as int) and, if
// condition is not null, κ_∞. A cell's outcome is its status; only a node count outside
// 1 … max_nodes or a missing array throws.
template <class T>
void dqmom_sources(int node_count, std::size_t n, const T* nodes, const T* weights, const T* moment_sources,
                   T* weight_sources, T* weighted_node_sources, int* statuses, T* condition) {
  if (node_count < 1 || node_count > max_nodes)
    throw InvalidArgument("fluidbed: dqmom_sources: " + std::to_string(node_count) + " nodes; 1 to " +
                          std::to_string(max_nodes) + " are offered");
  require_arrays(n, "dqmom_sources", nodes, weights, moment_sources, weight_sources, weighted_node_sources, statuses);
  detail::with_compiled_count<max_nodes>(std::size_t(node_count), [&]<std::size_t N>(detail::Count<N>) {
    moments::dqmom::SourceBatch<T, int(N)> batch;
    for (std::size_t i = 0; i < N; ++i) {
      batch.nodes[i] = std::span<const T>(nodes + i * n, n);
      batch.weights[i] = std::span<const T>(weights + i * n, n);
      batch.weight_sources[i] = std::span<T>(weight_sources + i * n, n);
      batch.weighted_node_sources[i] = std::span<T>(weighted_node_sources + i * n, n);
    }
    for (std::size_t k = 0; k < 2 * N; ++k) batch.moment_sources[k] = std::span<const T>(moment_sources + k * n, n);
    std::vector<moments::dqmom::SourceStatus> status(n);
    batch.status = std::span<moments::dqmom::SourceStatus>(status);
    if (condition != nullptr) batch.condition = std::span<T>(condition, n);
    moments::dqmom::solve_batched(batch);
    for (std::size_t c = 0; c < n; ++c) statuses[c] = static_cast<int>(status[c]);
  });
}

// DQMOM sources of growth at rates growth_rate[i n + c] (weights of the given kind) and of
// diffusion of intensity 𝒞_i = diffusion_intensity[i n + c], as point functionals
// (moments::dqmom::System, growth_terms, diffusion_terms: exact to rounding); either array may be
// null (no such source). Layout and outputs as dqmom_sources.
template <class T>
void dqmom_growth_diffusion_sources(int node_count, moments::dqmom::Weights form, std::size_t n, const T* nodes,
                                    const T* weights, const T* growth_rate, const T* diffusion_intensity,
                                    T* weight_sources, T* weighted_node_sources, int* statuses, T* condition) {
  if (node_count < 1 || node_count > max_nodes)
    throw InvalidArgument("fluidbed: dqmom_growth_diffusion_sources: " + std::to_string(node_count) +
                          " nodes; 1 to " + std::to_string(max_nodes) + " are offered");
  require_arrays(n, "dqmom_growth_diffusion_sources", nodes, weights, weight_sources, weighted_node_sources, statuses);
  detail::with_compiled_count<max_nodes>(std::size_t(node_count), [&]<std::size_t N>(detail::Count<N>) {
    for_each_cell(n, [&](std::size_t c) {
      std::array<T, N> x{}, w{}, rate{}, intensity{};
      for (std::size_t i = 0; i < N; ++i) {
        x[i] = nodes[i * n + c], w[i] = weights[i * n + c];
        rate[i] = growth_rate != nullptr ? growth_rate[i * n + c] : T(0);
        intensity[i] = diffusion_intensity != nullptr ? diffusion_intensity[i * n + c] : T(0);
      }
      const moments::dqmom::System<T, int(N)> system{std::span<const T>(x), std::span<const T>(w)};
      const auto growth = moments::dqmom::growth_terms<T, int(N)>(form, std::span<const T>(w), std::span<const T>(x),
                                                                  std::span<const T>(rate));
      const auto diffusion =
          moments::dqmom::diffusion_terms<T, int(N)>(std::span<const T>(x), std::span<const T>(intensity));
      std::array<moments::dqmom::PointSource<T>, 3 * N> terms{};
      for (std::size_t j = 0; j < 2 * N; ++j) terms[j] = growth[j];
      for (std::size_t j = 0; j < N; ++j) terms[2 * N + j] = diffusion[j];
      const auto out = system.solve(std::span<const moments::dqmom::PointSource<T>>(terms));
      for (std::size_t i = 0; i < N; ++i) {
        weight_sources[i * n + c] = out.weight[i];
        weighted_node_sources[i * n + c] = out.weighted_node[i];
      }
      statuses[c] = static_cast<int>(out.status);
      if (condition != nullptr) condition[c] = out.condition;
    });
  });
}

}  // namespace fluidbed::bindings
