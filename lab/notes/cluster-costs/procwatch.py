#!/usr/bin/env python3
"""procwatch.py ROOT_PID OUT.json: samples ROOT_PID and its descendants every 0.2 s until ROOT_PID
exits, and writes per process its role (coordinator: the root; worker: a ClusterWorker JVM), its last
seen CPU seconds (user + system, from /proc/PID/stat; up to 0.2 s short for a process that exits
between samples), its peak resident memory (VmHWM) and how long it was seen. Linux only."""
import json
import os
import sys
import time

TICK = os.sysconf("SC_CLK_TCK")


def stat(pid):
    with open(f"/proc/{pid}/stat") as f:
        s = f.read()
    rest = s[s.rindex(")") + 2:].split()
    return int(rest[1]), (int(rest[11]) + int(rest[12])) / TICK  # ppid, utime + stime


def hwm(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) * 1024
    return 0


def cmd(pid):
    with open(f"/proc/{pid}/cmdline", "rb") as f:
        return f.read().replace(b"\0", b" ").decode(errors="replace")


def main(root, out):
    seen = {}
    start = time.time()
    while os.path.exists(f"/proc/{root}"):
        parents = {}
        for p in os.listdir("/proc"):
            if p.isdigit():
                try:
                    parents[int(p)] = stat(int(p))[0]
                except OSError:
                    pass
        tree = {root}
        grew = True
        while grew:
            grew = False
            for p, pp in parents.items():
                if pp in tree and p not in tree:
                    tree.add(p)
                    grew = True
        now = time.time() - start
        for p in tree:
            try:
                cpu = stat(p)[1]
                mem = hwm(p)
                c = cmd(p)
            except OSError:
                continue
            if "java" not in c:
                continue
            e = seen.setdefault(p, {"pid": p, "role": "coordinator" if p == root else
                                    ("worker" if "ClusterWorker" in c else "other"),
                                    "first": now, "cpuSeconds": 0.0, "peakRssBytes": 0})
            e["cpuSeconds"] = max(e["cpuSeconds"], cpu)
            e["peakRssBytes"] = max(e["peakRssBytes"], mem)
            e["last"] = now
        time.sleep(0.2)
    with open(out, "w") as f:
        json.dump(sorted(seen.values(), key=lambda e: e["first"]), f, indent=1)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(int(sys.argv[1]), sys.argv[2])
