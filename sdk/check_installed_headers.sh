#!/usr/bin/env bash
# Installs the build tree BUILD into a fresh prefix and compiles every public header alone against
# the installed tree only (no source or build directory on the include path): a header the install
# leaves out (cmake/package.cmake, T800SIM_DETAIL_HEADERS) fails here, as does a public header that
# reaches SystemC. Usage: check_installed_headers.sh BUILD_DIR CXX
set -euo pipefail
build=$1
cxx=$2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
headers=("$prefix"/include/t800sim/*.hpp)
[ ${#headers[@]} -gt 0 ] || { echo "no public headers installed in $prefix/include/t800sim"; exit 1; }
cd "$prefix"
for header in "${headers[@]}"; do
  name=t800sim/$(basename "$header")
  deps=$(echo "#include <$name>" |
    "$cxx" -std=c++17 -x c++ -fsyntax-only -Wall -Wextra -I include -I include/t800sim/detail -M -MF - - 2>&1) ||
    { echo "FAIL $name does not compile alone against the installed tree:"; echo "$deps"; exit 1; }
  if grep -qi systemc <<<"$deps"; then echo "FAIL $name includes SystemC"; exit 1; fi
  echo "#include <$name>" | "$cxx" -std=c++17 -x c++ -fsyntax-only -Wall -Wextra -I include -I include/t800sim/detail - ||
    { echo "FAIL $name does not compile alone against the installed tree"; exit 1; }
  echo "ok   $name"
done
