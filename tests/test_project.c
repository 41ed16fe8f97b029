/*
 * test_project [N] [seed]: boxes under a projective map (cbx_project_box,
 * cbx_project_boxf) against exact rational arithmetic (GMP), in both
 * formats.
 *
 * For every case (a 4x4 map, a box) the exact values X_i and W at the 8
 * corners are rationals (products and sums of floats), and so is every
 * quantity of the contract (specs/cbx_proj.h).  Checked:
 *   1. the status and special outputs: NaN -> CBX_EINVAL and the whole
 *      space; an empty axis -> CBX_EMPTY and the empty box; an entry or a
 *      box end outside the range -> CBX_ERANGE and the whole space;
 *      CBX_EBEHIND only when some corner is not clear of the camera plane
 *      (W <= 12 u S_W + 2^-1065 there), with the whole space; CBX_ERANGE
 *      for inputs in the range only with W > 0 at every corner; CBX_OK
 *      whenever every corner's quotients are in range (proj_ok, decided
 *      exactly);
 *   2. with CBX_OK, containment: W > 0 and lo_i W <= X_i <= hi_i W at the
 *      8 corners and at 4 random points of the box (every such point's
 *      image lies in the corners' hull: lemma plo_box), every end finite;
 *   3. with CBX_OK, the proven tightness: some corner has
 *      X - lo W <= 24 u (S_X + |lo| S_W) + 2^-1064 (1 + |lo| + S_W)
 *      (binary32: 2^-139), and the same for hi; and (printed) the largest
 *      used fraction of that tolerance (X - lo W over it, the least over
 *      the corners);
 *   4. out == in gives the same bits;
 *   5. (shown, not asserted) how often the round-to-nearest 8-corner
 *      divide of pbrt and three.js misses the exact image.
 * Cases: a table of hard cases (NaN in each input, empty axes, W exactly 0
 * at a corner, a box crossing the camera plane, W tiny, huge translations,
 * rank-deficient maps, 90-degree and very wide fields of view), then N
 * random camera cases (a perspective projection times a random rigid view,
 * boxes in front of, across and behind the camera, near and far, tiny and
 * large, the whole map scaled by 2^k, k up to 300 (binary32: 40), so that
 * W ranges over 1e-90 to 1e90) and N random general maps, per format.
 * The last line is "P passed, F failed".
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>

#include "certbox.h"
#include "exact_util.h"
#include "proj_oracle.h"

static int fmt32;          /* the format of the current run */



static double P[4][4], BL[3], BH[3]; /* the current case (values of the format) */
static const char *case_name;

static void fail_case(const char *what)
{
    int i;
    printf("FAIL %s (%s, binary%d)\n  map:", what, case_name, fmt32 ? 32 : 64);
    for (i = 0; i < 4; i++)
        printf(" [%a %a %a %a]", P[i][0], P[i][1], P[i][2], P[i][3]);
    printf("\n  box: [%a %a] [%a %a] [%a %a]\n", BL[0], BH[0], BL[1], BH[1], BL[2], BH[2]);
}

/* the function under test, in the current format; out as doubles */
static cbx_status run(const double lo[3], const double hi[3], double olo[3], double ohi[3], int in_place)
{
    int i, j;
    cbx_status st;
    if (!fmt32) {
        cbx_proj p;
        cbx_box b, o;
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                p.m[i][j] = P[i][j];
        for (i = 0; i < 3; i++) {
            b.lo[i] = lo[i];
            b.hi[i] = hi[i];
        }
        if (in_place) {
            st = cbx_project_box(&p, &b, &b);
            o = b;
        } else {
            st = cbx_project_box(&p, &b, &o);
        }
        for (i = 0; i < 3; i++) {
            olo[i] = o.lo[i];
            ohi[i] = o.hi[i];
        }
    } else {
        cbx_projf p;
        cbx_boxf b, o;
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                p.m[i][j] = (float)P[i][j];
        for (i = 0; i < 3; i++) {
            b.lo[i] = (float)lo[i];
            b.hi[i] = (float)hi[i];
        }
        if (in_place) {
            st = cbx_project_boxf(&p, &b, &b);
            o = b;
        } else {
            st = cbx_project_boxf(&p, &b, &o);
        }
        for (i = 0; i < 3; i++) {
            olo[i] = o.lo[i];
            ohi[i] = o.hi[i];
        }
    }
    return st;
}

/* ---- statistics ------------------------------------------------------------ */
static po_stats S;

static void on_fail(const char *what)
{
    if (S.failed <= 20)
        fail_case(what);
}

/* One case in the current format (P, BL, BH hold the format's values). */
static void check_case(const char *name)
{
    double olo[3], ohi[3], ilo[3], ihi[3];
    cbx_status st, st2;
    case_name = name;
    st = run(BL, BH, olo, ohi, 0);
    st2 = run(BL, BH, ilo, ihi, 1);
    if (st2 == st && memcmp(ilo, olo, sizeof olo) == 0 && memcmp(ihi, ohi, sizeof ohi) == 0)
        S.passed++;
    else {
        S.failed++;
        on_fail("out == in gives the same bits");
    }
    po_judge((const double (*)[4])P, BL, BH, fmt32, st, olo, ohi, &S, on_fail);
}

