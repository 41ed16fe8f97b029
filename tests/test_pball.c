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
    int i;
    if (S.failed > 20)
        return;
    printf("FAIL %s (%s)\n  map:", what, case_name);
    for (i = 0; i < 4; i++)
        printf(" [%a %a %a %a]", P[i][0], P[i][1], P[i][2], P[i][3]);
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

/* ---- cases ------------------------------------------------------------------- */
static void random_camera(xu_rng *g)
{
    double q[4], T[3], vc[3], n;
    int j;
    tc_random_camera(g, P, q, T, &n);
    /* a center in view space: in front (mostly), near the plane, behind;
     * half of the balls around the near plane (so that it cuts them) */
    if (xu_rng_int(g, 0, 1) == 0) {
        vc[2] = -tc_scaled(g, xu_rng_unit(g) + 0.01, -8, 14);
        if (xu_rng_int(g, 0, 9) == 0)
            vc[2] = -vc[2];
        R = fabs(vc[2]) * tc_scaled(g, xu_rng_unit(g), -30, 1);
    } else {
        vc[2] = -n * 4 * xu_rng_unit(g);
        R = n * tc_scaled(g, xu_rng_unit(g) + 0.01, -4, 4);
    }
    vc[0] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    vc[1] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    tc_to_world(q, T, vc, C);
    WN = n * ldexp(1.0, xu_rng_int(g, -3, 1));
    if (xu_rng_int(g, 0, 7) == 0) { /* the whole map scaled by 2^k, and wn with it */
        int i, k = xu_rng_int(g, -40, 40);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                P[i][j] = ldexp(P[i][j], k);
        WN = ldexp(WN, k);
    }
}

static void random_general(xu_rng *g)
{
    double w;
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = xu_gen_signed(g, -20, 20);
    P[3][3] = fabs(P[3][3]) * 64; /* W mostly positive near the origin */
    w = P[3][3];
    for (j = 0; j < 3; j++) {
        C[j] = tc_scaled(g, 2 * xu_rng_unit(g) - 1, -10, 2);
        w += P[3][j] * C[j];
    }
    R = tc_scaled(g, xu_rng_unit(g), -30, 3);
    /* the near plane at W's value at the center times 2^-6 .. 2 (it cuts
     * the ball often), or anywhere when W is not positive there */
    WN = w > 0x1p-90 ? w * tc_scaled(g, 1 + xu_rng_unit(g), -7, 0) : tc_scaled(g, 1 + xu_rng_unit(g), -30, 10);
}

static void identity_camera(void)
{
    static const double q0[4] = {1, 0, 0, 0}, t0[3] = {0, 0, 0};
    tc_camera(P, 2.0, 1.0, 0.125, 128, q0, t0);
}

static void ball(double c0, double c1, double c2, double r)
{
    C[0] = c0;
    C[1] = c1;
    C[2] = c2;
    R = r;
}

