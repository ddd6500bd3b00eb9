"""What the Bridge client tests share (docs/bridge-inproc.md "Tests"): the vendor Python SDK's way
of finding and binding libbridge_inproc, GL contexts through ctypes (a GLFW window's GLX context
and an EGL surfaceless one, the two kinds of caller the issue names), the screen of Xvfb read from
its -fbdir file, fixtures made with numpy, and PSNR by `lfd compare`."""
import ctypes
import json
import os
import re
import struct
import subprocess
import zlib
from ctypes import (POINTER, c_bool, c_char_p, c_float, c_int32, c_int64, c_uint, c_uint32, c_uint64, c_ulong,
                    c_void_p, c_wchar_p)
from pathlib import Path

import numpy as np

LFD = os.environ.get("LFD_EXE", "build/apps/lfd")
DATA = Path(os.environ.get("LFD_TEST_DATA_DIR", "tests/data"))
CALIBRATION = DATA / "calibrations" / "LKG-PORT-portrait.visual.json"
RGBA = 0x1908

# --- the SDK's rules ------------------------------------------------------------------------------

def ver_tuple(v):
    return tuple(int(p) for p in v.split("."))


def find_library_as_the_sdk_does(home, requested="2.6.0"):
    """settings.json's install_locations (>= 2.6.0), else the legacy list, the requested version or
    the highest of its major: what BridgeApi._bridge_install_location does."""
    found = {}
    settings = Path(home) / ".config" / "LookingGlass" / "Bridge" / "settings.json"
    if settings.is_file():
        for d in json.loads(settings.read_text()).get("install_locations", []):
            if ver_tuple(d["version"]) >= (2, 6, 0):
                found[d["version"]] = Path(d["path"])
    legacy = Path(home) / ".lgf" / "bridge_install_locations"
    if legacy.is_file():
        for line in legacy.read_text().splitlines():
            m = re.search(r"\d+\.\d+\.\d+", Path(line.strip()).name)
            if line.strip() and m and ver_tuple(m.group(0)) >= (2, 6, 0):
                found[m.group(0)] = Path(line.strip())
    if not found:
        return None
    if requested in found:
        return found[requested] / "libbridge_inproc.so"
    same = [v for v in found if v.split(".")[0] == requested.split(".")[0]]
    return found[max(same or found, key=ver_tuple)] / "libbridge_inproc.so"


