#!/usr/bin/env bash
# Instructions and cycles of one call of each occam kernel, compiled by the INMOS D7205A toolset
# and run on t800sim's ISS. The toolset itself (oc, ilink, icollect) runs on t800sim too, so
# nothing but t800sim, bash and python3 is needed on the host. See README.md.
#
# usage: measure.sh TOOLSET [T800SIM] [NAME...]
#   TOOLSET  the D7205A directory (the one holding itools/ and libs/)
#   T800SIM  the t800sim binary; default: build/t800sim of this repository, else t800sim on PATH
#   NAME     configurations to measure (harness.py list); default: all
# environment: MEASURE_TIMEOUT  seconds allowed for each t800sim run (default 600)
#              MEASURE_KEEP=1   keep each configuration's temporary directory (its path is printed)
set -euo pipefail
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1

HERE=$(cd "$(dirname "$0")" && pwd)
HARNESS="$HERE/harness.py"
TIMEOUT=${MEASURE_TIMEOUT:-600}

usage() {
  sed -n '6,11s/^# \{0,1\}//p' "$0" >&2
  exit 2
}

die() { # status message...
  local status=$1; shift
  echo "measure.sh: $*" >&2
  exit "$status"
}

default_t800sim() {
  local built="$HERE/../../build/t800sim"
  if [ -x "$built" ]; then absolute_program "$built"
  elif command -v t800sim >/dev/null; then command -v t800sim
  else die 2 "no t800sim: not built at $built and not on PATH; give T800SIM"
  fi
}

# The runs happen in a temporary directory, so a relative T800SIM must be made absolute.
absolute_program() { # path-or-command
  case $1 in
    */*) [ -f "$1" ] && [ -x "$1" ] && echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" ;;
    *) command -v "$1" ;;
  esac
}

is_config() { # name
  "$HARNESS" list | grep -xF -- "$1" >/dev/null  # not -q: an early exit would break the pipe
}

# Build the harness calling the kernel R times with `t800sim occam build` (oc, ilink and icollect
# running on t800sim; the configuration's oc options apply to the kernel and the harness alike), boot
# it, and leave its report in rR.json.
build_and_run() { # R
  local r=$1 oc=()
  for o in ${OPTIONS[@]+"${OPTIONS[@]}"}; do oc+=("--oc=$o"); done
  "$HARNESS" source "$NAME" "$r" >"h$r.occ"
  if ! timeout "$TIMEOUT" "$T800SIM" occam build "h$r.occ" --with "$KERNEL.occ" \
      --toolset "$TOOLSET" ${oc[@]+"${oc[@]}"} -o "h$r.btl" --work-dir "work$r" \
      --max-host-s "$TIMEOUT" >"build$r.log" 2>&1; then
    echo "measure.sh: $NAME: building the R=$r harness failed (its files are left in $PWD):" >&2
    cat "build$r.log" >&2
    exit 1
  fi
  # Default board: T800-20, 2 MiB; the harness prints GO and END and exits with sps.success.
  if ! timeout "$TIMEOUT" "$T800SIM" boot "h$r.btl" --host-dir . --json "r$r.json" \
      >"run$r.log" 2>&1; then
    echo "measure.sh: $NAME: the R=$r harness failed (its files are left in $PWD):" >&2
    cat "run$r.log" >&2
    exit 1
  fi
}

# Per call = (R=2 run) - (R=1 run): the start-up, initialisation and host I/O cancel, leaving one
# kernel call plus one iteration of the harness's loop (argument set-up, call, ldlp; ldc; lend).
per_call() {
  python3 - r1.json r2.json <<'EOF'
import json, sys
def figures(path):
    p = json.load(open(path))["workload"]["processors"][0]
    return p["instructions"], p["cycles"]
(i1, c1), (i2, c2) = figures(sys.argv[1]), figures(sys.argv[2])
print(i2 - i1, c2 - c1)
EOF
}

measure() { # name
  NAME=$1
  KERNEL=$("$HARNESS" kernel "$NAME")
  local dir
  read -r -a OPTIONS <<<"$("$HARNESS" options "$NAME")"
  dir=$(mktemp -d "${TMPDIR:-/tmp}/occam-measure.$NAME.XXXXXX")
  (
    cd "$dir"
    cp "$HERE/$KERNEL.occ" .
    build_and_run 1
    build_and_run 2
    local figures instr cycles
    figures=$(per_call)  # not read < <(per_call): a failure there would go unnoticed
    read -r instr cycles <<<"$figures"
    printf '%-13s %-36s %9s %9s\n' "$NAME" "$("$HARNESS" label "$NAME")" "$instr" "$cycles"
  )
  if [ "${MEASURE_KEEP:-0}" = 1 ]; then echo "  (kept $dir)" >&2; else rm -rf "$dir"; fi
}

main() {
  [ $# -ge 1 ] || usage
  TOOLSET=$(cd "$1" 2>/dev/null && pwd) || die 2 "TOOLSET '$1' is not a directory"
  shift
  # The second argument is T800SIM unless it names a configuration.
  if [ $# -ge 1 ] && ! is_config "$1"; then
    T800SIM=$(absolute_program "$1") ||
      die 2 "T800SIM '$1' is not an executable file (nor a configuration name)"
    shift
  else
    T800SIM=$(default_t800sim)
  fi
  local names=("$@") n
  [ ${#names[@]} -gt 0 ] || mapfile -t names < <("$HARNESS" list)
  for n in "${names[@]}"; do is_config "$n" || die 2 "no configuration '$n' (harness.py list names them)"; done

  printf '%-13s %-36s %9s %9s\n' name label instr cycles
  for n in "${names[@]}"; do measure "$n"; done
}

main "$@"
