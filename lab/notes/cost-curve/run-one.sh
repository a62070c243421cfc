#!/bin/sh
# run-one.sh CODE N PHI UNTIL ROWS: one whole run of CODE on the periodic gas of gas-scene.sh (N discs,
# packing fraction PHI, to UNTIL), appending one CSV row to ROWS:
#   code,n,phi,until,collisions,engine_s,command_s,max_rss_kb,bytes_per_disc,load1,started
# CODE: fast | slabs2 (slabs --threads 2) | c (the C port of lab/notes/fast-vs-c, binary $FASTC).
# engine_s: carom's wallSeconds (first predictions, loop, final state; not reading the scene or laying
# out the table); the C port's own time for its table, first predictions, loop and final state.
# command_s and max_rss_kb: /usr/bin/time -v of the whole process (JVM start, scene, outputs).
# CAROM (default ./carom of this checkout) runs carom, through its launcher; WORK holds the scenes and
# dumps (default /tmp/cost-curve).
set -eu
code=$1 n=$2 phi=$3 until=$4 rows=$5
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
CAROM=${CAROM:-$root/carom}
WORK=${WORK:-/tmp/cost-curve}
mkdir -p "$WORK"
scene="$WORK/gas-$n-$phi-$until.json"
[ -f "$scene" ] || "$here/gas-scene.sh" "$n" "$phi" "$until" > "$scene"
load=$(cut -d' ' -f1 /proc/loadavg)
started=$(date -u +%H:%M:%S)
timing="$WORK/time-$$.txt"
summary="$WORK/summary-$$.json"
case "$code" in
  fast|slabs2)
    engine=fast threads=1
    [ "$code" = slabs2 ] && engine=slabs threads=2
    /usr/bin/time -v -o "$timing" "$CAROM" simulate "$scene" --engine "$engine" --threads "$threads" \
        --allow-long --summary "$summary" > /dev/null
    read -r collisions engine_s <<PY
$(python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(s["collisions"]["pair"] + s["collisions"]["wall"], s["wallSeconds"])' "$summary")
PY
    ;;
  c)
    dump="$WORK/gas-$n-$phi-$until.bin"
    if [ ! -f "$dump" ]; then
      . "$root/.mvn/find-jdk.sh"
      "$JAVA_HOME/bin/java" -cp "$root/app/target/carom.jar" "$here/DumpGas.java" "$scene" "$dump"
    fi
    /usr/bin/time -v -o "$timing" "${FASTC:-$WORK/fastc}" "$dump" 1 0 > "$WORK/c-$$.txt"
    collisions=$(sed -n 's/^c port: collisions \([0-9]*\) .* in \([0-9.]*\) s,.*/\1/p' "$WORK/c-$$.txt")
    engine_s=$(sed -n 's/^c port: collisions \([0-9]*\) .* in \([0-9.]*\) s,.*/\2/p' "$WORK/c-$$.txt")
    rm -f "$WORK/c-$$.txt"
    ;;
  *) echo "error: unknown code $code (fast, slabs2 or c)" >&2; exit 2 ;;
esac
rss=$(sed -n 's/^[[:space:]]*Maximum resident set size (kbytes): //p' "$timing")
wall=$(sed -n 's/^[[:space:]]*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$timing" \
  | awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; print s }')
rm -f "$timing" "$summary"
[ -f "$rows" ] || echo "code,n,phi,until,collisions,engine_s,command_s,max_rss_kb,bytes_per_disc,load1,started" > "$rows"
echo "$code,$n,$phi,$until,$collisions,$engine_s,$wall,$rss,$(( rss * 1024 / n )),$load,$started" >> "$rows"
