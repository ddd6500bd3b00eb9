#!/usr/bin/env bash
# The GPU table of docs/performance.md in one command, on a machine with an NVIDIA GPU and the
# renderer-only bundle (LFD_BUNDLE_TESTS=1 scripts/bundle-renderer.sh) and the EGL loader
# packages (.gl/*.deb, fetched beforehand as docs/performance.md says) carried along:
#
#   bash scripts/gpu-table.sh OUT_DIR [STEP...]
#
# Unpacks the EGL loader when the machine has none, points libglvnd at the NVIDIA vendor file,
# then runs the steps (all by default), each under its own time limit, writing OUT_DIR/STEP.md
# (the table as printed), OUT_DIR/STEP.json where the step writes JSON, and a line per step in
# OUT_DIR/steps.txt (exit code, seconds); a failing step does not stop the others:
#   tests       the bundled GL test programs (the GL renderers, shaders, sort and interlacer
#               against their CPU twins), when the bundle has them
#   render-gl   per view vs G2LF at the paper's sizes: 100k/1M/3M Gaussians, 45 views of 512x512
#   gpu-frame   the frame with timers waited for vs read late, swizzle variants, plane formats
#   gpu-sort    the sort rows: all N against the visible Gaussians, float against normalised keys
#   voxels-gl   per view vs V2LF on the level-7 tabletop (15,688 voxels), drawn by the hardware
#               raster and by the compute tile rasterizer, both in one run
#   voxels-gl-1m  the same on the generated level-10 tabletop (>= 1M voxels), 45 views of 512x512
#   direct-gl   the direct panel pass against swizzle + interlace on the three displays at 16/64/256
#               planes (bilinear planes filtered by the texture unit, the GL default): the compute
#               passes the offscreen paths use, and in the same run the fragment stages of the
#               interlacer and the direct pass (what a window draws with), and the compute direct
#               pass walking the planes plane-major (--plane-major)
#   direct-gl-shader  the same at 1M Gaussians with the planes filtered by hand (four texelFetch)
#   direct-v2lf-gl  the direct pass against swizzle + interlace on V2LF planes: the tabletop and
#               the level-10 one, the three displays, 16/64/256 planes
#   gpu-probe   compute FMA rate and bandwidth against the raster fill rate, and --raster auto's
#               probe and choice (docs/gpu.md "Choosing the path: auto")
#   raster-gl   per view and G2LF (N_chunk 64, 256, 512; P_s 1) drawn by the hardware raster and by
#               the compute tile rasterizer, both in one run: 100k and 1M Gaussians, 45 views of 512x512
#   raster-gl-910  the same with the paper's views, 45 of 512x910
#   raster-gl-large  the same at 3M and a generated 6M, 45 views of 512x512, at most 3 timed frames a row
#   raster-gl-large-910  3M and 6M with 45 views of 512x910
# Each step fits one 15-minute GPU loan (docs/performance.md "The GPU table"): name the steps to run
# them on separate loans; the raster steps run under LFD_GPU_TABLE_RASTER_LIMIT (default 420 s).
# The script's mechanics are tested without a GPU on a stub bundle (tests/scripts/gpu_table_test.sh).
# LFD_GPU_TABLE_LIMIT (seconds, default 150) bounds each step; LFD_GPU_TABLE_RUNS (default 10) is
# the timed frames per row, LFD_GPU_TABLE_SIZES (default 100000,1000000,3000000) render-gl's scenes.
# LFD_GPU_TABLE_SMOKE=zink proves the script on the CPU before a loan is spent on it: the same
# steps and options on Mesa's zink over lavapipe (EGL surfaceless, no NVIDIA parts), at toy sizes
# (1-6 thousand Gaussians, 5 views of 64 pixels, voxel levels 4 and 5, the direct steps on the Go
# at 16 planes 64 pixels high, one timed frame; 600 s a step unless LFD_GPU_TABLE_LIMIT). Its
# figures measure nothing (docs/gpu.md "What zink found"); its exit codes say every step runs.
set -uo pipefail
out=${1:?usage: scripts/gpu-table.sh OUT_DIR [STEP...]}
shift
steps=("$@")
[ ${#steps[@]} -gt 0 ] || steps=(tests render-gl gpu-frame gpu-sort voxels-gl voxels-gl-1m direct-gl direct-gl-shader direct-v2lf-gl \
  gpu-probe raster-gl raster-gl-910 raster-gl-large raster-gl-large-910)
smoke=${LFD_GPU_TABLE_SMOKE:-}
case "$smoke" in
  "") ;;
  zink) ;;
  *) echo "gpu-table: LFD_GPU_TABLE_SMOKE must be zink or unset, not '$smoke'" >&2; exit 2 ;;
