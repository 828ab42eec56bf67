#!/usr/bin/python3
"""Independent high-precision reference for the DQMOM source system.

Writes (next to this file):
  dqmom_reference.csv   case,nu,quantity,index,value

The system (Marchisio & Fox (2005), J. Aerosol Sci. 36, 43-73, doi:10.1016/j.jaerosci.2004.07.009;
seed 000 eq. 5.63 and App. D) for nu nodes xi_1..xi_nu and 2 nu distinct real moment orders p:

  sum_i (1 - p) xi_i^p c_i^a + p xi_i^(p-1) c_i^xi = s_p

unknowns c^a (sources of the weights) and c^xi (sources of the weighted nodes), ordered
(c^a_1..c^a_nu, c^xi_1..c^xi_nu), one row per order in the order listed.

Quantities per case (index i = node, k = row): order k, node i, source k (s), weight i (c^a),
weighted_node i (c^xi), length_scale (L), condition, condition_si, condition_source.
Every input (node, order, source) is a double written with repr(), so that strtod gives it back
exactly; the reference solution is the exact solution for those doubles, written to 21 significant
digits (strtod gives the double nearest the exact value, strtold a long double to 1e-21):
  * orders 0..2nu-1: exact rational arithmetic (the doubles are dyadic rationals),
    cross-checked against mpmath LU at 60 digits;
  * fractional orders: mpmath LU at 100 digits, cross-checked at 60 digits.
Condition numbers, mpmath at 60 digits and checked at 100, in units L = 2^floor(log2(max xi))
(nodes xi/L, unknowns x~ = (c^a, c^xi/L), right-hand side s~_p = s_p/L^p, matrix X~):
  * condition = kappa_inf(X~) = ||X~||_inf ||X~^-1||_inf (the library solves in these units);
  * condition_si = kappa_inf of the SI matrix X = D_r X~ D_c (checked against a direct inversion
    at 60 + log10(kappa) digits);
  * condition_source = || |X~^-1| |s~| ||_inf / ||x~||_inf, the condition of the solution with
    respect to the right-hand side alone (1 <= it <= condition).

Run with Debian's python:  /usr/bin/python3 dqmom_reference.py   (~3 s)
It prints a single summary line.  Deterministic: random.Random(20170), exact rationals and
mpmath only.
"""
import os
import random
from fractions import Fraction

from mpmath import mp, mpf, matrix, log, exp, pi, fabs, nstr, inf, mnorm, lu_solve, inverse, floor, ceil

mp.dps = 60

HERE = os.path.dirname(os.path.abspath(__file__))
N_CHECKS = [0]


def check(cond, msg):
    N_CHECKS[0] += 1
    if not cond:
        raise AssertionError(msg)


def F(x):
    """exact Fraction of a double / int / Fraction"""
    if isinstance(x, Fraction):
        return x
    return Fraction(x)


def mpq(q):
    q = F(q)
    return mpf(q.numerator) / q.denominator


def dbl(x):
    """round an mpf or Fraction to the nearest double"""
    if isinstance(x, Fraction):
        return float(x)          # correctly rounded (Fraction.__float__ is exact division)
    return float(mpf(x))


# ----------------------------------------------------------------------------
# the system
# ----------------------------------------------------------------------------
def exact_matrix(nodes, orders):
    """X for integer orders, exact Fractions (nodes are doubles or Fractions)."""
    nu = len(nodes)
    X = []
    for p in orders:
        p = int(p)
        row = [(1 - p) * F(x) ** p for x in nodes]
        row += [p * F(x) ** (p - 1) if p else Fraction(0) for x in nodes]
        X.append(row)
    check(len(X) == 2 * nu, 'square')
    return X


def mp_matrix(nodes, orders):
    """X for real orders (mpf entries; nodes and orders as exact doubles or mpf)."""
    nu = len(nodes)
    X = matrix(2 * nu, 2 * nu)
    for r, p in enumerate(orders):
        p = mpf(p) if not isinstance(p, Fraction) else mpq(p)
        for i, x in enumerate(nodes):
            x = mpf(x) if not isinstance(x, Fraction) else mpq(x)
            X[r, i] = (1 - p) * x ** p
            X[r, nu + i] = p * x ** (p - 1) if p != 0 else mpf(0)
    return X


