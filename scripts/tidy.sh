#!/usr/bin/env bash
# clang-tidy with the checks of .clang-tidy (bugprone-*, performance-*) over the project's own
# sources: prints the findings, one summary line per check, and exits 1 if there is any.
#   tidy.sh               the libraries, the program and the Python module (about 45 min on one core)
#   tidy.sh --tests       the tests too (about twice as long)
#   tidy.sh FILE.cpp ...  those files
# It configures ./build-tidy as scripts/build.sh configures ./build (Release, the Simbody it
# finds) but compiles nothing: each source on its own (no unity batches, no precompiled header),
# as clang-tidy reads the compile database. third_party/ and the generated headers are left out
# (HeaderFilterRegex in .clang-tidy). JOBS=N runs N files at a time (default 1); it runs at the
# lowest priority (nice).
set -euo pipefail
cd "$(dirname "$0")/.."
tidy=""
for c in clang-tidy-14 clang-tidy; do
  if command -v "$c" >/dev/null; then tidy="$c" && break; fi
done
if [ -z "$tidy" ]; then
  echo "tidy: clang-tidy not found (Debian: apt-get install clang-tidy)" >&2
  exit 1
fi
gen=()
if [ ! -f build-tidy/CMakeCache.txt ] && command -v ninja >/dev/null; then gen=(-G Ninja); fi
cmake -S . -B build-tidy "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DDTWIN_BUILD_TESTS=ON \
  -DDTWIN_UNITY_BUILD=OFF -DDTWIN_PCH=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
files=()
if [ $# -gt 0 ] && [ "$1" != "--tests" ]; then
  files=("$@")
else
  tests=0
  [ "${1:-}" = "--tests" ] && tests=1
  mapfile -t files < <(python3 - "$tests" <<'EOF'
import json, os, sys
root = os.getcwd() + "/"
seen = set()
for e in json.load(open("build-tidy/compile_commands.json")):
    f = os.path.relpath(os.path.join(e["directory"], e["file"]), root)
    if f.startswith(("build", "third_party/", "..")) or (f.startswith("tests/") and sys.argv[1] == "0"):
        continue
    seen.add(f)
print("\n".join(sorted(seen)))
EOF
)
fi
echo "tidy: $tidy over ${#files[@]} files"
start=$SECONDS
out=$(printf '%s\0' "${files[@]}" |
      nice -n 19 xargs -0 -n 1 -P "${JOBS:-1}" "$tidy" -p build-tidy --quiet 2>/dev/null || true)
# A header's finding is reported once per file that includes it: each printed once.
findings=$(grep -E '^[^ ].*:[0-9]+:[0-9]+: (warning|error): ' <<<"$out" | sort -u || true)
[ -n "$findings" ] && echo "$findings"
echo "tidy: $((SECONDS - start)) s"
if [ -z "$findings" ]; then
  echo "tidy: no findings"
  exit 0
fi
echo "tidy: $(wc -l <<<"$findings") findings:"
grep -oE '\[[a-z0-9.,-]+\]$' <<<"$findings" | sort | uniq -c | sort -rn
exit 1
