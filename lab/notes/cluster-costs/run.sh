#!/bin/bash
# run.sh N PER_DISC CONFIG...: the runs of this note, one at a time, from the worktree's root.
#   N         discs (packing fraction 0.5, periodic: GasBench's gas, see make_scene.py)
#   PER_DISC  pair collisions per disc of each measured run (after 2 per disc of equilibration)
#   CONFIG    fast | slabs2 | clusterK (K nodes, default checkpoints) | clusterK-nock (no checkpoint:
#             checkpointWindows=2^40) | clusterKxT-nock (K nodes of T domains each, --threads T, no checkpoint;
#             the domains in the layout with the shortest cuts, blocks where they cut less than slabs)
#             | clusterKxT-nock-slabs (the same, kept to vertical slabs: --option domainRows=1)
# Writes raw/N-CONFIG.json (or into $RAW) (SUMMARY.json), .err (stderr), .proc.json (CPU and peak memory per JVM,
# procwatch.py) and a line per run in raw/runs.log with `uptime` before and after. Large scenes go to
# $SCRATCH (default /tmp/carom-cluster-costs), not into the repository.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
n=$1 perdisc=$2
shift 2
scratch=${SCRATCH:-/tmp/carom-cluster-costs}
raw=${RAW:-$here/raw}
mkdir -p "$scratch" "$raw"
export CAROM_JAVA_OPTS=${CAROM_JAVA_OPTS:--Xmx8g}
cd "$root"
log() { echo "$*" | tee -a "$raw/runs.log"; }

scene=$scratch/gas-$n-eq-$perdisc.json
if [ ! -f "$scene" ]; then
  # Equilibration: 2 pair collisions per disc from the jittered lattice with `fast` (rate guess
  # 4*phi/(1-phi) = 4 per disc per unit time at phi 0.5, as GasBench's), then the state listed.
  python3 "$here/make_scene.py" lattice "$n" 0.5 0.5 "$scratch/gas-$n-lattice.json"
  log "# $(date -u +%FT%TZ) equilibrate N=$n: uptime before: $(uptime)"
  ./carom simulate "$scratch/gas-$n-lattice.json" --engine fast --out "$scratch/gas-$n-eq.csv" \
      --summary "$raw/$n-equilibration.json"
  log "#   uptime after: $(uptime)"
  python3 "$here/make_scene.py" particles "$n" 0.5 "$scratch/gas-$n-eq.csv" "$raw/$n-equilibration.json" \
      "$perdisc" "$scene" | tee -a "$raw/runs.log"
fi

for config in "$@"; do
  case $config in
    fast) args=(--engine fast) ;;
    slabs2) args=(--engine slabs --threads 2) ;;
    cluster*x*-nock-slabs) kt=${config#cluster}; kt=${kt%-nock-slabs}
        args=(--engine cluster --nodes "${kt%x*}" --threads "${kt#*x}" --option checkpointWindows=1099511627776
              --option domainRows=1) ;;
    cluster*x*-nock) kt=${config#cluster}; kt=${kt%-nock}
        args=(--engine cluster --nodes "${kt%x*}" --threads "${kt#*x}" --option checkpointWindows=1099511627776) ;;
    cluster*-nock) k=${config#cluster}; k=${k%-nock}; args=(--engine cluster --nodes "$k" --option checkpointWindows=1099511627776) ;;
    cluster*) args=(--engine cluster --nodes "${config#cluster}") ;;
    *) echo "unknown config $config" >&2; exit 2 ;;
  esac
  tag=$n-$perdisc-$config
  before=$(uptime)
  t0=$(date +%s.%N)
  ./carom simulate "$scene" "${args[@]}" --summary "$raw/$tag.json" 2> "$raw/$tag.err" &
  pid=$!
  python3 "$here/procwatch.py" "$pid" "$raw/$tag.proc.json" &
  watcher=$!
  rc=0
  wait "$pid" || rc=$?
  wait "$watcher" || true
  t1=$(date +%s.%N)
  log "$(date -u +%FT%TZ) $tag rc=$rc process_s=$(echo "$t1 - $t0" | bc) args: ${args[*]} $CAROM_JAVA_OPTS | before: $before | after: $(uptime)"
  # No JVM of this run may outlive it (the coordinator stops its workers).
  sleep 1
  if pgrep -f "ClusterWorker" > /dev/null; then log "#   warning: ClusterWorker processes still running: $(pgrep -af ClusterWorker | cut -c1-200)"; fi
done
