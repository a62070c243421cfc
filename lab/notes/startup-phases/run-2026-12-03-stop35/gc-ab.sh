#!/bin/bash
# Whole './carom simulate' commands, default collector (G1) against CAROM_JAVA_OPTS=-XX:+UseParallelGC,
# alternating, order swapped every round. Args: ROUNDS SCENE [extra simulate args...]
rounds=$1; scene=$2; shift 2
cd /work/main
for r in $(seq 1 $rounds); do
  if [ $((r % 2)) = 1 ]; then order="g1 par"; else order="par g1"; fi
  for gc in $order; do
    opts=""; [ $gc = par ] && opts="-XX:+UseParallelGC"
    load=$(cut -d' ' -f1 /proc/loadavg)
    /usr/bin/time -o /tmp/gc/t -f "%e %U %S %M" env CAROM_JAVA_OPTS="$opts" ./carom simulate "$scene" --summary /tmp/gc/s-$gc.json "$@" >/dev/null 2>/tmp/gc/err; s=$(cat /tmp/gc/t)
    run=$(grep -o '"wallSeconds" *: *[0-9.e-]*' /tmp/gc/s-$gc.json | grep -o '[0-9.e-]*$')
    echo "round $r $gc load $load wall/user/sys/maxKB $s run $run"
  done
done
