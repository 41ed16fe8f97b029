/*
 * pball_oracle.c: the exact oracle of a ball under a projective map clipped
 * at a near plane (cbx_project_sphere_near), shared by tests/test_pball.c
 * and the fuzz harness tests/fuzz/fuzz_pball.c.  pbo_judge decides, for one
 * call, every clause the tests check (tests/pball_oracle.h), in GMP
 * rationals and MPFR.
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
#include "pball_oracle.h"

#define PREC 1200     /* MPFR's precision */
#define MARGIN (-1000) /* the exact end's enclosure: 2^MARGIN times its terms' magnitude */

static double P[4][4], C[3], R, WN;   /* the case being judged */
static pbo_stats *S;
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

/* ---- exact pieces ------------------------------------------------------------ */
/* the row's value at the center */
static void at_center(mpq_t v, const double a[4])
{
    mpq_t cq[3];
    int j;
    for (j = 0; j < 3; j++) {
        mpq_init(cq[j]);
        mpq_set_d(cq[j], C[j]);
    }
    xu_aff_q(v, a, (mpq_t const *)cq);
    for (j = 0; j < 3; j++)
        mpq_clear(cq[j]);
}

/* D = W(c) - wn, bb = |b|^2, r2 = r^2, exactly */
static void plane_terms(mpq_t D, mpq_t bb, mpq_t r2)
{
    mpq_t w;
    mpq_init(w);
    at_center(D, P[3]);
    mpq_set_d(w, WN);
    mpq_sub(D, D, w);
    xu_dot3_q(bb, P[3], P[3]);
    mpq_set_d(r2, R);
    mpq_mul(r2, r2, r2);
    mpq_clear(w);
}

/* W < wn on the whole ball: D < 0 and D^2 > r^2 |b|^2 (exactly) */
static int is_void(void)
{
    mpq_t D, bb, r2, t, u;
    int v;
    mpq_inits(D, bb, r2, t, u, NULL);
    plane_terms(D, bb, r2);
    mpq_mul(t, D, D);
    mpq_mul(u, r2, bb);
    v = mpq_sgn(D) < 0 && mpq_cmp(t, u) > 0;
    mpq_clears(D, bb, r2, t, u, NULL);
    return v;
}

/* e(s) = A - s B in MPFR */
static void e_at(mpfr_t e, const mpfr_t s, const mpq_t A, const mpq_t B)
{
    mpfr_t t;
    mpfr_init2(t, PREC);
    mpfr_mul_q(t, s, B, MPFR_RNDN);
    mpfr_set_q(e, A, MPFR_RNDN);
    mpfr_sub(e, e, t, MPFR_RNDN);
    mpfr_clear(t);
}

/* 2^-1000 (|A| + |s B|): e(s)'s sign is decided beyond that */
static void e_tol(mpfr_t y, const mpfr_t s, const mpq_t A, const mpq_t B)
{
    mpfr_t t;
    mpfr_init2(t, PREC);
    mpfr_mul_q(t, s, B, MPFR_RNDN);
    mpfr_abs(t, t, MPFR_RNDN);
    mpfr_set_q(y, A, MPFR_RNDN);
    mpfr_abs(y, y, MPFR_RNDN);
    mpfr_add(y, y, t, MPFR_RNDN);
    mpfr_mul_2si(y, y, -1000, MPFR_RNDN);
    mpfr_clear(t);
}

/* The exact upper end of a / W over the part W >= wn of the ball, in
 * [t - m, t + m]: 1, or 0 when the closed form has no answer (the ball
 * touching the near plane at one point, or void).  *clip: the end is on
 * the near plane's circle. */
