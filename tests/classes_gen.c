/*
 * The generators of test_classes (tests/classes_parts.h): maps of a known
 * class (realistic, extreme, random exponents over the class kernels' fast
 * range), the independent class rule, boxes of every kind, and the small
 * helpers the parts share.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "classes_parts.h"

const char *const clt_cls_name[NCLS] = { "GENERAL", "PERMUTE", "SCALE", "TRANSLATE",
                                         "IDENTITY" };
long clt_fail_logs = 0;

double clt_sgn(xu_rng *r) { return xu_rng_sign(r); }

/* ---------------------------------------------------------------------- */
/* Generators                                                             */
/* ---------------------------------------------------------------------- */

/* clt_sgn(r) * (1 + unit) * 2^e and (1 + unit) * 2^e, e in [lo, hi], with the
 * draws in a fixed order (C leaves the order of function arguments to the
 * compiler: gcc takes them right to left on x86-64, left to right on ARM) */
static double mant_pow(xu_rng *r, int lo, int hi)
{
    int e = xu_rng_int(r, lo, hi);
    return ldexp(1.0 + xu_rng_unit(r), e);
}

double clt_sgn_pow(xu_rng *r, int lo, int hi)
{
    double s = clt_sgn(r);
    return s * mant_pow(r, lo, hi);
}

/* A nonzero linear entry; g = 0 realistic (2^[-5,5)), g = 1 extreme, g = 2
 * random exponents over the class kernels' fast range (|m| <= 2^509). */
static double lin_val(xu_rng *r, int g)
{
    double v;
    if (g == 2) {
        do v = xu_gen_signed(r, -1074, 509); while (v == 0.0);
        return v;
    }
    if (!g || xu_rng_int(r, 0, 3) == 0)
        return clt_sgn_pow(r, -5, 4);
    switch (xu_rng_int(r, 0, 10)) {
    case 0: return clt_sgn(r) * 0x1p509;
    case 1: return clt_sgn(r) * nextafter(0x1p509, INF);     /* just past the fast range */
    case 2: return clt_sgn(r) * 0x1p-1074;
    case 3: return clt_sgn(r) * ldexp((double)((xu_rng_next(r) >> 12) | 1u), -1074);
    case 4: return clt_sgn(r) * DBL_MIN;
    case 5: return clt_sgn(r) * 0x1p1018;
    case 6: return clt_sgn(r) * 1.0;
    case 7: return clt_sgn_pow(r, 400, 600);
    case 8: return clt_sgn_pow(r, -1060, -900);
    default:
        do v = xu_gen_signed(r, -1074, 1023); while (v == 0.0 || isinf(v));
        return v;
    }
}

/* A translation; g = 0 realistic, g = 1 extreme (may be out of the domain),
 * g = 2 random exponents over the fast range (|t| <= 2^1018). */
static double tr_val(xu_rng *r, int g)
{
    if (g == 2) return xu_gen_signed(r, -1074, 1018);
    if (!g || xu_rng_int(r, 0, 2) == 0) {
        if (xu_rng_int(r, 0, 9) == 0) return clt_sgn(r) * 0.0;
        return clt_sgn(r) * xu_rng_unit(r) * ldexp(1.0, xu_rng_int(r, -2, 10));
    }
    switch (xu_rng_int(r, 0, 8)) {
    case 0: return clt_sgn(r) * 0.0;
    case 1: return clt_sgn(r) * 0x1p1018;
    case 2: return clt_sgn(r) * nextafter(0x1p1018, INF);   /* out of the domain */
    case 3: return clt_sgn(r) * 0x1p1019;
    case 4: return clt_sgn(r) * DBL_MAX;
    case 5: return clt_sgn(r) * 0x1p-1074;
    case 6: return clt_sgn_pow(r, 900, 1017);
    case 7: return clt_sgn_pow(r, 500, 520);
    default: return xu_gen_signed(r, -1074, 1018);
    }
}

static void zero_map(xu_rng *r, cbx_affine *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) a->m[i][j] = clt_sgn(r) * 0.0;
}

/* R diag(s): a uniform random rotation with scales 2^[-4,4], 10% reflected. */
static void rot_scale(xu_rng *r, double M[3][3])
{
    double R[3][3], s[3];
    int i, j;
    xu_rand_rotation(r, R);
    for (j = 0; j < 3; j++) {
        s[j] = mant_pow(r, -5, 3);
        if (xu_rng_int(r, 0, 9) == 0) s[j] = -s[j];
    }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) M[i][j] = R[i][j] * s[j];
}

/* A map of class cls by construction (the smallest class that holds it);
 * g = 0 realistic magnitudes, g = 1 extreme. */
