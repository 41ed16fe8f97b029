/*
 * gltf_exact.c: part of tests/test_gltf.c (gltf_parts.h): the exact
 * helpers the checks share (a box end's excess over an exact bound, an
 * exact value outside an interval, the exact sign of a quaternion dot
 * product), and cbx_transform_box_imat alone on random interval matrices
 * and boxes, checked exactly (GMP).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <gmp.h>

#include "gltf_parts.h"

/* relative excess of box end e over the exact bound x (sign: outward) */
double glt_excess(double e, const mpq_t x, double scale, int upper)
{
    if (!isfinite(e)) return 0.0;
    mpq_t d;
    mpq_init(d);
    mpq_set_d(d, e);
    if (upper) mpq_sub(d, d, x); else mpq_sub(d, x, d);
    double r = mpq_get_d(d) / (scale > 0 ? scale : 1.0);
    mpq_clear(d);
    return r;
}

double glt_qabs_max(const mpq_t a, const mpq_t b)
{
    double x = fabs(mpq_get_d(a)), y = fabs(mpq_get_d(b));
    return x > y ? x : y;
}

/* 1 if the exact q lies outside [lo, hi] (an infinite end holds all) */
int glt_q_out(const mpq_t q, double lo, double hi, mpq_t t)
{
    if (lo != -HUGE_VAL) { mpq_set_d(t, lo); if (mpq_cmp(q, t) < 0) return 1; }
    if (hi != HUGE_VAL) { mpq_set_d(t, hi); if (mpq_cmp(q, t) > 0) return 1; }
    return 0;
}

/* the exact sign of the dot product of two stored quaternions */
int glt_dot_sign(const double *a, const double *b)
{
    mpq_t d, x, y;
    mpq_inits(d, x, y, NULL);
    for (int j = 0; j < 4; j++) { mpq_set_d(x, a[j]); mpq_set_d(y, b[j]); mpq_mul(x, x, y); mpq_add(d, d, x); }
    int sg = mpq_sgn(d);
    mpq_clears(d, x, y, NULL);
    return sg;
}

/* ---- cbx_transform_box_imat alone: random interval matrices and boxes ------ */
static uint64_t rng = 0x9E3779B97F4A7C15u;
static uint64_t rnd(void) { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; return rng; }
/* a random double: zero, tiny, huge, ordinary; sometimes infinite */
static double rnd_d(int allow_inf)
{
    uint64_t r = rnd();
    int kind = (int)(r % 16);
    double sgn = (r >> 8) & 1 ? -1.0 : 1.0, m = 1.0 + (double)((r >> 12) % 1000003) / 1000003.0;
    if (kind == 0) return 0.0;
    if (kind == 1 && allow_inf) return sgn * HUGE_VAL;
    if (kind == 2) return sgn * ldexp(m, -1074 + (int)((r >> 40) % 60));      /* subnormal / tiny */
    if (kind == 3) return sgn * ldexp(m, 1000 + (int)((r >> 40) % 24));       /* near overflow */
    return sgn * ldexp(m, (int)((r >> 40) % 80) - 40);
}
static void rnd_iv(double *lo, double *hi, int allow_inf)
{
    double a = rnd_d(allow_inf), b = (rnd() % 4 == 0) ? a : rnd_d(allow_inf);
    if (a > b) { double t = a; a = b; b = t; }
    if (a == HUGE_VAL) a = DBL_MAX;                /* lo < +inf, hi > -inf */
    if (b == -HUGE_VAL) b = -DBL_MAX;
    *lo = a; *hi = b;
}

/* The fast range of output axis i (certbox.h): every interval of the row
 * and of the box finite, linear entries and box ends within 2^509, the
 * translation within 2^1018 (the intervals here are ordered). */
