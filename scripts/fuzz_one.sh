#!/usr/bin/env bash
# One fuzz harness for a given time (used by scripts/fuzz.sh and the CTest `fuzz` tests):
#   fuzz_one.sh <harness> <corpus-dir> <seconds> [seed file or folder ...]
# The corpus folder is made afresh from the seeds; what the fuzzer finds is added to it. A crash,
# hang (> 10 s on one input), memory use over 2 GiB, sanitizer report or an exception other than
# InputError (tests/fuzz/fuzz_common.hpp) stops the run with a non-zero exit and leaves the input
# in <corpus-dir>.artifacts/.
set -euo pipefail
bin=$1; corpus=$2; seconds=$3; shift 3
rm -rf "$corpus" "$corpus.artifacts"
mkdir -p "$corpus" "$corpus.artifacts"
for s in "$@"; do
  if [ -d "$s" ]; then cp "$s"/* "$corpus"/ 2>/dev/null || true; else cp "$s" "$corpus"/; fi
done
log="$corpus.log"
set +e
"$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 \
  -artifact_prefix="$corpus.artifacts/" "$corpus" >"$log" 2>&1
rc=$?
set -e
name=$(basename "$bin")
execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
units=$(ls "$corpus" | wc -l)
echo "$name: ${seconds} s, $execs inputs, coverage $cov edges, corpus $units files, exit $rc"
if [ "$rc" -ne 0 ]; then
  tail -40 "$log"
  echo "$name: FAILED; the input is in $corpus.artifacts/"
fi
exit "$rc"
