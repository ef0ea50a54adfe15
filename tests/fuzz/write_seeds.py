#!/usr/bin/env python3
"""Writes the seeds of two fuzz targets:
  corpus/fulgur_fuzz_engine/ (fuzz_engine.c): one per scene feature (a
    spark, a continuous plasma ball, lightning through every propagation
    effect, Abe's model, a moving listener, parameters at their
    limits' edges), in the byte layout the target reads; beside them,
    not written here, the inputs the fuzzer found (found_*: each once
    failed the target, kept so that every run replays them);
  corpus/fulgur_fuzz_wav/ (fuzz_wav.c): WAVs as fulgur and others write
    them (float mono, 16-bit stereo, with fulgur's calibration comment,
    RF64, truncated); beside them, the found_* inputs as above.
Usage: python3 tests/fuzz/write_seeds.py"""
import os
import struct

BASE = 148  # value(): the preset's own value
CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def config(rate_index=4, block_index=4, channels=2, voices=8, speed=343.0, tight=False):
    shape = rate_index + 6 * block_index + 36 * (channels - 1)
    return bytes([shape, voices - 1, round((speed - 100) * 256 / 1000), 1 if tight else 0])


def coordinate(metres):
    raw = round(metres * 512)
    if raw & 0xFF == 0xEE:  # the edge marker: one step over
        raw += 1
    return struct.pack("<h", raw)


def post(nodes, preset=0, sound=(BASE,) * 7, emit=0, strokes=1, continuous=False,
         duration=None, model=0, repeats=(BASE, BASE), seed=1, air=0, air_values=()):
    b = bytearray([0, len(nodes) - 1])  # the op "post"; count = 1 + byte % 16
    for i, (x, y, z) in enumerate(nodes):
        b.append(max(i - 1, 0))  # parent i - 1: a chain
        b += coordinate(x) + coordinate(y) + coordinate(z)
    b.append(preset)
    b += bytes(sound)
    b.append(emit)
    b.append(strokes)
    mode = (1 if continuous else 0) | (2 if duration is not None else 0) | model << 2
    b.append(mode)
    b += bytes(repeats)
    if duration is not None:
        b.append(duration)
    b.append(seed)
    b.append(air)
    b += bytes(air_values)
    return bytes(b)


def render(blocks):
    return bytes([2 + 4 * (blocks - 1)])


def listener(position, look=0, extra=b""):
    b = bytearray([1])
    for v in position:
        b += coordinate(v)
    b.append(look)
    return bytes(b) + extra


def line(start, step, count):
    return [tuple(start[k] + step[k] * i for k in range(3)) for i in range(count)]


def chunk(tag, body):
    return tag + struct.pack("<I", len(body)) + body + (b"\0" if len(body) % 2 else b"")


def wav(samples, channels=1, rate=48000, fmt=3, bits=32, comment=None, rf64=False,
        keep=None):
    """A RIFF (or RF64) WAV of the samples (floats, or ints for PCM);
    keep: cut the file after that many bytes (a truncated copy)."""
    width = bits // 8
    pack = "<%d%s" % (len(samples), "f" if fmt == 3 else "h")
    data = struct.pack(pack, *samples)
    body = chunk(b"fmt ", struct.pack("<HHIIHH", fmt, channels, rate, rate * channels * width,
                                      channels * width, bits))
    if comment:
        body += chunk(b"LIST", b"INFO" + chunk(b"ICMT", comment.encode() + b"\0"))
    if rf64:
        ds64 = chunk(b"ds64", struct.pack("<QQQI", 0, len(data), len(samples) // channels, 0))
        body = ds64 + body + b"data" + struct.pack("<I", 0xFFFFFFFF) + data
        head = b"RF64" + struct.pack("<I", 0xFFFFFFFF) + b"WAVE"
    else:
        body += chunk(b"data", data)
        head = b"RIFF" + struct.pack("<I", 4 + len(body)) + b"WAVE"
    out = head + body
    if rf64:
        out = out[:20] + struct.pack("<Q", len(out) - 8) + out[28:]
    return out[:keep] if keep else out


def write(folder, seeds):
    os.makedirs(os.path.join(CORPUS, folder), exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(CORPUS, folder, name), "wb") as f:
            f.write(data)


def wav_seeds():
    click = [0.0, 0.5, -0.25, 0.125] * 8
    return {
        "float_mono.wav": wav(click),
        "pcm16_stereo.wav": wav([0, 1000, -1000, 32767, -32768, 5] * 4, channels=2, rate=44100,
                                fmt=1, bits=16),
        "calibrated.wav": wav(click, channels=2,
                              comment="fulgur calibration: full scale = 496.2 Pa"),
        "rf64.wav": wav(click, rf64=True),
        "truncated.wav": wav(click * 4, keep=44 + 40),
    }


def main():
    write("fulgur_fuzz_wav", wav_seeds())
    spark = line((0, 1, 1.7), (0.001, 0, 0.004), 5)
    seeds = {
        "spark": config() + post(spark) + render(16) * 4,
        "continuous": config() + post(line((0, 0.6, 1.2), (0.01, 0.005, 0.02), 8), preset=1,
                                      continuous=True, duration=BASE, emit=13)
        + render(16) * 8 + bytes([3]) + render(16) * 2,
        # refraction, turbulence, Abe's FIR, ground and head shadow
        "propagation": config(rate_index=0) + post(line((5, 40, 0), (0.5, 0.2, 5), 12), preset=2,
                                                   strokes=0, air=2 | 4 | 8 | 16 | 32 | 64,
                                                   air_values=(BASE,) * 5) + render(16) * 16,
        "abe": config(rate_index=1) + post(line((0, 3, 2), (0.01, 0, 0.1), 6), model=1)
        + render(16) * 8,
        "moving": config() + post(spark, emit=30)
        + listener((0, 0, 1.7), look=1 | 32 | 64, extra=bytes([BASE, 0, BASE, 1, BASE, 0, 40]))
        + render(4) + listener((0.5, 0, 1.7)) + render(16) * 3,
        # every sound field at an edge (T0 1e-7, r0 1000, ...), a tight work bound
        "edges": config(tight=True) + post(spark, sound=(9, 22, 29, 0, 0, 27, 11))
        + post(spark, sound=(16, 23, 29, 19, 0, 26, 11), continuous=True, repeats=(13, 13),
               duration=16) + render(16) * 3,
    }
    write("fulgur_fuzz_engine", seeds)


if __name__ == "__main__":
    main()
