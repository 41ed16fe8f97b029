/*
 * test_sphere [N] [seed]: cbx_sphere_box and cbx_ellipsoid_box against
 * exact rational arithmetic (GMP) and a 256-bit MPFR evaluation.
 *
 * cbx_sphere_box(a): the image of the unit ball under y = M p + T; the
 * exact axis i is t -+ sqrt(s) with t = m[i][3] and
 * s = m[i][0]^2 + m[i][1]^2 + m[i][2]^2.
 * cbx_ellipsoid_box(center, radii, rot): M = rot * diag(radii) taken
 * exactly (a_ij = rot[i][j] * radii[j] as rationals), t = center[i].
 *
 * For each function: a table of hand-picked hard cases (printed row by
 * row), then N random cases (default 200000 each).  Every case checks:
 *   - the status equals the one decided exactly from the contract in
 *     certbox.h (NaN -> EINVAL; a row outside the domain -> ERANGE);
 *   - every output field is written (NaN pre-fill), EINVAL gives exactly
 *     [-inf, +inf]^3, out-of-domain axes are exactly [-inf, +inf];
 *   - in-domain axes are finite, lo <= hi, and contain t -+ sqrt(s)
 *     EXACTLY, on integers: lo <= t - sqrt(s) iff t - lo >= 0 and
 *     (t - lo)^2 >= s, and the same for hi;
 *   - tightness against MPFR (256 bits, raised automatically where t and
 *     sqrt(s) cancel): in ulps of the exact end, and in units of
 *     u*(|t| + sqrt(s)) + eta (u = 2^-53, eta = 2^-1074); the sanity bound
 *     (documented floor: an end may be up to 2^-1064 out, the absolute terms
 *     of src/algo/cbx_sphere.c; a gap must exceed both 64 units and 2^-1064 to fail)
 *     (check "sanity<=64") fails an end more than 64 units out on axes with
 *     u*(|t| + sqrt(s)) >= 2^-1000; on the other axes (check "tiny-abs")
 *     an end fails when its gap is above both 64 units and 2^-1000;
 *   - the proven tightness (check "proven-bound", the contract's ball_tight):
 *     every in-domain end within 80 u (|t| + sqrt(s)) + 2^-1064 of the exact
 *     end, on every axis;
 *   - points: for up to 8 points p with p.p <= 1 (checked exactly; points
 *     that fail are nudged toward 0 or skipped), 6 of them the double
 *     nearest to the maximising directions -+ M_i/|M_i|, the exact image
 *     M p + T lies in the box (exact comparison on integers);
 *   - the inputs are not modified.
 * The last line is "N passed, M failed" (cases); exit status 1 on failure.
 * This file is the driver; the checks, the exact oracle, the hard cases and
 * the generators are in tests/sphere_check.c, sphere_oracle.c and
 * sphere_cases.c (tests/sphere_parts.h).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"

#include "sphere_parts.h"

/* ---------------------------------------------------------------------- */
/* Drivers                                                                */
/* ---------------------------------------------------------------------- */

static void hard_row(ctx *k, group *g, const char *what, int h, const char *name,
                     const problem *P, cbx_status expect, int oob_tab)
{
    cbx_box out;
    verdict v;
    double mx;
    int oob;
    spt_run_problem(k, g, P, &out, &v, &mx, NULL);
    if (spt_prob_expected(P, &oob) != expect || oob != oob_tab) {
        if (!v.failed)
            snprintf(v.why, sizeof v.why, "table says %s/oob %d, oracle oob %d",
                     cbx_status_name(expect), oob_tab, oob);
        v.failed = 1;
    }
    spt_g_add(g, &v);
    printf("  %-46s %-10s max units %9.4g  %s\n", name, cbx_status_name(v.got), mx,
           v.failed ? "FAIL" : "ok");
    if (v.failed) spt_log_failure(what, h, P, &out, &v);
}

static void run_sphere(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    spt_fail_logs = 0;
    printf("-- cbx_sphere_box: hard cases (%d) --\n", spt_n_sph_hard);
    for (h = 0; h < spt_n_sph_hard; h++) {
        problem P;
        memset(&P, 0, sizeof P);
        P.a = spt_sph_hard[h].a;
        hard_row(k, gh, "sphere hard", h, spt_sph_hard[h].name, &P, spt_sph_hard[h].expect,
                 spt_sph_hard[h].oob);
    }
    r.s = seed;
    for (c = 0; c < n; c++) {
        problem P;
        cbx_box out;
        verdict v;
        double mx;
        spt_gen_sphere(&r, k, &P);
        if (spt_run_problem(k, gr, &P, &out, &v, &mx, &r))
            spt_log_failure("sphere random", c, &P, &out, &v);
        spt_g_add(gr, &v);
    }
}

static void run_ellipsoid(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    spt_fail_logs = 0;
    printf("-- cbx_ellipsoid_box: hard cases (%d) --\n", spt_n_ell_hard);
    for (h = 0; h < spt_n_ell_hard; h++) {
        const ell_case *e = &spt_ell_hard[h];
        problem P;
        memset(&P, 0, sizeof P);
        P.ell = 1;
        memcpy(P.center, e->center, sizeof P.center);
        memcpy(P.radii, e->radii, sizeof P.radii);
        memcpy(P.rot, e->rot, sizeof P.rot);
        hard_row(k, gh, "ellipsoid hard", h, e->name, &P, e->expect, e->oob);
    }
    r.s = seed ^ UINT64_C(0xe111950d);
    for (c = 0; c < n; c++) {
        problem P;
        cbx_box out;
        verdict v;
        double mx;
        spt_gen_ellipsoid(&r, k, &P);
        if (spt_run_problem(k, gr, &P, &out, &v, &mx, &r))
            spt_log_failure("ellipsoid random", c, &P, &out, &v);
        spt_g_add(gr, &v);
    }
}

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 200000ULL, "[N] [seed]");
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 0x5fe5eed0e11ULL, "[N] [seed]");
    ctx k;
    group g[4];
    long passed = 0, failed = 0;
    int i;
    clock_t t0 = clock();

    spt_ctx_init(&k);
    spt_g_init(&g[0], "cbx_sphere_box, hard cases");
    spt_g_init(&g[1], "cbx_sphere_box, random cases");
    spt_g_init(&g[2], "cbx_ellipsoid_box, hard cases");
    spt_g_init(&g[3], "cbx_ellipsoid_box, random cases");
    printf("test_sphere: N = %ld random cases per function, seed 0x%llx, sanity "
           "bound %g units, MPFR %d bits (up to %d on cancellation)\n\n", n,
           (unsigned long long)seed, SANITY, PREC0, PRECMAX);
    run_sphere(&k, &g[0], &g[1], n, seed);
    run_ellipsoid(&k, &g[2], &g[3], n, seed);
    printf("\n");
    for (i = 0; i < 4; i++) {
        spt_g_print(&g[i]);
        passed += g[i].cases - g[i].failed;
        failed += g[i].failed;
    }
    printf("units = gap / (u*(|t| + sqrt(s)) + 2^-1074); ulps = gap / ulp(exact end); "
           "\"no cancellation\" = |exact end| >= (|t| + sqrt(s))/4\n");
    printf("CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    spt_ctx_clear(&k);
    mpfr_free_cache();
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
