/*
 * test_trs [N] [seed]: motion with rotation (cbx_motion_trs_box,
 * cbx_motion_trs_path, cbx_trs_pieces, cbx_transform_box_pieces) against
 * the exact motion evaluated in MPFR at 160 bits.  Defaults: N = 100000
 * keyframe pairs, seed 1.
 *
 * The exact motion (certbox.h): at time s, x -> T(s) + R(s) diag(S(s)) x
 * with T, S = (1 - s) k0 + s k1 and R the rotation of the unit quaternion
 * slerp(s) (or nlerp(s)) from q0/|q0| to q1/|q1|, q1 negated when the exact
 * q0.q1 < 0 (decided here exactly: the products of doubles and their sum
 * are exact at 2400 bits).  slerp(s) = (sin((1-s) th) q0 + sin(s th) q1) / sin th with
 * cos th = q0.q1 (q0 when th < 2^-200), nlerp(s) the normalised blend.
 *
 * Cases: rotations between the keyframes of 0, 1e-9, 1e-4, 45, 90, 179.9,
 * 180 degrees and random ones, about random axes, from random orientations;
 * stored quaternions scaled by 2^-20 .. 2^20 and negated at random (the
 * same rotation); per-axis scales of either sign (axis flips, pbrt-v3 #41),
 * equal keyframes (pbrt-v4 #204), huge translations beside tiny boxes; the
 * full shutter and random sub-intervals; depths 0 to 6; slerp and nlerp.
 *
 * Checks:
 *   status   CBX_OK and every end finite on these in-range inputs;
 *   sample   each of the 8 corners' exact image at s0, s1 and 7 random
 *            times between (doubles, so exact rationals) lies in the box;
 *   extreme  (every 64th pair) the smallest and largest coordinate of the
 *            image over [s0, s1], found by 17 even samples of every corner
 *            and 50 golden-section steps on the best one (to about 1e-20),
 *            lies in the box;
 *   tight    the excess of each end beyond that extreme, as a share of the
 *            exact image's largest extent (its box's longest side), is at
 *            most 10 / 2^depth + 2%
 *            (no 180-degree ties, no 1e12 translations: there the rounding
 *            of the lever dominates a tiny box); it is reported per depth
 *            (about halved per level: the interval matrix of a cell loses
 *            the correlation of its entries, a first-order excess);
 *   pieces   cbx_trs_pieces + cbx_transform_box_pieces give the same bits
 *            and status as cbx_motion_trs_box;
 *   alias    out == in gives the same bits;
 *   ball     a ball around the box's centre (radius up to the box's size,
 *            either sign): at the same 9 times, each axis's two extreme
 *            points of the exact image lie in cbx_motion_trs_ball's box,
 *            and cbx_ball_pieces gives the same bits;
 *   path     (every 16th pair) three to five keyframes: the exact image at
 *            9 times of [s0, s1] lies in cbx_motion_trs_path's box;
 *   special  NaN, zero quaternion, bad shutter or depth, out-of-range
 *            entries, empty and infinite boxes, 180-degree turns whose arc
 *            direction is a tie (both arcs must be covered).
 * Also reported (not a failure): how often and by how much the renderers'
 * bounds miss the exact image on the same pairs (every 16th, full shutter):
 * the union of the boxes at s = 0 and 1 (pbrt's endpoints) and the box of
 * the 8 corners at 128 samples t = k/128 (Cycles), both in round to
 * nearest, checked at 17 exact times between their samples and at s = 1;
 * misses by more than 1e-9 of the box are the geometric ones (the rest is
 * rounding).
 * The last line is "N passed, M failed" (checks); exit 1 on any failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <gmp.h>
#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"

#define PREC 160
#define MAX_LOGS 10

static long n_check, n_fail, n_logs;

static void check(int ok, const char *what, long pair)
{
    n_check++;
    if (ok) {
        return;
    }
    n_fail++;
    if (n_logs++ < MAX_LOGS) {
        printf("FAIL %s (pair %ld)\n", what, pair);
    }
}

/* ---- the exact motion (MPFR) ------------------------------------------- */

typedef struct exact {
    xu_slerp sl;                      /* the keys' quaternions and angle */
    mpfr_t q[4], t1, t2, R[3][3], T[3], SC[3][2];
} exact;

static void ex_init(exact *e)
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

