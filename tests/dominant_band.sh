# Sourced by the aero CLI tests: dominant SPECTROGRAM prints the centre of
# the 1/24-octave band of `fulgur analyze --spectrogram` output with the
# most power summed over time.
dominant() {
    awk 'NF == 3 && $1 !~ /#/ {e[$2] += 10 ^ ($3 / 10)}
         END {best = -1; for (f in e) if (e[f] > best) {best = e[f]; at = f}; print at}' "$1"
}
