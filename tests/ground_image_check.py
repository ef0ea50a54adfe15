#!/usr/bin/env python3
"""usage: ground_image_check.py SCENE.json OUT.wav -- checks a render of
tests/scenes/ground_image.json: one segment broadside to a mono ear, and
its image in the ground z = 0. From the scene alone (Matsuyama eqs. 3-4:
ps = r0 ps0 / (r sqrt(1 + sigma0 ln(r/r0))), T = T0 sqrt(1 + sigma0 ln(r/r0));
a broadside N-wave's energy is (2/3) ps^2 T) it predicts the image's delay
after the direct wave, (r_image - r_direct) / c, and its energy relative to
the direct wave's, reflection^2 (ps_i/ps_d)^2 (T_i/T_d). The render must
give the delay within one sample and the energy ratio within 0.2 dB.
Exits 1 otherwise. WAV: 32-bit float, read with the standard library."""
import json
import math
import struct
import sys


def wav_float(path):
    data = open(path, 'rb').read()
    if data[:4] != b'RIFF' or data[8:12] != b'WAVE':
        raise ValueError('not a RIFF WAVE')
    i, fmt, samples = 12, None, None
    while i + 8 <= len(data):
        kind, n = struct.unpack('<4sI', data[i:i + 8])
        body = data[i + 8:i + 8 + n]
        if kind == b'fmt ':
            fmt = struct.unpack('<HHIIHH', body[:16])
        elif kind == b'data':
            samples = struct.unpack('<%df' % (n // 4), body[:n - n % 4])
        i += 8 + n + (n & 1)
    if fmt is None or samples is None or fmt[0] not in (3, 0xFFFE) or fmt[5] != 32:
        raise ValueError('not a 32-bit float WAV')
    if fmt[1] != 1:
        raise ValueError('expected one channel')
    return fmt[2], samples


def main():
    scene = json.load(open(sys.argv[1]))
    rate, x = wav_float(sys.argv[2])
    d = scene['discharges'][0]
    c = scene['speed_of_sound']
    (a, b) = d['tree']['nodes']
    mid = [(a[k] + b[k]) / 2 for k in range(3)]
    ear = scene['listener']['position']
    image = [mid[0], mid[1], -mid[2]]
    r_d, r_i = math.dist(mid, ear), math.dist(image, ear)
    stretch = [math.sqrt(1 + d['sigma0'] * math.log(r / d['r0'])) for r in (r_d, r_i)]
    ps = [d['r0'] * d['ps0'] / (r * st) for r, st in zip((r_d, r_i), stretch)]
    want_delay = (r_i - r_d) / c * rate
    want_db = 10 * math.log10(d['propagation']['ground']['reflection'] ** 2 *
                              (ps[1] / ps[0]) ** 2 * stretch[1] / stretch[0])
    # the two waves: split halfway between their predicted arrivals
    split = round(d['time'] * rate + (r_d + r_i) / 2 / c * rate)
    waves = [x[:split], x[split:]]
    energy = [sum(v * v for v in w) for w in waves]
    # each N-wave's centre: where its (odd) pressure crosses zero between
    # its two extremes, to a fraction of a sample
    centre = []
    for off, w in zip((0, split), waves):
        lo = min(range(len(w)), key=lambda k: w[k])
        hi = max(range(len(w)), key=lambda k: w[k])
        k0, k1 = sorted((lo, hi))
        k = next(k for k in range(k0, k1) if (w[k] > 0) != (w[k + 1] > 0))
        centre.append(off + k + w[k] / (w[k] - w[k + 1]))
    got_delay = centre[1] - centre[0]
    got_db = 10 * math.log10(energy[1] / energy[0])
    print('image delay %.2f samples (geometry %.2f), energy %+.3f dB (geometry %+.3f dB)' %
          (got_delay, want_delay, got_db, want_db))
    if energy[0] <= 0 or abs(got_delay - want_delay) > 1 or abs(got_db - want_db) > 0.2:
        print('the ground image does not match the geometry')
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
