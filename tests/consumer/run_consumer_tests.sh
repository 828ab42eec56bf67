#!/usr/bin/env bash
# Builds tests/consumer against fluidbed in every supported way and runs it:
#   package       cmake --install of the source tree into a private prefix, then
#                 find_package(fluidbed 0.1 CONFIG REQUIRED)
#   subdirectory  add_subdirectory(<source tree>)
#   fetchcontent  FetchContent_Declare(fluidbed SOURCE_DIR <source tree>)
#   pkg-config    g++ $(pkg-config --cflags fluidbed) against the installed prefix
# Usage: run_consumer_tests.sh <fluidbed source dir> <scratch dir>
set -euo pipefail
source_dir=$(cd "$1" && pwd)
work=$2
rm -rf "$work"
mkdir -p "$work"
consumer="$source_dir/tests/consumer"
prefix="$work/prefix"

echo "== install into $prefix"
cmake -S "$source_dir" -B "$work/fluidbed" -G Ninja -DFLUIDBED_BUILD_TESTS=OFF -DFLUIDBED_BUILD_EXAMPLES=OFF \
      -DCMAKE_INSTALL_PREFIX="$prefix" >/dev/null
cmake --install "$work/fluidbed" >/dev/null
test -f "$prefix/include/fluidbed/fluidbed.hpp"
test -f "$prefix/share/cmake/fluidbed/fluidbedConfigVersion.cmake"

for way in package subdirectory fetchcontent; do
  echo "== consumer: $way"
  where=(-DCMAKE_PREFIX_PATH="$prefix")
  [ $way = package ] || where=(-DFLUIDBED_SOURCE_DIR="$source_dir")
  cmake -S "$consumer" -B "$work/$way" -G Ninja -DFLUIDBED_CONSUME=$way "${where[@]}" >/dev/null
  cmake --build "$work/$way" >/dev/null
  "$work/$way/consumer"
done

echo "== consumer: a version the package does not satisfy is refused"
mkdir -p "$work/too_new_src"
sed 's/find_package(fluidbed 0.1 /find_package(fluidbed 9.0 /' "$consumer/CMakeLists.txt" > "$work/too_new_src/CMakeLists.txt"
cp "$consumer/main.cpp" "$work/too_new_src/"
if cmake -S "$work/too_new_src" -B "$work/too_new_build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null 2>&1; then
  echo "find_package(fluidbed 9.0) accepted version 0.1" >&2
  exit 1
fi

echo "== consumer: pkg-config"
PKG_CONFIG_PATH="$prefix/share/pkgconfig" pkg-config --exists --print-errors fluidbed
# shellcheck disable=SC2046
g++ $(PKG_CONFIG_PATH="$prefix/share/pkgconfig" pkg-config --cflags fluidbed) "$consumer/main.cpp" -o "$work/pkgconfig_consumer"
"$work/pkgconfig_consumer"
echo "consumer tests passed"
