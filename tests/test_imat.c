/*
 * test_imat [N] [M] [seed]: the interval-matrix functions of certbox.h,
 * cbx_transform_box_imat and cbx_imat_compose (binary64), against exact
 * arithmetic (GMP).  Defaults: N = 200000 boxes, M = 50000 compositions,
 * seed 1.
 *
 * The promise (certbox.h, specs/cbx_imat.h): one output coordinate is
 *     [tl, th] + sum_j [ml_j, mh_j] [l_j, h_j]
 * (transform: row i of the matrix and the box; compose: row i of a and
 * column j of b, with a's translation for j = 3 and [0, 0] otherwise).  Its
 * exact ends are L = tl + sum_j min of the four corner products
 * ml_j l_j, ml_j h_j, mh_j l_j, mh_j h_j, and H = th + sum_j the max; its
 * scale S = max(|tl|, |th|) + sum_j the largest |corner product|.  The
 * coordinate is "fast" when every interval is ordered and finite, the
 * linear entries and box ends (compose: b's entries) within [-2^509, 2^509]
 * and the translation within [-2^1018, 2^1018].  Status and output:
 *   NaN anywhere, or a matrix entry with hi < lo  -> CBX_EINVAL, the whole
 *     space (compose: every entry [-inf, +inf]);
 *   transform, a box axis with no real point (hi < lo, lo = +inf or
 *     hi = -inf)                                   -> CBX_EMPTY, every axis
 *     lo = +inf, hi = -inf;
 *   otherwise each fast coordinate finite, L >= lo and H <= hi, and each
 *     end within 12 u S + 2^-1065 of L / H (u = 2^-53); each other one
 *     exactly [-inf, +inf]; CBX_OK iff every coordinate is fast, else
 *     CBX_ERANGE.
 *
 * Inputs: interval entries of every kind (points lo == hi, intervals one
 * to three ulps wide, wide ones, intervals straddling 0, signed zeros in
 * either order, subnormals), magnitudes in exponent windows from the
 * subnormals to the fast limits (2^509 exactly, 2^1018 exactly for the
 * translation), translations cancelling the linear part, intervals around
 * random rotations (the chains of a glTF scene); ~20% of the cases pushed
 * out of the fast range (2^509 + ulp, 2^510, 1e300, DBL_MAX, infinite
 * ends, [+inf, +inf] entries, 2^1018 + ulp translations), ~2% with a NaN,
 * ~2% with an inverted entry, ~4% (transform) with an empty box axis,
 * and 10% of the boxes with point matrices (lo == hi), also run through
 * cbx_transform_box for comparison (information only: the two widen
 * differently, no bit identity is required).
 *
 * Checks (each exact; the fixed-point path scales every value by 2^2148,
 * so that every product of two doubles is an integer (mpz); the mpq path
 * uses rationals):
 *   status    the status equals the one decided here from the rules above;
 *   written   no output field is left at the NaN pre-fill;
 *   special   CBX_EINVAL / CBX_EMPTY outputs exactly as specified;
 *   whole     a coordinate outside the fast range is exactly [-inf, +inf];
 *   finite    a fast coordinate is finite;
 *   contain   lo <= L and H <= hi (fixed point, exact);
 *   tight     L - lo and hi - H at most 12 u S + 2^-1065 (exact);
 *   cross     (every 8th case) L, H recomputed as rationals (mpq, the four
 *             corners of each term) equal the fixed-point ones;
 *   points    (every 8th case) a random real point: t in [tl, th], m_j in
 *             [ml_j, mh_j], x_j in [l_j, h_j] (exact rationals: an end or
 *             a random fraction between), t + sum m_j x_j (mpq) in [lo, hi];
 *   product   (compose, every other case) random real matrices A in a and
 *             B in b (exact rationals): every entry of A B (A's translation
 *             added in column 3) lies in the entry of the result;
 *   alias     (transform) out == in gives the same status and bits;
 *   input     the inputs are unchanged by the call.
 * Teeth: the checker run on doctored results must fail: a fast end moved
 * to the first double past the exact end (inside the image), an end moved
 * to the first double beyond 12 u S + 2^-1065, a whole coordinate made
 * finite, a status flipped, a compose entry of point matrices moved past
 * the exact product.  Excess over the exact end is reported in units of
 * u S + 2^-1074 (ends with u S < 2^-1000 apart, as the other suites do).
 * The first failures are printed with their inputs in hex; the last line
 * is "N passed, M failed" (cases); exit status 1 on any failure.
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
#define SB 0x1p509      /* linear entries and box ends */
#define RT 0x1p1018     /* translations */
#define MAX_FAIL_LOGS 20
#define DEEP_EVERY 8    /* cross and points on every 8th case */
#define TEETH_MAX 60    /* doctored results per kind of tooth */

/* ---------------------------------------------------------------------- */
/* The checks and their tallies                                           */
/* ---------------------------------------------------------------------- */

enum { C_STATUS, C_WRITTEN, C_SPECIAL, C_WHOLE, C_FINITE, C_CONTAIN, C_TIGHT, C_CROSS,
       C_POINTS, C_PRODUCT, C_ALIAS, C_INPUT, NC };
