#!/usr/bin/env python3
"""Prints docs/gpu.md's table of binding points ("Binding points") from the contract headers.

Every `LFD_IO_INT(k...Binding|Unit|Image, N)` in gpu/*/shaders/*_io.h, rgbd/, play/ and live/
shaders/*_io.h is a row: its kind (storage buffer, texture unit, image unit), point, name,
header, and the C++ files that name it (the passes that bind it). tests/gpu/binding_points_doc_test.cpp
checks the docs' table against the headers, so a new or moved point fails until the table is
regenerated:

    python3 scripts/binding-points-table.py   # from the repository root; paste over the table
"""
import glob
import os
import re

ROW = re.compile(r"LFD_IO_INT\((k\w+(Binding|Unit|Image)),\s*(\d+)\)")
KIND = {"Binding": "storage", "Unit": "texture", "Image": "image"}
HEADERS = ["gpu/*/shaders/*_io.h", "rgbd/shaders/*_io.h", "play/shaders/*_io.h", "live/shaders/*_io.h"]
SOURCES = ["gpu/*/*.cpp", "rgbd/*.cpp", "play/*.cpp", "live/*.cpp"]


def points():
    rows = []
    for pattern in HEADERS:
        for header in sorted(glob.glob(pattern)):
            with open(header, encoding="utf-8") as f:
                for name, suffix, point in ROW.findall(f.read()):
                    rows.append((KIND[suffix], int(point), name, header))
    return rows


def users(name):
    found = []
    for pattern in SOURCES:
        for source in sorted(glob.glob(pattern)):
            with open(source, encoding="utf-8") as f:
                if re.search(r"\b" + name + r"\b", f.read()):
                    found.append(os.path.splitext(source)[0])
    return found


def main():
    order = {"storage": 0, "image": 1, "texture": 2}
    print("| Point | Name | Contract header | Bound by |")
    print("|---|---|---|---|")
    for kind, point, name, header in sorted(points(), key=lambda r: (order[r[0]], r[1], r[2])):
        by = ", ".join(f"`{u}`" for u in users(name)) or "(none in C++)"
        print(f"| {kind} {point} | `{name}` | `{header}` | {by} |")


if __name__ == "__main__":
    main()