static void ex_clear(exact *e)
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
static void ex_keys(exact *e, const cbx_trs *k0, const cbx_trs *k1, int nlerp, int sign)
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
static void ex_at(exact *e, const cbx_trs *k0, const cbx_trs *k1, const mpfr_t s, const cbx_box *in)
{
    ex_rot(e, s);
    ex_ts(e, k0, k1, s, in);
}

/* Coordinate i of corner c's image (ex_at done for the time). */
static void ex_coord(exact *e, mpfr_t out, int c, int i)
{
    int j;
    mpfr_set(out, e->T[i], MPFR_RNDN);
    for (j = 0; j < 3; j++) {
        mpfr_fma(out, e->R[i][j], e->SC[j][(c >> j) & 1], out, MPFR_RNDN);
    }
}


/* 1 when every corner's exact image at time sd lies in *out. */
static int sample_in(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const cbx_box *in,
                     const cbx_box *out)
{
    mpfr_t s, v;
    int c, i, ok = 1;
    mpfr_inits2(PREC, s, v, (mpfr_ptr)0);
    mpfr_set_d(s, sd, MPFR_RNDN);
    ex_at(e, k0, k1, s, in);
    for (c = 0; c < 8; c++) {
        for (i = 0; i < 3; i++) {
            ex_coord(e, v, c, i);
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
static double sample_miss(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const cbx_box *in,
                          const cbx_box *box)
{
    mpfr_t s, v, d;
    int c, i;
    double worst = -HUGE_VAL;
    mpfr_inits2(PREC, s, v, d, (mpfr_ptr)0);
    mpfr_set_d(s, sd, MPFR_RNDN);
    ex_at(e, k0, k1, s, in);
    for (c = 0; c < 8; c++) {
        for (i = 0; i < 3; i++) {
            ex_coord(e, v, c, i);
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
static int ball_in(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const double c[3], double r,
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
        ex_coord(e, v, 0, i);
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
    ex_at(e, k0, k1, s, in);
    ex_coord(e, v, c, i);
    if (sg < 0) {
        mpfr_neg(v, v, MPFR_RNDN);
    }
}

#define XS 16 /* samples of [s0, s1] before the golden section */

/* For each axis i and side (sg = -1: the smallest coordinate, +1: the
 * largest), best[i][sg > 0] = the largest sg * coordinate found: every
 * corner at XS + 1 even times, then 50 golden-section steps on the best
 * corner's bracket (its extreme to about 1e-20 relative). */
static void extremes(exact *e, mpfr_t best[3][2], const cbx_trs *k0, const cbx_trs *k1, double s0,
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
        ex_at(e, k0, k1, s, in);
        for (c = 0; c < 8; c++) {
            for (i = 0; i < 3; i++) {
                ex_coord(e, v, c, i);
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

/* ---- the renderers' bounds (round to nearest) --------------------------- */

/* sin, cos, acos correctly rounded to double (MPFR at 53 bits): the same
 * bits on every platform, so that the ARM run (make check-cross) sees the
 * same cases as this one. */
static double cr_fn(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), double x)
{
    mpfr_t t;
    double r;
    mpfr_init2(t, 53);
    mpfr_set_d(t, x, MPFR_RNDN);
    f(t, t, MPFR_RNDN);
    r = mpfr_get_d(t, MPFR_RNDN);
    mpfr_clear(t);
    return r;
}

/* The renderers' methods (bench/bench_ref.h), with these functions. */
#define REF_SIN(x) cr_fn(mpfr_sin, (x))
#define REF_ACOS(x) cr_fn(mpfr_acos, (x))
#include "../bench/bench_ref.h"



/* ---- generators --------------------------------------------------------- */

static double uni(xu_rng *r, double a, double b) { return a + (b - a) * xu_rng_unit(r); }

static void quat_mul(const double a[4], const double b[4], double o[4])
{
    /* (x, y, z, w) Hamilton product a b */
    o[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
    o[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
    o[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
    o[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
}

static void rand_axis_quat(xu_rng *r, double deg, double q[4])
{
    double ax[3], n = 0, h = deg * 3.14159265358979323846 / 360.0;
    int i;
    do {
        n = 0;
        for (i = 0; i < 3; i++) {
            ax[i] = uni(r, -1, 1);
            n += ax[i] * ax[i];
        }
    } while (n < 0.01 || n > 1);
    n = sqrt(n);
    for (i = 0; i < 3; i++) {
        q[i] = cr_fn(mpfr_sin, h) * ax[i] / n;
    }
    q[3] = cr_fn(mpfr_cos, h);
}

static const double angles[] = { 0, 1e-9, 1e-4, 45, 90, 179.9, 180, -1 };

/* A keyframe pair; returns the angle category's index. */
static int gen_pair(xu_rng *r, cbx_trs *k0, cbx_trs *k1, cbx_box *b, int *big)
{
    int cat = xu_rng_int(r, 0, 7), i;
    double deg = angles[cat] < 0 ? uni(r, 0, 180) : angles[cat];
    double q0[4], dq[4], q1[4], sc0, sc1;
    int huge = xu_rng_int(r, 0, 19) == 0;
    *big = huge;
    rand_axis_quat(r, uni(r, 0, 360), q0);
    rand_axis_quat(r, deg, dq);
    quat_mul(q0, dq, q1);
    sc0 = ldexp(1.0, xu_rng_int(r, -20, 20)) * uni(r, 0.5, 1) * xu_rng_sign(r);
    sc1 = ldexp(1.0, xu_rng_int(r, -20, 20)) * uni(r, 0.5, 1) * xu_rng_sign(r);
    for (i = 0; i < 4; i++) {
        k0->q[i] = q0[i] * sc0;
        k1->q[i] = q1[i] * sc1;
    }
    for (i = 0; i < 3; i++) {
        double c = huge ? uni(r, -1e12, 1e12) : uni(r, -100, 100);
        double h = huge ? uni(r, 1e-6, 1e-3) : uni(r, 1e-3, 10);
        k0->t[i] = huge ? uni(r, -1e12, 1e12) : uni(r, -100, 100);
        k1->t[i] = xu_rng_int(r, 0, 3) == 0 ? k0->t[i] : k0->t[i] + uni(r, -50, 50);
        k0->s[i] = uni(r, 0.1, 10) * (xu_rng_int(r, 0, 5) == 0 ? -1 : 1);
        k1->s[i] = k0->s[i];
        b->lo[i] = c - h;
        b->hi[i] = c + h;
        (void)c;
    }
    if (xu_rng_int(r, 0, 2) == 0) { /* scales that change (and may flip) */
        for (i = 0; i < 3; i++) {
            k1->s[i] = uni(r, 0.1, 10) * (xu_rng_int(r, 0, 5) == 0 ? -1 : 1);
        }
    }
    if (xu_rng_int(r, 0, 19) == 0) { /* equal keyframes */
        *k1 = *k0;
        cat = 0;
    }
    return cat;
}

static int same_box(const cbx_box *a, const cbx_box *b) { return memcmp(a, b, sizeof *a) == 0; }

static int box_finite(const cbx_box *b)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (!(fabs(b->lo[i]) <= 1e308 && fabs(b->hi[i]) <= 1e308)) {
            return 0;
        }
    }
    return 1;
}

static int box_finite_axis(const cbx_box *b, int i)
{
    return fabs(b->lo[i]) <= 1e308 && fabs(b->hi[i]) <= 1e308;
}

static int is_whole(const cbx_box *b)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (!(b->lo[i] == -HUGE_VAL && b->hi[i] == HUGE_VAL)) {
            return 0;
        }
    }
    return 1;
}

/* ---- special cases ------------------------------------------------------ */

static void specials(exact *e)
{
    cbx_trs k0 = { { 1, 2, 3 }, { 0, 0, 0, 1 }, { 1, 1, 1 } };
    cbx_trs k1 = { { 2, 2, 3 }, { 0, 0, 1, 0 }, { 1, 1, 1 } }; /* 180 degrees about z, dot 0: a tie */
    cbx_box b = { { -1, -1, -1 }, { 1, 1, 1 } }, o, o2;
    cbx_trs bad;
    cbx_imat pc[64];
    size_t np = 0;
    cbx_status st;
    int d;
    /* the tie: both arcs covered (exact samples of each direction) */
    for (d = 0; d <= 4; d++) {
        int sgn, k, ok = 1;
        st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, (unsigned)d, &b, &o);
        check(st == CBX_OK && box_finite(&o), "tie: status", -1);
        for (sgn = -1; sgn <= 1; sgn += 2) {
            ex_keys(e, &k0, &k1, 0, sgn);
            for (k = 0; k <= 32; k++) {
                ok &= sample_in(e, &k0, &k1, k / 32.0, &b, &o);
            }
        }
        check(ok, "tie: both arcs inside", -1);
    }
    bad = k0;
    bad.q[2] = NAN;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "NaN quaternion -> EINVAL, whole", -1);
    bad = k0;
    bad.q[0] = bad.q[1] = bad.q[2] = bad.q[3] = 0;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "zero quaternion -> EINVAL, whole", -1);
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0.7, 0.2, 3, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "s0 > s1 -> EINVAL", -1);
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, -0.1, 0.2, 3, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "s0 < 0 -> EINVAL", -1);
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 17, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "depth 17 -> EINVAL", -1);
    st = cbx_motion_trs_box(&k0, &k1, (cbx_interp)7, 0, 1, 3, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "bad mode -> EINVAL", -1);
    bad = k0;
    bad.t[1] = 0x1p501;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    check(st == CBX_ERANGE && is_whole(&o), "translation 2^501 -> ERANGE, whole", -1);
    bad = k0;
    bad.s[0] = HUGE_VAL;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    check(st == CBX_ERANGE && is_whole(&o), "infinite scale -> ERANGE, whole", -1);
    bad = k0;
    bad.q[3] = 0x1p-130;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    check(st == CBX_ERANGE && is_whole(&o), "tiny quaternion -> ERANGE, whole", -1);
    o2 = b;
    o2.lo[1] = 2;
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 3, &o2, &o);
    check(st == CBX_EMPTY && o.lo[0] == HUGE_VAL && o.hi[2] == -HUGE_VAL, "empty box -> EMPTY", -1);
    o2 = b;
    o2.lo[1] = NAN;
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 3, &o2, &o);
    check(st == CBX_EINVAL && is_whole(&o), "NaN box -> EINVAL", -1);
    o2 = b;
    o2.hi[0] = HUGE_VAL; /* x unbounded: every output axis that x reaches */
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 3, &o2, &o);
    check(st == CBX_ERANGE && o.lo[0] == -HUGE_VAL && o.hi[0] == HUGE_VAL, "infinite end -> ERANGE axis", -1);
    st = cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 7, pc, 64, &np);
    check(st == CBX_EINVAL && np == 0, "pieces: 128 needed, cap 64 -> EINVAL", -1);
    st = cbx_transform_box_pieces(pc, 0, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "pieces: n = 0 -> EINVAL", -1);
    {
        double c[3] = { 1, 2, 3 }, cn[3] = { 1, NAN, 3 };
        st = cbx_motion_trs_ball(&k0, &k1, CBX_SLERP, 0, 1, 3, cn, 1.0, &o);
        check(st == CBX_EINVAL && is_whole(&o), "ball: NaN centre -> EINVAL", -1);
        st = cbx_motion_trs_ball(&k0, &k1, CBX_SLERP, 0, 1, 3, c, 0x1p501, &o);
        check(st == CBX_ERANGE && is_whole(&o), "ball: radius 2^501 -> ERANGE", -1);
        st = cbx_motion_trs_ball(&bad, &k1, CBX_SLERP, 0, 1, 3, c, 1.0, &o);
        check(st == CBX_ERANGE && is_whole(&o), "ball: tiny quaternion -> ERANGE", -1);
        {   /* pieces a caller filled: a NaN entry, an entry beyond 2^509 */
            cbx_imat bp[2];
            size_t nb = 0;
            cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 1, bp, 2, &nb);
            bp[1].lo[0][0] = NAN;
            st = cbx_ball_pieces(bp, nb, c, 1.0, &o);
            check(st == CBX_EINVAL && is_whole(&o), "ball pieces: NaN entry -> EINVAL", -1);
            bp[1].lo[0][0] = -0x1p600;
            st = cbx_ball_pieces(bp, nb, c, 1.0, &o);
            check(st == CBX_ERANGE && o.lo[0] == -HUGE_VAL && o.hi[0] == HUGE_VAL && box_finite_axis(&o, 1),
                  "ball pieces: entry 2^600 -> ERANGE on that axis", -1);
        }
        st = cbx_ball_pieces(pc, 0, c, 1.0, &o);
        check(st == CBX_EINVAL && is_whole(&o), "ball pieces: n = 0 -> EINVAL", -1);
        cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 2, pc, 64, &np);
        st = cbx_ball_pieces(pc, np, c, 0x1p501, &o);
        check(st == CBX_ERANGE && is_whole(&o), "ball pieces: radius 2^501 -> ERANGE", -1);
        st = cbx_ball_pieces(pc, 0, c, 1.0, &o);
        check(st == CBX_EINVAL && is_whole(&o), "ball pieces: n = 0 -> EINVAL", -1);
        st = cbx_motion_trs_ball(&k0, &k1, CBX_SLERP, 0, 1, 2, c, 0.0, &o);
        check(st == CBX_OK && box_finite(&o), "ball: radius 0 (a moving point)", -1);
    }
    /* instants and cell edges: s0 = s1 at 0, 1/2 (a cell edge) and 1 */
    {
        static const double inst[3] = { 0.0, 0.5, 1.0 };
        int m, q;
        for (q = 0; q < 2; q++) {
            for (m = 0; m < 3; m++) {
                int okk;
                st = cbx_motion_trs_box(&k0, &k1, q ? CBX_NLERP : CBX_SLERP, inst[m], inst[m], 3, &b, &o);
                ex_keys(e, &k0, &k1, q, 1);
                okk = sample_in(e, &k0, &k1, inst[m], &b, &o);
                ex_keys(e, &k0, &k1, q, -1);
                okk &= sample_in(e, &k0, &k1, inst[m], &b, &o);
                check(st == CBX_OK && okk, "instant: the exact image inside", -1);
            }
        }
    }
    /* pieces: bad keyframes, and boxes that are not ordinary */
    st = cbx_trs_pieces(&bad, &k1, CBX_SLERP, 0, 1, 3, pc, 64, &np);
    check(st == CBX_ERANGE && np == 0, "pieces: tiny quaternion -> ERANGE, none", -1);
    st = cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 3, pc, 64, &np);
    check(st == CBX_OK && np == 8, "pieces: 8 at depth 3", -1);
    o2 = b;
    o2.hi[0] = HUGE_VAL;
    st = cbx_transform_box_pieces(pc, np, &o2, &o);
    check(st == CBX_ERANGE && o.lo[0] == -HUGE_VAL && o.hi[0] == HUGE_VAL, "pieces: infinite end -> ERANGE", -1);
    o2 = b;
    o2.lo[2] = NAN;
    st = cbx_transform_box_pieces(pc, np, &o2, &o);
    check(st == CBX_EINVAL && is_whole(&o), "pieces: NaN box -> EINVAL", -1);
    o2 = b;
    o2.lo[2] = 5;
    st = cbx_transform_box_pieces(pc, np, &o2, &o);
    check(st == CBX_EMPTY && o.lo[0] == HUGE_VAL, "pieces: empty box -> EMPTY", -1);
    st = cbx_motion_trs_path(&k0, 0, CBX_SLERP, 0, 1, 3, &b, &o);
    check(st == CBX_EINVAL && is_whole(&o), "path: no keyframe -> EINVAL", -1);
    {
        cbx_trs ks[3];
        ks[0] = k0;
        ks[1] = k1;
        ks[2] = k0;
        st = cbx_motion_trs_path(ks, 3, CBX_SLERP, 0.7, 0.2, 3, &b, &o);
        check(st == CBX_EINVAL && is_whole(&o), "path: s0 > s1 -> EINVAL", -1);
        o2 = b;
        o2.lo[0] = 3;
        st = cbx_motion_trs_path(ks, 3, CBX_SLERP, 0, 1, 3, &o2, &o);
        check(st == CBX_EMPTY && o.lo[1] == HUGE_VAL && o.hi[1] == -HUGE_VAL, "path: empty box -> EMPTY", -1);
        ks[2].t[0] = NAN;
        st = cbx_motion_trs_path(ks, 3, CBX_SLERP, 0, 1, 3, &b, &o);
        check(st == CBX_EINVAL && is_whole(&o), "path: NaN keyframe -> EINVAL", -1);
    }
    st = cbx_motion_trs_path(&k0, 1, CBX_SLERP, 0, 1, 3, &b, &o);
    check(st == CBX_OK && o.lo[0] <= 0 && o.hi[0] >= 2, "path: one keyframe, still", -1);
}

