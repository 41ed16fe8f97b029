/*
 * imat_check.c: the checks of test_imat (tests/test_imat.c; the rules and
 * the checks are described there): the tallies, one output coordinate
 * against its exact ends (fixed point scaled by 2^2148, mpz; cross and
 * points with mpq), a whole cbx_transform_box_imat or cbx_imat_compose
 * call, the product check of a composition, and printing the tallies.
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
/* The checks and their tallies                                           */
/* ---------------------------------------------------------------------- */

static const char *const c_name[NC] = { "status", "written", "special", "whole", "finite",
                                        "contain", "tight", "cross", "points", "product",
                                        "alias", "input" };
static const char *const c_unit[NC] = { "cases", "cases", "cases", "coords", "coords",
                                        "coords", "coords", "coords", "points", "entries",
                                        "cases", "cases" };

/* Count one check; 1 if it failed (the first reason is kept). */
int imt_tick(tally *t, int c, int ok, const char *why, int coord)
{
    t->n[c]++;
    if (ok) return 0;
    t->f[c]++;
    if (t->why[0] == '\0')
        snprintf(t->why, sizeof t->why, "%s (coordinate %d): %s", c_name[c], coord, why);
    return 1;
}

void imt_ex_add(exstat *e, double v, int tiny)
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

row imt_trow(const cbx_imat *a, int i, const cbx_box *b)
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

row imt_crow(const cbx_imat *a, const cbx_imat *b, int i, int j)
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

/* The rules, written from test_imat.c's header (IEEE comparisons). */
static int iv_bad(double l, double h) { return isnan(l) || isnan(h) || h < l; }
static int iv_fast(double l, double h, double b)
{
    return isfinite(l) && isfinite(h) && -b <= l && l <= h && h <= b;
}
int imt_row_fast(const row *r)
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

/* Exact ends and scale of one fast coordinate, scaled by 2^2148:
 * k->L, k->H, k->S. */
