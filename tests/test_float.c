/*
 * test_float [N] [seed]: the binary32 (float) family against exact rational
 * arithmetic.  The oracle is exact_util in its binary32 format
 * (xu_set_format(&xu_binary32): u = 2^-24, eta = 2^-149, domain bound
 * 2^122, classes (2^k, 2^(122-k)), proven tightness 12 u S + 2^-140): the
 * same code that checks the binary64 family in test_exact, so both
 * families are held to the same rules.  Every float is held exactly in a
 * double for the oracle; every generated value is checked to be a float.
 *
 *  1. cbx_transform_boxf: a table of binary32 hard cases (class corners,
 *     2^122, FLT_MAX, subnormals, half-spaces, cancellation), then N random
 *     cases drawn by xu_gen_case (the generator of test_exact, binary32
 *     values): status, every field written, EINVAL/EMPTY outputs, each
 *     end's kind (full row, vertex, unbounded, lost, whole line), exact
 *     containment, the proven bound 12 u S + 2^-140 (exactly), the 8 corners
 *     with mpq on every 50th case, inputs unchanged, and the in-place call
 *     (out == in) bit for bit.
 *  2. cbx_transform_boxesf: N/100 batches (sizes 0, 1, 2, 7, 100) under one
 *     map, every out[k] bit for bit against the single call, the most
 *     severe status, nothing written past out[n-1].
 *  2b. Prepared maps: N/100 + 20 batches (sizes 0, 1, 2, 7, 100; maps of
 *     xu_gen_case, a quarter with entries at the fast range's edge 2^61,
 *     2^122 or the next float), and every row of the special-value table
 *     (6) as a batch of one box.  cbx_preparef into a struct of garbage:
 *     the map copied bit for bit, the fast flag set iff every linear entry
 *     is at most 2^61 and every translation at most 2^122 in magnitude.
 *     The structs: cbx_preparef's; zero-initialised (= { 0 }) with the map
 *     set by hand; cls forged (a value of xu_cls_values, fast kept or
 *     cleared); fast and cls forged (fast = 1 whatever the map).
 *     cbx_transform_box_prepf (not on the fast-forged struct: it trusts the
 *     flag) bit for bit and status against cbx_transform_boxf, and in
 *     place; cbx_transform_boxes_prepf bit for bit and status against
 *     cbx_transform_boxesf, nothing written past out[n-1], *p unchanged;
 *     the boxes of the forged structs against the exact oracle.
 *  3. cbx_transform_cboxf: N/2 random cases (zero columns against infinite
 *     or huge centers and half-widths included): status and each axis's
 *     kind (full, dropped, lost), exact containment of [c-h, c+h] of the
 *     image of the input box, the proven bound 12 u S + 2^-140, in place.
 *  4. cbx_box_to_cboxf, cbx_cbox_to_boxf: N/2 cases each: status, kinds,
 *     exact containment of the input's real box.
 *  5. cbx_sphere_boxf, cbx_ellipsoid_boxf: N/2 cases each: status, kinds,
 *     exact containment of t -+ sqrt(sum m_ij^2) (equivalent to containing
 *     every point of the ball), the ellipsoid's rows as exact products, and
 *     the proven tightness 80 u (|t| + sqrt s) + 2^-139 of each end, exactly.
 *  6. A special-value table: every function x every input position x 32
 *     binary32 values (NaN, +-inf, +-0, subnormals, FLT_MAX, the domain
 *     limits 2^30, 2^61, 2^122, 2^123 and the next float beyond each) on an
 *     ordinary base input, through the same checks.
 * Tightness is measured in units of u S + eta (u = 2^-24, eta = 2^-149).
 * The last line is "N passed, M failed" (read by CI).
 * This file is the driver, with the special-value table (6); sections 1 to
 * 5 are in tests/float_box.c, float_cbox.c and float_ball.c, the tallies
 * and conversions in tests/float_util.c (tests/float_parts.h).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "certbox.h"
#include "exact_util.h"

#include "float_parts.h"

/* ---- 6. the special-value table --------------------------------------- */

static const double specials[] = {
    NAN, -NAN, HUGE_VAL, -HUGE_VAL, 0.0, -0.0, 0x1p-149, -0x1p-149, 0x1p-126, -0x1p-126,
    FLT_MAX, -FLT_MAX, 1.0, -1.0,
    0x1p30, 0x1.000002p30, -0x1p30, 0x1p61, 0x1.000002p61, -0x1p61, -0x1.000002p61,
    0x1p122, 0x1.000002p122, -0x1p122, -0x1.000002p122,
    0x1p123, 0x1.000002p123, -0x1p123, -0x1.000002p123, 0x1p-30, 3e-39f, 1e38f,
};
#define N_SPECIAL ((int)(sizeof specials / sizeof specials[0]))

