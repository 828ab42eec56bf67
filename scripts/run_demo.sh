#!/usr/bin/env bash
# Builds and runs the main demonstration: homogeneous bed expansion of the three
# liquid-fluidized systems of Mazzei's thesis (seed 000 Table 4.4), computed from the
# Richardson–Zaki, Wen–Yu, Ergun and Mazzei–Lettieri closures, and the minimum bubbling
# voidage of its fifteen Geldart A powders (Table 4.6) from three stability criteria, each
# printed beside the thesis's values; the stability functions of one powder are plotted
# (PNG, gnuplot) into build/release/plots.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLUIDBED_BUILD_TESTS=OFF -DFLUIDBED_BUILD_EXAMPLES=ON >/dev/null
cmake --build build/release -j "$(nproc)" --target bed_expansion_table_4_4 minimum_bubbling_table_4_6
./build/release/examples/bed_expansion_table_4_4
echo
mkdir -p build/release/plots
./build/release/examples/minimum_bubbling_table_4_6 build/release/plots
