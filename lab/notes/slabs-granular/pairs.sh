#!/bin/bash
# usage (as run in the session; paths are its own): pairs.sh OUT ROUNDS JAR... -- every example, fast then slabs of each jar, ROUNDS rounds
JAVA=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java
OUT=$1; R=$2; shift 2
cd /work/wt-slabsfix
for r in $(seq 1 $R); do
for f in examples/*.json; do
  s=$(basename $f .json); case " ${SKIP:-} " in *" $s "*) continue;; esac
  for spec in "fast:$1" $(for j in "$@"; do echo "slabs:$j"; done); do
    e=${spec%%:*}; J=${spec#*:}
    rm -f /tmp/sfx/p.json
    /usr/bin/time -f "%U %S" -o /tmp/sfx/cpu.txt timeout 400 $JAVA -jar $J simulate $f --engine $e --threads 2 --summary /tmp/sfx/p.json >/dev/null 2>&1
    if [ -f /tmp/sfx/p.json ]; then
      python3 - "$s" "$e" "$(basename $J .jar)" "$r" "$(cut -d' ' -f1 /proc/loadavg)" "$(tail -1 /tmp/sfx/cpu.txt)" <<'PY' >> $OUT
import json,sys
d=json.load(open('/tmp/sfx/p.json'));c=d.get('counters',{})
print(sys.argv[4],sys.argv[1],sys.argv[2],sys.argv[3],'%.4f'%d['wallSeconds'],d['collisions']['pair'],d['events'],
 c.get('windows','-'),c.get('rollbacks','-'),c.get('undoneEvents','-'),c.get('merges','-'),c.get('mergedEvents','-'),sys.argv[5],'%.2f'%sum(map(float,sys.argv[6].split())))
PY
    else echo "$r $s $e $(basename $J .jar) TIMEOUT" >> $OUT; fi
  done
done
done
