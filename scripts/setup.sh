#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs (only those that are missing).
# Safe to run repeatedly. Needs root (or sudo) for apt-get. `setup.sh demo`: the demo's only;
# `setup.sh fuzz`: also clang and its sanitizer/libFuzzer runtimes (scripts/fuzz.sh).
set -euo pipefail
PKGS=(build-essential cmake ninja-build pkg-config git
      libsimbody-dev libeigen3-dev libnlopt-cxx-dev libnlopt-dev
      googletest libgtest-dev libgmock-dev
      libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
      libmuparser-dev         # user-defined effects: force expressions in the study file
      zlib1g-dev libexpat1-dev   # mdflib (third_party/mdflib): MF4 logs for `twin import`
      gnuplot-nox chromium    # gnuplot: `twin report`; chromium: its rendering test
      pybind11-dev python3-dev python3-numpy   # the Python module dtwin (docs/python.md)
      python3-matplotlib      # the plots of docs/python.md's example (and its test)
      mypy                    # the module's type stubs checked by its tests (python/dtwin.pyi)
      python3-build python3-setuptools python3-wheel python3-venv   # the wheel and its test (docs/install.md)
      file                    # cpack -G DEB: which files dpkg-shlibdeps reads (docs/install.md)
      clang-format            # the format check of the tests (scripts/format_check.sh, .clang-format)
      libopenmpi-dev openmpi-bin    # MPI: `mpirun -n K twin ...` (docs/cluster.md)
      libxml2-dev libminizip-dev libxml2-utils)   # fmusim and xmllint for the FMU's tests (third_party/reference-fmus)
# `setup.sh demo`: only what the demo needs (no test framework, no browser for the report test, no
# MPI: the demo runs in one process, and MPI's 80 packages, gfortran among them, add about 105 MB;
# no matplotlib: the demo builds the Python module but plots nothing with it; no mypy: it checks
# the module's stubs in the tests; no wheel or Debian package tools: their tests build them; no
# clang-format: the tests check the formatting).
if [ "${1:-}" = "demo" ]; then
  keep=()
  for p in "${PKGS[@]}"; do
    case "$p" in googletest|libgtest-dev|libgmock-dev|chromium|libxml2-dev|libminizip-dev|libxml2-utils|libopenmpi-dev|openmpi-bin|python3-matplotlib|mypy|python3-build|python3-setuptools|python3-wheel|python3-venv|file|clang-format) ;; *) keep+=("$p") ;; esac
  done
  PKGS=("${keep[@]}")
fi
if [ "${1:-}" = "fuzz" ]; then
  PKGS+=(clang libclang-rt-dev)
fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep "install ok installed" >/dev/null || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all packages present"
fi
