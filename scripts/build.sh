#!/usr/bin/env bash
# Installs missing Debian packages, then configures and builds (Release) into ./build.
#   build.sh          everything, the test suite included
#   build.sh --demo   only the `twin` program and the packages it needs (scripts/demo.sh)
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
else
  bash scripts/setup.sh
  simbody
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=ON
  cmake --build build -j"$(nproc)"
fi
