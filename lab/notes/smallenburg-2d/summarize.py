"""Steady-state CPU rate of each code per density from cpu-pairs.sh outputs: within each round, the
collisions and CPU seconds between the short run (T1) and the long one (T2), so start-up, JIT and set-up
cancel. usage: summarize.py [--wall] [--code=NAME] LABEL=FILE ... (--wall: per wall second, from lines that carry
it; --code: compare carom's lines of that name, default fast)"""
import collections, statistics as st, sys
wall = "--wall" in sys.argv
code_arg = [a for a in sys.argv[1:] if a.startswith("--code=")]
ours = code_arg[0].split("=", 1)[1] if code_arg else "fast"
unit = "wall s" if wall else "CPU s"
print(f"| packing fraction | rounds | Smallenburg M coll per {unit} | `{ours}` M coll per {unit} | `{ours}` / Smallenburg (median of rounds) | range | load |")
print("|---|---|---|---|---|---|---|")
for arg in [a for a in sys.argv[1:] if not a.startswith("--")]:
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
        # A round counts when both codes ran in it to both end times.
        if any(len(runs[(r, code)]) < 2 for code in ("smallenburg", ours)):
            continue
        for code in ("smallenburg", ours):
            (t1, (c1, n1)), (t2, (c2, n2)) = sorted(runs[(r, code)].items())
            rates[code].append((n2 - n1) / (c2 - c1) / 1e6)
    ratios = sorted(f / s for f, s in zip(rates[ours], rates["smallenburg"]))
    print(f"| {label} | {len(ratios)} | {st.median(rates['smallenburg']):.2f} | {st.median(rates[ours]):.2f} | "
          f"{st.median(ratios):.2f} | {ratios[0]:.2f}-{ratios[-1]:.2f} | {min(loads):.1f}-{max(loads):.1f} |")
