/*
 * cbox_random.c: part of tests/test_cbox.c (cbox_parts.h): the random case
 * generators (splitmix64, exact_util.h), for cbx_transform_cbox (in the
 * domain by construction, then perturbed; zero-coefficient columns) and
 * for both conversions.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "cbox_parts.h"

/* ---------------------------------------------------------------------- */
/* Random generation                                                      */
/* ---------------------------------------------------------------------- */

/* half-diagonal in [0, 2^hmax] (with -0.0 and exact zeros) */
static double gen_half(xu_rng *r, int hmin, int hmax)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 8) return 0.0;
    if (p < 12) return -0.0;
    return xu_gen_mag(r, hmin, hmax);
}

/* cbox case inside the domain by construction (per column a class k),
 * "narrow" mode: all products of one size P (cancellation happens). */
static void gen_tc_in_domain(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int narrow = xu_rng_int(r, 0, 1);
    int P = xu_rng_int(r, -1070, 1016);
    int i, j;
    for (j = 0; j < 3; j++) {
        int k = xu_class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        int mlo = -1074, mhi = k, clo = -1074, chi = 1018 - k;
        if (narrow) {
            int lo = P - 1018 + k > -1074 ? P - 1018 + k : -1074;
            int hi = k < P + 1074 ? k : P + 1074;
            int am = xu_rng_int(r, lo, hi);
            mhi = am;
            mlo = am - 4;
            chi = P - am;
            clo = chi - 4;
        }
        for (i = 0; i < 3; i++) a->m[i][j] = xu_gen_signed(r, mlo, mhi);
        b->c[j] = xu_gen_signed(r, clo, chi);
        switch (xu_rng_int(r, 0, 9)) {
        case 0: b->h[j] = fabs(b->c[j]); break;               /* c-h = 0 */
        case 1: b->h[j] = gen_half(r, -1074, chi - 30); break; /* h << c */
        default: b->h[j] = gen_half(r, clo, chi); break;
        }
    }
    for (i = 0; i < 3; i++) {
        int p = xu_rng_int(r, 0, 9);
        if (p < 2) { /* t = -fl(m.c): the centre nearly cancels */
            double s = 0;
            for (j = 0; j < 3; j++) s += a->m[i][j] * b->c[j];
            a->m[i][3] = -s;
        } else if (p < 3) a->m[i][3] = xu_rng_sign(r) * 0.0;
        else if (narrow) a->m[i][3] = xu_gen_signed(r, P - 4, P);
        else a->m[i][3] = xu_gen_signed(r, -1074, 1018);
    }
}

static void perturb_tc(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 2), k;
    switch (xu_rng_int(r, 0, 7)) {
    case 0: a->m[i][j] = xu_gen_signed(r, 200, 1023); break;
    case 1: b->c[j] = xu_gen_signed(r, 900, 1023); break;
    case 2: b->h[j] = xu_gen_mag(r, 900, 1023); break;
    case 3: /* infinities: c = -+inf, h = +inf, entry or t */
        switch (xu_rng_int(r, 0, 2)) {
        case 0: b->c[j] = xu_rng_sign(r) * INF; break;
        case 1: b->h[j] = INF; break;
        default: a->m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF; break;
        }
        break;
    case 4: /* translation beyond 2^1018 */
        k = xu_rng_int(r, 0, 2);
        a->m[i][3] = xu_rng_sign(r) * (k == 0 ? P1018U : k == 1 ? DBL_MAX
                                       : xu_gen_mag(r, 1019, 1023));
        break;
    case 5: /* one ulp outward on an entry */
        a->m[i][j] = nextafter(a->m[i][j], a->m[i][j] < 0 ? -INF : INF);
        break;
    default: /* exact class corner, then c or h one ulp beyond (or not) */
        k = xu_class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        a->m[i][j] = xu_rng_sign(r) * ldexp(1.0, k);
        b->c[j] = xu_rng_sign(r) * ldexp(1.0, 1018 - k);
        b->h[j] = ldexp(1.0, 1018 - k);
        if (xu_rng_int(r, 0, 1)) {
            if (xu_rng_int(r, 0, 1)) b->h[j] = nextafter(b->h[j], INF);
            else b->c[j] = nextafter(b->c[j], b->c[j] < 0 ? -INF : INF);
        }
        break;
    }
}

