#!/usr/bin/python3
"""Independent high-precision reference generator for the solids' wall boundary conditions
(project issue 18): Johnson & Jackson's partial-slip wall and Jenkins & Louge's small-friction
flat wall.

Writes (next to this file):
  wall_reference.csv   long format, one row per (law, quantity, wall, state):
      law,quantity,specularity,wall_restitution,max_packing,wall_friction,slip_floor,
      solid_fraction,granular_temperature,wall_slip,g0,particle_density,restitution,
      value,d_solid_fraction,d_granular_temperature,d_wall_slip

Laws, written here from the papers' forms (never from the C++ code under include/):
  Johnson, P.C. & Jackson, R. (1987) J. Fluid Mech. 176, 67-93, doi:10.1017/S0022112087000570,
  with the host's g0 (the form of FLUENT, MFiX and OpenFOAM):
    F = (phi/phi_max) rho_s g0 sqrt(Theta)
    shear = (pi sqrt3/6) psi F u,  slip coefficient k = shear/u
    generation = (pi sqrt3/6) psi F u^2,  dissipation = (pi sqrt3/4)(1 - e_w^2) F Theta
  Jenkins, J.T. & Louge, M.Y. (1997) Phys. Fluids 9, 2835-2840, doi:10.1063/1.869396, small
  friction, as MFiX implements its eqs. (2)-(3):
    N = rho_s phi Theta (1 + 2(1 + e) phi g0)
    shear = mu_w N u / sqrt(u^2 + u0^2),  k = shear/u (= mu_w N/sqrt(u^2 + u0^2))
    generation = (21/16) sqrt3 mu_w^2 (1 + e_w) N sqrt(Theta)
    dissipation = (3/8) sqrt3 (1 - e_w) N sqrt(Theta)
  energy_flux = generation - dissipation (positive INTO the bed); dissipation_coefficient =
  dissipation/Theta.

States: seed 001's riser walls (specularity 0.001 with e_w 0.2; 0.01 with e_w 0.9), a free-slip
(specularity 0) and a fully diffuse (specularity 1) wall; phi_max = 0.63, glass rho_s = 2480,
e = 0.9 (seed 001 Table 1); g0 is the Sinclair-Jackson form 1/(1 - (phi/0.63)^(1/3)) (written in
the g0 column; d_solid_fraction includes dg0/dphi). Partial derivatives come from mpmath.diff of
the value functions, never by hand. mpmath, 40 digits; inputs are exact decimal strings; output
nstr(x, 17). Before writing, the script asserts identities that do not use the formulas above as
written: the codes' own arrangements (MFiX's F_2, HW, CW; OpenFOAM's Robin coefficient c and
reference value), the free-slip limit, and the Maxwellian average of the sliding-contact model by
quadrature (the ratio of Jenkins & Louge's two terms).

Run with Debian's python:  /usr/bin/python3 wall_reference.py   (prints one line)
"""
import os
import sys

sys.dont_write_bytecode = True

from mpmath import mp, mpf, sqrt, pi, cbrt, nstr, diff, quad, exp, inf  # noqa: E402

mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
NCHK = [0]


def M(s):
    return mpf(s)


def out(x):
    return nstr(mpf(x), 17)


def chk(x, ref, rel=mpf("1e-30"), what=""):
    NCHK[0] += 1
    if ref == 0:
        assert abs(x) <= rel, (what, x, ref)
    else:
        assert abs(x - ref) <= rel * abs(ref), (what, x, ref)


RHO = M("2480")
E = M("0.9")
PHI_MAX = M("0.63")


def g0_sj(phi):
    return 1 / (1 - cbrt(phi / PHI_MAX))


# ------------------------------------------------------------------ the laws, from the papers


def jj(quantity, psi, e_w, phi_max, phi, theta, u, g0):
    F = phi / phi_max * RHO * g0 * sqrt(theta)
    shear = pi * sqrt(3) / 6 * psi * F * u
    k = pi * sqrt(3) / 6 * psi * F
    gen = pi * sqrt(3) / 6 * psi * F * u**2
    a = pi * sqrt(3) / 4 * (1 - e_w**2) * F
    diss = a * theta
    return {"shear": shear, "slip_coefficient": k, "generation": gen, "dissipation": diss,
            "dissipation_coefficient": a, "energy_flux": gen - diss}[quantity]


