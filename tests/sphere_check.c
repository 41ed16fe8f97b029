/*
 * The checks of tests/test_sphere.c (tests/sphere_parts.h): the verdict of
 * one call of cbx_sphere_box or cbx_ellipsoid_box against the contract and
 * the exact oracle (tests/sphere_oracle.c), and the tallies of each group.
 */
#include <stdio.h>
#include <string.h>
#include <math.h>

#include "sphere_parts.h"

/* ---------------------------------------------------------------------- */
/* Checks, verdicts, statistics                                           */
/* ---------------------------------------------------------------------- */

static const char *const f_name[NF] = {
    "status", "out-set", "special-out", "oob-axes", "finite", "containment",
    "sanity<=64", "tiny-abs", "proven-bound", "points", "inputs"
};
static const char *const f_unit[NF] = {
    "cases", "cases", "cases", "axes", "axes", "axes", "axes", "axes", "axes",
    "pt-axes", "cases"
};

long spt_fail_logs;

static void v_init(verdict *v) { memset(v, 0, sizeof *v); }

static void v_fail(verdict *v, int f, const char *why)
{
    v->flag[f]++;
    if (!v->failed) {
        strncpy(v->why, why, sizeof v->why - 1);
        v->why[sizeof v->why - 1] = '\0';
    }
    v->failed = 1;
}

static void ex_add(exstat *e, double u)
{
    if (e->n == 0 || u > e->max) e->max = u;
    e->sum += u;
    e->n++;
}

static void ex_print(const char *what, const exstat *e)
{
    if (e->n)
        printf("  %-44s max %10.4g  mean %10.4g  (%ld ends)\n", what, e->max,
               e->sum / (double)e->n, e->n);
}

void spt_g_init(group *g, const char *name)
{
    memset(g, 0, sizeof *g);
    g->name = name;
}

void spt_g_add(group *g, const verdict *v)
{
    int f, si = xu_status_index(v->expected);
    g->cases++;
    g->failed += v->failed;
    if (si >= 0) g->status_seen[si]++;
    for (f = 0; f < NF; f++) {
        g->applied[f] += v->applied[f];
        g->fails[f] += v->flag[f];
    }
}

void spt_g_print(const group *g)
{
    int f;
    printf("== %s: %ld cases (expected OK %ld, EINVAL %ld, ERANGE %ld), %ld failed\n",
           g->name, g->cases, g->status_seen[0], g->status_seen[2],
           g->status_seen[3], g->failed);
    for (f = 0; f < NF; f++)
        if (g->applied[f])
            printf("  check %-12s %9ld %-7s checked, %6ld failed\n", f_name[f],
                   g->applied[f], f_unit[f], g->fails[f]);
    printf("  in-domain axes %ld (%ld with u*(|t|+sqrt s) < 2^-1000), ends equal to "
           "the exact end %ld, MPFR precision raised on %ld axes\n",
           g->axes, g->axes_tiny, g->exact_ends, g->prec_raised);
    ex_print("units of u*(|t|+sqrt s)+eta:", &g->units);
    ex_print("  same, axes with |t|+sqrt s >= 2^-480:", &g->units_big);
    ex_print("  same, axes with u*(|t|+sqrt s) < 2^-1000:", &g->units_tiny);
    ex_print("ulps of the exact end, no cancellation", &g->ulps_nocancel);
    printf("    (ulps counted on axes with |t|+sqrt s >= 2^-480)\n");
    if (g->axes)
        printf("  ulps of the exact end, all ends: max %.4g, %ld ends above 64 ulps "
               "(where t and sqrt(s) cancel the end is tiny and its ulp too)\n",
               g->ulps_max, g->ulps_over64);
    if (g->pts || g->pts_skipped)
        printf("  points in the ball: %ld used, %ld skipped (p.p > 1 after nudging)\n",
               g->pts, g->pts_skipped);
    if (g->worst_case[0])
        printf("  largest units (%.4g) at:\n%s", g->worst, g->worst_case);
}

/* ---------------------------------------------------------------------- */
/* One call: status, special outputs, per-axis checks                     */
/* ---------------------------------------------------------------------- */

static double prob_t(const problem *P, int i)
{
    return P->ell ? P->center[i] : P->a.m[i][3];
}

