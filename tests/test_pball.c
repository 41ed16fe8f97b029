/*
 * test_pball [N] [seed]: balls under a projective map clipped at a near
 * plane (cbx_project_sphere_near) against exact arithmetic (GMP rationals
 * for the statuses and the points, MPFR at 1200 bits for the exact ends'
 * closed form).
 *
 * Checked, per call (tests/pball_oracle.c):
 *   1. statuses: NaN (wn included) -> CBX_EINVAL; outside the domain
 *      (wn <= 0 included) -> CBX_ERANGE; every status but CBX_OK -> the
 *      whole space or, for CBX_EMPTY, the empty box; CBX_EMPTY for a ball in
 *      the domain only when W < wn on the whole ball, exactly;
 *   2. with CBX_OK: something in front of the near plane, every end finite,
 *      on the right side of the exact end and within the proven 2^-20
 *      (1 + |end|) of it (pb_tight); the distance to the exact end is
 *      printed, in units of 2^-52 (1 + |end|);
 *   3. with CBX_OK: lo W <= X <= hi W at 8 random rational points of the
 *      ball in front of the near plane;
 * and, here:
 *   4. radius -r gives the same status and bits as r (the same ball);
 *   5. a ball wholly in front of the near plane gets cbx_project_sphere's
 *      exact ends: each end of both within 2^-20 (1 + |end|) (both are
 *      judged against the exact end as well);
 *   6. CBX_ERANGE in the domain is rare: below 1% of the random cases
 *      where W's magnitude on the ball (|W(c)| + |r| |b|) is at most
 *      2^20 wn; above that it is shown.
 * Cases: a table of hard cases, then N random cameras (fields of view 1 to
 * 179 degrees, random rigid views) with balls in front of, across and
 * behind the near plane, tiny to huge, and N random general maps.  The
 * last line is "P passed, F failed".
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "certbox.h"
#include "exact_util.h"
#include "pball_oracle.h"
#include "proj_cases.h"

static double P[4][4], C[3], R, WN;
static const char *case_name;
static pbo_stats S;
static long random_cases, random_erange, wide_cases, wide_erange, same_as_unclipped;

static void on_fail(const char *what)
{
    if (S.failed > 20)
        return;
    tc_fail_map(what, case_name, (const double (*)[4])P);
    printf("\n  c: %a %a %a  r: %a  wn: %a\n", C[0], C[1], C[2], R, WN);
}

static void check(int cond, const char *what)
{
    if (cond) {
        S.passed++;
    } else {
        S.failed++;
        on_fail(what);
    }
}

static cbx_status run_case(const char *name)
{
    cbx_proj p;
    cbx_box o, o2, u;
    cbx_status st, st2;
    int i, j;
    case_name = name;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    st = cbx_project_sphere_near(&p, C, R, WN, &o);
    st2 = cbx_project_sphere_near(&p, C, -R, WN, &o2);
    check(st2 == st && memcmp(&o2, &o, sizeof o) == 0, "radius -r gives other bits than r (the same ball)");
    if (getenv("PBALL_DUMP") && st != CBX_OK) {
        printf("D %s %d", name, (int)st);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                printf(" %a", P[i][j]);
        printf(" | %a %a %a %a | %a\n", C[0], C[1], C[2], R, WN);
    }
    pbo_judge((const double (*)[4])P, C, R, WN, st, &o, &S, on_fail);
    /* wholly in front of the near plane (W(c) - |r| |b| >= wn, with a
     * margin for the rounding here): the unclipped bound's exact ends */
    if (st == CBX_OK) {
        double b = sqrt(P[3][0] * P[3][0] + P[3][1] * P[3][1] + P[3][2] * P[3][2]);
        double w = P[3][0] * C[0] + P[3][1] * C[1] + P[3][2] * C[2] + P[3][3];
        if (w - fabs(R) * b >= 2 * WN && cbx_project_sphere(&p, C, R, &u) == CBX_OK) {
            for (i = 0; i < 3; i++) {
                check(fabs(o.lo[i] - u.lo[i]) <= ldexp(1 + fabs(u.lo[i]), -20)
                      && fabs(o.hi[i] - u.hi[i]) <= ldexp(1 + fabs(u.hi[i]), -20),
                      "a ball in front of the near plane: the unclipped ends");
            }
            same_as_unclipped++;
        }
    }
    return st;
}

/* W's magnitude on the ball at most 2^20 wn */
static int moderate(void)
{
    double b = fabs(P[3][0]) + fabs(P[3][1]) + fabs(P[3][2]);
    double s = fabs(P[3][0] * C[0]) + fabs(P[3][1] * C[1]) + fabs(P[3][2] * C[2]) + fabs(P[3][3]) + fabs(R) * b;
    return s <= ldexp(WN, 20);
}

static void random_run(const char *name)
{
    long before = S.erange;
    int m = moderate();
    run_case(name);
    if (m) {
        random_cases++;
        random_erange += S.erange - before;
    } else {
        wide_cases++;
        wide_erange += S.erange - before;
    }
}

/* ---- cases (tests/proj_cases.c) ------------------------------------------------ */
static void hard_run(const char *name, cbx_status want, const char *what)
{
    cbx_status st = run_case(name);
    if (what)
        check(st == want, what);
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 20000, k;
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    xu_rng g;
    g.s = seed;
    pbo_init(&S, seed + 99);
    tc_ball_hard(P, C, &R, &WN, 0x1p-40, hard_run);
    for (k = 0; k < n; k++) {
        tc_ball_camera(&g, P, C, &R, &WN);
        random_run("random camera");
        tc_ball_general(&g, P, C, &R, &WN);
        random_run("random general map");
    }
    case_name = "the random cases";
    check(random_erange * 100 <= random_cases, "CBX_ERANGE in the domain for 1% or more of the random cases");
    printf("test_pball: %ld random cameras and %ld random general maps (seed %llu), and the hard cases\n",
           n, n, (unsigned long long)seed);
    pbo_print(stdout, &S);
    printf("  balls wholly in front of the near plane compared with cbx_project_sphere: %ld\n", same_as_unclipped);
    printf("  CBX_ERANGE among the random cases with W's magnitude at most 2^20 wn: %ld of %ld (asserted below 1%%);\n"
           "  among those with a larger W (shown): %ld of %ld\n", random_erange, random_cases, wide_erange, wide_cases);
    printf("%ld passed, %ld failed\n", S.passed, S.failed);
    pbo_free(&S);
    return S.failed != 0;
}
