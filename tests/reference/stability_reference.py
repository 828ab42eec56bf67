#!/usr/bin/python3
"""Independent high-precision reference generator for the elastic modulus and the
linear stability of homogeneous fluidization (seed 000, Mazzei 2008, secs 3.5 and 4.6).

Writes (next to this file):
  elastic_functions_reference.csv  n_e, N, C, D, H of the Mazzei-Lettieri elastic closure
                                   on a (voidage, Re*) grid
  elastic_state_reference.csv      drag-based M&L modulus at non-equilibrium states, with an
                                   independent numerical derivative of the drag (eq 3.108)
  stability_reference.csv          minimum bubbling voidage / velocity (Table 4.6, sec 4.6.3)
                                   for the F&G, J&F and M&L stability functions
  stability_curve_reference.csv    u_k, u_d, K and S along voidage for four systems

Formulas, sources and conventions: README.md (same folder); seed 000 secs 3.5, 4.6.1-4.6.3,
Tables 4.5 and 4.6.  mpmath, 40 digits; inputs are exact decimal strings; output nstr(x, 17).
Before writing anything the script asserts seed 000's Table 4.6 and sec. 4.6.3 numbers, and
the numbers of an independent double-precision evaluation of the same equations made when
the thesis was read (each quoted where it is checked).  It never reads the C++ code.

Run with Debian's python:  /usr/bin/python3 stability_reference.py   (prints one line)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # keep the folder free of __pycache__

from mpmath import mp, mpf, sqrt, log, exp, pi, findroot, nstr, diff, mpc  # noqa: E402
import drag_reference as dr  # noqa: E402
import settling_reference as sr  # noqa: E402

mp.dps = max(mp.dps, 40)  # or more where an importer asked for it (scalar_types_reference.py)
M, out, close, G = dr.M, dr.out, dr.close, dr.G
n_e = dr.n_e  # seed 000 eq 3.24 / 3.54


def tiny(k):
    return mpf(10) ** (-k)


# ----------------------------------------------------------------------------
# Mazzei-Lettieri elastic functions (seed 000 Table 3.1, eqs 3.103-3.109)
# ----------------------------------------------------------------------------
def xfun(R):
    return M('0.175') * R ** M('0.75')


def N_fun(R):
    """dn_e/dRe* of seed 000 eq 3.24, simplified: -0.315 Re*^-1/4 / (1 + x)^2, 0.315 = 1.8 * 0.175"""
    x = xfun(R)
    return -M('0.315') * R ** M('-0.25') / (1 + x) ** 2


def N_table(R):
    """dn_e/dRe* exactly as printed in Table 3.1"""
    x = xfun(R)
    q = R ** M('0.25')
    return M('0.75') * M('0.175') * (M('2.40') / (q * (1 + x)) - (M('4.80') + M('2.40') * x) / (q * (1 + x) ** 2))


def C_fun(eps, R, with_C=True):
    """C = 1/(1 + Re* N ln eps) (eq 3.105); with_C=False gives the C = 1 variant"""
    if not with_C:
        return mpf(1)
    return 1 / (1 + R * N_fun(R) * log(eps))


def D_fun(R):
    """D = 4.8 Re*^-1/2 / (0.63 + 4.8 Re*^-1/2) (eq 3.107), written regular at Re* -> 0"""
    return M('4.8') / (M('0.63') * sqrt(R) + M('4.8'))


def H_fun(eps, R, with_C=True):
    """H = C n_e (D - 2)/eps (eq 3.109)"""
    return C_fun(eps, R, with_C) * n_e(R) * (D_fun(R) - 2) / eps


# ----------------------------------------------------------------------------
# Re* = Re/eps^{n_e(Re*)}: safeguarded Newton in ln Re*, converged to the working precision
# (so that mpmath.diff, which raises the precision, differentiates a smooth function)
# ----------------------------------------------------------------------------
def restar_hp(eps, Re):
    if eps == 1:
        return +Re
    le, lR = log(eps), log(Re)
    a, b = lR - M('2.4') * le, lR - M('4.8') * le
    g = lambda lx: lx + n_e(exp(lx)) * le - lR  # noqa: E731
    assert g(a) <= 0 <= g(b)
    lx = (a + b) / 2
    tol = mpf(2) ** (-mp.prec + 8) * (1 + abs(lx))
    for _ in range(200):
        R = exp(lx)
        gv = g(lx)
        if gv > 0:
            b = lx
        else:
            a = lx
        step = gv / (1 + R * N_fun(R) * le)  # g' = 1/C >= 1
        nx = lx - step
        if not (a <= nx <= b):
            nx = (a + b) / 2
        if abs(nx - lx) <= tol:
            lx = nx
            break
        lx = nx
    else:
        raise RuntimeError('restar_hp did not converge')
    return exp(lx)


def fhat(rf, mu, R):
    """drag per particle F^ = (pi mu^2/(8 rho)) C_D*(Re*) Re*^2 (eq 3.99), regular form"""
    return pi * mu ** 2 / (8 * rf) * (M('0.63') * sqrt(R) + M('4.8')) ** 2 * R


# ----------------------------------------------------------------------------
# material systems for the stability analysis (seed 000 Tables 4.5, 4.6 and sec. 4.6.3). The
# thesis gives no gas properties: air 1.205 kg/m3, 1.81e-5 Pa s (powders 1-10, 13) and N2 at
# 20 C 1.165 kg/m3, 1.76e-5 Pa s (11, 12, 14, 15) reproduce Table 4.6 to +-0.001
# ----------------------------------------------------------------------------
AIR = ('1.205', '1.81e-5')
N2_20C = ('1.165', '1.76e-5')
POWDERS = {  # number: (d, rho_p)
    1: ('137e-6', '1210'), 2: ('130e-6', '1220'), 3: ('115e-6', '1230'), 4: ('110e-6', '1240'),
    5: ('94e-6', '1260'), 6: ('71e-6', '1300'), 7: ('68e-6', '1310'), 8: ('63e-6', '1310'),
    9: ('47e-6', '1350'), 10: ('26e-6', '1420'), 11: ('109e-6', '880'), 12: ('71e-6', '1420'),
    13: ('62e-6', '2550'), 14: ('57e-6', '1420'), 15: ('49e-6', '1420'),
}
# Table 4.6: (powder, T degC) -> (exp, F&G, J&F, M&L)
TABLE46 = [
    (1, 20, '0.418', '0.359', '0.421', '0.401'), (2, 20, '0.441', '0.369', '0.431', '0.413'),
    (3, 20, '0.449', '0.397', '0.456', '0.440'), (4, 20, '0.454', '0.406', '0.465', '0.450'),
    (5, 20, '0.481', '0.440', '0.497', '0.485'), (6, 20, '0.482', '0.503', '0.556', '0.549'),
    (7, 20, '0.495', '0.512', '0.565', '0.559'), (8, 20, '0.539', '0.532', '0.583', '0.578'),
    (9, 20, '0.581', '0.606', '0.654', '0.652'), (10, 20, '0.646', '0.855', '0.896', '0.902'),
    (11, 20, '0.448', '0.456', '0.513', '0.500'), (12, 20, '0.553', '0.483', '0.536', '0.529'),
    (13, 20, '0.514', '0.430', '0.485', '0.477'), (14, 20, '0.583', '0.537', '0.588', '0.584'),
    (15, 20, '0.542', '0.578', '0.626', '0.624'),
    (12, 100, '0.579', '0.512', '0.563', '0.559'), (12, 200, '0.593', '0.543', '0.592', '0.590'),
    (12, 300, '0.595', '0.568', '0.616', '0.615'), (12, 400, '0.607', '0.588', '0.635', '0.635'),
    (12, 500, '0.608', '0.609', '0.655', '0.656'), (12, 600, '0.611', '0.629', '0.674', '0.675'),
    (13, 100, '0.509', '0.452', '0.505', '0.500'), (13, 200, '0.507', '0.480', '0.532', '0.529'),
    (13, 300, '0.563', '0.503', '0.553', '0.551'),
]
MODELS = ['foscolo_gibilaro', 'jean_fan', 'mazzei_lettieri']
SEC463 = ('1.19', '1.82e-5', '2500', '71.5e-6')


def n2_ideal_gas(T_celsius):
    """N2 at 101325 Pa: ideal-gas density, Sutherland viscosity (mu0 1.663e-5 Pa s, T0 273.15 K,
    S 107 K); reproduces the 100 C rows of Table 4.6 and drifts low above"""
    T = M(str(T_celsius)) + M('273.15')
    rho = M('101325') * M('0.0280134') / (M('8.314462618') * T)
    T0, S = M('273.15'), M('107')
    mu = M('1.663e-5') * (T / T0) ** M('1.5') * (T0 + S) / (T + S)
    return rho, mu


def case_list():
    """(case name, powder label, T degC or None, gas, rho_f, mu_f, rho_p, d, {model: thesis})"""
    cases = []
    for p, T, _ex, fg, jf, ml in TABLE46:
        d, rp = POWDERS[p]
        if T == 20:
            gas = 'air' if (p <= 10 or p == 13) else 'N2'
            rf, mu = (M(x) for x in (AIR if gas == 'air' else N2_20C))
        else:
            gas = 'N2'
            rf, mu = n2_ideal_gas(T)
        cases.append(('powder%d_%dC' % (p, T), str(p), T, gas, rf, mu, M(rp), M(d),
                      dict(zip(MODELS, (fg, jf, ml)))))
    rf, mu, rp, d = (M(x) for x in SEC463)
    cases.append(('section_4_6_3', '', None, 'air', rf, mu, rp, d, {}))
    return cases


class System:
    """a fluid/particle pair at homogeneous equilibrium: Dallavalle u_t, Re_t, n_e(Re_t)"""

    def __init__(self, rf, mu, rp, d):
        self.rf, self.mu, self.rp, self.d = rf, mu, rp, d
        self.Ret = sr.ret_dallavalle(rf, mu, rp, d)
        self.ut = self.Ret * mu / (rf * d)
        self.n = n_e(self.Ret)
        self.drho = rp - rf

    # --- explicit stability functions (eqs 3.76, 4.37, 4.36)
    def S(self, model, eps, with_C=True):
        n = self.n
        pre = self.d * G / self.ut ** 2 * self.drho / self.rp / n ** 2
        if model == 'foscolo_gibilaro':
            arg = M('3.2') * pre * eps ** (2 * (1 - n)) / (1 - eps)
        elif model == 'jean_fan':
            arg = M('3.2') * pre * eps ** (1 - 2 * n) / (1 - eps)
        else:
            arg = -2 * H_fun(eps, self.Ret, with_C) / 3 * pre * eps ** (2 * (1 - n)) / (1 - eps)
        return 1 - sqrt(arg)

    # --- wave speeds and damping (eqs 4.27, 4.31, 4.32, 3.75, 3.95, 3.111)
    def us(self, eps):
        return self.ut * eps ** self.n

    def modulus(self, model, eps):
        Ef = M('3.2') * self.d * (1 - eps) * self.drho * G
        if model == 'foscolo_gibilaro':
            return Ef
        if model == 'jean_fan':
            return Ef / eps
        return -M(2) / 3 * self.d * (1 - eps) * self.drho * G * H_fun(eps, self.Ret)

    def u_k(self, eps):
        return self.ut * self.n * (1 - eps) * eps ** (self.n - 1)

    def u_d(self, model, eps):
        return sqrt(self.modulus(model, eps) / self.rp)

    def K(self, eps, with_C=True):
        R = self.Ret
        return self.drho * G * C_fun(eps, R, with_C) * (2 - D_fun(R)) / (self.rp * self.us(eps))

    def K_numeric(self, eps):
        """K = -A/((1-eps) rho_p), A = dF1/dv at fixed u_s (eqs 4.19, 4.24, 4.31), with
        F1 = (1-eps)[6 F^/(pi d^3) - (rho_p - rho_f) g] and F^ the M&L drag per particle at
        the superficial slip U = u_s - v (Re* from Re = rho U d/mu, eq 3.99)"""
        us = self.us(eps)

        def F1(v):
            Re = self.rf * (us - v) * self.d / self.mu
            return (1 - eps) * (6 * fhat(self.rf, self.mu, restar_hp(eps, Re)) / (pi * self.d ** 3)
                                - self.drho * G)

        assert abs(F1(mpf(0))) < tiny(30) * (1 - eps) * self.drho * G, 'not at equilibrium'
        A = diff(F1, mpf(0))
        return -A / ((1 - eps) * self.rp)


# ----------------------------------------------------------------------------
# roots and maximum of S on [0.30, 1)
# ----------------------------------------------------------------------------
SCAN = [M('0.30') + mpf(i) / 1000 for i in range(0, 691)]  # 0.300 .. 0.990
SCAN += [1 - mpf(10) ** (-2 - mpf(j) / 50) for j in range(1, 651)]  # 1 - 1e-2.02 .. 1 - 1e-15


def bisect_root(f, a, b, fa):
    r = findroot(f, (a, b), solver='anderson')
    if not (a <= r <= b) or abs(f(r)) > tiny(36):
        # fall back to plain bisection
        for _ in range(400):
            m = (a + b) / 2
            fm = f(m)
            if (fm > 0) == (fa > 0):
                a, fa = m, fm
            else:
                b = m
            if b - a < tiny(45):
                break
        r = (a + b) / 2
    assert a <= r <= b and abs(f(r)) < tiny(34), (a, b, f(r))
    return r


def analyse(sysm, model, with_C=True):
    """returns (roots list ascending, max_voidage, max_value)"""
    f = lambda e: sysm.S(model, e, with_C)  # noqa: E731
    vals = [f(e) for e in SCAN]
    assert vals[0] < 0 and vals[-1] < 0, (model, vals[0], vals[-1])
    roots = []
    for i in range(len(SCAN) - 1):
        if (vals[i] > 0) != (vals[i + 1] > 0):
            roots.append(bisect_root(f, SCAN[i], SCAN[i + 1], vals[i]))
    # one interior maximum on the scan (S rises, then falls)
    loc = [i for i in range(1, len(SCAN) - 1) if vals[i] >= vals[i - 1] and vals[i] >= vals[i + 1]]
    assert len(loc) == 1, (model, loc)
    i = loc[0]
    dS = lambda e: diff(f, e)  # noqa: E731
    a, b = SCAN[i - 1], SCAN[i + 1]
    assert dS(a) > 0 > dS(b)
    em = bisect_root(dS, a, b, dS(a))
    # the maximum is the root of dS/deps, located to |S'/S''| < 1e-30 (the max_voidage column, which the
    # library's argmax is tested against to 1e-13 relative in double), and a maximum: S'' < 0
    d2S = diff(f, em, 2)
    assert d2S < 0 and abs(dS(em) / d2S) < tiny(30), (model, em, dS(em), d2S)
    return roots, em, f(em)


# ----------------------------------------------------------------------------
# checks
# ----------------------------------------------------------------------------
def within(x, ref, tol, what):
    assert abs(mpf(x) - M(ref)) <= M(tol) + tiny(30), '%s: got %s expected %s +- %s' % (
        what, nstr(x, 10), ref, tol)


def checks_elastic():
    n = 0
    # N: simplified form = Table 3.1 form = numerical derivative of n_e
    for R in ['1e-10', '1e-3', '0.1', '1', '10', '100', '1000', '1e4', '1e12']:
        R = M(R)
        Ns = N_fun(R)
        assert abs(Ns - N_table(R)) < tiny(32) * abs(Ns)
        assert abs(Ns - diff(n_e, R)) < tiny(28) * abs(Ns)
        n += 2
    # eq. 3.112: E_r^e/E_j = H/(-4.8/eps), an independent evaluation printed to 5 decimals
    ratio_table = {'1e-10': ('1.00000', '1.00000'), '1e-3': ('1.00241', '1.00345'), '1': ('0.89187', '1.00867'),
                   '10': ('0.74135', '0.92855'), '100': ('0.77793', '0.88206'), '1e4': ('0.96329', '0.96904'),
                   '1e12': ('1.00000', '1.00000')}
    for R, (r5, r9) in ratio_table.items():
        for e, ref in (('0.5', r5), ('0.9', r9)):
            close(-H_fun(M(e), M(R)) * M(e) / M('4.8'), ref, what='E_r^e/E_j eps=%s Re*=%s' % (e, R))
            n += 1
    # (4.38): H -> -4.8/eps in both limits
    for e in ['0.4', '0.7', '0.99']:
        for R in ['1e-30', '1e40']:
            assert abs(H_fun(M(e), M(R)) * M(e) / M('4.8') + 1) < tiny(6)
            n += 1
    # D, N, C, H at (eps, Re) with Re* from the implicit relation (eqs. 3.53, 3.100-3.112): an
    # independent evaluation printed to 6 digits
    tab = [('0.40', '0.01', '0.905177', '-0.278698', '0.860084', '-10.672887'),
           ('0.40', '1', '0.627469', '-0.0205653', '0.721722', '-8.158258'),
           ('0.40', '10', '0.408833', '-0.00173338', '0.838380', '-9.085732'),
           ('0.40', '100', '0.196778', '-5.74671e-05', '0.951538', '-10.623385'),
           ('0.40', '1000', '0.073819', '-1.1897e-06', '0.990137', '-11.512633'),
           ('0.50', '0.01', '0.938110', '-0.393668', '0.935504', '-9.256742'),
           ('0.50', '1', '0.690690', '-0.0385609', '0.762678', '-7.072469'),
           ('0.50', '10', '0.472912', '-0.00380422', '0.840230', '-7.314302'),
           ('0.50', '100', '0.241856', '-0.000140405', '0.947406', '-8.368403'),
           ('0.50', '1000', '0.094275', '-3.01014e-06', '0.988944', '-9.128146'),
           ('0.70', '0.01', '0.970272', '-0.626975', '0.987961', '-6.908470'),
           ('0.70', '1', '0.789013', '-0.096927', '0.874506', '-6.037212'),
           ('0.70', '10', '0.579486', '-0.0124896', '0.880146', '-5.595461'),
           ('0.70', '100', '0.324023', '-0.000540558', '0.953551', '-5.932520'),
           ('0.70', '1000', '0.134904', '-1.22047e-05', '0.989715', '-6.433001'),
           ('0.90', '0.01', '0.983396', '-0.864244', '0.998495', '-5.392048'),
           ('0.90', '1', '0.858486', '-0.180956', '0.970805', '-5.326291'),
           ('0.90', '10', '0.667693', '-0.0307872', '0.955437', '-4.875376'),
           ('0.90', '100', '0.397842', '-0.00150409', '0.979361', '-4.717053'),
           ('0.90', '1000', '0.174665', '-3.48676e-05', '0.995261', '-4.969341')]
    for e, Re, Dr, Nr, Cr, Hr in tab:
        eps = M(e)
        R = restar_hp(eps, M(Re))
        assert abs(R - dr.restar(eps, M(Re))) < tiny(30) * R
        close(D_fun(R), Dr, what='D'); close(N_fun(R), Nr, what='N')
        close(C_fun(eps, R), Cr, what='C'); close(H_fun(eps, R), Hr, what='H')
        n += 5
    # 0 < C <= 1 and H < 0 (C = 1/(1 + Re* N ln eps) with Re* N < 0, ln eps <= 0)
    for e in ['0.3', '0.5', '0.9', '1']:
        for R in ['1e-6', '10', '1e6']:
            c = C_fun(M(e), M(R))
            assert 0 < c <= 1 and H_fun(M(e), M(R)) < 0
            n += 1
    return n


def checks_system1():
    """system 1 of seed 000 Table 4.3 at u_s = 5.28e-3 m/s (an independent evaluation)"""
    n = 0
    s = System(M('998'), M('1e-3'), M('2780'), M('253e-6'))
    us = M('5.28e-3')
    eps = (us / s.ut) ** (1 / s.n)
    close(eps, '0.6037180', what='eps_RZ')
    Ef = s.modulus('foscolo_gibilaro', eps)
    close(Ef, '5.6085623', what='E_f'); close(s.modulus('jean_fan', eps), '9.2900366', what='E_j')
    close(s.modulus('mazzei_lettieri', eps), '7.42052', what='E_r^e')
    close(s.u_k(eps), '0.012755751', what='u_k'); close(s.u_d('mazzei_lettieri', eps), '0.051664802', what='u_d')
    close(s.S('mazzei_lettieri', eps), '-3.0503145', what='S_r'); close(s.S('foscolo_gibilaro', eps), '-2.521254')
    close(s.S('jean_fan', eps), '-3.5318997', what='S_j')
    close(s.K(eps), '1240.66', what='K'); close(s.K(eps, with_C=False), '1521.14', what='K without C')
    assert abs(s.K_numeric(eps) / s.K(eps) - 1) < tiny(25)
    n += 12
    # eq. 4.26 as printed omits C.  Off equilibrium (water rho 1000, mu 1e-3, d 500 um):
    # A = dF1/dv = -(1-eps) 6/(pi d^3) dF^/dU = A_printed * C, A_printed = -(1-eps) 6 F^/(pi d^3) (2-D)/U
    for e_s, U_s, Anum, Apr in (('0.45', '1e-4', '-1.5163e6', '-1.8623e6'), ('0.5', '1e-3', '-8.237e5', '-1.075e6')):
        ew, Uw, rw, mw, dw = M(e_s), M(U_s), M('1000'), M('1e-3'), M('500e-6')
        Fu = lambda u: fhat(rw, mw, restar_hp(ew, rw * u * dw / mw))  # noqa: E731
        Rw = restar_hp(ew, rw * Uw * dw / mw)
        A = -(1 - ew) * 6 / (pi * dw ** 3) * diff(Fu, Uw)
        Ap = -(1 - ew) * 6 / (pi * dw ** 3) * Fu(Uw) * (2 - D_fun(Rw)) / Uw
        close(A, Anum, what='A_num'); close(Ap, Apr, what='A_printed')
        assert abs(A / (Ap * C_fun(ew, Rw)) - 1) < tiny(25)
        n += 3
    # the drag-based modulus (3.110) equals the equilibrium one (3.111) at equilibrium
    R = restar_hp(eps, s.rf * us * s.d / s.mu)
    assert abs(R / s.Ret - 1) < tiny(30)
    F = fhat(s.rf, s.mu, R)
    Er = -4 * (1 - eps) / (pi * s.d ** 2) * H_fun(eps, R) * F
    assert abs(Er / s.modulus('mazzei_lettieri', eps) - 1) < tiny(30)
    n += 2
    return n


def checks_stability(results):
    """results[(case, model)] = (roots, em, Smax); asserts Table 4.6 and sec. 4.6.3"""
    n = 0
    failures = []
    cases = {c[0]: c for c in case_list()}

    def low(case, model):
        return results[(case, model)][0][0]

    # (a) Table 4.6 rows at 20 degC (powders 1-9, 11-15) and 12/13 at 100 degC: +-0.001.
    # "+-0.001" holds only after rounding the root to the printed 3 decimals for four
    # N2 rows (rho_f 1.165, mu_f 1.76e-5); unrounded they miss by 0.0011-0.0012.  They are listed
    # here explicitly with their own bound (README, "Disagreements"); every other row is strict.
    known = {('powder11_20C', 'mazzei_lettieri'): '0.00124', ('powder12_20C', 'jean_fan'): '0.00117',
             ('powder15_20C', 'jean_fan'): '0.00113', ('powder15_20C', 'mazzei_lettieri'): '0.00117'}
    strict = ['powder%d_20C' % p for p in (1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 12, 13, 14, 15)]
    strict += ['powder12_100C', 'powder13_100C']
    for c in strict:
        for m in MODELS:
            r = low(c, m)
            th = M(cases[c][8][m])
            tol = M(known.get((c, m), '0.001'))
            if abs(r - th) > tol + tiny(30):
                failures.append((c, m, r, th))
            if (c, m) in known:
                assert abs(r - th) > M('0.001')  # the exception is real
            # one unit of the printed third decimal after rounding
            assert abs(round(float(r), 3) - float(th)) < 0.0010001
            n += 1
    assert not failures, ['%s %s %s vs %s' % (c, m, nstr(r, 6), nstr(t, 3)) for c, m, r, t in failures]
    # (b) the independent evaluation's numbers (half a unit of the printed 3rd decimal)
    for c, vals in [('powder1_20C', ('0.358', '0.421', '0.401')), ('powder5_20C', ('0.440', '0.497', '0.485')),
                    ('powder9_20C', ('0.606', '0.653', '0.652')), ('powder12_20C', ('0.484', '0.537', '0.530')),
                    # it printed 0.477 (= Table 4.6) for powder 13 M&L; the root is 0.47633
                    ('powder13_20C', ('0.430', '0.485', '0.476')), ('powder12_100C', ('0.512', '0.563', '0.559')),
                    ('powder13_100C', ('0.452', '0.505', '0.500'))]:
        for m, v in zip(MODELS, vals):
            close(low(c, m), v, what='%s %s' % (c, m))
            n += 1
    # (c) every regular row has exactly two roots (onset and re-stabilisation near 1)
    for (c, m), (roots, em, Smax) in results.items():
        if c == 'powder10_20C' and m != 'foscolo_gibilaro':
            continue
        assert len(roots) == 2 and roots[0] < em < roots[1] and Smax > 0, (c, m)
        n += 1
    # (d) powder 10: F&G has roots 0.855 (Table 4.6) and 0.907; J&F and M&L have none, and the
    # table's 0.896 and 0.902 sit at the maximum of S
    roots, em, Smax = results[('powder10_20C', 'foscolo_gibilaro')]
    close(roots[0], '0.855', what='p10 F&G'); close(roots[1], '0.907', what='p10 F&G 2nd'); n += 2
    for m, smax in (('jean_fan', '-0.046'), ('mazzei_lettieri', '-0.054')):
        roots, em, Smax = results[('powder10_20C', m)]
        assert roots == []
        close(Smax, smax, what='p10 max S ' + m)
        within(em, '0.895', '0.005', 'p10 argmax ' + m)
        n += 3
    # (e) elevated temperatures with N2 ideal gas + Sutherland: drift low, at most 0.022 + 0.0005
    for c in cases:
        if c.startswith('powder12_') or c.startswith('powder13_'):
            if c.endswith('_20C') or c.endswith('_100C'):
                continue
            for m in MODELS:
                dev = low(c, m) - M(cases[c][8][m])
                assert M('-0.0225') <= dev <= M('0.001'), (c, m, dev)
                n += 1
    dev600 = min(low('powder12_600C', m) - M(cases['powder12_600C'][8][m]) for m in MODELS)
    within(dev600, '-0.022', '0.0005', 'largest 600 C drift'); n += 1
    # (f) sec. 4.6.3
    s = System(*(M(x) for x in SEC463[:2]), *(M(x) for x in SEC463[2:]))
    close(s.ut, '0.29866'); close(s.Ret, '1.3962'); close(s.n, '4.3595'); n += 3
    for m, e, u in (('foscolo_gibilaro', '0.4026', '0.566'), ('jean_fan', '0.4588', '1.000'),
                    ('mazzei_lettieri', '0.4479', '0.900')):
        r = low('section_4_6_3', m)
        close(r, e, what='4.6.3 ' + m); close(100 * s.us(r), u, what='4.6.3 u_mb ' + m); n += 2
    return n


def checks_variants():
    """side claims: C = 1 variant, rho 1.2/mu 1.8e-5, powder 13 with N2, R-Z (independent evaluation)"""
    n = 0
    # M&L without C: powder 1 -> 0.421, sec. 4.6.3 -> 0.4608 and 1.02 cm/s
    d, rp = POWDERS[1]
    s = System(M(AIR[0]), M(AIR[1]), M(rp), M(d))
    close(analyse(s, 'mazzei_lettieri', with_C=False)[0][0], '0.421', what='p1 ML C=1'); n += 1
    s = System(*(M(x) for x in SEC463))
    r = analyse(s, 'mazzei_lettieri', with_C=False)[0][0]
    close(r, '0.4608', what='4.6.3 C=1'); close(100 * s.us(r), '1.02', what='4.6.3 C=1 u_mb'); n += 2
    # R-Z at 1.55 cm/s gives 0.507
    close((M('0.0155') / s.ut) ** (1 / s.n), '0.507'); n += 1
    # powders 1-9 with rho_f 1.2, mu_f 1.8e-5: +-0.002
    for p in range(1, 10):
        d, rp = POWDERS[p]
        s = System(M('1.2'), M('1.8e-5'), M(rp), M(d))
        for m, th in zip(MODELS, TABLE46[p - 1][3:]):
            within(analyse(s, m)[0][0], th, '0.002', 'p%d %s air 1.2' % (p, m)); n += 1
    # powder 13 with N2 at 20 C is 0.004-0.005 low
    d, rp = POWDERS[13]
    s = System(M(N2_20C[0]), M(N2_20C[1]), M(rp), M(d))
    for m, th in zip(MODELS, TABLE46[12][3:]):
        dev = analyse(s, m)[0][0] - M(th)
        assert M('-0.0055') <= dev <= M('-0.0035'), ('p13 N2', m, dev)
        n += 1
    # the 20 C N2 properties are the ideal-gas/Sutherland values rounded; with the unrounded
    # values (1.16455, 1.75654e-5) powders 11, 12, 14, 15 are strictly within +-0.001
    rho, mu = n2_ideal_gas(20)
    close(rho, '1.165'); close(mu, '1.76e-5'); n += 2
    for p in (11, 12, 14, 15):
        d, rp = POWDERS[p]
        s = System(rho, mu, M(rp), M(d))
        row = [t for t in TABLE46 if t[0] == p and t[1] == 20][0]
        for m, th in zip(MODELS, row[3:]):
            within(analyse(s, m)[0][0], th, '0.001', 'p%d %s N2 ideal gas' % (p, m)); n += 1
    return n


# ----------------------------------------------------------------------------
def main():
    nchk = checks_elastic() + checks_system1()

    # --- elastic_functions_reference.csv
    rows = ['voidage,re_star,n_e,N,C,D,H']
    for e in ['0.36', '0.4', '0.5', '0.6', '0.7', '0.8', '0.9', '0.95', '0.99', '0.999', '1']:
        for R in ['1e-10', '1e-3', '0.1', '1', '10', '100', '1000', '1e4', '1e12']:
            eps, Rs = M(e), M(R)
            c, D, H = C_fun(eps, Rs), D_fun(Rs), H_fun(eps, Rs)
            assert abs(H - c * n_e(Rs) * (D - 2) / eps) == 0
            rows.append(','.join(out(v) for v in (eps, Rs, n_e(Rs), N_fun(Rs), c, D, H)))
    felastic = rows

    # --- elastic_state_reference.csv
    rows = ['fluid_density,fluid_viscosity,particle_density,diameter,voidage,slip,reynolds,re_star,'
            'drag_per_particle,drag_force_density,dF_dvoidage,H,modulus']
    maxrel = mpf(0)
    for rf_s, mu_s, d_s, rp_s in [('998', '1e-3', '253e-6', '2780'), ('1.205', '1.81e-5', '137e-6', '1210'),
                                  ('1.2', '1.8e-5', '5e-4', '2500')]:
        rf, mu, d, rp = M(rf_s), M(mu_s), M(d_s), M(rp_s)
        for e in ['0.4', '0.5', '0.7', '0.9', '0.99']:
            eps = M(e)
            for Re_s in ['1e-3', '1', '10', '100', '1e3']:
                w = M(out(M(Re_s) * mu / (rf * eps * d)))  # slip rounded to 17 digits
                Re = rf * eps * w * d / mu
                assert abs(Re / M(Re_s) - 1) < tiny(15)
                R = restar_hp(eps, Re)
                assert abs(R / dr.restar(eps, Re) - 1) < tiny(30)
                F = fhat(rf, mu, R)
                fd = 6 * (1 - eps) / (pi * d ** 3) * F
                # = beta_ML (classical) * w, from the drag script's M&L law
                bcl = dr.law_mazzei_lettieri(None, eps, w, rf, mu, d, Re, None)[0]
                assert abs(bcl * w / fd - 1) < tiny(30)
                U = eps * w  # superficial slip, held fixed

                def Fof(x):
                    return fhat(rf, mu, restar_hp(x, rf * U * d / mu))

                dF = diff(Fof, eps)
                H = H_fun(eps, R)
                rel = abs(dF / (H * F) - 1)
                assert rel < tiny(25), ('eq 3.108', e, Re_s, rel)
                maxrel = max(maxrel, rel)
                Er = -4 * (1 - eps) / (pi * d ** 2) * H * F
                assert Er > 0
                rows.append(','.join(out(v) for v in (rf, mu, rp, d, eps, w, Re, R, F, fd, dF, H, Er)))
                nchk += 3
    fstate = rows

    # --- stability_reference.csv
    results = {}
    systems = {}
    rows = ['case,powder,temperature,gas,fluid_density,fluid_viscosity,particle_density,diameter,'
            'terminal_velocity,terminal_reynolds,n_e,model,lower_root,upper_root,max_voidage,max_value,'
            'bubbling_velocity,thesis']
    for name, powder, T, gas, rf, mu, rp, d, thesis in case_list():
        s = System(rf, mu, rp, d)
        systems[name] = s
        # closed-form Dallavalle u_t solves the force balance
        assert abs(M('0.75') * dr.cdre_dv(s.Ret) * s.Ret / sr.archimedes(rf, mu, rp, d) - 1) < tiny(30)
        for m in MODELS:
            roots, em, Smax = analyse(s, m)
            results[(name, m)] = (roots, em, Smax)
            lo = out(roots[0]) if roots else ''
            hi = out(roots[-1]) if roots else ''
            ub = out(s.us(roots[0])) if roots else ''
            rows.append(','.join([name, powder, '' if T is None else str(T), gas] +
                                 [out(v) for v in (rf, mu, rp, d, s.ut, s.Ret, s.n)] +
                                 [m, lo, hi, out(em), out(Smax), ub, thesis.get(m, '')]))
    fstab = rows
    nchk += checks_stability(results) + checks_variants()

    # --- stability_curve_reference.csv
    rows = ['case,model,voidage,kinematic_wave_speed,dynamic_wave_speed,damping,stability']
    for name in ['powder1_20C', 'powder10_20C', 'powder13_20C', 'section_4_6_3']:
        s = systems[name]
        for m in MODELS:
            for e in ['0.35', '0.4', '0.45', '0.5', '0.6', '0.7', '0.8', '0.9', '0.95', '0.99']:
                eps = M(e)
                uk, ud, K = s.u_k(eps), s.u_d(m, eps), s.K(eps)
                st = 1 - ud / uk
                assert abs(st - s.S(m, eps)) < tiny(35)
                # u_k = (1 - eps) du_s/deps along R-Z (eq 4.27)
                assert abs(uk / ((1 - eps) * diff(s.us, eps)) - 1) < tiny(30)
                # K from the linearised M&L drag (numerical) = closed form with C
                assert abs(s.K_numeric(eps) / K - 1) < tiny(25), (name, e)
                if m == 'mazzei_lettieri':
                    # drag-based modulus (3.110) at the equilibrium state = (3.111)
                    R = restar_hp(eps, s.rf * s.us(eps) * s.d / s.mu)
                    Er = -4 * (1 - eps) / (pi * s.d ** 2) * H_fun(eps, R) * fhat(s.rf, s.mu, R)
                    assert abs(Er / s.modulus(m, eps) - 1) < tiny(28)
                # dispersion relation (4.35) solves the characteristic equation of (4.33)
                nu = (uk + ud) / 2
                a = K * (uk - nu) / (2 * nu)
                k = sqrt(K ** 2 / (4 * nu ** 2) * (uk ** 2 - nu ** 2) / (nu ** 2 - ud ** 2))
                sig = mpc(a, -k * nu)
                resid = sig ** 2 + ud ** 2 * k ** 2 + K * sig + mpc(0, 1) * K * uk * k
                assert abs(resid) < tiny(30) * (K ** 2 + abs(sig) ** 2)
                assert (a < 0) == (ud > uk)
                rows.append(','.join([name, m] + [out(v) for v in (eps, uk, ud, K, st)]))
                nchk += 5
    fcurve = rows

    for fname, r in [('elastic_functions_reference.csv', felastic), ('elastic_state_reference.csv', fstate),
                     ('stability_reference.csv', fstab), ('stability_curve_reference.csv', fcurve)]:
        with open(os.path.join(HERE, fname), 'w') as f:
            f.write('\n'.join(r) + '\n')
    print('stability_reference: %d elastic-function, %d elastic-state, %d stability, %d curve rows; '
          '%d checks passed; max |dF/deps / (H F) - 1| = %s'
          % (len(felastic) - 1, len(fstate) - 1, len(fstab) - 1, len(fcurve) - 1, nchk, nstr(maxrel, 2)))


if __name__ == '__main__':
    main()
