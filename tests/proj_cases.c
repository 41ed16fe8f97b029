/* Cameras and cases for the projective tests (tests/proj_cases.h). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "proj_cases.h"

static void rotation(const double q[4], double Q[3][3])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    Q[0][0] = 1 - 2 * (y * y + z * z); Q[0][1] = 2 * (x * y - w * z); Q[0][2] = 2 * (x * z + w * y);
    Q[1][0] = 2 * (x * y + w * z); Q[1][1] = 1 - 2 * (x * x + z * z); Q[1][2] = 2 * (y * z - w * x);
    Q[2][0] = 2 * (x * z - w * y); Q[2][1] = 2 * (y * z + w * x); Q[2][2] = 1 - 2 * (x * x + y * y);
}

void tc_camera(double P[4][4], double F, double asp, double n, double f, const double q[4], const double T[3])
{
    double Pm[4][4] = {{0}}, V[4][4] = {{0}}, Q[3][3];
    int i, j, k;
    Pm[0][0] = F / asp;
    Pm[1][1] = F;
    Pm[2][2] = (f + n) / (n - f);
    Pm[2][3] = 2 * f * n / (n - f);
    Pm[3][2] = -1;
    rotation(q, Q);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++)
            V[i][j] = Q[i][j];
        V[i][3] = T[i];
    }
    V[3][3] = 1;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double s = 0;
            for (k = 0; k < 4; k++)
                s += Pm[i][k] * V[k][j];
            P[i][j] = s;
        }
}

void tc_to_world(const double q[4], const double T[3], const double v[3], double c[3])
{
    double Q[3][3], d[3];
    int j;
    rotation(q, Q);
    for (j = 0; j < 3; j++)
        d[j] = v[j] - T[j];
    for (j = 0; j < 3; j++)
        c[j] = Q[0][j] * d[0] + Q[1][j] * d[1] + Q[2][j] * d[2];
}

double tc_scaled(xu_rng *g, double m, int lo, int hi)
{
    int e = xu_rng_int(g, lo, hi);
    return ldexp(m, e);
}

void tc_random_camera(xu_rng *g, double P[4][4], double q[4], double T[3], double *n)
{
    double nq = 0, F, f;
    int j;
    for (j = 0; j < 4; j++) {
        q[j] = 2 * xu_rng_unit(g) - 1;
        nq += q[j] * q[j];
    }
    nq = sqrt(nq);
    for (j = 0; j < 4; j++)
        q[j] /= nq;
    for (j = 0; j < 3; j++)
        T[j] = tc_scaled(g, 2 * xu_rng_unit(g) - 1, -2, 12);
    F = tc_scaled(g, 1 + xu_rng_unit(g), -7, 6);
    *n = ldexp(1.0, xu_rng_int(g, -8, 2));
    f = *n * ldexp(1.0, xu_rng_int(g, 2, 20));
    tc_camera(P, F, 0.5 + 2 * xu_rng_unit(g), *n, f, q, T);
}

void tc_identity_camera(double P[4][4])
{
    static const double q0[4] = {1, 0, 0, 0}, t0[3] = {0, 0, 0};
    tc_camera(P, 2.0, 1.0, 0.125, 128, q0, t0);
}

/* ---- random cases ---------------------------------------------------------------- */
/* the whole map scaled by 2^k */
static void scale_map(double P[4][4], int k)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = ldexp(P[i][j], k);
}

/* a general map: entries 2^-20 .. 2^20, W mostly positive near the origin */
static void general_map(xu_rng *g, double P[4][4])
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = xu_gen_signed(g, -20, 20);
    P[3][3] = fabs(P[3][3]) * 64;
}

/* the view point's x and y from its z (within twice the distance), back
 * to world space: c = Q^T (vc - T), rounded (any double will do) */
static void view_to_world(xu_rng *g, const double q[4], const double T[3], double vc[3], double c[3])
{
    vc[0] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    vc[1] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    tc_to_world(q, T, vc, c);
}

/* the near plane at the camera's n times 2^-3 .. 2; one time in 8 the
 * whole map scaled by 2^k, and wn with it */
