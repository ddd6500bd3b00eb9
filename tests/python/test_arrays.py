"""Arrays of a wrong shape, dtype or with NaN raise ValueError naming the argument and what was
expected; a torch tensor (through DLPack) renders as its numpy twin."""
import threading
import time

import numpy as np
import pytest

import lfd
from conftest import scene_arrays


def with_(arrays, **changes):
    out = dict(arrays)
    out.update(changes)
    return out


@pytest.mark.parametrize("name, bad, message", [
    ("means", np.zeros((150, 2), np.float32), r"^means: shape \(150, 2\), expected \(N, 3\)$"),
    ("rotations", np.zeros((150, 3), np.float32), r"^rotations: shape \(150, 3\), expected \(N, 4\)$"),
    ("sh", np.zeros((150, 3), np.float32), r"^sh: shape \(150, 3\), expected \(N, K, 3\)$"),
    ("sh", np.zeros((150, 5, 3), np.float32), r"^sh: 5 coefficients per colour; expected 1, 4, 9 or 16"),
    ("log_scales", np.zeros((149, 3), np.float32), r"^log_scales: N = 149 but means has N = 150$"),
    ("means", np.zeros((150, 3), np.int32), r"^means: dtype int32 is not floating point"),
    ("opacity_logits", np.array(["a"] * 150), r"^opacity_logits: dtype <U1 is not floating point"),
])
def test_wrong_shape_or_dtype_names_the_argument(arrays, name, bad, message):
    with pytest.raises(ValueError, match=message):
        lfd.Gaussians(**with_(arrays, **{name: bad}))


def test_nan_names_the_argument_and_the_row(arrays):
    means = arrays["means"].copy()
    means[7, 1] = np.nan
    with pytest.raises(ValueError, match=r"^means: element \[7\] \(nan\) is NaN$"):
        lfd.Gaussians(**with_(arrays, means=means))


def test_missing_and_mixed_conventions_are_refused(arrays):
    with pytest.raises(ValueError, match=r"^sh: required"):
        lfd.Gaussians(**{k: v for k, v in arrays.items() if k != "sh"})
    with pytest.raises(ValueError, match=r"^scales: given with activated=False"):
        lfd.Gaussians(**with_(arrays, scales=np.ones((150, 3), np.float32)))
    with pytest.raises(ValueError, match=r"^opacities: \[0\] = .* is outside \[0, 1\]"):
        lfd.Gaussians(means=arrays["means"], scales=np.ones((150, 3)), rotations=arrays["rotations"],
                      opacities=np.full(150, 3.0), sh=arrays["sh"], activated=True)


def test_render_settings_are_checked_with_their_keyword(arrays):
    g = lfd.Gaussians(**arrays)
    with pytest.raises(ValueError, match=r"^views: 300 is outside 1..256$"):
        lfd.render_quilt(g, views=300)
    with pytest.raises(ValueError, match=r"^view_cone: 200 must lie in \(0, 170\) degrees$"):
        lfd.render_quilt(g, view_cone=200.0)
    with pytest.raises(ValueError, match=r"^cols: needs rows too$"):
        lfd.render_quilt(g, cols=3)
    with pytest.raises(ValueError, match=r"^filter: 'cubic' is not one of nearest, bilinear$"):
        lfd.render_quilt(g, filter="cubic")
    with pytest.raises(ValueError, match=r"^camera: "):
        lfd.render_quilt(g, camera={"position": [0, 0]})
    with pytest.raises(ValueError, match=r"^split_levels, no_plane_lowpass: V2LF options"):
        lfd.render_quilt(g, split_levels=1)
    with pytest.raises(lfd.InputError, match=r"^precision: f16 .* needs the GL backend"):
        lfd.render_quilt(g, precision="f16")
    with pytest.raises(ValueError, match=r"^raster: chooses how the GL backend draws; the CPU backend has no"):
        lfd.render_quilt(g, raster="compute")
    with pytest.raises(ValueError, match=r"^raster: 'fast' is not one of hardware, compute, auto$"):
        lfd.render_quilt(g, raster="fast", backend="gl")


def test_bad_files_raise_lfd_s_one_line_message(tmp_path):
    (tmp_path / "bad.ply").write_bytes(b"ply\nformat ascii 1.0\nend_header\n")
    with pytest.raises(ValueError, match=str(tmp_path / "bad.ply")):
        lfd.Gaussians.load(tmp_path / "bad.ply")
    with pytest.raises(ValueError, match="missing.json"):
        lfd.Display.load(tmp_path / "missing.json")


def test_torch_tensor_renders_as_its_numpy_twin(arrays):
    torch = pytest.importorskip("torch", reason="python3-torch (scripts/install-test-deps.sh)")
    tensors = {k: torch.from_numpy(v.copy()).requires_grad_(k != "sh") for k, v in arrays.items()}
    settings = dict(views=4, cols=2, rows=2, size=(32, 32), chunks=8)
    from_torch = lfd.render_quilt(lfd.Gaussians(**tensors), **settings)
    from_numpy = lfd.render_quilt(lfd.Gaussians(**arrays), **settings)
    assert np.array_equal(from_torch.image, from_numpy.image)
    with pytest.raises(ValueError, match=r"^means: shape \(150, 2\), expected \(N, 3\)$"):
        lfd.Gaussians(**with_(tensors, means=torch.zeros(150, 2)))
    with pytest.raises(ValueError, match=r"^means: dtype int64 is not floating point"):
        lfd.Gaussians(**with_(tensors, means=torch.zeros(150, 3, dtype=torch.int64)))


def test_dlpack_without_torch_reads_numpy_s_own_export(arrays):
    class DlpackOnly:  # what a tensor library offers that numpy cannot read directly
        def __init__(self, a):
            self.a = a

        def __dlpack__(self, stream=None):
            return self.a.__dlpack__()

        def __dlpack_device__(self):
            return self.a.__dlpack_device__()

    wrapped = lfd.Gaussians(**{k: DlpackOnly(v) for k, v in arrays.items()})
    np.testing.assert_array_equal(wrapped.means, lfd.Gaussians(**arrays).means)


def test_the_gil_is_released_while_rendering():
    g = lfd.Gaussians(**scene_arrays(count=3000, degree=0))
    ticks = []
    started = threading.Event()
    done = threading.Event()

    def render():
        started.set()
        lfd.render_quilt(g, views=16, size=(160, 160), method="per-view")
        done.set()

    thread = threading.Thread(target=render)
    thread.start()
    started.wait()
    # A render that held the GIL would keep this thread from running until it returned (C++
    # code never hands the GIL over by itself): no tick. Released, this thread ticks meanwhile.
    while not done.is_set():
        ticks.append(time.monotonic())
        time.sleep(0.001)
    thread.join()
    assert ticks, "this thread did not run while the render did"
