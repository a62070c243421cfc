#!/bin/bash
# usage: gbt.sh ROUNDS OUT N PHI CPD JAR TUNABLES...  GasBench fast, fresh JVMs, one per tunables string in rotated order each round
set -eu
rounds=$1; out=$2; n=$3; phi=$4; cpd=$5; jar=$6; shift 6
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
tun=("$@"); k=${#tun[@]}
for r in $(seq 1 $rounds); do for q in $(seq 0 $((k-1))); do
  t=${tun[$(( (q + r) % k ))]}
  line=$($J --enable-native-access=ALL-UNNAMED -Xmx4g -XX:+UseParallelGC -cp $jar carom.lab.bench.GasBench fast $n $phi $cpd 6 "$t" 1 3 2>&1 | grep "^fast,")
  echo "$r $t $line $(cut -d' ' -f1 /proc/loadavg)" >> $out
done; done
