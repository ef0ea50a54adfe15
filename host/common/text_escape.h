/* Text from outside (a scene's keys and strings, command-line arguments)
 * made safe to print: a message that echoes it must not send a terminal
 * control sequence or invalid bytes to the user's terminal or log. */
#ifndef HOST_COMMON_TEXT_ESCAPE_H
#define HOST_COMMON_TEXT_ESCAPE_H

#include <stddef.h>

/* Copies the NUL-terminated in into out (out_size > 0; always
 * terminated), keeping printable ASCII and well-formed UTF-8 of printable
 * characters as they are and writing every other byte (controls such as
 * ESC or a newline, DEL, C1 controls, bytes of invalid or overlong UTF-8)
 * as \xHH. A backslash stays one backslash. What does not fit is cut at a
 * whole character or escape. Returns the length written. [any-thread] */
size_t text_escape(char *out, size_t out_size, const char *in);

#endif