static int upper_end(const double a[4], mpfr_t t, mpfr_t m, int *clip)
{
    mpq_t A, B, D, aa, bb, ab, r2, q, w, u;
    mpfr_t s, n, h, x, y, mag;
    int ok = 0, cut, off;
    mpq_inits(A, B, D, aa, bb, ab, r2, q, w, u, NULL);
    mpfr_inits2(PREC, s, n, h, x, y, mag, (mpfr_ptr)0);
    *clip = 0;
    plane_terms(D, bb, r2);
    at_center(A, a);
    at_center(B, P[3]);
    xu_dot3_q(aa, a, a);
    xu_dot3_q(ab, a, P[3]);
    mpq_mul(q, D, D);
    mpq_mul(w, r2, bb);
    cut = mpq_cmp(q, w) < 0;
    off = mpq_sgn(D) < 0 && !cut;      /* W <= wn on the whole ball */
    if (cut) {
        /* the near plane cuts the ball: s* = alpha + y, alpha = a.b / |b|^2,
         * y = D sqrt(Q), Q = |u|^2 / (|b|^2 (r^2 |b|^2 - D^2)), |u|^2 =
         * |a|^2 - (a.b)^2 / |b|^2 (u = a - alpha b, orthogonal to b); then
         * |a - s* b|^2 = |u|^2 + y^2 |b|^2 and h(s*) = (A - alpha B) - y B
         * + |r| |a - s* b|: sums of terms without cancellation inside the
         * square roots, the error of h at most 2^-1100 times its terms */
        mpfr_t e0, eh;
        mpfr_inits2(PREC, e0, eh, (mpfr_ptr)0);
        mpq_sub(w, w, q);                 /* r^2 |b|^2 - D^2 > 0 */
        mpq_mul(w, w, bb);
        mpq_mul(q, ab, ab);
        mpq_div(q, q, bb);
        mpq_sub(u, aa, q);                /* |u|^2 */
        mpq_div(q, u, w);                 /* Q */
        mpfr_set_q(x, q, MPFR_RNDN);
        mpfr_sqrt(x, x, MPFR_RNDN);
        mpfr_mul_q(x, x, D, MPFR_RNDN);   /* y = D sqrt(Q) */
        mpq_div(q, ab, bb);               /* alpha */
        mpfr_set_q(s, q, MPFR_RNDN);
        mpfr_add(s, s, x, MPFR_RNDN);     /* s* */
        mpfr_set_q(mag, q, MPFR_RNDN);
        mpfr_abs(mag, mag, MPFR_RNDN);
        mpfr_abs(y, x, MPFR_RNDN);
        mpfr_add(mag, mag, y, MPFR_RNDN); /* |alpha| + |y| */
        mpfr_sqr(y, x, MPFR_RNDN);
        mpfr_mul_q(y, y, bb, MPFR_RNDN);
        mpfr_add_q(y, y, u, MPFR_RNDN);
        mpfr_sqrt(n, y, MPFR_RNDN);       /* |a - s* b| */
        mpq_mul(w, q, B);
        mpq_sub(w, A, w);                 /* A - alpha B, exactly */
        mpfr_set_q(e0, w, MPFR_RNDN);
        mpfr_mul_q(y, x, B, MPFR_RNDN);   /* y B */
        mpfr_mul_d(h, n, fabs(R), MPFR_RNDN);
        mpfr_abs(eh, e0, MPFR_RNDN);
        mpfr_add(eh, eh, h, MPFR_RNDN);
        mpfr_sub(h, h, y, MPFR_RNDN);
        mpfr_add(h, h, e0, MPFR_RNDN);    /* h(s*) */
        mpfr_abs(y, y, MPFR_RNDN);
        mpfr_add(eh, eh, y, MPFR_RNDN);
        mpfr_mul_2si(eh, eh, -1100, MPFR_RNDU);   /* h's error bound */
        mpfr_neg(y, eh, MPFR_RNDN);
        if (mpfr_cmp(h, y) >= 0) {
            /* the end s* + h(s*) / wn; m: s*'s error times the slopes,
             * h's over wn, and the rounding of t */
            double bq = fabs(mpq_get_d(B)) + fabs(R) * sqrt(mpq_get_d(bb));
            mpfr_div_d(y, h, WN, MPFR_RNDN);
            mpfr_add(t, s, y, MPFR_RNDN);
            mpfr_mul_d(m, mag, 1.0 + bq / WN, MPFR_RNDU);
            mpfr_mul_2si(m, m, -1100, MPFR_RNDU);
            mpfr_div_d(y, eh, WN, MPFR_RNDU);
            mpfr_mul_2si(y, y, 1, MPFR_RNDU);
            mpfr_add(m, m, y, MPFR_RNDU);
            mpfr_abs(y, t, MPFR_RNDU);
            mpfr_add_ui(y, y, 1, MPFR_RNDU);
            mpfr_mul_2si(y, y, MARGIN, MPFR_RNDU);
            mpfr_add(m, m, y, MPFR_RNDU);
            *clip = 1;
            ok = 1;
        }
        mpfr_clears(e0, eh, (mpfr_ptr)0);
    }
    if (!ok && !off) {
        /* the least root of h (the unclipped tangent): of
         * al s^2 - 2 be s + ga = 0 (al = B^2 - r^2 |b|^2, be = A B - r^2 a.b,
         * ga = A^2 - r^2 |a|^2), the roots with e(s) <= 0 */
        mpq_t al, be, ga, de;
        mpfr_t r1, r2f, e1;
        int n1, n2;
        mpq_inits(al, be, ga, de, NULL);
        mpfr_inits2(PREC, r1, r2f, e1, (mpfr_ptr)0);
        mpq_mul(al, B, B);
        mpq_mul(q, r2, bb);
        mpq_sub(al, al, q);
        mpq_mul(be, A, B);
        mpq_mul(q, r2, ab);
        mpq_sub(be, be, q);
        mpq_mul(ga, A, A);
        mpq_mul(q, r2, aa);
        mpq_sub(ga, ga, q);
        mpq_mul(de, be, be);
        mpq_mul(q, al, ga);
        mpq_sub(de, de, q);
        n1 = n2 = 0;
        if (mpq_sgn(de) >= 0 && (mpq_sgn(al) != 0 || mpq_sgn(be) != 0)) {
            if (mpq_sgn(al) == 0) {
                mpq_set_ui(q, 2, 1);
                mpq_mul(q, q, be);
                mpq_div(q, ga, q);
                mpfr_set_q(r1, q, MPFR_RNDN);
                n1 = 1;
            } else {
                /* stable: k = be + sign(be) sqrt(de); roots k / al and ga / k */
                mpfr_set_q(x, de, MPFR_RNDN);
                mpfr_sqrt(x, x, MPFR_RNDN);
                if (mpq_sgn(be) < 0)
                    mpfr_neg(x, x, MPFR_RNDN);
                mpfr_add_q(x, x, be, MPFR_RNDN);
                mpfr_div_q(r1, x, al, MPFR_RNDN);
                n1 = 1;
                if (mpfr_sgn(x) != 0) {
                    mpfr_set_q(r2f, ga, MPFR_RNDN);
                    mpfr_div(r2f, r2f, x, MPFR_RNDN);
                    n2 = 1;
                }
            }
        }
        /* keep the roots with e(s) <= 0 (h(s) = 0 there), the least */
        mpfr_set_ui(mag, 0, MPFR_RNDN);
        if (n1) {
            e_at(e1, r1, A, B);
            e_tol(y, r1, A, B);
            if (mpfr_cmp(e1, y) <= 0) {
                mpfr_set(t, r1, MPFR_RNDN);
                ok = 1;
            }
        }
        if (n2) {
            e_at(e1, r2f, A, B);
            e_tol(y, r2f, A, B);
            if (mpfr_cmp(e1, y) <= 0 && (!ok || mpfr_cmp(r2f, t) < 0)) {
                mpfr_set(t, r2f, MPFR_RNDN);
                ok = 1;
            }
        }
        if (ok) {
            mpfr_abs(m, t, MPFR_RNDU);
            mpfr_add_ui(m, m, 1, MPFR_RNDU);
            mpfr_mul_2si(m, m, MARGIN, MPFR_RNDU);
        }
        mpq_clears(al, be, ga, de, NULL);
        mpfr_clears(r1, r2f, e1, (mpfr_ptr)0);
    }
    mpq_clears(A, B, D, aa, bb, ab, r2, q, w, u, NULL);
    mpfr_clears(s, n, h, x, y, mag, (mpfr_ptr)0);
    return ok;
}

