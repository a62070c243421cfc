#!/bin/bash
# usage: conc.sh OUT ROUNDS N PHI PERDISC REPEATS WARM : C port and Java fast at once, one per core, cores swapped each round
OUT=$1; R=$2; N=$3; PHI=$4; PER=$5; REP=$6; W=$7
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
echo "# N=$N phi $PHI, $PER collisions per disc, $W warm-up + $REP timed runs; C port (fastc.c, gcc 12.2 -O3 -march=native -ffp-contract=off) and Java fast (GasBench, commit 06b957a, Temurin 25.0.3, -Xmx10g -XX:+UseParallelGC) at the same time, one per core (taskset), cores swapped each round; $(grep -m1 'model name' /proc/cpuinfo)" >> $OUT
for r in $(seq 1 $R); do
  cj=$(( r % 2 )); cc=$(( 1 - cj ))
  echo "# round $r $(date +%H:%M:%S) java on cpu $cj, load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
  taskset -c $cj $JAVA -Xmx10g -XX:+UseParallelGC -cp /tmp/fc/carom-lab-06b957a.jar carom.lab.bench.GasBench fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" > /tmp/fc/cj.txt &
  taskset -c $cc /tmp/fc/fastc /tmp/fc/gas-$N-$PHI.bin $REP $W | grep "^c," > /tmp/fc/cc.txt &
  wait
  cat /tmp/fc/cj.txt /tmp/fc/cc.txt >> $OUT
done
echo "# end $(date +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
