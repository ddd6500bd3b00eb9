#!/usr/bin/env python3
"""Embeds a GLSL file in a C++ header (cmake/embed_shaders.cmake, docs/gpu.md "Shaders and their
contracts").

`#include "path"` lines (paths from the repository root, as in C++) are replaced by the file they
name, once per file however often it is included (the header contracts, `*_io.h`, are read by C++
too). Each file gets a source-string number: the text carries `#line N S` directives, so a driver's
error names the file and line, and its first line `//! files: a b ...` lists the files by number
for gpu::Program to translate. A Makefile depfile lists every file read, so Ninja re-embeds when an
included file changes.

    embed_shader.py ROOT INPUT OUTPUT SYMBOL DEPFILE
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"\s*$')


def main():
    root, source, output, symbol, depfile = sys.argv[1:6]
    files = []  # repository-relative paths, by source-string number
    out = []

    def expand(rel, including):
        if rel in files:
            return
        path = os.path.join(root, rel)
        if not os.path.isfile(path):
            sys.exit(f"{including}: #include \"{rel}\": no such file (paths are from the repository root)")
        number = len(files)
        files.append(rel)
        out.append(f"#line 1 {number}")
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        if lines and lines[-1] == "":
            lines.pop()
        for index, line in enumerate(lines):
            m = INCLUDE.match(line)
            if m:
                expand(m.group(1), f"{rel}:{index + 1}")
                out.append(f"#line {index + 2} {number}")
            elif line.lstrip().startswith("#version"):
                sys.exit(f"{rel}:{index + 1}: no #version in a shader file (gpu::Program adds it)")
            else:
                out.append(line)

    main_rel = os.path.relpath(os.path.abspath(source), os.path.abspath(root))
    expand(main_rel, main_rel)
    text = "//! files: " + " ".join(files) + "\n" + "\n".join(out) + "\n"
    if ")embedded\"" in text:
        sys.exit(f"{main_rel}: contains the raw-string delimiter )embedded\"")
    header = (f"// Generated from {main_rel} by cmake/embed_shader.py; edit the source files.\n"
              "#pragma once\n"
              f"inline constexpr char {symbol}[] = R\"embedded({text})embedded\";\n")
    os.makedirs(os.path.dirname(output), exist_ok=True)
    old = open(output, encoding="utf-8").read() if os.path.exists(output) else None
    if old != header:
        with open(output + ".tmp", "w", encoding="utf-8") as f:
            f.write(header)
        os.replace(output + ".tmp", output)
    with open(depfile, "w", encoding="utf-8") as f:
        deps = " ".join(os.path.join(root, rel).replace(" ", "\\ ") for rel in files)
        f.write(f"{output}: {deps}\n")


if __name__ == "__main__":
    main()
