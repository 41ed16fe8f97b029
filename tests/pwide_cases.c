/*
 * pwide_cases.c: the hard cases of tests/test_pwide.c (the binary32 twins of
 * the projective bounds): the ball's hard cases as ellipsoids, test_psphere's
 * and test_pball's tables through the twins, test_pnear's box cases, and the
 * float cases of the twins' own (extreme floats in each input, empty float
 * boxes, subnormal ends, ends near 2^98).  Each case sets the driver's
 * current inputs (pwt_P, pwt_C, ...) and runs the twins through the
 * driver's pwt_run_* (tests/pwide_parts.h).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "certbox.h"
#include "exact_util.h"
#include "proj_cases.h"
#include "pwide_parts.h"
/* the ball's hard cases as ellipsoids: a ball, and a tilted disk */
int pwt_ell_kind;
void pwt_ell_run(const char *name, cbx_status want, const char *what)
{
    (void)want;
    (void)what;
    pwt_E[0] = pwt_E[1] = pwt_E[2] = pwt_R;
    tc_identity3(pwt_Q);
    if (pwt_ell_kind == 1) {
        tc_rotation(pwt_Q, 0.9, 0.3, -0.2, 0.1);
        pwt_E[2] = 0;
    }
    pwt_run_ell(name);
}

/* ---- cases: test_psphere's and test_pball's (tests/proj_cases.c) ------------------ */
static const double q0[4] = {1, 0, 0, 0}, t0[3] = {0, 0, 0};

void pwt_sph_run(const char *name, cbx_status want, const char *what)
{
    cbx_status st = pwt_run_sph(name);
    if (what)
        pwt_expect(st, want, what);
}

void pwt_ball_run(const char *name, cbx_status want, const char *what)
{
    cbx_status st = pwt_run_ball(name);
    if (what)
        pwt_expect(st, want, what);
}

/* ---- cases: test_pnear's ---------------------------------------------------------- */
/* a box wholly in front of the camera plane (cbx_project_box gives CBX_OK
 * on the binary64 case), the near plane far below it */
void pwt_near_in_front(xu_rng *g)
{
    cbx_proj p;
    cbx_box o;
    int i, j;
    tc_box_camera(g, pwt_P, &pwt_B, &pwt_WN);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = pwt_P[i][j];
    if (cbx_project_box(&p, &pwt_B, &o) != CBX_OK)
        return;
    pwt_WN = 0x1p-90;
    pwt_run_near("box in front, near plane at 2^-90");
}

void pwt_near_run(const char *name, cbx_status want, const char *what)
{
    cbx_status st = pwt_run_near(name);
    if (what)
        pwt_expect(st, want, what);
}

/* ---- cases: float's own ------------------------------------------------------------ */
/* the three twins on the current map, ball (C, R), its box [C - |R|, C + |R|] and WN */
static void run_all(const char *name)
{
    int j;
    for (j = 0; j < 3; j++) {
        pwt_B.lo[j] = pwt_C[j] - fabs(pwt_R);
        pwt_B.hi[j] = pwt_C[j] + fabs(pwt_R);
    }
    pwt_run_sph(name);
    pwt_run_near(name);
    pwt_run_ball(name);
}

static void base_case(void)
{
    tc_identity_camera(pwt_P);
    tc_set_ball(pwt_C, &pwt_R, 0.5, -0.25, -4, 1);
    pwt_WN = 0.125;
}

