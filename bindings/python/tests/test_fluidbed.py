"""The Python package against the C interface and the reference tables (pytest, ctest python.pytest).

Bit for bit: every drag reference row (both conventions, derivatives), every sphere drag,
settling and minimum-fluidization closure row, every one-class kinetic-theory and friction row,
every mixture, solid-solid drag and gas exchange source row, the elastic states, and the moments
reference sets (with corrupted copies) through the inversion, the realizability test and the
correction equal the C interface's result, called through ctypes on the same numbers
(tests/test_c_interface.cpp shows the C interface equal bit for bit to the C++ library); the
values also lie within 1e-12 (drag), 1e-9 (settling) or 1e-13 of the mpmath tables. Then shapes
and broadcasting, float32, bad input, the parameters and help().

Environment: FLUIDBED_C_LIBRARY (the built libfluidbed_c), FLUIDBED_REFERENCE_DIR (tests/reference).
"""
import csv
import ctypes
import os
import pydoc
from collections import defaultdict

import numpy as np
import pytest

import fluidbed

REFERENCE = os.environ.get("FLUIDBED_REFERENCE_DIR", os.path.join(os.path.dirname(__file__), "../../../tests/reference"))
C = ctypes.CDLL(os.environ["FLUIDBED_C_LIBRARY"])
DOUBLES = ctypes.POINTER(ctypes.c_double)


class CError(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int), ("index", ctypes.c_size_t), ("message", ctypes.c_char * 512)]


def c_closure(name):
    handle = ctypes.c_void_p()
    error = CError()
    assert C.fluidbed_closure_create(name.encode(), ctypes.byref(handle), ctypes.byref(error)) == 0, error.message
    return handle


def ptr(array):
    return array.ctypes.data_as(DOUBLES) if array is not None else None


def rows(table):
    with open(os.path.join(REFERENCE, table), newline="") as f:
        return list(csv.DictReader(f))


def same_bits(a, b):
    return np.array_equal(np.asarray(a).view(np.uint64), np.asarray(b).view(np.uint64))


def drag_cells():
    by_law = defaultdict(list)
    for row in rows("drag_reference.csv"):
        by_law[row["law"]].append(row)
    return by_law


@pytest.mark.parametrize("law_name,cells", sorted(drag_cells().items()))
def test_drag_reference_rows_bit_for_bit_with_the_c_interface(law_name, cells):
    columns = {k: np.array([float(r[k]) for r in cells]) for k in
               ("voidage", "slip", "fluid_density", "fluid_viscosity", "diameter", "beta_classical",
                "beta_pressure_gradient")}
    arguments = [columns[k] for k in ("voidage", "slip", "fluid_density", "fluid_viscosity", "diameter")]
    law = fluidbed.closure(law_name)
    handle = c_closure(law_name)
    n = len(cells)
    for convention, code in (("classical", 0), ("pressure_gradient", 1)):
        python = law.beta(*arguments, convention=convention, derivatives=True)
        c = [np.empty(n) for _ in range(4)]
        error = CError()
        status = C.fluidbed_drag(handle, code, ctypes.c_size_t(n), *(ptr(a) for a in arguments), *(ptr(a) for a in c),
                                 ctypes.byref(error))
        assert status == 0, error.message
        for p, q in zip(python, c):
            assert same_bits(p, q)
        np.testing.assert_allclose(python.beta, columns["beta_" + convention], rtol=1e-12, atol=0)
        assert same_bits(law.beta(*arguments, convention=convention), python.beta)
    C.fluidbed_closure_destroy(handle)


RADIAL_NAMES = {"carnahan_starling": "CarnahanStarling", "percus_yevick": "PercusYevick", "lun_savage": "LunSavage",
                "sinclair_jackson": "SinclairJackson", "ogawa": "Ogawa", "gidaspow": "GidaspowRadialDistribution",
                "ma_ahmadi": "MaAhmadi", "lathouwers_bellan": "LathouwersBellan",
                "song_stratt_mason": "SongStrattMason", "tobochnik_chapin": "TobochnikChapin"}
CONSTITUTIVE_NAMES = {"granular_pressure:lun": "LunPressure",
                      "granular_pressure:syamlal_rogers_obrien": "SyamlalRogersOBrienPressure",
                      "granular_pressure:ma_ahmadi": "AhmadiMaPressure", "shear_viscosity:gidaspow": "GidaspowViscosity",
                      "shear_viscosity:syamlal": "SyamlalViscosity",
                      "shear_viscosity:hrenya_sinclair": "HrenyaSinclairViscosity", "bulk_viscosity:lun": "LunBulkViscosity",
                      "conductivity:gidaspow": "GidaspowConductivity", "conductivity:syamlal": "SyamlalConductivity",
                      "conductivity:hrenya_sinclair": "HrenyaSinclairConductivity", "dissipation:lun": "LunDissipation",
                      "shear_viscosity:enskog": "EnskogViscosity", "conductivity:enskog": "EnskogConductivity"}


def test_kinetic_theory_reference_rows_bit_for_bit_with_the_c_interface():
    compared = 0
    for row in rows("ktgf_reference.csv"):
        function, variant = row["function"], row["variant"]
        number = {k: np.array([float(row[k])]) for k in ("solid_fraction", "granular_temperature", "diameter",
                                                         "particle_density", "restitution")}
        if function == "radial_distribution":
            name = RADIAL_NAMES[variant]
            python = fluidbed.closure(name).g0(number["solid_fraction"], derivatives=True)
            value, slope = np.empty(1), np.empty(1)
            assert C.fluidbed_of_solid_fraction(c_closure(name), ctypes.c_size_t(1), ptr(number["solid_fraction"]),
                                                ptr(value), ptr(slope), None) == 0
            assert same_bits(python.value, value) and same_bits(python.d_solid_fraction, slope)
            compared += 1
            continue
        author, radial = variant.split(":")
        name = CONSTITUTIVE_NAMES.get(f"{function}:{author}")
        if name is None:
            continue  # the kinetic and collisional parts, the algebraic temperature: not closures
        arguments = [number[k] for k in ("solid_fraction", "granular_temperature", "diameter", "particle_density",
                                         "restitution")]
        law = fluidbed.closure(name)
        python = law(*arguments, radial=RADIAL_NAMES[radial], derivatives=True)
        out = [np.empty(1) for _ in range(3)]
        assert C.fluidbed_constitutive(c_closure(name), c_closure(RADIAL_NAMES[radial]), ctypes.c_size_t(1),
                                       *(ptr(a) for a in arguments), *(ptr(a) for a in out), None) == 0
        for p, q in zip(python, out):
            assert same_bits(p, q)
        compared += 1
    assert compared == 214 + 1260


