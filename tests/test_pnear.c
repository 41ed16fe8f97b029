/*
 * test_pnear [N] [seed]: boxes under a projective map clipped at a near
 * plane (cbx_project_box_near) against exact arithmetic (GMP rationals:
 * the vertices of the clipped box, and X / W there, are rational).
 *
 * Checked, per call (tests/pnear_oracle.c):
 *   1. statuses: NaN -> CBX_EINVAL; an empty box -> CBX_EMPTY; outside the
 *      domain (wn <= 0 included) -> CBX_ERANGE; every status but CBX_OK ->
 *      the whole space or, for CBX_EMPTY, the empty box; CBX_EMPTY for a
 *      box in the domain only when W < wn at its 8 corners, exactly;
 *   2. with CBX_OK: something in front of the near plane, every end finite,
 *      on the right side of the exact end and within the proven 2^-20
 *      (1 + |end|) of it (pn_tight); the distance to the exact end is
 *      printed, in units of 2^-52 (1 + |end|);
 *   3. with CBX_OK: lo W <= X <= hi W at each vertex of the clipped box and
 *      at 6 random rational points of the box in front of the near plane;
 * and, here:
 *   4. out == in gives the same status and bits;
 *   5. boxes wholly in front of the camera plane (cbx_project_box gives
 *      CBX_OK) with the near plane far below them (wn = 2^-90);
 *   6. CBX_ERANGE in the domain is rare: below 1% of the random cases
 *      where W's magnitude on the box is at most 2^20 wn (a search that
 *      fails would show here); above that it is expected (the witness of
 *      tightness needs W to better than 2^-20 wn) and shown.
 * Cases: a table of hard cases, then N random cameras (fields of view 1 to
 * 179 degrees, random rigid views) with boxes in front of, across and
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
#include "pnear_oracle.h"
#include "proj_cases.h"

static double P[4][4], WN;
static cbx_box B;
static const char *case_name;
static pno_stats S;
static long random_cases, random_erange, wide_cases, wide_erange;

static cbx_status run_case(const char *name);

/* W's magnitude over the box (|b0 x| + |b1 y| + |b2 z| + |b3| at the
 * corners, the largest) at most 2^20 wn: the near plane not far below the
 * rounding of W (above that, the witness of tightness needs W computed to
 * better than 2^-20 wn, and CBX_ERANGE is expected; counted apart) */
static int moderate(void)
{
    double s = 0;
    int k, j;
    for (k = 0; k < 8; k++) {
        double t = fabs(P[3][3]);
        for (j = 0; j < 3; j++)
            t += fabs(P[3][j] * ((k >> j) & 1 ? B.hi[j] : B.lo[j]));
        if (t > s)
            s = t;
    }
    return s <= ldexp(WN, 20);
}

static void random_run(const char *name)
{
    long before = S.erange;
    int m = moderate();
    S.wide = !m;
    run_case(name);
    S.wide = 0;
    if (m) {
        random_cases++;
        random_erange += S.erange - before;
    } else {
        wide_cases++;
        wide_erange += S.erange - before;
    }
}

static void on_fail(const char *what)
{
    if (S.failed > 20)
        return;
    tc_fail_map(what, case_name, (const double (*)[4])P);
    printf("\n  box: [%a %a] [%a %a] [%a %a]  wn: %a\n", B.lo[0], B.hi[0], B.lo[1], B.hi[1], B.lo[2], B.hi[2], WN);
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
    cbx_box o, a;
    cbx_status st, sa;
    int i, j;
    case_name = name;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    st = cbx_project_box_near(&p, &B, WN, &o);
    a = B;
    sa = cbx_project_box_near(&p, &a, WN, &a);
    check(sa == st && memcmp(&a, &o, sizeof o) == 0, "out == in gives other bits");
    if (getenv("PNEAR_DUMP") && st == CBX_ERANGE) {
        printf("D %s", name);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                printf(" %a", P[i][j]);
        printf(" | %a %a %a %a %a %a | %a\n", B.lo[0], B.hi[0], B.lo[1], B.hi[1], B.lo[2], B.hi[2], WN);
    }
    pno_judge((const double (*)[4])P, &B, WN, st, &o, &S, on_fail);
    return st;
}

