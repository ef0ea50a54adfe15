"""Fire voices from Python (Engine.post_fire, push_fire, close_fire,
set_fire_pose, fire_report, and fulgur.FireFeed): a pushed stream is
heard as a point source (a 250 Hz tone of 1 Pa at 1 m is 1/r at 4 m
within 0.05 dB and arrives r / c later, to the frame); the campfire's
flux through a FireFeed plays at the level fulgur.render gives its
scene; an unfed voice counts its underrun; bad input is refused."""
import os
import re

import numpy as np
import pytest

import fulgur
from conftest import example

RATE = 48000


def rms(x):
    return float(np.sqrt(np.mean(np.square(x, dtype=np.float64))))


def render(e, seconds, block=256):
    return np.concatenate([e.render(block) for _ in range(int(seconds * RATE) // block)])


def flux_file(name):
    text = open(example(os.path.join("fire", name))).read()
    text = "\n".join(line.split("#")[0] for line in text.splitlines())
    return np.array([float(v) for v in re.split(r"[\s,]+", text) if v])


def test_pushed_stream_is_a_point_source():
    """A 250 Hz tone of 1 Pa at 1 m, 4 m away: 0.25 Pa peak (1/r) within
    0.05 dB once it has arrived, and silence before r / c."""
    with fulgur.Engine(sample_rate_hz=RATE, channels=1, max_block_frames=256) as e:
        c = e._config["speed_of_sound_m_s"]
        e.set_listener([0, 0, 0], forward=[0, 1, 0])
        voice = e.post_fire([0, 4, 0], emit_time_s=0.0)
        tone = np.sin(2 * np.pi * 250 * np.arange(RATE) / RATE).astype(np.float32)
        given, heard = 0, []
        for _ in range(3 * RATE // 4 // 256):
            given += e.push_fire(voice, tone[given:])
            heard.append(e.render(256))
        report = e.fire_report(voice)
    x = np.concatenate(heard)[:, 0]
    arrive = int(np.argmax(np.abs(x) > 1e-6))
    want = 4.0 / c * RATE
    steady = x[int(want) + RATE // 20:int(want) + RATE // 20 + RATE // 5]
    db = 20 * np.log10(rms(steady) * np.sqrt(2) / 0.25)
    print(f"fire voice: arrives at frame {arrive} (4 m / c: {want:.1f}), "
          f"{rms(steady) * np.sqrt(2):.5f} Pa peak at 4 m ({db:+.3f} dB against 1/r)")
    assert abs(arrive - want) <= 3
    assert abs(db) < 0.05
    assert report["pushed_frames"] == RATE and report["underrun_frames"] == 0


def test_feed_plays_the_campfire_as_its_scene():
    """examples/fire/campfire.flux through a FireFeed into a voice where
    examples/fire/campfire.json has it: its RMS within 0.5 dB of what
    fulgur.render gives the scene (the scene's two ears, averaged)."""
    flux = flux_file("campfire.flux")
    seconds = 2.0
    scene, _ = fulgur.render(example(os.path.join("fire", "campfire.json")),
                             overrides={"duration": seconds})
    with fulgur.Engine(sample_rate_hz=RATE, max_block_frames=256) as e:
        e.set_listener([0, 0, 1.2], forward=[0, 1, 0])
        voice = e.post_fire([0, 3, 0.3], emit_time_s=0.0)
        feed = fulgur.FireFeed(e, sim_rate_hz=360, alpha=3.0, seed=1)
        assert 0 < feed.latency_s < 0.5
        given, out = 0, []
        for _ in range(int(seconds * RATE) // 256):
            given += feed.push(voice, flux[given:])
            out.append(e.render(256))
        x = np.concatenate(out)
    got, want = rms(x), rms(scene[:len(x)])
    db = 20 * np.log10(got / want)
    print(f"campfire through FireFeed: rms {got:.5f} Pa, fulgur.render {want:.5f} Pa ({db:+.2f} dB)")
    assert abs(db) < 0.5


def test_underrun_close_and_bad_input():
    """An unfed voice counts its underrun; a NaN sample, a flux rate
    above a quarter of the engine's, a push after close are refused by
    name; a closed voice finishes and is collected."""
    with fulgur.Engine(sample_rate_hz=RATE, channels=1, max_block_frames=256) as e:
        voice = e.post_fire([0, 2, 0], emit_time_s=0.0)
        render(e, 0.1)
        assert e.fire_report(voice)["underrun_frames"] > 0
        with pytest.raises(fulgur.FulgurError, match="push_fire"):
            e.push_fire(voice, np.array([0.0, np.nan], dtype=np.float32))
        with pytest.raises(fulgur.FulgurError, match="FireFeed"):
            fulgur.FireFeed(e, sim_rate_hz=RATE / 2)
        with pytest.raises(ValueError, match="extension"):
            fulgur.FireFeed(e, extension="texture")
        e.close_fire(voice)
        with pytest.raises(fulgur.FulgurError, match="push_fire"):
            e.push_fire(voice, np.zeros(16, dtype=np.float32))
        render(e, 0.1)
        e.collect()
        with pytest.raises(fulgur.FulgurError, match="fire_report"):
            e.fire_report(voice)
