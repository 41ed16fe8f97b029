/*
 * imat_gen.c: the inputs of test_imat (tests/test_imat.c): random interval
 * matrices and boxes of every kind of entry, rotations, cancelling
 * translations, and the perturbations (out of the fast range, NaN,
 * inverted entries, empty box axes); and printing them (a failure's
 * reproducer).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"
#include "imat_parts.h"

/* ---------------------------------------------------------------------- */
/* Inputs                                                                 */
/* ---------------------------------------------------------------------- */

/* An exponent window [emin, emax] under top (values below 2^emax). */
static void window(xu_rng *r, int top, int *emin, int *emax)
{
    int p = xu_rng_int(r, 0, 99), c;
    if (p < 15) { *emin = -1074; *emax = top; return; }          /* everything */
    if (p < 30) { *emin = top - 30; *emax = top; return; }        /* at the limit */
    if (p < 38) { *emin = -1074; *emax = -1000; return; }         /* subnormal scale */
    c = xu_rng_int(r, -1000, top);
    *emin = c - 12;
    *emax = c + 8 < top ? c + 8 : top;
}

/* One interval of a random kind, within [-2^emax, 2^emax]. */
static void gen_iv(xu_rng *r, double *lo, double *hi, int emin, int emax)
{
    int p = xu_rng_int(r, 0, 99), n;
    double u, v, lim = ldexp(1.0, emax);
    if (p < 22) { /* a point */
        u = xu_gen_signed(r, emin, emax);
        *lo = *hi = u;
    } else if (p < 34) { /* one to three ulps */
        u = xu_gen_signed(r, emin, emax);
        v = u;
        for (n = xu_rng_int(r, 1, 3); n > 0; n--) v = nextafter(v, INF);
        if (v > lim) v = u;
        *lo = u;
        *hi = v;
    } else if (p < 42) { /* signed zeros, either order (ordered: -0 == 0) */
        u = xu_rng_sign(r);
        v = xu_rng_sign(r);
        *lo = u * 0.0;
        *hi = v * 0.0;
    } else if (p < 58) { /* straddling 0 */
        u = xu_gen_mag(r, emin, emax);
        v = xu_gen_mag(r, emin, emax);
        *lo = -u;
        *hi = v;
    } else if (p < 64) { /* subnormal ends */
        u = xu_gen_signed(r, -1074, -1022);
        v = xu_gen_signed(r, -1074, -1022);
        *lo = u < v ? u : v;
        *hi = u < v ? v : u;
    } else { /* wide */
        u = xu_gen_signed(r, emin, emax);
        v = xu_gen_signed(r, emin, emax);
        *lo = u < v ? u : v;
        *hi = u < v ? v : u;
    }
}

/* Intervals of a random rotation (or of a scaled one), each entry its
 * double widened by 0 to 2 ulps on each side: the maps of a node chain. */
void imt_gen_rot(xu_rng *r, cbx_imat *a, int with_t)
{
    double R[3][3], s = 1.0;
    int i, j, n;
    xu_rand_rotation(r, R);
    if (xu_rng_int(r, 0, 3) == 0) s = xu_gen_mag(r, -20, 20);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double lo = R[i][j] * s, hi = lo;
            for (n = xu_rng_int(r, 0, 2); n > 0; n--) lo = nextafter(lo, -INF);
            for (n = xu_rng_int(r, 0, 2); n > 0; n--) hi = nextafter(hi, INF);
            a->lo[i][j] = lo;
            a->hi[i][j] = hi;
        }
        if (with_t) {
            double t = xu_gen_signed(r, -10, 10);
            a->lo[i][3] = t;
            a->hi[i][3] = xu_rng_int(r, 0, 1) ? t : nextafter(t, INF);
        } else {
            a->lo[i][3] = a->hi[i][3] = 0.0;
        }
    }
}

/* A random interval matrix within the fast range (every row: linear
 * entries within 2^509, translation within 2^1018). */
void imt_gen_imat(xu_rng *r, cbx_imat *a, int ttop)
{
    int i, j, emin, emax;
    if (xu_rng_int(r, 0, 9) == 0) {
        imt_gen_rot(r, a, 1);
        return;
    }
    for (i = 0; i < 3; i++) {
        window(r, 509, &emin, &emax);
        for (j = 0; j < 3; j++) gen_iv(r, &a->lo[i][j], &a->hi[i][j], emin, emax);
        int p = xu_rng_int(r, 0, 99);
        if (p < 25) {
            double u = xu_rng_sign(r), v = xu_rng_sign(r);
            a->lo[i][3] = u * 0.0;
            a->hi[i][3] = v * 0.0;
        } else if (p < 80) {
            window(r, ttop, &emin, &emax);
            gen_iv(r, &a->lo[i][3], &a->hi[i][3], emin, emax);
        } else {
            /* large: the products' scale, up to the limit */
            int e2 = emax + xu_rng_int(r, 0, 509);
            if (e2 > ttop) e2 = ttop;
            gen_iv(r, &a->lo[i][3], &a->hi[i][3], e2 - 20, e2);
        }
    }
}

void imt_gen_box(xu_rng *r, cbx_box *b)
{
    int j, emin, emax;
    for (j = 0; j < 3; j++) {
        window(r, 509, &emin, &emax);
        gen_iv(r, &b->lo[j], &b->hi[j], emin, emax);
    }
}

/* A translation cancelling the linear part at the box's centre: [t, t] or
 * [t, t + ulp], t = -(sum of the entries' midpoints times the centres),
 * rounded (within 2^1018: the inputs are within 2^509). */
