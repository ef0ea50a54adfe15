"""The real-time rules hold when Python drives the engine: rendering
through the package makes no allocation, lock, sleep or I/O call inside
libfulgur. The guard (tests/rt_guard.c) is preloaded into a child
interpreter and armed around each render call, counting only calls whose
stack passes through libfulgur: the library, not the interpreter."""
import json
import os
import subprocess
import sys

from conftest import env_path


def test_render_from_python_does_not_allocate_in_the_engine():
    child = os.path.join(os.path.dirname(__file__), "rt_guard_child.py")
    env = dict(os.environ, LD_PRELOAD=env_path("FULGUR_RT_GUARD"))
    r = subprocess.run([sys.executable, child], capture_output=True, text=True, env=env,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    report = json.loads(r.stdout)
    render = report["render"]
    assert render == {"alloc": 0, "lock": 0, "io": 0, "sleep": 0, "first": None}, render
    stats = report["stats"]
    assert stats["blocks"] == report["render_blocks"] and stats["adopted"] == 3
    assert stats["finished"] == 3 and stats["late_events"] == 0
    assert report["peak"] > 1e-3  # it really rendered sound
    # controls: library allocations are seen; the interpreter's are not
    assert report["generator"]["alloc"] > 0
    assert report["python_everything"]["alloc"] >= 1000
    assert report["python_within"]["alloc"] == 0