def jl(quantity, mu, e_w, u0, phi, theta, u, g0):
    N = RHO * phi * theta * (1 + 2 * (1 + E) * phi * g0)
    k = mu * N / sqrt(u**2 + u0**2)
    gen = mpf(21) / 16 * sqrt(3) * mu**2 * (1 + e_w) * N * sqrt(theta)
    diss = mpf(3) / 8 * sqrt(3) * (1 - e_w) * N * sqrt(theta)
    return {"shear": k * u, "slip_coefficient": k, "generation": gen, "dissipation": diss,
            "dissipation_coefficient": diss / theta, "energy_flux": gen - diss}[quantity]


QUANTITIES = ("shear", "slip_coefficient", "energy_flux", "generation", "dissipation", "dissipation_coefficient")

# ------------------------------------------------------------------ independent checks


def checks():
    phi, theta, u = M("0.2"), M("0.04"), M("0.7")
    g0 = g0_sj(phi)
    for psi, e_w in ((M("0.001"), M("0.2")), (M("0.01"), M("0.9")), (M("1"), M("0.5"))):
        # MFiX's arrangement: F_2 = (PHIP*sqrt(3 TH)*pi*RO_s*EPS*G_0)/(6 EPS_max) is k.
        f2 = psi * sqrt(3 * theta) * pi * RHO * phi * g0 / (6 * PHI_MAX)
        chk(jj("slip_coefficient", psi, e_w, PHI_MAX, phi, theta, u, g0), f2, what="MFiX F_2")
        # HW = (pi sqrt3/(4 EPS_max))(1 - e_w^2) RO_s EPS G_0 sqrt(TH): A; CW = ... VSLIPSQ: generation.
        hw = pi * sqrt(3) / (4 * PHI_MAX) * (1 - e_w**2) * RHO * phi * g0 * sqrt(theta)
        cw = pi * sqrt(3) / (6 * PHI_MAX) * psi * RHO * phi * g0 * sqrt(theta) * u**2
        chk(jj("dissipation_coefficient", psi, e_w, PHI_MAX, phi, theta, u, g0), hw, what="MFiX HW")
        chk(jj("generation", psi, e_w, PHI_MAX, phi, theta, u, g0), cw, what="MFiX CW")
        # OpenFOAM's partial slip: c = pi phi g0 psi sqrt(3 Theta)/(6 nu phi_max), stress rho nu c u.
        nu = M("0.013")  # any kinematic viscosity: it cancels
        c = pi * phi * g0 * psi * sqrt(3 * theta) / (6 * nu * PHI_MAX)
        chk(jj("shear", psi, e_w, PHI_MAX, phi, theta, u, g0), RHO * nu * c * u, what="OpenFOAM slip")
        # OpenFOAM's mixed Theta condition with the conductivity kappa including rho_s:
        # kappa dTheta/dn = kappa c (Theta_ref - Theta), c = pi phi g0 (1 - e_w^2) sqrt(3 Theta)/(4 kappa phi_max),
        # Theta_ref = (2/3) psi u^2/(1 - e_w^2). Times rho_s it is our energy flux.
        kappa = M("0.37")
        cT = pi * phi * g0 * (1 - e_w**2) * sqrt(3 * theta) / (4 * kappa * PHI_MAX)
        ref = mpf(2) / 3 * psi * u**2 / (1 - e_w**2)
        chk(jj("energy_flux", psi, e_w, PHI_MAX, phi, theta, u, g0), RHO * kappa * cT * (ref - theta),
            what="OpenFOAM Theta x rho_s")
    # free slip: specularity 0 gives no shear and no generation, only dissipation
    for q in ("shear", "slip_coefficient", "generation"):
        chk(jj(q, M("0"), M("0.2"), PHI_MAX, phi, theta, u, g0), 0, what="free slip " + q)
    # Jenkins & Louge, MFiX's arrangement: F_2 = tan_Phi_w RO_s EPS (1 + 4 Eta EPS G_0) TH/VSLIP (u0 -> 0)
    mu, e_w = M("0.1"), M("0.9")
    eta = (1 + E) / 2
    u0 = mpf("1e-30")
    f2 = mu * RHO * phi * (1 + 4 * eta * phi * g0) * theta / u
    chk(jl("slip_coefficient", mu, e_w, u0, phi, theta, u, g0), f2, rel=mpf("1e-25"), what="MFiX Jenkins F_2")
    hw = mpf(3) / 8 * sqrt(3 * theta) * (1 - e_w) * RHO * phi * (1 + 4 * eta * phi * g0)
    cw = mu * mu * (1 + e_w) * mpf(21) / 16 * sqrt(3 * theta) * RHO * phi * (1 + 4 * eta * phi * g0) * theta
    chk(jl("dissipation_coefficient", mu, e_w, u0, phi, theta, u, g0), hw, what="MFiX Jenkins HW")
    chk(jl("generation", mu, e_w, u0, phi, theta, u, g0), cw, what="MFiX Jenkins CW")
    # Maxwellian average of the sliding-contact model (unit mass, temperature T, wall flux of
    # particles with normal speed c > 0 weighted by c): with N = n m (1+e_w) <c^2>_+,
    # normal loss n (1/2)(1-e_w^2) <c^3>_+ = (1-e_w) sqrt(2/pi) N sqrt(T), and the second-order
    # sliding term n (7/4) mu^2 (1+e_w)^2 <c^3>_+ = (7/2) mu^2 (1+e_w) sqrt(2/pi) N sqrt(T).
    T = M("0.3")
    f = lambda c: exp(-c * c / (2 * T)) / sqrt(2 * pi * T)  # noqa: E731
    c2 = quad(lambda c: c * c * f(c), [0, inf])
    c3 = quad(lambda c: c**3 * f(c), [0, inf])
    n, ew = M("1"), M("0.6")
    N = n * (1 + ew) * c2
    normal = n * (1 - ew**2) / 2 * c3
    sliding = n * mpf(7) / 4 * mu**2 * (1 + ew) ** 2 * c3
    chk(normal / (N * sqrt(T)), (1 - ew) * sqrt(2 / pi), rel=mpf("1e-25"), what="Maxwell normal")
    chk(sliding / (N * sqrt(T)), mpf(7) / 2 * mu**2 * (1 + ew) * sqrt(2 / pi), rel=mpf("1e-25"), what="Maxwell sliding")
    # the same two terms in Jenkins & Louge's constants differ by one common factor
    chk(sqrt(2 / pi) / (mpf(3) / 8 * sqrt(3)), (mpf(7) / 2 * sqrt(2 / pi)) / (mpf(21) / 16 * sqrt(3)), what="ratio")
    chk(sqrt(2 / pi) / (mpf(3) / 8 * sqrt(3)), M("1.2284236426"), rel=mpf("1e-10"), what="factor 1.2284")


