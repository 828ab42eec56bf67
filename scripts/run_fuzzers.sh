#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang++ (AddressSanitizer + UndefinedBehaviorSanitizer)
# and runs each, one after the other, for a bounded time from the committed seed corpus. A crash, a
# sanitizer report or a contract violation fails the script; the input that caused it is left in
# build/fuzz/artifacts/ (replay: build/fuzz/fuzz/<fuzzer> <that file>).
#
#   bash scripts/run_fuzzers.sh [seconds per fuzzer]     default: $FLUIDBED_FUZZ_SECONDS, else 60
#
# A target named in FLUIDBED_FUZZ_REPLAY_ONLY (space-separated) only replays its committed seeds:
# for a target whose open contract violations are being fixed, so that CI still checks the seeds.
#
# Needs clang and libclang-rt-dev (libFuzzer's runtime) besides the usual build dependencies.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-${FLUIDBED_FUZZ_SECONDS:-60}}
build=build/fuzz
fuzzers=(moment_inversion_fuzzer drag_fuzzer)

if ! command -v clang++ >/dev/null; then
  echo "run_fuzzers.sh: clang++ not found (Debian: apt-get install clang libclang-rt-dev)" >&2
  exit 1
fi
echo "== fuzzers: build ($build)"
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DFLUIDBED_BUILD_FUZZERS=ON -DFLUIDBED_WARNINGS_AS_ERRORS=ON \
  -DFLUIDBED_BUILD_TESTS=OFF \
  -DFLUIDBED_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target "${fuzzers[@]}"

mkdir -p "$build/artifacts"
status=0
for fuzzer in "${fuzzers[@]}"; do
  if [[ " ${FLUIDBED_FUZZ_REPLAY_ONLY:-} " == *" $fuzzer "* ]]; then
    echo "== $fuzzer: replaying the committed seeds only (FLUIDBED_FUZZ_REPLAY_ONLY)"
    "$build/fuzz/$fuzzer" -runs=0 "fuzz/corpus/$fuzzer" >"$build/$fuzzer.log" 2>&1 || { tail -n 40 "$build/$fuzzer.log"; status=1; }
    continue
  fi
  echo "== $fuzzer: $seconds s"
  # New inputs go to the first corpus directory (build/, kept between local runs); the committed
  # seeds are only read.
  corpus="$build/corpus/$fuzzer"
  log="$build/$fuzzer.log"
  mkdir -p "$corpus"
  if "$build/fuzz/$fuzzer" -max_total_time="$seconds" -timeout=30 -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$fuzzer-" "$corpus" "fuzz/corpus/$fuzzer" >"$log" 2>&1; then
    executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    coverage=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -n 1)
    echo "$fuzzer: $executions executions in $seconds s ($rate/s), $coverage"
  else
    tail -n 40 "$log"
    echo "$fuzzer: FAILED (log: $log; input: $build/artifacts/$fuzzer-*)" >&2
    status=1
  fi
done
exit $status
