// fluidbed — the C interface's evaluations of the drag laws, the single-sphere drag
// coefficients, the terminal velocities, the minimum fluidization correlations and the
// Richardson–Zaki exponents (fluidbed_c.h) over arrays: one dispatch on the closure per array,
// each cell through the law's checked entry points.
#include <cstddef>
#include <string>
#include <variant>

#include "closure_handle.hpp"

using namespace fluidbed::c_api;

namespace {

constexpr std::size_t sphere_drag = FLUIDBED_SPHERE_DRAG_COEFFICIENT;
constexpr std::size_t terminal_velocity = FLUIDBED_TERMINAL_VELOCITY;
constexpr std::size_t richardson_zaki = FLUIDBED_RICHARDSON_ZAKI_EXPONENT;
constexpr std::size_t minimum_fluidization = FLUIDBED_MINIMUM_FLUIDIZATION;
constexpr std::size_t drag_law = FLUIDBED_DRAG_LAW;

fluidbed::drag::Buoyancy buoyancy_of(fluidbed_buoyancy convention) {
  switch (convention) {
    case FLUIDBED_BUOYANCY_CLASSICAL: return fluidbed::drag::Buoyancy::classical;
    case FLUIDBED_BUOYANCY_PRESSURE_GRADIENT: return fluidbed::drag::Buoyancy::pressure_gradient;
  }
  throw InvalidArgument("fluidbed: unknown fluidbed_buoyancy " + std::to_string(static_cast<int>(convention)));
}

// The value of law.checked(x) and, where asked for, the derivative of
// law.checked_with_derivatives(x) (member `d`), for the closures of one argument.
template <class Variant, class Value, class WithDerivative>
void one_argument(const Variant& closure, std::size_t n, const double* x, double* value, double* derivative,
                  const Value& value_of, const WithDerivative& derivative_of) {
  std::visit(
      [&](const auto& law) {
        for_each_cell(n, [&](std::size_t i) {
          value[i] = value_of(law, x[i]);
          if (derivative != nullptr) derivative[i] = derivative_of(law, x[i]);
        });
      },
      closure);
}

}  // namespace

extern "C" fluidbed_status fluidbed_drag(const fluidbed_closure* law, fluidbed_buoyancy convention, size_t n,
                                         const double* voidage, const double* slip, const double* fluid_density,
                                         const double* fluid_viscosity, const double* diameter, double* beta,
                                         double* d_voidage, double* d_slip, double* d_force_d_slip,
                                         fluidbed_error* error) {
  return guarded(error, [&] {
    const auto& closure = closure_of<drag_law>(law, "fluidbed_drag");
    const fluidbed::drag::Buoyancy b = buoyancy_of(convention);
    require_arrays(n, "fluidbed_drag", voidage, slip, fluid_density, fluid_viscosity, diameter, beta);
    const bool derivatives = d_voidage != nullptr || d_slip != nullptr || d_force_d_slip != nullptr;
    std::visit(
        [&](const auto& l) {
          for_each_cell(n, [&](std::size_t i) {
            const fluidbed::drag::DragState<double> state{
                voidage[i], slip[i], {fluid_density[i], fluid_viscosity[i]}, diameter[i]};
            beta[i] = l.checked(state).in(b);
            if (!derivatives) return;
            const auto with = l.checked_with_derivatives(state);
            const auto d = with.in(b);
            if (d_voidage != nullptr) d_voidage[i] = d.d_voidage;
            if (d_slip != nullptr) d_slip[i] = d.d_slip;
            if (d_force_d_slip != nullptr) d_force_d_slip[i] = with.force_slip_derivative(b);
          });
        },
        closure);
  });
}

extern "C" fluidbed_status fluidbed_sphere_drag_coefficient(const fluidbed_closure* law, size_t n,
                                                            const double* reynolds, double* cd_re, double* d_reynolds,
                                                            fluidbed_error* error) {
  return guarded(error, [&] {
    const auto& closure = closure_of<sphere_drag>(law, "fluidbed_sphere_drag_coefficient");
    require_arrays(n, "fluidbed_sphere_drag_coefficient", reynolds, cd_re);
    one_argument(
        closure, n, reynolds, cd_re, d_reynolds, [](const auto& l, double re) { return l.checked(re); },
        [](const auto& l, double re) { return l.checked_with_derivatives(re).d_reynolds; });
  });
}

extern "C" fluidbed_status fluidbed_reynolds_of_archimedes(const fluidbed_closure* law, size_t n,
                                                           const double* archimedes, double* reynolds,
                                                           double* d_archimedes, fluidbed_error* error) {
  return guarded(error, [&] {
    if (law == nullptr) throw InvalidArgument("fluidbed: fluidbed_reynolds_of_archimedes: the closure is NULL");
    require_arrays(n, "fluidbed_reynolds_of_archimedes", archimedes, reynolds);
    const auto value_of = [](const auto& l, double ar) { return l.checked_reynolds(ar); };
    const auto derivative_of = [](const auto& l, double ar) { return l.checked_with_derivatives(ar).d_archimedes; };
    if (law->closure.index() == minimum_fluidization)
      one_argument(closure_of<minimum_fluidization>(law, ""), n, archimedes, reynolds, d_archimedes, value_of,
                   derivative_of);
    else
      one_argument(closure_of<terminal_velocity>(law, "fluidbed_reynolds_of_archimedes"), n, archimedes, reynolds,
                   d_archimedes, value_of, derivative_of);
  });
}

extern "C" fluidbed_status fluidbed_richardson_zaki_exponent(const fluidbed_closure* law, size_t n,
                                                             const double* argument, double* exponent,
                                                             double* d_argument, fluidbed_error* error) {
  return guarded(error, [&] {
    const auto& closure = closure_of<richardson_zaki>(law, "fluidbed_richardson_zaki_exponent");
    require_arrays(n, "fluidbed_richardson_zaki_exponent", argument, exponent);
    one_argument(
        closure, n, argument, exponent, d_argument, [](const auto& l, double x) { return l.checked(x); },
        [](const auto& l, double x) { return l.checked_with_derivatives(x).d_argument; });
  });
}

extern "C" const char* fluidbed_richardson_zaki_argument(const fluidbed_closure* law) {
  if (law == nullptr || law->closure.index() != richardson_zaki) return nullptr;
  // The laws' `argument` is a literal: static storage, terminated.
  return std::visit([](const auto& l) { return std::remove_cvref_t<decltype(l)>::argument.data(); },
                    std::get<richardson_zaki>(law->closure));
}
