#!/usr/bin/env bash
# The GPU table of docs/performance.md in one command, on a machine with an NVIDIA GPU and the
# renderer-only bundle (scripts/bundle-renderer.sh) and the EGL loader packages (.gl/*.deb,
# fetched beforehand as docs/performance.md says) carried along:
#
#   bash scripts/gpu-table.sh OUT_DIR
#
# Unpacks the EGL loader when the machine has none, points libglvnd at the NVIDIA EGL vendor
# file, and writes, each as Markdown (.md) and JSON: render-gl (per view vs G2LF at the paper's
# sizes: 100k/1M/3M Gaussians, 45 views of 512x512), gpu-frame (the frame with timers waited for
# vs read late, swizzle variants: 1M Gaussians, 45 views of 512x512) and voxels-gl (per view vs
# V2LF). About 5 minutes on an H100 by estimate: no GPU was lent to the session that wrote it, so
# it has not been run there.
set -euo pipefail
out=${1:?usage: scripts/gpu-table.sh OUT_DIR}
cd "$(dirname "$0")/.."
mkdir -p "$out"
run=bundle/lfd-renderer/run.sh
[ -x "$run" ] || { echo "gpu-table: $run missing: run scripts/bundle-renderer.sh first" >&2; exit 2; }
if ! ldconfig -p | grep -q 'libEGL.so.1 '; then
  ls .gl/*.deb >/dev/null 2>&1 || { echo "gpu-table: no libEGL and no .gl/*.deb (docs/performance.md)" >&2; exit 2; }
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
fi
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f "$vendor" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; fi
"$run" version | tee "$out/version.txt"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv | tee "$out/gpu.txt" || true
"$run" bench render --backend gl --generated 100000,1000000,3000000 --views 45 --size 512 --runs 10 \
  --png-runs 0 --json "$out/render-gl.json" | tee "$out/render-gl.md"
"$run" bench gpu-frame --generated 1000000 --views 45 --size 512 --runs 10 --warmup 2 --batch 8 \
  --swizzle-views 1,4,8 --json "$out/gpu-frame.json" | tee "$out/gpu-frame.md"
# Issue #23's sort rows: all N against the visible (binned) Gaussians, float against normalised keys.
"$run" bench gpu-frame --generated 1000000 --views 45 --size 512 --runs 10 --warmup 2 --sort-only --zoom 2 \
  --json "$out/gpu-sort.json" | tee "$out/gpu-sort.md"
"$run" bench voxels --backend gl --level 7 --views 45 --size 512 --runs 5 --json "$out/voxels-gl.json" \
  | tee "$out/voxels-gl.md"
