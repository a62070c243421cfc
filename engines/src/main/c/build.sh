#!/bin/sh
# Builds the optional prefetch helper (carom_prefetch.c) into OUT/carom/native/linux-ARCH/ for the
# engines jar; run by Maven before the classes are packed. Without a C compiler, or off Linux, it says
# so and builds nothing: carom then runs without prefetch hints (same results, slower at large N).
set -eu
out=$1
src=$(cd "$(dirname "$0")" && pwd)/carom_prefetch.c
[ "$(uname -s)" = Linux ] || { echo "carom: not Linux; building without the native prefetch helper" >&2; exit 0; }
case "$(uname -m)" in
  x86_64) arch=amd64 ;;
  aarch64) arch=aarch64 ;;
  *) echo "carom: no prefetch helper for $(uname -m)" >&2; exit 0 ;;
esac
cc=${CC:-cc}
command -v "$cc" >/dev/null 2>&1 || { echo "carom: no C compiler ($cc); building without the native prefetch helper" >&2; exit 0; }
dir="$out/carom/native/linux-$arch"
mkdir -p "$dir"
lib="$dir/libcarom_prefetch.so"
if [ ! -f "$lib" ] || [ "$src" -nt "$lib" ]; then
  "$cc" -O2 -shared -fPIC -o "$lib.tmp" "$src" && mv -f "$lib.tmp" "$lib" \
    || { rm -f "$lib.tmp"; echo "carom: the prefetch helper did not compile; building without it" >&2; }
fi
