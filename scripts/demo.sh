#!/usr/bin/env bash
# The main job on the embedded default study (data/studies/demo.toml): simulate every assembly
# over the bump (lab scenario), writing traces, sidecars and out/bump/summary.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/cli/twin simulate --study data/studies/demo.toml --assembly all --scenario lab --out out/bump
echo "traces, sidecars and summary in out/bump/"
