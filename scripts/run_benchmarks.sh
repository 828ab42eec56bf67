#!/usr/bin/env bash
# Builds the microbenchmarks with optimisation and runs them; prints ns per cell and the
# ratio of every drag law to Wen–Yu, of every moment-inversion path to a generic (dynamic
# Eigen, dense eigen-solver) baseline, of drag + elastic force to the drag alone, of the
# kinetic-theory set per cell to the Wen–Yu drag, of the batched DQMOM solve to a dense LU per
# cell, of the C interface over a field to the C++ loop over it, and of the Python package to
# the C interface, each measured in the same run. Extra arguments go to Google Benchmark (e.g.
# --benchmark_filter=Mazzei).
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
./build/bench/bench/fluidbed_dqmom_bench --benchmark_repetitions=5 "$@"
./build/bench/bench/fluidbed_bindings_bench --benchmark_repetitions=5 "$@"
/usr/bin/python3 bench/bindings_python.py build/bench
