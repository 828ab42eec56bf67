"""fluidbed: closures for Eulerian models of fluidized suspensions, from Python.

Every closure of the C++ library, chosen by its run-time name (``fluidbed.closure("MazzeiLettieri")``)
or by its class (``fluidbed.drag_laws.MazzeiLettieri()``), evaluated over NumPy arrays: any shape,
broadcast against each other, float64 (or float32 where every array is float32, the library then
evaluated in single precision), derivatives on request. The values are bit for bit the C++
library's checked calls. ``help()`` of a closure shows its equation, its family's convention,
its validity and its reference.

Errors are exceptions carrying the C++ library's message: ``DomainError`` for an argument or
parameter outside its domain (with ``index``, the first failing cell in the broadcast shape),
``UnknownName``, ``UnknownParameter``, ``InvalidArgument``; all are ``fluidbed.Error``, a
``ValueError``.

    >>> import fluidbed, numpy as np
    >>> law = fluidbed.drag_laws.MazzeiLettieri()
    >>> law.beta(np.linspace(0.4, 0.9, 6), 0.3, 1.2, 1.8e-5, 3e-4, convention="pressure_gradient")
"""

from collections import namedtuple
from types import SimpleNamespace

import numpy as np

from . import _fluidbed
from ._closure_docs import SECTIONS as _SECTIONS

__all__ = ["Error", "DomainError", "UnknownName", "UnknownParameter", "InvalidArgument", "closure", "closure_names",
           "Closure", "DragLaw", "SphereDragCoefficient", "ReynoldsOfArchimedes", "RichardsonZakiExponent",
           "ElasticModulus", "RadialDistribution", "FrictionalPressure", "ConstitutiveLaw", "FrictionalViscosity",
           "FrictionalStress", "MixtureRadialDistribution", "GasExchangeSource", "SolidSolidDrag", "WallBoundaryCondition",
           "CONVENTIONS",
           "invert", "INVERSION_STATUSES", "realizability", "correct", "CORRECTION_STATUSES", "dqmom_sources",
           "dqmom_growth_diffusion_sources", "DQMOM_STATUSES", "unequal_temperature_mixture", "ClassKinetics",
           "ClassSensitivity"]


class Error(ValueError):
    """An error of fluidbed, with the C++ library's message; ``index`` is the failing cell."""

    index = None


class DomainError(Error):
    """An argument or parameter outside its domain, or a result that is not finite."""


class InvalidArgument(Error):
    """A closure of another family than the function needs, or arrays that do not broadcast."""


class UnknownName(Error, LookupError):
    """No closure by that name."""


class UnknownParameter(Error, LookupError):
    """The closure has no parameter by that name."""


_fluidbed.set_error_types({"Error": Error, "DomainError": DomainError, "InvalidArgument": InvalidArgument,
                           "UnknownName": UnknownName, "UnknownParameter": UnknownParameter})

#: The buoyancy conventions: "classical" (−φ ρ_f g, the papers') and "pressure_gradient" (−φ ∇p:
#: OpenFOAM, MFiX model A, Fluent). For the same physics β_pressure_gradient = ε β_classical.
CONVENTIONS = ("classical", "pressure_gradient")

Drag = namedtuple("Drag", "beta d_voidage d_slip d_force_d_slip")
WithSlope = namedtuple("WithSlope", "value d_solid_fraction")
WithDerivative = namedtuple("WithDerivative", "value derivative")
Constitutive = namedtuple("Constitutive", "value d_solid_fraction d_granular_temperature")
Stress = namedtuple("Stress", "pressure viscosity d_pressure d_viscosity")
Quadrature = namedtuple("Quadrature", "nodes weights sizes status node_errors weight_errors count_errors")

#: A cell's outcome of ``invert`` (the C++ library's moments::InversionStatus).
INVERSION_STATUSES = ("ok", "reduced", "zero_mass", "not_realizable", "invalid_input", "eigen_failure", "inaccurate")


def closure_names():
    """The run-time names of every closure of the library, presets included."""
    return list(_fluidbed.closure_names())


