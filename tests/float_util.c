/*
 * The tallies and conversions of tests/test_float.c (tests/float_parts.h):
 * one counter per function, and floats held in doubles (exact both ways;
 * every generated value checked to be a float).
 */
#include <math.h>
#include <stdio.h>

#include "float_parts.h"

#define MAX_LOGS 20

/* ---- one counter per function ------------------------------------------ */

static long logs;

void flt_fs_fail(fstat *s, const char *what, const char *why)
{
    if (logs++ < MAX_LOGS) printf("  FAIL %s: %s: %s\n", s->name, what, why);
}

void flt_fs_excess(fstat *s, double e)
{
    s->axes++;
    s->sum_ex += e;
    if (e > s->max_ex) s->max_ex = e;
}

void flt_fs_print(const fstat *s)
{
    printf("  %-25s %8ld cases, %9ld exact checks, %ld failed", s->name, s->cases, s->checks,
           s->failed);
    if (s->axes)
        printf("; excess over %ld ends: max %.2f mean %.2f", s->axes, s->max_ex,
               s->sum_ex / (double)s->axes);
    printf("\n");
}

/* ---- float <-> double (exact both ways on float values) --------------- */

long flt_not_float; /* generated values that are not floats (a bug here) */

float flt_F(double d)
{
    volatile float f = (float)d; /* see xu_round_fmt */
    if (!((double)f == d) && !(d != d)) flt_not_float++;
    return f;
}

void flt_to_af(const cbx_affine *d, cbx_affinef *f)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) f->m[i][j] = flt_F(d->m[i][j]);
}

void flt_to_bf(const cbx_box *d, cbx_boxf *f)
{
    int j;
    for (j = 0; j < 3; j++) { f->lo[j] = flt_F(d->lo[j]); f->hi[j] = flt_F(d->hi[j]); }
}

void flt_to_cf(const cbx_cbox *d, cbx_cboxf *f)
{
    int j;
    for (j = 0; j < 3; j++) { f->c[j] = flt_F(d->c[j]); f->h[j] = flt_F(d->h[j]); }
}

void flt_from_af(const cbx_affinef *f, cbx_affine *d)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) d->m[i][j] = f->m[i][j];
}

void flt_from_bf(const cbx_boxf *f, cbx_box *d)
{
    int j;
    for (j = 0; j < 3; j++) { d->lo[j] = f->lo[j]; d->hi[j] = f->hi[j]; }
}

void flt_from_cf(const cbx_cboxf *f, cbx_cbox *d)
{
    int j;
    for (j = 0; j < 3; j++) { d->c[j] = f->c[j]; d->h[j] = f->h[j]; }
}

void flt_nan_bf(cbx_boxf *o)
{
    int j;
    for (j = 0; j < 3; j++) o->lo[j] = o->hi[j] = NAN;
}

void flt_nan_cf(cbx_cboxf *o)
{
    int j;
    for (j = 0; j < 3; j++) o->c[j] = o->h[j] = NAN;
}

int flt_is_pinf(double d) { return d > 0 && isinf(d); }
int flt_is_ninf(double d) { return d < 0 && isinf(d); }