static const char *const c_name[NC] = { "status", "written", "special", "whole", "finite",
                                        "contain", "tight", "cross", "points", "product",
                                        "alias", "input" };
static const char *const c_unit[NC] = { "cases", "cases", "cases", "coords", "coords",
                                        "coords", "coords", "coords", "points", "entries",
                                        "cases", "cases" };

typedef struct tally {
    long n[NC], f[NC];
    char why[300];              /* the first failure of the current case */
} tally;

/* Count one check; 1 if it failed (the first reason is kept). */
static int tick(tally *t, int c, int ok, const char *why, int coord)
{
    t->n[c]++;
    if (ok) return 0;
    t->f[c]++;
    if (t->why[0] == '\0')
        snprintf(t->why, sizeof t->why, "%s (coordinate %d): %s", c_name[c], coord, why);
    return 1;
}

/* Excess statistics, in units of u S + eta. */
typedef struct exstat {
    long ends, tiny;
    double max, sum, max_tiny;
} exstat;

static void ex_add(exstat *e, double v, int tiny)
{
    if (tiny) {
        e->tiny++;
        if (v > e->max_tiny) e->max_tiny = v;
        return;
    }
    e->ends++;
    e->sum += v;
    if (v > e->max) e->max = v;
}

/* ---------------------------------------------------------------------- */
/* One coordinate: inputs, rules, exact ends                              */
/* ---------------------------------------------------------------------- */

typedef struct row {
    double ml[3], mh[3];        /* linear entries */
    double tl, th;              /* translation */
    double l[3], h[3];          /* box (compose: a column of b) */
} row;

static row trow(const cbx_imat *a, int i, const cbx_box *b)
{
    row r;
    int j;
    for (j = 0; j < 3; j++) {
        r.ml[j] = a->lo[i][j];
        r.mh[j] = a->hi[i][j];
        r.l[j] = b->lo[j];
        r.h[j] = b->hi[j];
    }
    r.tl = a->lo[i][3];
    r.th = a->hi[i][3];
    return r;
}

static row crow(const cbx_imat *a, const cbx_imat *b, int i, int j)
{
    row r;
    int k;
    for (k = 0; k < 3; k++) {
        r.ml[k] = a->lo[i][k];
        r.mh[k] = a->hi[i][k];
        r.l[k] = b->lo[k][j];
        r.h[k] = b->hi[k][j];
    }
    r.tl = j == 3 ? a->lo[i][3] : 0.0;
    r.th = j == 3 ? a->hi[i][3] : 0.0;
    return r;
}

/* The rules, written from the text above (IEEE comparisons). */
static int iv_bad(double l, double h) { return isnan(l) || isnan(h) || h < l; }
static int iv_fast(double l, double h, double b)
{
    return isfinite(l) && isfinite(h) && -b <= l && l <= h && h <= b;
}
static int row_fast(const row *r)
{
    int j, f = iv_fast(r->tl, r->th, RT);
    for (j = 0; j < 3; j++)
        f = f && iv_fast(r->ml[j], r->mh[j], SB) && iv_fast(r->l[j], r->h[j], SB);
    return f;
}
static int imat_bad(const cbx_imat *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (iv_bad(a->lo[i][j], a->hi[i][j])) return 1;
    return 0;
}
static int box_nan(const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        if (isnan(b->lo[j]) || isnan(b->hi[j])) return 1;
    return 0;
}
static int box_empty(const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        if (b->hi[j] < b->lo[j] || b->lo[j] == INF || b->hi[j] == -INF) return 1;
    return 0;
}

typedef struct ctx {
    xu_exact x;                 /* exact_util's scratch */
    mpz_t L, H, S, p[4], g, g2, tol, z;
    mpq_t q, qa, qb, qs, qmin, qmax, qt;
    xu_rng rng;
} ctx;

/* Exact ends and scale of one fast coordinate, scaled by 2^2148:
 * k->L, k->H, k->S. */
static void row_exact(ctx *k, const row *r)
{
    int j, c;
    xu_scaled_d(&k->x, k->L, r->tl);
    xu_scaled_d(&k->x, k->H, r->th);
    mpz_abs(k->S, k->L);
    mpz_abs(k->z, k->H);
    if (mpz_cmp(k->z, k->S) > 0) mpz_set(k->S, k->z);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(&k->x, k->p[0], r->ml[j], r->l[j]);
        xu_scaled_mul(&k->x, k->p[1], r->ml[j], r->h[j]);
        xu_scaled_mul(&k->x, k->p[2], r->mh[j], r->l[j]);
        xu_scaled_mul(&k->x, k->p[3], r->mh[j], r->h[j]);
        int mn = 0, mx = 0, mg = 0;
        for (c = 1; c < 4; c++) {
            if (mpz_cmp(k->p[c], k->p[mn]) < 0) mn = c;
            if (mpz_cmp(k->p[c], k->p[mx]) > 0) mx = c;
            if (mpz_cmpabs(k->p[c], k->p[mg]) > 0) mg = c;
        }
        mpz_add(k->L, k->L, k->p[mn]);
        mpz_add(k->H, k->H, k->p[mx]);
        mpz_abs(k->z, k->p[mg]);
        mpz_add(k->S, k->S, k->z);
    }
}

