#!/usr/bin/env bash
# Every public header, included from a C++17 translation unit, must either compile or stop with
# core/config.hpp's message naming C++20 as the FIRST error (not hundreds of errors from the first
# C++20 construct). Checked with g++ and clang++ (where installed).
# Usage: check_cxx20_required.sh <fluidbed source dir> <scratch dir>
set -euo pipefail
source_dir=$(cd "$1" && pwd)
work=$2
mkdir -p "$work"
eigen_flags=$(pkg-config --cflags eigen3 2>/dev/null || echo -I/usr/include/eigen3)
failures=0
checked=0
for compiler in g++ clang++; do
  command -v "$compiler" >/dev/null || { echo "$compiler not installed: not checked"; continue; }
  while IFS= read -r header; do
    printf '#include <%s>\n' "$header" >"$work/tu.cpp"
    # shellcheck disable=SC2086
    if "$compiler" -std=c++17 -fsyntax-only -I"$source_dir/include" $eigen_flags "$work/tu.cpp" >"$work/out.txt" 2>&1; then
      checked=$((checked + 1))
      continue
    fi
    first_error=$(grep -m1 -E "error:" "$work/out.txt" || true)
    if [[ $first_error != *"fluidbed needs C++20"* ]]; then
      echo "$compiler, $header: the first error is not fluidbed's C++20 message: $first_error"
      failures=$((failures + 1))
    fi
    checked=$((checked + 1))
  done < <(cd "$source_dir/include" && find fluidbed -name '*.hpp' | sort)
done
echo "$checked header compilations checked, $failures without the C++20 message first"
[ "$failures" -eq 0 ]
