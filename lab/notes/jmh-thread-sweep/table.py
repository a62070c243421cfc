#!/usr/bin/env python3
"""Markdown tables from this folder's JMH JSON files: collisions per second (the run:collisions
secondary result) as the mean of the measured iterations with their min-max, and the load average
logged during the file's run (STEP.load: min / mean / max of the 1-minute figure).

  table.py sweep-0.5 sweep-0.5-cell   one row per engine and layout, one column per thread count
  table.py akka-throughput-1          one row per trial
"""
import json
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
ACTOR_ENGINES = {"akka", "vthreads"}


def load(step):
    path = os.path.join(here, step + ".load")
    values = [float(line.split()[1]) for line in open(path) if len(line.split()) > 1] if os.path.exists(path) else []
    return "%.1f / %.1f / %.1f" % (min(values), sum(values) / len(values), max(values)) if values else "n/a"


def trials(step):
    for b in json.load(open(os.path.join(here, step + ".json"))):
        c = b["secondaryMetrics"]["collisions"]
        raw = [x for fork in c["rawData"] for x in fork]
        yield b["params"], "%.1f (%.1f-%.1f)" % (c["score"] / 1e3, min(raw) / 1e3, max(raw) / 1e3)


def layout(p):
    """cellsPerActor as the engine used it: only the actor engines have cells per actor."""
    return (p.get("cellsPerActor") or "1 (default)") if p["engine"] in ACTOR_ENGINES else "-"


def sweep(steps):
    rows, threads = {}, []
    for step in steps:
        for p, cell in trials(step):
            key = (p["engine"], p["phi"], layout(p), p["collisionsPerDisc"])
            rows.setdefault(key, {})[p["threads"]] = cell
            if p["threads"] not in threads:
                threads.append(p["threads"])
    threads.sort(key=int)
    print("| engine | phi | cellsPerActor | collisions/disc per run | "
          + " | ".join("%s thread%s" % (t, "" if t == "1" else "s") for t in threads) + " |")
    print("|---" * (4 + len(threads)) + "|")
    for (engine, phi, cells, per_disc), by_threads in rows.items():
        print("| %s | %s | %s | %s | %s |" % (engine, phi, cells, per_disc,
                                             " | ".join(by_threads.get(t, "") for t in threads)))


def flat(step):
    print("| engine | phi | threads | cellsPerActor | tunables | k collisions/s, mean (min-max) |")
    print("|---|---|---|---|---|---|")
    for p, cell in trials(step):
        print("| %s | %s | %s | %s | %s | %s |" % (p["engine"], p["phi"], p["threads"], layout(p),
                                                    p.get("tunables") or "-", cell))


if __name__ == "__main__":
    steps = sys.argv[1:]
    for step in steps:
        print("%s: load average min / mean / max %s" % (step, load(step)))
    print()
    if all(s.startswith("sweep") for s in steps):
        sweep(steps)
    else:
        for step in steps:
            flat(step)
            print()
