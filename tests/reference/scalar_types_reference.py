#!/usr/bin/python3
"""Independent high-precision reference for the scalar-type tests (tests/test_scalar_types_*.cpp):
every closure of the drag, settling, elastic/stability and kinetic-theory families evaluated at
inputs that float, double and x87 long double all represent exactly, to 55 significant digits.

Writes scalar_types_reference.csv (next to this file), one row per (family, closure, input):
    family,closure,p1,p2,p3,p4,p5,p6,p7,p8,value,d1,d2
p1..p8 are the inputs (unused ones 0), value the result, d1 and d2 two partial derivatives
where the closure has them (empty otherwise). The meaning of p1..p8, d1 and d2 for each
family is listed with its writer below (drag_rows, settling_rows, elastic_rows, stability_rows,
kinetic_theory_rows) and read the same way by the C++ tests.

Why a table of its own. The other tables print their inputs as short decimals (0.35, 1.8e-5),
which float and double round differently, and their values to 17 digits, which is 46 ulp of
long double. Here every input is a dyadic rational with at most 24 significant bits (asserted),
so the C++ test converts it to float, double and long double exactly, and each result differs
from the value below only by the rounding inside the closure: the test's tolerance can be a
small multiple of the type's epsilon. The values have 55 significant digits, so that a 50-digit type
(Boost's cpp_bin_float_50, 168 bits, epsilon 2^-167 = 5.3e-51) can be tested the same way: the
printed value is then within 5e-55 relative of the exact one, 1e-4 of that epsilon. The inputs
print exactly (asserted): a type that parses them gets the same number as one that converts them.

Conventions: the closures' published decimal constants (0.175, 4.8, 0.63, ...) are exact
decimals here, as in the other generators. A law's run-time parameters are double members of
its C++ type (ConstantExponentDrag's exponent, Syamlal-O'Brien's c1 and d1, the packing limits
and margins of the radial distributions): they enter here as the exact values of those doubles
(mpf of the Python float), which is what every scalar type evaluates. g = 9.81 exactly (the C++
default standard_gravity_as<T>() is 9.81 rounded once to T, an input rounding the tests allow
for). Derivatives are mpmath.diff of the value function with the branch of the state frozen.

Precision. Everything runs at mp.dps = 80 (the imported generators keep a precision raised before
they are imported, so that their constants, 9.81 and the published decimals, have 80 digits too);
the roots (Re*, Schiller-Naumann's Re_t, the equilibrium voidage, the stability points) are converged
to that precision, and mpmath.diff evaluates at twice it. Running the script at mp.dps = 100 changes
no printed digit of any value or derivative beyond the 53rd (checked when the precision was raised).

The formulas are those of drag_reference.py, settling_reference.py, stability_reference.py and
ktgf_reference.py (imported, never re-typed); this script only chooses inputs and writes.
It never reads the C++ code. Run with Debian's python: /usr/bin/python3 scalar_types_reference.py
"""
import os
import sys
from decimal import Decimal
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # keep the folder free of __pycache__

from mpmath import mp, mpf, nstr, diff, sqrt, log, sin  # noqa: E402

mp.dps = 80  # before the imports: they keep a precision raised by their importer
DIGITS = 55  # significant digits of the values and derivatives written
import drag_reference as dr  # noqa: E402
import settling_reference as sr  # noqa: E402
import stability_reference as st  # noqa: E402
import ktgf_reference as kt  # noqa: E402

G = dr.G  # 9.81
ROWS = []
# Syamlal-O'Brien's c1 = 0.8 and d1 = 2.65 are double members of the C++ law
dr.SO_C1, dr.SO_D1 = mpf(0.8), mpf(2.65)


def exact(s):
    """a decimal string that binary32 represents exactly (at most 24 significant bits) -> mpf"""
    f = Fraction(s)
    den = f.denominator
    assert den & (den - 1) == 0, s + ' is not dyadic'
    num = abs(f.numerator)
    while num and num % 2 == 0:
        num //= 2
    assert num < 2 ** 24, s + ' needs more than 24 bits'
    return mpf(f.numerator) / den


def of_double(x):
    """the exact value of the double nearest to x (a law's double parameter)"""
    return mpf(float(x))


def fraction(x):
    """an mpf as an exact Fraction (for the generators' branch decisions)"""
    man, e = x.man_exp
    return Fraction(man) * Fraction(2) ** e


def exact_text(x):
    """an input (a dyadic rational of at most 24 bits, or a double) as its exact decimal"""
    assert mpf(float(x)) == x, 'an input is not a double'
    return str(Decimal(float(x)))


def text(x):
    """a result to DIGITS significant digits"""
    return nstr(mpf(x), DIGITS, strip_zeros=True) if x != 0 else '0'


