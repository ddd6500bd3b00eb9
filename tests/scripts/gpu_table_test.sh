#!/usr/bin/env bash
# scripts/gpu-table.sh's mechanics without a GPU (docs/performance.md "The GPU table"): a stub
# bundle whose lfd prints its arguments, writes the --json file it is given, fails on one step and
# outlasts the limit on another. Every step must still run, each under the limit, with its exit
# code in steps.txt; the options reach the commands; an unknown step is one line and exit 2.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bundle=$work/bundle
mkdir -p "$bundle/tests" "$bundle/lib"
cat > "$bundle/run.sh" <<'EOF'
#!/usr/bin/env bash
echo "stub lfd $*"
echo "stub driver ${MESA_LOADER_DRIVER_OVERRIDE:-default}"
previous=""
for a in "$@"; do
  [ "$previous" = --json ] && echo '{}' > "$a"
  previous=$a
done
case "$*" in
  *--sort-only*) sleep 30 ;;     # outlasts the limit
  "bench voxels --backend gl --raster hardware,compute --level 7 "*) exit 3 ;;     # fails
esac
exit 0
EOF
cat > "$bundle/tests/lfd_stub_tests" <<'EOF'
#!/usr/bin/env bash
echo "stub tests $*"
echo "[  PASSED  ] 1 test."
EOF
chmod +x "$bundle/run.sh" "$bundle/tests/lfd_stub_tests"
echo "$root" > "$bundle/tests/source_dir.txt"

fail() { echo "gpu_table_test: $*" >&2; exit 1; }
out=$work/out
LFD_BUNDLE_DIR=$bundle LFD_GPU_TABLE_LIMIT=2 LFD_GPU_TABLE_RUNS=3 bash "$root/scripts/gpu-table.sh" "$out" > "$work/log" 2>&1 \
  || fail "the table exited $? (a failing step must not stop it): $(tail -3 "$work/log")"
for expected in "tests: exit 0" "render-gl: exit 0" "gpu-frame: exit 0" "gpu-sort: exit 124" "voxels-gl: exit 3" \
                "voxels-gl-1m: exit 0" "direct-gl: exit 0" "direct-gl-shader: exit 0" "direct-v2lf-gl: exit 0" \
                "gpu-probe: exit 0" "raster-gl: exit 0" "raster-gl-910: exit 0" "raster-gl-large: exit 0" \
                "raster-gl-large-910: exit 0"; do
  grep -q "== $expected after" "$out/steps.txt" || fail "steps.txt lacks '$expected': $(cat "$out/steps.txt")"
done
grep -q -- "--gtest_filter=-\*Cli\*" "$out/tests.md" || fail "the bundled tests ran without the CLI filter"
grep -q -- "bench render --backend gl --generated 100000,1000000,3000000 .*--runs 3" "$out/render-gl.md" \
  || fail "render-gl did not get the sizes and LFD_GPU_TABLE_RUNS: $(head -1 "$out/render-gl.md")"
grep -q -- "--direct-sampler shader" "$out/direct-gl-shader.md" || fail "direct-gl-shader did not filter by hand"
grep -q -- "--plane-major" "$out/direct-gl.md" || fail "direct-gl did not time the plane-major walk"
grep -q -- "bench voxels --backend gl --raster hardware,compute --level 10 --views 45 --size 512 --runs 3" "$out/voxels-gl-1m.md" \
  || fail "voxels-gl-1m did not render the level-10 (>= 1M voxel) tabletop: $(head -1 "$out/voxels-gl-1m.md")"
grep -q -- "--method v2lf --voxel-level 7,10 --chunks 16,64,256" "$out/direct-v2lf-gl.md" \
  || fail "direct-v2lf-gl did not take both voxel scenes and the three plane counts: $(head -1 "$out/direct-v2lf-gl.md")"
# The raster steps: both paths, N_chunk 64/256/512 at P_s 1, the paper's 512x910 views, 6M.
for step in raster-gl raster-gl-910 raster-gl-large raster-gl-large-910; do
  grep -q -- "bench render --backend gl --raster hardware,compute .*--views 45 .*--chunks 64,256,512 --plane-scale 1 " \
    "$out/$step.md" || fail "$step did not run both raster paths at N 64/256/512: $(head -1 "$out/$step.md")"
done
grep -q -- "--generated 100000,1000000 --views 45 --size 512x910 .*--runs 3 " "$out/raster-gl-910.md" \
  || fail "raster-gl-910: $(head -1 "$out/raster-gl-910.md")"
