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
  run          each pair of `equivalence` for RUN_STEPS time steps, the OpenFOAM model and the fluidbed
               law (with K compared at every step, as in `equivalence`): the fields differ by no more
               than RUN_FACTOR times what the solver's own tolerance makes of the OpenFOAM model's run
               (the largest difference among three runs of it: as shipped and with every linear
               solver's tolerance 10 and 100 times smaller, TIGHTER), in the root mean square over the
               cells; and a wrong pairing (WenYu1966, exponent 2.70, against WenYu, 2.65) exceeds it,
               so that the check can fail.
  parallel     MazzeiLettieri, Beetstra, DiFeliceDallavalle (no OpenFOAM counterparts), PARALLEL_STEPS
               steps serially and on 2 processes (decomposePar, mpirun, reconstructPar), with
               OpenFOAM's kinetic theory, and MazzeiLettieri with every kinetic-theory sub-model
               fluidbed's (laws OpenFOAM lacks): the fields agree within PARALLEL_TOLERANCES (why
               these: docs/openfoam.md); OpenFOAM's own GidaspowErgunWenYu, run the same way, is
               reported beside them.
  installed    the plugin installed by `cmake --install BUILD --component openfoam` into a fresh
               prefix, where BUILD is the build folder holding PLUGIN_LIBRARY: a step of the tutorial
               loads it by its full path, and by its bare name through LD_LIBRARY_PATH.
  zero_slip    every fluidbed law for one step from the tutorial's state with the gas at rest
               (zero slip in every cell) and its freeboard without particles: K is finite in
               every cell (the plugin's `report`), where a model written with Cd = f(Re)/Re
               needs OpenFOAM's residualRe.
  parameters   laws' parameters from the drag dictionary: WenYu1966 with exponent 2.65 equal to
               OpenFOAM's WenYu within 1e-12 (and not without it), SyamlalOBrien with c1, d1 set to
               OpenFOAM's values equal to its SyamlalOBrien; an entry the law lacks stops the solver
               with the law's parameters listed, and so does a value outside its domain, with the
               library's checked message; the same for a kinetic-theory sub-model's entries.
"""

import os
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from itertools import combinations
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RUN_CASE = ROOT / "openfoam" / "run_case.sh"
COMPARE = ROOT / "openfoam" / "compare_fields.py"
sys.path.insert(0, str(COMPARE.parent))
from compare_fields import differences, root_mean_square  # noqa: E402

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

RUN_STEPS = 300
RUN_FACTOR = 4.0
TIGHTER = (10, 100)  # one pair of runs alone measures the solver's spread only to a factor of about 2
RUN_FIELDS = [
    "alpha.particles",
    "U.particles*alpha.particles",
    "U.air",
    "p_rgh",
    "Theta.particles*alpha.particles",
]


def tighten(factor):
    """FLUIDBED_CASE_SETUP dividing every linear solver's tolerance by `factor`."""
    return f"perl -pi -e 's/^(\\s*tolerance\\s+)(\\S+);/$1 . ($2 \\/ {factor}) . \";\"/e' system/fvSolution"


WRONG_PAIR = ("WenYu1966", "WenYu")

PARALLEL_STEPS = 5
PARALLEL_TOLERANCES = [
    "alpha.particles:1e-6",
    "U.particles*alpha.particles:1e-5",  # the particle volume flux: U.particles is arbitrary without particles
    "Theta.particles*alpha.particles:1e-8",
    "U.air:1e-4",
    "p_rgh:1e-2",
    "T.air:1e-2",
]
# With fluidbed's kinetic-theory laws OpenFOAM lacks the decomposition makes five times the difference
# in alpha and p_rgh: 9.8e-7 and 1.4e-2 after 5 steps, OpenFOAM's own GidaspowErgunWenYu drag with the
# same sub-models 9.6e-7 and 1.4e-2 (docs/openfoam.md).
PARALLEL_TOLERANCES_FLUIDBED_KINETIC_THEORY = [
    "alpha.particles:5e-6",
    "U.particles*alpha.particles:5e-5",
    "Theta.particles*alpha.particles:1e-8",
    "U.air:1e-4",
    "p_rgh:7e-2",
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


def compared(case, law, reference, steps, parameters=""):
    """K of `law` (with `parameters`) against OpenFOAM's `reference` at each of `steps` steps: the
    logged comparisons, or None (and a message) where fewer were logged."""
    title = f"{law}{' ' + parameters if parameters else ''} against {reference}"
    lines = COMPARED.findall(run_case(case, law, steps, compare=reference, setup=with_parameters(parameters)))
    if len(lines) < steps:
        print(f"{title}: {len(lines)} comparisons logged, expected {steps}")
        return title, None
    return title, lines


def equivalent(case, law, reference, parameters=""):
    """1 unless K of `law` equals OpenFOAM's `reference` within BOUND at each of the first STEPS steps."""
    title, lines = compared(case, law, reference, STEPS, parameters)
    if lines is None:
        return 1
    worst = max(float(line[2]) for line in lines)
    max_re = max(float(line[6]) for line in lines)
    first = lines[0]
    ok = worst <= BOUND
    note = ""
    if reference in NEWTON_REYNOLDS:
        ok &= max_re < NEWTON_REYNOLDS[reference]
        note = f"; Re < {NEWTON_REYNOLDS[reference]:g} required, max Re {max_re:.3g}"
    print(f"{title}: first step {float(first[2]):.2e} over {first[3]} cells "
          f"({first[5]} with alpha < {first[4]} excluded); worst of {len(lines)} steps {worst:.2e} "
          f"(bound {BOUND:g}){note} {'ok' if ok else 'FAILS'}")
    return not ok


def equivalence(work):
    return sum(equivalent(work / f"{law}_{reference}", law, reference) for law, reference in PAIRS)


def final_fields(case):
    """The time folder of a case's last written fields."""
    return max((folder for folder in Path(case).iterdir() if re.fullmatch(r"[0-9.e+-]+", folder.name)),
               key=lambda folder: float(folder.name))


def spread(reference_case, other_case):
    """Root mean square over the cells of each RUN_FIELDS difference between two runs' final fields."""
    return [root_mean_square(differences(final_fields(reference_case), final_fields(other_case), field)[0])
            for field in RUN_FIELDS]


def run(work):
    """The `run` check: the runs two at a time, then each pair judged."""
    native = sorted({reference for _, reference in PAIRS})
    jobs = [(work / f"openfoam_{reference}", f"openfoam:{reference}", "", "") for reference in native]
    jobs += [(work / f"openfoam_{reference}_tighter_{factor}", f"openfoam:{reference}", "", tighten(factor))
             for reference in native for factor in TIGHTER]
    jobs += [(work / f"{law}_{reference}", law, reference, "") for law, reference in PAIRS + [WRONG_PAIR]]
    with ThreadPoolExecutor(max_workers=2) as pool:
        logs = dict(zip((case for case, *_ in jobs),
                        pool.map(lambda job: run_case(job[0], job[1], RUN_STEPS, compare=job[2], setup=job[3]),
                                 jobs)))
    print(f"{RUN_STEPS} steps; root mean square over the cells of the difference from OpenFOAM's model, "
          f"over the largest among its runs as shipped and with every solver tolerance "
          f"{' and '.join(map(str, TIGHTER))} times smaller (at most {RUN_FACTOR:g} required):")
    return sum(judge_run(work, law, reference, logs[work / f"{law}_{reference}"])
               for law, reference in PAIRS + [WRONG_PAIR])


def judge_run(work, law, reference, log):
    """1 unless the fields of `law` are as close to `reference`'s as the solver's tolerance makes them
    (and its K within BOUND at every step), or, for the wrong pairing, farther."""
    native = work / f"openfoam_{reference}"
    runs = [native] + [work / f"openfoam_{reference}_tighter_{factor}" for factor in TIGHTER]
    solver = [max(spreads) for spreads in zip(*(spread(a, b) for a, b in combinations(runs, 2)))]
    closure = spread(native, work / f"{law}_{reference}")
    ratios = [c / s for c, s in zip(closure, solver)]
    within = max(ratios) <= RUN_FACTOR
    steps = COMPARED.findall(log)
    worst_k = max((float(line[2]) for line in steps), default=float("inf"))
    max_re = max((float(line[6]) for line in steps), default=float("inf"))
    k_ok = len(steps) == RUN_STEPS and worst_k <= BOUND and max_re < NEWTON_REYNOLDS.get(reference, float("inf"))
    wrong = (law, reference) == WRONG_PAIR
    ok = (not within) if wrong else (within and k_ok)
    print(f"  {law} against {reference}{' (wrong pairing, must exceed)' if wrong else ''}: "
          + ", ".join(f"{field} {c:.2e}/{s:.2e} = {c / s:.2f}" for field, c, s in zip(RUN_FIELDS, closure, solver))
          + ("" if wrong else f"; K over {len(steps)} steps within {worst_k:.2e}, max Re {max_re:.3g}")
          + f" {'ok' if ok else 'FAILS'}", flush=True)
    return not ok


# The parallel runs: fluidbed's drag laws that OpenFOAM lacks with OpenFOAM's kinetic theory (the
# tutorial's), and Mazzei-Lettieri with every kinetic-theory sub-model fluidbed's, laws OpenFOAM lacks
# (openfoam/kinetic_theory_case.py). OpenFOAM's own drag in the same runs is reported beside them, as
# the measure of what the decomposition does to the solver's fields whatever the closure.
KINETIC_THEORY_CASE = ROOT / "openfoam" / "kinetic_theory_case.py"
PARALLEL_LAWS = ["MazzeiLettieri", "Beetstra", "DiFeliceDallavalle"]
PARALLEL_REFERENCE = "openfoam:GidaspowErgunWenYu"


def parallel_runs():
    fluidbed_kinetic_theory = f"python3 {KINETIC_THEORY_CASE} setup fluidbed-only {PLUGIN.resolve()}"
    return [(law, "", PARALLEL_TOLERANCES) for law in PARALLEL_LAWS + [PARALLEL_REFERENCE]] + \
        [(law, fluidbed_kinetic_theory, PARALLEL_TOLERANCES_FLUIDBED_KINETIC_THEORY)
         for law in ("MazzeiLettieri", PARALLEL_REFERENCE)]


def parallel(work):
    failures = 0
    for index, (law, setup, tolerances) in enumerate(parallel_runs()):
        serial, decomposed = work / f"serial_{index}", work / f"parallel_{index}"
        run_case(serial, law, PARALLEL_STEPS, setup=setup)
        run_case(decomposed, law, PARALLEL_STEPS, nprocs=2, setup=setup)
        kinetic_theory = "fluidbed's kinetic-theory sub-models" if setup else "OpenFOAM's kinetic theory"
        reference = law == PARALLEL_REFERENCE
        print(f"{law} with {kinetic_theory}, {PARALLEL_STEPS} steps, serial against 2 processes (reconstructed)"
              f"{', for reference (not checked)' if reference else ''}:", flush=True)
        result = subprocess.run([sys.executable, str(COMPARE), str(final_fields(serial)),
                                 str(final_fields(decomposed)),
                                 *(tolerance.partition(":")[0] if reference else tolerance for tolerance in tolerances)])
        failures += result.returncode
    return failures


def installed(work):
    build = next(folder for folder in PLUGIN.resolve().parents if (folder / "CMakeCache.txt").is_file())
    prefix = work / "prefix"
    subprocess.run(["cmake", "--install", str(build), "--component", "openfoam", "--prefix", str(prefix)],
                   check=True, stdout=subprocess.DEVNULL)
    library = next(prefix.glob("lib*/libfluidbedOpenFOAM.so"))
    failures = 0
    for way, name, search_path in (("full path", str(library), {}),
                                   ("bare name", library.name, {"LD_LIBRARY_PATH": str(library.parent)})):
        case = work / way.replace(" ", "_")
        env = dict(os.environ, FLUIDBED_OPENFOAM_LIB=name, **search_path)
        ok = subprocess.run(["bash", str(RUN_CASE), str(case), "MazzeiLettieri", "1"], env=env,
                            stdout=subprocess.DEVNULL).returncode == 0 \
            and "fluidbed drag law MazzeiLettieri" in (case / "log.twoPhaseEulerFoam").read_text()
        failures += not ok
        print(f"installed {library.relative_to(prefix)}, loaded by its {way}: "
              f"{'runs MazzeiLettieri' if ok else 'FAILS'}")
    return failures


def known_laws(work):
    case = work / "unknown"
    try:
        run_case(case, "NoSuchLaw", 1)
    except subprocess.CalledProcessError:
        pass
    listed = re.search(r"unknown drag law 'NoSuchLaw'; known: (.*)", (case / "log.twoPhaseEulerFoam").read_text())
    return listed.group(1).split(", ")


def with_parameters(parameters):
    """FLUIDBED_CASE_SETUP adding `parameters` ("key value; ...") to the fluidbed drag dictionary."""
    return f"sed -i -E 's/^( *law .*)$/\\1\\n        {parameters}/' constant/phaseProperties" if parameters else ""


# A parameter changes the law: WenYu1966's exponent 2.70 set to 2.65 is OpenFOAM's WenYu (net
# exponent 2.65, docs/openfoam.md), which WenYu1966 as registered is not (K differs by the factor
# voidage^-0.05, more than UNEQUAL in the bed). SyamlalOBrien's c1 and d1 set to OpenFOAM's values.
PARAMETER_PAIRS = [
    ("WenYu1966", "exponent 2.65;", "WenYu"),
    ("SyamlalOBrien", "c1 0.8; d1 2.65;", "SyamlalOBrien"),
]
UNEQUAL = 1e-2
# An entry that is not a parameter of the law stops the solver with the law's parameters; a
# parameter outside its domain stops it with the library's checked message naming it.
REJECTED = [
    ("SyamlalOBrien", "exponent 2.65;", "fluidbed: SyamlalOBrien has no parameter 'exponent'; its parameters: c1, d1"),
    ("Ergun", "c1 0.8;", "fluidbed: Ergun has no parameter 'c1'; its parameters: none"),
    ("SyamlalOBrien", "c1 -1;",
     "fluidbed::SyamlalOBrien: argument 'c1' = -1 is out of domain (must be finite and > 0)"),
    ("Ergun", "minParticleFraction 1;", "minParticleFraction 1 is not in [0, 1)"),
]


# The kinetic-theory sub-models' parameters: the solver's alphaMax is not a dictionary entry, and a
# value outside its domain stops the solver with the library's checked message.
KINETIC_THEORY_REJECTED = [
    ("fluidbedRadialCoeffs", "maxPacking 0.6;",
     "fluidbed: LunSavage has no parameter 'maxPacking'; its parameters: packingMargin"),
    ("fluidbedRadialCoeffs", "packingMargin 0.75;",
     "fluidbed::LunSavage: argument 'packing_margin' = 0.75 is out of domain (must lie in (0, 0.63))"),
]


def with_kinetic_theory_entry(coefficients, given):
    """FLUIDBED_CASE_SETUP: the plugin's kinetic-theory sub-models (the `hrenya` set of
    openfoam/kinetic_theory_case.py) with `given` added to the sub-dictionary `coefficients`."""
    return (f"python3 {KINETIC_THEORY_CASE} setup hrenya {PLUGIN.resolve()} && "
            f"sed -i -E 's/({coefficients} *\\{{ *)/\\1{given} /' constant/turbulenceProperties.particles")


def parameters(work):
    failures = sum(equivalent(work / f"{law}_{reference}", law, reference, given)
                   for law, given, reference in PARAMETER_PAIRS)
    title, lines = compared(work / "WenYu1966_unchanged", "WenYu1966", "WenYu", 1)
    if lines is None:
        failures += 1
    else:
        ok = float(lines[0][2]) > UNEQUAL
        failures += not ok
        print(f"{title}: {float(lines[0][2]):.3g} (more than {UNEQUAL:g} required) {'ok' if ok else 'FAILS'}")
    for index, (law, given, expected) in enumerate(REJECTED):
        case = work / f"rejected_{index}_{law}"
        try:
            run_case(case, law, 1, setup=with_parameters(given))
            stopped = False
        except subprocess.CalledProcessError:
            stopped = True
        ok = stopped and expected in (case / "log.twoPhaseEulerFoam").read_text()
        failures += not ok
        print(f"{law} {given}: {'stops' if stopped else 'runs'} {'with' if ok else 'without'} \"{expected}\" "
              f"{'ok' if ok else 'FAILS'}")
    for index, (coefficients, given, expected) in enumerate(KINETIC_THEORY_REJECTED):
        case = work / f"rejected_kinetic_theory_{index}"
        stopped = subprocess.run(["bash", str(RUN_CASE), str(case), "openfoam:GidaspowErgunWenYu", "1"],
                                 env=dict(os.environ, FLUIDBED_OPENFOAM_LIB=str(PLUGIN),
                                          FLUIDBED_CASE_SETUP=with_kinetic_theory_entry(coefficients, given)),
                                 stdout=subprocess.DEVNULL).returncode != 0
        ok = stopped and expected in (case / "log.twoPhaseEulerFoam").read_text()
        failures += not ok
        print(f"{coefficients} {given}: {'stops' if stopped else 'runs'} {'with' if ok else 'without'} "
              f"\"{expected}\" {'ok' if ok else 'FAILS'}")
    return failures


# The gas at rest in every cell, and the plugin's report of K once per time step.
AT_REST = ("sed -i -E 's/^internalField .*/internalField   uniform (0 0 0);/' 0/U.air && "
           + with_parameters("report          yes;"))


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
    return 1 if {"equivalence": equivalence, "run": run, "parallel": parallel, "installed": installed, "zero_slip": zero_slip,
                 "parameters": parameters}[argv[3]](work) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