/* ---- main --------------------------------------------------------------- */

#define NDEPTH 7
#define XEVERY 64 /* extremes on every 64th pair */
#define REVERY 16 /* the renderers' bounds on every 16th */

int main(int argc, char **argv)
{
    const char *usage = "[N keyframe pairs] [seed]";
    long n = (long)xu_arg_num(argc, argv, 1, 100000, usage);
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, usage);
    xu_rng r;
    exact e;
    long p, samples = 0, paths = 0, balls = 0;
    long miss_any[2] = { 0, 0 }, miss_geo[2] = { 0, 0 }, tested_rn = 0, per_cat[8];
    double miss_rel[2] = { 0, 0 };
    double ex_sum[2][NDEPTH], ex_max[2][NDEPTH];
    long ex_n[2][NDEPTH], extremes_n = 0;
    int i;
    memset(per_cat, 0, sizeof per_cat);
    memset(ex_sum, 0, sizeof ex_sum);
    memset(ex_max, 0, sizeof ex_max);
    memset(ex_n, 0, sizeof ex_n);
    r.s = UINT64_C(0x9e3779b97f4a7c15) ^ seed;
    ex_init(&e);
    printf("-- test_trs: motion with rotation (slerp / nlerp keyframes) against MPFR at %d bits, seed %llu --\n",
           PREC, (unsigned long long)seed);
    specials(&e);
    for (p = 0; p < n; p++) {
        cbx_trs k0, k1;
        cbx_box in, out, o2;
        double s0 = 0, s1 = 1, ts[9];
        unsigned depth = (unsigned)xu_rng_int(&r, 0, NDEPTH - 1);
        int nl = xu_rng_int(&r, 0, 3) == 0, k, ok = 1;
        cbx_interp mode = nl ? CBX_NLERP : CBX_SLERP;
        cbx_status st;
        int big;
        int cat = gen_pair(&r, &k0, &k1, &in, &big);
        per_cat[cat]++;
        if (xu_rng_int(&r, 0, 9) < 3) {
            s0 = xu_rng_unit(&r);
            s1 = xu_rng_unit(&r);
            if (s1 < s0) {
                double t = s0;
                s0 = s1;
                s1 = t;
            }
        }
        st = cbx_motion_trs_box(&k0, &k1, mode, s0, s1, depth, &in, &out);
        check(st == CBX_OK && box_finite(&out), "status OK, finite", p);
        if (st != CBX_OK) {
            continue;
        }
        /* samples */
        ex_keys(&e, &k0, &k1, nl, 0);
        ts[0] = s0;
        ts[1] = s1;
        for (k = 2; k < 9; k++) {
            ts[k] = s0 + (s1 - s0) * xu_rng_unit(&r);
        }
        for (k = 0; k < 9; k++) {
            ok &= sample_in(&e, &k0, &k1, ts[k], &in, &out);
        }
        samples += 9 * 8;
        check(ok, "sample: exact image inside", p);
        /* pieces give the same bits */
        {
            cbx_imat pc[260];
            size_t np = 0;
            cbx_status s2 = cbx_trs_pieces(&k0, &k1, mode, s0, s1, depth, pc, 260, &np);
            cbx_status s3 = cbx_transform_box_pieces(pc, np, &in, &o2);
            check(s2 == CBX_OK && s3 == st && same_box(&o2, &out), "pieces: same bits", p);
        }
        /* the ball around the box's centre, radius up to the box's size */
        {
            double c[3], rr = 0;
            cbx_box bo, bo2;
            cbx_imat pc[260];
            size_t np = 0;
            cbx_status sb, sb2;
            for (i = 0; i < 3; i++) {
                c[i] = 0.5 * (in.lo[i] + in.hi[i]);
                rr = fmax(rr, in.hi[i] - in.lo[i]);
            }
            rr *= xu_rng_unit(&r) * (xu_rng_int(&r, 0, 1) ? 1 : -1); /* |r| counts */
            sb = cbx_motion_trs_ball(&k0, &k1, mode, s0, s1, depth, c, rr, &bo);
            check(sb == CBX_OK && box_finite(&bo), "ball: status OK, finite", p);
            ok = 1;
            for (k = 0; k < 9; k++) {
                ok &= ball_in(&e, &k0, &k1, ts[k], c, rr, &bo);
            }
            balls += 9;
            check(ok, "ball: exact image inside", p);
            cbx_trs_pieces(&k0, &k1, mode, s0, s1, depth, pc, 260, &np);
            sb2 = cbx_ball_pieces(pc, np, c, rr, &bo2);
            check(sb2 == sb && same_box(&bo2, &bo), "ball: pieces give the same bits", p);
        }
        /* alias */
        o2 = in;
        st = cbx_motion_trs_box(&k0, &k1, mode, s0, s1, depth, &o2, &o2);
        check(st == CBX_OK && same_box(&o2, &out), "alias: same bits", p);
        /* extremes and excess */
        if (p % XEVERY == 0) {
            mpfr_t best[3][2];
            int ax;
            for (ax = 0; ax < 3; ax++) {
                mpfr_inits2(PREC, best[ax][0], best[ax][1], (mpfr_ptr)0);
            }
            extremes(&e, best, &k0, &k1, s0, s1, &in);
            {
                double lo[3], hi[3], side = 0;
                for (ax = 0; ax < 3; ax++) {
                    lo[ax] = -mpfr_get_d(best[ax][0], MPFR_RNDN);
                    hi[ax] = mpfr_get_d(best[ax][1], MPFR_RNDN);
                    side = fmax(side, hi[ax] - lo[ax]);
                    check(mpfr_cmp_d(best[ax][1], out.hi[ax]) <= 0, "extreme: max inside", p);
                    check(mpfr_cmp_d(best[ax][0], -out.lo[ax]) <= 0, "extreme: min inside", p);
                    extremes_n += 2;
                }
                /* excess: typical scenes (no 180-degree tie, no 1e12 lever) */
                for (ax = 0; ax < 3 && cat != 6 && !big && side > 0; ax++) {
                    double x = fmax(lo[ax] - out.lo[ax], out.hi[ax] - hi[ax]) / side;
                    int bin = cat <= 2 ? 0 : 1;
                    if (x > 10.0 / (double)(1 << depth) + 0.02 && n_logs < MAX_LOGS) {
                        printf("  excess %.3g of the longest side: depth %u, rotation class %d, %s, axis %d, "
                               "shutter [%g, %g]\n", x, depth, cat, nl ? "nlerp" : "slerp", ax, s0, s1);
                    }
                    check(x <= 10.0 / (double)(1 << depth) + 0.02, "tight: excess within 10 / 2^depth + 2%", p);
                    ex_sum[bin][depth] += x;
                    ex_n[bin][depth]++;
                    if (x > ex_max[bin][depth]) {
                        ex_max[bin][depth] = x;
                    }
                }
            }
            for (ax = 0; ax < 3; ax++) {
                mpfr_clears(best[ax][0], best[ax][1], (mpfr_ptr)0);
            }
        }
        /* the renderers' bounds on the same pair (full shutter only) */
        if (p % REVERY == 0 && s0 == 0 && s1 == 1) {
            double t2[2] = { 0, 1 }, t128[128], side = 0;
            cbx_box rb;
            int kk, which;
            for (kk = 0; kk < 128; kk++) {
                t128[kk] = kk / 128.0; /* Cycles: never at t = 1 */
            }
            for (i = 0; i < 3; i++) {
                side = fmax(side, out.hi[i] - out.lo[i]);
            }
            tested_rn++;
            for (which = 0; which < 2; which++) {
                double worst = -HUGE_VAL;
                if (which == 0) {
                    ref_trs_samples(&k0, &k1, nl, t2, 2, &in, &rb);
                } else {
                    ref_trs_samples(&k0, &k1, nl, t128, 128, &in, &rb);
                }
                /* exact samples between the renderers' times, and s = 1 */
                for (kk = 1; kk <= 17; kk++) {
                    double sd = kk == 17 ? 1.0 : (16.0 * kk - 1.0) / 256.0;
                    worst = fmax(worst, sample_miss(&e, &k0, &k1, sd, &in, &rb));
                }
                if (worst > 0) {
                    miss_any[which]++;
                    if (worst > 1e-9 * side) {
                        miss_geo[which]++;
                    }
                    miss_rel[which] = fmax(miss_rel[which], worst / side);
                }
            }
        }
        /* paths of 3 to 5 keyframes */
        if (p % 16 == 0) {
            cbx_trs keys[5];
            int nk = xu_rng_int(&r, 3, 5), j;
            cbx_box pb;
            keys[0] = k0;
            keys[1] = k1;
            for (j = 2; j < nk; j++) {
                cbx_trs a, b;
                cbx_box dummy;
                int bg;
                gen_pair(&r, &a, &b, &dummy, &bg);
                keys[j] = b;
            }
            st = cbx_motion_trs_path(keys, (size_t)nk, mode, s0, s1, depth, &in, &pb);
            check(st == CBX_OK && box_finite(&pb), "path: status OK", p);
            ok = 1;
            for (k = 0; k < 9; k++) {
                double s = k == 0 ? s0 : k == 8 ? s1 : s0 + (s1 - s0) * xu_rng_unit(&r);
                /* the segment of s and its local time (exact: m s - i in MPFR) */
                double m = nk - 1;
                long seg;
                mpfr_t ls;
                mpfr_init2(ls, PREC);
                mpfr_set_d(ls, s, MPFR_RNDN);
                mpfr_mul_d(ls, ls, m, MPFR_RNDN); /* exact */
                seg = mpfr_get_si(ls, MPFR_RNDD);
                if (seg >= nk - 1) {
                    seg = nk - 2;
                }
                mpfr_sub_si(ls, ls, seg, MPFR_RNDN);
                ex_keys(&e, &keys[seg], &keys[seg + 1], nl, 0);
                {
                    mpfr_t v;
                    int cc, ii;
                    mpfr_init2(v, PREC);
                    ex_at(&e, &keys[seg], &keys[seg + 1], ls, &in);
                    for (cc = 0; cc < 8; cc++) {
                        for (ii = 0; ii < 3; ii++) {
                            ex_coord(&e, v, cc, ii);
                            if (mpfr_cmp_d(v, pb.lo[ii]) < 0 || mpfr_cmp_d(v, pb.hi[ii]) > 0) {
                                ok = 0;
                            }
                        }
                    }
                    mpfr_clear(v);
                }
                mpfr_clear(ls);
            }
            check(ok, "path: exact image inside", p);
            paths++;
        }
    }
    printf("keyframe pairs: %ld (by rotation: 0 deg %ld, 1e-9 %ld, 1e-4 %ld, 45 %ld, 90 %ld, 179.9 %ld, "
           "180 %ld, random %ld)\n", n, per_cat[0], per_cat[1], per_cat[2], per_cat[3], per_cat[4],
           per_cat[5], per_cat[6], per_cat[7]);
    printf("exact corner samples checked: %ld; exact extremes checked: %ld; paths: %ld; "
           "ball samples (6 extreme points each): %ld\n", samples, extremes_n, paths, balls);
    printf("excess of each end beyond the exact extreme, share of the exact image's longest side\n"
           "(the larger of an axis's two ends; no 180-degree ties, no 1e12 translations), by depth:\n  rotations up to 1e-4 deg | 45 deg and more\n");
    for (i = 0; i < NDEPTH; i++) {
        printf("  depth %d (%2d cells): mean %7.3f%%, max %7.3f%% (%4ld axes) | mean %6.2f%%, max %6.2f%% (%4ld axes)\n",
               i, 1 << i, ex_n[0][i] ? 100 * ex_sum[0][i] / (double)ex_n[0][i] : 0.0, 100 * ex_max[0][i],
               ex_n[0][i], ex_n[1][i] ? 100 * ex_sum[1][i] / (double)ex_n[1][i] : 0.0, 100 * ex_max[1][i],
               ex_n[1][i]);
    }
    printf("renderers' bounds (round to nearest) on %ld full-shutter pairs, checked at 17 exact times between "
           "their samples and at s = 1:\n", tested_rn);
    for (i = 0; i < 2; i++) {
        printf("  %-34s misses the exact image in %5.1f%% of the pairs (by more than 1e-9 of the box: "
               "%5.1f%%), by up to %.3g of the box's longest side\n",
               i == 0 ? "union of the boxes at s0 and s1:" : "8 corners at 128 samples (Cycles):",
               tested_rn ? 100.0 * (double)miss_any[i] / (double)tested_rn : 0.0,
               tested_rn ? 100.0 * (double)miss_geo[i] / (double)tested_rn : 0.0, miss_rel[i]);
    }
    printf("%ld passed, %ld failed\n", n_check - n_fail, n_fail);
    ex_clear(&e);
    mpfr_free_cache();
    return n_fail != 0;
}
