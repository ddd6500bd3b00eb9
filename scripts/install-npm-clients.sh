#!/usr/bin/env bash
# Installs the Looking Glass clients lfd serve is tested with (docs/serve.md) at the versions
# pinned in tests/serve/clients/package-lock.json: holoplay-core, @lookingglass/bridge,
# @lookingglass/webxr; and what the console's browser tests drive Debian's Chromium with
# (docs/console.md): puppeteer-core and axe-core. Idempotent (nothing to do when node_modules matches the lock) and
# offline-tolerant: without node/npm or the registry it says so and exits 0, and the client
# tests skip.
set -uo pipefail
cd "$(dirname "$0")/../tests/serve/clients"
if ! command -v npm >/dev/null; then
  echo "install-npm-clients: npm not found; the lfd serve client tests will be skipped"
  exit 0
fi
# Already there: every pinned client installed at its pinned version.
if node -e '
  const deps = require("./package.json").dependencies;
  for (const [name, version] of Object.entries(deps))
    if (require("./node_modules/" + name + "/package.json").version !== version) process.exit(1);' 2>/dev/null; then
  exit 0
fi
# --ignore-scripts: the clients' optional native add-ons (bufferutil, utf-8-validate) are not built.
if ! npm ci --ignore-scripts --no-audit --no-fund --loglevel=error; then
  echo "install-npm-clients: npm ci failed (offline?); the lfd serve client tests will be skipped"
fi
exit 0
