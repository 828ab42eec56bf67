#!/usr/bin/env python3
"""The OpenFOAM plugin on OpenFOAM's fluidisedBed tutorial (twoPhaseEulerFoam v1912): ctest's
`openfoam` tests. Exits 77 (skipped) where the plugin was not built or OpenFOAM is not installed.

Usage: check_plugin.py PLUGIN_LIBRARY|none WORK_DIR CHECK
  equivalence  K of each fluidbed law against the OpenFOAM model that computes the same formula
               (docs/openfoam.md), on the same fields, at each of the first STEPS time steps: at
               most 1e-12 relative over the cells where the dispersed fraction is at least its
               residualAlpha (1e-6; below it OpenFOAM floors the fraction, fluidbed does not);
               GidaspowSchillerNaumann only where Re = rho alpha_c |Ur| d/mu < 1000 (its Newton
               branch above has no fluidbed counterpart), which is checked on the compared cells.
  parallel     MazzeiLettieri (no OpenFOAM counterpart), PARALLEL_STEPS steps serially and on 2
               processes (decomposePar, mpirun, reconstructPar): the fields agree within
               PARALLEL_TOLERANCES (why these: docs/openfoam.md).
  zero_slip    every fluidbed law for one step from the tutorial's state with the gas at rest
               (zero slip in every cell) and its freeboard without particles: K is finite in
               every cell (the plugin's `report`), where a model written with Cd = f(Re)/Re
               needs OpenFOAM's residualRe.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RUN_CASE = ROOT / "openfoam" / "run_case.sh"
COMPARE = ROOT / "openfoam" / "compare_fields.py"

BOUND = 1e-12
STEPS = 10
PAIRS = [  # fluidbed law, OpenFOAM type
    ("Ergun", "Ergun"),
    ("WenYuGidaspow", "WenYu"),
    ("GidaspowSwitched", "GidaspowErgunWenYu"),
    ("WenYuGidaspow", "GidaspowSchillerNaumann"),
    ("SyamlalOBrien", "SyamlalOBrien"),
]
NEWTON_REYNOLDS = {"GidaspowSchillerNaumann": 1000.0}

PARALLEL_STEPS = 5
PARALLEL_TOLERANCES = [
    "alpha.particles:1e-6",
    "U.particles*alpha.particles:1e-5",  # the particle volume flux: U.particles is arbitrary without particles
    "Theta.particles*alpha.particles:1e-8",
    "U.air:1e-4",
    "p_rgh:1e-2",
    "T.air:1e-2",
]

COMPARED = re.compile(r"^fluidbed: K of (\S+) against (\S+): max relative difference (\S+) over (\d+) cells "
                      r"with alpha >= (\S+) \((\d+) excluded\), max Re (\S+)$", re.M)
REPORTED = re.compile(r"^fluidbed: K of (\S+) over (\d+) cells: (\d+) not finite, (\d+) at zero slip, "
                      r"(\d+) without particles, range (\S+) to (\S+)$", re.M)


def run_case(case, law, steps, nprocs=1, compare="", setup=""):
    env = dict(os.environ, FLUIDBED_OPENFOAM_LIB=str(PLUGIN), FLUIDBED_CASE_SETUP=setup)
    subprocess.run(["bash", str(RUN_CASE), str(case), law, str(steps), str(nprocs), compare],
                   env=env, check=True, stdout=subprocess.DEVNULL)
    return (Path(case) / "log.twoPhaseEulerFoam").read_text()


def equivalence(work):
    failures = 0
    for law, reference in PAIRS:
        log = run_case(work / f"{law}_{reference}", law, STEPS, compare=reference)
        lines = COMPARED.findall(log)
        if len(lines) < STEPS:
            print(f"{law} against {reference}: {len(lines)} comparisons logged, expected {STEPS}")
            failures += 1
            continue
        worst = max(float(line[2]) for line in lines)
        max_re = max(float(line[6]) for line in lines)
        first = lines[0]
        ok = worst <= BOUND
        note = ""
        if reference in NEWTON_REYNOLDS:
            ok &= max_re < NEWTON_REYNOLDS[reference]
            note = f"; Re < {NEWTON_REYNOLDS[reference]:g} required, max Re {max_re:.3g}"
        failures += not ok
        print(f"{law} against {reference}: first step {float(first[2]):.2e} over {first[3]} cells "
              f"({first[5]} with alpha < {first[4]} excluded); worst of {len(lines)} steps {worst:.2e} "
              f"(bound {BOUND:g}){note} {'ok' if ok else 'FAILS'}")
    return failures


def parallel(work):
    time = repr(PARALLEL_STEPS * 2e-4)
    serial, decomposed = work / "serial", work / "parallel"
    run_case(serial, "MazzeiLettieri", PARALLEL_STEPS)
    run_case(decomposed, "MazzeiLettieri", PARALLEL_STEPS, nprocs=2)
    print(f"MazzeiLettieri, {PARALLEL_STEPS} steps, serial against 2 processes (reconstructed):", flush=True)
    return subprocess.run([sys.executable, str(COMPARE), str(serial / time), str(decomposed / time),
                           *PARALLEL_TOLERANCES]).returncode


def known_laws(work):
    case = work / "unknown"
    try:
        run_case(case, "NoSuchLaw", 1)
    except subprocess.CalledProcessError:
        pass
    listed = re.search(r"unknown drag law 'NoSuchLaw'; known: (.*)", (case / "log.twoPhaseEulerFoam").read_text())
    return listed.group(1).split(", ")


# The gas at rest in every cell, and the plugin's report of K once per time step.
AT_REST = ("sed -i -E 's/^internalField .*/internalField   uniform (0 0 0);/' 0/U.air && "
           "sed -i -E 's/^( *law .*)$/\\1\\n        report          yes;/' constant/phaseProperties")


def zero_slip(work):
    failures = 0
    laws = known_laws(work)
    for law in laws:
        log = run_case(work / law, law, 1, setup=AT_REST)
        reports = REPORTED.findall(log)
        if not reports:
            print(f"{law}: no report of K logged")
            failures += 1
            continue
        _, cells, not_finite, at_rest, empty, low, high = reports[0]
        ok = int(not_finite) == 0 and int(at_rest) == int(cells) and int(empty) > 0
        failures += not ok
        print(f"{law}: {cells} cells, {at_rest} at zero slip, {empty} without particles: {not_finite} "
              f"with K not finite, K from {float(low):.4g} to {float(high):.4g} {'ok' if ok else 'FAILS'}")
    return failures


def main(argv):
    global PLUGIN
    if len(argv) != 4:
        sys.exit(__doc__)
    PLUGIN = Path(argv[1])
    if not PLUGIN.is_file():
        print("skipped: the OpenFOAM plugin is not built (FLUIDBED_BUILD_OPENFOAM, scripts/install_openfoam.sh)")
        return 77
    if shutil.which("twoPhaseEulerFoam") is None:
        print("skipped: OpenFOAM's twoPhaseEulerFoam is not installed (scripts/install_openfoam.sh)")
        return 77
    work = Path(argv[2]) / argv[3]
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    return 1 if {"equivalence": equivalence, "parallel": parallel, "zero_slip": zero_slip}[argv[3]](work) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
