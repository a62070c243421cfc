#!/bin/bash
# usage: lab/notes/slabs-short-runs/pairs.sh OUT ROUNDS [SCENE.json...]
# Every example (or the scenes given) to its end with ./carom (so with its start-up cache), `fast` then
# `slabs --threads 2` in each round; one line per run: round scene engine wallSeconds pairCollisions
# events windows mergedEvents load1.
set -eu
root=$(cd "$(dirname "$0")/../../.." && pwd)
out=$1; rounds=$2; shift 2
scenes=("$@"); [ ${#scenes[@]} -gt 0 ] || scenes=("$root"/examples/*.json)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for r in $(seq 1 "$rounds"); do
  for f in "${scenes[@]}"; do
    for e in fast slabs; do
      "$root/carom" simulate "$f" --engine $e --threads 2 --summary "$tmp/s.json" >/dev/null 2>&1
      python3 - "$r" "$(basename "$f" .json)" "$e" "$(cut -d' ' -f1 /proc/loadavg)" "$tmp/s.json" >> "$out" <<'PY'
import json, sys
r, s, e, load, path = sys.argv[1:]
d = json.load(open(path)); c = d.get('counters', {})
print(r, s, e, '%.4f' % d['wallSeconds'], d['collisions']['pair'], d['events'],
      c.get('windows', '-'), c.get('mergedEvents', '-'), load)
PY
    done
  done
done
