#!/usr/bin/env python3
"""Renders every scene of a folder into a quilt for a display (or lfd's defaults without one).

    python3 render_folder.py scenes/ quilts/ --calibration visual.json [--method g2lf] [--views 45]

Each scene (any format lfd reads: .ply, .splat, .spz, .sog, .glb, .ksplat, .voxels) becomes
quilts/<name>_qsCxRaA.png; a file lfd cannot read is reported with lfd's one-line reason and
skipped. The keywords of lfd.render_quilt are `lfd render`'s flags.
"""
import argparse
import sys
from pathlib import Path

import lfd

SCENE_SUFFIXES = {".ply", ".splat", ".spz", ".sog", ".glb", ".gltf", ".ksplat", ".voxels"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--calibration", help="visual.json or calibration.json")
    parser.add_argument("--method", help="g2lf (v2lf for voxels) or per-view")
    parser.add_argument("--views", type=int)
    parser.add_argument("--size", help="WxH of one view")
    parser.add_argument("--backend", default="cpu", help="cpu, gl or auto")
    args = parser.parse_args()

    display = lfd.Display.load(args.calibration) if args.calibration else None
    size = tuple(int(v) for v in args.size.split("x")) if args.size else None
    args.out.mkdir(parents=True, exist_ok=True)
    failed = 0
    for path in sorted(p for p in args.folder.iterdir() if p.suffix.lower() in SCENE_SUFFIXES):
        try:
            scene = lfd.load(path)
            quilt = lfd.render_quilt(scene, display, method=args.method, views=args.views, size=size,
                                     backend=args.backend)
        except lfd.InputError as error:
            print(f"skipped: {error}", file=sys.stderr)
            failed += 1
            continue
        written = quilt.save(str(args.out / (path.stem + ".png")))
        print(f"{path.name}: {len(scene)} {scene.kind}, {quilt.views} views -> {written}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
