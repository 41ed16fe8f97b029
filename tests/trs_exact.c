/*
 * trs_exact.c: the exact motion of tests/test_trs.c (tests/trs_parts.h),
 * evaluated in MPFR at PREC bits: the keyframes' rotation (exact_util's
 * slerp / nlerp oracle), translation and scales at a time s, the image of
 * a corner, and what the driver checks with them: the corners' images at
 * one time inside a box (or by how much outside), a ball's extreme points,
 * and each axis's extremes over [s0, s1] (samples, then golden section).
 */
#include <math.h>

#include <mpfr.h>

#include "trs_parts.h"

void trt_ex_init(exact *e)
{
    int i, j;
    xu_slerp_init(&e->sl, PREC);
    for (i = 0; i < 4; i++) {
        mpfr_init2(e->q[i], PREC);
    }
    mpfr_inits2(PREC, e->t1, e->t2, (mpfr_ptr)0);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            mpfr_init2(e->R[i][j], PREC);
        }
        mpfr_inits2(PREC, e->T[i], e->SC[i][0], e->SC[i][1], (mpfr_ptr)0);
    }
}

void trt_ex_clear(exact *e)
{
    int i, j;
    xu_slerp_clear(&e->sl);
    for (i = 0; i < 4; i++) {
        mpfr_clear(e->q[i]);
    }
    mpfr_clears(e->t1, e->t2, (mpfr_ptr)0);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            mpfr_clear(e->R[i][j]);
        }
        mpfr_clears(e->T[i], e->SC[i][0], e->SC[i][1], (mpfr_ptr)0);
    }
}

/* Normalised keyframe quaternions, q1 on the shorter arc (sign = +1 / -1
 * forces the arc: used for the ties): exact_util's slerp oracle. */
void trt_ex_keys(exact *e, const cbx_trs *k0, const cbx_trs *k1, int nlerp, int sign)
{
    xu_slerp_keys(&e->sl, k0->q, k1->q, nlerp, sign);
}

/* R at time s (an mpfr value). */
static void ex_rot(exact *e, const mpfr_t s)
{
    xu_slerp_at(&e->sl, s, e->q);
    {
        mpfr_ptr x = e->q[0], y = e->q[1], z = e->q[2], w = e->q[3];
        /* R = [[1-2(yy+zz), 2(xy-zw), 2(xz+yw)], [2(xy+zw), 1-2(xx+zz), 2(yz-xw)],
         *      [2(xz-yw), 2(yz+xw), 1-2(xx+yy)]] */
#define SQ2(d, a, b) do { mpfr_mul(e->t1, a, a, MPFR_RNDN); mpfr_fma(e->t1, b, b, e->t1, MPFR_RNDN); \
        mpfr_mul_2ui(e->t1, e->t1, 1, MPFR_RNDN); mpfr_ui_sub(d, 1, e->t1, MPFR_RNDN); } while (0)
#define PR2(d, a, b, c, f, sg) do { mpfr_mul(e->t1, a, b, MPFR_RNDN); mpfr_mul(e->t2, c, f, MPFR_RNDN); \
        if (sg > 0) mpfr_add(d, e->t1, e->t2, MPFR_RNDN); else mpfr_sub(d, e->t1, e->t2, MPFR_RNDN); \
        mpfr_mul_2ui(d, d, 1, MPFR_RNDN); } while (0)
        SQ2(e->R[0][0], y, z);
        SQ2(e->R[1][1], x, z);
        SQ2(e->R[2][2], x, y);
        PR2(e->R[0][1], x, y, z, w, -1);
        PR2(e->R[0][2], x, z, y, w, 1);
        PR2(e->R[1][0], x, y, z, w, 1);
        PR2(e->R[1][2], y, z, x, w, -1);
        PR2(e->R[2][0], x, z, y, w, -1);
        PR2(e->R[2][1], y, z, x, w, 1);
#undef SQ2
#undef PR2
    }
}

/* T(s), and S_j(s) times box end lo_j (SC[j][0]) and hi_j (SC[j][1]). */
static void ex_ts(exact *e, const cbx_trs *k0, const cbx_trs *k1, const mpfr_t s, const cbx_box *in)
{
    int j;
    for (j = 0; j < 3; j++) {
        mpfr_set_d(e->t1, k1->t[j], MPFR_RNDN);
        mpfr_sub_d(e->t1, e->t1, k0->t[j], MPFR_RNDN);
        mpfr_mul(e->t1, e->t1, s, MPFR_RNDN);
        mpfr_add_d(e->T[j], e->t1, k0->t[j], MPFR_RNDN);
        mpfr_set_d(e->t2, k1->s[j], MPFR_RNDN);
        mpfr_sub_d(e->t2, e->t2, k0->s[j], MPFR_RNDN);
        mpfr_mul(e->t2, e->t2, s, MPFR_RNDN);
        mpfr_add_d(e->t2, e->t2, k0->s[j], MPFR_RNDN);
        mpfr_mul_d(e->SC[j][0], e->t2, in->lo[j], MPFR_RNDN);
        mpfr_mul_d(e->SC[j][1], e->t2, in->hi[j], MPFR_RNDN);
    }
}

