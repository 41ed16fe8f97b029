/*
 * batch_gen.c: part of tests/test_batch.c (batch_parts.h): the random maps
 * (ordinary, zero columns, infinite, NaN and huge entries, maps of a class,
 * the edge of the fast range) and boxes of each kind, a batch of a random
 * mix of kinds (the draws in a fixed order: the same batches on every
 * machine), and the special values, each in each position of a base map
 * of each class and a base box.
 */
#include <stddef.h>
#include <float.h>
#include <math.h>

#include "batch_parts.h"

/* ---- random maps and boxes -------------------------------------------- */

static double sgm(xu_rng *r, int emin, int emax) { return xu_gen_signed(r, emin, emax); }

void bat_gen_map(xu_rng *r, cbx_affine *a, int kind)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) a->m[i][j] = sgm(r, -10, 10);
        a->m[i][3] = sgm(r, -20, 20);
    }
    switch (kind) {
    case 1: /* zero and -0.0 columns */
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++)
                if (xu_rng_int(r, 0, 2) == 0) a->m[i][j] = xu_rng_sign(r) * 0.0;
        break;
    case 2: /* an infinite entry: that row is lost for every box */
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF;
        break;
    case 3: /* a NaN: every box CBX_EINVAL */
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
        break;
    case 4: /* huge entries */
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 2)] = xu_rng_sign(r) * 1e300;
        break;
    case 5: { /* a map of a class: identity, translation, scale, permutation */
        int c = xu_rng_int(r, CBX_CLASS_PERMUTE, CBX_CLASS_IDENTITY), col;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = 0.0;
            col = c == CBX_CLASS_PERMUTE ? (i + 1) % 3 : i;
            a->m[i][col] = c >= CBX_CLASS_TRANSLATE ? 1.0 : sgm(r, -10, 10);
            if (c == CBX_CLASS_IDENTITY) a->m[i][3] = 0.0;
        }
        break;
    }
    case 6: /* entries at the edge of the fast range (2^509, 2^1018) or just past it */
        for (i = 0; i < 3; i++) {
            double e = xu_rng_int(r, 0, 1) ? 0x1p509 : 0x1.0000000000001p509;
            j = xu_rng_int(r, 0, 2);
            a->m[i][j] = xu_rng_sign(r) * e;
            e = xu_rng_int(r, 0, 1) ? 0x1p1018 : 0x1.0000000000001p1018;
            a->m[i][3] = xu_rng_sign(r) * e;
        }
        break;
    default:
        break;
    }
}

void bat_gen_box(xu_rng *r, cbx_box *b, int kind)
{
    int j, q;
    for (j = 0; j < 3; j++) {
        double u = sgm(r, -30, 30), w = sgm(r, -30, 30);
        b->lo[j] = u < w ? u : w;
        b->hi[j] = u < w ? w : u;
    }
    q = xu_rng_int(r, 0, 2);
    switch (kind) {
    case B_NAN:
        if (xu_rng_int(r, 0, 1)) b->lo[q] = NAN;
        else b->hi[q] = NAN;
        break;
    case B_EMPTY:
        switch (xu_rng_int(r, 0, 2)) {
        case 0: { double t = b->lo[q]; b->lo[q] = b->hi[q] + 1.0; b->hi[q] = t; } break;
        case 1: b->lo[q] = INF; break;
        default: b->hi[q] = -INF; break;
        }
        break;
    case B_OOD:
        if (xu_rng_int(r, 0, 1)) b->hi[q] = xu_rng_int(r, 0, 1) ? DBL_MAX : 0x1p1019;
        else b->lo[q] = -DBL_MAX;
        break;
    case B_HALF:
        if (xu_rng_int(r, 0, 1)) b->lo[q] = -INF;
        else b->hi[q] = INF;
        if (xu_rng_int(r, 0, 3) == 0) { b->lo[(q + 1) % 3] = -INF; b->hi[(q + 1) % 3] = INF; }
        break;
    case B_FLAT:
        for (j = 0; j < 3; j++) b->hi[j] = b->lo[j];
        break;
    case B_EDGE: /* an end at the edge of the fast range (2^509) or just past it */
        if (xu_rng_int(r, 0, 1)) b->hi[q] = xu_rng_int(r, 0, 1) ? 0x1p509 : 0x1.0000000000001p509;
        else b->lo[q] = xu_rng_int(r, 0, 1) ? -0x1p509 : -0x1.0000000000001p509;
        break;
    default:
        break;
    }
}

