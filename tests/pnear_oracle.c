/*
 * The exact oracle of cbx_project_box_near (tests/pnear_oracle.h).
 *
 * The part of the box with W >= wn is a convex polytope; its vertices are
 * the corners with W >= wn and the points where an edge whose ends lie on
 * either side of W = wn crosses it (u = (wn - W_p) / (W_q - W_p) of the
 * way from p to q).  With rational inputs these are rational, and so is
 * X_i / W there (W = wn at a crossing); the exact ends of the image are the
 * least and largest of those values (X_i / W is linear-fractional, its
 * extremes over a polytope with W > 0 are at vertices).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>

#include "exact_util.h"
#include "pnear_oracle.h"

#define NV 20   /* at most 8 corners and 12 crossings */

static uint64_t next(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

static int in_range(double x, double b)
{
    return x >= -b && x <= b;
}

/* the documented domain: linear entries and box ends at most 2^60, translations at most 2^120, wn in [2^-100, 2^120] */
static int in_domain(const double p[4][4], const cbx_box *in, double wn)
{
    int i, j;
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 3; j++)
            if (!in_range(p[i][j], 0x1p60))
                return 0;
        if (!in_range(p[i][3], 0x1p120))
            return 0;
    }
    for (j = 0; j < 3; j++)
        if (!in_range(in->lo[j], 0x1p60) || !in_range(in->hi[j], 0x1p60) || in->lo[j] > in->hi[j])
            return 0;
    return wn >= 0x1p-100 && wn <= 0x1p120;
}

/* X_i / W at the point x (W > 0) */
static void value_at(mpq_t v, const double p[4][4], int i, mpq_t x[3])
{
    mpq_t w;
    mpq_init(w);
    xu_aff_q(v, p[i], (mpq_t const *)x);
    xu_aff_q(w, p[3], (mpq_t const *)x);
    mpq_div(v, v, w);
    mpq_clear(w);
}

/* lo W <= X_i <= hi W at x (W >= wn > 0 there) */
static int point_ok(const double p[4][4], int i, mpq_t x[3], double lo, double hi)
{
    mpq_t v, e;
    int ok;
    mpq_inits(v, e, NULL);
    value_at(v, p, i, x);
    mpq_set_d(e, lo);
    ok = mpq_cmp(e, v) <= 0;
    mpq_set_d(e, hi);
    ok = ok && mpq_cmp(v, e) <= 0;
    mpq_clears(v, e, NULL);
    return ok;
}

/* The vertices of the part W >= wn: returns their number (0: the part is
 * empty); vx[k] their points. */
static int vertices(const double p[4][4], const cbx_box *in, double wn, mpq_t vx[NV][3])
{
    mpq_t c[8][3], w[8], q, d;
    int k, j, n = 0;
    mpq_inits(q, d, NULL);
    for (k = 0; k < 8; k++) {
        mpq_init(w[k]);
        for (j = 0; j < 3; j++) {
            mpq_init(c[k][j]);
            mpq_set_d(c[k][j], (k >> j) & 1 ? in->hi[j] : in->lo[j]);
        }
        xu_aff_q(w[k], p[3], (mpq_t const *)c[k]);
    }
    mpq_set_d(q, wn);
    for (k = 0; k < 8; k++)
        if (mpq_cmp(w[k], q) >= 0) {
            for (j = 0; j < 3; j++)
                mpq_set(vx[n][j], c[k][j]);
            n++;
        }
    for (k = 0; k < 8; k++)
        for (j = 0; j < 3; j++) {
            int m = k | (1 << j), a, b;
            if (m == k)
                continue;
            a = mpq_cmp(w[k], q) >= 0;
            b = mpq_cmp(w[m], q) >= 0;
            if (a == b)
                continue;
            /* u = (wn - W_k) / (W_m - W_k); x = c_k + u (c_m - c_k) */
            mpq_sub(d, q, w[k]);
            {
                mpq_t den, u;
                int t;
                mpq_inits(den, u, NULL);
                mpq_sub(den, w[m], w[k]);
                mpq_div(u, d, den);
                for (t = 0; t < 3; t++) {
                    mpq_sub(den, c[m][t], c[k][t]);
                    mpq_mul(den, den, u);
                    mpq_add(vx[n][t], c[k][t], den);
                }
                mpq_clears(den, u, NULL);
            }
            n++;
        }
    for (k = 0; k < 8; k++) {
        mpq_clear(w[k]);
        for (j = 0; j < 3; j++)
            mpq_clear(c[k][j]);
    }
    mpq_clears(q, d, NULL);
    return n;
}

