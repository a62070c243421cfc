#!/usr/bin/env python3
"""model.py [costs.csv]: what the cluster engine's protocol would cost on a real cluster, from the
costs measured on this machine (costs.csv, written by table.py) and stated assumptions about the
network. Prints Markdown: the parameters it took from the measurements, the prediction for N = 1e8
and 1e9 discs on 16 and 64 nodes, the node count where the speed-up peaks, and memory.

The model (hard-disc gas, packing fraction 0.5, radius 0.5, periodic square box of side
L = sqrt(N pi / 2), as measured):

  windows per collision per disc   W = beta * B / nu
      B: total length of domain boundary: K slabs B = K L; K blocks a x b (a b = K) B = (a + b) L
      beta: windows per unit boundary length per unit simulated time (measured: one window per
            cross-domain event, and cross events happen along the boundary)
      nu: pair collisions per disc per unit time (measured)
  events per node per window       m = e N / (W K)   (e: events per collision, fast's)
  one window on the critical path  t = c E[max of K Poisson(m)]      the slowest node's events
                                     + s (messages through the coordinator per window)  software
                                     + r RTT                                         latency
                                     + bytes per window / bandwidth of the coordinator's link
      c: CPU seconds per event on one core (slabs' threads in windows at the largest N measured; CPU,
            because the machine was shared and wall times are inflated)
      messages per window = 2K (window, reply) + 2K rho (undo round) + 4 fc + 4 fm (install or
            emigrate and install, with replies); rho, fc, fm: rollbacks, cross contacts and
            migrations per window (measured)
      r = 1 + rho + fc + 2 fm round trips: the window, the undo, a contact's two installs at once,
            a migration's emigrate then install
      s: software seconds per message (Akka, serialization, actor hand-offs, loopback TCP), from the
            measured 2-node run: its wall time per window beyond the slowest node's events, over its
            messages per window; it includes one more serialization per message for counting
      bytes per window = h K + p + bx (fc + fm): h bytes per node (the window and its reply), p the
            changed edge discs' records and segments (the same for any K and N: a window lasts as
            long as one cross event on the whole boundary takes, and the edge discs that change in
            that time are proportional to that boundary's length), bx per cross event (measured)
  time per collision per disc      T = W t;  speed-up S = N e c / T (fast on one core)

Checkpoints (every 1024 windows, every disc's state to the coordinator) and the start (every node
gets the whole scene) are reported apart: both grow with N, not with the windows.
"""
import csv
import math
import os
import sys

# Assumptions about a typical cluster (stated in the README).
NETWORKS = [("fast network", 10e-6, 25.0), ("slow network", 50e-6, 10.0)]  # name, round trip s, Gbit/s
NODE_MEMORY = 256 * 2**30  # bytes of a node
SOFTWARE = 5e-6  # seconds of coordinator software per message on a dedicated machine (assumed; README)
CHECKPOINT_WINDOWS = 1024


def side(n):
    return math.sqrt(n * math.pi * 0.25 / 0.5)


def blocks(k):
    """a x b blocks, a b = k, as square as k allows."""
    a = int(math.isqrt(k))
    while k % a:
        a -= 1
    return a, k // a


def boundary(n, k, geometry):
    if k == 1:
        return 0.0
    if geometry == "slabs":
        return k * side(n)
    a, b = blocks(k)
    return ((a if a > 1 else 0) + (b if b > 1 else 0)) * side(n)


def expected_max_poisson(mean, k):
    """E[max of k independent Poisson(mean)], summed exactly: sum over j of 1 - F(j)^k."""
    if k == 1:
        return mean
    if mean > 2000:  # normal approximation with the Gumbel mean of the maximum
        z = math.sqrt(2 * math.log(k)) - (math.log(math.log(k)) + math.log(4 * math.pi) - 2 * 0.5772) / (2 * math.sqrt(2 * math.log(k)))
        return mean + z * math.sqrt(mean)
    # Below j0 = mean - 15 sd, F(j) is under 1e-40: each of those terms is 1. Starting there, in
    # logarithms, keeps exp(-mean) from underflowing to 0 (from mean 745 on), which made every term 1.
    j0 = max(0, int(mean - 15 * math.sqrt(mean)))
    total, cdf, j = float(j0), 0.0, j0
    pj = math.exp(-mean + j0 * math.log(mean) - math.lgamma(j0 + 1)) if mean > 0 else 1.0
    while True:
        cdf += pj
        tail = 1 - cdf ** k
        total += tail
        j += 1
        pj *= mean / j
        if j > mean and (tail < 1e-12 or j > mean + 40 * math.sqrt(mean) + 100):  # rounding may keep cdf below 1
            return total


