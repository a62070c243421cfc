#!/bin/bash
# run.sh [COUNT]: every pile of make_piles.py with fast, serial, slabs (default) and slabs kept to
# windows; one line per pile: the first stderr line of each engine that stopped, "ok" for the others.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
python3 "$here/make_piles.py" "$dir" "${1:-12}"
cd "$root"
for f in $(ls "$dir"/wp*.json | sort -V); do
  echo "## $(basename "$f" .json)"
  for e in "fast" "serial" "slabs --threads 2" "slabs --threads 2 --option mergeEvents=1 --option windowEvents=0 --option estimateWindows=false"; do
    # shellcheck disable=SC2086
    msg=$(./carom simulate "$f" --engine $e 2>&1 >/dev/null | grep -m1 "^error" | sed "s|$dir/||" | cut -c1-200)
    echo "$e: ${msg:-ok}"
  done
done
