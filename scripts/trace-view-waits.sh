#!/usr/bin/env bash
# Records `lfd view` with apitrace under a virtual X screen and asserts that no steady-state frame
# makes a GL call that waits for the GPU (scripts/count-gl-waits.py; docs/gpu.md "A frame that
# never waits"). Prints the per-frame counts of waits, dispatches, draws and barriers.
#   scripts/trace-view-waits.sh LFD_EXE g2lf|per-view|v2lf WORK_DIR [FRAMES [WARMUP]]
# The display is LKG-2K-04409's calibration at 640x400 (a quarter panel: quick on llvmpipe), the
# scene data/scenes/demo.ply (27k Gaussians), 9 views of 128 px height, no control window.
# v2lf: the voxel path, `lfd view`'s g2lf method on a sparse-voxel scene (V2LF), the scene
# generated first (`lfd scene generate --kind voxels --level 6`: the tabletop, 3,486 voxels).
# Needs apitrace and xvfb-run (scripts/install-test-deps.sh); `xvfb-run -a -n N` takes the first
# free display from :N (LFD_TRACE_DISPLAY; default 93, v2lf 94, so the tests can run together).
set -euo pipefail
lfd=$1 mode=$2 work=$3 frames=${4:-8} warmup=${5:-3}
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$work"
method=$mode scene="$root/data/scenes/demo.ply" display=${LFD_TRACE_DISPLAY:-93}
if [ "$mode" = v2lf ]; then
  method=g2lf scene="$work/tabletop-6.voxels" display=${LFD_TRACE_DISPLAY:-94}
  "$lfd" scene generate --kind voxels --level 6 --out "$scene" > /dev/null
fi
sed -e 's/"screenW":{"value":2560.0}/"screenW":{"value":640.0}/' -e 's/"screenH":{"value":1600.0}/"screenH":{"value":400.0}/' \
  "$root/tests/data/calibrations/LKG-2K-04409.visual.json" > "$work/quarter.visual.json"
grep -q '"screenW":{"value":640.0}' "$work/quarter.visual.json"  # the fixture's format changed otherwise
printf '{"method":"%s","views":9,"view_height_px":128}\n' "$method" > "$work/settings-$mode.json"
rm -f "$work/view-$mode.trace"
xvfb-run -a -n "$display" -s "-screen 0 1280x1024x24" \
  apitrace trace -o "$work/view-$mode.trace" \
  "$lfd" view "$scene" --calibration "$work/quarter.visual.json" --simulated \
  --no-controls --no-vsync --frames "$frames" --method "$method" --settings "$work/settings-$mode.json"
apitrace dump --color=never "$work/view-$mode.trace" > "$work/view-$mode.dump"
python3 "$root/scripts/count-gl-waits.py" "$work/view-$mode.dump" --warmup "$warmup" \
  --label "lfd view --method $method ($(basename "$scene"))" --assert-no-waits