def _prepare(arrays):
    """The arrays broadcast against each other, as contiguous flat arrays of one dtype, and the shape;
    a None (an argument the closure does not read) stays None."""
    given = [np.asarray(a) for a in arrays if a is not None]
    dtype = np.float32 if all(a.dtype == np.float32 for a in given) else np.float64
    try:
        shape = np.broadcast_shapes(*(a.shape for a in given))
    except ValueError as e:
        raise InvalidArgument(f"fluidbed: the arrays do not broadcast against each other: {e}") from None
    flat = [None if a is None else np.ascontiguousarray(np.broadcast_to(np.asarray(a), shape), dtype=dtype).reshape(-1)
            for a in arrays]
    return dtype, shape, flat


def _module(dtype):
    return _fluidbed.float32 if dtype == np.float32 else _fluidbed.float64


def _call(function, shape, *arguments):
    """function(*arguments); a failing cell's flat index is given in ``shape``."""
    try:
        return function(*arguments)
    except Error as e:
        if e.index is not None:
            e.index = np.unravel_index(e.index, shape) if shape else ()
        raise


def _evaluate(kernel, closures, arrays, derivatives, *flags):
    """kernel(*closures, *flags, *flat arrays, derivatives) in the arrays' dtype, reshaped; a failing
    cell's index is given in the broadcast shape."""
    dtype, shape, flat = _prepare(arrays)
    results = _call(getattr(_module(dtype), kernel), shape, *closures, *flags, *flat, bool(derivatives))
    return [None if r is None else r.reshape(shape) for r in results]


class Closure:
    """A closure of the library (base of the families' classes)."""

    family = None  # the family's index in the library's list of registries

    def __init__(self, name, **parameters):
        self._closure = _fluidbed.NamedClosure(name)
        if self.family is not None and self._closure.family != self.family:
            raise InvalidArgument(f"fluidbed: {name} is not a {_fluidbed.family_what(self.family)}")
        self.set(**parameters)

    @property
    def name(self):
        return self._closure.name

    @property
    def reference(self):
        return self._closure.reference

    @property
    def family_what(self):
        """What the family's closures are, e.g. "drag law"."""
        return _fluidbed.family_what(self._closure.family)

    @property
    def convention(self):
        """The family's convention: the quantity, its units and sign, the arguments' definitions."""
        return _fluidbed.family_convention(self._closure.family)

    @property
    def validity(self):
        """{quantity: (min, max)}: the ranges the closure was fitted or derived for."""
        return {q: (low, high) for q, low, high in self._closure.validity}

    @property
    def parameters(self):
        """{name: value} of the closure's parameters (snake_case; angles in radians)."""
        return {n: self._closure.get_parameter(n) for n in self._closure.parameter_names}

    def set(self, **parameters):
        """Sets parameters by name, each validated at once (DomainError, the closure unchanged)."""
        for name, value in parameters.items():
            self._closure.set_parameter(name, float(value))
        return self

    def __repr__(self):
        parameters = ", ".join(f"{k}={v!r}" for k, v in self.parameters.items())
        return f"<fluidbed {self.family_what} {self.name}{' (' + parameters + ')' if parameters else ''}>"


def _convention(convention):
    if convention not in CONVENTIONS:
        raise InvalidArgument(f"fluidbed: convention must be one of {CONVENTIONS}, not {convention!r}")
    return convention == "pressure_gradient"


class DragLaw(Closure):
    family = 4

    def beta(self, voidage, slip, fluid_density, fluid_viscosity, diameter, *, convention, derivatives=False):
        """β [kg m⁻³ s⁻¹] per unit volume of suspension in ``convention`` ("classical" or
        "pressure_gradient", required) at voidage ε, interstitial slip w = |u_f − v_p| [m/s], fluid
        density [kg/m³] and viscosity [Pa s], particle diameter [m]; with ``derivatives`` a ``Drag``
        of β, ∂β/∂ε, ∂β/∂w and ∂(βw)/∂w."""
        pg = _convention(convention)
        r = _evaluate("drag", [self._closure], [voidage, slip, fluid_density, fluid_viscosity, diameter],
                      derivatives, pg)
        return Drag(*r) if derivatives else r[0]


class SphereDragCoefficient(Closure):
    family = 0

    def cd_re(self, reynolds, *, derivatives=False):
        """C_D·Re of one sphere at Re = ρ_f w d/μ_f; with ``derivatives`` also d(C_D·Re)/dRe."""
        r = _evaluate("sphere_drag_coefficient", [self._closure], [reynolds], derivatives)
        return WithDerivative(*r) if derivatives else r[0]


