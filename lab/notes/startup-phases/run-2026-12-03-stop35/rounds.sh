#!/bin/bash
# Alternating rounds on the periodic thesis workload, N = 1e6: the C port (3 runs), fast (1 thread) and
# slabs (2 threads), each a fresh JVM with 4 runs (the first cold). Load logged per round.
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
for r in 1 2 3 4; do
  echo "# round $r, load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%H:%M:%S)"
  PHASES=1 DILUTE_CELLS=1 ./fastc thesis-1e6.bin 3 0 2>&1
  $J --enable-native-access=ALL-UNNAMED -Xmx10g -XX:+UseParallelGC -cp lab.jar:cls carom.lab.bench.ThesisDump 1000000 1 - fast 4 "" 1
  $J --enable-native-access=ALL-UNNAMED -Xmx10g -XX:+UseParallelGC -cp lab.jar:cls carom.lab.bench.ThesisDump 1000000 1 - slabs 4 "" 2
done
echo "# end, load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%H:%M:%S)"