/* k->tol = (12 u S + 2^-1065) 2^(2148 + 53) = 12 S + 2^1136 (S scaled). */
static void tol53(ctx *k)
{
    mpz_mul_ui(k->tol, k->S, 12);
    mpz_set_ui(k->z, 1);
    mpz_mul_2exp(k->z, k->z, 2148 + 53 - 1065);
    mpz_add(k->tol, k->tol, k->z);
}

/* The first double above (up) or below (!up) the value v / 2^(2148 + 53),
 * i.e. strictly beyond it; v is within the double range. */
static double past(ctx *k, const mpz_t v, int up)
{
    long e;
    double d = mpz_get_d_2exp(&e, v);
    d = ldexp(d, (int)(e - 2148 - 53));
    for (;;) { /* move until strictly beyond, then back while still beyond */
        xu_scaled_sh(k->z, d, 2148 + 53);
        int c = mpz_cmp(k->z, v);
        if (up ? c > 0 : c < 0) break;
        d = nextafter(d, up ? INF : -INF);
    }
    for (;;) {
        double n = nextafter(d, up ? -INF : INF);
        xu_scaled_sh(k->z, n, 2148 + 53);
        int c = mpz_cmp(k->z, v);
        if (!(up ? c > 0 : c < 0)) break;
        d = n;
    }
    return d;
}

/* A random exact rational in [lo, hi] (lo, hi finite): an end, or a
 * random fraction of the way. */
static void rand_q(ctx *k, mpq_t q, double lo, double hi)
{
    int p = xu_rng_int(&k->rng, 0, 5);
    if (p == 0) { mpq_set_d(q, lo); return; }
    if (p == 1) { mpq_set_d(q, hi); return; }
    uint64_t f = xu_rng_next(&k->rng) >> 24;      /* 40 bits */
    mpq_set_d(k->qa, lo);
    mpq_set_d(q, hi);
    mpq_sub(q, q, k->qa);
    mpz_set_ui(mpq_numref(k->qt), (unsigned long)(f >> 20));
    mpz_mul_2exp(mpq_numref(k->qt), mpq_numref(k->qt), 20);
    mpz_add_ui(mpq_numref(k->qt), mpq_numref(k->qt), (unsigned long)(f & 0xfffff));
    mpz_set_ui(mpq_denref(k->qt), 1);
    mpz_mul_2exp(mpq_denref(k->qt), mpq_denref(k->qt), 40);
    mpq_canonicalize(k->qt);
    mpq_mul(q, q, k->qt);
    mpq_add(q, q, k->qa);
}

/* v outside [lo, hi] (an infinite end holds everything on its side) */
static int q_outside(ctx *k, const mpq_t v, double lo, double hi)
{
    if (isfinite(lo)) { mpq_set_d(k->qt, lo); if (mpq_cmp(v, k->qt) < 0) return 1; }
    if (isfinite(hi)) { mpq_set_d(k->qt, hi); if (mpq_cmp(v, k->qt) > 0) return 1; }
    return 0;
}

/* Check one output coordinate [lo, hi] of row r.  deep: also cross and
 * points.  ex: excess statistics (NULL: none).  Returns the failures. */
static int check_coord(ctx *k, tally *t, exstat *ex, const row *r, double lo, double hi,
                       int coord, int deep)
{
    char why[200];
    int f = 0, j, c;
    if (!row_fast(r)) {
        snprintf(why, sizeof why, "outside the fast range but [%a, %a]", lo, hi);
        return tick(t, C_WHOLE, lo == -INF && hi == INF, why, coord);
    }
    snprintf(why, sizeof why, "fast but [%a, %a]", lo, hi);
    if (tick(t, C_FINITE, isfinite(lo) && isfinite(hi), why, coord)) return 1;
    row_exact(k, r);
    /* g = L - lo, g2 = hi - H (scaled): both >= 0 */
    xu_scaled_d(&k->x, k->z, lo);
    mpz_sub(k->g, k->L, k->z);
    xu_scaled_d(&k->x, k->z, hi);
    mpz_sub(k->g2, k->z, k->H);
    snprintf(why, sizeof why, "lo %a > L or hi %a < H", lo, hi);
    f += tick(t, C_CONTAIN, mpz_sgn(k->g) >= 0 && mpz_sgn(k->g2) >= 0, why, coord);
    tol53(k);
    mpz_mul_2exp(k->z, k->g, 53);
    int ok = mpz_cmp(k->z, k->tol) <= 0;
    mpz_mul_2exp(k->z, k->g2, 53);
    ok = ok && mpz_cmp(k->z, k->tol) <= 0;
    snprintf(why, sizeof why, "[%a, %a] beyond 12 u S + 2^-1065 of the exact ends", lo, hi);
    f += tick(t, C_TIGHT, ok, why, coord);
    if (ex) {
        int tiny = xu_scale_tiny(k->S);
        ex_add(ex, xu_units(&k->x, k->g, k->S), tiny);
        ex_add(ex, xu_units(&k->x, k->g2, k->S), tiny);
    }
    if (!deep) return f;
    /* cross: the corners as rationals */
    mpq_set_d(k->qmin, r->tl);
    mpq_set_d(k->qmax, r->th);
    for (j = 0; j < 3; j++) {
        for (c = 0; c < 4; c++) {
            mpq_set_d(k->qa, c & 2 ? r->mh[j] : r->ml[j]);
            mpq_set_d(k->qb, c & 1 ? r->h[j] : r->l[j]);
            mpq_mul(k->qa, k->qa, k->qb);
            if (c == 0 || mpq_cmp(k->qa, k->q) < 0) mpq_set(k->q, k->qa);
            if (c == 0 || mpq_cmp(k->qa, k->qs) > 0) mpq_set(k->qs, k->qa);
        }
        mpq_add(k->qmin, k->qmin, k->q);
        mpq_add(k->qmax, k->qmax, k->qs);
    }
    xu_scaled_to_q(k->q, k->L);
    xu_scaled_to_q(k->qs, k->H);
    f += tick(t, C_CROSS, mpq_equal(k->q, k->qmin) && mpq_equal(k->qs, k->qmax),
              "the mpq corners disagree with the fixed-point L, H", coord);
    /* points: one random real point of every interval */
    rand_q(k, k->qs, r->tl, r->th);
    for (j = 0; j < 3; j++) {
        rand_q(k, k->q, r->ml[j], r->mh[j]);
        rand_q(k, k->qb, r->l[j], r->h[j]);
        mpq_mul(k->q, k->q, k->qb);
        mpq_add(k->qs, k->qs, k->q);
    }
    snprintf(why, sizeof why, "a real point of the image, %.17g, outside [%a, %a]",
             mpq_get_d(k->qs), lo, hi);
    f += tick(t, C_POINTS, !q_outside(k, k->qs, lo, hi), why, coord);
    return f;
}

