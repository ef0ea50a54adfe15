/* Text from outside made safe to print (text_escape.h). */
#include "text_escape.h"

#include <stdint.h>
#include <stdio.h>

/* The length of the well-formed UTF-8 sequence of a printable character at
 * s (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF; C1
 * controls U+0080..U+009F excluded), or 0. */
static size_t utf8_printable(const unsigned char *s)
{
    uint32_t c;
    size_t n;
    if (s[0] >= 0xc2 && s[0] <= 0xdf) {
        n = 2;
        c = s[0] & 0x1fu;
    } else if (s[0] >= 0xe0 && s[0] <= 0xef) {
        n = 3;
        c = s[0] & 0x0fu;
    } else if (s[0] >= 0xf0 && s[0] <= 0xf4) {
        n = 4;
        c = s[0] & 0x07u;
    } else {
        return 0;
    }
    for (size_t i = 1; i < n; i++) {
        if ((s[i] & 0xc0) != 0x80)
            return 0; /* also stops at the terminating NUL */
        c = c << 6 | (s[i] & 0x3fu);
    }
    static const uint32_t shortest[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (c < shortest[n] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff) || c <= 0x9f)
        return 0;
    return n;
}

size_t text_escape(char *out, size_t out_size, const char *in)
{
    const unsigned char *s = (const unsigned char *)in;
    size_t used = 0;
    while (*s) {
        size_t n = *s >= 0x20 && *s < 0x7f ? 1 : utf8_printable(s);
        char hex[5];
        const char *piece = (const char *)s;
        size_t len = n;
        if (n == 0) {
            snprintf(hex, sizeof hex, "\\x%02X", *s);
            piece = hex;
            len = 4;
            n = 1;
        }
        if (used + len >= out_size)
            break;
        for (size_t i = 0; i < len; i++)
            out[used++] = piece[i];
        s += n;
    }
    out[used] = '\0';
    return used;
}
