"""lfd.Window under Xvfb (tests/python/CMakeLists.txt: a screen of the test display's panel size,
so the window finds the display's monitor and goes full screen): what it shows equals
`lfd interlace` of the same quilt, and update() returns without waiting for the frame."""
import numpy as np

import lfd
from conftest import PORTRAIT, read_png, run_lfd, scene_arrays


def psnr(a, b):
    mse = np.mean((a.astype(np.float64) - b.astype(np.float64)) ** 2)
    return float("inf") if mse == 0 else 10 * np.log10(255.0 ** 2 / mse)


def test_window_shows_a_quilt_as_lfd_interlace_does(tmp_path):
    display = lfd.Display.load(PORTRAIT)
    quilt = lfd.render_quilt(lfd.Gaussians(**scene_arrays()), display, views=6, size=(48, 64), chunks=8)
    path = quilt.save(str(tmp_path / "q.png"))
    run_lfd("interlace", "--calibration", PORTRAIT, "--quilt", path, "--out", tmp_path / "panel.png")
    reference = read_png(tmp_path / "panel.png")
    with lfd.Window(display) as window:
        assert window.on_display, "not full screen on the display's monitor"
        window.update(quilt).wait()
        shown = window.screenshot()
    assert shown.shape == reference.shape == (2048, 1536, 3)
    print("window vs lfd interlace: %.1f dB" % psnr(shown, reference))
    assert psnr(shown, reference) >= 40.0


def test_window_renders_scenes_handed_over_from_a_loop(tmp_path):
    display = lfd.Display.load(PORTRAIT)
    settings = dict(views=4, size=(48, 64), chunks=4,
                    camera=dict(position=[0, 0, 4], look_at=[0, 0, 0], fov_y_deg=40))
    arrays = scene_arrays(count=80)
    scenes = []
    with lfd.Window(display) as window:
        for step in range(3):  # a training loop's display step: hands the scene over, goes on
            arrays["means"][:, 0] += 0.3
            scenes.append(lfd.Gaussians(**arrays))
            window.update(scenes[-1], **settings)
        window.wait()
        shown = window.screenshot()
    first, last = (lfd.interlace(lfd.render_quilt(g, display, **settings), display) for g in (scenes[0], scenes[-1]))
    # The last scene handed over is the one on screen, not an earlier one.
    assert psnr(shown, last) >= 40.0
    assert psnr(shown, first) < 40.0


def test_show_keeps_one_window_per_display():
    display = lfd.Display.load(PORTRAIT)
    first = lfd.show(np.zeros((64, 48 * 4, 3), np.uint8), display, cols=4, rows=1, aspect=0.75)
    second = lfd.show(np.full((64, 48 * 4, 3), 255, np.uint8), display, cols=4, rows=1, aspect=0.75)
    assert first is second
    assert second.wait().screenshot().mean() > 100  # the white quilt is what is shown
    second.close()
    assert not second.is_open


def test_training_loop_example_shows_its_gaussians_every_n_steps():
    import subprocess
    import sys
    from pathlib import Path
    example = Path(__file__).parents[2] / "python" / "examples" / "training_loop.py"
    result = subprocess.run([sys.executable, example, "--calibration", PORTRAIT, "--steps", "6", "--every", "3",
                             "--count", "60", "--views", "4"], capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stdout + result.stderr
    assert [line.split(":")[0] for line in result.stdout.splitlines()] == ["step 3", "step 6"]


def test_simulated_window_shows_the_same_panel():
    display = lfd.Display.load(PORTRAIT)
    quilt = lfd.render_quilt(lfd.Gaussians(**scene_arrays()), display, views=6, size=(48, 64), chunks=8)
    with lfd.Window(display, simulated=True) as window:
        assert not window.on_display  # the simulated display, in a window of its own
        shown = window.update(quilt).wait().screenshot()  # the interlaced panel it shows, scaled
    assert shown.shape == (2048, 1536, 3)
    assert psnr(shown, lfd.interlace(quilt, display)) >= 40.0
