#!/usr/bin/env bash
# Builds and runs the demonstration: every example program (examples/*.cpp). Each recomputes
# a published table or figure with the library, prints it beside the published values and
# checks the agreement (it exits non-zero if a check fails):
#   bed_expansion_table_4_4          seed 000 Table 4.4: homogeneous bed expansion of three
#                                    liquid-fluidized systems (Richardson–Zaki, Wen–Yu, Ergun,
#                                    Mazzei–Lettieri)
#   minimum_bubbling_table_4_6       seed 000 Table 4.6: minimum bubbling voidage of fifteen
#                                    Geldart A powders from three stability criteria; both roots
#                                    of the stability functions of powder 1
#   voidage_ratio_vs_reynolds        ε_law/ε_R&Z against Re for Ergun, Wen–Yu, Di Felice and
#                                    Mazzei–Lettieri (the quantity of seed 000 Figs 3.1–3.3, 3.5)
#   elastic_modulus_vs_reynolds      ψ_e and the equivalent exponents of four laws against Re (the
#                                    model curves of seed 000 Figs 3.4, 3.6), E_r^e/E_j (eq. 3.112)
#   drag_laws_vs_voidage             every drag law against ε, FCC in air and glass in water, with
#                                    validity ranges and homogeneous-bed voidages
#   quadrature_vs_size_distribution  2-, 3-, 4-node quadratures of a log-normal and a sieve PSD
#   seed003_tables_1_2               seed 003 Tables 1–2: moments and published quadratures, and
#                                    the band of rules the printed digits allow
#   inversion_error_estimate         the error estimate of Gauss rules (2–10 nodes, double and
#                                    float) against the error measured with 50 digits
# the Python example (examples/python/voidage_ratio.py): the same quantity through the Python
# package, in the few lines of NumPy and Matplotlib a user would write;
# and the OpenFOAM demonstration (scripts/run_openfoam_demo.sh): OpenFOAM's fluidisedBed tutorial
# with four drag laws through the plugin, pressure drop and bed height against time.
# The plots (PNG, with their gnuplot scripts and data) are written to build/release/plots and
# listed at the end. Each script redraws its PNG from any directory (gnuplot /path/to/x.gp);
# the demo checks that on a copy of the directory.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLUIDBED_BUILD_TESTS=OFF -DFLUIDBED_BUILD_EXAMPLES=ON >/dev/null
examples=()
for source in examples/*.cpp; do examples+=("$(basename "$source" .cpp)"); done
cmake --build build/release -j "$(nproc)" --target "${examples[@]}"

plots=build/release/plots
rm -rf "$plots"
mkdir -p "$plots"
failed=()
for example in "${examples[@]}"; do
  echo
  echo "==== $example"
  ./build/release/examples/"$example" "$plots" || failed+=("$example")
done

echo
echo "==== Python: the voidage ratio of four drag laws (examples/python/voidage_ratio.py)"
cmake -S . -B build/release -DFLUIDBED_BUILD_PYTHON=ON >/dev/null
cmake --build build/release -j "$(nproc)" --target fluidbed_python
PYTHONPATH=build/release/python /usr/bin/python3 examples/python/voidage_ratio.py "$plots" || failed+=("Python example")

echo
echo "==== OpenFOAM: the fluidisedBed tutorial with four drag laws"
bash scripts/run_openfoam_demo.sh build/release "$plots" || failed+=("OpenFOAM demonstration")

# Every script must redraw its picture beside itself when run from elsewhere (here /, on a copy
# of the directory whose PNGs were removed), without a gnuplot warning.
copy=$(mktemp -d)
trap 'rm -rf "$copy"' EXIT
cp "$plots"/*.gp "$plots"/*.dat "$copy"/
for script in "$copy"/*.gp; do
  name=$(basename "$script" .gp)
  messages=$(cd / && gnuplot "$script" 2>&1) || true
  if [ -n "$messages" ] || [ ! -s "$copy/$name.png" ]; then
    echo "gnuplot $plots/$name.gp does not redraw $name.png from another directory:${messages:+ $messages}"
    failed+=("$name.gp")
  fi
done

echo
echo "==== API reference (Doxygen)"
bash scripts/build_api_docs.sh || failed+=("API reference")

echo
echo "Pictures: $plots/*.png"
for png in "$plots"/*.png; do [ -e "$png" ] && echo "  $png"; done
if ((${#failed[@]})); then
  echo "FAILED: ${failed[*]}"
  exit 1
fi
echo "All ${#examples[@]} examples reproduce their references within the stated tolerances;"
echo "every plot script redraws its picture from any directory."
