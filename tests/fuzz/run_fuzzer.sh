#!/usr/bin/env bash
# One bounded libFuzzer run of a target from its saved inputs, with the project's settings:
#   run_fuzzer.sh FUZZER FUZZ_DIR NAME WORK_DIR SECONDS [extra libFuzzer flags...]
# FUZZ_DIR is tests/fuzz (corpus/NAME/ and NAME.dict are read there, never written). New inputs go
# to WORK_DIR/NAME/corpus, crashes, timeouts and OOMs to WORK_DIR/NAME/artifacts/. Inputs up to
# 1 MB (nesting and size attacks need room), 10 s and 2 GB per input; any sanitizer report stops
# the run with a non-zero status.
set -euo pipefail
fuzzer=$1 fuzz_dir=$2 name=$3 work=$4/$3 seconds=$5
shift 5
# A fresh corpus each run; earlier runs' artifacts stay, so a rerun does not wipe a failure's input.
rm -rf "$work/corpus"
mkdir -p "$work/corpus" "$work/artifacts"
flags=(-max_total_time="$seconds" -max_len=1048576 -timeout=10 -rss_limit_mb=2048
       -malloc_limit_mb=2048 -artifact_prefix="$work/artifacts/" -print_final_stats=1)
if [[ -f "$fuzz_dir/$name.dict" ]]; then
  flags+=(-dict="$fuzz_dir/$name.dict")
elif [[ $name == pipeline ]]; then  # every input kind: every dictionary
  cat "$fuzz_dir"/*.dict > "$work/all.dict"
  flags+=(-dict="$work/all.dict")
fi
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
# The one known leak inside Xerces-C (see docs/testing.md).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$(cd "$fuzz_dir/../.." && pwd)/.ci/lsan.supp}
exec "$fuzzer" "${flags[@]}" "$@" "$work/corpus" "$fuzz_dir/corpus/$name"
