#!/usr/bin/env python3
"""Writes the flux series the fire examples play (I, m^3/s, at 360 Hz).

These are stand-ins for a flame simulation's front flux until the flame
simulation (engine/src/fire/flame_*) drives the scenes: a mean flux from
the fire's heat release Q, I0 = (gamma - 1) Q / (rho0 c0^2) (the volume
integral of div u that Chadwick & James' eq. 3 relates to the heat
release), plus random-phase fluctuations whose rate dI/dt has a power
spectrum flat up to 30 Hz and falling as f^-3 from there to the
simulation's Nyquist frequency (the law the bandwidth extension
continues above it, Chadwick & James section 6), plus the puffing of a pool fire at f = 1.5 / sqrt(D) Hz (D the fire's
diameter in metres; Cetegen & Ahmed 1993). The fluctuations are scaled so
that p = rho0 / (4 pi) dI/dt has the rms pressure at 1 m given below
between 30 and 180 Hz (what the 30 Hz high-pass lets through).
Those levels are our choice for each example, not measurements. Standard
library only; the same seed writes the same file.

usage: python3 make_flux.py   (writes the .flux files next to itself)
"""
import math
import os
import random

RATE = 360.0
GAMMA, RHO0, C0 = 1.4, 1.204, 343.0

# name: seconds, heat release W, diameter m, rms Pa at 1 m, puff share, seed
FIRES = {
    "campfire": (8.0, 50e3, 0.5, 0.02, 0.5, 1),
    "torch": (8.0, 5e3, 0.05, 0.005, 0.3, 2),
    "flame_jet": (4.0, 500e3, 0.3, 0.3, 0.1, 3),
    "tree_fire": (10.0, 2e6, 3.0, 0.3, 0.5, 4),
}


def series(seconds, q_w, d_m, p_rms, puff, seed):
    rng = random.Random(seed)
    n = int(seconds * RATE)
    i0 = (GAMMA - 1.0) * q_w / (RHO0 * C0 * C0)
    df = 1.0 / seconds
    comps = []
    f = df
    while f < RATE / 2:
        # dI/dt amplitude ~ f^-1.5 above 30 Hz (power f^-3), I amplitude = that / (2 pi f)
        comps.append((f, max(f, 30.0) ** -1.5 / (2 * math.pi * f), rng.uniform(0, 2 * math.pi)))
        f += df
    fp = 1.5 / math.sqrt(d_m)
    total = sum((2 * math.pi * f * a) ** 2 / 2 for f, a, _ in comps)
    # the puffing carries `puff` of the rate's power
    a_puff = math.sqrt(2 * puff / (1 - puff) * total) / (2 * math.pi * fp)
    comps.append((fp, a_puff, rng.uniform(0, 2 * math.pi)))
    rate_rms = math.sqrt(sum((2 * math.pi * f * a) ** 2 / 2 for f, a, _ in comps if f >= 30.0))
    scale = p_rms * 4 * math.pi / RHO0 / rate_rms
    out = []
    for k in range(n):
        t = k / RATE
        out.append(i0 + scale * sum(a * math.sin(2 * math.pi * f * t + ph) for f, a, ph in comps))
    return out, i0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for name, spec in FIRES.items():
        values, i0 = series(*spec)
        with open(os.path.join(here, name + ".flux"), "w") as fh:
            fh.write("# %s: flux I (m^3/s) at 360 Hz, %d steps; written by make_flux.py\n"
                     % (name, len(values)))
            fh.write("# mean %.6g m^3/s from Q = %g W; rms p at 1 m %g Pa\n"
                     % (i0, spec[1], spec[3]))
            for v in values:
                fh.write("%.9g\n" % v)


if __name__ == "__main__":
    main()
