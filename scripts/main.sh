#!/usr/bin/env bash
# README command (1): install what is missing, build, and run the main job -- the paper reproduction.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
./build/t800sim paper
