#!/usr/bin/env python3
"""usage: in_cloud_check.py FULGUR SCENE.json TMPDIR -- renders
tests/scenes/in_cloud_3km.json as given, with "in_cloud": 0 and without the
key. The last two must be the same WAV byte for byte (0 is today's tree);
the in-cloud channel, 10 km long, ends ~11.6 km from the listener against
the main channel's <= ~6 km, so its render must run >= 10 s longer and hold
>= 1 % of its energy after the end of the render without it, where that one
has none. Exits 1 otherwise. WAV: 32-bit float, standard library only."""
import json
import math
import os
import struct
import subprocess
import sys


def wav_float(path):
    data = open(path, 'rb').read()
    i, rate, samples = 12, None, None
    while i + 8 <= len(data):
        kind, n = struct.unpack('<4sI', data[i:i + 8])
        body = data[i + 8:i + 8 + n]
        if kind == b'fmt ':
            rate = struct.unpack('<I', body[4:8])[0]
        elif kind == b'data':
            samples = struct.unpack('<%df' % (n // 4), body[:n - n % 4])
        i += 8 + n + (n & 1)
    return rate, samples


def render(fulgur, scene, tmp, name, in_cloud):
    gen = scene['discharges'][0]['generator']
    gen.pop('in_cloud', None)
    if in_cloud is not None:
        gen['in_cloud'] = in_cloud
    path = os.path.join(tmp, name + '.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    out = os.path.join(tmp, name + '.wav')
    subprocess.run([fulgur, 'render', path, '-o', out], check=True, stdout=subprocess.DEVNULL)
    return out


def main():
    fulgur, scene_path, tmp = sys.argv[1:4]
    scene = json.load(open(scene_path))
    cloud = render(fulgur, scene, tmp, 'cloud', 10000)
    zero = render(fulgur, scene, tmp, 'zero', 0)
    plain = render(fulgur, scene, tmp, 'plain', None)
    ok = open(zero, 'rb').read() == open(plain, 'rb').read()
    print('in_cloud 0 and no key: %s' % ('identical' if ok else 'DIFFER'))
    rate, c = wav_float(cloud)
    _, p = wav_float(plain)
    longer = (len(c) - len(p)) / rate
    total = sum(x * x for x in c)
    late = sum(x * x for x in c[len(p):]) / total if total > 0 else 0.0
    print('in_cloud 10000: %.2f s longer, %.1f %% of its energy after %.2f s'
          % (longer, 100 * late, len(p) / rate))
    ok = ok and longer >= 10.0 and late >= 0.01 and math.isfinite(total)
    return 0 if ok else 1


sys.exit(main())
