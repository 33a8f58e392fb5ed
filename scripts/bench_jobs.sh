#!/usr/bin/env bash
# Times the user-facing jobs of docs/performance.md ("Jobs, end to end"), one row each, on this
# machine, and prints a markdown table. Each job runs from scratch in a fresh folder under
# ${BENCH_DIR:-/tmp/dtwin_bench} (outputs kept for inspection). Not a test: timing targets live
# here, never in CTest.
#
#   bash scripts/bench_jobs.sh                 # every row but the paper-scale study
#   bash scripts/bench_jobs.sh readme drive_calibrate   # only these rows
#   bash scripts/bench_jobs.sh paper           # the paper-scale study (about 1.5 h: run it alone;
#                                              # resumable: rerun to continue, delete its folder to start over)
#
# Rows: readme (the README's diagnose walkthrough), drive_calibrate (`twin calibrate` of M1 on the
# demonstration drive), drive_vehicle (the same with the chassis mass and pitch inertia and the
# seat accelerometer's x position calibrated too), drive_diagnose (the drive's diagnose walkthrough of docs/measurements.md),
# unknown_car (docs/measurements.md, "A car nobody measured": two imports, then the timed
# twelve-value calibration on drive A, then the comparison on drive B with the FIR baseline;
# figures in its logs),
# controlled_car (docs/measurements.md, "A car with a controller": two imports, the calibration on
# drive A, the diagnosis with drive B held out and its causes applied, the comparison on drive B
# with the FIR baseline; the whole walk timed, each step's time in its log), long_window (a
# two-minute window at 110 Hz of the same car, calibrated with the structure the diagnosis found:
# the hub input and a skyhook), corner_car and feedforward_car (docs/measurements.md, "A sensor nobody
# placed": the same walk on a car whose road signal is one corner's and whose accelerometer sits over
# that wheel, with a skyhook or a feed-forward controller; the comparison with --discrepancy too),
# passive_car (the same walk's diagnosis on a car without a
# controller, whose road signal is the road under its tires: the verdict must be "none"),
# long_drive (a real car's sizes: the diagnosis `--causes 3 --candidates 2` of a 60 s window at
# 110 Hz of the controlled car with its five calibrated values, then the structure it finds, the hub
# input and a skyhook, calibrated on a whole 12-minute drive at 110 Hz, 72 199 records, which
# scripts/make_controlled_car_drives.py --long makes into the row's folder once; each step's stage
# times in its log), demo_study (scripts/demo.sh's study), fresh_demo (scripts/demo.sh on a fresh clone of HEAD with an
# empty Simbody cache: the newcomer's first run, the Release Simbody build included), run (one 15 s
# run per assembly: `twin bench`), hand_ode (`twin bench --hand-ode`: one run against a hand-written
# ODE), accumulation (`twin bench --accumulation` on the paper's sizes: the synthesis's measured
# costs and its modelled wall time on 1 to 256 ranks), mpi_synthesis (one synthesis of the demo
# study's M1, one process of two threads against `mpirun -n 2`, bit-identical moments; needs the
# demo_study row's calibration), paper, paper_draws (how the paper study's decision depends on the
# number of synthetic draws: its calibrations and field records, synthesized again with 100, 300
# and 1000 draws under several seeds and classified; needs the paper row, or PAPER_DIR).
# TWIN=PATH times another build of the program (default: ./build/cli/twin).
set -euo pipefail
cd "$(dirname "$0")/.."
B="${TWIN:-$PWD/build/cli/twin}"
[[ -x "$B" ]] || { echo "bench_jobs.sh: build first (bash scripts/build.sh)" >&2; exit 2; }
D="${BENCH_DIR:-/tmp/dtwin_bench}"
mkdir -p "$D"
rows=("$@")
[[ ${#rows[@]} -gt 0 ]] || rows=(run readme drive_calibrate drive_diagnose demo_study)
for r in "${rows[@]}"; do
  case "$r" in readme | drive_calibrate | drive_vehicle | drive_diagnose | unknown_car | controlled_car | corner_car | feedforward_car | passive_car | long_window | long_drive | demo_study | fresh_demo | run | hand_ode | accumulation | mpi_synthesis | paper | paper_draws) ;;
    *) echo "bench_jobs.sh: unknown row '$r' (rows: readme drive_calibrate drive_vehicle drive_diagnose unknown_car controlled_car corner_car feedforward_car passive_car long_window long_drive demo_study fresh_demo run hand_ode accumulation mpi_synthesis paper paper_draws)" >&2; exit 2 ;;
  esac
done

declare -A secs
timed() {  # timed NAME LOG COMMAND...: wall seconds of COMMAND into secs[NAME]
  local name=$1 log=$2 t0
  shift 2
  t0=$(date +%s.%N)
  if ! "$@" >"$log" 2>&1; then
    echo "bench_jobs.sh: $name failed; see $log" >&2
    exit 1
  fi
  secs[$name]=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  printf '%s: %.0f s\n' "$name" "${secs[$name]}" >&2
}

import_car() {  # import_car PREFIX DIR [MAP_STUDY]: drives A and B of data/drives/PREFIX_*.csv with the mapping and study
  # data/drives/MAP_STUDY_map.toml and _study.toml (default: the controlled car's)
  local ms="${3:-controlled_car}"
  "$B" import --log "data/drives/$1_a.csv" --map "data/drives/${ms}_map.toml" --study "data/drives/${ms}_study.toml" \
    --out "$2/A" --scenario drive_a >"$2/import_a.log"
  "$B" import --log "data/drives/$1_b.csv" --map "data/drives/${ms}_map.toml" --study "$2/A/study.toml" \
    --out "$2/B" --scenario drive_b >"$2/import_b.log"
}

corner_walk() {  # corner_walk PREFIX DIR: docs/measurements.md, "A sensor nobody placed"
  import_car "$1" "$2" corner_car
  /usr/bin/time -f "calibrate %e s" "$B" calibrate --study "$2/B/study.toml" --data "$2/A/measurements.csv@drive_a" \
    --out "$2/cal" >"$2/calibrate.log" 2>&1
  /usr/bin/time -f "diagnose %e s" "$B" diagnose --study "$2/B/study.toml" --data "$2/A/measurements.csv@drive_a" \
    --holdout "$2/B/measurements.csv@drive_b" --out "$2/diag" --causes 5 --candidates 2 >"$2/diagnose.log" 2>&1
  local found
  found=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['causes'][-1]['folder'])" "$2/diag/diagnosis.json")
  /usr/bin/time -f "compare %e s" "$B" compare --study "$2/B/study.toml" --calibration "$found" \
    --data "$2/B/measurements.csv@drive_b" --baseline "$2/A/measurements.csv@drive_a" \
    --discrepancy "$2/A/measurements.csv@drive_a" --out "$2/compare_b" >"$2/compare_b.txt" 2>&1
}

