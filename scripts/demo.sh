#!/usr/bin/env bash
# The main job on the embedded default study (data/studies/demo.toml): the whole method end to
# end (twin study): lab and field data, Griddy Gibbs calibration of every assembly, synthetic
# field data, Bayesian classification and the cost-aware recommendation, into out/study/, and
# its self-contained HTML report out/study/report.html.
# About 4 minutes on 2 cores (plus the build). Rerunning resumes where a killed run stopped.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/cli/twin study data/studies/demo.toml --out out/study
./build/cli/twin report out/study --out out/study/report.html
echo "results in out/study/ (summary.json: wins, recommended, stages); open out/study/report.html"
