"""fulgur.render against fulgur render: the same samples, to the bit, and
the same messages, from one parser and one render loop."""
import glob
import json
import os
import threading

import numpy as np
import pytest

import fulgur
from conftest import SOURCE, cli_render, example, load_json, wav_data

EXAMPLES = sorted(glob.glob(os.path.join(SOURCE, "examples", "*.json")))


@pytest.mark.parametrize("path", EXAMPLES, ids=os.path.basename)
def test_dict_scene_gives_the_cli_samples(path, tmp_path):
    """Every example, as a dict, renders the bytes of fulgur render's WAV data."""
    scene = load_json(path)
    written = tmp_path / "scene.json"
    written.write_text(json.dumps(scene))
    rc, err = cli_render(str(written), str(tmp_path / "cli.wav"))
    assert rc == 0, err
    tag, channels, rate, bits, data = wav_data(tmp_path / "cli.wav")
    samples, sample_rate = fulgur.render(scene)
    assert (tag, bits) == (3, 32)  # WAVE_FORMAT_IEEE_FLOAT
    assert samples.dtype == np.float32 and samples.flags.c_contiguous
    assert samples.shape == (len(data) // (4 * channels), channels)
    assert sample_rate == rate
    assert samples.tobytes() == data
    assert np.abs(samples).max() > 1e-3  # not silence


@pytest.mark.parametrize("name", ["campfire.json", "torch.json"])
def test_fire_scene_gives_the_cli_samples(name, tmp_path):
    """A scene of fires (its flux file beside it) renders fulgur render's
    bytes: the fire voices, their feeds and a moving fire's poses run in
    the one render loop."""
    path = example(os.path.join("fire", name))
    rc, err = cli_render(path, str(tmp_path / "cli.wav"), "--set", "duration=2")
    assert rc == 0, err
    data = wav_data(tmp_path / "cli.wav")[4]
    samples, _ = fulgur.render(path, overrides={"duration": 2})
    assert samples.tobytes() == data
    assert np.sqrt(np.mean(samples.astype(np.float64) ** 2)) > 1e-4  # the fire is heard


def test_path_and_overrides_as_set(tmp_path):
    """A path with overrides gives what fulgur render --set gives."""
    path = example("lightning_3km.json")
    sets = {"discharges[0].offset[1]": 8000, "seed": 9, "propagation": {"ground": True}}
    args = []
    for k, v in sets.items():
        args += ["--set", f"{k}={json.dumps(v)}"]
    rc, err = cli_render(path, str(tmp_path / "cli.wav"), *args)
    assert rc == 0, err
    data = wav_data(tmp_path / "cli.wav")[4]
    rendered = fulgur.render(path, overrides=sets)
    assert rendered.samples.tobytes() == data
    as_strings = fulgur.render(path, overrides=[f"{k}={json.dumps(v)}" for k, v in sets.items()])
    assert as_strings.samples.tobytes() == data
    # the override changed the sound: 8 km, not 3 km, later and quieter (in
    # energy: the calibrated bolt's long waves keep single peaks high)
    plain = fulgur.render(path).samples.astype(np.float64)
    moved = rendered.samples.astype(np.float64)
    assert (moved ** 2).sum() < 0.5 * (plain ** 2).sum()


def test_report_and_write_wav(tmp_path):
    """The report's numbers are the samples'; write_wav writes the CLI's bytes."""
    path = example("explicit_tree.json")
    r = fulgur.render(path)
    samples, rate = r
    assert r.report["frames"] == samples.shape[0]
    assert r.report["duration_s"] == pytest.approx(samples.shape[0] / rate)
    assert r.report["peak"] == float(np.abs(samples).max())
    assert r.report["seed"] == 11 and r.report["pa_per_unit"] == 1.0
    assert r.report["segments"] == 62 and r.report["late_events"] == 0
    rc, err = cli_render(path, str(tmp_path / "cli.wav"))
    assert rc == 0, err
    fulgur.write_wav(tmp_path / "py.wav", samples, rate)
    assert (tmp_path / "py.wav").read_bytes() == (tmp_path / "cli.wav").read_bytes()


def test_gain_scales_the_samples():
    """The scene's gain multiplies the pascals, as in the WAV."""
    scene = load_json(example("explicit_tree.json"))
    plain = fulgur.render(scene).samples
    scene["gain"] = 0.5
    r = fulgur.render(scene)
    assert np.array_equal(r.samples, (plain * np.float32(0.5)).astype(np.float32))
    assert r.report["pa_per_unit"] == 2.0


BAD = sorted(glob.glob(os.path.join(SOURCE, "tests", "scenes", "bad_*.json")))


@pytest.mark.parametrize("path", BAD, ids=os.path.basename)
def test_bad_scene_messages_are_the_cli_s(path, tmp_path):
    """Each bad scene raises SceneError with fulgur render's message."""
    rc, err = cli_render(path, str(tmp_path / "x.wav"))
    assert rc == 2
    with pytest.raises(fulgur.SceneError) as raised:
        fulgur.render(path)
    assert f"fulgur: {raised.value}" == err.strip()
    with open(path[:-5] + ".err", encoding="utf-8") as f:
        assert f.read().strip() in str(raised.value)
    assert not os.path.exists(tmp_path / "x.wav")


@pytest.mark.parametrize("assignment", [
    "discharges[5].time=1",
    "discharges[0].time=abc",
    "seed.x=1",
    "discharges[0].generator.height=-3",
    "noequals",
])
def test_bad_overrides_say_what_set_says(assignment, tmp_path):
    path = example("lightning_3km.json")
    rc, err = cli_render(path, str(tmp_path / "x.wav"), "--set", assignment)
    assert rc == 2
    with pytest.raises(fulgur.SceneError) as raised:
        fulgur.render(path, overrides=[assignment])
    assert f"fulgur: {raised.value}" == err.strip()


def test_dict_errors_name_the_path():
    scene = {"discharges": [{"time": 0, "preset": "spark_balls",
                             "tree": {"nodes": [[0, 1, 1.7, -1], [0, 1, 1.71, 5]]}}]}
    with pytest.raises(fulgur.SceneError, match=r"discharges\[0\]\.tree\.nodes\[1\]: parent 5"):
        fulgur.render(scene)
    with pytest.raises(fulgur.SceneError, match="sample_rate"):
        fulgur.render({**scene, "sample_rate": 1000})


def test_scenes_render_on_threads_at_once():
    """Different scenes on different threads at once (the GIL is released
    in the C calls) give what each gives alone."""
    seeds = [1, 2, 3, 4]
    path = example("lightning_3km.json")
    alone = [fulgur.render(path, {"seed": s})[0] for s in seeds]
    results = [None] * len(seeds)
    errors = []

    def work(i):
        try:
            results[i] = fulgur.render(path, {"seed": seeds[i]})[0]
        except Exception as e:  # reported below, not lost in the thread
            errors.append(e)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(seeds))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for i in range(len(seeds)):
        assert results[i].tobytes() == alone[i].tobytes(), seeds[i]
    assert alone[0].tobytes() != alone[1].tobytes()
