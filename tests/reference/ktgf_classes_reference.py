#!/usr/bin/python3
"""Independent high-precision reference generator for the multi-class kinetic theory of
granular flow with unequal granular temperatures (Lathouwers & Bellan 2001, Int. J.
Multiphase Flow 27, 2155-2187; seed 004's "Constitutive
particle-phase equations" and "Granular pressure and transport coefficients" slides).

Writes (next to this file):
  ktgf_classes_reference.csv   long format, one row per (case, quantity, i, k):
      case,rdf,max_packing,restitution,n_classes,a0..a3,d0..d3,rho0..rho3,theta0..theta3,
      quantity,i,k,value,d_a0..d_a3,d_theta0..d_theta3

Formulas, conventions and the checks: README.md (same folder, section "Multi-class KTGF").
mpmath, 40 digits; inputs are exact decimal strings; output nstr(x, 17).  Every partial
derivative is mpmath.diff of the value function (never by hand).  Before writing anything the
script asserts the source review's numbers for seed 004 (monodisperse reduction and binary
sand/biomass example, 6 significant figures), the one-class reductions to Lun, Gidaspow and
Carnahan-Starling, energy conservation at e = 1, the symmetries, that seed 004's printed
h_ik differs from the corrected one, and that the pair energy sink equals the Maxwellian
(Enskog) cooling rate of a granular mixture (Garzo & Dufty 1999) both in closed form and by
quadrature of the collision integral.  It never reads the C++ code under include/.

Run with Debian's python:  /usr/bin/python3 ktgf_classes_reference.py   (prints one line)
"""
import os
import random
import sys

sys.dont_write_bytecode = True  # keep the folder free of __pycache__

from mpmath import mp, mpf, sqrt, pi, nstr, diff, exp, quad, inf  # noqa: E402

mp.dps = 40
# The decimal input, output and checking helpers of the one-class generator (never re-typed).
from ktgf_reference import M, out, chk, differs, NCHK  # noqa: E402
HERE = os.path.dirname(os.path.abspath(__file__))
NMAX = 4  # class columns in the file


def same(x, y, what, rel='1e-30', scale=None):
    """identity check to `rel` relative to max(|x|, |y|), or to `scale` where the two sides are
    a cancellation (then `scale` is the size of the cancelling terms)"""
    if scale is None:
        scale = max(abs(x), abs(y))
    assert abs(x - y) <= M(rel) * scale, '%s: %s vs %s' % (what, nstr(x, 20), nstr(y, 20))
    NCHK[0] += 1


