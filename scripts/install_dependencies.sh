#!/usr/bin/env bash
# Installs the Debian packages fluidbed's build, tests, benchmarks and reference
# generators need (clang and libclang-rt-dev: libFuzzer for fuzz/ and the sanitizer build; doxygen,
# graphviz and libjs-mathjax: the API reference; gfortran: the Fortran module over the C
# interface; pybind11-dev, python3-numpy, python3-pytest, python3-matplotlib: the Python package,
# its tests and its example), skipping those already present. Run as root (or with sudo available).
set -euo pipefail

packages=(cmake ninja-build g++ libeigen3-dev libboost-dev libboost-math-dev doctest-dev libbenchmark-dev
          python3 python3-mpmath gnuplot-nox pkgconf clang libclang-rt-dev doxygen graphviz libjs-mathjax gfortran
          pybind11-dev python3-numpy python3-pytest python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "fluidbed: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
