#!/usr/bin/env bash
# Where compile time goes: a cold build of ./build-times (no compiler cache), each object's wall time
# logged by this script acting as the compiler launcher, then the objects and the folders that cost most.
#   bash scripts/compile_times.sh            # build and report (about the time of a full cold build)
#   bash scripts/compile_times.sh --report   # report the last build's log again
# docs/developing.md gives the figures it printed.
set -euo pipefail
if [ "${1:-}" = "--launch" ]; then  # the launcher: --launch LOG compiler args...
  log=$2
  shift 2
  object=?
  prev=
  for a in "$@"; do
    [ "$prev" = "-o" ] && object=$a
    prev=$a
  done
  start=$(date +%s%N)
  rc=0
  "$@" || rc=$?
  end=$(date +%s%N)
  echo "$(((end - start) / 1000000)) $object" >>"$log"
  exit $rc
fi
cd "$(dirname "$0")/.."
log=$PWD/build-times/compile-times.log
if [ "${1:-}" != "--report" ]; then
  rm -rf build-times
  mkdir -p build-times
  cmake -S . -B build-times -DCMAKE_BUILD_TYPE=Release -DT800SIM_CCACHE=OFF \
    "-DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/compile_times.sh;--launch;$log" >/dev/null
  start=$(date +%s)
  cmake --build build-times -j"$(nproc)" >/dev/null
  echo "cold build: $(($(date +%s) - start)) s wall on $(nproc) cores"
fi
awk '{ total += $1 } END { printf "objects: %d, compile time summed: %.0f s\n", NR, total / 1000 }' "$log"
echo "-- the 15 slowest objects (s)"
sort -rn "$log" | head -15 | awk '{ printf "%6.1f  %s\n", $1 / 1000, $2 }'
echo "-- by target (s summed, objects)"
awk '{ p = $2; sub(/^CMakeFiles\//, "", p); sub(/\.dir\/.*/, "", p); t[p] += $1; n[p]++ }
     END { for (p in t) printf "%7.1f  %3d  %s\n", t[p] / 1000, n[p], p }' "$log" | sort -rn | head -20