/* ---------------------------------------------------------------------- */
/* Checking a whole call                                                  */
/* ---------------------------------------------------------------------- */

static int is_nan_bits(double v) { return isnan(v); }

/* The checks of one cbx_transform_box_imat result. */
static int check_transform(ctx *k, tally *t, exstat *ex, const cbx_imat *a, const cbx_box *in,
                           const cbx_box *out, cbx_status got, int deep, cbx_status *expected)
{
    int f = 0, i, unset = 0, nfast = 0;
    char why[200];
    for (i = 0; i < 3; i++) unset |= is_nan_bits(out->lo[i]) || is_nan_bits(out->hi[i]);
    f += tick(t, C_WRITTEN, !unset, "an output field left at the NaN pre-fill", -1);
    if (imat_bad(a) || box_nan(in)) {
        *expected = CBX_EINVAL;
        int ok = 1;
        for (i = 0; i < 3; i++) ok = ok && out->lo[i] == -INF && out->hi[i] == INF;
        f += tick(t, C_SPECIAL, ok, "EINVAL but not the whole space", -1);
    } else if (box_empty(in)) {
        *expected = CBX_EMPTY;
        int ok = 1;
        for (i = 0; i < 3; i++) ok = ok && out->lo[i] == INF && out->hi[i] == -INF;
        f += tick(t, C_SPECIAL, ok, "EMPTY but not lo = +inf, hi = -inf", -1);
    } else {
        for (i = 0; i < 3; i++) {
            row r = trow(a, i, in);
            nfast += row_fast(&r);
            f += check_coord(k, t, ex, &r, out->lo[i], out->hi[i], i, deep);
        }
        *expected = nfast == 3 ? CBX_OK : CBX_ERANGE;
    }
    snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(got), cbx_status_name(*expected));
    f += tick(t, C_STATUS, got == *expected, why, -1);
    return f;
}

/* The checks of one cbx_imat_compose result. */
static int check_compose(ctx *k, tally *t, exstat *ex, const cbx_imat *a, const cbx_imat *b,
                         const cbx_imat *out, cbx_status got, int deep, cbx_status *expected)
{
    int f = 0, i, j, unset = 0, nfast = 0;
    char why[200];
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) unset |= is_nan_bits(out->lo[i][j]) || is_nan_bits(out->hi[i][j]);
    f += tick(t, C_WRITTEN, !unset, "an output field left at the NaN pre-fill", -1);
    if (imat_bad(a) || imat_bad(b)) {
        *expected = CBX_EINVAL;
        int ok = 1;
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) ok = ok && out->lo[i][j] == -INF && out->hi[i][j] == INF;
        f += tick(t, C_SPECIAL, ok, "EINVAL but not every entry [-inf, +inf]", -1);
    } else {
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) {
                row r = crow(a, b, i, j);
                nfast += row_fast(&r);
                f += check_coord(k, t, ex, &r, out->lo[i][j], out->hi[i][j], 4 * i + j, deep);
            }
        *expected = nfast == 12 ? CBX_OK : CBX_ERANGE;
    }
    snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(got), cbx_status_name(*expected));
    f += tick(t, C_STATUS, got == *expected, why, -1);
    return f;
}

/* A real number in [lo, hi] (0 if there is none: lo = +inf or hi = -inf;
 * the caller skips those). */