/* A batch of n boxes with a random mix of kinds. */
void bat_random_batch(xu_rng *r, stats *st, xu_exact *x, const cbx_affine *a, size_t n)
{
    static cbx_box in[MAXN];
    static int kinds[MAXN];
    int w[NB_RAND], total = 0, q;
    size_t k;
    /* the mix: weights per kind for this batch; often all normal */
    for (q = 0; q < NB_RAND; q++) {
        w[q] = xu_rng_int(r, 0, 3) == 0 ? 0 : xu_rng_int(r, 1, 10);
        total += w[q];
    }
    if (xu_rng_int(r, 0, 4) == 0 || total == 0) {
        for (q = 0; q < NB_RAND; q++) w[q] = 0;
        w[xu_rng_int(r, 0, 3) ? B_NORMAL : xu_rng_int(r, 0, NB_RAND - 1)] = 1;
        total = 1;
    }
    for (k = 0; k < n; k++) {
        int p = xu_rng_int(r, 0, total - 1);
        for (q = 0; q < NB_RAND - 1 && p >= w[q]; q++) p -= w[q];
        kinds[k] = q;
        bat_gen_box(r, &in[k], q);
    }
    bat_run_batch(st, x, a, in, kinds, n, (int)(st->batches % XU_NCLS_VALUES), 1);
}

/* ---- special values --------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
static const double specials[] = {
    NAN, -NAN, INF, -INF, 0.0, -0.0, 0x1p-1074, -DBL_MIN, 1.0, -1.0, 2.0,
    0x1p509, 0x1.0000000000001p509, -0x1p509, 0x1p1018, -0x1.0000000000001p1018, 0x1p1019,
    DBL_MAX, -DBL_MAX
};
#define N_SPECIAL ((int)(sizeof specials / sizeof specials[0]))
const int bat_n_special = N_SPECIAL;
/* one base map of each class, identity first */
static const cbx_affine base_maps[] = {
    MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
    MAT(ROW(1, 0, 0, 1), ROW(0, 1, 0, -2), ROW(0, 0, 1, 3)),
    MAT(ROW(2, 0, 0, 1), ROW(0, -3, 0, -2), ROW(0, 0, 0.5, 3)),
    MAT(ROW(0, 1, 0, 1), ROW(0, 0, -3, -2), ROW(0.5, 0, 0, 3)),
    MAT(ROW(0.5, -2, 0.25, 1), ROW(0, 1.5, -1, -3), ROW(4, 0, 0.125, 0.75)),
};
#define N_BASE ((int)(sizeof base_maps / sizeof base_maps[0]))
const int bat_n_base = N_BASE;

/* Each special value in each of the 18 positions (12 map entries, 6 box
 * ends) of each base map and the base box: a batch of one box, with every
 * forged cls value. */
void bat_run_specials(stats *st, xu_exact *x)
{
    static const cbx_box base_box = { { -1, 0.5, -4 }, { 2, 3, -2 } };
    static const int kind = B_SPECIAL;
    int m, p, v;
    for (m = 0; m < N_BASE; m++)
        for (p = 0; p < 18; p++)
            for (v = 0; v < N_SPECIAL; v++) {
                cbx_affine a = base_maps[m];
                cbx_box b = base_box;
                if (p < 12) a.m[p / 4][p % 4] = specials[v];
                else if (p < 15) b.lo[p - 12] = specials[v];
                else b.hi[p - 15] = specials[v];
                st->special++;
                bat_run_batch(st, x, &a, &b, &kind, 1, 0, XU_NCLS_VALUES);
            }
}