def row(family, closure, inputs, value, d1=None, d2=None):
    assert len(inputs) <= 8
    ps = list(inputs) + [mpf(0)] * (8 - len(inputs))
    ROWS.append(','.join([family, closure] + [exact_text(p) for p in ps] + [text(value)] +
                         ['' if d is None else text(d) for d in (d1, d2)]))


# ============================================================================ drag
# closure = the law's name; p1..p5 = voidage, slip, fluid density, fluid viscosity, diameter;
# value = beta_classical, d1 = d beta_classical/d voidage (fixed slip), d2 = d/d slip (fixed
# voidage; empty at slip 0, where laws with a fractional power of Re have an infinite slope).
AIR = ('1.25', '0.0000152587890625', '0.00048828125')  # rho, mu = 2^-16, d = 2^-11: Re = 40 eps w
WATER = ('1000', '0.0009765625', '0.000244140625')  # mu = 2^-10, d = 2^-12: Re = 250 eps w
DRAG_VOIDAGES = ['0.375', '0.4375', '0.5', '0.625', '0.75', '0.8125', '0.875', '0.9375', '0.984375', '1']
DRAG_SLIPS = {AIR: ['0', '0.0078125', '0.125', '1', '8', '64'], WATER: ['0', '0.0009765625', '0.0625', '1']}


def mazzei_lettieri_classical(eps, w, rho, mu, d):
    """beta_classical of Mazzei-Lettieri (drag_reference's form) with the Re* solve converged to
    the working precision (stability_reference.restar_hp), so that mpmath.diff sees a smooth function"""
    Re = rho * eps * w * d / mu
    Rs = st.restar_hp(eps, Re) if Re > 0 else mpf(0)
    return 3 * mu * (1 - eps) / (4 * d ** 2) * (M('0.63') * sqrt(Rs) + M('4.8')) ** 2 * eps ** (1 - dr.n_e(Rs))


def M(s):
    return mpf(s)


def drag_laws():
    """(name, beta_classical(eps, w, rho, mu, d), keep(ef, Rf)) for every law of the family. The branch
    decisions are taken on the exact voidage and Reynolds number of the point evaluated (no state lies on
    a switch, so mpmath.diff's neighbouring points take the same branches)."""
    def generic(law):
        def beta(eps, w, rho, mu, d):
            Re = rho * eps * w * d / mu
            return law(fraction(eps), eps, w, rho, mu, d, Re, fraction(Re))
        return beta

    # ConstantExponentDrag holds its exponent as a double: 2.65 for Lewis and WenYuGidaspow (also the
    # dilute branch of the three Gidaspow laws)
    def constant_exponent(alpha):
        return generic(dr.make_wenyu_classical(exact_text(alpha)))
    lewis = constant_exponent(2.65)

    def wen_yu_gidaspow(eps, w, rho, mu, d):
        return lewis(eps, w, rho, mu, d)  # classical; the pressure-gradient form is eps times it

    def gidaspow_switched(eps, w, rho, mu, d):
        return (generic(dr.law_ergun) if eps < M('0.8') else wen_yu_gidaspow)(eps, w, rho, mu, d)

    def gidaspow_blended(eps, w, rho, mu, d):
        psi = M('0.5') + dr.atan(150 * M('1.75') * (eps - M('0.8'))) / dr.pi
        return ((1 - psi) * generic(dr.law_ergun)(eps, w, rho, mu, d)[0] +
                psi * wen_yu_gidaspow(eps, w, rho, mu, d)[0], None)
    # GidaspowLeboreiro's switch voidage and half-width are doubles too (0.54 and 0.02 as the C++ holds them)
    def gidaspow_leboreiro(eps, w, rho, mu, d):
        switch, half_width = mpf(0.54), mpf(0.02)
        t = (eps - switch + half_width) / (2 * half_width)
        s = mpf(0) if t <= 0 else mpf(1) if t >= 1 else t * t * (3 - 2 * t)
        return ((1 - s) * generic(dr.law_ergun)(eps, w, rho, mu, d)[0] +
                s * wen_yu_gidaspow(eps, w, rho, mu, d)[0], None)
    laws = {name: generic(law) for name, law, _ in dr.LAWS}
    laws.update({'Lewis': lewis, 'WenYu1966': constant_exponent(2.70), 'Kmiec': constant_exponent(2.78),
                 'WenYuGidaspow': wen_yu_gidaspow, 'GidaspowSwitched': gidaspow_switched,
                 'GidaspowBlended': gidaspow_blended, 'GidaspowLeboreiro': gidaspow_leboreiro,
                 'MazzeiLettieri': lambda eps, w, rho, mu, d: (mazzei_lettieri_classical(eps, w, rho, mu, d), None)})
    keep = {name: k for name, _, k in dr.LAWS}
    return [(name, (lambda f: lambda *args: f(*args)[0])(laws[name]), keep[name]) for name, _, _ in dr.LAWS]


