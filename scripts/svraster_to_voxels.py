#!/usr/bin/env python3
"""Convert an SVRaster checkpoint (NVlabs/svraster) to lfd's .voxels file (docs/voxels.md, "Files").

    python3 scripts/svraster_to_voxels.py RUN/checkpoints/iter020000_model.pt --out scene.voxels
        [--config RUN/config.yaml]

The checkpoint is the dict SVRaster's `SVInOut.save` writes with torch.save: `octpath` (int64,
[N, 1]) and `octlevel` (int8, [N, 1]) per voxel, `_geo_grid_pts` ([M, 1] raw densities, one per
grid point shared between neighbours), `_sh0` ([N, 3]) and `_shs` ([N, (d+1)^2 - 1, 3]),
`scene_center`, `inside_extent`, `scene_extent`, `active_sh_degree` and `quantized` (then the
geometry and SH are 256-entry codebooks with uint8 indices). The run's config.yaml (beside
checkpoints/ by default) gives `model.ss`, `model.n_samp_per_vox` and
`model.white_background`.

Only `load_checkpoint` needs torch (users with a trained model have it); the conversion works on
numpy arrays, so it is tested without torch (tests/voxel/svraster_fixture.py).

The .voxels layout is docs/file-formats.md ("Sparse-voxel scenes"), the one voxel/voxel_file.cpp
reads: little-endian header, then per voxel u32 index x, y, z, u32 level, f32 density[8] (corner
i at x = bit 2, y = bit 1, z = bit 0), f32 SH[(d+1)^2][3].
"""
import argparse
import os
import struct
import sys

import numpy as np

MAX_NUM_LEVELS = 16  # svraster cuda/src/config.h
MAGIC = b"LFDVOXEL"
VERSION = 1


def octpath_to_ijk(octpath, octlevel):
    """Integer voxel coordinates at each voxel's own level (svraster utils.cu octpath_2_ijk_cuda):
    level l's octant sits in bits 3 (MAX - l) .. 3 (MAX - l) + 2 of the path, x in its high bit."""
    path = np.asarray(octpath, dtype=np.int64).reshape(-1)
    level = np.asarray(octlevel, dtype=np.int64).reshape(-1)
    path = path >> (3 * (MAX_NUM_LEVELS - level))
    ijk = np.zeros((len(path), 3), dtype=np.int64)
    for bit in range(MAX_NUM_LEVELS):
        octant = (path >> (3 * bit)) & 0b111
        ijk[:, 0] |= ((octant >> 2) & 1) << bit
        ijk[:, 1] |= ((octant >> 1) & 1) << bit
        ijk[:, 2] |= (octant & 1) << bit
    return ijk


def corner_keys(ijk, octlevel):
    """The 8 grid points of each voxel as integer positions at the finest level, corner i at
    (bit 2, bit 1, bit 0) = (x, y, z) (octree_utils.gen_gridpoints_coordinate)."""
    level = np.asarray(octlevel, dtype=np.int64).reshape(-1, 1, 1)
    shift = MAX_NUM_LEVELS - level
    corners = np.array([[(c >> 2) & 1, (c >> 1) & 1, c & 1] for c in range(8)], dtype=np.int64)
    return (ijk.reshape(-1, 1, 3) << shift) + (corners.reshape(1, 8, 3) << shift)


def gather_corner_densities(ijk, octlevel, geo_grid_pts):
    """Each voxel's 8 raw densities. SVRaster numbers its grid points by
    torch.unique(corner keys, dim=0) (octree_utils.build_grid_pts_link): sorted rows, which
    numpy's unique(axis=0) reproduces, and vox_key is the inverse index."""
    keys = corner_keys(ijk, octlevel).reshape(-1, 3)
    unique, vox_key = np.unique(keys, axis=0, return_inverse=True)
    grid = np.asarray(geo_grid_pts, dtype=np.float32).reshape(-1)
    if len(unique) != len(grid):
        raise ValueError(f"_geo_grid_pts: {len(grid)} values, but the voxels have {len(unique)} grid points")
    return grid[vox_key.reshape(-1)].reshape(-1, 8)


def dequantize(value):
    """SVRaster's quantized tensors: dict(index=uint8, codebook=float[256]) (io.py)."""
    return np.asarray(value["codebook"], dtype=np.float32)[np.asarray(value["index"]).astype(np.int64)]


def dequantize_checkpoint(ckpt):
    """io.dequantize_state_dict on numpy: _sh0 and _shs were quantized per column of dim 1."""
    out = dict(ckpt)
    out["_geo_grid_pts"] = dequantize(ckpt["_geo_grid_pts"])
    out["_sh0"] = np.concatenate([dequantize(v) for v in ckpt["_sh0"]], axis=1)
    out["_shs"] = np.concatenate([dequantize(v) for v in ckpt["_shs"]], axis=1)
    return out


