/*
 * psph_oracle.c: the exact oracle of a ball under a projective map
 * (cbx_project_sphere), shared by tests/test_psphere.c and the fuzz
 * harness tests/fuzz/fuzz_psphere.c, and of an ellipsoid
 * (cbx_project_ellipsoid: tests/test_pell.c, tests/fuzz/fuzz_pell.c).
 * pso_judge and pso_judge_ell decide, for one call, every clause the tests
 * check (tests/psph_oracle.h), in GMP rationals and MPFR with directed
 * rounding.  Both shapes are {c + M q : |q| <= 1} (the ball: M = r I); the
 * exact quantities are the quadratic form Q = M M^T of the map's rows.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"
#include "psph_oracle.h"

#define PREC 300

static double P[4][4], C[3], R;   /* the case being judged */
static int ELL;                   /* an ellipsoid: M = ROT diag(RAD) */
static double RAD[3], ROT[3][3];
static pso_stats *S;
static void (*FAIL)(const char *what);

static void check(int ok, const char *what)
{
    if (ok) {
        S->passed++;
    } else {
        S->failed++;
        FAIL(what);
    }
}

/* ---- exact pieces ---------------------------------------------------------- */
/* u^T Q v for the linear parts u, v of two rows (Q = M M^T: the ball's
 * r^2 u.v; the ellipsoid's (M^T u).(M^T v)), exactly */
static void quad_q(mpq_t q, const double u[4], const double v[4])
{
    mpq_t t, x, y, e;
    int i, j;
    if (!ELL) {
        xu_dot3_q(q, u, v);
        mpq_init(t);
        mpq_set_d(t, R);
        mpq_mul(q, q, t);
        mpq_mul(q, q, t);
        mpq_clear(t);
        return;
    }
    mpq_inits(t, x, y, e, NULL);
    mpq_set_ui(q, 0, 1);
    for (j = 0; j < 3; j++) {          /* (M^T u)_j = rad_j sum_i rot_ij u_i */
        mpq_set_ui(x, 0, 1);
        mpq_set_ui(y, 0, 1);
        for (i = 0; i < 3; i++) {
            mpq_set_d(e, ROT[i][j]);
            mpq_set_d(t, u[i]);
            mpq_mul(t, t, e);
            mpq_add(x, x, t);
            mpq_set_d(t, v[i]);
            mpq_mul(t, t, e);
            mpq_add(y, y, t);
        }
        mpq_set_d(e, RAD[j]);
        mpq_mul(x, x, e);
        mpq_mul(x, x, e);
        mpq_mul(x, x, y);
        mpq_add(q, q, x);
    }
    mpq_clears(t, x, y, e, NULL);
}

/* a bound on the shape's scale, for the rounding allowance below: the
 * ball's |r| (its norm's absolute rounding, about 2^-1066 under the square
 * root, is scaled by |r| after it); the ellipsoid's
 * 1 + sum_j |rad_j| (1 + sum_i |rot_ij|) (its norm is the last operation:
 * the square root of that rounding, about 2^-533, stays unscaled) */
static double shape_scale(void)
{
    double m = 1;
    int i, j;
    if (!ELL)
        return fabs(R);
    for (j = 0; j < 3; j++) {
        double c = 1;
        for (i = 0; i < 3; i++)
            c += fabs(ROT[i][j]);
        m += fabs(RAD[j]) * c;
    }
    return m;
}

/* sign of B - |M^T b| (B = W(c), qbb = b^T Q b, the ball's r^2 |b|^2),
 * exactly: B > 0 and B^2 > qbb */