# ============================================================================
# The model.  A case fixes the diameters d, envelope densities rho, restitution e and the RDF;
# the state is (a, Theta) (volume fractions and granular temperatures of the classes).
# ============================================================================
class Case:
    def __init__(self, name, rdf, amax, e, a, d, rho, theta):
        assert rdf in ('ModifiedMansoori', 'Mansoori')
        assert len(a) == len(d) == len(rho) == len(theta) <= NMAX
        self.name, self.rdf = name, rdf
        self.amax_s = amax if rdf == 'ModifiedMansoori' else '1'
        self.e_s, self.a_s, self.d_s, self.rho_s, self.theta_s = e, a, d, rho, theta
        self.amax, self.e = M(self.amax_s), M(e)
        self.a, self.T = [M(x) for x in a], [M(x) for x in theta]
        self.d, self.rho = [M(x) for x in d], [M(x) for x in rho]
        self.N = len(a)
        self.vol = [pi * x ** 3 / 6 for x in self.d]  # particle (envelope) volume
        self.m = [r * v for r, v in zip(self.rho, self.vol)]
        # no state in the file needs a continuation of h beyond packing (rule R of ktgf_reference)
        assert sum(self.a) < self.amax - M('0.01')

    def with_e(self, e):
        return Case(self.name, self.rdf, self.amax_s, e, self.a_s, self.d_s, self.rho_s, self.theta_s)

    # --- ingredients -----------------------------------------------------------------
    def n(self, a, i):
        return a[i] / self.vol[i]

    def Mk(self, i, k):
        """M_k of the pair (i, k) = m_k/(m_i + m_k)"""
        return self.m[k] / (self.m[i] + self.m[k])

    def sigma(self, i, k):
        """contact distance = sum of radii"""
        return (self.d[i] + self.d[k]) / 2

    def h(self, a, i, k):
        """Mansoori et al. (1971) mixture contact value with the packing ratio x = a_t/a_max
        (seed 004's h_ik, third term corrected to 2 D^2 xi^2/(1-x)^3)"""
        x = sum(a) / self.amax
        xi = sum(a[m] / self.d[m] for m in range(self.N))
        D = self.d[i] * self.d[k] / (self.d[i] + self.d[k])
        return 1 / (1 - x) + 3 * D * xi / (1 - x) ** 2 + 2 * D ** 2 * xi ** 2 / (1 - x) ** 3

    def base(self, a, i, k):
        """n_i n_k m_i M_k (1+e) h_ik"""
        return self.n(a, i) * self.n(a, k) * self.m[i] * self.Mk(i, k) * (1 + self.e) * self.h(a, i, k)

    # --- pair quantities (i, k) ----------------------------------------------------------
    def F(self, a, T, i, k):
        return self.base(a, i, k) * self.sigma(i, k) ** 2

    def p_pair(self, a, T, i, k):
        return pi / 3 * self.base(a, i, k) * self.sigma(i, k) ** 3 * (T[i] + T[k])

    def mu_own(self, a, T, i, k):
        return (sqrt(2 * pi) / 15 * self.n(a, i) * self.n(a, k) * self.m[i] * self.Mk(i, k) ** 2 * (1 + self.e)
                * self.h(a, i, k) * self.sigma(i, k) ** 4 * (T[i] + T[k]) ** M('1.5') / T[i])

    def mu_partner(self, a, T, i, k):
        return (sqrt(2 * pi) / 15 * self.n(a, i) * self.n(a, k) * self.m[k] * self.Mk(k, i) ** 2 * (1 + self.e)
                * self.h(a, i, k) * self.sigma(i, k) ** 4 * (T[i] + T[k]) ** M('1.5') / T[k])

    def kappa_common(self, a, T, i, k):
        return sqrt(2 * pi) / 3 * self.base(a, i, k) * self.sigma(i, k) ** 4 * sqrt(T[i] + T[k])

    def kappa_own(self, a, T, i, k):
        return self.kappa_common(a, T, i, k) * self.Mk(i, k) * T[k] / T[i]

    def kappa_partner(self, a, T, i, k):
        return self.kappa_common(a, T, i, k) * self.Mk(k, i) * T[i] / T[k]

    def sink_pair(self, a, T, i, k):
        """-gamma_ik of seed 004 (positive = loss of class i's fluctuating energy)"""
        Mi, Mk, s = self.Mk(k, i), self.Mk(i, k), T[i] + T[k]
        return 2 * sqrt(2 * pi) * self.F(a, T, i, k) * sqrt(s) * (2 * (Mi * T[i] - Mk * T[k]) + Mk * (1 - self.e) * s)

    def drag(self, a, T, i, k):
        return self.F(a, T, i, k) * M(4) / 3 * sqrt(2 * pi) * sqrt(T[i] + T[k])

    def segregation(self, a, T, i, k):
        return pi / 3 * self.F(a, T, i, k) * self.sigma(i, k) * (T[i] + T[k])

    # --- per class and matrices ---------------------------------------------------------
    def pressure(self, a, T, i):
        return self.n(a, i) * self.m[i] * T[i] + sum(self.p_pair(a, T, i, k) for k in range(self.N))

    def sink(self, a, T, i):
        return sum(self.sink_pair(a, T, i, k) for k in range(self.N))

    def viscosity(self, a, T, i, j):
        own = sum(self.mu_own(a, T, i, k) for k in range(self.N)) if i == j else 0
        return own + self.mu_partner(a, T, i, j)

    def conductivity(self, a, T, i, j):
        own = sum(self.kappa_own(a, T, i, k) for k in range(self.N)) if i == j else 0
        return own + self.kappa_partner(a, T, i, j)

    def quantities(self):
        """(name, function(a, T, i, k), kind) in file order"""
        pair = [('radial_distribution', lambda a, T, i, k: self.h(a, i, k)),
                ('contact_factor', self.F), ('pair_pressure', self.p_pair),
                ('pair_viscosity_own', self.mu_own), ('pair_viscosity_partner', self.mu_partner),
                ('pair_conductivity_own', self.kappa_own), ('pair_conductivity_partner', self.kappa_partner),
                ('pair_energy_sink', self.sink_pair), ('drag_coefficient', self.drag),
                ('segregation_coefficient', self.segregation)]
        res = [(nm, f, 'pair') for nm, f in pair]
        res += [('pressure', lambda a, T, i, k: self.pressure(a, T, i), 'class'),
                ('energy_sink', lambda a, T, i, k: self.sink(a, T, i), 'class'),
                ('viscosity', self.viscosity, 'pair'), ('conductivity', self.conductivity, 'pair')]
        return res


