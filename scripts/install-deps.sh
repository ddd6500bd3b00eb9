#!/usr/bin/env bash
# Installs every Debian 12 package lfd needs to build, test and run.
# Idempotent: quiet and fast when everything is already installed.
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config git clang
  # the shader embedding (cmake/embed_shader.py: #includes and #line per file)
  python3
  # math, vision, optimisation
  libeigen3-dev libopencv-dev libopencv-contrib-dev libceres-dev
  # device access
  libhidapi-dev libusb-1.0-0-dev
  # graphics: GL loading, headless EGL on Mesa, windows, UI; Xvfb and Xlib for the window tests
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libglfw3-dev libglm-dev libimgui-dev
  xvfb xauth libx11-dev
  # GL call recorder: the test that no frame of lfd view waits for the GPU (docs/gpu.md)
  apitrace
  # formats and utilities
  nlohmann-json3-dev libcli11-dev libspdlog-dev libfmt-dev libstb-dev libpng-dev libzstd-dev zlib1g-dev
  libtbb-dev
  # tests and benchmarks (numpy: the SVRaster converter's test, scripts/svraster_to_voxels.py)
  libgtest-dev libgmock-dev libbenchmark-dev python3-numpy
  # the reference GLSL front end over every shader variant (scripts/check-shader-variants.sh) and
  # the second GL driver, zink over lavapipe (docs/gpu.md "Drivers and limits")
  glslang-tools mesa-vulkan-drivers
  # the Python package lfd (docs/python.md): pybind11, its tests (pytest), torch tensors as input
  python3-dev python3-pybind11 pybind11-dev python3-pytest python3-torch
  # plots in validation reports
  gnuplot-nox
  # Debian packages (scripts/package.sh: cpack computes the Depends with dpkg-shlibdeps)
  dpkg-dev file
  # scene formats: SOG (ZIP archive of WebP images), glTF/GLB with KHR_gaussian_splatting
  libzip-dev libwebp-dev libtinygltf-dev
  # lfd play (docs/play.md): FFmpeg's libraries for quilt videos, libwebp for WebP quilts
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev
  # lfd serve (docs/serve.md): NNG (HoloPlay WebSocket, events), libcbor, cpp-httplib (Bridge
  # HTTP API); Chromium for the @lookingglass/webxr page test
  libnng-dev libcbor-dev libcpp-httplib-dev chromium
)
# lfd serve's client tests run the npm clients in Node.js (scripts/install-npm-clients.sh); a
# machine that already has node (NodeSource's, say) keeps it.
command -v node >/dev/null || PACKAGES+=(nodejs npm)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${#missing[@]} package(s): ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
