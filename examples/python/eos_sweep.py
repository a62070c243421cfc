"""The hard-disc equation of state from Python: a sweep over packing fractions with carom, Z(φ) plotted
against Henderson's equation (Mol. Phys. 30, 971, 1975).

    pip install './python[plot]'          # from the repository's root
    python examples/python/eos_sweep.py   # writes eos.png; seconds once ./carom is built

Each packing fraction is one `carom simulate` of 1,000 discs; the runs' folders (final state, summary,
GSD trajectory) are printed with the table.
"""
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no window
import matplotlib.pyplot as plt
import numpy as np

import carom

disc = carom.Species("disc", radius=0.5, mass=1.0)


def scene(phi: float) -> carom.Scene:
    # Random addition jams near 0.547: denser starts come from a shaken triangular lattice.
    layout = dict(layout="random") if phi < 0.45 else dict(layout="triangular", jitter=0.5)
    return carom.Scene.at_packing_fraction(disc, phi, 1000, seed=1, until=20.0, **layout)


result = carom.sweep([0.1, 0.2, 0.3, 0.4, 0.5, 0.6], scene, every=1.0, trajectory="gsd", workers=2)
for phi, z, dz, run in zip(result.values, result.Z, result.Z_error, result.runs):
    print(f"phi = {phi:.2f}   Z = {z:.3f} ± {dz:.3f}   {run.folder}")

grid = np.linspace(0, 0.65, 200)
plt.plot(grid, (1 + grid**2 / 8) / (1 - grid) ** 2, label="Henderson (1975)")
plt.errorbar(result.values, result.Z, yerr=result.Z_error, fmt="o", label="carom, N = 1000")
plt.xlabel("packing fraction φ")
plt.ylabel("Z = PA/(NkT)")
plt.legend()
out = sys.argv[1] if len(sys.argv) > 1 else "eos.png"
plt.savefig(out, dpi=120)
print("wrote", out)
