"""Median over rounds of each scene's wall seconds and of the per-round ratio slabs / fast (pairs.sh output)."""
import collections, statistics as st, sys
runs = collections.defaultdict(dict)
for path in sys.argv[1:]:
    for line in open(path):
        p = line.split()
        runs[(p[1], p[0])][p[2]] = p
scenes = sorted({s for s, _ in runs})
print("| scene | `fast` s | `slabs` s | slabs / fast (median of rounds) | range | windows | merged events / events |")
print("|---|---|---|---|---|---|---|")
for s in scenes:
    rounds = [v for (sc, _), v in runs.items() if sc == s and 'fast' in v and 'slabs' in v]
    f = [float(v['fast'][3]) for v in rounds]; sl = [float(v['slabs'][3]) for v in rounds]
    ratios = sorted(b / a for a, b in zip(f, sl))
    last = rounds[-1]['slabs']
    print(f"| {s} | {st.median(f):.3f} | {st.median(sl):.3f} | {st.median(ratios):.2f} | {ratios[0]:.2f}-{ratios[-1]:.2f} | {last[6]} | {last[7]} / {last[5]} |")