static void add_dist(pno_stats *s, double d)
{
    if (s->wide) {
        s->n_wide++;
        if (d > s->worst_wide)
            s->worst_wide = d;
        return;
    }
    xu_dists_add(&s->dist, d);
}

/* end against the exact end e: on the right side (up: end >= e), within
 * 2^-20 (1 + |end|); the distance kept in units of 2^-52 (1 + |end|) */
static int end_ok(pno_stats *s, double end, mpq_t e, int up)
{
    mpq_t t, u;
    int side, near;
    double dist;
    mpq_inits(t, u, NULL);
    mpq_set_d(t, end);
    side = up ? mpq_cmp(t, e) >= 0 : mpq_cmp(t, e) <= 0;
    mpq_sub(t, t, e);
    if (!up)
        mpq_neg(t, t);
    mpq_set_d(u, ldexp(1 + fabs(end), -20));
    near = mpq_cmp(t, u) <= 0;
    dist = mpq_get_d(t) / ldexp(1 + fabs(end), -52);
    add_dist(s, dist);
    mpq_clears(t, u, NULL);
    return side && near;
}

#define CHECK(cond, what) do { if (cond) s->passed++; else { s->failed++; fail(what); } } while (0)

/* a random rational point of the box with W >= wn, if the draw gives one */
static int random_point(pno_stats *s, const double p[4][4], const cbx_box *in, double wn, mpq_t x[3])
{
    mpq_t w, q;
    int j, ok;
    mpq_inits(w, q, NULL);
    for (j = 0; j < 3; j++) {
        double f = (double)(next(&s->rng) >> 11) * 0x1p-53;
        double v = in->lo[j] + f * (in->hi[j] - in->lo[j]);
        if (!(v >= in->lo[j]))
            v = in->lo[j];
        if (!(v <= in->hi[j]))
            v = in->hi[j];
        mpq_set_d(x[j], v);
    }
    xu_aff_q(w, p[3], (mpq_t const *)x);
    mpq_set_d(q, wn);
    ok = mpq_cmp(w, q) >= 0;
    mpq_clears(w, q, NULL);
    return ok;
}

static void judge_ok(const double p[4][4], const cbx_box *in, double wn, const cbx_box *o, int n,
                     mpq_t vx[NV][3], pno_stats *s, void (*fail)(const char *))
{
    mpq_t v, best_lo, best_hi, x[3];
    int i, k, j, ok;
    mpq_inits(v, best_lo, best_hi, x[0], x[1], x[2], NULL);
    for (i = 0; i < 3; i++) {
        CHECK(isfinite(o->lo[i]) && isfinite(o->hi[i]), "CBX_OK with an end not finite");
        for (k = 0; k < n; k++) {
            value_at(v, p, i, vx[k]);
            if (k == 0 || mpq_cmp(v, best_lo) < 0)
                mpq_set(best_lo, v);
            if (k == 0 || mpq_cmp(v, best_hi) > 0)
                mpq_set(best_hi, v);
        }
        CHECK(end_ok(s, o->hi[i], best_hi, 1), "an upper end below the exact end, or above it by more than 2^-20 (1 + |end|)");
        CHECK(end_ok(s, o->lo[i], best_lo, 0), "a lower end above the exact end, or below it by more than 2^-20 (1 + |end|)");
        for (k = 0; k < n; k++) {
            CHECK(point_ok(p, i, vx[k], o->lo[i], o->hi[i]), "a vertex of the clipped box outside [lo, hi]");
            s->points++;
        }
        for (k = 0; k < 6; k++)
            if (random_point(s, p, in, wn, x)) {
                CHECK(point_ok(p, i, x, o->lo[i], o->hi[i]), "a point of the box in front of the near plane outside [lo, hi]");
                s->points++;
            }
    }
    /* clipped: a corner behind the near plane */
    ok = 0;
    for (k = 0; k < 8; k++) {
        for (j = 0; j < 3; j++)
            mpq_set_d(x[j], (k >> j) & 1 ? in->hi[j] : in->lo[j]);
        xu_aff_q(v, p[3], (mpq_t const *)x);
        mpq_set_d(best_lo, wn);
        if (mpq_cmp(v, best_lo) < 0)
            ok = 1;
    }
    s->clipped += ok;
    mpq_clears(v, best_lo, best_hi, x[0], x[1], x[2], NULL);
}

