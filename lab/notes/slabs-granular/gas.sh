#!/bin/bash
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
OUT=/tmp/sfx/gasbench.txt
N=${1:-200000}
for r in 1 2 3; do
  for spec in slabs:before slabs:after4 fast:after4; do
    e=${spec%%:*}; v=${spec#*:}
    echo "## round $r $e $v N=$N load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
    $JAVA -Xmx8g -cp /tmp/sfx/carom-lab-$v.jar carom.lab.bench.GasBench $e $N 0.5 10 2 "" 2 1 2>&1 | grep -v "^#.*machine" >> $OUT
  done
done