/* ---- cases ----------------------------------------------------------------- */
static double fmt(double v)
{
    return fmt32 ? (double)(float)v : v;
}

/* P = Proj(f, aspect, n, far) * View(R, T): OpenGL's projection, in double. */
static void camera(double f, double aspect, double n, double far, double R[3][3], const double T[3])
{
    double pr[4][4] = {{f / aspect, 0, 0, 0}, {0, f, 0, 0},
                       {0, 0, (far + n) / (n - far), 2 * far * n / (n - far)}, {0, 0, -1, 0}};
    double v[4][4] = {{R[0][0], R[0][1], R[0][2], T[0]}, {R[1][0], R[1][1], R[1][2], T[1]},
                      {R[2][0], R[2][1], R[2][2], T[2]}, {0, 0, 0, 1}};
    int i, j, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double s = 0;
            for (k = 0; k < 4; k++)
                s += pr[i][k] * v[k][j];
            P[i][j] = fmt(s);
        }
}

static void set_box(double l0, double h0, double l1, double h1, double l2, double h2)
{
    BL[0] = fmt(l0); BH[0] = fmt(h0);
    BL[1] = fmt(l1); BH[1] = fmt(h1);
    BL[2] = fmt(l2); BH[2] = fmt(h2);
}

static void identity_view(double R[3][3])
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            R[i][j] = i == j;
}

static void hard_cases(void)
{
    double R[3][3], T[3] = {0, 0, 0};
    int i, j;
    identity_view(R);
    /* a unit cube 5 in front of a 90-degree camera (f = 1) */
    camera(1, 1, 0.1, 100, R, T);
    set_box(-0.5, 0.5, -0.5, 0.5, -5.5, -4.5);
    check_case("90-degree camera, cube in front");
    /* NaN in each of the 16 entries and the 6 box ends */
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double keep = P[i][j];
            P[i][j] = NAN;
            check_case("NaN in the map");
            P[i][j] = keep;
        }
    for (i = 0; i < 3; i++) {
        double keep = BL[i];
        BL[i] = NAN;
        check_case("NaN in lo");
        BL[i] = keep;
        keep = BH[i];
        BH[i] = NAN;
        check_case("NaN in hi");
        BH[i] = keep;
    }
    /* empty axes */
    set_box(1, -1, -0.5, 0.5, -5.5, -4.5);
    check_case("empty axis");
    set_box(HUGE_VAL, HUGE_VAL, -0.5, 0.5, -5.5, -4.5);
    check_case("lo = +inf");
    /* infinite box end, infinite entry: out of range */
    set_box(-HUGE_VAL, 0.5, -0.5, 0.5, -5.5, -4.5);
    check_case("infinite box end");
    P[0][0] = HUGE_VAL;
    set_box(-0.5, 0.5, -0.5, 0.5, -5.5, -4.5);
    check_case("infinite map entry");
    /* the camera plane: W = -z, so z = 0 is W = 0 */
    camera(1, 1, 0.1, 100, R, T);
    set_box(-0.5, 0.5, -0.5, 0.5, -1, 0);
    check_case("W exactly 0 at 4 corners");
    set_box(-0.5, 0.5, -0.5, 0.5, -1, 1);
    check_case("box crossing the camera plane");
    set_box(-0.5, 0.5, -0.5, 0.5, 1, 2);
    check_case("box behind the camera");
    set_box(-0.5, 0.5, -0.5, 0.5, -1, -0x1p-60);
    check_case("box touching the camera plane (W = 2^-60)");
    set_box(-0.5, 0.5, -0.5, 0.5, -1, -0x1p-1000);
    check_case("W tiny (2^-1000) at a corner");
    /* very wide and very narrow fields of view */
    camera(1e-6, 1, 0.1, 100, R, T);
    set_box(-0.5, 0.5, -0.5, 0.5, -5.5, -4.5);
    check_case("field of view near 180 degrees");
    camera(1e6, 1.5, 0.1, 1e6, R, T);
    set_box(-1e-3, 1e-3, -1e-3, 1e-3, -1e5, -1e5 + 1e-3);
    check_case("tiny box far away, narrow field of view");
    /* huge translation beside a tiny box */
    T[0] = 1e15;
    camera(1, 1, 0.1, 100, R, T);
    set_box(-1e15 - 1, -1e15 + 1, -0.5, 0.5, -5.5, -4.5);
    check_case("huge translation, small box");
    T[0] = 0;
    /* rank-deficient: X rows zero, W constant */
    memset(P, 0, sizeof P);
    P[3][3] = 2;
    set_box(-1, 1, -1, 1, -1, 1);
    check_case("zero rows, W = 2");
    /* W constant negative: behind */
    P[3][3] = -2;
    check_case("W = -2 everywhere");
    /* the range's edges */
    memset(P, 0, sizeof P);
    P[0][0] = fmt32 ? 0x1p61 : 0x1p509;
    P[3][3] = 1;
    set_box(-1, 1, -1, 1, -1, 1);
    check_case("entry at the range's edge");
    P[0][0] = fmt32 ? 0x1p62 : 0x1p510;
    check_case("entry just outside the range");
    P[0][0] = 1;
    P[0][3] = fmt32 ? 0x1p100 : 0x1p1000;
    P[3][3] = fmt32 ? 0x1p-30 : 0x1p-10;
    check_case("quotient beyond the range (|X| / W above 2^1000)");
}

