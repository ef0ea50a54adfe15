/* The viewer's overlay: the controls and the live counters (discharges
 * posted, voices sounding, late events, the recent audio callbacks' p99)
 * in a translucent panel at the top left, F1 to show or hide it. The text
 * is set in fontconfig's "monospace" face through FreeType, its glyphs
 * rendered once at create, and laid over the picture as an image
 * (fgg_picture_set_overlay). Built without FreeType, there is no overlay. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view.h"

#ifdef FULGUR_HAVE_FREETYPE
#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#define FIRST_GLYPH 32
#define GLYPHS 95                 /* printable ASCII */
#define MAX_TEXT 1024
#define PAD_PX 6
static const uint8_t TEXT_RGB[3] = {235, 235, 230};
#define PANEL_ALPHA 150

typedef struct glyph {
    uint8_t *coverage;            /* w x h */
    int w, h, left, top;          /* bitmap size; offset from the pen, y up */
} glyph;

struct view_overlay {
    glyph glyphs[GLYPHS];
    int advance, line_h, ascent;  /* pixels */
    uint8_t *rgba;
    size_t rgba_bytes;
    char shown[MAX_TEXT];         /* the text of the image on the picture */
};

/* The file of fontconfig's best "monospace" face; NULL when none. */
static char *monospace_file(void)
{
    if (!FcInit())
        return NULL;
    FcPattern *pat = FcNameParse((const FcChar8 *)"monospace");
    char *path = NULL;
    if (pat) {
        FcConfigSubstitute(NULL, pat, FcMatchPattern);
        FcDefaultSubstitute(pat);
        FcResult res;
        FcPattern *match = FcFontMatch(NULL, pat, &res);
        FcChar8 *file = NULL;
        if (match && FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch)
            path = strdup((const char *)file);
        if (match)
            FcPatternDestroy(match);
        FcPatternDestroy(pat);
    }
    return path;
}

void view_overlay_destroy(view_overlay *o)
{
    if (!o)
        return;
    for (int i = 0; i < GLYPHS; i++)
        free(o->glyphs[i].coverage);
    free(o->rgba);
    free(o);
}

view_overlay *view_overlay_create(int picture_height, char *err, size_t err_size)
{
    char *file = monospace_file();
    if (!file) {
        snprintf(err, err_size, "fontconfig finds no monospace font (install fonts-dejavu-core)");
        return NULL;
    }
    FT_Library lib;
    FT_Face face;
    if (FT_Init_FreeType(&lib) != 0) {
        snprintf(err, err_size, "FreeType did not start");
        free(file);
        return NULL;
    }
    view_overlay *o = calloc(1, sizeof *o);
    int px = picture_height / 42;
    px = px < 10 ? 10 : px > 28 ? 28 : px;
    int ok = o && FT_New_Face(lib, file, 0, &face) == 0;
    if (ok && FT_Set_Pixel_Sizes(face, 0, (FT_UInt)px) != 0)
        ok = 0, FT_Done_Face(face);
    if (ok) {
        o->ascent = (int)(face->size->metrics.ascender >> 6);
        o->line_h = (int)(face->size->metrics.height >> 6);
        o->advance = (int)(face->size->metrics.max_advance >> 6);
        for (int i = 0; ok && i < GLYPHS; i++) {
            if (FT_Load_Char(face, (FT_ULong)(FIRST_GLYPH + i), FT_LOAD_RENDER) != 0)
                continue; /* a glyph the face lacks stays blank */
            FT_GlyphSlot g = face->glyph;
            glyph *to = &o->glyphs[i];
            to->w = (int)g->bitmap.width, to->h = (int)g->bitmap.rows;
            to->left = g->bitmap_left, to->top = g->bitmap_top;
            if (i == 'M' - FIRST_GLYPH)
                o->advance = (int)(g->advance.x >> 6);
            if (to->w == 0 || to->h == 0)
                continue;
            to->coverage = malloc((size_t)to->w * (size_t)to->h);
            if (!to->coverage) {
                ok = 0;
                break;
            }
            for (int y = 0; y < to->h; y++)
                memcpy(to->coverage + (size_t)y * (size_t)to->w,
                       g->bitmap.buffer + (ptrdiff_t)y * g->bitmap.pitch, (size_t)to->w);
        }
        FT_Done_Face(face);
    }
    FT_Done_FreeType(lib);
    if (!ok) {
        snprintf(err, err_size, "FreeType cannot use %s", file);
        view_overlay_destroy(o);
        o = NULL;
    }
    free(file);
    return o;
}