void clt_gen_map_cls(xu_rng *r, cbx_affine *a, int cls, int g)
{
    int i, j, any;
    zero_map(r, a);
    switch (cls) {
    case CBX_CLASS_IDENTITY:
        for (i = 0; i < 3; i++) a->m[i][i] = 1.0;
        break;
    case CBX_CLASS_TRANSLATE:
        for (i = 0; i < 3; i++) {
            a->m[i][i] = 1.0;
            a->m[i][3] = tr_val(r, g);
        }
        if (a->m[0][3] == 0.0 && a->m[1][3] == 0.0 && a->m[2][3] == 0.0)
            a->m[xu_rng_int(r, 0, 2)][3] = g ? clt_sgn(r) * 0x1p-1074 : 1.5;
        break;
    case CBX_CLASS_SCALE:
        for (i = 0; i < 3; i++) {
            int p = xu_rng_int(r, 0, 9);
            a->m[i][i] = p == 0 ? clt_sgn(r) * 0.0 : p == 1 ? 1.0 : p == 2 ? -1.0 : lin_val(r, g);
            a->m[i][3] = tr_val(r, g);
        }
        if (a->m[0][0] == 1.0 && a->m[1][1] == 1.0 && a->m[2][2] == 1.0) {
            i = xu_rng_int(r, 0, 2);
            a->m[i][i] = xu_rng_int(r, 0, 1) ? -1.0 : 2.0;
        }
        break;
    case CBX_CLASS_PERMUTE: {
        int col[3];
        any = 0;
        for (i = 0; i < 3; i++) {
            col[i] = xu_rng_int(r, 0, 9) == 0 ? -1 : xu_rng_int(r, 0, 2);
            if (col[i] >= 0 && col[i] != i) any = 1;
        }
        if (!any) {
            i = xu_rng_int(r, 0, 2);
            col[i] = (i + xu_rng_int(r, 1, 2)) % 3;
        }
        for (i = 0; i < 3; i++) {
            if (col[i] >= 0) {
                int p = xu_rng_int(r, 0, 3);
                /* 90-degree rotations: +-1; else a scale */
                a->m[i][col[i]] = p < 2 ? clt_sgn(r) : lin_val(r, g);
            }
            a->m[i][3] = tr_val(r, g);
        }
        break;
    }
    default: /* GENERAL */
        if (!g) {
            double M[3][3];
            rot_scale(r, M);
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) a->m[i][j] = M[i][j];
        } else {
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++)
                    if (xu_rng_int(r, 0, 4)) a->m[i][j] = lin_val(r, g);
        }
        for (i = 0; i < 3; i++) a->m[i][3] = tr_val(r, g);
        /* at least one row with two nonzero linear entries */
        i = xu_rng_int(r, 0, 2);
        j = xu_rng_int(r, 0, 2);
        if (a->m[i][j] == 0.0) a->m[i][j] = lin_val(r, g);
        j = (j + xu_rng_int(r, 1, 2)) % 3;
        if (a->m[i][j] == 0.0) a->m[i][j] = lin_val(r, g);
        if (g && xu_rng_int(r, 0, 19) == 0) /* an infinite entry: still GENERAL */
            a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = clt_sgn(r) * INF;
        break;
    }
}

/* The class by an independent rule: count nonzero linear entries. */
int clt_rule_class(const cbx_affine *a)
{
    int i, j, offdiag = 0, sparse = 1, diag1 = 1, t0 = 1;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (!isfinite(a->m[i][j])) return CBX_CLASS_GENERAL;
    for (i = 0; i < 3; i++) {
        int nz = 0;
        for (j = 0; j < 3; j++)
            if (a->m[i][j] != 0.0) {
                nz++;
                if (j != i) offdiag = 1;
            }
        if (nz > 1) sparse = 0;
        if (a->m[i][i] != 1.0) diag1 = 0;
        if (a->m[i][3] != 0.0) t0 = 0;
    }
    if (!offdiag) return diag1 ? (t0 ? CBX_CLASS_IDENTITY : CBX_CLASS_TRANSLATE) : CBX_CLASS_SCALE;
    return sparse ? CBX_CLASS_PERMUTE : CBX_CLASS_GENERAL;
}

const char *const clt_bx_name[NBX] = { "realistic", "tiny", "point", "flat", "big",
                                       "half-space", "empty", "NaN", "random-exp",
                                       "fast-range" };

static double big_end(xu_rng *r)
{
    switch (xu_rng_int(r, 0, 8)) {
    case 0: return clt_sgn(r) * 0x1p509;
    case 1: return clt_sgn(r) * nextafter(0x1p509, INF);
    case 2: return clt_sgn(r) * 0x1p1018;
    case 3: return clt_sgn(r) * nextafter(0x1p1018, INF);
    case 4: return clt_sgn(r) * 0x1p1019;
    case 5: return clt_sgn(r) * DBL_MAX;
    case 6: return clt_sgn_pow(r, 490, 509);
    case 7: return clt_sgn_pow(r, 1000, 1017);
    default: return clt_sgn(r) * xu_rng_unit(r) * 64.0;
    }
}