def test_shapes_broadcasting_and_float32():
    law = fluidbed.drag_laws.MazzeiLettieri()
    voidage = np.linspace(0.4, 0.95, 12).reshape(3, 4)
    slip = np.array([0.1, 0.2, 0.3, 0.4])
    beta = law.beta(voidage, slip, 1.2, 1.8e-5, 3e-4, convention="classical")
    assert beta.shape == (3, 4) and beta.dtype == np.float64
    for i in range(3):
        for j in range(4):
            assert same_bits(beta[i, j], law.beta(voidage[i, j], slip[j], 1.2, 1.8e-5, 3e-4, convention="classical"))
    # Both conventions: β_pg = ε β_cl (to rounding).
    np.testing.assert_allclose(law.beta(voidage, slip, 1.2, 1.8e-5, 3e-4, convention="pressure_gradient"),
                               voidage * beta, rtol=4e-16)
    # float32 arrays: the library in single precision, the C interface's fluidbed_drag_f bit for bit.
    single = [np.float32(x) for x in (0.5, 0.3, 1.2, 1.8e-5, 3e-4)]
    beta32 = law.beta(*single, convention="classical")
    assert beta32.dtype == np.float32
    out = np.empty(1, np.float32)
    floats = ctypes.POINTER(ctypes.c_float)
    args = [np.array([x], np.float32) for x in single]
    assert C.fluidbed_drag_f(c_closure("MazzeiLettieri"), 0, ctypes.c_size_t(1),
                             *(a.ctypes.data_as(floats) for a in args), out.ctypes.data_as(floats), None, None, None,
                             None) == 0
    assert beta32 == out[0]
    # A mix of float32 and float64 is evaluated in float64.
    assert law.beta(np.float32(0.5), 0.3, 1.2, 1.8e-5, 3e-4, convention="classical").dtype == np.float64


def test_bad_input_gives_the_checked_message_never_a_nan_or_a_crash():
    law = fluidbed.drag_laws.SyamlalOBrien()
    voidage = np.array([[0.5, 0.6], [np.nan, 0.7]])
    with pytest.raises(fluidbed.DomainError) as caught:
        law.beta(voidage, 0.1, 1.2, 1.8e-5, 3e-4, convention="classical")
    assert caught.value.index == (1, 0)
    assert str(caught.value).startswith("fluidbed::SyamlalOBrien: argument 'voidage' = nan is out of domain")
    with pytest.raises(fluidbed.DomainError, match="'diameter' = -0.001"):
        law.beta(0.5, 0.1, 1.2, 1.8e-5, -1e-3, convention="classical")
    with pytest.raises(fluidbed.InvalidArgument, match="do not broadcast"):
        law.beta(np.ones(3) * 0.5, np.ones(4) * 0.1, 1.2, 1.8e-5, 3e-4, convention="classical")
    with pytest.raises(TypeError):
        law.beta(0.5, 0.1, 1.2, 1.8e-5, 3e-4)  # the convention is required
    with pytest.raises(fluidbed.InvalidArgument, match="convention must be one of"):
        law.beta(0.5, 0.1, 1.2, 1.8e-5, 3e-4, convention="pressure")
    with pytest.raises(fluidbed.UnknownName, match="unknown closure 'NoSuchLaw'; known: StokesCoefficient, "):
        fluidbed.closure("NoSuchLaw")
    with pytest.raises(fluidbed.UnknownParameter, match="SyamlalOBrien has no parameter 'exponent'; its parameters: c1, d1"):
        law.set(exponent=2.65)
    with pytest.raises(fluidbed.DomainError, match=r"argument 'c1' = -1 is out of domain \(must be finite and > 0\)"):
        law.set(c1=-1)
    assert law.parameters == {"c1": 0.8, "d1": 2.65}
    with pytest.raises(fluidbed.InvalidArgument, match="GidaspowViscosity is not a radial distribution"):
        fluidbed.shear_viscosities.GidaspowViscosity()(0.3, 0.01, 3e-4, 2500, 0.9, radial="GidaspowViscosity")
    with pytest.raises(fluidbed.InvalidArgument, match="Ergun is not a radial distribution"):
        fluidbed.RadialDistribution("Ergun")
    empty = law.beta(np.empty((0, 3)), 0.1, 1.2, 1.8e-5, 3e-4, convention="classical")
    assert empty.shape == (0, 3)


def test_parameters_and_classes():
    wen_yu = fluidbed.drag_laws.WenYu1966(exponent=2.65)
    assert wen_yu.parameters == {"exponent": 2.65}
    state = (0.7, 0.3, 1.2, 1.8e-5, 3e-4)
    assert same_bits(wen_yu.beta(*state, convention="classical"),
                     fluidbed.drag_laws.WenYuGidaspow().beta(*state, convention="classical"))
    assert isinstance(fluidbed.closure("MazzeiLettieri"), fluidbed.drag_laws.MazzeiLettieri)
    # Every closure is a class in its family's namespace (fluidbed.drag_laws, fluidbed.radial_distributions, ...).
    for name in fluidbed.closure_names():
        cls = type(fluidbed.closure(name))
        assert cls.__name__ == name
        assert getattr(getattr(fluidbed, cls.__module__.split(".")[1]), name) is cls
    assert len(fluidbed.closure_names()) == 70


