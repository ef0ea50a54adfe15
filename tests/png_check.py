#!/usr/bin/env python3
"""What the shell tests ask of fulgur's 8-bit RGBA PNGs (no imaging library
needed: the rows are unfiltered here).

usage: png_check.py mean FILE...          each file's mean RGB (0..255)
       png_check.py size FILE             WIDTHxHEIGHT
       png_check.py region FILE X0 Y0 X1 Y1
                                          the mean RGB of pixels [X0, X1) x [Y0, Y1)
       png_check.py marker FILE red|blue  how many pixels have a charge marker's
                                          colour, and their centroid "N X Y"
                                          (pixel centres, from the top left)
Exits 1 on an invalid PNG, naming it."""
import struct
import sys
import zlib


def decode(path):
    """(width, height, rows): rows[y] is a bytearray of RGBA."""
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
    raw, stride, prev, rows = zlib.decompress(idat), 4 * w, bytearray(4 * w), []
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
        rows.append(row)
        prev = row
    return w, h, rows


def region_mean(rows, x0, y0, x1, y1):
    total = sum(sum(rows[y][4 * x + k] for k in range(3)) for y in range(y0, y1) for x in range(x0, x1))
    return total / (3 * max(1, (x1 - x0) * (y1 - y0)))


# The markers' fill (marker_fs.glsl): red (+), blue (-), in sRGB.
MARKER = {'red': lambda r, g, b: r > 150 and g < 90 and b < 90,
          'blue': lambda r, g, b: b > 150 and r < 90 and g < 140}


def main(argv):
    what, files = argv[1] if len(argv) > 1 else '', argv[2:]
    current = files[0] if files else '?'
    try:
        if what == 'mean' and files:
            for p in files:
                current = p
                w, h, rows = decode(p)
                print('%s %.4f' % (p, region_mean(rows, 0, 0, w, h)))
        elif what == 'size' and len(files) == 1:
            w, h, _ = decode(files[0])
            print('%dx%d' % (w, h))
        elif what == 'region' and len(files) == 5:
            _, _, rows = decode(files[0])
            x0, y0, x1, y1 = (int(v) for v in files[1:])
            print('%.4f' % region_mean(rows, x0, y0, x1, y1))
        elif what == 'marker' and len(files) == 2 and files[1] in MARKER:
            w, h, rows = decode(files[0])
            hits = [(x, y) for y in range(h) for x in range(w)
                    if MARKER[files[1]](*rows[y][4 * x:4 * x + 3])]
            n = len(hits)
            cx = sum(x for x, _ in hits) / n + 0.5 if n else -1
            cy = sum(y for _, y in hits) / n + 0.5 if n else -1
            print('%d %.2f %.2f' % (n, cx, cy))
        else:
            print(__doc__.strip(), file=sys.stderr)
            return 2
    except Exception as e:  # an unreadable file: say which
        print('%s: invalid PNG: %s' % (current, e))
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
