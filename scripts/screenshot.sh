#!/usr/bin/env bash
# A screenshot of a report page in headless Chromium, for the docs (docs/img/).
#   bash scripts/screenshot.sh PAGE.html[#ANCHOR] OUT.png [WIDTH,HEIGHT]
# The pages in docs/img and the commands that made them:
#   diagnose_readme.png: `bash scripts/bench_jobs.sh readme`, then
#     bash scripts/screenshot.sh /tmp/dtwin_bench/readme/run/compare.html docs/img/diagnose_readme.png 1400,1600
#   compare_unknown_car_b.png: `bash scripts/bench_jobs.sh unknown_car`, then
#     bash scripts/screenshot.sh /tmp/dtwin_bench/unknown_car/compare_b/compare.html docs/img/compare_unknown_car_b.png
#   study_report_lab.png, study_report_pairs.png, study_report_lab_view.png: `bash scripts/bench_jobs.sh demo_study`,
#     then build/cli/twin report --study-dir /tmp/dtwin_bench/demo_study, then
#     bash scripts/screenshot.sh '/tmp/dtwin_bench/demo_study/report.html#lab' docs/img/study_report_lab.png 1100,1200
#     bash scripts/screenshot.sh '/tmp/dtwin_bench/demo_study/report.html#pairs-M1' docs/img/study_report_pairs.png 1100,960
#     bash scripts/screenshot.sh /tmp/dtwin_bench/demo_study/report_lab.html docs/img/study_report_lab_view.png 1400,900
#   compare_stop_and_go.png: `bash scripts/bench_jobs.sh drive_calibrate`, then
#     build/cli/twin compare --study /tmp/dtwin_bench/drive/study.toml --calibration /tmp/dtwin_bench/drive_calibrate/M1 \
#       --data /tmp/dtwin_bench/drive/measurements.csv --out /tmp/dtwin_bench/drive_calibrate/compare
#     bash scripts/screenshot.sh /tmp/dtwin_bench/drive_calibrate/compare/compare.html docs/img/compare_stop_and_go.png 1400,1250
#   compare_discrepancy_controlled_car.png: the imports and the calibration of docs/measurements.md ("A car with a
#     controller", O=out/controlled), then
#     build/cli/twin compare --study $O/B/study.toml --calibration $O/cal/M1 --data $O/B/measurements.csv@drive_b \
#       --discrepancy $O/A/measurements.csv@drive_a --out $O/compare_disc
#     bash scripts/screenshot.sh "$O/compare_disc/compare.html#discrepancy-seat_mps2" docs/img/compare_discrepancy_controlled_car.png 1400,900
set -euo pipefail
[[ $# -ge 2 ]] || { echo "usage: screenshot.sh PAGE.html OUT.png [WIDTH,HEIGHT]" >&2; exit 2; }
page=$1 out=$2 size=${3:-1400,1500}
anchor=""
if [[ "$page" == *"#"* ]]; then anchor="#${page#*#}"; page=${page%%#*}; fi  # PAGE.html#section: scrolled to it
[[ -f "$page" ]] || { echo "screenshot.sh: $page: no such file" >&2; exit 2; }
chromium=$(command -v chromium || command -v chromium-browser || true)
[[ -n "$chromium" ]] || { echo "screenshot.sh: chromium is not installed (bash scripts/setup.sh installs it)" >&2; exit 2; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
url="file://$(realpath "$page")"
if [[ -n "$anchor" ]]; then
  # Headless Chromium shoots before it scrolls to an anchor: frame the page, scrolled, in a
  # throw-away page beside it (same folder: the frame's relative address).
  frame=$(mktemp -p "$(dirname "$(realpath "$page")")" .screenshot_XXXXXX.html)
  trap 'rm -rf "$profile" "$frame"' EXIT
  printf '<!DOCTYPE html><html><body style="margin:0;overflow:hidden"><iframe src="%s%s" style="border:0;width:100vw;height:100vh"></iframe></body></html>\n' \
    "$(basename "$page")" "$anchor" >"$frame"
  url="file://$frame"
fi
"$chromium" --headless --no-sandbox --disable-gpu --disable-background-networking --user-data-dir="$profile" \
  --window-size="$size" --screenshot="$(realpath -m "$out")" "$url" >/dev/null 2>&1
echo "wrote $out"