esac
limit=${LFD_GPU_TABLE_LIMIT:-150}
[ -n "$smoke" ] && limit=${LFD_GPU_TABLE_LIMIT:-600}  # lavapipe compiles the voxel passes for minutes
# The sizes each step runs at: the table's, or the smoke run's toy ones (same options otherwise).
if [ -z "$smoke" ]; then
  runs=${LFD_GPU_TABLE_RUNS:-10}
  sizes=${LFD_GPU_TABLE_SIZES:-100000,1000000,3000000}
  million=1000000 direct_sizes=100000,1000000 raster_sizes=100000,1000000 large_sizes=3000000,6000000
  views=45 size=512 size_910=512x910 voxel_level=7 voxel_level_1m=10
  direct_extra=() direct_chunks=16,64,256 shader_chunks=16,64
else
  runs=${LFD_GPU_TABLE_RUNS:-1}
  sizes=${LFD_GPU_TABLE_SIZES:-1000,2000}
  million=2000 direct_sizes=1000,2000 raster_sizes=1000,2000 large_sizes=3000,6000
  views=5 size=64 size_910=64x114 voxel_level=4 voxel_level_1m=5
  direct_extra=(--calibration data/displays/go.visual.json --view-height 64)  # one panel, small planes
  direct_chunks=16 shader_chunks=16  # the direct pass walks the whole panel per plane: slow on a CPU
fi
cd "$(dirname "$0")/.."
mkdir -p "$out"
bundle=${LFD_BUNDLE_DIR:-bundle/lfd-renderer}  # another bundle folder (tests/scripts: a stub)
run=$bundle/run.sh
[ -x "$run" ] || { echo "gpu-table: $run missing: run scripts/bundle-renderer.sh first" >&2; exit 2; }
if [ -n "$smoke" ]; then
  # zink over lavapipe on Mesa's headless EGL (mesa-vulkan-drivers; scripts/install-test-deps.sh).
  export EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 MESA_LOADER_DRIVER_OVERRIDE=zink
  export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