# Every function the Python SDK binds at load, with its argument types (BridgeApi._bind_functions).
SDK_SIGNATURES = {
    "initialize_bridge": ([c_wchar_p], c_bool),
    "uninitialize_bridge": ([], c_bool),
    "instance_window_gl": ([POINTER(c_uint32), c_uint32], c_bool),
    "instance_offscreen_window_gl": ([POINTER(c_uint32), c_uint32], c_bool),
    "get_window_dimensions": ([c_uint32, POINTER(c_ulong), POINTER(c_ulong)], c_bool),
    "get_max_texture_size": ([c_uint32, POINTER(c_ulong)], c_bool),
    "set_interop_quilt_texture_gl": ([c_uint32, c_uint64, c_uint, c_ulong, c_ulong, c_ulong, c_ulong, c_float,
                                      c_float], c_bool),
    "draw_interop_quilt_texture_gl": ([c_uint32, c_uint64, c_uint, c_ulong, c_ulong, c_ulong, c_ulong, c_float,
                                       c_float], c_bool),
    "draw_interop_rgbd_texture_gl": ([c_uint32, c_uint64, c_uint, c_ulong, c_ulong, c_ulong, c_ulong, c_ulong,
                                      c_ulong, c_float, c_float, c_float, c_float, c_int32], c_bool),
    "save_texture_to_file_gl": ([c_uint32, c_char_p, c_uint64, c_uint, c_ulong], c_bool),
    "show_window": ([c_uint32, c_bool], c_bool),
    "get_offscreen_window_texture_gl": ([c_uint32, POINTER(c_uint64), POINTER(c_uint), POINTER(c_ulong),
                                         POINTER(c_ulong)], c_bool),
    "get_default_quilt_settings": ([c_uint32, POINTER(c_float), POINTER(c_int32), POINTER(c_int32),
                                    POINTER(c_int32), POINTER(c_int32)], c_bool),
    "get_display_for_window": ([c_uint32, POINTER(c_uint64)], c_bool),
    "get_device_type": ([c_uint32, POINTER(c_int32)], c_bool),
    "get_viewcone": ([c_uint32, POINTER(c_float)], c_bool),
    "get_invview": ([c_uint32, POINTER(c_int32)], c_bool),
    "get_ri": ([c_uint32, POINTER(c_int32)], c_bool),
    "get_bi": ([c_uint32, POINTER(c_int32)], c_bool),
    "get_tilt": ([c_uint32, POINTER(c_float)], c_bool),
    "get_displayaspect": ([c_uint32, POINTER(c_float)], c_bool),
    "get_fringe": ([c_uint32, POINTER(c_float)], c_bool),
    "get_subp": ([c_uint32, POINTER(c_float)], c_bool),
    "get_pitch": ([c_uint32, POINTER(c_float)], c_bool),
    "get_center": ([c_uint32, POINTER(c_float)], c_bool),
    "get_window_position": ([c_uint32, POINTER(c_int64), POINTER(c_int64)], c_bool),
    "get_calibration": ([c_uint32] + [POINTER(c_float)] * 3 + [POINTER(c_int32)] * 2 + [POINTER(c_float)] * 2
                        + [POINTER(c_int32), POINTER(c_float), POINTER(c_float), POINTER(c_int32),
                           POINTER(c_int32), c_void_p], c_bool),
    "get_device_name": ([c_uint32, POINTER(c_int32), c_void_p], c_bool),
    "get_device_serial": ([c_uint32, POINTER(c_int32), c_void_p], c_bool),
    "save_image_to_file": ([c_uint32, c_char_p, c_void_p, c_uint, c_ulong, c_ulong], c_bool),
    "quiltify_rgbd": ([c_uint32, c_ulong, c_ulong, c_ulong] + [c_float] * 6 + [c_ulong] * 3 + [c_float] * 3
                      + [c_char_p, c_char_p], c_bool),
    "get_displays": ([POINTER(c_int32), POINTER(c_uint64)], c_bool),
    "get_device_name_for_display": ([c_uint64, POINTER(c_int32), c_void_p], c_bool),
    "get_device_serial_for_display": ([c_uint64, POINTER(c_int32), c_void_p], c_bool),
    "get_dimensions_for_display": ([c_uint64, POINTER(c_ulong), POINTER(c_ulong)], c_bool),
    "get_device_type_for_display": ([c_uint64, POINTER(c_int32)], c_bool),
    "get_calibration_for_display": ([c_uint64] + [POINTER(c_float)] * 3 + [POINTER(c_int32)] * 2
                                    + [POINTER(c_float)] * 2 + [POINTER(c_int32), POINTER(c_float),
                                                                POINTER(c_float), POINTER(c_int32),
                                                                POINTER(c_int32), c_void_p], c_bool),
    "get_default_quilt_settings_for_display": ([c_uint64, POINTER(c_float), POINTER(c_int32), POINTER(c_int32),
                                                POINTER(c_int32), POINTER(c_int32)], c_bool),
    "get_window_position_for_display": ([c_uint64, POINTER(c_int64), POINTER(c_int64)], c_bool),
}
for _name, _type in {"get_invview_for_display": c_int32, "get_ri_for_display": c_int32,
                     "get_bi_for_display": c_int32, "get_tilt_for_display": c_float,
                     "get_displayaspect_for_display": c_float, "get_fringe_for_display": c_float,
                     "get_subp_for_display": c_float, "get_viewcone_for_display": c_float,
                     "get_center_for_display": c_float, "get_pitch_for_display": c_float}.items():
    SDK_SIGNATURES[_name] = ([c_uint64, POINTER(_type)], c_bool)

# bridge.h's others: the version, the offscreen window from a file, DirectX and Metal.
OTHER_EXPORTS = [
    "get_bridge_version", "instance_offscreen_window", "device_from_resource_dx", "release_device_dx",
    "instance_window_dx", "instance_offscreen_window_dx", "register_texture_dx", "unregister_texture_dx",
    "save_texture_to_file_dx", "draw_interop_quilt_texture_dx", "draw_interop_rgbd_texture_dx", "create_texture_dx",
    "release_texture_dx", "copy_texture_dx", "get_offscreen_window_texture_dx", "instance_window_metal",
    "instance_offscreen_window_metal", "create_metal_texture_with_iosurface", "copy_metal_texture",
    "release_metal_texture", "save_metal_texture_to_file", "draw_interop_quilt_texture_metal",
    "get_offscreen_window_texture_metal",
]


