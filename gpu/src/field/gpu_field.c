/* The GPU field's life: creation from a CPU field's description, updates
 * of the Dirichlet set, the whole-grid readback, the growth models' source. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gpu_field_internal.h"
#include "gpu_shaders.h"

/* The engine's multigrid.c coarsens while every size is odd and >= 9. */
static int coarsenable(const int n[3])
{
    for (int a = 0; a < 3; a++)
        if ((n[a] - 1) % 2 != 0 || n[a] < 9)
            return 0;
    return 1;
}

static GLuint texture(const int n[3], GLenum format)
{
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_3D, t);
    glTexStorage3D(GL_TEXTURE_3D, 1, format, n[0], n[1], n[2]);
    return t;
}

static GLuint buffer(size_t bytes)
{
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, b);
    glBufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)bytes, NULL, GL_DYNAMIC_COPY);
    return b;
}

static fg_result build_programs(fgg_programs *p)
{
    struct { const char *label; const char *source; GLuint *out; } list[] = {
        {"field_smooth", fgg_shader_field_smooth, &p->smooth},
        {"field_residual", fgg_shader_field_residual, &p->residual},
        {"field_restrict", fgg_shader_field_restrict, &p->restrict_},
        {"field_prolong", fgg_shader_field_prolong, &p->prolong},
        {"field_vector", fgg_shader_field_vector, &p->vector},
        {"field_dot", fgg_shader_field_dot, &p->dot},
        {"field_sum", fgg_shader_field_sum, &p->sum},
        {"field_gather", fgg_shader_field_gather, &p->gather},
    };
    for (size_t i = 0; i < sizeof list / sizeof list[0]; i++) {
        fg_result r = fgg_program_compute(list[i].label, list[i].source, list[i].out);
        if (r != FG_OK)
            return r;
    }
    return FG_OK;
}

static void delete_texture(GLuint *t)
{
    if (*t)
        glDeleteTextures(1, t);
    *t = 0;
}

void fgg_field_destroy(fgg_field *f)
{
    if (!f)
        return;
    GLuint *progs = &f->prog.smooth;
    for (size_t i = 0; i < sizeof f->prog / sizeof(GLuint); i++)
        if (progs[i])
            glDeleteProgram(progs[i]);
    delete_texture(&f->phi);
    delete_texture(&f->p);
    for (int l = 0; l < f->levels; l++) {
        delete_texture(&f->level[l].mask);
        delete_texture(&f->level[l].e);
        delete_texture(&f->level[l].rhs);
        delete_texture(&f->level[l].tmp);
    }
    GLuint bufs[] = {f->partials, f->result, f->gather_cells, f->gather_fracs, f->gather_out};
    for (size_t i = 0; i < sizeof bufs / sizeof bufs[0]; i++)
        if (bufs[i])
            glDeleteBuffers(1, &bufs[i]);
    free(f);
}

/* The labels of description, checked to hold an origin and a target. */
static fg_result read_labels(const fg_field *d, size_t count, uint8_t **out)
{
    uint8_t *lab = malloc(count);
    if (!lab)
        return FG_ERR_NO_MEMORY;
    if (fg_field_get_labels(d, lab) != FG_OK) {
        free(lab);
        return FG_ERR_NULL;
    }
    int origin = 0, target = 0;
    for (size_t i = 0; i < count; i++) {
        origin |= lab[i] == FG_REGION_ORIGIN;
        target |= lab[i] == FG_REGION_TARGET;
    }
    if (!origin || !target) {
        free(lab);
        return fgg_fail(FG_ERR_ARGUMENT, "the description field has no shapes set");
    }
    *out = lab;
    return FG_OK;
}

/* Uploads the masks of every level (coarse ones by injection, as the
 * engine's) and the description's Dirichlet values; free nodes keep phi. */