class ReynoldsOfArchimedes(Closure):
    """Terminal velocities (Re_t) and minimum fluidization (Re_mf) as Re(Ar)."""

    def reynolds(self, archimedes, *, derivatives=False):
        """Re at Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f²; with ``derivatives`` also dRe/dAr."""
        r = _evaluate("reynolds_of_archimedes", [self._closure], [archimedes], derivatives)
        return WithDerivative(*r) if derivatives else r[0]


class TerminalVelocity(ReynoldsOfArchimedes):
    family = 1


class MinimumFluidization(ReynoldsOfArchimedes):
    family = 3


class RichardsonZakiExponent(Closure):
    family = 2

    @property
    def argument(self):
        """"terminal_reynolds" (Re_t) or "archimedes" (Ar): what ``exponent`` takes."""
        return self._closure.richardson_zaki_argument()

    def exponent(self, argument, *, derivatives=False):
        """n at Re_t or Ar (see ``argument``); with ``derivatives`` also dn/d(argument)."""
        r = _evaluate("richardson_zaki_exponent", [self._closure], [argument], derivatives)
        return WithDerivative(*r) if derivatives else r[0]


Modulus = namedtuple("Modulus", "value d_voidage d_slip")


class ElasticModulus(Closure):
    family = 5

    def at_equilibrium(self, voidage, fluid_density, fluid_viscosity, particle_density, diameter, terminal_reynolds,
                       gravity=9.80665, *, derivatives=False):
        """E^e [Pa] of a homogeneous bed at equilibrium (ε, ρ_f, μ_f, ρ_p, d, Re_t = ρ_f u_t d/μ_f, g);
        with ``derivatives`` also ∂E^e/∂ε."""
        r = _evaluate("elastic_modulus_at_equilibrium", [self._closure],
                      [voidage, fluid_density, fluid_viscosity, particle_density, diameter, terminal_reynolds,
                       gravity], derivatives)
        return WithDerivative(*r) if derivatives else r[0]

    def at_state(self, voidage, slip, fluid_density, fluid_viscosity, diameter, *, derivatives=False):
        """E [Pa] off equilibrium at the drag state (ε, w, ρ_f, μ_f, d), for the models that define one
        (Mazzei–Lettieri); with ``derivatives`` a ``Modulus`` with ∂E/∂ε and ∂E/∂w."""
        r = _evaluate("elastic_modulus_at_state", [self._closure],
                      [voidage, slip, fluid_density, fluid_viscosity, diameter], derivatives)
        return Modulus(*r) if derivatives else r[0]


class _OfSolidFraction(Closure):
    def _of(self, solid_fraction, derivatives):
        r = _evaluate("of_solid_fraction", [self._closure], [solid_fraction], derivatives)
        return WithSlope(*r) if derivatives else r[0]


class RadialDistribution(_OfSolidFraction):
    family = 6

    def g0(self, solid_fraction, *, derivatives=False):
        """g0(φ); with ``derivatives`` also dg0/dφ."""
        return self._of(solid_fraction, derivatives)


class FrictionalPressure(_OfSolidFraction):
    family = 13

    def pressure(self, solid_fraction, *, derivatives=False):
        """p_f(φ) [Pa]; with ``derivatives`` also dp_f/dφ."""
        return self._of(solid_fraction, derivatives)


class ConstitutiveLaw(Closure):
    """Granular pressures, shear and bulk viscosities, conductivities, dissipation: law(φ, Θ, g0, material)."""

    families = (8, 9, 10, 11, 12)

    def __init__(self, name, **parameters):
        super().__init__(name, **parameters)
        if self._closure.family not in self.families:
            raise InvalidArgument(f"fluidbed: {name} is not a law of (phi, Theta, g0, material)")

    def __call__(self, solid_fraction, granular_temperature, diameter, solid_density, restitution, *, radial,
                 derivatives=False):
        """The law per unit volume of suspension at φ, Θ [m² s⁻²], d [m], ρ_s [kg/m³], e, with g0 the
        radial distribution ``radial`` (a RadialDistribution or its name); with ``derivatives`` a
        ``Constitutive`` of the value, ∂/∂φ (through g0 as well) and ∂/∂Θ."""
        rdf = radial if isinstance(radial, RadialDistribution) else RadialDistribution(radial)
        r = _evaluate("constitutive", [self._closure, rdf._closure],
                      [solid_fraction, granular_temperature, diameter, solid_density, restitution], derivatives)
        return Constitutive(*r) if derivatives else r[0]


