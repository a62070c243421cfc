#!/bin/bash
# usage: skin-pairs.sh CONFIGDIR ROUNDS OUT T1 T2 JAR OPTION...
# `fast` from carom's app jar JAR on CONFIGDIR/scene.json (make-config.py) to T1 and to T2 under each
# --option (for example skin=0 skin=0.5), alternating, ROUNDS rounds. One line per run: round option T
# cpuSeconds wallSeconds pairCollisions load1. skin-rates.py makes the loop rates (T2 - T1) and ratios.
set -eu
cfg=$1; rounds=$2; out=$3; t1=$4; t2=$5; jar=$6; shift 6
java=${JAVA:-java}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
for r in $(seq 1 "$rounds"); do
  for o in "$@"; do
    for t in $t1 $t2; do
      /usr/bin/time -f "%U %S %e" -o "$work/cpu" "$java" -jar "$jar" simulate "$cfg/scene.json" --engine fast \
          --until "$t" --option "$o" --summary "$work/s.json" > /dev/null 2>&1
      c=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['collisions']['pair'])" "$work/s.json")
      echo "$r $o $t $(awk '{print $1+$2, $3}' "$work/cpu") $c $(cut -d' ' -f1 /proc/loadavg)" >> "$out"
    done
  done
done
