#!/usr/bin/env python3
"""Make Wobble's own texture and course-format example, with nothing but the standard library.

Rerun from the repository root:  python3 assets/textures/generate.py
Writes assets/textures/flag.png and assets/course/banner.obj.
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ASSETS = os.path.dirname(HERE)


def write_png(path, width, height, pixel):
    """pixel(x, y) -> (r, g, b), rows from the top."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter: none
        for x in range(width):
            rows.extend(pixel(x, y))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                  chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))


def flag(x, y):
    # Three bands with a ring near the hoist: clear enough to show how the cloth stretches.
    size = 256
    u, v = x / size, y / size
    band = [(32, 72, 160), (240, 240, 235), (200, 40, 50)][min(int(v * 3), 2)]
    distance = math.hypot(u - 0.3, v - 0.5)
    if 0.12 < distance < 0.17:
        return (250, 200, 40)
    # A fine grid, one line every 32 pixels.
    if x % 32 == 0 or y % 32 == 0:
        return tuple(int(c * 0.8) for c in band)
    return band


def banner_obj(path, columns=11, rows=8, width=1.0, height=0.7):
    """A vertical quad sheet in the xy plane, top row at y = 1.5, with texture coordinates."""
    lines = ["# Wobble's course-format example: a banner of %d x %d vertices" % (columns, rows)]
    for r in range(rows):
        for c in range(columns):
            x = -width / 2 + width * c / (columns - 1)
            y = 1.5 - height * r / (rows - 1)
            lines.append("v %.6f %.6f 0" % (x, y))
    for r in range(rows):
        for c in range(columns):
            lines.append("vt %.6f %.6f" % (c / (columns - 1), 1 - r / (rows - 1)))
    for r in range(rows - 1):
        for c in range(columns - 1):
            a = r * columns + c + 1
            b, d, e = a + 1, a + columns, a + columns + 1
            # Counter-clockwise seen from +z.
            lines.append("f %d/%d %d/%d %d/%d %d/%d" % (a, a, d, d, e, e, b, b))
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    write_png(os.path.join(HERE, "flag.png"), 256, 256, flag)
    banner_obj(os.path.join(ASSETS, "course", "banner.obj"))
