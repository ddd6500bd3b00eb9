#!/usr/bin/env bash
# Fresh machine to demo: installs what lfd needs (the program's packages only, not the tests'),
# builds it, runs `lfd demo` on the embedded
# defaults and prints where the report is.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
LFD_BUILD_TESTS="${LFD_BUILD_TESTS:-OFF}" bash scripts/build.sh lfd  # no GoogleTest needed
./build/apps/lfd demo --out "${1:-out/demo}"
