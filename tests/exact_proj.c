/* exact_proj: exact helpers shared by the projective oracles
 * (tests/psph_oracle.c, pnear_oracle.c, pball_oracle.c): the special
 * outputs, an affine row at a rational point, the dot product of two
 * rows' linear parts, a rational point of a ball, and the summary of the
 * distances of ends to their exact ends.
 * Part of the oracle declared in exact_util.h (see there for the map). */
#include "exact_util.h"

#include <math.h>
#include <stdlib.h>

/* ---- shared by the projective oracles -------------------------------------- */
int xu_whole_box(const cbx_box *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(o->lo[i]) && o->lo[i] < 0 && isinf(o->hi[i]) && o->hi[i] > 0))
            return 0;
    return 1;
}

int xu_empty_box(const cbx_box *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(o->lo[i]) && o->lo[i] > 0 && isinf(o->hi[i]) && o->hi[i] < 0))
            return 0;
    return 1;
}

/* The same for the binary32 box (the twins of src/f32/cbx_pwide.c). */
int xu_whole_boxf(const cbx_boxf *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(o->lo[i]) && o->lo[i] < 0 && isinf(o->hi[i]) && o->hi[i] > 0))
            return 0;
    return 1;
}

int xu_empty_boxf(const cbx_boxf *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(o->lo[i]) && o->lo[i] > 0 && isinf(o->hi[i]) && o->hi[i] < 0))
            return 0;
    return 1;
}

void xu_aff_q(mpq_t q, const double m[4], mpq_t const x[3])
{
    mpq_t t;
    int j;
    mpq_init(t);
    mpq_set_d(q, m[3]);
    for (j = 0; j < 3; j++) {
        mpq_set_d(t, m[j]);
        mpq_mul(t, t, x[j]);
        mpq_add(q, q, t);
    }
    mpq_clear(t);
}

void xu_dot3_q(mpq_t q, const double u[4], const double v[4])
{
    mpq_t t, w;
    int j;
    mpq_inits(t, w, NULL);
    mpq_set_ui(q, 0, 1);
    for (j = 0; j < 3; j++) {
        mpq_set_d(t, u[j]);
        mpq_set_d(w, v[j]);
        mpq_mul(t, t, w);
        mpq_add(q, q, t);
    }
    mpq_clears(t, w, NULL);
}

void xu_ball_point(mpq_t x[3], const double c[3], double r, double u, double v, double s)
{
    mpq_t q, uq, vq, den, t;
    int j;
    mpq_inits(q, uq, vq, den, t, NULL);
    mpq_set_d(uq, u);
    mpq_set_d(vq, v);
    mpq_mul(den, uq, uq);
    mpq_mul(t, vq, vq);
    mpq_add(den, den, t);
    mpq_set_ui(t, 1, 1);
    mpq_add(den, den, t);                    /* 1 + u^2 + v^2 */
    for (j = 0; j < 3; j++) {
        if (j == 0) {
            mpq_add(q, uq, uq);
        } else if (j == 1) {
            mpq_add(q, vq, vq);
        } else {
            mpq_set_ui(t, 2, 1);
            mpq_sub(q, den, t);              /* u^2 + v^2 - 1 */
        }
        mpq_div(q, q, den);
        mpq_set_d(t, r);
        mpq_mul(q, q, t);
        mpq_set_d(t, s);
        mpq_mul(q, q, t);
        mpq_set_d(t, c[j]);
        mpq_add(x[j], t, q);
    }
    mpq_clears(q, uq, vq, den, t, NULL);
}

void xu_dists_add(xu_dists *d, double u)
{
    if (d->n == d->cap) {
        d->cap = d->cap ? 2 * d->cap : 1024;
        d->v = realloc(d->v, (size_t)d->cap * sizeof *d->v);
        if (!d->v)
            abort();
    }
    d->v[d->n++] = u;
    if (u > d->worst)
        d->worst = u;
}

void xu_dists_print(FILE *f, xu_dists *d)
{
    if (d->n > 0) {
        qsort(d->v, (size_t)d->n, sizeof *d->v, xu_cmp_double);
        fprintf(f, "  distance of an end to the exact end, in units of 2^-52 (1 + |end|) (proven: at most 2^32):\n"
                   "    median %.1f, 99th percentile %.1f, 99.9th %.1f, largest %.3g (%ld ends)\n",
                d->v[d->n / 2], d->v[d->n * 99 / 100], d->v[d->n * 999 / 1000], d->worst, d->n);
    }
}

void xu_dists_free(xu_dists *d)
{
    free(d->v);
    d->v = NULL;
    d->n = d->cap = 0;
}

int xu_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}