def drag_rows():
    n = 0
    for name, beta, keep in drag_laws():
        for fluid in (AIR, WATER):
            rho, mu, d = (exact(x) for x in fluid)
            for es in DRAG_VOIDAGES:
                for ws in DRAG_SLIPS[fluid]:
                    eps, w = exact(es), exact(ws)
                    if keep is not None and not keep(fraction(eps), fraction(rho * eps * w * d / mu)):
                        continue
                    value = beta(eps, w, rho, mu, d)
                    # no derivatives at eps = 1 (a one-sided difference of sqrt(phi)-type terms) and
                    # in the slip at w = 0 (infinite for laws with a fractional power of Re)
                    d_eps = diff(lambda x: beta(x, w, rho, mu, d), eps) if eps < 1 else None
                    d_w = diff(lambda x: beta(eps, x, rho, mu, d), w) if w > 0 else None
                    row('drag', name, (eps, w, rho, mu, d), value, d_eps, d_w)
                    n += 1
    # Beetstra polydisperse, species 1 of two: p1..p8 = phi1, phi2, d1, d2, slip, rho, mu, cubic
    # coefficient (0.064 as a double, or 0); value = beta_classical, d1 = beta_pressure_gradient
    for phis in (('0.125', '0.25'), ('0.3125', '0.09375')):
        for ds in (('0.00048828125', '0.001953125'),):
            for ws in ('0', '0.125', '2'):
                for cubic in (of_double(0.064), mpf(0)):
                    ph, dd, w = [exact(x) for x in phis], [exact(x) for x in ds], exact(ws)
                    rho, mu = exact(AIR[0]), exact(AIR[1])
                    phi = sum(ph)
                    eps = 1 - phi
                    dbar = 1 / sum((p / phi) / x for p, x in zip(ph, dd))
                    F = dr.F_beetstra(phi, rho * eps * dbar * w / mu)
                    y = dd[0] / dbar
                    f_b = eps * y + phi * y ** 2 + cubic * eps * y ** 3
                    cl = 18 * mu * ph[0] * F * f_b / dd[0] ** 2
                    pg = 18 * mu * eps * ph[0] * F * y / dd[0] ** 2
                    row('drag', 'BeetstraPolydisperse', (ph[0], ph[1], dd[0], dd[1], w, rho, mu, cubic), cl, pg)
                    n += 1
    # single-sphere C_D Re: p1 = Re
    for Re_s in ('0.0009765625', '0.5', '24', '999.5', '1000', '4096'):
        Re = exact(Re_s)
        row('drag', 'Stokes', (Re,), dr.cdre_stokes(Re))
        row('drag', 'SchillerNaumann', (Re,), dr.cdre_sn(Re, fraction(Re)))
        row('drag', 'Dallavalle', (Re,), dr.cdre_dv(Re))
        n += 3
    return n


# ============================================================================ settling
# closure = the quantity; p1..p8 as listed per quantity below; value.
SETTLING_SYSTEMS = [  # rho_f, mu_f, rho_p, d
    ('1000', '0.0009765625', '2500', '0.000244140625'),
    ('1000', '0.0009765625', '2500', '0.00390625'),
    ('1.25', '0.0000152587890625', '2500', '0.00048828125'),
    ('1.25', '0.0000152587890625', '1250', '0.0001220703125'),
]


def equilibrium_voidage(beta, us, rho, mu, rp, d):
    """lowest root in (0, 1) of beta_cl(eps, w) w/((1 - eps) (rho_p - rho_f) g) - 1, w = u_s/eps (seed 000
    eq 3.28 divided by (1 - eps)), the law's branch taken at each trial voidage"""
    def residual(eps):
        w = us / eps
        return beta(eps, w, rho, mu, d) * w / ((1 - eps) * (rp - rho) * G) - 1
    grid = [mpf(k) / 256 for k in range(16, 256)]
    assert residual(grid[0]) > 0, 'no root above 1/16'
    i = next(i for i in range(len(grid) - 1) if residual(grid[i + 1]) <= 0)  # the first sign change
    a, b = grid[i], grid[i + 1]
    for _ in range(200):  # bisection: the laws switched in voidage are discontinuous
        m = (a + b) / 2
        if residual(m) > 0:
            a = m
        else:
            b = m
    assert b - a < mpf(10) ** -(DIGITS + 5)
    return (a + b) / 2


