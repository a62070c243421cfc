"""Steady-state CPU rate of each code per density from cpu-pairs.sh outputs: within each round, the
collisions and CPU seconds between the short run (T1) and the long one (T2), so start-up, JIT and set-up
cancel. usage: summarize.py [--wall] LABEL=FILE ... (--wall: per wall second, from lines that carry it)"""
import collections, statistics as st, sys
wall = "--wall" in sys.argv
unit = "wall s" if wall else "CPU s"
print(f"| packing fraction | rounds | Smallenburg M coll per {unit} | `fast` M coll per {unit} | `fast` / Smallenburg (median of rounds) | range | load |")
print("|---|---|---|---|---|---|---|")
for arg in [a for a in sys.argv[1:] if a != "--wall"]:
    label, path = arg.split("=")
    runs = collections.defaultdict(dict)
    loads = []
    for line in open(path):
        fields = line.split()
        r, code, t, cpu, coll, load = fields[:6]
        runs[(r, code)][float(t)] = (float(fields[6] if wall else cpu), int(coll))
        loads.append(float(load))
    rates = collections.defaultdict(list)
    rounds = sorted({r for r, _ in runs})
    for r in rounds:
        for code in ("smallenburg", "fast"):
            d = runs[(r, code)]
            if len(d) < 2:
                continue
            (t1, (c1, n1)), (t2, (c2, n2)) = sorted(d.items())
            rates[code].append((n2 - n1) / (c2 - c1) / 1e6)
    ratios = sorted(f / s for f, s in zip(rates["fast"], rates["smallenburg"]))
    print(f"| {label} | {len(ratios)} | {st.median(rates['smallenburg']):.2f} | {st.median(rates['fast']):.2f} | "
          f"{st.median(ratios):.2f} | {ratios[0]:.2f}-{ratios[-1]:.2f} | {min(loads):.1f}-{max(loads):.1f} |")