/* distance |end - x| in units of 2^-52 (1 + |end|) */
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

/* One end against the exact end, enclosed in [x - m, x + m]: on the
 * right side of the enclosure (an upper end not below x - m, a lower end
 * not above x + m) and within 2^-20 (1 + |end|) of its far side. */
static void end_check(double end, const mpfr_t x, const mpfr_t m, int up)
{
    mpfr_t lo, hi, d;
    double tau = ldexp(1.0 + fabs(end), -20);
    mpfr_inits2(PREC, lo, hi, d, (mpfr_ptr)0);
    mpfr_sub(lo, x, m, MPFR_RNDD);
    mpfr_add(hi, x, m, MPFR_RNDU);
    if (up) {
        check(mpfr_cmp_d(lo, end) <= 0, "hi >= the exact upper end");
        mpfr_sub_d(d, lo, end, MPFR_RNDU);
        mpfr_neg(d, d, MPFR_RNDU);          /* end - lo */
    } else {
        check(mpfr_cmp_d(hi, end) >= 0, "lo <= the exact lower end");
        mpfr_sub_d(d, hi, end, MPFR_RNDU);  /* hi - end */
    }
    check(mpfr_cmp_d(d, tau * (1 - 0x1p-50)) <= 0, "each end within 2^-20 (1 + |end|) of the exact end");
    xu_dists_add(&S->dist, units(end, x));
    mpfr_clears(lo, hi, d, (mpfr_ptr)0);
}

