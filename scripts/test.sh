#!/usr/bin/env bash
# README command (2): install what is missing, build everything (t800sim, the tests, the benchmarks), and run
# every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --build build -j"$(nproc)"
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
ctest --test-dir build --output-on-failure -j"$(nproc)"
