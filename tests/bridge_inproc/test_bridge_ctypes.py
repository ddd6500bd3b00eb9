"""libbridge_inproc through ctypes as the vendor's Python SDK uses it (docs/bridge-inproc.md
"Tests"): found through the settings files `lfd bridge register` writes, every SDK function bound,
getters against the calibration file, bad calls, and quilt / RGB-D / offscreen drawing compared
with what `lfd interlace` and `lfd rgbd-quilt` make. Runs under Xvfb with a screen of the test
display's panel size, whose -fbdir file is the screen read back."""
import ctypes
import json
import math
import os
import subprocess
import time
from ctypes import byref, c_float, c_int32, c_int64, c_uint, c_uint32, c_uint64, c_ulong, c_void_p
from pathlib import Path

import numpy as np
import pytest

from bridge_support import (CALIBRATION, LFD, OTHER_EXPORTS, RGBA, SDK_SIGNATURES, Bridge, EglContext, GlfwContext,
                            find_library_as_the_sdk_does, lfd, make_texture, psnr, read_screen, read_texture,
                            synthetic_quilt, synthetic_rgbd, write_png)

FBDIR = os.environ.get("LFD_TEST_FBDIR", "")
CAL = json.loads(CALIBRATION.read_text())
W, H = int(CAL["screenW"]["value"]), int(CAL["screenH"]["value"])


def value(key):
    v = CAL[key]
    return v["value"] if isinstance(v, dict) else v


@pytest.fixture(scope="module")
def home(tmp_path_factory):
    """A HOME with a vendor Bridge already registered, then lfd's library registered over it."""
    home = tmp_path_factory.mktemp("home")
    os.environ["HOME"] = str(home)
    os.environ["LFD_BRIDGE_CONFIG"] = str(home / ".config" / "lfd" / "bridge.json")
    py = home / ".config" / "LookingGlass" / "Bridge" / "settings.json"
    py.parent.mkdir(parents=True)
    py.write_text(json.dumps({"enable_utilization_telemetry": False,
                              "install_locations": [{"version": "2.5.1", "path": "/opt/vendor/bridge-2.5.1"}]}))
    native = home / ".lgf" / "Bridge" / "settings.json"
    native.parent.mkdir(parents=True)
    native.write_text(json.dumps({"install_locations": [{"version": "2.6.0", "path": "/opt/vendor/b2.6.0"}]}))
    (home / ".lgf" / "bridge_install_locations").write_text("/opt/vendor/Bridge-2.4.9\n")
    lfd("bridge", "register", "--calibration", CALIBRATION)
    return home


@pytest.fixture(scope="module")
def bridge(home):
    path = find_library_as_the_sdk_does(home)
    assert path is not None and path.is_file(), path
    b = Bridge(path)
    yield b
    b.f.uninitialize_bridge()


@pytest.fixture(scope="module")
def glfw_context(bridge):
    return GlfwContext()


@pytest.fixture(scope="module")
def window(bridge, glfw_context):
    assert bridge.f.initialize_bridge("test_bridge_ctypes")
    h = c_uint32(0)
    assert bridge.f.instance_window_gl(byref(h), 0xFFFFFFFF)  # FIRST_LOOKING_GLASS_DEVICE as the SDK passes -1
    assert h.value != 0
    return h.value


def test_register_keeps_the_vendors_entries(home):
    py = json.loads((home / ".config" / "LookingGlass" / "Bridge" / "settings.json").read_text())
    assert py["enable_utilization_telemetry"] is False
    versions = [e["version"] for e in py["install_locations"]]
    assert "2.5.1" in versions and "2.6.2" in versions
    native = json.loads((home / ".lgf" / "Bridge" / "settings.json").read_text())
    assert [e["version"] for e in native["install_locations"]] == ["2.6.0", "2.6.2"]
    legacy = (home / ".lgf" / "bridge_install_locations").read_text().splitlines()
    assert legacy[0] == "/opt/vendor/Bridge-2.4.9" and legacy[1].endswith("lfd-bridge-2.6.2")
    status = json.loads(lfd("bridge", "status", "--json").stdout)
    assert status["registered"] and status["settings"]["calibrations"] == [str(CALIBRATION.resolve())]


