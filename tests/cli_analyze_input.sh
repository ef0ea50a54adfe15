#!/bin/sh
# usage: cli_analyze_input.sh FULGUR
# fulgur analyze sizes its spectrogram window from the WAV header's rate: an
# 844-byte file claiming 2 147 483 647 Hz once took 8.3 GB and 25 s. It is
# refused (exit 2, the rate named) before anything is allocated; the same
# file at 48 kHz is analysed. A file cut short (its data chunk declares 200
# frames, 100 are there) is analysed with a warning that names the file and
# both counts; the whole file gives none. A 166-byte WAV whose LIST chunk
# claims 4 GB (found by fulgur_fuzz_wav) kept libsndfile's header parser
# busy for minutes: it is refused at once, the chunk named. So is a 98-byte
# WAV whose LIST holds a size libsndfile reads as a step backwards (its
# parser looped forever; found by fulgur_fuzz_wav in CI).
set -u
fulgur=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# header: RIFF, float (3), mono, RATE, byte rate, align 4, 32 bits, 800 data bytes
wav() {
    printf 'RIFF\104\003\000\000WAVEfmt \020\000\000\000\003\000\001\000'"$1"'\000\000\000\000\004\000\040\000data\040\003\000\000'
    head -c 800 /dev/zero
}
wav '\377\377\377\177' > "$tmp/fast.wav"
wav '\200\273\000\000' > "$tmp/ok.wav"
head -c 444 "$tmp/ok.wav" > "$tmp/cut.wav"
"$fulgur" analyze "$tmp/fast.wav" --spectrogram "$tmp/s.dat" 2>"$tmp/err" >/dev/null
rc=$?
fail=0
[ "$rc" -eq 2 ] || { echo "2147483647 Hz: exit $rc, expected 2"; fail=1; }
grep -q "a sample rate of 2147483647 Hz, outside 1..768000" "$tmp/err" ||
    { echo "2147483647 Hz: stderr lacks the rate: $(cat "$tmp/err")"; fail=1; }
[ ! -e "$tmp/s.dat" ] || { echo "a refused file left a spectrogram"; fail=1; }
"$fulgur" analyze "$tmp/ok.wav" --spectrogram "$tmp/s.dat" >/dev/null ||
    { echo "the 48 kHz file was not analysed"; fail=1; }
grep -q "window 4096" "$tmp/s.dat" || { echo "48 kHz: not a 4096 window"; fail=1; }
"$fulgur" analyze "$tmp/ok.wav" 2>"$tmp/err" >/dev/null
grep -q warning "$tmp/err" && { echo "the whole file warned: $(cat "$tmp/err")"; fail=1; }
"$fulgur" analyze "$tmp/cut.wav" 2>"$tmp/err" >"$tmp/out"
rc=$?
[ "$rc" -eq 0 ] || { echo "truncated file: exit $rc, expected 0"; fail=1; }
grep -q "warning: $tmp/cut.wav is truncated: 100 frames found, 200 declared" "$tmp/err" ||
    { echo "truncated file: no warning naming it and its frames: $(cat "$tmp/err")"; fail=1; }
grep -q "0.002 s" "$tmp/out" || { echo "truncated file: not 100 frames long: $(cat "$tmp/out")"; fail=1; }
printf 'RIFF\342\000\000\000WAVEfmt \020\000\000\000\003\000\002\000\200\273\000\000\000\334\005\000\010\000 \000LIST6\000\000\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\374\377\377\377\337\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377=\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\377\000INfulguRF64\045\377\377r/\377 ' > "$tmp/list.wav"
timeout 20 "$fulgur" analyze "$tmp/list.wav" 2>"$tmp/err" >/dev/null
rc=$?
[ "$rc" -eq 2 ] || { echo "a LIST chunk past the end: exit $rc, expected 2 (124: it hung)"; fail=1; }
grep -q "'LIST' chunk at byte 36 claims .* past the file's end (166 bytes)" "$tmp/err" ||
    { echo "a LIST chunk past the end: no message naming it: $(cat "$tmp/err")"; fail=1; }
printf 'RIFF\342\000\000\000WAVEfmt \020\000\000\000\003\000\002\000\200\273\000\000\000\334\000\010\005\000 \000LIST6\000\000\000a\200\000\000\000\000\000\000\001\000\000\000\370\377\377\377?\000\000\200\276\000\000\000>\000\000\000\000\000?\000\200\276\000\000\000>\000\000\000\000\000\000\000?\000\000\200\276\000\000\000>' > "$tmp/back.wav"
[ "$(wc -c < "$tmp/back.wav")" -eq 98 ] || { echo "back.wav: not the 98-byte file"; fail=1; }
timeout 20 "$fulgur" analyze "$tmp/back.wav" 2>"$tmp/err" >/dev/null
rc=$?
[ "$rc" -eq 2 ] || { echo "a LIST size read backwards: exit $rc, expected 2 (124: it hung)"; fail=1; }
grep -q "'LIST' chunk at byte 36 holds .* at byte 52 claiming 4294967288 bytes" "$tmp/err" ||
    { echo "a LIST size read backwards: no message naming it: $(cat "$tmp/err")"; fail=1; }
[ "$fail" -eq 0 ] && echo "analyze: the header's rate and length are checked"
exit "$fail"