/* ---- containment at rational points of the ball in front ---------------- */
/* the point c + r s q of xu_ball_point, s in [0, 1]; 0 when W < wn there
 * (not checked) */
static int point_check(const cbx_box *o, double u, double v, double s)
{
    mpq_t x[3], t, X, W;
    int j, i, in;
    for (j = 0; j < 3; j++)
        mpq_init(x[j]);
    mpq_inits(t, X, W, NULL);
    xu_ball_point(x, C, R, u, v, s);
    xu_aff_q(W, P[3], (mpq_t const *)x);
    mpq_set_d(t, WN);
    in = mpq_cmp(W, t) >= 0;
    if (in) {
        for (i = 0; i < 3; i++) {
            xu_aff_q(X, P[i], (mpq_t const *)x);
            mpq_set_d(t, o->lo[i]);
            mpq_mul(t, t, W);
            check(mpq_cmp(t, X) <= 0, "lo W <= X at a point of the ball in front of the near plane");
            mpq_set_d(t, o->hi[i]);
            mpq_mul(t, t, W);
            check(mpq_cmp(X, t) <= 0, "X <= hi W at a point of the ball in front of the near plane");
        }
        S->points++;
    }
    for (j = 0; j < 3; j++)
        mpq_clear(x[j]);
    mpq_clears(t, X, W, NULL);
    return in;
}

/* ---- one case ------------------------------------------------------------ */
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
    return fabs(R) <= 0x1p60 && WN >= 0x1p-100 && WN <= 0x1p120;
}

static int any_nan(void)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            if (isnan(P[i][j]))
                return 1;
    return isnan(C[0]) || isnan(C[1]) || isnan(C[2]) || isnan(R) || isnan(WN);
}