class FrictionalViscosity(Closure):
    family = 14

    def viscosity(self, frictional_pressure, divergence, contraction, *, derivatives=False):
        """μ_f [Pa s] at p_f [Pa], ∇·u [s⁻¹] and D':D' [s⁻²]; with ``derivatives`` also ∂μ_f/∂p_f."""
        r = _evaluate("frictional_viscosity", [self._closure], [frictional_pressure, divergence, contraction],
                      derivatives)
        return WithDerivative(*r) if derivatives else r[0]


class FrictionalStress(Closure):
    family = 15

    def stress(self, solid_fraction, granular_temperature, diameter, divergence, contraction, *, derivatives=False):
        """A ``Stress`` of p_f [Pa] and μ_f [Pa s] at (φ, Θ, d, ∇·u, D':D'); with ``derivatives`` also
        their ∂/∂φ."""
        return Stress(*_evaluate("frictional_stress", [self._closure],
                                 [solid_fraction, granular_temperature, diameter, divergence, contraction],
                                 derivatives))


class MixtureRadialDistribution(Closure):
    family = 7

    def g(self, fractions, diameters, i, k, *, derivatives=False):
        """g_ik, the contact value between a particle of class i and one of class k (0-based), of cells
        whose classes' volume fractions φ_m and diameters d_m [m] lie along the last axis of
        ``fractions`` and ``diameters`` (..., classes; 1 to 10 classes, broadcast against each other);
        with ``derivatives`` a ``MixtureContact`` of g_ik (...) and ∂g_ik/∂φ_m (..., classes)."""
        dtype, shape, (phi, d) = _prepare_classes(fractions, diameters)
        value, slopes = _call(_module(dtype).mixture_radial_distribution, shape[:-1], self._closure, int(i), int(k),
                              phi, d, bool(derivatives))
        value = value.reshape(shape[:-1])
        return MixtureContact(value, np.moveaxis(slopes, 0, -1).reshape(shape)) if derivatives else value


def _prepare_classes(fractions, diameters):
    """Per-class arrays (..., classes) broadcast together, as (classes, cells) contiguous arrays."""
    dtype, shape, flat = _prepare([fractions, diameters])
    if len(shape) == 0:
        raise InvalidArgument("fluidbed: the classes must lie along the last axis of fractions and diameters")
    return dtype, shape, [np.ascontiguousarray(a.reshape(-1, shape[-1]).T) for a in flat]


MixtureContact = namedtuple("MixtureContact", "value d_fractions")
SolidSolid = namedtuple("SolidSolid", "value d_phi_p d_phi_q d_contact_rdf d_relative_speed")
Source = namedtuple("Source", "value d_solid_fraction d_granular_temperature d_beta d_slip")


class SolidSolidDrag(Closure):
    family = 17

    def coefficient(self, phi_p, phi_q, density_p, diameter_p, density_q, diameter_q, restitution, contact_rdf,
                    relative_speed, *, derivatives=False):
        """K_pq [kg m⁻³ s⁻¹] between classes p and q per unit volume of suspension (the force on p is
        K_pq (v_q − v_p)) at their volume fractions, their particles' densities [kg/m³] and diameters
        [m], the restitution of their collisions, their contact value g_pq (``MixtureRadialDistribution.g``)
        and their relative speed |v_p − v_q| [m/s]; with ``derivatives`` a ``SolidSolid`` with
        ∂/∂φ_p, ∂/∂φ_q, ∂/∂g_pq and ∂/∂|v_p − v_q|."""
        r = _evaluate("solid_solid_drag", [self._closure],
                      [phi_p, phi_q, density_p, diameter_p, density_q, diameter_q, restitution, contact_rdf,
                       relative_speed], derivatives)
        return SolidSolid(*r) if derivatives else r[0]


class WallBoundaryCondition(Closure):
    """A wall boundary condition of the solids phase: by name, with its parameters and metadata (its
    evaluation over arrays is offered in C++ only so far, kinetic_theory/walls.hpp)."""

    family = 18