static fg_result load_boundary(fgg_field *f, const fg_field *d)
{
    const fgg_level *L0 = &f->level[0];
    uint8_t *lab = NULL;
    fg_result r = read_labels(d, L0->count, &lab);
    if (r != FG_OK)
        return r;
    double *phi = malloc(L0->count * sizeof *phi);
    float *v = malloc(L0->count * sizeof *v);
    uint8_t *coarse = malloc(f->levels > 1 ? f->level[1].count : 1);
    if (!phi || !v || !coarse) {
        free(lab), free(phi), free(v), free(coarse);
        return FG_ERR_NO_MEMORY;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const uint8_t *fine = lab;
    for (int l = 0; l < f->levels; l++) {
        const fgg_level *L = &f->level[l];
        uint8_t *m = lab;
        if (l > 0) {
            const fgg_level *F = &f->level[l - 1];
            m = l == 1 ? coarse : (uint8_t *)fine;
            /* In place is safe from level 2 on: node (I,J,K) reads fine node
             * (2I,2J,2K), whose index is never below its own. */
            for (int K = 0; K < L->n[2]; K++)
                for (int J = 0; J < L->n[1]; J++)
                    for (int I = 0; I < L->n[0]; I++)
                        m[I + (size_t)L->n[0] * (J + (size_t)L->n[1] * K)] =
                            fine[2 * I + (size_t)F->n[0] * (2 * J + (size_t)F->n[1] * 2 * K)];
        }
        glBindTexture(GL_TEXTURE_3D, L->mask);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, L->n[0], L->n[1], L->n[2], GL_RED_INTEGER,
                        GL_UNSIGNED_BYTE, m);
        fine = m;
    }
    r = fg_field_get_potential(d, phi);
    for (size_t i = 0; i < L0->count; i++)
        v[i] = (float)phi[i];
    /* Staged through q, then copied onto the masked nodes only. */
    glBindTexture(GL_TEXTURE_3D, L0->tmp);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, L0->n[0], L0->n[1], L0->n[2], GL_RED, GL_FLOAT, v);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    fgg_k_vector(f, L0, FGG_VEC_SET_MASKED, f->phi, L0->tmp, 0.0f);
    free(lab), free(phi), free(v), free(coarse);
    f->b_norm = -1.0;
    if (r != FG_OK)
        return r;
    return fgg_gl_check("uploading the field's boundary");
}

static fg_result allocate(fgg_field *f)
{
    fgg_level *L = &f->level[0];
    double h[3] = {f->h[0], f->h[1], f->h[2]};
    for (int a = 0; a < 3; a++)
        L->n[a] = f->config.size[a];
    f->levels = 1;
    for (int l = 0;; l++) {
        L = &f->level[l];
        L->count = (size_t)L->n[0] * (size_t)L->n[1] * (size_t)L->n[2];
        L->c[0] = (float)(h[1] * h[2] / h[0]);
        L->c[1] = (float)(h[0] * h[2] / h[1]);
        L->c[2] = (float)(h[0] * h[1] / h[2]);
        L->mask = texture(L->n, GL_R8UI);
        L->e = texture(L->n, GL_R32F);
        L->rhs = texture(L->n, GL_R32F);
        L->tmp = texture(L->n, GL_R32F);
        if (l + 1 >= FGG_MAX_LEVELS || !coarsenable(L->n))
            break;
        for (int a = 0; a < 3; a++) {
            f->level[l + 1].n[a] = (L->n[a] - 1) / 2 + 1;
            h[a] *= 2.0;
        }
        f->levels = l + 2;
    }
    f->phi = texture(f->level[0].n, GL_R32F);
    f->p = texture(f->level[0].n, GL_R32F);
    f->partial_count = fgg_dot_partials(f->level[0].count);
    f->partials = buffer(f->partial_count * sizeof(double));
    f->result = buffer(sizeof(double));
    GLenum e = glGetError();
    if (e == GL_OUT_OF_MEMORY)
        return fgg_fail(FG_ERR_CAPACITY, "the GPU cannot hold a %d x %d x %d field",
                        f->level[0].n[0], f->level[0].n[1], f->level[0].n[2]);
    if (e != GL_NO_ERROR)
        return fgg_fail(FG_ERR_GPU, "creating the field's textures: GL error 0x%x", e);
    /* Every vector starts at zero, so that nodes no kernel writes (the
     * masked ones of z, p and q) are zero. */
    for (int l = 0; l < f->levels; l++) {
        fgg_k_vector(f, &f->level[l], FGG_VEC_ZERO, f->level[l].e, 0, 0.0f);
        fgg_k_vector(f, &f->level[l], FGG_VEC_ZERO, f->level[l].rhs, 0, 0.0f);
        fgg_k_vector(f, &f->level[l], FGG_VEC_ZERO, f->level[l].tmp, 0, 0.0f);
    }
    fgg_k_vector(f, &f->level[0], FGG_VEC_ZERO, f->phi, 0, 0.0f);
    fgg_k_vector(f, &f->level[0], FGG_VEC_ZERO, f->p, 0, 0.0f);
    return fgg_gl_check("clearing the field");
}

