#!/usr/bin/env bash
# Regenerates the regression traces in data/reference/ (bump response of M1..M4 at the true
# parameters of data/studies/paper.toml). Run only when a change of the physics is intended,
# and say so in the commit message.
set -euo pipefail
cd "$(dirname "$0")/.."
for M in M1 M2 M3 M4; do
  ./build/cli/twin simulate --study data/studies/paper.toml --assembly "$M" --scenario lab --quiet \
    --channels hub_force_fl_N,hub_force_rl_N,susp_defl_fl_m,chassis_heave_m,chassis_pitch_rad \
    --window 5.5,9.0 --out "data/reference/${M}_lab.csv"
done