class GasExchangeSource(Closure):
    family = 16

    def source(self, solid_fraction, granular_temperature, slip, diameter, solid_density, restitution, *, beta=None,
               gas_viscosity=None, radial=None, derivatives=False):
        """The gas's production of granular energy [W m⁻³] (positive, on the right-hand side of the
        granular energy balance) at φ, Θ [m² s⁻²], the slip speed |u_g − u_s| [m/s] and the material
        (d [m], ρ_s [kg/m³], e). KochSanganiSource reads ``gas_viscosity`` [Pa s] and ``radial`` (a
        RadialDistribution or its name, for g0(φ)); DragFluctuationSource reads ``beta``, the drag
        coefficient [kg m⁻³ s⁻¹] of the host's momentum equation. With ``derivatives`` a ``Source``
        with ∂/∂φ (through g0 as well), ∂/∂Θ, ∂/∂β and ∂/∂w."""
        rdf = None
        if radial is not None:
            rdf = (radial if isinstance(radial, RadialDistribution) else RadialDistribution(radial))._closure
        dtype, shape, flat = _prepare([solid_fraction, granular_temperature, slip, beta, gas_viscosity, diameter,
                                       solid_density, restitution])
        r = _call(_module(dtype).gas_exchange_source, shape, self._closure, rdf, *flat, bool(derivatives))
        r = [None if a is None else a.reshape(shape) for a in r]
        return Source(*r) if derivatives else r[0]


ClassKinetics = namedtuple("ClassKinetics", "pressure shear_viscosity bulk_viscosity conductivity dissipation drag "
                                           "segregation radial_distribution")
ClassSensitivity = namedtuple("ClassSensitivity", "value d_fractions d_temperatures")


def unequal_temperature_mixture(fractions, temperatures, diameters, densities, restitution, *,
                                radial="ModifiedMansoori", derivatives=False):
    """The kinetic theory of classes with their own granular temperatures (Lathouwers & Bellan 2001;
    the C++ kinetic_theory::UnequalTemperatureMixture, checked), per unit volume of suspension.
    Each class's envelope volume fraction α_m, granular temperature Θ_m [m² s⁻²], diameter [m] and
    envelope density [kg/m³] lie along the last axis of their arrays (..., classes; 1 to 10 classes,
    broadcast against each other); ``restitution`` (...) is that of every pair of the cell; ``radial``
    is the mixture radial distribution h_ik (a MixtureRadialDistribution or its name: "Lebowitz",
    "Mansoori", "ModifiedMansoori", the latter seed 004's with max_packing 0.64).

    Returns a ``ClassKinetics`` of p_i [Pa] and γ_i [W m⁻³] (a sink, transfer included) as (...,
    classes), and the matrices μ_ik, λ_ik [Pa s], κ_ik [kg m⁻¹ s⁻¹], β_ik [kg m⁻³ s⁻¹], s_ik [Pa]
    and h_ik as (..., classes, classes), entry [..., i, k] (μ_ik: class k's strain rate in class
    i's stress; q_i = −Σ_k κ_ik ∇Θ_k). With ``derivatives`` every field is a ``ClassSensitivity``
    of the value and its ∂/∂α_m and ∂/∂Θ_m, the value's shape with m along one more last axis.
    The C interface's fluidbed_unequal_temperature_mixture_with_derivatives, bit for bit."""
    rdf = radial if isinstance(radial, MixtureRadialDistribution) else MixtureRadialDistribution(radial)
    dtype, shape, flat = _prepare([fractions, temperatures, diameters, densities, np.asarray(restitution)[..., None]])
    if len(shape) == 0 or shape[-1] == 0:
        raise InvalidArgument("fluidbed: unequal_temperature_mixture: the classes must lie along the last axis")
    cells, classes = shape[:-1], shape[-1]
    fields = [np.ascontiguousarray(a.reshape(-1, classes).T) for a in flat[:4]]
    e = np.ascontiguousarray(flat[4].reshape(-1, classes)[:, 0])
    values, by_fraction, by_temperature = _call(_module(dtype).unequal_temperature_mixture, cells, rdf._closure,
                                                *fields, e, bool(derivatives))

    def cells_first(a, derivative=False):
        a = np.moveaxis(a, -1, 0)  # (cells, [m,] i[, k])
        if derivative:
            a = np.moveaxis(a, 1, -1)  # m last
        return a.reshape(cells + a.shape[1:])

    if not derivatives:
        return ClassKinetics(*(cells_first(v) for v in values))
    return ClassKinetics(*(ClassSensitivity(cells_first(v), cells_first(a, True), cells_first(t, True))
                           for v, a, t in zip(values, by_fraction, by_temperature)))


