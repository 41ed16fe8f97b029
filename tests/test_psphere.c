/*
 * test_psphere [N] [seed]: balls under a projective map (cbx_project_sphere)
 * against exact arithmetic: GMP rationals, and MPFR with directed rounding
 * where a square root is involved.
 *
 * For a case (a 4x4 map with rows X_0, X_1, X_2, W; a center c; a radius
 * r), the exact values A = X_i(c), B = W(c), |a|^2, |b|^2, a.b (a, b the
 * linear parts of rows i and 3) are rationals.  With B > |r| |b| (the ball
 * in front of the camera), X_i / W ranges over the ball between the two
 * roots of (A - t B)^2 = r^2 |a - t b|^2, which MPFR encloses to 300 bits
 * (rounded down and up).  Checked:
 *   1. statuses: NaN -> CBX_EINVAL; an entry outside the domain ->
 *      CBX_ERANGE; every status but CBX_OK -> the whole space; a ball
 *      touching, crossing or behind the camera plane -> CBX_EBEHIND; CBX_EBEHIND
 *      only when the ball comes near the camera plane (B - |r| |b| <=
 *      2^-40 (S_W + |r| |b|) + 2^-1000 + |r| 2^-520, S_W the magnitude of
 *      W at c), exactly;
 *   2. with CBX_OK: the ball in front (B > |r| |b|, exactly), every end
 *      finite, each end on the right side of the exact end (containment at
 *      the extreme points of the ball) and within the proven 2^-20
 *      (1 + |end|) of it (tightness: ps_tight); the largest distance to
 *      the exact end is printed, in units of 2^-52 (1 + |end|);
 *   3. with CBX_OK: containment at 8 exact rational points of the ball
 *      (on the sphere, by the rational parametrization of the unit sphere,
 *      and inside it): W > 0 and lo W <= X <= hi W there, in rationals;
 *   4. the radius -r gives the same status and bits as r (the same ball);
 *   5. (shown, not asserted) how often the round-to-nearest closed form
 *      (Mara and McGuire's bound, computed in binary64) misses the exact
 *      image.
 * Cases: a table of hard cases, then N random cameras (a perspective
 * projection of field of view 1 to 179 degrees times a random rigid view)
 * with balls in front of, across and behind the camera, tiny to huge,
 * and N random general maps.  The last line is "P passed, F failed".
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "certbox.h"
#include "exact_util.h"
#include "psph_oracle.h"
#include "proj_cases.h"

static double P[4][4], C[3], R;
static const char *case_name;
static pso_stats S;

static void on_fail(const char *what)
{
    int i;
    if (S.failed > 20)
        return;
    printf("FAIL %s (%s)\n  map:", what, case_name);
    for (i = 0; i < 4; i++)
        printf(" [%a %a %a %a]", P[i][0], P[i][1], P[i][2], P[i][3]);
    printf("\n  c: %a %a %a  r: %a\n", C[0], C[1], C[2], R);
}

static void run_case(const char *name, xu_rng *g)
{
    cbx_proj p;
    cbx_box o;
    cbx_status st;
    int i, j;
    (void)g;
    case_name = name;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    st = cbx_project_sphere(&p, C, R, &o);
    {   /* the same ball: radius -r gives the same bits */
        cbx_box o2;
        cbx_status st2 = cbx_project_sphere(&p, C, -R, &o2);
        if (st2 == st && memcmp(&o2, &o, sizeof o) == 0) {
            S.passed++;
        } else {
            S.failed++;
            on_fail("radius -r gives other bits than r (the same ball)");
        }
    }
    if (getenv("PSPHERE_DUMP")) {
        printf("D %s %d", name, (int)st);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                printf(" %a", P[i][j]);
        printf(" | %a %a %a %a | %a %a %a %a %a %a\n", C[0], C[1], C[2], R, o.lo[0], o.hi[0], o.lo[1], o.hi[1], o.lo[2], o.hi[2]);
    }
    pso_judge((const double (*)[4])P, C, R, st, &o, &S, on_fail);
}

/* ---- cases ------------------------------------------------------------------- */
static void camera(double F, double asp, double n, double f, const double q[4], const double T[3])
{
    tc_camera(P, F, asp, n, f, q, T);
}

static double scaled(xu_rng *g, double m, int lo, int hi)
{
    return tc_scaled(g, m, lo, hi);
}

static void random_camera(xu_rng *g)
{
    double q[4], T[3], vc[3], n;
    int j;
    tc_random_camera(g, P, q, T, &n);
    /* a center in view space: in front (mostly), beside, behind */
    vc[2] = -scaled(g, xu_rng_unit(g) + 0.01, -6, 16);
    if (xu_rng_int(g, 0, 9) == 0)
        vc[2] = -vc[2];
    vc[0] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    vc[1] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    R = fabs(vc[2]) * scaled(g, xu_rng_unit(g), -40, 1);
    /* back to world space: c = Q^T (vc - T), rounded (any double center will do) */
    tc_to_world(q, T, vc, C);
    if (xu_rng_int(g, 0, 7) == 0) { /* the whole map scaled by 2^k: W from 1e-60 to 1e60 */
        int i, k = xu_rng_int(g, -200, 200);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                P[i][j] = ldexp(P[i][j], k / 4);
    }
}

static void random_general(xu_rng *g)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = xu_gen_signed(g, -20, 20);
    P[3][3] = fabs(P[3][3]) * 64; /* W mostly positive near the origin */
    for (j = 0; j < 3; j++)
        C[j] = scaled(g, 2 * xu_rng_unit(g) - 1, -10, 2);
    R = scaled(g, xu_rng_unit(g), -30, 0);
}