static void hard_cases(void)
{
    static const double bad_wn[] = {0.0, -0.0, -1.0, 0x1p-101, 0x1p121, INFINITY, -INFINITY};
    int k;
    /* the identity camera looks down -z, W = -z */
    identity_camera();
    WN = 0.125;
    ball(0, 0, -10, 1);
    run_case("ball ahead");
    ball(0, 0, 0, 4);
    run_case("ball around the camera");
    ball(3, 1, -0.5, 1);
    run_case("ball across the near plane, off axis");
    ball(0, 0, 10, 1);
    check(run_case("ball behind the camera") == CBX_EMPTY, "a ball behind the camera without CBX_EMPTY");
    ball(0, 0, 0.875, 1);
    run_case("ball touching the near plane from behind");
    ball(0, 0, -1.125, 1);
    run_case("ball touching the near plane from in front");
    ball(0, 0, -1, 1);
    run_case("ball touching the camera plane");
    ball(0, 0, -0.125, 0);
    run_case("a point on the near plane");
    ball(0, 0, -0.0625, 0);
    check(run_case("a point behind the near plane") == CBX_EMPTY, "a point behind the near plane without CBX_EMPTY");
    ball(1e6, -1e6, -1e3, 1e7);
    run_case("huge ball around the camera");
    ball(1e3, 1e3, -1e4, 1e-9);
    run_case("tiny ball far away");
    ball(0.5, 0.5, -0.25, 0.125 + 0x1p-40);
    run_case("nearly tangent to the near plane");
    /* NaN in each input, bad near planes */
    for (k = 0; k < 21; k++) {
        identity_camera();
        ball(0, 0, -1, 2);
        WN = 0.125;
        if (k < 16)
            P[k / 4][k % 4] = NAN;
        else if (k < 19)
            C[k - 16] = NAN;
        else if (k < 20)
            R = NAN;
        else
            WN = NAN;
        check(run_case("NaN") == CBX_EINVAL, "NaN without CBX_EINVAL");
    }
    identity_camera();
    for (k = 0; k < (int)(sizeof bad_wn / sizeof bad_wn[0]); k++) {
        ball(0, 0, -10, 1);   /* a ball that gets CBX_OK with wn = 0.125 */
        WN = bad_wn[k];
        check(run_case("near plane outside the domain") == CBX_ERANGE, "wn outside the domain without CBX_ERANGE");
    }
    WN = 0.125;
    for (k = 0; k < 8; k++) {   /* each row, the center, the radius outside the domain */
        identity_camera();
        ball(0, 0, -10, 1);
        if (k < 4)
            P[k][k == 3 ? 2 : k] = k == 3 ? -0x1p61 : 0x1p61;
        else if (k < 7)
            C[k - 4] = 0x1p61;
        else
            R = INFINITY;
        check(run_case("an entry, the center or the radius beyond the domain") == CBX_ERANGE,
              "outside the domain without CBX_ERANGE");
    }
    /* an end beyond 2^99: X up to 2^60 at W = 2^-100 */
    memset(P, 0, sizeof P);
    P[0][0] = 0x1p60; P[1][1] = 1; P[2][2] = 1; P[3][2] = 1;
    ball(1, 0, 0.5, 0.5);
    WN = 0x1p-100;
    check(run_case("an end beyond 2^99") == CBX_ERANGE, "an end beyond 2^99 without CBX_ERANGE");
    /* rank-deficient maps: W constant (in front, on the plane, behind); X zero */
    for (k = 0; k < 3; k++) {
        memset(P, 0, sizeof P);
        P[0][0] = 1; P[1][1] = 1; P[2][2] = 1;
        P[3][3] = k == 0 ? 2 : k == 1 ? 0.125 : 0.0625;
        ball(1, 2, 3, 4);
        WN = 0.125;
        run_case("W constant");
    }
    identity_camera();
    P[0][0] = P[0][1] = P[0][2] = P[0][3] = 0;
    ball(0, 0, -1, 4);
    run_case("X_0 zero");
    identity_camera();
    memcpy(P[0], P[3], sizeof P[0]);
    run_case("X_0 = W (X / W constant)");
    /* wide and narrow fields of view; W from 2^-90 to 2^100 */
    for (k = 0; k < 8; k++) {
        static const double q0[4] = {1, 0, 0, 0}, t0[3] = {0, 0, 0};
        int i, j;
        tc_camera(P, k < 4 ? ldexp(1.0, -6 - k) : ldexp(1.0, 4 + k), 1.5, 0.01, 1e4, q0, t0);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                P[i][j] = ldexp(P[i][j], 12 * k - 40);
        ball(-3, 5, -2, 7);
        WN = ldexp(0.01, 12 * k - 40);
        run_case("scaled wide or narrow camera");
    }
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 20000, k;
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    xu_rng g;
    g.s = seed;
    pbo_init(&S, seed + 99);
    hard_cases();
    for (k = 0; k < n; k++) {
        random_camera(&g);
        random_run("random camera");
        random_general(&g);
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