class Measured:
    """The parameters, taken from costs.csv."""

    def __init__(self, path):
        with open(path) as f:
            rows = [{k: (v if k in ("tag", "config", "engine") else float(v or 0)) for k, v in r.items()} for r in csv.DictReader(f)]
        big = max(r["N"] for r in rows)
        self.n_measured = big
        at = {r["config"]: r for r in rows if r["N"] == big}
        fast = at["fast"]
        # CPU, not wall time: the machine was shared (load 7-13), and slabs' counters time its threads' CPU.
        slabs = at["slabs2"]
        self.c = slabs["windowCpuSeconds"] / slabs["events"]
        self.c_wall_fast = fast["wallSeconds"] / fast["events"]
        self.e = fast["events"] / fast["collisions"]
        self.nu = fast["collisions"] / big / fast["until"]
        self.table_bytes = fast["tableBytesPerDisc"]
        # One slab per JVM (--threads 1): the protocol between JVMs, which a real cluster has.
        clusters = [r for r in rows if r["engine"] == "cluster" and r["nodes"] >= 2 and r["config"].endswith("-nock")
                    and r["domains"] == r["nodes"]]
        if not clusters:
            clusters = [r for r in rows if r["engine"] == "cluster" and r["nodes"] >= 2]
        self.clusters = clusters
        betas = [r["windows"] / (r["until"] * boundary(r["N"], int(r["nodes"]), "slabs")) for r in clusters]
        self.beta = sum(betas) / len(betas)
        self.betas = betas
        ref = [r for r in clusters if r["N"] == big]
        w = sum(r["windows"] for r in ref)
        self.rho = sum(r["rollbacks"] for r in ref) / w
        self.fc = sum(r["crossContacts"] for r in ref) / w
        self.fm = sum(r["migrations"] for r in ref) / w
        self.bx = sum(r["bytesPerCrossEvent"] * (r["crossContacts"] + r["migrations"]) for r in ref) / sum(
            r["crossContacts"] + r["migrations"] for r in ref)
        by_k = {int(r["nodes"]): r for r in ref}
        ks = sorted(by_k)
        if len(ks) >= 2:
            k0, k1 = ks[0], ks[-1]
            self.h = (by_k[k1]["windowBytesPerWindow"] - by_k[k0]["windowBytesPerWindow"]) / (k1 - k0)
            self.p = by_k[k0]["windowBytesPerWindow"] - self.h * k0
        else:
            self.h, self.p = by_k[ks[0]]["windowBytesPerWindow"] / ks[0], 0.0
        two = by_k[2]
        m2 = two["events"] / two["windows"] / 2
        self.work2 = self.c * expected_max_poisson(m2, 2)
        self.loop2 = (two["windowUsPerWindow"] + two["serialUsPerWindow"]) * 1e-6
        self.overhead2 = self.loop2 - self.work2
        self.s = self.overhead2 / self.messages(2)
        self.m2 = m2
        self.two = two
        # Memory: peak resident set of a worker JVM, per disc, between the two N measured.
        sizes = sorted({r["N"] for r in rows})
        wk = {r["N"]: r["peakRssWorker"] for r in rows if r["engine"] == "cluster" and r["peakRssWorker"] > 0}
        if len(wk) >= 2:
            lo, hi = min(wk), max(wk)
            self.node_bytes_per_disc = (wk[hi] - wk[lo]) / (hi - lo)
        else:
            self.node_bytes_per_disc = float("nan")
        co = {r["N"]: r["peakRssCoordinator"] for r in rows if r["engine"] == "cluster" and r["nodes"] >= 2}
        lo, hi = min(co), max(co)
        self.coord_bytes_per_disc = (co[hi] - co[lo]) / (hi - lo) if hi > lo else float("nan")
        # Bytes per disc outside the windows: the scene to every node, start, finish (no-checkpoint runs).
        self.other_per_disc_node = sum(r["otherBytes"] / (r["N"] * r["nodes"]) for r in ref) / len(ref)
        ck = [(r, at.get(r["config"][:-5])) for r in ref if at.get(r["config"][:-5])]
        self.checkpoint_per_disc = float("nan")
        for r, d in ck:
            parts = d["snapshots"]
            if parts > 0:
                per_ck_parts = math.ceil(big / 16384) * d["nodes"]
                cks = parts / per_ck_parts
                self.checkpoint_per_disc = (d["otherBytes"] - r["otherBytes"]) / (cks * big)
                break

    def messages(self, k):
        return 2 * k + 2 * k * self.rho + 4 * self.fc + 4 * self.fm

    def round_trips(self):
        return 1 + self.rho + self.fc + 2 * self.fm

    def bytes_per_window(self, k):
        return self.h * k + self.p + self.bx * (self.fc + self.fm)