def exact_solve(A, b):
    """Gauss elimination in Fractions (any nonzero pivot is exact); returns (x, det)."""
    n = len(A)
    M = [list(A[r]) + [F(b[r])] for r in range(n)]
    det = Fraction(1)
    for k in range(n):
        piv = next((r for r in range(k, n) if M[r][k] != 0), None)
        check(piv is not None, 'exact matrix singular')
        if piv != k:
            M[k], M[piv] = M[piv], M[k]
            det = -det
        det *= M[k][k]
        inv = 1 / M[k][k]
        for r in range(k + 1, n):
            f = M[r][k] * inv
            if f:
                Mr, Mk = M[r], M[k]
                for c in range(k, n + 1):
                    Mr[c] -= f * Mk[c]
    x = [Fraction(0)] * n
    for k in range(n - 1, -1, -1):
        acc = M[k][n] - sum(M[k][c] * x[c] for c in range(k + 1, n))
        x[k] = acc / M[k][k]
    return x, det


def mp_solve(nodes, orders, s, dps):
    with mp.workdps(dps):
        X = mp_matrix(nodes, orders)
        b = matrix([mpf(v) if not isinstance(v, Fraction) else mpq(v) for v in s])
        x = lu_solve(X, b)
        return [x[i] for i in range(len(s))]


def length_scale(nodes):
    """L = 2^floor(log2(max xi)), the power of two at or below the largest node (exact)"""
    e = int(floor(log(mpf(max(nodes)), 2)))
    return Fraction(2) ** e, e


def conditions(nodes, orders, s):
    """(kappa_inf of the scaled matrix, kappa_inf of the SI matrix, L, the condition of the solution
    with respect to the right-hand side ||(|X~^-1| |s~|)||_inf / ||x~||_inf)"""
    nu = len(nodes)
    L, _ = length_scale(nodes)
    out = []
    for dps in (60, 100):
        with mp.workdps(dps):
            Lm = mpq(L)
            pw = [Lm ** (mpf(p) if not isinstance(p, Fraction) else mpq(p)) for p in orders]
            Xs = mp_matrix([mpf(x) / Lm for x in nodes], orders)
            Xs_inv = inverse(Xs)
            k_scaled = mnorm(Xs, inf) * mnorm(Xs_inv, inf)
            # X = D_r Xs D_c, D_r = diag(L^p), D_c = diag(1 .. 1, 1/L .. 1/L): X^-1 = D_c^-1 Xs^-1 D_r^-1
            X = mp_matrix(nodes, orders)
            Xinv = matrix(2 * nu, 2 * nu)
            for j in range(2 * nu):
                for r in range(2 * nu):
                    Xinv[j, r] = Xs_inv[j, r] * (Lm if j >= nu else 1) / pw[r]
            k_si = mnorm(X, inf) * mnorm(Xinv, inf)
            st = [mpf(v) / pw[r] for r, v in enumerate(s)]
            xt = [sum(Xs_inv[j, r] * st[r] for r in range(2 * nu)) for j in range(2 * nu)]
            at = [sum(fabs(Xs_inv[j, r] * st[r]) for r in range(2 * nu)) for j in range(2 * nu)]
            k_rhs = max(at) / max(fabs(v) for v in xt) if max(at) > 0 else mpf(1)
            out.append((k_scaled, k_si, k_rhs))
    (k1, s1, r1), (k2, s2, r2) = out
    check(fabs(k1 - k2) <= mpf(10) ** -30 * k2, 'scaled condition stable 60 vs 100 digits')
    check(fabs(s1 - s2) <= mpf(10) ** -30 * s2, 'SI condition stable 60 vs 100 digits')
    check(fabs(r1 - r2) <= mpf(10) ** -30 * r2, 'right-hand-side condition stable 60 vs 100 digits')
    check(k2 >= 1 and s2 >= 1 and 1 - mpf(10) ** -40 <= r2 <= k2, '1 <= condition, 1 <= rhs condition <= condition')
    # the SI condition by direct inversion of the SI matrix at 60 + log10(kappa) digits
    with mp.workdps(60 + int(ceil(log(s2, 10)))):
        X = mp_matrix(nodes, orders)
        direct = mnorm(X, inf) * mnorm(inverse(X), inf)
    check(fabs(direct - s2) <= mpf(10) ** -25 * s2, 'SI condition: direct inversion agrees')
    return k2, s2, L, r2