static void near_plane(xu_rng *g, double P[4][4], double n, double *wn)
{
    *wn = n * ldexp(1.0, xu_rng_int(g, -3, 1));
    if (xu_rng_int(g, 0, 7) == 0) {
        int k = xu_rng_int(g, -40, 40);
        scale_map(P, k);
        *wn = ldexp(*wn, k);
    }
}

/* the near plane at W's value w at the center times 2^-7 .. 2 (it cuts the
 * ball or box often), or anywhere when W is not positive there */
static double near_at(xu_rng *g, double w)
{
    return w > 0x1p-90 ? w * tc_scaled(g, 1 + xu_rng_unit(g), -7, 0) : tc_scaled(g, 1 + xu_rng_unit(g), -30, 10);
}

void tc_sphere_camera(xu_rng *g, double P[4][4], double c[3], double *r)
{
    double q[4], T[3], vc[3], n;
    tc_random_camera(g, P, q, T, &n);
    /* a center in view space: in front (mostly), beside, behind */
    vc[2] = -tc_scaled(g, xu_rng_unit(g) + 0.01, -6, 16);
    if (xu_rng_int(g, 0, 9) == 0)
        vc[2] = -vc[2];
    vc[0] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    vc[1] = vc[2] * (2 * xu_rng_unit(g) - 1) * 2;
    *r = fabs(vc[2]) * tc_scaled(g, xu_rng_unit(g), -40, 1);
    tc_to_world(q, T, vc, c);
    if (xu_rng_int(g, 0, 7) == 0) /* the whole map scaled by 2^k: W from 1e-60 to 1e60 */
        scale_map(P, xu_rng_int(g, -200, 200) / 4);
}

void tc_sphere_general(xu_rng *g, double P[4][4], double c[3], double *r)
{
    int j;
    general_map(g, P);
    for (j = 0; j < 3; j++)
        c[j] = tc_scaled(g, 2 * xu_rng_unit(g) - 1, -10, 2);
    *r = tc_scaled(g, xu_rng_unit(g), -30, 0);
}

void tc_box_camera(xu_rng *g, double P[4][4], cbx_box *b, double *wn)
{
    double q[4], T[3], vc[3], c[3], n, hs;
    int e, j;
    tc_random_camera(g, P, q, T, &n);
    /* a center in view space: in front (mostly), near the plane, behind;
     * half of the boxes around the near plane (so that it cuts them) */
    if (xu_rng_int(g, 0, 1) == 0) {
        vc[2] = -tc_scaled(g, xu_rng_unit(g) + 0.01, -8, 14);
        if (xu_rng_int(g, 0, 9) == 0)
            vc[2] = -vc[2];
        hs = fabs(vc[2]) + n;
        e = -30;
    } else {
        vc[2] = -n * 4 * xu_rng_unit(g);
        hs = n * 8;
        e = -4;
    }
    view_to_world(g, q, T, vc, c);
    for (j = 0; j < 3; j++) {
        double h = hs * tc_scaled(g, xu_rng_unit(g), e, 1);
        b->lo[j] = c[j] - h;
        b->hi[j] = c[j] + h;
    }
    near_plane(g, P, n, wn);
}

void tc_box_general(xu_rng *g, double P[4][4], cbx_box *b, double *wn)
{
    double w;
    int j;
    general_map(g, P);
    w = P[3][3];
    for (j = 0; j < 3; j++) {
        double c = tc_scaled(g, 2 * xu_rng_unit(g) - 1, -10, 4);
        double h = tc_scaled(g, xu_rng_unit(g), -30, 3);
        b->lo[j] = c - h;
        b->hi[j] = c + h;
        w += P[3][j] * c;
    }
    *wn = near_at(g, w);
}

void tc_ball_camera(xu_rng *g, double P[4][4], double c[3], double *r, double *wn)
{
    double q[4], T[3], vc[3], n;
    tc_random_camera(g, P, q, T, &n);
    /* a center in view space: in front (mostly), near the plane, behind;
     * half of the balls around the near plane (so that it cuts them) */
    if (xu_rng_int(g, 0, 1) == 0) {
        vc[2] = -tc_scaled(g, xu_rng_unit(g) + 0.01, -8, 14);
        if (xu_rng_int(g, 0, 9) == 0)
            vc[2] = -vc[2];
        *r = fabs(vc[2]) * tc_scaled(g, xu_rng_unit(g), -30, 1);
    } else {
        vc[2] = -n * 4 * xu_rng_unit(g);
        *r = n * tc_scaled(g, xu_rng_unit(g) + 0.01, -4, 4);
    }
    view_to_world(g, q, T, vc, c);
    near_plane(g, P, n, wn);
}

