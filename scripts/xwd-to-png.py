#!/usr/bin/env python3
"""Converts a 24/32-bit TrueColor XWD image (an X screen: `Xvfb -fbdir DIR` keeps one in
DIR/Xvfb_screen0, or `xwd -root`) to an RGB PNG, with the standard library only, so a
screenshot of the viewer under Xvfb needs neither xwd nor ImageMagick.

    scripts/xwd-to-png.py SCREEN.xwd OUT.png [--part X,Y,W,H[/K] ...]

Without --part: the whole screen. Each --part is a rectangle of the screen, shrunk K times
(box average) when /K is given; parts go left to right, top-aligned, 8 px apart. An interlaced
panel is noise to a PNG coder: shrinking the display window's part keeps a README figure small.
"""
import struct
import sys
import zlib


def read_xwd(path):
    data = open(path, "rb").read()
    order = ">" if struct.unpack(">I", data[:4])[0] < 65536 else "<"
    h = struct.unpack(order + "25I", data[:100])
    header_size, width, height = h[0], h[4], h[5]
    byte_order, bits_per_pixel, bytes_per_line = h[7], h[11], h[12]
    masks, ncolors = h[14:17], h[19]
    if bits_per_pixel not in (24, 32):
        sys.exit(f"{path}: {bits_per_pixel} bits per pixel (expected a 24/32-bit TrueColor screen)")
    start = header_size + 12 * ncolors
    bpp = bits_per_pixel // 8
    shifts = [(m & -m).bit_length() - 1 for m in masks]
    endian = "little" if byte_order == 0 else "big"
    rows = []
    for y in range(height):
        line = data[start + y * bytes_per_line:start + y * bytes_per_line + width * bpp]
        out = bytearray(width * 3)
        for x in range(width):
            p = int.from_bytes(line[x * bpp:(x + 1) * bpp], endian)
            out[3 * x:3 * x + 3] = bytes((p & m) >> s for m, s in zip(masks, shifts))
        rows.append(bytes(out))
    return width, height, rows


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    # Filter "Sub" (each byte minus the one a pixel to the left): flat UI areas become zeros.
    raw = b"".join(b"\x01" + bytes((r[i] - (r[i - 3] if i >= 3 else 0)) & 255 for i in range(len(r))) for r in rows)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


def shrink(rows, k):
    height, width = len(rows) // k, len(rows[0]) // 3 // k
    out = []
    for y in range(height):
        line = bytearray(width * 3)
        block = rows[y * k:(y + 1) * k]
        for x in range(width):
            for c in range(3):
                line[3 * x + c] = sum(r[3 * (x * k + dx) + c] for r in block for dx in range(k)) // (k * k)
        out.append(bytes(line))
    return out


def main():
    args = sys.argv[1:]
    if len(args) < 2 or len(args) % 2 or any(a != "--part" for a in args[2::2]):
        sys.exit(__doc__)
    width, height, rows = read_xwd(args[0])
    parts = []
    for spec in args[3::2]:
        rect, _, k = spec.partition("/")
        x, y, w, h = (int(v) for v in rect.split(","))
        part = [r[3 * x:3 * (x + w)] for r in rows[y:y + h]]
        parts.append(shrink(part, int(k)) if k else part)
    if parts:
        gap = 8
        height = max(len(p) for p in parts)
        width = sum(len(p[0]) // 3 for p in parts) + gap * (len(parts) - 1)
        rows = []
        for y in range(height):
            line = b""
            for i, p in enumerate(parts):
                w = len(p[0])
                line += (p[y] if y < len(p) else b"\x1a" * w) + (b"\x1a" * 3 * gap if i + 1 < len(parts) else b"")
            rows.append(line)
    write_png(args[1], width, height, rows)


if __name__ == "__main__":
    main()
