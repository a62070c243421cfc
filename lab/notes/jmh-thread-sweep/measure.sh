#!/bin/sh
# The JMH runs behind docs/measurements/jmh/README.md, one result file per step:
#   docs/measurements/jmh/measure.sh akka-throughput [ROUND] | akka-throughput-paired | sweep-PHI | sweep-PHI-cell
# Few iterations (1 warm-up of 2 s, 3 measured of 3 s, 1 fork) to keep a sweep under ten minutes
# on 2 cores; the load average is logged every 15 s beside each result (STEP.load).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bench="$here/../../../jmh/bench"
quick="-f 1 -wi 1 -i 3 -w 2s -r 3s"

with_load() { # STEP OUT COMMAND...: runs COMMAND into OUT with the load average logged in STEP.load
  step=$1; out=$2; shift 2
  (while :; do echo "$(date +%T) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 15; done) > "$here/$step.load" &
  logger=$!
  status=0
  "$@" > "$out" 2>&1 || status=$?
  kill "$logger"
  return "$status"
}

logged() { # STEP JMH-ARGS...: GasThroughput at N = 1e5, STEP.json and JMH's text output STEP.txt
  step=$1; shift
  # shellcheck disable=SC2086
  with_load "$step" "$here/$step.txt" "$bench" GasThroughput -p n=100000 $quick -rf json -rff "$here/$step.json" "$@"
}

case "${1:-}" in
  akka-throughput)
    # The akka dispatcher's throughput at 2 threads: one actor per thread, and 4 x 4 blocks.
    # Repeated in rounds (ROUND names the files) because the machine is shared: compare within a round.
    logged "akka-throughput${2:+-$2}" -p engine=akka -p phi=0.5 -p threads=2 -p cellsPerActor=perThread,16 \
      -p tunables=throughput=1,throughput=5,throughput=20,throughput=100 ;;
  akka-throughput-paired)
    # The same comparison run by run in one JVM, settings shuffled within each of 15 rounds (see the class).
    . "$here/../../../.mvn/find-jdk.sh"
    # shellcheck disable=SC2086
    with_load "$1" "$here/$1.csv" "$JAVA_HOME/bin/java" $CAROM_UNSAFE_OPT -Xmx8g -XX:+UseParallelGC \
      -cp "$here/../../../jmh/target/benchmarks.jar" "$here/AkkaThroughputPaired.java" 15 ;;
  sweep-*-cell)
    phi=${1#sweep-}; phi=${phi%-cell}
    # The thesis's one actor per cell: 50 to 100 times slower, so a tenth of a collision per disc per run.
    logged "$1" -p engine=akka,vthreads -p phi="$phi" -p threads=1,2,4 -p cellsPerActor=1 \
      -p collisionsPerDisc=0.1 ;;
  sweep-*)
    # Every engine, one actor per thread for the actor engines; serial engines ignore threads, so
    # their three rows are the same run three times (the day's noise).
    logged "$1" -p engine=serial,fast,stripes,akka,vthreads -p phi="${1#sweep-}" -p threads=1,2,4 \
      -p cellsPerActor=perThread ;;
  *)
    echo "usage: $0 akka-throughput [ROUND] | akka-throughput-paired | sweep-PHI | sweep-PHI-cell" >&2; exit 2 ;;
esac
