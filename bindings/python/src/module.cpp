// fluidbed._fluidbed — the compiled part of the Python package (bindings/python/fluidbed): closures
// by name with their metadata and parameters, and the bindings' shared array kernels
// (bindings/common/kernels.hpp) over contiguous one-dimensional NumPy arrays of float64 or float32.
// Broadcasting, shapes, conventions by name and the documentation are the pure-Python layer's.
// Errors become fluidbed.Error subclasses carrying the C++ library's message (and, for a cell,
// its flat index).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "any_closure.hpp"
#include "kernels.hpp"

namespace py = pybind11;
namespace fb = fluidbed::bindings;

namespace {

template <class T>
using Array = py::array_t<T, py::array::c_style>;

// The Python exception types, set by the package (fluidbed/__init__.py) at import; kept for the
// interpreter's life (a static py::object would be released after the interpreter has ended).
py::dict* error_types = nullptr;

// Runs body with the GIL released; a cell's failure or the library's exception becomes the
// package's exception of that kind, with the cell's flat index where there is one.
template <class Body>
void guarded(Body&& body) {
  std::optional<std::size_t> index;
  std::string message;
  const char* kind = nullptr;
  {
    py::gil_scoped_release release;
    try {
      try {
        body();
        return;
      } catch (const fb::CellError& cell) {
        index = cell.index;
        std::rethrow_exception(cell.cause);
      }
    } catch (const fb::UnknownName& e) {
      kind = "UnknownName", message = e.what();
    } catch (const fb::UnknownParameter& e) {
      kind = "UnknownParameter", message = e.what();
    } catch (const fb::InvalidArgument& e) {
      kind = "InvalidArgument", message = e.what();
    } catch (const std::domain_error& e) {
      kind = "DomainError", message = e.what();
    } catch (const std::exception& e) {
      kind = "Error", message = e.what();
    }
  }
  py::object error = (*error_types)[kind](message);
  error.attr("index") = index ? py::cast(*index) : py::none();
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
  throw py::error_already_set();
}

template <class T>
const T* data_of(const std::optional<Array<T>>& a) {
  return a ? a->data() : nullptr;
}

// A new output array of n elements, or nothing where it is not asked for.
template <class T>
std::optional<Array<T>> output(py::ssize_t n, bool wanted) {
  return wanted ? std::optional<Array<T>>(Array<T>(n)) : std::nullopt;
}

template <class T>
T* data_of(std::optional<Array<T>>& a) {
  return a ? a->mutable_data() : nullptr;
}

template <class T>
py::tuple drag(const fb::NamedClosure& law, bool pressure_gradient, const Array<T>& voidage, const Array<T>& slip,
               const Array<T>& density, const Array<T>& viscosity, const Array<T>& diameter, bool derivatives) {
  const py::ssize_t n = voidage.size();
  Array<T> beta(n);
  auto d_voidage = output<T>(n, derivatives), d_slip = output<T>(n, derivatives), d_force = output<T>(n, derivatives);
  const auto convention = pressure_gradient ? fluidbed::drag::Buoyancy::pressure_gradient
                                            : fluidbed::drag::Buoyancy::classical;
  T* out = beta.mutable_data();
  guarded([&] {
    fb::drag<T>(law, convention, static_cast<std::size_t>(n), voidage.data(), slip.data(), density.data(),
                viscosity.data(), diameter.data(), out, data_of(d_voidage), data_of(d_slip), data_of(d_force));
  });
  return py::make_tuple(beta, d_voidage, d_slip, d_force);
}

template <class T>
py::tuple constitutive(const fb::NamedClosure& law, const fb::NamedClosure& radial, const Array<T>& phi,
                       const Array<T>& theta, const Array<T>& diameter, const Array<T>& density,
                       const Array<T>& restitution, bool derivatives) {
  const py::ssize_t n = phi.size();
  Array<T> value(n);
  auto d_phi = output<T>(n, derivatives), d_theta = output<T>(n, derivatives);
  T* out = value.mutable_data();
  guarded([&] {
    fb::constitutive<T>(law, radial, static_cast<std::size_t>(n), phi.data(), theta.data(), diameter.data(),
                        density.data(), restitution.data(), out, data_of(d_phi), data_of(d_theta));
  });
  return py::make_tuple(value, d_phi, d_theta);
}

// The closures of one argument: value and derivative.
template <class T, class Kernel>
py::tuple one_argument(const fb::NamedClosure& law, const Array<T>& x, bool derivatives, const Kernel& kernel) {
  const py::ssize_t n = x.size();
  Array<T> value(n);
  auto slope = output<T>(n, derivatives);
  T* out = value.mutable_data();
  guarded([&] { kernel(law, static_cast<std::size_t>(n), x.data(), out, data_of(slope)); });
  return py::make_tuple(value, slope);
}

// Moment inversion of n cells, moment-major (moment k of cell c at [k, c]), with the error
// estimate's options (moments::InversionOptions): the estimates are returned where asked for,
// None otherwise.
template <class T>
py::tuple invert_moments(int node_count, bool real_line, const Array<T>& moments_in, double moment_accuracy,
                         double required_accuracy, bool estimate_error) {
  if (moments_in.ndim() != 2)
    guarded([] { throw fb::InvalidArgument("fluidbed: invert_moments: moments must be (2N, cells)"); });
  const py::ssize_t n = moments_in.shape(1);
  if (moments_in.shape(0) != 2 * node_count)
    guarded([&] {
      throw fb::InvalidArgument("fluidbed: invert_moments: " + std::to_string(moments_in.shape(0)) +
                                " moments per cell for " + std::to_string(node_count) + " nodes");
    });
  Array<T> nodes({static_cast<py::ssize_t>(node_count), n}), weights({static_cast<py::ssize_t>(node_count), n});
  py::array_t<int> sizes(n), status(n);
  auto node_errors = output<T>(n, estimate_error), weight_errors = output<T>(n, estimate_error),
       count_errors = output<T>(n, estimate_error);
  T *x = nodes.mutable_data(), *w = weights.mutable_data(), *dx = data_of(node_errors), *dw = data_of(weight_errors),
    *dr = data_of(count_errors);
  int *s = sizes.mutable_data(), *st = status.mutable_data();
  const fluidbed::moments::InversionOptions options{
      .support = real_line ? fluidbed::moments::Support::real_line : fluidbed::moments::Support::positive_half_line,
      .estimate_error = estimate_error,
      .moment_accuracy = moment_accuracy,
      .required_accuracy = required_accuracy};
  guarded([&] {
    fb::invert_moments<T>(node_count, options, static_cast<std::size_t>(n), moments_in.data(), x, w, s, st, dx, dw,
                          dr);
  });
  return py::make_tuple(nodes, weights, sizes, status, node_errors, weight_errors, count_errors);
}

// The moment functions' sets, moment-major (moment k of cell c at [k, c]): their count.
template <class T>
py::ssize_t moment_rows(const Array<T>& moments_in) {
  if (moments_in.ndim() != 2)
    guarded([] { throw fb::InvalidArgument("fluidbed: the moments must be (moment count, cells)"); });
  return moments_in.shape(0);
}

template <class T>
py::tuple moment_realizability(bool real_line, const Array<T>& moments_in) {
  const py::ssize_t count = moment_rows(moments_in), n = moments_in.shape(1);
  py::array_t<int> status(n), realizable(n), first_failing(n);
  Array<T> failing(n);
  int *st = status.mutable_data(), *r = realizable.mutable_data(), *f = first_failing.mutable_data();
  T* v = failing.mutable_data();
  guarded([&] {
    fb::moment_realizability<T>(real_line ? fluidbed::moments::Support::real_line
                                          : fluidbed::moments::Support::positive_half_line,
                                static_cast<int>(count), static_cast<std::size_t>(n), moments_in.data(), st, r, f, v);
  });
  return py::make_tuple(status, realizable, first_failing, failing);
}

// The correction with the options given, each None for the library's default.
template <class T>
py::tuple correct_moments(const Array<T>& moments_in, std::optional<int> protected_moments,
                          std::optional<int> max_iterations, std::optional<double> degenerate_tolerance) {
  const py::ssize_t count = moment_rows(moments_in), n = moments_in.shape(1);
  fluidbed::moments::CorrectionOptions<T> options;
  if (protected_moments) options.protected_moments = *protected_moments;
  if (max_iterations) options.max_iterations = *max_iterations;
  if (degenerate_tolerance) options.degenerate_tolerance = static_cast<T>(*degenerate_tolerance);
  Array<T> corrected({count, n});
  py::array_t<int> status(n), realizable(n);
  T* out = corrected.mutable_data();
  int *st = status.mutable_data(), *r = realizable.mutable_data();
  guarded([&] {
    fb::correct_moments<T>(static_cast<int>(count), static_cast<std::size_t>(n), moments_in.data(), options, out, st,
                           r);
  });
  return py::make_tuple(corrected, status, realizable);
}

// DQMOM sources of cells whose nodes and weights are the rows of (N, cells) arrays; moment sources
// (2N, cells), or growth rates and diffusion intensities (N, cells) each optional.
template <class T>
py::ssize_t dqmom_node_rows(const Array<T>& nodes, const Array<T>& weights) {
  if (nodes.ndim() != 2 || weights.ndim() != 2 || nodes.shape(0) != weights.shape(0) ||
      nodes.shape(1) != weights.shape(1))
    guarded([] { throw fb::InvalidArgument("fluidbed: the nodes and weights must be (nodes, cells) alike"); });
  return nodes.shape(0);
}

template <class T>
py::tuple dqmom_sources(const Array<T>& nodes, const Array<T>& weights, const Array<T>& sources) {
  const py::ssize_t count = dqmom_node_rows(nodes, weights), n = nodes.shape(1);
  if (sources.ndim() != 2 || sources.shape(0) != 2 * count || sources.shape(1) != n)
    guarded([] { throw fb::InvalidArgument("fluidbed: dqmom_sources: the moment sources must be (2 nodes, cells)"); });
  Array<T> a({count, n}), b({count, n}), condition(n);
  py::array_t<int> status(n);
  T *pa = a.mutable_data(), *pb = b.mutable_data(), *pc = condition.mutable_data();
  int* st = status.mutable_data();
  guarded([&] {
    fb::dqmom_sources<T>(static_cast<int>(count), static_cast<std::size_t>(n), nodes.data(), weights.data(),
                         sources.data(), pa, pb, st, pc);
  });
  return py::make_tuple(a, b, status, condition);
}

template <class T>
py::tuple dqmom_growth_diffusion_sources(bool number_density, const Array<T>& nodes, const Array<T>& weights,
                                         const std::optional<Array<T>>& growth, const std::optional<Array<T>>& intensity) {
  const py::ssize_t count = dqmom_node_rows(nodes, weights), n = nodes.shape(1);
  for (const auto* field : {&growth, &intensity})
    if (*field && ((*field)->ndim() != 2 || (*field)->shape(0) != count || (*field)->shape(1) != n))
      guarded([] { throw fb::InvalidArgument("fluidbed: growth rates and diffusion intensities must be (nodes, cells)"); });
  Array<T> a({count, n}), b({count, n}), condition(n);
  py::array_t<int> status(n);
  T *pa = a.mutable_data(), *pb = b.mutable_data(), *pc = condition.mutable_data();
  int* st = status.mutable_data();
  guarded([&] {
    fb::dqmom_growth_diffusion_sources<T>(
        static_cast<int>(count),
        number_density ? fluidbed::moments::dqmom::Weights::number_density : fluidbed::moments::dqmom::Weights::volume_fraction,
        static_cast<std::size_t>(n), nodes.data(), weights.data(), growth ? growth->data() : nullptr,
        intensity ? intensity->data() : nullptr, pa, pb, st, pc);
  });
  return py::make_tuple(a, b, status, condition);
}

// g_ik of cells whose classes are the rows of fractions and diameters (class m of cell c at [m, c]).
template <class T>
py::tuple mixture_radial_distribution(const fb::NamedClosure& law, std::size_t i, std::size_t k,
                                      const Array<T>& fractions, const Array<T>& diameters, bool derivatives) {
  if (fractions.ndim() != 2 || diameters.ndim() != 2 || fractions.shape(0) != diameters.shape(0) ||
      fractions.shape(1) != diameters.shape(1))
    guarded([] { throw fb::InvalidArgument("fluidbed: the fractions and diameters must be (classes, cells) alike"); });
  const py::ssize_t classes = fractions.shape(0), n = fractions.shape(1);
  Array<T> value(n);
  auto slopes = derivatives ? std::optional<Array<T>>(Array<T>({classes, n})) : std::nullopt;
  T* out = value.mutable_data();
  guarded([&] {
    fb::mixture_radial_distribution<T>(law, static_cast<std::size_t>(n), static_cast<std::size_t>(classes), i, k,
                                       fractions.data(), diameters.data(), out, data_of(slopes));
  });
  return py::make_tuple(value, slopes);
}

template <class T>
py::tuple solid_solid_drag(const fb::NamedClosure& law, const Array<T>& phi_p, const Array<T>& phi_q,
                           const Array<T>& density_p, const Array<T>& diameter_p, const Array<T>& density_q,
                           const Array<T>& diameter_q, const Array<T>& restitution, const Array<T>& contact_rdf,
                           const Array<T>& relative_speed, bool derivatives) {
  const py::ssize_t n = phi_p.size();
  Array<T> value(n);
  auto d_phi_p = output<T>(n, derivatives), d_phi_q = output<T>(n, derivatives), d_g = output<T>(n, derivatives),
       d_speed = output<T>(n, derivatives);
  T* out = value.mutable_data();
  guarded([&] {
    fb::solid_solid_drag<T>(law, static_cast<std::size_t>(n), phi_p.data(), phi_q.data(), density_p.data(),
                            diameter_p.data(), density_q.data(), diameter_q.data(), restitution.data(),
                            contact_rdf.data(), relative_speed.data(), out, data_of(d_phi_p), data_of(d_phi_q),
                            data_of(d_g), data_of(d_speed));
  });
  return py::make_tuple(value, d_phi_p, d_phi_q, d_g, d_speed);
}

// A gas exchange source; beta, gas_viscosity and radial are None where the source does not read them.
template <class T>
py::tuple gas_exchange_source(const fb::NamedClosure& law, const fb::NamedClosure* radial, const Array<T>& phi,
                              const Array<T>& theta, const Array<T>& slip, const std::optional<Array<T>>& beta,
                              const std::optional<Array<T>>& gas_viscosity, const Array<T>& diameter,
                              const Array<T>& density, const Array<T>& restitution, bool derivatives) {
  const py::ssize_t n = phi.size();
  Array<T> value(n);
  auto d_phi = output<T>(n, derivatives), d_theta = output<T>(n, derivatives), d_beta = output<T>(n, derivatives),
       d_slip = output<T>(n, derivatives);
  T* out = value.mutable_data();
  guarded([&] {
    fb::gas_exchange_source<T>(law, radial, static_cast<std::size_t>(n), phi.data(), theta.data(), slip.data(),
                               data_of(beta), data_of(gas_viscosity), diameter.data(), density.data(),
                               restitution.data(), out, data_of(d_phi), data_of(d_theta), data_of(d_beta),
                               data_of(d_slip));
  });
  return py::make_tuple(value, d_phi, d_theta, d_beta, d_slip);
}

// The unequal-temperature mixture of cells whose classes are the rows of (classes, cells) arrays,
// restitution (cells,): a tuple of the quantities in fb::ClassQuantity's order, (classes, cells)
// for p and γ and (classes, classes, cells) for the matrices, and, with derivatives, tuples of
// their ∂/∂α_m and ∂/∂Θ_m, each (classes_m, ...) the quantity's shape m after m; else None.
template <class T>
py::tuple unequal_temperature_mixture(const fb::NamedClosure& radial, const Array<T>& fractions,
                                      const Array<T>& temperatures, const Array<T>& diameters,
                                      const Array<T>& densities, const Array<T>& restitution, bool derivatives) {
  for (const auto* field : {&temperatures, &diameters, &densities})
    if (fractions.ndim() != 2 || field->ndim() != 2 || field->shape(0) != fractions.shape(0) ||
        field->shape(1) != fractions.shape(1))
      guarded([] { throw fb::InvalidArgument("fluidbed: the class fields must be (classes, cells) alike"); });
  const py::ssize_t classes = fractions.shape(0), n = fractions.shape(1);
  if (restitution.ndim() != 1 || restitution.shape(0) != n)
    guarded([] { throw fb::InvalidArgument("fluidbed: the restitution must be (cells,)"); });
  py::list values, d_fractions, d_temperatures;
  fb::ClassOutputs<T> out{};
  for (std::size_t q = 0; q < fb::class_quantity_count; ++q) {
    const bool per_class = q == fb::class_pressure || q == fb::class_dissipation;
    std::vector<py::ssize_t> shape = per_class ? std::vector<py::ssize_t>{classes, n}
                                               : std::vector<py::ssize_t>{classes, classes, n};
    Array<T> value(shape);
    out[q].value = value.mutable_data();
    values.append(value);
    if (!derivatives) continue;
    shape.insert(shape.begin(), classes);
    Array<T> by_fraction(shape), by_temperature(shape);
    out[q].d_fractions = by_fraction.mutable_data();
    out[q].d_temperatures = by_temperature.mutable_data();
    d_fractions.append(by_fraction);
    d_temperatures.append(by_temperature);
  }
  guarded([&] {
    fb::unequal_temperature_mixture<T>(radial, static_cast<std::size_t>(n), static_cast<std::size_t>(classes),
                                       fractions.data(), temperatures.data(), diameters.data(), densities.data(),
                                       restitution.data(), out);
  });
  if (!derivatives) return py::make_tuple(py::tuple(values), py::none(), py::none());
  return py::make_tuple(py::tuple(values), py::tuple(d_fractions), py::tuple(d_temperatures));
}

template <class T>
void define_kernels(py::module_& m) {
  m.def("moment_realizability", &moment_realizability<T>);
  m.def("correct_moments", &correct_moments<T>);
  m.def("dqmom_sources", &dqmom_sources<T>);
  m.def("dqmom_growth_diffusion_sources", &dqmom_growth_diffusion_sources<T>, py::arg("number_density"),
        py::arg("nodes"), py::arg("weights"), py::arg("growth").none(true), py::arg("intensity").none(true));
  m.def("mixture_radial_distribution", &mixture_radial_distribution<T>);
  m.def("solid_solid_drag", &solid_solid_drag<T>);
  m.def("unequal_temperature_mixture", &unequal_temperature_mixture<T>);
  m.def("gas_exchange_source", &gas_exchange_source<T>, py::arg("law"), py::arg("radial").none(true),
        py::arg("phi"), py::arg("theta"), py::arg("slip"), py::arg("beta").none(true),
        py::arg("gas_viscosity").none(true), py::arg("diameter"), py::arg("density"), py::arg("restitution"),
        py::arg("derivatives"));
  m.def("drag", &drag<T>);
  m.def("invert_moments", &invert_moments<T>);
  m.def("constitutive", &constitutive<T>);
  m.def("sphere_drag_coefficient", [](const fb::NamedClosure& law, const Array<T>& re, bool derivatives) {
    return one_argument<T>(law, re, derivatives, fb::sphere_drag_coefficient<T>);
  });
  m.def("reynolds_of_archimedes", [](const fb::NamedClosure& law, const Array<T>& ar, bool derivatives) {
    return one_argument<T>(law, ar, derivatives, fb::reynolds_of_archimedes<T>);
  });
  m.def("richardson_zaki_exponent", [](const fb::NamedClosure& law, const Array<T>& x, bool derivatives) {
    return one_argument<T>(law, x, derivatives, fb::richardson_zaki_exponent<T>);
  });
  m.def("of_solid_fraction", [](const fb::NamedClosure& law, const Array<T>& phi, bool derivatives) {
    return one_argument<T>(law, phi, derivatives, fb::of_solid_fraction<T>);
  });
  m.def("elastic_modulus_at_equilibrium",
        [](const fb::NamedClosure& model, const Array<T>& voidage, const Array<T>& fluid_density,
           const Array<T>& fluid_viscosity, const Array<T>& particle_density, const Array<T>& diameter,
           const Array<T>& terminal_reynolds, const Array<T>& gravity, bool derivatives) {
          const py::ssize_t n = voidage.size();
          Array<T> value(n);
          auto slope = output<T>(n, derivatives);
          T* out = value.mutable_data();
          guarded([&] {
            fb::elastic_modulus_at_equilibrium<T>(model, static_cast<std::size_t>(n), voidage.data(),
                                                  fluid_density.data(), fluid_viscosity.data(),
                                                  particle_density.data(), diameter.data(), terminal_reynolds.data(),
                                                  gravity.data(), out, data_of(slope));
          });
          return py::make_tuple(value, slope);
        });
  m.def("elastic_modulus_at_state", [](const fb::NamedClosure& model, const Array<T>& voidage, const Array<T>& slip,
                                       const Array<T>& fluid_density, const Array<T>& fluid_viscosity,
                                       const Array<T>& diameter, bool derivatives) {
    const py::ssize_t n = voidage.size();
    Array<T> value(n);
    auto d_voidage = output<T>(n, derivatives), d_slip = output<T>(n, derivatives);
    T* out = value.mutable_data();
    guarded([&] {
      fb::elastic_modulus_at_state<T>(model, static_cast<std::size_t>(n), voidage.data(), slip.data(),
                                      fluid_density.data(), fluid_viscosity.data(), diameter.data(), out,
                                      data_of(d_voidage), data_of(d_slip));
    });
    return py::make_tuple(value, d_voidage, d_slip);
  });
  m.def("frictional_viscosity", [](const fb::NamedClosure& law, const Array<T>& pressure, const Array<T>& divergence,
                                   const Array<T>& contraction, bool derivatives) {
    const py::ssize_t n = pressure.size();
    Array<T> value(n);
    auto slope = output<T>(n, derivatives);
    T* out = value.mutable_data();
    guarded([&] {
      fb::frictional_viscosity<T>(law, static_cast<std::size_t>(n), pressure.data(), divergence.data(),
                                  contraction.data(), out, data_of(slope));
    });
    return py::make_tuple(value, slope);
  });
  m.def("frictional_stress", [](const fb::NamedClosure& law, const Array<T>& phi, const Array<T>& theta,
                                const Array<T>& diameter, const Array<T>& divergence, const Array<T>& contraction,
                                bool derivatives) {
    const py::ssize_t n = phi.size();
    Array<T> pressure(n), viscosity(n);
    auto d_pressure = output<T>(n, derivatives), d_viscosity = output<T>(n, derivatives);
    T *p = pressure.mutable_data(), *v = viscosity.mutable_data();
    guarded([&] {
      fb::frictional_stress<T>(law, static_cast<std::size_t>(n), phi.data(), theta.data(), diameter.data(),
                               divergence.data(), contraction.data(), p, v, data_of(d_pressure), data_of(d_viscosity));
    });
    return py::make_tuple(pressure, viscosity, d_pressure, d_viscosity);
  });
}

}  // namespace

