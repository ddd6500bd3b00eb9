#!/usr/bin/env bash
# Records `lfd view` with apitrace under a virtual X screen and asserts that no steady-state frame
# makes a GL call that waits for the GPU (scripts/count-gl-waits.py; docs/gpu.md "A frame that
# never waits"). Prints the per-frame counts of waits, dispatches, draws and barriers.
#   scripts/trace-view-waits.sh LFD_EXE g2lf|per-view WORK_DIR [FRAMES [WARMUP]]
# The display is LKG-2K-04409's calibration at 640x400 (a quarter panel: quick on llvmpipe), the
# scene data/scenes/demo.ply (27k Gaussians), 9 views of 128 px height, no control window.
# Needs apitrace and xvfb-run (scripts/install-deps.sh); `xvfb-run -a -n 93` takes the first
# free display from :93.
set -euo pipefail
lfd=$1 method=$2 work=$3 frames=${4:-8} warmup=${5:-3}
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$work"
sed -e 's/"screenW":{"value":2560.0}/"screenW":{"value":640.0}/' -e 's/"screenH":{"value":1600.0}/"screenH":{"value":400.0}/' \
  "$root/tests/data/calibrations/LKG-2K-04409.visual.json" > "$work/quarter.visual.json"
grep -q '"screenW":{"value":640.0}' "$work/quarter.visual.json"  # the fixture's format changed otherwise
printf '{"method":"%s","views":9,"view_height_px":128}\n' "$method" > "$work/settings-$method.json"
rm -f "$work/view-$method.trace"
xvfb-run -a -n 93 -s "-screen 0 1280x1024x24" \
  apitrace trace -o "$work/view-$method.trace" \
  "$lfd" view "$root/data/scenes/demo.ply" --calibration "$work/quarter.visual.json" --simulated \
  --no-controls --no-vsync --frames "$frames" --method "$method" --settings "$work/settings-$method.json"
apitrace dump --color=never "$work/view-$method.trace" > "$work/view-$method.dump"
python3 "$root/scripts/count-gl-waits.py" "$work/view-$method.dump" --warmup "$warmup" \
  --label "lfd view --method $method" --assert-no-waits