static void real_in(ctx *k, mpq_t q, double lo, double hi)
{
    double a = lo, b = hi;
    if (a == -INF) a = isfinite(b) ? (b < -1e300 ? b : (b > 0 ? -b : b) - 1.0) : -1e300;
    if (b == INF) b = a > 1e300 ? a : (a < 0 ? -a : a) + 1.0;
    if (!(a <= b) || !isfinite(a) || !isfinite(b)) { mpq_set_ui(q, 0, 1); return; }
    rand_q(k, q, a, b);
}

static int has_real(const cbx_imat *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (a->lo[i][j] == INF || a->hi[i][j] == -INF) return 0;
    return 1;
}

/* product: random real A in a, B in b; every entry of A B in out. */
static int check_product(ctx *k, tally *t, const cbx_imat *a, const cbx_imat *b, const cbx_imat *out,
                         mpq_t A[3][4], mpq_t B[3][4])
{
    int i, j, m, f = 0;
    char why[200];
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            real_in(k, A[i][j], a->lo[i][j], a->hi[i][j]);
            real_in(k, B[i][j], b->lo[i][j], b->hi[i][j]);
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            if (j == 3) mpq_set(k->qs, A[i][3]); else mpq_set_ui(k->qs, 0, 1);
            for (m = 0; m < 3; m++) {
                mpq_mul(k->q, A[i][m], B[m][j]);
                mpq_add(k->qs, k->qs, k->q);
            }
            snprintf(why, sizeof why, "(A B) = %.17g outside [%a, %a]", mpq_get_d(k->qs),
                     out->lo[i][j], out->hi[i][j]);
            f += tick(t, C_PRODUCT, !q_outside(k, k->qs, out->lo[i][j], out->hi[i][j]), why, 4 * i + j);
        }
    return f;
}

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
static void gen_rot(xu_rng *r, cbx_imat *a, int with_t)
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
static void gen_imat(xu_rng *r, cbx_imat *a, int ttop)
{
    int i, j, emin, emax;
    if (xu_rng_int(r, 0, 9) == 0) {
        gen_rot(r, a, 1);
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

static void gen_box(xu_rng *r, cbx_box *b)
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
static void cancel_t(xu_rng *r, cbx_imat *a, const cbx_box *b, int i)
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
static void make_empty(xu_rng *r, cbx_box *b)
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
static int perturb(xu_rng *r, cbx_imat *a, cbx_box *b, cbx_imat *b2)
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

static void print_imat(const char *name, const cbx_imat *a)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        printf("  %s[%d] =", name, i);
        for (j = 0; j < 4; j++) printf(" [%a, %a]%s", a->lo[i][j], a->hi[i][j], j == 2 ? " |" : "");
        printf("\n");
    }
}

static void print_box(const char *name, const cbx_box *b)
{
    int j;
    printf("  %s =", name);
    for (j = 0; j < 3; j++) printf(" [%a, %a]", b->lo[j], b->hi[j]);
    printf("\n");
}

static void print_tally(const tally *t)
{
    int c;
    for (c = 0; c < NC; c++)
        if (t->n[c])
            printf("  check %-8s %10ld %-8s checked, %ld failed\n", c_name[c], t->n[c], c_unit[c], t->f[c]);
}

static void print_ex(const char *what, const exstat *e)
{
    printf("  excess over the exact ends (units of u S + 2^-1074; proven bound 12 u S + 2^-1065):\n"
           "    %s: %ld ends with u S >= 2^-1000: max %.3f, mean %.3f; %ld ends at a tinier scale: max %.3g\n",
           what, e->ends, e->max, e->ends ? e->sum / (double)e->ends : 0.0, e->tiny, e->max_tiny);
}

static long checks_of(const tally *t, long *failed)
{
    long n = 0;
    int c;
    for (c = 0; c < NC; c++) {
        n += t->n[c];
        *failed += t->f[c];
    }
    return n;
}

/* ---------------------------------------------------------------------- */
/* Teeth: doctored results must be caught                                 */
/* ---------------------------------------------------------------------- */

enum { T_INSIDE, T_LOOSE, T_WHOLE, T_STATUS, T_PRODUCT, NT };
static const char *const t_name[NT] = { "end inside the image", "end beyond the bound",
                                        "whole coord finite", "status flipped", "compose product" };
static long teeth_n[NT], teeth_caught[NT];

static void tooth(int kind, int caught)
{
    teeth_n[kind]++;
    teeth_caught[kind] += caught != 0;
}

/* Doctor one coordinate [lo, hi] of a fast row and a checker that sees it:
 * moved inside the exact image, or beyond the proven bound. */
static void teeth_coord(ctx *k, const row *r, double *lo, double *hi, int which)
{
    row_exact(k, r);
    tol53(k);
    if (which == 0) { /* first double above L / below H */
        mpz_mul_2exp(k->g, k->L, 53);
        *lo = past(k, k->g, 1);
    } else if (which == 1) {
        mpz_mul_2exp(k->g, k->H, 53);
        *hi = past(k, k->g, 0);
    } else if (which == 2) { /* first double below L - tol / above H + tol */
        mpz_mul_2exp(k->g, k->L, 53);
        mpz_sub(k->g, k->g, k->tol);
        *lo = past(k, k->g, 0);
    } else {
        mpz_mul_2exp(k->g, k->H, 53);
        mpz_add(k->g, k->g, k->tol);
        *hi = past(k, k->g, 1);
    }
}

