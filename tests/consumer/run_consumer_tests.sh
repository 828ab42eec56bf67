#!/usr/bin/env bash
# Builds tests/consumer against fluidbed in every supported way and runs it:
#   package       configured with the defaults and built (the C interface and the Fortran module are
#                 compiled, and the OpenFOAM plugin where OpenFOAM is found), then
#                 `cmake --install build --prefix P` (the prefix chosen at install time, not at
#                 configure time), the tree then moved elsewhere, and
#                 find_package(fluidbed 0.1 CONFIG REQUIRED) from the new place, for the C++
#                 consumer and a C program through fluidbed::fluidbed_c
#   subdirectory  add_subdirectory(<source tree>)
#   fetchcontent  FetchContent_Declare(fluidbed SOURCE_DIR <source tree>)
#   pkg-config    g++ $(pkg-config --cflags fluidbed) against the moved prefix (the .pc file
#                 must be relocatable), and gcc with pkg-config's fluidbed_c for the C program
#   Fortran       gfortran with the installed module fluidbed.mod and libraries (where built)
#   drag only     configured and installed as on a machine with none of the optional packages
#                 (no doctest, no Boost, no Eigen), then the drag + kinetic-theory consumer built
#                 against it; the compiler's include trace must show neither Boost nor Eigen
# Usage: run_consumer_tests.sh <fluidbed source dir> <scratch dir>
set -euo pipefail
source_dir=$(cd "$1" && pwd)
work=$2
rm -rf "$work"
mkdir -p "$work"
consumer="$source_dir/tests/consumer"

echo "== configure with the defaults, build, install with --prefix, move the installed tree"
cmake -S "$source_dir" -B "$work/fluidbed" -G Ninja -DFLUIDBED_BUILD_TESTS=OFF -DFLUIDBED_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$work/fluidbed" >/dev/null
cmake --install "$work/fluidbed" --prefix "$work/installed_here" >/dev/null
mv "$work/installed_here" "$work/moved_there"
prefix="$work/moved_there"
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
# The C program found fluidbed::fluidbed_c in the moved package and runs with the library there.
LD_LIBRARY_PATH="$(dirname "$(ls "$prefix"/lib*/libfluidbed_c.so)")" "$work/package/c_consumer"

echo "== consumer: a version the package does not satisfy is refused"
mkdir -p "$work/too_new_src"
sed 's/find_package(fluidbed 0.1 /find_package(fluidbed 9.0 /' "$consumer/CMakeLists.txt" > "$work/too_new_src/CMakeLists.txt"
cp "$consumer/main.cpp" "$work/too_new_src/"
if cmake -S "$work/too_new_src" -B "$work/too_new_build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null 2>&1; then
  echo "find_package(fluidbed 9.0) accepted version 0.1" >&2
  exit 1
fi

echo "== consumer: pkg-config from the moved prefix"
export PKG_CONFIG_PATH="$prefix/share/pkgconfig"
pkg-config --exists --print-errors fluidbed
cflags=$(pkg-config --cflags fluidbed)
case " $cflags " in
  *" -I$prefix/"*) ;;
  *) echo "pkg-config --cflags fluidbed does not point into the moved prefix $prefix: $cflags" >&2; exit 1 ;;
esac
# shellcheck disable=SC2086
g++ $cflags "$consumer/main.cpp" -o "$work/pkgconfig_consumer"
"$work/pkgconfig_consumer"
# shellcheck disable=SC2046
gcc -std=c11 $(pkg-config --cflags fluidbed_c) "$source_dir/tests/c/drag_from_c.c" $(pkg-config --libs fluidbed_c) -lm \
    -o "$work/pkgconfig_c_consumer"
LD_LIBRARY_PATH="$(pkg-config --variable=libdir fluidbed_c)" "$work/pkgconfig_c_consumer"

if [ -f "$prefix/include/fluidbed.mod" ]; then
  echo "== consumer: the Fortran module from the moved prefix (the MFiX-shaped example)"
  libdir=$(dirname "$(ls "$prefix"/lib*/libfluidbed_c.so)")
  gfortran -I"$prefix/include" -J "$work" "$source_dir/examples/fortran/mfix_usr_drag.f90" -L"$libdir" -lfluidbed_fortran \
           -lfluidbed_c -o "$work/fortran_consumer"
  LD_LIBRARY_PATH="$libdir" "$work/fortran_consumer" | tail -1
fi

echo "== consumer: drag and kinetic theory only, on a machine without doctest, Boost or Eigen"
cmake -S "$source_dir" -B "$work/minimal" -G Ninja -DCMAKE_DISABLE_FIND_PACKAGE_doctest=ON \
      -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON >"$work/minimal.log"
cmake --build "$work/minimal" >/dev/null
cmake --install "$work/minimal" --prefix "$work/minimal_prefix" >/dev/null
if grep -q "eigen3" "$work/minimal_prefix/share/pkgconfig/fluidbed.pc"; then
  echo "the pkg-config file of a build without Eigen requires eigen3" >&2
  exit 1
fi
cmake -S "$consumer" -B "$work/minimal_package" -G Ninja -DFLUIDBED_CONSUME=package \
      -DCMAKE_PREFIX_PATH="$work/minimal_prefix" >/dev/null
cmake --build "$work/minimal_package" >/dev/null
"$work/minimal_package/consumer"
# -H lists every header the translation unit opens: none may come from Boost or Eigen.
g++ -std=c++20 -H -fsyntax-only -I"$work/minimal_prefix/include" "$consumer/main.cpp" 2>"$work/minimal_headers.txt"
if grep -E "/(boost|eigen3)/" "$work/minimal_headers.txt"; then
  echo "the drag and kinetic-theory headers include Boost or Eigen (above)" >&2
  exit 1
fi
echo "consumer tests passed"
