#!/usr/bin/env bash
# Installs what the OpenFOAM plugin (openfoam/) needs, from Debian only:
#  - the binary packages openfoam, libopenfoam, openfoam-examples (OpenFOAM v1912), which ship
#    the solvers, the libraries and the tutorials but no headers;
#  - the headers, from Debian's source package of the same version (apt-get source), unpacked
#    into FLUIDBED_OPENFOAM_SRC (default /opt/fluidbed-openfoam), with the lnInclude folders
#    that a dragModel plugin's include path needs, made by the tree's own wmakeLnInclude.
# Idempotent: each step is skipped when its result is already there. Run as root (or with sudo).
set -euo pipefail

cache=${FLUIDBED_OPENFOAM_SRC:-/opt/fluidbed-openfoam}
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"

packages=(openfoam libopenfoam openfoam-examples dpkg-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# apt-get source needs a deb-src entry; derive it from the machine's own Debian sources
# (deb822 or one-line format) so that the same mirror and suites are used.
src_list=/etc/apt/sources.list.d/fluidbed-deb-src.sources
need_update=0
if ! apt-get indextargets --format '$(IDENTIFIER)' 2>/dev/null | grep -qx Sources; then
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed -e 's/^Types:.*/Types: deb-src/' /etc/apt/sources.list.d/debian.sources | $sudo tee "$src_list" >/dev/null
  else
    grep -hE '^deb +[^[]*debian' /etc/apt/sources.list | sed -e 's/^deb /deb-src /' \
      | $sudo tee "${src_list%.sources}.list" >/dev/null
  fi
  need_update=1
fi
if ((${#missing[@]})) || ((need_update)); then
  $sudo apt-get update -qq
fi
if ((${#missing[@]})); then
  echo "fluidbed: installing ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

version=$(dpkg-query -W -f='${source:Upstream-Version}' openfoam)
tree="$cache/openfoam-$version"
if [ ! -d "$tree/src/OpenFOAM" ]; then
  $sudo mkdir -p "$cache"
  echo "fluidbed: fetching the source of openfoam $version into $cache"
  (cd "$cache" && $sudo apt-get source -qq "openfoam=$(dpkg-query -W -f='${source:Version}' openfoam)" >/dev/null)
fi

# The folders whose headers a Foam::dragModel plugin includes (directly or transitively).
ln_dirs=(
  src/OpenFOAM
  src/OSspecific/POSIX
  src/finiteVolume
  src/meshTools
  src/transportModels/compressible
  src/thermophysicalModels/basic
  src/thermophysicalModels/specie
  src/TurbulenceModels/turbulenceModels
  src/TurbulenceModels/compressible
  src/TurbulenceModels/phaseCompressible
  applications/solvers/multiphase/twoPhaseEulerFoam/twoPhaseSystem
  applications/solvers/multiphase/twoPhaseEulerFoam/interfacialModels
  applications/solvers/multiphase/twoPhaseEulerFoam/phaseCompressibleTurbulenceModels
)
for d in "${ln_dirs[@]}"; do
  if [ ! -d "$tree/$d/lnInclude" ]; then
    (cd "$tree/$d" && $sudo env WM_PROJECT_DIR="$tree" "$tree/wmake/wmakeLnInclude" -s .)
  fi
done
echo "fluidbed: OpenFOAM $version headers in $tree"
