"""The explicit-particles scene of the read measurement: the thesis layout (unit lattice pitch, radius
0.2, jitter 0.1, velocity components uniform in [-1, 1]) at N = 1e6, every disc listed in "particles".
Usage: python3 make-explicit.py OUT.json"""
import json, random, sys

random.seed(1)
parts = []
for r in range(1000):
    for c in range(1000):
        parts.append({"x": c + 0.5 + random.uniform(-0.1, 0.1), "y": r + 0.5 + random.uniform(-0.1, 0.1),
                      "vx": random.uniform(-1, 1), "vy": random.uniform(-1, 1), "species": "disc"})
scene = {"name": "explicit-1m", "box": {"width": 1000.0, "height": 1000.0, "boundary": "walls"},
         "species": [{"name": "disc", "radius": 0.2, "mass": 1.0}], "particles": parts, "until": 0.0001}
json.dump(scene, open(sys.argv[1], "w"))
