#!/usr/bin/env bash
# The Debian 12 packages only the tests need, on top of scripts/install-deps.sh's (scripts/test.sh
# runs both; the npm clients are scripts/install-npm-clients.sh). The demo and the .deb do without
# them (docs/install.md "A lean install").
# Idempotent: quiet and fast when everything is already installed (scripts/apt-install.sh).
set -euo pipefail

PACKAGES=(
  # GoogleTest and the benchmark library (LFD_BUILD_TESTS)
  libgtest-dev libgmock-dev libbenchmark-dev
  # the window tests: a virtual X screen (xvfb-run) and Xlib to read it
  xvfb xauth libx11-dev
  # GL call recorder: the test that no frame of lfd view waits for the GPU (docs/gpu.md)
  apitrace
  # the reference GLSL front end over every shader variant (scripts/check-shader-variants.sh) and
  # the second GL driver, zink over lavapipe (docs/gpu.md "Drivers and limits")
  glslang-tools mesa-vulkan-drivers
  # the Python package's tests (pytest) with torch tensors as input
  python3-pytest python3-torch
  # lfd serve's @lookingglass/webxr page test
  chromium
  # libFuzzer targets and their corpora (scripts/fuzz.sh)
  clang
)
# lfd serve's client tests run the npm clients in Node.js (scripts/install-npm-clients.sh); a
# machine that already has node (NodeSource's, say) keeps it.
command -v node >/dev/null || PACKAGES+=(nodejs npm)

LFD_APT_LABEL=install-test-deps bash "$(dirname "$0")/apt-install.sh" "${PACKAGES[@]}"