void tc_ball_general(xu_rng *g, double P[4][4], double c[3], double *r, double *wn)
{
    double w;
    int j;
    general_map(g, P);
    w = P[3][3];
    for (j = 0; j < 3; j++) {
        c[j] = tc_scaled(g, 2 * xu_rng_unit(g) - 1, -10, 2);
        w += P[3][j] * c[j];
    }
    *r = tc_scaled(g, xu_rng_unit(g), -30, 3);
    *wn = near_at(g, w);
}

/* ---- hard cases ------------------------------------------------------------------ */
static const double q0[4] = {1, 0, 0, 0}, t0[3] = {0, 0, 0};

void tc_scaled_camera(double P[4][4], int k)
{
    tc_camera(P, k < 4 ? ldexp(1.0, -6 - k) : ldexp(1.0, 4 + k), 1.5, 0.01, 1e4, q0, t0);
    scale_map(P, 12 * k - 40);
}

static void zero_map(double P[4][4])
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = 0;
}

void tc_set_ball(double c[3], double *r, double c0, double c1, double c2, double r0)
{
    c[0] = c0;
    c[1] = c1;
    c[2] = c2;
    *r = r0;
}

void tc_sphere_hard(double P[4][4], double c[3], double *r, tc_run run)
{
    int i, j, k;
    /* a sphere straight ahead */
    tc_camera(P, 1.83, 1.0, 0.1, 100, q0, t0);
    c[0] = 0; c[1] = 0; c[2] = -10; *r = 1;
    run("centered sphere", CBX_OK, NULL);
    /* NaN in each input */
    for (k = 0; k < 20; k++) {
        tc_camera(P, 1.83, 1.0, 0.1, 100, q0, t0);
        c[0] = 0; c[1] = 0; c[2] = -10; *r = 1;
        if (k < 16)
            P[k / 4][k % 4] = NAN;
        else if (k < 19)
            c[k - 16] = NAN;
        else
            *r = NAN;
        run("NaN", CBX_EINVAL, "NaN without CBX_EINVAL");
    }
    /* infinities and out-of-domain entries */
    for (k = 0; k < 6; k++) {
        tc_camera(P, 1.83, 1.0, 0.1, 100, q0, t0);
        c[0] = 0; c[1] = 0; c[2] = -10; *r = 1;
        if (k == 0) P[0][0] = INFINITY;
        if (k == 1) P[3][3] = 0x1p121;
        if (k == 2) c[1] = 0x1p61;
        if (k == 3) *r = -INFINITY;
        if (k == 4) P[1][2] = -0x1p60;   /* at the edge: in the domain */
        if (k == 5) *r = 0x1p60;
        run("range", CBX_OK, NULL);
    }
    /* a ball touching, crossing, behind the camera plane, and nearly tangent */
    for (k = 0; k < 8; k++) {
        tc_camera(P, 1.83, 1.0, 0.1, 100, q0, t0);
        c[0] = 0.3; c[1] = -0.2; c[2] = -1;
        *r = k == 0 ? 1.0 : k == 1 ? 2.0 : k == 2 ? 1 - 0x1p-20 : k == 3 ? 1 - 0x1p-40 : k == 4 ? 1 - 0x1p-52 : 0.5;
        if (k == 5) c[2] = 5;
        if (k == 6) { c[2] = -1e-300; *r = 1e-300; }
        if (k == 7) { c[2] = -1e-300; *r = 0; }
        run("camera plane", CBX_OK, NULL);
    }
    /* radius 0 and negative radius (the same ball) */
    tc_camera(P, 1.46, 1.5, 0.1, 100, q0, t0);
    c[0] = 1; c[1] = 2; c[2] = -7; *r = 0;
    run("point", CBX_OK, NULL);
    *r = -2;
    run("negative radius", CBX_OK, NULL);
    /* rank-deficient maps: a zero row, a row equal to W */
    tc_camera(P, 1.46, 1.5, 0.1, 100, q0, t0);
    for (j = 0; j < 4; j++) {
        P[0][j] = 0;
        P[1][j] = P[3][j];
    }
    c[0] = 1; c[1] = 2; c[2] = -7; *r = 3;
    run("rank-deficient", CBX_OK, NULL);
    /* very wide and very narrow fields of view, huge translations */
    for (k = 0; k < 4; k++) {
        double T[3] = {0, 0, k >= 2 ? 1e30 : 0};
        tc_camera(P, k % 2 ? 0.0208 : 2000.0, 1.0, 1e-3, 1e6, q0, T); /* 179 and 0.06 degrees */
        c[0] = 0.5; c[1] = 0.25; c[2] = T[2] - 10;
        *r = 2;
        run("field of view", CBX_OK, NULL);
    }
    /* each input out of the domain alone (2^121: every check of the chain) */
    for (k = 0; k < 20; k++) {
        tc_camera(P, 1.83, 1.0, 0.1, 100, q0, t0);
        c[0] = 0; c[1] = 0; c[2] = -10; *r = 1;
        if (k < 16)
            P[k / 4][k % 4] = 0x1p121;
        else if (k < 19)
            c[k - 16] = -0x1p121;
        else
            *r = 0x1p61;
        run("one input out of the domain", CBX_ERANGE, "outside the domain without CBX_ERANGE");
    }
    /* an end beyond 2^99 on one axis only: row 1 (then row 2) huge against
     * a constant W, the other axes in range; and a range from 0 to 2^101 */
    for (k = 1; k <= 3; k++) {
        zero_map(P);
        P[0][0] = P[1][1] = P[2][2] = 1;
        P[3][3] = 0x1p-10;
        c[0] = 0.25; c[1] = 0.5; c[2] = 0.75; *r = 0.125;
        if (k < 3) {
            P[k][3] = 0x1p120;
        } else {
            P[0][0] = 0x1p60;
            P[3][3] = 0x1p-80;
            c[0] = 0x1p-40;
            *r = 0x1p-40;
        }
        run("an end beyond 2^99", CBX_OK, NULL);
    }
    /* the map scaled by 2^-120 .. 2^120 (W from 1e-36 to 1e36) */
    for (k = -120; k <= 120; k += 40) {
        tc_camera(P, 1.83, 1.0, 0.1, 100, q0, t0);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                P[i][j] = ldexp(P[i][j], k / 3);
        c[0] = 0.1; c[1] = 0.2; c[2] = -3; *r = 0.5;
        run("scaled map", CBX_OK, NULL);
    }
}

