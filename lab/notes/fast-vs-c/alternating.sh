#!/bin/bash
# usage: alternating.sh OUT ROUNDS N PHI PERDISC REPEATS WARM : C port and Java fast alternating, each alone on the machine
# The paths default to the first measurement's (2026-11-22); stop 33 ran it with SWAP=1 (who goes first
# changes every round) and JAR=/tmp/fc/carom-lab-06b957a.jar CLASS=carom.lab.bench.GasBench FASTC=/tmp/fc/fastc GASDIR=/tmp/fc
OUT=$1; R=$2; N=$3; PHI=$4; PER=$5; REP=$6; W=$7
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
# Extra JVM flags, e.g. JAVA_OPTS=--enable-native-access=ALL-UNNAMED for the prefetch helper (stop 34).
JAVA_OPTS=${JAVA_OPTS:-}
JAR=${JAR:-/tmp/bench-ca94c87.jar}; CLASS=${CLASS:-carom.jmh.GasBench}; FASTC=${FASTC:-/tmp/alt/fastc}; GASDIR=${GASDIR:-/tmp}
echo "# N=$N phi $PHI, $PER collisions per disc, $W warm-up + $REP timed runs; C port (gcc 12.2 -O3 -march=native -ffp-contract=off) and Java fast (GasBench, $JAR $JAVA_OPTS, -XX:+UseParallelGC) alternating, each alone on the machine; $(grep -m1 'model name' /proc/cpuinfo)" >> $OUT
java_fast() { $JAVA $JAVA_OPTS -Xmx10g -XX:+UseParallelGC -cp $JAR $CLASS fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" >> $OUT; }
c_port() { $FASTC $GASDIR/gas-$N-$PHI.bin $REP $W | grep "^c," >> $OUT; }
for r in $(seq 1 $R); do
  echo "# round $r $(date +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
  if [ "${SWAP:-0}" = 1 ] && [ $((r % 2)) = 0 ]; then c_port; java_fast; else java_fast; c_port; fi
done
echo "# end $(date +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
