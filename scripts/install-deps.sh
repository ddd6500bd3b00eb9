#!/usr/bin/env bash
# The Debian 12 packages lfd needs to build and run: the program, its libraries and its Python
# package (the demo's set-up, scripts/demo.sh, and the .deb's build, scripts/package.sh). What
# only the tests need is scripts/install-test-deps.sh (scripts/test.sh runs both).
# Idempotent: quiet and fast when everything is already installed (scripts/apt-install.sh).
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # the shader embedding (cmake/embed_shader.py: #includes and #line per file)
  python3
  # math, vision, optimisation
  libeigen3-dev libopencv-dev libopencv-contrib-dev libceres-dev
  # device access
  libhidapi-dev libusb-1.0-0-dev
  # graphics: GL loading (desktop OpenGL 4.5 and OpenGL ES 3.1, docs/arm.md), headless EGL on
  # Mesa, windows, UI
  libepoxy-dev libegl-dev libegl-mesa0 libgles2 libgl1-mesa-dri libglfw3-dev libglm-dev libimgui-dev
  # formats and utilities
  nlohmann-json3-dev libcli11-dev libspdlog-dev libfmt-dev libstb-dev libpng-dev libzstd-dev zlib1g-dev
  libtbb-dev
  # the Python package lfd (docs/python.md): pybind11, numpy arrays in and out (numpy also runs
  # scripts/svraster_to_voxels.py)
  python3-dev python3-pybind11 pybind11-dev python3-numpy
  # plots in validation reports
  gnuplot-nox
  # Debian packages (scripts/package.sh: cpack computes the Depends with dpkg-shlibdeps)
  dpkg-dev file
  # scene formats: SOG (ZIP archive of WebP images), glTF/GLB with KHR_gaussian_splatting
  libzip-dev libwebp-dev libtinygltf-dev
  # lfd play (docs/play.md): FFmpeg's libraries for quilt videos, libwebp for WebP quilts
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev
  # lfd serve (docs/serve.md): Boost.Beast (HoloPlay WebSocket), NNG (events), libcbor,
  # cpp-httplib (Bridge HTTP API)
  libboost-dev libnng-dev libcbor-dev libcpp-httplib-dev
)

LFD_APT_LABEL=install-deps bash "$(dirname "$0")/apt-install.sh" "${PACKAGES[@]}"
