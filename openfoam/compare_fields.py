#!/usr/bin/env python3
"""Largest differences between the cell values of OpenFOAM fields in two time folders.

Usage: compare_fields.py DIR_A DIR_B FIELD[*WEIGHT][:TOLERANCE] ...

For each field (an ASCII volScalarField or volVectorField file present in both folders) prints
the largest absolute difference of its internal values (all vector components together) and the
largest absolute value in DIR_A. FIELD*WEIGHT compares the field times a scalar field, each run's
own (e.g. U.particles*alpha.particles, the particle volume flux, which is defined where the
particle velocity is not). With a tolerance, exits 1 when the difference exceeds it.
Python 3 standard library only.
"""

import gzip
import re
import sys
from pathlib import Path


def internal_values(path):
    """The internal values of the field file `path`, or of `path`.gz (writeCompression on)."""
    path = Path(path)
    text = path.read_text() if path.exists() else gzip.decompress(Path(f"{path}.gz").read_bytes()).decode()
    start = text.index("internalField")
    uniform = re.match(r"internalField\s+uniform\s+(\([^)]*\)|\S+?);", text[start:])
    if uniform:
        return [float(x) for x in uniform.group(1).strip("()").split()]
    header = re.match(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text[start:])
    count, body = int(header.group(2)), text[start + header.end():]
    if header.group(1) == "scalar":
        return [float(x) for x in body.split(None, count)[:count]]
    return [float(x) for vector in re.findall(r"\(([^()]*)\)", body)[:count] for x in vector.split()]


def weighted(values, weights):
    per_cell = len(values) // len(weights)
    return [x * weights[i // per_cell] for i, x in enumerate(values)]


def differences(folder_a, folder_b, name):
    """Cell-by-cell |a - b| of field `name` (FIELD or FIELD*WEIGHT) between two time folders, and the
    values in folder_a."""
    field, _, weight = name.partition("*")
    a, b = (internal_values(Path(folder) / field) for folder in (folder_a, folder_b))
    if weight:
        a, b = (weighted(values, internal_values(Path(folder) / weight))
                for values, folder in ((a, folder_a), (b, folder_b)))
    if len(a) != len(b):
        sys.exit(f"{name}: {len(a)} values against {len(b)}")
    return [abs(x - y) for x, y in zip(a, b)], a


def root_mean_square(values):
    return (sum(v * v for v in values) / len(values)) ** 0.5


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    failed = False
    for spec in argv[3:]:
        name, _, tolerance = spec.partition(":")
        cell_differences, a = differences(argv[1], argv[2], name)
        difference = max(cell_differences)
        verdict = ""
        if tolerance:
            failed |= difference > float(tolerance)
            verdict = " FAILS" if difference > float(tolerance) else " ok"
        print(f"{name}: max |difference| {difference:.3e}, max |value| {max(map(abs, a)):.3e}{verdict}")
    return 1 if failed else 0

if __name__ == "__main__":
    sys.exit(main(sys.argv))