void tc_ball_hard(double P[4][4], double c[3], double *r, double *wn, double gap, tc_run run)
{
    static const double bad_wn[] = {0.0, -0.0, -1.0, 0x1p-101, 0x1p121, INFINITY, -INFINITY};
    int k;
    /* the identity camera looks down -z, W = -z */
    tc_identity_camera(P);
    *wn = 0.125;
    tc_set_ball(c, r, 0, 0, -10, 1);
    run("ball ahead", CBX_OK, NULL);
    tc_set_ball(c, r, 0, 0, 0, 4);
    run("ball around the camera", CBX_OK, NULL);
    tc_set_ball(c, r, 3, 1, -0.5, 1);
    run("ball across the near plane, off axis", CBX_OK, NULL);
    tc_set_ball(c, r, 0, 0, 10, 1);
    run("ball behind the camera", CBX_EMPTY, "a ball behind the camera without CBX_EMPTY");
    tc_set_ball(c, r, 0, 0, 0.875, 1);
    run("ball touching the near plane from behind", CBX_OK, NULL);
    tc_set_ball(c, r, 0, 0, -1.125, 1);
    run("ball touching the near plane from in front", CBX_OK, NULL);
    tc_set_ball(c, r, 0, 0, -1, 1);
    run("ball touching the camera plane", CBX_OK, NULL);
    tc_set_ball(c, r, 0, 0, -0.125, 0);
    run("a point on the near plane", CBX_OK, NULL);
    tc_set_ball(c, r, 0, 0, -0.0625, 0);
    run("a point behind the near plane", CBX_EMPTY, "a point behind the near plane without CBX_EMPTY");
    tc_set_ball(c, r, 1e6, -1e6, -1e3, 1e7);
    run("huge ball around the camera", CBX_OK, NULL);
    tc_set_ball(c, r, 1e3, 1e3, -1e4, 1e-9);
    run("tiny ball far away", CBX_OK, NULL);
    tc_set_ball(c, r, 0.5, 0.5, -0.25, 0.125 + gap);
    run("nearly tangent to the near plane", CBX_OK, NULL);
    /* NaN in each input, bad near planes */
    for (k = 0; k < 21; k++) {
        tc_identity_camera(P);
        tc_set_ball(c, r, 0, 0, -1, 2);
        *wn = 0.125;
        if (k < 16)
            P[k / 4][k % 4] = NAN;
        else if (k < 19)
            c[k - 16] = NAN;
        else if (k < 20)
            *r = NAN;
        else
            *wn = NAN;
        run("NaN", CBX_EINVAL, "NaN without CBX_EINVAL");
    }
    tc_identity_camera(P);
    for (k = 0; k < (int)(sizeof bad_wn / sizeof bad_wn[0]); k++) {
        tc_set_ball(c, r, 0, 0, -10, 1);   /* a ball that gets CBX_OK with wn = 0.125 */
        *wn = bad_wn[k];
        run("near plane outside the domain", CBX_ERANGE, "wn outside the domain without CBX_ERANGE");
    }
    *wn = 0.125;
    for (k = 0; k < 8; k++) {   /* each row, the center, the radius outside the domain */
        tc_identity_camera(P);
        tc_set_ball(c, r, 0, 0, -10, 1);
        if (k < 4)
            P[k][k == 3 ? 2 : k] = k == 3 ? -0x1p61 : 0x1p61;
        else if (k < 7)
            c[k - 4] = 0x1p61;
        else
            *r = INFINITY;
        run("an entry, the center or the radius beyond the domain", CBX_ERANGE,
            "outside the domain without CBX_ERANGE");
    }
    /* an end beyond 2^99: X up to 2^60 at W = 2^-100 */
    zero_map(P);
    P[0][0] = 0x1p60; P[1][1] = 1; P[2][2] = 1; P[3][2] = 1;
    tc_set_ball(c, r, 1, 0, 0.5, 0.5);
    *wn = 0x1p-100;
    run("an end beyond 2^99", CBX_ERANGE, "an end beyond 2^99 without CBX_ERANGE");
    /* rank-deficient maps: W constant (in front, on the plane, behind); X zero */
    for (k = 0; k < 3; k++) {
        zero_map(P);
        P[0][0] = 1; P[1][1] = 1; P[2][2] = 1;
        P[3][3] = k == 0 ? 2 : k == 1 ? 0.125 : 0.0625;
        tc_set_ball(c, r, 1, 2, 3, 4);
        *wn = 0.125;
        run("W constant", CBX_OK, NULL);
    }
    tc_identity_camera(P);
    P[0][0] = P[0][1] = P[0][2] = P[0][3] = 0;
    tc_set_ball(c, r, 0, 0, -1, 4);
    run("X_0 zero", CBX_OK, NULL);
    tc_identity_camera(P);
    memcpy(P[0], P[3], sizeof P[0]);
    run("X_0 = W (X / W constant)", CBX_OK, NULL);
    /* wide and narrow fields of view; W from 2^-90 to 2^100 */
    for (k = 0; k < 8; k++) {
        tc_scaled_camera(P, k);
        tc_set_ball(c, r, -3, 5, -2, 7);
        *wn = ldexp(0.01, 12 * k - 40);
        run("scaled wide or narrow camera", CBX_OK, NULL);
    }
}

