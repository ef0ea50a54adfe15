# Sourced by the tests that check which objects the fulgur program maps
# (cli_no_gl_mapped.sh, cli_lazy_libraries.sh); they set $tmp first.
# mapped CMD...: runs it with glibc's loader log (LD_DEBUG=files) and
# leaves in $tmp/log the lines naming each object the loader mapped,
# dlopen included; exits 1 when the command fails or nothing was logged.
mapped() {
    LD_DEBUG=files LD_DEBUG_OUTPUT="$tmp/ld" "$@" >/dev/null 2>"$tmp/err" ||
        { cat "$tmp/err"; echo "failed: $*"; exit 1; }
    cat "$tmp"/ld.* | grep 'file=' > "$tmp/log"
    rm -f "$tmp"/ld.*
    [ -s "$tmp/log" ] || { echo "LD_DEBUG logged nothing for: $*"; exit 1; }
}
