#!/usr/bin/env python3
"""make_piles.py OUTDIR [COUNT]: COUNT (default 12) small piles, scene files OUTDIR/wp<seed>.json: eleven
discs of radius 0.5 dropped from just above the floor of an 11.6 x 6 walled box, ten into the hollows
above them, heights jittered by seed; gravity 9.81, restitution 0.7 (discs and walls), the TC model at
tc = 1e-3, until 5."""
import json
import os
import random
import sys

out = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 12
os.makedirs(out, exist_ok=True)
for seed in range(count):
    r = random.Random(seed)
    discs = [{"species": "d", "x": 0.55 + 1.05 * k, "y": 0.6 + 0.15 * r.random(), "vx": 0, "vy": 0} for k in range(11)]
    discs += [{"species": "d", "x": 1.075 + 1.05 * k, "y": 1.8 + 0.3 * r.random(), "vx": 0, "vy": 0} for k in range(10)]
    scene = {"name": "wide-pile-%d" % seed, "box": {"width": 11.6, "height": 6, "boundary": "walls"},
             "species": [{"name": "d", "radius": 0.5, "mass": 1}],
             "effects": {"gravity": [0, -9.81], "restitution": 0.7, "wallRestitution": 0.7, "tc": 1e-3},
             "particles": discs, "until": 5}
    with open(os.path.join(out, "wp%d.json" % seed), "w") as f:
        json.dump(scene, f)
