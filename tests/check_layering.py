#!/usr/bin/env python3
"""Keeps the folders of include/fluidbed/ layered without cycles.

Usage: check_layering.py [PROJECT_ROOT]   (default: the parent of this file's folder)

Each folder (and each umbrella header at the top) has a layer; a header may include headers of
its own folder and of lower layers only, and may call `<namespace>::detail::` only for its own
family's namespace or core's (`fluidbed::detail`, `fluidbed::numbers::detail`). Every `throw` of the library, and
`#include <stdexcept>`, is in core/errors.hpp, the host-only header of the checked entry points
(device code, compiled by tests/cuda/, never reaches it). No header calls std::isnormal, which
nvcc compiles to false in device code. Fails (exit 1, listing every
violation) otherwise, and when a folder exists that LAYERS does not place. Python 3 standard
library only.
"""

import re
import sys
from pathlib import Path

# Lowest first. A folder may use the folders before it.
LAYERS = [
    ("core",),
    ("properties.hpp",),
    ("single_particle", "moments", "interaction"),
    ("settling", "kinetic_theory"),
    ("drag",),
    ("fluidization",),
    ("elastic",),
    ("polydisperse",),
    ("umbrellas",),
]
LEVEL = {name: level for level, names in enumerate(LAYERS) for name in names}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
DETAIL_CALL = re.compile(r"\b(\w+)::detail::")
THROWING = re.compile(r"\bthrow\b|#\s*include\s*<stdexcept>")
THROWING_HEADER = Path("core") / "errors.hpp"
# Standard functions nvcc compiles wrongly in device code without a diagnostic: std::isnormal is
# constant false there (core/config.hpp has fluidbed::detail::is_normal instead).
DEVICE_UNSAFE = re.compile(r"\bisnormal\b")


def unit_of(path, include_dir):
    """The folder of a header (its first path component), or 'properties.hpp', or 'umbrellas'."""
    parts = path.relative_to(include_dir).parts
    if len(parts) == 1:
        return "properties.hpp" if parts[0] == "properties.hpp" else "umbrellas"
    return parts[0]


def main():
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
    include_dir = root / "include" / "fluidbed"
    problems = []
    for header in sorted(include_dir.rglob("*.hpp")):
        unit = unit_of(header, include_dir)
        if unit not in LEVEL:
            problems.append(f"{header.relative_to(root)}: folder '{unit}' has no layer in check_layering.py")
            continue
        text = header.read_text(encoding="utf-8")
        for target in INCLUDE.findall(text):
            resolved = (header.parent / target).resolve()
            if include_dir.resolve() not in resolved.parents:
                continue  # not a fluidbed header
            target_unit = unit_of(resolved, include_dir.resolve())
            if target_unit != unit and LEVEL.get(target_unit, 99) >= LEVEL[unit]:
                problems.append(f"{header.relative_to(root)} ({unit}) includes {target} ({target_unit}): "
                                "not a lower layer")
        code = re.sub(r"//[^\n]*", "", text)
        if header.relative_to(include_dir) != THROWING_HEADER and THROWING.search(code):
            problems.append(f"{header.relative_to(root)} throws or includes <stdexcept>: "
                            f"only {THROWING_HEADER.as_posix()} may (the checked paths call its helpers)")
        if DEVICE_UNSAFE.search(code):
            problems.append(f"{header.relative_to(root)} uses isnormal, which nvcc makes false in device code: "
                            "use fluidbed::detail::is_normal (core/config.hpp)")
        if unit != "umbrellas":
            for namespace in set(DETAIL_CALL.findall(code)):
                if namespace not in ("fluidbed", "numbers", unit):  # fluidbed::numbers is core's too
                    problems.append(f"{header.relative_to(root)} ({unit}) calls {namespace}::detail:: "
                                    "of another family")
    if problems:
        print(f"layering check FAILED ({len(problems)} problems):")
        for problem in problems:
            print("  " + problem)
        return 1
    print(f"layering OK: {len(LAYERS)} layers, no include of a higher or equal layer, no cross-family detail:: call, "
          f"no throw outside {THROWING_HEADER.as_posix()}, no isnormal")
    return 0


if __name__ == "__main__":
    sys.exit(main())
