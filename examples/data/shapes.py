#!/usr/bin/env python3
"""Writes the test images of the image method (mechkit com IMAGE), black shapes on white,
400 x 400 pixels, as 1-bit greyscale PNGs (standard library only: zlib and struct). A pixel
is black when its centre (column + 0.5, row + 0.5, y down from the top-left corner) is inside
the shape, so the expected values are those of the rasterised shape:

- disk_r150.png: a disk of radius 150 px centred at (200, 200); its centre of mass is
  (200, 200) exactly, I/(M R^2) = 0.5000227 (0.5 for the continuous disk);
- triangle_b150.png: an equilateral triangle of side 2b = 300 px with its base on the bottom
  edge, centred; Y_cm/b = 0.5773034 above the base (1/sqrt(3) = 0.5773503 for the
  continuous triangle).

Run from this directory: python3 shapes.py (the CLI test
`com_image::shapes_match_their_generator` checks the files against the shapes)."""
import math
import struct
import zlib

SIZE = 400


def disk(x, y):
    return (x - 200) ** 2 + (y - 200) ** 2 < 150**2


def triangle(x, y, b=150):
    return SIZE - y < math.sqrt(3) * (b - abs(x - 200))


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))


def png(inside):
    rows = bytearray()
    for j in range(SIZE):
        rows.append(0)  # filter: none
        bits = [0 if inside(i + 0.5, j + 0.5) else 1 for i in range(SIZE)]
        bits += [1] * (-len(bits) % 8)
        for k in range(0, len(bits), 8):
            rows.append(int("".join(map(str, bits[k : k + 8])), 2))
    header = struct.pack(">IIBBBBB", SIZE, SIZE, 1, 0, 0, 0, 0)  # 1-bit greyscale
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", zlib.compress(bytes(rows), 9))
        + chunk(b"IEND", b"")
    )


for name, shape in [("disk_r150.png", disk), ("triangle_b150.png", triangle)]:
    with open(name, "wb") as out:
        out.write(png(shape))
