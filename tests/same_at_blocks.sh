# Sourced by the render tests. same_at_blocks SCENE NAME renders SCENE for
# 1 s with $fulgur at blocks of 64, 256 (the default) and 1000 frames into
# $tmp, and sets fail=1 unless the three WAVs are the same bytes: the
# block a host renders in changes nothing.
same_at_blocks() { # scene name
    for block in 64 256 1000; do
        "$fulgur" render "$1" -o "$tmp/$2@$block.wav" --set duration=1 --set block=$block \
            >/dev/null 2>&1 || { echo "$2: render at $block failed"; fail=1; }
    done
    for block in 64 1000; do
        if cmp -s "$tmp/$2@256.wav" "$tmp/$2@$block.wav"; then
            echo "$2: the same bytes at blocks of 256 and $block"
        else
            echo "$2: blocks of 256 and $block render differently"
            fail=1
        fi
    done
}
