#!/bin/bash
# usage: jarpairs.sh SCENE ROUNDS T1 T2 OUT JAR...
set -eu
scene=$1; rounds=$2; t1=$3; t2=$4; out=$5; shift 5
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
for r in $(seq 1 $rounds); do for t in $t1 $t2; do for jar in "$@"; do
  /usr/bin/time -f "%U %S" -o /tmp/jp.cpu $J --sun-misc-unsafe-memory-access=allow -jar $jar simulate $scene --engine fast --until $t --summary /tmp/jp.json >/dev/null 2>&1
  c=$(python3 -c "import json;print(json.load(open('/tmp/jp.json'))['collisions']['pair'])")
  echo "$r $(basename $jar .jar) $t $(awk '{print $1+$2}' /tmp/jp.cpu) $c $(cut -d' ' -f1 /proc/loadavg)" >> $out
done; done; done
