#!/bin/sh
# gas-scene.sh N PHI UNTIL: a periodic gas of N equal discs (radius 0.5, unit mass) at packing fraction
# PHI, on the lattice (jitter 0.5) with Maxwell velocities at temperature 1 (seed 42), to time UNTIL;
# the scene StandardScenes.gas describes, as a scene file on stdout.
set -eu
n=$1 phi=$2 until=$3
side=$(awk -v n="$n" -v phi="$phi" 'BEGIN { printf "%.17g", sqrt(n * 3.141592653589793 * 0.25 / phi) }')
cat <<JSON
{
  "name": "gas-$n-phi$phi",
  "box": {"width": $side, "height": $side, "boundary": "periodic"},
  "species": [{"name": "disc", "radius": 0.5, "mass": 1.0}],
  "generate": [
    {"species": "disc", "count": $n, "layout": "lattice", "jitter": 0.5,
     "velocity": {"distribution": "maxwell", "temperature": 1.0}, "seed": 42}
  ],
  "until": $until
}
JSON
