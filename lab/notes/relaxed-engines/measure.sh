#!/usr/bin/env bash
# Issue 3's table: every relaxed engine at 1 and 2 threads on a hard-disc gas of N discs (radius 0.5,
# Maxwell T = 1, periodic, lattice with jitter 0.5) at packing fraction 0.3 and 0.6, each run about
# 0.3 to 0.4 collisions per disc (the thesis workload has 0.27). One ./carom run per cell of the table; its
# SUMMARY.json goes to results/. Usage: measure.sh [N ...]   (default: 10000 100000 1000000)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
out="$here/results"
mkdir -p "$out" "$here/scenes"
export CAROM_JAVA_OPTS="${CAROM_JAVA_OPTS:--Xmx14g -XX:+UseParallelGC}"
sizes=("${@:-10000 100000 1000000}")
# Build once, then run a snapshot of the jar, so that edits made meanwhile cannot change the runs.
"$root/carom" --version >/dev/null
. "$root/.mvn/find-jdk.sh"
jar="$(mktemp -d)/carom.jar"
cp "$root/app/target/carom.jar" "$jar"
# until per packing fraction for about 0.3 to 0.4 collisions per disc from the jittered lattice (measured with serial at N = 1e4)
declare -A until=([0.3]=1.0 [0.6]=0.25)
for n in ${sizes[@]}; do
  for phi in 0.3 0.6; do
    scene="$here/scenes/gas-$n-$phi.json"
    side=$(python3 -c "import math; print(math.sqrt($n*math.pi*0.25/$phi))")
    cat > "$scene" <<JSON
{"name": "gas-$n-$phi", "box": {"width": $side, "height": $side, "boundary": "periodic"},
 "species": [{"name": "disc", "radius": 0.5, "mass": 1.0}],
 "generate": [{"species": "disc", "count": $n, "layout": "lattice", "jitter": 0.5,
               "velocity": {"distribution": "maxwell", "temperature": 1.0}, "seed": 1}],
 "until": ${until[$phi]}}
JSON
    # engine threads cellsPerActor ("-": not an actor engine); RUNS="..." replaces the list
    # (for N = 1e6 one actor per cell takes a quarter of an hour a run here: see README.md)
    if [[ -n "${RUNS:-}" ]]; then IFS=',' read -r -a runs <<<"$RUNS"; else
    runs=("serial 1 -" "stripes 1 -" "stripes 2 -" "akka 1 1" "akka 2 1" "vthreads 1 1" "vthreads 2 1"
          "akka 2 16" "vthreads 2 16" "akka 2 perthread" "vthreads 2 perthread"); fi
    for run in "${runs[@]}"; do
      read -r engine threads block <<<"$run"
      opts=()
      tag="$engine-t$threads"
      if [[ "$block" == "perthread" ]]; then
        # one actor per thread: the grid's cells (side >= 2 diameters) split into $threads blocks of whole rows
        block=$(python3 -c "import math; c=int(math.sqrt($n*math.pi*0.25/$phi)//2); print(max(1,-(-c*c//$threads)))")
        tag="$tag-perthread"
      elif [[ "$block" != "-" ]]; then
        tag="$tag-b$block"
      fi
      [[ "$block" != "-" ]] && opts=(--option "cellsPerActor=$block" --option stallSeconds=600)
      file="$out/$n-$phi-$tag.json"
      [[ -s "$file" ]] && continue
      echo "$(date +%T) $n $phi $tag" >&2
      # shellcheck disable=SC2086
      "$JAVA_HOME/bin/java" $CAROM_UNSAFE_OPT $CAROM_JAVA_OPTS -jar "$jar" simulate "$scene" --engine "$engine" --threads "$threads" "${opts[@]}" \
          --summary "$file" >/dev/null || echo "failed: $n $phi $tag" >&2
    done
  done
done
