#!/bin/bash
# EOS study, N=16384 (128 rows of 128, the 1 : sqrt(3)/2 box of Li et al. 2022's 128^2 runs), the two
# densities where their data are nearest ours: 0.704 (the loop's top) and 0.716 (its floor); both starts,
# seed 4; under nice 19 beside this session's edits (builds and measurements pause it with SIGSTOP).
cd /work/eosrun16k-li   # the lab jar of commit 3de634c, copied here
( while true; do echo "$(date -u +%FT%TZ) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) > load-during-run.log &
LOGGER=$!
trap 'kill $LOGGER' EXIT
nice -n 19 /usr/lib/jvm/temurin-25-jdk-amd64/bin/java -jar carom-lab.jar study eos --n 16384 \
  --phis 0.704,0.716 --engine fast --start both --block-collisions 50 --window 10 --blocks 64 \
  --deadline 2026-12-02T17:10:00Z --fill-to-deadline --snapshots 0.704,0.716 --seed 4 --out eos16k-li > study.log 2>&1
echo "exit $?" >> study.log
