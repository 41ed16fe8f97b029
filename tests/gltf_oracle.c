/* The exact oracle of the glTF reader (see gltf_oracle.h). */
#include <math.h>
#include <stdio.h>
#include "gltf_oracle.h"

/* an accessor without a bufferView up to this count: every vertex */
#define GX_ALL 100000L

#define REPORT(...) do { if (report) report(__VA_ARGS__); } while (0)

void gx_init(gx_map *q)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            mpq_init(q->m[i][j]);
    q->done = 0;
}
void gx_clear(gx_map *q)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            mpq_clear(q->m[i][j]);
}

/* T R(q)/|q|^2 diag(S), exactly (q not zero) */
void gx_trs(gx_map *L, mpq_t T[3], mpq_t q[4], mpq_t S[3])
{
    mpq_t n, t, u, R[3][3];
    mpq_inits(n, t, u, NULL);
    mpq_t *x = &q[0], *y = &q[1], *z = &q[2], *w = &q[3];
    mpq_set_ui(n, 0, 1);
    for (int k = 0; k < 4; k++) { mpq_mul(t, q[k], q[k]); mpq_add(n, n, t); }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            mpq_init(R[i][j]);
    /* diagonal: w^2 + a^2 - b^2 - c^2 for axis a */
    mpq_t *ax[3] = {x, y, z};
    for (int i = 0; i < 3; i++) {
        mpq_mul(t, *w, *w);
        for (int k = 0; k < 3; k++) {
            mpq_mul(u, *ax[k], *ax[k]);
            if (k == i) mpq_add(t, t, u); else mpq_sub(t, t, u);
        }
        mpq_set(R[i][i], t);
    }
    /* off-diagonal: 2(ab -+ wc) */
    static const int pa[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
    for (int k = 0; k < 3; k++) {
        int a = pa[k][0], b = pa[k][1], c = pa[k][2];   /* (a, b) with c the third */
        mpq_mul(t, *ax[a], *ax[b]);
        mpq_mul(u, *w, *ax[c]);
        mpq_sub(R[a][b], t, u);
        mpq_add(R[b][a], t, u);
        mpq_add(R[a][b], R[a][b], R[a][b]);
        mpq_add(R[b][a], R[b][a], R[b][a]);
    }
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            mpq_div(t, R[i][j], n);
            mpq_mul(L->m[i][j], t, S[j]);
        }
        mpq_set(L->m[i][3], T[i]);
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            mpq_clear(R[i][j]);
    mpq_clears(n, t, u, NULL);
}

/* The node's exact local map from the numbers the reader kept. */
void gx_local(gx_map *L, const gl_node *g)
{
    if (g->has_matrix) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                mpq_set_d(L->m[i][j], g->matrix[4 * j + i]);
        return;
    }
    mpq_t T[3], q[4], S[3];
    for (int k = 0; k < 4; k++) { mpq_init(q[k]); mpq_set_d(q[k], g->r[k]); }
    for (int k = 0; k < 3; k++) {
        mpq_init(T[k]); mpq_set_d(T[k], g->t[k]);
        mpq_init(S[k]); mpq_set_d(S[k], g->s[k]);
    }
    gx_trs(L, T, q, S);
    for (int k = 0; k < 4; k++) mpq_clear(q[k]);
    for (int k = 0; k < 3; k++) { mpq_clear(T[k]); mpq_clear(S[k]); }
}

/* r = a o b (b first) */
void gx_compose(gx_map *r, const gx_map *a, const gx_map *b)
{
    mpq_t t;
    mpq_init(t);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            if (j == 3) mpq_set(r->m[i][j], a->m[i][3]); else mpq_set_ui(r->m[i][j], 0, 1);
            for (int k = 0; k < 3; k++) {
                mpq_mul(t, a->m[i][k], b->m[k][j]);
                mpq_add(r->m[i][j], r->m[i][j], t);
            }
        }
    mpq_clear(t);
}

/* exact world maps, memoised per node */
const gx_map *gx_world(const gl_doc *d, gx_map *W, int k)
{
    if (W[k].done)
        return &W[k];
    gx_map L;
    gx_init(&L);
    gx_local(&L, &d->nodes[k]);
    if (d->nodes[k].parent < 0) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                mpq_set(W[k].m[i][j], L.m[i][j]);
    } else {
        gx_compose(&W[k], gx_world(d, W, d->nodes[k].parent), &L);
    }
    gx_clear(&L);
    W[k].done = 1;
    return &W[k];
}

/* y outside [b->lo[i], b->hi[i]] (an infinite end holds everything) */
int gx_outside(const mpq_t y, const cbx_box *b, int i, mpq_t tmp)
{
    if (isfinite(b->lo[i])) { mpq_set_d(tmp, b->lo[i]); if (mpq_cmp(y, tmp) < 0) return 1; }
    if (isfinite(b->hi[i])) { mpq_set_d(tmp, b->hi[i]); if (mpq_cmp(y, tmp) > 0) return 1; }
    return 0;
}

/* Check leaf L's box `b` against the exact vertices (and min/max corners
 * if corners).  Returns the failures; fills the exact hull and image. */
