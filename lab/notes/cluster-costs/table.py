#!/usr/bin/env python3
"""table.py [RAWDIR]: the README's tables from raw/ (SUMMARY.json per run, procwatch's .proc.json), as
Markdown on stdout and as costs.csv (one row per run, every derived figure; model.py reads it); from
raw-quiet/ (the quiet machine's runs), costs-quiet.csv.

Per run: wall time (the summary's wallSeconds: the engine's run, for cluster after the nodes joined),
pair collisions, events, the window counters, messages and bytes (cluster), and derived per collision
and per window. 'protocol us/window' is (cluster wall - fast's wall on the same scene) / windows: what
a window costs on top of the events' own work."""
import csv
import glob
import json
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
ORDER = {"fast": 0, "slabs2": 1}


def key(tag):
    n, per, config = tag.split("-", 2)
    m = re.match(r"cluster(\d+)(?:x(\d+))?(-nock)?", config)
    slabs = int(m.group(1)) * int(m.group(2) or 1) if m else 0
    rank = ORDER.get(config, 10 + slabs * 4 + (2 if m.group(2) else 0) + (0 if m.group(3) else 1) if m else 99)
    return int(n), float(per), rank


def load(raw):
    runs = []
    for p in glob.glob(os.path.join(raw, "*-*-*.json")):
        tag = os.path.basename(p)[:-5]
        if tag.endswith(".proc") or "equilibration" in tag:
            continue
        with open(p) as f:
            s = json.load(f)
        proc = []
        pp = os.path.join(raw, tag + ".proc.json")
        if os.path.exists(pp):
            with open(pp) as f:
                proc = json.load(f)
        runs.append((tag, s, proc))
    runs.sort(key=lambda r: key(r[0]))
    return runs


def derive(tag, s, proc, fast_wall):
    n, per, config = tag.split("-", 2)
    c = s["counters"]
    coll = s["collisions"]["pair"] + s["collisions"]["wall"]
    wall = s["wallSeconds"]
    w = c.get("windows", 0)
    cross = c.get("crossDomainEvents", 0)
    mig = c.get("migrations", 0)
    msgs = c.get("messages", 0)
    mbytes = c.get("messageBytes", 0)
    bpw = c.get("messageBytesPerWindow", 0)
    bpx = c.get("messageBytesPerCrossEvent", 0)
    other_bytes = mbytes - bpw * w - bpx * (cross + mig) if msgs else 0
    d = {
        "tag": tag, "N": int(n), "perDisc": float(per), "config": config, "engine": s["engine"],
        "nodes": c.get("nodes", ""), "threads": s["threads"], "domains": c.get("domains", 1),
        "until": s["until"], "wallSeconds": wall, "collisions": coll, "events": s["events"], "collisionsPerSecond": coll / wall,
        "windows": w, "commits": c.get("commits", 0), "rollbacks": c.get("rollbacks", 0),
        "undoneEvents": c.get("undoneEvents", 0), "crossContacts": cross, "migrations": mig,
        "resyncs": c.get("resyncs", 0), "messages": msgs, "messageBytes": mbytes,
        "snapshots": c.get("messages.snapshot", 0), "tableBytesPerDisc": c.get("bytesPerDisc", 0),
        "windowCpuSeconds": c.get("windowCpuNanos", 0) * 1e-9, "criticalCpuSeconds": c.get("criticalCpuNanos", 0) * 1e-9,
        "messagesPerWindow": msgs / w if w else 0, "windowBytesPerWindow": bpw, "bytesPerCrossEvent": bpx,
        "otherBytes": other_bytes,
        "messagesPerCollision": msgs / coll, "bytesPerCollision": mbytes / coll,
        "eventsPerWindow": s["events"] / w if w else 0, "collisionsPerWindow": coll / w if w else 0,
        "crossEventsPerCollision": (cross + mig) / coll,
        "windowShare": c.get("windowNanos", 0) * 1e-9 / wall if w else 0,
        "serialShare": c.get("serialNanos", 0) * 1e-9 / wall if w else 0,
        "usPerWindow": wall / w * 1e6 if w else 0,
        "windowUsPerWindow": c.get("windowNanos", 0) * 1e-3 / w if w else 0,
        "serialUsPerWindow": c.get("serialNanos", 0) * 1e-3 / w if w else 0,
        "protocolUsPerWindow": (wall - fast_wall) / w * 1e6 if w and fast_wall else 0,
        "cpuSeconds": sum(p["cpuSeconds"] for p in proc),
        "coordinatorCpu": sum(p["cpuSeconds"] for p in proc if p["role"] == "coordinator"),
        "workerCpu": sum(p["cpuSeconds"] for p in proc if p["role"] == "worker"),
        "peakRssCoordinator": max([p["peakRssBytes"] for p in proc if p["role"] == "coordinator"] or [0]),
        "peakRssWorker": max([p["peakRssBytes"] for p in proc if p["role"] == "worker"] or [0]),
        "processSeconds": max([p.get("last", 0) for p in proc] or [0]),
    }
    return d


