#!/bin/bash
# usage: gb.sh ROUNDS OUT N PHI CPD VARIANT...   VARIANT = JAR or JAR@TUNABLES (e.g. lab.jar@skin=0.4)
# GasBench `fast` (6 timed runs after 3 warm-ups, 1 thread) in a fresh JVM per variant, the variants in an order
# rotated every round. One line per run: round label GasBench-CSV load1, the label being the tunables if given,
# else the jar's name.
set -eu
rounds=$1; out=$2; n=$3; phi=$4; cpd=$5; shift 5
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
variants=("$@"); k=${#variants[@]}
for r in $(seq 1 $rounds); do for q in $(seq 0 $((k-1))); do
  v=${variants[$(( (q + r) % k ))]}
  jar=${v%%@*}; tunables=""; label=$(basename "$jar" .jar)
  if [[ $v == *@* ]]; then tunables=${v#*@}; label=$tunables; fi
  line=$($J --enable-native-access=ALL-UNNAMED -Xmx4g -XX:+UseParallelGC -cp "$jar" carom.lab.bench.GasBench fast $n $phi $cpd 6 "$tunables" 1 3 2>&1 | grep "^fast,")
  echo "$r $label $line $(cut -d' ' -f1 /proc/loadavg)" >> "$out"
done; done
