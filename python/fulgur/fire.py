"""A flame's flux turned into a fire voice's sound (fulgur/fire_voice.h,
fg_fire_feed) from Python: a game's or a study's own flame simulation
drives the engine's fire voice (docs/python.md, docs/fire-voice.md).

    with fulgur.Engine() as e:
        e.set_listener([0, 0, 1.2])
        voice = e.post_fire([0, 3, 0.3])
        feed = fulgur.FireFeed(e, sim_rate_hz=360, alpha=3.0)
        taken = feed.push(voice, flux)         # I in m^3/s, one per simulation step
        block = e.render(256)
        ...
        while not feed.finish(voice):          # no more flux: drain, then close
            e.render(256)

The feed runs fg_fire_sound (p = dI/dt through the 30 Hz high-pass and
the bandwidth extension of Chadwick & James' section 4, or the low band
alone) at the engine's rate, scales it to pascals at 1 m and pushes it
into the voice's ring, as far as the ring takes: push what it did not
take again later. Its calls are the sim thread's, as Engine.post's.
"""
import numpy as np

from ._native import ffi, lib
from .errors import check

EXTENSIONS = {"bwe": lib.FG_FIRE_BANDWIDTH_EXTENSION, "low": lib.FG_FIRE_LOW_ONLY}


class FireFeed:
    """One fg_fire_feed for fires of engine (an Engine): its flux at
    sim_rate_hz (360; 10 .. the engine's rate / 4); extension "bwe"
    (power-law noise P(f) ~ f^-alpha above the simulation's Nyquist
    frequency, seeded by seed) or "low" (the simulated band alone);
    highpass_hz the high-pass on p (0: 30 Hz, negative: none). FulgurError
    names what fg_fire_feed_create refused. Texture synthesis is not
    offered here yet (fulgur render's scenes have it)."""

    def __init__(self, engine, *, sim_rate_hz=360.0, extension="bwe", alpha=3.0, seed=0,
                 highpass_hz=0.0):
        if extension not in EXTENSIONS:
            raise ValueError(f"FireFeed: extension: unknown {extension!r} (known: "
                             f"{', '.join(EXTENSIONS)})")
        cfg = ffi.new("fg_fire_sound_config *")
        cfg.sample_rate_hz = engine._config["sample_rate_hz"]
        cfg.sim_rate_hz = float(sim_rate_hz)
        cfg.highpass_hz = float(highpass_hz)
        cfg.extension = EXTENSIONS[extension]
        cfg.bwe.alpha = float(alpha)
        cfg.bwe.seed = int(seed)
        out = ffi.new("fg_fire_feed **")
        check(lib.fg_fire_feed_create(cfg, 0, out), "FireFeed")
        self._handle = ffi.gc(out[0], lib.fg_fire_feed_destroy)
        self._engine = engine

    @property
    def latency_s(self):
        """How far the sound lags the flux (fg_fire_sound_latency_s)."""
        return lib.fg_fire_feed_latency_s(self._handle)

    def push(self, voice, flux_m3_s):
        """Turns flux (I, m^3/s, the steps after those already taken) into
        sound and pushes it into fire voice's ring while the ring takes
        everything: fg_fire_feed_push. Returns the steps taken (fewer when
        the ring filled: give the rest again)."""
        flux = np.ascontiguousarray(flux_m3_s, dtype=np.float64)
        if flux.ndim != 1:
            raise ValueError(f"FireFeed.push: flux_m3_s: expected one dimension, got shape "
                             f"{flux.shape}")
        taken = ffi.new("size_t *")
        e = self._engine
        handle = e._enter(e._sim, "FireFeed.push")
        try:
            code = lib.fg_fire_feed_push(self._handle, handle, int(voice),
                                         ffi.from_buffer("double[]", flux), flux.size, taken)
        finally:
            e._leave(e._sim)
        check(code, "FireFeed.push")
        return int(taken[0])

    def finish(self, voice):
        """Ends the flux: drains the sound, pushes what fits and, once
        nothing is held, closes the voice's stream (fg_fire_feed_finish).
        Returns whether it has closed it; call again, after a render has
        emptied the ring, until it has."""
        done = ffi.new("bool *")
        e = self._engine
        handle = e._enter(e._sim, "FireFeed.finish")
        try:
            code = lib.fg_fire_feed_finish(self._handle, handle, int(voice), done)
        finally:
            e._leave(e._sim)
        check(code, "FireFeed.finish")
        return bool(done[0])
