#!/bin/sh
# usage: cli_render_fire.sh FULGUR EXAMPLES_FIRE_DIR
# fulgur render of the fire examples (examples/fire/), with numbers that
# can fail: the campfire's rms at the ears is its flux file's 0.02 Pa at
# 1 m over the distance (1/r, rho0 / (4 pi) dI/dt), within 1.5 dB; the
# spectrum above f_cut falls as f^-alpha (the slope of the power per FFT
# bin against log f over 400 Hz .. 8 kHz within alpha +- 0.25) for the
# campfire (3) and the flame jet (2.5); the torch is loudest as it passes
# (4 s); in the storm the strike's thunder comes first and the tree's
# fire after its arrival (0.6 s + 300 m / 343 m/s = 1.475 s); the moving
# torch renders to the same bytes whatever the block.
set -u
fulgur=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
. "$(dirname "$0")/same_at_blocks.sh"

render() { # name [--set ...]
    name=$1
    shift
    "$fulgur" render "$dir/$name.json" -o "$tmp/$name.wav" "$@" >/dev/null 2>"$tmp/$name.err" ||
        { echo "$name: render failed: $(cat "$tmp/$name.err")"; fail=1; return 1; }
}

# the least-squares slope of log10 of the power density (each band's
# power, summed over time, over its width: half the distance between its
# neighbours' centres) against log10 f over 400 Hz .. 8 kHz
slope() {
    "$fulgur" analyze "$1" --spectrogram "$tmp/s.dat" >/dev/null
    awk 'NF == 3 && $1 !~ /#/ {e[$2] += 10 ^ ($3 / 10); if (!($2 in seen)) {seen[$2] = 1; f[m++] = $2}}
         END {for (i = 1; i + 1 < m; i++) {
                  if (f[i] < 400 || f[i] > 8000) continue;
                  x = log(f[i]) / log(10); y = log(e[f[i]] / ((f[i + 1] - f[i - 1]) / 2)) / log(10);
                  n++; sx += x; sy += y; sxx += x * x; sxy += x * y}
              print (n * sxy - sx * sy) / (n * sxx - sx * sx)}' "$tmp/s.dat"
}

if render campfire; then
    rms=$("$fulgur" analyze "$tmp/campfire.wav" | sed -n 's/.* rms \([-0-9.e+]*\) Pa.*/\1/p')
    awk -v p="$rms" 'BEGIN {r = sqrt(9 + 0.81); want = 0.02 / r; d = 20 * log(p / want) / log(10);
        printf "campfire: rms %.6f Pa, 0.02 Pa / %.2f m = %.6f Pa (%+.2f dB)\n", p, r, want, d;
        exit !(d > -1.5 && d < 1.5)}' || { echo "campfire: level off"; fail=1; }
    s=$(slope "$tmp/campfire.wav")
    awk -v s="$s" 'BEGIN {printf "campfire: slope %.3f (alpha 3)\n", -s; exit !(-s > 2.75 && -s < 3.25)}' ||
        { echo "campfire: spectrum slope $s, expected -3 +- 0.25"; fail=1; }
fi

if render flame_jet; then
    s=$(slope "$tmp/flame_jet.wav")
    awk -v s="$s" 'BEGIN {printf "flame_jet: slope %.3f (alpha 2.5)\n", -s; exit !(-s > 2.25 && -s < 2.75)}' ||
        { echo "flame_jet: spectrum slope $s, expected -2.5 +- 0.25"; fail=1; }
fi

if render torch; then
    "$fulgur" analyze "$tmp/torch.wav" --waveform "$tmp/torch.dat" >/dev/null
    # the mean envelope per second: loudest in the second around its pass (4 s)
    awk '$1 !~ /#/ && NF >= 3 {s = int($1); a = $3 > -$2 ? $3 : -$2; e[s] += a; n[s]++}
         END {best = -1; for (k in e) if (e[k] / n[k] > best) {best = e[k] / n[k]; at = k};
              printf "torch: loudest in second %d\n", at; exit !(at == 3 || at == 4)}' \
        "$tmp/torch.dat" || { echo "torch: not loudest as it passes"; fail=1; }
fi

# first sound (|sample| above 1e-6 Pa) of a render, s
first() {
    "$fulgur" analyze "$1" --waveform "$tmp/w.dat" >/dev/null
    awk '$1 !~ /#/ && NF >= 3 && ($2 < -1e-6 || $3 > 1e-6) {print $1; exit}' "$tmp/w.dat"
}
if render storm_tree_fire && cp "$tmp/storm_tree_fire.wav" "$tmp/both.wav" &&
    render storm_tree_fire --set 'discharges[0].time=7.9'; then
    both=$(first "$tmp/both.wav")
    fire=$(first "$tmp/storm_tree_fire.wav")
    awk -v b="$both" -v f="$fire" 'BEGIN {
        printf "storm: first sound %.4f s (the strike at 300 m: 1.375 s), the fire alone from %.4f s (1.475 s)\n", b, f;
        exit !(b >= 1.30 && b < 1.45 && f >= 1.46 && f < 1.60)}' ||
        { echo "storm: the thunder at $both s, the fire from $fire s"; fail=1; }
fi
# the torch, carried past the listener
same_at_blocks "$dir/torch.json" torch
exit $fail
