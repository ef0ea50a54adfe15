#!/bin/sh
# usage: cli_analyze_input.sh FULGUR
# fulgur analyze sizes its spectrogram window from the WAV header's rate: an
# 844-byte file claiming 2 147 483 647 Hz once took 8.3 GB and 25 s. It is
# refused (exit 2, the rate named) before anything is allocated; the same
# file at 48 kHz is analysed. A file cut short (its data chunk declares 200
# frames, 100 are there) is analysed with a warning that names the file and
# both counts; the whole file gives none. A 166-byte WAV whose LIST chunk
# claims 4 GB (found by fulgur_fuzz_wav) kept libsndfile's header parser
# busy for minutes: it is refused at once, the chunk named. libsndfile's
# parser looped forever on a LIST holding a size it reads as a step
# backwards (found by fulgur_fuzz_wav in CI: before the samples, then after
# them) and on an RF64 LIST claiming 0xFFFFFFFF bytes (found by it here);
# it now reads a header of fulgur's own (host/common/wav_file.c): the
# 98-byte file, which has no data chunk, is refused, saying so; the same
# LIST after 200 frames is not read, and the frames are analysed; the
# 132-byte RF64 is refused, its LIST named.
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
# refused FILE WHAT PATTERN: analyze of $tmp/FILE exits 2 at once (within
# 20 s), its message matching PATTERN
refused() {
    timeout 20 "$fulgur" analyze "$tmp/$1" 2>"$tmp/err" >/dev/null
    rc=$?
    [ "$rc" -eq 2 ] || { echo "$2: exit $rc, expected 2 (124: it hung)"; fail=1; }
    grep -q "$3" "$tmp/err" || { echo "$2: no message naming the fault: $(cat "$tmp/err")"; fail=1; }
}
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
refused list.wav "a LIST chunk past the end" "'LIST' chunk at byte 36 claims .* past the file's end (166 bytes)"
back='LIST6\000\000\000a\200\000\000\000\000\000\000\001\000\000\000\370\377\377\377?\000\000\200\276\000\000\000>\000\000\000\000\000?\000\200\276\000\000\000>\000\000\000\000\000\000\000?\000\000\200\276\000\000\000>'
printf 'RIFF\342\000\000\000WAVEfmt \020\000\000\000\003\000\002\000\200\273\000\000\000\334\000\010\005\000 \000'"$back" > "$tmp/back.wav"
[ "$(wc -c < "$tmp/back.wav")" -eq 98 ] || { echo "back.wav: not the 98-byte file"; fail=1; }
refused back.wav "a LIST size read backwards" "back.wav: it has no 'data' chunk"
{ cat "$tmp/ok.wav"; printf "$back"; } > "$tmp/after.wav"
timeout 20 "$fulgur" analyze "$tmp/after.wav" 2>"$tmp/err" >"$tmp/out"
rc=$?
[ "$rc" -eq 0 ] || { echo "that LIST after the samples: exit $rc, expected 0 (124: it hung)"; fail=1; }
grep -q "0.004 s" "$tmp/out" || { echo "that LIST after the samples: not 200 frames: $(cat "$tmp/out")"; fail=1; }
{ printf 'RF64\377\377\377\377WAVELIST'; head -c 110 /dev/zero | tr '\000' '\377'; printf '\350\350\350\377\377\377'; } > "$tmp/rf64.wav"
[ "$(wc -c < "$tmp/rf64.wav")" -eq 132 ] || { echo "rf64.wav: not the 132-byte file"; fail=1; }
refused rf64.wav "an RF64 LIST of 0xFFFFFFFF bytes" \
    "'LIST' chunk at byte 12 claims 4294967295 bytes, past the file's end (132 bytes)"
[ "$fail" -eq 0 ] && echo "analyze: the header's rate and length are checked"
exit "$fail"
