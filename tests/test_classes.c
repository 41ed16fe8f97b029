/*
 * test_classes [N] [seed]: the transform classes (cbx_classify,
 * cbx_transform_box_as, with its class hint misused too) and the motion box
 * (cbx_motion_box) against exact rational arithmetic (GMP,
 * tests/exact_util.h).
 *
 * Part 1, classification (N maps).  Maps built to be of a known class
 * (IDENTITY, TRANSLATE, SCALE, PERMUTE, GENERAL; random signs, -0.0 zeros,
 * exact 1.0 entries, realistic and extreme magnitudes) and near misses of
 * each (a diagonal 1 + 2^-52 or 1 - 2^-53 or -1, an off-diagonal 2^-1074, a
 * translation 2^-1074, an extra tiny entry in a permutation row, zero
 * scales, all-(-0.0) zeros, DBL_MAX entries, a NaN or an infinity in any
 * entry).  The expected class is known by construction AND computed by an
 * independent rule (rule_class: count the nonzero entries); both must agree
 * with cbx_classify.
 *
 * Part 2, class kernels (N cases).  A map of each class (realistic, or
 * extreme: 2^509 and just above, 2^1018, subnormals, zero scales, huge and
 * out-of-domain translations, sometimes an infinity or a NaN, or random
 * exponents over the fast range of the class kernels: |m| <= 2^509,
 * |t| <= 2^1018) and a box (realistic, tiny/subnormal, point boxes,
 * lo == hi axes, ends at 2^509 / 2^1018 / beyond, half-spaces, empty, NaN,
 * random exponents, random exponents with |ends| <= 2^509).
 * cbx_transform_box_as is called with the class of cbx_classify and with
 * every larger class down to GENERAL, and cbx_transform_box once.  Each
 * class-kernel call must:
 *   - pass every exact check of exact_util (xu_check_result: the status
 *     computed exactly from the spec, special outputs, full-row containment
 *     of the exact image and the proven tightness 12 u S + 2^-1065, the
 *     half-space / out-of-domain end rules; the mpq 8-corner checks on
 *     every CORNER_EVERY-th case);
 *   - return the same status as cbx_transform_box, with identical (bit for
 *     bit) infinite ends, and every finite end never looser than the
 *     general kernel's (lo >= general lo, hi <= general hi);
 *   - give the same status and output in place (out == in);
 *   - leave *a and *in unchanged.
 * The general kernel's output goes through the same exact checks.  Excess
 * (distance to the exact end in units of u S + 2^-1074) is reported per
 * class for the class kernel (called with its own class) and for the
 * general kernel on the same axes.
 *
 * Part 3, motion (N pairs).  Pairs (a0, a1): both general, one map of each
 * class, identical maps, sign-flipped maps (an entry crosses 0 inside the
 * interval), a NaN, out-of-domain maps or boxes (mixed full / not-full
 * axes), half-space boxes, empty boxes.  With s in {0, 1, 1/2, 1/3, 2/7}
 * and 5 random p/q:
 *   - status: EINVAL on a NaN, EMPTY on an empty box, else CBX_OK iff both
 *     maps' exactly computed statuses are CBX_OK and no axis mixes a full
 *     row (xu_row_in_domain) with a non-full one, else CBX_ERANGE;
 *   - both rows full: the axis is finite and every corner c of the box has
 *     lo <= (M(s) c)_i <= hi exactly (fixed-point mpz, (1-s) and s as
 *     (q-p)/q and p/q), for every sampled s; the axis is bit for bit the
 *     union of the two cbx_transform_box outputs; the exact extreme over
 *     the sampled s equals the one over s in {0, 1}; and the ends are
 *     within 12 u max(S0, S1) + 2^-1065 of the exact extreme over s;
 *     every MOTION_DIRECT_EVERY-th case the same corner check again with
 *     M(s) built entry by entry in mpq (independent of the linearity);
 *   - neither row full, both map rows finite: the union, bit for bit, and
 *     each finite end below (above) the exact inf (sup) of (M(s) p)_i over
 *     every real point p of the box (extended vertex rule in mpq on the
 *     interpolated row: an infinite needed end means unbounded);
 *   - one full and one not, or a non-finite map row: exactly [-inf, +inf];
 *   - special outputs, in place, inputs unchanged.
 *
 * Part 4, misuse (a table, then N/4 cases).  cls is a hint: a class the
 * map is not in, or an int outside the enum, must run the general kernel.
 * Each input goes through cbx_transform_box_as with each of the 11 values
 * of xu_cls_values (GENERAL .. IDENTITY, 5, 7, -1, -3, INT_MAX, INT_MIN):
 *   - every exact check of exact_util (xu_check_result: status, special
 *     outputs, containment of the exact image, proven tightness, the
 *     half-space / out-of-domain end rules; mpq corners every
 *     CORNER_EVERY-th case), cbx_transform_box's status, inputs unchanged;
 *   - bit for bit cbx_transform_box's output when cls is GENERAL or not a
 *     class of the map (outside 0 .. clt_rule_class(a): the fallback);
 *   - the table (diag(2,2,2) on [0,1]^3, a translation, a scale, a
 *     permutation, a shear, huge maps beyond 2^509) has the exact image
 *     written out: the output must contain it, with CBX_OK, for every cls.
 *     The diag(2,2,2) case called as IDENTITY is printed: before the hint
 *     was checked it returned [0,1]^3 with CBX_OK (exact image [0,2]^3).
 *   The random inputs are part 2's draws (maps of each class, boxes with
 *   infinite ends, NaN, empty, huge magnitudes, random exponents).
 *
 * A summary line per part; the last line is "N passed, M failed" (cases of
 * all parts); exit status 1 on any failure.
 *
 * This file is the driver (arguments, the order of the parts, the summary
 * lines); the parts are in tests/classes_gen.c, tests/classes_kernels.c,
 * tests/classes_motion.c and tests/classes_misuse.c (tests/classes_parts.h).
 */
