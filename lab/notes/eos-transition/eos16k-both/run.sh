#!/bin/bash
# EOS study, N=16384 (128 rows of 128), both starts, seed 3, fresh quiet VM; this session's builds share it, under nice 19 here
cd /work/eosrun16k   # the lab jar of commit ebe7cf7, copied here
( while true; do echo "$(date -u +%FT%TZ) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) > load-during-run.log &
LOGGER=$!
trap 'kill $LOGGER' EXIT
nice -n 19 /usr/lib/jvm/temurin-25-jdk-amd64/bin/java -jar carom-lab.jar study eos --n 16384 \
  --phis 0.70,0.71,0.72 --engine fast --start both --block-collisions 50 --window 10 --blocks 64 \
  --deadline 2026-12-02T14:30:00Z --fill-to-deadline --snapshots 0.70,0.71,0.72 --seed 3 --out eos16k-both > study.log 2>&1
echo "exit $?" >> study.log
