#!/bin/sh
# The measurements of this note, in order (lab jar built from the commit named in README.md):
#   sh lab/notes/observables-cost/run.sh
set -eu
J=${JAVA:-$(ls -d /usr/lib/jvm/*25* | head -1)/bin/java}
N=lab/notes/observables-cost
S=lab/notes/species-observables/bidisperse-1e5.json
run() { out=$1; shift; { uptime; "$J" -Xmx3g -cp lab/target/carom-lab.jar "$@" 2>&1 | grep -v WARNING; uptime; } > "$N/$out"; }
# the list, paired with plain runs, alternating, 200 collisions per disc (20 samples)
run paired-study-200.txt $N/ObservablesCost.java $S gr,msd,psi6,pressure,sk,fs 200 4
# the same at 100 collisions per disc (10 samples), as species-observables measured it
run paired-study-100.txt $N/ObservablesCost.java $S gr,msd,psi6,pressure,sk,fs 100 4
# each observable alone, one pair each, 200 collisions per disc
for k in gr sk psi6 msd fs pressure; do
  run alone-$k-200.txt $N/ObservablesCost.java $S $k 200 1
done
