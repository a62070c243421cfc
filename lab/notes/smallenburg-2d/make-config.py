"""One starting configuration of N = m*m equal discs (diameter 1) for both codes: a triangular crystal of
m rows of m discs in a periodic box of the crystal's aspect ratio at packing fraction phi, each disc
moved by a small seeded jitter. Writes init.sph for Smallenburg's Single code (all discs at z = 2.75 in a
box 5.5 deep: three cell layers of his 1.5 shell, so no disc meets its own image) and scene.json for
carom (Maxwell velocities at kT = 1 in 2D, zero total momentum; his code draws its own at kT = 1).
usage: make-config.py M PHI SEED OUTDIR"""
import json, math, random, sys, os
m, phi, seed, out = int(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
n = m * m
a = math.sqrt(math.pi / (2 * math.sqrt(3) * phi))          # lattice spacing for packing fraction phi
lx, ly = m * a, m * a * math.sqrt(3) / 2
rng = random.Random(seed)
jitter = 0.2 * (a - 1)                                      # keeps every pair apart: |shift| < (a-1)/2
pos = []
for r in range(m):
    for c in range(m):
        x = (c + 0.5 * (r % 2) + 0.25) * a + rng.uniform(-jitter, jitter) / 2
        y = (r + 0.5) * a * math.sqrt(3) / 2 + rng.uniform(-jitter, jitter) / 2
        pos.append((x % lx, y % ly))
vel = [(rng.gauss(0, 1), rng.gauss(0, 1)) for _ in range(n)]
mx = sum(v[0] for v in vel) / n; my = sum(v[1] for v in vel) / n
vel = [(vx - mx, vy - my) for vx, vy in vel]
k = math.sqrt(2 * n / sum(vx * vx + vy * vy for vx, vy in vel))   # kinetic energy N kT, kT = 1
vel = [(vx * k, vy * k) for vx, vy in vel]
os.makedirs(out, exist_ok=True)
with open(os.path.join(out, "init.sph"), "w") as f:
    f.write(f"{n}\n{lx:.12f} {ly:.12f} 5.5\n")
    for x, y in pos:
        f.write(f"a {x:.12f} {y:.12f} 2.75 0.5\n")
scene = {"name": f"smallenburg-2d-n{n}-phi{phi}",
         "box": {"width": lx, "height": ly, "boundary": "periodic"},
         "species": [{"name": "disc", "radius": 0.5, "mass": 1.0}],
         "particles": [{"species": "disc", "x": x, "y": y, "vx": vx, "vy": vy} for (x, y), (vx, vy) in zip(pos, vel)],
         "until": 1.0}
with open(os.path.join(out, "scene.json"), "w") as f:
    json.dump(scene, f)
print(n, lx, ly, phi)
