#!/bin/bash
# usage: alt.sh OUT ROUNDS N PHI PERDISC REPEATS WARM : C port and Java fast (GasBench) alternating, each alone on the machine
OUT=$1; R=$2; N=$3; PHI=$4; PER=$5; REP=$6; W=$7
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
echo "# N=$N phi $PHI, $PER collisions per disc, $W warm-up + $REP timed runs; C port (fastc.c, gcc 12.2 -O3 -march=native -ffp-contract=off) and Java fast (GasBench, commit 06b957a, Temurin 25.0.3, -Xmx10g -XX:+UseParallelGC) alternating, each alone; $(grep -m1 'model name' /proc/cpuinfo)" >> $OUT
for r in $(seq 1 $R); do
  echo "# round $r $(date +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
  if [ $((r % 2)) = 1 ]; then
    $JAVA -Xmx10g -XX:+UseParallelGC -cp /tmp/fc/carom-lab-06b957a.jar carom.lab.bench.GasBench fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" >> $OUT
    /tmp/fc/fastc /tmp/fc/gas-$N-$PHI.bin $REP $W | grep "^c," >> $OUT
  else
    /tmp/fc/fastc /tmp/fc/gas-$N-$PHI.bin $REP $W | grep "^c," >> $OUT
    $JAVA -Xmx10g -XX:+UseParallelGC -cp /tmp/fc/carom-lab-06b957a.jar carom.lab.bench.GasBench fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" >> $OUT
  fi
done
echo "# end $(date +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
