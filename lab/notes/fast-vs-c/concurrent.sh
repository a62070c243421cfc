#!/bin/bash
# usage: concurrent.sh OUT ROUNDS N PHI PERDISC REPEATS WARM : C port and Java fast at once, one per core, cores swapped each round
# The paths default to the first measurement's (2026-11-22); stop 33 ran it with
#   JAR=/tmp/fc/carom-lab-06b957a.jar CLASS=carom.lab.bench.GasBench FASTC=/tmp/fc/fastc GASDIR=/tmp/fc
OUT=$1; R=$2; N=$3; PHI=$4; PER=$5; REP=$6; W=$7
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
# Extra JVM flags, e.g. JAVA_OPTS=--enable-native-access=ALL-UNNAMED for the prefetch helper (stop 34).
JAVA_OPTS=${JAVA_OPTS:-}
JAR=${JAR:-/tmp/bench-ca94c87.jar}; CLASS=${CLASS:-carom.jmh.GasBench}; FASTC=${FASTC:-/tmp/alt/fastc}; GASDIR=${GASDIR:-/tmp}
echo "# N=$N phi $PHI, $PER collisions per disc, $W warm-up + $REP timed runs; C port (gcc 12.2 -O3 -march=native -ffp-contract=off) and Java fast (GasBench, $JAR $JAVA_OPTS) at the same time, one per core, cores swapped each round; $(grep -m1 'model name' /proc/cpuinfo)" >> $OUT
for r in $(seq 1 $R); do
  cj=$(( r % 2 )); cc=$(( 1 - cj ))
  echo "# round $r $(date +%H:%M:%S) java on cpu $cj, load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
  taskset -c $cj $JAVA $JAVA_OPTS -Xmx10g -XX:+UseParallelGC -cp $JAR $CLASS fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" > /tmp/cvj-j.txt &
  taskset -c $cc $FASTC $GASDIR/gas-$N-$PHI.bin $REP $W | grep "^c," > /tmp/cvj-c.txt &
  wait
  cat /tmp/cvj-j.txt /tmp/cvj-c.txt >> $OUT
done
echo "# end $(date +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