#: A cell's outcome of ``correct`` (the C++ library's moments::CorrectionStatus).
CORRECTION_STATUSES = ("unchanged", "mcgraw", "lognormal", "monodisperse", "zero_mass", "failed")

Realizability = namedtuple("Realizability", "status realizable_moments first_failing_index failing_value")
Correction = namedtuple("Correction", "moments status realizable_moments")


def _moment_sets(moments, function, limit):
    """(dtype, the cells' shape, the sets as a (count, cells) contiguous array) of ``moments`` (..., count)."""
    m = np.asarray(moments)
    if m.ndim < 1 or not 1 <= m.shape[-1] <= limit:
        raise InvalidArgument(f"fluidbed: {function}: the last axis must hold 1 to {limit} moments, not shape "
                              f"{m.shape}")
    dtype = np.float32 if m.dtype == np.float32 else np.float64
    return dtype, m.shape, np.ascontiguousarray(m.reshape(-1, m.shape[-1]).T, dtype=dtype)


def _support(support):
    if support not in ("positive_half_line", "real_line"):
        raise InvalidArgument(f"fluidbed: support must be 'positive_half_line' or 'real_line', not {support!r}")
    return support == "real_line"


def realizability(moments, *, support="positive_half_line"):
    """The realizability of moment sets ``moments`` (..., L), the last axis m_0 … m_(L−1) of one cell (L
    from 1 to 16), on ``support``, by the signs of the recurrence's coefficients (no threshold): a
    ``Realizability`` of the status (..., indices into INVERSION_STATUSES: ok when the whole set is
    realizable, reduced when only a prefix is), the length R of the realizable prefix (the Gauss
    rule has R // 2 nodes), the first failing coefficient's index (ζ_j on [0, ∞), β_k on the real
    line; 0 where none fails) and its value (m_0 itself when m_0 <= 0). The C++ library's
    moments::realizability, bit for bit; a cell's outcome is its status, never an exception."""
    real_line = _support(support)
    dtype, shape, sets = _moment_sets(moments, "realizability", 16)
    r = _module(dtype).moment_realizability(real_line, sets)
    return Realizability(*(a.reshape(shape[:-1]) for a in r))


def correct(moments, *, protected_moments=None, max_iterations=None, degenerate_tolerance=None):
    """Size moment sets ``moments`` (..., L; L from 1 to 16) made realizable where their transport left
    moment space: McGraw's iterations toward a smooth ln m_k, the realizability test, and the
    log-normal sharing m_0, m_1, m_2 as the fallback. Options (None: the library's default):
    ``protected_moments`` (1: m_0 is never changed), ``max_iterations`` (20), ``degenerate_tolerance``
    (the cube root of the dtype's epsilon: sets that close to the boundary are left unchanged).
    Returns a ``Correction`` of the corrected sets (..., L), the statuses (..., indices into
    CORRECTION_STATUSES) and the realizable prefix of each returned set. The C++ library's
    moments::correct_moments, bit for bit."""
    dtype, shape, sets = _moment_sets(moments, "correct", 16)
    corrected, status, realizable = _module(dtype).correct_moments(sets, protected_moments, max_iterations,
                                                                   degenerate_tolerance)
    return Correction(corrected.T.reshape(shape), status.reshape(shape[:-1]), realizable.reshape(shape[:-1]))


#: A cell's outcome of the DQMOM source solve (the C++ library's moments::dqmom::SourceStatus).
DQMOM_STATUSES = ("ok", "merged_nodes", "invalid_input")

DqmomSources = namedtuple("DqmomSources", "weight weighted_node status condition")


def _dqmom_fields(function, nodes, weights, *others):
    """(dtype, the cells' shape, nodes, weights and the others as (count, cells) arrays) of (..., count) inputs."""
    x = np.asarray(nodes)
    if x.ndim < 1 or not 1 <= x.shape[-1] <= 8:
        raise InvalidArgument(f"fluidbed: {function}: the last axis must hold 1 to 8 nodes, not shape {x.shape}")
    dtype = np.float32 if x.dtype == np.float32 else np.float64
    fields = []
    for name, array, count in (("weights", weights, x.shape[-1]),) + others:
        if array is None:
            fields.append(None)
            continue
        a = np.asarray(array)
        if a.shape != x.shape[:-1] + (count,):
            raise InvalidArgument(f"fluidbed: {function}: {name} must have shape {x.shape[:-1] + (count,)}, not {a.shape}")
        fields.append(np.ascontiguousarray(a.reshape(-1, count).T, dtype=dtype))
    return dtype, x.shape, np.ascontiguousarray(x.reshape(-1, x.shape[-1]).T, dtype=dtype), fields