static long special_rows;

static void run_specials(xu_exact *x, xu_stats *all)
{
    static const cbx_affine base_a = MAT(ROW(0.5f, -2, 0.25f, 1), ROW(0, 1.5f, -1, -3),
                                         ROW(4, 0, 0.125f, 0.75f));
    static const cbx_box base_b = BOX(-1, 2, 0.5f, 3, -4, -2);
    static const double base_cen[3] = { 1, -2, 3 }, base_rad[3] = { 2, 0.5f, 1 };
    static const double base_rot[3][3] = { { 0.6f, -0.8f, 0 }, { 0.8f, 0.6f, 0 }, { 0, 0, 1 } };
    int v, p;
    char what[64];
    for (v = 0; v < N_SPECIAL; v++) {
        double s = specials[v];
        for (p = 0; p < 18; p++) { /* transform_box: 12 map entries, 6 box ends */
            cbx_affine a = base_a;
            cbx_box b = base_b;
            cbx_cbox c;
            int j;
            if (p < 12) a.m[p / 4][p % 4] = s;
            else if (p < 15) b.lo[p - 12] = s;
            else b.hi[p - 15] = s;
            snprintf(what, sizeof what, "special box pos %d value %a", p, s);
            flt_run_box(x, all, &a, &b, 1, what);
            flt_run_prep(x, &a, &b, 1, v * 18 + p, 0, XU_NCLS_VALUES, what);
            for (j = 0; j < 3; j++) { c.c[j] = base_b.lo[j]; c.h[j] = 1.5f; }
            if (p >= 12 && p < 15) c.c[p - 12] = s;
            else if (p >= 15) c.h[p - 15] = s;
            flt_run_cbox(x, &a, &c, what);
            if (p >= 12) {
                flt_run_b2c(x, &b, what);
                flt_run_c2b(x, &c, what);
            }
            special_rows += 2 + (p >= 12) * 2;
        }
        for (p = 0; p < 12; p++) {
            cbx_affine a = base_a;
            a.m[p / 4][p % 4] = s;
            snprintf(what, sizeof what, "special sphere pos %d value %a", p, s);
            flt_run_sphere(x, &a, what);
            special_rows++;
        }
        for (p = 0; p < 15; p++) {
            double cen[3], rad[3], rot[3][3];
            memcpy(cen, base_cen, sizeof cen);
            memcpy(rad, base_rad, sizeof rad);
            memcpy(rot, base_rot, sizeof rot);
            if (p < 3) cen[p] = s;
            else if (p < 6) rad[p - 3] = s;
            else rot[(p - 6) / 3][(p - 6) % 3] = s;
            snprintf(what, sizeof what, "special ellipsoid pos %d value %a", p, s);
            flt_run_ellipsoid(x, cen, rad, (const double (*)[3])rot, what);
            special_rows++;
        }
    }
}

