#!/usr/bin/env python3
"""Summarises akka-throughput-paired.csv: per layout and throughput, the median rate over the
measured rounds (round 0 is warm-up) and the median, min and max, over rounds, of the rate divided by
throughput 5's rate in the same round."""
import csv
import os
import statistics
from collections import defaultdict

here = os.path.dirname(os.path.abspath(__file__))
rate = {}
for row in csv.DictReader(line for line in open(os.path.join(here, "akka-throughput-paired.csv")) if not line.startswith("#")):
    if int(row["round"]) > 0:
        rate[(int(row["round"]), row["layout"], int(row["throughput"]))] = float(row["collisionsPerSecond"])
rounds = sorted({r for r, _, _ in rate})
print("| cellsPerActor | throughput | k coll/s median (min-max) | / throughput 5, same round: median (min-max) | rounds it beat 5 |")
print("|---|---|---|---|---|")
for layout in ("perThread", "16"):
    for t in (1, 5, 20, 100):
        rates = [rate[(r, layout, t)] for r in rounds]
        ratios = [rate[(r, layout, t)] / rate[(r, layout, 5)] for r in rounds]
        wins = sum(1 for x in ratios if x > 1)
        print("| %s | %d | %.1f (%.1f-%.1f) | %.2f (%.2f-%.2f) | %s |" % (
            layout, t, statistics.median(rates) / 1e3, min(rates) / 1e3, max(rates) / 1e3,
            statistics.median(ratios), min(ratios), max(ratios), "-" if t == 5 else "%d of %d" % (wins, len(rounds))))
