"""Every bad argument raises a Python exception carrying what is wrong;
none crashes the interpreter. Each case runs in this process: a crash
fails the whole file."""
import math

import numpy as np
import pytest

import fulgur

NAN = math.nan
SEG = [[0, 1, 1.7, -1], [0, 1.01, 1.7, 0]]


def engine():
    e = fulgur.Engine(channels=1, max_block_frames=256)
    e.set_listener([0, 0, 1.7])
    return e


def closed_engine():
    e = fulgur.Engine()
    e.close()
    return e


# (what, call, the exception, a piece of its message)
CASES = [
    # the engine's configuration
    ("channels 3", lambda: fulgur.Engine(channels=3), fulgur.FulgurError, "argument"),
    ("rate NaN", lambda: fulgur.Engine(sample_rate_hz=NAN), fulgur.FulgurError, "finite"),
    ("rate 1000", lambda: fulgur.Engine(sample_rate_hz=1000), fulgur.FulgurError, "sample rate"),
    ("channels -1", lambda: fulgur.Engine(channels=-1), ValueError, "config.channels"),
    ("channels 2.5", lambda: fulgur.Engine(channels=2.5), TypeError, "config.channels"),
    ("channels '2'", lambda: fulgur.Engine(channels="2"), TypeError, "config.channels"),
    ("unknown key", lambda: fulgur.Engine(voices=3), TypeError, "unknown setting 'voices'"),
    ("config list", lambda: fulgur.Engine([1, 2]), TypeError, "config"),
    ("block 10**6", lambda: fulgur.Engine(max_block_frames=10**6), fulgur.FulgurError, ""),
    # post: the tree
    ("nodes of text", lambda: engine().post([["a", "b", "c", "d"]], "spark_balls"), TypeError,
     "nodes"),
    ("nodes (n, 3)", lambda: engine().post([[0, 0, 0], [0, 0, 1]], "spark_balls"), ValueError,
     "shape"),
    ("nodes 1-D", lambda: engine().post([0, 0, 0, -1], "spark_balls"), ValueError, "shape"),
    ("nodes empty", lambda: engine().post(np.zeros((0, 4)), "spark_balls"), fulgur.FulgurError,
     "no node"),
    ("one node", lambda: engine().post([[0, 0, 0, -1]], "spark_balls"), fulgur.FulgurError,
     "nodes"),
    ("NaN coordinate", lambda: engine().post([[0, 0, 0, -1], [NAN, 0, 1, 0]], "spark_balls"),
     fulgur.FulgurError, "node 1"),
    ("parent after", lambda: engine().post([[0, 0, 0, -1], [0, 0, 1, 5]], "spark_balls"),
     fulgur.FulgurError, "parent 5"),
    ("parent 0.5", lambda: engine().post([[0, 0, 0, -1], [0, 0, 1, 0.5]], "spark_balls"),
     ValueError, "parent"),
    ("parent NaN", lambda: engine().post([[0, 0, 0, -1], [0, 0, 1, NAN]], "spark_balls"),
     ValueError, "parent"),
    ("parent 2**40", lambda: engine().post([[0, 0, 0, -1], [0, 0, 1, 2**40]], "spark_balls"),
     ValueError, "parent"),
    ("flags -1", lambda: engine().post([[0, 0, 0, -1, 0], [0, 0, 1, 0, -1]], "spark_balls"),
     ValueError, "flags"),
    ("zero length", lambda: engine().post([[0, 0, 0, -1], [0, 0, 0, 0]], "spark_balls"),
     fulgur.FulgurError, "node 1"),
    ("wrong structured", lambda: engine().post(np.zeros(2, dtype=[("x", "f4")]), "spark_balls"),
     TypeError, "NODE_DTYPE"),
    ("2-D structured", lambda: engine().post(np.zeros((2, 2), dtype=fulgur.NODE_DTYPE),
                                             "spark_balls"), ValueError, "dimension"),
    # post: the rest
    ("unknown preset", lambda: engine().post(SEG, "sprak"), ValueError, "sprak"),
    ("preset 3", lambda: engine().post(SEG, 3), TypeError, "sound"),
    ("sound key", lambda: engine().post(SEG, {"preset": "spark_balls", "T0": 1}), TypeError,
     "unknown setting 'T0'"),
    ("sound NaN", lambda: engine().post(SEG, {"preset": "spark_balls", "t0_s": NAN}),
     fulgur.FulgurError, "finite"),
    ("sound no preset", lambda: engine().post(SEG, {"t0_s": 1e-5}), fulgur.FulgurError, ""),
    ("emit NaN", lambda: engine().post(SEG, "spark_balls", emit_time_s=NAN), fulgur.FulgurError,
     "finite"),
    ("emit -5", lambda: engine().post(SEG, "spark_balls", emit_time_s=-5), fulgur.FulgurError,
     "argument"),
    ("emit text", lambda: engine().post(SEG, "spark_balls", emit_time_s="now"), TypeError,
     "emit_time_s"),
    ("strokes 33", lambda: engine().post(SEG, "spark_balls", strokes=33), fulgur.FulgurError,
     "argument"),
    ("strokes -1", lambda: engine().post(SEG, "spark_balls", strokes=-1), ValueError, "strokes"),
    ("seed 2**64", lambda: engine().post(SEG, "spark_balls", seed=2**64), ValueError, "seed"),
    ("repeat min > max", lambda: engine().post(SEG, "plasma_ball", continuous=True,
                                              repeat_min_s=0.5, repeat_max_s=0.1),
     fulgur.FulgurError, "argument"),
    ("model", lambda: engine().post(SEG, "spark_balls", model="xyz"), ValueError, "model"),
    ("absorption", lambda: engine().post(SEG, "spark_balls", propagation={"absorption": "x"}),
     ValueError, "absorption"),
    ("refraction 5 m", lambda: engine().post(SEG, "spark_balls",
                                             propagation={"refraction_radius_m": 5}),
     fulgur.FulgurError, "argument"),
    ("propagation list", lambda: engine().post(SEG, "spark_balls", propagation=[1]), TypeError,
     "propagation"),
    # render, listener, stop
    ("render -1", lambda: engine().render(-1), ValueError, "frames"),
    ("render 257", lambda: engine().render(257), ValueError, "max_block_frames"),
    ("render 1.5", lambda: engine().render(1.5), TypeError, ""),
    ("render None", lambda: engine().render(None), TypeError, ""),
    ("listener NaN", lambda: engine().set_listener([NAN, 0, 0]), fulgur.FulgurError, "finite"),
    ("listener parallel", lambda: engine().set_listener([0, 0, 0], [0, 1, 0], [0, 2, 0]),
     fulgur.FulgurError, "argument"),
    ("listener (2,)", lambda: engine().set_listener([0, 0]), ValueError, "position"),
    ("listener text", lambda: engine().set_listener("abc"), TypeError, "position"),
    ("stop -1", lambda: engine().stop(-1), ValueError, "voice"),
    ("stop unknown", lambda: engine().stop(12345), fulgur.FulgurError, "no live voice"),
    ("stop text", lambda: engine().stop("a"), TypeError, ""),
    # a closed engine
    ("closed render", lambda: closed_engine().render(16), ValueError, "closed"),
    ("closed post", lambda: closed_engine().post(SEG, "spark_balls"), ValueError, "closed"),
    ("closed stats", lambda: closed_engine().stats(), ValueError, "closed"),
    # scenes
    ("scene 5", lambda: fulgur.render(5), TypeError, "scene"),
    ("scene NaN", lambda: fulgur.render({"duration": NAN}), fulgur.SceneError, "JSON"),
    ("scene object", lambda: fulgur.render({"seed": object()}), TypeError, "JSON"),
    ("scene missing", lambda: fulgur.render("/nonexistent/x.json"), fulgur.FulgurError,
     "/nonexistent/x.json: cannot open"),
    ("scene no discharges", lambda: fulgur.render({}), fulgur.SceneError, "discharges"),
    ("overrides key", lambda: fulgur.render({}, overrides={1: 2}), TypeError, "overrides"),
    ("overrides str", lambda: fulgur.render({}, overrides="seed=1"), TypeError, "overrides"),
    ("overrides [3]", lambda: fulgur.render({}, overrides=[3]), TypeError, "overrides"),
    ("override NaN", lambda: fulgur.render({}, overrides={"seed": NAN}), fulgur.SceneError,
     "seed"),
    ("write_wav text", lambda: fulgur.write_wav("/tmp/x.wav", "abc", 48000), TypeError,
     "samples"),
    ("write_wav (n, 3)", lambda: fulgur.write_wav("/tmp/x.wav", np.zeros((4, 3)), 48000),
     ValueError, "shape"),
    ("write_wav rate", lambda: fulgur.write_wav("/tmp/x.wav", np.zeros(4), 100), ValueError,
     "8000"),
    ("write_wav dir", lambda: fulgur.write_wav("/nonexistent/x.wav", np.zeros(4), 48000),
     OSError, "cannot create"),
    # generators
    ("skeleton (k, 2)", lambda: fulgur.lightning(skeleton=[[0, 0], [1, 1]]), ValueError,
     "skeleton"),
    ("skeleton 1 point", lambda: fulgur.lightning(skeleton=[[0, 0, 100]]), ValueError,
     "skeleton"),
    ("skeleton NaN", lambda: fulgur.lightning(skeleton=[[0, 0, NAN], [0, 0, 0]]),
     fulgur.FulgurError, "finite"),
    ("skeleton underground", lambda: fulgur.lightning(skeleton=[[0, 0, 100], [0, 0, -5]]),
     fulgur.FulgurError, "argument"),
    ("feature kind", lambda: fulgur.lightning(features=[{"kind": "boom"}]), ValueError, "boom"),
    ("feature range", lambda: fulgur.lightning(features=[{"kind": "clap", "start": 0.8,
                                                           "end": 0.2}]),
     fulgur.FulgurError, "argument"),
    ("17 features", lambda: fulgur.lightning(features=[{"kind": "roar"}] * 17), ValueError,
     "at most"),
    ("height -1", lambda: fulgur.lightning(height_m=-1), fulgur.FulgurError, "argument"),
    ("lightning key", lambda: fulgur.lightning(hieght_m=1), TypeError, "hieght_m"),
    ("charges (k, 3)", lambda: fulgur.charges([[0, 0, 1]], [0, 0, 1]), ValueError, "charges"),
    ("no charges", lambda: fulgur.charges(np.zeros((0, 4)), [0, 0, 100]), fulgur.FulgurError,
     "argument"),
    ("start NaN", lambda: fulgur.charges([[0, 0, 5000, -10]], [0, 0, NAN]), fulgur.FulgurError,
     "finite"),
    ("start underground", lambda: fulgur.charges([[0, 0, 5000, -10]], [0, 0, -1]),
     fulgur.FulgurError, "argument"),
    ("grow lightning", lambda: fulgur.grow("lightning"), fulgur.FulgurError, "argument"),
    ("grow size 3", lambda: fulgur.grow("spark_balls", size=3), fulgur.FulgurError, "argument"),
    ("grow size text", lambda: fulgur.grow("spark_balls", size="65"), TypeError, "size"),
    ("grow method", lambda: fulgur.grow("spark_balls", method="x"), ValueError, "method"),
    ("grow nothing", lambda: fulgur.grow(), fulgur.FulgurError, ""),
    ("shape outside", lambda: fulgur.grow("spark_balls", size=17, shapes=[
        {"kind": "sphere", "role": "origin", "centre_m": [5, 5, 5], "radius_m": 0.01},
        {"kind": "ground", "role": "target"}]), fulgur.FulgurError, "shapes[0]"),
    ("shape kind", lambda: fulgur.grow("spark_balls", shapes=[{"kind": "cone"}]), ValueError,
     "cone"),
    ("shapes 65", lambda: fulgur.grow("spark_balls", shapes=[{}] * 65), ValueError, "at most"),
    ("grid size (2,)", lambda: fulgur.grow("spark_balls", grid={"size": [9, 9]}), ValueError,
     "grid.size"),
    ("grid size 9.5", lambda: fulgur.grow("spark_balls", grid={"size": [9.5, 9, 9]}),
     ValueError, "grid.size"),
    ("growth step 0", lambda: fulgur.grow("spark_balls", size=17, growth={"step_m": 0}),
     fulgur.FulgurError, "argument"),
]


