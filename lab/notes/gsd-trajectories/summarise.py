"""lab/notes/gsd-trajectories/summarise.py RUNS.txt FRAMES: the table of bench.sh's runs.

For each round: the CPU seconds a frame costs in each format, (cpu of the run with frames - cpu of
the round's plain run) / FRAMES, their ratio, and the bytes a disc a frame; then the medians.
"""
import statistics
import sys

path, frames = sys.argv[1], int(sys.argv[2])
rounds = {}
for line in open(path):
    if line.startswith("#") or not line.strip():
        continue
    n, fmt, r, wall, cpu, size = line.split()
    rounds.setdefault(r, {})[fmt] = (float(cpu), int(size), int(n))
print("| round | XYZ s/frame | GSD s/frame | GSD/XYZ | XYZ MB/frame | GSD MB/frame | XYZ B/disc | GSD B/disc |")
print("|---|---|---|---|---|---|---|---|")
costs = {"xyz": [], "gsd": []}
ratios = []
for r, runs in sorted(rounds.items(), key=lambda kv: int(kv[0])):
    base = runs["none"][0]
    row = {}
    for fmt in ("xyz", "gsd"):
        cpu, size, n = runs[fmt]
        row[fmt] = ((cpu - base) / frames, size / frames / 1e6, size / frames / n)
        costs[fmt].append(row[fmt][0])
    ratio = row["gsd"][0] / row["xyz"][0]
    ratios.append(ratio)
    print(f"| {r} | {row['xyz'][0]:.3f} | {row['gsd'][0]:.3f} | {ratio:.2f} | {row['xyz'][1]:.1f} | {row['gsd'][1]:.1f} "
          f"| {row['xyz'][2]:.1f} | {row['gsd'][2]:.1f} |")
print(f"| median | {statistics.median(costs['xyz']):.3f} | {statistics.median(costs['gsd']):.3f} "
      f"| {statistics.median(ratios):.2f} | | | | |")