static int front_sign(const mpq_t B, const mpq_t qbb)
{
    mpq_t t;
    int s;
    if (mpq_sgn(B) <= 0)
        return mpq_sgn(B) < 0 || mpq_sgn(qbb) > 0 ? -1 : 0;
    mpq_init(t);
    mpq_mul(t, B, B);
    s = mpq_cmp(t, qbb);
    mpq_clear(t);
    return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

/* B - m <= eps S + 2^-1000 + sc 2^-520 + eps m, eps = 2^-40, m = |M^T b|
 * (the ball's |r| |b|), S = W(c)'s magnitude, sc the shape's scale
 * (shape_scale): with B > 0, squared.  For the ellipsoid S also holds the
 * magnitude of M^T b's terms, sum_j |s_j| sum_i |rot_ij| |b_i|: M^T b is
 * enclosed from its terms, so it is known to within a few units of their
 * magnitude, not of m itself, which they can cancel to 0 (the fuzz input of
 * 2026-12-01: rot's second column (3, 3, 3), b = (-1, 0.5, 0.5), W = 2^-300
 * on the whole segment, CBX_EBEHIND; the contract allows it: the enclosure
 * of min W is not above 0). */
static int near_plane(const mpq_t B, const mpq_t qbb)
{
    mpq_t t, u, e, S;
    int s, j;
    if (mpq_sgn(B) <= 0)
        return 1;
    mpq_inits(t, u, e, S, NULL);
    /* S = |b0 c0| + |b1 c1| + |b2 c2| + |b3|: W(c)'s magnitude (then, for
     * an ellipsoid, the magnitude of M^T b's terms: see above) */
    mpq_set_d(S, fabs(P[3][3]));
    for (j = 0; j < 3; j++) {
        mpq_set_d(t, fabs(P[3][j]));
        mpq_set_d(u, fabs(C[j]));
        mpq_mul(t, t, u);
        mpq_add(S, S, t);
    }
    for (j = 0; ELL && j < 3; j++) {
        int i;
        for (i = 0; i < 3; i++) {
            mpq_set_d(t, fabs(ROT[i][j]));
            mpq_set_d(u, fabs(P[3][i]));
            mpq_mul(t, t, u);
            mpq_set_d(u, fabs(RAD[j]));
            mpq_mul(t, t, u);
            mpq_add(S, S, t);
        }
    }
    mpq_set_ui(e, 1, 1);
    mpq_div_2exp(e, e, 40);
    mpq_mul(t, e, S);
    mpq_sub(t, B, t);          /* B - eps S - 2^-1000 - |r| 2^-520 */
    mpq_set_ui(u, 1, 1);
    mpq_div_2exp(u, u, 1000);
    mpq_sub(t, t, u);
    mpq_set_d(u, shape_scale());
    mpq_div_2exp(u, u, 520);   /* the square root of the norm's underflow: |r| sqrt(2^-1040) */
    mpq_sub(t, t, u);
    if (mpq_sgn(t) <= 0) {
        s = 1;
    } else {
        mpq_mul(t, t, t);
        mpq_set_ui(u, 1, 1);
        mpq_add(u, u, e);
        mpq_mul(u, u, u);
        mpq_mul(u, u, qbb);     /* ((1 + eps) |r| |b|)^2 */
        s = mpq_cmp(t, u) <= 0;
    }
    mpq_clears(t, u, e, S, NULL);
    return s;
}

/* (beta + sgn s) / alpha rounded in direction rnd (RNDD or RNDU), alpha > 0:
 * the numerator rounded the same way, the divisor the other way when the
 * numerator is nonnegative (the same way when it is negative). */
static void root_end(mpfr_t out, const mpq_t be, const mpfr_t s, int sgn, const mpq_t al, mpfr_rnd_t rnd)
{
    mpfr_rnd_t other = rnd == MPFR_RNDD ? MPFR_RNDU : MPFR_RNDD;
    mpfr_t num, den;
    mpfr_inits2(PREC, num, den, (mpfr_ptr)0);
    mpfr_set_q(num, be, rnd);
    if (sgn > 0)
        mpfr_add(num, num, s, rnd);
    else
        mpfr_sub(num, num, s, rnd);
    mpfr_set_q(den, al, mpfr_sgn(num) >= 0 ? other : rnd);
    mpfr_div(out, num, den, rnd);
    mpfr_clears(num, den, (mpfr_ptr)0);
}

/* B = W(c), qbb = b^T Q b (the ball's r^2 |b|^2) of the current case, exactly */
static void ball_w(mpq_t B, mpq_t qbb)
{
    mpq_t cq[3];
    int j;
    for (j = 0; j < 3; j++) {
        mpq_init(cq[j]);
        mpq_set_d(cq[j], C[j]);
    }
    xu_aff_q(B, P[3], (mpq_t const *)cq);
    quad_q(qbb, P[3], P[3]);
    for (j = 0; j < 3; j++)
        mpq_clear(cq[j]);
}

/* The exact ends of axis i, enclosed: lo in [l0, l1], hi in [h0, h1]
 * (MPFR, PREC bits, directed rounding).  The ball must be in front. */
static void exact_ends(int i, mpfr_t l0, mpfr_t l1, mpfr_t h0, mpfr_t h1)
{
    mpq_t cq[3], A, B, aa, bb, ab, al, be, ga, de, t;
    mpfr_t sd, su;
    int j;
    for (j = 0; j < 3; j++) {
        mpq_init(cq[j]);
        mpq_set_d(cq[j], C[j]);
    }
    mpq_inits(A, B, aa, bb, ab, al, be, ga, de, t, NULL);
    mpfr_inits2(PREC, sd, su, (mpfr_ptr)0);
    ball_w(B, bb);
    xu_aff_q(A, P[i], (mpq_t const *)cq);
    quad_q(aa, P[i], P[i]);
    quad_q(ab, P[i], P[3]);
    mpq_mul(al, B, B);
    mpq_sub(al, al, bb);       /* alpha = B^2 - b^T Q b > 0 (the ball: Q = r^2 I) */
    mpq_mul(be, A, B);
    mpq_sub(be, be, ab);       /* beta = A B - a^T Q b */
    mpq_mul(ga, A, A);
    mpq_sub(ga, ga, aa);       /* gamma = A^2 - a^T Q a */
    mpq_mul(de, be, be);
    mpq_mul(t, al, ga);
    mpq_sub(de, de, t);        /* beta^2 - alpha gamma >= 0 */
    if (mpq_sgn(de) < 0)
        mpq_set_ui(de, 0, 1);
    mpfr_set_q(sd, de, MPFR_RNDD);
    mpfr_sqrt(sd, sd, MPFR_RNDD);
    mpfr_set_q(su, de, MPFR_RNDU);
    mpfr_sqrt(su, su, MPFR_RNDU);
    /* hi = (beta + sqrt) / alpha, lo = (beta - sqrt) / alpha, alpha > 0 */
    root_end(h0, be, sd, 1, al, MPFR_RNDD);
    root_end(h1, be, su, 1, al, MPFR_RNDU);
    root_end(l0, be, su, -1, al, MPFR_RNDD);
    root_end(l1, be, sd, -1, al, MPFR_RNDU);
    for (j = 0; j < 3; j++)
        mpq_clear(cq[j]);
    mpq_clears(A, B, aa, bb, ab, al, be, ga, de, t, NULL);
    mpfr_clears(sd, su, (mpfr_ptr)0);
}

/* distance |end - exact| in units of 2^-52 (1 + |end|) */
static double units(double end, const mpfr_t x)
{
    mpfr_t d;
    double u;
    mpfr_init2(d, PREC);
    mpfr_sub_d(d, x, end, MPFR_RNDN);
    mpfr_abs(d, d, MPFR_RNDN);
    u = mpfr_get_d(d, MPFR_RNDN) / (ldexp(1.0, -52) * (1.0 + fabs(end)));
    mpfr_clear(d);
    return u;
}

/* end within 2^-20 (1 + |end|) of x (x the exact end's enclosure ends) */
static int within_tau(double end, const mpfr_t x)
{
    mpfr_t d, tau;
    int ok;
    mpfr_inits2(PREC, d, tau, (mpfr_ptr)0);
    mpfr_sub_d(d, x, end, MPFR_RNDN);
    mpfr_abs(d, d, MPFR_RNDU);
    mpfr_set_d(tau, 1.0 + fabs(end), MPFR_RNDD); /* 1 + |end| is exact or rounds down harmlessly */
    mpfr_mul_2si(tau, tau, -20, MPFR_RNDD);
    ok = mpfr_cmp(d, tau) <= 0;
    mpfr_clears(d, tau, (mpfr_ptr)0);
    return ok;
}

/* ---- containment at rational points of the ball ---------------------------- */
/* the point c + r s q of xu_ball_point, s in [0, 1] */
static void point_check(const cbx_box *o, double u, double v, double s)
{
    mpq_t x[3], t, X, W;
    int j, i;
    for (j = 0; j < 3; j++)
        mpq_init(x[j]);
    mpq_inits(t, X, W, NULL);
    if (!ELL) {
        xu_ball_point(x, C, R, u, v, s);
    } else {                   /* c + M q, q the unit ball's point */
        static const double zero[3] = {0, 0, 0};
        mpq_t q[3], e;
        for (j = 0; j < 3; j++)
            mpq_init(q[j]);
        mpq_init(e);
        xu_ball_point(q, zero, 1.0, u, v, s);
        for (i = 0; i < 3; i++) {
            mpq_set_d(x[i], C[i]);
            for (j = 0; j < 3; j++) {
                mpq_set_d(e, ROT[i][j]);
                mpq_mul(e, e, q[j]);
                mpq_set_d(t, RAD[j]);
                mpq_mul(e, e, t);
                mpq_add(x[i], x[i], e);
            }
        }
        for (j = 0; j < 3; j++)
            mpq_clear(q[j]);
        mpq_clear(e);
    }
    xu_aff_q(W, P[3], (mpq_t const *)x);
    check(mpq_sgn(W) > 0, "W > 0 at a point of the ball");
    for (i = 0; i < 3; i++) {
        xu_aff_q(X, P[i], (mpq_t const *)x);
        mpq_set_d(t, o->lo[i]);
        mpq_mul(t, t, W);
        check(mpq_cmp(t, X) <= 0, "lo W <= X at a point of the ball");
        mpq_set_d(t, o->hi[i]);
        mpq_mul(t, t, W);
        check(mpq_cmp(X, t) <= 0, "X <= hi W at a point of the ball");
    }
    S->points++;
    for (j = 0; j < 3; j++)
        mpq_clear(x[j]);
    mpq_clears(t, X, W, NULL);
}

/* ---- the round-to-nearest closed form (shown) ------------------------------- */
void pso_closed_form(const double p[4][4], const double c[3], double rad, int i, double *lo, double *hi)
{
    const double *a = p[i], *b = p[3];
    double A = a[0] * c[0] + a[1] * c[1] + a[2] * c[2] + a[3];
    double B = b[0] * c[0] + b[1] * c[1] + b[2] * c[2] + b[3];
    double r2 = rad * rad;
    double al = B * B - r2 * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    double be = A * B - r2 * (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
    double ga = A * A - r2 * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    double de = be * be - al * ga;
    double sq = sqrt(de > 0 ? de : 0);
    *lo = (be - sq) / al;
    *hi = (be + sq) / al;
}

/* the same on the rows in the ellipsoid's frame (M^T a, M^T b, rounded
 * to nearest), radius 1 */
void pso_closed_form_ell(const double p[4][4], const double c[3], const double radii[3],
                         const double rot[3][3], int i, double *lo, double *hi)
{
    double q[4][4];
    const double z[3] = {0, 0, 0};
    int j, k;
    memset(q, 0, sizeof q);
    for (k = 0; k < 2; k++) {
        const double *a = p[k == 0 ? i : 3];
        double *t = q[k == 0 ? i : 3];
        for (j = 0; j < 3; j++)
            t[j] = radii[j] * (rot[0][j] * a[0] + rot[1][j] * a[1] + rot[2][j] * a[2]);
        t[3] = a[0] * c[0] + a[1] * c[1] + a[2] * c[2] + a[3];
    }
    pso_closed_form((const double (*)[4])q, z, 1.0, i, lo, hi);
}

/* ---- one case ---------------------------------------------------------------- */
static int in_dom(void)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            if (!(fabs(P[i][j]) <= (j < 3 ? 0x1p60 : 0x1p120)))
                return 0;
    for (j = 0; j < 3; j++)
        if (!(fabs(C[j]) <= 0x1p60))
            return 0;
    if (ELL) {
        for (j = 0; j < 3; j++)
            if (!(fabs(RAD[j]) <= 0x1p30 && fabs(ROT[j][0]) <= 0x1p30 && fabs(ROT[j][1]) <= 0x1p30
                  && fabs(ROT[j][2]) <= 0x1p30))
                return 0;
        return 1;
    }
    return fabs(R) <= 0x1p60;
}

static int any_nan(void)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            if (isnan(P[i][j]))
                return 1;
    if (ELL) {
        for (j = 0; j < 3; j++)
            if (isnan(RAD[j]) || isnan(ROT[j][0]) || isnan(ROT[j][1]) || isnan(ROT[j][2]))
                return 1;
    }
    return isnan(C[0]) || isnan(C[1]) || isnan(C[2]) || isnan(R);
}

