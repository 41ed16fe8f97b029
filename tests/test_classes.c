/*
 * test_classes [N] [seed]: the transform classes (cbx_classify,
 * cbx_transform_box_as, with its class hint misused too) and the motion box
 * (cbx_motion_box) against exact rational arithmetic (GMP,
 * tests/exact_util.h).
 *
 * Part 1, classification (N maps).  Maps built to be of a known class
 * (IDENTITY, TRANSLATE, SCALE, PERMUTE, GENERAL; random signs, -0.0 zeros,
 * exact 1.0 entries, realistic and extreme magnitudes) and near misses of
 * each (a diagonal 1 + 2^-52 or 1 - 2^-53 or -1, an off-diagonal 2^-1074, a
 * translation 2^-1074, an extra tiny entry in a permutation row, zero
 * scales, all-(-0.0) zeros, DBL_MAX entries, a NaN or an infinity in any
 * entry).  The expected class is known by construction AND computed by an
 * independent rule (rule_class: count the nonzero entries); both must agree
 * with cbx_classify.
 *
 * Part 2, class kernels (N cases).  A map of each class (realistic, or
 * extreme: 2^509 and just above, 2^1018, subnormals, zero scales, huge and
 * out-of-domain translations, sometimes an infinity or a NaN, or random
 * exponents over the fast range of the class kernels: |m| <= 2^509,
 * |t| <= 2^1018) and a box (realistic, tiny/subnormal, point boxes,
 * lo == hi axes, ends at 2^509 / 2^1018 / beyond, half-spaces, empty, NaN,
 * random exponents, random exponents with |ends| <= 2^509).
 * cbx_transform_box_as is called with the class of cbx_classify and with
 * every larger class down to GENERAL, and cbx_transform_box once.  Each
 * class-kernel call must:
 *   - pass every exact check of exact_util (xu_check_result: the status
 *     computed exactly from the spec, special outputs, full-row containment
 *     of the exact image and the proven tightness 12 u S + 2^-1065, the
 *     half-space / out-of-domain end rules; the mpq 8-corner checks on
 *     every CORNER_EVERY-th case);
 *   - return the same status as cbx_transform_box, with identical (bit for
 *     bit) infinite ends, and every finite end never looser than the
 *     general kernel's (lo >= general lo, hi <= general hi);
 *   - give the same status and output in place (out == in);
 *   - leave *a and *in unchanged.
 * The general kernel's output goes through the same exact checks.  Excess
 * (distance to the exact end in units of u S + 2^-1074) is reported per
 * class for the class kernel (called with its own class) and for the
 * general kernel on the same axes.
 *
 * Part 3, motion (N pairs).  Pairs (a0, a1): both general, one map of each
 * class, identical maps, sign-flipped maps (an entry crosses 0 inside the
 * interval), a NaN, out-of-domain maps or boxes (mixed full / not-full
 * axes), half-space boxes, empty boxes.  With s in {0, 1, 1/2, 1/3, 2/7}
 * and 5 random p/q:
 *   - status: EINVAL on a NaN, EMPTY on an empty box, else CBX_OK iff both
 *     maps' exactly computed statuses are CBX_OK and no axis mixes a full
 *     row (xu_row_in_domain) with a non-full one, else CBX_ERANGE;
 *   - both rows full: the axis is finite and every corner c of the box has
 *     lo <= (M(s) c)_i <= hi exactly (fixed-point mpz, (1-s) and s as
 *     (q-p)/q and p/q), for every sampled s; the axis is bit for bit the
 *     union of the two cbx_transform_box outputs; the exact extreme over
 *     the sampled s equals the one over s in {0, 1}; and the ends are
 *     within 12 u max(S0, S1) + 2^-1065 of the exact extreme over s;
 *     every MOTION_DIRECT_EVERY-th case the same corner check again with
 *     M(s) built entry by entry in mpq (independent of the linearity);
 *   - neither row full, both map rows finite: the union, bit for bit, and
 *     each finite end below (above) the exact inf (sup) of (M(s) p)_i over
 *     every real point p of the box (extended vertex rule in mpq on the
 *     interpolated row: an infinite needed end means unbounded);
 *   - one full and one not, or a non-finite map row: exactly [-inf, +inf];
 *   - special outputs, in place, inputs unchanged.
 *
 * Part 4, misuse (a table, then N/4 cases).  cls is a hint: a class the
 * map is not in, or an int outside the enum, must run the general kernel.
 * Each input goes through cbx_transform_box_as with each of the 11 values
 * of xu_cls_values (GENERAL .. IDENTITY, 5, 7, -1, -3, INT_MAX, INT_MIN):
 *   - every exact check of exact_util (xu_check_result: status, special
 *     outputs, containment of the exact image, proven tightness, the
 *     half-space / out-of-domain end rules; mpq corners every
 *     CORNER_EVERY-th case), cbx_transform_box's status, inputs unchanged;
 *   - bit for bit cbx_transform_box's output when cls is GENERAL or not a
 *     class of the map (outside 0 .. rule_class(a): the fallback);
 *   - the table (diag(2,2,2) on [0,1]^3, a translation, a scale, a
 *     permutation, a shear, huge maps beyond 2^509) has the exact image
 *     written out: the output must contain it, with CBX_OK, for every cls.
 *     The diag(2,2,2) case called as IDENTITY is printed: before the hint
 *     was checked it returned [0,1]^3 with CBX_OK (exact image [0,2]^3).
 *   The random inputs are part 2's draws (maps of each class, boxes with
 *   infinite ends, NaN, empty, huge magnitudes, random exponents).
 *
 * A summary line per part; the last line is "N passed, M failed" (cases of
 * all parts); exit status 1 on any failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <time.h>

#include "certbox.h"
#include "exact_util.h"

#define INF HUGE_VAL
#define MAX_FAIL_LOGS 20
#ifndef CORNER_EVERY
#define CORNER_EVERY 8
#endif
#ifndef MOTION_DIRECT_EVERY
#define MOTION_DIRECT_EVERY 8
#endif
#define NCLS 5
#define NS 10 /* sampled s per motion case */

static const char *const cls_name[NCLS] = { "GENERAL", "PERMUTE", "SCALE", "TRANSLATE",
                                            "IDENTITY" };
static long fail_logs;

static double sgn(xu_rng *r) { return xu_rng_sign(r); }

/* ---------------------------------------------------------------------- */
/* Generators                                                             */
/* ---------------------------------------------------------------------- */

/* sgn(r) * (1 + unit) * 2^e and (1 + unit) * 2^e, e in [lo, hi], with the
 * draws in a fixed order (C leaves the order of function arguments to the
 * compiler: gcc takes them right to left on x86-64, left to right on ARM) */
static double mant_pow(xu_rng *r, int lo, int hi)
{
    int e = xu_rng_int(r, lo, hi);
    return ldexp(1.0 + xu_rng_unit(r), e);
}

static double sgn_pow(xu_rng *r, int lo, int hi)
{
    double s = sgn(r);
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
        return sgn_pow(r, -5, 4);
    switch (xu_rng_int(r, 0, 10)) {
    case 0: return sgn(r) * 0x1p509;
    case 1: return sgn(r) * nextafter(0x1p509, INF);     /* just past the fast range */
    case 2: return sgn(r) * 0x1p-1074;
    case 3: return sgn(r) * ldexp((double)((xu_rng_next(r) >> 12) | 1u), -1074);
    case 4: return sgn(r) * DBL_MIN;
    case 5: return sgn(r) * 0x1p1018;
    case 6: return sgn(r) * 1.0;
    case 7: return sgn_pow(r, 400, 600);
    case 8: return sgn_pow(r, -1060, -900);
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
        if (xu_rng_int(r, 0, 9) == 0) return sgn(r) * 0.0;
        return sgn(r) * xu_rng_unit(r) * ldexp(1.0, xu_rng_int(r, -2, 10));
    }
    switch (xu_rng_int(r, 0, 8)) {
    case 0: return sgn(r) * 0.0;
    case 1: return sgn(r) * 0x1p1018;
    case 2: return sgn(r) * nextafter(0x1p1018, INF);   /* out of the domain */
    case 3: return sgn(r) * 0x1p1019;
    case 4: return sgn(r) * DBL_MAX;
    case 5: return sgn(r) * 0x1p-1074;
    case 6: return sgn_pow(r, 900, 1017);
    case 7: return sgn_pow(r, 500, 520);
    default: return xu_gen_signed(r, -1074, 1018);
    }
}