def predict(m, n, k, geometry, rtt, gbit, s):
    bw = gbit * 1e9 / 8
    b = boundary(n, k, geometry)
    t1 = n * m.e * m.c
    if b == 0:
        return {"T": t1, "S": 1.0, "W": 0, "mean": m.e * n, "work": t1, "soft": 0, "lat": 0, "band": 0, "cross": 0,
                "bytes": 0}
    w = m.beta * b / m.nu
    mean = m.e * n / (w * k)
    work = m.c * expected_max_poisson(mean, k)
    soft = s * m.messages(k)
    lat = m.round_trips() * rtt
    band = m.bytes_per_window(k) / bw
    t = w * (work + soft + lat + band)
    return {"T": t, "S": t1 / t, "W": w, "mean": mean, "work": w * work, "soft": w * soft, "lat": w * lat,
            "band": w * band, "cross": w * (m.fc + m.fm) / n, "bytes": m.bytes_per_window(k)}


def domains_label(k, geometry):
    """'16 slabs' or '4x4 blocks'."""
    a, b = blocks(k)
    return f"{k} slabs" if geometry == "slabs" else f"{a}x{b} blocks"


def peak(m, n, geometry, rtt, gbit, s):
    best = (1, 1.0)
    grid = sorted({round(2 ** (x / 8)) for x in range(8, 97)})  # 2 to 4096, 8 a doubling
    for k in ([q * q for q in range(2, 65)] if geometry == "blocks" else grid):
        sp = predict(m, n, k, geometry, rtt, gbit, s)["S"]
        if sp > best[1]:
            best = (k, sp)
    return best


def g(x):
    if x >= 100:
        return f"{x:,.0f}"
    if x >= 10:
        return f"{x:.1f}"
    return f"{x:.2g}"