@pytest.mark.parametrize("what,call,error,text", CASES, ids=[c[0] for c in CASES])
def test_bad_argument_raises(what, call, error, text):
    with pytest.raises(error) as raised:
        call()
    assert text in str(raised.value), f"{what}: {raised.value}"
    if isinstance(raised.value, fulgur.FulgurError):
        assert raised.value.code < 0 and raised.value.name.startswith("FG_ERR_")


def test_nothing_changed_after_refusals():
    """Refused posts leave the engine as it was: nothing posted, dropped
    or sounding; a good post still works."""
    e = engine()
    for nodes in ([[0, 0, 0, -1], [NAN, 0, 1, 0]], [[0, 0, 0, -1], [0, 0, 1, 5]]):
        with pytest.raises(fulgur.FulgurError):
            e.post(nodes, "spark_balls")
    with pytest.raises(fulgur.FulgurError):
        e.post(SEG, "spark_balls", strokes=40)
    assert e.stats()["posted"] == 0 and e.stats()["dropped_posts"] == 0
    assert not e.render(256).any()
    e.post(SEG, "spark_balls", strokes=1)  # now: the clock is past 0
    out = np.concatenate([e.render(256) for _ in range(4)])
    assert e.stats()["posted"] == 1 and np.abs(out).max() > 0
