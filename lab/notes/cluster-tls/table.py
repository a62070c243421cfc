"""table.py RAW: the note's table from RAW/MODE-ROUND.json and RAW/runs.log (measure.sh)."""
import json
import pathlib
import re
import statistics
import sys

raw = pathlib.Path(sys.argv[1])
runs = {}
for line in (raw / "runs.log").read_text().splitlines():
    m = re.match(r"(plain|tls|keytool) round=(\d+) wall=([0-9.]+)", line)
    if m:
        runs.setdefault(m[1], {})[int(m[2])] = float(m[3])
print("mode   round  command s  engine s  windows  s/1000 windows  messageBytes")
per = {"plain": [], "tls": []}
for mode in ("plain", "tls"):
    for r, wall in sorted(runs.get(mode, {}).items()):
        s = json.loads((raw / f"{mode}-{r}.json").read_text())
        c = s.get("counters", {})
        w = c.get("windows", 0)
        per[mode].append((r, wall, s["wallSeconds"], w))
        print(f"{mode:6} {r:5}  {wall:9.2f}  {s['wallSeconds']:8.2f}  {w:7}  {1000 * s['wallSeconds'] / max(w, 1):14.3f}  {c.get('messageBytes', 0)}")
pairs = [(t[2] / p[2], t[1] / p[1]) for p in per["plain"] for t in per["tls"] if p[0] == t[0]]
if pairs:
    print("TLS / plain per round (engine, command):", ", ".join(f"{e:.3f}/{c:.3f}" for e, c in pairs))
    print(f"median engine ratio {statistics.median(e for e, _ in pairs):.3f}, command ratio {statistics.median(c for _, c in pairs):.3f}")
kt = list(runs.get("keytool", {}).values())
if kt:
    print(f"keytool -genkeypair: median {statistics.median(kt):.2f} s of {len(kt)} ({min(kt):.2f}-{max(kt):.2f})")