for step in raster-gl-large raster-gl-large-910; do
  grep -q -- "--generated 3000000,6000000 .*--runs 3 " "$out/$step.md" || fail "$step: $(head -1 "$out/$step.md")"
done
grep -q -- "--size 512x910 " "$out/raster-gl-large-910.md" || fail "raster-gl-large-910: $(head -1 "$out/raster-gl-large-910.md")"
for json in render-gl gpu-frame gpu-sort voxels-gl voxels-gl-1m direct-gl direct-gl-shader direct-v2lf-gl gpu-probe raster-gl \
            raster-gl-910 raster-gl-large raster-gl-large-910; do
  [ -s "$out/$json.json" ] || fail "$json.json was not written"
done
grep -q "stub lfd version" "$out/version.txt" || fail "version.txt: $(cat "$out/version.txt")"

# Named steps run alone; an unknown one is refused with one line and exit 2.
rm -rf "$out"
LFD_BUNDLE_DIR=$bundle bash "$root/scripts/gpu-table.sh" "$out" direct-gl > "$work/log" 2>&1 || fail "direct-gl alone failed"
[ "$(grep -c '^== .*: exit' "$out/steps.txt")" = 1 ] || fail "more than the named step ran: $(cat "$out/steps.txt")"
set +e
LFD_BUNDLE_DIR=$bundle bash "$root/scripts/gpu-table.sh" "$out" no-such-step > "$work/log" 2> "$work/err"
rc=$?
set -e
[ "$rc" = 2 ] || fail "an unknown step exited $rc, not 2"
grep -q "unknown step 'no-such-step'" "$work/err" || fail "no one-line reason: $(cat "$work/err")"
# No bundle: one line, exit 2.
set +e
LFD_BUNDLE_DIR=$work/none bash "$root/scripts/gpu-table.sh" "$out" > /dev/null 2> "$work/err"
rc=$?
set -e
[ "$rc" = 2 ] && grep -q "missing" "$work/err" || fail "a missing bundle exited $rc: $(cat "$work/err")"

# The zink smoke run: the same steps on zink at toy sizes, one timed frame; a bad value is refused.
rm -rf "$out"
LFD_BUNDLE_DIR=$bundle LFD_GPU_TABLE_SMOKE=zink LFD_GPU_TABLE_LIMIT=2 bash "$root/scripts/gpu-table.sh" "$out" \
  > "$work/log" 2>&1 || fail "the smoke run exited $?: $(tail -3 "$work/log")"
[ "$(grep -c '^== .*: exit' "$out/steps.txt")" = 14 ] || fail "the smoke run did not run every step: $(cat "$out/steps.txt")"
grep -q "stub driver zink" "$out/render-gl.md" || fail "the smoke run's lfd was not on zink: $(cat "$out/render-gl.md")"
grep -q -- "bench render --backend gl --generated 1000,2000 --views 5 --size 64 --runs 1 " "$out/render-gl.md" \
  || fail "the smoke run's render-gl was not at toy sizes: $(head -1 "$out/render-gl.md")"
grep -q -- "--generated 3000,6000 --views 5 --size 64x114 " "$out/raster-gl-large-910.md" \
  || fail "the smoke run's raster-gl-large-910: $(head -1 "$out/raster-gl-large-910.md")"
grep -q -- "--method v2lf --voxel-level 4,5 .*--calibration data/displays/go.visual.json --view-height 64 " \
  "$out/direct-v2lf-gl.md" || fail "the smoke run's direct-v2lf-gl: $(head -1 "$out/direct-v2lf-gl.md")"
grep -q "smoke run on zink" "$out/gpu.txt" || fail "gpu.txt: $(cat "$out/gpu.txt")"
set +e
LFD_BUNDLE_DIR=$bundle LFD_GPU_TABLE_SMOKE=nvidia bash "$root/scripts/gpu-table.sh" "$out" > /dev/null 2> "$work/err"
rc=$?
set -e
[ "$rc" = 2 ] && grep -q "LFD_GPU_TABLE_SMOKE" "$work/err" || fail "LFD_GPU_TABLE_SMOKE=nvidia exited $rc: $(cat "$work/err")"
echo "gpu_table_test: every step ran under its limit (exit codes 0, 124, 3 as planted), named and unknown steps, no bundle, the zink smoke run"
