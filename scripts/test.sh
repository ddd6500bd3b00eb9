#!/usr/bin/env bash
# Fresh machine to test results: installs what lfd needs, builds everything and runs the whole
# suite with CTest (GoogleTest; GL tests through EGL on Mesa llvmpipe, the viewer under Xvfb).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh       # the program (docs/install.md)
bash scripts/install-test-deps.sh  # what only the tests need
bash scripts/install-npm-clients.sh  # lfd serve's client tests (docs/serve.md)
LFD_BUILD_TESTS=ON bash scripts/build.sh
cd "${LFD_BUILD_DIR:-build}"
ctest --output-on-failure --timeout 900 -j "$(nproc)"
