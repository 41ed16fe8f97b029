/*
 * test_batch [N] [seed]: cbx_transform_boxes (the batch form) against
 * the class kernel cbx_transform_box_as(a, cbx_classify(a), ...) called once
 * per box (the batch classifies the map once; the class kernels have
 * cbx_transform_box's promise and are checked against it, and against the
 * exact oracle, in tests/test_classes).
 *
 * The promise (certbox.h): out[k] has cbx_transform_box's promise for
 * in[k] under *a, for k = 0 .. n-1; the result is the most severe status met,
 * CBX_EINVAL > CBX_ERANGE > CBX_EMPTY > CBX_OK, and CBX_OK for n == 0; only
 * out[0 .. n-1] is written.
 *
 * Batches: for each of N rounds (default 200), one random map and one batch
 * of each size n = 0, 1, 2, 7, 1000 and of one random size in [0, 64], the
 * boxes a random mix (the mix itself drawn per batch, so that some batches
 * are all-normal and some all-special) of: normal boxes in the domain, NaN
 * boxes, empty boxes (hi < lo, lo = +inf, hi = -inf), boxes with a huge end
 * outside the domain, half-space boxes (infinite ends), zero-width boxes.
 * The maps: ordinary, with zero / -0.0 columns, with an infinite entry
 * (CBX_ERANGE rows), with a NaN (every box CBX_EINVAL), with huge entries.
 * Then every ordered sequence of 3 boxes drawn from {normal, empty,
 * out-of-domain, NaN} (64 batches, the severity rule in every order), and
 * n = 0 with null pointers (the contract's ranges are empty).
 *
 * Checks per batch:
 *   bits     memcmp(out[k], cbx_transform_box's output for in[k]) == 0
 *            for every k (the reference out is pre-filled differently, so
 *            an unwritten field shows);
 *   status   the returned status == the most severe per-box status, and
 *            the per-box statuses agree with exact_util's expected status;
 *   guards   GUARD = 4 entries before out[0] and after out[n-1], filled
 *            with a byte pattern, are unchanged;
 *   inputs   *a and in[0 .. n-1] unchanged.
 *
 * Prepared maps, on every batch above (the same map and boxes): the
 * structs a caller may hand over,
 *   cbx_prepare       filled by cbx_prepare (checked: the map copied bit
 *                     for bit, cls == cbx_classify(a), fast set iff every
 *                     linear entry is at most 2^509 and every translation
 *                     at most 2^1018 in magnitude);
 *   zero-init         cbx_prepared p = { 0 }, then p.a = *a (fast 0, cls 0);
 *   cls forged        cbx_prepare's with p.cls set by hand to a value of
 *                     xu_cls_values (the five classes and ints outside the
 *                     enum), the fast flag kept or cleared;
 *   fast+cls forged   the same with p.fast = 1 whatever the map (huge,
 *                     infinite, NaN entries included);
 * the forged value cycling with the batch number.  Checks:
 *   box_prep   cbx_transform_box_prep(&p, in[k]) == cbx_transform_box_as(
 *              &p.a, p.cls, in[k]), status and bits (pre-filled
 *              differently), and in place (out == in); not for fast+cls
 *              forged (cbx_transform_box_prep trusts the fast flag);
 *   boxes_prep cbx_transform_boxes_prep(&p, in, out, n) == cbx_transform_
 *              boxes(a, in, out, n), status and bits, guards unchanged,
 *              *p unchanged, for every struct;
 *   exact      the boxes of boxes_prep on the forged structs against the
 *              exact oracle (xu_check_result: status, special outputs,
 *              containment of the exact image, proven tightness);
 *   n == 0 with null in / out: CBX_OK.
 * Special values: a base map of each class (identity, translation, scale,
 * permutation, general) and a base box, one of 19 values (NaN, +-inf,
 * +-0, 2^-1074, DBL_MIN, 2^509 and the next double, 2^1018 and the next,
 * 2^1019, DBL_MAX, ...) in one of the 18 positions, as a batch of one box
 * through every check above, with every forged cls value.
 * Last line "N passed, M failed" (batches); exit status 1 on failure.
 * This file is the driver (the arguments, the rounds, the order of the
 * batches, the summary); the random maps, boxes and batches and the special
 * values are in tests/batch_gen.c, the checks of one batch and of the
 * prepared forms in tests/batch_check.c (tests/batch_parts.h).
 */
#include <stdint.h>
#include <stdio.h>
#include <time.h>

#include "certbox.h"
#include "exact_util.h"

#include "batch_parts.h" /* the generators, the special values, the checks */

static const char *const k_name[NK] = { "bits", "status", "guards", "inputs" };
static const char *const k_unit[NK] = { "boxes", "batches", "batches", "batches" };

