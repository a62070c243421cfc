#!/bin/bash
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
for round in 1 2; do
  for v in base blocks; do
    [ $round = 2 ] && v=$([ $v = base ] && echo blocks || echo base)
    echo "round $round $v load $(cut -d' ' -f1 /proc/loadavg)"
    $J -Xmx10g -XX:+UseParallelGC -cp /tmp/lab-$v.jar carom.lab.bench.GasBench slabs 1000000 0.5 4 3 "sequential=true" 2 1 2>&1 | grep -v "^#" | tail -2
  done
done