fg_result fgg_field_create(fgg_context *context, const fg_field *d, fgg_field **out)
{
    if (!context || !d || !out)
        return fgg_fail(FG_ERR_NULL, "fgg_field_create: NULL %s",
                        !context ? "context" : (!d ? "description" : "out"));
    fgg_field *f = calloc(1, sizeof *f);
    if (!f)
        return FG_ERR_NO_MEMORY;
    f->context = context;
    fg_field_get_config(d, &f->config);
    fg_field_cell(d, f->h);
    /* No GPU work for a description without shapes. */
    uint8_t *lab = NULL;
    fg_result r = read_labels(d, fg_field_node_count(d), &lab);
    free(lab);
    if (r == FG_OK)
        r = build_programs(&f->prog);
    if (r == FG_OK)
        r = allocate(f);
    if (r == FG_OK)
        r = load_boundary(f, d);
    if (r != FG_OK) {
        fgg_field_destroy(f);
        return r;
    }
    *out = f;
    return FG_OK;
}

fg_result fgg_field_update(fgg_field *f, const fg_field *d)
{
    if (!f || !d)
        return fgg_fail(FG_ERR_NULL, "fgg_field_update: NULL %s", !f ? "field" : "description");
    fg_grid_config c;
    double h[3];
    fg_field_get_config(d, &c);
    fg_field_cell(d, h);
    for (int a = 0; a < 3; a++)
        if (c.size[a] != f->config.size[a] || c.min_m[a] != f->config.min_m[a] ||
            c.max_m[a] != f->config.max_m[a] || h[a] != f->h[a])
            return fgg_fail(FG_ERR_ARGUMENT,
                            "fgg_field_update: the description's grid differs on axis %d", a);
    return load_boundary(f, d);
}

fg_result fgg_field_read_potential(fgg_field *f, double *phi)
{
    if (!f || !phi)
        return fgg_fail(FG_ERR_NULL, "fgg_field_read_potential: NULL %s", !f ? "field" : "phi");
    size_t count = f->level[0].count;
    float *v = malloc(count * sizeof *v);
    if (!v)
        return FG_ERR_NO_MEMORY;
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_3D, f->phi);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RED, GL_FLOAT, v);
    fg_result r = fgg_gl_check("reading the potential back");
    if (r == FG_OK)
        for (size_t i = 0; i < count; i++)
            phi[i] = v[i];
    free(v);
    return r;
}

static fg_result src_sample(void *ctx, const double *pts, size_t n, double *out)
{
    return fgg_field_sample(ctx, pts, n, out);
}

static fg_result src_classify(void *ctx, const double *pts, size_t n, uint8_t *out)
{
    return fg_field_classify(((fgg_field *)ctx)->description, pts, n, out);
}

static size_t src_origin_sites(void *ctx, double *pts, size_t max)
{
    return fg_field_origin_sites(((fgg_field *)ctx)->description, pts, max);
}

void fgg_field_source_init(fgg_field *f, fg_field *description, fg_field_source *out)
{
    assert(f && description && out);
    f->description = description;
    double cell = f->h[0];
    if (f->h[1] < cell)
        cell = f->h[1];
    if (f->h[2] < cell)
        cell = f->h[2];
    *out = (fg_field_source){f, src_sample, src_classify, src_origin_sites, cell};
}
