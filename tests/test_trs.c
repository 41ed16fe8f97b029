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
 * This file is the driver (the arguments, the random pairs' checks in
 * order, the summary); the exact motion and its checks, the generators and
 * the special cases are in tests/trs_exact.c, trs_gen.c and trs_special.c
 * (tests/trs_parts.h).
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

#include "trs_parts.h"

/* ---- the renderers' bounds (round to nearest) --------------------------- */

/* The renderers' methods (bench/bench_ref.h), with these functions. */
#define REF_SIN(x) trt_cr_fn(mpfr_sin, (x))
#define REF_ACOS(x) trt_cr_fn(mpfr_acos, (x))
#include "../bench/bench_ref.h"

static int same_box(const cbx_box *a, const cbx_box *b) { return memcmp(a, b, sizeof *a) == 0; }

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
    trt_ex_init(&e);
    printf("-- test_trs: motion with rotation (slerp / nlerp keyframes) against MPFR at %d bits, seed %llu --\n",
           PREC, (unsigned long long)seed);
    trt_specials(&e);
    for (p = 0; p < n; p++) {
        cbx_trs k0, k1;
        cbx_box in, out, o2;
        double s0 = 0, s1 = 1, ts[9];
        unsigned depth = (unsigned)xu_rng_int(&r, 0, NDEPTH - 1);
        int nl = xu_rng_int(&r, 0, 3) == 0, k, ok = 1;
        cbx_interp mode = nl ? CBX_NLERP : CBX_SLERP;
        cbx_status st;
        int big;
        int cat = trt_gen_pair(&r, &k0, &k1, &in, &big);
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
        trt_check(st == CBX_OK && trt_box_finite(&out), "status OK, finite", p);
        if (st != CBX_OK) {
            continue;
        }
        /* samples */
        trt_ex_keys(&e, &k0, &k1, nl, 0);
        ts[0] = s0;
        ts[1] = s1;
        for (k = 2; k < 9; k++) {
            ts[k] = s0 + (s1 - s0) * xu_rng_unit(&r);
        }
        for (k = 0; k < 9; k++) {
            ok &= trt_sample_in(&e, &k0, &k1, ts[k], &in, &out);
        }
        samples += 9 * 8;
        trt_check(ok, "sample: exact image inside", p);
        /* pieces give the same bits */
        {
            cbx_imat pc[260];
            size_t np = 0;
            cbx_status s2 = cbx_trs_pieces(&k0, &k1, mode, s0, s1, depth, pc, 260, &np);
            cbx_status s3 = cbx_transform_box_pieces(pc, np, &in, &o2);
            trt_check(s2 == CBX_OK && s3 == st && same_box(&o2, &out), "pieces: same bits", p);
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
            trt_check(sb == CBX_OK && trt_box_finite(&bo), "ball: status OK, finite", p);
            ok = 1;
            for (k = 0; k < 9; k++) {
                ok &= trt_ball_in(&e, &k0, &k1, ts[k], c, rr, &bo);
            }
            balls += 9;
            trt_check(ok, "ball: exact image inside", p);
            cbx_trs_pieces(&k0, &k1, mode, s0, s1, depth, pc, 260, &np);
            sb2 = cbx_ball_pieces(pc, np, c, rr, &bo2);
            trt_check(sb2 == sb && same_box(&bo2, &bo), "ball: pieces give the same bits", p);
        }
        /* alias */
        o2 = in;
        st = cbx_motion_trs_box(&k0, &k1, mode, s0, s1, depth, &o2, &o2);
        trt_check(st == CBX_OK && same_box(&o2, &out), "alias: same bits", p);
        /* extremes and excess */
        if (p % XEVERY == 0) {
            mpfr_t best[3][2];
            int ax;
            for (ax = 0; ax < 3; ax++) {
                mpfr_inits2(PREC, best[ax][0], best[ax][1], (mpfr_ptr)0);
            }
            trt_extremes(&e, best, &k0, &k1, s0, s1, &in);
            {
                double lo[3], hi[3], side = 0;
                for (ax = 0; ax < 3; ax++) {
                    lo[ax] = -mpfr_get_d(best[ax][0], MPFR_RNDN);
                    hi[ax] = mpfr_get_d(best[ax][1], MPFR_RNDN);
                    side = fmax(side, hi[ax] - lo[ax]);
                    trt_check(mpfr_cmp_d(best[ax][1], out.hi[ax]) <= 0, "extreme: max inside", p);
                    trt_check(mpfr_cmp_d(best[ax][0], -out.lo[ax]) <= 0, "extreme: min inside", p);
                    extremes_n += 2;
                }
                /* excess: typical scenes (no 180-degree tie, no 1e12 lever) */
                for (ax = 0; ax < 3 && cat != 6 && !big && side > 0; ax++) {
                    double x = fmax(lo[ax] - out.lo[ax], out.hi[ax] - hi[ax]) / side;
                    int bin = cat <= 2 ? 0 : 1;
                    if (x > 10.0 / (double)(1 << depth) + 0.02 && trt_n_logs < MAX_LOGS) {
                        printf("  excess %.3g of the longest side: depth %u, rotation class %d, %s, axis %d, "
                               "shutter [%g, %g]\n", x, depth, cat, nl ? "nlerp" : "slerp", ax, s0, s1);
                    }
                    trt_check(x <= 10.0 / (double)(1 << depth) + 0.02, "tight: excess within 10 / 2^depth + 2%", p);
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
                    worst = fmax(worst, trt_sample_miss(&e, &k0, &k1, sd, &in, &rb));
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
                trt_gen_pair(&r, &a, &b, &dummy, &bg);
                keys[j] = b;
            }
            st = cbx_motion_trs_path(keys, (size_t)nk, mode, s0, s1, depth, &in, &pb);
            trt_check(st == CBX_OK && trt_box_finite(&pb), "path: status OK", p);
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
                trt_ex_keys(&e, &keys[seg], &keys[seg + 1], nl, 0);
                {
                    mpfr_t v;
                    int cc, ii;
                    mpfr_init2(v, PREC);
                    trt_ex_at(&e, &keys[seg], &keys[seg + 1], ls, &in);
                    for (cc = 0; cc < 8; cc++) {
                        for (ii = 0; ii < 3; ii++) {
                            trt_ex_coord(&e, v, cc, ii);
                            if (mpfr_cmp_d(v, pb.lo[ii]) < 0 || mpfr_cmp_d(v, pb.hi[ii]) > 0) {
                                ok = 0;
                            }
                        }
                    }
                    mpfr_clear(v);
                }
                mpfr_clear(ls);
            }
            trt_check(ok, "path: exact image inside", p);
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
    printf("%ld passed, %ld failed\n", trt_n_check - trt_n_fail, trt_n_fail);
    trt_ex_clear(&e);
    mpfr_free_cache();
    return trt_n_fail != 0;
}
