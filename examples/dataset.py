#!/usr/bin/env python3
"""A labelled set of discharge sounds: every distance x humidity x preset
(x variation), each rendered by the fulgur package into OUT/NAME.wav, its
scene into OUT/scenes/NAME.json (so `fulgur render OUT/scenes/NAME.json`
gives the same bytes), and one row per file in OUT/manifest.csv.

    PYTHONPATH=build/python python3 examples/dataset.py --out thunder/ \\
        --presets lightning --distances 500,1000,2000,4000 --humidities 30,60,90 \\
        --variations 5

distance_m is the horizontal distance from the listener to the discharge:
to the lightning's ground point, or to the spark gap or plasma ball at ear
height. The air absorbs as ISO 9613-1 says for its humidity (at 20 C,
101.325 kPa), over a reflecting ground. Variation k renders with seed SEED + k (a different tree and
jitter). The labels, the columns and the calibration: docs/batch.md.
"""
import argparse
import csv
import json
import os
import sys

import fulgur

LISTENER = {"position": [0, 0, 1.7], "forward": [0, 1, 0], "up": [0, 0, 1]}
EAR_HEIGHT_M = 1.7
COLUMNS = ["file", "scene", "preset", "distance_m", "humidity_pct", "variation", "seed",
           "sample_rate", "channels", "frames", "duration_s", "peak_pa", "pa_per_unit"]


def discharge(preset, distance_m):
    """The one discharge of a row: the preset's own generator, distance_m
    ahead of the listener (+y)."""
    if preset in ("lightning", "lightning_table1"):
        return {"time": 0.2, "preset": preset, "offset": [0, distance_m, 0],
                "generator": {"type": "lightning"}}
    if preset == "spark_balls":
        return {"time": 0.1, "preset": preset, "offset": [0, distance_m, EAR_HEIGHT_M],
                "generator": {"type": "spark_gap"}}
    if preset == "plasma_ball":
        return {"time": 0.1, "preset": preset, "offset": [0, distance_m, EAR_HEIGHT_M],
                "continuous": {"min_interval": 0.01, "max_interval": 0.05, "duration": 1},
                "generator": {"type": "plasma_ball"}}
    raise ValueError(f"no discharge for preset {preset!r}")


def scene(preset, distance_m, humidity_pct, seed, sample_rate):
    return {"description": f"dataset.py: {preset} at {distance_m:g} m, {humidity_pct:g} % "
                           f"humidity, seed {seed}",
            "sample_rate": sample_rate, "channels": 2, "seed": seed,
            "humidity": humidity_pct, "listener": LISTENER,
            "propagation": {"absorption": "iso9613", "ground": True},
            "discharges": [discharge(preset, distance_m)]}


def numbers(text, what, low, high):
    """A comma-separated list of numbers in (low, high]."""
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{what}: expected numbers separated by commas, "
                                         f"got {text!r}") from None
    for v in values:
        if not low < v <= high:
            raise argparse.ArgumentTypeError(f"{what}: {v:g} is outside ({low:g}, {high:g}]")
    return values


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, help="the directory to fill (made if absent; "
                   "refused if it has a manifest.csv already)")
    p.add_argument("--presets", default=",".join(fulgur.preset_names()),
                   help="comma-separated fulgur presets (default: all)")
    p.add_argument("--distances", default="100,1000,3000",
                   type=lambda t: numbers(t, "--distances", 0, 1e5),
                   help="metres, comma-separated (default: 100,1000,3000)")
    p.add_argument("--humidities", default="30,60,90",
                   type=lambda t: numbers(t, "--humidities", 0, 100),
                   help="relative humidity in %%, comma-separated (default: 30,60,90)")
    p.add_argument("--variations", type=int, default=1, help="seeds per cell (default: 1)")
    p.add_argument("--seed", type=int, default=1, help="the first seed (default: 1)")
    p.add_argument("--sample-rate", type=int, default=48000, help="Hz (default: 48000)")
    a = p.parse_args(argv)
    a.presets = a.presets.split(",")
    for name in a.presets:
        if name not in fulgur.preset_names():
            p.error(f"--presets: unknown {name!r} (known: {', '.join(fulgur.preset_names())})")
    if a.variations < 1:
        p.error("--variations: at least 1")
    if a.seed < 0:
        p.error("--seed: at least 0")
    return a


def rows(a):
    """Every cell and variation, in a fixed order: (name, labels)."""
    for preset in a.presets:
        for distance in a.distances:
            for humidity in a.humidities:
                for k in range(a.variations):
                    name = f"{preset}_d{distance:g}_h{humidity:g}_v{k}"
                    yield name, {"preset": preset, "distance_m": distance,
                                 "humidity_pct": humidity, "variation": k, "seed": a.seed + k}


def main(argv):
    a = parse_args(argv)
    manifest = os.path.join(a.out, "manifest.csv")
    if os.path.exists(manifest):
        print(f"dataset.py: {manifest} exists: not overwriting a dataset", file=sys.stderr)
        return 2
    os.makedirs(os.path.join(a.out, "scenes"), exist_ok=True)
    table = []
    for name, labels in rows(a):
        doc = scene(labels["preset"], labels["distance_m"], labels["humidity_pct"],
                    labels["seed"], a.sample_rate)
        scene_path = os.path.join("scenes", name + ".json")
        try:
            rendering = fulgur.render(doc)
        except fulgur.FulgurError as e:
            print(f"dataset.py: {name}: {e}", file=sys.stderr)
            return 2 if isinstance(e, fulgur.SceneError) else 1
        fulgur.write_wav(os.path.join(a.out, name + ".wav"), rendering.samples,
                         rendering.sample_rate_hz)
        with open(os.path.join(a.out, scene_path), "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=1)
        r = rendering.report
        table.append({"file": name + ".wav", "scene": scene_path, **labels,
                      "sample_rate": rendering.sample_rate_hz, "channels": doc["channels"],
                      "frames": r["frames"], "duration_s": r["duration_s"],
                      "peak_pa": r["peak"] * r["pa_per_unit"], "pa_per_unit": r["pa_per_unit"]})
    part = manifest + ".part"
    with open(part, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(table)
    os.replace(part, manifest)
    print(f"dataset.py: {len(table)} files and {manifest}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
