#!/bin/bash
# EOS study, N=4096, both starts, seed 2, quiet-ish machine (this session's builds share it, under nice 19 here)
cd /work/eosrun
( while true; do echo "$(date -u +%FT%TZ) $(cut -d' ' -f1-3 /proc/loadavg)"; sleep 60; done ) > load-during-run.log &
LOGGER=$!
trap 'kill $LOGGER' EXIT
nice -n 19 /usr/lib/jvm/temurin-25-jdk-amd64/bin/java -jar carom-lab.jar study eos --n 4096 \
  --phis 0.69,0.70,0.705,0.71,0.715,0.72 --engine fast --start both --block-collisions 50 --window 10 --blocks 64 \
  --deadline 2026-12-02T06:45:00Z --fill-to-deadline --snapshots 0.70,0.71,0.72 --seed 2 --out eos4096-seed2 > study.log 2>&1
echo "exit $?" >> study.log
