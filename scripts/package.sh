#!/usr/bin/env bash
# Builds lfd in Release and makes the Debian packages:
#   build-pkg/lfd_<version>_<arch>.deb       the program and its data (Depends from dpkg-shlibdeps)
#   build-pkg/lfd-dev_<version>_<arch>.deb   the libraries, headers and CMake package
# Install with: sudo apt-get install ./build-pkg/lfd_*.deb
# Options: BUILD_DIR (default build-pkg), JOBS (default: all cores).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh

BUILD_DIR=${BUILD_DIR:-build-pkg}
JOBS=${JOBS:-$(nproc)}
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

# Installed under /usr; `install` does not build the whole tree first (tests and benchmarks
# are not packaged): lfd_packaged builds exactly what the packages hold.
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
  -DLFD_BUILD_TESTS=OFF -DLFD_RENDER_ONLY=OFF -DCMAKE_SKIP_INSTALL_ALL_DEPENDENCY=ON "${launcher[@]}"
cmake --build "$BUILD_DIR" --target lfd_packaged -j "$JOBS"

rm -f "$BUILD_DIR"/lfd_*.deb "$BUILD_DIR"/lfd-dev_*.deb
(cd "$BUILD_DIR" && cpack -G DEB)
for deb in "$BUILD_DIR"/lfd_*.deb "$BUILD_DIR"/lfd-dev_*.deb; do
  echo "package: $deb ($(du -h "$deb" | cut -f1))"
done
"$BUILD_DIR"/apps/lfd --version
