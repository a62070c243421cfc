#!/bin/bash
# usage: MD_DIR=DIR cpu-pairs.sh CONFIGDIR ROUNDS T1 T2 OUT
# User + system CPU seconds of Smallenburg's Single code (binaries DIR/mdT1 and DIR/mdT2, built from the
# patched source with -DMAXTIME=T1 and T2) and of `./carom simulate --engine fast` to T1 and T2 on the same
# start (CONFIGDIR/init.sph and scene.json from make-config.py), alternating. One line per run: round code
# T cpuSeconds pairCollisions load1 wallSeconds. The difference between T2 and T1 is each code's steady-state loop:
# start-up, the JIT and set-up cancel (summarize.py). Optional: FAST_OPTS (extra options of carom, e.g.
# '--option skin=0'), FAST_LABEL (the code's name in the lines, default fast), ROUND_BASE (added to round numbers).
set -eu
cfg=$1; rounds=$2; t1=$3; t2=$4; out=$5
md=${MD_DIR:?set MD_DIR to the folder of the md binaries}
carom=$(cd "$(dirname "$0")/../../.." && pwd)/carom
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cp "$cfg/init.sph" "$work/"
label=${FAST_LABEL:-fast}
for r in $(seq $((1 + ${ROUND_BASE:-0})) $((rounds + ${ROUND_BASE:-0}))); do
  for t in $t1 $t2; do
    ( cd "$work" && /usr/bin/time -f "%U %S %e" -o "$work/cpu" "$md/md$t" > "$work/md.out" )
    c=$(grep -o 'Collisions: [0-9]*' "$work/md.out" | tail -1 | cut -d' ' -f2)
    echo "$r smallenburg $t $(awk '{print $1+$2}' "$work/cpu") $c $(cut -d' ' -f1 /proc/loadavg) $(awk '{print $3}' "$work/cpu")" >> "$out"
    /usr/bin/time -f "%U %S %e" -o "$work/cpu" "$carom" simulate "$cfg/scene.json" --engine fast --until $t ${FAST_OPTS:-} \
        --summary "$work/s.json" > /dev/null 2>&1
    c=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['collisions']['pair'])" "$work/s.json")
    echo "$r $label $t $(awk '{print $1+$2}' "$work/cpu") $c $(cut -d' ' -f1 /proc/loadavg) $(awk '{print $3}' "$work/cpu")" >> "$out"
  done
done