def test_every_function_the_sdk_binds_is_exported(bridge):
    for name in list(SDK_SIGNATURES) + OTHER_EXPORTS:
        assert hasattr(bridge.lib, name), name


def test_only_the_c_api_is_exported(bridge):
    out = subprocess.run(["nm", "-D", "--defined-only", bridge.lib._name], capture_output=True, text=True).stdout
    names = {line.split()[-1] for line in out.splitlines() if line.split()[1] == "T"}
    assert names == set(SDK_SIGNATURES) | set(OTHER_EXPORTS), sorted(names ^ (set(SDK_SIGNATURES) | set(OTHER_EXPORTS)))


def test_calls_before_initialize_return_false(bridge):
    n = c_int32(0)
    assert not bridge.f.get_displays(byref(n), None)
    h = c_uint32(0)
    assert not bridge.f.instance_window_gl(byref(h), 0)


def test_version_is_one_the_clients_accept(bridge, window):
    major, minor, build, n = c_ulong(), c_ulong(), c_ulong(), c_int32(0)
    assert bridge.f.get_bridge_version(byref(major), byref(minor), byref(build), byref(n), None)
    buf = ctypes.create_unicode_buffer(n.value)
    assert bridge.f.get_bridge_version(byref(major), byref(minor), byref(build), byref(n), ctypes.cast(buf, c_void_p))
    assert (major.value, minor.value) == (2, 6) and buf.value.startswith("lfd ")


def test_getters_equal_the_calibration(bridge, window):
    n = c_int32(0)
    assert bridge.f.get_displays(byref(n), None) and n.value == 1
    arr = (c_uint64 * 1)()
    assert bridge.f.get_displays(byref(n), arr) and list(arr) == [0]
    w, h = c_ulong(), c_ulong()
    assert bridge.f.get_window_dimensions(window, byref(w), byref(h)) and (w.value, h.value) == (W, H)
    assert bridge.f.get_dimensions_for_display(0, byref(w), byref(h)) and (w.value, h.value) == (W, H)
    for getter in (lambda name, t: bridge.scalar(name, window, t),
                   lambda name, t: bridge.scalar(name + "_for_display", 0, t)):
        pitch, slope, dpi = value("pitch"), value("slope"), value("DPI")
        # The shader terms (docs/display-model.md): lens periods across the width and the tilt.
        assert getter("get_pitch", c_float) == pytest.approx(pitch * W / dpi * abs(slope) / math.hypot(1, slope), 1e-5)
        assert getter("get_tilt", c_float) == pytest.approx(H / (W * slope), 1e-5)
        assert getter("get_subp", c_float) == pytest.approx(1 / (3 * W), 1e-6)
        assert getter("get_center", c_float) == pytest.approx(value("center"), 1e-6)
        assert getter("get_fringe", c_float) == pytest.approx(value("fringe"))
        assert getter("get_displayaspect", c_float) == pytest.approx(W / H, 1e-6)
        assert getter("get_viewcone", c_float) == pytest.approx(value("viewCone"))
        assert getter("get_invview", c_int32) == int(value("invView"))
        assert (getter("get_ri", c_int32), getter("get_bi", c_int32)) == (0, 2)
    f = [c_float() for _ in range(7)]
    i = [c_int32() for _ in range(5)]
    args = [byref(f[0]), byref(f[1]), byref(f[2]), byref(i[0]), byref(i[1]), byref(f[3]), byref(f[4]), byref(i[2]),
            byref(f[5]), byref(f[6]), byref(i[3]), byref(i[4]), None]
    assert bridge.f.get_calibration(window, *args)
    assert (f[0].value, f[1].value, f[2].value) == pytest.approx((value("center"), value("pitch"), value("slope")))
    assert (i[0].value, i[1].value, f[3].value) == (W, H, pytest.approx(value("DPI")))
    assert (f[5].value, i[2].value, i[4].value) == (pytest.approx(value("viewCone")), int(value("invView")), 0)
    assert bridge.f.get_calibration_for_display(0, *args)
    assert bridge.wide("get_device_serial_for_display", 0) == CAL["serial"]
    assert bridge.wide("get_device_name_for_display", 0) == "Looking Glass Portrait"
    aspect, qw, qh, qc, qr = c_float(), c_int32(), c_int32(), c_int32(), c_int32()
    assert bridge.f.get_default_quilt_settings(window, byref(aspect), byref(qw), byref(qh), byref(qc), byref(qr))
    # lfd's quilt for the display (the view-count rule), as `lfd info` recommends it, 512-pixel views.
    views = json.loads(lfd("info", "--calibration", CALIBRATION, "--json").stdout)["recommended_views"]
    assert aspect.value == pytest.approx(0.75) and (qc.value, qr.value) == (views["cols"], views["rows"])
    assert (qw.value, qh.value) == (384 * views["cols"], 512 * views["rows"])
    display = c_uint64(9)
    assert bridge.f.get_display_for_window(window, byref(display)) and display.value == 0
    size = c_ulong()
    assert bridge.f.get_max_texture_size(window, byref(size)) and size.value >= 4096
    x, y = c_int64(), c_int64()
    assert bridge.f.get_window_position(window, byref(x), byref(y))
    assert bridge.f.get_window_position_for_display(0, byref(x), byref(y))


