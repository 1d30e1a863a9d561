#!/usr/bin/env bash
# README command (1): install what is missing, build the t800sim executable (nothing else: the tests are
# scripts/test.sh's), and run the main job -- the paper reproduction.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --build build --target t800sim -j"$(nproc)"
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
./build/t800sim paper
