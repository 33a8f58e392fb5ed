#!/usr/bin/env bash
# Checks that every C++ file of the project is formatted as .clang-format says (clang-format
# --dry-run -Werror): prints the files that are not and the command that formats them, and exits 1
# if there is any. Run by CTest (the test format_check, label unit) and so by scripts/test.sh.
#   format_check.sh         check
#   format_check.sh --fix   format every project file in place (clang-format -i)
# The project's files: *.cpp, *.hpp and *.h outside third_party/ (vendored code keeps its own
# style), the build folders (build/, build-*/: generated files) and the other folders .gitignore
# names. CLANG_FORMAT=/path/to/clang-format picks another binary; the style is Debian 12's
# clang-format 14's, and another version may format some lines differently.
set -euo pipefail
cd "$(dirname "$0")/.."
cf="${CLANG_FORMAT:-}"
if [ -z "$cf" ]; then
  for c in clang-format-14 clang-format; do
    if command -v "$c" >/dev/null; then cf="$c" && break; fi
  done
fi
if [ -z "$cf" ] || ! command -v "$cf" >/dev/null; then
  echo "format_check: FAILED: clang-format not found (Debian: apt-get install clang-format;" \
       "scripts/setup.sh installs it)" >&2
  exit 1
fi
files=()
while IFS= read -r -d '' f; do files+=("${f#./}"); done < <(
  find . \( -path ./third_party -o -path './build' -o -path './build-*' -o -path ./out -o -path ./dist \
            -o -path ./Testing -o -name '.*' ! -name . \) -prune \
         -o -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print0 | sort -z)
if [ ${#files[@]} -eq 0 ]; then
  echo "format_check: FAILED: no C++ files found under $(pwd)" >&2
  exit 1
fi
if [ "${1:-}" = "--fix" ]; then
  printf '%s\0' "${files[@]}" | xargs -0 "$cf" -i
  echo "format_check: formatted ${#files[@]} files with $("$cf" --version)"
  exit 0
fi
# One error per file at most (--ferror-limit=1): the list of files that are off.
set +e
out=$(printf '%s\0' "${files[@]}" | xargs -0 "$cf" --dry-run -Werror --ferror-limit=1 2>&1)
rc=$?
set -e
if [ $rc -eq 0 ]; then
  echo "format_check: ${#files[@]} files formatted as .clang-format says ($("$cf" --version))"
  exit 0
fi
mapfile -t off < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' <<<"$out" | sort -u)
if [ ${#off[@]} -eq 0 ]; then  # clang-format itself failed (a bad .clang-format, a file it cannot read)
  echo "$out" >&2
  echo "format_check: FAILED: $cf exited with $rc" >&2
  exit 1
fi
echo "format_check: FAILED: ${#off[@]} of ${#files[@]} files are not formatted as .clang-format says ($("$cf" --version)):"
printf '  %s\n' "${off[@]}"
if [ ${#off[@]} -le 20 ]; then
  echo "Format them with:"
  echo "  cd $(pwd) && $cf -i ${off[*]}"
  echo "or every project file with:"
else
  echo "Format every project file with:"
fi
echo "  bash scripts/format_check.sh --fix"
exit 1