static int prob_has_nan(const problem *P)
{
    int i, j;
    if (!P->ell) {
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++)
                if (xu_is_nan(P->a.m[i][j])) return 1;
        return 0;
    }
    for (i = 0; i < 3; i++) {
        if (xu_is_nan(P->center[i]) || xu_is_nan(P->radii[i])) return 1;
        for (j = 0; j < 3; j++)
            if (xu_is_nan(P->rot[i][j])) return 1;
    }
    return 0;
}

/* row i in the domain (no NaN assumed); comparisons with exact powers of
 * two, false for infinities */
static int prob_row_ok(const problem *P, int i)
{
    int j;
    if (!P->ell) {
        for (j = 0; j < 3; j++)
            if (!(fabs(P->a.m[i][j]) <= 0x1p509)) return 0;
        return fabs(P->a.m[i][3]) <= 0x1p1018;
    }
    for (j = 0; j < 3; j++)
        if (!(fabs(P->rot[i][j]) <= 0x1p254) || !(fabs(P->radii[j]) <= 0x1p254))
            return 0;
    return fabs(P->center[i]) <= 0x1p1018;
}

cbx_status spt_prob_expected(const problem *P, int *oob)
{
    int i;
    *oob = 0;
    if (prob_has_nan(P)) return CBX_EINVAL;
    for (i = 0; i < 3; i++)
        if (!prob_row_ok(P, i)) *oob |= 1 << i;
    return *oob ? CBX_ERANGE : CBX_OK;
}

static cbx_status prob_call(const problem *P, cbx_box *out)
{
    return P->ell ? cbx_ellipsoid_box(P->center, P->radii, P->rot, out)
                  : cbx_sphere_box(&P->a, out);
}

static void print_problem(FILE *f, const problem *P)
{
    int i;
    if (!P->ell) {
        for (i = 0; i < 3; i++)
            fprintf(f, "  m[%d] = {%a, %a, %a | %a}\n", i, P->a.m[i][0],
                    P->a.m[i][1], P->a.m[i][2], P->a.m[i][3]);
        return;
    }
    fprintf(f, "  center = {%a, %a, %a}\n", P->center[0], P->center[1], P->center[2]);
    fprintf(f, "  radii  = {%a, %a, %a}\n", P->radii[0], P->radii[1], P->radii[2]);
    for (i = 0; i < 3; i++)
        fprintf(f, "  rot[%d] = {%a, %a, %a}\n", i, P->rot[i][0], P->rot[i][1],
                P->rot[i][2]);
}

static void row_dir(const problem *P, int i, double f[3], int e[3])
{
    int j;
    for (j = 0; j < 3; j++) {
        if (!P->ell) {
            f[j] = frexp(P->a.m[i][j], &e[j]);
        } else {
            int e1, e2;
            double f1 = frexp(P->rot[i][j], &e1), f2 = frexp(P->radii[j], &e2);
            f[j] = f1 * f2; /* |f| in [1/4, 1) or 0; rounding is harmless */
            e[j] = e1 + e2;
        }
    }
}

static void check_points(ctx *k, group *g, verdict *v, const problem *P,
                         const cbx_box *out, int okmask, xu_rng *r)
{
    double pts[8][3];
    int np = 0, i, j, n;
    char why[160];
    for (i = 0; i < 3; i++) {
        double f[3];
        int e[3], s;
        if (!(okmask & (1 << i))) continue; /* finite rows only */
        row_dir(P, i, f, e);
        for (s = 0; s < 2; s++) {
            if (spt_unit_point(k, f, e, s ? -1.0 : 1.0, pts[np])) np++;
            else g->pts_skipped++;
        }
    }
    for (n = 0; n < 2 && r; n++) {
        double f[3], rad;
        int e[3] = { 0, 0, 0 };
        for (j = 0; j < 3; j++)
            f[j] = xu_rng_unit(r) + xu_rng_unit(r) + xu_rng_unit(r) - 1.5;
        rad = n == 0 ? 1.0 : xu_rng_unit(r);
        if (spt_unit_point(k, f, e, 1.0, pts[np])) {
            for (j = 0; j < 3; j++) pts[np][j] *= rad; /* rad <= 1 */
            if (spt_in_ball(k, pts[np])) np++;
            else g->pts_skipped++;
        } else {
            g->pts_skipped++;
        }
    }
    g->pts += np;
    for (n = 0; n < np; n++)
        for (i = 0; i < 3; i++) {
            if (!(okmask & (1 << i))) continue;
            v->applied[F_POINT]++;
            if (P->ell) spt_ell_image(k, P->center, P->radii, P->rot, i, pts[n]);
            else spt_sphere_image(k, &P->a, i, pts[n]);
            xu_scaled_sh(k->z, out->lo[i], PT_SHIFT);
            xu_scaled_sh(k->w, out->hi[i], PT_SHIFT);
            if (mpz_cmp(k->y, k->z) < 0 || mpz_cmp(k->y, k->w) > 0) {
                snprintf(why, sizeof why, "axis %d: image of p = (%a, %a, %a) outside",
                         i, pts[n][0], pts[n][1], pts[n][2]);
                v_fail(v, F_POINT, why);
            }
        }
}