def test_gen3_cells_come_back_in_two_calls(bridge, window, tmp_path):
    gen3 = CALIBRATION.parent / "template-16in-portrait-gen3.visual.json"
    cells_json = json.loads(gen3.read_text())["subpixelCells"]
    h = c_uint32(0)
    assert bridge.f.instance_offscreen_window(byref(h), 216, 384, str(gen3))
    f = [c_float() for _ in range(7)]
    i = [c_int32() for _ in range(5)]
    args = [byref(f[0]), byref(f[1]), byref(f[2]), byref(i[0]), byref(i[1]), byref(f[3]), byref(f[4]), byref(i[2]),
            byref(f[5]), byref(f[6]), byref(i[3])]
    n = c_int32(0)
    assert bridge.f.get_calibration(h.value, *args, byref(n), None) and n.value == len(cells_json)
    cells = (c_float * (6 * n.value))()
    assert bridge.f.get_calibration(h.value, *args, byref(n), ctypes.cast(cells, c_void_p))
    first = cells_json[0]
    assert list(cells[:6]) == pytest.approx([first[k] for k in ("ROffsetX", "ROffsetY", "GOffsetX", "GOffsetY",
                                                                   "BOffsetX", "BOffsetY")])
    assert bridge.wide("get_device_name", h.value)


def _screen_equals(reference_png, tmp_path, label):
    """Polls the screen until it matches the reference (the drawing thread swaps on its own)."""
    best = 0.0
    for _ in range(40):
        time.sleep(0.5)
        shot = tmp_path / f"{label}_screen.png"
        write_png(shot, read_screen(FBDIR, W, H))
        best = max(best, psnr(shot, reference_png))
        if best >= 40:
            break
    print(f"PSNR {label} {best:.2f} dB")
    return best


@pytest.fixture(scope="module")
def quilt_and_panel(tmp_path_factory):
    d = tmp_path_factory.mktemp("quilt")
    quilt = synthetic_quilt(8, 6, 192, 256)
    path = d / "fixture_qs8x6a0.75.png"
    write_png(path, quilt)
    panel = d / "panel.png"
    lfd("interlace", "--calibration", CALIBRATION, "--quilt", path, "--out", panel)
    return quilt, panel


@pytest.mark.skipif(not FBDIR, reason="needs Xvfb with -fbdir (LFD_TEST_FBDIR)")
def test_quilt_from_a_glfw_context_is_lfd_interlace_on_screen(bridge, window, glfw_context, quilt_and_panel,
                                                              tmp_path):
    quilt, panel = quilt_and_panel
    glfw_context.make_current()
    tex = make_texture(quilt)
    h, w = quilt.shape[:2]
    assert bridge.f.draw_interop_quilt_texture_gl(window, tex, RGBA, w, h, 8, 6, 0.75, 1.0)
    assert _screen_equals(panel, tmp_path, "glfw-glx") >= 40


