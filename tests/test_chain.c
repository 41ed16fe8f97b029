/*
 * test_chain [steps=1000] [chains=20] [seed=1]: stability of repeated
 * transforms.
 *
 * Each chain starts from a random box B_0 (centre in [-8, 8], half-widths
 * in [2^-3, 2^3), every 5th chain flat on axis 2) and applies `steps`
 * random rigid maps A_k (a random unit quaternion -> 3x3 rotation computed
 * in doubles, so only nearly orthogonal; plus a translation with entries in
 * [-1/16, 1/16]), each output feeding the next step, in two forms:
 *   box chain:   B_{k+1} = cbx_transform_box(A_k, B_k);
 *   cbox chain:  C_0 = cbx_box_to_cbox(B_0), C_{k+1} = cbx_transform_cbox(A_k, C_k).
 * The map actually applied is the one made of the doubles, taken exactly.
 *
 * Checks (every one exact, GMP):
 *   start      cbx_box_to_cbox(B_0) is CBX_OK and [c - h, c + h] holds B_0;
 *   box-step   every step of the box chain with xu_run_case (exact_util):
 *              the status equals the exact oracle's, no output field left
 *              unset (NaN pre-fill), every end as the rules of exact_util.h
 *              say (rows outside the domain: each end proven from its
 *              vertex or exactly infinite), and on in-domain (full) rows
 *              the exact image of the step's input box B_k under A_k is
 *              contained in B_{k+1} (fixed-point bounds AND all 8 corners
 *              with mpq_t) and within the proven tightness 12 u S + 2^-1065;
 *   cbox-step  every step of the cbox chain: status equals the exact oracle's
 *              (exact_util's cbox rules: full rows A, rows full once their
 *              zero-coefficient columns are dropped D, lost rows W), no NaN
 *              left, lost axes c = 0, h = +inf, and on the others the 8
 *              corners c_j -+ h_j of C_k (for D, of the dropped box: c_j =
 *              h_j = 0 where the coefficient is 0) mapped by A_k exactly
 *              (mpq_t) lie in [c' - h', c' + h'];
 *   box-comp / cbox-comp  the composed map P_k = A_{k-1} o ... o A_0 is
 *              kept exactly as mpq_t (the double matrices multiplied as
 *              rationals, every one of the `steps` steps), and at every
 *              checkpoint (steps 1, 2, 3, 5, 10, 20, 50, then every
 *              CHECK_EVERY = 100 steps, and after the last step) the 8
 *              corners of the ORIGINAL box B_0 mapped exactly by P_k lie in
 *              B_k and in [c - h, c + h] of C_k.  Nothing is skipped: the
 *              exact composition of all 1000 steps stays fast (its time and
 *              the size of its numbers are printed).  The early checkpoints
 *              are the sharp ones: later the boxes are so much wider than
 *              the exact image (the wrapping effect, below) that this check
 *              only confirms soundness, it could no longer see a wrong P.
 *   chain-fn   at every checkpoint, cbx_transform_box_chain on the maps so
 *              far (last applied first) and B_0: the same box as the box
 *              chain's B_k, bit for bit, the status the most severe of the
 *              steps', and the 8 corners of B_0 mapped by the exact
 *              composition inside it (its proven promise, checked exactly);
 *   chain-spec its special cases: no map (CBX_EINVAL, whole space), a NaN
 *              in the box or in one map of the chain (CBX_EINVAL, whole
 *              space), an empty box (CBX_EMPTY, lo +inf, hi -inf), two
 *              scalings by 2^1000 and one more map (CBX_ERANGE, the whole
 *              space), the result written in place (out == in).
 * Growth, reported per axis as max / median over the chains: the final box
 * width of the box chain divided by the width 2h of the cbox chain, and
 * divided by the width of the exact bound of P(B_0) (the naive exact
 * box, sum_j |P_ij| (hi_j - lo_j), a rational); also cbox / exact, the
 * per-step factor (box / exact)^(1 / steps), and box / exact at every
 * checkpoint.  A chain whose box leaves the proven domain (ERANGE, the
 * widths grow geometrically) is reported with the step; its widths are
 * then infinite.
 * The last line is "N passed, M failed" (checked steps and checkpoints);
 * exit status 1 on failure.
 * This file is the driver (the arguments, the chains, the order of the
 * checks, the summary); the exact composition and the checked cbox step are
 * in tests/chain_exact.c, the tallies, the random maps, the chain
 * function's special cases and the statistics in tests/chain_cases.c
 * (tests/chain_parts.h).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>

#include "certbox.h"
#include "exact_util.h"

#include "chain_parts.h" /* the exact composition, the cases, the statistics */

