/* The output layout: the scene's "layout" block, the hosts' --layout text,
 * and the HRIRs a binaural scene needs read from its SOFA file. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_internal.h"
#include "common/sofa_hrir.h"

/* In fg_layout's order: a name's index is its FG_LAYOUT_* value. */
static const char *const layout_names[] = {"stereo", "ambisonics", "binaural"};
static const char *const layout_keys[] = {"type", "order", "sofa", NULL};

const char *scene_layout_name(fg_layout layout)
{
    return layout_names[layout];
}

void scene_set_layout(scene *s, scene_layout l)
{
    s->layout = l.layout;
    s->ambisonic_order = l.layout == FG_LAYOUT_AMBISONICS ? l.order : 0;
    if (l.layout == FG_LAYOUT_AMBISONICS)
        s->channels = (l.order + 1) * (l.order + 1);
    else
        s->channels = 2;
}

int scene_parse_layout(const cJSON *json, const char *dir, scene *s, char *err, size_t err_size)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(json, "layout");
    if (!item)
        return 0;
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, "layout",
                         "expected an object: {\"type\": \"stereo\" | \"binaural\" | "
                         "\"ambisonics\", \"order\": 1..3, \"sofa\": FILE}");
    if (json_check_keys(item, "layout", layout_keys, err, err_size))
        return -1;
    if (!cJSON_GetObjectItemCaseSensitive(item, "type"))
        return json_fail(err, err_size, "layout.type",
                         "required: \"stereo\", \"ambisonics\" or \"binaural\"");
    int type = 0;
    if (json_name(item, "layout", "type", layout_names, 3, &type, err, err_size))
        return -1;
    scene_layout l = {(fg_layout)type, FG_AMBISONIC_ORDER_MIN};
    bool has_order = cJSON_GetObjectItemCaseSensitive(item, "order") != NULL;
    bool has_sofa = cJSON_GetObjectItemCaseSensitive(item, "sofa") != NULL;
    if (has_order && l.layout != FG_LAYOUT_AMBISONICS)
        return json_fail(err, err_size, "layout.order", "only with \"type\": \"ambisonics\"");
    if (has_sofa && l.layout != FG_LAYOUT_BINAURAL)
        return json_fail(err, err_size, "layout.sofa", "only with \"type\": \"binaural\"");
    if (l.layout != FG_LAYOUT_STEREO && cJSON_GetObjectItemCaseSensitive(json, "channels"))
        return json_fail(err, err_size, "channels",
                         "only with the stereo layout (layout.type sets the channels)");
    double order = FG_AMBISONIC_ORDER_MIN;
    if (json_number(item, "layout", "order",
                    (number_range){FG_AMBISONIC_ORDER_MIN, FG_AMBISONIC_ORDER_MAX, .integer = true},
                    &order, err, err_size))
        return -1;
    l.order = (uint32_t)order;
    if (has_sofa) {
        char file[4096];
        if (json_file_name(item, "layout", "sofa", dir,
                           "the name of a SOFA file (AES69 SimpleFreeFieldHRIR)", file, sizeof file,
                           err, err_size))
            return -1;
        s->sofa_file = strdup(file);
        if (!s->sofa_file)
            return json_fail(err, err_size, "layout.sofa", "out of memory");
    }
    if (l.layout != FG_LAYOUT_STEREO) /* stereo keeps "channels" (1 or 2) */
        scene_set_layout(s, l);
    return 0;
}

int scene_layout_from_text(const char *text, scene_layout *out, char *why, size_t why_size)
{
    static const char ambi[] = "ambisonics:";
    if (strcmp(text, "stereo") == 0 || strcmp(text, "binaural") == 0) {
        *out = (scene_layout){text[0] == 's' ? FG_LAYOUT_STEREO : FG_LAYOUT_BINAURAL, 0};
        return 0;
    }
    if (strncmp(text, ambi, sizeof ambi - 1) == 0) {
        const char *n = text + sizeof ambi - 1;
        if (n[0] >= '0' + (int)FG_AMBISONIC_ORDER_MIN && n[0] <= '0' + (int)FG_AMBISONIC_ORDER_MAX &&
            n[1] == '\0') {
            *out = (scene_layout){FG_LAYOUT_AMBISONICS, (uint32_t)(n[0] - '0')};
            return 0;
        }
        snprintf(why, why_size, "ambisonic order \"%s\": expected 1, 2 or 3", n);
        return -1;
    }
    snprintf(why, why_size, "\"%s\": expected stereo, binaural or ambisonics:ORDER (1..3)",
             text);
    return -1;
}

int scene_layout_option(const char *text, void *value, char *why, size_t why_size)
{
    scene_layout_choice *c = value;
    c->given = scene_layout_from_text(text, &c->layout, why, why_size) == 0;
    return c->given ? 0 : -1;
}

int scene_read_hrirs(scene *s, const char *sofa, double rate_hz, sofa_hrirs *out, char *err,
                     size_t err_size)
{
    if (s->layout != FG_LAYOUT_BINAURAL) {
        if (!sofa)
            return 0;
        snprintf(err, err_size, "--sofa %s: only with the binaural layout (--layout binaural or "
                                "the scene's \"layout\")", sofa);
        return -1;
    }
    const char *file = sofa ? sofa : s->sofa_file ? s->sofa_file : SOFA_DEFAULT_FILE;
    const char *from = sofa ? "--sofa " : s->sofa_file ? "layout.sofa: " : "";
    char why[512];
    if (sofa_hrirs_read(file, rate_hz, out, why, sizeof why) != 0) {
        snprintf(err, err_size, "%s%s", from, why);
        return -1;
    }
    s->hrirs = &out->set;
    return 0;
}
