#!/usr/bin/env bash
# Runs every libFuzzer target (fuzz/CMakeLists.txt) for SECONDS each (default 60) on its seed
# corpus fuzz/corpus/<target>/, after configuring and building the clang fuzz build (ASan +
# UBSan + libFuzzer coverage on the whole tree). Exits non-zero if any target finds a crash,
# a sanitizer report, a leak, a timeout or an out-of-memory input; the inputs that did it are
# kept in $BUILD/fuzz-artifacts/<target>/ (replay: $BUILD/fuzz/<target> FILE).
#   scripts/fuzz.sh                 every target, 60 s each
#   scripts/fuzz.sh 300 fuzz_visual_json fuzz_scene_spz
# Environment: LFD_FUZZ_BUILD_DIR (default build-fuzz), LFD_FUZZ_JOBS (build jobs, default all
# cores), LFD_RENDER_ONLY=ON (no OpenCV/Ceres: the scene, cam.json and display-file targets;
# read when the build folder is first configured, so give it its own LFD_FUZZ_BUILD_DIR).
# New inputs that reach new code go to $BUILD/fuzz-corpus/<target>/, not into the repo; add
# small interesting ones to fuzz/corpus/<target>/ by hand. docs/fuzzing.md: what each covers.
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_EACH="${1:-60}"
[ $# -gt 0 ] && shift
if ! [[ "$SECONDS_EACH" =~ ^[0-9]+$ ]] || [ "$SECONDS_EACH" -lt 1 ]; then
  echo "usage: scripts/fuzz.sh [SECONDS] [TARGET...]  (SECONDS: a positive whole number)" >&2
  exit 2
fi
BUILD="${LFD_FUZZ_BUILD_DIR:-build-fuzz}"
JOBS="${LFD_FUZZ_JOBS:-$(nproc)}"

if ! command -v clang++ >/dev/null; then
  echo "scripts/fuzz.sh: needs clang (apt-get install clang)" >&2
  exit 2
fi

if [ ! -f "$BUILD/build.ninja" ]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  # -O1 -g without NDEBUG: assertions stay on, stacks stay readable.
  CC=clang CXX=clang++ cmake -S . -B "$BUILD" -G Ninja -DLFD_FUZZ=ON -DLFD_BUILD_TESTS=OFF \
    -DLFD_RENDER_ONLY="${LFD_RENDER_ONLY:-OFF}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" \
    "${launcher[@]}" >/dev/null
fi

if [ $# -gt 0 ]; then
  targets=("$@")
  ninja -C "$BUILD" -j "$JOBS" "${targets[@]}"
else
  ninja -C "$BUILD" -j "$JOBS" fuzz
  targets=()
  for exe in "$BUILD"/fuzz/fuzz_*; do
    [ -f "$exe" ] && [ -x "$exe" ] && targets+=("$(basename "$exe")")
  done
fi

failed=()
printf '%-28s %8s %12s %8s  %s\n' target seconds execs corpus result
for t in "${targets[@]}"; do
  seeds="fuzz/corpus/$t"
  work="$BUILD/fuzz-corpus/$t"
  artifacts="$BUILD/fuzz-artifacts/$t"
  log="$BUILD/fuzz-logs/$t.log"
  mkdir -p "$work" "$artifacts" "$(dirname "$log")"
  [ -d "$seeds" ] || { echo "scripts/fuzz.sh: $seeds: no seed corpus for $t" >&2; exit 2; }
  dict=()
  [ -f "fuzz/dict/$t.dict" ] && dict=(-dict="fuzz/dict/$t.dict")
  # -timeout: an input that takes 10 s is a hang; -rss_limit_mb/-malloc_limit_mb: a parser
  # that allocates 2 GiB from a length field is a bug; -close_fd_mask=1: no stdout chatter.
  rc=0
  ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}" \
    "$BUILD/fuzz/$t" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=2048 -close_fd_mask=1 -print_final_stats=1 "${dict[@]}" \
    -artifact_prefix="$artifacts/" "$work" "$seeds" >"$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  corpus=$(find "$work" -type f | wc -l)
  if [ "$rc" -eq 0 ]; then
    result=ok
  else
    result="FAILED (exit $rc): $(grep -m1 -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" || echo "see $log")"
    failed+=("$t")
  fi
  printf '%-28s %8s %12s %8s  %s\n' "$t" "$SECONDS_EACH" "${execs:-?}" "$corpus" "$result"
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "findings in: ${failed[*]} (inputs in $BUILD/fuzz-artifacts/, logs in $BUILD/fuzz-logs/)" >&2
  exit 1
fi
echo "no findings in ${#targets[@]} targets"
