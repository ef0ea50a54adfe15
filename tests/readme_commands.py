#!/usr/bin/env python3
"""usage: readme_commands.py REPO BUILD_DIR

Runs every command the README shows, as written, the way a newcomer would
after the two set-up commands: each line of each ```sh block, in order, in
a scratch copy of the repository (its folders linked) where build-demo/ is
BUILD_DIR, with HOME in the scratch folder (the LV2 bundle goes to its
~/.lv2). The README's scene (its ```json block) is rendered too.

- The README must open (after its title) with a block of exactly two
  commands, bash scripts/demo.sh and bash scripts/test.sh.
- The set-up block: of its first command (scripts/demo.sh) the renders
  run (scripts/demo_render.sh on BUILD_DIR, which stands in for the
  demo's build; the install and build are the test's own) and their
  outputs are checked: for every scene in examples/ a WAV whose peak is
  below 0 dBFS (read here from its float samples) and that carries its
  calibration, a plot, and a picture that is not black (at least 1e-5 of
  its filtered PNG image bytes are not zero, some 37 bytes of a 1280 x 720
  RGBA picture: an all-black image's are all zero, whatever the filter;
  lightning_3km before its stroke has 1 such byte, the 2 cm spark of
  explicit_tree 174). The second (scripts/test.sh) is what runs
  this test, so it is not run again.
- Live-audio commands (--audio jack / portaudio, jalv, a viewer window)
  run against a JACK server with the dummy backend that this script
  starts under a name of its own (JACK_DEFAULT_SERVER) and ends; a window
  gets a virtual X server (xvfb-run). Commands that run until the user stops
  them (a viewer window without --frames, jalv) pass when they are still
  running after INTERACTIVE_S seconds (then they are stopped) or have
  exited 0.
- A command that cannot run here is skipped with the reason: aplay without
  a sound card; live audio where jackd cannot start; a window without
  xvfb-run.
Every other command must exit 0 within COMMAND_TIMEOUT_S. Prints one line
per command and "readme: N passed, N failed, N skipped"; exits 1 if any
failed."""
import array
import os
import re
import shutil
import signal
import subprocess
import struct
import sys
import tempfile
import time
import zlib

INTERACTIVE_S = 6
COMMAND_TIMEOUT_S = 300


def blocks(readme):
    return re.findall(r"^```(\w*)\n(.*?)^```", readme, re.S | re.M)


