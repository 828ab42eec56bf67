#!/usr/bin/env bash
# Builds the microbenchmarks with optimisation and runs them; prints ns per cell and the
# ratio of every drag law to Wen–Yu, of every moment-inversion path to a generic (dynamic
# Eigen, dense eigen-solver) baseline, of drag + elastic force to the drag alone, and of
# the kinetic-theory set per cell to the Wen–Yu drag, each measured in the same run. Extra
# arguments go to Google Benchmark (e.g. --benchmark_filter=Mazzei).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLUIDBED_BUILD_TESTS=OFF -DFLUIDBED_BUILD_EXAMPLES=OFF \
      -DFLUIDBED_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build/bench -j "$(nproc)"
./build/bench/bench/fluidbed_drag_bench --benchmark_repetitions=5 "$@"
./build/bench/bench/fluidbed_moments_bench --benchmark_repetitions=5 "$@"
./build/bench/bench/fluidbed_elastic_bench --benchmark_repetitions=5 "$@"
./build/bench/bench/fluidbed_kinetic_theory_bench --benchmark_repetitions=5 "$@"
