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

# Looked up now, not when an engine is freed: __del__ may run from the
# garbage collector inside one of cffi's own calls, which holds cffi's
# (non-reentrant) lock that a first lookup of a library function takes.
_engine_destroy = lib.fg_engine_destroy

LAYOUT = {"stereo": lib.FG_LAYOUT_STEREO, "ambisonics": lib.FG_LAYOUT_AMBISONICS}
BODIES = {"stick": lib.FG_AERO_STICK, "compact": lib.FG_AERO_COMPACT}
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
    ambisonic_order, chunk_frames); those not given take the engine's
    defaults."""

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
        self._planes = ffi.new("float *[]", self._channels)  # up to 16 in ambisonics
        self._life = threading.Condition()
        self._active = 0
        self._sim = threading.Lock()
        self._audio = threading.Lock()
        self._textures = []  # borrowed by aero voices: kept until close

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
            _engine_destroy(handle)
        self._textures = []

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

    def post_aero(self, texture, *, position, axis, normal, velocity=(0.0, 0.0, 0.0),
                  body="stick", start_m=0.0, end_m=0.0, sources=0, gain=0.0, wind=None,
                  gust=0.0, gust_period_s=0.0, seed=0, absorption="off", emit_time_s=None,
                  duration_s=0.0):
        """Posts an aero object (fg_aero_object_post): texture (an
        AeroTexture; 2-D for body "stick", 3-D for "compact"), its first
        pose (position, axis, normal, velocity), a stick's span start_m ..
        end_m along the axis and its sources (0: one per 3 D), the wind
        (a velocity, m/s) with gust, gust_period_s and seed, absorption
        ("off" or "iso9613"), emit_time_s (None: the adopting block) and
        duration_s (0: until stop). Returns the voice's id. FulgurError:
        the engine refused it (docs/aero-objects.md, "Bad input")."""
        from .aero import AeroTexture
        if not isinstance(texture, AeroTexture):
            raise TypeError(f"Engine.post_aero: texture: expected an AeroTexture, got "
                            f"{type(texture).__name__}")
        if body not in BODIES:
            raise ValueError(f"body: unknown {body!r} (known: {', '.join(BODIES)})")
        o = ffi.new("fg_aero_object *")
        o.texture = texture._handle
        o.body = BODIES[body]
        _aero_pose(o.pose, position, axis, normal, velocity, 0.0)
        _aero_wind(o.wind, (0.0, 0.0, 0.0) if wind is None else wind, gust, gust_period_s, seed)
        o.absorption = propagation_config({"absorption": absorption}).absorption
        _convert.fill(o, {"start_m": start_m, "end_m": end_m, "sources": sources, "gain": gain,
                          "emit_time_s": EMIT_NOW if emit_time_s is None else emit_time_s,
                          "duration_s": duration_s}, "post_aero")
        voice = ffi.new("fg_voice_id *")
        handle = self._enter(self._sim, "post_aero")
        try:
            code = lib.fg_aero_object_post(handle, o, voice)
        finally:
            self._leave(self._sim)
        check(code, "Engine.post_aero")
        self._textures.append(texture)
        return voice[0]

    def set_aero_pose(self, voice, position, axis, normal, velocity=(0.0, 0.0, 0.0),
                      time_s=0.0, angular_velocity=(0.0, 0.0, 0.0), velocity_given=False):
        """Publishes where aero object voice is at time_s on the engine
        clock (0: now), its velocity (m/s) and angular velocity (rad/s;
        all zero: from the poses, unless velocity_given, when zeros are
        at rest): fg_aero_object_set_pose. One thread per object."""
        pose = ffi.new("fg_aero_pose *")
        _aero_pose(pose, position, axis, normal, velocity, time_s)
        _set3(pose.angular_velocity, angular_velocity, "angular_velocity")
        pose.velocity_given = 1 if velocity_given else 0
        handle = self._enter(None, "set_aero_pose")
        try:
            code = lib.fg_aero_object_set_pose(handle, _voice(voice, "set_aero_pose"), pose)
        finally:
            self._leave(None)
        check(code, "Engine.set_aero_pose")

    def set_aero_wind(self, voice, velocity, gust=0.0, gust_period_s=0.0, seed=0):
        """Changes aero object voice's wind (fg_aero_object_set_wind):
        blended in over 20 ms from the next block on. One thread per
        object."""
        wind = ffi.new("fg_aero_wind *")
        _aero_wind(wind, velocity, gust, gust_period_s, seed)
        handle = self._enter(None, "set_aero_wind")
        try:
            code = lib.fg_aero_object_set_wind(handle, _voice(voice, "set_aero_wind"), wind)
        finally:
            self._leave(None)
        check(code, "Engine.set_aero_wind")

    def aero_report(self, voice):
        """What aero object voice has done (fg_aero_report) as a dict:
        sources, blocks, beyond_range_blocks, max_speed_m_s."""
        report = ffi.new("fg_aero_report *")
        handle = self._enter(None, "aero_report")
        try:
            code = lib.fg_aero_object_get_report(handle, _voice(voice, "aero_report"), report)
        finally:
            self._leave(None)
        check(code, "Engine.aero_report")
        return _convert.as_dict(report)

    def post_fire(self, position, *, velocity=(0.0, 0.0, 0.0), gain=0.0, absorption="off",
                  emit_time_s=None, ring_s=0.0):
        """Posts a fire voice (fg_fire_voice_post): a point source at
        position (moving at velocity) whose stream, the fire's pressure at
        1 m, you push with push_fire or a FireFeed; absorption "off" or
        "iso9613"; emit_time_s the engine clock of stream frame 0 (None:
        the adopting block); ring_s the sample ring's seconds (0: 0.5).
        Returns the voice's id. FulgurError: the engine refused it
        (docs/fire-voice.md)."""
        f = ffi.new("fg_fire_voice *")
        _fire_pose(f.pose, position, velocity, 0.0)
        f.absorption = propagation_config({"absorption": absorption}).absorption
        _convert.fill(f, {"gain": gain, "ring_s": ring_s,
                          "emit_time_s": EMIT_NOW if emit_time_s is None else emit_time_s},
                      "post_fire")
        voice = ffi.new("fg_voice_id *")
        handle = self._enter(self._sim, "post_fire")
        try:
            code = lib.fg_fire_voice_post(handle, f, voice)
        finally:
            self._leave(self._sim)
        check(code, "Engine.post_fire")
        return int(voice[0])

    def set_fire_pose(self, voice, position, velocity=(0.0, 0.0, 0.0), time_s=0.0):
        """Publishes where fire voice is at time_s on the engine clock (0:
        now): fg_fire_voice_set_pose. One thread per fire."""
        pose = ffi.new("fg_fire_pose *")
        _fire_pose(pose, position, velocity, time_s)
        handle = self._enter(None, "set_fire_pose")
        try:
            code = lib.fg_fire_voice_set_pose(handle, _voice(voice, "set_fire_pose"), pose)
        finally:
            self._leave(None)
        check(code, "Engine.set_fire_pose")

    def push_fire(self, voice, pa_at_1m):
        """Appends samples (the fire's pressure at 1 m, Pa, one per audio
        frame) to fire voice's stream, as many as its ring has room for:
        fg_fire_voice_push. Returns how many were taken; push the rest
        again later. A sim-thread call."""
        samples = np.ascontiguousarray(pa_at_1m, dtype=np.float32)
        if samples.ndim != 1:
            raise ValueError(f"Engine.push_fire: pa_at_1m: expected one dimension, got shape "
                             f"{samples.shape}")
        pushed = ffi.new("size_t *")
        handle = self._enter(self._sim, "push_fire")
        try:
            code = lib.fg_fire_voice_push(handle, _voice(voice, "push_fire"),
                                          ffi.from_buffer("float[]", samples), samples.size,
                                          pushed)
        finally:
            self._leave(self._sim)
        check(code, "Engine.push_fire")
        return int(pushed[0])

    def close_fire(self, voice):
        """Ends fire voice's stream (fg_fire_voice_close): it plays what it
        holds and finishes. A sim-thread call."""
        handle = self._enter(self._sim, "close_fire")
        try:
            code = lib.fg_fire_voice_close(handle, _voice(voice, "close_fire"))
        finally:
            self._leave(self._sim)
        check(code, "Engine.close_fire")

    def fire_report(self, voice):
        """What fire voice has done (fg_fire_voice_report) as a dict:
        capacity_frames, pushed_frames, held_frames, read_frame,
        underrun_frames, underruns, blocks, closed."""
        report = ffi.new("fg_fire_voice_report *")
        handle = self._enter(None, "fire_report")
        try:
            code = lib.fg_fire_voice_get_report(handle, _voice(voice, "fire_report"), report)
        finally:
            self._leave(None)
        check(code, "Engine.fire_report")
        return _convert.as_dict(report)

    def stop(self, voice):
        """Ends a continuous voice (or a bolt's later strokes)."""
        voice = _voice(voice, "stop")
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
                     velocity=(0.0, 0.0, 0.0), angular_velocity=(0.0, 0.0, 0.0),
                     velocity_given=False):
        """Publishes the listener's pose: position (metres), forward and up
        (any length, not parallel), velocity (m/s) and angular velocity
        (rad/s; all zero: from the poses, unless velocity_given, when
        zeros are at rest)."""
        pose = ffi.new("fg_listener *")
        for name, value in (("position", position), ("forward", forward), ("up", up),
                            ("velocity", velocity), ("angular_velocity", angular_velocity)):
            v = _convert.vector(value, 3, name)
            target = getattr(pose, name)
            for i in range(3):
                target[i] = float(v[i])
        pose.velocity_given = 1 if velocity_given else 0
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
        return {k: list(getattr(pose, k))
                for k in ("position", "forward", "up", "velocity", "angular_velocity")}

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


def _voice(voice, what):
    voice = operator.index(voice)
    if not 0 <= voice < 2**64:
        raise ValueError(f"Engine.{what}: {voice} is not a voice id")
    return voice


def _set3(target, value, what):
    v = _convert.vector(value, 3, what)
    for i in range(3):
        target[i] = float(v[i])


def _aero_pose(pose, position, axis, normal, velocity, time_s):
    for name, value in (("position", position), ("axis", axis), ("normal", normal),
                        ("velocity", velocity)):
        _set3(getattr(pose, name), value, name)
    pose.time_s = float(time_s)


def _fire_pose(pose, position, velocity, time_s):
    _set3(pose.position, position, "position")
    _set3(pose.velocity, velocity, "velocity")
    pose.time_s = float(time_s)


def _aero_wind(wind, velocity, gust, gust_period_s, seed):
    _set3(wind.velocity, velocity, "wind")
    wind.gust = float(gust)
    wind.gust_period_s = float(gust_period_s)
    wind.seed = operator.index(seed)
