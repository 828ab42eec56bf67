#!/usr/bin/env bash
# Installs the Python package fluidbed for Debian's python3 on this machine: the Debian packages it
# needs (scripts/install_dependencies.sh: pybind11, NumPy), a Release build of the package, and
# `cmake --install --component python` into python3's local site directory
# (/usr/local/lib/python3.X/dist-packages). Then `python3 -c "import fluidbed"` works anywhere.
# Run as root (or with sudo available). For development, PYTHONPATH=BUILD/python imports the
# package from any build folder without installing it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
build=build/python-install
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLUIDBED_BUILD_TESTS=OFF -DFLUIDBED_BUILD_EXAMPLES=OFF \
      -DFLUIDBED_BUILD_OPENFOAM=OFF -DFLUIDBED_BUILD_FORTRAN=OFF -DFLUIDBED_BUILD_PYTHON=ON >/dev/null
cmake --build "$build" --target fluidbed_python
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo cmake --install "$build" --component python
cd /
/usr/bin/python3 -c "import fluidbed; print('fluidbed for Python:', fluidbed.__file__, '-', len(fluidbed.closure_names()), 'closures')"
