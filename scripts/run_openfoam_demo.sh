#!/usr/bin/env bash
# The OpenFOAM demonstration: OpenFOAM's fluidisedBed tutorial (twoPhaseEulerFoam v1912, Debian's
# openfoam-examples: 6000 cells, 0.15 m x 1 m, 0.5 m of 300 um particles at 0.55, air at
# 0.25 m/s from below) run with four of fluidbed's drag laws through the plugin — Gidaspow's
# switched Ergun/Wen–Yu (OpenFOAM's own GidaspowErgunWenYu, the tutorial's choice) and three
# laws OpenFOAM lacks: Mazzei–Lettieri, Beetstra, Di Felice — and, as the reference, OpenFOAM's
# own GidaspowErgunWenYu, side by side on the cores there are. Plots the pressure drop across
# the bed over the bed's weight and the bed height against time (openfoam/demo/bed_history.py)
# into PLOTS_DIR/openfoam_fluidised_bed.png.
#
#   scripts/run_openfoam_demo.sh [BUILD_DIR [PLOTS_DIR]]     (default build/release, BUILD_DIR/plots)
#
# FLUIDBED_OPENFOAM_DEMO_SECONDS: simulated time (default 0.6 s of the tutorial's 2 s; fields
# written every 0.01 s).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
plots=${2:-$build/plots}
seconds=${FLUIDBED_OPENFOAM_DEMO_SECONDS:-0.6}
bash scripts/install_openfoam.sh
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLUIDBED_BUILD_OPENFOAM=ON >/dev/null
cmake --build "$build" --target fluidbedOpenFOAM

laws=(GidaspowSwitched MazzeiLettieri Beetstra DiFeliceDallavalle)
reference=GidaspowErgunWenYu  # OpenFOAM's own, the formula of GidaspowSwitched
runs=$build/openfoam_demo
mkdir -p "$runs"
steps=$(python3 -c "print(round($seconds / 2e-4))")
export FLUIDBED_OPENFOAM_LIB=$build/openfoam/libfluidbedOpenFOAM.so
# 60 writes of every field: 8 digits, gzipped (1.1 GB for the four runs at 16 digits uncompressed)
export FLUIDBED_CASE_SETUP="sed -i -E 's/^writeInterval .*/writeInterval   0.01;/; s/^writePrecision .*/writePrecision  8;/; \
s/^writeCompression .*/writeCompression on;/' system/controlDict"
echo "fluidbed: the fluidisedBed tutorial for $seconds s ($steps steps) with ${laws[*]} and OpenFOAM's $reference"
start=$SECONDS
printf '%s\n' "${laws[@]}" "openfoam:$reference" \
  | xargs -P "$(nproc)" -I{} sh -c 'exec bash openfoam/run_case.sh "$1/$(echo "$2" | tr : _)" "$2" "$3"' _ "$runs" {} "$steps"
echo "fluidbed: $((SECONDS - start)) s for the $((${#laws[@]} + 1)) runs on $(nproc) cores"
cases=()
for law in "${laws[@]}"; do cases+=("$law=$runs/$law"); done
cases+=(--reference "OpenFOAM $reference=$runs/openfoam_$reference")
python3 openfoam/demo/bed_history.py "$plots" "${cases[@]}"
gnuplot "$plots/openfoam_fluidised_bed.gp"
echo "fluidbed: $plots/openfoam_fluidised_bed.png"