void tc_set_box(cbx_box *b, double l0, double h0, double l1, double h1, double l2, double h2)
{
    b->lo[0] = l0; b->hi[0] = h0;
    b->lo[1] = l1; b->hi[1] = h1;
    b->lo[2] = l2; b->hi[2] = h2;
}

void tc_box_hard(double P[4][4], cbx_box *b, double *wn, void (*mid)(void), tc_run run)
{
    static const double bad_wn[] = {0.0, -0.0, -1.0, 0x1p-101, 0x1p121, INFINITY, -INFINITY};
    int k;
    /* a box straight ahead, in front; across the near plane; behind */
    tc_identity_camera(P);
    tc_set_box(b, -1, 1, -1, 1, -12, -8); *wn = 0.125;
    run("box ahead", CBX_OK, NULL);
    tc_set_box(b, -1, 1, -1, 1, -4, 4);
    run("box across the near plane (the camera inside)", CBX_OK, NULL);
    tc_set_box(b, -1, 1, -1, 1, 1, 4);
    run("box behind the camera", CBX_EMPTY, "a box behind the camera without CBX_EMPTY");
    tc_set_box(b, -1, 1, -1, 1, -0.125, 4);
    run("box with a face on the near plane", CBX_OK, NULL);
    tc_set_box(b, -1, 1, -1, 1, -0.0625, 4);
    run("box just behind the near plane", CBX_OK, NULL);
    tc_set_box(b, 1, 1, 1, 1, -0.125, -0.125);
    run("a point on the near plane", CBX_OK, NULL);
    tc_set_box(b, -1e6, 1e6, -1e6, 1e6, -1e6, 1e6);
    run("huge box around the camera", CBX_OK, NULL);
    tc_set_box(b, 1e3, 1e3 + 1e-9, 1e3, 1e3 + 1e-9, -1e4, -1e4 + 1e-9);
    run("tiny box far away (a point in binary32)", CBX_OK, NULL);
    tc_set_box(b, 1e3, 1e3 + 1e-3, 1e3, 1e3 + 1e-3, -1e4, -1e4 + 1e-3);
    run("small box far away", CBX_OK, NULL);
    /* NaN in each input, an empty box, bad near planes */
    for (k = 0; k < 23; k++) {
        tc_identity_camera(P);
        tc_set_box(b, -1, 1, -1, 1, -4, 4); *wn = 0.125;
        if (k < 16)
            P[k / 4][k % 4] = NAN;
        else if (k < 22)
            ((k - 16) % 2 ? b->hi : b->lo)[(k - 16) / 2] = NAN;
        else
            *wn = NAN;
        run("NaN", CBX_EINVAL, "NaN without CBX_EINVAL");
    }
    tc_identity_camera(P);
    tc_set_box(b, -1, 1, 1, -1, -4, 4); *wn = 0.125;
    run("empty box", CBX_EMPTY, "an empty box without CBX_EMPTY");
    tc_set_box(b, -1, 1, -1, 1, -4, INFINITY);
    run("an infinite end", CBX_OK, NULL);
    for (k = 0; k < (int)(sizeof bad_wn / sizeof bad_wn[0]); k++) {
        tc_set_box(b, -1, 1, -1, 1, -12, -8); *wn = bad_wn[k];   /* CBX_OK with wn = 0.125 */
        run("near plane outside the domain", CBX_ERANGE, "wn outside the domain without CBX_ERANGE");
    }
    *wn = 0.125;
    for (k = 0; k < 10; k++) {   /* each row, then each box end, outside the domain */
        tc_identity_camera(P);
        tc_set_box(b, -1, 1, -1, 1, -12, -8);
        if (k < 4)
            P[k][k == 3 ? 2 : k] = k == 3 ? -0x1p61 : 0x1p61;
        else
            (k % 2 ? b->hi : b->lo)[(k - 4) / 2] = k % 2 ? 0x1p61 : -0x1p61;
        run("an entry or a box end above 2^60", CBX_ERANGE, "outside the domain without CBX_ERANGE");
    }
    /* a ratio a_j / b_j beyond 2^100 (W's x coefficient 2^-60, X's 2^50) */
    tc_identity_camera(P);
    P[3][0] = 0x1p-60;
    P[0][0] = 0x1p50;
    tc_set_box(b, -1, 1, -1, 1, -4, 4);
    run("a ratio beyond the range of an end", CBX_OK, NULL);
    /* a vertex's value beyond 2^99: X up to 2^60, W down to 2^-100 */
    memset(P, 0, 16 * sizeof P[0][0]);
    P[0][0] = 0x1p60; P[1][1] = 1; P[2][2] = 1; P[3][2] = 1;
    tc_set_box(b, 1, 2, 0, 1, 0x1p-100, 1); *wn = 0x1p-100;
    run("an end beyond 2^99 (a corner)", CBX_ERANGE, "an end beyond 2^99 without CBX_ERANGE");
    tc_set_box(b, 1, 2, 0, 1, 0, 1);
    run("an end beyond 2^99 (a crossing)", CBX_ERANGE, "an end beyond 2^99 without CBX_ERANGE");
    if (mid)
        mid();
    /* rank-deficient maps: W constant (in front, on the plane, behind); X zero */
    for (k = 0; k < 3; k++) {
        memset(P, 0, 16 * sizeof P[0][0]);
        P[0][0] = 1; P[1][1] = 1; P[2][2] = 1;
        P[3][3] = k == 0 ? 2 : k == 1 ? 0.125 : 0.0625;
        tc_set_box(b, -1, 1, -1, 1, -4, 4);
        *wn = 0.125;
        run("W constant", CBX_OK, NULL);
    }
    tc_identity_camera(P);
    P[0][0] = P[0][1] = P[0][2] = P[0][3] = 0;
    tc_set_box(b, -1, 1, -1, 1, -4, 4);
    run("X_0 zero", CBX_OK, NULL);
    /* a corner exactly on the near plane (integer map: W exact) */
    memset(P, 0, 16 * sizeof P[0][0]);
    P[0][0] = 1; P[1][1] = 1; P[2][2] = 1; P[3][0] = 1; P[3][1] = 1; P[3][2] = 1;
    tc_set_box(b, 0, 1, 0, 1, 0, 1); *wn = 1;
    run("corner on the near plane", CBX_OK, NULL);
    *wn = 3;
    run("only the far corner on the near plane", CBX_OK, NULL);
    *wn = 2;
    run("a diagonal plane through four corners", CBX_OK, NULL);
    /* wide and narrow fields of view; W from 2^-90 to 2^100 */
    for (k = 0; k < 8; k++) {
        tc_scaled_camera(P, k);
        tc_set_box(b, -3, 5, -2, 7, -9, 0.5); *wn = ldexp(0.01, 12 * k - 40);
        run("scaled wide or narrow camera", CBX_OK, NULL);
    }
}

