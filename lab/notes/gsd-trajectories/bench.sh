#!/bin/sh
# lab/notes/gsd-trajectories/bench.sh N FRAMES PAIRS: the cost of writing a trajectory frame, GSD against
# extended XYZ. For a periodic gas of N discs at packing fraction 0.5 (examples/gas.json scaled up), runs
# `fast` PAIRS times in each of three ways, in rotating order within a round: no trajectory, FRAMES
# frames of extended XYZ, FRAMES frames of GSD (the same run, sampled every 0.01). Prints one line a run:
#   N format round wall_s cpu_s bytes
# (cpu_s = user + system of the whole JVM) and the load average before each round. The cost of a frame
# is (cpu of a run with frames - cpu of the plain run of its round) / FRAMES; bytes / (FRAMES N) is the
# size of a frame per disc. Run from the repository root; files go to a temporary folder, removed.
set -eu
n=${1:?N}; frames=${2:?FRAMES}; pairs=${3:?PAIRS}
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
side=$(python3 -c "import math; print(50 * math.sqrt($n / 2500))")
every=0.01
until=$(python3 -c "print(round($every * ($frames - 1), 10))")
sed -e "s/\"width\": 50, \"height\": 50/\"width\": $side, \"height\": $side/" -e "s/\"count\": 2500/\"count\": $n/" \
    -e "s/\"until\": 5.0/\"until\": $until/" "$root/examples/gas.json" > "$work/gas.json"
export CAROM_AOT=0
run() { # format round
  rm -f "$work/frames.xyz" "$work/frames.gsd"
  case $1 in
    none) set -- "$1" "$2" ;;
    xyz) set -- "$1" "$2" --trajectory "$work/frames.xyz" ;;
    gsd) set -- "$1" "$2" --trajectory "$work/frames.gsd" ;;
  esac
  format=$1; round=$2; shift 2
  /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$root/carom" simulate "$work/gas.json" --every "$every" "$@" \
      > /dev/null 2> "$work/err.txt" || { cat "$work/err.txt" >&2; exit 1; }
  bytes=0
  [ $format = none ] || bytes=$(stat -c %s "$work/frames.$format")
  read -r wall user sys < "$work/time.txt"
  echo "$n $format $round $wall $(python3 -c "print(round($user + $sys, 2))") $bytes"
}
"$root/carom" engines > /dev/null 2>&1 # build the jar first, outside the timings
for r in $(seq 1 "$pairs"); do
  echo "# round $r, load $(cut -d' ' -f1-3 /proc/loadavg)"
  case $((r % 3)) in
    1) order="none xyz gsd" ;;
    2) order="xyz gsd none" ;;
    0) order="gsd none xyz" ;;
  esac
  for f in $order; do run "$f" "$r"; done
done
