#!/usr/bin/env bash
# Installs missing Debian packages, then configures and builds (Release) into ./build.
#   build.sh          everything, the test suite included
#   build.sh --demo   only the `twin` program and the packages it needs (scripts/demo.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--demo" ]; then
  bash scripts/setup.sh demo
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=OFF
  cmake --build build -j"$(nproc)" --target twin
else
  bash scripts/setup.sh
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=ON
  cmake --build build -j"$(nproc)"
fi
