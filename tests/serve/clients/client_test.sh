#!/usr/bin/env bash
# One named client test, run inside run_with_lfd_serve.sh (docs/serve.md):
#   holoplay-core | bridge | screenshot | cross-origin | garbage
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
node make_quilts.js "$LFD_SERVE_TMP"
A="$LFD_SERVE_TMP/a_qs4x3a0.75.png" B="$LFD_SERVE_TMP/b_qs4x3a0.75.png"
case "$1" in
  holoplay-core) node holoplay_core_test.js "$CALIBRATION" "$A" 4 3 0.75 ;;
  bridge) node bridge_test.js "$CALIBRATION" "$A" "$B" 4 3 0.75 ;;
  cross-origin) node cross_origin_test.js "$A" ;;
  garbage) node garbage_test.js ;;
  webxr)
    command -v chromium >/dev/null || { echo "SKIP: Debian's chromium is not installed"; exit 77; }
    node webxr_test.js "$CALIBRATION" ;;
  screenshot)
    # What the window shows (the Xvfb screen) against `lfd interlace` of the quilt sent.
    node holoplay_core_test.js "$CALIBRATION" "$A" 4 3 0.75 >/dev/null
    sleep 2
    python3 "$here/../../../scripts/xwd-to-png.py" "$LFD_SERVE_TMP/fb/Xvfb_screen0" "$LFD_SERVE_TMP/screen.png"
    "$LFD_EXE" interlace --calibration "$CALIBRATION" --quilt "$A" --out "$LFD_SERVE_TMP/panel.png" >/dev/null
    psnr=$("$LFD_EXE" compare "$LFD_SERVE_TMP/screen.png" "$LFD_SERVE_TMP/panel.png" --json |
           node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>{const j=JSON.parse(s);console.log(j.identical?"inf":j.psnr_db)})')
    echo "screen vs lfd interlace: PSNR $psnr dB"
    node -e "process.exit('$psnr' === 'inf' || Number('$psnr') >= 40 ? 0 : 1)" || { echo "FAIL: below 40 dB"; exit 1; }
    echo "ok: the window shows lfd interlace of the cast quilt (>= 40 dB)" ;;
  *) echo "unknown test $1"; exit 2 ;;
esac