void imt_row_exact(ctx *k, const row *r)
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
void imt_tol53(ctx *k)
{
    mpz_mul_ui(k->tol, k->S, 12);
    mpz_set_ui(k->z, 1);
    mpz_mul_2exp(k->z, k->z, 2148 + 53 - 1065);
    mpz_add(k->tol, k->tol, k->z);
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
    if (!imt_row_fast(r)) {
        snprintf(why, sizeof why, "outside the fast range but [%a, %a]", lo, hi);
        return imt_tick(t, C_WHOLE, lo == -INF && hi == INF, why, coord);
    }
    snprintf(why, sizeof why, "fast but [%a, %a]", lo, hi);
    if (imt_tick(t, C_FINITE, isfinite(lo) && isfinite(hi), why, coord)) return 1;
    imt_row_exact(k, r);
    /* g = L - lo, g2 = hi - H (scaled): both >= 0 */
    xu_scaled_d(&k->x, k->z, lo);
    mpz_sub(k->g, k->L, k->z);
    xu_scaled_d(&k->x, k->z, hi);
    mpz_sub(k->g2, k->z, k->H);
    snprintf(why, sizeof why, "lo %a > L or hi %a < H", lo, hi);
    f += imt_tick(t, C_CONTAIN, mpz_sgn(k->g) >= 0 && mpz_sgn(k->g2) >= 0, why, coord);
    imt_tol53(k);
    mpz_mul_2exp(k->z, k->g, 53);
    int ok = mpz_cmp(k->z, k->tol) <= 0;
    mpz_mul_2exp(k->z, k->g2, 53);
    ok = ok && mpz_cmp(k->z, k->tol) <= 0;
    snprintf(why, sizeof why, "[%a, %a] beyond 12 u S + 2^-1065 of the exact ends", lo, hi);
    f += imt_tick(t, C_TIGHT, ok, why, coord);
    if (ex) {
        int tiny = xu_scale_tiny(k->S);
        imt_ex_add(ex, xu_units(&k->x, k->g, k->S), tiny);
        imt_ex_add(ex, xu_units(&k->x, k->g2, k->S), tiny);
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
    f += imt_tick(t, C_CROSS, mpq_equal(k->q, k->qmin) && mpq_equal(k->qs, k->qmax),
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
    f += imt_tick(t, C_POINTS, !q_outside(k, k->qs, lo, hi), why, coord);
    return f;
}

/* ---------------------------------------------------------------------- */
/* Checking a whole call                                                  */
/* ---------------------------------------------------------------------- */

static int is_nan_bits(double v) { return isnan(v); }

/* The checks of one cbx_transform_box_imat result. */
int imt_check_transform(ctx *k, tally *t, exstat *ex, const cbx_imat *a, const cbx_box *in,
                        const cbx_box *out, cbx_status got, int deep, cbx_status *expected)
{
    int f = 0, i, unset = 0, nfast = 0;
    char why[200];
    for (i = 0; i < 3; i++) unset |= is_nan_bits(out->lo[i]) || is_nan_bits(out->hi[i]);
    f += imt_tick(t, C_WRITTEN, !unset, "an output field left at the NaN pre-fill", -1);
    if (imat_bad(a) || box_nan(in)) {
        *expected = CBX_EINVAL;
        int ok = 1;
        for (i = 0; i < 3; i++) ok = ok && out->lo[i] == -INF && out->hi[i] == INF;
        f += imt_tick(t, C_SPECIAL, ok, "EINVAL but not the whole space", -1);
    } else if (box_empty(in)) {
        *expected = CBX_EMPTY;
        int ok = 1;
        for (i = 0; i < 3; i++) ok = ok && out->lo[i] == INF && out->hi[i] == -INF;
        f += imt_tick(t, C_SPECIAL, ok, "EMPTY but not lo = +inf, hi = -inf", -1);
    } else {
        for (i = 0; i < 3; i++) {
            row r = imt_trow(a, i, in);
            nfast += imt_row_fast(&r);
            f += check_coord(k, t, ex, &r, out->lo[i], out->hi[i], i, deep);
        }
        *expected = nfast == 3 ? CBX_OK : CBX_ERANGE;
    }
    snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(got), cbx_status_name(*expected));
    f += imt_tick(t, C_STATUS, got == *expected, why, -1);
    return f;
}

/* The checks of one cbx_imat_compose result. */
int imt_check_compose(ctx *k, tally *t, exstat *ex, const cbx_imat *a, const cbx_imat *b,
                      const cbx_imat *out, cbx_status got, int deep, cbx_status *expected)
{
    int f = 0, i, j, unset = 0, nfast = 0;
    char why[200];
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) unset |= is_nan_bits(out->lo[i][j]) || is_nan_bits(out->hi[i][j]);
    f += imt_tick(t, C_WRITTEN, !unset, "an output field left at the NaN pre-fill", -1);
    if (imat_bad(a) || imat_bad(b)) {
        *expected = CBX_EINVAL;
        int ok = 1;
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) ok = ok && out->lo[i][j] == -INF && out->hi[i][j] == INF;
        f += imt_tick(t, C_SPECIAL, ok, "EINVAL but not every entry [-inf, +inf]", -1);
    } else {
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) {
                row r = imt_crow(a, b, i, j);
                nfast += imt_row_fast(&r);
                f += check_coord(k, t, ex, &r, out->lo[i][j], out->hi[i][j], 4 * i + j, deep);
            }
        *expected = nfast == 12 ? CBX_OK : CBX_ERANGE;
    }
    snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(got), cbx_status_name(*expected));
    f += imt_tick(t, C_STATUS, got == *expected, why, -1);
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

int imt_has_real(const cbx_imat *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (a->lo[i][j] == INF || a->hi[i][j] == -INF) return 0;
    return 1;
}

/* product: random real A in a, B in b; every entry of A B in out. */
int imt_check_product(ctx *k, tally *t, const cbx_imat *a, const cbx_imat *b, const cbx_imat *out,
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
            f += imt_tick(t, C_PRODUCT, !q_outside(k, k->qs, out->lo[i][j], out->hi[i][j]), why, 4 * i + j);
        }
    return f;
}

/* ---------------------------------------------------------------------- */
/* Printing the tallies                                                   */
/* ---------------------------------------------------------------------- */

void imt_print_tally(const tally *t)
{
    int c;
    for (c = 0; c < NC; c++)
        if (t->n[c])
            printf("  check %-8s %10ld %-8s checked, %ld failed\n", c_name[c], t->n[c], c_unit[c], t->f[c]);
}

void imt_print_ex(const char *what, const exstat *e)
{
    printf("  excess over the exact ends (units of u S + 2^-1074; proven bound 12 u S + 2^-1065):\n"
           "    %s: %ld ends with u S >= 2^-1000: max %.3f, mean %.3f; %ld ends at a tinier scale: max %.3g\n",
           what, e->ends, e->max, e->ends ? e->sum / (double)e->ends : 0.0, e->tiny, e->max_tiny);
}

long imt_checks_of(const tally *t, long *failed)
{
    long n = 0;
    int c;
    for (c = 0; c < NC; c++) {
        n += t->n[c];
        *failed += t->f[c];
    }
    return n;
}
