#!/bin/sh
# Benchmark pairs: the tree before the vibrated floor (BASE, main at 98eb385) against the floor branch
# (FLOOR), fresh JVMs alternating (the order flips every round), scenes without a vibrated floor.
# Prints: round scene engine tree wallSeconds collisionsPerSecond loadavg1
BASE=${BASE:-/work/wt/floor-base}
FLOOR=${FLOOR:-/work/wt/floor}
ROUNDS=${ROUNDS:-6}
run() { # tree label scene engine until
  CAROM_AOT=0 "$1/carom" simulate "$FLOOR/examples/$3" --engine "$4" --until "$5" --summary /tmp/pair-$$.json >/dev/null 2>&1 || { echo "run failed: $*" >&2; exit 1; }
  python3 -c "import json,os; s=json.load(open('/tmp/pair-$$.json')); print('$6', '$3', '$4', '$2', s['wallSeconds'], round(s['collisionsPerSecond']), os.getloadavg()[0])"
}
r=1
while [ $r -le $ROUNDS ]; do
  for spec in "gas.json fast 40" "galton-board.json fast 12" "gas-in-box.json serial 20"; do
    set -- $spec
    if [ $((r % 2)) -eq 1 ]; then
      run "$BASE" base "$1" "$2" "$3" "$r"; run "$FLOOR" floor "$1" "$2" "$3" "$r"
    else
      run "$FLOOR" floor "$1" "$2" "$3" "$r"; run "$BASE" base "$1" "$2" "$3" "$r"
    fi
  done
  r=$((r + 1))
done
