"""Loop rates of skin-pairs.sh outputs: per round and option, the collisions over the wall seconds between
the T1 and the T2 run (start-up cancels), and each option's ratio to BASE in the same round.
usage: skin-rates.py FILE BASE (BASE: an option as written, e.g. skin=0)"""
import collections, statistics, sys
path, base = sys.argv[1], sys.argv[2]
rows = [line.split() for line in open(path)]
ends = sorted({float(r[2]) for r in rows})
runs = collections.defaultdict(dict)
for r, o, t, cpu, wall, coll, load in rows:
    runs[(r, o)][float(t)] = (float(wall), int(coll), float(load))
rates = collections.defaultdict(dict)
for (r, o), d in runs.items():
    (w1, n1, _), (w2, n2, _) = d[ends[0]], d[ends[1]]
    rates[r][o] = (n2 - n1) / (w2 - w1) / 1e6
loads = [l for d in runs.values() for (_, _, l) in d.values()]
print(f"{path}: load {min(loads):.2f}-{max(loads):.2f}")
for o in sorted({o for r in rates for o in rates[r]}):
    ws = [rates[r][o] for r in sorted(rates)]
    ratios = [rates[r][o] / rates[r][base] for r in sorted(rates)]
    print(f"  {o:10s} M coll per wall s {' '.join(f'{w:.2f}' for w in ws)}; / {base}: "
          f"{' '.join(f'{x:.2f}' for x in ratios)} (median {statistics.median(ratios):.2f})")
