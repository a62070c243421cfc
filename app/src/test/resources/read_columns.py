"""Reads the per-disc columns of a carom GSD trajectory (--trajectory-columns psi6,neighbours) with the
field's readers and prints what they saw as JSON.

Usage: read_columns.py FRAMES.gsd FRAMES.xyz

gsd.hoomd: each frame's log/particles/carom/psi6 and log/particles/carom/neighbours; freud: each frame's
per-disc |psi6| and neighbour count from the positions (neighbours closer than 1.4, for discs of
diameter 1: carom's definition); OVITO: the GSD file's frame count and its last frame's two particle
properties, and the same of the XYZ file (null if its module is not installed).
"""
import json
import sys

import freud
import gsd.hoomd
import numpy as np

path, xyz = sys.argv[1], sys.argv[2]
out = {"frames": []}
hexatic = freud.order.Hexatic(k=6)
with gsd.hoomd.open(path, "r") as trajectory:
    for frame in trajectory:
        lx, ly = frame.configuration.box[:2]
        box = freud.box.Box(Lx=lx, Ly=ly, is2D=True)
        points = frame.particles.position
        query = freud.locality.AABBQuery(box, points)
        bonds = query.query(points, {"r_max": 1.4, "exclude_ii": True}).toNeighborList()
        hexatic.compute(system=(box, points), neighbors=bonds)
        counts = np.bincount(bonds.query_point_indices, minlength=len(points))
        out["frames"].append({
            "psi6": [float(v) for v in frame.log["particles/carom/psi6"]],
            "neighbours": [int(v) for v in frame.log["particles/carom/neighbours"]],
            # A disc without neighbours has psi6 0 (carom's definition); freud leaves it NaN.
            "freud_psi6": [float(v) for v in np.abs(np.nan_to_num(hexatic.particle_order))],
            "freud_neighbours": [int(v) for v in counts],
        })

try:
    from ovito.io import import_file
except ImportError:
    out["ovito"] = None
else:
    def properties(file, psi6, neighbours):
        pipeline = import_file(file)
        data = pipeline.compute(pipeline.source.num_frames - 1)
        return {"frames": pipeline.source.num_frames,
                "psi6": [float(v) for v in data.particles[psi6]],
                "neighbours": [int(v) for v in data.particles[neighbours]]}
    out["ovito"] = properties(path, "carom_psi6", "carom_neighbours")
    out["ovito_xyz"] = properties(xyz, "psi6", "neighbours")
print(json.dumps(out))
