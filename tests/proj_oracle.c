/*
 * proj_oracle.c: the exact oracle of cbx_project_box / cbx_project_boxf
 * (tests/test_project.c and tests/fuzz/fuzz_project.c): the contract of
 * include/cbx_api.h decided in GMP rationals (specs/cbx_proj.h).
 */
#include <math.h>
#include <string.h>

#include <gmp.h>

#include "proj_oracle.h"

/* ---- the format's constants (include/cbx_prec_begin.h) ------------------- */
static int k_u, k_eta;           /* u = 2^-k_u, eta = 2^-k_eta */
static double k_sb, k_rt;        /* the range */
static int k_qs;                 /* QS = 2^-k_qs */

static void set_format(int is32)
{
    k_u = is32 ? 24 : 53;
    k_eta = is32 ? 149 : 1074;
    k_sb = is32 ? 0x1p61 : 0x1p509;
    k_rt = is32 ? 0x1p122 : 0x1p1018;
    k_qs = is32 ? 120 : 1000;
}

/* q = 2^e (e may be negative) */
static void q_pow2(mpq_t q, int e)
{
    mpq_set_ui(q, 1, 1);
    if (e >= 0)
        mpq_mul_2exp(q, q, (unsigned long)e);
    else
        mpq_div_2exp(q, q, (unsigned long)-e);
}

/* r = m0 x + m1 y + m2 z + m3, s = |m0 x| + |m1 y| + |m2 z| + |m3|, exactly */
static void q_row(mpq_t r, mpq_t s, const double m[4], const double p[3])
{
    mpq_t a, b;
    int j;
    mpq_inits(a, b, NULL);
    mpq_set_d(r, m[3]);
    mpq_set_d(s, m[3]);
    mpq_abs(s, s);
    for (j = 0; j < 3; j++) {
        mpq_set_d(a, m[j]);
        mpq_set_d(b, p[j]);
        mpq_mul(a, a, b);
        mpq_add(r, r, a);
        mpq_abs(a, a);
        mpq_add(s, s, a);
    }
    mpq_clears(a, b, NULL);
}

/* e = 12 u s + 2^-1065 (binary32: 2^-140): perr */
static void q_perr(mpq_t e, const mpq_t s)
{
    mpq_t t;
    mpq_init(t);
    q_pow2(t, -k_u);
    mpq_mul(e, s, t);
    mpq_set_ui(t, 12, 1);
    mpq_mul(e, e, t);
    q_pow2(t, -(k_eta - 9));
    mpq_add(e, e, t);
    mpq_clear(t);
}

/* ptol(r) = 24 u (SX + |r| SW) + 2^-1064 (1 + |r| + SW) (binary32: 2^-139) */
static void q_ptol(mpq_t tol, double r, const mpq_t sx, const mpq_t sw)
{
    mpq_t a, t;
    mpq_inits(a, t, NULL);
    mpq_set_d(a, fabs(r));
    mpq_mul(tol, a, sw);
    mpq_add(tol, tol, sx);
    q_pow2(t, -k_u);
    mpq_mul(tol, tol, t);
    mpq_set_ui(t, 24, 1);
    mpq_mul(tol, tol, t);
    mpq_set_ui(t, 1, 1);
    mpq_add(t, t, a);
    mpq_add(t, t, sw);
    q_pow2(a, -(k_eta - 10));
    mpq_mul(t, t, a);
    mpq_add(tol, tol, t);
    mpq_clears(a, t, NULL);
}

static int is_whole(const double lo[3], const double hi[3])
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(lo[i] == -HUGE_VAL && hi[i] == HUGE_VAL))
            return 0;
    return 1;
}

static int is_empty_out(const double lo[3], const double hi[3])
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(lo[i] == HUGE_VAL && hi[i] == -HUGE_VAL))
            return 0;
    return 1;
}

static void corner(const double BL[3], const double BH[3], int c, double p[3])
{
    p[0] = (c & 1) ? BH[0] : BL[0];
    p[1] = (c & 2) ? BH[1] : BL[1];
    p[2] = (c & 4) ? BH[2] : BL[2];
}

static uint64_t po_next(po_stats *s)
{
    s->rng = s->rng * 6364136223846793005ull + 1442695040888963407ull;
    return s->rng >> 33;
}

#define CHECK(cond, what) do { if (cond) s->passed++; else { s->failed++; fail(what); } } while (0)

