/* One manifest line, through cJSON (its numbers print back exactly). */
#include <stdlib.h>

#include <cjson/cJSON.h>

#include "render_manifest.h"

int manifest_write(FILE *to, const manifest_row *row)
{
    cJSON *o = cJSON_CreateObject();
    int ok = o && cJSON_AddStringToObject(o, "scene", row->scene_path);
    cJSON *sets = ok ? cJSON_AddArrayToObject(o, "set") : NULL;
    ok = sets != NULL;
    for (size_t i = 0; ok && i < row->set_count; i++)
        ok = cJSON_AddItemToArray(sets, cJSON_CreateString(row->sets[i]));
    const scene *s = row->s;
    ok = ok && cJSON_AddStringToObject(o, "output", row->output) &&
         cJSON_AddNumberToObject(o, "seed", (double)s->seed) &&
         cJSON_AddNumberToObject(o, "sample_rate", s->sample_rate_hz) &&
         cJSON_AddNumberToObject(o, "channels", s->channels) &&
         cJSON_AddNumberToObject(o, "frames", (double)row->frames) &&
         cJSON_AddNumberToObject(o, "duration_s", (double)row->frames / s->sample_rate_hz) &&
         cJSON_AddNumberToObject(o, "peak", row->peak) &&
         cJSON_AddNumberToObject(o, "gain", s->gain) &&
         cJSON_AddNumberToObject(o, "pa_per_unit", 1.0 / row->scale);
    char *line = ok ? cJSON_PrintUnformatted(o) : NULL;
    cJSON_Delete(o);
    if (!line)
        return -1;
    int rc = fprintf(to, "%s\n", line) < 0 ? -1 : 0;
    free(line);
    return rc;
}
