/* The streaming reader of explicit trees: "discharges"[i]."tree"."nodes"
 * read straight from the text, without building a cJSON tree for them.
 *
 * A big explicit tree is almost all of its scene file; as cJSON items its
 * numbers cost ~400 bytes of allocation per node and most of the parse.
 * This reader walks the document's top levels, reads each such "nodes"
 * array into fg_node values and writes the rest of the text, each such
 * array written "[]", for cJSON to parse. Should cJSON fail on the rest,
 * the scene reader parses the whole text again (scene_parse.c), so that a
 * message's line and column are the file's.
 *
 * It takes an array only when every element is [x, y, z, parent] or
 * [x, y, z, parent, main] of plain JSON numbers within the ranges
 * scene_tree.c accepts; anything else (a string, a missing element, a
 * number out of range, an escape in a key, a syntax error) leaves that
 * array, or the whole document, to cJSON, whose reading then produces the
 * usual message with its JSON path. So the errors are those of the cJSON
 * path by construction, and the values too: a number is converted exactly
 * (correctly rounded, as the C library's strtod, which cJSON uses). */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fg_array.h"
#include "fg_big_alloc.h"
#include "scene_internal.h"

/* cJSON reads at most 63 characters of a number. */
#define NUMBER_MAX_CHARS 63

typedef struct cursor {
    const char *p, *end;
    int extended; /* long double carries 64 bits here (extended_works) */
} cursor;

static void skip_space(cursor *c)
{
    /* cJSON's whitespace: every byte up to and including ' ' */
    while (c->p < c->end && (unsigned char)*c->p <= 32)
        c->p++;
}

static int take(cursor *c, char ch)
{
    skip_space(c);
    if (c->p < c->end && *c->p == ch) {
        c->p++;
        return 1;
    }
    return 0;
}

/* Past a string starting at c->p ('"'); 0 if it does not end. */
static int skip_string(cursor *c)
{
    for (c->p++; c->p < c->end; c->p++) {
        if (*c->p == '\\')
            c->p++;
        else if (*c->p == '"') {
            c->p++;
            return 1;
        }
    }
    return 0;
}

/* Past one value of any kind. Brackets are counted, not matched: a
 * document this misreads is invalid, and cJSON then reports it. */
static int skip_value(cursor *c)
{
    skip_space(c);
    if (c->p >= c->end)
        return 0;
    if (*c->p == '"')
        return skip_string(c);
    if (*c->p != '{' && *c->p != '[') {
        const char *start = c->p;
        while (c->p < c->end && (unsigned char)*c->p > 32 && !strchr(",]}", *c->p))
            c->p++;
        return c->p > start;
    }
    size_t depth = 0;
    while (c->p < c->end) {
        char ch = *c->p;
        if (ch == '"') {
            if (!skip_string(c))
                return 0;
            continue;
        }
        c->p++;
        if (ch == '{' || ch == '[')
            depth++;
        else if ((ch == '}' || ch == ']') && --depth == 0)
            return 1;
    }
    return 0;
}

/* Reads a key ("...":) of plain characters; *key and *len get its text (an
 * escaped key gets a length that matches no name here). */
static int read_key(cursor *c, const char **key, size_t *len)
{
    skip_space(c);
    if (c->p >= c->end || *c->p != '"')
        return 0;
    const char *start = c->p + 1;
    if (!skip_string(c))
        return 0;
    *key = start;
    *len = (size_t)(c->p - 1 - start);
    if (memchr(start, '\\', *len))
        *len = SIZE_MAX;
    return take(c, ':');
}

static int key_is(const char *key, size_t len, const char *name)
{
    return len == strlen(name) && memcmp(key, name, len) == 0;
}