def test_help_shows_equation_convention_validity_and_reference():
    text = pydoc.render_doc(fluidbed.drag_laws.MazzeiLettieri, renderer=pydoc.plaintext)
    assert "$$" in text or "```math" in text
    assert "Convention: " in text and "pressure" in text
    assert "Validity: voidage in [" in text
    assert "Reference: Mazzei" in text
    for name in fluidbed.closure_names():  # every closure's help has its section of docs/closures
        assert "Reference: " in fluidbed.closure(name).__doc__
        assert "(no section in docs/closures)" not in fluidbed.closure(name).__doc__


def moment_sets():
    sets = defaultdict(dict)
    for row in rows("moments_reference.csv"):
        if row["quantity"] == "moment":
            sets[row["case"]][int(row["index"])] = float(row["value"])
    return {name: np.array([m[k] for k in sorted(m)]) for name, m in sets.items()}


@pytest.mark.parametrize("support,code", [("positive_half_line", 0), ("real_line", 1)])
def test_moment_reference_sets_bit_for_bit_with_the_c_interface(support, code):
    sets = moment_sets()
    ints = ctypes.POINTER(ctypes.c_int)
    for n in range(1, 9):
        cells = np.array([m[:2 * n] for m in sets.values() if len(m) >= 2 * n])
        python = fluidbed.invert(cells, support=support)
        assert python.nodes.shape == (len(cells), n) and python.status.shape == (len(cells),)
        moments = np.ascontiguousarray(cells.T)
        nodes, weights = np.empty((n, len(cells))), np.empty((n, len(cells)))
        sizes, status = np.empty(len(cells), np.intc), np.empty(len(cells), np.intc)
        assert C.fluidbed_invert_moments(n, code, ctypes.c_size_t(len(cells)), ptr(moments), ptr(nodes), ptr(weights),
                                         sizes.ctypes.data_as(ints), status.ctypes.data_as(ints), None) == 0
        assert same_bits(python.nodes, nodes.T) and same_bits(python.weights, weights.T)
        assert np.array_equal(python.sizes, sizes) and np.array_equal(python.status, status)


def test_inversion_statuses_shapes_and_errors():
    k = np.arange(6)
    legendre = 1 / (k + 1)  # m_k of the uniform distribution on [0, 1]: the 3-point Gauss–Legendre rule
    q = fluidbed.invert(np.stack([[legendre, 2 * legendre], [np.zeros(6), np.full(6, np.nan)]]))
    assert q.nodes.shape == (2, 2, 3)
    np.testing.assert_allclose(q.nodes[0, 0], [0.5 - np.sqrt(0.15), 0.5, 0.5 + np.sqrt(0.15)], rtol=1e-14)
    np.testing.assert_allclose(q.weights[0, 1], [5 / 9, 8 / 9, 5 / 9], rtol=1e-14)
    assert [fluidbed.INVERSION_STATUSES[s] for s in q.status.ravel()] == ["ok", "ok", "zero_mass", "invalid_input"]
    with pytest.raises(fluidbed.InvalidArgument, match="2N moments"):
        fluidbed.invert(np.ones(5))
    with pytest.raises(fluidbed.InvalidArgument, match="1 to 8 are offered"):
        fluidbed.invert(np.ones(18))
    with pytest.raises(fluidbed.InvalidArgument, match="support must be"):
        fluidbed.invert(legendre, support="half_line")


@pytest.mark.parametrize("support,code", [("positive_half_line", 0), ("real_line", 1)])
def test_error_estimate_of_the_reference_sets_bit_for_bit_with_the_c_interface(support, code):
    sets = moment_sets()
    ints, doubles = ctypes.POINTER(ctypes.c_int), ctypes.c_double
    inaccurate = 0
    for n in range(1, 9):
        cells = np.array([m[:2 * n] for m in sets.values() if len(m) >= 2 * n])
        estimate = fluidbed.invert(cells, support=support, moment_accuracy=1e-9, estimate_error=True)
        larger = np.maximum(estimate.node_errors, estimate.weight_errors)
        required = np.median(larger[(larger >= 0) & np.isfinite(larger)])
        python = fluidbed.invert(cells, support=support, moment_accuracy=1e-9, required_accuracy=required,
                                 estimate_error=True)
        moments = np.ascontiguousarray(cells.T)
        nodes, weights = np.empty((n, len(cells))), np.empty((n, len(cells)))
        sizes, status = np.empty(len(cells), np.intc), np.empty(len(cells), np.intc)
        node_errors, weight_errors, count_errors = (np.empty(len(cells)) for _ in range(3))
        assert C.fluidbed_invert_moments_with_accuracy(
            n, code, ctypes.c_size_t(len(cells)), ptr(moments), doubles(1e-9), doubles(required), ptr(nodes),
            ptr(weights), sizes.ctypes.data_as(ints), status.ctypes.data_as(ints), ptr(node_errors),
            ptr(weight_errors), ptr(count_errors), None) == 0
        assert same_bits(python.nodes, nodes.T) and same_bits(python.weights, weights.T)
        assert np.array_equal(python.sizes, sizes) and np.array_equal(python.status, status)
        assert same_bits(python.node_errors, node_errors) and same_bits(python.weight_errors, weight_errors)
        assert same_bits(python.count_errors, count_errors)
        # A count error for every cell with a rule, −1 elsewhere.
        assert np.array_equal(python.count_errors >= 0, python.node_errors >= 0)
        # The requirement changes statuses, not rules; the estimates are those made without it.
        assert same_bits(python.nodes, estimate.nodes) and same_bits(python.node_errors, estimate.node_errors)
        inaccurate += np.count_nonzero(python.status == fluidbed.INVERSION_STATUSES.index("inaccurate"))
    assert inaccurate > 0


