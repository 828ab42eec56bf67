#!/usr/bin/env bash
# Builds and runs the whole test suite: a debug build with warnings as errors, then the
# same suite under AddressSanitizer + UndefinedBehaviorSanitizer, and checks that the
# reference tables in tests/reference/ are exactly what their mpmath generators produce.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
jobs=$(nproc)

echo "== reference tables: regenerate with mpmath and compare"
for generator in tests/reference/*_reference.py; do /usr/bin/python3 "$generator"; done
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git diff --exit-code --stat -- tests/reference || { echo "reference tables differ from their generators"; exit 1; }
fi

for config in debug sanitize; do
  echo "== tests: $config build"
  options=(-DCMAKE_BUILD_TYPE=Debug -DFLUIDBED_BUILD_TESTS=ON -DFLUIDBED_BUILD_EXAMPLES=ON)
  [ "$config" = sanitize ] && options+=(-DFLUIDBED_SANITIZE=ON)
  cmake -S . -B "build/$config" -G Ninja "${options[@]}" >/dev/null
  cmake --build "build/$config" -j "$jobs"
  ctest --test-dir "build/$config" -j "$jobs" --output-on-failure
done
