"""The engine API: post -> render -> collect, the CLI's samples through it,
the listener, the counters, and the lifetime."""
import threading

import numpy as np
import pytest

import fulgur

RATE = 48000
C = 343.0


def segment(y=10.0, z=1.7, length=0.01):
    return [[0.0, y, z, -1], [0.0, y + length, z, 0]]


def test_post_render_collect_round_trip():
    """One spark segment 10 m ahead: it is posted, adopted, arrives at
    emit + r/c, finishes, and is collected."""
    with fulgur.Engine(sample_rate_hz=RATE, channels=1, max_block_frames=512) as e:
        e.set_listener([0, 0, 1.7])
        voice = e.post(segment(), "spark_balls", emit_time_s=0.1, strokes=1, seed=3)
        assert voice != 0
        assert e.stats()["posted"] == 1 and e.collect() == 0
        out = np.concatenate([e.render(512) for _ in range(40)])  # 0.43 s
        assert out.shape == (40 * 512, 1) and out.dtype == np.float32
        assert e.frames == 40 * 512 and e.time_s == pytest.approx(40 * 512 / RATE)
        stats = e.stats()
        assert (stats["adopted"], stats["finished"], stats["late_events"]) == (1, 1, 0)
        assert e.collect() == 1 and e.stats()["collected"] == 1
        r = np.hypot(10.005, 0.0)  # the segment's midpoint to the ear
        arrival = (0.1 + r / C) * RATE
        first = int(np.argmax(np.abs(out[:, 0]) > 1e-6))
        # the N-wave (T about 56 us = 2.7 samples at 10 m) starts just before arrival
        assert arrival - 4 <= first <= arrival + 1
        # eq. 3 (Matsuyama): the broadside N-wave's peak ps at r, scaled by
        # the line integral (a half-length of 5 mm against the preset's l);
        # each sample is the N-wave's average over its interval, so at most
        # ps, and with T = 2.8 samples well above half of it
        p = fulgur.preset_sound("spark_balls")
        stretch = np.sqrt(1 + p["sigma0"] * np.log(r / p["r0_m"]))
        ps = p["r0_m"] * p["ps0_pa"] / (r * stretch) * 0.005 / p["ref_half_len_m"]
        assert 0.5 * ps <= np.abs(out).max() <= ps
        # the N-wave lasts 2T = 5.6 samples; then silence (the accumulator's
        # rounding leaves 1e-12 Pa at most)
        assert np.abs(out[first + 8:]).max() < 1e-9