def test_error_estimate_of_one_node_and_the_accuracy_options():
    # One node: x = m_1/m_0 and w = m_0, so moments off by δ relative move x by up to 2δ and w by δ
    # (first order, exact); the inversion's rounding, κ ε/√(2n) per moment with κ = 1/16 (accuracy.hpp),
    # adds κ ε √2 and κ ε/√2.
    delta, kappa_epsilon = 1e-6, np.finfo(np.float64).eps / 16
    q = fluidbed.invert([[3.0, 1.5e-4], [0.0, 0.0]], moment_accuracy=delta, estimate_error=True)
    np.testing.assert_allclose(q.node_errors[0], 2 * delta + np.sqrt(2) * kappa_epsilon, rtol=1e-14)
    np.testing.assert_allclose(q.weight_errors[0], delta + kappa_epsilon / np.sqrt(2), rtol=1e-14)
    assert q.node_errors[1] == -1 and q.weight_errors[1] == -1  # an empty cell: no rule, no estimate
    assert [fluidbed.INVERSION_STATUSES[s] for s in q.status] == ["ok", "zero_mass"]
    # Not asked for: None. A requirement below the estimate: "inaccurate", the rule still returned.
    plain = fluidbed.invert([3.0, 1.5e-4])
    assert plain.node_errors is None and plain.weight_errors is None and plain.count_errors is None
    # The count's one decision, ζ_1 = m_1/m_0 > 0, moves by δ + ε relative (U_1/V_1 = 1).
    np.testing.assert_allclose(q.count_errors, [delta + np.finfo(np.float64).eps, -1], rtol=1e-14)
    strict = fluidbed.invert([3.0, 1.5e-4], moment_accuracy=delta, required_accuracy=1.5 * delta)
    assert fluidbed.INVERSION_STATUSES[strict.status] == "inaccurate" and strict.node_errors is None
    assert same_bits(strict.nodes, plain.nodes) and same_bits(strict.weights, plain.weights)
    assert fluidbed.INVERSION_STATUSES[fluidbed.invert([3.0, 1.5e-4], moment_accuracy=delta,
                                                       required_accuracy=3 * delta).status] == "ok"
    single = fluidbed.invert(np.array([3.0, 1.5e-4], np.float32), moment_accuracy=delta, estimate_error=True)
    assert single.node_errors.dtype == np.float32
    np.testing.assert_allclose(single.node_errors, 2 * delta + np.sqrt(2) * np.finfo(np.float32).eps / 16, rtol=1e-5)
    for option in ("moment_accuracy", "required_accuracy"):
        for bad in (-1e-3, np.nan, np.inf):
            with pytest.raises(fluidbed.DomainError, match=option):
                fluidbed.invert([3.0, 1.5e-4], **{option: bad})


def test_elastic_moduli_bit_for_bit_with_the_c_interface():
    g = 9.80665
    for row in rows("elastic_state_reference.csv"):
        x = {k: np.array([float(row[k])]) for k in ("fluid_density", "fluid_viscosity", "particle_density", "diameter",
                                                    "voidage", "slip", "reynolds")}
        for name in ("FoscoloGibilaroModulus", "JeanFanModulus", "MazzeiLettieriModulus"):
            model = fluidbed.closure(name)
            python = model.at_equilibrium(x["voidage"], x["fluid_density"], x["fluid_viscosity"],
                                          x["particle_density"], x["diameter"], x["reynolds"], g, derivatives=True)
            value, slope, gravity = np.empty(1), np.empty(1), np.array([g])
            assert C.fluidbed_elastic_modulus_at_equilibrium(
                c_closure(name), ctypes.c_size_t(1), ptr(x["voidage"]), ptr(x["fluid_density"]),
                ptr(x["fluid_viscosity"]), ptr(x["particle_density"]), ptr(x["diameter"]), ptr(x["reynolds"]),
                ptr(gravity), ptr(value), ptr(slope), None) == 0
            assert same_bits(python.value, value) and same_bits(python.derivative, slope)
    model = fluidbed.elastic_moduli.MazzeiLettieriModulus()
    at_state = model.at_state(0.6, 0.01, 998.0, 1e-3, 2.5e-4, derivatives=True)
    assert at_state.value > 0 and np.isfinite(at_state.d_slip)
    with pytest.raises(fluidbed.InvalidArgument, match="defines no modulus off equilibrium"):
        fluidbed.elastic_moduli.JeanFanModulus().at_state(0.6, 0.01, 998.0, 1e-3, 2.5e-4)


INTS = ctypes.POINTER(ctypes.c_int)
MIXTURE_NAMES = {"lebowitz": "Lebowitz", "mansoori": "Mansoori", "modified_mansoori": "ModifiedMansoori"}