drive() {  # the demonstration drive, imported once
  if [[ ! -f "$D/drive/study.toml" ]]; then
    rm -rf "$D/drive"
    "$B" import --log data/drives/stop_and_go.csv --map data/drives/stop_and_go_map.toml --out "$D/drive" >/dev/null
  fi
}

for r in "${rows[@]}"; do
  case "$r" in
    run)
      "$B" bench --runs 3 --markdown >"$D/run.md"
      secs[run]=0
      ;;
    readme)
      rm -rf "$D/readme" && mkdir -p "$D/readme"
      for sc in diag_bump diag_rough; do
        "$B" generate lab --scenario "$sc" --times all --rate 200 --repetitions 3 \
          --channels hub_force_fl_N,hub_force_fr_N,hub_force_rl_N,hub_force_rr_N \
          --hidden-effect bump_stop:stiffness=5e6,gap_m=0.02 --out "$D/readme/$sc.csv" >/dev/null
      done
      timed readme "$D/readme/diagnose.log" "$B" diagnose --data "$D/readme/diag_bump.csv" --data "$D/readme/diag_rough.csv" \
        --out "$D/readme/run" --lhs-points 60 --iterations 4000 --burn-in 1000 --starts 2 --apply bump_stop --quiet
      ;;
    drive_calibrate)
      drive
      rm -rf "$D/drive_calibrate"
      timed drive_calibrate "$D/drive_calibrate.log" "$B" calibrate --study "$D/drive/study.toml" --assembly M1 \
        --data "$D/drive/measurements.csv@drive" --out "$D/drive_calibrate" --quiet
      ;;
    drive_vehicle)
      drive
      rm -rf "$D/drive_vehicle"
      # Beside the drive's study: its speed and road files are named relative to it.
      { cat "$D/drive/study.toml"
        printf '\n[[calibrated]]\nname = "chassis.mass_kg"\nlower = 1100\nupper = 1700\n'
        printf '\n[[calibrated]]\nname = "chassis.pitch_inertia_kgm2"\nlower = 1500\nupper = 2800\n'
        printf '\n[[calibrated]]\nname = "sensors.seat.x_m"\nlower = 0.4\nupper = 1.4\n'; } >"$D/drive/study_vehicle.toml"
      timed drive_vehicle "$D/drive_vehicle.log" "$B" calibrate --study "$D/drive/study_vehicle.toml" --assembly M1 \
        --data "$D/drive/measurements.csv@drive" --out "$D/drive_vehicle" --quiet
      ;;
    drive_diagnose)
      drive
      rm -rf "$D/drive_diagnose"
      timed drive_diagnose "$D/drive_diagnose.log" "$B" diagnose --study "$D/drive/study.toml" --assembly M1 \
        --data "$D/drive/measurements.csv" --out "$D/drive_diagnose" --lhs-points 60 --iterations 4000 --burn-in 1000 \
        --starts 2 --candidates 1 --apply damper_asymmetry
      ;;
    unknown_car)
      U="$D/unknown_car" && rm -rf "$U" && mkdir -p "$U"
      "$B" import --log data/drives/unknown_car_a.csv --map data/drives/unknown_car_map.toml --study data/drives/unknown_car_study.toml \
        --out "$U/A" --scenario drive_a >"$U/import_a.log"
      "$B" import --log data/drives/unknown_car_b.csv --map data/drives/unknown_car_map.toml --study "$U/A/study.toml" \
        --out "$U/B" --scenario drive_b >"$U/import_b.log"
      # The log holds the progress lines, each stage's time and the printed intervals.
      timed unknown_car "$U/calibrate.log" "$B" calibrate --study "$U/B/study.toml" \
        --data "$U/A/measurements.csv@drive_a" --out "$U/cal"
      "$B" compare --study "$U/B/study.toml" --calibration "$U/cal/M1" --data "$U/B/measurements.csv@drive_b" \
        --baseline "$U/A/measurements.csv@drive_a" --out "$U/compare_b" >"$U/compare_b.txt"
      ;;
    controlled_car)
      C="$D/controlled_car" && rm -rf "$C" && mkdir -p "$C"
      walk() {
        import_car controlled_car "$C"
        /usr/bin/time -f "calibrate %e s" "$B" calibrate --study "$C/B/study.toml" --data "$C/A/measurements.csv@drive_a" \
          --out "$C/cal" >"$C/calibrate.log" 2>&1
        /usr/bin/time -f "diagnose %e s" "$B" diagnose --study "$C/B/study.toml" --data "$C/A/measurements.csv@drive_a" \
          --holdout "$C/B/measurements.csv@drive_b" --out "$C/diag" --causes 3 --candidates 2 >"$C/diagnose.log" 2>&1
        # The model with every cause the verdict names (the last cause's folder: their joint calibration).
        local found
        found=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['causes'][-1]['folder'])" "$C/diag/diagnosis.json")
        /usr/bin/time -f "compare %e s" "$B" compare --study "$C/B/study.toml" --calibration "$found" \
          --data "$C/B/measurements.csv@drive_b" --baseline "$C/A/measurements.csv@drive_a" --out "$C/compare_b" >"$C/compare_b.txt" 2>&1
      }
      timed controlled_car "$C/walk.log" walk
      ;;
    corner_car | feedforward_car)
      K="$D/$r" && rm -rf "$K" && mkdir -p "$K"
      timed "$r" "$K/walk.log" corner_walk "$r" "$K"
      ;;
    passive_car)
      P="$D/passive_car" && rm -rf "$P" && mkdir -p "$P"
      walk_passive() {
        import_car passive_car "$P"
        /usr/bin/time -f "diagnose %e s" "$B" diagnose --study "$P/B/study.toml" --data "$P/A/measurements.csv@drive_a" \
          --holdout "$P/B/measurements.csv@drive_b" --out "$P/diag" --causes 3 --candidates 2 >"$P/diagnose.log" 2>&1
        grep -q "^Diagnosis of M1: none" "$P/diagnose.log" || { echo "passive_car: the verdict is not none; see $P/diagnose.log" >&2; return 1; }
      }
      timed passive_car "$P/walk.log" walk_passive
      ;;
    long_window)
      L="$D/long_window" && rm -rf "$L" && mkdir -p "$L"
      "$B" import --log data/drives/controlled_car_c.csv --map data/drives/controlled_car_map.toml --study data/drives/controlled_car_study.toml \
        --out "$L/C" --scenario drive_c >"$L/import.log"
      # The structure the diagnosis of the car found: the road at the hub and a skyhook.
      sed -e 's/^tire = \["pac2002"\]/tire = ["hub"]/' "$L/C/study.toml" >"$L/C/study_found.toml"
      printf '\n[effects.skyhook]\ndamping = 0.0\n\n[[calibrated]]\nname = "skyhook.damping"\nunit = "N*s/m"\nlower = 0.0\nupper = 8000.0\n' \
        >>"$L/C/study_found.toml"
      timed long_window "$L/calibrate.log" "$B" calibrate --study "$L/C/study_found.toml" \
        --data "$L/C/measurements.csv@drive_c" --out "$L/cal"
      ;;
    long_drive)
      R="$D/long_drive" && mkdir -p "$R" && rm -rf "$R/W" "$R/L" "$R/diag" "$R/cal"
      # (a) a 60 s window at 110 Hz, the five values of the study: the diagnosis.
      "$B" import --log data/drives/controlled_car_c.csv --map data/drives/controlled_car_map.toml \
        --study data/drives/controlled_car_study.toml --out "$R/W" --scenario drive_w --window 10,70 >"$R/import_w.log"
      timed long_drive_diagnose "$R/diagnose.log" "$B" diagnose --study "$R/W/study.toml" --data "$R/W/measurements.csv@drive_w" \
        --out "$R/diag" --causes 3 --candidates 2
      # (b) the structure found (hub input + skyhook, four values) on a whole 12-minute drive.
      [[ -f "$R/controlled_car_long.csv" ]] || python3 scripts/make_controlled_car_drives.py --long "$B" "$R" >"$R/make.log"
      "$B" import --log "$R/controlled_car_long.csv" --map data/drives/controlled_car_map.toml \
        --study data/drives/controlled_car_study.toml --out "$R/L" --scenario drive_long >"$R/import_l.log"
      sed -e 's/^tire = \["pac2002"\]/tire = ["hub"]/' "$R/L/study.toml" >"$R/L/study_found.toml"
      printf '\n[effects.skyhook]\ndamping = 0.0\n\n[[calibrated]]\nname = "skyhook.damping"\nunit = "N*s/m"\nlower = 0.0\nupper = 8000.0\n' \
        >>"$R/L/study_found.toml"
      timed long_drive "$R/calibrate.log" "$B" calibrate --study "$R/L/study_found.toml" \
        --data "$R/L/measurements.csv@drive_long" --out "$R/cal"
      ;;
    demo_study)
      rm -rf "$D/demo_study"
      timed demo_study "$D/demo_study.log" "$B" study --study data/studies/demo.toml --out "$D/demo_study" --quiet
      ;;
    fresh_demo)
      rm -rf "$D/fresh_demo" "$D/fresh_cache"
      git clone -q . "$D/fresh_demo"
      timed fresh_demo "$D/fresh_demo.log" env DTWIN_CACHE_DIR="$D/fresh_cache" CCACHE_DISABLE=1 bash "$D/fresh_demo/scripts/demo.sh"
      ;;
    hand_ode)
      "$B" bench --hand-ode --runs 30 >"$D/hand_ode.txt" 2>&1
      secs[hand_ode]=0
      ;;
    accumulation)
      "$B" bench --accumulation --study data/studies/paper.toml --runs 9 >"$D/accumulation.txt" 2>&1
      secs[accumulation]=0
      ;;
    mpi_synthesis)
      [[ -f "$D/demo_study/calibration/M1/posterior.csv" ]] || { echo "bench_jobs.sh: mpi_synthesis needs the demo_study row first" >&2; exit 2; }
      command -v mpirun >/dev/null || { echo "bench_jobs.sh: mpi_synthesis needs mpirun (openmpi-bin)" >&2; exit 2; }
      rm -rf "$D/mpi_synthesis"
      S=(synthesize --study data/studies/demo.toml --calibration "$D/demo_study/calibration" --assembly M1 --draws 400 --quiet)
      timed mpi_synthesis_threads "$D/mpi_synthesis_threads.log" "$B" "${S[@]}" --threads 2 --out "$D/mpi_synthesis/threads"
      timed mpi_synthesis "$D/mpi_synthesis.log" mpirun --allow-run-as-root --oversubscribe -n 2 "$B" "${S[@]}" --threads 1 \
        --out "$D/mpi_synthesis/ranks"
      cmp "$D/mpi_synthesis/threads/M1/moments.bin" "$D/mpi_synthesis/ranks/M1/moments.bin" >&2 ||
        { echo "bench_jobs.sh: mpi_synthesis: the moments differ between threads and ranks" >&2; exit 1; }
      ;;
    paper_draws)
      P="${PAPER_DIR:-$D/paper}"
      [[ -f "$P/summary.json" ]] || { echo "bench_jobs.sh: paper_draws needs a finished paper study in $P (the paper row, or PAPER_DIR)" >&2; exit 2; }
      mkdir -p "$D/paper_draws"
      t0=$(date +%s)
      for run in 100:1 100:2 100:3 300:1 300:2 300:3 1000:1; do
        n=${run%%:*} seed=${run##*:} out="$D/paper_draws/d${run%%:*}_s${run##*:}"
        "$B" synthesize --study data/studies/paper.toml --calibration "$P/calibration" --draws "$n" --seed "$seed" \
          --out "$out/synthetic" --quiet
        "$B" classify --study data/studies/paper.toml --field "$P/field/field.csv" --synthetic "$out/synthetic" \
          --out "$out/classification" --quiet
        python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print(sys.argv[2], 'draws, seed', sys.argv[3], ':', 'wins', j['wins'], 'recommended', j['recommended'])" \
          "$out/classification/summary.json" "$n" "$seed" | tee -a "$D/paper_draws/table.txt" >&2
      done
      secs[paper_draws]=$(( $(date +%s) - t0 ))
      ;;
    paper)
      # Resumable: a rerun continues the study in $D/paper; the time is this sitting's.
      timed paper "$D/paper.log" "$B" study --study data/studies/paper.toml --out "$D/paper"
      ;;
  esac
done

echo "| job | wall time (s) | output |"
echo "|---|---|---|"
for r in "${rows[@]}"; do
  case "$r" in
    run) echo "| one 15 s run per assembly (\`twin bench --runs 3\`) | see $D/run.md | $D/run.md |" ;;
    hand_ode | accumulation) echo "| $r | see $D/$r.txt | $D/$r.txt |" ;;
    long_drive) printf '| long_drive: (a) diagnose, 60 s at 110 Hz / (b) calibrate, 12 min at 110 Hz | %.0f / %.0f | %s |\n' \
      "${secs[long_drive_diagnose]}" "${secs[long_drive]}" "$D/long_drive" ;;
    mpi_synthesis) printf '| mpi_synthesis: 1 process x 2 threads / mpirun -n 2 x 1 thread | %.0f / %.0f | %s |\n' \
      "${secs[mpi_synthesis_threads]}" "${secs[mpi_synthesis]}" "$D/mpi_synthesis" ;;
    *) printf '| %s | %.0f | %s |\n' "$r" "${secs[$r]}" "$D/$r" ;;
  esac
done
echo "($(nproc) cores, $(date -u +%Y-%m-%d), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown))"