static void zero_map(xu_rng *r, cbx_affine *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) a->m[i][j] = sgn(r) * 0.0;
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
static void gen_map_cls(xu_rng *r, cbx_affine *a, int cls, int g)
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
            a->m[xu_rng_int(r, 0, 2)][3] = g ? sgn(r) * 0x1p-1074 : 1.5;
        break;
    case CBX_CLASS_SCALE:
        for (i = 0; i < 3; i++) {
            int p = xu_rng_int(r, 0, 9);
            a->m[i][i] = p == 0 ? sgn(r) * 0.0 : p == 1 ? 1.0 : p == 2 ? -1.0 : lin_val(r, g);
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
                a->m[i][col[i]] = p < 2 ? sgn(r) : lin_val(r, g);
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
            a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = sgn(r) * INF;
        break;
    }
}

/* The class by an independent rule: count nonzero linear entries. */
static int rule_class(const cbx_affine *a)
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

/* Boxes */
enum { BX_REAL, BX_TINY, BX_POINT, BX_FLAT, BX_BIG, BX_HALF, BX_EMPTY, BX_NAN, BX_RAND,
       BX_FASTR, NBX };
static const char *const bx_name[NBX] = { "realistic", "tiny", "point", "flat", "big",
                                          "half-space", "empty", "NaN", "random-exp",
                                          "fast-range" };

static double big_end(xu_rng *r)
{
    switch (xu_rng_int(r, 0, 8)) {
    case 0: return sgn(r) * 0x1p509;
    case 1: return sgn(r) * nextafter(0x1p509, INF);
    case 2: return sgn(r) * 0x1p1018;
    case 3: return sgn(r) * nextafter(0x1p1018, INF);
    case 4: return sgn(r) * 0x1p1019;
    case 5: return sgn(r) * DBL_MAX;
    case 6: return sgn_pow(r, 490, 509);
    case 7: return sgn_pow(r, 1000, 1017);
    default: return sgn(r) * xu_rng_unit(r) * 64.0;
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

static void gen_box(xu_rng *r, cbx_box *b, int kind)
{
    int j, q;
    for (j = 0; j < 3; j++) {
        double c = sgn(r) * xu_rng_unit(r) * ldexp(1.0, xu_rng_int(r, -4, 8));
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

static int pick_box_kind(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    return p < 45 ? BX_REAL : p < 52 ? BX_TINY : p < 58 ? BX_POINT : p < 64 ? BX_FLAT
         : p < 75 ? BX_BIG : p < 83 ? BX_HALF : p < 88 ? BX_EMPTY : p < 91 ? BX_NAN : BX_RAND;
}

/* ---------------------------------------------------------------------- */
/* Part 1: classification                                                 */
/* ---------------------------------------------------------------------- */

enum {
    C_ID, C_TR, C_SC, C_PE, C_GE,
    M_DIAG_UP, M_DIAG_DN, M_NEG_ONE, M_OFF_TINY, M_OFF_TINY_ZROW, M_PERM_EXTRA,
    M_TR_TINY, M_NEGZERO, M_ZERO_SCALE, M_NAN, M_INF, M_HUGE, NKIND
};
static const char *const kind_name[NKIND] = {
    "identity", "translate", "scale", "permute", "general",
    "diag 1+2^-52", "diag 1-2^-53", "diag -1", "off-diag 2^-1074", "tiny in zero row",
    "permute+tiny", "translation 2^-1074", "all zeros -0.0", "zero scale", "NaN entry",
    "inf entry", "DBL_MAX entries"
};

typedef struct cstats {
    long cases, failed, rule_disagree;
    long kind[NKIND], kind_fail[NKIND];
    long got[NCLS];
} cstats;

/* Builds a map of kind k; returns the class expected by construction. */
static int gen_kind(xu_rng *r, cbx_affine *a, int k)
{
    int g = xu_rng_int(r, 0, 2) == 0, i, j, c;
    switch (k) {
    case C_ID: gen_map_cls(r, a, CBX_CLASS_IDENTITY, g); return CBX_CLASS_IDENTITY;
    case C_TR: gen_map_cls(r, a, CBX_CLASS_TRANSLATE, g); return CBX_CLASS_TRANSLATE;
    case C_SC: gen_map_cls(r, a, CBX_CLASS_SCALE, g); return CBX_CLASS_SCALE;
    case C_PE: gen_map_cls(r, a, CBX_CLASS_PERMUTE, g); return CBX_CLASS_PERMUTE;
    case C_GE:
        gen_map_cls(r, a, CBX_CLASS_GENERAL, g);
        return CBX_CLASS_GENERAL;
    case M_DIAG_UP: case M_DIAG_DN:
        c = xu_rng_int(r, 0, 1) ? CBX_CLASS_IDENTITY : CBX_CLASS_TRANSLATE;
        gen_map_cls(r, a, c, g);
        i = xu_rng_int(r, 0, 2);
        a->m[i][i] = k == M_DIAG_UP ? 1.0 + 0x1p-52 : 1.0 - 0x1p-53;
        return CBX_CLASS_SCALE;
    case M_NEG_ONE:
        gen_map_cls(r, a, xu_rng_int(r, 0, 1) ? CBX_CLASS_IDENTITY : CBX_CLASS_TRANSLATE, g);
        a->m[0][0] = -1.0;
        a->m[1][1] = 1.0;
        a->m[2][2] = 1.0;
        return CBX_CLASS_SCALE;
    case M_OFF_TINY:
        gen_map_cls(r, a, xu_rng_int(r, 0, 1) ? CBX_CLASS_IDENTITY : CBX_CLASS_TRANSLATE, g);
        i = xu_rng_int(r, 0, 2);
        j = (i + xu_rng_int(r, 1, 2)) % 3;
        a->m[i][j] = sgn(r) * 0x1p-1074;
        return CBX_CLASS_GENERAL;
    case M_OFF_TINY_ZROW:
        gen_map_cls(r, a, CBX_CLASS_SCALE, g);
        i = xu_rng_int(r, 0, 2);
        j = (i + xu_rng_int(r, 1, 2)) % 3;
        a->m[i][i] = sgn(r) * 0.0;
        a->m[i][j] = sgn(r) * 0x1p-1074;
        return CBX_CLASS_PERMUTE;
    case M_PERM_EXTRA:
        gen_map_cls(r, a, CBX_CLASS_PERMUTE, g);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                if (a->m[i][j] != 0.0) break;
            if (j < 3) {
                a->m[i][(j + xu_rng_int(r, 1, 2)) % 3] = sgn(r) * 0x1p-1074;
                break;
            }
        }
        return CBX_CLASS_GENERAL;
    case M_TR_TINY:
        gen_map_cls(r, a, CBX_CLASS_IDENTITY, g);
        a->m[xu_rng_int(r, 0, 2)][3] = sgn(r) * 0x1p-1074;
        return CBX_CLASS_TRANSLATE;
    case M_NEGZERO:
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) a->m[i][j] = i == j ? 1.0 : -0.0;
        if (xu_rng_int(r, 0, 1)) {
            a->m[1][1] = -0.0; /* a diagonal -0.0: a zero scale */
            return CBX_CLASS_SCALE;
        }
        return CBX_CLASS_IDENTITY;
    case M_ZERO_SCALE:
        gen_map_cls(r, a, CBX_CLASS_SCALE, g);
        for (i = 0; i < 3; i++)
            if (xu_rng_int(r, 0, 1)) a->m[i][i] = sgn(r) * 0.0;
        if (a->m[0][0] == 1.0 && a->m[1][1] == 1.0 && a->m[2][2] == 1.0) a->m[1][1] = 0.0;
        return CBX_CLASS_SCALE;
    case M_NAN: case M_INF:
        gen_map_cls(r, a, xu_rng_int(r, 0, NCLS - 1), g);
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = k == M_NAN ? NAN : sgn(r) * INF;
        return CBX_CLASS_GENERAL;
    default: /* M_HUGE */
        c = xu_rng_int(r, 0, 1) ? CBX_CLASS_SCALE : CBX_CLASS_PERMUTE;
        gen_map_cls(r, a, c, g);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                if (a->m[i][j] != 0.0 && a->m[i][j] != 1.0) a->m[i][j] = sgn(r) * DBL_MAX;
            a->m[i][3] = sgn(r) * DBL_MAX;
        }
        return c; /* SCALE keeps a diagonal != 1, PERMUTE an off-diagonal nonzero */
    }
}

static void print_map(const char *label, const cbx_affine *a)
{
    int i;
    for (i = 0; i < 3; i++)
        printf("  %s[%d] = {%a, %a, %a | %a}\n", label, i, a->m[i][0], a->m[i][1],
               a->m[i][2], a->m[i][3]);
}

static void run_classify(xu_rng *r, cbx_affine *a, cstats *st, long n)
{
    long c;
    for (c = 0; c < n; c++) {
        int k = (int)(c % NKIND), want = gen_kind(r, a, k), rule = rule_class(a);
        cbx_affine a0 = *a;
        int got = (int)cbx_classify(a);
        st->cases++;
        st->kind[k]++;
        if (got >= 0 && got < NCLS) st->got[got]++;
        if (rule != want) st->rule_disagree++;
        if (got != want || rule != want || memcmp(&a0, a, sizeof a0)) {
            st->failed++;
            st->kind_fail[k]++;
            if (fail_logs++ < MAX_FAIL_LOGS) {
                printf("FAIL classify case %ld (%s): cbx_classify %d, by construction %d, "
                       "by rule %d\n", c, kind_name[k], got, want, rule);
                print_map("m", &a0);
            }
        }
    }
}

/* ---------------------------------------------------------------------- */
/* Part 2: class kernels                                                  */
/* ---------------------------------------------------------------------- */

typedef struct kstats {
    long cases, calls, failed;
    long ends, fin_ends, inf_ends, tighter;
    long contain_fail, looser, status_diff, inf_diff, inplace_diff, input_diff;
    long flag_fail[XU_NFLAGS], gflag_fail[XU_NFLAGS];
    long st[4];
    long axes;                        /* full-row axes with excess, not tiny */
    double sum_ex, max_ex, sum_exg, max_exg;
} kstats;

static void fill_nan(cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++) b->lo[j] = b->hi[j] = NAN;
}