@pytest.mark.skipif(not FBDIR, reason="needs Xvfb with -fbdir (LFD_TEST_FBDIR)")
def test_quilt_from_an_egl_context_is_lfd_interlace_on_screen(bridge, window, glfw_context, tmp_path):
    # Another quilt, so the screen cannot still hold the GLFW test's frame.
    quilt = synthetic_quilt(8, 6, 160, 213)[::-1].copy()
    path = tmp_path / "egl_qs8x6a0.75.png"
    write_png(path, quilt)
    panel = tmp_path / "egl_panel.png"
    lfd("interlace", "--calibration", CALIBRATION, "--quilt", path, "--out", panel)
    glfw_context.release()
    egl = EglContext()
    try:
        tex = make_texture(quilt)
        h, w = quilt.shape[:2]
        assert bridge.f.draw_interop_quilt_texture_gl(window, tex, RGBA, w, h, 8, 6, 0.75, 1.0)
        assert _screen_equals(panel, tmp_path, "egl") >= 40
    finally:
        egl.release()
        glfw_context.make_current()


@pytest.mark.skipif(not FBDIR, reason="needs Xvfb with -fbdir (LFD_TEST_FBDIR)")
def test_rgbd_is_lfds_rgbd_panel_on_screen(bridge, window, glfw_context, tmp_path):
    frame = synthetic_rgbd(240, 320)
    path = tmp_path / "photo.png"
    write_png(path, frame)
    lfd("rgbd-quilt", path, tmp_path / "views.png", "--calibration", CALIBRATION, "--views", 48, "--depthiness", 1.2,
        "--focus", 0.01, "--backend", "gl")
    [quilt_png] = list(tmp_path.glob("views_qs*.png"))
    cols, rows = 8, 6
    assert f"_qs{cols}x{rows}a" in quilt_png.name
    panel = tmp_path / "rgbd_panel.png"
    lfd("interlace", "--calibration", CALIBRATION, "--quilt", quilt_png, "--out", panel)
    glfw_context.make_current()
    tex = make_texture(frame)
    # The floats in the order the SDK passes them: aspect, focus, depthiness, zoom; depth on the right.
    assert bridge.f.draw_interop_rgbd_texture_gl(window, tex, RGBA, 480, 320, 240 * cols, 320 * rows, cols, rows,
                                                 0.75, 0.01, 1.2, 1.0, 2)
    assert _screen_equals(panel, tmp_path, "rgbd") >= 40


def test_offscreen_texture_is_lfd_interlace(bridge, window, glfw_context, quilt_and_panel, tmp_path):
    quilt, panel = quilt_and_panel
    glfw_context.make_current()
    h = c_uint32(0)
    assert bridge.f.instance_offscreen_window_gl(byref(h), 0)
    tex = make_texture(quilt)
    assert bridge.f.draw_interop_quilt_texture_gl(h.value, tex, RGBA, quilt.shape[1], quilt.shape[0], 8, 6, 0.75, 1.0)
    name, fmt, w, hh = c_uint64(), c_uint(), c_ulong(), c_ulong()
    assert bridge.f.get_offscreen_window_texture_gl(h.value, byref(name), byref(fmt), byref(w), byref(hh))
    assert (fmt.value, w.value, hh.value) == (RGBA, W, H)
    got = tmp_path / "offscreen.png"
    write_png(got, read_texture(name.value, W, H))
    assert psnr(got, panel) >= 40


