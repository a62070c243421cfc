#!/usr/bin/env python3
"""blocks.py RAWDIR: slabs against blocks in the cluster's protocol, from run.sh's summaries of
clusterKxT-nock (the layout with the shortest cuts) beside clusterKxT-nock-slabs (vertical slabs).
Counts only: they do not depend on the machine. Prints a Markdown table, one row per run, with the cut
length (cell sides a window's cross events come from, in box sides L) the layout has."""
import glob
import json
import os
import re
import sys


def cut_in_box_sides(cols, rows):
    """Periodic box: cols x rows domains cut along cols + rows lines of one box side each (1 if one)."""
    return (cols if cols > 1 else 0) + (rows if rows > 1 else 0)


def main(raw):
    rows = []
    for p in sorted(glob.glob(os.path.join(raw, "*-*-cluster*.json"))):
        if p.endswith(".proc.json"):
            continue
        tag = os.path.basename(p)[:-5]
        with open(p) as f:
            s = json.load(f)
        c = s["counters"]
        domains, drows = c["domains"], c.get("domainRows", 1)
        coll = s["collisions"]["pair"] + s["collisions"]["wall"]
        w = c["windows"]
        rows.append([tag, c["nodes"], domains, f"{domains // drows} x {drows}",
                     cut_in_box_sides(domains // drows, drows), f"{coll:,}", f"{w:,}", f"{c['rollbacks']:,}",
                     f"{c['crossDomainEvents']:,}", f"{c['migrations']:,}", f"{c['messages']:,}",
                     f"{c['messageBytes']:,}", f"{c['messages'] / coll:.3g}", f"{c['messageBytes'] / coll:.3g}",
                     f"{s['wallSeconds']:.1f}"])
    head = ["run", "JVMs", "domains", "layout (cols x rows)", "cut (box sides)", "collisions", "windows", "rollbacks",
            "cross contacts", "migrations", "messages", "bytes", "messages / collision", "bytes / collision",
            "wall s (loaded, not comparable)"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        print("| " + " | ".join(str(x) for x in r) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "raw-blocks"))