/* the case set up in P, C and R or RAD and ROT */
static void judge(cbx_status st, const cbx_box *out, pso_stats *s, void (*fail)(const char *what))
{
    cbx_box o = *out;
    int i;
    mpq_t B, bb;
    xu_rng gs;
    xu_rng *g = &gs;
    S = s;
    FAIL = fail;
    gs.s = s->rng;
    check(st == CBX_OK || st == CBX_EINVAL || st == CBX_ERANGE || st == CBX_EBEHIND, "a known status");
    s->st[st == CBX_OK ? 0 : st == CBX_EBEHIND ? 1 : st == CBX_ERANGE ? 2 : 3]++;
    if (st != CBX_OK)
        check(xu_whole_box(&o), "the whole space with a status other than CBX_OK");
    if (any_nan()) {
        check(st == CBX_EINVAL, "NaN -> CBX_EINVAL");
        return;
    }
    check(st != CBX_EINVAL, "CBX_EINVAL only with a NaN");
    if (!in_dom()) {
        check(st == CBX_ERANGE, "outside the domain -> CBX_ERANGE");
        return;
    }
    mpq_inits(B, bb, NULL);
    ball_w(B, bb);
    if (front_sign(B, bb) <= 0)
        check(st == CBX_EBEHIND, "a ball touching, crossing or behind the camera plane -> CBX_EBEHIND");
    if (st == CBX_EBEHIND)
        check(near_plane(B, bb), "CBX_EBEHIND only for a ball near the camera plane: W(c) - |r| |b| <= 2^-40 (S_W + |r| |b|) + 2^-1000 + |r| 2^-520 (an ellipsoid: S_W with the terms of M^T b)");
    if (st == CBX_ERANGE) { /* in the domain: how far from the camera plane (shown) */
        double b = mpq_get_d(B), m = sqrt(mpq_get_d(bb)), f = (b - m) / (b + m);
        s->erange++;
        if (f > s->erange_front)
            s->erange_front = f;
    }
    if (st == CBX_OK) {
        check(front_sign(B, bb) > 0, "CBX_OK: the ball in front of the camera");
        if (front_sign(B, bb) > 0) {
            mpfr_t l0, l1, h0, h1;
            mpfr_inits2(PREC, l0, l1, h0, h1, (mpfr_ptr)0);
            for (i = 0; i < 3; i++) {
                double nl, nh, u;
                check(isfinite(o.lo[i]) && isfinite(o.hi[i]), "finite ends");
                exact_ends(i, l0, l1, h0, h1);
                check(mpfr_cmp_d(l1, o.lo[i]) >= 0, "lo <= the exact lower end");
                check(mpfr_cmp_d(h0, o.hi[i]) <= 0, "hi >= the exact upper end");
                check(within_tau(o.lo[i], l1) && within_tau(o.hi[i], h0), "each end within 2^-20 (1 + |end|) of the exact end");
                u = units(o.lo[i], l1);
                xu_dists_add(&S->dist, u);
                u = units(o.hi[i], h0);
                xu_dists_add(&S->dist, u);
                if (ELL)
                    pso_closed_form_ell((const double (*)[4])P, C, RAD, (const double (*)[3])ROT, i, &nl, &nh);
                else
                    pso_closed_form((const double (*)[4])P, C, R, i, &nl, &nh);
                s->naive++;
                if (!(mpfr_cmp_d(l1, nl) >= 0 && mpfr_cmp_d(h0, nh) <= 0))
                    s->naive_miss++;
            }
            mpfr_clears(l0, l1, h0, h1, (mpfr_ptr)0);
            for (i = 0; i < 8; i++) {
                /* one generator call per statement: the same order on every target */
                double su = xu_rng_sign(g), mu = xu_rng_unit(g);
                int eu = xu_rng_int(g, -4, 4);
                double sv = xu_rng_sign(g), mv = xu_rng_unit(g);
                int ev = xu_rng_int(g, -4, 4);
                double sc = i < 6 ? 1.0 : xu_rng_unit(g);
                point_check(&o, su * ldexp(mu, eu), sv * ldexp(mv, ev), sc);
            }
        }
    }
    mpq_clears(B, bb, NULL);
    s->rng = gs.s;
}

