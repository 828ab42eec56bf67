#!/usr/bin/env python3
"""Pressure drop and bed height against time from runs of OpenFOAM's fluidisedBed tutorial.

Usage: bed_history.py OUT_DIR [--reference] LABEL=CASE_DIR ...

--reference before a case draws it dashed in black (OpenFOAM's own model, beside the fluidbed law
that computes the same formula).

For each case (a run of openfoam/run_case.sh whose fields were written at several times) and
each written time: the pressure drop across the domain, mean p of the bottom cell row minus
mean p of the top row, over the weight of the particles per unit area, sum(alpha_d rho_s g V)/A
(1 once the gas carries the whole bed; the gas's own weight and buoyancy, of order 10 Pa against
6.7 kPa, are left in); and the bed height, the height below which
95 % of the particle volume lies. Writes OUT_DIR/openfoam_fluidised_bed.dat (one block per
case) and OUT_DIR/openfoam_fluidised_bed.gp, which draws OUT_DIR/openfoam_fluidised_bed.png
beside itself. Runs of 1 s or more are also summarised over their second half (a bubbling bed's
statistics: the mean and standard deviation of both quantities), printed and put in the legend.
The mesh is the tutorial's: 30 x 200 uniform cells over 0.15 m x 1 m.
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


STATISTICS_FROM = 1.0  # s: runs at least this long are summarised over their second half


def second_half_statistics(rows):
    """Mean and standard deviation of dp/W and of the bed height over t >= half the run's end."""
    end = rows[-1][0]
    window = [row for row in rows if row[0] >= end / 2]
    summary = []
    for column in (1, 2):
        values = [row[column] for row in window]
        mean = sum(values) / len(values)
        summary.append((mean, (sum((v - mean) ** 2 for v in values) / len(values)) ** 0.5))
    return end / 2, end, summary


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out = Path(argv[1])
    out.mkdir(parents=True, exist_ok=True)
    curves, blocks, reference = [], [], False
    for spec in argv[2:]:
        if spec == "--reference":
            reference = True
            continue
        label, _, case = spec.partition("=")
        rows = history(case)
        line = f"{label}: {len(rows)} times; last: t = {rows[-1][0]:.3f} s, dp/W = {rows[-1][1]:.3f}, " \
               f"h95 = {rows[-1][2]:.3f} m"
        title = label
        if rows[-1][0] >= STATISTICS_FROM:
            start, end, ((dp, dp_sd), (h, h_sd)) = second_half_statistics(rows)
            line += f"; over {start:g}-{end:g} s: dp/W {dp:.3f} +- {dp_sd:.3f}, h95 {h:.3f} +- {h_sd:.3f} m"
            title += f" ({start:g}-{end:g} s: dp/W {dp:.2f}, h95 {h:.2f} m)"
        print(line)
        style = "lw 2 dt 2 lc rgb 'black'" if reference else "lw 2"
        curves.append((title, label, style))
        blocks.append(f"# {label}: time [s], pressure drop / bed weight, bed height (95 % of particles) [m]\n" +
                      "".join(f"{t:.4f} {dp:.6f} {h:.6f}\n" for t, dp, h in rows))
        reference = False
    dashed = "; dashed: OpenFOAM's own model" if any("dt 2" in style for *_, style in curves) else ""
    name = "openfoam_fluidised_bed"
    (out / f"{name}.dat").write_text("\n\n".join(blocks))
    # The pressure-drop panel's legend carries the statistics, the bed-height panel's the names only.
    plots = lambda column, titled: ", \\\n     ".join(
        f"data index {i} using 1:{column} with lines {style} title '{title if titled else label}'"
        for i, (title, label, style) in enumerate(curves))
    (out / f"{name}.gp").write_text(f"""# OpenFOAM's fluidisedBed tutorial (twoPhaseEulerFoam v1912) with fluidbed's drag laws
# Draws {name}.png from {name}.dat, both beside this script, from any working directory.
here = (strlen(ARG0) > strlen('{name}.gp')) ? ARG0[1:strlen(ARG0) - strlen('{name}.gp')] : ''
data = here . '{name}.dat'
set encoding utf8
set terminal pngcairo size 900,900 noenhanced font ',11'
set output here . '{name}.png'
set multiplot layout 2,1 title "OpenFOAM v1912 fluidisedBed tutorial (twoPhaseEulerFoam, 30 x 200 cells, air at 0.25 m/s)\\ndrag: fluidbed laws through the plugin (K = the law's pressure-gradient beta){dashed}"
set xlabel 'time [s]'
set grid
set key top right Left reverse
set ylabel 'p(bottom row) - p(top row) over particle weight per area [-]'
set yrange [0.6:3.6]
set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb 'gray40'
set label 1 'dotted: 1, the gas carries the whole weight' at graph 0.98, graph 0.6 right textcolor rgb 'gray40'
plot {plots(2, True)}
set ylabel 'bed height, 95 % of particles below [m]'
unset arrow 1
unset label 1
set yrange [0.4:1.0]
set key top left Left reverse
plot {plots(3, False)}
unset multiplot
""")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
