#!/usr/bin/env bash
# Regenerates the scene-format fixtures of this folder with the reference tools (run ONCE; the
# outputs are committed, so the tests need neither Node nor npm). Needs Node 20+, npm and a
# built lfd (build/apps/lfd). See README.md.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
lfd="${LFD:-$here/../../../../build/apps/lfd}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
npm init -y >/dev/null
npm install --no-audit --no-fund @playcanvas/splat-transform@3.7.0 \
  @mkkellogg/gaussian-splats-3d@0.4.7 three@0.187.0 >/dev/null 2>&1
st="npx --no-install splat-transform -q -w"

"$lfd" scene generate --kind tabletop --count 400 --seed 7 --sh-degree 2 --out "$here/tabletop.ply"
cd "$here"
# SOG v2 (ZIP of WebP images; SH palette by k-means on the CPU) and its unpacked layout.
(cd "$work" && $st -g cpu "$here/tabletop.ply" "$here/tabletop.sog")
rm -rf tabletop-sog && mkdir tabletop-sog && (cd tabletop-sog && unzip -q ../tabletop.sog)
# glTF binary with KHR_gaussian_splatting.
(cd "$work" && $st "$here/tabletop.ply" "$here/tabletop.glb")
# .ksplat at compression levels 0, 1, 2 (alpha threshold 1, centre 0,0,0, block 5, bucket 256,
# SH degree 2), written by GaussianSplats3D.
for level in 0 1 2; do
  (cd "$work" && cp "$here/create-ksplat.mjs" . && node create-ksplat.mjs "$here/tabletop.ply" \
    "$here/tabletop-c$level.ksplat" $level 1 0,0,0 5.0 256 2 2>/dev/null)
done
# The truth each test compares with: the reference tool's own decode back to PLY.
for f in tabletop.sog tabletop-c0.ksplat tabletop-c1.ksplat tabletop-c2.ksplat; do
  (cd "$work" && $st "$here/$f" "$here/$f.decoded.ply")
done
ls -l "$here"