void pwt_float_hard(void)
{
    /* each input in turn: infinities (CBX_ERANGE), the largest float (out
     * of the domain) and the least subnormal (in it, except wn) */
    static const double v[] = {INFINITY, -INFINITY, FLT_MAX, -FLT_MAX, 0x1p-149, -0x1p-149, 0x1.ffffffp127, -1e39};
    int k, s, j, i;
    for (k = 0; k < (int)(sizeof v / sizeof v[0]); k++) {
        for (s = 0; s < 31; s++) {   /* 16 map entries, the center, the radii, rot */
            base_case();
            pwt_E[0] = 1; pwt_E[1] = 0.5; pwt_E[2] = 0.25;
            tc_identity3(pwt_Q);
            if (s < 16)
                pwt_P[s / 4][s % 4] = v[k];
            else if (s < 19)
                pwt_C[s - 16] = v[k];
            else if (s < 22)
                pwt_E[s - 19] = v[k];
            else
                pwt_Q[(s - 22) / 3][(s - 22) % 3] = v[k];
            pwt_run_ell("an extreme float in one input of the ellipsoid");
        }
        for (s = 0; s < 21; s++) {   /* 16 map entries, the center, the radius, wn */
            base_case();
            if (s < 16)
                pwt_P[s / 4][s % 4] = v[k];
            else if (s < 19)
                pwt_C[s - 16] = v[k];
            else if (s < 20)
                pwt_R = v[k];
            else
                pwt_WN = v[k];
            if (s < 20)
                pwt_run_sph("an extreme float in one input");
            pwt_run_ball("an extreme float in one input");
        }
        for (s = 0; s < 23; s++) {   /* 16 map entries, the 6 box ends, wn */
            base_case();
            tc_set_box(&pwt_B, 0, 1, -1, 0, -8, -2);
            if (s < 16)
                pwt_P[s / 4][s % 4] = v[k];
            else if (s < 22)
                ((s - 16) % 2 ? pwt_B.hi : pwt_B.lo)[(s - 16) / 2] = v[k];
            else
                pwt_WN = v[k];
            pwt_run_near("an extreme float in one input");
        }
    }
    /* empty float boxes: hi < lo, lo = +inf, hi = -inf (each alone: [+inf,
     * +inf], [-inf, -inf]); alone, with NaN
     * (CBX_EINVAL first), with an infinite or out-of-domain input or a bad
     * wn (CBX_EMPTY first) */
    for (k = 0; k < 5; k++)
        for (s = 0; s < 5; s++) {
            base_case();
            tc_set_box(&pwt_B, 0, 1, -1, 0, -8, -2);
            if (k == 0) { pwt_B.lo[1] = 0.5f; pwt_B.hi[1] = 0.25f; }
            if (k == 1) pwt_B.lo[2] = INFINITY;
            if (k == 2) pwt_B.hi[0] = -INFINITY;
            if (k == 3) { pwt_B.lo[1] = INFINITY; pwt_B.hi[1] = INFINITY; }   /* lo = +inf, not hi < lo */
            if (k == 4) { pwt_B.lo[2] = -INFINITY; pwt_B.hi[2] = -INFINITY; } /* hi = -inf, not hi < lo */
            if (s == 1) pwt_P[2][1] = NAN;
            if (s == 2) pwt_P[0][3] = INFINITY;
            if (s == 3) pwt_B.lo[0] = -INFINITY;
            if (s == 4) pwt_WN = -1;
            pwt_expect(pwt_run_near("an empty float box"), s == 1 ? CBX_EINVAL : CBX_EMPTY,
                   s == 1 ? "an empty box with NaN without CBX_EINVAL" : "an empty box without CBX_EMPTY");
        }
    /* a box one float wide; negative zeros */
    base_case();
    tc_set_box(&pwt_B, 0.5, 0x1.000002p-1, -0.25, -0.25, -4, -4);
    pwt_run_near("a box one float wide");
    base_case();
    tc_set_ball(pwt_C, &pwt_R, -0.0, -0.0, -4, -0.0);
    run_all("negative zeros");
    /* ends in float's subnormal range and around 0: rows X scaled down
     * (2^-120 .. 2^-150: the entries themselves float subnormals) */
    for (k = 0; k < 4; k++) {
        base_case();
        for (j = 0; j < 3; j++)
            for (i = 0; i < 4; i++)
                pwt_P[j][i] = ldexp(pwt_P[j][i], -120 - 10 * k);
        run_all("ends in float's subnormal range");
        tc_set_ball(pwt_C, &pwt_R, 0, 0, -4, 1);
        run_all("ends around 0, tiny");
    }
    /* X / W constant 0 (a zero row) and exactly representable ends */
    memset(pwt_P, 0, sizeof pwt_P);
    pwt_P[1][1] = 1; pwt_P[2][2] = 1; pwt_P[3][3] = 1;
    tc_set_ball(pwt_C, &pwt_R, 0.5, 0.25, 0.75, 0.125);
    pwt_WN = 0.5;
    run_all("a zero row, the rest the identity");
    /* ends near 2^98 (X up to 2^60 times 2^38) */
    memset(pwt_P, 0, sizeof pwt_P);
    pwt_P[0][0] = 0x1p60; pwt_P[1][1] = 1; pwt_P[2][2] = 1; pwt_P[3][3] = 1;
    tc_set_ball(pwt_C, &pwt_R, 0x1p38, 0, 0, 1);
    pwt_WN = 0.5;
    run_all("ends near 2^98");
    /* a double case that float rounding moves across the camera plane */
    tc_camera(pwt_P, 1.83, 1.0, 0.1, 100, q0, t0);
    tc_set_ball(pwt_C, &pwt_R, 0.3, -0.2, -1, 1 - 0x1p-30);
    run_all("a ball tangent to the camera plane in float");
}
