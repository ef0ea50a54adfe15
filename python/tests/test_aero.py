"""Aero objects from Python (fulgur.AeroTexture, Engine.post_aero,
set_aero_pose, set_aero_wind, aero_report) on the shipped 1 cm rod
texture (examples/aero/rod_1cm.aerotex: 258.74 Hz at v0 = 10 m/s): the
pitch follows the wind speed (f = f_tex v / v0), the level the corrected
(v / v0)^3 law, a pose twice as far away is 6.02 dB quieter, and bad
files and poses are refused by name."""
import os

import numpy as np
import pytest

import fulgur
from conftest import example

RATE = 48000


def rod_texture():
    return fulgur.AeroTexture(example(os.path.join("aero", "rod_1cm.aerotex")))


def peak_hz(x):
    """The strongest frequency of x, refined by the parabola through the
    three bins at the peak of its Hann-windowed spectrum."""
    spectrum = np.abs(np.fft.rfft(x * np.hanning(len(x))))
    k = int(np.argmax(spectrum[1:])) + 1
    a, b, c = np.log(spectrum[k - 1:k + 2])
    return (k + 0.5 * (a - c) / (a - 2 * b + c)) * RATE / len(x)


def rms(x):
    return float(np.sqrt(np.mean(np.square(x, dtype=np.float64))))


