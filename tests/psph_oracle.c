/*
 * psph_oracle.c: the exact oracle of a ball under a projective map
 * (cbx_project_sphere), shared by tests/test_psphere.c and the fuzz harness
 * tests/fuzz/fuzz_psphere.c.  pso_judge decides, for one call, every
 * clause the tests check (tests/psph_oracle.h), in GMP rationals and MPFR
 * with directed rounding.
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
/* sign of B - |r| |b| (B = W(c)), exactly: B > 0 and B^2 > r^2 |b|^2 */
static int front_sign(const mpq_t B, const mpq_t r2, const mpq_t bb)
{
    mpq_t t, u;
    int s;
    if (mpq_sgn(B) <= 0)
        return mpq_sgn(B) < 0 || mpq_sgn(r2) * mpq_sgn(bb) > 0 ? -1 : 0;
    mpq_inits(t, u, NULL);
    mpq_mul(t, B, B);
    mpq_mul(u, r2, bb);
    s = mpq_cmp(t, u);
    mpq_clears(t, u, NULL);
    return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

/* B - |r| |b| <= eps (B + |r| |b|), eps = 2^-40: with B > 0 and m = |r| |b|,
 * (1 - eps) B <= (1 + eps) m, squared. */
static int near_plane(const mpq_t B, const mpq_t r2, const mpq_t bb)
{
    mpq_t t, u, e, S;
    int s, j;
    if (mpq_sgn(B) <= 0)
        return 1;
    mpq_inits(t, u, e, S, NULL);
    /* S = |b0 c0| + |b1 c1| + |b2 c2| + |b3|: W(c)'s magnitude */
    mpq_set_d(S, fabs(P[3][3]));
    for (j = 0; j < 3; j++) {
        mpq_set_d(t, fabs(P[3][j]));
        mpq_set_d(u, fabs(C[j]));
        mpq_mul(t, t, u);
        mpq_add(S, S, t);
    }
    mpq_set_ui(e, 1, 1);
    mpq_div_2exp(e, e, 40);
    mpq_mul(t, e, S);
    mpq_sub(t, B, t);          /* B - eps S - 2^-1000 - |r| 2^-520 */
    mpq_set_ui(u, 1, 1);
    mpq_div_2exp(u, u, 1000);
    mpq_sub(t, t, u);
    mpq_set_d(u, fabs(R));
    mpq_div_2exp(u, u, 520);   /* the square root of the norm's underflow: |r| sqrt(2^-1040) */
    mpq_sub(t, t, u);
    if (mpq_sgn(t) <= 0) {
        s = 1;
    } else {
        mpq_mul(t, t, t);
        mpq_set_ui(u, 1, 1);
        mpq_add(u, u, e);
        mpq_mul(u, u, u);
        mpq_mul(u, u, r2);
        mpq_mul(u, u, bb);     /* ((1 + eps) |r| |b|)^2 */
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

/* B = W(c), bb = |b|^2, r2 = r^2 of the current case, exactly */
static void ball_w(mpq_t B, mpq_t bb, mpq_t r2)
{
    mpq_t cq[3];
    int j;
    for (j = 0; j < 3; j++) {
        mpq_init(cq[j]);
        mpq_set_d(cq[j], C[j]);
    }
    xu_aff_q(B, P[3], (mpq_t const *)cq);
    xu_dot3_q(bb, P[3], P[3]);
    mpq_set_d(r2, R);
    mpq_mul(r2, r2, r2);
    for (j = 0; j < 3; j++)
        mpq_clear(cq[j]);
}

/* The exact ends of axis i, enclosed: lo in [l0, l1], hi in [h0, h1]
 * (MPFR, PREC bits, directed rounding).  The ball must be in front. */
static void exact_ends(int i, mpfr_t l0, mpfr_t l1, mpfr_t h0, mpfr_t h1)
{
    mpq_t cq[3], A, B, aa, bb, ab, r2, al, be, ga, de, t;
    mpfr_t sd, su;
    int j;
    for (j = 0; j < 3; j++) {
        mpq_init(cq[j]);
        mpq_set_d(cq[j], C[j]);
    }
    mpq_inits(A, B, aa, bb, ab, r2, al, be, ga, de, t, NULL);
    mpfr_inits2(PREC, sd, su, (mpfr_ptr)0);
    ball_w(B, bb, r2);
    xu_aff_q(A, P[i], (mpq_t const *)cq);
    xu_dot3_q(aa, P[i], P[i]);
    xu_dot3_q(ab, P[i], P[3]);
    mpq_mul(al, B, B);
    mpq_mul(t, r2, bb);
    mpq_sub(al, al, t);        /* alpha = B^2 - r^2 |b|^2 > 0 */
    mpq_mul(be, A, B);
    mpq_mul(t, r2, ab);
    mpq_sub(be, be, t);        /* beta = A B - r^2 a.b */
    mpq_mul(ga, A, A);
    mpq_mul(t, r2, aa);
    mpq_sub(ga, ga, t);        /* gamma = A^2 - r^2 |a|^2 */
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
    mpq_clears(A, B, aa, bb, ab, r2, al, be, ga, de, t, NULL);
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
    xu_ball_point(x, C, R, u, v, s);
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
    return fabs(R) <= 0x1p60;
}

static int any_nan(void)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            if (isnan(P[i][j]))
                return 1;
    return isnan(C[0]) || isnan(C[1]) || isnan(C[2]) || isnan(R);
}

void pso_judge(const double p[4][4], const double c[3], double r, cbx_status st, const cbx_box *out,
               pso_stats *s, void (*fail)(const char *what))
{
    cbx_box o = *out;
    int i;
    mpq_t B, bb, r2;
    xu_rng gs;
    xu_rng *g = &gs;
    memcpy(P, p, sizeof P);
    memcpy(C, c, sizeof C);
    R = r;
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
    mpq_inits(B, bb, r2, NULL);
    ball_w(B, bb, r2);
    if (front_sign(B, r2, bb) <= 0)
        check(st == CBX_EBEHIND, "a ball touching, crossing or behind the camera plane -> CBX_EBEHIND");
    if (st == CBX_EBEHIND)
        check(near_plane(B, r2, bb), "CBX_EBEHIND only for a ball near the camera plane: W(c) - |r| |b| <= 2^-40 (S_W + |r| |b|) + 2^-1000 + |r| 2^-520");
    if (st == CBX_ERANGE) { /* in the domain: how far from the camera plane (shown) */
        double b = mpq_get_d(B), m = sqrt(mpq_get_d(r2) * mpq_get_d(bb)), f = (b - m) / (b + m);
        s->erange++;
        if (f > s->erange_front)
            s->erange_front = f;
    }
    if (st == CBX_OK) {
        check(front_sign(B, r2, bb) > 0, "CBX_OK: the ball in front of the camera");
        if (front_sign(B, r2, bb) > 0) {
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
    mpq_clears(B, bb, r2, NULL);
    s->rng = gs.s;
}

int pso_contains(const double p[4][4], const double c[3], double r, int i, double lo, double hi)
{
    mpfr_t l0, l1, h0, h1;
    mpq_t B, bb, r2;
    int ok = 0;
    memcpy(P, p, sizeof P);
    memcpy(C, c, sizeof C);
    R = r;
    mpq_inits(B, bb, r2, NULL);
    ball_w(B, bb, r2);
    if (front_sign(B, r2, bb) > 0) {
        mpfr_inits2(PREC, l0, l1, h0, h1, (mpfr_ptr)0);
        exact_ends(i, l0, l1, h0, h1);
        ok = mpfr_cmp_d(l1, lo) >= 0 && mpfr_cmp_d(h0, hi) <= 0 ? 1 : 0;
        if (ok && !(mpfr_cmp_d(l0, lo) >= 0 && mpfr_cmp_d(h1, hi) <= 0))
            ok = -1; /* within the enclosure's 2^-300: undecided */
        mpfr_clears(l0, l1, h0, h1, (mpfr_ptr)0);
    }
    mpq_clears(B, bb, r2, NULL);
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