void pno_judge(const double p[4][4], const cbx_box *in, double wn, cbx_status st, const cbx_box *out,
               pno_stats *s, void (*fail)(const char *what))
{
    int i, j, k, nan = isnan(wn), empty = 0;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            nan |= isnan(p[i][j]);
    for (j = 0; j < 3; j++) {
        nan |= isnan(in->lo[j]) || isnan(in->hi[j]);
        empty |= in->hi[j] < in->lo[j] || (isinf(in->lo[j]) && in->lo[j] > 0) || (isinf(in->hi[j]) && in->hi[j] < 0);
    }
    if (st == CBX_OK)
        s->st[0]++;
    else if (st == CBX_EMPTY)
        s->st[1]++;
    else if (st == CBX_ERANGE)
        s->st[2]++;
    else if (st == CBX_EINVAL)
        s->st[3]++;
    if (nan) {
        CHECK(st == CBX_EINVAL && xu_whole_box(out), "NaN without CBX_EINVAL and the whole space");
        return;
    }
    CHECK(st != CBX_EINVAL, "CBX_EINVAL without NaN");
    if (empty) {
        CHECK(st == CBX_EMPTY && xu_empty_box(out), "an empty box without CBX_EMPTY and the empty box");
        return;
    }
    if (!in_domain(p, in, wn)) {
        CHECK(st == CBX_ERANGE && xu_whole_box(out), "outside the domain without CBX_ERANGE and the whole space");
        return;
    }
    CHECK(st == CBX_OK || st == CBX_EMPTY || st == CBX_ERANGE, "an undocumented status");
    {
        mpq_t vx[NV][3];
        int n;
        for (k = 0; k < NV; k++)
            for (j = 0; j < 3; j++)
                mpq_init(vx[k][j]);
        n = vertices(p, in, wn, vx);
        if (st == CBX_EMPTY) {
            CHECK(n == 0 && xu_empty_box(out), "CBX_EMPTY with a point of the box in front of the near plane, or not the empty box");
            s->behind++;
        } else if (st == CBX_ERANGE) {
            CHECK(xu_whole_box(out), "CBX_ERANGE without the whole space");
            s->erange++;
            s->erange_void += n == 0;
        } else if (st == CBX_OK) {
            CHECK(n > 0, "CBX_OK with nothing of the box in front of the near plane");
            if (n > 0)
                judge_ok(p, in, wn, out, n, vx, s, fail);
        }
        for (k = 0; k < NV; k++)
            for (j = 0; j < 3; j++)
                mpq_clear(vx[k][j]);
    }
}

void pno_init(pno_stats *s, uint64_t seed)
{
    memset(s, 0, sizeof *s);
    s->rng = seed | 1;
}

void pno_print(FILE *f, pno_stats *s)
{
    fprintf(f, "  statuses: %ld CBX_OK (%ld with the near plane cutting the box), %ld CBX_EMPTY (%ld in the domain: all behind), %ld CBX_ERANGE, %ld CBX_EINVAL\n",
            s->st[0], s->clipped, s->st[1], s->behind, s->st[2], s->st[3]);
    fprintf(f, "  with CBX_OK: every end against the exact end (GMP rationals over the clipped box's vertices), and %ld exact points\n", s->points);
    fprintf(f, "  CBX_ERANGE in the domain: %ld (%ld of them with nothing in front of the near plane)\n", s->erange, s->erange_void);
    xu_dists_print(f, &s->dist);
    if (s->n_wide > 0)
        fprintf(f, "    with W's magnitude on the box above 2^20 wn: largest %.3g (%ld ends)\n", s->worst_wide, s->n_wide);
}

void pno_free(pno_stats *s)
{
    xu_dists_free(&s->dist);
}