static void inject_neg_h(xu_rng *r, cbx_cbox *b)
{
    int j = xu_rng_int(r, 0, 2);
    switch (xu_rng_int(r, 0, 4)) {
    case 0: b->h[j] = -0x1p-1074; break;
    case 1: b->h[j] = -1.0; break;
    case 2: b->h[j] = -INF; break;
    case 3: b->h[j] = -DBL_MAX; break;
    default: b->h[j] = b->h[j] > 0 ? -b->h[j] : -0x1p-1022; break;
    }
}

/* ~87% in domain, ~10% pushed out (or to the edge), ~1.5% NaN, ~1.5% empty */
void cbt_gen_tc_case(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int p = xu_rng_int(r, 0, 999);
    gen_tc_in_domain(r, a, b);
    if (p < 100) perturb_tc(r, a, b);
    else if (p < 115) xu_inject_nan(r, a, b->c, b->h);
    else if (p < 130) {
        inject_neg_h(r, b);
        if (p < 118) xu_inject_nan(r, a, b->c, b->h);
    }
}

/* A value no row could use unless its coefficient is zero: +-inf or a
 * magnitude outside every class (|x| > 2^1018); sg: the sign (h >= 0). */
static double gen_unusable(xu_rng *r, double sg)
{
    switch (xu_rng_int(r, 0, 5)) {
    case 0: case 1: return sg * INF;
    case 2: return sg * DBL_MAX;
    case 3: return sg * P1018U;
    case 4: return sg * 0x1p1023;
    default: return sg * xu_gen_mag(r, 1019, 1023);
    }
}

/* Zero-coefficient columns (kind D and its neighbours): an in-domain case,
 * then 1 to 3 columns j get m_ij = +-0.0 in some rows (random sign, so
 * -0.0 is frequent) and c_j and / or h_j a value outside the domain
 * (+-inf, DBL_MAX, 2^1018 + ulp, ...) or left ordinary; sometimes a
 * nonzero column gets such a value too (those rows are lost), t leaves the
 * domain, or a NaN / a negative h lands in a zero column. */
void cbt_gen_tc_drop_case(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int nz = xu_rng_int(r, 0, 9) < 7 ? 1 : xu_rng_int(r, 2, 3);
    int first = xu_rng_int(r, 0, 2), n, i, j, p;
    gen_tc_in_domain(r, a, b);
    for (n = 0; n < nz; n++) {
        int rows = xu_rng_int(r, 1, 7);       /* nonempty set of rows */
        if (xu_rng_int(r, 0, 3) == 0) rows = 7;
        j = (first + n) % 3;
        for (i = 0; i < 3; i++)
            if (rows & (1 << i)) a->m[i][j] = xu_rng_sign(r) * 0.0;
        switch (xu_rng_int(r, 0, 5)) {
        case 0: b->c[j] = gen_unusable(r, xu_rng_sign(r)); break;
        case 1: b->h[j] = gen_unusable(r, 1.0); break;
        case 2: case 3:
            b->c[j] = gen_unusable(r, xu_rng_sign(r));
            b->h[j] = gen_unusable(r, 1.0);
            break;
        case 4: b->h[j] = xu_rng_int(r, 0, 1) ? -0.0 : INF;
                b->c[j] = xu_rng_sign(r) * INF; break;
        default: break;                        /* ordinary values: A rows */
        }
    }
    p = xu_rng_int(r, 0, 99);
    j = (first + nz) % 3;                      /* a column not zeroed above */
    i = xu_rng_int(r, 0, 2);
    if (p < 20 && nz < 3) {                    /* mix: a nonzero column unusable */
        if (xu_rng_int(r, 0, 1)) b->c[j] = gen_unusable(r, xu_rng_sign(r));
        else b->h[j] = gen_unusable(r, 1.0);
    } else if (p < 25) {                       /* t out of the domain */
        a->m[i][3] = xu_rng_int(r, 0, 1) ? xu_rng_sign(r) * INF : xu_rng_sign(r) * P1018U;
    } else if (p < 28) {                       /* a coefficient not quite zero */
        a->m[i][first] = xu_rng_sign(r) * 0x1p-1074;
    } else if (p < 30) {                       /* an infinite coefficient */
        a->m[i][xu_rng_int(r, 0, 2)] = xu_rng_sign(r) * INF;
    } else if (p < 32) {                       /* NaN in a zero column */
        if (xu_rng_int(r, 0, 1)) b->c[first] = xu_rng_sign(r) * NAN;
        else b->h[first] = NAN;
    } else if (p < 34) {                       /* h < 0 in a zero column */
        b->h[first] = xu_rng_int(r, 0, 1) ? -INF : -0x1p-1074;
    }
}

