#!/usr/bin/env bash
# Builds Debian's own Simbody (the source package of the installed libsimbody-dev, Debian's patches
# applied) with Simbody's Release configuration (-DNDEBUG), raised to -O3 -fno-semantic-interposition
# (calls inside the shared libraries may be inlined; the results stay bit-identical, about 20 % faster
# than -O2), libraries only, into a cache outside the repository, once per machine. CMake prefers this build and falls back to the binary package
# (docs/performance.md, "Which Simbody"): Debian's binary package is built without NDEBUG, so every
# range, stage and argument check of Simbody runs inside each step, and a run is about twice as slow.
#
# The libraries are compiled as a unity build (batches of 8 sources, each batch one compiler run;
# the sources that do not compile beside others alone): about 2.5 minutes on 2 cores instead of 4.
# Where the unity build fails (another Simbody version), the ordinary build follows.
#
#   simbody.sh          build it if it is missing (about 2.5 minutes on 2 cores, once)
#   simbody.sh --where  print the folder it is (or would be) installed in, build nothing
#
# The cache is $DTWIN_CACHE_DIR, else $XDG_CACHE_HOME/dtwin, else ~/.cache/dtwin. A build that is
# interrupted leaves nothing half-installed: the folder is renamed into place only when complete.
# Needs root (or sudo) once, to add a deb-src line for `apt-get source` and the build's packages.
set -euo pipefail
cache="${DTWIN_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/dtwin}"
version="$(dpkg-query -W -f='${Version}' libsimbody-dev 2>/dev/null || true)"
if [ -z "$version" ]; then
  echo "simbody: libsimbody-dev is not installed (run scripts/setup.sh first)" >&2
  exit 2
fi
prefix="$cache/simbody-${version}-release"
flags="-DNDEBUG -O3 -fno-semantic-interposition"
recipe="Simbody $version (Debian source package, Release: $flags, libraries only)"
if [ "${1:-}" = "--where" ]; then echo "$prefix"; exit 0; fi
present() { [ -f "$prefix/dtwin-build.txt" ] && [ "$(head -n1 "$prefix/dtwin-build.txt")" = "$recipe" ]; }
if present; then
  echo "simbody: Release build present ($prefix)"
  exit 0
fi
mkdir -p "$cache"
exec 9>"$cache/simbody.lock"
if ! flock -n 9; then
  echo "simbody: another set-up is building it; waiting"
  flock 9
  present && { echo "simbody: Release build present ($prefix)"; exit 0; }
fi
start=$SECONDS
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
# The source package comes from the same archive as the binaries: one deb-src line for each
# suite of the machine's own sources, added once.
if ! apt-get source --print-uris -qq "simbody=$version" >/dev/null 2>&1; then
  src=/etc/apt/sources.list.d/dtwin-src.sources
  echo "simbody: adding the archive's source packages ($src)"
  $SUDO tee "$src" >/dev/null <<'EOF'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
  $SUDO apt-get update -qq
fi
need=()
for p in dpkg-dev liblapack-dev libblas-dev cmake g++; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep "install ok installed" >/dev/null || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  echo "simbody: installing ${need[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}"
fi
work="$cache/simbody-${version}-work"
rm -rf "$work" "$prefix.partial"
mkdir -p "$work"
( cd "$work" && apt-get source -qq "simbody=$version" >/dev/null 2>&1 ) || {
  echo "simbody: 'apt-get source simbody=$version' failed; the binary package stays in use" >&2
  rm -rf "$work"; exit 1; }
srcdir="$(find "$work" -mindepth 1 -maxdepth 1 -type d -name 'simbody-*' -print -quit)"
# Simbody sets its Release flags itself (CMakeLists.txt, BUILD_CXX_FLAGS_RELEASE): raise them there.
sed -i 's/"-DNDEBUG -O2 ${GCC_OPT_ENABLE}/"'"$flags"' ${GCC_OPT_ENABLE}/' "$srcdir/CMakeLists.txt"
grep -q -- "$flags" "$srcdir/CMakeLists.txt" || { echo "simbody: could not set the Release flags in $srcdir/CMakeLists.txt" >&2; exit 1; }
# The unity build's exceptions: sources that declare BLAS/LAPACK or f2c names their own way, reuse
# a static helper's name or define macros (the polynomial solvers, the random generator), and the C
# sources, each compiled alone. Source properties hold in the folder that defines the library.
for lib in SimTKcommon SimTKmath Simbody; do
  cat >>"$srcdir/$lib/sharedTarget/CMakeLists.txt" <<'EOF'
# scripts/simbody.sh (dtwin): the sources compiled alone in a unity build
foreach(f ${SOURCE_FILES})
  if(f MATCHES "/(cpoly|rpoly|gcvspl|ParallelWorkQueue|IpLapack|IpLapackSolverInterface|IpBlas|lbfgs|lbfgsb|LapackInterface|About|SFMT|Random|HuntCrossleyForce|PLUSImpulseSolver)\\.cpp$" OR f MATCHES "\\.c$")
    set_source_files_properties(${f} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
  endif()
endforeach()
EOF
done
echo "simbody: building Debian's simbody $version with Release flags into $prefix (once per machine)"
gen=()
command -v ninja >/dev/null && gen=(-G Ninja)
configure() {  # configure UNITY(ON|OFF): a fresh $work/build
  rm -rf "$work/build"
  cmake -S "$srcdir" -B "$work/build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$prefix.partial" -DCMAKE_INSTALL_LIBDIR=lib \
    -DBUILD_TESTING=OFF -DBUILD_EXAMPLES=OFF -DBUILD_VISUALIZER=OFF \
    -DSIMBODY_VISUALIZER_INSTALL_DIR="$prefix/lib/simbody/libexec" \
    -DCMAKE_UNITY_BUILD="$1" -DCMAKE_UNITY_BUILD_BATCH_SIZE=8 \
    -DBUILD_DYNAMIC_LIBRARIES=ON -DBUILD_STATIC_LIBRARIES=OFF -DINSTALL_DOCS=OFF >"$work/configure.log" 2>&1 || {
    echo "simbody: configure failed ($work/configure.log); the binary package stays in use" >&2; exit 1; }
}
how="unity build"
configure ON
if ! cmake --build "$work/build" -j"$(nproc)" >"$work/build.log" 2>&1; then
  echo "simbody: the unity build failed ($work/build-unity.log); building source by source"
  mv "$work/build.log" "$work/build-unity.log"
  how="source by source"
  configure OFF
  cmake --build "$work/build" -j"$(nproc)" >"$work/build.log" 2>&1 || {
    echo "simbody: build failed ($work/build.log); the binary package stays in use" >&2; exit 1; }
fi
cmake --install "$work/build" >"$work/install.log" 2>&1
# The installed CMake files name the prefix they were installed to; they locate themselves
# relative to their own folder, so the rename below keeps them valid. (Debian's patch asks for the
# visualizer's folder even when the visualizer is not built.)
cat >"$prefix.partial/dtwin-build.txt" <<EOF
$recipe
built $(date -u +%Y-%m-%dT%H:%M:%SZ) by scripts/simbody.sh in $((SECONDS - start)) s ($how)
EOF
rm -rf "$prefix.old"
[ -d "$prefix" ] && mv "$prefix" "$prefix.old"  # an earlier recipe's build: replaced
mv "$prefix.partial" "$prefix"
rm -rf "$work" "$prefix.old"
echo "simbody: done in $((SECONDS - start)) s ($prefix)"
