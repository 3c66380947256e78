#!/usr/bin/env python3
"""Writes the texture pictures the scenes use (run from anywhere; needs only Python 3).

bricks.png  256x256: four courses of bricks, two bricks to a course, offset every other course,
            grey mortar; the brick wall of the exam's texturing question.
target.png  256x256: an 8 x 8 grid with red lines at s = 0.5 and t = 0.5 and a yellow disc at the
            centre (0.5, 0.5), to see where a parametrisation puts the middle of a texture.
tiles.png   128x128: 2 x 2 floor tiles with dark joints.
wood.png    128x128: light and dark stripes along t, for the OBJ model's map_Kd.

The pictures are computed, with a fixed pseudo-random sequence for the bricks' shades, so running
the script again gives the same bytes.
"""
import os
import struct
import zlib


def write_png(path, width, height, pixel):
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter type: none
        for x in range(width):
            rows.extend(bytes(pixel(x, y)))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9))
    png += chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def lcg(seed):
    state = seed
    while True:
        state = (state * 1103515245 + 12345) % 2147483648
        yield state / 2147483648.0


def bricks():
    size, courses, per_course, mortar = 256, 4, 2, 6
    course_height = size // courses
    brick_width = size // per_course
    random = lcg(7)
    shade = {}
    for c in range(courses):
        for b in range(per_course):
            shade[(c, b)] = 0.8 + 0.3 * next(random)

    def pixel(x, y):
        course = y // course_height
        offset = brick_width // 2 if course % 2 else 0
        bx = (x + offset) % size
        brick = (x + offset) // brick_width
        in_mortar = (y % course_height) < mortar or (bx % brick_width) < mortar
        if in_mortar:
            return (178, 172, 160)
        s = shade[(course, brick % per_course)]
        grain = 0.93 + 0.07 * (((x * 7 + y * 13) % 11) / 10.0)
        return tuple(min(255, int(v * s * grain)) for v in (165, 62, 42))

    return size, size, pixel


def target():
    size = 256

    def pixel(x, y):
        u, v = (x + 0.5) / size, (y + 0.5) / size
        du, dv = u - 0.5, v - 0.5
        if du * du + dv * dv < 0.06 ** 2:
            return (250, 210, 30)
        if abs(du) < 0.008 or abs(dv) < 0.008:
            return (210, 30, 30)
        cell = (x * 8 // size + y * 8 // size) % 2
        return (235, 235, 235) if cell == 0 else (70, 110, 170)

    return size, size, pixel


def tiles():
    size = 128

    def pixel(x, y):
        if x % 64 < 3 or y % 64 < 3:
            return (90, 80, 70)
        light = ((x // 64) + (y // 64)) % 2 == 0
        return (214, 200, 176) if light else (186, 170, 146)

    return size, size, pixel


def wood():
    size = 128

    def pixel(x, y):
        ring = (y + 3 * ((x * 5) % 7)) % 16
        t = 0.75 + 0.25 * (1.0 if ring < 10 else 0.55)
        return tuple(int(v * t) for v in (196, 140, 84))

    return size, size, pixel


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for name, make in (("bricks", bricks), ("target", target), ("tiles", tiles), ("wood", wood)):
        width, height, pixel = make()
        write_png(os.path.join(here, name + ".png"), width, height, pixel)