static void teeth_transform(ctx *k, const cbx_imat *a, const cbx_box *in, const cbx_box *out,
                            cbx_status got)
{
    tally scratch;
    cbx_status e;
    cbx_box d;
    int i, w;
    for (i = 0; i < 3; i++) {
        row r = trow(a, i, in);
        if (row_fast(&r)) {
            for (w = 0; w < 4; w++) {
                int kind = w < 2 ? T_INSIDE : T_LOOSE;
                if (teeth_n[kind] >= TEETH_MAX) continue;
                d = *out;
                teeth_coord(k, &r, &d.lo[i], &d.hi[i], w);
                memset(&scratch, 0, sizeof scratch);
                tooth(kind, check_transform(k, &scratch, NULL, a, in, &d, got, 0, &e));
            }
        } else if (teeth_n[T_WHOLE] < TEETH_MAX) {
            d = *out;
            d.lo[i] = 0.0;
            d.hi[i] = 0.0;
            memset(&scratch, 0, sizeof scratch);
            tooth(T_WHOLE, check_transform(k, &scratch, NULL, a, in, &d, got, 0, &e));
        }
    }
    if (teeth_n[T_STATUS] < TEETH_MAX && (got == CBX_OK || got == CBX_ERANGE)) {
        memset(&scratch, 0, sizeof scratch);
        tooth(T_STATUS, check_transform(k, &scratch, NULL, a, in, out,
                                        got == CBX_OK ? CBX_ERANGE : CBX_OK, 0, &e));
    }
}

/* Point matrices a, b: the product A B is one matrix; an entry moved to
 * the first double past it must fail the product check. */
static void teeth_product(ctx *k, mpq_t A[3][4], mpq_t B[3][4])
{
    cbx_imat a, b, o;
    tally scratch;
    int i, j, m;
    gen_rot(&k->rng, &a, 1);
    gen_rot(&k->rng, &b, 1);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            a.hi[i][j] = a.lo[i][j];
            b.hi[i][j] = b.lo[i][j];
        }
    cbx_imat_compose(&a, &b, &o);
    i = xu_rng_int(&k->rng, 0, 2);
    j = xu_rng_int(&k->rng, 0, 3);
    row r = crow(&a, &b, i, j);
    m = xu_rng_int(&k->rng, 0, 1);
    teeth_coord(k, &r, &o.lo[i][j], &o.hi[i][j], m);
    memset(&scratch, 0, sizeof scratch);
    tooth(T_PRODUCT, check_product(k, &scratch, &a, &b, &o, A, B));
}