def settling_rows():
    n = 0

    def add(q, params, v):
        nonlocal n
        row('settling', q, params, v)
        n += 1
    for R in ('0', '0.001953125', '0.125', '1', '12.5', '100', '1024', '16384'):
        Re = exact(R)
        add('rz_exponent_mazzei', (Re,), sr.n_mazzei(Re))
        add('rz_exponent_rowe1987', (Re,), sr.n_rowe(Re))
        add('rz_exponent_garside_aldibouni1977', (Re,), sr.n_garside(Re))
        if Re > 0:  # -inf at 0
            add('rz_exponent_mazzei_derivative', (Re,), -M('0.315') * Re ** M('-0.25') /
                (1 + M('0.175') * Re ** M('0.75')) ** 2)
    for A in ('0', '0.015625', '1', '100', '16384', '1048576'):
        for dD in ('0', '0.0078125', '0.03125'):
            add('rz_exponent_khan_richardson1989', (exact(A), exact(dD)), sr.n_khan_richardson(exact(A), exact(dD)))
    for R in ('0.0625', '0.5', '6.25', '300', '1024'):
        for dD in ('0', '0.0078125', '0.09375'):
            add('rz_exponent_richardson_zaki1954', (exact(R), exact(dD)), sr.n_rz1954(exact(R), Fraction(R), exact(dD)))
    for ut, eps, ne in (('0.03125', '0.375', '4.75'), ('1.5', '0.8125', '2.5')):
        u, e, n_ = exact(ut), exact(eps), exact(ne)
        add('richardson_zaki_velocity', (u, e, n_), u * e ** n_)
        add('richardson_zaki_voidage', (u * exact('0.125'), u, n_), exact('0.125') ** (1 / n_))
    for R, eps in (('0.015625', '0.375'), ('1', '0.5'), ('12.5', '0.625'), ('1024', '0.875'), ('100', '0.984375')):
        add('richardson_zaki_terminal_reynolds', (exact(R), exact(eps)), st.restar_hp(exact(eps), exact(R)))
    for A in ('0.125', '10', '1000', '100000', '8388608'):
        Ar = exact(A)
        add('terminal_reynolds_stokes', (Ar,), Ar / 18)
        add('terminal_reynolds_newton', (Ar,), sqrt(Ar / (M('0.75') * M('0.44'))))
        # Dallavalle's closed form, and Schiller-Naumann's root (u_t = Re_t at rho = mu = d = 1, g = Ar)
        add('terminal_reynolds_dallavalle', (Ar,), sr.ret_dallavalle(mpf(1), mpf(1), 1 + Ar / G, mpf(1)))
        add('terminal_reynolds_schiller_naumann', (Ar,), sr.ut_schiller_naumann(mpf(1), mpf(1), 1 + Ar / G, mpf(1)))
    for system in SETTLING_SYSTEMS:
        rho, mu, rp, d = (exact(x) for x in system)
        for q, f in (('terminal_velocity_stokes', sr.ut_stokes), ('terminal_velocity_newton', sr.ut_newton),
                     ('terminal_velocity_dallavalle', sr.ut_dallavalle),
                     ('terminal_velocity_schiller_naumann', sr.ut_schiller_naumann)):
            add(q, (rho, mu, rp, d), f(rho, mu, rp, d))
        Ar = sr.archimedes(rho, mu, rp, d)
        for emf, sph in (('0.375', '1'), ('0.4375', '0.75')):
            e, s = exact(emf), exact(sph)
            # the Ergun quadratic with sphericity: 150 (1-e) Re/(e^3 s^2) + 1.75 Re^2/(e^3 s) = Ar
            a, b = M('1.75') / (e ** 3 * s), 150 * (1 - e) / (e ** 3 * s ** 2)
            remf = (-b + sqrt(b * b + 4 * a * Ar)) / (2 * a)
            add('minimum_fluidization_velocity_ergun', (rho, mu, rp, d, e, s), remf * mu / (rho * d))
            add('minimum_fluidization_reynolds_ergun', (Ar, e, s), remf)
        add('minimum_fluidization_velocity_wen_yu', (rho, mu, rp, d), sr.remf_wenyu(Ar) * mu / (rho * d))
        add('minimum_fluidization_reynolds_wen_yu', (Ar,), sr.remf_wenyu(Ar))
    # equilibrium voidage of every law (and Richardson-Zaki's): p1..p5 = u_s, rho_f, mu_f, rho_p, d
    for system, velocities in ((SETTLING_SYSTEMS[0], ('0.001953125', '0.0078125')),
                               (SETTLING_SYSTEMS[2], ('0.125', '0.5'))):
        rho, mu, rp, d = (exact(x) for x in system)
        for us_s in velocities:
            us = exact(us_s)
            for name, beta, _ in drag_laws():
                add('equilibrium_voidage_' + name, (us, rho, mu, rp, d), equilibrium_voidage(beta, us, rho, mu, rp, d))
            ret = sr.ret_dallavalle(rho, mu, rp, d)
            ut = ret * mu / (rho * d)
            add('equilibrium_voidage_RichardsonZaki', (us, rho, mu, rp, d), (us / ut) ** (1 / dr.n_e(ret)))
    # the voidage ratio (p1 = Re, p2 = eps_RZ) and the equivalent exponent (p1 = eps, p2 = Re) of every law
    for name, beta, _ in drag_laws():
        for Re_s, eps_s in (('1', '0.5'), ('64', '0.75')):
            Re, e_rz = exact(Re_s), exact(eps_s)
            ret = st.restar_hp(e_rz, Re)
            ar = M('0.75') * dr.cdre_dv(ret) * ret
            e = equilibrium_voidage(beta, Re, mpf(1), mpf(1), 1 + ar / G, mpf(1))
            add('voidage_ratio_' + name, (Re, e_rz), e / e_rz)
        for eps_s, Re_s in (('0.5', '0.125'), ('0.875', '16')):
            eps, Re = exact(eps_s), exact(Re_s)
            b = beta(eps, Re / eps, mpf(1), mpf(1), mpf(1))
            single = M('0.75') * dr.cdre_dv(Re) * (1 - eps) / eps
            add('equivalent_exponent_' + name, (eps, Re), -log(b / single) / log(eps))
    add('bed_height', (exact('0.75'), exact('0.375'), exact('0.625')), exact('0.75') * exact('0.625') / exact('0.375'))
    return n