def test_engine_reproduces_the_scene_render():
    """Posting a scene's discharge through the Engine as fulgur render does
    (same config, emit time, pose, 256-frame blocks in 1024-frame chunks)
    gives its samples."""
    nodes, _ = fulgur.lightning(seed=2, height_m=1500)
    nodes["y"] += 2000.0
    rows = [[float(n["x"]), float(n["y"]), float(n["z"]), int(n["parent"]), int(n["flags"])]
            for n in nodes]
    scene = {"sample_rate": RATE, "channels": 2, "block": 256, "duration": 8.0, "seed": 1,
             "listener": {"position": [0, 0, 1.7], "forward": [0, 1, 0], "up": [0, 0, 1]},
             "discharges": [{"time": 0.3, "preset": "lightning", "strokes": 2, "seed": 5,
                             "tree": {"nodes": rows}}]}
    expected = fulgur.render(scene).samples
    with fulgur.Engine(sample_rate_hz=RATE, channels=2, max_block_frames=256, max_voices=1,
                       segment_capacity=len(nodes) - 1, chunk_frames=1024) as e:
        e.set_listener([0, 0, 1.7], [0, 1, 0], [0, 0, 1])
        e.post(nodes, "lightning", emit_time_s=0.3, strokes=2, seed=5)
        blocks = []
        for _ in range(int(8.0 * RATE) // 256):
            e.set_listener([0, 0, 1.7], [0, 1, 0], [0, 0, 1])
            blocks.append(e.render(256))
            e.collect()
    got = np.ascontiguousarray(np.concatenate(blocks))
    assert got.shape == expected.shape
    assert got.tobytes() == expected.tobytes()
    assert np.abs(got).max() > 1e-3


def test_listener_and_config():
    with fulgur.Engine({"channels": 2}, max_voices=4) as e:
        assert e.config["max_voices"] == 4 and e.config["sample_rate_hz"] == 48000
        assert e.channels == 2 and e.sample_rate_hz == 48000
        e.set_listener([1, 2, 3], forward=[0, 2, 0], velocity=[1, 0, 0],
                       angular_velocity=[0, 0, 0.5])
        pose = e.listener
        assert pose["position"] == [1, 2, 3] and pose["forward"] == [0, 2, 0]
        assert pose["velocity"] == [1, 0, 0] and pose["angular_velocity"] == [0, 0, 0.5]
        with pytest.raises(fulgur.FulgurError):
            e.set_listener([1, 2, 3], angular_velocity=[2e4, 0, 0])  # above 1e4 rad/s


def test_continuous_voice_stops():
    """A continuous plasma-ball voice sounds until stopped, then finishes."""
    tree = [[0, 0.5, 1.7, -1], [0.01, 0.5, 1.7, 0], [0.02, 0.51, 1.7, 1]]
    with fulgur.Engine(channels=1) as e:
        e.set_listener([0, 0, 1.7])
        voice = e.post(tree, "plasma_ball", continuous=True, seed=1)
        loud = np.concatenate([e.render(480) for _ in range(50)])  # 0.5 s
        assert e.stats()["finished"] == 0
        e.stop(voice)
        for _ in range(50):
            e.render(480)
        assert e.stats()["finished"] == 1 and e.collect() == 1
        # repeats every 10-50 ms: at least ten pulses in half a second
        onsets = np.flatnonzero(np.diff((np.abs(loud[:, 0]) > 1e-3).astype(int)) == 1)
        assert len(onsets) >= 10
        with pytest.raises(fulgur.FulgurError) as raised:
            e.stop(voice)
        assert raised.value.name == "FG_ERR_NOT_FOUND"


def test_nodes_dtype_and_rows_agree():
    """A NODE_DTYPE array and the same rows post the same sound."""
    rows = segment(y=5.0)
    arr = np.zeros(2, dtype=fulgur.NODE_DTYPE)
    arr["y"], arr["z"], arr["parent"] = [5.0, 5.01], 1.7, [-1, 0]
    outs = []
    for nodes in (rows, arr):
        with fulgur.Engine(channels=1) as e:
            e.set_listener([0, 0, 1.7])
            e.post(nodes, "spark_balls", emit_time_s=0.0, seed=1)
            outs.append(np.concatenate([e.render(256) for _ in range(10)]))
    assert outs[0].tobytes() == outs[1].tobytes() and np.abs(outs[0]).max() > 0


def test_closed_engine_raises():
    e = fulgur.Engine()
    e.close()
    e.close()  # twice is fine
    assert e.closed
    calls = [lambda: e.render(16), lambda: e.post(segment(), "spark_balls"),
             lambda: e.collect(), lambda: e.stop(1), lambda: e.set_listener([0, 0, 0]),
             lambda: e.stats(), lambda: e.frames, lambda: e.listener]
    for call in calls:
        with pytest.raises(ValueError, match="closed"):
            call()


def test_one_renderer_at_a_time():
    """A second thread in render while one is in it is refused, not raced."""
    with fulgur.Engine() as e:
        e._audio.acquire()  # stands for another thread inside render
        try:
            with pytest.raises(RuntimeError, match="another thread"):
                e.render(64)
        finally:
            e._audio.release()
        e._sim.acquire()
        try:
            with pytest.raises(RuntimeError, match="another thread"):
                e.post(segment(), "spark_balls")
        finally:
            e._sim.release()
        assert e.render(64).shape == (64, 2)


def test_render_and_post_on_their_threads():
    """The audio thread renders while the sim thread posts and collects, as
    a host runs them (the engine's rings between them)."""
    e = fulgur.Engine(channels=1, max_voices=8)
    e.set_listener([0, 0, 1.7])
    done = threading.Event()
    errors = []

    def sim():
        try:
            for k in range(20):
                while True:
                    try:
                        e.post(segment(y=2.0 + k * 0.1), "spark_balls", seed=k)
                        break
                    except fulgur.FulgurError as err:
                        if err.name not in ("FG_ERR_POOL_FULL", "FG_ERR_QUEUE_FULL"):
                            raise
                        e.collect()
                e.collect()
        except Exception as err:  # reported below
            errors.append(err)
        finally:
            done.set()

    t = threading.Thread(target=sim)
    t.start()
    blocks = 0
    while not done.is_set() or blocks < 200:
        e.render(256)
        blocks += 1
    t.join()
    for _ in range(100):
        e.render(256)
    e.collect()
    stats = e.stats()
    e.close()
    assert not errors
    assert stats["posted"] == 20 and stats["finished"] == 20 and stats["collected"] == 20
