#!/bin/sh
# usage: lab/notes/open-core/bench-pairs.sh BEFORE_JAR AFTER_JAR [ROUNDS]
# Collisions per second of `fast` before and after a change, in pairs of fresh JVMs, alternating which
# jar runs first in each round, on GasBench's equilibrated periodic gas: N = 10,000 and 1,000,000 at
# packing fraction 0.5 (cell scans), and N = 11,664 at 0.72 (neighbour lists, the default there).
# One line per pair: case, round, before and after collisions/s, and after/before; then each case's
# median ratio (above 1: the change is faster). The JARs are lab jars (lab/target/carom-lab.jar).
# Make the "before" jar from the commit to compare against, outside any worktree:
#   mkdir /tmp/before && git archive COMMIT | tar -x -C /tmp/before
#   (cd /tmp/before && ./mvnw -q -B -o -pl lab -am package -DskipTests)   # /tmp/before/lab/target/carom-lab.jar
# Environment: ROUNDS (default 5, or the third argument), PER_DISC (collisions per disc per run,
# default 10), REPEATS (timed runs per JVM, default 3), WARMUPS (untimed runs first, default 1),
# JAVA_OPTS (default -Xmx6g, enough for a million discs), CASES (default all three, e.g. "10000:0.5").
# Run it on a quiet machine: the ratios mean nothing while other work shares the cores.
set -eu
before=$1; after=$2; rounds=${3:-${ROUNDS:-5}}
root=$(cd "$(dirname "$0")/../../.." && pwd)
. "$root/.mvn/find-jdk.sh"
java="$JAVA_HOME/bin/java"
opts=${JAVA_OPTS:--Xmx6g}
cases=${CASES:-"10000:0.5 1000000:0.5 11664:0.72"}
lines=$(mktemp); trap 'rm -f "$lines"' EXIT INT TERM

# Mean collisions/s of one fresh JVM of jar $1 on N = $2 at packing fraction $3.
rate() {
  # shellcheck disable=SC2086
  "$java" $opts --enable-native-access=ALL-UNNAMED -cp "$1" carom.lab.bench.GasBench fast "$2" "$3" \
      "${PER_DISC:-10}" "${REPEATS:-3}" "" 1 "${WARMUPS:-1}" | awk -F, '$1 == "fast" { print $4 }'
}

echo "case round before after ratio"
for c in $cases; do
  n=${c%%:*}; phi=${c#*:}
  r=1
  while [ "$r" -le "$rounds" ]; do
    if [ $((r % 2)) -eq 1 ]; then
      b=$(rate "$before" "$n" "$phi"); a=$(rate "$after" "$n" "$phi")
    else
      a=$(rate "$after" "$n" "$phi"); b=$(rate "$before" "$n" "$phi")
    fi
    ratio=$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", a / b }')
    echo "N=$n,phi=$phi $r $b $a $ratio" | tee -a "$lines"
    r=$((r + 1))
  done
done
echo "# median after/before per case"
for c in $cases; do
  n=${c%%:*}; phi=${c#*:}
  awk -v k="N=$n,phi=$phi" '$1 == k { print $5 }' "$lines" | sort -g \
    | awk -v k="N=$n,phi=$phi" '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%s median %.4f over %d pairs\n", k, m, NR }'
done