/* The motion at time s: R, T and the scaled box ends. */
void trt_ex_at(exact *e, const cbx_trs *k0, const cbx_trs *k1, const mpfr_t s, const cbx_box *in)
{
    ex_rot(e, s);
    ex_ts(e, k0, k1, s, in);
}

/* Coordinate i of corner c's image (trt_ex_at done for the time). */
void trt_ex_coord(exact *e, mpfr_t out, int c, int i)
{
    int j;
    mpfr_set(out, e->T[i], MPFR_RNDN);
    for (j = 0; j < 3; j++) {
        mpfr_fma(out, e->R[i][j], e->SC[j][(c >> j) & 1], out, MPFR_RNDN);
    }
}


/* 1 when every corner's exact image at time sd lies in *out. */
int trt_sample_in(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const cbx_box *in,
                     const cbx_box *out)
{
    mpfr_t s, v;
    int c, i, ok = 1;
    mpfr_inits2(PREC, s, v, (mpfr_ptr)0);
    mpfr_set_d(s, sd, MPFR_RNDN);
    trt_ex_at(e, k0, k1, s, in);
    for (c = 0; c < 8; c++) {
        for (i = 0; i < 3; i++) {
            trt_ex_coord(e, v, c, i);
            if (mpfr_cmp_d(v, out->lo[i]) < 0 || mpfr_cmp_d(v, out->hi[i]) > 0) {
                ok = 0;
            }
        }
    }
    mpfr_clears(s, v, (mpfr_ptr)0);
    return ok;
}

/* The largest distance by which a corner's exact image at time sd lies
 * outside *box (negative: all inside), rounded to a double. */
double trt_sample_miss(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const cbx_box *in,
                          const cbx_box *box)
{
    mpfr_t s, v, d;
    int c, i;
    double worst = -HUGE_VAL;
    mpfr_inits2(PREC, s, v, d, (mpfr_ptr)0);
    mpfr_set_d(s, sd, MPFR_RNDN);
    trt_ex_at(e, k0, k1, s, in);
    for (c = 0; c < 8; c++) {
        for (i = 0; i < 3; i++) {
            trt_ex_coord(e, v, c, i);
            mpfr_d_sub(d, box->lo[i], v, MPFR_RNDN);
            worst = fmax(worst, mpfr_get_d(d, MPFR_RNDU));
            mpfr_sub_d(d, v, box->hi[i], MPFR_RNDN);
            worst = fmax(worst, mpfr_get_d(d, MPFR_RNDU));
        }
    }
    mpfr_clears(s, v, d, (mpfr_ptr)0);
    return worst;
}

/* The ball |x - c| <= |r| at time sd: each axis's two extreme points,
 * T_i + (R S c)_i -+ |r| |row i of R S| (exact reals, MPFR), inside *box. */
int trt_ball_in(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const double c[3], double r,
                   const cbx_box *box)
{
    mpfr_t s, v, nr, t;
    cbx_box pt, one;
    int i, j, ok = 1;
    mpfr_inits2(PREC, s, v, nr, t, (mpfr_ptr)0);
    for (j = 0; j < 3; j++) {
        pt.lo[j] = pt.hi[j] = c[j];
        one.lo[j] = one.hi[j] = 1.0;
    }
    mpfr_set_d(s, sd, MPFR_RNDN);
    ex_rot(e, s);
    for (i = 0; i < 3; i++) {
        ex_ts(e, k0, k1, s, &one); /* SC[j][0] = S_j */
        mpfr_set_ui(nr, 0, MPFR_RNDN);
        for (j = 0; j < 3; j++) {
            mpfr_mul(t, e->R[i][j], e->SC[j][0], MPFR_RNDN);
            mpfr_fma(nr, t, t, nr, MPFR_RNDN);
        }
        mpfr_sqrt(nr, nr, MPFR_RNDN);
        mpfr_mul_d(nr, nr, fabs(r), MPFR_RNDN);
        ex_ts(e, k0, k1, s, &pt);
        trt_ex_coord(e, v, 0, i);
        mpfr_sub(t, v, nr, MPFR_RNDN);
        ok &= mpfr_cmp_d(t, box->lo[i]) >= 0;
        mpfr_add(t, v, nr, MPFR_RNDN);
        ok &= mpfr_cmp_d(t, box->hi[i]) <= 0;
    }
    mpfr_clears(s, v, nr, t, (mpfr_ptr)0);
    return ok;
}

