#!/usr/bin/env bash
# Builds Debian's own Simbody (the source package of the installed libsimbody-dev, Debian's patches
# applied) with Simbody's Release configuration (-DNDEBUG), raised to -O3 -fno-semantic-interposition
# (calls inside the shared libraries may be inlined; the results stay bit-identical, about 20 % faster
# than -O2), libraries only, into a cache outside the repository, once per machine. CMake prefers this build and falls back to the binary package
# (docs/performance.md, "Which Simbody"): Debian's binary package is built without NDEBUG, so every
# range, stage and argument check of Simbody runs inside each step, and a run is about twice as slow.
#
# The libraries are compiled as a unity build (batches of 8 sources, each batch one compiler run;
# the sources that do not compile beside others alone), and the code the twin never runs at -O1:
# about 2 minutes on 2 cores instead of 4. Where the unity build fails (another Simbody version),
# the ordinary build follows.
#
#   simbody.sh          build it if it is missing (about 2 minutes on 2 cores, once)
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
# The multibody library's own batches are large enough to stop GCC's inlining at its unit-growth
# limit: raised there, the twin's runs are about 7 % faster than with the library compiled source
# by source (docs/performance.md, "Which Simbody").
inline="--param=inline-unit-growth=400"
recipe="Simbody $version (Debian source package, Release: $flags, SimTKsimbody $inline, libraries only)"
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
# a static helper's name or define macros (the polynomial solvers, the random generator, the contact
# tracker), and the C sources, each compiled alone. Source properties hold in the folder that
# defines the library.
# Code the twin never runs (the optimizers with Ipopt, contact geometry and contact forces, cables,
# the assembler and point fitters, the visualizer client, XML and meshes) is compiled at -O1, in
# batches of 16 of its own: a fifth less compiler time; what the twin runs (the multibody tree,
# the integrators, linear algebra, SimTKcommon's core) keeps the Release flags above.
for lib in SimTKcommon SimTKmath Simbody; do
  cat >>"$srcdir/$lib/sharedTarget/CMakeLists.txt" <<'EOF2'
# scripts/simbody.sh (dtwin): the sources compiled alone in a unity build
foreach(f ${SOURCE_FILES})
  if(f MATCHES "/(cpoly|rpoly|gcvspl|ParallelWorkQueue|IpLapack|IpLapackSolverInterface|IpBlas|lbfgs|lbfgsb|LapackInterface|About|SFMT|Random|HuntCrossleyForce|PLUSImpulseSolver|ContactTracker)\\.cpp$" OR f MATCHES "\\.c$")
    set_source_files_properties(${f} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
  endif()
endforeach()
# scripts/simbody.sh (dtwin): code the twin never runs, at -O1 in batches of 16 (dtwin_cold_N.cpp);
# in the ordinary build (the fallback) each such source alone at -O1
set(_dtwin_cold "")
foreach(f ${SOURCE_FILES})
  if(f MATCHES "/Optimizers/|/Geometry/|/(Cable[A-Za-z]*|[A-Za-z_]*Contact[A-Za-z_]*|HuntCrossley[A-Za-z]*|[A-Za-z]*ImpulseSolver|ElasticFoundationForce|Visualizer[A-Za-z_]*|ObservedPointFitter|LocalEnergyMinimizer|Assembler|AssemblyCondition_[A-Za-z]*|TextDataEventReporter|SmoothSphereHalfSpaceForce|OBSOLETE_LengthConstraints|DecorationSubsystem|Force_Thermostat|Xml|tinyxml[a-z]*|PolygonalMesh|DecorativeGeometry)\\.cpp$")
    get_source_file_property(_dtwin_alone ${f} SKIP_UNITY_BUILD_INCLUSION)
    if(_dtwin_alone OR f MATCHES "\\.c$" OR NOT CMAKE_UNITY_BUILD)
      set_source_files_properties(${f} PROPERTIES COMPILE_OPTIONS "-O1")
    else()
      set_source_files_properties(${f} PROPERTIES HEADER_FILE_ONLY ON)
      list(APPEND _dtwin_cold ${f})
    endif()
  endif()
endforeach()
list(LENGTH _dtwin_cold _dtwin_len)
set(_dtwin_n 0)
set(_dtwin_text "")
foreach(f ${_dtwin_cold})
  string(APPEND _dtwin_text "#include \"${f}\"\n")
  math(EXPR _dtwin_n "${_dtwin_n} + 1")
  math(EXPR _dtwin_r "${_dtwin_n} % 16")
  if(_dtwin_r EQUAL 0 OR _dtwin_n EQUAL _dtwin_len)
    math(EXPR _dtwin_k "(${_dtwin_n} - 1) / 16")
    set(_dtwin_file "${CMAKE_CURRENT_BINARY_DIR}/dtwin_cold_${_dtwin_k}.cpp")
    file(WRITE "${_dtwin_file}" "${_dtwin_text}")
    target_sources(${SHARED_TARGET} PRIVATE "${_dtwin_file}")
    set_source_files_properties("${_dtwin_file}" PROPERTIES COMPILE_OPTIONS "-O1" SKIP_UNITY_BUILD_INCLUSION ON)
    set(_dtwin_text "")
  endif()
endforeach()
EOF2
done
echo "target_compile_options(\${SHARED_TARGET} PRIVATE $inline)  # scripts/simbody.sh (dtwin)" >>"$srcdir/Simbody/sharedTarget/CMakeLists.txt"
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
how="unity build; code the twin never runs at -O1"
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