def test_mixture_radial_distributions_and_solid_solid_drag_rows_bit_for_bit_with_the_c_interface():
    compared = 0
    for row in rows("ktgf_mixture_reference.csv"):
        classes, i, k = int(row["classes"]), int(row["i"]), int(row["k"])
        phi = np.array([float(row[f"phi{m + 1}"]) for m in range(classes)])
        d = np.array([float(row[f"d{m + 1}"]) for m in range(classes)])
        author, _, rdf_table_name = row["variant"].partition(":")
        drag = row["function"] == "solid_solid_drag"
        name = MIXTURE_NAMES[rdf_table_name if drag else author]
        parameters = {"max_packing": float(row["max_packing"])} if name == "ModifiedMansoori" else {}
        python = fluidbed.closure(name, **parameters).g(phi, d, i, k, derivatives=True)
        handle = c_closure(name)
        for key, value in parameters.items():
            assert C.fluidbed_closure_set_parameter(handle, key.encode(), ctypes.c_double(value), None) == 0
        g, slopes = np.empty(1), np.empty(classes)
        assert C.fluidbed_mixture_radial_distribution(handle, ctypes.c_size_t(1), ctypes.c_size_t(classes),
                                                      ctypes.c_size_t(i), ctypes.c_size_t(k), ptr(phi), ptr(d), ptr(g),
                                                      ptr(slopes), None) == 0
        assert same_bits(python.value, g[0]) and same_bits(python.d_fractions, slopes)
        if drag:
            friction = float(row["friction_coefficient"])
            state = [np.array([float(x)]) for x in (phi[i], phi[k], row["rho_i"], d[i], row["rho_k"], d[k],
                                                     row["restitution"], g[0], row["relative_speed"])]
            law = fluidbed.solid_solid_drags.SyamlalSolidSolidDrag(friction_coefficient=friction)
            python = law.coefficient(*state, derivatives=True)
            handle = c_closure("SyamlalSolidSolidDrag")
            assert C.fluidbed_closure_set_parameter(handle, b"friction_coefficient", ctypes.c_double(friction),
                                                    None) == 0
            out = [np.empty(1) for _ in range(5)]
            assert C.fluidbed_solid_solid_drag(handle, ctypes.c_size_t(1), *(ptr(a) for a in state),
                                               *(ptr(a) for a in out), None) == 0
            for p, q in zip(python, out):
                assert same_bits(p, q)
        np.testing.assert_allclose(python.value, float(row["value"]), rtol=1e-13)
        compared += 1
    assert compared == 354
    # Cells along any leading axes, the classes along the last, broadcast: g_01 of 2 x 3 cells.
    lebowitz = fluidbed.mixture_radial_distributions.Lebowitz()
    fractions = np.stack([np.full((2, 3), 0.1), np.linspace(0.05, 0.3, 6).reshape(2, 3)], axis=-1)
    contact = lebowitz.g(fractions, [1e-4, 2e-4], 0, 1, derivatives=True)
    assert contact.value.shape == (2, 3) and contact.d_fractions.shape == (2, 3, 2)
    assert same_bits(contact.value[1, 2], lebowitz.g(fractions[1, 2], [1e-4, 2e-4], 0, 1))
    assert lebowitz.g(fractions.astype(np.float32), np.float32([1e-4, 2e-4]), 0, 1).dtype == np.float32
    fractions[1, 1, 0] = np.nan
    with pytest.raises(fluidbed.DomainError, match=r"'fractions\[0\]' = nan") as caught:
        lebowitz.g(fractions, [1e-4, 2e-4], 0, 1)
    assert caught.value.index == (1, 1)
    with pytest.raises(fluidbed.DomainError, match="'k' = 2 is out of domain"):
        lebowitz.g([0.1, 0.2], [1e-4, 2e-4], 0, 2)
    with pytest.raises(fluidbed.InvalidArgument, match="11 classes; 1 to 10 are offered"):
        lebowitz.g(np.full(11, 0.01), np.full(11, 1e-4), 0, 1)
    with pytest.raises(fluidbed.InvalidArgument, match="do not broadcast"):
        lebowitz.g([0.1, 0.2], [1e-4, 2e-4, 3e-4], 0, 1)


def test_gas_exchange_sources_bit_for_bit_with_the_c_interface():
    compared = 0
    for row in rows("ktgf_exchange_reference.csv"):
        if row["function"] != "fluctuating_energy_source":
            continue
        x = {k: np.array([float(row[k])]) for k in ("solid_fraction", "granular_temperature", "slip", "beta",
                                                    "gas_viscosity", "diameter", "particle_density", "restitution")}
        common = [x[k] for k in ("solid_fraction", "granular_temperature", "slip")]
        material = [x[k] for k in ("diameter", "particle_density", "restitution")]
        author, _, rdf = row["variant"].partition(":")
        out = [np.empty(1) for _ in range(5)]
        if author == "koch_sangani":
            radial = fluidbed.closure(RADIAL_NAMES[rdf], **({"max_packing": 0.63} if rdf == "ogawa" else {}))
            python = fluidbed.gas_exchange_sources.KochSanganiSource().source(
                *common, *material, gas_viscosity=x["gas_viscosity"], radial=radial, derivatives=True)
            c_radial = c_closure(RADIAL_NAMES[rdf])
            if rdf == "ogawa":
                assert C.fluidbed_closure_set_parameter(c_radial, b"max_packing", ctypes.c_double(0.63), None) == 0
            assert C.fluidbed_gas_exchange_source(c_closure("KochSanganiSource"), c_radial, ctypes.c_size_t(1),
                                                  *(ptr(a) for a in common), None, ptr(x["gas_viscosity"]),
                                                  *(ptr(a) for a in material), *(ptr(a) for a in out), None) == 0
        else:
            python = fluidbed.gas_exchange_sources.DragFluctuationSource().source(*common, *material, beta=x["beta"],
                                                                                   derivatives=True)
            assert C.fluidbed_gas_exchange_source(c_closure("DragFluctuationSource"), None, ctypes.c_size_t(1),
                                                  *(ptr(a) for a in common), ptr(x["beta"]), None,
                                                  *(ptr(a) for a in material), *(ptr(a) for a in out), None) == 0
        for p, q in zip(python, out):
            assert same_bits(p, q)
        np.testing.assert_allclose(python.value, float(row["value"]), rtol=1e-13)
        compared += 1
    assert compared == 72
    with pytest.raises(fluidbed.InvalidArgument, match="DragFluctuationSource needs beta"):
        fluidbed.gas_exchange_sources.DragFluctuationSource().source(0.3, 1e-3, 0.5, 3e-4, 2500, 0.9)
    with pytest.raises(fluidbed.InvalidArgument, match="KochSanganiSource needs a radial distribution"):
        fluidbed.gas_exchange_sources.KochSanganiSource().source(0.3, 1e-3, 0.5, 3e-4, 2500, 0.9, gas_viscosity=1.8e-5)


def corrupted_moment_sets():
    """The reference sets and copies with one moment k >= 1 multiplied by 1.3 or 0.6."""
    sets = []
    for m in moment_sets().values():
        sets.append(m)
        for k in range(1, len(m)):
            for factor in (1.3, 0.6):
                sets.append(m.copy())
                sets[-1][k] *= factor
    return sets


