#!/usr/bin/env bash
# Fails, naming the files, when a C++ file of the project is not laid out as .clang-format says
# (clang-format would change it). Usage: check_format.sh SOURCE_DIR [CLANG_FORMAT]
set -euo pipefail
source_dir=$1
clang_format=${2:-clang-format}
cd "$source_dir"
mapfile -d '' files < <(find fapcodec transcoder xmt tools tests bench -path tests/vendor -prune -o \
  -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print0 | sort -z)
[ "${#files[@]}" -gt 100 ] || { echo "check_format.sh: only ${#files[@]} C++ files found under $source_dir" >&2; exit 1; }
# One clang-format for all files (one per file costs a process start each); it names each file
# it would change in a "code should be clang-formatted" error.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if "$clang_format" --dry-run --Werror "${files[@]}" 2> "$log" > /dev/null; then
  echo "${#files[@]} files formatted"
  exit 0
fi
echo "not formatted as .clang-format says (run: clang-format -i FILE...):" >&2
grep -o '^[^:]*:[0-9]*:[0-9]*: error: code should be clang-formatted' "$log" | cut -d: -f1 | sort -u |
  sed 's/^/  /' >&2 || cat "$log" >&2
exit 1