# ----------------------------------------------------------------------------
# right-hand sides (exact Fractions of the doubles involved; rounded to doubles for the file)
# ----------------------------------------------------------------------------
def powq(x, p):
    """x^p for a double x and an order p that is an int/Fraction integer (exact) or a double (mp)"""
    if isinstance(p, int):
        return F(x) ** p
    return mpf(x) ** mpf(p)


def rhs_random(nodes, phi, orders, rng):
    out = []
    for p in orders:
        r = rng.uniform(0.2, 2.0) * rng.choice((-1, 1))
        out.append(Fraction(r) / 1000 * sum(F(f) * powq(x, p) for f, x in zip(phi, nodes))
                   if isinstance(p, int) else
                   mpf(r) / 1000 * sum(mpf(f) * powq(x, p) for f, x in zip(phi, nodes)))
    return out


def rhs_growth_volume(nodes, phi, G, orders):
    """(3 + p) sum phi_i xi_i^(p-1) G_i   (seed 000 eq. 5.63, xi a diameter)"""
    if all(isinstance(p, int) for p in orders):
        return [(3 + p) * sum(F(f) * F(x) ** (p - 1) * F(g) for f, x, g in zip(phi, nodes, G)) for p in orders]
    return [(3 + mpf(p)) * sum(mpf(f) * mpf(x) ** (mpf(p) - 1) * mpf(g) for f, x, g in zip(phi, nodes, G))
            for p in orders]


def rhs_growth_number(nodes, w, G, orders):
    """p sum w_i xi_i^(p-1) G_i   (Marchisio & Fox 2005, number densities)"""
    if all(isinstance(p, int) for p in orders):
        return [p * sum(F(a) * F(x) ** (p - 1) * F(g) for a, x, g in zip(w, nodes, G)) for p in orders]
    return [mpf(p) * sum(mpf(a) * mpf(x) ** (mpf(p) - 1) * mpf(g) for a, x, g in zip(w, nodes, G))
            for p in orders]


def rhs_diffusion(nodes, C, orders):
    """p(p-1) sum xi_i^(p-2) C_i   (seed 000 eqs. 6.18-6.23; integer orders)"""
    return [p * (p - 1) * sum(F(x) ** (p - 2) * F(c) for x, c in zip(nodes, C)) if p >= 2 else Fraction(0)
            for p in orders]


def rhs_points(points, amplitudes, orders):
    """sum_e a_e x_e^p: point sources (births and deaths) at sizes x_e that are not nodes"""
    if all(isinstance(p, int) for p in orders):
        return [sum(F(a) * F(x) ** p for a, x in zip(amplitudes, points)) for p in orders]
    return [sum(mpf(a) * mpf(x) ** mpf(p) for a, x in zip(amplitudes, points)) for p in orders]


# ----------------------------------------------------------------------------
# deterministic inputs
# ----------------------------------------------------------------------------
RNG = random.Random(20170)


def log_uniform(rng, lo, hi):
    u = rng.random()
    return dbl(exp(log(mpf(lo)) + mpf(u) * (log(mpf(hi)) - log(mpf(lo)))))


def node_set(rng, nu, lo=50e-6, hi=500e-6, min_gap=0.03, shuffle=False):
    """nu sizes log-uniform in [lo, hi], rounded to 0.1 um, relative gaps >= min_gap"""
    while True:
        x = sorted(round(log_uniform(rng, lo, hi) * 1e7) / 1e7 for _ in range(nu))
        if all((x[i + 1] - x[i]) / x[i] >= min_gap for i in range(nu - 1)):
            break
    if shuffle:
        rng.shuffle(x)
    return x