#include <stdint.h>
#include <stdio.h>
#include <time.h>

#include "classes_parts.h"

#ifndef CORNER_EVERY
#define CORNER_EVERY 8
#endif
#ifndef MOTION_DIRECT_EVERY
#define MOTION_DIRECT_EVERY 8
#endif

/* ---------------------------------------------------------------------- */
/* Driver                                                                 */
/* ---------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 200000, "[N] [seed]");
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N] [seed]");
    static cstats cs;
    static kstats ks[NCLS];
    static mstats ms;
    static ustats us;
    static long bxk[NBX], bxu[NBX];
    xu_rng rng;
    xu_exact x;
    cbx_affine a;
    long cases, failed, kfailed = 0, kcases = 0;
    int k, f;
    clock_t t0 = clock(), t1, t2, t3;

    xu_init(&x);
    printf("-- test_classes: cbx_classify, cbx_transform_box_as, cbx_motion_box against GMP, "
           "%ld cases per part, seed %llu --\n", n, (unsigned long long)seed);

    /* part 1 */
    rng.s = UINT64_C(0x243f6a8885a308d3) ^ seed;
    clt_run_classify(&rng, &a, &cs, n);
    printf("part 1 classify: %ld maps, %ld failed (construction vs rule disagreements: %ld)\n",
           cs.cases, cs.failed, cs.rule_disagree);
    printf("  classify returned:");
    for (k = NCLS - 1; k >= 0; k--) printf(" %s %ld", clt_cls_name[k], cs.got[k]);
    printf("\n  kinds (maps / failed):");
    for (k = 0; k < NKIND; k++) printf("%s %s %ld/%ld", k ? "," : "", clt_kind_name[k], cs.kind[k],
                                       cs.kind_fail[k]);
    printf("\n");

    /* part 2 */
    t1 = clock();
    rng.s = UINT64_C(0x13198a2e03707344) ^ seed;
    clt_run_kernels(&rng, &x, ks, n, bxk, CORNER_EVERY);
    printf("part 2 class kernels (cbx_transform_box_as with the class of cbx_classify and "
           "every larger class, vs cbx_transform_box and GMP; mpq corners every %d-th case):\n",
           CORNER_EVERY);
    printf("  boxes:");
    for (k = 0; k < NBX; k++) printf("%s %s %ld", k ? "," : "", clt_bx_name[k], bxk[k]);
    printf("\n");
    for (k = NCLS - 1; k >= 0; k--) {
        kstats *s = &ks[k];
        double na = s->axes ? (double)(2 * s->axes) : 1.0;
        printf("  %-9s %7ld cases (OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld), %7ld calls, "
               "%8ld ends (%ld finite, %ld infinite/special), containment failures %ld, "
               "looser than general %ld, strictly tighter %ld, status differs %ld, infinite "
               "ends differ %ld, in-place differs %ld, inputs changed %ld; failed cases %ld\n",
               clt_cls_name[k], s->cases, s->st[0], s->st[1], s->st[2], s->st[3], s->calls, s->ends,
               s->fin_ends, s->inf_ends, s->contain_fail, s->looser, s->tighter, s->status_diff,
               s->inf_diff, s->inplace_diff, s->input_diff, s->failed);
        printf("  %-9s excess (units of u*S + 2^-1074, full-row axes with u*S >= 2^%d eta, "
               "%ld axes): class kernel mean %.4f max %.4f; general kernel mean %.4f max %.4f\n",
               "", XU_TINY, s->axes, s->sum_ex / na, s->max_ex, s->sum_exg / na, s->max_exg);
        for (f = 0; f < XU_NFLAGS; f++)
            if (s->flag_fail[f] || s->gflag_fail[f])
                printf("  %-9s exact check %s failed: class kernel %ld, general kernel %ld\n", "",
                       xu_flag_name[f], s->flag_fail[f], s->gflag_fail[f]);
        kfailed += s->failed;
        kcases += s->cases;
    }
    printf("part 2 class kernels: %ld cases, %ld failed\n", kcases, kfailed);

    /* part 3 */
    t2 = clock();
    rng.s = UINT64_C(0xa4093822299f31d0) ^ seed;
    clt_run_motion(&rng, &x, &ms, n, MOTION_DIRECT_EVERY);
    printf("part 3 motion (s in {0, 1, 1/2, 1/3, 2/7} + 5 random p/q; M(s) entry by entry in mpq "
           "every %d-th case):\n", MOTION_DIRECT_EVERY);
    printf("  pairs:");
    for (k = 0; k < NPAIR; k++) printf("%s %s %ld", k ? "," : "", clt_pair_name[k], ms.kind[k]);
    printf("\n  statuses: OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld; status failures %ld, special "
           "outputs %ld, in place %ld, inputs changed %ld\n", ms.st[0], ms.st[1], ms.st[2],
           ms.st[3], ms.status_fail, ms.special_fail, ms.inplace_fail, ms.input_fail);
    printf("  axes: both full %ld, neither full %ld, mixed %ld, infinite map row %ld; "
           "[-inf,+inf] required and not given: %ld; full axis not finite: %ld\n", ms.ax_full,
           ms.ax_none, ms.ax_mixed, ms.ax_infmap, ms.whole_fail, ms.finite_fail);
    printf("  corner checks (s, corner) %ld, failed %ld; direct mpq M(s) %ld, failed %ld; "
           "half-space end checks %ld, failed %ld\n", ms.corner_checks, ms.corner_fail,
           ms.direct_checks, ms.direct_fail, ms.end_checks, ms.end_fail);
    printf("  union of the two cbx_transform_box outputs: %ld axes, %ld not bit-identical "
           "(0/-0 ties seen %ld); extreme over sampled s == extreme over {0,1}: %ld checks, %ld "
           "failed; tightness 12 u max(S0,S1) + 2^-1065 failed %ld\n", ms.union_checks,
           ms.union_fail, ms.zero_ties, ms.extreme_checks, ms.extreme_fail, ms.tight_fail);
    printf("  excess vs the exact extreme over s (units of u*max(S0,S1) + 2^-1074, %ld axes): "
           "mean %.4f max %.4f\n", ms.ex_axes, ms.ex_axes ? ms.sum_ex / (2.0 * (double)ms.ex_axes) : 0.0,
           ms.max_ex);
    printf("part 3 motion: %ld cases, %ld failed\n", ms.cases, ms.failed);

    /* part 4 */
    t3 = clock();
    rng.s = UINT64_C(0x452821e638d01377) ^ seed;
    printf("part 4 misuse (cbx_transform_box_as with each of the %d cls values below: the "
           "five classes, so also classes the map is not in, and ints outside the enum; a "
           "table of %d maps with the exact image written out, then N/4 = %ld random cases as "
           "in part 2):\n", XU_NCLS_VALUES, clt_n_misuse_table, n / 4);
    clt_run_misuse(&rng, &x, &us, n / 4, bxu, CORNER_EVERY);
    printf("  maps (by rule_class):");
    for (k = NCLS - 1; k >= 0; k--) printf(" %s %ld", clt_cls_name[k], us.map_cls[k]);
    printf("\n  boxes:");
    for (k = 0; k < NBX; k++) printf("%s %s %ld", k ? "," : "", clt_bx_name[k], bxu[k]);
    printf("\n  table: %ld calls, exact image not contained (or status not OK) %ld\n",
           us.table_calls, us.table_img_fail);
    for (k = 0; k < XU_NCLS_VALUES; k++) {
        char nb[16];
        printf("  cls %-9s %7ld calls, %7ld of them GENERAL or not a class of the map (general "
               "kernel expected): not bit for bit cbx_transform_box %ld; exact checks failed "
               "%ld, status differs %ld, inputs changed %ld\n",
               xu_cls_str(xu_cls_values[k], nb), us.v_calls[k], us.v_general[k],
               us.v_bits_fail[k], us.v_exact_fail[k], us.v_status_fail[k], us.v_input_fail[k]);
    }
    printf("part 4 misuse: %ld cases (%ld calls), %ld failed\n", us.cases, us.calls, us.failed);

    printf("  CPU time: part 1 %.2f s, part 2 %.2f s, part 3 %.2f s, part 4 %.2f s\n",
           (double)(t1 - t0) / CLOCKS_PER_SEC, (double)(t2 - t1) / CLOCKS_PER_SEC,
           (double)(t3 - t2) / CLOCKS_PER_SEC, (double)(clock() - t3) / CLOCKS_PER_SEC);
    xu_clear(&x);
    cases = cs.cases + kcases + ms.cases + us.cases;
    failed = cs.failed + kfailed + ms.failed + us.failed;
    printf("%ld passed, %ld failed\n", cases - failed, failed);
    return failed ? 1 : 0;
}
