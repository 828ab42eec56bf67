#!/usr/bin/env bash
# Builds fluidbed's API reference with Doxygen (docs/Doxyfile) into build/api/html; open
# build/api/html/index.html. Installs what it needs first (scripts/install_dependencies.sh:
# Debian's doxygen, graphviz for the include graphs, libjs-mathjax for the formulas). Fails if Doxygen reports any warning: they are in
# build/api/doxygen_warnings.log (a broken reference, a comment Doxygen cannot parse).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh

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