# ============================================================================
# Cases
# ============================================================================
D5, RHO, E9 = '0.0005', '2500', '0.9'
FIXED = [
    # seed 004 monodisperse reduction (source review sec. 3.6): eps 0.30 and 0.55
    Case('mono_030', 'ModifiedMansoori', '0.64', E9, ['0.30'], [D5], [RHO], ['0.01']),
    Case('mono_055', 'ModifiedMansoori', '0.64', E9, ['0.55'], [D5], [RHO], ['0.01']),
    # seed 004 binary sand (0) / biomass (1) example: equal sizes, then biomass 1 mm
    Case('sand_biomass', 'ModifiedMansoori', '0.64', E9, ['0.30', '0.15'], [D5, D5], [RHO, '500'],
         ['0.01', '0.02']),
    Case('sand_biomass_unequal', 'ModifiedMansoori', '0.64', E9, ['0.30', '0.15'], [D5, '0.001'], [RHO, '500'],
         ['0.01', '0.02']),
    # one class split into two identical classes (must reproduce mono_030)
    Case('mono_030_split', 'ModifiedMansoori', '0.64', E9, ['0.1', '0.2'], [D5, D5], [RHO, RHO],
         ['0.01', '0.01']),
    # elastic binary with unequal temperatures (energy exchange without loss)
    Case('elastic_binary', 'ModifiedMansoori', '0.63', '1', ['0.25', '0.2'], ['0.0002', '0.0011'],
         ['2500', '7800'], ['0.003', '0.04']),
    # Mansoori (a_max = 1)
    Case('mansoori_mono', 'Mansoori', '1', E9, ['0.30'], [D5], [RHO], ['0.01']),
    Case('mansoori_binary', 'Mansoori', '1', '0.95', ['0.2', '0.1'], ['0.0001', '0.0003'], ['2500', '1500'],
         ['0.001', '0.05']),
    Case('mansoori_ternary', 'Mansoori', '1', '0.8', ['0.05', '0.15', '0.25'], ['0.00005', '0.0004', '0.002'],
         ['8000', '900', '2650'], ['0.7', '0.0002', '0.00003']),
]


