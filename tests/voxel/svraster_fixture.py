#!/usr/bin/env python3
"""A synthetic SVRaster checkpoint, as numpy arrays, through scripts/svraster_to_voxels.py.

    svraster_fixture.py CONVERTER.py OUTDIR   -> OUTDIR/plain.voxels, OUTDIR/quantized.voxels

Written from SVRaster's conventions, not from the converter's code: the octree is the root's 8
children with child (1,1,1) split and its child (2,2,2) split again (7 + 7 + 8 = 22 leaves, in
a shuffled order); octpaths are encoded level by level from the root; grid points are numbered
in sorted order of their finest-level integer positions. Every grid value is
1 + 2x - 3y + 0.5z of its world position; _sh0 is the voxel centre; _shs coefficient k
(1-based), channel c holds 0.01 k + 0.1 c + level. active_sh_degree 2 of 3. The C++ side
(svraster_converter_test.cpp) reads the files back and checks exactly these.
"""
import importlib.util
import os
import sys

import numpy as np

CENTER = np.array([0.5, -1.0, 2.0], dtype=np.float32)
EXTENT = 4.0
CONFIG = """model:
  black_background: false
  n_samp_per_vox: 2
  sh_degree: 3
  ss: 1.25
  white_background: true
data:
  eval: true
"""


def leaves():
    out = [((i, j, k), 1) for i in (0, 1) for j in (0, 1) for k in (0, 1) if (i, j, k) != (1, 1, 1)]
    out += [((i, j, k), 2) for i in (2, 3) for j in (2, 3) for k in (2, 3) if (i, j, k) != (2, 2, 2)]
    out += [((i, j, k), 3) for i in (4, 5) for j in (4, 5) for k in (4, 5)]
    return out


def octpath(ijk, level):
    path = 0
    for l in range(1, level + 1):  # the octant taken at level l, from the root down
        bit = level - l
        octant = ((ijk[0] >> bit) & 1) << 2 | ((ijk[1] >> bit) & 1) << 1 | ((ijk[2] >> bit) & 1)
        path |= octant << (3 * (16 - l))
    return path


def density(p):
    return 1.0 + 2.0 * p[0] - 3.0 * p[1] + 0.5 * p[2]


def checkpoint():
    voxels = leaves()
    order = np.random.default_rng(7).permutation(len(voxels))
    voxels = [voxels[i] for i in order]
    n = len(voxels)
    keys = set()
    for ijk, level in voxels:
        s = 16 - level
        for c in range(8):
            keys.add(tuple((ijk[a] + ((c >> (2 - a)) & 1)) << s for a in range(3)))
    keys = sorted(keys)
    unit = EXTENT / 2**16
    grid = np.array([density(CENTER - EXTENT / 2 + unit * np.array(k)) for k in keys], dtype=np.float32)
    sh0 = np.zeros((n, 3), dtype=np.float32)
    shs = np.zeros((n, 15, 3), dtype=np.float32)
    for v, (ijk, level) in enumerate(voxels):
        size = EXTENT / 2**level
        sh0[v] = CENTER - EXTENT / 2 + (np.array(ijk) + 0.5) * size
        for k in range(15):
            shs[v, k] = [0.01 * (k + 1) + 0.1 * c + level for c in range(3)]
    return {
        "active_sh_degree": 2,
        "scene_center": CENTER.copy(),
        "inside_extent": np.array([EXTENT / 2], dtype=np.float32),
        "scene_extent": np.array([EXTENT], dtype=np.float32),
        "octpath": np.array([[octpath(ijk, level)] for ijk, level in voxels], dtype=np.int64),
        "octlevel": np.array([[level] for _, level in voxels], dtype=np.int8),
        "_geo_grid_pts": grid.reshape(-1, 1),
        "_sh0": sh0,
        "_shs": shs,
        "quantized": False,
    }


def quantize(values):
    """An exact codebook (at most 256 distinct values), in SVRaster's dict layout."""
    codebook, index = np.unique(values, return_inverse=True)
    assert len(codebook) <= 256
    return {"index": index.reshape(values.shape).astype(np.uint8),
            "codebook": np.pad(codebook, (0, 256 - len(codebook))).astype(np.float32)}


def quantized(ckpt):
    q = dict(ckpt)
    q["_geo_grid_pts"] = quantize(ckpt["_geo_grid_pts"])
    q["_sh0"] = [quantize(ckpt["_sh0"][:, i : i + 1]) for i in range(3)]
    q["_shs"] = [quantize(ckpt["_shs"][:, i : i + 1]) for i in range(15)]
    q["quantized"] = True
    return q


def main(converter_path, out_dir):
    spec = importlib.util.spec_from_file_location("svraster_to_voxels", converter_path)
    converter = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(converter)
    config = converter.parse_config(CONFIG)
    ckpt = checkpoint()
    with open(os.path.join(out_dir, "plain.voxels"), "wb") as f:
        f.write(converter.convert(ckpt, config))
    with open(os.path.join(out_dir, "quantized.voxels"), "wb") as f:
        f.write(converter.convert(quantized(ckpt), config))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