static const double exact_powers_of_ten[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                             1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                             1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

#if LDBL_MANT_DIG == 64 && defined(__x86_64__)
#define EXTENDED_POWERS 27 /* 5^27 < 2^64: 10^0..10^27 are exact in x87 long double */
/* mantissa 10^exponent, |exponent| <= EXTENDED_POWERS, mantissa < 2^64,
 * rounded once to the 64-bit significand of long double; that rounds to the
 * nearest double as the exact value does unless it lies within one unit of
 * its last place of a halfway point between two doubles: its 11 bits
 * below a double's 53 are then 0x3FF..0x401, and 0 is returned (strtod
 * decides). */
/* Whether long double arithmetic really has 64 bits of significand here:
 * an emulator (valgrind) may compute it in double. */
static int extended_works(void)
{
    volatile uint64_t probe = (UINT64_C(1) << 62) + 1;
    return (long double)probe - (long double)(UINT64_C(1) << 62) == 1.0L;
}

static int extended_convert(uint64_t mantissa, int exponent, double *out)
{
    static const long double powers[EXTENDED_POWERS + 1] = {
        1e0L,  1e1L,  1e2L,  1e3L,  1e4L,  1e5L,  1e6L,  1e7L,  1e8L,  1e9L,
        1e10L, 1e11L, 1e12L, 1e13L, 1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L,
        1e20L, 1e21L, 1e22L, 1e23L, 1e24L, 1e25L, 1e26L, 1e27L};
    long double power = powers[exponent < 0 ? -exponent : exponent];
    long double q = exponent >= 0 ? (long double)mantissa * power : (long double)mantissa / power;
    uint64_t significand;
    memcpy(&significand, &q, sizeof significand); /* x87: the low 8 bytes */
    unsigned below = (unsigned)(significand & 0x7FF);
    if (below >= 0x3FF && below <= 0x401)
        return 0;
    *out = (double)q;
    return 1;
}
#else
#define EXTENDED_POWERS (-1)
static int extended_works(void)
{
    return 0;
}

static int extended_convert(uint64_t mantissa, int exponent, double *out)
{
    (void)mantissa;
    (void)exponent;
    (void)out;
    return 0;
}
#endif

/* The value of the eight characters at p when all are digits, else -1.
 * The eight bytes are read as one little-endian word: each is a digit
 * when its high nibble is 3 both as it is and with 6 added (no byte
 * carries into the next then); the digits are then combined in pairs,
 * fours and the eight by multiplications whose lanes cannot overflow
 * (99, 9 999, 99 999 999). A tree's coordinates have 16 or 17 significant
 * digits, mostly after the point: read a character at a time they were
 * most of this reader's time. */
static int64_t eight_digits(const char *p)
{
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    const uint64_t ones = UINT64_C(0x0101010101010101), high = 0xF0 * ones, three = 0x30 * ones;
    uint64_t v;
    memcpy(&v, p, sizeof v);
    if ((v & high) != three || ((v + 6 * ones) & high) != three)
        return -1;
    v -= three;
    v = (v * 10 + (v >> 8)) & UINT64_C(0x00FF00FF00FF00FF);
    v = (v * 100 + (v >> 16)) & UINT64_C(0x0000FFFF0000FFFF);
    v = (v * 10000 + (v >> 32)) & UINT64_C(0xFFFFFFFF);
    return (int64_t)v;
#else
    (void)p;
    return -1; /* a character at a time */
#endif
}

/* A JSON number (RFC 8259 grammar, at most NUMBER_MAX_CHARS characters)
 * into *out, correctly rounded. A mantissa below 2^53 with a power of ten
 * up to 10^22 is converted with one correctly rounded multiplication or
 * division of two exact doubles (Clinger's fast path); one of at most 19
 * digits with a power up to 10^27 through x87 extended precision where
 * that is provably exact (extended_convert); any other through strtod. */
static int read_number(cursor *c, double *out)
{
    skip_space(c);
    const char *p = c->p, *start = p, *end = c->end;
    int negative = p < end && *p == '-';
    p += negative;
    if (p >= end || *p < '0' || *p > '9')
        return 0;
    uint64_t mantissa = 0;
    int digits = 0, exponent = 0; /* digits from the first non-zero one */
    if (*p == '0')
        p++;
    else
        for (; p < end && *p >= '0' && *p <= '9'; p++, digits++) {
            if (digits < 19)
                mantissa = mantissa * 10 + (uint64_t)(*p - '0');
            else
                exponent++;
        }
    if (p < end && *p == '.') {
        const char *first = ++p;
        for (; p < end && *p >= '0' && *p <= '9'; p++) {
            /* eight at once when they all count (not leading zeros) */
            int64_t eight;
            if (digits <= 19 - 8 && (digits > 0 || *p != '0') && end - p >= 8 &&
                (eight = eight_digits(p)) >= 0) {
                mantissa = mantissa * 100000000 + (uint64_t)eight;
                exponent -= 8;
                digits += 8;
                p += 7;
                continue;
            }
            if (digits == 0 && *p == '0') {
                exponent--;
                continue;
            }
            if (digits < 19) {
                mantissa = mantissa * 10 + (uint64_t)(*p - '0');
                exponent--;
            }
            digits++;
        }
        if (p == first)
            return 0;
    }
    if (p < end && (*p == 'e' || *p == 'E')) {
        p++;
        int minus = p < end && *p == '-';
        p += p < end && (*p == '-' || *p == '+');
        const char *first = p;
        int e = 0;
        for (; p < end && *p >= '0' && *p <= '9'; p++)
            if (e < 100000)
                e = e * 10 + (*p - '0');
        if (p == first)
            return 0;
        exponent += minus ? -e : e;
    }
    size_t length = (size_t)(p - start);
    if (length > NUMBER_MAX_CHARS)
        return 0;
    c->p = p;
    double v;
    if (mantissa == 0)
        v = 0.0;
    else if (digits <= 19 && mantissa < (UINT64_C(1) << 53) && exponent >= -22 && exponent <= 22)
        v = exponent >= 0 ? (double)mantissa * exact_powers_of_ten[exponent]
                          : (double)mantissa / exact_powers_of_ten[-exponent];
    else if (!(c->extended && digits <= 19 && exponent >= -EXTENDED_POWERS && exponent <= EXTENDED_POWERS &&
               extended_convert(mantissa, exponent, &v))) {
        char text[NUMBER_MAX_CHARS + 1];
        memcpy(text, start, length);
        text[length] = '\0';
        *out = strtod(text, NULL);
        return 1;
    }
    *out = negative ? -v : v;
    return 1;
}

/* The elements of the array whose elements begin at c.p (past its '['):
 * each '[' at the start or after a ',' up to its first ']' (memchr), as
 * long as a ',' follows. Exact for an array this reader takes (flat
 * elements of numbers); for any other it is only where the array's
 * storage starts (read_nodes). */
static size_t count_elements(cursor c)
{
    size_t count = 0;
    while (take(&c, '[')) {
        const char *close = memchr(c.p, ']', (size_t)(c.end - c.p));
        if (!close)
            break;
        count++;
        c.p = close + 1;
        if (!take(&c, ','))
            break;
    }
    return count;
}

/* One "nodes" array at c->p ('[') into *list; 0 (c->p anywhere, nothing
 * allocated) if it is not one this reader takes. The nodes are counted
 * first, so that their storage is allocated once at its size
 * (fg_big_alloc.h: a big tree's in huge pages), not grown and copied. */
static int read_nodes(cursor *c, scene_node_list *list)
{
    size_t capacity = 0;
    list->nodes = NULL;
    list->count = 0;
    /* an empty list is left to cJSON, which names what is missing */
    if (!take(c, '[') || take(c, ']'))
        return 0;
    const size_t expected = count_elements(*c);
    do {
        double v[5] = {0};
        int n = 0;
        if (!take(c, '['))
            goto refuse;
        do {
            if (n == 5 || !read_number(c, &v[n++]))
                goto refuse;
        } while (take(c, ','));
        if (!take(c, ']') || !scene_node_values(v, n))
            goto refuse;
        fg_node *grown = fg_big_grow(list->nodes, &capacity, list->count + 1, sizeof *grown,
                                     expected > 0 ? expected : 1);
        if (!grown)
            goto refuse;
        list->nodes = grown;
        list->nodes[list->count++] = scene_node_from(v);
    } while (take(c, ','));
    if (take(c, ']'))
        return 1;
refuse:
    fg_big_free(list->nodes);
    list->nodes = NULL;
    list->count = 0;
    return 0;
}

static int add_list(scene_node_lists *lists, size_t *capacity, scene_node_list list)
{
    scene_node_list *grown =
        fg_array_grow(lists->list, capacity, lists->count + 1, sizeof *grown, 16);
    if (!grown) {
        fg_big_free(list.nodes);
        return 0;
    }
    lists->list = grown;
    lists->list[lists->count++] = list;
    return 1;
}

/* What a walk collects: the lists, their capacity, the discharge it is in. */
typedef struct walk {
    scene_node_lists *lists;
    size_t capacity;
    size_t discharge;
} walk;

/* Reads the value of one member (its key given) and returns 1, or 0 when
 * the text is not what it should be. */
typedef int (*member_reader)(cursor *c, const char *key, size_t len, walk *w);

/* An object at c->p, each member's value read by member; a value that is
 * not an object is skipped when skip is set, else refused. */
static int walk_object(cursor *c, member_reader member, walk *w, int skip)
{
    if (!take(c, '{'))
        return skip && skip_value(c);
    if (take(c, '}'))
        return 1;
    do {
        const char *key;
        size_t len;
        if (!read_key(c, &key, &len) || !member(c, key, len, w))
            return 0;
    } while (take(c, ','));
    return take(c, '}');
}

/* A member of a "tree": "nodes" taken when it can be. */
static int tree_member(cursor *c, const char *key, size_t len, walk *w)
{
    skip_space(c);
    cursor at = *c;
    scene_node_list list = {.discharge = w->discharge,
                            .start = (size_t)(c->p - w->lists->text)};
    if (key_is(key, len, "nodes") && read_nodes(c, &list)) {
        list.end = (size_t)(c->p - w->lists->text);
        return add_list(w->lists, &w->capacity, list);
    }
    *c = at;
    return skip_value(c);
}

/* A member of a discharge: its "tree" walked, the rest skipped. */
static int discharge_member(cursor *c, const char *key, size_t len, walk *w)
{
    return key_is(key, len, "tree") ? walk_object(c, tree_member, w, 1) : skip_value(c);
}

static int walk_discharges(cursor *c, walk *w)
{
    if (!take(c, '['))
        return skip_value(c);
    if (take(c, ']'))
        return 1;
    do {
        if (!walk_object(c, discharge_member, w, 1))
            return 0;
        w->discharge++;
    } while (take(c, ','));
    return take(c, ']');
}

/* A member of the document: "discharges" walked, the rest skipped. */
static int document_member(cursor *c, const char *key, size_t len, walk *w)
{
    return key_is(key, len, "discharges") ? walk_discharges(c, w) : skip_value(c);
}

char *scene_nodes_stream(const char *text, size_t size, scene_node_lists *lists,
                         size_t *rest_size)
{
    memset(lists, 0, sizeof *lists);
    lists->text = text;
    cursor c = {text, text + size, extended_works()};
    walk w = {.lists = lists};
    if (!walk_object(&c, document_member, &w, 0) || lists->count == 0) {
        scene_node_lists_free(lists);
        return NULL;
    }
    size_t taken = 0;
    for (size_t i = 0; i < lists->count; i++)
        taken += lists->list[i].end - lists->list[i].start - 2;
    char *rest = malloc(size - taken);
    if (!rest) {
        scene_node_lists_free(lists);
        return NULL;
    }
    /* the text between the lists, each list written "[]" */
    size_t from = 0, at = 0;
    for (size_t i = 0; i < lists->count; i++) {
        const scene_node_list *l = &lists->list[i];
        memcpy(rest + at, text + from, l->start - from);
        at += l->start - from;
        rest[at++] = '[';
        rest[at++] = ']';
        from = l->end;
    }
    memcpy(rest + at, text + from, size - from);
    *rest_size = at + size - from;
    lists->text = NULL;
    return rest;
}

void scene_node_lists_bind(scene_node_lists *lists, const cJSON *json)
{
    const cJSON *discharges = cJSON_GetObjectItemCaseSensitive(json, "discharges");
    const cJSON *item = discharges ? discharges->child : NULL;
    size_t index = 0;
    for (size_t i = 0; i < lists->count; i++) {
        scene_node_list *l = &lists->list[i];
        for (; item && index < l->discharge; item = item->next)
            index++;
        const cJSON *tree = cJSON_GetObjectItemCaseSensitive(item, "tree");
        l->json = item ? cJSON_GetObjectItemCaseSensitive(tree, "nodes") : NULL;
    }
}

int scene_node_lists_take(scene_node_lists *lists, const cJSON *nodes_json, fg_node **nodes,
                          size_t *count)
{
    /* explicit trees are read in document order, the order of the lists */
    if (!lists || lists->next >= lists->count || lists->list[lists->next].json != nodes_json)
        return 0;
    scene_node_list *l = &lists->list[lists->next++];
    *nodes = l->nodes;
    *count = l->count;
    l->nodes = NULL;
    return 1;
}

void scene_node_lists_free(scene_node_lists *lists)
{
    for (size_t i = 0; i < lists->count; i++)
        fg_big_free(lists->list[i].nodes);
    free(lists->list);
    memset(lists, 0, sizeof *lists);
}
