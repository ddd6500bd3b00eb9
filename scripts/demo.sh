#!/usr/bin/env bash
# Fresh machine to demo: installs what lfd needs, builds it, runs `lfd demo` on the embedded
# defaults and prints where the report is.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh lfd
./build/apps/lfd demo --out "${1:-out/demo}"