def random_cases():
    """deterministic random cases: d log-uniform 50 um - 2 mm, rho 500 - 8000, total fraction
    0.05 - 0.58, Theta 1e-5 - 1 over decades, e 0.7 - 1; all inputs short decimal strings"""
    rng = random.Random(20240611)
    cases = []
    for N in (2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4):
        amax = rng.choice(['0.63', '0.64'])
        total = rng.randint(50, 580)  # thousandths
        w = [rng.randint(1, 100) for _ in range(N)]
        parts = [max(1, total * x // sum(w)) for x in w]
        a = ['0.%03d' % q for q in parts]
        d = ['%de-6' % int(50 * 40 ** rng.random()) for _ in range(N)]  # 50 um .. 2 mm, log-uniform
        rho = [str(rng.randint(5, 80) * 100) for _ in range(N)]
        theta = ['%de-%d' % (rng.randint(1, 9), rng.randint(1, 5)) for _ in range(N)]  # 1e-5 .. 0.9
        e = '%.2f' % (rng.randint(70, 100) / 100)
        cases.append(Case('random_%d_%02d' % (N, len(cases) + 1), 'ModifiedMansoori', amax, e, a, d, rho, theta))
    return cases


# ============================================================================
# Independent physics: the Maxwellian (Enskog) energy production of a granular mixture
# ============================================================================
def zeta_garzo_dufty(c, i, j, Tref, mref):
    """partial cooling rate zeta_ij of species i due to j, Maxwellian (leading Sonine)
    approximation of Garzo & Dufty, Phys. Rev. E 60, 5706 (1999), in the reduced variables of
    Garzo, Hrenya & Dufty, Phys. Rev. E 76, 031303 (2007) as MFiX model/GhdTheory/ghd.f writes it:
      zeta_ij = (8/3) sqrt(pi) v0 n_j mu_ji chi_ij sigma_ij^2 (1+alpha) sqrt((th_i+th_j)/(th_i th_j))
                * [1 - (mu_ji/2)(1+alpha)(th_i+th_j)/th_j],
    th_i = m_i T/(mbar T_i), v0 = sqrt(2T/mbar), T_i = m_i Theta_i (energy per particle), for an
    arbitrary reference temperature T and mass mbar (the result does not depend on them)."""
    Ti, Tj = c.m[i] * c.T[i], c.m[j] * c.T[j]
    thi, thj = c.m[i] * Tref / (mref * Ti), c.m[j] * Tref / (mref * Tj)
    v0 = sqrt(2 * Tref / mref)
    mu_ji = c.m[j] / (c.m[i] + c.m[j])
    al = c.e
    return (M(8) / 3 * sqrt(pi) * v0 * c.n(c.a, j) * mu_ji * c.h(c.a, i, j) * c.sigma(i, j) ** 2 * (1 + al)
            * sqrt((thi + thj) / (thi * thj)) * (1 - mu_ji / 2 * (1 + al) * (thi + thj) / thj))


def sink_by_quadrature(c, i, j):
    """loss rate of (3/2) n_i m_i Theta_i by i-j collisions of smooth inelastic spheres, Enskog
    collision integral for two Maxwellians (zero mean velocities, variances Theta_i, Theta_j per
    component), evaluated by quadrature.  For relative velocity g and contact normal k with
    g.k > 0 the post-collision velocity is c_i' = c_i - M_j (1+e)(g.k) k; the integrand is linear
    in c_i once g is fixed, and E[c_i | g] = Theta_i g/(Theta_i + Theta_j) exactly (Gaussians),
    so it remains a 2-D integral over |g| and the cosine between g and k."""
    s = c.T[i] + c.T[j]
    Mj, e, mi = c.Mk(i, j), c.e, c.m[i]

    # g = sqrt(s) u: the quadrature runs in the dimensionless speed u
    def phi(u):  # Maxwellian of the relative velocity, per unit u^3
        return (2 * pi) ** M('-1.5') * exp(-u ** 2 / 2)

    def gain(u, mu):  # energy change of i in one collision, averaged over c_i given g
        gk = sqrt(s) * u * mu
        return mi / 2 * (-2 * Mj * (1 + e) * gk * (c.T[i] / s) * gk + Mj ** 2 * (1 + e) ** 2 * gk ** 2)

    val = quad(lambda u, mu: 4 * pi * u ** 2 * phi(u) * 2 * pi * sqrt(s) * u * mu * gain(u, mu), [0, inf], [0, 1])
    return -c.h(c.a, i, j) * c.n(c.a, i) * c.n(c.a, j) * c.sigma(i, j) ** 2 * val


def drag_by_quadrature(c, i, j):
    """linear response of the i-j momentum exchange to the mean relative velocity w = u_i - u_j:
    the momentum gain of i per unit volume, -chi n_i n_j sigma^2 m_i M_j (1+e) (pi/2) <|g| g_w>,
    with g Maxwellian about w; the drag coefficient is minus its derivative at w = 0 (mpmath.diff
    of the quadrature)."""
    s = c.T[i] + c.T[j]

    def rate(w):  # w in units of sqrt(s); g = sqrt(s) u at angle acos(mu) to w
        def f(u, mu):  # |u - w|^2 = u^2 + w^2 - 2 u w mu; integrand |g| (g . w/|w|)
            return 2 * pi * u ** 2 * (2 * pi) ** M('-1.5') * exp(-(u * u + w * w - 2 * u * w * mu) / 2) * s * u * u * mu
        return (-c.h(c.a, i, j) * c.n(c.a, i) * c.n(c.a, j) * c.sigma(i, j) ** 2 * c.m[i] * c.Mk(i, j) * (1 + c.e)
                * pi / 2 * quad(f, [0, inf], [-1, 1]))
    return -diff(rate, 0) / sqrt(s)


# ============================================================================
# Checks
# ============================================================================
def check_seed004(cases):
    c = {x.name: x for x in cases}
    # --- source review sec. 3.6: monodisperse reduction, h = LB with a_max 0.64
    table = {'mono_030': ('3.77695', '7.5', '32.2929', '0.0364387', '0.0607311', '0.0910967', '-2186.32', '3.08375e6'),
             'mono_055': ('103.218', '13.75', '2966.23', '3.34704', '5.57839', '8.36759', '-200822', '2.83254e8')}
    for nm, (h, nmT, p, mu, lam, kap, gam, F) in table.items():
        x = c[nm]
        a, T = x.a, x.T
        chk(x.h(a, 0, 0), h, what=nm + ' h')
        chk(x.n(a, 0) * x.m[0] * T[0], nmT, what=nm + ' n m Theta')
        chk(x.p_pair(a, T, 0, 0), p, what=nm + ' p_ii')
        chk(x.viscosity(a, T, 0, 0), mu, what=nm + ' mu')
        chk(M(5) / 3 * x.viscosity(a, T, 0, 0), lam, what=nm + ' lambda')
        chk(x.conductivity(a, T, 0, 0), kap, what=nm + ' kappa')
        chk(-x.sink(a, T, 0), gam, what=nm + ' gamma')
        chk(x.F(a, T, 0, 0), F, what=nm + ' F')
    # --- sec. 3.7: binary sand (0) / biomass (1)
    x = c['sand_biomass']
    a, T = x.a, x.T
    chk(x.n(a, 0), '4.58366e9', what='n_s')
    chk(x.n(a, 1), '2.29183e9', what='n_b')
    for i in range(2):
        for k in range(2):
            chk(x.h(a, i, k), '14.8968', what='3.7 h')
    rows = {(0, 0): ('1.21627e7', '127.368', '0.0718596', '0.0718596', '0.179649', '0.179649', '-8623.15', '5.74877e6'),
            (0, 1): ('2.02712e6', '31.8420', '0.00733414', '0.0183353', '0.0244471', '0.0305589', '-18482.0',
                     '1.17346e6')}
    for (i, k), v in rows.items():
        got = (x.F(a, T, i, k), x.p_pair(a, T, i, k), x.mu_own(a, T, i, k), x.mu_partner(a, T, i, k),
               x.kappa_own(a, T, i, k), x.kappa_partner(a, T, i, k), -x.sink_pair(a, T, i, k), x.drag(a, T, i, k))
        for g, ref, nm in zip(got, v, ('F', 'p', 'mu_own', 'mu_partner', 'kappa_own', 'kappa_partner', 'gamma',
                                       'drag')):
            chk(g, ref, what='3.7 %s (%d,%d)' % (nm, i, k))
    x = c['sand_biomass_unequal']
    for (i, k), v in {(0, 0): '12.4380', (0, 1): '16.6555', (1, 0): '16.6555', (1, 1): '26.8821'}.items():
        chk(x.h(x.a, i, k), v, what='3.7 unequal h')
    # --- seed 004's h_ik as printed, in radii: third term 8 r^2 xi/(1-x)^2 (dimensionally wrong);
    #     the corrected radius form equals the D, xi form used here
    for x in cases:
        a, N = x.a, x.N
        xt = sum(a) / x.amax
        xi_r = 2 * pi / 3 * sum(x.n(a, m) * (x.d[m] / 2) ** 2 for m in range(N))
        for i in range(N):
            for k in range(N):
                r = (x.d[i] / 2) * (x.d[k] / 2) / (x.d[i] / 2 + x.d[k] / 2)
                corrected = 1 / (1 - xt) + 6 * r * xi_r / (1 - xt) ** 2 + 8 * r ** 2 * xi_r ** 2 / (1 - xt) ** 3
                printed = 1 / (1 - xt) + 6 * r * xi_r / (1 - xt) ** 2 + 8 * r ** 2 * xi_r / (1 - xt) ** 2
                same(corrected, x.h(a, i, k), 'h radius form')
                differs(printed, corrected, 'printed h_ik')


def check_reductions(cases):
    """one class: Lun pressure, Gidaspow collisional viscosity and conductivity, Lun dissipation,
    the monodisperse LB / Carnahan-Starling RDF; also on a grid of states"""
    extra = [Case('grid', 'ModifiedMansoori', pm, e, [p], [d], [r], [t])
             for pm in ('0.63', '0.64') for e in ('0.7', '0.9', '1') for p in ('0.01', '0.3', '0.55')
             for d, r in (('0.0001', '900'), ('0.002', '7800')) for t in ('1e-5', '0.01', '1')]
    extra += [Case('grid', 'Mansoori', '1', '0.8', [p], ['0.0003'], ['2500'], ['0.1']) for p in ('0.01', '0.3', '0.55')]
    for x in [c for c in cases if c.N == 1] + extra:
        a, T = x.a, x.T
        p, t, e, d, r = a[0], T[0], x.e, x.d[0], x.rho[0]
        xx = 1 - p / x.amax
        same(x.h(a, 0, 0), 1 / xx + M('1.5') * p / xx ** 2 + M('0.5') * p ** 2 / xx ** 3, 'mono h')
        if x.rdf == 'Mansoori':
            same(x.h(a, 0, 0), (1 - p / 2) / (1 - p) ** 3, 'Mansoori = Carnahan-Starling')
        g = x.h(a, 0, 0)
        same(x.p_pair(a, T, 0, 0), 2 * r * (1 + e) * p ** 2 * g * t, 'Lun pressure')
        same(x.pressure(a, T, 0), p * r * t + 2 * r * (1 + e) * p ** 2 * g * t, 'Lun pressure total')
        same(x.viscosity(a, T, 0, 0), M('0.8') * p ** 2 * r * d * g * (1 + e) * sqrt(t / pi), 'Gidaspow mu_col')
        same(x.conductivity(a, T, 0, 0), 2 * p ** 2 * r * d * g * (1 + e) * sqrt(t / pi), 'Gidaspow kappa_col')
        same(x.sink(a, T, 0), 12 * (1 - e ** 2) * g * p ** 2 * r * t ** M('1.5') / (d * sqrt(pi)), 'Lun dissipation',
             scale=x.F(a, T, 0, 0) * t ** M('1.5'))
    # splitting one class into two identical classes changes no mixture total
    c = {x.name: x for x in cases}
    one, two = c['mono_030'], c['mono_030_split']
    for f in (one.p_pair, one.sink_pair, one.F, one.drag):
        g = getattr(two, f.__name__)
        same(sum(g(two.a, two.T, i, k) for i in range(2) for k in range(2)), f(one.a, one.T, 0, 0),
             'split ' + f.__name__)
    for i in range(2):
        same(two.h(two.a, i, 1 - i), one.h(one.a, 0, 0), 'split h')
    same(sum(two.pressure(two.a, two.T, i) for i in range(2)), one.pressure(one.a, one.T, 0), 'split pressure')
    same(sum(two.viscosity(two.a, two.T, i, j) for i in range(2) for j in range(2)), one.viscosity(one.a, one.T, 0, 0),
         'split viscosity')
    same(sum(two.conductivity(two.a, two.T, i, j) for i in range(2) for j in range(2)),
         one.conductivity(one.a, one.T, 0, 0), 'split conductivity')


def check_identities(x):
    """symmetries, energy balance, segregation = pair pressure, Garzo-Dufty, GHD pressure"""
    a, T, N, e = x.a, x.T, x.N, x.e
    for i in range(N):
        for k in range(N):
            for f in (x.F, x.p_pair, x.drag, x.segregation):
                same(f(a, T, i, k), f(a, T, k, i), 'symmetry ' + f.__name__)
            same(x.h(a, i, k), x.h(a, k, i), 'symmetry h')
            same(x.segregation(a, T, i, k), x.p_pair(a, T, i, k), 'segregation = p_ik')
            # the pair's net loss is the dissipation, 2 sqrt(2 pi) F (1-e)(Theta_i+Theta_k)^(3/2)
            s = T[i] + T[k]
            terms = x.F(a, T, i, k) * s ** M('1.5')  # size of the terms that cancel at e = 1
            same(x.sink_pair(a, T, i, k) + x.sink_pair(a, T, k, i),
                 2 * sqrt(2 * pi) * x.F(a, T, i, k) * (1 - e) * s ** M('1.5'), 'pair dissipation', scale=terms)
            # Garzo & Dufty (1999): sink_ik = (3/2) n_i T_i zeta_ik, T_i = m_i Theta_i;
            # two different reference temperatures and masses
            for Tref, mref in ((sum(x.n(a, m) * x.m[m] * T[m] for m in range(N)) / sum(x.n(a, m) for m in range(N)),
                                sum(x.m) / N), (M('1e-7'), M('3.3e-9'))):
                gd = M(3) / 2 * x.n(a, i) * x.m[i] * T[i] * zeta_garzo_dufty(x, i, k, Tref, mref)
                same(x.sink_pair(a, T, i, k), gd, 'Garzo-Dufty', scale=terms)
    # energy conservation at e = 1, unequal temperatures: sum_i energy_sink_i = 0
    y = x.with_e('1')
    tot = sum(y.sink(a, T, i) for i in range(N))
    scale = sum(abs(y.sink_pair(a, T, i, k)) for i in range(N) for k in range(N)) + 1
    assert abs(tot) <= M('1e-35') * scale, 'energy conservation'
    NCHK[0] += 1
    # Garzo, Hrenya & Dufty (2007) collisional pressure, as MFiX model/GhdTheory/pressure.f:
    # p = n T + (2 pi/3) sum_ij mu_ji (1+alpha) sigma_ij^3 chi_ij n_i n_j T_i,  n T = sum n_i T_i
    ghd = sum(x.n(a, i) * x.m[i] * T[i] for i in range(N)) + 2 * pi / 3 * sum(
        x.Mk(i, j) * (1 + e) * x.sigma(i, j) ** 3 * x.h(a, i, j) * x.n(a, i) * x.n(a, j) * x.m[i] * T[i]
        for i in range(N) for j in range(N))
    same(sum(x.pressure(a, T, i) for i in range(N)), ghd, 'GHD total pressure')


def check_quadrature(x):
    """at 25 digits (the 2-D quadratures dominate the run time)"""
    with mp.workdps(25):
        for i in range(x.N):
            for k in range(x.N):
                same(sink_by_quadrature(x, i, k), x.sink_pair(x.a, x.T, i, k), 'sink by quadrature', rel='1e-20',
                     scale=x.F(x.a, x.T, i, k) * (x.T[i] + x.T[k]) ** M('1.5'))


# ============================================================================
# Rows
# ============================================================================
HEADER = ('case,rdf,max_packing,restitution,n_classes,a0,a1,a2,a3,d0,d1,d2,d3,rho0,rho1,rho2,rho3,'
          'theta0,theta1,theta2,theta3,quantity,i,k,value,d_a0,d_a1,d_a2,d_a3,d_theta0,d_theta1,d_theta2,d_theta3')


def pad(v):
    return v + ['0'] * (NMAX - len(v))


def case_rows(x):
    prefix = [x.name, x.rdf, x.amax_s, x.e_s, str(x.N)] + pad(x.a_s) + pad(x.d_s) + pad(x.rho_s) + pad(x.theta_s)
    rows = []
    for name, f, kind in x.quantities():
        idx = [(i, k) for i in range(x.N) for k in range(x.N)] if kind == 'pair' else [(i, -1) for i in range(x.N)]
        for i, k in idx:
            v = f(x.a, x.T, i, k)
            ders = []
            for m in range(x.N):
                ders.append(diff(lambda t: f([t if j == m else x.a[j] for j in range(x.N)], x.T, i, k), x.a[m]))
            ders += [mpf(0)] * (NMAX - x.N)
            for m in range(x.N):
                ders.append(diff(lambda t: f(x.a, [t if j == m else x.T[j] for j in range(x.N)], i, k), x.T[m]))
            ders += [mpf(0)] * (NMAX - x.N)
            # Theta enters only through powers, and the a's through h, n_i n_k: homogeneity checks
            if name == 'radial_distribution':
                assert all(dd == 0 for dd in ders[NMAX:])
            else:
                # every quantity is a sum of terms homogeneous of degree q in (Theta_m): q = 1 for
                # pressures and p_ik, 1/2 for mu, kappa, 3/2 for the sinks, 1/2 for drag, 0 for h, F
                q = {'contact_factor': 0, 'pair_pressure': 1, 'pressure': 1, 'segregation_coefficient': 1,
                     'pair_energy_sink': M('1.5'), 'energy_sink': M('1.5')}.get(name, M('0.5'))
                euler = sum(x.T[m] * ders[NMAX + m] for m in range(x.N))
                assert abs(euler - q * v) <= M('1e-25') * (abs(v) + sum(abs(x.T[m] * ders[NMAX + m])
                                                                        for m in range(x.N))), (x.name, name)
                NCHK[0] += 1
            rows.append(','.join(prefix + [name, str(i), str(k), out(v)] + [out(dd) for dd in ders]))
    return rows


def main():
    cases = FIXED + random_cases()
    names = [x.name for x in cases]
    assert len(set(names)) == len(names)
    check_seed004(cases)
    check_reductions(cases)
    for x in cases:
        check_identities(x)
    c = {x.name: x for x in cases}
    for nm in ('sand_biomass', 'sand_biomass_unequal', 'elastic_binary', 'random_3_05'):
        check_quadrature(c[nm])
    for nm, i, k in (('sand_biomass', 0, 1), ('random_3_05', 2, 0)):
        x = c[nm]
        with mp.workdps(25):
            same(drag_by_quadrature(x, i, k), x.drag(x.a, x.T, i, k), 'drag by quadrature', rel='1e-15')
    rows = [HEADER]
    for x in cases:
        rows += case_rows(x)
    # every assertion has passed: write
    with open(os.path.join(HERE, 'ktgf_classes_reference.csv'), 'w') as fh:
        fh.write('\n'.join(rows) + '\n')
    print('ktgf_classes_reference: %d rows, %d cases (N = 1..4); %d checks passed'
          % (len(rows) - 1, len(cases), NCHK[0]))


if __name__ == '__main__':
    main()
