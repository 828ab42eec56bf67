#!/usr/bin/env bash
# Runs OpenFOAM's fluidisedBed tutorial (twoPhaseEulerFoam, Debian's openfoam-examples) with a
# chosen drag model, serially or on several processes, in a fresh case folder.
#
#   openfoam/run_case.sh CASE_DIR MODEL STEPS [NPROCS] [COMPARE_WITH]
#
# MODEL: a fluidbed drag law by run-time name (e.g. MazzeiLettieri), through the plugin, or
# "openfoam:<type>" for OpenFOAM's own model (e.g. openfoam:GidaspowErgunWenYu).
# STEPS: time steps of the tutorial's 2e-4 s; fields are written at the end (16 digits).
# NPROCS > 1: decomposePar (simple, along the height), mpirun, reconstructPar.
# COMPARE_WITH: an OpenFOAM drag type the plugin also evaluates each step, logging the largest
# relative difference of K (the plugin's compareWith check).
# The plugin is FLUIDBED_OPENFOAM_LIB (default build/openfoam/libfluidbedOpenFOAM.so); a bare file
# name is given to OpenFOAM as it is (found through LD_LIBRARY_PATH or the loader's cache).
# FLUIDBED_CASE_SETUP: a shell command run in the case folder once it is set up, before blockMesh
# (the tests use it to change initial fields, solver tolerances, the drag dictionary or the
# kinetic-theory sub-models).
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,16p' "$0"; exit 2; }
case_dir=$1 model=$2 steps=$3 nprocs=${4:-1} compare=${5:-}
root=$(cd "$(dirname "$0")/.." && pwd)
lib=${FLUIDBED_OPENFOAM_LIB:-$root/build/openfoam/libfluidbedOpenFOAM.so}
[[ $lib != */* ]] || lib=$(realpath "$lib")
tutorial=/usr/share/doc/openfoam-examples/examples/multiphase/twoPhaseEulerFoam/RAS/fluidisedBed
export WM_PROJECT_DIR=/usr/share/openfoam FOAM_ETC=/usr/share/openfoam/etc

rm -rf "$case_dir"
cp -r "$tutorial" "$case_dir"
cd "$case_dir"
find . -name '*.gz' -exec gunzip -f {} +
end_time=$(python3 -c "print('%.10g' % ($steps * 2e-4))")  # as OpenFOAM names the time folder
sed -i -e "s/^endTime .*/endTime         $end_time;/" -e "s/^writeInterval .*/writeInterval   $end_time;/" \
       -e "s/^writePrecision .*/writePrecision  16;/" system/controlDict
python3 - "$model" "$lib" "$compare" <<'PY'
import re, sys
model, lib, compare = sys.argv[1:]
props = open('constant/phaseProperties').read()
drag = re.search(r'\(particles in air\)\s*\{.*?\n    \}', props, re.S)
if model.startswith('openfoam:'):
    body = f'        type            {model.split(":", 1)[1]};\n        residualRe      1e-3;\n' \
           '        swarmCorrection\n        {\n            type        none;\n        }\n'
else:
    body = f'        type            fluidbed;\n        law             {model};\n'
    if compare:
        body += (f'        compareWith\n        {{\n            type            {compare};\n'
                 '            residualRe      1e-3;\n            swarmCorrection { type none; }\n'
                 '        }\n')
    control = open('system/controlDict').read()
    control = re.sub(r'^(application .*\n)', rf'\1libs            ("{lib}");\n', control, count=1, flags=re.M)
    open('system/controlDict', 'w').write(control)
props = props[:drag.start()] + '(particles in air)\n    {\n' + body + '    }' + props[drag.end():]
open('constant/phaseProperties', 'w').write(props)
PY

[ -z "${FLUIDBED_CASE_SETUP:-}" ] || bash -c "$FLUIDBED_CASE_SETUP"
blockMesh > log.blockMesh 2>&1
if [ "$nprocs" -gt 1 ]; then
  cat > system/decomposeParDict <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains $nprocs;
method          simple;
coeffs { n (1 $nprocs 1); }
DICT
  decomposePar > log.decomposePar 2>&1
  mpi_flags=(--oversubscribe)
  [ "$(id -u)" -ne 0 ] || mpi_flags+=(--allow-run-as-root)
  mpirun "${mpi_flags[@]}" -np "$nprocs" twoPhaseEulerFoam -parallel > log.twoPhaseEulerFoam 2>&1
  reconstructPar -latestTime > log.reconstructPar 2>&1
else
  twoPhaseEulerFoam > log.twoPhaseEulerFoam 2>&1
fi
grep -h '^fluidbed' log.twoPhaseEulerFoam | head -3 || true
echo "$case_dir: $model, $steps steps on $nprocs process(es), fields in $case_dir/$end_time"