def test_realizability_and_correction_bit_for_bit_with_the_c_interface():
    sets = corrupted_moment_sets()
    seen = set()
    for count in range(1, 17):
        cells = np.array([m[:count] for m in sets if len(m) >= count])
        n = len(cells)
        moments = np.ascontiguousarray(cells.T)
        for support, code in (("positive_half_line", 0), ("real_line", 1)):
            python = fluidbed.realizability(cells, support=support)
            status, realizable, failing_index = (np.empty(n, np.intc) for _ in range(3))
            failing = np.empty(n)
            assert C.fluidbed_moment_realizability(code, count, ctypes.c_size_t(n), ptr(moments),
                                                   *(a.ctypes.data_as(INTS) for a in (status, realizable,
                                                                                      failing_index)),
                                                   ptr(failing), None) == 0
            for p, q in zip(python, (status, realizable, failing_index)):
                assert np.array_equal(p, q)
            assert same_bits(python.failing_value, failing)
        python = fluidbed.correct(cells)
        corrected, status, realizable = np.empty((count, n)), np.empty(n, np.intc), np.empty(n, np.intc)
        assert C.fluidbed_correct_moments(count, ctypes.c_size_t(n), ptr(moments), None, ptr(corrected),
                                          status.ctypes.data_as(INTS), realizable.ctypes.data_as(INTS), None) == 0
        assert same_bits(python.moments, corrected.T)
        assert np.array_equal(python.status, status) and np.array_equal(python.realizable_moments, realizable)
        seen.update(fluidbed.CORRECTION_STATUSES[s] for s in python.status)
    assert {"unchanged", "mcgraw", "lognormal", "monodisperse"} <= seen
    # Every set McGraw or the log-normal corrected is realizable; the failures are the sets without a
    # size scale (m_1 <= 0: the real-line reference sets), returned as given.
    corrupted = np.array([m[:8] for m in sets if len(m) >= 8])
    fixed = fluidbed.correct(corrupted)
    status = np.array(fluidbed.CORRECTION_STATUSES)[fixed.status]
    corrected = (status == "mcgraw") | (status == "lognormal")
    assert corrected.sum() > 100
    assert np.all(fluidbed.realizability(fixed.moments[corrected]).realizable_moments == 8)
    failed = status == "failed"
    assert np.all(corrupted[failed, 1] <= 0) and same_bits(fixed.moments[failed], corrupted[failed])


def test_realizability_and_correction_shapes_float32_and_errors():
    k = np.arange(6)
    legendre = 1 / (k + 1)
    broken = legendre.copy()
    broken[4] *= 0.6
    report = fluidbed.realizability(np.stack([[legendre, broken]]))
    assert report.status.shape == (1, 2)
    assert [fluidbed.INVERSION_STATUSES[s] for s in report.status[0]] == ["ok", "reduced"]
    assert report.realizable_moments[0, 1] < 6
    fixed32 = fluidbed.correct(broken.astype(np.float32))
    assert fixed32.moments.dtype == np.float32 and fixed32.moments.shape == (6,)
    assert fluidbed.CORRECTION_STATUSES[fixed32.status] != "unchanged"
    assert fluidbed.realizability(fixed32.moments).realizable_moments == 6
    # McGraw never changes the protected moments.
    kept = fluidbed.correct(broken, protected_moments=3, max_iterations=50)
    assert same_bits(kept.moments[:3], broken[:3])
    with pytest.raises(fluidbed.DomainError, match="'protected_moments' = 0 is out of domain"):
        fluidbed.correct(broken, protected_moments=0)
    with pytest.raises(fluidbed.DomainError, match="'degenerate_tolerance' = -1 is out of domain"):
        fluidbed.correct(broken, degenerate_tolerance=-1)
    with pytest.raises(fluidbed.InvalidArgument, match="1 to 16 moments"):
        fluidbed.realizability(np.ones(17))
    with pytest.raises(fluidbed.InvalidArgument, match="1 to 16 moments"):
        fluidbed.correct(np.ones((3, 0)))
    nan_cell = fluidbed.correct([1.0, np.nan, 1.0])
    assert fluidbed.CORRECTION_STATUSES[nan_cell.status] == "failed"


def c_one_argument(function, handle, x):
    """A C function of one argument array (value, derivative) on one cell."""
    value, slope = np.empty(1), np.empty(1)
    error = CError()
    assert function(handle, ctypes.c_size_t(1), ptr(np.array([x])), ptr(value), ptr(slope), ctypes.byref(error)) == 0, \
        error.message
    return value, slope


SETTLING_CLOSURES = {"rz_exponent_mazzei": ("MazzeiExponent", None), "rz_exponent_rowe1987": ("RoweExponent", None),
                     "rz_exponent_garside_aldibouni1977": ("GarsideAlDibouniExponent", None),
                     "rz_exponent_khan_richardson1989": ("KhanRichardsonExponent", "wall_ratio"),
                     "rz_exponent_richardson_zaki1954": ("RichardsonZaki1954Exponent", "wall_ratio"),
                     "terminal_velocity_stokes": ("StokesTerminalVelocity", None),
                     "terminal_velocity_newton": ("NewtonTerminalVelocity", None),
                     "terminal_velocity_dallavalle": ("DallavalleTerminalVelocity", None),
                     "terminal_velocity_schillernaumann": ("SchillerNaumannTerminalVelocity", None),
                     "remf_ergun": ("ErgunMinimumFluidization", "voidage"),
                     "remf_wenyu1966": ("WenYuMinimumFluidization", None)}


