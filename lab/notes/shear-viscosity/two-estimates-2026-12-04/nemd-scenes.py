# Writes nemd0.5.json and nemd0.3.json: N = 2000 discs (sigma = m = 1) on a square lattice (jitter 0.1,
# random cells), Maxwell velocities at kT = 1 (mean removed) plus the Couette profile 0.05 y, in a square
# Lees-Edwards box sheared at 0.05 with the thermostat at kT = 1; until = 30,000 collisions a disc by
# Enskog's collision rate. Run: java -jar carom.jar simulate nemdPHI.json --engine fast --observe stress
#   --observe-every 0.2 --report nemd-report-PHI; then python3 nemd-blocks.py 0.5 0.3
import math, json, random
for phi, seed in ((0.5, 31), (0.3, 32)):
    n = 2000; rate = 0.05
    side = math.sqrt(n * math.pi * 0.25 / phi)
    chi = (1 - 7 * phi / 16) / (1 - phi) ** 2
    om = 2 * (phi / (math.pi / 4)) * chi * math.sqrt(math.pi)
    random.seed(seed)
    m = int(math.ceil(math.sqrt(n))); a = side / m
    cells = [(i, j) for i in range(m) for j in range(m)]; random.shuffle(cells); cells = cells[:n]
    vs = [(random.gauss(0, 1), random.gauss(0, 1)) for _ in range(n)]
    mx = sum(v[0] for v in vs) / n; my = sum(v[1] for v in vs) / n
    ps = []
    for (i, j), (vx, vy) in zip(cells, vs):
        x = (i + 0.5) * a + random.uniform(-0.1, 0.1); y = (j + 0.5) * a + random.uniform(-0.1, 0.1)
        ps.append({"species": "disc", "x": round(x, 6), "y": round(y, 6), "vx": round(vx - mx + rate * y, 6), "vy": round(vy - my, 6)})
    scene = {"name": f"nemd-{phi}", "box": {"width": side, "height": side, "boundary": "lees-edwards", "shearRate": rate, "thermostat": 1.0},
             "species": [{"name": "disc", "radius": 0.5, "mass": 1.0}], "particles": ps, "until": round(30000 / om, 1)}
    json.dump(scene, open(f"nemd{phi}.json", "w"))
