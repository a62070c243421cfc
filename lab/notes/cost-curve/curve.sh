#!/bin/sh
# curve.sh ROWS ROUNDS "N..." "PHI..." "CODE...": the cost curve's raw rows. For each N, one batch:
# ROUNDS rounds of every CODE (fast, slabs2, c: run-one.sh) at every PHI, the order of the codes
# turned by one each round, so that no code always runs first or last in a batch. Each run goes to
# max(1, 2e6 / N) collisions a disc (UNTIL from the rate a disc collides at that PHI, RATE_05 and
# RATE_072 below, measured at N = 1e4; the runs' own collisions are what the rows report).
# Rerun it on a quiet machine: ROWS gets one row a run with the 1-minute load at its start.
set -eu
rows=$1 rounds=$2 sizes=$3 phis=$4 codes=$5
here=$(cd "$(dirname "$0")" && pwd)
RATE_05=${RATE_05:-3.4}
RATE_072=${RATE_072:-15}
for n in $sizes; do
  n=$(awk -v n="$n" 'BEGIN { printf "%.0f", n }')
  for phi in $phis; do
    rate=$RATE_05
    [ "$phi" = 0.72 ] && rate=$RATE_072
    until=$(awk -v n="$n" -v r="$rate" 'BEGIN { c = 2e6 / n; if (c < 1) c = 1; printf "%.4g", c / r }')
    r=0
    while [ "$r" -lt "$rounds" ]; do
      set -- $codes
      k=0
      while [ "$k" -lt $(( r % $# )) ]; do first=$1; shift; set -- "$@" "$first"; k=$((k + 1)); done
      for code in "$@"; do
        "$here/run-one.sh" "$code" "$n" "$phi" "$until" "$rows" || echo "# $code $n $phi failed" >> "$rows"
      done
      r=$((r + 1))
    done
  done
done
