#!/usr/bin/env python3
"""Pressure drop and bed height against time from runs of OpenFOAM's fluidisedBed tutorial.

Usage: bed_history.py OUT_DIR LABEL=CASE_DIR ...

For each case (a run of openfoam/run_case.sh whose fields were written at several times) and
each written time: the pressure drop across the domain, mean p of the bottom cell row minus
mean p of the top row, over the weight of the particles per unit area, sum(alpha_d rho_s g V)/A
(1 once the gas carries the whole bed; the gas's own weight and buoyancy, of order 10 Pa against
6.7 kPa, are left in); and the bed height, the height below which
95 % of the particle volume lies. Writes OUT_DIR/openfoam_fluidised_bed.dat (one block per
case) and OUT_DIR/openfoam_fluidised_bed.gp, which draws OUT_DIR/openfoam_fluidised_bed.png
beside itself. The mesh is the tutorial's: 30 x 200 uniform cells over 0.15 m x 1 m.
Python 3 standard library only.
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from compare_fields import internal_values  # noqa: E402

COLUMNS, ROWS, HEIGHT = 30, 200, 1.0
RHO_PARTICLES, GRAVITY = 2500.0, 9.81  # constant/thermophysicalProperties.particles, constant/g


def history(case):
    rows = []
    times = sorted((d for d in Path(case).iterdir() if d.is_dir() and _is_time(d.name) and float(d.name) > 0),
                   key=lambda d: float(d.name))
    for folder in times:
        alpha = internal_values(folder / "alpha.particles")
        p = internal_values(folder / "p")
        row_mean = [sum(p[j * COLUMNS:(j + 1) * COLUMNS]) / COLUMNS for j in (0, ROWS - 1)]
        dy = HEIGHT / ROWS
        weight = sum(alpha) * RHO_PARTICLES * GRAVITY * dy / COLUMNS
        per_row = [sum(alpha[j * COLUMNS:(j + 1) * COLUMNS]) for j in range(ROWS)]
        total, below, height = sum(per_row), 0.0, HEIGHT
        for j, amount in enumerate(per_row):
            if below + amount >= 0.95 * total:
                height = (j + (0.95 * total - below) / amount) * dy
                break
            below += amount
        rows.append((float(folder.name), (row_mean[0] - row_mean[1]) / weight, height))
    return rows


def _is_time(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out = Path(argv[1])
    out.mkdir(parents=True, exist_ok=True)
    labels, blocks = [], []
    for spec in argv[2:]:
        label, _, case = spec.partition("=")
        rows = history(case)
        labels.append(label)
        blocks.append(f"# {label}: time [s], pressure drop / bed weight, bed height (95 % of particles) [m]\n" +
                      "".join(f"{t:.4f} {dp:.6f} {h:.6f}\n" for t, dp, h in rows))
        print(f"{label}: {len(rows)} times; last: t = {rows[-1][0]:.3f} s, dp/W = {rows[-1][1]:.3f}, "
              f"h95 = {rows[-1][2]:.3f} m")
    name = "openfoam_fluidised_bed"
    (out / f"{name}.dat").write_text("\n\n".join(blocks))
    plots = lambda column: ", \\\n     ".join(
        f"data index {i} using 1:{column} with lines lw 2 title '{label}'" for i, label in enumerate(labels))
    (out / f"{name}.gp").write_text(f"""# OpenFOAM's fluidisedBed tutorial (twoPhaseEulerFoam v1912) with fluidbed's drag laws
# Draws {name}.png from {name}.dat, both beside this script, from any working directory.
here = (strlen(ARG0) > strlen('{name}.gp')) ? ARG0[1:strlen(ARG0) - strlen('{name}.gp')] : ''
data = here . '{name}.dat'
set encoding utf8
set terminal pngcairo size 900,900 noenhanced font ',11'
set output here . '{name}.png'
set multiplot layout 2,1 title "OpenFOAM v1912 fluidisedBed tutorial (twoPhaseEulerFoam, 30 x 200 cells, air at 0.25 m/s)\\nwith four fluidbed drag laws, K = the law's pressure-gradient beta"
set xlabel 'time [s]'
set grid
set key bottom right
set ylabel 'p(bottom row) - p(top row) over particle weight per area [-]'
plot {plots(2)}
set ylabel 'bed height, 95 % of particles below [m]'
set key top left
plot {plots(3)}
unset multiplot
""")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
