"""The real-time engine (fulgur/engine.h) from Python.

    with fulgur.Engine(sample_rate_hz=48000) as e:
        e.set_listener([0, 0, 1.7])
        voice = e.post(nodes, "spark_balls")
        block = e.render(256)        # (256, channels) float32, pascals
        e.collect()

Each method keeps to the thread rule of the call it makes: render is the
audio thread's (one thread at a time), post, stop and collect the sim
thread's (one at a time); set_listener and the getters may come from any
thread. A second thread entering render (or post) while another is in it
gets RuntimeError instead of breaking the engine's single-producer,
single-consumer rings. close() waits for calls in progress and frees the
engine; a closed engine raises ValueError.
"""
import operator
import threading

import numpy as np

from . import _convert
from ._native import EMIT_NOW, ffi, lib
from .errors import FulgurError, check

LAYOUT = {"stereo": lib.FG_LAYOUT_STEREO, "ambisonics": lib.FG_LAYOUT_AMBISONICS}
ABSORPTION = {"off": lib.FG_ABSORPTION_OFF, "iso9613": lib.FG_ABSORPTION_ISO9613,
              "abe_fir": lib.FG_ABSORPTION_ABE_FIR}
MODELS = {"wm": lib.FG_MODEL_WM, "abe": lib.FG_MODEL_ABE}


def preset_names():
    """The presets' names, in fg_preset order."""
    return [ffi.string(lib.fg_preset_name(p)).decode() for p in range(lib.FG_PRESET_COUNT)]


def preset_value(name):
    """fg_preset of a name ("lightning"), or ValueError."""
    if not isinstance(name, str):
        raise TypeError(f"preset: expected a name ({', '.join(preset_names())}), got {name!r}")
    out = ffi.new("fg_preset *")
    if lib.fg_preset_from_name(name.encode(), out) != lib.FG_OK:
        raise ValueError(f"preset: unknown {name!r} (known: {', '.join(preset_names())})")
    return out[0]


def preset_sound(name):
    """The sound parameters of a preset, as a dict (fg_sound_config)."""
    cfg = ffi.new("fg_sound_config *")
    check(lib.fg_preset_sound(preset_value(name), cfg), "fg_preset_sound")
    return _convert.as_dict(cfg)


def sound_config(sound):
    """An fg_sound_config from a preset name, or a dict: "preset" (optional)
    and any of its fields over it."""
    cfg = ffi.new("fg_sound_config *")
    if isinstance(sound, str):
        sound = {"preset": sound}
    if not hasattr(sound, "items"):
        raise TypeError(f"sound: expected a preset name or a dict, got {type(sound).__name__}")
    sound = dict(sound)
    if "preset" in sound:
        check(lib.fg_preset_sound(preset_value(sound.pop("preset")), cfg), "fg_preset_sound")
    return _convert.fill(cfg, sound, "sound")


def propagation_config(propagation):
    cfg = ffi.new("fg_propagation_config *")
    return _convert.fill(cfg, propagation, "propagation", names={"absorption": ABSORPTION})


