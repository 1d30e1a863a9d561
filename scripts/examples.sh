#!/usr/bin/env bash
# The SDK as a user meets it: install the build (./build, from scripts/test.sh or main.sh) into a fresh
# temporary prefix, build examples/ against that prefix alone, and run its scenes through the installed
# t800sim and the examples' own executable. Fails on any error.
set -euo pipefail
cd "$(dirname "$0")/.."
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install build --prefix "$prefix" >/dev/null
rm -rf examples/build  # the scenes name their plugin as examples/build/commstime.so
cmake -S examples -B examples/build -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build examples/build -j"$(nproc)"
for scene in examples/commstime/commstime-1.toml examples/commstime/commstime-4.toml; do
  echo "== t800sim run $scene  (the installed t800sim)"
  "$prefix/bin/t800sim" run "$scene" | sed -n '/^workload$/,/placement:/p'
done
echo "== t800sim run examples/sumfarm/sumfarm.toml --json  (a farm on the SDK's skeleton)"
"$prefix/bin/t800sim" run examples/sumfarm/sumfarm.toml --json >"$prefix/sumfarm.json"
# every result against its closed form, x (i + 1)(i + 2) / 2
grep -q '"wrong_results": 0' "$prefix/sumfarm.json" || { echo "sumfarm: wrong results"; cat "$prefix/sumfarm.json"; exit 1; }
grep -o '"round_tp_us": \[[^]]*\]' "$prefix/sumfarm.json"
echo "== examples/build/run_scene examples/run_scene/pipeline.toml"
examples/build/run_scene examples/run_scene/pipeline.toml >"$prefix/report.json"
# 1 + 2 + ... + 100, doubled by three stages: 5050 * 8.
grep -q '"sum": 40400' "$prefix/report.json" || { echo "run_scene: wrong sum"; cat "$prefix/report.json"; exit 1; }
grep -o '"us_per_value": [0-9.]*' "$prefix/report.json"
