"""Shared fixtures of the Python package's tests: a small Gaussian scene as arrays and the same
scene as a 3DGS PLY written by hand (numpy), the `lfd` program, the test calibrations."""
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

DATA = Path(os.environ.get("LFD_TEST_DATA_DIR", Path(__file__).parents[1] / "data"))
LFD = os.environ.get("LFD_EXE", "build/apps/lfd")
PORTRAIT = DATA / "calibrations" / "LKG-PORT-portrait.visual.json"


def run_lfd(*args):
    """Runs the program; returns its output, failing the test with it on a non-zero exit."""
    result = subprocess.run([LFD, *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


def scene_arrays(count=150, degree=1, seed=3):
    """Gaussians in a 2 x 2 x 1 box in the 3DGS PLY's stored convention: log scales, opacity
    logits, unnormalised (w, x, y, z) rotations, SH N x K x 3 with the DC first."""
    rng = np.random.default_rng(seed)
    k = (degree + 1) ** 2
    return dict(
        means=rng.uniform([-1, -1, -0.5], [1, 1, 0.5], (count, 3)).astype(np.float32),
        log_scales=np.log(rng.uniform(0.03, 0.15, (count, 3))).astype(np.float32),
        rotations=rng.normal(size=(count, 4)).astype(np.float32),
        opacity_logits=rng.uniform(-1, 3, count).astype(np.float32),
        sh=(rng.normal(size=(count, k, 3)) * np.r_[1.0, [0.3] * (k - 1)][None, :, None]).astype(np.float32),
    )


def write_3dgs_ply(path, a):
    """The arrays as the 3DGS trainer writes them: f_rest channel-major, opacity (N, 1)."""
    n, k, _ = a["sh"].shape
    rest = a["sh"][:, 1:, :].transpose(0, 2, 1).reshape(n, -1)  # [gaussian][channel][coefficient]
    columns = [a["means"], np.zeros((n, 3), np.float32), a["sh"][:, 0, :], rest,
               a["opacity_logits"].reshape(n, 1), a["log_scales"], a["rotations"]]
    names = (["x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"]
             + [f"f_rest_{i}" for i in range(rest.shape[1])]
             + ["opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3"])
    body = np.ascontiguousarray(np.concatenate(columns, axis=1), dtype="<f4")
    header = "ply\nformat binary_little_endian 1.0\nelement vertex %d\n" % n
    header += "".join(f"property float {name}\n" for name in names) + "end_header\n"
    Path(path).write_bytes(header.encode() + body.tobytes())


@pytest.fixture(scope="session")
def arrays():
    return scene_arrays()


@pytest.fixture(scope="session")
def scene_file(tmp_path_factory, arrays):
    path = tmp_path_factory.mktemp("scene") / "gaussians.ply"
    write_3dgs_ply(path, arrays)
    return path


def read_png(path):
    """A PNG as an H x W x 3 uint8 array, through the package (lfd's own reader)."""
    import lfd
    return lfd.Quilt.load(path, cols=1, rows=1).image.copy()
