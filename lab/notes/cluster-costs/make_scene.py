#!/usr/bin/env python3
"""Scenes for the cluster-costs note: GasBench's gas (lab/.../StandardScenes.gas), as scene files.

  make_scene.py lattice N PHI UNTIL OUT.json
      N discs of radius 0.5 in a periodic square box of side sqrt(N*pi*0.25/PHI), on the scene
      format's lattice with jitter 0.5, Maxwell velocities at kT = 1, seed 42 (GasBench's scene).
  make_scene.py particles N PHI FINAL.csv EQ_SUMMARY.json PER_DISC OUT.json
      The same box with the discs listed one by one at FINAL.csv's state (an equilibration run's
      --out, numbers copied verbatim so they parse to the same doubles), and an end time that gives
      about PER_DISC pair collisions per disc at the equilibration run's rate.
"""
import json
import math
import sys


def box(n, phi):
    side = math.sqrt(n * math.pi * 0.25 / phi)
    return {"width": side, "height": side, "boundary": "periodic"}


SPECIES = [{"name": "disc", "radius": 0.5, "mass": 1.0}]


def lattice(n, phi, until, out):
    scene = {"name": f"gas-{n}-phi{phi}", "box": box(n, phi), "species": SPECIES,
             "generate": [{"species": "disc", "count": n, "layout": "lattice", "jitter": 0.5,
                           "velocity": {"distribution": "maxwell", "temperature": 1.0}, "seed": 42}],
             "until": until}
    with open(out, "w") as f:
        json.dump(scene, f, indent=1)


def particles(n, phi, final_csv, summary_json, per_disc, out):
    with open(summary_json) as f:
        s = json.load(f)
    rate = s["collisions"]["pair"] / n / s["until"]
    until = per_disc / rate
    head = {"name": f"gas-{n}-phi{phi}-equilibrated", "box": box(n, phi), "species": SPECIES}
    with open(final_csv) as f, open(out, "w") as o:
        o.write(json.dumps(head)[:-1] + ', "until": %r, "particles": [\n' % until)
        header = f.readline().strip()
        assert header == "id,x,y,vx,vy", header
        first = True
        count = 0
        for line in f:
            _, x, y, vx, vy = line.strip().split(",")
            o.write(("" if first else ",\n") + '{"species":"disc","x":%s,"y":%s,"vx":%s,"vy":%s}' % (x, y, vx, vy))
            first = False
            count += 1
        o.write("\n]}\n")
    assert count == n, (count, n)
    print(f"{out}: {n} discs, equilibration rate {rate:.4f} pair collisions per disc per unit time, until {until:.6g}")


if __name__ == "__main__":
    a = sys.argv[1:]
    if a and a[0] == "lattice" and len(a) == 5:
        lattice(int(a[1]), float(a[2]), float(a[3]), a[4])
    elif a and a[0] == "particles" and len(a) == 7:
        particles(int(a[1]), float(a[2]), a[3], a[4], float(a[5]), a[6])
    else:
        sys.exit(__doc__)
