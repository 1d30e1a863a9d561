#!/usr/bin/env bash
# Configures ./build-asan as scripts/sanitize.sh does (a unity build, batches of 8 sources) and checks,
# without compiling, that no two sources of a batch define the same name in their anonymous namespaces
# (scripts/unity_names.py): a clash there compiles in ./build and fails only in the sanitizer build. A
# few seconds; run it before a commit that adds file-local helpers. scripts/sanitize.sh runs it first.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DT800SIM_SANITIZE=ON -DT800SIM_BENCHMARKS=OFF \
      -DCMAKE_UNITY_BUILD=ON >/dev/null
python3 scripts/unity_names.py build-asan
