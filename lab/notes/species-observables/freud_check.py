"""g_ab(r) and S(k) of a carom GSD trajectory by freud, against carom's gab.csv and sk.csv of the same frames.

usage: python freud_check.py FRAMES.gsd REPORT_DIR
Prints, per pair of species, the largest difference of g_ab between carom and freud over the bins and
that difference in units of carom's block error; and for S(k), kσ in [1, 12], the difference from a
numpy direct sum over every wave vector of the box (freud's refuses 2D boxes).
freud's RDF normalises a pair of one species by N_a^2 where carom counts N_a (N_a - 1) pairs: scaled here.
"""
import csv
import sys

import freud
import gsd.hoomd
import numpy as np

frames_path, report = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(f"{report}/gab.csv")))
pairs = {}
for r in rows:
    pairs.setdefault((r["a"], r["b"]), []).append(r)
with gsd.hoomd.open(frames_path) as traj:
    frames = list(traj)
types = list(frames[0].particles.types)
for (a, b), rs in pairs.items():
    sigma = float(rs[0]["sigma"])
    bins = len(rs)
    rdf = freud.density.RDF(bins=bins, r_max=bins * sigma / 50)
    for f in frames:
        box = freud.box.Box.from_box(f.configuration.box[:2], dimensions=2)
        pos = f.particles.position
        ta = pos[f.particles.typeid == types.index(a)]
        tb = pos[f.particles.typeid == types.index(b)]
        rdf.compute(system=(box, tb), query_points=ta, reset=False)
    g = rdf.rdf.copy()
    if a == b:
        n = len(ta)
        g *= n / (n - 1)
    ours = np.array([float(r["g"]) for r in rs])
    err = np.array([float(r["error"]) for r in rs])
    beyond = np.array([float(r["r"]) for r in rs]) > 1.02 * sigma
    diff = np.abs(ours - g)[beyond]
    z = (diff / np.where(err[beyond] > 0, err[beyond], np.nan))
    print(f"g_{a}{b}: bins {bins}, max |carom - freud| {diff.max():.2e}, mean {diff.mean():.2e}, "
          f"max in block errors {np.nanmax(z):.3f}")
sk_rows = [r for r in csv.DictReader(open(f"{report}/sk.csv")) if r["a"] == ""]
k = np.array([float(r["k"]) for r in sk_rows])
ours = np.array([float(r["S"]) for r in sk_rows])
err = np.array([float(r["error"]) for r in sk_rows])
# freud's direct structure factor refuses 2D boxes: a direct sum in numpy over every wave vector of the
# box in each bin (carom takes eight lattice directions only), for kσ in [1, 12].
lx, ly = frames[0].configuration.box[:2]
radius = frames[0].particles.diameter / 2
sigma = 2 * radius.mean()
width = k[1] - k[0]
k_max = 12 / sigma
nx = np.arange(0, int(k_max * lx / (2 * np.pi)) + 1)
ny = np.arange(-int(k_max * ly / (2 * np.pi)), int(k_max * ly / (2 * np.pi)) + 1)
KX, KY = np.meshgrid(2 * np.pi * nx / lx, 2 * np.pi * ny / ly, indexing="ij")
half = (KX > 0) | ((KX == 0) & (KY > 0))
kx, ky = KX[half], KY[half]
mag = np.hypot(kx, ky)
keep = mag <= k_max
kx, ky, mag = kx[keep], ky[keep], mag[keep]
bin_of = (mag / width).astype(int)
total = np.zeros(bin_of.max() + 1)
count = np.bincount(bin_of, minlength=len(total))
for f in frames:
    p = f.particles.position.astype(np.float64)
    rho = np.exp(1j * (np.outer(kx, p[:, 0]) + np.outer(ky, p[:, 1]))).sum(axis=1)
    total += np.bincount(bin_of, weights=np.abs(rho) ** 2 / len(p), minlength=len(total))
numpy_s = total / np.maximum(count, 1) / len(frames)
d, z = [], []
for i, kk in enumerate(k):
    b = int(kk / width)
    if 1 <= kk * sigma <= 12 and b < len(count) and count[b] > 0:
        d.append(ours[i] - numpy_s[b])
        z.append((ours[i] - numpy_s[b]) / err[i])
d, z = np.array(d), np.array(z)
print(f"S(k), kσ in [1, 12]: {len(d)} bins, mean carom - numpy {d.mean():.3e}, rms {np.sqrt((d ** 2).mean()):.3e}, "
      f"rms in carom's block errors {np.sqrt((z ** 2).mean()):.3f} (8 directions against every vector of a bin)")
