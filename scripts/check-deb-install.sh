#!/usr/bin/env bash
# Installs lfd's runtime package on a clean Debian 12 (bookworm) made with debootstrap and checks
# it there (docs/python.md "The .deb on a clean machine"):
#   - apt-get installs the .deb, so its Depends (from dpkg-shlibdeps, plus python3 and
#     python3-numpy) are resolved from Debian alone;
#   - `python3 -c "import lfd"` prints lfd.__version__ and where the module is;
#   - the module renders a quilt from numpy arrays on the CPU (a 2-Gaussian scene, 4 views);
#   - `lfd --version` runs.
# Usage: scripts/check-deb-install.sh [lfd_VERSION_ARCH.deb]
#   Without a package it builds one with scripts/package.sh (BUILD_DIR, default build-pkg).
#   MIRROR (default http://deb.debian.org/debian), SECURITY_MIRROR, KEEP_ROOT=1 (keep the chroot
#   and say where it is).
# Needs root (debootstrap, chroot), debootstrap (installed here when missing) and the network
# (the Debian mirror). Not a CTest test: it downloads ~200 MB and takes minutes. Without the
# mirror it says so and exits 77 (skipped).
set -euo pipefail
cd "$(dirname "$0")/.."

MIRROR=${MIRROR:-http://deb.debian.org/debian}
SECURITY_MIRROR=${SECURITY_MIRROR:-http://deb.debian.org/debian-security}
SUITE=bookworm

fail() { echo "check-deb-install: $*" >&2; exit 2; }
[[ $(id -u) -eq 0 ]] || fail "needs root (debootstrap and chroot)"

deb=${1:-}
if [[ -z $deb ]]; then
  BUILD_DIR=${BUILD_DIR:-build-pkg}
  BUILD_DIR=$BUILD_DIR bash scripts/package.sh
  deb=$(ls "$BUILD_DIR"/lfd_*.deb | head -n 1)
fi
[[ -f $deb ]] || fail "$deb: no such package"
dpkg-deb --field "$deb" Package | grep -qx lfd || fail "$deb: not the lfd runtime package"

# Offline: the mirror's release file cannot be fetched; skip, as the npm client tests do.
if ! python3 -c "import sys, urllib.request; urllib.request.urlopen(sys.argv[1], timeout=15)" \
    "$MIRROR/dists/$SUITE/Release" >/dev/null 2>&1; then
  echo "check-deb-install: $MIRROR is not reachable: skipped"
  exit 77
fi
command -v debootstrap >/dev/null || apt-get install -y -q --no-install-recommends debootstrap >/dev/null

root=$(mktemp -d /var/tmp/lfd-clean-root.XXXXXX)
chmod 755 "$root"  # it is the chroot's /: apt's _apt user and package scripts must enter it
cleanup() {
  mountpoint -q "$root/proc" && umount "$root/proc"
  if [[ ${KEEP_ROOT:-0} == 1 ]]; then echo "check-deb-install: the root is kept at $root"; else rm -rf "$root"; fi
}
trap cleanup EXIT

echo "== debootstrap --variant=minbase $SUITE (a clean Debian 12) into $root"
debootstrap --variant=minbase "$SUITE" "$root" "$MIRROR" >"$root.debootstrap.log" 2>&1 ||
  { tail -n 20 "$root.debootstrap.log"; fail "debootstrap failed (log: $root.debootstrap.log)"; }
rm -f "$root.debootstrap.log"
echo "   packages after debootstrap: $(chroot "$root" dpkg-query -W -f '.\n' | wc -l)"
cat >"$root/etc/apt/sources.list" <<EOF
deb $MIRROR $SUITE main
deb $MIRROR $SUITE-updates main
deb $SECURITY_MIRROR $SUITE-security main
EOF
mount -t proc proc "$root/proc"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  DEBIAN_FRONTEND=noninteractive "$@"; }

cp "$deb" "$root/tmp/"
package=/tmp/$(basename "$deb")
echo "== apt-get install $package (its Depends from Debian)"
in_root apt-get update -q >/dev/null
in_root apt-get install -y -q --no-install-recommends "$package" >"$root/tmp/apt.log" 2>&1 ||
  { tail -n 30 "$root/tmp/apt.log"; fail "apt-get install failed"; }
grep -E '^(Setting up|Unpacking) lfd ' "$root/tmp/apt.log" || true
echo "   packages in the root: $(in_root dpkg-query -W -f '.\n' | wc -l)"

echo "== python3 -c 'import lfd' (in the clean root)"
in_root python3 - <<'EOF'
import numpy as np
import lfd
print("import lfd:", lfd.__version__, "from", lfd.__file__)
g = lfd.Gaussians(means=np.array([[0.0, 0.0, 0.0], [0.3, 0.1, -0.2]], np.float32),
                  log_scales=np.full((2, 3), -2.5, np.float32),
                  rotations=np.array([[1.0, 0.0, 0.0, 0.0]] * 2, np.float32),
                  opacity_logits=np.full(2, 2.0, np.float32),
                  sh=np.full((2, 1, 3), 0.8, np.float32))
q = lfd.render_quilt(g, views=4, cols=2, rows=2, size=(64, 48))
image = q.image
assert image.shape == (96, 128, 3) and image.dtype == np.uint8, image.shape
assert image.max() > 0, "an empty quilt"
print("render_quilt on the CPU: %dx%d quilt, %d x %d views, max %d" % (image.shape[1], image.shape[0], q.cols, q.rows, image.max()))
EOF
echo "== lfd --version (in the clean root)"
in_root lfd --version
echo "check-deb-install: $deb installs and runs on a clean Debian 12"