/* A box wholly in front of the camera plane (cbx_project_box gives
 * CBX_OK) with the near plane far below every corner (wn = 2^-90): the
 * clipped bound is the unclipped one, judged against the same exact
 * vertices (the corners). */
static void in_front_case(const char *name)
{
    cbx_proj p;
    cbx_box o;
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    if (cbx_project_box(&p, &B, &o) != CBX_OK)
        return;
    WN = 0x1p-90;
    run_case(name);
}

/* ---- cases ------------------------------------------------------------------- */
/* the five random cameras of test_pnear 20000 1 with W's magnitude at most
 * 2^20 wn that got CBX_ERANGE (the part in front a sliver) */
static void sliver_cases(void)
{
    static const double c[][23] = {
        {0x1.75f3c5867623dp+1, -0x1.30fee123f5ca2p+3, 0x1.f551ddd473114p+2, -0x1.4010b9c834832p+5,
         -0x1.78b1691329002p+2, 0x1.df2edd4866044p+2, 0x1.69c66f3e3d027p+3, 0x1.6b1313ad8d1bdp+15,
         0x1.c6b6dc83e9be4p-1, 0x1.b07bb5c3be38ep-2, 0x1.76173f419c725p-3, 0x1.70cbee5890bc2p+9,
         0x1.c69a71f975d34p-1, 0x1.b060aee099162p-2, 0x1.75ffde88ae2p-3, 0x1.70b5e24a0ba74p+9,
         0x1.2ae32d2ee2ecp+9, 0x1.2ae34030b4bccp+9, -0x1.dc897e79775abp+10, -0x1.dc869730f0b71p+10,
         -0x1.3d242b5dc850ep+11, -0x1.3d23d4d9d78bep+11, 0x1p-7},
        {0x1.351fcb7d5e939p+2, -0x1.683d943db42dfp+1, -0x1.3344453cc3e5p+1, 0x1.1878d473cd9afp+10,
         0x1.ee5cd1efdaa43p+1, 0x1.00d487f13a002p+2, 0x1.887c2a879013ap+1, 0x1.9f83bad199f65p-4,
         -0x1.a91eafd8fd497p-6, 0x1.3ecd601e52aa8p-1, -0x1.907ed8eab858ap-1, -0x1.83d750d686c94p+7,
         -0x1.a9116718a183p-6, 0x1.3ec369db2ac49p-1, -0x1.907255260015cp-1, -0x1.83c7325c79fd4p+7,
         -0x1.2ee46fc0c293ep+7, -0x1.2ee0589b7dab6p+7, 0x1.9c047ad475c6fp+7, 0x1.9c056e84ace13p+7,
         -0x1.3b9381f51acfep+6, -0x1.3b8d0da4588ccp+6, 0x1p-8}};
    int k, i, j;
    for (k = 0; k < (int)(sizeof c / sizeof c[0]); k++) {
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                P[i][j] = c[k][4 * i + j];
        tc_set_box(&B, c[k][16], c[k][17], c[k][18], c[k][19], c[k][20], c[k][21]);
        WN = c[k][22];
        run_case("a sliver in front of the near plane");
    }
}

/* the runner of a case that tc_box_hard has set up in P, B and WN */
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
    pno_init(&S, seed + 99);
    tc_box_hard(P, &B, &WN, sliver_cases, hard_run);
    for (k = 0; k < n; k++) {
        tc_box_camera(&g, P, &B, &WN);
        random_run("random camera");
        tc_box_general(&g, P, &B, &WN);
        random_run("random general map");
        if (k % 8 == 0) {
            tc_box_camera(&g, P, &B, &WN);
            in_front_case("box in front, near plane at 2^-90");
        }
    }
    case_name = "the random cases";
    check(random_erange * 100 <= random_cases, "CBX_ERANGE in the domain for 1% or more of the random cases");
    printf("test_pnear: %ld random cameras and %ld random general maps (seed %llu), and the hard cases\n",
           n, n, (unsigned long long)seed);
    pno_print(stdout, &S);
    printf("  CBX_ERANGE among the random cases with W's magnitude at most 2^20 wn: %ld of %ld (asserted below 1%%);\n"
           "  among those with a larger W (shown): %ld of %ld\n", random_erange, random_cases, wide_erange, wide_cases);
    printf("%ld passed, %ld failed\n", S.passed, S.failed);
    pno_free(&S);
    return S.failed != 0;
}
