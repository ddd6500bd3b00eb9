"""python/examples/render_folder.py renders each scene of a folder as `lfd render` does and
skips an unreadable one with lfd's reason."""
import subprocess
import sys
from pathlib import Path

import numpy as np

from conftest import read_png, run_lfd

EXAMPLES = Path(__file__).parents[2] / "python" / "examples"


def test_render_folder_writes_one_quilt_per_scene(tmp_path, scene_file):
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    (scenes / "a.ply").write_bytes(scene_file.read_bytes())
    (scenes / "broken.splat").write_bytes(b"\x00" * 7)
    result = subprocess.run([sys.executable, EXAMPLES / "render_folder.py", scenes, tmp_path / "out",
                             "--views", "4", "--size", "24x24"], capture_output=True, text=True)
    assert result.returncode == 1, result.stdout + result.stderr  # one scene skipped
    assert "skipped: " in result.stderr and "broken.splat" in result.stderr
    written = tmp_path / "out" / "a_qs2x2a1.png"
    assert written.exists(), result.stdout
    run_lfd("render", "--scene", scenes / "a.ply", "--views", 4, "--size", "24x24", "--out", tmp_path / "cli.png")
    assert np.array_equal(read_png(written), read_png(tmp_path / "cli_qs2x2a1.png"))
