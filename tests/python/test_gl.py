"""backend="gl": the quilt equals `lfd render --backend gl` of the same file (one GL code path,
Mesa llvmpipe here through headless EGL), and the GL interlacer is the CPU's to 1/255."""
import numpy as np
import pytest

import lfd
from conftest import PORTRAIT, read_png, run_lfd


def gl_or_skip():
    try:
        lfd.render_view(lfd.Gaussians.load(PORTRAIT.parents[1] / "scenes" / "three-points.ply"), 0,
                        views=1, size=(8, 8), backend="gl")
    except lfd.GlUnavailable as error:
        pytest.skip(f"no headless OpenGL 4.5: {error}")


def test_gl_quilt_equals_lfd_render_backend_gl(tmp_path, scene_file):
    gl_or_skip()
    run_lfd("render", "--scene", scene_file, "--backend", "gl", "--views", 4, "--cols", 2, "--rows", 2,
            "--size", "32x32", "--chunks", 8, "--out", tmp_path / "cli.png")
    quilt = lfd.render_quilt(lfd.Gaussians.load(scene_file), backend="gl", views=4, cols=2, rows=2,
                             size=(32, 32), chunks=8)
    assert np.array_equal(quilt.image, read_png(tmp_path / "cli_qs2x2a1.png"))


def test_raster_compute_equals_lfd_render_raster_compute(tmp_path, scene_file):
    gl_or_skip()
    run_lfd("render", "--scene", scene_file, "--backend", "gl", "--raster", "compute", "--views", 4, "--cols", 2,
            "--rows", 2, "--size", "32x32", "--chunks", 8, "--out", tmp_path / "cli.png")
    quilt = lfd.render_quilt(lfd.Gaussians.load(scene_file), backend="gl", raster="compute", views=4, cols=2,
                             rows=2, size=(32, 32), chunks=8)
    assert np.array_equal(quilt.image, read_png(tmp_path / "cli_qs2x2a1.png"))


def test_gl_interlace_is_the_cpu_s_to_one_level(arrays):
    gl_or_skip()
    display = lfd.Display.load(PORTRAIT)
    quilt = lfd.render_quilt(lfd.Gaussians(**arrays), display, views=6, size=(30, 40), chunks=8)
    cpu = lfd.interlace(quilt, display).astype(int)
    gl = lfd.interlace(quilt, display, backend="gl").astype(int)
    assert np.abs(cpu - gl).max() <= 1
