"""Reads a carom GSD trajectory with the field's own readers and prints what they saw as JSON.

Usage: read_with_gsd.py FRAMES.gsd SIGMA BIN_WIDTH R_MAX

gsd.hoomd: every frame's box, dimensions, types, typeid, diameter, mass, step, position, image and
log values (numbers as the float32/float64 the file holds, printed to round-trip); freud: g(r) over
all frames (bins of BIN_WIDTH up to R_MAX) and each frame's global |psi6| (neighbours closer than
1.4 SIGMA); MDAnalysis: frames and atoms; OVITO: frames, particles and cell (null if its module is
not installed).
"""
import json
import sys

import freud
import gsd.hoomd
import MDAnalysis
import numpy as np

path, sigma, bin_width, r_max = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
out = {"frames": []}
rdf = freud.density.RDF(bins=int(round(r_max / bin_width)), r_max=r_max)
hexatic = freud.order.Hexatic(k=6)
psi6 = []
with gsd.hoomd.open(path, "r") as trajectory:
    for frame in trajectory:
        lx, ly, _, xy = frame.configuration.box[:4]
        box = freud.box.Box(Lx=lx, Ly=ly, xy=xy, is2D=frame.configuration.dimensions == 2)
        points = frame.particles.position
        rdf.compute(system=(box, points), reset=False)
        hexatic.compute(system=(box, points), neighbors={"r_max": 1.4 * sigma})
        # A disc without neighbours has psi6 0 (carom's definition); freud leaves it NaN.
        psi6.append(float(abs(np.mean(np.nan_to_num(hexatic.particle_order)))))
        out["frames"].append({
            "step": int(frame.configuration.step),
            "dimensions": int(frame.configuration.dimensions),
            "box": [float(v) for v in frame.configuration.box],
            "N": int(frame.particles.N),
            "types": list(frame.particles.types),
            "typeid": [int(v) for v in frame.particles.typeid],
            "diameter": [float(v) for v in frame.particles.diameter],
            "mass": [float(v) for v in frame.particles.mass],
            "position": [float(v) for v in points.ravel()],
            "velocity": [float(v) for v in frame.particles.velocity.ravel()],
            "image": [int(v) for v in frame.particles.image.ravel()],
            "time": float(frame.log["carom/time"][0]),
            "collisions": int(frame.log["carom/collisions"][0]),
            # JSON has no NaN: frame 0's Z (no interval ends there) comes as null.
            "Z": None if np.isnan(frame.log["carom/Z"][0]) else float(frame.log["carom/Z"][0]),
        })
out["rdf"] = {"r": [float(v) for v in rdf.bin_centers], "g": [float(v) for v in rdf.rdf]}
out["psi6"] = psi6

universe = MDAnalysis.Universe(path)
out["mdanalysis"] = {"frames": len(universe.trajectory), "atoms": len(universe.atoms)}

try:
    from ovito.io import import_file
except ImportError:
    out["ovito"] = None
else:
    pipeline = import_file(path)
    data = pipeline.compute(pipeline.source.num_frames - 1)
    out["ovito"] = {"frames": pipeline.source.num_frames, "count": int(data.particles.count),
                    "cell": [float(data.cell[0][0]), float(data.cell[1][1])]}
print(json.dumps(out))
