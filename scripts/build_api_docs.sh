#!/usr/bin/env bash
# Builds fluidbed's API reference with Doxygen (docs/Doxyfile) into build/api/html; open
# build/api/html/index.html. Installs Debian's doxygen, graphviz (include graphs) and
# libjs-mathjax (the catalogue's formulas) if they are missing, as
# scripts/install_dependencies.sh does. Fails if Doxygen reports any warning: they are in
# build/api/doxygen_warnings.log (a broken reference, a comment Doxygen cannot parse).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(doxygen graphviz libjs-mathjax python3)
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

rm -rf build/api
mkdir -p build/api
status=0
doxygen docs/Doxyfile || status=$?  # WARN_AS_ERROR = FAIL_ON_WARNINGS
warnings=build/api/doxygen_warnings.log
if [ "$status" -ne 0 ] || [ -s "$warnings" ]; then
  echo "Doxygen failed (status $status); warnings ($warnings):"
  cat "$warnings"
  exit 1
fi
echo "API reference: $(pwd)/build/api/html/index.html"
