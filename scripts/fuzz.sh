#!/usr/bin/env bash
# The fuzz harnesses of tests/fuzz/ (docs/fuzzing.md), built with clang's libFuzzer under
# AddressSanitizer + UndefinedBehaviorSanitizer in ./build-fuzz, each run for a given time, after
# the unit tests of the same readers, built and run under the same sanitizers:
#   scripts/fuzz.sh              30 s each (the CI smoke run, part of scripts/test.sh)
#   scripts/fuzz.sh 600          10 minutes each
#   scripts/fuzz.sh 600 study    only harnesses whose name contains "study"
# Two harnesses run at a time (ctest -j2). Exit non-zero when a test fails or a harness finds a
# crash, a hang, a sanitizer report or an error that is not one InputError line.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
filter=${2:-}
# The unit tests of what the harnesses read (the whole suite under sanitizers: scripts/sanitize.sh).
SAN_TESTS=(messages_test study_test measurement_test road_test speed_trace_test time_road_test sensor_test grid_sample_test work_test calib_folder_test)
bash scripts/setup.sh fuzz
t0=$(date +%s)
# -O1 and line tables (CMakeLists.txt): the sanitizer reports keep file and line, the build is
# shorter (docs/performance.md, "Build time"). Ninja where it is installed.
gen=()
if [ ! -f build-fuzz/CMakeCache.txt ] && command -v ninja >/dev/null; then gen=(-G Ninja); fi
cmake -S . -B build-fuzz "${gen[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DDTWIN_BUILD_TESTS=ON -DDTWIN_WITH_MPI=OFF -DDTWIN_PYTHON=OFF -DDTWIN_FUZZ=ON -DDTWIN_FUZZ_SECONDS="$seconds" >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_all "${SAN_TESTS[@]}"
t1=$(date +%s)
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
if [ -z "$filter" ]; then
  # -L unit selects the discovered tests of the executables built above (the others are not built).
  ctest --test-dir build-fuzz -L unit -j"$(nproc)" --timeout 600 --output-on-failure
fi
t2=$(date +%s)
ctest --test-dir build-fuzz -L fuzz -R "fuzz.*${filter}" -j2 --timeout $((seconds * 3 + 120)) --output-on-failure
t3=$(date +%s)
grep -h '^fuzz_.*inputs' build-fuzz/tests/fuzz/corpus/*.log 2>/dev/null || true
echo "wall time: build $((t1 - t0)) s, sanitized unit tests $((t2 - t1)) s, fuzzing $((t3 - t2)) s"
