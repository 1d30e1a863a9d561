#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer, leak detection on, in
# ./build-asan (-DT800SIM_SANITIZE=ON). Only SystemC's own leaks are suppressed: tests/sanitizer/lsan.supp
# says why each entry is there. Run after scripts/setup.sh (the same packages: gcc brings the sanitizer
# runtimes). Used by .ci/run. The benchmarks are not tests and are not built here. Each target compiles
# in batches of 8 sources (a CMake unity build): the third-party headers are parsed once a batch, not
# once a file; docs/developing.md says what it saves and why ./build is not built so.
set -euo pipefail
cd "$(dirname "$0")/.."
# Configures build-asan and fails in seconds, not after the build, on a name two sources of a batch define.
bash scripts/unity_names.sh
cmake --build build-asan -j"$(nproc)"
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
# Children the tests start (t800sim run, sweeps) inherit these.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=0:suppressions=$PWD/tests/sanitizer/asan.supp"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
