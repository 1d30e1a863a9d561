#!/usr/bin/env bash
# Installs the Debian packages t800sim needs (only those missing), then configures the build in ./build.
# Run as root, or as a user with sudo. Used by scripts/main.sh (which builds only the t800sim executable) and
# scripts/test.sh (which builds everything: the tests and benchmarks too).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config libsystemc-dev libeigen3-dev libfmt-dev googletest libgtest-dev
          libtomlplusplus-dev libcli11-dev liborocos-kdl-dev nlohmann-json3-dev
          python3 python3-matplotlib parallel  # tools/plot; sweep jobs through GNU parallel (tests)
          ccache)  # compiler cache: a rebuild or a second clone recompiles only what changed (cmake/compiler_cache.cmake)
# Optional, not installed here: libsimgrid-dev (bench/simgrid_bench's SimGrid side), clang (fuzz/).
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
