/*
 * test_tight [N_THOUSANDS] [seed]: cbx_transform_box_tight against exact
 * arithmetic (GMP fixed point, cross-checked with MPFR and mpq_t).
 *
 * The promise checked (certbox.h): the same status, special outputs and
 * infinite ends as cbx_transform_box on the same input, and every FINITE
 * end the tightest double,
 *     lo_i = RD(E_lo),   hi_i = RU(E_hi),
 * with E the exact value at the end's vertex (exact_util.h rule B: v_j =
 * lo_j for m_j > 0, hi_j for m_j < 0, 0 for m_j == 0; mirrored for the
 * upper end).  On a full row E is the exact bound L_i = t + sum_j
 * min(m_j lo_j, m_j hi_j) (resp. H_i): checked to agree on a subset.
 *
 * Documented exception (certbox.h): an end whose vertex has a nonzero
 * product |m_j v_j| below 2^-968 ("tiny"), or where a magnitude above
 * 2^1015 occurs ("big": |t|, some |m_j v_j| or |E| above 2^1015) may keep
 * cbx_transform_box's end.  There only containment and "never looser than
 * cbx_transform_box" are required; such ends are counted (optimal anyway /
 * the kernel's end / in between).  Non-optimal ends in the exception whose
 * largest magnitude is in (2^1015, 2^1016] are counted apart (allowed by
 * certbox.h's 2^1015, not by a 2^1016 reading).
 *
 * Per case (every check below failing fails the case):
 *   status   tight status == cbx_transform_box's status;
 *   oracle   exact_util's xu_check_result on the tight output: the whole
 *            cbx_transform_box promise (expected status, every field
 *            written, EINVAL / EMPTY outputs, end kinds A F U L W,
 *            containment, proven tightness 12 u S + 2^-1065; mpq corner
 *            checks on every 16th case);
 *   kinds    EINVAL / EMPTY output bit-identical to cbx_transform_box's;
 *            each end infinite exactly where cbx_transform_box's is, and
 *            then bit-identical to it;
 *   contain  each finite lo <= E (hi >= E), exactly (mpz);
 *   looser   lo >= cbx_transform_box's lo (hi <= its hi);
 *   optimal  nextafter(lo, +inf) > E (hi: nextafter(hi, -inf) < E), mpz,
 *            i.e. 0 ulp from RD(E); required outside the exception;
 *   cross    the same optimality decided independently by MPFR (RD / RU
 *            of E in binary64 with subnormals) agrees; on every 8th case
 *            also E recomputed with mpq_t from the vertex, and on full
 *            rows E == the fixed-point L / H of xu_row_bounds;
 *   inplace  on every 4th case cbx_transform_box_tight(a, &b, &b) gives the
 *            same status and bits as the separate output;
 *   inputs   *a and *in unchanged by the call;
 *   gap      where the map and box are in the fast range and the row in
 *            the tight mode's range (specs/cbx_tight_gap.h: trow_dom),
 *            |E - end| <= 2^-50 |E| + 2^-96 S + 2^-1050 (the proven
 *            accuracy, trow_near), exactly (mpq).
 *
 * Sections (N = N_THOUSANDS * 1000, default N_THOUSANDS = 30):
 *   0 hard cases (a table: permutations, 0.1 * 3, exact cancellation,
 *     subnormal results, the boundaries 2^-968 and 2^1015 of the exception);
 *   1 N random full rows over wide exponent ranges (products from 2^-1074
 *     to 2^1018, rows of one scale and rows of mixed scales);
 *   2 N integer-valued and small dyadic inputs (the exact end is often a
 *     double: lo must then equal it), permutations / sign flips, large
 *     integers (sums not representable), powers of two with wide spreads,
 *     all of these scaled by powers of two;
 *   3 N heavy cancellation rows: t = -fl(m.v) (+- a few ulps), exact
 *     cancellation of two products (m_1 v_1 = -m_0 v_0) with a tiny rest,
 *     t = -fl(m_0 v_0) (E = the rounding error of a product), results in
 *     the subnormal range;
 *   4 N/2 half-space / infinite-end boxes, huge (out-of-domain) ends,
 *     zero and -0.0 coefficients, infinite map entries, NaN, empty boxes;
 *   5 N/4 inputs near the exception's boundaries (products around 2^-968,
 *     magnitudes around 2^1015 .. 2^1001).
 * Printed per section and in total: cases, statuses, end kinds, finite
 * ends checked, containment / optimality failures, exception counts; the
 * first failures with their inputs in hex (%a).  Last line "N passed,
 * M failed" (cases); exit status 1 on any failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <time.h>
#include <gmp.h>
#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"
#include "cbx_eft.h" /* only CBX_TWO_PROD_NAME: the form this build's flags select */
#include "tight_parts.h" /* the checks, the generators, the hard cases */