/* Sets text (lines split by '\n') into o->rgba; the image's size out. */
static int compose(view_overlay *o, const char *text, int *w, int *h)
{
    int lines = 1, longest = 0, run = 0;
    for (const char *c = text; *c; c++) {
        if (*c == '\n')
            lines++, run = 0;
        else if (++run > longest)
            longest = run;
    }
    *w = 2 * PAD_PX + longest * o->advance;
    *h = 2 * PAD_PX + lines * o->line_h;
    size_t bytes = 4 * (size_t)*w * (size_t)*h;
    if (bytes > o->rgba_bytes) {
        uint8_t *grown = realloc(o->rgba, bytes);
        if (!grown)
            return -1;
        o->rgba = grown;
        o->rgba_bytes = bytes;
    }
    for (size_t i = 0; i < bytes; i += 4) /* the panel: translucent black */
        o->rgba[i] = o->rgba[i + 1] = o->rgba[i + 2] = 0, o->rgba[i + 3] = PANEL_ALPHA;
    int pen_x = PAD_PX, base = PAD_PX + o->ascent;
    for (const char *c = text; *c; c++) {
        if (*c == '\n') {
            pen_x = PAD_PX, base += o->line_h;
            continue;
        }
        int k = (unsigned char)*c - FIRST_GLYPH;
        const glyph *g = k >= 0 && k < GLYPHS ? &o->glyphs[k] : NULL;
        for (int y = 0; g && g->coverage && y < g->h; y++)
            for (int x = 0; x < g->w; x++) {
                int px = pen_x + g->left + x, py = base - g->top + y;
                if (px < 0 || py < 0 || px >= *w || py >= *h)
                    continue;
                unsigned cov = g->coverage[y * g->w + x];
                uint8_t *d = &o->rgba[4 * ((size_t)py * (size_t)*w + (size_t)px)];
                for (int ch = 0; ch < 3; ch++)
                    d[ch] = (uint8_t)((TEXT_RGB[ch] * cov + d[ch] * (255 - cov)) / 255);
                d[3] = (uint8_t)(d[3] + (255 - d[3]) * cov / 255);
            }
        pen_x += o->advance;
    }
    return 0;
}

static int by_value(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* The p99 of the recent audio callbacks' durations, milliseconds. */
static double callback_p99_ms(view *v)
{
    uint64_t done = atomic_load_explicit(&v->callbacks, memory_order_acquire);
    size_t n = done < VIEW_RECENT_CALLBACKS ? (size_t)done : VIEW_RECENT_CALLBACKS;
    if (n == 0)
        return 0;
    uint32_t copy[VIEW_RECENT_CALLBACKS];
    for (size_t i = 0; i < n; i++)
        copy[i] = atomic_load_explicit(&v->recent_us[i], memory_order_relaxed);
    qsort(copy, n, sizeof *copy, by_value);
    size_t rank = (size_t)ceil(0.99 * (double)n); /* 1-based */
    return copy[rank - 1] / 1000.0;
}

void view_overlay_show(view *v)
{
    if (!v->overlay)
        return;
    if (!v->overlay_on) {
        if (v->overlay->shown[0] && fgg_picture_set_overlay(v->pic, NULL, 0, 0, 0, 0) == FG_OK)
            v->overlay->shown[0] = '\0';
        return;
    }
    fg_engine_report st;
    fg_engine_get_report(v->engine, &st);
    char text[MAX_TEXT];
    snprintf(text, sizeof text,
             "fulgur view  %s  t %.1f s\n"
             "discharges %llu  voices %llu  late events %llu  callback p99 %.2f ms\n"
             "click +charge  right/shift-click -charge  C clear  space discharge\n"
             "H hold  R replay the scene  F frame it  middle/alt-drag orbit  scroll zoom\n"
             "F1 hide this  Esc quit",
             v->opt.scene_path, v->now_s, (unsigned long long)st.posted,
             (unsigned long long)(st.adopted - st.finished), (unsigned long long)st.late_events,
             callback_p99_ms(v));
    if (strcmp(text, v->overlay->shown) == 0)
        return;
    int w, h;
    if (compose(v->overlay, text, &w, &h) != 0 ||
        fgg_picture_set_overlay(v->pic, v->overlay->rgba, w, h, 8, 8) != FG_OK) {
        fprintf(stderr, "fulgur view: the overlay: %s\n", fgg_error_message());
        v->overlay_on = false;
        return;
    }
    snprintf(v->overlay->shown, sizeof v->overlay->shown, "%s", text);
}

#else /* no FreeType: no overlay */

struct view_overlay {
    int unused;
};

view_overlay *view_overlay_create(int picture_height, char *err, size_t err_size)
{
    (void)picture_height;
    snprintf(err, err_size, "this fulgur was built without FreeType and fontconfig "
                            "(libfreetype-dev, libfontconfig-dev)");
    return NULL;
}

void view_overlay_destroy(view_overlay *o)
{
    (void)o;
}

void view_overlay_show(view *v)
{
    (void)v;
}

#endif
