#!/usr/bin/env python3
"""combine.py RUN_DIR...: the runs' accepted points (both starts within two combined errors; the plain
mean of the two, as the study reports it) side by side, and their inverse-variance mean over the runs
per packing fraction; then every fall of the combined βPσ² as
φ rises from 0.70, in combined standard errors. Reads each run's eos.csv (carom study eos)."""
import csv
import math
import sys
from collections import defaultdict


def accepted(path):
    rows = defaultdict(dict)
    with open(path) as f:
        for r in csv.DictReader(f):
            if r["status"] != "measured":
                continue
            rows[float(r["phi"])][r["start"]] = r
    out = {}
    for phi, starts in rows.items():
        if {"crystal", "fluid"} <= starts.keys():
            c, l = starts["crystal"], starts["fluid"]
            diff = float(r_diff(c))
            if abs(diff) <= 2:
                # The study's own value of an accepted point: the plain mean of the two starts (an error
                # marked not converged is a lower bound, so it must not weigh a start down).
                (vc, ec), (vl, el) = [(float(x["betaP_sigma2"]), float(x["betaP_sigma2_error"])) for x in (c, l)]
                out[phi] = ((vc + vl) / 2, math.hypot(ec, el) / 2, diff,
                            c["error_converged"] == "true" and l["error_converged"] == "true")
            else:
                out[phi] = (None, None, diff, False)
    return out


def r_diff(row):
    return row["branch_difference_sigmas"]


def mean(vals):
    w = [1 / e ** 2 for _, e in vals]
    m = sum(v * wi for (v, _), wi in zip(vals, w)) / sum(w)
    return (m, 1 / math.sqrt(sum(w)))


def main(dirs):
    runs = [(d, accepted(d.rstrip("/") + "/eos.csv")) for d in dirs]
    phis = sorted({p for _, r in runs for p in r})
    print("| φ | " + " | ".join(d for d, _ in runs) + " | combined |")
    print("|---|" + "---|" * (len(runs) + 1))
    combined = {}
    for p in phis:
        cells, vals = [], []
        for _, r in runs:
            if p not in r:
                cells.append("")
            elif r[p][0] is None:
                cells.append(f"not accepted (Δ {r[p][2]:+.1f})")
            else:
                m, e, diff, conv = r[p]
                cells.append(f"{m:.4f} ± {e:.4f}{'' if conv else ' (nc)'} (Δ {diff:+.1f})")
                vals.append((m, e))
        if vals:
            combined[p] = mean(vals)
            cells.append(f"{combined[p][0]:.4f} ± {combined[p][1]:.4f}")
        else:
            cells.append("")
        print(f"| {p:g} | " + " | ".join(cells) + " |")
    print()
    ps = sorted(combined)
    for i, a in enumerate(ps):
        for b in ps[i + 1:]:
            if a >= 0.695:
                (ma, ea), (mb, eb) = combined[a], combined[b]
                s = math.hypot(ea, eb)
                print(f"{a:g} -> {b:g}: {mb - ma:+.4f} ({(mb - ma) / s:+.1f} combined errors)")


if __name__ == "__main__":
    main(sys.argv[1:])