def scenarios(m):
    """(label, round trip s, Gbit/s, software s per message)."""
    out = []
    for name, rtt, gbit in NETWORKS:
        out.append((f"{name} ({rtt * 1e6:.0f} us, {gbit:.0f} Gbit/s), {SOFTWARE * 1e6:.0f} us a message", rtt, gbit, SOFTWARE))
    name, rtt, gbit = NETWORKS[0]
    out.append((f"{name}, {4 * SOFTWARE * 1e6:.0f} us a message", rtt, gbit, 4 * SOFTWARE))
    out.append((f"{name}, software as measured here ({m.s * 1e6:.0f} us a message)", rtt, gbit, m.s))
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    m = Measured(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "costs.csv"))
    print(f"Parameters from the measurements (largest N measured: {m.n_measured:,.0f}):\n")
    print("| parameter | value | from |")
    print("|---|---|---|")
    print(f"| c, seconds per event on one core | {m.c * 1e9:.0f} ns | slabs on 2 threads at N = {m.n_measured:,.0f}: its slabs' CPU in windows over its events (fast's wall time per event: {m.c_wall_fast * 1e9:.0f} ns) |")
    print(f"| e, events per collision | {m.e:.2f} | fast |")
    print(f"| nu, pair collisions per disc per unit time | {m.nu:.3f} | fast |")
    print(f"| beta, windows per unit boundary length per unit time | {m.beta:.3f} (runs: {', '.join(f'{b:.3f}' for b in m.betas)}) | cluster, 2 and 3 nodes, no checkpoints |")
    print(f"| rho, fc, fm: rollbacks, cross contacts, migrations per window | {m.rho:.4f}, {m.fc:.3f}, {m.fm:.3f} | cluster at N = {m.n_measured:,.0f} |")
    print(f"| r, round trips per window | {m.round_trips():.2f} | 1 + rho + fc + 2 fm |")
    print(f"| messages per window | {m.messages(2):.2f} at 2 nodes, {m.messages(3):.2f} at 3 (measured {m.two['messagesPerWindow']:.2f} at 2, all messages of the run) | 2K(1 + rho) + 4(fc + fm) |")
    print(f"| h, bytes per node per window; p, edge payload per window | {m.h:.0f}; {m.p:.0f} | window bytes per window at 2 and 3 nodes |")
    print(f"| bx, bytes per cross event | {m.bx:.0f} | cluster |")
    print(f"| overhead per window at 2 nodes, loopback | {m.overhead2 * 1e6:.0f} us (window loop {m.loop2 * 1e6:.0f} us a window, less the slower node's events, {m.m2:.0f} on average, {m.work2 * 1e6:.0f} us) | cluster, 2 nodes |")
    print(f"| software per message as measured here | {m.s * 1e6:.0f} us | that overhead over the messages per window |")
    print(f"| software per message, assumed | {SOFTWARE * 1e6:.0f} us | see README |")
    print(f"| memory per disc, a worker JVM (whole table) | {m.node_bytes_per_disc:.0f} B | peak RSS, 1e5 to 1e6 |")
    print(f"| memory per disc, the coordinator JVM | {m.coord_bytes_per_disc:.0f} B | peak RSS, 1e5 to 1e6 (it also parsed the scene file, discs listed one by one) |")
    print(f"| the table alone, per disc | {m.table_bytes:.0f} B | fast's bytesPerDisc |")
    print(f"| bytes per disc and node outside windows (scene, start, finish) | {m.other_per_disc_node:.0f} B | no-checkpoint runs |")
    print(f"| bytes per disc of a checkpoint | {m.checkpoint_per_disc:.0f} B | default minus no-checkpoint run |")
    print()
    sc = scenarios(m)
    print("Prediction: T, wall seconds per collision per disc (N collisions), and the speed-up over `fast` on one core:\n")
    head = "| N | nodes | domains | windows per coll. per disc | cross events / collision | events / node / window | bytes / window | fast, 1 core s |"
    for i, _ in enumerate(sc):
        head += f" T{i + 1} s | S{i + 1} |"
    print(head)
    print("|" + "---|" * (8 + 2 * len(sc)))
    for n in (1e8, 1e9):
        for k in (16, 64):
            for geo in ("slabs", "blocks"):
                dom = domains_label(k, geo)
                p0 = predict(m, n, k, geo, *sc[0][1:])
                row = f"| {n:.0e} | {k} | {dom} | {g(p0['W'])} | {p0['cross']:.1e} | {g(p0['mean'])} | {g(p0['bytes'])} | {g(n * m.e * m.c)} |"
                for _, rtt, gbit, s in sc:
                    p = predict(m, n, k, geo, rtt, gbit, s)
                    row += f" {g(p['T'])} | {p['S']:.1f} |"
                print(row)
    print()
    for i, (label, *_) in enumerate(sc):
        print(f"- T{i + 1}, S{i + 1}: {label}")
    print()
    print(f"Where the time goes ({sc[0][0]}), seconds per collision per disc:\n")
    print("| N | domains | work (slowest node per window) | software | latency | bandwidth | T |")
    print("|---|---|---|---|---|---|---|")
    for n in (1e8, 1e9):
        for k in (16, 64):
            for geo in ("slabs", "blocks"):
                dom = domains_label(k, geo)
                p = predict(m, n, k, geo, *sc[0][1:])
                print(f"| {n:.0e} | {dom} | {g(p['work'])} | {g(p['soft'])} | {g(p['lat'])} | {g(p['band'])} | {g(p['T'])} |")
    print()
    print("Where the speed-up peaks (2 to 4096 nodes, 8 steps a doubling; blocks: square counts):\n")
    head = "| N | domains |" + "".join(f" best nodes, S{i + 1} |" for i in range(len(sc)))
    print(head)
    print("|" + "---|" * (2 + len(sc)))
    for n in (1e8, 1e9):
        for geo in ("slabs", "blocks"):
            row = f"| {n:.0e} | {geo} |"
            for _, rtt, gbit, s in sc:
                kb, sb = peak(m, n, geo, rtt, gbit, s)
                row += f" {kb}, {sb:.1f} |"
            print(row)
    print()
    print("Memory and the phases outside the windows (every node and the coordinator hold the whole table):\n")
    print("| N | nodes | a node: table alone; peak RSS slope | own share of the table | coordinator: table + a checkpoint | a checkpoint: time at 25 / 10 Gbit/s | 1024 windows take (T1's slabs) | the scene to every node at 25 / 10 Gbit/s |")
    print("|---|---|---|---|---|---|---|---|")
    gib = 2 ** 30
    for n in (1e8, 1e9):
        for k in (16, 64):
            table = n * m.table_bytes
            node = n * m.node_bytes_per_disc
            ck = n * m.checkpoint_per_disc
            p = predict(m, n, k, "slabs", *sc[0][1:])
            per_window = p["T"] / p["W"]
            scene = n * k * m.other_per_disc_node
            fit = "fits" if node <= NODE_MEMORY else "does not fit"
            print(f"| {n:.0e} | {k} | {table / gib:,.0f} GiB; {node / gib:,.0f} GiB ({fit} in {NODE_MEMORY / gib:.0f} GiB) | {table / k / gib:,.1f} GiB | {(table + ck) / gib:,.0f} GiB | {ck * 8 / 25e9:,.0f} / {ck * 8 / 10e9:,.0f} s | {CHECKPOINT_WINDOWS * per_window:.2f} s | {scene * 8 / 25e9:,.0f} / {scene * 8 / 10e9:,.0f} s |")


if __name__ == "__main__":
    main()
