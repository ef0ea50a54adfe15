"""What the tests share: the fulgur program, the repository, WAV data.

CTest runs them with FULGUR_CLI (the fulgur program of the same build),
FULGUR_SOURCE_DIR, FULGUR_BUILD_DIR, FULGUR_RT_GUARD (tests/rt_guard.c as
an LD_PRELOAD module), FULGUR_CC and PYTHONPATH=BUILD/python."""
import json
import os
import struct
import subprocess

import pytest


def env_path(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run the tests through CTest (python/CMakeLists.txt)")
    return value


SOURCE = os.environ.get("FULGUR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def example(name):
    return os.path.join(SOURCE, "examples", name)


def load_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def cli_render(scene_path, out_path, *extra):
    """fulgur render SCENE -o OUT [extra...]: (returncode, stderr)."""
    r = subprocess.run([env_path("FULGUR_CLI"), "render", scene_path, "-o", out_path, *extra],
                       capture_output=True, text=True)
    return r.returncode, r.stderr


def wav_data(path):
    """(format tag, channels, rate, bits, data bytes) of a RIFF WAV."""
    with open(path, "rb") as f:
        blob = f.read()
    assert blob[:4] == b"RIFF" and blob[8:12] == b"WAVE", path
    at, fmt, data = 12, None, None
    while at + 8 <= len(blob):
        tag, size = blob[at:at + 4], struct.unpack("<I", blob[at + 4:at + 8])[0]
        body = blob[at + 8:at + 8 + size]
        if tag == b"fmt ":
            fmt = struct.unpack("<HHIIHH", body[:16])
        elif tag == b"data":
            data = body
        at += 8 + size + (size & 1)
    assert fmt and data is not None, path
    tag, channels, rate, _, _, bits = fmt
    return tag, channels, rate, bits, data
