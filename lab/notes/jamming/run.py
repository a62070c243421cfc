#!/usr/bin/env python3
"""The jamming table: compress each scene of CASES to Z > 1e12 with ./carom compress and collect
the summaries into jamming.csv and table.md (run from the repository root:
python3 lab/notes/jamming/run.py; CAROM=path overrides ./carom). Scenes are written beside this script."""
import json, math, os, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
PHI0 = 0.37  # starting packing fraction (random sequential addition jams near 0.54)

def bidisperse(n, growth, seed):
    side = math.sqrt(n * math.pi * (0.5**2 + 0.7**2) / 2 / PHI0)
    return {"name": f"bidisperse-{n}", "box": {"width": side, "height": side, "boundary": "periodic"},
            "species": [{"name": "small", "radius": 0.5, "mass": 1}, {"name": "large", "radius": 0.7, "mass": 1}],
            "generate": [{"species": ["small", "large"], "fractions": [0.5, 0.5], "count": n, "layout": "random",
                          "velocity": {"distribution": "maxwell", "temperature": 1}, "seed": seed}],
            "effects": {"growth": growth}, "until": 1e6}

def monodisperse(cols, rows, growth, seed):
    # a box a triangular lattice of cols x rows fits, at PHI0
    n = cols * rows
    pitch = math.sqrt(n * math.pi * 0.25 / PHI0 / (cols * rows * math.sqrt(3) / 2))
    return {"name": f"monodisperse-{n}", "box": {"width": pitch * cols, "height": pitch * math.sqrt(3) / 2 * rows,
                                                "boundary": "periodic"},
            "species": [{"name": "disc", "radius": 0.5, "mass": 1}],
            "generate": [{"species": "disc", "count": n, "layout": "random",
                          "velocity": {"distribution": "maxwell", "temperature": 1}, "seed": seed}],
            "effects": {"growth": growth}, "until": 1e6}

CASES = [
    ("50:50, ratio 1.4", bidisperse(200, 0.01, 7)),
    ("50:50, ratio 1.4", bidisperse(200, 0.001, 7)),
    ("50:50, ratio 1.4", bidisperse(1000, 0.01, 8)),
    ("50:50, ratio 1.4", bidisperse(1000, 0.001, 8)),
    ("50:50, ratio 1.4", bidisperse(4000, 0.01, 9)),
    ("equal", monodisperse(20, 24, 0.01, 5)),
    ("equal", monodisperse(20, 24, 0.001, 5)),
]

def main():
    rows = []
    for mixture, scene in CASES:
        name = f"{scene['name']}-g{scene['effects']['growth']}"
        path = os.path.join(HERE, name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f, indent=1)
        summary = os.path.join(HERE, name + ".summary.json")
        load0 = open("/proc/loadavg").read().split()[0]
        started = time.time()
        subprocess.run([os.environ.get("CAROM", "./carom"), "compress", path, "--to-pressure", "1e12", "--every", "1",
                        "--summary", summary, "--out", os.path.join(HERE, name + ".packing.csv")], check=True)
        wall = time.time() - started
        load1 = open("/proc/loadavg").read().split()[0]
        s = json.load(open(summary))
        c = s["compression"]
        rows.append(dict(mixture=mixture, N=s["particles"], growth=scene["effects"]["growth"],
                         phi0=c["packingFractionInitial"], phi=c["packingFraction"], Z=c["Z"],
                         gap=c["smallestGap"], collisions=s["collisions"]["pair"], t=c["time"],
                         rescalings=c["rescalings"], seconds=s["wallSeconds"], process=wall,
                         load=f"{load0}/{load1}", stop=c["stop"]))
        print(rows[-1], flush=True)
    keys = list(rows[0].keys())
    with open(os.path.join(HERE, "jamming.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(str(r[k]) for k in keys) + "\n")
    with open(os.path.join(HERE, "table.md"), "w") as f:
        f.write("| mixture | N | growth G | φ start | φ final | Z final | smallest gap | collisions | t | rescalings | run s | load (before/after) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write(f"| {r['mixture']} | {r['N']} | {r['growth']} | {r['phi0']:.4f} | {r['phi']:.5f} | {r['Z']:.3g} | "
                    f"{r['gap']:.2g} | {r['collisions']:,} | {r['t']:.2f} | {r['rescalings']} | {r['seconds']:.1f} | {r['load']} |\n")

if __name__ == "__main__":
    main()
