#!/bin/sh
# At once: configuration A on one core, B on the other (taskset), cores swapped every round, so both see
# the same moment of the VM. Each configuration is "name|jar|jvm options|tunables"; GasBench fast.
#   usage: atonce.sh N PHI ROUNDS A B      (PERDISC collisions a disc, default 4; REPEATS timed runs, default 2)
# The prototype rows: A = "base|PROTO.jar|-Dx=1|", B = "slice|PROTO.jar|-Dcarom.prefetch=LIB -Dcarom.prefetch.nonext=true
#   -Dcarom.prefetch.slice=true|"; the product's: A = "off|carom-lab.jar||prefetch=false", B = "on|carom-lab.jar||".
J=/usr/lib/jvm/temurin-25-jdk-amd64/bin/java; N=$1; PHI=$2; ROUNDS=$3; A=$4; B=$5
run() { IFS='|' read -r name jar opts tun <<E
$2
E
  # shellcheck disable=SC2086
  taskset -c "$1" $J --enable-native-access=ALL-UNNAMED $opts -Xmx8g -XX:+UseParallelGC -XX:ParallelGCThreads=1 -XX:CICompilerCount=2 \
    -cp "$jar" carom.lab.bench.GasBench fast "$N" "$PHI" "${PERDISC:-4}" "${REPEATS:-2}" "$tun" 1 1 2>&1 | grep "^fast," | sed "s/^/$name core$1 /"; }
for r in $(seq 1 "$ROUNDS"); do
  if [ $((r % 2)) = 1 ]; then ca=0; cb=1; else ca=1; cb=0; fi
  echo "round $r load $(uptime | sed 's/.*average: //' | cut -d, -f1) $(date -u +%H:%M:%S)"
  run $ca "$A" > /tmp/atonce-a.out & pa=$!
  run $cb "$B" > /tmp/atonce-b.out & pb=$!
  wait $pa $pb; cat /tmp/atonce-a.out /tmp/atonce-b.out
done
