"""lfd: lenticular light field displays from Python (docs/python.md).

    import lfd
    display = lfd.Display.load("visual.json")          # or lfd.Display.from_device("auto")
    scene = lfd.Gaussians.load("scene.ply")            # or lfd.Gaussians(means=..., ...)
    quilt = lfd.render_quilt(scene, display)           # `lfd render`'s flags as keywords
    quilt.save("scene.png")                            # -> scene_qs8x6a0.75.png
    panel = lfd.interlace(quilt, display)              # the panel image, H x W x 3 uint8
    window = lfd.Window(display)                       # the display's window (or its simulation)
    window.update(scene)                               # returns at once; rendered and shown

Arrays are numpy arrays or CPU torch tensors (read through DLPack); bad input raises
lfd.InputError, a ValueError, with lfd's one-line message naming the argument.
"""
import atexit as _atexit
import weakref as _weakref

from . import _lfd
from ._lfd import (Display, GlUnavailable, Gaussians, InputError, Quilt, Scene, Voxels,
                   __version__, load)

__all__ = ["Display", "Gaussians", "Voxels", "Scene", "Quilt", "Window", "InputError",
           "GlUnavailable", "load", "render_quilt", "render_view", "interlace", "show"]

_DEFAULTS = _lfd.render_defaults()


def render_quilt(scene, display=None, *, method=None, backend="cpu", camera=None, views=None,
                 cols=None, rows=None, size=None, view_cone=None, orbit=_DEFAULTS["orbit"],
                 focal_distance=None, chunks=_DEFAULTS["chunks"],
                 plane_scale=_DEFAULTS["plane_scale"], shift=None, filter=None,
                 precision=_DEFAULTS["precision"], binning=_DEFAULTS["binning"],
                 split_levels=None, no_plane_lowpass=False, background=None, raster=None):
    """The quilt `lfd render` renders for the same flags, as an lfd.Quilt.

    Each keyword is the flag of the same name (--view-cone is view_cone, --size WxH is
    size=(W, H), --camera cam.json is camera={cam.json's fields}); None leaves the choice to
    the display (its views, grid, aspect and cone) or to lfd's defaults, as the flag left out
    does. method: "g2lf" (Gaussians) or "v2lf" (voxels) by default, or "per-view". backend:
    "cpu", "gl" (OpenGL 4.5, headless) or "auto". raster (GL, Gaussians): "hardware" (the
    default), "compute" or "auto", as --raster. The GIL is released while it renders.
    """
    settings = dict(method=method, camera=camera, views=views, cols=cols, rows=rows, size=size,
                    view_cone=view_cone, orbit=orbit, focal_distance=focal_distance,
                    chunks=chunks, plane_scale=plane_scale, shift=shift, filter=filter,
                    precision=precision, binning=binning, split_levels=split_levels,
                    no_plane_lowpass=no_plane_lowpass, background=background, raster=raster)
    return _lfd.render_quilt(scene, display, settings, backend)


def render_view(scene, view, display=None, *, backend="cpu", **settings):
    """One view (0 = the leftmost) of the quilt render_quilt would render, as `lfd render --view`:
    an H x W x 3 uint8 array. Takes render_quilt's keywords."""
    return _lfd.render_view(scene, view, display, settings, backend)


def interlace(quilt, display, *, blend="nearest", overscan=False, backend="cpu"):
    """The panel image of a quilt for a display, as `lfd interlace` writes it (H x W x 3 uint8)."""
    return _lfd.interlace(_as_quilt(quilt, display, None, None, None, None), display, blend,
                          overscan, backend)


def _as_quilt(content, display, cols, rows, aspect, views):
    """A Quilt, or an H x W x 3 uint8 array tiled as given or as the display asks."""
    if isinstance(content, Quilt):
        return content
    grid = display.quilt
    return Quilt(_lfd._as_numpy(content), cols or grid["cols"], rows or grid["rows"],
                 aspect if aspect is not None else grid["aspect"], views)


class Window:
    """The display's window: full screen on its monitor, or the simulated display in a window
    when that monitor is absent (or simulated=True). update() hands it a quilt, an array or a
    scene and returns at once; a scene is rendered on the window's own thread (the newest one
    handed over wins), so a training loop is never held up by the display."""

    def __init__(self, display, *, simulated=False, blend="nearest", overscan=False):
        self.display = display
        self._window = _lfd.Window(display, simulated, blend, overscan)
        _open_windows.add(self)

    def update(self, content, *, backend="cpu", **keywords):
        """Shows a Quilt, an H x W x 3 uint8 quilt array (tiled by the keywords cols, rows,
        aspect, views, else as the display asks) or a scene (rendered with render_quilt's
        keywords for the display). Returns at once."""
        if isinstance(content, Scene):
            self._window._render(content, self.display, keywords, backend)
            return self
        tiling = {k: keywords.pop(k, None) for k in ("cols", "rows", "aspect", "views")}
        if keywords:
            raise InputError(f"{next(iter(keywords))}: a render setting; only scenes are rendered")
        self._window._show_quilt(_as_quilt(content, self.display, **tiling))
        return self

    def wait(self):
        """Until what was handed over is on screen."""
        self._window.wait()
        return self

    def screenshot(self):
        """The next frame as shown (H x W x 3 uint8): the framebuffer when full screen on the
        display, else the panel."""
        return self._window.screenshot()

    @property
    def on_display(self):
        return self._window.on_display

    @property
    def is_open(self):
        return self._window.is_open

    def close(self):
        self._window.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


_open_windows = _weakref.WeakSet()
_shown = {}


def show(content, display=None, *, simulated=False, **keywords):
    """Shows content on a display's window, opened on first use and kept for the next call
    (display: the attached Looking Glass by default). Returns the Window."""
    if display is None:
        display = Display.from_device("auto")
    window = _shown.get(display.name)
    if window is None or not window.is_open:
        window = _shown[display.name] = Window(display, simulated=simulated)
    return window.update(content, **keywords)


@_atexit.register
def _close_all():
    for window in list(_open_windows):
        window.close()
    _lfd.release_gl_devices()