def fractions_of(rng, nu):
    return [round(rng.uniform(0.02, 0.2), 4) for _ in range(nu)]


def growth_rates(rng, nu):
    """m/s, mixed signs (growth and attrition)"""
    return [round(rng.uniform(0.1, 2.0), 4) * 1e-7 * rng.choice((-1, 1)) for _ in range(nu)]


def number_densities(phi, nodes):
    """w_i = phi_i / (pi xi_i^3 / 6), 1/m^3 (rounded to double; exact as such)"""
    return [dbl(6 * mpf(f) / (pi * mpf(x) ** 3)) for f, x in zip(phi, nodes)]


def diffusion_coefficients(rng, nu):
    """C_i = D phi_i |grad xi_i|^2 ~ 1e-6 m^2/s * 0.1 * (1e-2)^2 -> 1e-11 m^2/s"""
    return [round(rng.uniform(0.1, 2.0), 4) * 1e-11 for _ in range(nu)]


def point_sources(rng, nodes):
    n_points = 3 + len(nodes) // 2
    pts = []
    while len(pts) < n_points:
        x = round(log_uniform(rng, 40e-6, 600e-6) * 1e7) / 1e7
        if all(abs(x - xi) > 0.01 * xi for xi in nodes) and x not in pts:
            pts.append(x)
    amps = [round(rng.uniform(0.1, 1.0), 4) * 1e-3 * rng.choice((-1, 1)) for _ in pts]
    return pts, amps


SEED_SETS = {
    # seed 000 Tables 6.2/6.4 (powders A and B, the 4-class mixture) and the computed nodes of Table 6.6
    1: [165e-6],
    2: [75e-6, 103e-6],
    3: [75e-6, 103e-6, 240e-6],
    4: [75e-6, 103e-6, 240e-6, 355e-6],
    5: [75e-6, 103e-6, 240e-6, 355e-6, 165e-6],
}
SEED_FRACTIONS = [0.131, 0.169, 0.190, 0.110, 0.05]


# ----------------------------------------------------------------------------
# output
# ----------------------------------------------------------------------------
ROWS = []
STATS = {}


def fmt(x):
    s = repr(float(x))
    check(' ' not in s and ',' not in s and 'nan' not in s and 'inf' not in s, 'plain number')
    return s


def fmt_exact(v):
    """the exact solution to 21 significant digits: strtod gives the double nearest it (a 21-digit
    decimal is closer to the exact value than 1e-20 relative), strtold a long double to 1e-21"""
    with mp.workdps(60):
        x = mpq(v) if isinstance(v, Fraction) else mpf(v)
        s = nstr(x, 21) if x != 0 else '0.0'
        check(dbl(mpf(s)) == (float(v) if isinstance(v, Fraction) else dbl(x)), 'printed value rounds to the double')
    check(' ' not in s and ',' not in s, 'plain number')
    return s


def write_case(case, nodes, orders, s_dbl, ca, cxi, k_scaled, k_si, L, k_rhs, kind):
    nu = len(nodes)
    for k, p in enumerate(orders):
        ROWS.append('%s,%d,order,%d,%s' % (case, nu, k, p if isinstance(p, int) else fmt(p)))
    for i, x in enumerate(nodes):
        ROWS.append('%s,%d,node,%d,%s' % (case, nu, i, fmt(x)))
    for k, v in enumerate(s_dbl):
        ROWS.append('%s,%d,source,%d,%s' % (case, nu, k, fmt(v)))
    for i, v in enumerate(ca):
        ROWS.append('%s,%d,weight,%d,%s' % (case, nu, i, fmt_exact(v)))
    for i, v in enumerate(cxi):
        ROWS.append('%s,%d,weighted_node,%d,%s' % (case, nu, i, fmt_exact(v)))
    ROWS.append('%s,%d,length_scale,0,%s' % (case, nu, fmt(float(L))))
    ROWS.append('%s,%d,condition,0,%s' % (case, nu, nstr(k_scaled, 17)))
    ROWS.append('%s,%d,condition_si,0,%s' % (case, nu, nstr(k_si, 17)))
    ROWS.append('%s,%d,condition_source,0,%s' % (case, nu, nstr(k_rhs, 17)))
    STATS[kind] = STATS.get(kind, 0) + 1


