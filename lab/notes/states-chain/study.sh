#!/bin/sh
# The issue's study, as a user would run it: a 50:50 mixture of radii 0.5 and 0.7 (4,000 discs) generated
# on a lattice at packing fraction 0.55, compressed to 0.70, run from the state, and reported.
#   sh lab/notes/states-chain/study.sh [OUT]      (from the clone's root; OUT default /tmp/states-chain)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
carom="$here/../../../carom"
out=${1:-/tmp/states-chain}
mkdir -p "$out"
cp "$here/grow.json" "$here/mix.json" "$out/"
cd "$out"
"$carom" compress grow.json --to-phi 0.70 --every 1 --out-state s.json --summary compress.json
"$carom" simulate mix.json --from s.json --until 20 --trajectory-every 1 --trajectory frames.xyz \
  --observe gr,msd,psi6,pressure --observe-every 0.1 --report r --summary run.json
"$carom" report r --out page.html
