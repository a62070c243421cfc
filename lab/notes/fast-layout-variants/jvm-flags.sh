#!/bin/bash
# usage: abf.sh OUT ROUNDS N PHI PERDISC REPEATS WARM "VARIANT FLAGS"
OUT=$1; R=$2; N=$3; PHI=$4; PER=$5; REP=$6; W=$7; VF=$8
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
echo "# fast ca94c87, base flags vs variant flags [$VF]; N=$N phi $PHI, $PER coll/disc, $W warm-up + $REP timed; at once, one per core, swapped each round" > $OUT
for r in $(seq 1 $R); do
  cb=$(( r % 2 )); cv=$(( 1 - cb ))
  echo "# round $r $(date +%H:%M:%S)" >> $OUT
  taskset -c $cb $JAVA -Xmx10g -XX:+UseParallelGC -cp /tmp/bench-ca94c87.jar carom.jmh.GasBench fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" > /tmp/abf-b.txt &
  taskset -c $cv $JAVA -Xmx10g -XX:+UseParallelGC $VF -cp /tmp/bench-ca94c87.jar carom.jmh.GasBench fast $N $PHI $PER $REP "" 1 $W 2>&1 | grep -E "^fast" > /tmp/abf-v.txt &
  wait
  echo "# base" >> $OUT; cat /tmp/abf-b.txt >> $OUT
  echo "# variant" >> $OUT; cat /tmp/abf-v.txt >> $OUT
done
