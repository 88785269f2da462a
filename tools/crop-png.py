#!/usr/bin/env python3
"""Crops 8-bit RGBA PNGs (as lixel writes them), scales the crop up by whole pixels
(nearest), and puts several side by side with a gap: the zoomed comparisons in docs/.
Usage: crop-png.py OUT.png X Y W H ZOOM IN.png [IN.png ...]   (X, Y from the top left)"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            if depth != 8 or ctype != 6:
                sys.exit(f"{path}: expected 8-bit RGBA")
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, rows, prev, stride, i = zlib.decompress(idat), [], bytearray(w * 4), w * 4, 0
    for _ in range(h):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - 4] if x >= 4 else 0
            b = prev[x]
            c = prev[x - 4] if x >= 4 else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, rows


def write_png(path, w, h, rows):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    if len(sys.argv) < 8:
        sys.exit(__doc__)
    out, (x, y, w, h, zoom), ins = sys.argv[1], map(int, sys.argv[2:7]), sys.argv[7:]
    gap = 8
    total_w = len(ins) * w * zoom + (len(ins) - 1) * gap
    rows = [bytearray(b"\xff\xff\xff\xff" * total_w) for _ in range(h * zoom)]
    for k, path in enumerate(ins):
        iw, ih, src = read_png(path)
        if x + w > iw or y + h > ih:
            sys.exit(f"{path}: crop exceeds the {iw}x{ih} image")
        ox = k * (w * zoom + gap)
        for yy in range(h * zoom):
            s = src[y + yy // zoom]
            for xx in range(w * zoom):
                px = (x + xx // zoom) * 4
                rows[yy][(ox + xx) * 4:(ox + xx) * 4 + 4] = s[px:px + 4]
    write_png(out, total_w, h * zoom, rows)


main()