# grep reads all of ldconfig's output (no -q): under pipefail, grep -q leaving early would let
# ldconfig die of SIGPIPE and the test fail at random.
elif ! ldconfig -p | grep 'libEGL.so.1 ' > /dev/null; then
  ls .gl/*.deb >/dev/null 2>&1 || { echo "gpu-table: no libEGL and no .gl/*.deb (docs/performance.md)" >&2; exit 2; }
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
fi
if [ -z "$smoke" ]; then
  vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f "$vendor" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; fi
  unset EGL_PLATFORM  # the EGL device platform (the GPU), not Mesa's surfaceless one
fi
"$run" version | tee "$out/version.txt"
if [ -z "$smoke" ]; then
  nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv | tee "$out/gpu.txt" || true
else
  echo "smoke run on $smoke (no GPU; the figures measure nothing)" | tee "$out/gpu.txt"
fi

# One step: its command under the time limit (step_limit when set, else LFD_GPU_TABLE_LIMIT), its
# output in OUT/STEP.md, a line in steps.txt.
step() {
  local name=$1; shift
  local start=$SECONDS
  echo "== $name: $*" | tee -a "$out/steps.txt"
  timeout --kill-after=10 "${step_limit:-$limit}" "$@" > "$out/$name.md" 2>&1
  local rc=$?
  tail -n 40 "$out/$name.md"
  echo "== $name: exit $rc after $((SECONDS - start)) s" | tee -a "$out/steps.txt"
}

# The GL test programs have their fixtures' path compiled in (tests/test_data.hpp): link the
# checkout they were built in to this one when it is elsewhere.
bundled_tests() {
  local source_dir
  source_dir=$(cat "$bundle/tests/source_dir.txt")
  if [ ! -e "$source_dir" ]; then mkdir -p "$(dirname "$source_dir")" && ln -s "$PWD" "$source_dir"; fi
  local rc=0 t
  for t in "$bundle"/tests/lfd_*_tests; do
    # The CLI tests run the build tree's lfd, which does not travel.
    LD_LIBRARY_PATH="$bundle/lib" "$t" --gtest_filter='-*Cli*:*CLI*' --gtest_brief=1 || rc=1
  done
  return $rc
}
export -f bundled_tests
export bundle

# The Gaussians' two raster paths (docs/gpu.md "Two ways to draw Gaussians"), both in one run:
# per view and G2LF N_chunk 64, 256 and 512 at P_s 1 (Table 1's N=512 bilinear row with them), at
# 45 views of SIZE (512 or the paper's 512x910). raster_step NAME SIZE SCENES RUNS.
raster_step() {
  local step_limit=${LFD_GPU_TABLE_RASTER_LIMIT:-420}
  step "$1" "$run" bench render --backend gl --raster hardware,compute --generated "$3" --views "$views" --size "$2" \
    --configs table1,chunks --chunks 64,256,512 --plane-scale 1 --runs "$4" --warmup 1 --png-runs 0 \
    --json "$out/$1.json"
}
raster_steps() {
  local large_runs=$(( runs < 3 ? runs : 3 ))
  case "$1" in
    raster-gl) raster_step raster-gl "$size" "$raster_sizes" "$runs" ;;
    raster-gl-910) raster_step raster-gl-910 "$size_910" "$raster_sizes" "$runs" ;;
    raster-gl-large) raster_step raster-gl-large "$size" "$large_sizes" "$large_runs" ;;
    raster-gl-large-910) raster_step raster-gl-large-910 "$size_910" "$large_sizes" "$large_runs" ;;
    *) return 1 ;;
  esac
}

for s in "${steps[@]}"; do
  case "$s" in
    tests)
      if [ -d "$bundle/tests" ]; then step tests bash -c bundled_tests; else echo "== tests: none in the bundle"; fi ;;
    render-gl)
      step render-gl "$run" bench render --backend gl --generated "$sizes" --views "$views" --size "$size" \
        --runs "$runs" --png-runs 0 --json "$out/render-gl.json" ;;
    gpu-frame)
      step gpu-frame "$run" bench gpu-frame --generated "$million" --views "$views" --size "$size" --runs "$runs" --warmup 2 \
        --batch 8 --swizzle-views 1,4,8 --json "$out/gpu-frame.json" ;;
    gpu-sort)
      step gpu-sort "$run" bench gpu-frame --generated "$million" --views "$views" --size "$size" --runs "$runs" --warmup 2 \
        --sort-only --zoom 2 --json "$out/gpu-sort.json" ;;
    voxels-gl)
      step voxels-gl "$run" bench voxels --backend gl --raster hardware,compute --level "$voxel_level" --views "$views" --size "$size" --runs "$runs" \
        --json "$out/voxels-gl.json" ;;
    voxels-gl-1m)
      step voxels-gl-1m "$run" bench voxels --backend gl --raster hardware,compute --level "$voxel_level_1m" --views "$views" --size "$size" --runs "$runs" \
        --json "$out/voxels-gl-1m.json" ;;
    direct-gl)
      step direct-gl "$run" bench direct --backend gl --generated "$direct_sizes" --chunks "$direct_chunks" --runs "$runs" \
        --reference-views 0 --plane-major ${direct_extra[@]+"${direct_extra[@]}"} --json "$out/direct-gl.json" ;;
    direct-gl-shader)
      step direct-gl-shader "$run" bench direct --backend gl --generated "$million" --chunks "$shader_chunks" --runs "$runs" \
        --reference-views 0 --direct-sampler shader ${direct_extra[@]+"${direct_extra[@]}"} --json "$out/direct-gl-shader.json" ;;
    direct-v2lf-gl)
      step direct-v2lf-gl "$run" bench direct --backend gl --method v2lf --voxel-level "$voxel_level,$voxel_level_1m" --chunks "$direct_chunks" \
        --runs "$runs" --reference-views 0 ${direct_extra[@]+"${direct_extra[@]}"} --json "$out/direct-v2lf-gl.json" ;;
    gpu-probe)
      step gpu-probe "$run" bench gpu-probe --runs "$runs" --json "$out/gpu-probe.json" ;;
    raster-gl|raster-gl-910|raster-gl-large|raster-gl-large-910) raster_steps "$s" ;;
    *) echo "gpu-table: unknown step '$s' (tests, render-gl, gpu-frame, gpu-sort, voxels-gl, voxels-gl-1m," \
         "direct-gl, direct-gl-shader, direct-v2lf-gl, gpu-probe, raster-gl, raster-gl-910, raster-gl-large," \
         "raster-gl-large-910)" >&2; exit 2 ;;
  esac
done
cat "$out/steps.txt"
