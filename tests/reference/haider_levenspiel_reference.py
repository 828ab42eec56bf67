#!/usr/bin/python3
"""Independent reference for the Haider-Levenspiel (1989) terminal velocity.

Writes haider_levenspiel_reference.csv (next to this file) with columns
    sphericity,archimedes,terminal_reynolds,d_terminal_reynolds_d_archimedes
at sphericities 1, 0.75, 0.5 and Ar = 0 and 2^k, k = -20, -17, ..., 40 (every input exact in
float, double and long double).

Evaluated the way the paper writes the fit, in the dimensionless diameter and velocity
    d* = d [rho_f (rho_p - rho_f) g / mu_f^2]^(1/3),   u* = u_t [rho_f^2 / (mu_f (rho_p - rho_f) g)]^(1/3),
    u* = [18 / d*^2 + (2.3348 - 1.7439 phi_s) / d*^0.5]^(-1),
for a fluid and particles chosen to give each Ar, and Re_t = rho_f u_t d / mu_f from the
dimensional u_t: not through the library's reduced form Re_t = Ar / (18 + c sqrt(Ar)).
The derivative is mpmath's numerical derivative of that evaluation in Ar. Asserts, before
writing, the two exact limits: Re_t -> Ar/18 as Ar -> 0 (Stokes) and Re_t -> sqrt(Ar)/c as
Ar -> infinity. mpmath, 40 digits. Run: /usr/bin/python3 haider_levenspiel_reference.py
"""
import os
import sys

from mpmath import mp, mpf, cbrt, sqrt, diff, nstr

mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))

RHO_F, MU_F, G = mpf('1.2'), mpf('1.8e-5'), mpf('9.80665')
RHO_P = mpf('2500')


def terminal_reynolds(phi_s, archimedes):
    """Re_t from the paper's d*, u* for particles whose diameter gives this Ar."""
    if archimedes == 0:
        return mpf(0)
    delta = RHO_P - RHO_F
    d = cbrt(archimedes * MU_F**2 / (RHO_F * delta * G))  # Ar = rho_f delta g d^3 / mu_f^2
    d_star = d * cbrt(RHO_F * delta * G / MU_F**2)
    u_star = 1 / (18 / d_star**2 + (mpf('2.3348') - mpf('1.7439') * phi_s) / sqrt(d_star))
    u_t = u_star * cbrt(MU_F * delta * G / RHO_F**2)
    return RHO_F * u_t * d / MU_F


def main():
    rows = []
    for phi_s in (mpf(1), mpf('0.75'), mpf('0.5')):
        c = mpf('2.3348') - mpf('1.7439') * phi_s
        stokes = terminal_reynolds(phi_s, mpf(2)**-60) * 18 / mpf(2)**-60
        newton = terminal_reynolds(phi_s, mpf(2)**120) * c / sqrt(mpf(2)**120)
        assert abs(stokes - 1) < mpf('1e-9'), stokes
        assert abs(newton - 1) < mpf('1e-16'), newton
        for archimedes in [mpf(0)] + [mpf(2)**k for k in range(-20, 41, 3)]:
            value = terminal_reynolds(phi_s, archimedes)
            slope = 1 / mpf(18) if archimedes == 0 else diff(lambda a: terminal_reynolds(phi_s, a), archimedes)
            rows.append((phi_s, archimedes, value, slope))
    with open(os.path.join(HERE, 'haider_levenspiel_reference.csv'), 'w') as f:
        f.write('sphericity,archimedes,terminal_reynolds,d_terminal_reynolds_d_archimedes\n')
        for phi_s, archimedes, value, slope in rows:
            f.write(','.join(nstr(x, 25, min_fixed=-30, max_fixed=30) for x in (phi_s, archimedes, value, slope)) + '\n')
    print(f'haider_levenspiel_reference.csv: {len(rows)} rows (Stokes and Newton limits asserted)')


if __name__ == '__main__':
    sys.exit(main())