# ============================================================================ elastic and stability
# Table 3.1 (closure table_3_1_<n_e|N|C|D|H>): p1 = voidage, p2 = Re*.
# equilibrium moduli (modulus_<model>): p1 = voidage, p2..p5 = rho_f, mu_f, rho_p, d, p6 = Re_t.
# state functions (effective_reynolds, mazzei_lettieri_sensitivity, mazzei_lettieri_modulus):
#   p1 = voidage, p2 = slip, p3, p4 = rho_f, mu_f, p5 = d.
def elastic_rows():
    n = 0
    for es in ('0.375', '0.5', '0.8125', '0.984375', '1'):
        for Rs in ('0', '0.0078125', '1', '24', '1024'):
            eps, R = exact(es), exact(Rs)
            for name, f in (('n_e', dr.n_e), ('N', st.N_fun), ('C', lambda R_: st.C_fun(eps, R_)), ('D', st.D_fun),
                            ('H', lambda R_: st.H_fun(eps, R_))):
                if name in ('N', 'C', 'H') and R == 0:
                    if name == 'N':
                        continue  # -inf
                    v = mpf(1) if name == 'C' else -M('4.8') / eps  # the limits the C++ takes at Re* = 0
                else:
                    v = f(R)
                row('elastic', 'table_3_1_' + name, (eps, R), v)
                n += 1
    rho, mu, rp, d = (exact(x) for x in ('1.25', '0.0000152587890625', '1250', '0.0001220703125'))
    for es in ('0.375', '0.5', '0.875', '0.984375', '1'):
        eps = exact(es)
        for Rs in ('0.5', '12.5'):
            Ret = exact(Rs)
            weight = M(2) / 3 * d * (rp - rho) * G * (1 - eps)
            for model, h in (('foscolo_gibilaro', -M('4.8')), ('jean_fan', -M('4.8') / eps),
                             ('mazzei_lettieri', st.H_fun(eps, Ret))):
                row('elastic', 'modulus_' + model, (eps, rho, mu, rp, d, Ret), -weight * h)
                n += 1
    for fluid in (AIR, WATER):
        rho, mu, d = (exact(x) for x in fluid)
        for es in ('0.4375', '0.75', '0.984375'):
            for ws in DRAG_SLIPS[fluid][1:]:
                eps, w = exact(es), exact(ws)
                Re = rho * eps * w * d / mu
                R = st.restar_hp(eps, Re)
                H = st.H_fun(eps, R)
                beta = mazzei_lettieri_classical(eps, w, rho, mu, d)
                row('elastic', 'effective_reynolds', (eps, w, rho, mu, d), R)
                row('elastic', 'mazzei_lettieri_sensitivity', (eps, w, rho, mu, d), H)
                row('elastic', 'mazzei_lettieri_modulus', (eps, w, rho, mu, d), -M(2) / 3 * d * H * beta * w)
                n += 3
    return n


# minimum bubbling point (closure bubbling_<model>): p1..p4 = rho_f, mu_f, rho_p, d;
#   value = the lowest root of S (empty row value when there is none: closure no_bubbling_<model>
#   carries the maximum instead), d1 = where S is largest, d2 = that largest S.
# suspension data (suspension_terminal_velocity, _terminal_reynolds, _exponent): p1..p4 as above.
# stability function and wave speeds (stability_<model>, kinematic_wave_speed, dynamic_wave_speed_<model>,
#   damping): p1..p4 as above, p5 = voidage.
STABILITY_SYSTEMS = [
    # powder 1 and powder 10 of seed 000 Table 4.6 in air, on binary-exact inputs nearby: rho_f 77/64,
    # mu_f 1.1875 2^-16, d 1.125 2^-13 and 109 2^-22 (137 and 26 um), rho_p 1210 and 1420
    ('1.203125', '0.0000181198120117187500', '1210', '0.0001373291015625'),
    ('1.203125', '0.0000181198120117187500', '1420', '0.0000259876251220703125'),
]


