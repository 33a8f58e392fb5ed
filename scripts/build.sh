#!/usr/bin/env bash
# Installs missing Debian packages, then configures and builds (Release) into ./build.
#   build.sh          everything, the test suite included
#   build.sh --demo   only the `twin` program, the Python module dtwin and the packages they need
#                     (scripts/demo.sh)
# Both first build Debian's Simbody with Release flags into a cache outside the repository, once
# per machine (scripts/simbody.sh, about 2 minutes on 2 cores); if that fails the project links
# Debian's binary Simbody instead (about half the speed) and says so.
set -euo pipefail
cd "$(dirname "$0")/.."
simbody() {
  bash scripts/simbody.sh || echo "build: the Release Simbody could not be built; using Debian's binary package (about half the speed)"
}
# Ninja where it is installed (setup.sh installs it): about 15 % faster than make on 2 cores. A
# build folder keeps the generator it was first configured with.
gen=()
if [ ! -f build/CMakeCache.txt ] && command -v ninja >/dev/null; then gen=(-G Ninja); fi
# Each phase's wall time, printed at the end (docs/performance.md, "Which Simbody": the newcomer's path).
phases=""
phase_start=$SECONDS
phase() {  # phase NAME: the time since the last phase ends here
  phases="$phases${phases:+, }$1 $((SECONDS - phase_start)) s"
  phase_start=$SECONDS
}
if [ "${1:-}" = "--demo" ]; then
  bash scripts/setup.sh demo
  phase packages
  simbody
  phase simbody
  cmake -S . -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=OFF
  # The program and the Python module (docs/python.md, when CMake found pybind11 and Python's
  # headers) in one build, so that the module's bindings compile beside the program's last sources.
  if [ -d build/python/CMakeFiles/dtwin_python.dir ]; then
    cmake --build build -j"$(nproc)" --target twin dtwin_python
    phase "twin and python module"
  else
    cmake --build build -j"$(nproc)" --target twin
    phase twin
  fi
else
  bash scripts/setup.sh
  phase packages
  simbody
  phase simbody
  cmake -S . -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=ON
  cmake --build build -j"$(nproc)"
  phase "twin, python module and tests"
fi
echo "build phases: $phases"
# `import dtwin` in Debian's Python with no setting: a path file in /usr/local's dist-packages (on
# Debian's sys.path) names this build's module folder. Only as root, and only where that folder is
# Debian Python's own; elsewhere docs/python.md says to set PYTHONPATH=build/python.
module=""
for f in build/python/dtwin.cpython-*.so; do [ -e "$f" ] && module="$f" && break; done
if [ -n "$module" ] && [ "$(id -u)" -eq 0 ] && [ -x /usr/bin/python3 ]; then
  site=$(/usr/bin/python3 -c 'import sys; print("/usr/local/lib/python%d.%d/dist-packages" % sys.version_info[:2])')
  if /usr/bin/python3 -c "import sys; sys.exit(0 if '$site' in sys.path else 1)" 2>/dev/null; then
    mkdir -p "$site"
    echo "$(pwd)/build/python" > "$site/dtwin.pth"
    echo "build: /usr/bin/python3 finds the module dtwin ($site/dtwin.pth -> $(pwd)/build/python)"
    # and mypy its types: the stub package dtwin-stubs of this build (python/dtwin.pyi)
    if [ -d build/python/dtwin-stubs ] && { [ -L "$site/dtwin-stubs" ] || [ ! -e "$site/dtwin-stubs" ]; }; then
      ln -sfn "$(pwd)/build/python/dtwin-stubs" "$site/dtwin-stubs"
    fi
  fi
fi