def render(e, seconds):
    return np.concatenate([e.render(256) for _ in range(int(seconds * RATE) // 256)])[:, 0]


def post_rod(e, rod, wind, y=3.0):
    return e.post_aero(rod, start_m=-0.25, end_m=0.25, position=[0, y, 0], axis=[0, 0, 1],
                       normal=[1, 0, 0], wind=[wind, 0, 0], emit_time_s=0.0)


def test_pitch_and_level_follow_the_wind():
    """The rod in 10 m/s, then the wind changed to 20 m/s: x2 in pitch
    within 0.2 %, at the texture's frequency within 0.5 %, +18.06 dB
    within 0.2 dB; the report counts the rod's 16 sources."""
    rod = rod_texture()
    assert rod.dims == 2 and rod.speed_m_s == 10.0 and rod.reference_m == 0.01
    with fulgur.Engine(sample_rate_hz=RATE, channels=1, max_block_frames=256) as e:
        e.set_listener([0, 0, 0], forward=[0, 1, 0])
        voice = post_rod(e, rod, 10.0)
        slow = render(e, 1.0)[RATE // 10:]
        e.set_aero_wind(voice, [20.0, 0, 0])
        render(e, 0.1)  # the blend and the travel
        fast = render(e, 0.9)
        report = e.aero_report(voice)
    f_slow, f_fast = peak_hz(slow), peak_hz(fast)
    db = 20 * np.log10(rms(fast) / rms(slow))
    print(f"rod: {f_slow:.2f} Hz at 10 m/s, {f_fast:.2f} Hz at 20 m/s (x{f_fast / f_slow:.4f}), "
          f"{db:+.2f} dB")
    assert f_slow == pytest.approx(rod.frequency_hz[0], rel=5e-3)
    assert f_fast / f_slow == pytest.approx(2.0, rel=2e-3)
    assert db == pytest.approx(60 * np.log10(2), abs=0.2)
    assert report["sources"] == 16 and report["blocks"] > 0
    assert report["max_speed_m_s"] == pytest.approx(20.0, rel=1e-3)


def test_a_pose_twice_as_far_is_6_db_quieter():
    """set_aero_pose moves the rod from 3 m to 6 m: -6.02 dB within 0.1
    dB (the dipole's 1 / r; -6.006 dB measured for a rod posted there),
    the pitch unchanged. A pose whose velocity is all zero moves along the
    chord from the one before (fulgur/aero_object.h), and another one at
    rest at the same place is not published again, so the rod is stopped
    at 6 m by a second pose 10 ms later with a negligible velocity."""
    rod = rod_texture()
    with fulgur.Engine(sample_rate_hz=RATE, channels=1, max_block_frames=256) as e:
        e.set_listener([0, 0, 0], forward=[0, 1, 0])
        voice = post_rod(e, rod, 10.0)
        near = render(e, 1.0)[RATE // 10:]
        now = e.time_s
        e.set_aero_pose(voice, [0, 6, 0], [0, 0, 1], [1, 0, 0], time_s=now)
        e.set_aero_pose(voice, [0, 6, 0], [0, 0, 1], [1, 0, 0], velocity=[0, 1e-9, 0],
                        time_s=now + 0.01)
        render(e, 0.1)
        far = render(e, 0.9)
    db = 20 * np.log10(rms(far) / rms(near))
    print(f"rod at 3 m -> 6 m: {db:+.3f} dB")
    assert db == pytest.approx(-6.02, abs=0.1)
    assert peak_hz(far) == pytest.approx(peak_hz(near), rel=2e-3)


def test_refusals(tmp_path):
    with pytest.raises(fulgur.FulgurError, match="cannot open") as missing:
        fulgur.AeroTexture(tmp_path / "none.aerotex")
    assert missing.value.code == -16  # FG_ERR_IO
    src = example(os.path.join("aero", "rod_1cm.aerotex"))
    data = open(src, "rb").read()
    cut = tmp_path / "cut.aerotex"
    cut.write_bytes(data[:len(data) // 2])
    with pytest.raises(fulgur.FulgurError, match="cut.aerotex") as bad:
        fulgur.AeroTexture(cut)
    assert bad.value.code == -2  # FG_ERR_ARGUMENT
    rod = rod_texture()
    with fulgur.Engine(sample_rate_hz=RATE, channels=1) as e:
        with pytest.raises(fulgur.FulgurError, match="Engine.post_aero"):
            e.post_aero(rod, start_m=0.1, end_m=0.1, position=[0, 3, 0], axis=[0, 0, 1],
                        normal=[1, 0, 0])  # zero length
        with pytest.raises(fulgur.FulgurError, match="Engine.post_aero"):
            e.post_aero(rod, body="compact", position=[0, 3, 0], axis=[0, 0, 1],
                        normal=[1, 0, 0])  # a 2-D texture for a compact body
        with pytest.raises(TypeError):
            e.post_aero("rod", position=[0, 3, 0], axis=[0, 0, 1], normal=[1, 0, 0])
        voice = post_rod(e, rod, 10.0)
        with pytest.raises(fulgur.FulgurError, match="Engine.set_aero_pose"):
            e.set_aero_pose(voice, [0, float("nan"), 0], [0, 0, 1], [1, 0, 0])
        with pytest.raises(fulgur.FulgurError, match="Engine.set_aero_wind"):
            e.set_aero_wind(voice, [150.0, 0, 0])
        with pytest.raises(fulgur.FulgurError, match="Engine.aero_report"):
            e.aero_report(voice + 12345)
        assert e.stats()["posted"] == 1


def test_ambisonics_from_python():
    """A rod 3 m to the listener's left in first-order ambisonics: four
    channels; W is the one-ear render sample for sample, and the
    intensity vector (W times X, Y, Z) points left (+y in the head's
    frame) within 1 degree."""
    rod = rod_texture()
    with fulgur.Engine(sample_rate_hz=RATE, layout="ambisonics", ambisonic_order=1,
                       max_block_frames=256) as e:
        e.set_listener([0, 0, 0], forward=[1, 0, 0])
        post_rod(e, rod, 10.0)  # at (0, 3, 0): to the left of a listener facing +x
        out = np.concatenate([e.render(256) for _ in range(100)])
    with fulgur.Engine(sample_rate_hz=RATE, channels=1, max_block_frames=256) as e:
        e.set_listener([0, 0, 0], forward=[1, 0, 0])
        post_rod(e, rod, 10.0)
        mono = np.concatenate([e.render(256) for _ in range(100)])[:, 0]
    assert out.shape == (100 * 256, 4)
    assert np.array_equal(out[:, 0], mono)
    w = out[:, 0].astype(np.float64)
    i = np.array([w @ out[:, 3], w @ out[:, 1], w @ out[:, 2]])  # ACN 3, 1, 2: X, Y, Z
    angle = np.degrees(np.arccos(i[1] / np.linalg.norm(i)))
    print(f"rod to the left: intensity vector {angle:.3g} deg from +y")
    assert angle < 1.0