/* f(s) = sg * coordinate i of corner c at time s. */
static void golden_f(exact *e, mpfr_t v, const cbx_trs *k0, const cbx_trs *k1, const mpfr_t s,
                     const cbx_box *in, int c, int i, int sg)
{
    trt_ex_at(e, k0, k1, s, in);
    trt_ex_coord(e, v, c, i);
    if (sg < 0) {
        mpfr_neg(v, v, MPFR_RNDN);
    }
}

#define XS 16 /* samples of [s0, s1] before the golden section */

/* For each axis i and side (sg = -1: the smallest coordinate, +1: the
 * largest), best[i][sg > 0] = the largest sg * coordinate found: every
 * corner at XS + 1 even times, then 50 golden-section steps on the best
 * corner's bracket (its extreme to about 1e-20 relative). */
void trt_extremes(exact *e, mpfr_t best[3][2], const cbx_trs *k0, const cbx_trs *k1, double s0,
                     double s1, const cbx_box *in)
{
    mpfr_t s, a, b, m1, m2, f1, f2, v;
    int k, c, i, side, kb[3][2], cb[3][2];
    mpfr_inits2(PREC, s, a, b, m1, m2, f1, f2, v, (mpfr_ptr)0);
    for (i = 0; i < 3; i++) {
        mpfr_set_inf(best[i][0], -1);
        mpfr_set_inf(best[i][1], -1);
    }
    for (k = 0; k <= XS; k++) {
        mpfr_set_d(s, s1 - s0, MPFR_RNDN);
        mpfr_mul_ui(s, s, (unsigned long)k, MPFR_RNDN);
        mpfr_div_ui(s, s, XS, MPFR_RNDN);
        mpfr_add_d(s, s, s0, MPFR_RNDN);
        trt_ex_at(e, k0, k1, s, in);
        for (c = 0; c < 8; c++) {
            for (i = 0; i < 3; i++) {
                trt_ex_coord(e, v, c, i);
                if (mpfr_cmp(v, best[i][1]) > 0) {
                    mpfr_set(best[i][1], v, MPFR_RNDN);
                    kb[i][1] = k;
                    cb[i][1] = c;
                }
                mpfr_neg(v, v, MPFR_RNDN);
                if (mpfr_cmp(v, best[i][0]) > 0) {
                    mpfr_set(best[i][0], v, MPFR_RNDN);
                    kb[i][0] = k;
                    cb[i][0] = c;
                }
            }
        }
    }
    for (i = 0; i < 3; i++) {
        for (side = 0; side < 2; side++) {
            int sg = side ? 1 : -1, kk = kb[i][side], cc = cb[i][side];
            mpfr_set_d(a, s1 - s0, MPFR_RNDN);
            mpfr_mul_ui(a, a, (unsigned long)(kk > 0 ? kk - 1 : 0), MPFR_RNDN);
            mpfr_div_ui(a, a, XS, MPFR_RNDN);
            mpfr_add_d(a, a, s0, MPFR_RNDN);
            mpfr_set_d(b, s1 - s0, MPFR_RNDN);
            mpfr_mul_ui(b, b, (unsigned long)(kk < XS ? kk + 1 : XS), MPFR_RNDN);
            mpfr_div_ui(b, b, XS, MPFR_RNDN);
            mpfr_add_d(b, b, s0, MPFR_RNDN);
            for (k = 0; k < 50; k++) {
                mpfr_sub(v, b, a, MPFR_RNDN);
                mpfr_mul_d(v, v, 0.6180339887498949, MPFR_RNDN);
                mpfr_sub(m1, b, v, MPFR_RNDN);
                mpfr_add(m2, a, v, MPFR_RNDN);
                golden_f(e, f1, k0, k1, m1, in, cc, i, sg);
                golden_f(e, f2, k0, k1, m2, in, cc, i, sg);
                if (mpfr_cmp(f1, f2) < 0) {
                    mpfr_set(a, m1, MPFR_RNDN);
                } else {
                    mpfr_set(b, m2, MPFR_RNDN);
                }
                if (mpfr_cmp(f1, best[i][side]) > 0) {
                    mpfr_set(best[i][side], f1, MPFR_RNDN);
                }
                if (mpfr_cmp(f2, best[i][side]) > 0) {
                    mpfr_set(best[i][side], f2, MPFR_RNDN);
                }
            }
        }
    }
    mpfr_clears(s, a, b, m1, m2, f1, f2, v, (mpfr_ptr)0);
}
