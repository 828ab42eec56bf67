#!/usr/bin/env bash
# The check of the plugin's kinetic-theory sub-models against OpenFOAM's own: runs the fluidisedBed
# tutorial for STEPS time steps (default 5) with each set of fluidbed laws of
# openfoam/kinetic_theory_case.py, every sub-model also evaluating OpenFOAM's model of the same
# closure on the same arguments (compareWith), and fails unless every logged largest relative
# difference is within its tolerance (1e-12) and the run with laws OpenFOAM lacks completes.
# Exits 77 (skipped, for ctest's SKIP_RETURN_CODE) when OpenFOAM or the plugin is missing.
#
#   openfoam/check_kinetic_theory.sh [WORK_DIR] [STEPS]
#
# The drag is fluidbed's GidaspowSwitched (the formula of the tutorial's GidaspowErgunWenYu) with
# minParticleFraction 1e-6 (the tutorial's residualAlpha): a drag sink in the cells without
# particles keeps the granular-temperature equation's diagonal nonzero there, which Syamlal's
# viscosity and conductivity (0 at alpha = 0) need (docs/openfoam.md).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$root/build/openfoam/check_kinetic_theory} steps=${2:-5}
lib=$(realpath -m "${FLUIDBED_OPENFOAM_LIB:-$root/build/openfoam/libfluidbedOpenFOAM.so}")
if ! command -v twoPhaseEulerFoam > /dev/null || [ ! -f "$lib" ]; then
  echo "skipped: twoPhaseEulerFoam or $lib not found"
  exit 77
fi
mkdir -p "$work"
status=0
for config in gidaspow syamlal hrenya fluidbed-only; do
  echo "== $config"
  setup="python3 $root/openfoam/kinetic_theory_case.py setup $config $lib && \
sed -i -E 's/^( *law .*)$/\1\n        minParticleFraction 1e-6;/' constant/phaseProperties"
  if ! FLUIDBED_OPENFOAM_LIB=$lib FLUIDBED_CASE_SETUP="$setup" \
       "$root/openfoam/run_case.sh" "$work/$config" GidaspowSwitched "$steps" > "$work/$config.out" 2>&1; then
    echo "the run failed: $work/$config/log.twoPhaseEulerFoam"
    status=1
    continue
  fi
  python3 "$root/openfoam/kinetic_theory_case.py" check "$config" "$work/$config/log.twoPhaseEulerFoam" || status=1
done
exit $status
