#!/bin/sh
# histogram.sh JAR SCENE DELAY OUT [JVM flags...]: runs 'simulate SCENE --engine fast' on JAR and, DELAY
# seconds in, appends the heap's class histogram (jcmd GC.class_histogram, which collects first, so it
# shows what is live) to OUT; then /usr/bin/time -v's maximum resident set of the whole run.
set -eu
jar=$1 scene=$2 delay=$3 out=$4
shift 4
root=$(cd "$(dirname "$0")/../../.." && pwd)
. "$root/.mvn/find-jdk.sh"
/usr/bin/time -v -o "$out.time" "$JAVA_HOME/bin/java" --enable-native-access=ALL-UNNAMED "$@" -jar "$jar" \
    simulate "$scene" --engine fast --allow-long --summary "$out.summary.json" > /dev/null &
sleep "$delay"
pid=$(pgrep -f -n "simulate $scene" || true)
{
  echo "# $(date -u +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg), $delay s into: java $* -jar $jar simulate $scene"
  [ -n "$pid" ] && "$JAVA_HOME/bin/jcmd" "$pid" GC.class_histogram | head -n 14
} >> "$out"
wait
grep -E "Maximum resident|Elapsed" "$out.time" >> "$out"
rm -f "$out.time"