def _dqmom_result(shape, r):
    a, b, status, condition = r
    return DqmomSources(a.T.reshape(shape), b.T.reshape(shape), status.reshape(shape[:-1]),
                        condition.reshape(shape[:-1]))


def dqmom_sources(nodes, weights, moment_sources):
    """DQMOM source terms: the sources c^a of the weights and c^ξ of the weighted nodes (each (..., N))
    that make the moments M_k = Σ a_i ξ_i^k, k = 0 … 2N − 1, change at the rates ``moment_sources``
    (..., 2N) (any kernel of moments: aggregation, breakage, nucleation). ``nodes`` and ``weights``
    are (..., N), N from 1 to 8, the last axis one cell's quadrature (weights only place merged
    nodes). Returns a ``DqmomSources`` of c^a, c^ξ, the status (indices into DQMOM_STATUSES) and the
    condition number of the system solved (about log10 of it digits are lost). The C++ library's
    moments::dqmom::solve_batched, bit for bit; a cell's outcome is its status, never an exception."""
    x = np.asarray(nodes)
    dtype, shape, xs, (ws, ss) = _dqmom_fields("dqmom_sources", nodes, weights,
                                               ("moment_sources", moment_sources, 2 * x.shape[-1] if x.ndim else 0))
    return _dqmom_result(shape, _module(dtype).dqmom_sources(xs, ws, ss))


def dqmom_growth_diffusion_sources(nodes, weights, *, weights_kind="volume_fraction", growth_rate=None,
                                   diffusion_intensity=None):
    """DQMOM source terms of growth (node i growing at ``growth_rate`` [m/s], (..., N)) and of the
    diffusion-induced sources (intensity 𝒞_i = 𝒟 φ_i |∇ξ_i|², ``diffusion_intensity`` (..., N); seed 000
    eqs 6.18–6.23), each optional, solved as point functionals: exact to rounding whatever the
    conditioning. ``weights_kind`` is "volume_fraction" (growth gives c^a = 3φG/ξ, c^ξ = 4φG) or
    "number_density" (0 and wG). Returns a ``DqmomSources`` as ``dqmom_sources``; the C++ library's
    moments::dqmom::System with growth_terms and diffusion_terms, bit for bit."""
    if weights_kind not in ("volume_fraction", "number_density"):
        raise InvalidArgument(f"fluidbed: weights_kind must be 'volume_fraction' or 'number_density', not "
                              f"{weights_kind!r}")
    x = np.asarray(nodes)
    count = x.shape[-1] if x.ndim else 0
    dtype, shape, xs, (ws, gs, cs) = _dqmom_fields("dqmom_growth_diffusion_sources", nodes, weights,
                                                   ("growth_rate", growth_rate, count),
                                                   ("diffusion_intensity", diffusion_intensity, count))
    return _dqmom_result(shape, _module(dtype).dqmom_growth_diffusion_sources(weights_kind == "number_density", xs, ws,
                                                                              gs, cs))


