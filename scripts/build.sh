#!/usr/bin/env bash
# Configures and builds lfd with Ninja into build/ (or $LFD_BUILD_DIR). Extra arguments are
# targets. Used by the demo and test commands; safe to run repeatedly.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${LFD_BUILD_DIR:-build}"
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="${LFD_BUILD_TYPE:-Release}" ${LFD_CMAKE_ARGS:-} >/dev/null
fi
ninja -C "$BUILD_DIR" "$@"
