#!/bin/bash
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
OUT=/tmp/sfx/gasbench-1e6.txt
while pgrep -f "gas.sh 200000" >/dev/null; do sleep 5; done
for spec in slabs:after4 fast:after4 slabs:before; do
  e=${spec%%:*}; v=${spec#*:}
  echo "## $e $v N=1e6 load $(cut -d' ' -f1-3 /proc/loadavg) $(date -u +%H:%M:%S)" >> $OUT
  $JAVA -Xmx8g -cp /tmp/sfx/carom-lab-$v.jar carom.lab.bench.GasBench $e 1000000 0.5 10 1 "" 2 0 2>&1 | grep -v "machine" >> $OUT
done