void imt_cancel_t(xu_rng *r, cbx_imat *a, const cbx_box *b, int i)
{
    double t = 0.0;
    int j;
    for (j = 0; j < 3; j++)
        t -= (a->lo[i][j] / 2 + a->hi[i][j] / 2) * (b->lo[j] / 2 + b->hi[j] / 2);
    if (!isfinite(t) || fabs(t) > RT) return;
    a->lo[i][3] = t;
    a->hi[i][3] = xu_rng_int(r, 0, 1) ? t : nextafter(t, INF);
    if (a->hi[i][3] > RT) a->hi[i][3] = t;
}

/* A value beyond the fast range (2^509 for linear entries and box ends,
 * 2^1018 for a translation), positive. */
static double big(xu_rng *r, int trans)
{
    static const double lin[] = { 0x1.0000000000001p509, 0x1p510, 1e300, DBL_MAX, INF, INF };
    static const double tr[] = { 0x1.0000000000001p1018, 0x1p1019, DBL_MAX, INF, INF };
    return trans ? tr[xu_rng_int(r, 0, 4)] : lin[xu_rng_int(r, 0, 5)];
}

/* Push one interval out of the fast range, keeping it ordered: one end
 * beyond, both, or (matrix entries only) a point at an infinity. */
static void push_out(xu_rng *r, double *lo, double *hi, int trans, int matrix)
{
    int p = xu_rng_int(r, 0, matrix ? 4 : 2);
    double v = big(r, trans);
    switch (p) {
    case 0: *hi = v; break;
    case 1: *lo = -v; break;
    case 2: *lo = -v; *hi = big(r, trans); break;
    case 3: *lo = *hi = v; break;            /* [v, v]: +inf: no real entry */
    default: *lo = *hi = -v; break;
    }
}

/* A NaN in one of the n numbers of p[] (either sign). */
static void put_nan(xu_rng *r, double *const *p, int n)
{
    double s = xu_rng_sign(r);
    *p[xu_rng_int(r, 0, n - 1)] = s * NAN;
}

/* Invert one entry of a: hi < lo. */
static void invert(xu_rng *r, cbx_imat *a)
{
    int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 3);
    double l = a->lo[i][j], h = a->hi[i][j];
    if (l < h) {
        a->lo[i][j] = h;
        a->hi[i][j] = l;
    } else {
        a->hi[i][j] = nextafter(l, -INF);   /* also -0 -> -2^-1074 */
        if (!(a->hi[i][j] < a->lo[i][j])) {
            a->lo[i][j] = 0.0;
            a->hi[i][j] = -INF;
        }
    }
}

/* Make one axis of b have no real point. */
void imt_make_empty(xu_rng *r, cbx_box *b)
{
    int j = xu_rng_int(r, 0, 2), p = xu_rng_int(r, 0, 3);
    double l = b->lo[j], h = b->hi[j];
    switch (p) {
    case 0:
        if (l < h) { b->lo[j] = h; b->hi[j] = l; }
        else { b->lo[j] = 1.0; b->hi[j] = -1.0; }
        break;
    case 1: b->lo[j] = INF; break;
    case 2: b->hi[j] = -INF; break;
    default: b->lo[j] = INF; b->hi[j] = INF; break;
    }
}

/* The 24 numbers of an interval matrix and the 6 of a box. */
static int slots(cbx_imat *a, cbx_box *b, double **p)
{
    int i, j, n = 0;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            p[n++] = &a->lo[i][j];
            p[n++] = &a->hi[i][j];
        }
    if (b)
        for (j = 0; j < 3; j++) {
            p[n++] = &b->lo[j];
            p[n++] = &b->hi[j];
        }
    return n;
}

/* Perturbations common to both functions: out of range (20%), NaN (2%),
 * inverted (2%).  Returns 1 if something was pushed out of range. */
int imt_perturb(xu_rng *r, cbx_imat *a, cbx_box *b, cbx_imat *b2)
{
    int pushed = 0, n, m;
    if (xu_rng_int(r, 0, 99) < 20) {
        pushed = 1;
        for (m = xu_rng_int(r, 1, 2); m > 0; m--) {
            int w = xu_rng_int(r, 0, 1), i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 3);
            if (w == 0) push_out(r, &a->lo[i][j], &a->hi[i][j], j == 3, 1);
            else if (b) push_out(r, &b->lo[i], &b->hi[i], 0, 0);
            else push_out(r, &b2->lo[i][j], &b2->hi[i][j], 0, 1);
        }
    }
    if (xu_rng_int(r, 0, 99) < 2) {
        double *p[30];
        int w = b2 ? xu_rng_int(r, 0, 1) : 0;
        n = slots(w ? b2 : a, w ? NULL : b, p);
        put_nan(r, p, n);
    }
    if (xu_rng_int(r, 0, 99) < 2) invert(r, b2 && xu_rng_int(r, 0, 1) ? b2 : a);
    return pushed;
}

/* ---------------------------------------------------------------------- */
/* Printing                                                               */
/* ---------------------------------------------------------------------- */

void imt_print_imat(const char *name, const cbx_imat *a)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        printf("  %s[%d] =", name, i);
        for (j = 0; j < 4; j++) printf(" [%a, %a]%s", a->lo[i][j], a->hi[i][j], j == 2 ? " |" : "");
        printf("\n");
    }
}

void imt_print_box(const char *name, const cbx_box *b)
{
    int j;
    printf("  %s =", name);
    for (j = 0; j < 3; j++) printf(" [%a, %a]", b->lo[j], b->hi[j]);
    printf("\n");
}