void pso_judge(const double p[4][4], const double c[3], double r, cbx_status st, const cbx_box *out,
               pso_stats *s, void (*fail)(const char *what))
{
    memcpy(P, p, sizeof P);
    memcpy(C, c, sizeof C);
    R = r;
    ELL = 0;
    judge(st, out, s, fail);
}

void pso_judge_ell(const double p[4][4], const double c[3], const double radii[3], const double rot[3][3],
                   cbx_status st, const cbx_box *out, pso_stats *s, void (*fail)(const char *what))
{
    memcpy(P, p, sizeof P);
    memcpy(C, c, sizeof C);
    memcpy(RAD, radii, sizeof RAD);
    memcpy(ROT, rot, sizeof ROT);
    R = 0;
    ELL = 1;
    judge(st, out, s, fail);
}

int pso_contains(const double p[4][4], const double c[3], double r, int i, double lo, double hi)
{
    mpfr_t l0, l1, h0, h1;
    mpq_t B, bb;
    int ok = 0;
    memcpy(P, p, sizeof P);
    memcpy(C, c, sizeof C);
    R = r;
    ELL = 0;
    mpq_inits(B, bb, NULL);
    ball_w(B, bb);
    if (front_sign(B, bb) > 0) {
        mpfr_inits2(PREC, l0, l1, h0, h1, (mpfr_ptr)0);
        exact_ends(i, l0, l1, h0, h1);
        ok = mpfr_cmp_d(l1, lo) >= 0 && mpfr_cmp_d(h0, hi) <= 0 ? 1 : 0;
        if (ok && !(mpfr_cmp_d(l0, lo) >= 0 && mpfr_cmp_d(h1, hi) <= 0))
            ok = -1; /* within the enclosure's 2^-300: undecided */
        mpfr_clears(l0, l1, h0, h1, (mpfr_ptr)0);
    }
    mpq_clears(B, bb, NULL);
    return ok;
}

void pso_init(pso_stats *s, uint64_t seed)
{
    memset(s, 0, sizeof *s);
    s->erange_front = -1;
    s->rng = seed;
}

void pso_print(FILE *f, pso_stats *s)
{
    fprintf(f, "  statuses: %ld CBX_OK, %ld CBX_EBEHIND, %ld CBX_ERANGE, %ld CBX_EINVAL\n", s->st[0], s->st[1], s->st[2], s->st[3]);
    fprintf(f, "  with CBX_OK: every end against its exact value (MPFR, %d bits), and %ld exact points of the balls\n", PREC, s->points);
    fprintf(f, "  CBX_ERANGE in the domain: %ld, the farthest from the camera plane at (min W) / (max W) = %.3g on the ball\n", s->erange, s->erange_front);
    xu_dists_print(f, &s->dist);
    fprintf(f, "  round-to-nearest closed form (shown, not asserted): %ld of %ld axes miss the exact image\n", s->naive_miss, s->naive);
}

void pso_free(pso_stats *s)
{
    xu_dists_free(&s->dist);
}
