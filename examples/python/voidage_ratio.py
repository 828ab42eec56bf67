#!/usr/bin/env python3
"""The quantity of Mazzei's thesis Figs 3.1–3.3 and 3.5 from Python, in the few lines a user would
write: the equilibrium voidage of a homogeneously fluidized bed under a drag law, over the voidage
Richardson and Zaki's law gives at the same superficial velocity, against the Reynolds number.

Dimensionless units: ρ_f = μ_f = d = 1, so Re = u_s and Ar = (ρ_p − ρ_f) g. For each Re and
ε_RZ: Re_t from Re = Re_t ε_RZ^n(Re_t) (Mazzei's exponent), Ar = ¾ (C_D Re)(Re_t) Re_t
(Dallavalle's C_D, the one Mazzei's exponent was built with); the law's equilibrium ε solves
β_classical(ε, w = u_s/ε) w = (1 − ε) Ar, found on a grid of ε with NumPy. Mazzei–Lettieri's law
reproduces Richardson–Zaki exactly (ratio 1), which the script checks.

Usage: voidage_ratio.py [OUT_DIR]   (writes voidage_ratio_python.png; needs NumPy and Matplotlib)

The same as a Jupyter notebook: voidage_ratio.ipynb, made from this script's cells (the "# %%"
lines) by notebook_from_script.py.
"""
# %%
import sys
from pathlib import Path

import matplotlib
import numpy as np

import fluidbed

in_notebook = "ipykernel" in sys.modules
if not in_notebook:
    matplotlib.use("Agg")                                     # a script writes the picture to a file
import matplotlib.pyplot as plt

# %% [markdown]
# Re_t and Ar of each (ε_R&Z, Re) from Richardson–Zaki with Mazzei's exponent and Dallavalle's C_D.

# %%
reynolds = np.geomspace(1e-3, 1e5, 161)                       # Re = ρ_f u_s d/μ_f
eps_rz = np.array([0.4, 0.6, 0.8])[:, None]                   # Richardson–Zaki voidages, one row each
exponent = fluidbed.richardson_zaki_exponents.MazzeiExponent()
cd_re = fluidbed.sphere_drag_coefficients.DallavalleCoefficient()

# Re_t from Re = Re_t ε^n(Re_t): the right side grows with Re_t; interpolate on a fine grid.
re_t_grid = np.geomspace(1e-4, 1e7, 20001)
re_t = np.stack([np.interp(np.log(reynolds), np.log(re_t_grid * e ** exponent.exponent(re_t_grid)), re_t_grid)
                 for e in eps_rz[:, 0]])
archimedes = 0.75 * cd_re.cd_re(re_t) * re_t


# %% [markdown]
# The equilibrium voidage of a drag law: the bed's weight less buoyancy balances the drag.

# %%
def equilibrium_voidage(law):
    """The root in ε of β(ε, u_s/ε) u_s/ε − (1 − ε) Ar, for every (ε_RZ, Re), on a grid of ε."""
    eps = np.linspace(0.2, 0.9999, 4001)[:, None, None]
    w = reynolds / eps
    residual = law.beta(eps, w, 1.0, 1.0, 1.0, convention="classical") * w - (1 - eps) * archimedes
    k = np.argmax(residual < 0, axis=0)                        # the first grid point past the root
    r0, r1 = np.take_along_axis(residual, k[None] - 1, 0)[0], np.take_along_axis(residual, k[None], 0)[0]
    e0, e1 = eps[k - 1, 0, 0], eps[k, 0, 0]
    root = e0 + (e1 - e0) * r0 / (r0 - r1)
    # No sign change: the drag carries the bed away below ε = 1 (Ergun at high Re): no equilibrium.
    return np.where(np.any(residual < 0, axis=0) & (k > 0), root, np.nan)


# %% [markdown]
# Four laws against Richardson–Zaki; Mazzei–Lettieri's reproduces it (checked to 1e-6).

# %%
out = Path(sys.argv[1] if len(sys.argv) > 1 and not in_notebook else ".")
out.mkdir(parents=True, exist_ok=True)
laws = ["Ergun", "WenYu1966", "DiFeliceDallavalle", "MazzeiLettieri"]
figure, axes = plt.subplots(1, 3, figsize=(15, 4.5), sharey=True)
for name, style in zip(laws, ["-", "--", "-.", ":"]):
    ratio = equilibrium_voidage(fluidbed.closure(name)) / eps_rz
    if name == "MazzeiLettieri":
        assert np.max(np.abs(ratio - 1)) < 1e-6, f"Mazzei–Lettieri departs from Richardson–Zaki by {np.max(np.abs(ratio - 1)):.2e}"
    for axis, row, e in zip(axes, ratio, eps_rz[:, 0]):
        axis.semilogx(reynolds, row, style, lw=2, label=name)
        axis.set_title(f"ε_R&Z = {e}")
for axis in axes:
    axis.set_xlabel("Re = ρ_f u_s d/μ_f  [-]")
    axis.grid(True, which="both", alpha=0.3)
axes[0].set_ylabel("ε_law / ε_R&Z  [-]")
axes[0].legend()
figure.suptitle("Equilibrium voidage of a homogeneous bed under four drag laws over Richardson–Zaki's "
                "(Mazzei's exponent, Dallavalle's C_D)\nclassical buoyancy; where a curve ends, the law has "
                "no equilibrium below ε = 1")
figure.tight_layout()
figure.savefig(out / "voidage_ratio_python.png", dpi=110)
print(f"wrote {out / 'voidage_ratio_python.png'}; Mazzei–Lettieri reproduces Richardson–Zaki to 1e-6")
