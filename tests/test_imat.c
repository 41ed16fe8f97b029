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
 *
 * This file is the driver (the arguments, the two suites, the report);
 * its parts, declared in tests/imat_parts.h: the checks in
 * tests/imat_check.c, the inputs in tests/imat_gen.c, the teeth in
 * tests/imat_teeth.c.
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
#include "imat_parts.h"

#define MAX_FAIL_LOGS 20
#define DEEP_EVERY 8    /* cross and points on every 8th case */

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
        imt_gen_imat(r, &a, 1018);
        imt_gen_box(r, &in);
        if (xu_rng_int(r, 0, 9) == 0) { /* a point matrix, in range */
            point = 1;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++) a.hi[i][j] = a.lo[i][j];
        }
        for (i = 0; i < 3; i++)
            if (xu_rng_int(r, 0, 9) == 0) imt_cancel_t(r, &a, &in, i);
        if (point) {
            for (i = 0; i < 3; i++) a.hi[i][3] = a.lo[i][3];
        } else {
            pushed += imt_perturb(r, &a, &in, NULL);
            if (xu_rng_int(r, 0, 99) < 4) imt_make_empty(r, &in);
        }
        a0 = a;
        in0 = in;
        for (j = 0; j < 3; j++) out.lo[j] = out.hi[j] = NAN;
        got = cbx_transform_box_imat(&a, &in, &out);
        memset(tt.why, 0, sizeof tt.why);
        f = imt_check_transform(&k, &tt, &ext, &a0, &in0, &out, got, deep, &exp);
        st_seen[0][xu_status_index(exp)]++;
        if (exp == CBX_OK || exp == CBX_ERANGE)
            for (i = 0; i < 3; i++) {
                row rr = imt_trow(&a0, i, &in0);
                if (imt_row_fast(&rr)) fast_coords[0]++; else whole_coords[0]++;
            }
        f += imt_tick(&tt, C_INPUT, memcmp(&a, &a0, sizeof a) == 0 && memcmp(&in, &in0, sizeof in) == 0,
                      "an input changed", -1);
        io = in0;
        got2 = cbx_transform_box_imat(&a0, &io, &io);
        f += imt_tick(&tt, C_ALIAS, got2 == got && memcmp(&io, &out, sizeof io) == 0,
                      "out == in differs from out != in", -1);
        if (f) {
            failed_cases++;
            if (logs++ < MAX_FAIL_LOGS) {
                printf("FAIL box case %ld: %s (status %s, expected %s)\n", c, tt.why,
                       cbx_status_name(got), cbx_status_name(exp));
                imt_print_imat("a", &a0);
                imt_print_box("in", &in0);
                imt_print_box("out", &out);
            }
        }
        imt_teeth_transform(&k, &a0, &in0, &out, got);
        /* point matrices: the same map through cbx_transform_box */
        if (point && got == CBX_OK) {
            cbx_affine aff;
            cbx_box o2;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++) aff.m[i][j] = a0.lo[i][j];
            if (cbx_transform_box(&aff, &in0, &o2) == CBX_OK)
                for (i = 0; i < 3; i++) {
                    row rr = imt_trow(&a0, i, &in0);
                    imt_row_exact(&k, &rr);
                    int tiny = xu_scale_tiny(k.S);
                    double e1, e2;
                    xu_scaled_d(&k.x, k.z, out.lo[i]);
                    mpz_sub(k.g, k.L, k.z);
                    e1 = xu_units(&k.x, k.g, k.S);
                    imt_ex_add(&ex_pt_imat, e1, tiny);
                    xu_scaled_d(&k.x, k.z, o2.lo[i]);
                    mpz_sub(k.g2, k.L, k.z);
                    e2 = xu_units(&k.x, k.g2, k.S);
                    imt_ex_add(&ex_pt_aff, e2, tiny);
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
        imt_gen_imat(r, &a, 1018);
        imt_gen_imat(r, &b, 509);      /* b's columns are the "box": within 2^509 */
        pushed += imt_perturb(r, &a, NULL, &b);
        a0 = a;
        b0 = b;
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) out.lo[i][j] = out.hi[i][j] = NAN;
        got = cbx_imat_compose(&a, &b, &out);
        memset(tc.why, 0, sizeof tc.why);
        f = imt_check_compose(&k, &tc, &exc, &a0, &b0, &out, got, deep, &exp);
        st_seen[1][xu_status_index(exp)]++;
        if (exp != CBX_EINVAL)
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++) {
                    row rr = imt_crow(&a0, &b0, i, j);
                    if (imt_row_fast(&rr)) fast_coords[1]++; else whole_coords[1]++;
                }
        f += imt_tick(&tc, C_INPUT, memcmp(&a, &a0, sizeof a) == 0 && memcmp(&b, &b0, sizeof b) == 0,
                      "an input changed", -1);
        if (c % 2 == 0 && exp != CBX_EINVAL && imt_has_real(&a0) && imt_has_real(&b0)) {
            f += imt_check_product(&k, &tc, &a0, &b0, &out, A, B);
            products++;
        }
        if (f) {
            failed_cases++;
            if (logs++ < MAX_FAIL_LOGS) {
                printf("FAIL compose case %ld: %s (status %s, expected %s)\n", c, tc.why,
                       cbx_status_name(got), cbx_status_name(exp));
                imt_print_imat("a", &a0);
                imt_print_imat("b", &b0);
                imt_print_imat("out", &out);
            }
        }
        if (imt_teeth_n[T_PRODUCT] < TEETH_MAX) imt_teeth_product(&k, A, B);
    }
    double t_all = (double)(clock() - t0) / CLOCKS_PER_SEC;

    /* ---- report ---- */
    long nfail_checks = 0, nchecks = imt_checks_of(&tt, &nfail_checks) + imt_checks_of(&tc, &nfail_checks);
    long tn = 0, tcaught = 0;
    printf("\nboxes: %ld cases (%ld with point matrices taken through cbx_transform_box too); "
           "expected OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n",
           n, pt_axes / 3, st_seen[0][0], st_seen[0][1], st_seen[0][2], st_seen[0][3]);
    printf("  axes in the fast range %ld, outside (whole line) %ld\n", fast_coords[0], whole_coords[0]);
    imt_print_tally(&tt);
    imt_print_ex("cbx_transform_box_imat", &ext);
    printf("\ncompositions: %ld cases; expected OK %ld, EINVAL %ld, ERANGE %ld; %ld with the product check\n",
           m, st_seen[1][0], st_seen[1][2], st_seen[1][3], products);
    printf("  entries in the fast range %ld, outside (whole line) %ld\n", fast_coords[1], whole_coords[1]);
    imt_print_tally(&tc);
    imt_print_ex("cbx_imat_compose", &exc);
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
        printf(" %s %ld/%ld%s", imt_t_name[i], imt_teeth_caught[i], imt_teeth_n[i], i + 1 < NT ? "," : "\n");
        tn += imt_teeth_n[i];
        tcaught += imt_teeth_caught[i];
        if (imt_teeth_n[i] == 0) {
            printf("FAIL teeth: no doctored result of kind '%s' was made\n", imt_t_name[i]);
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