class Bridge:
    """The library with the SDK's bindings: `bridge.f.<name>(...)`."""

    def __init__(self, path):
        self.lib = ctypes.CDLL(str(path))
        for name, (args, ret) in SDK_SIGNATURES.items():
            fn = getattr(self.lib, name)
            fn.argtypes, fn.restype = args, ret
        self.lib.instance_offscreen_window.argtypes = [POINTER(c_uint32), c_ulong, c_ulong, c_wchar_p]
        self.lib.instance_offscreen_window.restype = c_bool
        self.lib.get_bridge_version.argtypes = [POINTER(c_ulong)] * 3 + [POINTER(c_int32), c_void_p]
        self.lib.get_bridge_version.restype = c_bool
        self.f = self.lib

    def scalar(self, name, handle, ctype):
        v = ctype()
        assert getattr(self.f, name)(handle, ctypes.byref(v)), name
        return v.value

    def wide(self, name, handle):
        n = c_int32(0)
        assert getattr(self.f, name)(handle, ctypes.byref(n), None)
        buf = ctypes.create_unicode_buffer(n.value)
        assert getattr(self.f, name)(handle, ctypes.byref(n), ctypes.cast(buf, c_void_p))
        return buf.value

# --- GL through ctypes ------------------------------------------------------------------------------

GLFW_VISIBLE = 0x00020004
EGL_PLATFORM_SURFACELESS_MESA = 0x31DD


def _gl():
    for name in ("libOpenGL.so.0", "libGL.so.1"):
        try:
            return ctypes.CDLL(name)
        except OSError:
            pass
    raise OSError("no libOpenGL/libGL")


GL = _gl()


class GlfwContext:
    """A hidden 1x1 GLFW window's context (GLX on X11), current on this thread."""

    def __init__(self):
        self.glfw = ctypes.CDLL("libglfw.so.3")
        self.glfw.glfwCreateWindow.restype = c_void_p
        self.glfw.glfwCreateWindow.argtypes = [ctypes.c_int, ctypes.c_int, c_char_p, c_void_p, c_void_p]
        self.glfw.glfwMakeContextCurrent.argtypes = [c_void_p]
        self.glfw.glfwGetCurrentContext.restype = c_void_p
        assert self.glfw.glfwInit()
        self.glfw.glfwWindowHint(GLFW_VISIBLE, 0)
        self.window = self.glfw.glfwCreateWindow(16, 16, b"client", None, None)
        assert self.window
        self.make_current()

    def make_current(self):
        self.glfw.glfwMakeContextCurrent(self.window)

    def release(self):
        self.glfw.glfwMakeContextCurrent(None)


class EglContext:
    """An OpenGL context on Mesa's surfaceless EGL platform, current on this thread."""

    def __init__(self):
        egl = ctypes.CDLL("libEGL.so.1")
        self.egl = egl
        egl.eglGetProcAddress.restype = c_void_p
        egl.eglGetProcAddress.argtypes = [c_char_p]
        get_platform_display = ctypes.CFUNCTYPE(c_void_p, c_uint, c_void_p, c_void_p)(
            egl.eglGetProcAddress(b"eglGetPlatformDisplayEXT"))
        self.display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, None, None)
        assert self.display
        egl.eglInitialize.argtypes = [c_void_p, c_void_p, c_void_p]
        assert egl.eglInitialize(self.display, None, None)
        assert egl.eglBindAPI(0x30A2)  # EGL_OPENGL_API
        # Mesa's surfaceless platform has EGL_KHR_no_config_context: no config is needed.
        egl.eglCreateContext.restype = c_void_p
        egl.eglCreateContext.argtypes = [c_void_p, c_void_p, c_void_p, c_void_p]
        self.context = egl.eglCreateContext(self.display, None, None, None)
        assert self.context
        egl.eglMakeCurrent.argtypes = [c_void_p, c_void_p, c_void_p, c_void_p]
        self.make_current()

    def make_current(self):
        assert self.egl.eglMakeCurrent(self.display, None, None, self.context)

    def release(self):
        self.egl.eglMakeCurrent(self.display, None, None, None)