static int same_bits(double p, double q) { return memcmp(&p, &q, sizeof p) == 0; }

static void log_kernel(long id, int cls, int as, const char *why, const cbx_affine *a,
                       const cbx_box *in, const cbx_box *o, const cbx_box *g)
{
    if (fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL kernel case %ld (classify %s, called as %s): %s\n", id, cls_name[cls],
           cls_name[as], why);
    xu_print_case(stdout, a, in);
    if (o) xu_print_box(stdout, "as", o);
    if (g) xu_print_box(stdout, "general", g);
}

static int contain_flags(const xu_verdict *v)
{
    return v->flag[XU_F_CONTAIN] + v->flag[XU_F_CORNER] + v->flag[XU_F_ENDCONT]
           + v->flag[XU_F_ENDCORNER] + v->flag[XU_F_FINITE] + v->flag[XU_F_ENDFIN];
}

static void kernel_case(xu_exact *x, kstats *ks, const cbx_affine *a, const cbx_box *in,
                        int corners, long id)
{
    cbx_affine a0 = *a;
    cbx_box in0 = *in, g, o, ip;
    cbx_status sg, s, s2;
    xu_verdict vg, v;
    int cls = (int)cbx_classify(a), c, i, f, bad = 0;
    char why[200];

    fill_nan(&g);
    sg = cbx_transform_box(a, in, &g);
    if (xu_check_result(x, &a0, &in0, &g, sg, corners, &vg)) {
        for (f = 0; f < XU_NFLAGS; f++) ks[cls].gflag_fail[f] += vg.flag[f];
        log_kernel(id, cls, CBX_CLASS_GENERAL, vg.why, &a0, &in0, (const cbx_box *)0, &g);
        bad = 1;
    }
    ks[cls].cases++;
    if (xu_status_index(sg) >= 0) ks[cls].st[xu_status_index(sg)]++;

    for (c = cls; c >= 0; c--) {
        int nbad = 0;
        kstats *k = &ks[cls];
        fill_nan(&o);
        s = cbx_transform_box_as(a, (cbx_class)c, in, &o);
        k->calls++;
        if (memcmp(&a0, a, sizeof a0) || memcmp(&in0, in, sizeof in0)) {
            k->input_diff++;
            log_kernel(id, cls, c, "the call modified its inputs", &a0, &in0, &o, &g);
            nbad = 1;
        }
        if (xu_check_result(x, &a0, &in0, &o, s, corners, &v)) {
            for (f = 0; f < XU_NFLAGS; f++) k->flag_fail[f] += v.flag[f];
            k->contain_fail += contain_flags(&v);
            if (!nbad) log_kernel(id, cls, c, v.why, &a0, &in0, &o, &g);
            nbad = 1;
        }
        if (s != sg) {
            k->status_diff++;
            snprintf(why, sizeof why, "status %s, cbx_transform_box %s", cbx_status_name(s),
                     cbx_status_name(sg));
            if (!nbad) log_kernel(id, cls, c, why, &a0, &in0, &o, &g);
            nbad = 1;
        }
        for (i = 0; i < 6; i++) {
            int up = i >= 3, j = i % 3;
            double e = up ? o.hi[j] : o.lo[j], eg = up ? g.hi[j] : g.lo[j];
            k->ends++;
            if (isinf(e) || isinf(eg) || e != e || eg != eg) {
                k->inf_ends++;
                if (!same_bits(e, eg)) {
                    k->inf_diff++;
                    snprintf(why, sizeof why, "axis %d %s end %a, general %a (infinite ends must "
                             "be identical)", j, up ? "hi" : "lo", e, eg);
                    if (!nbad) log_kernel(id, cls, c, why, &a0, &in0, &o, &g);
                    nbad = 1;
                }
            } else {
                k->fin_ends++;
                if (up ? e > eg : e < eg) {
                    k->looser++;
                    snprintf(why, sizeof why, "axis %d %s end %a looser than general %a", j,
                             up ? "hi" : "lo", e, eg);
                    if (!nbad) log_kernel(id, cls, c, why, &a0, &in0, &o, &g);
                    nbad = 1;
                } else if (e != eg) {
                    k->tighter++;
                }
            }
        }
        /* in place */
        ip = in0;
        s2 = cbx_transform_box_as(a, (cbx_class)c, &ip, &ip);
        if (s2 != s || memcmp(&ip, &o, sizeof o)) {
            k->inplace_diff++;
            if (!nbad) log_kernel(id, cls, c, "in place (out == in) differs", &a0, &in0, &ip, &o);
            nbad = 1;
        }
        /* excess of the class kernel (own class) and of the general one */
        if (c == cls)
            for (i = 0; i < 3; i++)
                if (v.ax[i].checked && vg.ax[i].checked && !v.ax[i].tiny) {
                    double e1 = v.ax[i].ex_lo > v.ax[i].ex_hi ? v.ax[i].ex_lo : v.ax[i].ex_hi;
                    double e2 = vg.ax[i].ex_lo > vg.ax[i].ex_hi ? vg.ax[i].ex_lo : vg.ax[i].ex_hi;
                    k->axes++;
                    k->sum_ex += v.ax[i].ex_lo + v.ax[i].ex_hi;
                    k->sum_exg += vg.ax[i].ex_lo + vg.ax[i].ex_hi;
                    if (e1 > k->max_ex) k->max_ex = e1;
                    if (e2 > k->max_exg) k->max_exg = e2;
                }
        bad |= nbad;
    }
    if (bad) ks[cls].failed++;
}