int main(int argc, char **argv)
{
    long rounds = (long)xu_arg_num(argc, argv, 1, 200, "[N] [seed]"), c;
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N] [seed]");
    static const size_t sizes[5] = { 0, 1, 2, 7, 1000 };
    static stats st;
    xu_rng rng;
    xu_exact x;
    cbx_affine a;
    cbx_prepared p;
    int q, seq;
    clock_t t0 = clock();

    xu_init(&x);
    rng.s = UINT64_C(0xb7e151628aed2a6a) ^ seed;
    printf("-- test_batch: cbx_transform_boxes against cbx_transform_box per box, and the "
           "prepared forms (cbx_prepare, cbx_transform_box_prep, cbx_transform_boxes_prep), "
           "%ld rounds, seed %llu --\n", rounds, (unsigned long long)seed);

    for (c = 0; c < rounds; c++) {
        /* ordinary 40%, zero columns 15%, class maps 15%, fast-range edge 10%,
         * infinite, huge, NaN entries 5%, 10%, 5% */
        static const int mk_kind[20] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 5, 5, 5, 6, 6, 2, 4, 4, 3 };
        bat_gen_map(&rng, &a, mk_kind[xu_rng_int(&rng, 0, 19)]);
        for (q = 0; q < 5; q++) bat_random_batch(&rng, &st, &x, &a, sizes[q]);
        bat_random_batch(&rng, &st, &x, &a, (size_t)xu_rng_int(&rng, 0, 64));
    }

    /* every ordered triple of {normal, empty, out-of-domain, NaN} */
    bat_gen_map(&rng, &a, 0);
    for (seq = 0; seq < 64; seq++) {
        static const int pick[4] = { B_NORMAL, B_EMPTY, B_OOD, B_NAN };
        cbx_box in[3];
        int kinds[3], j;
        for (j = 0; j < 3; j++) {
            kinds[j] = pick[(seq >> (2 * j)) & 3];
            bat_gen_box(&rng, &in[j], kinds[j]);
        }
        bat_run_batch(&st, &x, &a, in, kinds, 3, seq % XU_NCLS_VALUES, 1);
    }
    bat_run_specials(&st, &x);

    /* n == 0 with null pointers: nothing may be touched, CBX_OK */
    st.checked[K_STATUS]++;
    st.batches++;
    st.by_n[0]++;
    if (cbx_transform_boxes(&a, (const cbx_box *)0, (cbx_box *)0, 0) != CBX_OK) {
        st.fail[K_STATUS]++;
        st.failed++;
        printf("FAIL n == 0 with null in / out: status is not CBX_OK\n");
    }
    /* the same for the prepared batch, with a forged struct (huge map, fast
     * 1, cls IDENTITY) */
    a.m[0][1] = 1e300;
    cbx_prepare(&a, &p);
    p.fast = 1;
    p.cls = CBX_CLASS_IDENTITY;
    st.batches++;
    st.by_n[0]++;
    st.many[V_FORGED]++;
    if (cbx_transform_boxes_prep(&p, (const cbx_box *)0, (cbx_box *)0, 0) != CBX_OK) {
        st.many_fail[V_FORGED]++;
        st.failed++;
        printf("FAIL n == 0 with null in / out: cbx_transform_boxes_prep's status is not CBX_OK\n");
    }

    printf("  %ld batches (n = 0: %ld, 1: %ld, 2: %ld, 7: %ld, 1000: %ld, other: %ld), "
           "%ld boxes\n", st.batches, st.by_n[0], st.by_n[1], st.by_n[2], st.by_n[3], st.by_n[4],
           st.by_n[5], st.boxes);
    printf("  boxes by kind:");
    for (q = 0; q < NB; q++) printf(" %s %ld", bat_b_name[q], st.kinds[q]);
    printf("\n  returned statuses: OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n",
           st.status_ret[0], st.status_ret[1], st.status_ret[2], st.status_ret[3]);
    for (q = 0; q < NK; q++)
        printf("  check %-7s %9ld %-8s checked, %ld failed\n", k_name[q], st.checked[q],
               k_unit[q], st.fail[q]);
    printf("  special values: %ld inputs (%d base maps, one per class, x 18 positions x %d "
           "values), each a batch of one box with all %d cls values forged\n", st.special,
           bat_n_base, bat_n_special, XU_NCLS_VALUES);
    printf("  prepared maps: cbx_prepare on %ld maps (%ld in the fast range), %ld failed (copy, "
           "class, fast flag)\n", st.prep_maps, st.prep_fast, st.prep_fail);
    for (q = 0; q < NV; q++) {
        if (q == V_FORGED)
            printf("  %-16s box_prep: not called (it trusts the fast flag);", bat_v_name[q]);
        else
            printf("  %-16s box_prep vs cbx_transform_box_as(&p.a, p.cls): %7ld boxes, %ld "
                   "differ, in place %ld differ;", bat_v_name[q], st.one[q], st.one_fail[q],
                   st.inplace_fail[q]);
        printf(" boxes_prep vs cbx_transform_boxes: %5ld batches (%ld boxes), %ld differ\n",
               st.many[q], st.many_boxes[q], st.many_fail[q]);
    }
    printf("  forged structs' boxes_prep boxes against the exact oracle: %ld boxes, %ld failed\n",
           st.exact, st.exact_fail);
    printf("  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    xu_clear(&x);
    printf("%ld passed, %ld failed\n", st.batches - st.failed, st.failed);
    return st.failed ? 1 : 0;
}
