#!/bin/bash
# measure.sh ROUNDS: what TLS costs the cluster engine, from the worktree's root. Each round runs the same
# scene (examples/gas.json to t = $UNTIL, default 2) twice, in alternating order, over one running worker
# ('carom node', started afresh for each run): plain TCP on 127.0.0.1, and TLS with mutual authentication
# with keys made by 'carom node --make-keys'. Both are --seed-nodes runs of 2 JVMs, so they differ in the
# transport only. Then it times what a --nodes run adds before it starts: making its keys (one keytool
# -genkeypair). Writes raw/MODE-ROUND.json (SUMMARY.json) and a line per run to raw/runs.log with uptime.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
rounds=${1:-5}
until=${UNTIL:-2}
raw=$here/raw
mkdir -p "$raw"
cd "$root"
export CAROM_AOT=0
work=$(mktemp -d)
worker=""
cleanup() { [ -n "$worker" ] && kill "$worker" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
./carom node --make-keys "$work/keys" > /dev/null
log() { echo "$*" | tee -a "$raw/runs.log"; }
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

run() { # run MODE ROUND
  local mode=$1 round=$2 port keys=()
  port=$(free_port)
  [ "$mode" = tls ] && keys=(--keys "$work/keys/node")
  ./carom node --join "127.0.0.1:$port" --port "$port" "${keys[@]}" > "$work/node.log" 2>&1 &
  worker=$!
  for _ in $(seq 600); do grep -q '^node:' "$work/node.log" && break; sleep 0.1; done
  local before t0 t1
  before=$(uptime)
  t0=$(date +%s.%N)
  ./carom simulate examples/gas.json --engine cluster --nodes 2 --seed-nodes "127.0.0.1:$port" "${keys[@]}" \
      --until "$until" --summary "$raw/$mode-$round.json"
  t1=$(date +%s.%N)
  kill "$worker"; wait "$worker" 2>/dev/null || true; worker=""
  log "$mode round=$round wall=$(echo "$t1 - $t0" | bc) before: $before after: $(uptime)"
}

for round in $(seq "$rounds"); do
  if [ $((round % 2)) = 1 ]; then run plain "$round"; run tls "$round"; else run tls "$round"; run plain "$round"; fi
done
java_home=$(. .mvn/find-jdk.sh >/dev/null 2>&1; echo "${JAVA_HOME:-}")
keytool=${java_home:+$java_home/bin/}keytool
for k in $(seq "$rounds"); do
  t0=$(date +%s.%N)
  "$keytool" -J-Xmx64m -genkeypair -alias node -keyalg EC -groupname secp256r1 -sigalg SHA256withECDSA \
      -dname CN=carom-run -validity 2 -storetype PKCS12 -keystore "$work/k$k.p12" -storepass "pass-$k-word" > /dev/null 2>&1
  t1=$(date +%s.%N)
  log "keytool round=$k wall=$(echo "$t1 - $t0" | bc) uptime: $(uptime)"
done
python3 "$here/table.py" "$raw"