/* A case of the class kernels: a map of class cls (realistic, extreme or
 * random exponents over the fast range; a NaN entry in 1 of 50) and a box
 * (fast-range boxes for most random-exponent maps); returns the box kind. */
static int gen_kernel_case(xu_rng *r, cbx_affine *a, cbx_box *in, int cls)
{
    int p = xu_rng_int(r, 0, 9), g = p < 4 ? 0 : p < 8 ? 1 : 2;
    int bk = g == 2 && xu_rng_int(r, 0, 3) ? BX_FASTR : pick_box_kind(r);
    gen_map_cls(r, a, cls, g);
    if (xu_rng_int(r, 0, 49) == 0) a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
    gen_box(r, in, bk);
    return bk;
}

static void run_kernels(xu_rng *r, xu_exact *x, kstats *ks, long n, long *bxk)
{
    long c;
    cbx_affine a;
    cbx_box in;
    for (c = 0; c < n; c++) {
        bxk[gen_kernel_case(r, &a, &in, (int)(c % NCLS))]++;
        kernel_case(x, ks, &a, &in, c % CORNER_EVERY == 0, c);
    }
}

/* ---------------------------------------------------------------------- */
/* Part 3: motion                                                         */
/* ---------------------------------------------------------------------- */

enum { P_GENGEN, P_CLASSES, P_SAME, P_FLIP, P_NAN, P_OOD, P_HALF, P_EMPTY, NPAIR };
static const char *const pair_name[NPAIR] = { "general pair", "class pair", "identical",
                                              "sign-flipped", "NaN", "out-of-domain",
                                              "half-space", "empty" };

typedef struct mstats {
    long cases, failed, kind[NPAIR], st[4];
    long ax_full, ax_none, ax_mixed, ax_infmap;
    long corner_checks, corner_fail, direct_checks, direct_fail;
    long end_checks, end_fail;       /* neither-full ends against the exact inf / sup */
    long union_checks, union_fail, zero_ties;
    long extreme_checks, extreme_fail, tight_fail;
    long status_fail, special_fail, whole_fail, finite_fail, inplace_fail, input_fail;
    long ex_axes;
    double sum_ex, max_ex;
} mstats;

typedef struct mscratch {
    mpz_t V0[8], V1[8], LO, HI, W, Tq, L0, L1, S0, S1, M, G, Sm;
    mpq_t c[3], t, v, w, s, s1, lo, hi;
} mscratch;

static void ms_init(mscratch *m)
{
    int k;
    for (k = 0; k < 8; k++) mpz_inits(m->V0[k], m->V1[k], (mpz_ptr)0);
    mpz_inits(m->LO, m->HI, m->W, m->Tq, m->L0, m->L1, m->S0, m->S1, m->M, m->G, m->Sm,
              (mpz_ptr)0);
    for (k = 0; k < 3; k++) mpq_init(m->c[k]);
    mpq_inits(m->t, m->v, m->w, m->s, m->s1, m->lo, m->hi, (mpq_ptr)0);
}

static void ms_clear(mscratch *m)
{
    int k;
    for (k = 0; k < 8; k++) mpz_clears(m->V0[k], m->V1[k], (mpz_ptr)0);
    mpz_clears(m->LO, m->HI, m->W, m->Tq, m->L0, m->L1, m->S0, m->S1, m->M, m->G, m->Sm,
               (mpz_ptr)0);
    for (k = 0; k < 3; k++) mpq_clear(m->c[k]);
    mpq_clears(m->t, m->v, m->w, m->s, m->s1, m->lo, m->hi, (mpq_ptr)0);
}

/* z = (t + sum_j m_j c_j) * 2^XU_SHIFT at corner c (row i; all finite). */
static void corner_scaled(xu_exact *x, mpz_t z, const cbx_affine *a, const cbx_box *in, int i,
                          unsigned c)
{
    int j;
    xu_scaled_d(x, z, a->m[i][3]);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(x, x->pl, a->m[i][j], (c >> j) & 1u ? in->hi[j] : in->lo[j]);
        mpz_add(z, z, x->pl);
    }
}

/* The interpolated row of M(s), s = p/q, into m->c[0..2], m->t (mpq). */
static void interp_row(mscratch *m, const cbx_affine *a0, const cbx_affine *a1, int i,
                       unsigned long p, unsigned long q)
{
    int j;
    mpq_set_ui(m->s, p, q);
    mpq_canonicalize(m->s);
    mpq_set_ui(m->s1, 1, 1);
    mpq_sub(m->s1, m->s1, m->s);
    for (j = 0; j < 4; j++) {
        mpq_ptr d = j < 3 ? m->c[j] : m->t;
        mpq_set_d(m->v, a0->m[i][j]);
        mpq_mul(d, m->v, m->s1);
        mpq_set_d(m->v, a1->m[i][j]);
        mpq_mul(m->v, m->v, m->s);
        mpq_add(d, d, m->v);
    }
}

/* Extended vertex value of the interpolated row (mpq in m->v): upper = 0,
 * the inf over the real points of the box; returns 0 when it is -inf
 * (+inf for upper = 1), i.e. a needed box end is infinite. */
static int interp_vertex(mscratch *m, const cbx_box *in, int upper)
{
    int j;
    mpq_set(m->v, m->t);
    for (j = 0; j < 3; j++) {
        int sg = mpq_sgn(m->c[j]);
        double e;
        if (sg == 0) continue;
        e = (sg > 0) == (upper != 0) ? in->hi[j] : in->lo[j];
        if (isinf(e)) return 0;
        mpq_set_d(m->w, e);
        mpq_mul(m->w, m->w, m->c[j]);
        mpq_add(m->v, m->v, m->w);
    }
    return 1;
}

