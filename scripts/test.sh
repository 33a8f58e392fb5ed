#!/usr/bin/env bash
# Set-up and the whole test suite (unit + slow end-to-end), as CI runs it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