def stability_rows():
    n = 0
    for system in STABILITY_SYSTEMS:
        rf, mu, rp, d = (exact(x) for x in system)
        s = st.System(rf, mu, rp, d)
        row('stability', 'suspension_terminal_velocity', (rf, mu, rp, d), s.ut)
        row('stability', 'suspension_terminal_reynolds', (rf, mu, rp, d), s.Ret)
        row('stability', 'suspension_exponent', (rf, mu, rp, d), s.n)
        n += 3
        for model in st.MODELS:
            roots, em, smax = st.analyse(s, model)
            # the maximum is a root of dS/deps, and a maximum
            assert abs(diff(lambda e: s.S(model, e), em)) < mpf(10) ** -30
            assert diff(lambda e: s.S(model, e), em, 2) < 0
            if roots:
                row('stability', 'bubbling_' + model, (rf, mu, rp, d), roots[0], em, smax)
                row('stability', 'restabilisation_' + model, (rf, mu, rp, d), roots[-1])
                n += 2
            else:
                row('stability', 'no_bubbling_' + model, (rf, mu, rp, d), smax, em, smax)
                n += 1
            for es in ('0.375', '0.5', '0.75', '0.9375'):
                eps = exact(es)
                row('stability', 'stability_' + model, (rf, mu, rp, d, eps), s.S(model, eps))
                row('stability', 'dynamic_wave_speed_' + model, (rf, mu, rp, d, eps), s.u_d(model, eps))
                n += 2
        for es in ('0.375', '0.5', '0.75', '0.9375'):
            eps = exact(es)
            row('stability', 'kinematic_wave_speed', (rf, mu, rp, d, eps), s.u_k(eps))
            row('stability', 'damping', (rf, mu, rp, d, eps), s.K(eps))
            n += 2
    return n


# ============================================================================ kinetic theory
# one-class RDFs (closure radial_distribution:<variant>): p1 = phi, p2 = phi_max (a double; 0 where
#   the form has none); value = g0, d1 = dg0/dphi.
# constitutive closures (closure <function>:<author>, the names of ktgf_reference.csv, with g0 of
#   Carnahan-Starling): p1 = phi, p2 = Theta, p3 = e, p4 = d, p5 = rho_s, p6 = Hrenya-Sinclair L
#   (0 elsewhere); value, d1 = d/dphi (through g0), d2 = d/dTheta (empty at Theta = 0).
KT_PHIS = ['0.0078125', '0.125', '0.375', '0.5', '0.59375', '0.6328125']
KT_THETAS = ['0', '0.0009765625', '0.0625', '1']
KT_MATERIALS = [('0.75', '0.00048828125', '2500'), ('0.875', '0.001953125', '1250')]  # e, d, rho_s
KT_RDF_PACKINGS = {'lun_savage': 0.63, 'sinclair_jackson': 0.64, 'ogawa': 0.63, 'gidaspow': 0.64,
                   'ma_ahmadi': None, 'lathouwers_bellan': 0.64, 'carnahan_starling': None, 'percus_yevick': None,
                   'song_stratt_mason': None, 'tobochnik_chapin': None}
# the forms whose packing limit is a constant of the fit (a decimal, not a double parameter)
KT_RDF_FIT_PACKINGS = {'ma_ahmadi': kt.MA_PMAX, 'song_stratt_mason': kt.SSM_PMAX, 'tobochnik_chapin': kt.TC_PMAX}


def with_margin(f):
    """a radial distribution of the generator with the default margin as the C++ double 0.01"""
    def g(p, pmax, plain=None):
        saved = kt.DELTA
        kt.DELTA = of_double(0.01)
        try:
            return f(p, pmax, plain)
        finally:
            kt.DELTA = saved
    return g


KT_CONSTITUTIVE = [  # (function, author, value(p, T, e, d, r, g [, L]), takes L)
    ('granular_pressure', 'lun', kt.p_lun, False), ('granular_pressure', 'syamlal_rogers_obrien', kt.p_srob, False),
    ('granular_pressure', 'ma_ahmadi', kt.p_ma_ahmadi, False),
    ('shear_viscosity', 'gidaspow', kt.mu_gid, False), ('shear_viscosity', 'syamlal', kt.mu_sya, False),
    ('shear_viscosity', 'hrenya_sinclair', kt.mu_hs, True), ('bulk_viscosity', 'lun', kt.lam_lun, False),
    ('conductivity', 'gidaspow', kt.k_gid, False), ('conductivity', 'syamlal', kt.k_sya, False),
    ('conductivity', 'hrenya_sinclair', kt.k_hs, True), ('dissipation', 'lun', kt.gam_lun, False),
    ('shear_viscosity', 'enskog', kt.mu_es, False), ('conductivity', 'enskog', kt.k_es, False),
]


