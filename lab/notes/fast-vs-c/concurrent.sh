#!/bin/bash
# usage: cvj.sh OUT ROUNDS N PHI PERDISC REPEATS WARM : C port and Java fast at once, one per core, cores swapped each round
OUT=$1; R=$2; N=$3; PHI=$4; PER=$5; REP=$6; W=$7
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
echo "# N=$N phi $PHI, $PER collisions per disc, $W warm-up + $REP timed runs; C port (gcc 12.2 -O3 -march=native -ffp-contract=off) and Java fast (GasBench, ca94c87) at the same time, one per core, cores swapped each round" >> $OUT
for r in $(seq 1 $R); do
  cj=$(( r % 2 )); cc=$(( 1 - cj ))
  echo "# round $r $(date +%H:%M:%S) java on cpu $cj" >> $OUT
  taskset -c $cj $JAVA -Xmx10g -XX:+UseParallelGC -cp /tmp/bench-ca94c87.jar carom.jmh.GasBench fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" > /tmp/cvj-j.txt &
  taskset -c $cc /tmp/alt/fastc /tmp/gas-$N-$PHI.bin $REP $W | grep "^c," > /tmp/cvj-c.txt &
  wait
  cat /tmp/cvj-j.txt /tmp/cvj-c.txt >> $OUT
done
