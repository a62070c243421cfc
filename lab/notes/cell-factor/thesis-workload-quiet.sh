#!/bin/bash
# Quiet check of the new cellFactor default on the thesis workload (N = 1e6, phi 0.126), fast and slabs on 2 threads
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
for order in "cellFactor=1,cellFactor=1.380952,cellFactor=2" "cellFactor=2,cellFactor=1.380952,cellFactor=1"; do
  echo "# $(date -u +%FT%TZ) load before: $(cut -d' ' -f1-3 /proc/loadavg)"
  $J -Xmx10g -XX:+UseParallelGC -jar /tmp/lab-final.jar bench ThesisWorkload -p engine=fast,slabs -p threads=2 -p n=1000000 \
     -p "tunables=$order" -wi 2 -i 5 2>&1 | grep -E "^ThesisWorkloadBenchmark|^Benchmark"
  echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
done
