#!/usr/bin/env python3
"""Cost of the Python package over a field of a million cells, against the C interface called on
the same NumPy arrays through ctypes in the same process (which bench/bindings_bench.cpp measures
against the C++ loop): ns per cell and the ratio, for three drag laws, float64 and float32, value
and derivatives. The fastest of REPEATS runs of each.

Usage: bindings_python.py BUILD_DIR [REPEATS]   (BUILD_DIR/python holds the package, and the C
interface is BUILD_DIR/bindings/c/libfluidbed_c.so)
"""
import ctypes
import sys
import time
from pathlib import Path

build = Path(sys.argv[1])
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 7
sys.path.insert(0, str(build / "python"))
import numpy as np  # noqa: E402

import fluidbed  # noqa: E402

C = ctypes.CDLL(str(build / "bindings" / "c" / "libfluidbed_c.so"))
cells = 1 << 20
i = np.arange(cells)
voidage = 0.36 + 0.639 * ((i * 7919) % cells) / cells
slip = 1e-5 * 1e6 ** (((i * 104729) % cells) / cells)
density, viscosity, diameter = (np.full(cells, x) for x in (1.2, 1.8e-5, 3e-4))


def fastest(f):
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - start)
    return best * 1e9 / cells


print(f"{'law':<16} {'dtype':<8} {'derivatives':<12} {'C interface ns':>15} {'Python ns':>10} {'ratio':>6}")
for name in ("WenYu1966", "MazzeiLettieri", "Beetstra"):
    law = fluidbed.closure(name)
    handle = ctypes.c_void_p()
    C.fluidbed_closure_create(name.encode(), ctypes.byref(handle), None)
    for dtype, function, ctype in ((np.float64, C.fluidbed_drag, ctypes.c_double),
                                   (np.float32, C.fluidbed_drag_f, ctypes.c_float)):
        arrays = [a.astype(dtype) for a in (voidage, slip, density, viscosity, diameter)]
        outputs = [np.empty(cells, dtype) for _ in range(4)]
        pointer = ctypes.POINTER(ctype)
        for derivatives in (False, True):
            wanted = outputs if derivatives else outputs[:1] + [None] * 3
            c_arguments = [a.ctypes.data_as(pointer) for a in arrays] + [
                None if o is None else o.ctypes.data_as(pointer) for o in wanted]
            c_ns = fastest(lambda: function(handle, 1, ctypes.c_size_t(cells), *c_arguments, None))
            python_ns = fastest(lambda: law.beta(*arrays, convention="pressure_gradient", derivatives=derivatives))
            print(f"{name:<16} {np.dtype(dtype).name:<8} {str(derivatives):<12} {c_ns:>15.2f} {python_ns:>10.2f} "
                  f"{python_ns / c_ns:>6.3f}")
    C.fluidbed_closure_destroy(handle)
print(f"({cells} cells; ns per cell, fastest of {repeats}; ratio: Python over the C interface in this run)")
