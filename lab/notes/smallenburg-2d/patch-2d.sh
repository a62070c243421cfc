#!/bin/sh
# Turns a copy of Smallenburg's EDMD Single/mdSingle.c (github.com/FSmallenburg/EDMD) into the 2D runs of
# this note: no thermostat, z velocities zero and kT = 1 over two degrees of freedom, input from
# init.sph, the end time from the environment's MAXTIME at compile time. Usage: patch-2d.sh mdSingle.c
set -eu
f=$1
sed -i 's/^const int usethermostat = 1;/const int usethermostat = 0;/' "$f"
sed -i 's/^double maxtime = 100; /double maxtime = MAXTIME; /' "$f"
sed -i 's/^        p->vz = imsq \* random_gaussian();/        p->vz = 0; random_gaussian();/' "$f"
sed -i 's|^    double fac = sqrt(3.0 / (v2tot / N));|    double fac = sqrt(2.0 / (v2tot / N));|' "$f"
grep -q 'usethermostat = 0' "$f" && grep -q 'maxtime = MAXTIME' "$f" && grep -q 'p->vz = 0; random_gaussian' "$f" \
  && grep -q 'sqrt(2.0 / (v2tot' "$f" || { echo "error: the source is not the one this patch knows" >&2; exit 2; }