void pbo_judge(const double p[4][4], const double c[3], double r, double wn, cbx_status st,
               const cbx_box *out, pbo_stats *s, void (*fail)(const char *what))
{
    cbx_box o = *out;
    int i, k, drawn;
    xu_rng gs;
    xu_rng *g = &gs;
    memcpy(P, p, sizeof P);
    memcpy(C, c, sizeof C);
    R = r;
    WN = wn;
    S = s;
    FAIL = fail;
    gs.s = s->rng;
    check(st == CBX_OK || st == CBX_EINVAL || st == CBX_ERANGE || st == CBX_EMPTY, "a known status");
    s->st[st == CBX_OK ? 0 : st == CBX_EMPTY ? 1 : st == CBX_ERANGE ? 2 : 3]++;
    if (st == CBX_EINVAL || st == CBX_ERANGE)
        check(xu_whole_box(&o), "the whole space with CBX_EINVAL and CBX_ERANGE");
    if (st == CBX_EMPTY)
        check(xu_empty_box(&o), "the empty box with CBX_EMPTY");
    if (any_nan()) {
        check(st == CBX_EINVAL, "NaN -> CBX_EINVAL");
        return;
    }
    check(st != CBX_EINVAL, "CBX_EINVAL only with a NaN");
    if (!in_dom()) {
        check(st == CBX_ERANGE, "outside the domain -> CBX_ERANGE");
        return;
    }
    if (st == CBX_EMPTY) {
        check(is_void(), "CBX_EMPTY only when W < wn on the whole ball");
        s->behind++;
    }
    if (st == CBX_ERANGE) {
        s->erange++;
        if (is_void())
            s->erange_void++;
    }
    if (st == CBX_OK) {
        mpfr_t t, m;
        int clip, any_clip = 0, b;
        check(!is_void(), "CBX_OK: some point of the ball in front of the near plane");
        mpfr_inits2(PREC, t, m, (mpfr_ptr)0);
        for (i = 0; i < 3; i++) {
            double neg[4];
            check(isfinite(o.lo[i]) && isfinite(o.hi[i]), "finite ends");
            for (k = 0; k < 4; k++)
                neg[k] = -P[i][k];
            for (b = 0; b < 2; b++) {
                if (upper_end(b == 0 ? P[i] : neg, t, m, &clip)) {
                    if (b == 1)
                        mpfr_neg(t, t, MPFR_RNDN);
                    end_check(b == 0 ? o.hi[i] : o.lo[i], t, m, b == 0);
                    any_clip |= clip;
                } else {
                    s->degenerate++;
                }
            }
        }
        if (any_clip)
            s->clipped++;
        {
            mpq_t W0, bb, r2, u;
            mpq_inits(W0, bb, r2, u, NULL);
            at_center(W0, P[3]);
            xu_dot3_q(bb, P[3], P[3]);
            mpq_set_d(r2, R);
            mpq_mul(r2, r2, r2);
            mpq_mul(u, W0, W0);
            mpq_mul(r2, r2, bb);
            if (mpq_sgn(W0) <= 0 || mpq_cmp(u, r2) <= 0)
                s->crossing++;
            mpq_clears(W0, bb, r2, u, NULL);
        }
        mpfr_clears(t, m, (mpfr_ptr)0);
        drawn = 0;
        for (i = 0; i < 8 && drawn < 64; drawn++) {
            /* one generator call per statement: the same order on every target */
            double su = xu_rng_sign(g), mu = xu_rng_unit(g);
            int eu = xu_rng_int(g, -4, 4);
            double sv = xu_rng_sign(g), mv = xu_rng_unit(g);
            int ev = xu_rng_int(g, -4, 4);
            double sc = i < 6 ? 1.0 : xu_rng_unit(g);
            if (point_check(&o, su * ldexp(mu, eu), sv * ldexp(mv, ev), sc))
                i++;
        }
    }
    s->rng = gs.s;
}

void pbo_init(pbo_stats *s, uint64_t seed)
{
    memset(s, 0, sizeof *s);
    s->rng = seed;
}

void pbo_print(FILE *f, pbo_stats *s)
{
    fprintf(f, "  statuses: %ld CBX_OK, %ld CBX_EMPTY, %ld CBX_ERANGE, %ld CBX_EINVAL\n", s->st[0], s->st[1], s->st[2], s->st[3]);
    fprintf(f, "  with CBX_OK: every end against the exact end (closed form, MPFR %d bits, enclosed within 2^-1100 to 2^%d of its terms),\n"
               "    and %ld exact points of the balls in front of the near plane\n", PREC, MARGIN, s->points);
    fprintf(f, "  CBX_OK cases with an end on the near plane's circle: %ld; with the ball crossing the camera plane: %ld\n",
            s->clipped, s->crossing);
    fprintf(f, "  CBX_EMPTY in the domain (all behind the near plane, exactly): %ld\n", s->behind);
    fprintf(f, "  CBX_ERANGE in the domain: %ld (%ld with nothing in front, exactly); ends without a closed form (skipped): %ld\n",
            s->erange, s->erange_void, s->degenerate);
    xu_dists_print(f, &s->dist);
}

void pbo_free(pbo_stats *s)
{
    xu_dists_free(&s->dist);
}