/* ---------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    const char *usage = "[N boxes] [M compositions] [seed]";
    long n = (long)xu_arg_num(argc, argv, 1, 200000, usage);
    long m = (long)xu_arg_num(argc, argv, 2, 50000, usage);
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 3, 1, usage);
    static ctx k;
    static tally tt, tc;
    static exstat ext, exc, ex_pt_imat, ex_pt_aff;
    long c, logs = 0, failed_cases = 0, st_seen[2][4], pushed = 0, pt_ratio_n = 0;
    long fast_coords[2] = { 0, 0 }, whole_coords[2] = { 0, 0 };
    long pt_axes = 0, pt_wider = 0, pt_equal = 0, pt_narrower = 0;
    double pt_ratio_max = 0.0, pt_ratio_sum = 0.0;
    mpq_t A[3][4], B[3][4];
    int i, j;
    clock_t t0 = clock();

    memset(st_seen, 0, sizeof st_seen);
    xu_init(&k.x);
    mpz_inits(k.L, k.H, k.S, k.p[0], k.p[1], k.p[2], k.p[3], k.g, k.g2, k.tol, k.z, (mpz_ptr)0);
    mpq_inits(k.q, k.qa, k.qb, k.qs, k.qmin, k.qmax, k.qt, (mpq_ptr)0);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            mpq_init(A[i][j]);
            mpq_init(B[i][j]);
        }
    k.rng.s = UINT64_C(0x510e527fade682d1) ^ seed;
    printf("-- test_imat: cbx_transform_box_imat and cbx_imat_compose against exact arithmetic "
           "(GMP), seed %llu --\n", (unsigned long long)seed);

    /* ---- boxes ---- */
    for (c = 0; c < n; c++) {
        cbx_imat a, a0;
        cbx_box in, in0, out, io;
        cbx_status got, got2, exp;
        int deep = c % DEEP_EVERY == 0, point = 0, f;
        xu_rng *r = &k.rng;
        gen_imat(r, &a, 1018);
        gen_box(r, &in);
        if (xu_rng_int(r, 0, 9) == 0) { /* a point matrix, in range */
            point = 1;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++) a.hi[i][j] = a.lo[i][j];
        }
        for (i = 0; i < 3; i++)
            if (xu_rng_int(r, 0, 9) == 0) cancel_t(r, &a, &in, i);
        if (point) {
            for (i = 0; i < 3; i++) a.hi[i][3] = a.lo[i][3];
        } else {
            pushed += perturb(r, &a, &in, NULL);
            if (xu_rng_int(r, 0, 99) < 4) make_empty(r, &in);
        }
        a0 = a;
        in0 = in;
        for (j = 0; j < 3; j++) out.lo[j] = out.hi[j] = NAN;
        got = cbx_transform_box_imat(&a, &in, &out);
        memset(tt.why, 0, sizeof tt.why);
        f = check_transform(&k, &tt, &ext, &a0, &in0, &out, got, deep, &exp);
        st_seen[0][xu_status_index(exp)]++;
        if (exp == CBX_OK || exp == CBX_ERANGE)
            for (i = 0; i < 3; i++) {
                row rr = trow(&a0, i, &in0);
                if (row_fast(&rr)) fast_coords[0]++; else whole_coords[0]++;
            }
        f += tick(&tt, C_INPUT, memcmp(&a, &a0, sizeof a) == 0 && memcmp(&in, &in0, sizeof in) == 0,
                  "an input changed", -1);
        io = in0;
        got2 = cbx_transform_box_imat(&a0, &io, &io);
        f += tick(&tt, C_ALIAS, got2 == got && memcmp(&io, &out, sizeof io) == 0,
                  "out == in differs from out != in", -1);
        if (f) {
            failed_cases++;
            if (logs++ < MAX_FAIL_LOGS) {
                printf("FAIL box case %ld: %s (status %s, expected %s)\n", c, tt.why,
                       cbx_status_name(got), cbx_status_name(exp));
                print_imat("a", &a0);
                print_box("in", &in0);
                print_box("out", &out);
            }
        }
        teeth_transform(&k, &a0, &in0, &out, got);
        /* point matrices: the same map through cbx_transform_box */
        if (point && got == CBX_OK) {
            cbx_affine aff;
            cbx_box o2;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++) aff.m[i][j] = a0.lo[i][j];
            if (cbx_transform_box(&aff, &in0, &o2) == CBX_OK)
                for (i = 0; i < 3; i++) {
                    row rr = trow(&a0, i, &in0);
                    row_exact(&k, &rr);
                    int tiny = xu_scale_tiny(k.S);
                    double e1, e2;
                    xu_scaled_d(&k.x, k.z, out.lo[i]);
                    mpz_sub(k.g, k.L, k.z);
                    e1 = xu_units(&k.x, k.g, k.S);
                    ex_add(&ex_pt_imat, e1, tiny);
                    xu_scaled_d(&k.x, k.z, o2.lo[i]);
                    mpz_sub(k.g2, k.L, k.z);
                    e2 = xu_units(&k.x, k.g2, k.S);
                    ex_add(&ex_pt_aff, e2, tiny);
                    /* widths: (imat hi - imat lo) vs (affine hi - affine lo), exact */
                    xu_scaled_d(&k.x, k.g, out.hi[i]);
                    xu_scaled_d(&k.x, k.z, out.lo[i]);
                    mpz_sub(k.g, k.g, k.z);
                    xu_scaled_d(&k.x, k.g2, o2.hi[i]);
                    xu_scaled_d(&k.x, k.z, o2.lo[i]);
                    mpz_sub(k.g2, k.g2, k.z);
                    int cw = mpz_cmp(k.g, k.g2);
                    pt_axes++;
                    if (cw > 0) pt_wider++; else if (cw == 0) pt_equal++; else pt_narrower++;
                    /* excess of the width over the exact width H - L, imat / affine */
                    mpz_sub(k.z, k.H, k.L);
                    mpz_sub(k.g, k.g, k.z);
                    mpz_sub(k.g2, k.g2, k.z);
                    if (mpz_sgn(k.g2) > 0 && !tiny) {
                        long ea, eb;
                        double fa = mpz_get_d_2exp(&ea, k.g), fb = mpz_get_d_2exp(&eb, k.g2);
                        double ratio = mpz_sgn(k.g) > 0 ? ldexp(fa / fb, (int)(ea - eb)) : 0.0;
                        pt_ratio_sum += ratio;
                        pt_ratio_n++;
                        if (ratio > pt_ratio_max) pt_ratio_max = ratio;
                    }
                }
        }
    }
    double t_boxes = (double)(clock() - t0) / CLOCKS_PER_SEC;

    /* ---- compositions ---- */
    long products = 0;
    for (c = 0; c < m; c++) {
        cbx_imat a, b, a0, b0, out;
        cbx_status got, exp;
        int deep = c % DEEP_EVERY == 0, f;
        xu_rng *r = &k.rng;
        gen_imat(r, &a, 1018);
        gen_imat(r, &b, 509);      /* b's columns are the "box": within 2^509 */
        pushed += perturb(r, &a, NULL, &b);
        a0 = a;
        b0 = b;
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) out.lo[i][j] = out.hi[i][j] = NAN;
        got = cbx_imat_compose(&a, &b, &out);
        memset(tc.why, 0, sizeof tc.why);
        f = check_compose(&k, &tc, &exc, &a0, &b0, &out, got, deep, &exp);
        st_seen[1][xu_status_index(exp)]++;
        if (exp != CBX_EINVAL)
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++) {
                    row rr = crow(&a0, &b0, i, j);
                    if (row_fast(&rr)) fast_coords[1]++; else whole_coords[1]++;
                }
        f += tick(&tc, C_INPUT, memcmp(&a, &a0, sizeof a) == 0 && memcmp(&b, &b0, sizeof b) == 0,
                  "an input changed", -1);
        if (c % 2 == 0 && exp != CBX_EINVAL && has_real(&a0) && has_real(&b0)) {
            f += check_product(&k, &tc, &a0, &b0, &out, A, B);
            products++;
        }
        if (f) {
            failed_cases++;
            if (logs++ < MAX_FAIL_LOGS) {
                printf("FAIL compose case %ld: %s (status %s, expected %s)\n", c, tc.why,
                       cbx_status_name(got), cbx_status_name(exp));
                print_imat("a", &a0);
                print_imat("b", &b0);
                print_imat("out", &out);
            }
        }
        if (teeth_n[T_PRODUCT] < TEETH_MAX) teeth_product(&k, A, B);
    }
    double t_all = (double)(clock() - t0) / CLOCKS_PER_SEC;

    /* ---- report ---- */
    long nfail_checks = 0, nchecks = checks_of(&tt, &nfail_checks) + checks_of(&tc, &nfail_checks);
    long tn = 0, tcaught = 0;
    printf("\nboxes: %ld cases (%ld with point matrices taken through cbx_transform_box too); "
           "expected OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n",
           n, pt_axes / 3, st_seen[0][0], st_seen[0][1], st_seen[0][2], st_seen[0][3]);
    printf("  axes in the fast range %ld, outside (whole line) %ld\n", fast_coords[0], whole_coords[0]);
    print_tally(&tt);
    print_ex("cbx_transform_box_imat", &ext);
    printf("\ncompositions: %ld cases; expected OK %ld, EINVAL %ld, ERANGE %ld; %ld with the product check\n",
           m, st_seen[1][0], st_seen[1][2], st_seen[1][3], products);
    printf("  entries in the fast range %ld, outside (whole line) %ld\n", fast_coords[1], whole_coords[1]);
    print_tally(&tc);
    print_ex("cbx_imat_compose", &exc);
    printf("\n%ld cases (boxes and compositions) had an input pushed out of the fast range\n", pushed);
    printf("\npoint matrices (lo == hi), for information (no bit identity required): %ld axes\n", pt_axes);
    printf("  lower-end excess, units of u S + 2^-1074: cbx_transform_box_imat max %.3f mean %.3f, "
           "cbx_transform_box max %.3f mean %.3f\n",
           ex_pt_imat.max, ex_pt_imat.ends ? ex_pt_imat.sum / (double)ex_pt_imat.ends : 0.0,
           ex_pt_aff.max, ex_pt_aff.ends ? ex_pt_aff.sum / (double)ex_pt_aff.ends : 0.0);
    printf("  width of the imat box vs the cbx_transform_box box: wider on %ld axes, equal %ld, narrower %ld; "
           "(width - exact width) ratio imat / affine: max %.3f, mean %.3f\n",
           pt_wider, pt_equal, pt_narrower, pt_ratio_max,
           pt_ratio_n ? pt_ratio_sum / (double)pt_ratio_n : 0.0);
    printf("\nteeth (doctored results given to the checker):");
    for (i = 0; i < NT; i++) {
        printf(" %s %ld/%ld%s", t_name[i], teeth_caught[i], teeth_n[i], i + 1 < NT ? "," : "\n");
        tn += teeth_n[i];
        tcaught += teeth_caught[i];
        if (teeth_n[i] == 0) {
            printf("FAIL teeth: no doctored result of kind '%s' was made\n", t_name[i]);
            failed_cases++;
        }
    }
    if (tcaught != tn) {
        printf("FAIL teeth: %ld of %ld doctored results were not caught\n", tn - tcaught, tn);
        failed_cases++;
    }
    printf("  CPU time %.2f s (boxes %.2f s, compositions %.2f s)\n", t_all, t_boxes, t_all - t_boxes);
    double mean = ext.ends + exc.ends ? (ext.sum + exc.sum) / (double)(ext.ends + exc.ends) : 0.0;
    printf("test_imat: %ld boxes, %ld compositions, %ld exact checks: %ld passed, %ld failed; "
           "excess max %.2f mean %.2f (units of u S + eta), teeth %ld/%ld caught\n",
           n, m, nchecks, nchecks - nfail_checks, nfail_checks,
           ext.max > exc.max ? ext.max : exc.max, mean, tcaught, tn);

    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            mpq_clear(A[i][j]);
            mpq_clear(B[i][j]);
        }
    mpq_clears(k.q, k.qa, k.qb, k.qs, k.qmin, k.qmax, k.qt, (mpq_ptr)0);
    mpz_clears(k.L, k.H, k.S, k.p[0], k.p[1], k.p[2], k.p[3], k.g, k.g2, k.tol, k.z, (mpz_ptr)0);
    xu_clear(&k.x);
    printf("%ld passed, %ld failed\n", n + m - failed_cases, failed_cases);
    return failed_cases || nfail_checks ? 1 : 0;
}
