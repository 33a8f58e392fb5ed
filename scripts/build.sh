#!/usr/bin/env bash
# Installs missing Debian packages, then configures and builds (Release) into ./build.
#   build.sh          everything, the test suite included
#   build.sh --demo   only the `twin` program, the Python module dtwin and the packages they need
#                     (scripts/demo.sh)
# Both first build Debian's Simbody with Release flags into a cache outside the repository, once
# per machine (scripts/simbody.sh, about 2.5 minutes on 2 cores); if that fails the project links
# Debian's binary Simbody instead (about half the speed) and says so.
set -euo pipefail
cd "$(dirname "$0")/.."
simbody() {
  bash scripts/simbody.sh || echo "build: the Release Simbody could not be built; using Debian's binary package (about half the speed)"
}
if [ "${1:-}" = "--demo" ]; then
  bash scripts/setup.sh demo
  simbody
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=OFF
  cmake --build build -j"$(nproc)" --target twin
  # The Python module (docs/python.md), when CMake found pybind11 and Python's headers.
  if cmake --build build --target help | grep -q "dtwin_python"; then
    cmake --build build -j"$(nproc)" --target dtwin_python
  fi
else
  bash scripts/setup.sh
  simbody
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=ON
  cmake --build build -j"$(nproc)"
fi