/* ---- driver ------------------------------------------------------------ */

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 200000, "test_float [N] [seed]");
    uint64_t seed = xu_arg_num(argc, argv, 2, 1, "test_float [N] [seed]");
    xu_exact x;
    xu_stats all;
    xu_rng r;
    long c, failed;
    int k;
    static const int sizes[] = { 0, 1, 2, 7, 100 };

    xu_set_format(&xu_binary32);
    xu_init(&x);
    xu_stats_init(&all);
    r.s = seed;
    printf("test_float: the binary32 family against exact rationals "
           "(u = 2^-24, eta = 2^-149), N = %ld, seed = %llu\n", n, (unsigned long long)seed);

    for (k = 0; k < flt_n_box_hard; k++) flt_run_box(&x, &all, &flt_box_hard[k].a, &flt_box_hard[k].in, 1, flt_box_hard[k].name);
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_box b;
        char what[48];
        xu_gen_case(&r, &a, &b);
        snprintf(what, sizeof what, "random box case %ld", c);
        flt_run_box(&x, &all, &a, &b, c % 50 == 0, what);
    }
    for (c = 0; c < n / 100 + 5; c++) flt_run_batch(&r, sizes[c % 5]);
    {   /* its own generator: the draws of the sections below stay as they were */
        xu_rng rp;
        rp.s = UINT64_C(0x9e3779b97f4a7c15) ^ seed;
        for (c = 0; c < n / 100 + 20; c++) flt_prep_case(&x, &rp, sizes[c % 5], c);
    }
    for (c = 0; c < n / 2; c++) {
        cbx_affine a;
        cbx_cbox cb;
        cbx_box b;
        char what[48];
        flt_gen_cbox(&r, &a, &cb);
        snprintf(what, sizeof what, "random cbox case %ld", c);
        flt_run_cbox(&x, &a, &cb, what);
        xu_gen_case(&r, &a, &b);
        flt_run_b2c(&x, &b, what);
        flt_run_c2b(&x, &cb, what);
    }
    for (c = 0; c < n / 2; c++) {
        cbx_affine a;
        double cen[3], rad[3], rot[3][3];
        char what[48];
        int i, j;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = flt_gen_ball_entry(&r);
            a.m[i][3] = xu_rng_int(&r, 0, 19) == 0 ? xu_rng_sign(&r) * 0x1p122
                                                   : xu_gen_signed(&r, -149, 100);
        }
        if (xu_rng_int(&r, 0, 3) == 0) { /* a rotation times a scale: the common case */
            double R[3][3], sc = xu_gen_mag(&r, -20, 20);
            flt_rand_rot_f(&r, R);
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) a.m[i][j] = xu_round_fmt(R[i][j] * sc);
        }
        snprintf(what, sizeof what, "random sphere case %ld", c);
        flt_run_sphere(&x, &a, what);
        flt_rand_rot_f(&r, rot);
        for (i = 0; i < 3; i++) {
            cen[i] = xu_rng_int(&r, 0, 19) == 0 ? xu_rng_sign(&r) * 0x1.000002p122
                                                : xu_gen_signed(&r, -149, 110);
            rad[i] = xu_rng_int(&r, 0, 24) == 0 ? xu_rng_sign(&r) * 0x1.000002p30
                                                : xu_gen_signed(&r, -149, 30);
        }
        if (xu_rng_int(&r, 0, 9) == 0) rot[xu_rng_int(&r, 0, 2)][xu_rng_int(&r, 0, 2)] = xu_gen_signed(&r, -149, 31);
        snprintf(what, sizeof what, "random ellipsoid case %ld", c);
        flt_run_ellipsoid(&x, cen, rad, (const double (*)[3])rot, what);
    }
    run_specials(&x, &all);

    xu_stats_print(stdout, "cbx_transform_boxf (oracle: exact_util, binary32)", &all);
    printf("per function (binary32 family):\n");
    flt_fs_print(&flt_st_box);
    flt_fs_print(&flt_st_inpl);
    flt_fs_print(&flt_st_batch);
    flt_fs_print(&flt_st_prep);
    flt_fs_print(&flt_st_prep1);
    flt_fs_print(&flt_st_prepn);
    printf("  prepared maps: %ld prepared (%ld in the fast range); structs: cbx_preparef's, "
           "zero-initialised, cls forged, fast+cls forged (cls over the %d values of "
           "xu_cls_values); boxes of the forged structs against the exact oracle: %ld\n",
           flt_st_prep.cases, flt_prep_fast, XU_NCLS_VALUES, flt_prep_exact);
    flt_fs_print(&flt_st_cbox);
    flt_fs_print(&flt_st_b2c);
    flt_fs_print(&flt_st_c2b);
    flt_fs_print(&flt_st_sph);
    flt_fs_print(&flt_st_ell);
    printf("  special-value rows: %ld (%d values x every input position x every function)\n",
           special_rows, N_SPECIAL);
    printf("  generated values that were not floats: %ld\n", flt_not_float);
    failed = flt_st_box.failed + flt_st_inpl.failed + flt_st_batch.failed + flt_st_prep.failed + flt_st_prep1.failed
             + flt_st_prepn.failed + flt_st_cbox.failed + flt_st_b2c.failed + flt_st_c2b.failed + flt_st_sph.failed
             + flt_st_ell.failed + (flt_not_float != 0);
    c = flt_st_box.cases + flt_st_inpl.cases + flt_st_batch.cases + flt_st_prep.cases + flt_st_prep1.cases
        + flt_st_prepn.cases + flt_st_cbox.cases + flt_st_b2c.cases + flt_st_c2b.cases + flt_st_sph.cases
        + flt_st_ell.cases;
    xu_clear(&x);
    printf("%ld passed, %ld failed\n", c - failed, failed);
    return failed != 0;
}
