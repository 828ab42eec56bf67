#!/usr/bin/env bash
# Compiles a translation unit the way a host code does: -Wall -Wextra -Wpedantic -Werror at
# -O2 -DNDEBUG and at -O3 -march=native, with the headers (Eigen's too) found by -I as pkg-config
# gives them rather than -isystem, so that a warning in any header it reaches is an error.
# tests/test_moment_types.cpp reaches every public moments function, the batched and Eigen
# backends included.
# Usage: check_user_flags.sh <fluidbed source dir> <compiler> <source file>
set -euo pipefail
source_dir=$(cd "$1" && pwd)
compiler=$2
source=$3
command -v "$compiler" >/dev/null || { echo "skipped: $compiler is not installed"; exit 77; }
eigen_flags=$(pkg-config --cflags eigen3 2>/dev/null || echo -I/usr/include/eigen3)
for flags in "-O2 -DNDEBUG" "-O3 -march=native"; do
  echo "== $compiler $flags $source"
  # shellcheck disable=SC2086
  "$compiler" -std=c++20 $flags -Wall -Wextra -Wpedantic -Werror -I"$source_dir/include" $eigen_flags \
    -DFLUIDBED_REFERENCE_DIR='""' -c "$source" -o /dev/null  # -c: the optimizer's warnings too
done
echo "compiles clean at every flag set"