class Engine:
    """One fg_engine. config (a dict) and the keyword settings are fields of
    fg_engine_config (sample_rate_hz, max_block_frames, channels,
    max_voices, segment_capacity, speed_of_sound_m_s, ear_spacing_m,
    max_lookahead_s, max_adopt_per_block, air_temperature_k,
    air_humidity_pct, air_pressure_kpa, layout ("stereo" or "ambisonics"),
    ambisonic_order); those not given take the engine's defaults."""

    def __init__(self, config=None, **settings):
        values = dict(config or {}) if config is None or hasattr(config, "items") else None
        if values is None:
            raise TypeError(f"config: expected a dict, got {type(config).__name__}")
        values.update(settings)
        cfg = _convert.fill(ffi.new("fg_engine_config *"), values, "config",
                            names={"layout": LAYOUT})
        out = ffi.new("fg_engine **")
        check(lib.fg_engine_create(cfg, out), "fg_engine_create")
        self._handle = out[0]
        used = ffi.new("fg_engine_config *")
        lib.fg_engine_get_config(self._handle, used)
        self._config = _convert.as_dict(used)
        self._channels = used.channels
        self._planes = ffi.new("float *[2]")
        self._life = threading.Condition()
        self._active = 0
        self._sim = threading.Lock()
        self._audio = threading.Lock()

    # -- lifetime and the thread rules --

    def _enter(self, role=None, what=""):
        with self._life:
            if self._handle is None:
                raise ValueError(f"Engine.{what}: the engine is closed")
            self._active += 1
        if role is not None and not role.acquire(blocking=False):
            self._leave(None)
            kind = "render" if role is self._audio else "post, stop or collect"
            raise RuntimeError(f"Engine.{what}: another thread is in a {kind} call on this "
                               "engine (one thread at a time: fulgur/engine.h)")
        return self._handle

    def _leave(self, role):
        if role is not None:
            role.release()
        with self._life:
            self._active -= 1
            self._life.notify_all()

    def close(self):
        """Frees the engine once calls in progress have returned. Further
        calls raise ValueError; closing twice does nothing."""
        with self._life:
            handle, self._handle = self._handle, None
            while self._active:
                self._life.wait()
        if handle is not None:
            lib.fg_engine_destroy(handle)

    @property
    def closed(self):
        return self._handle is None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        if getattr(self, "_handle", None) is not None:
            self.close()

    # -- the sim thread's calls --

    def post(self, nodes, sound, *, emit_time_s=None, strokes=0, continuous=False,
             repeat_min_s=0.0, repeat_max_s=0.0, duration_s=0.0, seed=0, propagation=None,
             model="wm"):
        """Posts a discharge: nodes (fulgur.NODE_DTYPE, or rows of [x, y, z,
        parent(, flags)]) with sound (a preset name, or a dict of
        fg_sound_config fields over an optional "preset"). emit_time_s on
        the engine clock, None for the block that adopts it. Returns the
        voice's id. FulgurError: the engine refused it (a tree fault names
        the node; FG_ERR_POOL_FULL / FG_ERR_QUEUE_FULL: collect, retry)."""
        tree = _convert.as_nodes(nodes)
        d = ffi.new("fg_discharge *")
        d.sound = sound_config(sound)[0]
        d.propagation = propagation_config(propagation)[0]
        if model not in MODELS:
            raise ValueError(f"model: unknown {model!r} (known: {', '.join(MODELS)})")
        d.model = MODELS[model]
        _convert.fill(d, {"emit_time_s": EMIT_NOW if emit_time_s is None else emit_time_s,
                          "strokes": strokes, "continuous": bool(continuous),
                          "repeat_min_s": repeat_min_s, "repeat_max_s": repeat_max_s,
                          "duration_s": duration_s, "seed": seed}, "post")
        d.nodes, d.node_count = _convert.node_pointer(tree)
        voice = ffi.new("fg_voice_id *")
        handle = self._enter(self._sim, "post")
        try:
            code = lib.fg_engine_post(handle, d, voice)
        finally:
            self._leave(self._sim)
        if code == lib.FG_ERR_TREE:
            raise FulgurError(f"Engine.post: nodes: {_convert.tree_fault(tree)}", code)
        if code == lib.FG_ERR_NULL and d.node_count == 0:
            raise FulgurError("Engine.post: nodes: the tree has no node", lib.FG_ERR_TREE)
        check(code, "Engine.post")
        return voice[0]

    def stop(self, voice):
        """Ends a continuous voice (or a bolt's later strokes)."""
        voice = operator.index(voice)
        if not 0 <= voice < 2**64:
            raise ValueError(f"Engine.stop: {voice} is not a voice id")
        handle = self._enter(self._sim, "stop")
        try:
            code = lib.fg_engine_stop(handle, voice)
        finally:
            self._leave(self._sim)
        check(code, "Engine.stop")

    def collect(self):
        """Reclaims finished voices; returns how many."""
        handle = self._enter(self._sim, "collect")
        try:
            return lib.fg_engine_collect(handle)
        finally:
            self._leave(self._sim)

    # -- the audio thread's call --

    def render(self, nframes):
        """The next nframes (at most max_block_frames) of every ear: a
        (nframes, channels) float32 array in pascals."""
        nframes = operator.index(nframes)
        if not 0 <= nframes <= self._config["max_block_frames"]:
            raise ValueError(f"Engine.render: {nframes} frames: expected 0.."
                             f"{self._config['max_block_frames']} (max_block_frames)")
        out = np.empty((self._channels, max(nframes, 1)), dtype=np.float32)
        planes = self._planes
        for ch in range(self._channels):
            planes[ch] = ffi.cast("float *", ffi.from_buffer(out[ch]))
        handle = self._enter(self._audio, "render")
        try:
            code = lib.fg_engine_render(handle, planes, nframes)
        finally:
            self._leave(self._audio)
        check(code, "Engine.render")
        return out[:, :nframes].T

    # -- any thread --

    def set_listener(self, position, forward=(0.0, 1.0, 0.0), up=(0.0, 0.0, 1.0),
                     velocity=(0.0, 0.0, 0.0)):
        """Publishes the listener's pose: position (metres), forward and up
        (any length, not parallel), velocity (m/s, informational)."""
        pose = ffi.new("fg_listener *")
        for name, value in (("position", position), ("forward", forward), ("up", up),
                            ("velocity", velocity)):
            v = _convert.vector(value, 3, name)
            target = getattr(pose, name)
            for i in range(3):
                target[i] = float(v[i])
        handle = self._enter(None, "set_listener")
        try:
            code = lib.fg_engine_set_listener(handle, pose)
        finally:
            self._leave(None)
        check(code, "Engine.set_listener")

    @property
    def listener(self):
        """The latest pose, as a dict of lists."""
        pose = ffi.new("fg_listener *")
        handle = self._enter(None, "listener")
        try:
            lib.fg_engine_get_listener(handle, pose)
        finally:
            self._leave(None)
        return {k: list(getattr(pose, k)) for k in ("position", "forward", "up", "velocity")}

    def stats(self):
        """The engine's counters (fg_engine_report) as a dict: posted,
        adopted, finished, collected, late_events, late_samples, ..."""
        report = ffi.new("fg_engine_report *")
        handle = self._enter(None, "stats")
        try:
            lib.fg_engine_get_report(handle, report)
        finally:
            self._leave(None)
        return _convert.as_dict(report)

    @property
    def frames(self):
        """Frames rendered so far (the engine clock)."""
        handle = self._enter(None, "frames")
        try:
            return lib.fg_engine_frames(handle)
        finally:
            self._leave(None)

    @property
    def time_s(self):
        """The engine clock in seconds."""
        return self.frames / self._config["sample_rate_hz"]

    @property
    def config(self):
        """The configuration in use, defaults filled in."""
        return dict(self._config)

    @property
    def channels(self):
        return self._channels

    @property
    def sample_rate_hz(self):
        return self._config["sample_rate_hz"]
