"""lfd.render_quilt from arrays equals `lfd render` of the same scene's file (same camera, views
and method): the keywords are `lfd render`'s flags, mapped by the same code."""
import json

import numpy as np
import pytest

import lfd
from conftest import PORTRAIT, read_png, run_lfd


SMALL = dict(views=6, cols=3, rows=2, size=(48, 40))
FLAGS = ["--views", 6, "--cols", 3, "--rows", 2, "--size", "48x40"]


def cli_quilt(scene_file, out, *flags):
    run_lfd("render", "--scene", scene_file, "--out", out, *flags)
    written = list(out.parent.glob(out.stem + "_qs*.png"))
    assert len(written) == 1, written
    return written[0]


@pytest.mark.parametrize("method", ["g2lf", "per-view"])
def test_quilt_from_arrays_equals_lfd_render_of_the_file(tmp_path, arrays, scene_file, method):
    path = cli_quilt(scene_file, tmp_path / "cli.png", "--method", method, "--chunks", 16, *FLAGS)
    quilt = lfd.render_quilt(lfd.Gaussians(**arrays), method=method, chunks=16, **SMALL)
    assert (quilt.cols, quilt.rows, quilt.views) == (3, 2, 6)
    assert quilt.image.shape == (80, 144, 3) and quilt.image.dtype == np.uint8
    expected = read_png(path)
    assert np.array_equal(quilt.image, expected), np.abs(quilt.image.astype(int) - expected).max()
    assert quilt.image.std() > 5  # the scene is in view, not an empty frame


def test_camera_dict_equals_cam_json_and_display_decides_the_grid(tmp_path, arrays, scene_file):
    camera = dict(position=[0.3, 0.2, 4.0], look_at=[0, 0, 0], up=[0, 1, 0], fov_y_deg=40)
    (tmp_path / "cam.json").write_text(json.dumps(camera))
    path = cli_quilt(scene_file, tmp_path / "cli.png", "--camera", tmp_path / "cam.json",
                     "--calibration", PORTRAIT, "--views", 4, "--size", "30x40", "--chunks", 8)
    display = lfd.Display.load(PORTRAIT)
    quilt = lfd.render_quilt(lfd.Gaussians(**arrays), display, camera=camera, views=4,
                             size=(30, 40), chunks=8)
    assert path.name == f"cli_qs{quilt.cols}x{quilt.rows}a0.75.png"
    assert np.array_equal(quilt.image, read_png(path))


def test_loaded_file_equals_arrays(arrays, scene_file):
    loaded = lfd.Gaussians.load(scene_file)
    made = lfd.Gaussians(**arrays)
    assert len(loaded) == len(made) == 150 and loaded.sh_degree == 1
    for name in ["means", "scales", "rotations", "opacities", "sh"]:
        np.testing.assert_allclose(getattr(loaded, name), getattr(made, name), rtol=1e-6, atol=1e-7)
    np.testing.assert_allclose(made.scales, np.exp(arrays["log_scales"]), rtol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(made.rotations, axis=1), 1, rtol=1e-6)


def test_activated_values_as_gsplat_keeps_them_render_the_same(arrays):
    activated = lfd.Gaussians(means=arrays["means"], scales=np.exp(arrays["log_scales"]),
                              rotations=arrays["rotations"],
                              opacities=1 / (1 + np.exp(-arrays["opacity_logits"])),
                              sh=arrays["sh"], activated=True)
    a = lfd.render_quilt(activated, chunks=8, **SMALL).image
    b = lfd.render_quilt(lfd.Gaussians(**arrays), chunks=8, **SMALL).image
    assert np.abs(a.astype(int) - b.astype(int)).max() <= 1


def test_render_view_equals_lfd_render_view(tmp_path, scene_file):
    run_lfd("render", "--scene", scene_file, "--view", 2, "--out", tmp_path / "v.png", *FLAGS)
    view = lfd.render_view(lfd.Gaussians.load(scene_file), 2, **SMALL)
    assert view.shape == (40, 48, 3)
    assert np.array_equal(view, read_png(tmp_path / "v.png"))


def test_saved_quilt_is_named_with_its_tiling_and_reads_back(tmp_path, arrays):
    quilt = lfd.render_quilt(lfd.Gaussians(**arrays), chunks=8, **SMALL)
    written = quilt.save(str(tmp_path / "q.png"))
    assert written.endswith("q_qs3x2a1.2.png")
    again = lfd.Quilt.load(written)
    assert (again.cols, again.rows, again.views) == (3, 2, 6)
    assert np.array_equal(again.image, quilt.image)


def test_interlace_equals_lfd_interlace(tmp_path, arrays):
    display = lfd.Display.load(PORTRAIT)
    quilt = lfd.render_quilt(lfd.Gaussians(**arrays), display, views=6, size=(30, 40), chunks=8)
    path = quilt.save(str(tmp_path / "q.png"))
    run_lfd("interlace", "--calibration", PORTRAIT, "--quilt", path, "--out", tmp_path / "panel.png")
    panel = lfd.interlace(quilt, display)
    assert panel.shape == (2048, 1536, 3)
    assert np.array_equal(panel, read_png(tmp_path / "panel.png"))


def test_display_figures_are_lfd_info_s(tmp_path):
    display = lfd.Display.load(PORTRAIT)
    info = json.loads(run_lfd("info", "--calibration", PORTRAIT, "--json"))
    assert display.figures == info
    assert display.screen == (1536, 2048)
    assert display.recommended_views == info["recommended_views"]["views"]
    assert display.quilt["cols"] * display.quilt["rows"] >= display.recommended_views
    assert 0 < display.view_cone_deg < 90


def test_voxels_render_with_v2lf(tmp_path):
    run_lfd("scene", "generate", "--kind", "voxels", "--level", 4, "--out", tmp_path / "v.voxels")
    voxels = lfd.Voxels.load(tmp_path / "v.voxels")
    path = cli_quilt(tmp_path / "v.voxels", tmp_path / "cli.png", "--views", 4, "--cols", 2, "--rows", 2,
                     "--size", "24x24", "--chunks", 8)
    quilt = lfd.render_quilt(voxels, views=4, cols=2, rows=2, size=(24, 24), chunks=8)
    assert np.array_equal(quilt.image, read_png(path))
    with pytest.raises(ValueError, match="^method: g2lf is for Gaussian scenes"):
        lfd.render_quilt(voxels, method="g2lf")
    with pytest.raises(ValueError, match="holds sparse voxels; read it with lfd.Voxels.load$"):
        lfd.Gaussians.load(tmp_path / "v.voxels")
    assert isinstance(lfd.load(tmp_path / "v.voxels"), lfd.Voxels)
