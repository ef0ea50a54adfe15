#!/usr/bin/env python3
"""usage: png_mean.py FILE... -- prints each 8-bit RGBA PNG's mean RGB
(0..255) after undoing the row filters; exits 1 on an invalid PNG."""
import struct
import sys
import zlib


def mean(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError('not a PNG')
    i, idat, size = 8, b'', None
    while i < len(data):
        n, kind = struct.unpack('>I4s', data[i:i + 8])
        body = data[i + 8:i + 8 + n]
        if zlib.crc32(kind + body) != struct.unpack('>I', data[i + 8 + n:i + 12 + n])[0]:
            raise ValueError('bad CRC')
        if kind == b'IHDR':
            w, h, depth, colour = struct.unpack('>IIBB', body[:10])
            if depth != 8 or colour != 6:
                raise ValueError('expected 8-bit RGBA')
            size = (w, h)
        elif kind == b'IDAT':
            idat += body
        i += 12 + n
    w, h = size
    raw, stride, prev, total = zlib.decompress(idat), 4 * w, bytearray(4 * w), 0
    for y in range(h):
        f, row = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = row[x - 4] if x >= 4 else 0
            b, c = prev[x], prev[x - 4] if x >= 4 else 0
            if f == 1: row[x] = (row[x] + a) & 255
            elif f == 2: row[x] = (row[x] + b) & 255
            elif f == 3: row[x] = (row[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[x] = (row[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        total += sum(row) - sum(row[3::4])
        prev = row
    return total / (3 * w * h)


for p in sys.argv[1:]:
    try:
        print('%s %.4f' % (p, mean(p)))
    except Exception as e:
        print('%s: invalid PNG: %s' % (p, e))
        sys.exit(1)
