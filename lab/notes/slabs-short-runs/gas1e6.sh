#!/bin/bash
# usage: lab/notes/slabs-short-runs/gas1e6.sh OUT [ROUNDS] -- GasBench's dense periodic gas (N = 1e6,
# phi = 0.5, 10 collisions a disc, 1 warm-up then 1 timed run), `fast` then `slabs` on 2 threads per
# round, with the load average before each. Needs the lab jar (./mvnw -pl lab -am package -DskipTests).
set -eu
root=$(cd "$(dirname "$0")/../../.." && pwd)
. "$root/.mvn/find-jdk.sh"
out=$1; rounds=${2:-3}
for r in $(seq 1 "$rounds"); do
  for e in fast slabs; do
    echo "## round $r $e N=1e6 load $(cut -d' ' -f1-3 /proc/loadavg) $(date -u +%H:%M:%S)" >> "$out"
    "$JAVA_HOME/bin/java" $CAROM_UNSAFE_OPT -Xmx8g -cp "$root/lab/target/carom-lab.jar" carom.lab.bench.GasBench \
        $e 1000000 0.5 10 1 "" 2 1 2>&1 | grep -v machine >> "$out"
  done
done
echo "## done load $(cut -d' ' -f1-3 /proc/loadavg) $(date -u +%H:%M:%S)" >> "$out"