def invert(moments, *, support="positive_half_line", moment_accuracy=0.0, required_accuracy=0.0,
           estimate_error=False):
    """Gauss quadratures of moment sets: ``moments`` of shape (..., 2N), the last axis m_0 … m_(2N−1)
    of one cell (N from 1 to 8); ``support`` "positive_half_line" (sizes, masses) or "real_line"
    (velocities). Returns a ``Quadrature`` of nodes and weights (..., N), ascending nodes, weight 0
    beyond a cell's node count, the node counts (...) and the statuses (..., indices into
    INVERSION_STATUSES): a cell that cannot be inverted has its status, never an exception.

    The error estimate of each rule (docs/closures/moments.md, "How many digits a rule has"):
    ``moment_accuracy`` is the relative accuracy of each of the given moments (0: exact as given),
    ``required_accuracy`` > 0 gives a rule whose estimated node or weight error exceeds it the status
    "inaccurate" (the rule still returned). With ``estimate_error``, ``node_errors`` and
    ``weight_errors`` (...) hold each cell's estimated largest relative node error (relative to the
    node on [0, ∞), to the largest |node| on the real line) and weight error: −1 where the cell has
    no rule, inf where the rule has no digit; ``count_errors`` (...) the largest error, relative to
    its threshold, of the realizability decisions that set the cell's node count (>= 1: the count
    lies within the error, another count may be realizable), −1 where the cell has no rule; without ``estimate_error`` the three are None, as the
    derivatives of the closures are when not asked for. Accuracies must be finite and >= 0
    (DomainError). The C++ library's moments::invert_batched with these options, bit for bit."""
    real_line = _support(support)
    m = np.asarray(moments)
    if m.ndim < 1 or m.shape[-1] % 2 or m.shape[-1] == 0:
        raise InvalidArgument(f"fluidbed: invert: the last axis must hold 2N moments, not shape {m.shape}")
    dtype = np.float32 if m.dtype == np.float32 else np.float64
    n = m.shape[-1] // 2
    cells = m.reshape(-1, 2 * n)
    nodes, weights, sizes, status, *estimates = _module(dtype).invert_moments(
        n, real_line, np.ascontiguousarray(cells.T, dtype=dtype), float(moment_accuracy), float(required_accuracy),
        bool(estimate_error))
    shape = m.shape[:-1]
    errors = (None if e is None else e.reshape(shape) for e in estimates)
    return Quadrature(nodes.T.reshape(*shape, n), weights.T.reshape(*shape, n), sizes.reshape(shape),
                      status.reshape(shape), *errors)


# The class of each family.
_CLASS_OF_FAMILY = {0: SphereDragCoefficient, 1: TerminalVelocity, 2: RichardsonZakiExponent, 3: MinimumFluidization,
                    4: DragLaw, 5: ElasticModulus, 6: RadialDistribution, 7: MixtureRadialDistribution,
                    13: FrictionalPressure, 14: FrictionalViscosity, 15: FrictionalStress, 16: GasExchangeSource,
                    17: SolidSolidDrag, 18: WallBoundaryCondition, **{f: ConstitutiveLaw for f in ConstitutiveLaw.families}}
_NAMESPACES = {0: "sphere_drag_coefficients", 1: "terminal_velocities", 2: "richardson_zaki_exponents",
               3: "minimum_fluidizations", 4: "drag_laws", 5: "elastic_moduli", 6: "radial_distributions",
               7: "mixture_radial_distributions", 8: "granular_pressures", 9: "shear_viscosities",
               10: "bulk_viscosities", 11: "conductivities", 12: "dissipations", 13: "frictional_pressures",
               14: "frictional_viscosities", 15: "frictional_stresses", 16: "gas_exchange_sources",
               17: "solid_solid_drags", 18: "wall_boundary_conditions"}


def _documentation(c):
    """A closure's help: its equation (the docs' section), its family's convention, validity, reference."""
    section = next((body for body in _SECTIONS if f'"{c.name}"' in body), "(no section in docs/closures)")
    validity = "; ".join(f"{q} in [{low:g}, {high:g}]" for q, (low, high) in c.validity.items()) or "none stated"
    parameters = ", ".join(f"{k} = {v:g}" for k, v in c.parameters.items()) or "none"
    return (f"{c.name}: a {c.family_what} of fluidbed.\n\n{section.strip()}\n\n"
            f"Convention: {c.convention}\n\nValidity: {validity}\n\nParameters: {parameters}\n\n"
            f"Reference: {c.reference}\n")


def _make_class(name, family):
    base = _CLASS_OF_FAMILY[family]

    def __init__(self, **parameters):
        base.__init__(self, name, **parameters)

    cls = type(name, (base,), {"__init__": __init__, "__module__": f"fluidbed.{_NAMESPACES[family]}"})
    cls.__doc__ = _documentation(_Probe(name))
    return cls


class _Probe(Closure):
    """A closure of any family, for the documentation of the classes."""


def closure(name, **parameters):
    """The closure called ``name`` (any family), as an instance of its class, with ``parameters`` set."""
    return getattr(globals()[_NAMESPACES[_fluidbed.NamedClosure(name).family]], name)(**parameters)


for _f, _namespace in _NAMESPACES.items():
    globals()[_namespace] = SimpleNamespace()
for _name in _fluidbed.closure_names():
    _family = _fluidbed.NamedClosure(_name).family
    setattr(globals()[_NAMESPACES[_family]], _name, _make_class(_name, _family))
__all__ += list(_NAMESPACES.values())
del _f, _namespace, _name, _family
