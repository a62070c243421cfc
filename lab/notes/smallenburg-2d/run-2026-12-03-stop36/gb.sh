#!/bin/bash
# usage: gb.sh ROUNDS OUT N PHI CPD JAR...  GasBench fast, fresh JVMs alternating (order rotated each round)
set -eu
rounds=$1; out=$2; n=$3; phi=$4; cpd=$5; shift 5
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
jars=("$@"); k=${#jars[@]}
for r in $(seq 1 $rounds); do for q in $(seq 0 $((k-1))); do
  jar=${jars[$(( (q + r) % k ))]}
  line=$($J --enable-native-access=ALL-UNNAMED -Xmx4g -XX:+UseParallelGC -cp $jar carom.lab.bench.GasBench fast $n $phi $cpd 6 "" 1 3 2>&1 | grep "^fast,")
  echo "$r $(basename $jar .jar) $line $(cut -d' ' -f1 /proc/loadavg)" >> $out
done; done
