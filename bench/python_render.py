#!/usr/bin/env python3
"""Throughput of the Python package against the CLI: N small scenes
(examples/explicit_tree.json with seeds 1..N) rendered to WAV files by
fulgur.render + fulgur.write_wav in one interpreter, and by `fulgur render
SCENE --set seed=K -o FILE` once per scene in a loop (a process each, as a
shell loop would). The two alternate for ROUNDS rounds; the CSV has each
way's median total and the ratio Python / CLI of the medians (issue 18's
goal: at most 1.5). The files of both ways are compared byte for byte.

    PYTHONPATH=BUILD/python python3 bench/python_render.py BUILD/host/fulgur \\
        [--scenes 100] [--rounds 5] [--csv bench/results/python_render.csv]
"""
import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import fulgur

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples",
                     "explicit_tree.json")


def through_python(out_dir, n):
    for k in range(1, n + 1):
        samples, rate = fulgur.render(SCENE, overrides={"seed": k})
        fulgur.write_wav(os.path.join(out_dir, f"{k}.wav"), samples, rate)


def through_cli(cli, out_dir, n):
    for k in range(1, n + 1):
        subprocess.run([cli, "render", SCENE, "--quiet", "--set", f"seed={k}",
                        "-o", os.path.join(out_dir, f"{k}.wav")], check=True)


def timed(fn, *args):
    t0 = time.perf_counter()
    fn(*args)
    return time.perf_counter() - t0


def cpu_name():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.machine()


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("cli", help="the fulgur program")
    p.add_argument("--scenes", type=int, default=100)
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--csv", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                 "results", "python_render.csv"))
    a = p.parse_args(argv)
    if a.scenes < 1 or a.rounds < 1:
        p.error("--scenes and --rounds: at least 1")
    py, cli = [], []
    with tempfile.TemporaryDirectory() as tmp:
        py_dir, cli_dir = os.path.join(tmp, "py"), os.path.join(tmp, "cli")
        os.mkdir(py_dir)
        os.mkdir(cli_dir)
        through_python(py_dir, 1)  # the libraries loaded, as the CLI's are by then
        for _ in range(a.rounds):
            py.append(timed(through_python, py_dir, a.scenes))
            cli.append(timed(through_cli, a.cli, cli_dir, a.scenes))
        for k in range(1, a.scenes + 1):
            with open(os.path.join(py_dir, f"{k}.wav"), "rb") as f1, \
                 open(os.path.join(cli_dir, f"{k}.wav"), "rb") as f2:
                if f1.read() != f2.read():
                    print(f"python_render.py: scene {k}: the files differ", file=sys.stderr)
                    return 1
    py_s, cli_s = statistics.median(py), statistics.median(cli)
    ratio = py_s / cli_s
    with open(a.csv + ".part", "w", encoding="utf-8") as f:
        f.write(f"# bench/python_render.py, {a.scenes} scenes (explicit_tree.json, seeds "
                f"1..{a.scenes}) to WAV, median of {a.rounds} alternating rounds; {cpu_name()}\n")
        f.write("way,scenes,rounds,median total s,min total s,max total s,median ms per scene\n")
        for way, runs in (("python", py), ("cli loop", cli)):
            m = statistics.median(runs)
            f.write(f"{way},{a.scenes},{a.rounds},{m:.3f},{min(runs):.3f},{max(runs):.3f},"
                    f"{1e3 * m / a.scenes:.2f}\n")
        f.write(f"# python / cli loop = {ratio:.3f} (goal: at most 1.5); files identical\n")
    os.replace(a.csv + ".part", a.csv)
    print(f"python {py_s:.3f} s, cli loop {cli_s:.3f} s for {a.scenes} scenes: "
          f"ratio {ratio:.3f} (goal <= 1.5) -> {a.csv}")
    return 0 if ratio <= 1.5 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