def make_texture(rgb_top_down):
    """A GL_TEXTURE_2D of the current context from an HxWx3 uint8 image (GL rows bottom-up)."""
    h, w, _ = rgb_top_down.shape
    rgba = np.dstack([rgb_top_down[::-1], np.full((h, w, 1), 255, np.uint8)]).copy()
    tex = c_uint32(0)
    GL.glGenTextures(1, ctypes.byref(tex))
    GL.glBindTexture(0x0DE1, tex)
    GL.glPixelStorei(0x0CF5, 1)
    GL.glTexImage2D(0x0DE1, 0, 0x8058, w, h, 0, 0x1908, 0x1401, rgba.ctypes.data_as(c_void_p))
    GL.glTexParameteri(0x0DE1, 0x2801, 0x2601)
    GL.glFinish()
    return tex.value


def read_texture(name, w, h):
    """An HxWx3 top-down image of texture `name` of the current context."""
    out = np.zeros((h, w, 4), np.uint8)
    GL.glBindTexture(0x0DE1, name)
    GL.glPixelStorei(0x0D05, 1)
    GL.glGetTexImage(0x0DE1, 0, 0x1908, 0x1401, out.ctypes.data_as(c_void_p))
    return out[::-1, :, :3].copy()

# --- images -----------------------------------------------------------------------------------------

def write_png(path, rgb):
    h, w, _ = rgb.shape
    raw = np.hstack([np.zeros((h, 1), np.uint8), rgb.reshape(h, w * 3)]).tobytes()

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                           + chunk(b"IDAT", zlib.compress(raw, 1)) + chunk(b"IEND", b""))


def read_screen(fbdir, w, h):
    """The top-left w x h of Xvfb's screen 0 (its -fbdir XWD file), HxWx3 top-down."""
    data = (Path(fbdir) / "Xvfb_screen0").read_bytes()
    order = ">" if struct.unpack(">I", data[:4])[0] < 65536 else "<"
    hd = struct.unpack(order + "25I", data[:100])
    header, width, height, byte_order, bpp, line = hd[0], hd[4], hd[5], hd[7], hd[11], hd[12]
    assert bpp == 32, f"{bpp} bits per pixel"
    start = header + 12 * hd[19]
    px = np.frombuffer(data, np.uint8, height * line, start).reshape(height, line)[:, :width * 4]
    px = px.copy().view("<u4" if byte_order == 0 else ">u4").reshape(height, width)
    out = np.zeros((height, width, 3), np.uint8)
    for c, mask in enumerate(hd[14:17]):
        shift = (mask & -mask).bit_length() - 1
        out[:, :, c] = (px & mask) >> shift
    return out[:h, :w]


def psnr(a_png, b_png):
    out = subprocess.run([LFD, "compare", str(a_png), str(b_png), "--json"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    v = json.loads(out.stdout)["psnr_db"]
    return 99.0 if v is None else v


def lfd(*args):
    out = subprocess.run([LFD, *map(str, args)], capture_output=True, text=True)
    assert out.returncode == 0, f"lfd {' '.join(map(str, args))}: {out.stderr}"
    return out


def synthetic_quilt(cols, rows, tile_w, tile_h):
    """A quilt whose views differ (a bar that moves with the view over smooth gradients), top-down."""
    quilt = np.zeros((rows * tile_h, cols * tile_w, 3), np.uint8)
    yy, xx = np.mgrid[0:tile_h, 0:tile_w]
    for v in range(cols * rows):
        tile = np.zeros((tile_h, tile_w, 3), np.float64)
        tile[..., 0] = 40 + 160 * xx / tile_w
        tile[..., 1] = 40 + 160 * yy / tile_h
        tile[..., 2] = 30 + 180 * v / (cols * rows)
        bar = np.abs(xx - (0.2 + 0.6 * v / (cols * rows)) * tile_w) < tile_w * 0.06
        tile[bar] = (250, 240, 60)
        r, c = v // cols, v % cols
        y0 = (rows - 1 - r) * tile_h  # view 0 bottom-left
        quilt[y0:y0 + tile_h, c * tile_w:(c + 1) * tile_w] = tile.round().astype(np.uint8)
    return quilt


def synthetic_rgbd(w, h):
    """Colour left, depth right (a bump near the middle), top-down."""
    yy, xx = np.mgrid[0:h, 0:w]
    colour = np.dstack([60 + 150 * xx / w, 60 + 150 * yy / h, 120 + 60 * np.sin(xx / 9.0)])
    d = np.clip(1.2 - np.hypot((xx - w / 2) / (w / 3), (yy - h / 2) / (h / 3)), 0, 1) * 255
    depth = np.dstack([d, d, d])
    return np.hstack([colour, depth]).round().astype(np.uint8)
