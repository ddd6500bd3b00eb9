"""The library on OpenGL ES 3.1 (docs/arm.md, docs/bridge-inproc.md "OpenGL ES"): the C client
(bridge_c_client.c: a quilt texture of its GLFW context drawn in the library's window on the screen,
and the library's offscreen window read back) with the library's contexts on ES, asked for with
LFD_GL=es and chosen by the library itself when desktop GL is capped at 3.1 as on a Raspberry Pi 5
(MESA_GL_VERSION_OVERRIDE=3.1). The screen and the offscreen panel must be what `lfd interlace`
gives (>= 40 dB, checked by the client), and the library's log must say each window ran on ES."""
import os
import re
import subprocess

import pytest

from bridge_support import CALIBRATION, lfd, synthetic_quilt, write_png

NOTICE = "running on OpenGL ES 3.1"


@pytest.mark.parametrize("how", ["es", "capped"])
def test_the_library_draws_the_interlaced_panel_on_opengl_es(tmp_path, how):
    quilt = tmp_path / "c_qs8x6a0.75.png"
    write_png(quilt, synthetic_quilt(8, 6, 192, 256))
    panel = tmp_path / "panel.png"
    lfd("interlace", "--calibration", CALIBRATION, "--quilt", quilt, "--out", panel)  # the CPU's panel
    log = tmp_path / "bridge.log"
    env = dict(os.environ, LFD_BRIDGE_LOG=str(log))
    env.pop("LFD_GL", None)
    env.pop("MESA_GL_VERSION_OVERRIDE", None)
    if how == "es":
        env["LFD_GL"] = "es"
    else:
        env["MESA_GL_VERSION_OVERRIDE"] = "3.1"
    out = subprocess.run([os.environ["BRIDGE_C_CLIENT"], str(CALIBRATION.resolve()), str(quilt), "8", "6", "0.75",
                          str(panel), str(tmp_path)], capture_output=True, text=True, timeout=300, env=env)
    print(out.stdout)
    print(out.stderr[-4000:])
    assert out.returncode == 0, out.stdout + out.stderr[-4000:]
    assert "OK" in out.stdout
    for line in re.findall(r"PSNR .*", out.stdout):
        assert float(line.split()[-1]) >= 40.0, line
    text = log.read_text()
    gl_lines = [line for line in text.splitlines() if ": gl: " in line]
    # the window on the screen, the offscreen window of the display, the one from the file
    assert [line.split(":")[1].strip() for line in gl_lines] == [
        "instance_window_gl", "instance_offscreen_window_gl", "instance_offscreen_window"], text
    assert all(line.endswith("[OpenGL ES path]") and "OpenGL ES 3" in line for line in gl_lines), text
    # auto falling back says so once, on stderr; asked for, ES needs no notice
    assert out.stderr.count(NOTICE) == (1 if how == "capped" else 0), out.stderr