PYBIND11_MODULE(_fluidbed, m) {
  m.doc() = "fluidbed's compiled kernels; use the package fluidbed.";
  m.def("set_error_types", [](py::dict types) { error_types = new py::dict(std::move(types)); });

  py::class_<fb::NamedClosure>(m, "NamedClosure")
      .def(py::init([](const std::string& name) {
        std::optional<fb::NamedClosure> made;
        guarded([&] { made = fb::make_closure(name); });
        return *made;
      }))
      .def_readonly("name", &fb::NamedClosure::name)
      .def_readonly("reference", &fb::NamedClosure::reference)
      .def_property_readonly("family", &fb::NamedClosure::family)
      .def_property_readonly("validity",
                             [](const fb::NamedClosure& c) {
                               std::vector<std::tuple<std::string, double, double>> ranges;
                               for (const auto& r : fb::closure_validity(c))
                                 ranges.emplace_back(std::string(r.quantity), r.min, r.max);
                               return ranges;
                             })
      .def_property_readonly("parameter_names",
                             [](const fb::NamedClosure& c) {
                               std::vector<std::string> names;
                               for (const auto n : fb::parameter_names_of(c)) names.emplace_back(n);
                               return names;
                             })
      .def("get_parameter",
           [](const fb::NamedClosure& c, const std::string& name) {
             double value = 0;
             guarded([&] { value = fb::get_parameter(c, name); });
             return value;
           })
      .def("set_parameter",
           [](fb::NamedClosure& c, const std::string& name, double value) {
             guarded([&] { fb::set_parameter(c, name, value); });
           })
      .def("richardson_zaki_argument",
           [](const fb::NamedClosure& c) { return std::string(fb::richardson_zaki_argument(c)); })
      .def("__copy__", [](const fb::NamedClosure& c) { return c; });

  m.def("closure_names", [] {
    std::vector<std::string> names;
    for (const auto& c : fb::catalogue()) names.push_back(c.name);
    return names;
  });
  m.def("family_count", [] { return fb::family_count; });
  m.def("family_what", [](std::size_t f) { return std::string(fb::family_what(f)); });
  m.def("family_convention", [](std::size_t f) { return std::string(fb::family_convention(f)); });

  py::module_ f64 = m.def_submodule("float64"), f32 = m.def_submodule("float32");
  define_kernels<double>(f64);
  define_kernels<float>(f32);
}
