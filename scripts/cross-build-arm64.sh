#!/usr/bin/env bash
# The arm64 build of lfd's display side on a Debian 12 amd64 machine (docs/arm.md): Debian's
# multiarch packages (crossbuild-essential-arm64 and the :arm64 development packages of the lean
# configuration), the program and its arm64 .deb (CPack), then the play, serve and interlace test
# suites run on that build under qemu-user (qemu-user-static). Slow: minutes of apt, then every
# file compiled by the cross compiler, the tests emulated.
#
# The lean configuration: LFD_RENDER_ONLY=ON (no OpenCV, no Ceres: no calibration, simulation or
# validation) with LFD_WITH_PLAYBACK=ON (lfd play, lfd serve, lfd record) and the Python package off.
#
#   bash scripts/cross-build-arm64.sh             # packages, build, .deb, test suites
#   LFD_ARM64_STEPS="deps build" bash scripts/cross-build-arm64.sh
# Options: BUILD_DIR (default build-arm64), JOBS (default: all cores), LFD_ARM64_STEPS (any of
# plan deps build deb test; default all), LFD_ARM64_SUITES (the test suites built and run;
# default the interlace, play, play window (Xvfb) and serve suites; add lfd_gpu_tests for the GL interlacer's tests on
# ES and desktop GL). ccache is used when installed. Each step prints its time.
#
# `plan` adds the arm64 architecture and simulates the install: how many packages, and which of
# the host's would be upgraded (Debian keeps a Multi-Arch: same library at one version for both
# architectures, so the :arm64 packages pull the host's to the newest point release: on a
# machine behind on updates, perl, systemd, libssl, libpng, zlib...). `deps` refuses to upgrade
# the host's packages unless LFD_ARM64_UPGRADE_HOST=1 (a shared build machine whose other builds
# track system headers would all rebuild).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build-arm64}
JOBS=${JOBS:-$(nproc)}
STEPS=${LFD_ARM64_STEPS:-plan deps build deb test}
read -r -a SUITES <<<"${LFD_ARM64_SUITES:-lfd_interlace_tests lfd_play_tests lfd_play_window_tests lfd_serve_tests}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# The :arm64 development packages the lean build links (scripts/install-deps.sh's, less OpenCV,
# Ceres and Python), and GoogleTest for the suites.
ARM64_PACKAGES=(
  libepoxy-dev libegl-dev libglfw3-dev libimgui-dev libhidapi-dev libusb-1.0-0-dev
  libspdlog-dev libfmt-dev libpng-dev libzstd-dev zlib1g-dev libtbb-dev
  libzip-dev libwebp-dev libtinygltf-dev
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev
  libnng-dev libcbor-dev
  # Multi-Arch: same (a pkg-config file under the architecture's folder), though headers mostly
  libcpp-httplib-dev libstb-dev
  # Boost.Beast (lfd serve's HoloPlay endpoint): header-only, but its CMake package is per architecture
  libboost-dev
  libgtest-dev libgmock-dev
  # what the tests draw with under qemu: Mesa's EGL and llvmpipe, and libGLESv2, which libepoxy
  # loads for OpenGL ES contexts
  libegl-mesa0 libgl1-mesa-dri libgles2
)
# Architecture-independent headers, and the host tools: the cross compilers and qemu.
HOST_PACKAGES=(crossbuild-essential-arm64 qemu-user-static binfmt-support dpkg-dev file
  nlohmann-json3-dev libcli11-dev libglm-dev libeigen3-dev
  # the play window suite's virtual screen
  xvfb xauth)

step() { case " $STEPS " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }
timed() {  # timed LABEL COMMAND...: runs it and prints how long it took
  local label=$1 start=$SECONDS
  shift
  "$@"
  echo "cross-build-arm64: $label took $((SECONDS - start)) s"
}

arm64_names() { for p in "${ARM64_PACKAGES[@]}"; do printf '%s:arm64 ' "$p"; done; }

# The host packages the install would upgrade (not the :arm64 ones, not the new tools).
host_upgrades() {
  # shellcheck disable=SC2046
  apt-get -s install --no-install-recommends "${HOST_PACKAGES[@]}" $(arm64_names) 2>/dev/null |
    awk '/^Inst / && $3 ~ /^\[/ && $2 !~ /:arm64$/ {print $2}'
}