static void log_motion(long id, const char *kind, const char *why, const cbx_affine *a0,
                       const cbx_affine *a1, const cbx_box *in, const cbx_box *o)
{
    if (fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL motion case %ld (%s): %s\n", id, kind, why);
    print_map("m0", a0);
    print_map("m1", a1);
    xu_print_box(stdout, "in", in);
    if (o) xu_print_box(stdout, "out", o);
}

/* the union end: bitwise one of the two, with the value of the min / max
 * (a tie between 0.0 and -0.0 may take either) */
static int union_ok(double e, double e0, double e1, int upper, long *ties)
{
    double want = upper ? (e0 >= e1 ? e0 : e1) : (e0 <= e1 ? e0 : e1);
    if (e0 == e1 && !same_bits(e0, e1)) (*ties)++;
    return (same_bits(e, e0) || same_bits(e, e1)) && e == want;
}

static void motion_case(xu_exact *x, mscratch *m, mstats *st, const cbx_affine *a0,
                        const cbx_affine *a1, const cbx_box *in, int kind, int direct, long id,
                        const unsigned long sp[NS], const unsigned long sq[NS])
{
    cbx_affine c0 = *a0, c1 = *a1;
    cbx_box cin = *in, o, b0, b1, ip;
    cbx_status s, s2, want;
    int i, j, bad = 0;
    char why[240];
    const char *kn = pair_name[kind];

    st->cases++;
    st->kind[kind]++;
    fill_nan(&o);
    s = cbx_motion_box(a0, a1, in, &o);
    if (memcmp(&c0, a0, sizeof c0) || memcmp(&c1, a1, sizeof c1) || memcmp(&cin, in, sizeof cin)) {
        st->input_fail++;
        log_motion(id, kn, "the call modified its inputs", &c0, &c1, &cin, &o);
        bad = 1;
    }
    (void)cbx_transform_box(&c0, &cin, &b0);
    (void)cbx_transform_box(&c1, &cin, &b1);

    if (xu_has_nan(&c0, &cin) || xu_has_nan(&c1, &cin)) {
        want = CBX_EINVAL;
        for (i = 0; i < 3; i++)
            if (!(isinf(o.lo[i]) && o.lo[i] < 0 && isinf(o.hi[i]) && o.hi[i] > 0)) {
                st->special_fail++;
                if (!bad) log_motion(id, kn, "EINVAL: out is not [-inf,+inf]^3", &c0, &c1, &cin, &o);
                bad = 1;
                break;
            }
    } else if (xu_is_empty(&cin)) {
        want = CBX_EMPTY;
        for (i = 0; i < 3; i++)
            if (!(isinf(o.lo[i]) && o.lo[i] > 0 && isinf(o.hi[i]) && o.hi[i] < 0)) {
                st->special_fail++;
                if (!bad) log_motion(id, kn, "EMPTY: out is not lo=+inf, hi=-inf", &c0, &c1, &cin, &o);
                bad = 1;
                break;
            }
    } else {
        int mixed = 0;
        for (i = 0; i < 3; i++) {
            int f0 = xu_row_in_domain(&c0, &cin, i), f1 = xu_row_in_domain(&c1, &cin, i);
            double lo = o.lo[i], hi = o.hi[i];
            if (f0 != f1) mixed = 1;
            if (f0 != f1 || !xu_map_row_finite(&c0, i) || !xu_map_row_finite(&c1, i)) {
                if (f0 != f1) st->ax_mixed++;
                else st->ax_infmap++;
                if (!(isinf(lo) && lo < 0 && isinf(hi) && hi > 0)) {
                    st->whole_fail++;
                    snprintf(why, sizeof why, "axis %d: %s but not [-inf,+inf]", i,
                             f0 != f1 ? "one row full, the other not" : "infinite map entry");
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
                continue;
            }
            /* not mixed: the union of the two general outputs */
            st->union_checks++;
            if (!union_ok(lo, b0.lo[i], b1.lo[i], 0, &st->zero_ties)
                || !union_ok(hi, b0.hi[i], b1.hi[i], 1, &st->zero_ties)) {
                st->union_fail++;
                snprintf(why, sizeof why, "axis %d: [%a, %a] is not the union of [%a, %a] and "
                         "[%a, %a]", i, lo, hi, b0.lo[i], b0.hi[i], b1.lo[i], b1.hi[i]);
                if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                bad = 1;
            }
            if (f0 && f1) {
                unsigned c;
                int k, cf = 0, ef = 0;
                st->ax_full++;
                if (!isfinite(lo) || !isfinite(hi) || lo > hi) {
                    st->finite_fail++;
                    snprintf(why, sizeof why, "axis %d: both rows full but out = [%a, %a]", i, lo, hi);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                    continue;
                }
                for (c = 0; c < 8; c++) {
                    corner_scaled(x, m->V0[c], &c0, &cin, i, c);
                    corner_scaled(x, m->V1[c], &c1, &cin, i, c);
                }
                xu_scaled_d(x, m->LO, lo);
                xu_scaled_d(x, m->HI, hi);
                xu_row_bounds(x, &c0, &cin, i);
                mpz_set(m->L0, x->L); mpz_set(m->S0, x->S); mpz_set(m->M, x->H);
                xu_row_bounds(x, &c1, &cin, i);
                mpz_set(m->L1, x->L); mpz_set(m->S1, x->S);
                /* m->L0 = min(L0, L1) (the extreme over s in {0, 1}), m->M = max */
                if (mpz_cmp(m->L1, m->L0) < 0) mpz_set(m->L0, m->L1);
                if (mpz_cmp(x->H, m->M) > 0) mpz_set(m->M, x->H);
                for (k = 0; k < NS; k++) {
                    unsigned long p = sp[k], q = sq[k];
                    for (c = 0; c < 8; c++) {
                        /* W = q (M(s) c)_i = (q - p) V0 + p V1 */
                        mpz_mul_ui(m->W, m->V0[c], q - p);
                        mpz_addmul_ui(m->W, m->V1[c], p);
                        st->corner_checks++;
                        mpz_mul_ui(m->Tq, m->LO, q);
                        if (mpz_cmp(m->Tq, m->W) > 0) cf++;
                        mpz_mul_ui(m->Tq, m->HI, q);
                        if (mpz_cmp(m->W, m->Tq) > 0) cf++;
                        /* the extreme over s: never beyond the one over {0, 1} */
                        st->extreme_checks++;
                        mpz_mul_ui(m->Tq, m->L0, q);
                        if (mpz_cmp(m->W, m->Tq) < 0) ef++;
                        mpz_mul_ui(m->Tq, m->M, q);
                        if (mpz_cmp(m->W, m->Tq) > 0) ef++;
                    }
                }
                if (cf) {
                    st->corner_fail += cf;
                    snprintf(why, sizeof why, "axis %d: %d corner images (M(s) c) outside "
                             "[%a, %a]", i, cf, lo, hi);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
                if (ef) {
                    st->extreme_fail += ef;
                    snprintf(why, sizeof why, "axis %d: an extreme over sampled s beyond the one "
                             "over s in {0,1} (oracle)", i);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
                /* tightness against the exact extreme over s */
                mpz_set(m->Sm, mpz_cmp(m->S0, m->S1) >= 0 ? m->S0 : m->S1);
                mpz_sub(m->G, m->L0, m->LO);
                mpz_set(x->S, m->Sm);
                {
                    double u1 = xu_units(x, m->G, m->Sm), u2;
                    int t1, t2;
                    mpz_set(x->L, m->L0);
                    t1 = xu_lo_within_proven(x, lo);
                    mpz_sub(m->G, m->HI, m->M);
                    u2 = xu_units(x, m->G, m->Sm);
                    mpz_set(x->H, m->M);
                    mpz_set(x->S, m->Sm);
                    t2 = xu_hi_within_proven(x, hi);
                    if (!t1 || !t2) {
                        st->tight_fail++;
                        snprintf(why, sizeof why, "axis %d: beyond 12 u max(S0,S1) + 2^-1065 of "
                                 "the exact extreme over s (units %.3g, %.3g)", i, u1, u2);
                        if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                        bad = 1;
                    }
                    if (!xu_scale_tiny(m->Sm)) {
                        st->ex_axes++;
                        st->sum_ex += u1 + u2;
                        if (u1 > st->max_ex) st->max_ex = u1;
                        if (u2 > st->max_ex) st->max_ex = u2;
                    }
                }
                if (direct) { /* M(s) entry by entry, mpq, every corner */
                    int df = 0;
                    mpq_set_d(m->lo, lo);
                    mpq_set_d(m->hi, hi);
                    for (k = 0; k < NS; k++) {
                        interp_row(m, &c0, &c1, i, sp[k], sq[k]);
                        for (c = 0; c < 8; c++) {
                            mpq_set(m->v, m->t);
                            for (j = 0; j < 3; j++) {
                                mpq_set_d(m->w, (c >> j) & 1u ? cin.hi[j] : cin.lo[j]);
                                mpq_mul(m->w, m->w, m->c[j]);
                                mpq_add(m->v, m->v, m->w);
                            }
                            st->direct_checks++;
                            if (mpq_cmp(m->lo, m->v) > 0 || mpq_cmp(m->v, m->hi) > 0) df++;
                        }
                    }
                    if (df) {
                        st->direct_fail += df;
                        snprintf(why, sizeof why, "axis %d: %d corner images outside (mpq, M(s) "
                                 "entry by entry)", i, df);
                        if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                        bad = 1;
                    }
                }
            } else { /* neither row full, finite map rows */
                int k, up, ef = 0;
                st->ax_none++;
                for (k = 0; k < NS; k++) {
                    interp_row(m, &c0, &c1, i, sp[k], sq[k]);
                    for (up = 0; up < 2; up++) {
                        double e = up ? hi : lo;
                        int bounded;
                        if (isinf(e) && (up ? e > 0 : e < 0)) continue; /* no claim */
                        st->end_checks++;
                        bounded = interp_vertex(m, &cin, up);
                        if (!isfinite(e) || !bounded) {
                            ef++;
                            continue;
                        }
                        mpq_set_d(m->w, e);
                        if (up ? mpq_cmp(m->w, m->v) < 0 : mpq_cmp(m->w, m->v) > 0) ef++;
                    }
                }
                if (ef) {
                    st->end_fail += ef;
                    snprintf(why, sizeof why, "axis %d (neither row full): %d end checks fail "
                             "against the exact inf/sup of M(s) over the box", i, ef);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
            }
        }
        want = xu_expected_status(&c0, &cin) == CBX_OK && xu_expected_status(&c1, &cin) == CBX_OK
               && !mixed ? CBX_OK : CBX_ERANGE;
    }
    if (s != want) {
        st->status_fail++;
        snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(s), cbx_status_name(want));
        if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
        bad = 1;
    }
    if (xu_status_index(s) >= 0) st->st[xu_status_index(s)]++;
    ip = cin;
    s2 = cbx_motion_box(&c0, &c1, &ip, &ip);
    if (s2 != s || memcmp(&ip, &o, sizeof o)) {
        st->inplace_fail++;
        if (!bad) log_motion(id, kn, "in place (out == in) differs", &c0, &c1, &cin, &ip);
        bad = 1;
    }
    if (bad) st->failed++;
}

static void make_ood(xu_rng *r, cbx_affine *a)
{
    int i = xu_rng_int(r, 0, 2);
    if (xu_rng_int(r, 0, 1)) a->m[i][3] = sgn(r) * (xu_rng_int(r, 0, 1) ? 0x1p1019 : DBL_MAX);
    else {
        double v = sgn_pow(r, 1000, 1023); /* then the column: gcc's order, made explicit */
        a->m[i][xu_rng_int(r, 0, 2)] = v;
    }
}

static void run_motion(xu_rng *r, xu_exact *x, mstats *st, long n)
{
    mscratch m;
    long c;
    cbx_affine a0, a1;
    cbx_box in;
    unsigned long sp[NS] = { 0, 1, 1, 1, 2 }, sq[NS] = { 1, 1, 2, 3, 7 };
    int i, j, k;
    ms_init(&m);
    for (c = 0; c < n; c++) {
        int kind = (int)(c % NPAIR), g = xu_rng_int(r, 0, 3) == 0;
        for (k = 5; k < NS; k++) {
            sq[k] = (unsigned long)xu_rng_int(r, 2, 1 << 20);
            sp[k] = (unsigned long)xu_rng_int(r, 1, (int)sq[k] - 1);
        }
        gen_map_cls(r, &a0, xu_rng_int(r, 0, NCLS - 1), g);
        gen_map_cls(r, &a1, xu_rng_int(r, 0, NCLS - 1), g);
        gen_box(r, &in, g ? pick_box_kind(r) : BX_REAL);
        switch (kind) {
        case P_GENGEN:
            gen_map_cls(r, &a0, CBX_CLASS_GENERAL, 0);
            gen_map_cls(r, &a1, CBX_CLASS_GENERAL, 0);
            gen_box(r, &in, xu_rng_int(r, 0, 3) ? BX_REAL : BX_FLAT);
            break;
        case P_CLASSES:
            gen_map_cls(r, &a0, xu_rng_int(r, 0, NCLS - 1), g);
            gen_map_cls(r, &a1, xu_rng_int(r, 0, NCLS - 1), g);
            break;
        case P_SAME:
            a1 = a0;
            break;
        case P_FLIP: /* entries change sign (cross 0) inside the interval */
            a1 = a0;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++)
                    if (xu_rng_int(r, 0, 1)) a1.m[i][j] = -a1.m[i][j];
            if (xu_rng_int(r, 0, 1)) gen_box(r, &in, BX_HALF);
            break;
        case P_NAN:
            if (xu_rng_int(r, 0, 2) == 0) gen_box(r, &in, BX_NAN);
            else (xu_rng_int(r, 0, 1) ? &a0 : &a1)->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
            if (xu_rng_int(r, 0, 3) == 0) gen_box(r, &in, BX_EMPTY); /* NaN wins over empty */
            break;
        case P_OOD:
            if (xu_rng_int(r, 0, 2)) make_ood(r, xu_rng_int(r, 0, 1) ? &a0 : &a1);
            else gen_box(r, &in, BX_BIG);
            if (xu_rng_int(r, 0, 3) == 0) make_ood(r, &a0), make_ood(r, &a1);
            if (xu_rng_int(r, 0, 5) == 0)
                (xu_rng_int(r, 0, 1) ? &a0 : &a1)->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = sgn(r) * INF;
            break;
        case P_HALF:
            gen_box(r, &in, BX_HALF);
            if (xu_rng_int(r, 0, 4) == 0)
                (xu_rng_int(r, 0, 1) ? &a0 : &a1)->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = sgn(r) * INF;
            break;
        default: /* P_EMPTY */
            gen_box(r, &in, BX_EMPTY);
            break;
        }
        motion_case(x, &m, st, &a0, &a1, &in, kind, c % MOTION_DIRECT_EVERY == 0, c, sp, sq);
    }
    ms_clear(&m);
}

/* ---------------------------------------------------------------------- */
/* Part 4: misuse, cbx_transform_box_as with any cls                      */
/* ---------------------------------------------------------------------- */

/* The cls of cbx_transform_box_as is a hint (certbox.h): a class the map is
 * not in (larger than its class) or a value outside the enum runs the
 * general kernel.  Whether v is a class of the map is decided here by
 * rule_class (part 1 checks it against cbx_classify). */
static int general_expected(int v, const cbx_affine *a)
{
    return v == CBX_CLASS_GENERAL || !(v >= 0 && v <= rule_class(a));
}

typedef struct ustats {
    long cases, failed, calls;
    long map_cls[NCLS];                   /* random maps by rule_class       */
    long v_calls[XU_NCLS_VALUES];         /* calls per cls value             */
    long v_general[XU_NCLS_VALUES];       /* of which GENERAL or not a class */
    long v_exact_fail[XU_NCLS_VALUES], v_bits_fail[XU_NCLS_VALUES];
    long v_status_fail[XU_NCLS_VALUES], v_input_fail[XU_NCLS_VALUES];
    long table_calls, table_img_fail;     /* the table: image written out    */
} ustats;

static void log_misuse(long id, const char *what, int v, const char *why, const cbx_affine *a,
                       const cbx_box *in, const cbx_box *o, const cbx_box *g)
{
    char nb[16];
    if (fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL misuse %s %ld (map of class %s, called as %s): %s\n", what, id,
           cls_name[rule_class(a)], xu_cls_str(v, nb), why);
    xu_print_case(stdout, a, in);
    xu_print_box(stdout, "as", o);
    xu_print_box(stdout, "cbx_transform_box", g);
}

/* One call cbx_transform_box_as(a, xu_cls_values[vi], in, o), judged by
 * every exact check of exact_util (mpq corners when corners != 0), against
 * cbx_transform_box's status sg, and bit for bit against its output g when
 * the general kernel is expected; inputs unchanged.  Returns 1 on failure. */
static int misuse_call(xu_exact *x, ustats *st, int vi, const cbx_affine *a, const cbx_box *in,
                       const cbx_box *g, cbx_status sg, int corners, const char *what, long id,
                       cbx_box *o)
{
    int v = xu_cls_values[vi], bad = 0;
    cbx_affine a0 = *a;
    cbx_box in0 = *in;
    cbx_status s;
    xu_verdict vd;
    char why[200];
    fill_nan(o);
    s = cbx_transform_box_as(a, (cbx_class)v, in, o);
    st->calls++;
    st->v_calls[vi]++;
    if (memcmp(&a0, a, sizeof a0) || memcmp(&in0, in, sizeof in0)) {
        st->v_input_fail[vi]++;
        log_misuse(id, what, v, "the call modified its inputs", &a0, &in0, o, g);
        return 1;
    }
    if (xu_check_result(x, a, in, o, s, corners, &vd)) {
        st->v_exact_fail[vi]++;
        log_misuse(id, what, v, vd.why, a, in, o, g);
        bad = 1;
    }
    if (s != sg) {
        st->v_status_fail[vi]++;
        snprintf(why, sizeof why, "status %s, cbx_transform_box %s", cbx_status_name(s),
                 cbx_status_name(sg));
        if (!bad) log_misuse(id, what, v, why, a, in, o, g);
        bad = 1;
    }
    if (general_expected(v, a)) {
        st->v_general[vi]++;
        if (memcmp(o, g, sizeof *o)) {
            st->v_bits_fail[vi]++;
            if (!bad) log_misuse(id, what, v, "not bit for bit cbx_transform_box's output (the "
                                 "general kernel is expected)", a, in, o, g);
            bad = 1;
        }
    }
    return bad;
}

/* Every cls value on one input; o[vi] gets each call's output, *sg
 * cbx_transform_box's status (every call must return it). */
static int misuse_case(xu_exact *x, ustats *st, const cbx_affine *a, const cbx_box *in,
                       int corners, const char *what, long id, cbx_box o[XU_NCLS_VALUES],
                       cbx_status *sg)
{
    cbx_box g;
    int vi, bad = 0;
    fill_nan(&g);
    *sg = cbx_transform_box(a, in, &g);
    for (vi = 0; vi < XU_NCLS_VALUES; vi++)
        bad |= misuse_call(x, st, vi, a, in, &g, *sg, corners, what, id, &o[vi]);
    return bad;
}

/* Maps and boxes whose exact image is known and written out (all values
 * small integers, or powers of 2: the comparisons below are exact), each
 * with every cls value: the output must contain img with CBX_OK.  Before
 * the hint was checked, IDENTITY on diag(2,2,2) returned [0,1]^3 with
 * CBX_OK (the identity kernel copies the box). */
typedef struct misuse_row { const char *name; cbx_affine a; cbx_box in, img; } misuse_row;
static const misuse_row misuse_table[] = {
    { "diag(2,2,2) on [0,1]^3",
      XU_MAT(XU_ROW(2, 0, 0, 0), XU_ROW(0, 2, 0, 0), XU_ROW(0, 0, 2, 0)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(0, 2, 0, 2, 0, 2) },
    { "translation (1,2,3) on [0,1]^3",
      XU_MAT(XU_ROW(1, 0, 0, 1), XU_ROW(0, 1, 0, 2), XU_ROW(0, 0, 1, 3)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(1, 2, 2, 3, 3, 4) },
    { "diag(-1,3,1/2) + (0,0,1)",
      XU_MAT(XU_ROW(-1, 0, 0, 0), XU_ROW(0, 3, 0, 0), XU_ROW(0, 0, 0.5, 1)),
      XU_BOX(0, 1, -1, 2, 2, 4), XU_BOX(-1, 0, -3, 6, 2, 3) },
    { "permutation (y, -z, 2x)",
      XU_MAT(XU_ROW(0, 1, 0, 0), XU_ROW(0, 0, -1, 0), XU_ROW(2, 0, 0, 0)),
      XU_BOX(0, 1, 2, 3, 4, 5), XU_BOX(2, 3, -5, -4, 0, 2) },
    { "shear x + y",
      XU_MAT(XU_ROW(1, 1, 0, 0), XU_ROW(0, 1, 0, 0), XU_ROW(0, 0, 1, 0)),
      XU_BOX(0, 1, 2, 3, 4, 5), XU_BOX(2, 4, 2, 3, 4, 5) },
    { "huge diag(2^600, 2^600, 1) + (0, 0, 2^1000)",
      XU_MAT(XU_ROW(0x1p600, 0, 0, 0), XU_ROW(0, 0x1p600, 0, 0), XU_ROW(0, 0, 1, 0x1p1000)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(0, 0x1p600, 0, 0x1p600, 0x1p1000, 0x1p1000) },
    { "huge permutation (2^1000 z, y, x)",
      XU_MAT(XU_ROW(0, 0, 0x1p1000, 0), XU_ROW(0, 1, 0, 0), XU_ROW(1, 0, 0, 0)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(0, 0x1p1000, 0, 1, 0, 1) },
};
#define N_MISUSE_TABLE ((int)(sizeof misuse_table / sizeof misuse_table[0]))

static int contains(const cbx_box *o, const cbx_box *img)
{
    int j;
    for (j = 0; j < 3; j++)
        if (!(o->lo[j] <= img->lo[j] && o->hi[j] >= img->hi[j])) return 0;
    return 1;
}

static void run_misuse(xu_rng *r, xu_exact *x, ustats *st, long n, long *bxk)
{
    cbx_box o[XU_NCLS_VALUES], in;
    cbx_affine a;
    cbx_status sg;
    long c;
    int k, vi;
    char nb[16];
    for (k = 0; k < N_MISUSE_TABLE; k++) {
        const misuse_row *t = &misuse_table[k];
        int bad = misuse_case(x, st, &t->a, &t->in, 1, "table", k, o, &sg);
        for (vi = 0; vi < XU_NCLS_VALUES; vi++) { /* every call returned sg */
            st->table_calls++;
            if (sg != CBX_OK || !contains(&o[vi], &t->img)) {
                st->table_img_fail++;
                if (!bad) log_misuse(k, "table", xu_cls_values[vi], "the exact image (written "
                                     "out) is not contained, or the status is not CBX_OK",
                                     &t->a, &t->in, &o[vi], &t->img);
                bad = 1;
            }
        }
        if (k == 0) /* the case of the old bug, shown */
            printf("  %s as %s: [%a, %a] x [%a, %a] x [%a, %a] (%s [0,2]^3)\n", t->name,
                   xu_cls_str(CBX_CLASS_IDENTITY, nb), o[CBX_CLASS_IDENTITY].lo[0],
                   o[CBX_CLASS_IDENTITY].hi[0], o[CBX_CLASS_IDENTITY].lo[1],
                   o[CBX_CLASS_IDENTITY].hi[1], o[CBX_CLASS_IDENTITY].lo[2],
                   o[CBX_CLASS_IDENTITY].hi[2],
                   contains(&o[CBX_CLASS_IDENTITY], &t->img) ? "contains" : "DOES NOT contain");
        st->cases++;
        if (bad) st->failed++;
    }
    for (c = 0; c < n; c++) {
        bxk[gen_kernel_case(r, &a, &in, (int)(c % NCLS))]++;
        st->map_cls[rule_class(&a)]++;
        st->cases++;
        if (misuse_case(x, st, &a, &in, c % CORNER_EVERY == 0, "case", c, o, &sg)) st->failed++;
    }
}

/* ---------------------------------------------------------------------- */
/* Driver                                                                 */
/* ---------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 200000, "[N] [seed]");
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N] [seed]");
    static cstats cs;
    static kstats ks[NCLS];
    static mstats ms;
    static ustats us;
    static long bxk[NBX], bxu[NBX];
    xu_rng rng;
    xu_exact x;
    cbx_affine a;
    long cases, failed, kfailed = 0, kcases = 0;
    int k, f;
    clock_t t0 = clock(), t1, t2, t3;

    xu_init(&x);
    printf("-- test_classes: cbx_classify, cbx_transform_box_as, cbx_motion_box against GMP, "
           "%ld cases per part, seed %llu --\n", n, (unsigned long long)seed);

    /* part 1 */
    rng.s = UINT64_C(0x243f6a8885a308d3) ^ seed;
    run_classify(&rng, &a, &cs, n);
    printf("part 1 classify: %ld maps, %ld failed (construction vs rule disagreements: %ld)\n",
           cs.cases, cs.failed, cs.rule_disagree);
    printf("  classify returned:");
    for (k = NCLS - 1; k >= 0; k--) printf(" %s %ld", cls_name[k], cs.got[k]);
    printf("\n  kinds (maps / failed):");
    for (k = 0; k < NKIND; k++) printf("%s %s %ld/%ld", k ? "," : "", kind_name[k], cs.kind[k],
                                       cs.kind_fail[k]);
    printf("\n");

    /* part 2 */
    t1 = clock();
    rng.s = UINT64_C(0x13198a2e03707344) ^ seed;
    run_kernels(&rng, &x, ks, n, bxk);
    printf("part 2 class kernels (cbx_transform_box_as with the class of cbx_classify and "
           "every larger class, vs cbx_transform_box and GMP; mpq corners every %d-th case):\n",
           CORNER_EVERY);
    printf("  boxes:");
    for (k = 0; k < NBX; k++) printf("%s %s %ld", k ? "," : "", bx_name[k], bxk[k]);
    printf("\n");
    for (k = NCLS - 1; k >= 0; k--) {
        kstats *s = &ks[k];
        double na = s->axes ? (double)(2 * s->axes) : 1.0;
        printf("  %-9s %7ld cases (OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld), %7ld calls, "
               "%8ld ends (%ld finite, %ld infinite/special), containment failures %ld, "
               "looser than general %ld, strictly tighter %ld, status differs %ld, infinite "
               "ends differ %ld, in-place differs %ld, inputs changed %ld; failed cases %ld\n",
               cls_name[k], s->cases, s->st[0], s->st[1], s->st[2], s->st[3], s->calls, s->ends,
               s->fin_ends, s->inf_ends, s->contain_fail, s->looser, s->tighter, s->status_diff,
               s->inf_diff, s->inplace_diff, s->input_diff, s->failed);
        printf("  %-9s excess (units of u*S + 2^-1074, full-row axes with u*S >= 2^%d eta, "
               "%ld axes): class kernel mean %.4f max %.4f; general kernel mean %.4f max %.4f\n",
               "", XU_TINY, s->axes, s->sum_ex / na, s->max_ex, s->sum_exg / na, s->max_exg);
        for (f = 0; f < XU_NFLAGS; f++)
            if (s->flag_fail[f] || s->gflag_fail[f])
                printf("  %-9s exact check %s failed: class kernel %ld, general kernel %ld\n", "",
                       xu_flag_name[f], s->flag_fail[f], s->gflag_fail[f]);
        kfailed += s->failed;
        kcases += s->cases;
    }
    printf("part 2 class kernels: %ld cases, %ld failed\n", kcases, kfailed);

    /* part 3 */
    t2 = clock();
    rng.s = UINT64_C(0xa4093822299f31d0) ^ seed;
    run_motion(&rng, &x, &ms, n);
    printf("part 3 motion (s in {0, 1, 1/2, 1/3, 2/7} + 5 random p/q; M(s) entry by entry in mpq "
           "every %d-th case):\n", MOTION_DIRECT_EVERY);
    printf("  pairs:");
    for (k = 0; k < NPAIR; k++) printf("%s %s %ld", k ? "," : "", pair_name[k], ms.kind[k]);
    printf("\n  statuses: OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld; status failures %ld, special "
           "outputs %ld, in place %ld, inputs changed %ld\n", ms.st[0], ms.st[1], ms.st[2],
           ms.st[3], ms.status_fail, ms.special_fail, ms.inplace_fail, ms.input_fail);
    printf("  axes: both full %ld, neither full %ld, mixed %ld, infinite map row %ld; "
           "[-inf,+inf] required and not given: %ld; full axis not finite: %ld\n", ms.ax_full,
           ms.ax_none, ms.ax_mixed, ms.ax_infmap, ms.whole_fail, ms.finite_fail);
    printf("  corner checks (s, corner) %ld, failed %ld; direct mpq M(s) %ld, failed %ld; "
           "half-space end checks %ld, failed %ld\n", ms.corner_checks, ms.corner_fail,
           ms.direct_checks, ms.direct_fail, ms.end_checks, ms.end_fail);
    printf("  union of the two cbx_transform_box outputs: %ld axes, %ld not bit-identical "
           "(0/-0 ties seen %ld); extreme over sampled s == extreme over {0,1}: %ld checks, %ld "
           "failed; tightness 12 u max(S0,S1) + 2^-1065 failed %ld\n", ms.union_checks,
           ms.union_fail, ms.zero_ties, ms.extreme_checks, ms.extreme_fail, ms.tight_fail);
    printf("  excess vs the exact extreme over s (units of u*max(S0,S1) + 2^-1074, %ld axes): "
           "mean %.4f max %.4f\n", ms.ex_axes, ms.ex_axes ? ms.sum_ex / (2.0 * (double)ms.ex_axes) : 0.0,
           ms.max_ex);
    printf("part 3 motion: %ld cases, %ld failed\n", ms.cases, ms.failed);

    /* part 4 */
    t3 = clock();
    rng.s = UINT64_C(0x452821e638d01377) ^ seed;
    printf("part 4 misuse (cbx_transform_box_as with each of the %d cls values below: the "
           "five classes, so also classes the map is not in, and ints outside the enum; a "
           "table of %d maps with the exact image written out, then N/4 = %ld random cases as "
           "in part 2):\n", XU_NCLS_VALUES, N_MISUSE_TABLE, n / 4);
    run_misuse(&rng, &x, &us, n / 4, bxu);
    printf("  maps (by rule_class):");
    for (k = NCLS - 1; k >= 0; k--) printf(" %s %ld", cls_name[k], us.map_cls[k]);
    printf("\n  boxes:");
    for (k = 0; k < NBX; k++) printf("%s %s %ld", k ? "," : "", bx_name[k], bxu[k]);
    printf("\n  table: %ld calls, exact image not contained (or status not OK) %ld\n",
           us.table_calls, us.table_img_fail);
    for (k = 0; k < XU_NCLS_VALUES; k++) {
        char nb[16];
        printf("  cls %-9s %7ld calls, %7ld of them GENERAL or not a class of the map (general "
               "kernel expected): not bit for bit cbx_transform_box %ld; exact checks failed "
               "%ld, status differs %ld, inputs changed %ld\n",
               xu_cls_str(xu_cls_values[k], nb), us.v_calls[k], us.v_general[k],
               us.v_bits_fail[k], us.v_exact_fail[k], us.v_status_fail[k], us.v_input_fail[k]);
    }
    printf("part 4 misuse: %ld cases (%ld calls), %ld failed\n", us.cases, us.calls, us.failed);

    printf("  CPU time: part 1 %.2f s, part 2 %.2f s, part 3 %.2f s, part 4 %.2f s\n",
           (double)(t1 - t0) / CLOCKS_PER_SEC, (double)(t2 - t1) / CLOCKS_PER_SEC,
           (double)(t3 - t2) / CLOCKS_PER_SEC, (double)(clock() - t3) / CLOCKS_PER_SEC);
    xu_clear(&x);
    cases = cs.cases + kcases + ms.cases + us.cases;
    failed = cs.failed + kfailed + ms.failed + us.failed;
    printf("%ld passed, %ld failed\n", cases - failed, failed);
    return failed ? 1 : 0;
}
