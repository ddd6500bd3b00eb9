#!/usr/bin/env bash
# Runs one client test against a real `lfd serve` (docs/serve.md, "Tests with the real clients"):
# starts Xvfb with a screen of the calibration's panel size (the Player then finds "the display's
# monitor" by resolution and goes full screen on it, as on a real unit; -fbdir keeps the screen
# as an XWD file for the screenshot test), starts lfd serve on it with a temporary state file,
# waits until it answers, runs the test, checks that the service is still alive and stops both
# by their process ids. Exit 77 (CTest: skipped) when the npm clients are not installed.
#   run_with_lfd_serve.sh LFD_EXE CALIBRATION COMMAND [ARGS...]
# The command gets LFD_EXE, LFD_SERVE_TMP (a fresh folder), CALIBRATION and DISPLAY.
set -uo pipefail
LFD_EXE=$1 CALIBRATION=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v node >/dev/null || [ ! -d "$here/node_modules/holoplay-core" ] ||
   [ ! -d "$here/node_modules/@lookingglass/bridge" ]; then
  echo "SKIP: the npm clients are not installed (scripts/install-npm-clients.sh)"
  exit 77
fi
LFD_SERVE_TMP=$(mktemp -d)
read -r W H < <(node -e '
  const r = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
  const d = r.format === "lfd-calibration" ? r.display : r;
  console.log(d.screenW.value, d.screenH.value);' "$CALIBRATION")
mkdir -p "$LFD_SERVE_TMP/fb"
Xvfb -displayfd 3 -screen 0 "${W}x${H}x24" -fbdir "$LFD_SERVE_TMP/fb" -nolisten tcp 3>"$LFD_SERVE_TMP/display" \
  2>"$LFD_SERVE_TMP/xvfb.log" &
xvfb=$!
serve=""
cleanup() {
  [ -n "$serve" ] && kill "$serve" 2>/dev/null && wait "$serve" 2>/dev/null
  kill "$xvfb" 2>/dev/null && wait "$xvfb" 2>/dev/null
  rm -rf "$LFD_SERVE_TMP"
}
trap cleanup EXIT
for _ in $(seq 100); do [ -s "$LFD_SERVE_TMP/display" ] && break; sleep 0.1; done
export DISPLAY=":$(head -n1 "$LFD_SERVE_TMP/display")" LFD_EXE LFD_SERVE_TMP CALIBRATION
"$LFD_EXE" serve --calibration "$CALIBRATION" --state-file "$LFD_SERVE_TMP/state/playlists.json" --content "$LFD_SERVE_TMP/content" \
  >"$LFD_SERVE_TMP/serve.log" 2>&1 &
serve=$!
for _ in $(seq 150); do
  "$LFD_EXE" serve --status >/dev/null 2>&1 && break
  kill -0 "$serve" 2>/dev/null || { echo "FAIL: lfd serve exited at start"; cat "$LFD_SERVE_TMP/serve.log"; exit 1; }
  sleep 0.2
done
"$@"
rc=$?
if ! kill -0 "$serve" 2>/dev/null; then
  echo "FAIL: lfd serve is no longer running"
  rc=1
elif ! "$LFD_EXE" serve --status >/dev/null; then
  echo "FAIL: lfd serve no longer answers"
  rc=1
fi
if [ "$rc" -ne 0 ]; then echo "--- lfd serve's log"; tail -n 40 "$LFD_SERVE_TMP/serve.log"; fi
exit "$rc"