plan() {
  dpkg --print-foreign-architectures | grep -qx arm64 || $SUDO dpkg --add-architecture arm64
  $SUDO apt-get update -qq
  local sim
  # shellcheck disable=SC2046
  sim=$(apt-get -s install --no-install-recommends "${HOST_PACKAGES[@]}" $(arm64_names))
  echo "cross-build-arm64: plan: $(grep -c '^Inst' <<<"$sim") packages to install," \
    "$(grep -c '^Remv' <<<"$sim") to remove, $(host_upgrades | wc -l) of the host's upgraded:" \
    "$(host_upgrades | tr '\n' ' ')"
}

install_deps() {
  bash scripts/install-deps.sh
  dpkg --print-foreign-architectures | grep -qx arm64 || $SUDO dpkg --add-architecture arm64
  $SUDO apt-get update -qq
  if [ -n "$(host_upgrades)" ] && [ "${LFD_ARM64_UPGRADE_HOST:-0}" != 1 ]; then
    echo "cross-build-arm64: the :arm64 packages would upgrade $(host_upgrades | wc -l) of this machine's" \
      "packages (plan lists them); run again with LFD_ARM64_UPGRADE_HOST=1 to allow it" >&2
    exit 1
  fi
  local arm64=()
  for p in "${ARM64_PACKAGES[@]}"; do arm64+=("$p:arm64"); done
  # --no-remove: a package that would replace the host's version (not co-installable) stops
  # here, rather than taking the host's build away.
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends --no-remove \
    "${HOST_PACKAGES[@]}" "${arm64[@]}" >/dev/null
}

configure_and_build() {
  local launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr "${launcher[@]}" \
    -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/toolchain-arm64.cmake" \
    -DLFD_RENDER_ONLY=ON -DLFD_WITH_PLAYBACK=ON -DLFD_BUILD_TESTS=ON \
    -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON -DCMAKE_SKIP_INSTALL_ALL_DEPENDENCY=ON >/dev/null
  # What the .deb holds (lfd_packaged: the program, its libraries, libbridge_inproc) and the suites.
  cmake --build "$BUILD_DIR" -j "$JOBS" --target lfd lfd_packaged "${SUITES[@]}"
  file "$BUILD_DIR/apps/lfd"
}

make_deb() {
  rm -f "$BUILD_DIR"/lfd_*.deb "$BUILD_DIR"/lfd-dev_*.deb
  # dpkg-shlibdeps reads the arm64 libraries with the cross binutils.
  (cd "$BUILD_DIR" && eval "$(dpkg-architecture -a arm64 -s 2>/dev/null)" && cpack -G DEB)
  for deb in "$BUILD_DIR"/lfd_*.deb; do
    echo "package: $deb: $(dpkg-deb -f "$deb" Architecture) ($(du -h "$deb" | cut -f1))"
  done
}

run_suites() {
  # The suites of the display side, each binary under qemu-user; GL on arm64 llvmpipe.
  # -L /: libc6:arm64's loader, not the cross toolchain's (cmake/toolchain-arm64.cmake says why).
  local qemu=(qemu-aarch64-static -L /)
  export EGL_PLATFORM=surfaceless LFD_GL_CHECKS=strict
  "${qemu[@]}" "$BUILD_DIR/apps/lfd" --version
  # A suite that starts `lfd` or a helper program gets a script that starts it through qemu
  # (tests/CMakeLists.txt, lfd_test_program): no binfmt_misc is needed.
  local failed=0
  for suite in "${SUITES[@]}"; do
    local filter=() screen=() binary="$BUILD_DIR/tests/$suite"
    # The GL suite: the interlacer on OpenGL ES 3.1 and desktop GL (the renderers' tests are long).
    if [ "$suite" = lfd_gpu_tests ]; then filter=(--gtest_filter='*Interlace*:GlslEsSource.*'); fi
    # `lfd play` in real windows: on a virtual screen of the test display's size.
    if [ "$suite" = lfd_play_window_tests ]; then
      binary="$BUILD_DIR/tests/play/window/$suite"
      screen=(xvfb-run -a -s "-screen 0 1536x2048x24")
    fi
    timed "$suite under qemu" "${screen[@]}" "${qemu[@]}" "$binary" --gtest_brief=1 "${filter[@]}" || failed=1
  done
  return $failed
}

step plan && timed "plan" plan
step deps && timed "deps" install_deps
step build && timed "build" configure_and_build
step deb && timed "deb" make_deb
step test && timed "test suites" run_suites
echo "cross-build-arm64: done ($STEPS)"
