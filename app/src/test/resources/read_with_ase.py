"""Reads a carom trajectory with ASE's own extended XYZ reader and prints what ASE saw, as JSON.

Used by TrajectoryAseTest: every frame, its time, cell, periodicity, and per disc the type, id,
position, velocity and radius as ASE parsed them (repr of floats, so nothing is rounded on the way),
and the columns psi6 and neighbours when the frames have them (TrajectoryColumnsTest).
"""
import json
import sys

import ase.io

frames = ase.io.read(sys.argv[1], index=":", format="extxyz")
out = []
for f in frames:
    frame = {
        "time": repr(float(f.info["Time"])),
        "cell": [repr(float(v)) for v in f.cell.lengths()],
        "pbc": [bool(p) for p in f.pbc],
        "type": [str(t) for t in f.arrays["type"]],
        "id": [int(i) for i in f.arrays["id"]],
        "x": [repr(float(p[0])) for p in f.positions],
        "y": [repr(float(p[1])) for p in f.positions],
        "vx": [repr(float(v[0])) for v in f.arrays["velo"]],
        "vy": [repr(float(v[1])) for v in f.arrays["velo"]],
        "radius": [repr(float(r)) for r in f.arrays["radius"]],
    }
    if "psi6" in f.arrays:
        frame["psi6"] = [repr(float(v)) for v in f.arrays["psi6"]]
    if "neighbours" in f.arrays:
        frame["neighbours"] = [int(v) for v in f.arrays["neighbours"]]
    out.append(frame)
json.dump(out, sys.stdout)
