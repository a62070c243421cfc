#!/usr/bin/env python3
"""Prints issue 3's table (Markdown) from the SUMMARY.json files measure.sh wrote to results/."""
import json, pathlib, re

rows = []
for f in sorted(pathlib.Path(__file__).with_name("results").glob("*.json")):
    m = re.match(r"(\d+)-([\d.]+)-(\w+)-t(\d+)(?:-(b\d+|perthread))?$", f.stem)
    s = json.loads(f.read_text())
    n, phi, engine, threads, block = m.groups()
    coll = s["collisions"]["pair"] + s["collisions"]["wall"]
    c = s.get("counters", {})
    rows.append((int(n), float(phi), engine, int(threads), block or "",
                 c.get("cellsPerActor"), c.get("actors"), s["wallSeconds"], s["collisionsPerSecond"], coll,
                 s.get("violationsPerMillionCollisions", 0), s.get("messagesPerCollision"), s["energyDrift"]))
order = {"serial": 0, "stripes": 1, "akka": 2, "vthreads": 3}
rows.sort(key=lambda r: (r[0], r[1], order[r[2]], r[3], r[5] or 0))
print("| N | φ | engine | threads | cells/actor | actors | wall s | collisions/s | collisions | violations per 10^6 | messages/collision | energy drift |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for n, phi, e, t, b, cpa, actors, sec, cps, coll, vpm, mpc, drift in rows:
    print(f"| {n:.0e} | {phi} | {e} | {t} | {cpa if cpa is not None else ''} | {actors if actors is not None else ''} "
          f"| {sec:.2f} | {cps:,.0f} | {coll:,} | {vpm:.0f} | {'' if mpc is None else f'{mpc:.1f}'} | {drift:.1e} |")
