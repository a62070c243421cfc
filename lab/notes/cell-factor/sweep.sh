#!/bin/bash
# cellFactor sweep for fast, one thread, alternating order per pass
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
N=${N:-100000}
for pass in 1 2; do
  list="1 1.5 2 3"; [ $pass = 2 ] && list="3 2 1.5 1"
  for cf in $list; do
    echo "pass $pass cf $cf load $(cut -d' ' -f1 /proc/loadavg)"
    $J -Xmx10g -XX:+UseParallelGC -cp /tmp/lab-blocks.jar carom.lab.bench.GasBench fast $N 0.05,0.1,0.2,0.3 10 3 "cellFactor=$cf" 1 1 2>&1 | grep -v "^#" | grep -v "^engine"
  done
done
