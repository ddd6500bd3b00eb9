"""Runs the C client (bridge_c_client.c) against the fixtures it needs: a quilt and the panel
`lfd interlace` makes of it. The client itself checks every call, the bad calls and the screen."""
import os
import subprocess

from bridge_support import CALIBRATION, lfd, synthetic_quilt, write_png


def test_the_c_client_passes(tmp_path):
    quilt = tmp_path / "c_qs8x6a0.75.png"
    write_png(quilt, synthetic_quilt(8, 6, 192, 256))
    panel = tmp_path / "panel.png"
    lfd("interlace", "--calibration", CALIBRATION, "--quilt", quilt, "--out", panel)
    out = subprocess.run([os.environ["BRIDGE_C_CLIENT"], str(CALIBRATION.resolve()), str(quilt), "8", "6", "0.75",
                          str(panel), str(tmp_path)], capture_output=True, text=True, timeout=240)
    print(out.stdout)
    print(out.stderr[-4000:])
    assert out.returncode == 0, out.stdout + out.stderr[-4000:]
    assert "OK" in out.stdout