void tc_fail_map(const char *what, const char *name, const double P[4][4])
{
    int i;
    printf("FAIL %s (%s)\n  map:", what, name);
    for (i = 0; i < 4; i++)
        printf(" [%a %a %a %a]", P[i][0], P[i][1], P[i][2], P[i][3]);
}

/* the 3x3 identity */
void tc_identity3(double rot[3][3])
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            rot[i][j] = i == j;
}

/* the rotation of the unit quaternion (w, x, y, z), rounded (rot need not
 * be orthogonal) */
void tc_rotation(double rot[3][3], double w, double x, double y, double z)
{
    double n = sqrt(w * w + x * x + y * y + z * z);
    w /= n; x /= n; y /= n; z /= n;
    rot[0][0] = 1 - 2 * (y * y + z * z); rot[0][1] = 2 * (x * y - w * z); rot[0][2] = 2 * (x * z + w * y);
    rot[1][0] = 2 * (x * y + w * z); rot[1][1] = 1 - 2 * (x * x + z * z); rot[1][2] = 2 * (y * z - w * x);
    rot[2][0] = 2 * (x * z - w * y); rot[2][1] = 2 * (y * z + w * x); rot[2][2] = 1 - 2 * (x * x + y * y);
}

void tc_ell_shape(xu_rng *g, double r, double rad[3], double rot[3][3])
{
    int i, j, k;
    /* one generator call per statement: the same order on every target */
    double w = xu_rng_sign(g) * xu_rng_unit(g);
    double x = xu_rng_sign(g) * xu_rng_unit(g);
    double y = xu_rng_sign(g) * xu_rng_unit(g);
    double z = xu_rng_sign(g) * xu_rng_unit(g);
    int kind = xu_rng_int(g, 0, 7);
    tc_rotation(rot, w + 0x1p-30, x, y, z);
    if (kind == 7) {            /* a general (sheared, maybe singular) matrix */
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) {
                double s = xu_rng_sign(g);
                rot[i][j] = s * xu_rng_unit(g);
            }
    }
    for (k = 0; k < 3; k++) {
        double s = xu_rng_sign(g);
        double m = tc_scaled(g, 1.0, kind == 6 ? -30 : -6, 0);
        rad[k] = s * r * m;
    }
    if (kind == 5)              /* a disk */
        rad[xu_rng_int(g, 0, 2)] = 0;
}