static void order(cbx_box *b, int j)
{
    if (b->lo[j] > b->hi[j]) {
        double t = b->lo[j];
        b->lo[j] = b->hi[j];
        b->hi[j] = t;
    }
}

void clt_gen_box(xu_rng *r, cbx_box *b, int kind)
{
    int j, q;
    for (j = 0; j < 3; j++) {
        double c = clt_sgn(r) * xu_rng_unit(r) * ldexp(1.0, xu_rng_int(r, -4, 8));
        double h = xu_rng_int(r, 0, 19) == 0 ? 0.0 : mant_pow(r, -12, 5);
        b->lo[j] = c - h;
        b->hi[j] = c + h;
    }
    q = xu_rng_int(r, 0, 2);
    switch (kind) {
    case BX_TINY:
        for (j = 0; j < 3; j++) {
            if (xu_rng_int(r, 0, 4) == 0) {
                b->lo[j] = -0.0;
                b->hi[j] = xu_rng_int(r, 0, 1) ? 0.0 : -0.0;
            } else {
                b->lo[j] = xu_gen_signed(r, -1074, -1000);
                b->hi[j] = xu_gen_signed(r, -1074, -1000);
                order(b, j);
            }
        }
        break;
    case BX_POINT:
        for (j = 0; j < 3; j++) {
            double v = xu_rng_int(r, 0, 2) == 0 ? big_end(r) : b->lo[j];
            b->lo[j] = b->hi[j] = v;
        }
        break;
    case BX_FLAT:
        for (j = 0; j < 3; j++)
            if (xu_rng_int(r, 0, 1)) b->hi[j] = b->lo[j];
        break;
    case BX_BIG:
        for (j = 0; j < 3; j++)
            if (xu_rng_int(r, 0, 2)) {
                b->lo[j] = big_end(r);
                b->hi[j] = xu_rng_int(r, 0, 3) ? big_end(r) : b->lo[j];
                order(b, j);
            }
        break;
    case BX_HALF:
        if (xu_rng_int(r, 0, 1)) b->lo[q] = -INF;
        else b->hi[q] = INF;
        if (xu_rng_int(r, 0, 2) == 0) {
            b->lo[(q + 1) % 3] = -INF;
            b->hi[(q + 1) % 3] = INF;
        }
        if (xu_rng_int(r, 0, 3) == 0) {
            if (xu_rng_int(r, 0, 1)) b->lo[(q + 2) % 3] = -INF;
            else b->hi[(q + 2) % 3] = INF;
        }
        if (xu_rng_int(r, 0, 4) == 0) b->hi[(q + 2) % 3] = big_end(r), order(b, (q + 2) % 3);
        break;
    case BX_EMPTY:
        switch (xu_rng_int(r, 0, 3)) {
        case 0: { double t = b->lo[q]; b->lo[q] = b->hi[q] + 1.0; b->hi[q] = t; } break;
        case 1: b->lo[q] = INF; break;
        case 2: b->hi[q] = -INF; break;
        default: b->lo[q] = INF; b->hi[q] = -INF; break;
        }
        break;
    case BX_NAN:
        if (xu_rng_int(r, 0, 1)) b->lo[q] = NAN;
        else b->hi[q] = NAN;
        break;
    case BX_RAND:
    case BX_FASTR: /* random exponents over the fast range of SCALE / PERMUTE */
        for (j = 0; j < 3; j++) {
            int e = kind == BX_RAND ? 1023 : 509;
            b->lo[j] = xu_gen_signed(r, -1074, e);
            b->hi[j] = xu_rng_int(r, 0, 9) ? xu_gen_signed(r, -1074, e) : b->lo[j];
            order(b, j);
        }
        break;
    default:
        break;
    }
}

int clt_pick_box_kind(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    return p < 45 ? BX_REAL : p < 52 ? BX_TINY : p < 58 ? BX_POINT : p < 64 ? BX_FLAT
         : p < 75 ? BX_BIG : p < 83 ? BX_HALF : p < 88 ? BX_EMPTY : p < 91 ? BX_NAN : BX_RAND;
}

void clt_print_map(const char *label, const cbx_affine *a)
{
    int i;
    for (i = 0; i < 3; i++)
        printf("  %s[%d] = {%a, %a, %a | %a}\n", label, i, a->m[i][0], a->m[i][1],
               a->m[i][2], a->m[i][3]);
}

void clt_fill_nan(cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++) b->lo[j] = b->hi[j] = NAN;
}

int clt_same_bits(double p, double q) { return memcmp(&p, &q, sizeof p) == 0; }