static int is_pinf(double d) { return d > 0 && isinf(d); }
static int is_ninf(double d) { return d < 0 && isinf(d); }

/* Run one problem.  *mx: largest units over ends (non-tiny axes). */
int spt_run_problem(ctx *k, group *g, const problem *P, cbx_box *out,
                    verdict *v, double *mx, xu_rng *r)
{
    problem P0 = *P;
    int i, oob, okmask = 0;
    char why[200];

    for (i = 0; i < 3; i++) out->lo[i] = out->hi[i] = NAN;
    v_init(v);
    v->got = prob_call(P, out);
    v->expected = spt_prob_expected(P, &oob);
    *mx = 0;

    v->applied[F_INPUT]++;
    if (memcmp(&P0, P, sizeof P0)) v_fail(v, F_INPUT, "the call modified its inputs");
    v->applied[F_STATUS]++;
    if (v->got != v->expected) {
        snprintf(why, sizeof why, "status %s (%d), expected %s", cbx_status_name(v->got),
                 (int)v->got, cbx_status_name(v->expected));
        v_fail(v, F_STATUS, why);
    }
    v->applied[F_UNSET]++;
    for (i = 0; i < 3; i++)
        if (xu_is_nan(out->lo[i]) || xu_is_nan(out->hi[i])) {
            v_fail(v, F_UNSET, "NaN left in out (field not written)");
            break;
        }
    if (v->expected == CBX_EINVAL) {
        int ok = 1;
        v->applied[F_SPECIAL]++;
        for (i = 0; i < 3; i++) ok &= is_ninf(out->lo[i]) && is_pinf(out->hi[i]);
        if (!ok) v_fail(v, F_SPECIAL, "EINVAL: out is not [-inf,+inf]^3");
        return v->failed;
    }
    for (i = 0; i < 3; i++) {
        double t = prob_t(P, i);
        unsigned long sh = P->ell ? SH_ELL : SH_SPHERE;
        int lo_ok, hi_ok;
        rowres rr;
        if (oob & (1 << i)) {
            v->applied[F_OOB]++;
            if (!is_ninf(out->lo[i]) || !is_pinf(out->hi[i])) {
                snprintf(why, sizeof why, "axis %d out of domain but not [-inf,+inf]", i);
                v_fail(v, F_OOB, why);
            }
            continue;
        }
        v->applied[F_FINITE]++;
        if (!isfinite(out->lo[i]) || !isfinite(out->hi[i]) || out->lo[i] > out->hi[i]) {
            snprintf(why, sizeof why, "axis %d in domain but out = [%g, %g]", i,
                     out->lo[i], out->hi[i]);
            v_fail(v, F_FINITE, why);
            continue;
        }
        okmask |= 1 << i;
        if (P->ell) spt_ell_s(k, P->radii, P->rot, i);
        else spt_sphere_s(k, &P->a, i);
        v->applied[F_CONTAIN]++;
        lo_ok = xu_sqrt_lo_ok(&k->x, k->s[i], sh, t, out->lo[i]);
        hi_ok = xu_sqrt_hi_ok(&k->x, k->s[i], sh, t, out->hi[i]);
        spt_mp_row(k, k->s[i], sh, t, out->lo[i], out->hi[i], &rr);
        if (!lo_ok || !hi_ok) {
            snprintf(why, sizeof why, "axis %d: t -+ sqrt(s) not contained (%s%s; "
                     "ulps lo %.3g, hi %.3g)", i, lo_ok ? "" : "lo", hi_ok ? "" : " hi",
                     rr.ulps_lo, rr.ulps_hi);
            v_fail(v, F_CONTAIN, why);
        }
        /* tightness: 64 units (the brief's sanity bound) where
         * u*(|t|+sqrt s) >= 2^-1000, an absolute 2^-1000 below that */
        if (!rr.tiny) {
            v->applied[F_SANITY]++;
            if (rr.bad_lo || rr.bad_hi) {
                snprintf(why, sizeof why, "axis %d: sanity bound (units lo %.3g, hi %.3g)",
                         i, rr.units_lo, rr.units_hi);
                v_fail(v, F_SANITY, why);
            }
        } else {
            v->applied[F_TINYABS]++;
            if (rr.bad_lo || rr.bad_hi) {
                snprintf(why, sizeof why, "axis %d: gap above 2^-1000 at tiny scale "
                         "(units lo %.3g, hi %.3g)", i, rr.units_lo, rr.units_hi);
                v_fail(v, F_TINYABS, why);
            }
        }
        /* the contract's tightness (ball_tight), on every in-domain axis */
        v->applied[F_PROVEN]++;
        if (rr.over_proven) {
            snprintf(why, sizeof why, "axis %d: beyond the proven bound 80 u (|t| + sqrt s) + 2^-1064 "
                     "(units lo %.3g, hi %.3g)", i, rr.units_lo, rr.units_hi);
            v_fail(v, F_PROVEN, why);
        }
        g->axes++;
        g->prec_raised += rr.raised;
        g->exact_ends += rr.exact_lo + rr.exact_hi;
        if (rr.tiny) {
            g->axes_tiny++;
            ex_add(&g->units_tiny, rr.units_lo);
            ex_add(&g->units_tiny, rr.units_hi);
        } else {
            double m = rr.units_lo > rr.units_hi ? rr.units_lo : rr.units_hi;
            ex_add(&g->units, rr.units_lo);
            ex_add(&g->units, rr.units_hi);
            if (rr.big) {
                ex_add(&g->units_big, rr.units_lo);
                ex_add(&g->units_big, rr.units_hi);
            }
            if (m > *mx) *mx = m;
            if (m > g->worst || !g->worst_case[0]) {
                char *b = g->worst_case;
                size_t n = sizeof g->worst_case;
                int w = snprintf(b, n, "  axis %d, ulps lo %.4g hi %.4g\n", i,
                                 rr.ulps_lo, rr.ulps_hi);
                g->worst = m;
                if (w > 0 && (size_t)w < n) {
                    if (P->ell)
                        snprintf(b + w, n - (size_t)w, "  center %a, radii {%a, %a, %a},"
                                 " rot[%d] {%a, %a, %a}\n", P->center[i], P->radii[0],
                                 P->radii[1], P->radii[2], i, P->rot[i][0], P->rot[i][1],
                                 P->rot[i][2]);
                    else
                        snprintf(b + w, n - (size_t)w, "  m[%d] = {%a, %a, %a | %a}\n", i,
                                 P->a.m[i][0], P->a.m[i][1], P->a.m[i][2], P->a.m[i][3]);
                }
            }
        }
        if (rr.ulps_lo > g->ulps_max) g->ulps_max = rr.ulps_lo;
        if (rr.ulps_hi > g->ulps_max) g->ulps_max = rr.ulps_hi;
        g->ulps_over64 += (rr.ulps_lo > 64) + (rr.ulps_hi > 64);
        if (rr.big && !rr.cancel_lo) ex_add(&g->ulps_nocancel, rr.ulps_lo);
        if (rr.big && !rr.cancel_hi) ex_add(&g->ulps_nocancel, rr.ulps_hi);
    }
    if (okmask) check_points(k, g, v, P, out, okmask, r);
    return v->failed;
}

void spt_log_failure(const char *what, long id, const problem *P,
                     const cbx_box *out, const verdict *v)
{
    if (spt_fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL %s %ld: %s (status %s, expected %s)\n", what, id, v->why,
           cbx_status_name(v->got), cbx_status_name(v->expected));
    print_problem(stdout, P);
    xu_print_box(stdout, "out", out);
}
