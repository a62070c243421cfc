#!/bin/bash
# usage: table.sh JAR OUTFILE [timeout]  -- every example, fast then slabs (threads 2), summary counters
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
J=$1; OUT=$2; TO=${3:-300}
cd /work/wt-slabsfix
echo "# $(date -u) load $(cut -d' ' -f1-3 /proc/loadavg)" >> $OUT
for f in examples/*.json; do
  s=$(basename $f .json)
  for e in fast slabs; do
    rm -f /tmp/sfx/s.json
    start=$(date +%s.%N)
    timeout $TO $JAVA -jar $J simulate $f --engine $e --threads 2 --summary /tmp/sfx/s.json >/dev/null 2>&1
    rc=$?
    end=$(date +%s.%N)
    if [ -f /tmp/sfx/s.json ]; then
      python3 - "$s" "$e" "$(cut -d' ' -f1 /proc/loadavg)" <<'PY' >> $OUT
import json,sys
d=json.load(open('/tmp/sfx/s.json'));c=d.get('counters',{})
print(sys.argv[1],sys.argv[2],'wall=%.3f'%d['wallSeconds'],'pair=%d'%d['collisions']['pair'],'events=%d'%d['events'],
 'windows=%s'%c.get('windows','-'),'rollbacks=%s'%c.get('rollbacks','-'),'undone=%s'%c.get('undoneEvents','-'),
 'cross=%s'%c.get('crossDomainEvents','-'),'migr=%s'%c.get('migrations','-'),'load=%s'%sys.argv[3])
PY
    else
      echo "$s $e TIMEOUT/FAIL rc=$rc after $(echo "$end - $start" | bc) s load=$(cut -d' ' -f1 /proc/loadavg)" >> $OUT
    fi
  done
done