def close_vec(a, b, rtol, msg):
    """norm-wise: max |a - b| <= rtol * max |b|"""
    scale = max(fabs(mpf(v) if not isinstance(v, Fraction) else mpq(v)) for v in b)
    err = max(fabs((mpf(x) if not isinstance(x, Fraction) else mpq(x)) - (mpf(y) if not isinstance(y, Fraction) else mpq(y)))
              for x, y in zip(a, b))
    check(err <= rtol * scale, '%s: %s' % (msg, nstr(err / scale if scale else err, 5)))


def integer_case(case, nodes, s_exact, kind, expect=None):
    """s_exact: exact Fractions.  expect(c) asserts identities on the exact-RHS solution."""
    nu = len(nodes)
    orders = list(range(2 * nu))
    X = exact_matrix(nodes, orders)
    if expect is not None:
        c0, _ = exact_solve(X, s_exact)
        expect(c0[:nu], c0[nu:])
    s_dbl = [float(v) for v in s_exact]
    c, det = exact_solve(X, s_dbl)
    # det X = (-1)^(nu(nu-1)/2) prod_{i<j} (xi_i - xi_j)^4, exactly
    d = Fraction((-1) ** (nu * (nu - 1) // 2))
    for i in range(nu):
        for j in range(i + 1, nu):
            d *= (F(nodes[i]) - F(nodes[j])) ** 4
    check(det == d, '%s: det X closed form' % case)
    # residual exactly zero, and mpmath LU at 60 digits agrees norm-wise to 1e-30
    for r in range(2 * nu):
        check(sum(X[r][j] * c[j] for j in range(2 * nu)) == F(s_dbl[r]), '%s: exact residual' % case)
    cm = mp_solve(nodes, orders, s_dbl, 60)
    L, _ = length_scale(nodes)
    scaled_exact = c[:nu] + [v / L for v in c[nu:]]
    scaled_mp = cm[:nu] + [v / mpq(L) for v in cm[nu:]]
    close_vec(scaled_mp, scaled_exact, mpf(10) ** -30, '%s: mpmath LU vs exact' % case)
    if nu == 1:   # seed 000 eq. D.3: c^a = S_0, c^xi = S_1
        check(c[0] == F(s_dbl[0]) and c[1] == F(s_dbl[1]), '%s: one node D.3' % case)
    if nu == 2:
        two_node_closed_forms(nodes, [F(v) for v in s_dbl], c, case)
    k_scaled, k_si, L, k_rhs = conditions(nodes, orders, s_dbl)
    write_case(case, nodes, orders, s_dbl, c[:nu], c[nu:], k_scaled, k_si, L, k_rhs, kind)
    return c, k_scaled


def fractional_case(case, nodes, orders, s_val, kind, expect=None):
    """orders: doubles (written exactly); s_val: mpf or Fraction values (exact for the doubles)."""
    nu = len(nodes)
    if expect is not None:
        c0 = mp_solve(nodes, orders, s_val, 100)
        expect(c0[:nu], c0[nu:])
    s_dbl = [dbl(v) for v in s_val]
    c = mp_solve(nodes, orders, s_dbl, 100)
    c60 = mp_solve(nodes, orders, s_dbl, 60)
    close_vec(c60, c, mpf(10) ** -35, '%s: 60 vs 100 digits' % case)
    with mp.workdps(100):
        X = mp_matrix(nodes, orders)
        for r in range(2 * nu):
            res = sum(X[r, j] * c[j] for j in range(2 * nu)) - mpf(s_dbl[r])
            size = sum(fabs(X[r, j] * c[j]) for j in range(2 * nu)) + fabs(mpf(s_dbl[r]))
            check(fabs(res) <= mpf(10) ** -90 * size, '%s: residual' % case)
    # the rows may come in any order: sorting the orders (and s with them) gives the same solution
    perm = sorted(range(2 * nu), key=lambda k: orders[k])
    cs = mp_solve(nodes, [orders[k] for k in perm], [s_dbl[k] for k in perm], 100)
    close_vec(cs, c, mpf(10) ** -80, '%s: row order' % case)
    k_scaled, k_si, L, k_rhs = conditions(nodes, orders, s_dbl)
    write_case(case, nodes, orders, s_dbl, c[:nu], c[nu:], k_scaled, k_si, L, k_rhs, kind)
    return c, k_scaled


# ----------------------------------------------------------------------------
# independent closed forms
# ----------------------------------------------------------------------------
def two_node_closed_forms(nodes, S, c, case):
    """seed 000 App. D eqs. D.14-D.17 (valid as printed), exactly."""
    x1, x2 = F(nodes[0]), F(nodes[1])
    d3 = (x1 - x2) ** 3
    c1a = (x2 ** 2 * (3 * x1 - x2) * S[0] - 6 * x1 * x2 * S[1] + 3 * (x1 + x2) * S[2] - 2 * S[3]) / d3
    c2a = (x1 ** 2 * (3 * x2 - x1) * S[0] - 6 * x1 * x2 * S[1] + 3 * (x1 + x2) * S[2] - 2 * S[3]) / -d3
    c1x = (2 * x1 ** 2 * x2 ** 2 * S[0] - x2 * (4 * x1 ** 2 + x1 * x2 + x2 ** 2) * S[1]
           + 2 * (x1 ** 2 + x1 * x2 + x2 ** 2) * S[2] - (x1 + x2) * S[3]) / d3
    c2x = (2 * x1 ** 2 * x2 ** 2 * S[0] - x1 * (4 * x2 ** 2 + x1 * x2 + x1 ** 2) * S[1]
           + 2 * (x1 ** 2 + x1 * x2 + x2 ** 2) * S[2] - (x1 + x2) * S[3]) / -d3
    check([c1a, c2a, c1x, c2x] == [c[0], c[1], c[2], c[3]], '%s: D.14-D.17' % case)
    # D.9: c_2^a = S_0 - c_1^a, c_2^xi = S_1 - c_1^xi
    check(c2a == S[0] - c1a and c2x == S[1] - c1x, '%s: D.9' % case)


def printed_row_misprint():
    """seed 000 eq. D.8 prints the k = 3 row as (-2 xi_1^2, -2 xi_2^2, 3 xi_1^2, 3 xi_2^2); (1 - k) xi^k
    is -2 xi^3.  With the printed row, pure growth no longer gives 3 phi G / xi; with the correct
    row it does, exactly."""
    nodes, phi, G = [75e-6, 103e-6], [0.262, 0.338], [1e-7, 2e-7]
    s = rhs_growth_volume(nodes, phi, G, [0, 1, 2, 3])
    X = exact_matrix(nodes, [0, 1, 2, 3])
    Xp = [list(r) for r in X]
    Xp[3][0], Xp[3][1] = -2 * F(nodes[0]) ** 2, -2 * F(nodes[1]) ** 2
    c, _ = exact_solve(X, s)
    cp, _ = exact_solve(Xp, s)
    want = [3 * F(phi[i]) * F(G[i]) / F(nodes[i]) for i in range(2)]
    check(c[:2] == want, 'D.8 corrected row: pure growth')
    check(all(abs(cp[i] - want[i]) > Fraction(1, 1000) * abs(want[i]) for i in range(2)),
          'D.8 printed row (-2 xi^2) differs from pure growth by > 0.1 %')


def growth_volume_expect(nodes, phi, G, exact=True):
    def expect(ca, cxi):
        for i, (x, f, g) in enumerate(zip(nodes, phi, G)):
            if exact:
                check(ca[i] == 3 * F(f) * F(g) / F(x), 'pure growth c^a = 3 phi G / xi (exact)')
                check(cxi[i] == 4 * F(f) * F(g), 'pure growth c^xi = 4 phi G (exact)')
            else:
                a, b = 3 * mpf(f) * mpf(g) / mpf(x), 4 * mpf(f) * mpf(g)
                check(fabs(ca[i] - a) <= mpf(10) ** -80 * fabs(a), 'pure growth c^a (100 digits)')
                check(fabs(cxi[i] - b) <= mpf(10) ** -80 * fabs(b), 'pure growth c^xi (100 digits)')
    return expect


def growth_number_expect(nodes, w, G, exact=True):
    def expect(ca, cxi):
        for i, (a, g) in enumerate(zip(w, G)):
            if exact:
                check(ca[i] == 0 and cxi[i] == F(a) * F(g), 'number form: c^a = 0, c^xi = w G (exact)')
            else:
                b = mpf(a) * mpf(g)
                check(fabs(ca[i]) <= mpf(10) ** -80 * fabs(b) / mpf(nodes[i]), 'number form c^a = 0 (100 digits)')
                check(fabs(cxi[i] - b) <= mpf(10) ** -80 * fabs(b), 'number form c^xi = w G (100 digits)')
    return expect


def diffusion_expect(nodes, C):
    def expect(ca, cxi):
        if len(nodes) != 2:
            return
        for i, j in ((0, 1), (1, 0)):   # seed 000 eq. 6.22
            xi, xj, Ci, Cj = F(nodes[i]), F(nodes[j]), F(C[i]), F(C[j])
            check(ca[i] == 6 * (Cj - Ci) / (xi - xj) ** 2, 'eq. 6.22 c^a')
            check(cxi[i] == (2 * Cj * (xj + 2 * xi) - 2 * Ci * (xi + 2 * xj)) / (xi - xj) ** 2, 'eq. 6.22 c^xi')
    return expect


# ----------------------------------------------------------------------------
# cases
# ----------------------------------------------------------------------------
def integer_cases_for(tag, nodes, phi, rng, kinds=('random', 'growth_volume', 'growth_number', 'diffusion', 'points')):
    nu = len(nodes)
    orders = list(range(2 * nu))
    out = {}
    for kind in kinds:
        case = 'n%d_%s_%s' % (nu, tag, kind)
        if kind == 'random':
            s = rhs_random(nodes, phi, orders, rng)
            out[kind] = integer_case(case, nodes, s, 'integer/random')
        elif kind == 'growth_volume':
            G = growth_rates(rng, nu)
            s = rhs_growth_volume(nodes, phi, G, orders)
            out[kind] = integer_case(case, nodes, s, 'integer/growth_volume', growth_volume_expect(nodes, phi, G))
        elif kind == 'growth_number':
            G = growth_rates(rng, nu)
            w = number_densities(phi, nodes)
            s = rhs_growth_number(nodes, w, G, orders)
            out[kind] = integer_case(case, nodes, s, 'integer/growth_number', growth_number_expect(nodes, w, G))
        elif kind == 'diffusion':
            if nu == 1:
                continue   # s = 0: nothing to solve
            C = diffusion_coefficients(rng, nu)
            s = rhs_diffusion(nodes, C, orders)
            out[kind] = integer_case(case, nodes, s, 'integer/diffusion', diffusion_expect(nodes, C))
        elif kind == 'points':
            pts, amps = point_sources(rng, nodes)
            s = rhs_points(pts, amps, orders)
            out[kind] = integer_case(case, nodes, s, 'integer/points')
    return out


def main():
    printed_row_misprint()
    rng = RNG
    kappa = {}
    # 1. integer orders, nu = 1..8: two log-uniform node sets (the second shuffled), the seed sets
    for nu in range(1, 9):
        for tag, shuffle in (('a', False), ('b', True)):
            nodes = node_set(rng, nu, shuffle=shuffle)
            res = integer_cases_for(tag, nodes, fractions_of(rng, nu), rng)
            kappa.setdefault(nu, []).extend(v[1] for v in res.values())
        if nu in SEED_SETS:
            res = integer_cases_for('seed', SEED_SETS[nu], SEED_FRACTIONS[:nu], rng)
            kappa[nu].extend(v[1] for v in res.values())
    # 1e. two nodes close together: relative gaps 1e-2, 1e-3, 1e-4 (the same other nodes)
    for nu in (2, 3, 4, 8):
        base = node_set(rng, nu, min_gap=0.05)
        phi = fractions_of(rng, nu)
        for gap in ((1e-2, 1e-3, 1e-4) if nu < 8 else (1e-2,)):
            nodes = list(base)
            nodes[1] = base[0] * (1 + gap)
            tag = 'gap%s' % ('%.0e' % gap).replace('-0', 'm')
            res = integer_cases_for(tag, nodes, phi, rng, kinds=('random', 'growth_volume'))
            kappa[(nu, gap)] = res['random'][1]
    # kappa grows like gap^-3, the (xi_1 - xi_2)^3 of seed 000 eqs. D.14-D.17
    for nu in (2, 3, 4):
        for g in (1e-2, 1e-3):
            ratio = kappa[(nu, g / 10)] / kappa[(nu, g)]
            check(900 < ratio < 1100, 'close nodes: kappa ~ gap^-3 (nu = %d, ratio %s)' % (nu, nstr(ratio, 5)))
    # 2. fractional orders, nu = 1..4. Orders 0 and 1 are listed first (they carry the weights and
    # the weighted nodes; the library's contract); the others follow descending (thirds) or
    # ascending (halves). The row order does not change the solution (asserted per case).
    thirds = [Fraction(1, 3), Fraction(2, 3), Fraction(4, 3), Fraction(5, 3), Fraction(2), Fraction(7, 3)]
    halves = [0.5, 1.5, 2.0, 2.5, 3.0, 3.5]
    with mp.workdps(100):   # right-hand sides of irrational powers at 100 digits
        for nu in range(1, 5):
            for oname, oset in (('thirds', thirds), ('halves', halves)):
                rest = [float(p) for p in oset[:2 * nu - 2]]
                orders = [0.0, 1.0] + (rest[::-1] if oname == 'thirds' else rest)
                check(0.0 in orders and 1.0 in orders and len(set(orders)) == 2 * nu, 'orders include 0 and 1, distinct')
                if oname == 'thirds' and nu in SEED_SETS:
                    nodes, phi = SEED_SETS[nu][::-1], SEED_FRACTIONS[:nu][::-1]
                else:
                    nodes, phi = node_set(rng, nu), fractions_of(rng, nu)
                base = 'f%d_%s' % (nu, oname)
                s = rhs_random(nodes, phi, orders, rng)
                fractional_case(base + '_random', nodes, orders, s, 'fractional/random')
                G = growth_rates(rng, nu)
                s = rhs_growth_volume(nodes, phi, G, orders)
                fractional_case(base + '_growth_volume', nodes, orders, s, 'fractional/growth_volume',
                                growth_volume_expect(nodes, phi, G, exact=False))
                G = growth_rates(rng, nu)
                w = number_densities(phi, nodes)
                s = rhs_growth_number(nodes, w, G, orders)
                fractional_case(base + '_growth_number', nodes, orders, s, 'fractional/growth_number',
                                growth_number_expect(nodes, w, G, exact=False))
                pts, amps = point_sources(rng, nodes)
                fractional_case(base + '_points', nodes, orders, rhs_points(pts, amps, orders), 'fractional/points')
    # integer orders {0..2nu-1} as doubles through the real-order path give the exact solution
    nodes = SEED_SETS[3]
    s = [float(v) for v in rhs_random(nodes, SEED_FRACTIONS[:3], list(range(6)), random.Random(1))]
    c, _ = exact_solve(exact_matrix(nodes, range(6)), s)
    with mp.workdps(100):
        close_vec(mp_solve(nodes, [float(p) for p in range(6)], s, 100), c, mpf(10) ** -90, 'real-order path = exact')

    path = os.path.join(HERE, 'dqmom_reference.csv')
    with open(path, 'w', newline='\n') as f:
        f.write('case,nu,quantity,index,value\n')
        for r in ROWS:
            f.write(r + '\n')
    n_int = sum(v for k, v in STATS.items() if k.startswith('integer'))
    n_frac = sum(v for k, v in STATS.items() if k.startswith('fractional'))
    print('dqmom_reference.csv: %d rows, %d integer-order and %d fractional-order cases; %d checks passed'
          % (len(ROWS), n_int, n_frac, N_CHECKS[0]))


if __name__ == '__main__':
    main()
