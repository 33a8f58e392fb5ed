#!/usr/bin/env bash
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer, in ./build-asan.
#   scripts/sanitize.sh            the fast tests (label unit)
#   scripts/sanitize.sh -L slow    any ctest selection instead
# A memory error, leak or undefined behaviour fails the test that hits it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# Without MPI: LeakSanitizer reports OpenMPI's own allocations (libmpi and its plugins, which
# no suppression can name once unloaded) as leaks, so the MPI tests skip here; they run in the
# normal build.
# Without the Python module: a sanitized shared object cannot be loaded into an uninstrumented
# Python (CMakeLists.txt turns it off under DTWIN_SANITIZE in any case).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDTWIN_BUILD_TESTS=ON -DDTWIN_SANITIZE=ON -DDTWIN_WITH_MPI=OFF -DDTWIN_PYTHON=OFF
cmake --build build-asan -j"$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
if [ "$#" -gt 0 ]; then
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 1800 "$@"
else
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 1800 -L unit
fi
