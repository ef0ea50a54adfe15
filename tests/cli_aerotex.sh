#!/bin/sh
# usage: cli_aerotex.sh FULGUR
# fulgur aerotex: every bad option exits 2 with a message naming it and
# writes nothing (an older file at the output path stays as it was); a
# small real texture (a coarse cylinder at Re 100) is written and read
# back by --info; a corrupt texture file is refused by name.
set -u
fulgur=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
echo old >"$tmp/keep.aerotex"

# expect ARGS... -- MESSAGE: exit 2, MESSAGE on stderr, keep.aerotex untouched
bad() {
    message=$1
    shift
    "$fulgur" aerotex -o "$tmp/keep.aerotex" "$@" 2>"$tmp/stderr" >/dev/null
    rc=$?
    if [ "$rc" -ne 2 ]; then
        echo "aerotex $*: exit $rc, expected 2"; fail=1
    fi
    if ! grep -qF -- "$message" "$tmp/stderr"; then
        echo "aerotex $*: stderr lacks: $message"; echo "  got: $(cat "$tmp/stderr")"; fail=1
    fi
    [ "$(cat "$tmp/keep.aerotex")" = old ] || { echo "aerotex $*: changed the output file"; fail=1; }
}

c="--shape circle --diameter 0.01 --speed 10"
bad "--shape is required" --diameter 0.01 --speed 10
bad "--shape hexagon: expected" --shape hexagon --speed 10
bad "--diameter is required" --shape circle --speed 10
bad "--speed is required" --shape circle --diameter 0.01
bad "--speed 0: expected a number" --shape circle --diameter 0.01 --speed 0
bad "--speed nan: expected a number in (0, 340]" --shape circle --diameter 0.01 --speed nan
bad "--speed 10x: expected a number" --shape circle --diameter 0.01 --speed 10x
bad "--diameter -1: expected a number" --shape circle --diameter -1 --speed 10
bad "--side does not apply" $c --side 0.01
bad "--side is required" --shape square --speed 10
bad "--height is required" --shape rectangle --width 0.02 --speed 10
bad "--polygon is required" --shape polygon --speed 10
bad "--polygon 0,0,1,0: expected x,y pairs of at least 3" --shape polygon --polygon 0,0,1,0 --speed 10
bad "--polygon 0,0,1,0,1: expected x,y pairs" --shape polygon --polygon 0,0,1,0,1 --speed 10
bad "--polygon 0,0,a,1: expected up to" --shape polygon --polygon 0,0,a,1 --speed 10
bad "--polygon: edges 0 and 2 cross or touch" --shape polygon --polygon 0,0,1,1,1,0,0,1 --speed 10
bad "--polygon: vertex 2 repeats the one before it" --shape polygon --polygon 0,0,1,0,1,0,0,1 --speed 10
bad "--polygon: the vertices enclose no area" --shape polygon --polygon 0,0,1,0,2,0 --speed 10
bad "--length must be greater" --shape club --length 0.04 --diameters 0.02,0.05 --speed 10
bad "--diameters 0.02: expected two" --shape club --length 0.4 --diameters 0.02 --speed 10
bad "--grid 2: expected a number in 4..1024" $c --grid 2
bad "--cfl 9: expected" $c --cfl 9
bad "--threads 0: expected an integer in 1..64" $c --threads 0
bad "--sources applies to --shape club only" $c --sources 3
bad "--directions and --step apply" $c --step 5
bad "give --directions or --step, not both" --shape square --side 0.01 --speed 10 --directions 0,10 --step 5
bad "--domain 1,2: expected three" $c --domain 1,2
bad "--tone loud: expected aeolian or cavity" $c --tone loud
bad "--max-transient must be at least --transient" $c --transient 1 --max-transient 0.5
bad "unknown option \"--colour\"" $c --colour red
bad "unexpected argument \"extra\"" $c extra
bad "--rate needs a value" $c --rate
bad "--rate: at least 1600 Hz" $c --rate 100
bad "the flow's box would have" --shape sphere --diameter 1 --speed 10 --grid 1000

# -o is required
"$fulgur" aerotex $c 2>"$tmp/stderr"
[ $? -eq 2 ] && grep -qF -- "-o FILE.aerotex is required" "$tmp/stderr" || { echo "no -o: expected exit 2 and a message"; fail=1; }

# a real texture: a coarse cylinder at Re 100 (D = 1 cm, 0.15 m/s), short
"$fulgur" aerotex --shape circle --diameter 0.01 --speed 0.15 --grid 8 --domain 4,6,3 \
    --transient 2 --seconds 1 --quiet -o "$tmp/cyl.aerotex" >"$tmp/stdout" 2>"$tmp/stderr"
rc=$?
[ "$rc" -eq 0 ] || { echo "small texture: exit $rc: $(cat "$tmp/stderr")"; fail=1; }
grep -qF "Re 100" "$tmp/stdout" || { echo "small texture: summary lacks Re 100: $(cat "$tmp/stdout")"; fail=1; }
[ -z "$(ls "$tmp" | grep tmp-)" ] || { echo "a temporary file was left: $(ls "$tmp")"; fail=1; }
"$fulgur" aerotex --info "$tmp/cyl.aerotex" >"$tmp/info" 2>&1 || { echo "--info failed: $(cat "$tmp/info")"; fail=1; }
grep -qF "circle (2-D), aeolian tone" "$tmp/info" || { echo "--info: $(cat "$tmp/info")"; fail=1; }
# the shedding frequency it found: St = f D / v0 within 0.12..0.25 even this coarse
st=$(awk '/^ +0\.000/ {print $3}' "$tmp/info")
awk -v s="$st" 'BEGIN {exit !(s > 0.12 && s < 0.25)}' || { echo "--info: Strouhal number $st"; fail=1; }

# corrupt and foreign files: exit 2, named
head -c 100 "$tmp/cyl.aerotex" >"$tmp/short.aerotex"
"$fulgur" aerotex --info "$tmp/short.aerotex" 2>"$tmp/stderr" >/dev/null
[ $? -eq 2 ] && grep -qF "$tmp/short.aerotex: truncated" "$tmp/stderr" || { echo "truncated file: $(cat "$tmp/stderr")"; fail=1; }
echo "not a texture at all, but long enough to have a header of one hundred and sixty-four bytes............................................................................" >"$tmp/text.aerotex"
"$fulgur" aerotex --info "$tmp/text.aerotex" 2>"$tmp/stderr" >/dev/null
[ $? -eq 2 ] && grep -qF "not a fulgur aero texture" "$tmp/stderr" || { echo "text file: $(cat "$tmp/stderr")"; fail=1; }
"$fulgur" aerotex --info "$tmp/missing.aerotex" 2>"$tmp/stderr" >/dev/null
[ $? -eq 2 ] && grep -qF "missing.aerotex: cannot open" "$tmp/stderr" || { echo "missing file: $(cat "$tmp/stderr")"; fail=1; }
"$fulgur" aerotex --info "$tmp/cyl.aerotex" --quiet 2>"$tmp/stderr" >/dev/null
[ $? -eq 2 ] || { echo "--info with another option: expected exit 2"; fail=1; }
exit $fail
