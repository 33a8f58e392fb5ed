#!/usr/bin/env bash
# A screenshot of a report page in headless Chromium, for the docs (docs/img/).
#   bash scripts/screenshot.sh PAGE.html OUT.png [WIDTH,HEIGHT]
# The pages in docs/img and the commands that made them:
#   diagnose_readme.png: `bash scripts/bench_jobs.sh readme`, then
#     bash scripts/screenshot.sh /tmp/dtwin_bench/readme/run/compare.html docs/img/diagnose_readme.png 1400,1600
#   compare_unknown_car_b.png: `bash scripts/bench_jobs.sh unknown_car`, then
#     bash scripts/screenshot.sh /tmp/dtwin_bench/unknown_car/compare_b/compare.html docs/img/compare_unknown_car_b.png
#   compare_stop_and_go.png: `bash scripts/bench_jobs.sh drive_calibrate`, then
#     build/cli/twin compare --study /tmp/dtwin_bench/drive/study.toml --calibration /tmp/dtwin_bench/drive_calibrate/M1 \
#       --data /tmp/dtwin_bench/drive/measurements.csv --out /tmp/dtwin_bench/drive_calibrate/compare
#     bash scripts/screenshot.sh /tmp/dtwin_bench/drive_calibrate/compare/compare.html docs/img/compare_stop_and_go.png 1400,1250
set -euo pipefail
[[ $# -ge 2 ]] || { echo "usage: screenshot.sh PAGE.html OUT.png [WIDTH,HEIGHT]" >&2; exit 2; }
page=$1 out=$2 size=${3:-1400,1500}
[[ -f "$page" ]] || { echo "screenshot.sh: $page: no such file" >&2; exit 2; }
chromium=$(command -v chromium || command -v chromium-browser || true)
[[ -n "$chromium" ]] || { echo "screenshot.sh: chromium is not installed (bash scripts/setup.sh installs it)" >&2; exit 2; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
"$chromium" --headless --no-sandbox --disable-gpu --disable-background-networking --user-data-dir="$profile" \
  --window-size="$size" --screenshot="$(realpath -m "$out")" "file://$(realpath "$page")" >/dev/null 2>&1
echo "wrote $out"
