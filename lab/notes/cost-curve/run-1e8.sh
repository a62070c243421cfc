#!/bin/sh
# run-1e8.sh OUTDIR [ENGINE THREADS UNTIL N]: the large run of the note, through ./carom's launcher (the
# heap it sizes), with /usr/bin/time -v, the collector's log and the summary in OUTDIR. Defaults: fast,
# 1 thread, until 0.37 (about one collision a disc from the lattice start), N = 1e8, packing fraction 0.5.
# Needs about 15.3 GB free for fast (21.5 for slabs): check 'free -g' first.
set -eu
out=$1 engine=${2:-fast} threads=${3:-1} until=${4:-0.37} n=${5:-100000000}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
scene="$out/gas-$n-0.5-$until.json"
"$here/gas-scene.sh" "$n" 0.5 "$until" > "$scene"
tag="$out/$engine-$threads-$n"
{ echo "# $(date -u +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)"; free -m; } > "$tag.txt"
CAROM_JAVA_OPTS="-Xlog:gc:file=$tag.gc.log" /usr/bin/time -v -o "$tag.time" "$here/../../../carom" simulate "$scene" \
    --engine "$engine" --threads "$threads" --allow-long --summary "$tag.summary.json" >> "$tag.txt" 2>&1
{ echo "# end $(date -u +%H:%M:%S) load $(cut -d' ' -f1-3 /proc/loadavg)"; cat "$tag.time"; } >> "$tag.txt"
rm -f "$tag.time"
