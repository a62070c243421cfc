#!/bin/sh
# usage: lab/notes/granular-effects/cpu-pairs.sh BEFORE_JAR AFTER_JAR [ROUNDS]
# What a change costs a scene that does not use it, on a machine other work shares: the CPU seconds
# (perf's task-clock: every thread of the JVM, user and system) of one fresh JVM running GasBench on
# `fast` (an equilibrated periodic elastic gas at packing fraction 0.5, no effect named), before and
# after, alternating which jar runs first in each round. Both jars simulate the same collisions, so the
# CPU seconds compare the same work; CPU time, unlike wall time, does not count the time slices other
# processes take (the cache they share still moves it). The JARs are lab jars (lab/target/carom-lab.jar);
# lab/notes/open-core/bench-pairs.sh says how to build the "before" one. One line per pair: case,
# round, before and after CPU seconds, after/before (below 1: the change is cheaper).
# Environment: ROUNDS (default 8, or the third argument); CASES (N:collisions per disc per timed run,
# default "10000:100 100000:20"), 3 timed runs and 1 warm-up per JVM, -Xmx3g, one processor for the JVM.
set -eu
before=$1; after=$2; rounds=${3:-${ROUNDS:-8}}
root=$(cd "$(dirname "$0")/../../.." && pwd)
. "$root/.mvn/find-jdk.sh"
java="$JAVA_HOME/bin/java"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT INT TERM

# CPU seconds of one fresh JVM of jar $1 on N = $2 at $3 collisions per disc per timed run.
cpu() {
  perf stat -x, -e task-clock -o "$tmp/perf" -- "$java" -Xmx3g -XX:ActiveProcessorCount=1 \
      --enable-native-access=ALL-UNNAMED -cp "$1" carom.lab.bench.GasBench fast "$2" 0.5 "$3" 3 "" 1 1 >/dev/null
  awk -F, '/task-clock/ { printf "%.3f", $1 / 1000 }' "$tmp/perf"
}

echo "case round before_cpu_s after_cpu_s after/before"
for c in ${CASES:-"10000:100 100000:20"}; do
  n=${c%%:*}; per=${c#*:}
  r=1
  while [ "$r" -le "$rounds" ]; do
    if [ $((r % 2)) -eq 1 ]; then
      b=$(cpu "$before" "$n" "$per"); a=$(cpu "$after" "$n" "$per")
    else
      a=$(cpu "$after" "$n" "$per"); b=$(cpu "$before" "$n" "$per")
    fi
    echo "N=$n $r $b $a $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", a / b }')"
    r=$((r + 1))
  done
done
