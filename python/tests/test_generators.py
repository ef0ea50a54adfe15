"""The generators from Python: trees with the properties their headers
promise, measured."""
import numpy as np
import pytest

import fulgur


def segment_lengths(nodes):
    child = nodes[1:]
    parent = nodes[child["parent"]]
    return np.sqrt((child["x"] - parent["x"]) ** 2 + (child["y"] - parent["y"]) ** 2 +
                   (child["z"] - parent["z"]) ** 2)


def test_lightning_walk():
    """Glassner's walk: 3 m steps from the root at 5 km to the ground, the
    main channel first and flagged, turns of mean 16 degrees."""
    nodes, report = fulgur.lightning(seed=7)
    again, _ = fulgur.lightning(seed=7)
    assert nodes.dtype == fulgur.NODE_DTYPE and nodes.tobytes() == again.tobytes()
    main = report["main_nodes"]
    assert report["segments"] == len(nodes) - 1
    assert (nodes["flags"][:main] & fulgur.NODE_MAIN).all()
    assert not (nodes["flags"][main:] & fulgur.NODE_MAIN).any()
    assert nodes["parent"][0] == -1 and (nodes["parent"][1:] < np.arange(1, len(nodes))).all()
    assert nodes["z"][0] == pytest.approx(5000.0, rel=0.05)  # height_m, jittered joints
    assert nodes["z"][main - 1] == pytest.approx(0.0, abs=3.0)  # the strike
    assert (nodes["z"] >= -1e-9).all()
    lengths = segment_lengths(nodes[:main])
    assert np.allclose(lengths[:-5], 3.0, rtol=1e-9)  # the last steps join the end
    d = np.diff(np.stack([nodes["x"][:main], nodes["y"][:main], nodes["z"][:main]], 1), axis=0)
    d /= np.linalg.norm(d, axis=1)[:, None]
    turns = np.degrees(np.arccos(np.clip((d[1:] * d[:-1]).sum(1), -1, 1)))[:-5]
    assert np.mean(turns) == pytest.approx(16.0, rel=0.1)
    assert report["main_length_m"] == pytest.approx(lengths.sum(), rel=1e-9)


def test_lightning_settings_and_features():
    skeleton = [[0, 0, 2000], [300, 0, 1000], [300, 0, 0]]
    nodes, report = fulgur.lightning(skeleton=skeleton, seed=1, branch_probability=-1,
                                     listener_m=[3000, 0, 0],
                                     features=[{"kind": "clap", "start": 0.2, "end": 0.4}])
    assert report["main_nodes"] == len(nodes)  # no branches
    assert (nodes["x"][0], nodes["z"][0]) == (0.0, 2000.0)
    assert nodes["z"][-1] == pytest.approx(0.0, abs=1e-6)
    clap = report["features"][0]
    assert clap["first_node"] < clap["last_node"] < len(nodes)
    # on a clap every node lies at the arc's radius from the listener (within a step)
    arc = nodes[clap["first_node"] + 10:clap["last_node"] + 1]
    r = np.sqrt((arc["x"] - 3000) ** 2 + arc["y"] ** 2 + arc["z"] ** 2)
    assert np.abs(r - clap["distance_m"]).max() < 3.0


def test_lightning_in_cloud_channel():
    """in_cloud_m: the tree without it, then a channel from the root ending
    in_cloud_m away horizontally at the root's height."""
    plain, r0 = fulgur.lightning(seed=4)
    nodes, r = fulgur.lightning(seed=4, in_cloud_m=5000.0, in_cloud_azimuth_deg=45.0)
    assert r0["in_cloud_nodes"] == 0 and r0["in_cloud_first"] == len(plain)
    assert nodes[:len(plain)].tobytes() == plain.tobytes()
    first, count = r["in_cloud_first"], r["in_cloud_nodes"]
    assert first == len(plain) and count >= 5000 // 3 and len(nodes) > first + count
    chan = nodes[first:first + count]
    assert nodes["parent"][first] == 0 and not (chan["flags"] & fulgur.NODE_MAIN).any()
    far = chan[-1]
    assert far["x"] - nodes["x"][0] == pytest.approx(5000 / np.sqrt(2), abs=1e-6)
    assert far["y"] - nodes["y"][0] == pytest.approx(5000 / np.sqrt(2), abs=1e-6)
    assert far["z"] == pytest.approx(nodes["z"][0], abs=1e-6)
    lengths = segment_lengths(nodes)[first - 1:first - 1 + count]  # segment i ends at node i + 1
    assert r["in_cloud_length_m"] == pytest.approx(lengths.sum(), rel=1e-9)


def test_charges_reach_the_ground():
    nodes = fulgur.charges([[0, 0, 6000, -40], [0, 0, 9000, 40]], [0, 0, 5800], seed=2,
                           step_m=20)
    assert tuple(nodes[0][["x", "y", "z"]]) == (0.0, 0.0, 5800.0)
    main = nodes[(nodes["flags"] & fulgur.NODE_MAIN) != 0]
    assert main["z"].min() <= 0.0 < main["z"][-2]
    lengths = segment_lengths(nodes)
    above = nodes["z"][1:] > 0  # a step through the ground ends on it
    assert np.allclose(lengths[above], 20.0, rtol=1e-9) and (lengths <= 20.0 + 1e-9).all()


def test_grow_in_the_spark_gap():
    """Matsuyama growth between the balls: from the origin sphere's surface
    to the target sphere's, to within step / 256 (fulgur/growth.h) on the
    default 65^3 grid, whose 1.1 mm cells resolve the 1 cm balls."""
    field = fulgur.field_scene("spark_balls")
    origin, target = field["shapes"][0], field["shapes"][1]
    assert (origin["role"], target["role"]) == ("origin", "target")
    nodes, report = fulgur.grow("spark_balls", seed=4)
    step = field["growth"]["step_m"]
    assert report["nodes"] == len(nodes) and report["residual"] < 1e-5
    main = nodes[(nodes["flags"] & fulgur.NODE_MAIN) != 0]
    p0 = np.array([main["x"][0], main["y"][0], main["z"][0]])
    p1 = np.array([main["x"][-1], main["y"][-1], main["z"][-1]])
    assert np.linalg.norm(p0 - origin["centre_m"]) - origin["radius_m"] < 2 * step
    assert abs(np.linalg.norm(p1 - target["centre_m"]) - target["radius_m"]) < step / 256
    dbm, rep = fulgur.grow("spark_balls", size=17, method="dbm", seed=4)
    assert len(dbm) == rep["nodes"] > 2 and rep["solves"] >= 1


def test_grow_from_own_shapes():
    """A field given whole: a point origin above a ground target, reached
    within the ground's nodes' half cell (0.0625 m on this 17^3 grid)."""
    nodes, _ = fulgur.grow(grid={"size": [17, 17, 17], "min_m": [-1, -1, 0], "max_m": [1, 1, 2]},
                           shapes=[{"kind": "point", "role": "origin", "centre_m": [0, 0, 1.8]},
                                   {"kind": "ground", "role": "target"}],
                           growth={"step_m": 0.1}, seed=1)
    main = nodes[(nodes["flags"] & fulgur.NODE_MAIN) != 0]
    assert main["z"][0] > 1.5 and main["z"][-1] <= 0.0625 + 1e-9