def test_sphere_drag_settling_and_fluidization_rows_bit_for_bit_with_the_c_interface():
    for row in rows("cd_reference.csv"):
        name, re = row["law"] + "Coefficient", np.array([float(row["reynolds"])])
        python = fluidbed.closure(name).cd_re(re, derivatives=True)
        c = c_one_argument(C.fluidbed_sphere_drag_coefficient, c_closure(name), re[0])
        assert same_bits(python.value, c[0]) and same_bits(python.derivative, c[1])
    compared = 0
    for row in rows("settling_reference.csv"):
        if row["quantity"] not in SETTLING_CLOSURES:
            continue  # bed expansion and u_mf in m/s: not closures
        name, parameter = SETTLING_CLOSURES[row["quantity"]]
        p = [float(row[f"param{i}"]) for i in range(1, 5)]
        law, handle = fluidbed.closure(name), c_closure(name)
        if parameter:
            law.set(**{parameter: p[1]})
            assert C.fluidbed_closure_set_parameter(handle, parameter.encode(), ctypes.c_double(p[1]), None) == 0
        # Re_t or Ar; the terminal-velocity rows give the fluid (ρ_f, μ_f) and the particles (ρ_p, d), and
        # the library and the table take g = 9.81 m/s².
        x = np.array([p[0] * (p[2] - p[0]) * 9.81 * p[3] ** 3 / p[1] ** 2 if name.endswith("TerminalVelocity")
                      else p[0]])
        if isinstance(law, fluidbed.RichardsonZakiExponent):
            python = law.exponent(x, derivatives=True)
            c = c_one_argument(C.fluidbed_richardson_zaki_exponent, handle, x[0])
        else:
            python, c = law.reynolds(x, derivatives=True), c_one_argument(C.fluidbed_reynolds_of_archimedes, handle, x[0])
        assert same_bits(python.value, c[0]) and same_bits(python.derivative, c[1])
        # and the table's value: Re_t, u_mf's Re_mf or n; u_t [m/s] for the terminal-velocity rows
        value = python.value * p[1] / (p[0] * p[3]) if name.endswith("TerminalVelocity") else python.value
        np.testing.assert_allclose(value, float(row["value"]), rtol=1e-9)
        compared += 1
    assert compared == 96


def test_friction_rows_bit_for_bit_with_the_c_interface():
    compared = 0
    for row in rows("ktgf_friction_reference.csv"):
        number = {k: float(v) for k, v in row.items() if k not in ("function", "variant")}
        table_parameters = {k: number[k] for k in ("min_fraction", "max_packing", "coefficient", "numerator_exponent",
                                                   "denominator_exponent")}
        table_parameters["friction_angle"] = number["friction_angle_deg"] * np.pi / 180

        def made(name):
            """The closure in Python and in C, with the table's parameters that it has."""
            law, handle = fluidbed.closure(name), c_closure(name)
            for key in law.parameters.keys() & table_parameters.keys():
                law.set(**{key: table_parameters[key]})
                assert C.fluidbed_closure_set_parameter(handle, key.encode(), ctypes.c_double(table_parameters[key]),
                                                        None) == 0
            return law, handle

        phi = np.array([number["solid_fraction"]])
        rate = [np.array([number[k]]) for k in ("divergence", "deviatoric_contraction")]
        if row["variant"] == "srivastava_sundaresan":
            law, handle = made("SrivastavaSundaresan")
            state = [phi, np.array([number["granular_temperature"]]), np.array([number["diameter"]]), *rate]
            python = law.stress(*state, derivatives=True)
            out = [np.empty(1) for _ in range(4)]
            assert C.fluidbed_frictional_stress(handle, ctypes.c_size_t(1), *(ptr(a) for a in state),
                                                *(ptr(a) for a in out), None) == 0
            for p, q in zip(python, out):
                assert same_bits(p, q)
        else:
            law, handle = made("JohnsonJacksonPressure" if row["variant"].endswith("johnson_jackson")
                               else "SchaefferPressure")
            python = law.pressure(phi, derivatives=True)
            c = c_one_argument(C.fluidbed_of_solid_fraction, handle, phi[0])
            assert same_bits(python.value, c[0]) and same_bits(python.d_solid_fraction, c[1])
            if row["function"] == "frictional_viscosity":
                viscosity, handle = made("SchaefferViscosity")
                python = viscosity.viscosity(c[0], *rate, derivatives=True)
                out = [np.empty(1) for _ in range(2)]
                assert C.fluidbed_frictional_viscosity(handle, ctypes.c_size_t(1), ptr(c[0]), *(ptr(a) for a in rate),
                                                       *(ptr(a) for a in out), None) == 0
                assert same_bits(python.value, out[0]) and same_bits(python.derivative, out[1])
        compared += 1
    assert compared == 1253


def test_dqmom_sources_bit_for_bit_with_c_growth_identity_shapes_and_errors():
    ints = ctypes.POINTER(ctypes.c_int)
    rng = np.random.default_rng(17)
    for count in range(1, 9):
        cells = 23
        nodes = 40e-6 * 1.6 ** np.arange(count) * (1 + 0.01 * rng.random((cells, 1)))
        weights = 0.05 + 0.3 * rng.random((cells, count))
        sources = (-2e-4) ** np.arange(2 * count) * (1 + rng.random((cells, 2 * count)))
        growth = 1e-7 * rng.uniform(-1, 1, (cells, count))
        python = fluidbed.dqmom_sources(nodes, weights, sources)
        functional = fluidbed.dqmom_growth_diffusion_sources(nodes, weights, growth_rate=growth)
        # The C interface on the same (count, cells) fields.
        x, w, s, g = (np.ascontiguousarray(a.T) for a in (nodes, weights, sources, growth))
        for r, call in ((python, lambda a, b, st, k: C.fluidbed_dqmom_sources(
                            count, ctypes.c_size_t(cells), ptr(x), ptr(w), ptr(s), ptr(a), ptr(b),
                            st.ctypes.data_as(ints), ptr(k), None)),
                        (functional, lambda a, b, st, k: C.fluidbed_dqmom_growth_diffusion_sources(
                            count, 0, ctypes.c_size_t(cells), ptr(x), ptr(w), ptr(g), None, ptr(a), ptr(b),
                            st.ctypes.data_as(ints), ptr(k), None))):
            a, b, k = np.empty((count, cells)), np.empty((count, cells)), np.empty(cells)
            status = np.empty(cells, dtype=np.intc)
            assert call(a, b, status, k) == 0
            assert same_bits(r.weight, a.T) and same_bits(r.weighted_node, b.T) and same_bits(r.condition, k)
            assert np.array_equal(r.status, status)
        # Pure growth: c^phi = 3 phi G / xi and c^xi = 4 phi G whatever the conditioning.
        assert np.allclose(functional.weight, 3 * weights * growth / nodes, rtol=1e-14, atol=0)
        assert np.allclose(functional.weighted_node, 4 * weights * growth, rtol=1e-14, atol=0)
        assert all(fluidbed.DQMOM_STATUSES[st] == "ok" for st in python.status)
    # Broadcast shapes, float32, number densities, statuses, errors.
    one = fluidbed.dqmom_growth_diffusion_sources(np.array([75e-6, 103e-6], dtype=np.float32),
                                                  np.array([1e9, 2e9], dtype=np.float32), weights_kind="number_density",
                                                  growth_rate=np.array([1e-7, 1e-7], dtype=np.float32))
    assert one.weight.dtype == np.float32 and one.weight.shape == (2,) and one.status.shape == ()
    assert np.allclose(one.weighted_node, [100, 200], rtol=1e-6)
    merged = fluidbed.dqmom_sources([[1e-4, 1e-4]], [[0.1, 0.2]], [[1, 2e-4, 3e-8, 4e-12]])
    assert fluidbed.DQMOM_STATUSES[merged.status[0]] == "merged_nodes"
    with pytest.raises(fluidbed.InvalidArgument):
        fluidbed.dqmom_sources([1e-4, 2e-4], [0.1, 0.2], [1, 2, 3])
    with pytest.raises(fluidbed.InvalidArgument):
        fluidbed.dqmom_growth_diffusion_sources([1e-4, 2e-4], [0.1, 0.2], weights_kind="mass")
    with pytest.raises(fluidbed.InvalidArgument):
        fluidbed.dqmom_sources(np.full(9, 1e-4), np.ones(9), np.ones(18))