def convert(ckpt, config=None):
    """The .voxels bytes of a checkpoint given as numpy arrays (and lists of dicts when
    quantized). `config`: the run's config as nested dicts (its `model` section)."""
    if ckpt.get("quantized", False):
        ckpt = dequantize_checkpoint(ckpt)
    model = (config or {}).get("model", {})
    octlevel = np.asarray(ckpt["octlevel"]).reshape(-1).astype(np.int64)
    n = len(octlevel)
    if n and (octlevel.min() < 0 or octlevel.max() > MAX_NUM_LEVELS):
        raise ValueError(f"octlevel: levels {octlevel.min()}..{octlevel.max()} outside 0..{MAX_NUM_LEVELS}")
    ijk = octpath_to_ijk(ckpt["octpath"], octlevel)
    density = gather_corner_densities(ijk, octlevel, ckpt["_geo_grid_pts"])
    sh0 = np.asarray(ckpt["_sh0"], dtype=np.float32).reshape(n, 1, 3)
    shs = np.asarray(ckpt["_shs"], dtype=np.float32).reshape(n, -1, 3)
    degree = int(ckpt.get("active_sh_degree", round(np.sqrt(shs.shape[1] + 1)) - 1))
    if not 0 <= degree <= 3 or shs.shape[1] < (degree + 1) ** 2 - 1:
        raise ValueError(f"active_sh_degree: {degree} does not fit _shs with {shs.shape[1]} coefficients")
    sh = np.concatenate([sh0, shs[:, : (degree + 1) ** 2 - 1]], axis=1)  # coefficient-major, RGB innermost

    center = np.asarray(ckpt["scene_center"], dtype=np.float32).reshape(3)
    extent = float(np.asarray(ckpt["scene_extent"], dtype=np.float32).reshape(-1)[0])
    ss = float(model.get("ss", 1.5))
    samples = int(model.get("n_samp_per_vox", 1))
    white = bool(model.get("white_background", False))
    background = [1.0, 1.0, 1.0] if white else [0.0, 0.0, 0.0]  # SVRaster's bg_color

    header = MAGIC + struct.pack("<IIQ3fffI3f", VERSION, degree, n, *center, extent, ss, samples, *background)
    record = np.dtype([("index", "<u4", 3), ("level", "<u4"), ("density", "<f4", 8),
                       ("sh", "<f4", ((degree + 1) ** 2) * 3)])
    body = np.empty(n, dtype=record)
    body["index"] = ijk
    body["level"] = octlevel
    body["density"] = density
    body["sh"] = sh.reshape(n, -1)
    return header + body.tobytes()


def parse_config(text):
    """The run's config.yaml (yacs CfgNode.dump): PyYAML when installed, else the flat
    `section:` / `  key: value` subset that dump writes for scalars."""
    try:
        import yaml
        return yaml.safe_load(text) or {}
    except ImportError:
        pass
    config, section = {}, None
    for line in text.splitlines():
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        key, _, value = line.strip().partition(":")
        if not line.startswith(" "):
            section = config.setdefault(key, {})
        elif section is not None and line.startswith("  ") and not line.startswith("   "):
            value = value.strip()
            lowered = value.lower()
            if lowered in ("true", "false"):
                section[key] = lowered == "true"
            else:
                try:
                    section[key] = float(value) if any(c in value for c in ".e") else int(value)
                except ValueError:
                    section[key] = value
    return config


def load_checkpoint(path):
    """The thin torch front: torch.load, tensors to numpy."""
    import torch

    def to_numpy(v):
        if torch.is_tensor(v):
            return v.detach().cpu().numpy()
        if isinstance(v, dict):
            return {k: to_numpy(x) for k, x in v.items()}
        if isinstance(v, (list, tuple)):
            return [to_numpy(x) for x in v]
        return v

    return to_numpy(torch.load(path, map_location="cpu", weights_only=False))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("checkpoint", help="SVRaster checkpoint (.pt, torch.save dict)")
    parser.add_argument("--config", help="the run's config.yaml (default: beside checkpoints/)")
    parser.add_argument("--out", required=True, help="output .voxels file")
    args = parser.parse_args(argv)
    config_path = args.config or os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(args.checkpoint))),
                                               "config.yaml")
    config = {}
    if os.path.exists(config_path):
        with open(config_path) as f:
            config = parse_config(f.read())
    elif args.config:
        sys.exit(f"{args.config}: not found")
    else:
        print(f"no {config_path}: ss 1.5, 1 sample per voxel, black background", file=sys.stderr)
    try:
        ckpt = load_checkpoint(args.checkpoint)
    except ImportError:
        print(f"{args.checkpoint}: reading a torch checkpoint needs torch (pip install torch)", file=sys.stderr)
        return 2
    try:
        data = convert(ckpt, config)
    except KeyError as e:
        print(f"{args.checkpoint}: {e.args[0]}: missing", file=sys.stderr)
        return 2
    except ValueError as e:
        print(f"{args.checkpoint}: {e}", file=sys.stderr)
        return 2
    with open(args.out, "wb") as f:
        f.write(data)
    print(f"wrote {args.out} ({struct.unpack_from('<Q', data, 16)[0]} voxels)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