def wav_peak(path):
    """(peak |sample|, the file's bytes) of a 32-bit float WAV."""
    data = open(path, "rb").read()
    if data[:4] != b"RIFF" or data[8:12] != b"WAVE":
        raise ValueError("%s is not a RIFF WAVE file" % path)
    pos, tag, bits, samples = 12, None, None, None
    while pos + 8 <= len(data):
        kind, n = struct.unpack("<4sI", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"fmt ":
            tag, bits = struct.unpack("<H", body[:2])[0], struct.unpack("<H", body[14:16])[0]
            if tag == 0xFFFE:  # WAVE_FORMAT_EXTENSIBLE: the format is the sub-format's
                tag = struct.unpack("<H", body[24:26])[0]
        elif kind == b"data":
            samples = body
        pos += 8 + n + (n & 1)
    if tag != 3 or bits != 32 or samples is None:
        raise ValueError("%s is not 32-bit float (format %s, %s bits)" % (path, tag, bits))
    values = array.array("f")
    values.frombytes(samples[:len(samples) // 4 * 4])
    if sys.byteorder != "little":
        values.byteswap()
    return max((abs(v) for v in values), default=0.0), data


def png_lit(path):
    """The fraction of a PNG's filtered image bytes that are not zero (0
    exactly when every pixel is black, for every PNG filter)."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s is not a PNG" % path)
    pos, idat, width, height, pixel_bytes = 8, b"", 0, 0, 0
    while pos + 8 <= len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            pixel_bytes = {0: 1, 2: 3, 4: 2, 6: 4}[color] * depth // 8
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride = zlib.decompress(idat), 1 + width * pixel_bytes
    rows = [raw[r * stride + 1:(r + 1) * stride] for r in range(height)]
    return sum(len(row) - row.count(0) for row in rows) / float(width * height * pixel_bytes)


def check_demo(repo, work):
    """What the demo promises of its out/ (None when it holds, else why not)."""
    for scene in sorted(os.listdir(os.path.join(repo, "examples"))):
        if not scene.endswith(".json"):
            continue
        name = os.path.join(work, "out", scene[:-5])
        try:
            peak, data = wav_peak(name + ".wav")
            if not peak < 1.0:
                return "%s.wav peaks at %.3f of full scale: a player clips it" % (name, peak)
            if b"fulgur calibration: full scale = " not in data:
                return "%s.wav carries no calibration comment" % name
            if png_lit(name + ".png") <= 0.0:
                return "%s.png (the plot) is black" % name
            lit = png_lit(name + ".picture.png")
            if lit < 1e-5:
                return "%s.picture.png is black (%.2g of its bytes lit)" % (name, lit)
        except (OSError, ValueError) as e:
            return str(e)
    return None


def sound_card():
    if not shutil.which("aplay"):
        return False
    r = subprocess.run(["aplay", "-l"], capture_output=True, text=True)
    return r.returncode == 0 and "card " in r.stdout


class Jack:
    """jackd -d dummy under a name of its own, started on first need."""

    def __init__(self, work):
        self.work, self.proc, self.why, self.name = work, None, None, "fulgur-readme-%d" % os.getpid()

    def need(self, env):
        if self.proc is None and self.why is None:
            self.start(env)
        if self.why:
            return self.why
        env["JACK_DEFAULT_SERVER"] = self.name
        return None

    def start(self, env):
        if not shutil.which("jackd"):
            self.why = "jackd is not installed (Debian: jackd2)"
            return
        env = dict(env, JACK_NO_AUDIO_RESERVATION="1")
        for extra in ([], ["--no-realtime"]):
            log = open(os.path.join(self.work, "jackd.log"), "w")
            self.proc = subprocess.Popen(["jackd"] + extra + ["-n", self.name, "-d", "dummy",
                                          "-r", "48000", "-p", "256"], stdout=log,
                                         stderr=subprocess.STDOUT, env=env)
            for _ in range(50):
                time.sleep(0.1)
                if self.proc.poll() is not None:
                    break
                ok = subprocess.run(["jack_wait", "-s", self.name, "-c"], capture_output=True,
                                    text=True, env=env)
                if "running" in ok.stdout and "not" not in ok.stdout:
                    return
            self.stop()
        self.why = "jackd -d dummy did not start here (see %s/jackd.log)" % self.work

    def stop(self):
        if self.proc is not None:
            self.proc.terminate()
            self.proc.wait()
            self.proc = None


def run(cmd, env, cwd, interactive):
    """(passed, detail) for one command. stdin stays open (a console host
    such as jalv reads commands from it and ends at its end)."""
    t0 = time.monotonic()
    with tempfile.TemporaryFile() as out:
        p = subprocess.Popen(["bash", "-o", "pipefail", "-c", cmd], cwd=cwd, env=env,
                             stdin=subprocess.PIPE, stdout=out, stderr=subprocess.STDOUT,
                             start_new_session=True)
        limit = INTERACTIVE_S if interactive else COMMAND_TIMEOUT_S
        try:
            rc = p.wait(timeout=limit)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGINT if interactive else signal.SIGKILL)
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()
            rc = None
        p.stdin.close()
        out.seek(0)
        text = out.read().decode(errors="replace")
    took = time.monotonic() - t0
    if rc is None and interactive:
        return True, "still running after %d s, stopped" % INTERACTIVE_S
    if rc is None:
        return False, "still running after %d s\n%s" % (limit, text[-2000:])
    if rc == 0:
        return True, "%.1f s" % took
    return False, "exit %d after %.1f s\n%s" % (rc, took, text[-3000:])


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    repo, build = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    readme = open(os.path.join(repo, "README.md")).read()
    work = tempfile.mkdtemp(prefix="fulgur-readme-")
    for entry in os.listdir(repo):
        if entry.startswith(("build", ".")) or entry == "out":
            continue
        if entry == "python":  # pip install ./python writes build/ and egg-info beside it
            shutil.copytree(os.path.join(repo, entry), os.path.join(work, entry),
                            ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__"))
        else:
            os.symlink(os.path.join(repo, entry), os.path.join(work, entry))
    os.symlink(build, os.path.join(work, "build-demo"))
    os.mkdir(os.path.join(work, "out"))
    os.mkdir(os.path.join(work, "home"))
    env = dict(os.environ, HOME=os.path.join(work, "home"))
    env.pop("JACK_DEFAULT_SERVER", None)
    env.pop("LV2_PATH", None)  # the README's cp to ~/.lv2 is what finds the plugin
    jack = Jack(work)
    passed = failed = skipped = 0
    commands = []
    for i, (lang, body) in enumerate(blocks(readme)):
        if lang == "sh":
            joined = body.replace("\\\n", " ")  # a command continued with a backslash
            lines = [l for l in joined.splitlines() if l.strip() and not l.lstrip().startswith("#")]
            commands += [(i, l) for l in lines]
        elif lang == "json" and '"discharges"' in body:
            with open(os.path.join(work, "readme_scene.json"), "w") as f:
                f.write(body)
            commands.append((i, "build-demo/host/fulgur render readme_scene.json -o readme_scene.wav"))
    first_block = commands[0][0] if commands else None
    setup = [cmd.split("#")[0].split() for block, cmd in commands if block == first_block]
    if not readme.startswith("# fulgur\n\n```sh\n") or setup != [["bash", "scripts/demo.sh"],
                                                                 ["bash", "scripts/test.sh"]]:
        print("FAILED: the README does not open with its two set-up commands, bash "
              "scripts/demo.sh and bash scripts/test.sh, in its first block: %s" % setup)
        return 1
    card = sound_card()
    for block, cmd in commands:
        cenv = dict(env)
        if block == first_block and "scripts/demo.sh" in cmd:
            ok, detail = run("bash scripts/demo_render.sh build-demo out", cenv, work, False)
            why_not = check_demo(repo, work) if ok else None
            ok, detail = ok and not why_not, why_not or detail
            print("%s: %s (its renders on this build: %s)" % ("ok" if ok else "FAILED", cmd, detail))
            if ok:
                passed += 1
            else:
                failed += 1
            continue
        if block == first_block:
            print("skipped: %s: the set-up command that runs this test" % cmd)
            skipped += 1
            continue
        why = None
        window = "fulgur view" in cmd and "--gl " not in cmd
        live = ("--audio jack" in cmd or "--audio portaudio" in cmd or cmd.startswith("jalv")
                or window)
        interactive = cmd.startswith("jalv") or (window and "--frames" not in cmd)
        if "aplay" in cmd and not card:
            why = "no sound card here (aplay -l lists none); the raw stream is tested by cli_run_raw"
        if not why and live:
            why = jack.need(cenv)
        run_cmd = cmd
        if not why and window and not os.environ.get("DISPLAY"):
            if shutil.which("xvfb-run"):
                run_cmd = "xvfb-run -a " + cmd
            else:
                why = "a window needs a display, and xvfb-run is not installed (Debian: xvfb)"
        if why:
            print("skipped: %s: %s" % (cmd, why))
            skipped += 1
            continue
        ok, detail = run(run_cmd, cenv, work, interactive)
        print("%s: %s (%s)" % ("ok" if ok else "FAILED", cmd, detail))
        if ok:
            passed += 1
        else:
            failed += 1
    jack.stop()
    shutil.rmtree(work, ignore_errors=True)
    print("readme: %d passed, %d failed, %d skipped" % (passed, failed, skipped))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