void po_judge(const double P[4][4], const double BL[3], const double BH[3], int is32,
              cbx_status st, const double olo[3], const double ohi[3], po_stats *s,
              void (*fail)(const char *what))
{
    int i, c, j, nan = 0, empty = 0, fast = 1;
    int fmt32 = is32;
    set_format(is32);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            nan |= isnan(P[i][j]);
    for (i = 0; i < 3; i++) {
        nan |= isnan(BL[i]) | isnan(BH[i]);
    }
    if (nan) {
        CHECK(st == CBX_EINVAL && is_whole(olo, ohi), "NaN: CBX_EINVAL and the whole space");
        s->st[3]++;
        return;
    }
    for (i = 0; i < 3; i++)
        empty |= BH[i] < BL[i] || BL[i] == HUGE_VAL || BH[i] == -HUGE_VAL;
    if (empty) {
        CHECK(st == CBX_EMPTY && is_empty_out(olo, ohi), "empty: CBX_EMPTY and the empty box");
        s->st[3]++;
        return;
    }
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            fast &= fabs(P[i][j]) <= (j < 3 ? k_sb : k_rt);
    for (i = 0; i < 3; i++)
        fast &= fabs(BL[i]) <= k_sb && fabs(BH[i]) <= k_sb;
    if (!fast) {
        CHECK(st == CBX_ERANGE && is_whole(olo, ohi), "out of range: CBX_ERANGE and the whole space");
        s->st[2]++;
        return;
    }
    {
        mpq_t X[3][8], SX[3][8], W[8], SW[8], e, f, g, t, qs, eta;
        int clear = 1, near = 1;
        mpq_inits(e, f, g, t, qs, eta, NULL);
        q_pow2(qs, -k_qs);
        q_pow2(eta, -k_eta);
        for (c = 0; c < 8; c++) {
            double p[3];
            corner(BL, BH, c, p);
            mpq_inits(W[c], SW[c], NULL);
            q_row(W[c], SW[c], P[3], p);
            q_perr(e, SW[c]);
            if (mpq_cmp(W[c], e) <= 0)
                clear = 0;
            for (i = 0; i < 3; i++) {
                mpq_inits(X[i][c], SX[i][c], NULL);
                q_row(X[i][c], SX[i][c], P[i], p);
                /* pnear: (|X| + perr_X) 2 QS + eta <= W - perr_W */
                q_perr(f, SX[i][c]);
                mpq_abs(g, X[i][c]);
                mpq_add(g, g, f);
                mpq_mul(g, g, qs);
                mpq_mul_2exp(g, g, 1);
                mpq_add(g, g, eta);
                mpq_sub(t, W[c], e);
                if (mpq_cmp(g, t) > 0)
                    near = 0;
            }
        }
        if (near)
            CHECK(st == CBX_OK, "every quotient in range (proj_ok): CBX_OK");
        if (st == CBX_EBEHIND) {
            s->st[1]++;
            CHECK(!clear && is_whole(olo, ohi), "CBX_EBEHIND: a corner not clear, the whole space");
        } else if (st == CBX_ERANGE) {
            s->st[2]++;
            CHECK(!near && is_whole(olo, ohi), "CBX_ERANGE in range: a quotient out of range, the whole space");
            for (c = 0; c < 8; c++)
                CHECK(mpq_sgn(W[c]) > 0, "CBX_ERANGE in range: W > 0 at every corner (else CBX_EBEHIND)");
        } else if (st == CBX_OK) {
            s->st[0]++;
            for (i = 0; i < 3; i++) {
                int tight_lo = 0, tight_hi = 0, ok = isfinite(olo[i]) && isfinite(ohi[i]);
                double frac_lo = 0, frac_hi = 0;
                mpq_t best_lo, best_hi, r;
                CHECK(ok, "CBX_OK: finite ends");
                if (!ok)
                    continue;
                mpq_inits(best_lo, best_hi, r, NULL);
                for (c = 0; c < 8; c++) {
                    CHECK(mpq_sgn(W[c]) > 0, "CBX_OK: W > 0 at every corner");
                    /* lo W <= X <= hi W */
                    mpq_set_d(f, olo[i]);
                    mpq_mul(f, f, W[c]);
                    CHECK(mpq_cmp(f, X[i][c]) <= 0, "containment: lo W <= X at every corner");
                    mpq_sub(g, X[i][c], f); /* X - lo W */
                    q_ptol(t, olo[i], SX[i][c], SW[c]);
                    if (mpq_cmp(g, t) <= 0)
                        tight_lo = 1;
                    mpq_set_d(f, ohi[i]);
                    mpq_mul(f, f, W[c]);
                    CHECK(mpq_cmp(X[i][c], f) <= 0, "containment: X <= hi W at every corner");
                    mpq_sub(g, f, X[i][c]);
                    q_ptol(t, ohi[i], SX[i][c], SW[c]);
                    if (mpq_cmp(g, t) <= 0)
                        tight_hi = 1;
                    if (mpq_sgn(W[c]) > 0) {
                        mpq_div(r, X[i][c], W[c]);
                        /* (X - lo W) / ptol(lo): the least over the corners */
                        mpq_set_d(f, olo[i]);
                        mpq_mul(f, f, W[c]);
                        mpq_sub(g, X[i][c], f);
                        q_ptol(t, olo[i], SX[i][c], SW[c]);
                        mpq_div(g, g, t);
                        if (c == 0 || mpq_get_d(g) < frac_lo)
                            frac_lo = mpq_get_d(g);
                        mpq_set_d(f, ohi[i]);
                        mpq_mul(f, f, W[c]);
                        mpq_sub(g, f, X[i][c]);
                        q_ptol(t, ohi[i], SX[i][c], SW[c]);
                        mpq_div(g, g, t);
                        if (c == 0 || mpq_get_d(g) < frac_hi)
                            frac_hi = mpq_get_d(g);
                    }
                }
                if (frac_lo > s->max_frac) s->max_frac = frac_lo;
                if (frac_hi > s->max_frac) s->max_frac = frac_hi;
                CHECK(tight_lo, "proven tightness of lo (pt_lo at some corner)");
                CHECK(tight_hi, "proven tightness of hi (pt_hi at some corner)");
                mpq_clears(best_lo, best_hi, r, NULL);
            }
            /* random points of the box: W > 0, lo W <= X <= hi W there */
            for (j = 0; j < s->npoints; j++) {
                double p[3];
                mpq_t wq, sq, xq;
                mpq_inits(wq, sq, xq, NULL);
                for (i = 0; i < 3; i++) {
                    double u = (double)(po_next(s) % 1025) / 1024.0;
                    p[i] = BL[i] + u * (BH[i] - BL[i]);
                    if (fmt32)
                        p[i] = (float)p[i];
                    if (p[i] < BL[i]) p[i] = BL[i];
                    if (p[i] > BH[i]) p[i] = BH[i];
                }
                q_row(wq, sq, P[3], p);
                CHECK(mpq_sgn(wq) > 0, "CBX_OK: W > 0 at a point of the box");
                for (i = 0; i < 3; i++) {
                    if (!isfinite(olo[i]) || !isfinite(ohi[i]))
                        continue;
                    q_row(xq, sq, P[i], p);
                    mpq_set_d(f, olo[i]);
                    mpq_mul(f, f, wq);
                    CHECK(mpq_cmp(f, xq) <= 0, "containment: lo W <= X at a point of the box");
                    mpq_set_d(f, ohi[i]);
                    mpq_mul(f, f, wq);
                    CHECK(mpq_cmp(xq, f) <= 0, "containment: X <= hi W at a point of the box");
                }
                s->points++;
                mpq_clears(wq, sq, xq, NULL);
            }
            /* the round-to-nearest 8-corner divide (pbrt, three.js): a miss? */
            if (!fmt32) {
                int miss = 0;
                for (i = 0; i < 3; i++) {
                    double nlo = HUGE_VAL, nhi = -HUGE_VAL;
                    for (c = 0; c < 8; c++) {
                        double p[3], xs, ws;
                        corner(BL, BH, c, p);
                        xs = P[i][0] * p[0] + P[i][1] * p[1] + P[i][2] * p[2] + P[i][3];
                        ws = P[3][0] * p[0] + P[3][1] * p[1] + P[3][2] * p[2] + P[3][3];
                        if (xs / ws < nlo) nlo = xs / ws;
                        if (xs / ws > nhi) nhi = xs / ws;
                    }
                    for (c = 0; c < 8; c++) {
                        mpq_set_d(f, nlo);
                        mpq_mul(f, f, W[c]);
                        if (mpq_cmp(f, X[i][c]) > 0) miss = 1;
                        mpq_set_d(f, nhi);
                        mpq_mul(f, f, W[c]);
                        if (mpq_cmp(X[i][c], f) > 0) miss = 1;
                    }
                }
                s->naive_cases++;
                s->naive_miss += miss;
            }
        } else {
            s->st[3]++;
            CHECK(0, "a status of the contract (OK, ERANGE or EBEHIND)");
        }
        for (c = 0; c < 8; c++) {
            mpq_clears(W[c], SW[c], NULL);
            for (i = 0; i < 3; i++)
                mpq_clears(X[i][c], SX[i][c], NULL);
        }
        mpq_clears(e, f, g, t, qs, eta, NULL);
    }
}