def test_unequal_temperature_mixture_bit_for_bit_with_c_identities_shapes_and_errors():
    rng = np.random.default_rng(29)
    cells = 6
    for count in range(1, 5):
        fractions = (0.05 + 0.4 * rng.random((cells, 1))) / count * (1 + 0.2 * np.arange(count))
        temperatures = 1e-3 * (1 + 4 * rng.random((cells, count)))
        diameters = 1e-4 * (1 + 0.7 * np.arange(count)) * np.ones((cells, 1))
        densities = (2500 - 400 * np.arange(count)) * np.ones((cells, 1))
        restitution = 0.7 + 0.3 * rng.random(cells)
        fields = [np.ascontiguousarray(a.T) for a in (fractions, temperatures, diameters, densities)]
        for name in ("Lebowitz", "Mansoori", "ModifiedMansoori"):
            python = fluidbed.unequal_temperature_mixture(fractions, temperatures, diameters, densities, restitution,
                                                          radial=name, derivatives=True)
            plain = fluidbed.unequal_temperature_mixture(fractions, temperatures, diameters, densities, restitution,
                                                         radial=fluidbed.MixtureRadialDistribution(name))
            # The C interface on the same (classes, cells) fields: entry e of cell c at [e n + c], the
            # derivative in class m at [m S + e n + c].
            entries = [(count,) if q in (0, 4) else (count, count) for q in range(8)]
            out = [[np.empty(e + (cells,)), np.empty((count,) + e + (cells,)), np.empty((count,) + e + (cells,))]
                   for e in entries]
            assert C.fluidbed_unequal_temperature_mixture_with_derivatives(
                c_closure(name), ctypes.c_size_t(cells), ctypes.c_size_t(count), *(ptr(a) for a in fields),
                ptr(restitution), *(ptr(a) for trio in out for a in trio), None) == 0
            for field, unchecked, (value, by_fraction, by_temperature) in zip(python, plain, out):
                assert same_bits(field.value, np.moveaxis(value, -1, 0))
                assert same_bits(unchecked, field.value)
                assert same_bits(field.d_fractions, np.moveaxis(np.moveaxis(by_fraction, -1, 0), 1, -1))
                assert same_bits(field.d_temperatures, np.moveaxis(np.moveaxis(by_temperature, -1, 0), 1, -1))
            # Independent identities: entry [..., i, k] is μ_ik, and μ_12/μ_21 = m_1Θ_1/(m_2Θ_2); one class
            # gives Lun's pressure αρΘ(1 + 2(1 + e)α h).
            mu, h = plain.shear_viscosity, plain.radial_distribution
            if count > 1:
                mass = densities * diameters ** 3
                assert np.allclose(mu[:, 0, 1] / mu[:, 1, 0], mass[:, 0] * temperatures[:, 0] /
                                   (mass[:, 1] * temperatures[:, 1]), rtol=1e-13, atol=0)
            else:
                lun = fractions[:, 0] * densities[:, 0] * temperatures[:, 0] * (
                    1 + 2 * (1 + restitution) * fractions[:, 0] * h[:, 0, 0])
                assert np.allclose(plain.pressure[:, 0], lun, rtol=1e-14, atol=0)
            assert np.array_equal(plain.drag, np.swapaxes(plain.drag, -1, -2))
    # Broadcasting (one cell, scalars for the classes' common values), float32, errors.
    one = fluidbed.unequal_temperature_mixture([0.2, 0.1], [1e-3, 2e-3], 1e-4, 2500, 0.9)
    assert one.pressure.shape == (2,) and one.drag.shape == (2, 2)
    single = fluidbed.unequal_temperature_mixture(np.float32([0.2, 0.1]), np.float32([1e-3, 2e-3]), np.float32(1e-4),
                                                  np.float32(2500), np.float32(0.9), derivatives=True)
    assert single.pressure.value.dtype == np.float32 and single.pressure.d_fractions.shape == (2, 2)
    assert np.allclose(single.pressure.value, one.pressure, rtol=1e-5)
    with pytest.raises(fluidbed.DomainError) as cold:
        fluidbed.unequal_temperature_mixture([[0.2, 0.1], [0.2, 0.1]], [[1e-3, 2e-3], [1e-3, 0.0]], 1e-4, 2500, 0.9)
    assert cold.value.index == (1,) and "state.temperatures[1]" in str(cold.value)
    with pytest.raises(fluidbed.InvalidArgument):
        fluidbed.unequal_temperature_mixture(np.full(11, 0.01), 1e-3, 1e-4, 2500, 0.9)
    with pytest.raises(fluidbed.InvalidArgument):
        fluidbed.unequal_temperature_mixture([0.2, 0.1], 1e-3, 1e-4, 2500, 0.9, radial="CarnahanStarling")
