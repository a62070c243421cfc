#!/bin/bash
# usage: threeway.sh SCENEDIR ROUNDS T1 T2 OUT JAR...   (Smallenburg's md$T binaries in /tmp/sm)
# Each round: his code and each jar's `fast` to T1 and T2, order of jars rotated every round.
# One line per run: round code T cpuSeconds pairCollisions load1 wallSeconds
set -eu
cfg=$1; rounds=$2; t1=$3; t2=$4; out=$5; shift 5
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cp "$cfg/init.sph" "$work/"
jars=("$@")
for r in $(seq 1 "$rounds"); do
  for t in $t1 $t2; do
    ( cd "$work" && /usr/bin/time -f "%U %S %e" -o "$work/cpu" /tmp/sm/md$t > "$work/md.out" )
    c=$(grep -o 'Collisions: [0-9]*' "$work/md.out" | tail -1 | cut -d' ' -f2)
    echo "$r smallenburg $t $(awk '{print $1+$2}' "$work/cpu") $c $(cut -d' ' -f1 /proc/loadavg) $(awk '{print $3}' "$work/cpu")" >> "$out"
  done
  n=${#jars[@]}
  for q in $(seq 0 $((n - 1))); do
    jar=${jars[$(( (q + r) % n ))]}
    for t in $t1 $t2; do
      /usr/bin/time -f "%U %S %e" -o "$work/cpu" $J --enable-native-access=ALL-UNNAMED -jar "$jar" simulate "$cfg/scene.json" \
          --engine fast --until $t --summary "$work/s.json" > /dev/null 2>&1
      c=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['collisions']['pair'])" "$work/s.json")
      echo "$r $(basename "$jar" .jar) $t $(awk '{print $1+$2}' "$work/cpu") $c $(cut -d' ' -f1 /proc/loadavg) $(awk '{print $3}' "$work/cpu")" >> "$out"
    done
  done
done
