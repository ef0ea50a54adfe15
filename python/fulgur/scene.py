"""Scenes (docs/scene-format.md) rendered as fulgur render renders them.

    samples, rate = fulgur.render({"discharges": [...]})
    samples, rate = fulgur.render("examples/lightning_3km.json",
                                  overrides={"discharges[0].offset[1]": 8000})

The scene goes to libfulgur-scene as JSON text (a dict) or as a path, and
through the same parser, overrides, generators and block loop as fulgur
render: equal scenes give the WAV's samples to the bit, and every error
names the same JSON path.
"""
import json
import os

import numpy as np

from ._native import ffi, lib, scene_lib
from .errors import FulgurError, SceneError

_ERR_SIZE = 1024


def _json_default(value):
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"scene: {type(value).__name__} is not a JSON value")


def _assignments(overrides):
    """overrides as "KEY=VALUE" strings: a dict's values become JSON; a list
    of strings is taken as written (as fulgur render --set)."""
    if overrides is None:
        return []
    if hasattr(overrides, "items"):
        out = []
        for key, value in overrides.items():
            if not isinstance(key, str):
                raise TypeError(f"overrides: keys are JSON paths (str), not {key!r}")
            try:
                text = json.dumps(value, allow_nan=False, default=_json_default)
            except ValueError as e:
                raise SceneError(f"{key}: {value!r} is not a JSON value ({e})",
                                 lib.FG_ERR_ARGUMENT) from None
            out.append(f"{key}={text}")
        return out
    if isinstance(overrides, (str, bytes)):
        raise TypeError("overrides: expected a dict or a list of 'KEY=VALUE' strings")
    out = list(overrides)
    for item in out:
        if not isinstance(item, str):
            raise TypeError(f"overrides: expected 'KEY=VALUE' strings, got {item!r}")
    return out


def _raise(code, err):
    message = ffi.string(err).decode(errors="replace")
    if code == lib.FG_ERR_ARGUMENT:  # the scene's fault: the message names the path
        raise SceneError(message, code)
    raise FulgurError(message, code)


class Scene:
    """A parsed scene. scene: a dict (any JSON-able mapping) or a path;
    overrides as fulgur render's --set: a dict {KEY: value} or a list of
    "KEY=VALUE" strings. Raises SceneError naming the JSON path."""

    def __init__(self, scene, overrides=None):
        sets = _assignments(overrides)
        encoded = [ffi.new("char[]", s.encode()) for s in sets]
        set_array = ffi.new("const char *[]", encoded) if encoded else ffi.NULL
        err = ffi.new("char[]", _ERR_SIZE)
        out = ffi.new("fgs_scene **")
        if isinstance(scene, (str, os.PathLike)):
            code = scene_lib.fgs_scene_load(os.fsencode(scene), set_array, len(sets), out, err,
                                            _ERR_SIZE)
        elif hasattr(scene, "items"):
            try:
                text = json.dumps(scene, allow_nan=False, default=_json_default).encode()
            except ValueError as e:
                raise SceneError(f"scene: not JSON ({e})", lib.FG_ERR_ARGUMENT) from None
            code = scene_lib.fgs_scene_parse(text, len(text), set_array, len(sets), out, err,
                                             _ERR_SIZE)
        else:
            raise TypeError(f"scene: expected a dict or a path, got {type(scene).__name__}")
        if code != 0:
            _raise(code, err)
        self._handle = ffi.gc(out[0], scene_lib.fgs_scene_destroy)
        info = ffi.new("fgs_scene_info *")
        scene_lib.fgs_scene_get_info(self._handle, info)
        self.sample_rate_hz = info.sample_rate_hz
        self.channels = info.channels
        self.block_frames = info.block_frames
        self.duration_s = info.duration_s
        self.seed = info.seed
        self.gain = info.gain
        self.discharge_count = info.discharge_count

    def render(self):
        """Runs the generators (once) and renders: a Rendering, which
        unpacks as (samples, sample_rate_hz); samples is a (frames,
        channels) float32 array of pascals times the scene's gain."""
        report = ffi.new("fgs_render_report *")
        err = ffi.new("char[]", _ERR_SIZE)
        code = scene_lib.fgs_scene_render(self._handle, report, err, _ERR_SIZE)
        if code != 0:
            _raise(code, err)
        frames = ffi.new("uint64_t *")
        ptr = scene_lib.fgs_scene_samples(self._handle, frames)
        count = frames[0] * self.channels
        samples = np.frombuffer(ffi.buffer(ptr, count * 4), dtype=np.float32).copy()
        engine = report.engine
        return Rendering(samples.reshape(frames[0], self.channels), self.sample_rate_hz, {
            "frames": report.frames,
            "duration_s": report.frames / self.sample_rate_hz,
            "segments": report.segments,
            "peak": report.peak,
            "capped": bool(report.capped),
            "seed": self.seed,
            "gain": self.gain,
            "pa_per_unit": 1.0 / self.gain,
            "late_events": engine.late_events,
            "late_samples": engine.late_samples,
            "posted": engine.posted,
            "finished": engine.finished,
        })


class Rendering(tuple):
    """(samples, sample_rate_hz), with .report: frames, duration_s,
    segments, peak, seed, gain, pa_per_unit (the calibration: pascals per
    unit of the samples), late_events, ..."""

    def __new__(cls, samples, sample_rate_hz, report):
        self = super().__new__(cls, (samples, sample_rate_hz))
        self.report = report
        return self

    @property
    def samples(self):
        return self[0]

    @property
    def sample_rate_hz(self):
        return self[1]


def render(scene, overrides=None):
    """Renders a scene (a dict or a path; overrides as Scene's) as fulgur
    render does: (samples, sample_rate_hz), samples (frames, channels)
    float32 in pascals times the scene's gain (1 unless it says)."""
    return Scene(scene, overrides).render()


def write_wav(path, samples, sample_rate_hz):
    """Writes samples ((frames, channels) or (frames,), float32-able) as
    fulgur render writes a WAV: 32-bit float, equal samples give equal
    bytes; the file appears complete or not at all."""
    try:
        a = np.ascontiguousarray(samples, dtype=np.float32)
    except (TypeError, ValueError) as e:
        raise TypeError(f"samples: expected numbers, got {type(samples).__name__}") from e
    if a.ndim == 1:
        a = a[:, None]
    if a.ndim != 2 or a.shape[1] not in (1, 2):
        raise ValueError(f"samples: expected shape (frames, 1 or 2), got {a.shape}")
    rate = float(sample_rate_hz)
    err = ffi.new("char[]", _ERR_SIZE)
    data = ffi.cast("const float *", ffi.from_buffer(a)) if a.size else ffi.NULL
    code = scene_lib.fgs_wav_write(os.fsencode(path), data, a.shape[0], a.shape[1], rate, err,
                                   _ERR_SIZE)
    if code != 0:
        message = ffi.string(err).decode(errors="replace")
        if code == lib.FG_ERR_IO:
            raise OSError(message)
        raise ValueError(message)