typedef void (*gen_fn)(xu_rng *, cbx_affine *, cbx_box *);

int main(int argc, char **argv)
{
    long nth = (long)xu_arg_num(argc, argv, 1, 30, "[N_THOUSANDS] [seed]"), n, c;
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N_THOUSANDS] [seed]");
    static tctx k;
    static sec s[6], tot;
    static const char *const titles[6] = {
        "section 0: hard cases",
        "section 1: random full rows, wide exponent ranges",
        "section 2: integers, small dyadics, permutations, powers of two",
        "section 3: heavy cancellation",
        "section 4: half-spaces, huge ends, infinite entries, NaN, empty",
        "section 5: near the exception's boundaries (2^-968, 2^1015)"
    };
    static const gen_fn gens[6] = { 0, tgt_gen_wide, tgt_gen_int, tgt_gen_cancel, tgt_gen_special,
                                    tgt_gen_boundary };
    int q;
    clock_t t0 = clock();

    n = nth * 1000;
    xu_init(&k.x);
    mpz_inits(k.E, k.p, k.tiny, k.big, k.big1000, k.smallE, k.near967, (mpz_ptr)0);
    mpz_setbit(k.tiny, XU_SHIFT - 968);      /* 2^-968, scaled  */
    mpz_setbit(k.near967, XU_SHIFT - 967);   /* 2^-967, scaled  */
    mpz_setbit(k.big, XU_SHIFT + 1015);      /* 2^1015, scaled  */
    mpz_setbit(k.big1000, XU_SHIFT + 1016);  /* 2^1016, scaled  */
    mpz_setbit(k.smallE, XU_SHIFT - 900); /* 2^-900, scaled  */
    mpq_inits(k.q, k.qa, k.qb, (mpq_ptr)0);
    mpfr_init2(k.r53, 53);
    k.rng.s = UINT64_C(0x243f6a8885a308d3) ^ seed;
    k.logs = 0;
    k.notes = 0;

    printf("-- test_tight: cbx_transform_box_tight against GMP, %ld thousand cases per random "
           "section, seed %llu --\n", nth, (unsigned long long)seed);
    for (q = 0; q < 6; q++) tgt_sec_init(&s[q], titles[q]);
    tgt_sec_init(&tot, "totals");
    for (q = 0; q < tgt_n_hard; q++) {
        const char *nm = tgt_hard_cases[q].name;
        long before = s[0].failed;
        tgt_run_case(&k, &s[0], &tgt_hard_cases[q].a, &tgt_hard_cases[q].in);
        if (s[0].failed != before) printf("  (hard case \"%s\")\n", nm);
    }
    for (q = 1; q < 6; q++) {
        long m = q == 4 ? n / 2 : q == 5 ? n / 4 : n;
        for (c = 0; c < m; c++) {
            cbx_affine a;
            cbx_box b;
            gens[q](&k.rng, &a, &b);
            tgt_run_case(&k, &s[q], &a, &b);
        }
    }
    for (q = 0; q < 6; q++) {
        tgt_sec_print(&s[q]);
        tgt_sec_add(&tot, &s[q]);
    }
    tgt_sec_print(&tot);
    printf("\n  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    printf("tight: two_prod form (src/core/cbx_eft.h, as this test's flags select it): %s\n",
           CBX_TWO_PROD_NAME);
    printf("tight: %ld cases, %ld finite ends, %ld containment failures, %ld optimality "
           "failures, %ld ends in the exception\n", tot.cases, tot.fin, tot.fail[C_CONTAIN],
           tot.fail[C_OPTIMAL], tot.exc);

    mpfr_clear(k.r53);
    mpq_clears(k.q, k.qa, k.qb, (mpq_ptr)0);
    mpz_clears(k.E, k.p, k.tiny, k.big, k.big1000, k.smallE, k.near967, (mpz_ptr)0);
    xu_clear(&k.x);
    mpfr_free_cache();
    /* the gap check must be able to fail: cbx_transform_box's ends (12 u S)
     * leave the 2^-50 |E| gap on rows without cancellation */
    if (tot.checked[C_GAP] >= 1000 && tot.gap_kernel_out == 0) {
        printf("tight: FAIL: no cbx_transform_box end outside the proven gap in %ld ends: the "
               "gap check cannot tell\n", tot.checked[C_GAP]);
        tot.failed++;
    }
    printf("%ld passed, %ld failed\n", tot.cases - tot.failed, tot.failed);
    return tot.failed ? 1 : 0;
}