static int imat_row_fast(const cbx_imat *W, const cbx_box *x, int i)
{
    int f = isfinite(W->lo[i][3]) && isfinite(W->hi[i][3]) && fabs(W->lo[i][3]) <= 0x1p1018
            && fabs(W->hi[i][3]) <= 0x1p1018;
    for (int j = 0; j < 3; j++)
        f = f && isfinite(W->lo[i][j]) && isfinite(W->hi[i][j]) && fabs(W->lo[i][j]) <= 0x1p509
            && fabs(W->hi[i][j]) <= 0x1p509 && isfinite(x->lo[j]) && isfinite(x->hi[j])
            && fabs(x->lo[j]) <= 0x1p509 && fabs(x->hi[j]) <= 0x1p509;
    return f;
}

/* counts every failure in *nfail (the driver's count), prints the first 50 */
#define FAIL(...) do { if (++*nfail <= 50) fprintf(stderr, "FAIL " __VA_ARGS__); } while (0)

/* out holds every M x + t: on each axis in the fast range, the exact
 * extremes of the row over the end combinations; every other axis is
 * exactly [-inf, +inf], and then the status is CBX_ERANGE (else CBX_OK). */
void glt_test_imat_box(long n, long *nfail, long *n_fin, long *n_inf)
{
    mpq_t lo, hi, a, b, t, w;
    mpq_inits(lo, hi, a, b, t, w, NULL);
    long fin = 0, inf = 0;
    for (long k = 0; k < n; k++) {
        cbx_imat W;
        cbx_box x, o;
        int allow = k % 4 == 0, nfast = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                rnd_iv(&W.lo[i][j], &W.hi[i][j], allow);
        for (int j = 0; j < 3; j++) rnd_iv(&x.lo[j], &x.hi[j], allow);
        cbx_status s = cbx_transform_box_imat(&W, &x, &o);
        for (int i = 0; i < 3; i++) {
            if (isnan(o.lo[i]) || isnan(o.hi[i]) || o.lo[i] > o.hi[i])
                FAIL("imat_box case %ld: NaN or empty on axis %d\n", k, i);
            if (!imat_row_fast(&W, &x, i)) {
                if (o.lo[i] != -HUGE_VAL || o.hi[i] != HUGE_VAL)
                    FAIL("imat_box case %ld: axis %d outside the fast range but not [-inf, +inf]\n", k, i);
                continue;
            }
            nfast++;
            if (!isfinite(o.lo[i]) || !isfinite(o.hi[i])) {
                FAIL("imat_box case %ld: axis %d in the fast range but not finite\n", k, i);
                continue;
            }
            mpq_set_d(lo, W.lo[i][3]);
            mpq_set_d(hi, W.hi[i][3]);
            for (int j = 0; j < 3; j++) {
                int first = 1;
                for (int p = 0; p < 2; p++)
                    for (int q = 0; q < 2; q++) {
                        mpq_set_d(w, p ? W.hi[i][j] : W.lo[i][j]);
                        mpq_set_d(t, q ? x.hi[j] : x.lo[j]);
                        mpq_mul(t, w, t);
                        if (first) { mpq_set(a, t); mpq_set(b, t); first = 0; }
                        else { if (mpq_cmp(t, a) < 0) mpq_set(a, t); if (mpq_cmp(t, b) > 0) mpq_set(b, t); }
                    }
                mpq_add(lo, lo, a);
                mpq_add(hi, hi, b);
            }
            mpq_set_d(t, o.lo[i]); if (mpq_cmp(t, lo) > 0) FAIL("imat_box case %ld: lo above the exact minimum (axis %d)\n", k, i);
            mpq_set_d(t, o.hi[i]); if (mpq_cmp(t, hi) < 0) FAIL("imat_box case %ld: hi below the exact maximum (axis %d)\n", k, i);
        }
        if (s != (nfast == 3 ? CBX_OK : CBX_ERANGE))
            FAIL("imat_box case %ld: status %s with %d axes in the fast range\n", k, cbx_status_name(s), nfast);
        if (nfast == 3) fin++; else inf++;
    }
    mpq_clears(lo, hi, a, b, t, w, NULL);
    *n_fin = fin;
    *n_inf = inf;
}