/* an ordered pair of doubles within 2^emax (never empty) */
static void gen_conv_interval(xu_rng *r, double *lo, double *hi, int emax)
{
    int p = xu_rng_int(r, 0, 99);
    double u, v;
    if (p < 10) { *lo = *hi = xu_gen_signed(r, -1074, emax); return; }
    if (p < 15) { *lo = xu_rng_sign(r) * 0.0; *hi = xu_rng_sign(r) * 0.0; return; }
    if (p < 25) { u = xu_gen_mag(r, -1074, emax); *lo = -u; *hi = u; return; }
    if (p < 35) { /* k ulps wide */
        int n = xu_rng_int(r, 1, 3);
        u = xu_gen_signed(r, -1074, emax);
        v = u;
        while (n--) v = nextafter(v, INF);
        if (fabs(v) > ldexp(1.0, emax)) v = u;
        *lo = u; *hi = v; return;
    }
    if (p < 50) { /* similar magnitudes */
        int e = xu_rng_int(r, -1070, emax);
        u = xu_gen_signed(r, e - 3, e);
        v = xu_gen_signed(r, e - 3, e);
    } else {
        u = xu_gen_signed(r, -1074, emax);
        v = xu_gen_signed(r, -1074, emax);
    }
    *lo = u < v ? u : v;
    *hi = u < v ? v : u;
}

static double beyond_conv(xu_rng *r)
{
    switch (xu_rng_int(r, 0, 4)) {
    case 0: return nextafter(ldexp(1.0, CONV_EMAX), INF);
    case 1: return DBL_MAX;
    case 2: return INF;
    case 3: return ldexp(1.0, CONV_EMAX); /* the limit itself: in domain */
    default: return xu_gen_mag(r, CONV_EMAX, 1024);
    }
}

void cbt_gen_b2c_case(xu_rng *r, cbx_box *b)
{
    int j, p = xu_rng_int(r, 0, 999);
    for (j = 0; j < 3; j++) gen_conv_interval(r, &b->lo[j], &b->hi[j], CONV_EMAX);
    j = xu_rng_int(r, 0, 2);
    if (p < 100) {
        double big = beyond_conv(r);
        switch (xu_rng_int(r, 0, 3)) {
        case 0: b->hi[j] = big; if (b->lo[j] > big) b->lo[j] = -big; break;
        case 1: b->lo[j] = -big; if (b->hi[j] < -big) b->hi[j] = big; break;
        case 2: b->lo[j] = -big; b->hi[j] = big; break;
        default: b->lo[j] = b->hi[j] = xu_rng_sign(r) * big; break;
        }
    } else if (p < 115) {
        double nan = xu_rng_sign(r) * NAN;
        if (xu_rng_int(r, 0, 1)) b->lo[j] = nan; else b->hi[j] = nan;
    } else if (p < 130) {
        switch (xu_rng_int(r, 0, 2)) {
        case 0: b->lo[j] = nextafter(b->hi[j], INF); break;
        case 1: b->lo[j] = INF; b->hi[j] = -INF; break;
        default: b->lo[j] = 1.0; b->hi[j] = -1.0; break;
        }
        if (p < 118) b->hi[(j + 1) % 3] = NAN;
    }
}

void cbt_gen_c2b_case(xu_rng *r, cbx_cbox *b)
{
    int j, p = xu_rng_int(r, 0, 999);
    for (j = 0; j < 3; j++) {
        switch (xu_rng_int(r, 0, 5)) {
        case 0: /* c - h or c + h exactly 0 */
            b->c[j] = xu_gen_signed(r, -1074, CONV_EMAX);
            b->h[j] = fabs(b->c[j]);
            break;
        case 1: { /* similar magnitudes */
            int e = xu_rng_int(r, -1070, CONV_EMAX);
            b->c[j] = xu_gen_signed(r, e - 3, e);
            b->h[j] = gen_half(r, e - 3, e);
            break;
        }
        default:
            b->c[j] = xu_gen_signed(r, -1074, CONV_EMAX);
            b->h[j] = gen_half(r, -1074, CONV_EMAX);
            break;
        }
    }
    j = xu_rng_int(r, 0, 2);
    if (p < 100) {
        double big = beyond_conv(r);
        if (xu_rng_int(r, 0, 1)) b->c[j] = xu_rng_sign(r) * big;
        else b->h[j] = big;
    } else if (p < 115) {
        double nan = xu_rng_sign(r) * NAN;
        if (xu_rng_int(r, 0, 1)) b->c[j] = nan; else b->h[j] = nan;
    } else if (p < 130) {
        inject_neg_h(r, b);
        if (p < 118) b->c[(j + 1) % 3] = NAN;
    }
}