def kinetic_theory_rows():
    n = 0
    for variant, pmax_double in KT_RDF_PACKINGS.items():
        f, _ = kt.RDF[variant]
        f = with_margin(f)
        pmax = KT_RDF_FIT_PACKINGS.get(variant, None if pmax_double is None else of_double(pmax_double))
        for ps in KT_PHIS + ['0.640625']:
            p = exact(ps)
            if pmax is None and p > exact('0.625'):
                continue
            plain = None if pmax is None else p <= pmax - of_double(0.01)
            v = f(p, pmax, plain)
            dv = diff(lambda q: f(q, pmax, plain), p)
            row('kinetic_theory', 'radial_distribution:' + variant, (p, mpf(0) if pmax_double is None else pmax), v, dv)
            n += 1
    L = exact('0.0625')
    for function, author, law, takes_length in KT_CONSTITUTIVE:
        for es, ds, rs in KT_MATERIALS:
            e, d, r = exact(es), exact(ds), exact(rs)
            for ps in KT_PHIS[:-1]:
                for ts in KT_THETAS:
                    p, T = exact(ps), exact(ts)
                    extra = (L,) if takes_length else ()

                    def value(q, t):
                        return law(q, t, e, d, r, kt.g0_cs(q), *extra)
                    d_phi = diff(lambda q: value(q, T), p)
                    d_theta = diff(lambda t: value(p, t), T) if T > 0 else None
                    row('kinetic_theory', function + ':' + author, (p, T, e, d, r, L if takes_length else 0),
                        value(p, T), d_phi, d_theta)
                    n += 1
    # frictional pressures (p1 = phi; Johnson-Jackson: p2..p6 = phi_min, phi_max, Fr, a, b as doubles,
    # margin the double 0.01; Schaeffer: p2 = phi_min, p3 = A, p4 = n); value, d1 = d/dphi
    for ps in ('0.5', '0.59375', '0.625', '0.6328125', '0.640625'):
        p = exact(ps)
        pmin, pmax, fr = of_double(0.55), of_double(0.63), of_double(0.05)
        saved = kt.DELTA
        kt.DELTA = of_double(0.01)
        br = (p > pmin, p <= pmax - kt.DELTA)
        v = kt.p_fric_jj(p, pmin, pmax, fr, 2, 5, br)
        dv = diff(lambda q: kt.p_fric_jj(q, pmin, pmax, fr, 2, 5, br), p)
        kt.DELTA = saved
        row('kinetic_theory', 'frictional_pressure:johnson_jackson', (p, pmin, pmax, fr, 2, 5), v, dv)
        pmin_s = of_double(0.5)
        v = kt.p_fric_schaeffer(p, pmin_s, of_double(1e24), 10, (p > pmin_s,))
        dv = diff(lambda q: kt.p_fric_schaeffer(q, pmin_s, of_double(1e24), 10, (p > pmin_s,)), p)
        row('kinetic_theory', 'frictional_pressure:schaeffer', (p, pmin_s, of_double(1e24), 10), v, dv)
        n += 2
    # Schaeffer's frictional viscosity: p1 = p_f, p2 = D':D', p3 = friction angle [rad, a double], p4 = floor
    angle = of_double(0.5)
    for pf_s in ('0', '12.5', '65536'):
        for dd_s in ('0', '0.5', '200'):
            pf, dd = exact(pf_s), exact(dd_s)
            floor = of_double(1e-6)
            v = pf * sin(angle) / (2 * sqrt(dd / 2 + floor ** 2))
            row('kinetic_theory', 'frictional_viscosity:schaeffer', (pf, dd, angle, floor), v)
            n += 1
    # Srivastava-Sundaresan (closure frictional_stress:srivastava_sundaresan): p1 = phi, p2 = Theta, p3 = d,
    # p4 = div u, p5 = D':D', p6 = friction angle [rad, a double], critical-state pressure Johnson-Jackson
    # with phi_min 0.55, phi_max 0.63, Fr 0.05 (doubles), a = 2, b = 5; the floor s is the double 1e-6;
    # value = p_f, d1 = dp_f/dphi (its condition in phi, for the tolerance), d2 = mu_f
    saved_floor, saved_delta = kt.S_FLOOR, kt.DELTA
    kt.S_FLOOR, kt.DELTA = of_double(1e-6), of_double(0.01)
    for ps in ('0.59375', '0.625'):
        for ts in ('0', '0.0625'):
            for div_s in ('0.5', '0', '-0.25'):
                p, T, d, divu, dd = exact(ps), exact(ts), exact(AIR[2]), exact(div_s), exact('2')
                pmin, pmax, fr = of_double(0.55), of_double(0.63), of_double(0.05)
                br = (p > pmin, p <= pmax - kt.DELTA)

                def stress(q):
                    return kt.ss_fric(kt.p_fric_jj(q, pmin, pmax, fr, 2, 5, br), T, d, divu, dd, angle * 180 / kt.pi)
                pf, mu_f, _ = stress(p)
                row('kinetic_theory', 'frictional_stress:srivastava_sundaresan', (p, T, d, divu, dd, angle), pf,
                    diff(lambda q: stress(q)[0], p), mu_f)
                n += 1
    kt.S_FLOOR, kt.DELTA = saved_floor, saved_delta
    # gas exchange: damping (p1 = beta, p2 = Theta); Koch-Sangani (p1 = phi, p2 = Theta, p3 = g0, p4 = slip,
    # p5 = mu_g, p6 = d, p7 = rho_s); drag source (p1 = phi, p2 = Theta, p3 = beta, p4 = slip, p5 = d,
    # p6 = rho_s); the floor Theta_s is the double 1e-6
    kt.THETA_S = of_double(1e-6)
    for ps in ('0.125', '0.5'):
        for ts in ('0', '0.0625'):
            p, T = exact(ps), exact(ts)
            g0, w, mug, d, r, beta = exact('2.5'), exact('0.5'), exact(AIR[1]), exact(AIR[2]), exact('2500'), \
                exact('1024')
            row('kinetic_theory', 'gas_damping', (beta, T), kt.x_sink(T, beta))
            row('kinetic_theory', 'koch_sangani', (p, T, g0, w, mug, d, r), kt.x_source_ks(p, T, d, r, mug, w, g0))
            row('kinetic_theory', 'drag_fluctuation', (p, T, beta, w, d, r), kt.x_source_drag(p, T, d, r, w, beta))
            n += 3
    # algebraic granular temperature with Lun pressure, bulk viscosity, dissipation and the named
    # shear viscosity, g0 of Carnahan-Starling: p1 = phi, p2 = e, p3 = d, p4 = rho_s, p5 = beta,
    # p6 = div u, p7 = D':D'
    for author, mu_fun in (('gidaspow', kt.mu_gid), ('syamlal', kt.mu_sya)):
        for ps in ('0.125', '0.5'):
            for beta_s, div_s, dd_s in (('0', '0', '2'), ('16', '0.5', '2'), ('0', '-0.25', '8')):
                p, e, d, r = exact(ps), exact('0.875'), exact(AIR[2]), exact('2500')
                beta, divu, dd = exact(beta_s), exact(div_s), exact(dd_s)
                v = kt.theta_alg(mu_fun, p, e, d, r, kt.g0_cs(p), beta, divu, dd)
                row('kinetic_theory', 'algebraic_temperature:' + author, (p, e, d, r, beta, divu, dd), v)
                n += 1
    # mixture RDFs (closure mixture:<variant>): p1..p3 = phi_1..3, p4..p6 = d_1..3, p7 = i, p8 = k;
    # modified Mansoori with phi_max the double 0.64 and the double margin 0.01
    phis = [exact('0.125'), exact('0.1875'), exact('0.25')]
    ds = [exact('0.0001220703125'), exact('0.000244140625'), exact('0.00048828125')]
    saved = kt.DELTA
    kt.DELTA = of_double(0.01)
    for variant, f in kt.GMIX.items():
        for i, k in ((0, 0), (0, 2), (1, 2)):
            v = f(phis, ds, i, k, of_double(0.64))
            row('kinetic_theory', 'mixture:' + variant, tuple(phis) + tuple(ds) + (i, k), v)
            n += 1
    # Syamlal solid-solid drag between classes 0 and 2 (Lebowitz g): value; p1..p8 = phi_p, phi_q, d_p,
    # d_q, rho_p, rho_q, e, |dv|; C_f the double 0.15
    g = kt.gmix_lebowitz(phis, ds, 0, 2)
    rp, rq, e, w = exact('2500'), exact('1250'), exact('0.875'), exact('0.25')
    cf = of_double(0.15)
    K = 3 * (1 + e) * (kt.pi / 2 + cf * kt.pi ** 2 / 8) * phis[0] * rp * phis[2] * rq * (ds[0] + ds[2]) ** 2 * g \
        / (2 * kt.pi * (rp * ds[0] ** 3 + rq * ds[2] ** 3)) * w
    row('kinetic_theory', 'solid_solid_drag:syamlal', (phis[0], phis[2], ds[0], ds[2], rp, rq, e, w), K, g)
    kt.DELTA = saved
    return n + 1


def main():
    counts = [drag_rows(), settling_rows(), elastic_rows(), stability_rows(), kinetic_theory_rows()]
    header = 'family,closure,p1,p2,p3,p4,p5,p6,p7,p8,value,d1,d2'
    with open(os.path.join(HERE, 'scalar_types_reference.csv'), 'w') as f:
        f.write('\n'.join([header] + ROWS) + '\n')
    print('scalar_types_reference: %d drag, %d settling, %d elastic, %d stability, %d kinetic-theory rows'
          % tuple(counts))


if __name__ == '__main__':
    main()
