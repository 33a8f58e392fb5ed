#!/usr/bin/env bash
# The main job on the embedded default study (data/studies/demo.toml): the whole method end to
# end (twin study): lab and field data, Griddy Gibbs calibration of every assembly, synthetic
# field data, Bayesian classification and the cost-aware recommendation, into out/study/, and
# its self-contained HTML report out/study/report.html.
# Builds only what the demo needs (the `twin` program and the Python module; the tests are built by
# scripts/test.sh). About 2 minutes for the study on 2 cores, plus the build. Rerunning resumes
# where a killed run stopped.
#   demo.sh          into out/study
#   demo.sh DIR      into DIR (scripts/test.sh runs the demo into build/demo)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/study}"
start=$SECONDS
bash scripts/setup.sh demo
t_setup=$((SECONDS - start))
bash scripts/build.sh --demo
t_build=$((SECONDS - start - t_setup))
./build/cli/twin study --study data/studies/demo.toml --out "$out"
t_study=$((SECONDS - start - t_setup - t_build))
./build/cli/twin report --study-dir "$out" --out "$out"
t_report=$((SECONDS - start - t_setup - t_build - t_study))
echo "results in $out/ (summary.json: wins, recommended, stages); open $out/report.html"
echo "wall time: set-up ${t_setup} s, build ${t_build} s, study ${t_study} s, report ${t_report} s, total $((SECONDS - start)) s"
# The Python module (docs/python.md): `import dtwin` in Debian's Python, with no setting when
# scripts/build.sh could write its path file (as root), else with PYTHONPATH=build/python.
modules=(build/python/dtwin.cpython-*.so)
if [ ! -e "${modules[0]}" ]; then
  echo "python: no module dtwin (CMake found no pybind11 or Python headers; docs/python.md)"
elif [ "$(id -u)" -eq 0 ]; then
  /usr/bin/python3 -c 'import dtwin; print("python: /usr/bin/python3 -c \"import dtwin\" works (dtwin %s, %s)" % (dtwin.__version__, dtwin.__file__))'
else
  PYTHONPATH=build/python /usr/bin/python3 -c 'import dtwin; print("python: PYTHONPATH=build/python /usr/bin/python3 -c \"import dtwin\" works (dtwin %s)" % dtwin.__version__)'
fi
