/* The progress line: carriage returns, no terminal escapes. */
#include "progress.h"

void progress_begin(progress *p, FILE *to, const char *unit, uint64_t now_ns)
{
    *p = (progress){.to = to, .unit = unit, .label = "", .item_ns = now_ns,
                    .next_ns = now_ns + (uint64_t)(PROGRESS_AFTER_S * 1e9)};
}

void progress_item(progress *p, const char *label, double total, uint64_t now_ns)
{
    p->label = label;
    p->total = total;
    p->item_ns = now_ns;
}

bool progress_update(progress *p, double done, uint64_t now_ns)
{
    if (!p->to || now_ns < p->next_ns)
        return false;
    p->next_ns = now_ns + (uint64_t)(PROGRESS_EVERY_S * 1e9);
    double wall = (double)(now_ns - p->item_ns) * 1e-9;
    int n;
    if (p->total > 0 && done > 0) {
        double left = wall * (p->total - done) / done;
        n = fprintf(p->to, "\rfulgur: %s: %.0f%% (%.1f of %.1f %s, %.1f s, about %.1f s left)",
                    p->label, 100.0 * done / p->total, done, p->total, p->unit, wall,
                    left > 0 ? left : 0.0);
    } else {
        n = fprintf(p->to, "\rfulgur: %s: %.1f %s (%.1f s)", p->label, done, p->unit, wall);
    }
    /* a shorter line than the last leaves its tail: blank it */
    int shown = n > 0 ? n - 1 : 0;
    if (shown < p->width)
        fprintf(p->to, "%*s", p->width - shown, "");
    if (shown > p->width)
        p->width = shown;
    fflush(p->to);
    return true;
}

void progress_clear(progress *p)
{
    if (p->to && p->width > 0) {
        fprintf(p->to, "\r%*s\r", p->width, "");
        fflush(p->to);
    }
    p->width = 0;
}