static void random_camera(xu_rng *r)
{
    double R[3][3], T[3], f, aspect, n, far, c[3], h[3];
    int i, j, k;
    xu_rand_rotation(r, R);
    for (i = 0; i < 3; i++)
        T[i] = (xu_rng_unit(r) - 0.5) * 20;
    f = 1.0 / tan((0.05 + 2.9 * xu_rng_unit(r)) / 2); /* field of view 3 to 170 degrees */
    aspect = 0.5 + 2 * xu_rng_unit(r);
    n = ldexp(1.0, xu_rng_int(r, -10, 0));
    far = n * ldexp(1.0, xu_rng_int(r, 2, 20));
    camera(f, aspect, n, far, R, T);
    /* a box in view space: mostly in front (z < 0), some across, some behind */
    {
        double zc = -ldexp(1.0, xu_rng_int(r, -4, 12)) * (0.5 + xu_rng_unit(r));
        double size = ldexp(1.0, xu_rng_int(r, -20, 4)) * (0.1 + xu_rng_unit(r));
        int mode = xu_rng_int(r, 0, 9);
        double vc[3] = {(xu_rng_unit(r) - 0.5) * fabs(zc), (xu_rng_unit(r) - 0.5) * fabs(zc), zc};
        if (mode == 0)
            vc[2] = (xu_rng_unit(r) - 0.5) * size; /* across the camera plane */
        else if (mode == 1)
            vc[2] = -zc; /* behind */
        /* back to world space: p = R^T (v - T) */
        for (i = 0; i < 3; i++) {
            c[i] = 0;
            for (j = 0; j < 3; j++)
                c[i] += R[j][i] * (vc[j] - T[j]);
            h[i] = size * (0.2 + xu_rng_unit(r));
        }
    }
    set_box(c[0] - h[0], c[0] + h[0], c[1] - h[1], c[1] + h[1], c[2] - h[2], c[2] + h[2]);
    /* scale the whole map by 2^k: the same image, W scaled */
    k = xu_rng_int(r, fmt32 ? -40 : -300, fmt32 ? 40 : 300);
    if (xu_rng_int(r, 0, 2) == 0)
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                P[i][j] = fmt(ldexp(P[i][j], k));
    check_case("random camera");
}

static void random_general(xu_rng *r)
{
    int i, j, emax = fmt32 ? 20 : 200;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = fmt(xu_rng_int(r, 0, 5) == 0 ? 0.0 : xu_gen_signed(r, -emax, emax));
    /* a W row positive on most boxes: a dominant translation */
    if (xu_rng_int(r, 0, 3) != 0)
        P[3][3] = fmt(fabs(P[3][3]) + ldexp(1.0, emax));
    for (i = 0; i < 3; i++) {
        double a = xu_gen_signed(r, -emax / 2, emax / 2), b = xu_gen_signed(r, -emax / 2, emax / 2);
        BL[i] = fmt(a < b ? a : b);
        BH[i] = fmt(a < b ? b : a);
    }
    check_case("random general map");
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 20000, k, passed = 0, failed = 0;
    unsigned long seed = argc > 2 ? strtoul(argv[2], NULL, 0) : 1;
    int is32;
    for (is32 = 0; is32 <= 1; is32++) {
        xu_rng r = {seed * 0x9e3779b97f4a7c15ull + (uint64_t)is32};
        long total;
        memset(&S, 0, sizeof S);
        S.npoints = 4;
        S.rng = seed;
        fmt32 = is32;
        hard_cases();
        for (k = 0; k < n; k++) {
            random_camera(&r);
            random_general(&r);
        }
        total = S.st[0] + S.st[1] + S.st[2] + S.st[3];
        printf("binary%d: %ld cases (%ld hard, %ld random cameras, %ld random maps): "
               "CBX_OK %ld, CBX_EBEHIND %ld, CBX_ERANGE %ld, NaN/empty %ld\n",
               is32 ? 32 : 64, total, total - 2 * n, n, n, S.st[0], S.st[1], S.st[2], S.st[3]);
        printf("binary%d: containment at the 8 corners and %ld random points, proven tightness, "
               "each end's excess at most %.3f of the proven tolerance; %ld checks passed, %ld failed\n",
               is32 ? 32 : 64, S.points, S.max_frac, S.passed, S.failed);
        if (!is32)
            printf("binary64: the round-to-nearest 8-corner divide (pbrt, three.js) misses the exact image "
                   "in %ld of %ld cases with CBX_OK\n", S.naive_miss, S.naive_cases);
        passed += S.passed;
        failed += S.failed;
    }
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed != 0;
}
