#!/usr/bin/env bash
# Builds the microbenchmarks with optimisation and runs them; prints ns per cell and the
# ratio of every law to Wen–Yu measured in the same run. Extra arguments go to Google
# Benchmark (e.g. --benchmark_filter=Mazzei).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLUIDBED_BUILD_TESTS=OFF -DFLUIDBED_BUILD_EXAMPLES=OFF \
      -DFLUIDBED_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build/bench -j "$(nproc)"
./build/bench/bench/fluidbed_drag_bench --benchmark_repetitions=5 "$@"
