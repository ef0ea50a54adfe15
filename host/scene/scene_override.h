/* One value of a scene document set from outside the file: fulgur render's
 * --set KEY=VALUE and the Python package's overrides, applied to the JSON
 * before it is parsed, so the parser checks the result as if the file had
 * said it (its errors name the same paths).
 *
 * KEY is a JSON path as the parser's messages write it: a key, then any of
 * ".key" and "[index]" (discharges[0].offset[1], propagation.ground).
 * VALUE is JSON text (8000, true, [0, 3000, 0], {"type": "lightning"},
 * "lightning"), or, when it does not parse as JSON, a string (lightning).
 * Missing objects on the way are created for keys; an index must name an
 * element that exists, except that the last may be the array's length (the
 * value is appended). */
#ifndef HOST_SCENE_SCENE_OVERRIDE_H
#define HOST_SCENE_SCENE_OVERRIDE_H

#include <stddef.h>

#include <cjson/cJSON.h>

/* Sets "KEY=VALUE" in doc (the parsed scene document). Returns 0, or -1
 * with a message naming the path that cannot be set ("discharges[5]: past
 * the end of discharges (2 elements), setting discharges[5].offset[1]");
 * doc is then unchanged. [main-thread] */
int scene_override(cJSON *doc, const char *assignment, char *err, size_t err_size);

#endif