# ------------------------------------------------------------------ the table

PHIS = ("0.001", "0.01", "0.05", "0.2", "0.45")
THETAS = ("0.0001", "0.01", "0.1")
SLIPS = ("0", "0.05", "0.5", "2")
JJ_WALLS = (("0.001", "0.2"), ("0.01", "0.9"), ("0", "0.2"), ("1", "0.9"))
JL_WALLS = (("0.1", "0.2"), ("0.1", "0.9"), ("0.3", "0.9"), ("0", "0.9"))
U0 = "1e-6"

HEADER = ("law,quantity,specularity,wall_restitution,max_packing,wall_friction,slip_floor,solid_fraction,"
          "granular_temperature,wall_slip,g0,particle_density,restitution,value,d_solid_fraction,"
          "d_granular_temperature,d_wall_slip")


def rows():
    for law, walls in (("johnson_jackson", JJ_WALLS), ("jenkins_louge", JL_WALLS)):
        for a, e_w in walls:
            for phi in PHIS:
                for theta in THETAS:
                    for u in SLIPS:
                        for q in QUANTITIES:
                            P, Th, U = M(phi), M(theta), M(u)
                            if law == "johnson_jackson":
                                fn = lambda p, t, s: jj(q, M(a), M(e_w), PHI_MAX, p, t, s, g0_sj(p))  # noqa: E731
                                spec, fric, floor = a, "0", "0"
                            else:
                                fn = lambda p, t, s: jl(q, M(a), M(e_w), M(U0), p, t, s, g0_sj(p))  # noqa: E731
                                spec, fric, floor = "0", a, U0
                            value = fn(P, Th, U)
                            d_phi = diff(lambda p: fn(p, Th, U), P)
                            d_theta = diff(lambda t: fn(P, t, U), Th)
                            d_u = diff(lambda s: fn(P, Th, s), U)
                            yield ",".join([law, q, spec, e_w, "0.63", fric, floor, phi, theta, u, out(g0_sj(P)), "2480",
                                            "0.9", out(value), out(d_phi), out(d_theta), out(d_u)])


def main():
    checks()
    lines = [HEADER] + list(rows())
    with open(os.path.join(HERE, "wall_reference.csv"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wall_reference.py: {NCHK[0]} checks passed, {len(lines) - 1} rows written to wall_reference.csv")


if __name__ == "__main__":
    main()
