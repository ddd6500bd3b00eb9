#!/usr/bin/env bash
# One console case (docs/console.md) in headless Chromium: console_test.sh LFD_EXE CALIBRATION CASE.
# Exit 77 (CTest: skipped) without node, Chromium or the pinned puppeteer-core / axe-core
# (scripts/install-npm-clients.sh).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v node >/dev/null || [ ! -x /usr/bin/chromium ] || [ ! -d "$here/node_modules/puppeteer-core" ] ||
   [ ! -d "$here/node_modules/axe-core" ]; then
  echo "SKIP: node, /usr/bin/chromium or the pinned puppeteer-core / axe-core are not installed"
  exit 77
fi
cd "$here"
LFD_EXE=$1 CALIBRATION=$2 exec node console_test.js "$3"
