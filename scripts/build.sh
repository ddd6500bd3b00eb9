#!/usr/bin/env bash
# Configures and builds lfd with Ninja into build/ (or $LFD_BUILD_DIR). Extra arguments are
# targets. Used by the demo and test commands; safe to run repeatedly.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${LFD_BUILD_DIR:-build}"
# LFD_BUILD_TESTS=ON|OFF: the GoogleTest suites (scripts/test.sh turns them on, scripts/demo.sh
# off, so the demo needs no test packages); a build folder configured otherwise is reconfigured.
tests_arg=()
if [ -n "${LFD_BUILD_TESTS:-}" ]; then tests_arg=(-DLFD_BUILD_TESTS="$LFD_BUILD_TESTS"); fi
cached_tests=$(sed -n 's/^LFD_BUILD_TESTS:BOOL=//p' "$BUILD_DIR/CMakeCache.txt" 2>/dev/null || true)
if [ ! -f "$BUILD_DIR/build.ninja" ] || { [ -n "${LFD_BUILD_TESTS:-}" ] && [ "$cached_tests" != "$LFD_BUILD_TESTS" ]; }; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="${LFD_BUILD_TYPE:-Release}" "${tests_arg[@]}" \
    ${LFD_CMAKE_ARGS:-} >/dev/null
fi
ninja -C "$BUILD_DIR" "$@"
