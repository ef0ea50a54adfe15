"""Run by test_realtime.py under LD_PRELOAD=FULGUR_RT_GUARD: drives the
engine through the package and reports, as JSON on stdout, what the guard
counted inside libfulgur during each kind of call."""
import json
import os

import numpy as np
from cffi import FFI

import fulgur
from fulgur._native import ffi, lib

guard_ffi = FFI()
guard_ffi.cdef("""
typedef struct rt_guard_counts {
    unsigned long alloc, lock, io, sleep; const char *first;
} rt_guard_counts;
void rt_guard_arm(void);
int rt_guard_arm_within(const void *code);
rt_guard_counts rt_guard_disarm(void);
""")
guard = guard_ffi.dlopen(os.environ["FULGUR_RT_GUARD"])  # the preloaded module itself
in_libfulgur = guard_ffi.cast("void *", int(ffi.cast("uintptr_t", lib.fg_engine_render)))


def counts(c):
    return {"alloc": c.alloc, "lock": c.lock, "io": c.io, "sleep": c.sleep,
            "first": guard_ffi.string(c.first).decode() if c.first else None}


def within_libfulgur(call):
    assert guard.rt_guard_arm_within(in_libfulgur) == 0
    call()
    return counts(guard.rt_guard_disarm())


def everything(call):
    guard.rt_guard_arm()
    call()
    return counts(guard.rt_guard_disarm())


report = {}
# every feature: a bolt with strokes through ISO 9613-1 bands, refraction,
# turbulence and the ground; Abe's model; a continuous plasma ball; a
# moving listener
e = fulgur.Engine(channels=2, max_block_frames=256, max_voices=8)
e.set_listener([0, 0, 1.7])
bolt, _ = fulgur.lightning(seed=3, height_m=1000)
bolt["y"] += 800  # at most 1.3 km: heard within the 6.4 s
air = {"absorption": "iso9613", "refraction_radius_m": 55e3, "turbulence_s": 0.002,
       "ground_reflection": 0.9, "head_shadow": True}
e.post(bolt, "lightning", emit_time_s=0.05, strokes=3, seed=1, propagation=air)
e.post(bolt, "lightning", emit_time_s=0.1, seed=2, model="abe")
ball = e.post([[0, 2, 1.7, -1], [0.01, 2, 1.7, 0], [0.02, 2.01, 1.7, 1]], "plasma_ball",
              continuous=True, seed=4)
render = {"alloc": 0, "lock": 0, "io": 0, "sleep": 0, "first": None}
peak = 0.0
for block in range(1200):  # 6.4 s
    if block % 10 == 0:
        a = block * 0.001
        e.set_listener([np.sin(a), np.cos(a) - 1, 1.7], [np.sin(a), np.cos(a), 0])
    if block == 600:
        e.stop(ball)
    got = {}

    def one_block():
        got["out"] = e.render(256)  # the binding's own render call

    c = within_libfulgur(one_block)
    peak = max(peak, float(np.abs(got["out"]).max()))
    for k in ("alloc", "lock", "io", "sleep"):
        render[k] += c[k]
    render["first"] = render["first"] or c["first"]
    e.collect()
report["render"] = render
report["render_blocks"] = 1200
report["peak"] = peak
report["stats"] = e.stats()
e.close()
# the controls: the guard sees the library allocate (a generator), and
# does not count the interpreter's own allocations, which it does make
report["generator"] = within_libfulgur(lambda: fulgur.lightning(seed=1))
report["python_within"] = within_libfulgur(lambda: [bytearray(4096) for _ in range(1000)])
report["python_everything"] = everything(lambda: [bytearray(4096) for _ in range(1000)])
print(json.dumps(report))