def test_bad_calls_return_false_and_the_process_lives(bridge, window, glfw_context, tmp_path):
    glfw_context.make_current()
    tex = make_texture(np.zeros((60, 80, 3), np.uint8))
    gone = make_texture(np.zeros((4, 4, 3), np.uint8))
    from bridge_support import GL
    GL.glDeleteTextures(1, byref(c_uint32(gone)))
    f = bridge.f
    draw = f.draw_interop_quilt_texture_gl
    assert not draw(777, tex, RGBA, 80, 60, 4, 3, 1.0, 1.0)               # unknown window
    assert not draw(window, 0, RGBA, 80, 60, 4, 3, 1.0, 1.0)              # texture 0
    assert not draw(window, gone, RGBA, 80, 60, 4, 3, 1.0, 1.0)           # a deleted texture
    assert not draw(window, tex, 0x83F3, 80, 60, 4, 3, 1.0, 1.0)          # a compressed format
    assert not draw(window, tex, RGBA, 0, 60, 4, 3, 1.0, 1.0)             # zero size
    assert not draw(window, tex, RGBA, 80, 60, 0, 3, 1.0, 1.0)            # zero grid
    assert not draw(window, tex, RGBA, 80, 60, 4, 3, float("nan"), 1.0)   # NaN aspect
    assert not draw(window, tex, RGBA, 81, 60, 4, 3, 1.0, 1.0)            # not the texture's size
    assert not f.draw_interop_rgbd_texture_gl(window, tex, RGBA, 80, 60, 80, 60, 4, 3, 1.0, 0.0, 1.0, 1.0, 9)
    assert not f.get_viewcone(window, None)                               # null pointer
    assert not f.get_displays(None, None)
    assert not f.get_pitch_for_display(5, byref(c_float()))                # no such display
    assert not f.instance_offscreen_window(byref(c_uint32()), 64, 64, str(tmp_path / "missing.json"))
    assert not f.quiltify_rgbd(window, 8, 6, 48, 0.75, 1, 1, 14, 0, 0, 0, 0, 2, 1, 0, 0,
                               str(tmp_path / "missing.png").encode(), str(tmp_path / "q.png").encode())
    assert not f.save_image_to_file(window, str(tmp_path / "x.png").encode(), None, RGBA, 4, 4)
    assert not f.get_device_name(window, None, None)
    assert not hasattr(f, "not_a_bridge_function")
    # Still alive and still drawing.
    assert draw(window, tex, RGBA, 80, 60, 4, 3, 1.0, 1.0)


def test_quiltify_rgbd_writes_the_quilt_file(bridge, window, tmp_path):
    path = tmp_path / "photo.png"
    write_png(path, synthetic_rgbd(120, 160))
    out = tmp_path / "quilt.png"
    assert bridge.f.quiltify_rgbd(window, 8, 6, 48, 0.75, 1.0, 1.0, 14.0, 0.0, 0.0, 0, 0, 2, 1.5, 0.0, 0.0,
                                  str(path).encode(), str(out).encode())
    # The same views `lfd rgbd-quilt` makes for this display (the CPU reference both call).
    lfd("rgbd-quilt", path, tmp_path / "cli.png", "--calibration", CALIBRATION, "--views", 48, "--depthiness", 1.5)
    [cli] = list(tmp_path.glob("cli_qs8x6a*.png"))
    assert psnr(out, cli) >= 60
    saved = tmp_path / "image.png"
    pixels = np.zeros((4, 6, 3), np.uint8)
    assert bridge.f.save_image_to_file(window, str(saved).encode(), pixels.ctypes.data_as(c_void_p), 0x1907, 6, 4)
    assert saved.stat().st_size > 0


def test_show_window_hides_and_shows(bridge, window):
    assert bridge.f.show_window(window, False)
    assert bridge.f.show_window(window, True)


def test_unregister_keeps_the_vendors_entries(home, bridge):
    lfd("bridge", "unregister")
    py = json.loads((home / ".config" / "LookingGlass" / "Bridge" / "settings.json").read_text())
    assert [e["version"] for e in py["install_locations"]] == ["2.5.1"]
    assert py["enable_utilization_telemetry"] is False
    native = json.loads((home / ".lgf" / "Bridge" / "settings.json").read_text())
    assert [e["version"] for e in native["install_locations"]] == ["2.6.0"]
    assert (home / ".lgf" / "bridge_install_locations").read_text() == "/opt/vendor/Bridge-2.4.9\n"
    assert not json.loads(lfd("bridge", "status", "--json").stdout)["registered"]
