#!/bin/bash
# usage: cvjs.sh OUT ROUNDS N PHI PERDISC REPEATS WARM : C port and Java fast alternating, alone on the machine
OUT=$1; R=$2; N=$3; PHI=$4; PER=$5; REP=$6; W=$7
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
echo "# N=$N phi $PHI, $PER collisions per disc, $W warm-up + $REP timed runs; C port (gcc 12.2 -O3 -march=native -ffp-contract=off) and Java fast (GasBench, ca94c87, -XX:+UseParallelGC) alternating, each alone on the machine" >> $OUT
for r in $(seq 1 $R); do
  echo "# round $r $(date +%H:%M:%S)" >> $OUT
  $JAVA -Xmx10g -XX:+UseParallelGC -cp /tmp/bench-ca94c87.jar carom.jmh.GasBench fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" >> $OUT
  /tmp/alt/fastc /tmp/gas-$N-$PHI.bin $REP $W | grep "^c," >> $OUT
done
