# shellcheck shell=sh
# Sourced by ./mvnw, ./carom and .ci/run: exports JAVA_HOME pointing at a JDK 21 or newer.
# Order: JAVA_HOME if it is 21+, else the newest 21+ JDK in the usual install folders, else the
# JDK behind `java` on PATH. The machine default is often 17, which cannot build carom.
carom_jdk_major() {
  # Prints the feature version of the JDK at $1 (e.g. 25), or nothing.
  if [ -f "$1/release" ]; then
    sed -n 's/^JAVA_VERSION="\([0-9]*\).*/\1/p' "$1/release" | head -n 1
  elif [ -x "$1/bin/java" ]; then
    "$1/bin/java" -version 2>&1 | sed -n 's/.*version "\([0-9]*\).*/\1/p' | head -n 1
  fi
}
carom_is_jdk21() {
  [ -x "$1/bin/javac" ] || return 1
  carom_v=$(carom_jdk_major "$1")
  [ -n "$carom_v" ] && [ "$carom_v" -ge 21 ] 2>/dev/null
}
carom_find_jdk() {
  if [ -n "${JAVA_HOME:-}" ] && carom_is_jdk21 "$JAVA_HOME"; then
    printf '%s\n' "$JAVA_HOME"; return 0
  fi
  carom_best=""; carom_best_v=0
  for carom_d in /usr/lib/jvm/* /usr/java/* /usr/local/lib/jvm/* /opt/java/* /opt/*jdk* \
      /Library/Java/JavaVirtualMachines/*/Contents/Home "$HOME"/.sdkman/candidates/java/* \
      "$HOME"/.jdks/*; do
    [ -d "$carom_d" ] || continue
    carom_is_jdk21 "$carom_d" || continue
    carom_v=$(carom_jdk_major "$carom_d")
    if [ "$carom_v" -gt "$carom_best_v" ]; then carom_best="$carom_d"; carom_best_v=$carom_v; fi
  done
  if [ -z "$carom_best" ] && command -v javac >/dev/null 2>&1; then
    carom_d=$(dirname "$(dirname "$(readlink -f "$(command -v javac)")")")
    carom_is_jdk21 "$carom_d" && carom_best="$carom_d"
  fi
  [ -n "$carom_best" ] || return 1
  printf '%s\n' "$carom_best"
}
if carom_home=$(carom_find_jdk); then
  JAVA_HOME="$carom_home"; export JAVA_HOME
  # Maven's bundled Guava and Akka 2.6 call sun.misc.Unsafe, which JDK 24+ warns about on first use.
  CAROM_UNSAFE_OPT=""
  if [ "$(carom_jdk_major "$JAVA_HOME")" -ge 24 ] 2>/dev/null; then
    CAROM_UNSAFE_OPT="--sun-misc-unsafe-memory-access=allow"
    case "${MAVEN_OPTS:-}" in
      *sun-misc-unsafe-memory-access*) ;;
      *) MAVEN_OPTS="${MAVEN_OPTS:-} $CAROM_UNSAFE_OPT"; export MAVEN_OPTS ;;
    esac
  fi
else
  echo "error: carom needs a JDK 21 or newer and found none (JAVA_HOME=${JAVA_HOME:-unset}, /usr/lib/jvm, /opt, ~/.sdkman): install one (for example Temurin 21 or 25) and set JAVA_HOME to it" >&2
  exit 1
fi