static void hard_cases(xu_rng *g)
{
    static const double q0[4] = {1, 0, 0, 0}, t0[3] = {0, 0, 0};
    int i, j, k;
    /* a sphere straight ahead */
    camera(1.83, 1.0, 0.1, 100, q0, t0);
    C[0] = 0; C[1] = 0; C[2] = -10; R = 1;
    run_case("centered sphere", g);
    /* NaN in each input */
    for (k = 0; k < 20; k++) {
        camera(1.83, 1.0, 0.1, 100, q0, t0);
        C[0] = 0; C[1] = 0; C[2] = -10; R = 1;
        if (k < 16)
            P[k / 4][k % 4] = NAN;
        else if (k < 19)
            C[k - 16] = NAN;
        else
            R = NAN;
        run_case("NaN", g);
    }
    /* infinities and out-of-domain entries */
    for (k = 0; k < 6; k++) {
        camera(1.83, 1.0, 0.1, 100, q0, t0);
        C[0] = 0; C[1] = 0; C[2] = -10; R = 1;
        if (k == 0) P[0][0] = INFINITY;
        if (k == 1) P[3][3] = 0x1p121;
        if (k == 2) C[1] = 0x1p61;
        if (k == 3) R = -INFINITY;
        if (k == 4) P[1][2] = -0x1p60;   /* at the edge: in the domain */
        if (k == 5) R = 0x1p60;
        run_case("range", g);
    }
    /* a ball touching, crossing, behind the camera plane, and nearly tangent */
    for (k = 0; k < 8; k++) {
        camera(1.83, 1.0, 0.1, 100, q0, t0);
        C[0] = 0.3; C[1] = -0.2; C[2] = -1;
        R = k == 0 ? 1.0 : k == 1 ? 2.0 : k == 2 ? 1 - 0x1p-20 : k == 3 ? 1 - 0x1p-40 : k == 4 ? 1 - 0x1p-52 : 0.5;
        if (k == 5) C[2] = 5;
        if (k == 6) { C[2] = -1e-300; R = 1e-300; }
        if (k == 7) { C[2] = -1e-300; R = 0; }
        run_case("camera plane", g);
    }
    /* radius 0 and negative radius (the same ball) */
    camera(1.46, 1.5, 0.1, 100, q0, t0);
    C[0] = 1; C[1] = 2; C[2] = -7; R = 0;
    run_case("point", g);
    R = -2;
    run_case("negative radius", g);
    /* rank-deficient maps: a zero row, a row equal to W */
    camera(1.46, 1.5, 0.1, 100, q0, t0);
    for (j = 0; j < 4; j++) {
        P[0][j] = 0;
        P[1][j] = P[3][j];
    }
    C[0] = 1; C[1] = 2; C[2] = -7; R = 3;
    run_case("rank-deficient", g);
    /* very wide and very narrow fields of view, huge translations */
    for (k = 0; k < 4; k++) {
        double T[3] = {0, 0, k >= 2 ? 1e30 : 0};
        camera(k % 2 ? 0.0208 : 2000.0, 1.0, 1e-3, 1e6, q0, T); /* 179 and 0.06 degrees */
        C[0] = 0.5; C[1] = 0.25; C[2] = T[2] - 10;
        R = 2;
        run_case("field of view", g);
    }
    /* each input out of the domain alone (2^121: every check of the chain) */
    for (k = 0; k < 20; k++) {
        camera(1.83, 1.0, 0.1, 100, q0, t0);
        C[0] = 0; C[1] = 0; C[2] = -10; R = 1;
        if (k < 16)
            P[k / 4][k % 4] = 0x1p121;
        else if (k < 19)
            C[k - 16] = -0x1p121;
        else
            R = 0x1p61;
        run_case("one input out of the domain", g);
    }
    /* an end beyond 2^99 on one axis only: row 1 (then row 2) huge against
     * a constant W, the other axes in range; and a range from 0 to 2^101 */
    for (k = 1; k <= 3; k++) {
        memset(P, 0, sizeof P);
        P[0][0] = P[1][1] = P[2][2] = 1;
        P[3][3] = 0x1p-10;
        C[0] = 0.25; C[1] = 0.5; C[2] = 0.75; R = 0.125;
        if (k < 3) {
            P[k][3] = 0x1p120;
        } else {
            P[0][0] = 0x1p60;
            P[3][3] = 0x1p-80;
            C[0] = 0x1p-40;
            R = 0x1p-40;
        }
        run_case("an end beyond 2^99", g);
    }
    /* the map scaled by 2^-120 .. 2^120 (W from 1e-36 to 1e36) */
    for (k = -120; k <= 120; k += 40) {
        camera(1.83, 1.0, 0.1, 100, q0, t0);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                P[i][j] = ldexp(P[i][j], k / 3);
        C[0] = 0.1; C[1] = 0.2; C[2] = -3; R = 0.5;
        run_case("scaled map", g);
    }
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 20000, k;
    xu_rng g;
    g.s = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    pso_init(&S, g.s + 99);
    hard_cases(&g);
    for (k = 0; k < n; k++) {
        random_camera(&g);
        run_case("random camera", &g);
    }
    for (k = 0; k < n; k++) {
        random_general(&g);
        run_case("random map", &g);
    }
    printf("cbx_project_sphere: %ld cases (hard ones, %ld random cameras, %ld random maps)\n",
           S.st[0] + S.st[1] + S.st[2] + S.st[3], n, n);
    pso_print(stdout, &S);
    pso_free(&S);
    printf("%ld passed, %ld failed\n", S.passed, S.failed);
    return S.failed != 0;
}