def fmt(x, digits=3):
    if isinstance(x, str):
        return x
    if isinstance(x, int) or (isinstance(x, float) and x.is_integer() and abs(x) >= 1000):
        return f"{int(x):,}"
    if x == 0:
        return "0"
    if abs(x) >= 100:
        return f"{x:,.0f}"
    return f"{x:.{digits}g}"


def print_head(cols):
    """A Markdown table's heading row and rule, from (key, heading) pairs."""
    print("| " + " | ".join(h for _, h in cols) + " |")
    print("|" + "---|" * len(cols))


def main():
    rows = []
    fast = {}
    raw = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "raw")
    runs = load(raw)
    for tag, s, proc in runs:
        if tag.endswith("-fast"):
            fast[tag.rsplit("-", 1)[0]] = s["wallSeconds"]
    for tag, s, proc in runs:
        rows.append(derive(tag, s, proc, fast.get("-".join(tag.split("-")[:2]), 0)))
    # raw/ gives costs.csv, raw-quiet/ costs-quiet.csv, raw/round1/ costs-round1.csv (beside the folder).
    base = os.path.basename(os.path.normpath(raw))
    csv_name = "costs" + (base[3:] if base.startswith("raw") else "-" + base) + ".csv"
    with open(os.path.join(raw, "..", csv_name), "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        wr.writeheader()
        wr.writerows(rows)
    cols = [("N", "N"), ("config", "run"), ("wallSeconds", "wall s"), ("collisions", "collisions"),
            ("windows", "windows"), ("rollbacks", "rollbacks"), ("undoneEvents", "undone events"),
            ("crossContacts", "cross contacts"), ("migrations", "migrations"), ("messages", "messages"),
            ("messageBytes", "bytes"), ("eventsPerWindow", "events / window"),
            ("messagesPerWindow", "messages / window"), ("windowBytesPerWindow", "window bytes / window"),
            ("bytesPerCrossEvent", "bytes / cross event"), ("messagesPerCollision", "messages / collision"),
            ("bytesPerCollision", "bytes / collision")]
    print_head(cols)
    for r in rows:
        print("| " + " | ".join(fmt(r[k]) for k, _ in cols) + " |")
    print()
    cols2 = [("N", "N"), ("config", "run"), ("collisionsPerSecond", "collisions/s"),
             ("usPerWindow", "wall us / window"), ("windowUsPerWindow", "in windows us / window"),
             ("serialUsPerWindow", "serial us / window"), ("windowShare", "window share"),
             ("serialShare", "serial share"), ("protocolUsPerWindow", "protocol us / window (vs fast)"),
             ("crossEventsPerCollision", "cross events / collision"), ("otherBytes", "scene, checkpoint, start, end bytes"),
             ("coordinatorCpu", "coordinator CPU s"), ("workerCpu", "workers CPU s"),
             ("processSeconds", "process s"), ("peakRssCoordinator", "peak RSS coordinator"),
             ("peakRssWorker", "peak RSS a worker")]
    print_head(cols2)
    for r in rows:
        vals = []
        for k, _ in cols2:
            v = r[k]
            if k.startswith("peakRss"):
                v = f"{v / 2**20:,.0f} MiB" if v else "-"
            elif k.endswith("Share"):
                v = f"{100 * v:.0f}%" if v else "-"
            else:
                v = fmt(v)
            vals.append(v)
        print("| " + " | ".join(vals) + " |")


if __name__ == "__main__":
    main()
