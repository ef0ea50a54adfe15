"""examples/dataset.py at a small size (2 presets x 2 distances x 2
humidities): the CSV's labels are the cross product; every WAV is the bytes
fulgur render writes for the scene saved beside it; the peaks are the
files'; nearer is louder and, at 20 C, air at 30 % humidity takes more of
the kilohertz band than air at 90 % (ISO 9613-1, Table 1); an existing
dataset is not overwritten; bad arguments exit 2 with the reason."""
import csv
import itertools
import os
import subprocess
import sys

import numpy as np

from conftest import SOURCE, cli_render, wav_data

SCRIPT = os.path.join(SOURCE, "examples", "dataset.py")
SMALL = ["--presets", "lightning,spark_balls", "--distances", "50,400",
         "--humidities", "30,90"]


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


def band_energy(data, rate, low_hz):
    """The energy of the first channel above low_hz."""
    x = np.frombuffer(data, dtype="<f4")[0::2].astype(np.float64)
    spectrum = np.abs(np.fft.rfft(x)) ** 2
    f = np.fft.rfftfreq(x.size, 1.0 / rate)
    return spectrum[f >= low_hz].sum()


def test_small_dataset(tmp_path):
    out = tmp_path / "set"
    r = run("--out", str(out), *SMALL)
    assert r.returncode == 0, r.stderr
    with open(out / "manifest.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 8
    cells = {(row["preset"], float(row["distance_m"]), float(row["humidity_pct"])) for row in rows}
    assert cells == set(itertools.product(["lightning", "spark_balls"], [50.0, 400.0],
                                          [30.0, 90.0]))
    peak, high = {}, {}
    for row in rows:
        wav = out / row["file"]
        rc, err = cli_render(str(out / row["scene"]), str(tmp_path / "cli.wav"))
        assert rc == 0, err
        assert wav.read_bytes() == (tmp_path / "cli.wav").read_bytes(), row["file"]
        tag, channels, rate, bits, data = wav_data(wav)
        assert (tag, channels, rate, bits) == (3, 2, 48000, 32)
        samples = np.frombuffer(data, dtype="<f4")
        assert int(row["frames"]) * 2 == samples.size
        assert float(row["peak_pa"]) == float(np.abs(samples).max())
        assert float(row["pa_per_unit"]) == 1.0 and int(row["seed"]) == 1
        key = (row["preset"], float(row["distance_m"]), float(row["humidity_pct"]))
        peak[key] = float(row["peak_pa"])
        high[key] = band_energy(data, rate, 4000.0)
    for preset in ("lightning", "spark_balls"):
        for h in (30.0, 90.0):
            assert peak[(preset, 50.0, h)] > 2 * peak[(preset, 400.0, h)], (preset, h)
        for d in (50.0, 400.0):
            assert high[(preset, d, 30.0)] < high[(preset, d, 90.0)], (preset, d)

    before = (out / "manifest.csv").read_bytes()
    again = run("--out", str(out), *SMALL)
    assert again.returncode == 2 and "not overwriting" in again.stderr
    assert (out / "manifest.csv").read_bytes() == before


def test_bad_arguments(tmp_path):
    for args, message in [
        (["--presets", "sprak"], "--presets: unknown 'sprak'"),
        (["--distances", "100,-5"], "--distances: -5 is outside (0, 100000]"),
        (["--humidities", "50,wet"], "--humidities: expected numbers"),
        (["--variations", "0"], "--variations: at least 1"),
    ]:
        r = run("--out", str(tmp_path / "x"), *args)
        assert r.returncode == 2, args
        assert message in r.stderr, (args, r.stderr)
        assert not (tmp_path / "x").exists()