long gx_check_leaf(const gl_doc *d, const gl_leaf *L, const cbx_box *b, const gx_map *W, int corners,
                       int skip_outside, gx_counts *st, const char *file, gx_report_fn report, mpq_t hlo[3], mpq_t hhi[3], int *nh)
{
    const gl_acc *A = &d->accs[L->acc];
    long fails = 0;
    mpq_t v[3], y, t, tmp;
    for (int j = 0; j < 3; j++) mpq_init(v[j]);
    mpq_inits(y, t, tmp, NULL);
    *nh = 0;
    if (L->st == CBX_EINVAL) {            /* NaN met: the box must be the whole space */
        for (int i = 0; i < 3; i++)
            if (b->lo[i] != -HUGE_VAL || b->hi[i] != HUGE_VAL) {
                fails++;
                REPORT("%s: leaf %s: CBX_EINVAL but not the whole space\n", file, L->path);
            }
        goto done;
    }
    /* every vertex; but an accessor without a bufferView of more than
     * GX_ALL vertices (zeros but at its sparse indices: count may be 2^31
     * - 1) by its sparse entries and its first zero vertex */
    int few = A->base || A->count <= GX_ALL;
    long nvis = few ? A->count : A->sp_n + (A->sp_n < A->count), kz = few ? -1 : gltf_first_zero(d, L->acc);
    for (long e = 0; !A->no_data && e < nvis; e++) {
        long k = few ? e : e < A->sp_n ? gltf_sparse_index(d, L->acc, e) : kz;
        double num[3], den;
        gltf_vertex(d, L->acc, k, num, &den);
        if (skip_outside && A->outside) {
            /* flagged accessor with min/max boxes: only claim-abiding vertices */
            int in = 1;
            for (int j = 0; j < 3 && in; j++) {
                if (isnan(num[j])) { in = 0; break; }
                if (isinf(num[j])) { in = num[j] >= A->min[j] && num[j] <= A->max[j]; continue; }
                /* exactly: num / den rounded could land inside min/max
                 * when the exact fraction does not */
                mpq_set_d(y, num[j]);
                if (den != 1.0) { mpq_set_d(t, den); mpq_div(y, y, t); }
                mpq_set_d(t, A->min[j]);
                in = mpq_cmp(y, t) >= 0;
                mpq_set_d(t, A->max[j]);
                in = in && mpq_cmp(y, t) <= 0;
            }
            if (!in) continue;
        }
        int inf = 0;
        for (int j = 0; j < 3; j++) {
            if (isnan(num[j])) goto next;  /* only with a CBX_EINVAL leaf (above) */
            inf |= isinf(num[j]);
        }
        if (inf) {                          /* the end it pushes must be infinite */
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) {
                    int s = mpq_sgn(W->m[i][j]) * (num[j] > 0 ? 1 : -1);
                    if (!isinf(num[j]) || s == 0) continue;
                    st->inf_checks++;
                    if ((s > 0 && b->hi[i] != HUGE_VAL) || (s < 0 && b->lo[i] != -HUGE_VAL)) {
                        fails++;
                        REPORT("%s: leaf %s vertex %ld: infinite coordinate, finite end on axis %d\n",
                                         file, L->path, k, i);
                    }
                }
            continue;
        }
        for (int j = 0; j < 3; j++) {
            mpq_set_d(v[j], num[j]);
            if (den != 1.0) { mpq_set_d(t, den); mpq_div(v[j], v[j], t); }
        }
        st->vertices++;
        for (int i = 0; i < 3; i++) {
            mpq_set(y, W->m[i][3]);
            for (int j = 0; j < 3; j++) { mpq_mul(t, W->m[i][j], v[j]); mpq_add(y, y, t); }
            if (gx_outside(y, b, i, tmp)) {
                fails++;
                if (fails <= 5)
                    REPORT("%s: leaf %s vertex %ld axis %d = %.17g outside [%.17g, %.17g]\n",
                         file, L->path, k, i, mpq_get_d(y), b->lo[i], b->hi[i]);
            }
            if (*nh == 0 || mpq_cmp(y, hlo[i]) < 0) mpq_set(hlo[i], y);
            if (*nh == 0 || mpq_cmp(y, hhi[i]) > 0) mpq_set(hhi[i], y);
        }
        (*nh)++;
    next:;
    }
    if (corners) {
        for (int c = 0; c < 8; c++) {
            for (int j = 0; j < 3; j++) mpq_set_d(v[j], (c >> j) & 1 ? A->max[j] : A->min[j]);
            for (int i = 0; i < 3; i++) {
                mpq_set(y, W->m[i][3]);
                for (int j = 0; j < 3; j++) { mpq_mul(t, W->m[i][j], v[j]); mpq_add(y, y, t); }
                st->corners++;
                if (gx_outside(y, b, i, tmp)) {
                    fails++;
                    REPORT("%s: leaf %s min/max corner %d axis %d outside the box\n", file, L->path, c, i);
                }
            }
        }
    }
done:
    for (int j = 0; j < 3; j++) mpq_clear(v[j]);
    mpq_clears(y, t, tmp, NULL);
    return fails;
}