#define CHECK_EVERY 100

/* Checkpoints before the first hundred steps, where the boxes are still
 * only a few times wider than the exact image (a composition error would
 * show there; later the wrapping effect hides it). */
static int early_checkpoint(long s)
{
    return s == 1 || s == 2 || s == 3 || s == 5 || s == 10 || s == 20 || s == 50;
}

static const char *const k_unit[NK] = { "chains", "steps", "steps", "checkpts", "checkpts",
                                        "checkpts", "cases" };

static void usage(char **argv)
{
    fprintf(stderr, "usage: %s [steps=1000] [chains=20] [seed=1]  (steps, chains >= 1)\n",
            argv[0]);
    exit(2);
}

/* argv[k] as a number >= vmin, dflt if absent; a typo is an error */
static unsigned long long arg_num(int argc, char **argv, int k, unsigned long long dflt,
                                  unsigned long long vmin)
{
    char *end;
    unsigned long long v;
    if (argc <= k) return dflt;
    v = strtoull(argv[k], &end, 0);
    if (*argv[k] == '\0' || *argv[k] == '-' || *end != '\0' || v < vmin) usage(argv);
    return v;
}

int main(int argc, char **argv)
{
    long steps = (long)arg_num(argc, argv, 1, 1000, 1);
    int chains = (int)arg_num(argc, argv, 2, 20, 1);
    uint64_t seed = (uint64_t)arg_num(argc, argv, 3, 1, 0);
    int ncp = 0, cp;
    long *cp_at;
    double *r_bc[4], *r_be[4], *r_ce[4], *r_step, *cp_be;
    double comp_sec = 0, mx, med;
    size_t bits_max = 0;
    long total = 0, failed = 0;
    int ch, i, n_left = 0;
    ctx k;
    xu_rng rng;
    clock_t t0 = clock();
    cbx_prepared *pr, *rev;

    if (argc > 4 || steps > 100000000L || chains > 1000000) usage(argv);
    for (i = 0; i < 4; i++) {
        r_bc[i] = malloc(3 * (size_t)chains * sizeof(double));
        r_be[i] = malloc(3 * (size_t)chains * sizeof(double));
        r_ce[i] = malloc(3 * (size_t)chains * sizeof(double));
    }
    r_step = malloc((size_t)chains * 3 * sizeof(double));
    cp_at = malloc(((size_t)steps / CHECK_EVERY + 16) * sizeof *cp_at);
    if (!cp_at) return 2;
    for (i = 1; i <= steps; i++)
        if (early_checkpoint(i) || i % CHECK_EVERY == 0 || i == steps) cp_at[ncp++] = i;
    cp_be = malloc((size_t)ncp * 3 * (size_t)chains * sizeof(double));
    for (i = 0; i < 4; i++)
        if (!r_bc[i] || !r_be[i] || !r_ce[i]) return 2;
    if (!r_step || !cp_be) return 2;
    pr = malloc((size_t)steps * sizeof *pr);
    rev = malloc((size_t)steps * sizeof *rev);
    if (!pr || !rev) return 2;

    cht_ctx_init(&k);
    rng.s = seed;
    printf("-- test_chain: %d chains x %ld steps (seed %llu), random rotations +"
           " translations, box and cbox forms --\n", chains, steps, (unsigned long long)seed);

    for (ch = 0; ch < chains; ch++) {
        cbx_box b0, b, bn;
        cbx_cbox c, cn;
        cbx_affine a;
        xu_verdict v;
        char why[256];
        long s, left_box = -1, left_cbox = -1;
        int bad_chain = 0;
        double wb[3], wc[3], we[3];
        int start_ok;
        cbx_status worst = CBX_OK;

        cp = 0;
        cht_random_box(&rng, ch, &b0);
        b = b0;
        /* start: the cbox chain begins at box_to_cbox(B_0) */
        total++;
        cht_k_checked[K_START]++;
        start_ok = cbx_box_to_cbox(&b0, &c) == CBX_OK;
        for (i = 0; i < 3 && start_ok; i++) {
            mpq_set_d(k.qa, c.c[i]);
            mpq_set_d(k.qb, c.h[i]);
            mpq_sub(k.qlo, k.qa, k.qb);
            mpq_add(k.qhi, k.qa, k.qb);
            mpq_set_d(k.qa, b0.lo[i]);
            mpq_set_d(k.qb, b0.hi[i]);
            if (mpq_cmp(k.qlo, k.qa) > 0 || mpq_cmp(k.qb, k.qhi) > 0) start_ok = 0;
        }
        if (!start_ok) {
            cht_report(K_START, ch, 0, "box_to_cbox(B_0) not OK or not containing B_0");
            failed++;
            bad_chain = 1;
        }
        cht_set_identity(&k);

        for (s = 0; s < steps; s++) {
            clock_t tc;
            cht_random_step(&rng, &a);
            /* box chain: one checked step */
            total++;
            cht_k_checked[K_BOX]++;
            if (xu_run_case(&k.x, &a, &b, &bn, 1, &v)) {
                cht_report(K_BOX, ch, s + 1, v.why);
                if (cht_logs <= MAX_FAIL_LOGS) {
                    xu_print_case(stdout, &a, &b);
                    xu_print_box(stdout, "out", &bn);
                }
                failed++;
                bad_chain = 1;
            }
            if (v.got != CBX_OK && left_box < 0) left_box = s + 1;
            if (xu_severity(v.got) > xu_severity(worst)) worst = v.got;
            cbx_prepare(&a, &pr[s]);
            b = bn;
            /* cbox chain */
            total++;
            cht_k_checked[K_CBOX]++;
            if (cht_cbox_step(&k, &a, &c, &cn, why, sizeof why)) {
                cht_report(K_CBOX, ch, s + 1, why);
                failed++;
                bad_chain = 1;
            }
            if (!isfinite(cn.h[0] + cn.h[1] + cn.h[2]) && left_cbox < 0) left_cbox = s + 1;
            c = cn;
            /* exact composition */
            tc = clock();
            cht_compose(&k, &a);
            comp_sec += (double)(clock() - tc) / CLOCKS_PER_SEC;

            if (cp < ncp && cp_at[cp] == s + 1) {
                total += 2;
                cht_k_checked[K_BOXC]++;
                cht_k_checked[K_CBOXC]++;
                cht_fill_prod(&k, &b0);
                if (cht_composed_box_failures(&k, &b)) {
                    cht_report(K_BOXC, ch, s + 1, "a corner of B_0 mapped by the exact composition"
                                              " is outside the box");
                    failed++;
                    bad_chain = 1;
                }
                if (cht_composed_cbox_failures(&k, &c)) {
                    cht_report(K_CBOXC, ch, s + 1, "a corner of B_0 mapped by the exact composition"
                                               " is outside [c - h, c + h]");
                    failed++;
                    bad_chain = 1;
                }
                /* the chain function on the maps so far, last applied first */
                {
                    cbx_box w;
                    cbx_status ws;
                    long j;
                    for (j = 0; j <= s; j++) rev[j] = pr[s - j];
                    ws = cbx_transform_box_chain(rev, (size_t)s + 1, &b0, &w);
                    total++;
                    cht_k_checked[K_CHAIN]++;
                    if (ws != worst || memcmp(&w, &b, sizeof w) != 0
                        || cht_composed_box_failures(&k, &w)) {
                        cht_report(K_CHAIN, ch, s + 1,
                                   ws != worst ? "status is not the worst of the steps'"
                                   : memcmp(&w, &b, sizeof w) != 0 ? "box differs from the box chain's"
                                   : "a corner of B_0 mapped by the exact composition is outside it");
                        failed++;
                        bad_chain = 1;
                    }
                }
                for (i = 0; i < 3; i++)
                    cp_be[((size_t)cp * (size_t)chains + (size_t)ch) * 3 + (size_t)i] =
                        cht_ratio(b.hi[i] - b.lo[i], cht_exact_width(&k, &b0, i));
                cp++;
            }
        }
        {
            size_t bm = cht_max_bits(&k);
            if (bm > bits_max) bits_max = bm;
        }
        for (i = 0; i < 3; i++) {
            wb[i] = b.hi[i] - b.lo[i];
            wc[i] = 2 * c.h[i];
            we[i] = cht_exact_width(&k, &b0, i);
            r_bc[i][ch] = r_bc[3][3 * ch + i] = cht_ratio(wb[i], wc[i]);
            r_be[i][ch] = r_be[3][3 * ch + i] = cht_ratio(wb[i], we[i]);
            r_ce[i][ch] = r_ce[3][3 * ch + i] = cht_ratio(wc[i], we[i]);
            r_step[3 * ch + i] = pow(r_be[i][ch], 1.0 / (double)steps);
        }
        if (left_box >= 0 || left_cbox >= 0) n_left++;
        printf("  chain %2d: B_0 widths %-9.3g %-9.3g %-9.3g  final box/exact %-9.3g %-9.3g %-9.3g"
               "  box/cbox-1 %-10.3g %-10.3g %-10.3g", ch, b0.hi[0] - b0.lo[0], b0.hi[1] - b0.lo[1],
               b0.hi[2] - b0.lo[2], r_be[0][ch], r_be[1][ch], r_be[2][ch], r_bc[0][ch] - 1,
               r_bc[1][ch] - 1, r_bc[2][ch] - 1);
        if (left_box >= 0) printf("  box left the domain at step %ld", left_box);
        if (left_cbox >= 0) printf("  cbox left the domain at step %ld", left_cbox);
        printf("  %s\n", bad_chain ? "FAIL" : "ok");
    }

    printf("\ngrowth after %ld steps: final width / reference width, max / median over %d chains\n",
           steps, chains);
    for (i = 0; i < 4; i++) {
        int n = i < 3 ? chains : 3 * chains;
        char ax[24];
        if (i < 3) snprintf(ax, sizeof ax, "axis %d", i);
        else snprintf(ax, sizeof ax, "all axes");
        cht_max_med(r_bc[i], n, &mx, &med);
        printf("  %-8s box/cbox   max %.15f  median %.15f  (min %.15f)\n", ax, mx, med,
               r_bc[i][0]);
        cht_max_med(r_be[i], n, &mx, &med);
        printf("  %-8s box/exact  max %.4g  median %.4g\n", ax, mx, med);
        cht_max_med(r_ce[i], n, &mx, &med);
        printf("  %-8s cbox/exact max %.4g  median %.4g\n", ax, mx, med);
    }
    cht_max_med(r_step, 3 * chains, &mx, &med);
    printf("  per-step factor (box/exact)^(1/%ld): max %.6f  median %.6f\n", steps, mx, med);
    printf("  chains that left the proven domain: %d\n", n_left);
    printf("growth by checkpoint, box/exact over chains and axes:\n");
    for (cp = 0; cp < ncp; cp++) {
        cht_max_med(cp_be + (size_t)cp * 3 * (size_t)chains, 3 * chains, &mx, &med);
        printf("  step %5ld: max %.4g  median %.4g\n", cp_at[cp], mx, med);
    }
    printf("exact composition (mpq_t, all %ld steps): %.2f s in all, largest numerator or"
           " denominator %zu bits\n", steps, comp_sec, bits_max);
    {
        int sb = cht_chain_special(&rng);
        total += 6;
        failed += sb;
    }
    printf("checks:\n");
    for (i = 0; i < NK; i++)
        printf("  check %-10s %8ld %-8s checked, %ld failed\n", cht_k_name[i], cht_k_checked[i],
               k_unit[i], cht_k_failed[i]);
    printf("time %.2f s (CPU)\n", (double)(clock() - t0) / CLOCKS_PER_SEC);

    cht_ctx_clear(&k);
    for (i = 0; i < 4; i++) {
        free(r_bc[i]);
        free(r_be[i]);
        free(r_ce[i]);
    }
    free(r_step);
    free(cp_be);
    free(cp_at);
    free(pr);
    free(rev);
    printf("%ld passed, %ld failed\n", total - failed, failed);
    return failed ? 1 : 0;
}
