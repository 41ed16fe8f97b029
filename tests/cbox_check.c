/*
 * cbox_check.c: part of tests/test_cbox.c (cbox_parts.h): the verdict of
 * one case and its checks, the statistics per group of cases and their
 * report, the exact context (GMP fixed point, scaled by 2^XU_SHIFT), and
 * the oracle and checks of cbx_transform_cbox (kinds A, D, W; corners).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "cbox_parts.h"

/* ---------------------------------------------------------------------- */
/* Checks, verdicts, statistics                                           */
/* ---------------------------------------------------------------------- */

static const char *const f_name[NF] = {
    "status", "out-set", "special-out", "lost-axes", "finite", "containment",
    "spec-tight", "sanity<=64", "tiny-abs", "corners", "cross-CH",
    "D-finite", "D-contain", "D-spec-tight", "D-corners", "D-cross-CH",
    "round-trip", "inputs", "conv-tight"
};
static const char *const f_unit[NF] = {
    "cases", "cases", "cases", "axes", "axes", "axes",
    "axes", "axes", "axes", "axes", "axes",
    "axes", "axes", "axes", "axes", "axes", "cases", "cases", "axes"
};

long cbt_fail_logs;

void cbt_v_init(verdict *v) { memset(v, 0, sizeof *v); }

void cbt_v_fail(verdict *v, int f, const char *why)
{
    v->flag[f]++;
    if (!v->failed) {
        strncpy(v->why, why, sizeof v->why - 1);
        v->why[sizeof v->why - 1] = '\0';
    }
    v->failed = 1;
}

void cbt_ex_add(exstat *e, double u, int tiny, int exact)
{
    if (tiny) {
        if (e->n_tiny == 0 || u > e->max_tiny) e->max_tiny = u;
        e->n_tiny++;
        return;
    }
    if (e->n == 0 || u > e->max) e->max = u;
    e->sum += u;
    e->n++;
    e->n_exact += exact;
    e->over8 += u > 8;
}

void cbt_g_init(group *g, const char *name, const char *main_what)
{
    memset(g, 0, sizeof *g);
    g->name = name;
    g->main_what = main_what;
}

void cbt_g_add(group *g, const verdict *v)
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

static void ex_print(const char *what, const exstat *e)
{
    if (e->n)
        printf("  %-11s max %9.4f  mean %7.4f  (%ld axes, %ld exactly 0, %ld above 8)\n",
               what, e->max, e->sum / (double)e->n, e->n, e->n_exact, e->over8);
    else
        printf("  %-11s (no axis with u*S >= 2^-1000)\n", what);
    if (e->n_tiny)
        printf("  %-11s u*S < 2^-1000: %ld axes, max %.4g units (there only "
               "gap <= 2^-1000 is required)\n", "", e->n_tiny, e->max_tiny);
}

void cbt_g_print(const group *g)
{
    int f;
    printf("== %s: %ld cases (expected OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld), "
           "%ld failed\n", g->name, g->cases, g->status_seen[0], g->status_seen[1],
           g->status_seen[2], g->status_seen[3], g->failed);
    for (f = 0; f < NF; f++)
        if (g->applied[f])
            printf("  check %-12s %9ld %-5s checked, %6ld failed\n", f_name[f],
                   g->applied[f], f_unit[f], g->fails[f]);
    printf("  excess in units of %s:\n", g->main_what);
    ex_print("lower end", &g->lo);
    ex_print("upper end", &g->hi);
    ex_print("bounded qty", &g->main);
    if (g->kinds[XU_CAX_FULL] || g->kinds[XU_CAX_DROP] || g->kinds[XU_CAX_LOST]) {
        printf("  axes by kind: A full row %ld, D zero columns dropped %ld, "
               "W lost (c = 0, h = +inf) %ld\n", g->kinds[XU_CAX_FULL],
               g->kinds[XU_CAX_DROP], g->kinds[XU_CAX_LOST]);
        if (g->kinds[XU_CAX_DROP])
            ex_print("D axes", &g->drop);
    }
    if (g->rt_n || g->rt_skipped)
        printf("  round trips: %ld checked, %ld skipped (2nd step not CBX_OK), "
               "max widening %.4f units\n", g->rt_n, g->rt_skipped, g->rt_max);
}

/* ---------------------------------------------------------------------- */
/* Exact context                                                          */
/* ---------------------------------------------------------------------- */

void cbt_ctx_init(ctx *k)
{
    xu_init(&k->x);
    mpz_inits(k->C, k->H, k->S, k->p, k->olo, k->ohi, k->elo, k->ehi, k->g,
              k->t, (mpz_ptr)0);
    mpq_inits(k->q, k->qa, k->qb, k->qlo, k->qhi, k->qmin, k->qmax, (mpq_ptr)0);
}

void cbt_ctx_clear(ctx *k)
{
    xu_clear(&k->x);
    mpz_clears(k->C, k->H, k->S, k->p, k->olo, k->ohi, k->elo, k->ehi, k->g,
               k->t, (mpz_ptr)0);
    mpq_clears(k->q, k->qa, k->qb, k->qlo, k->qhi, k->qmin, k->qmax, (mpq_ptr)0);
}

int cbt_is_pinf(double d) { return d > 0 && isinf(d); }
int cbt_is_ninf(double d) { return d < 0 && isinf(d); }

/* k->olo, k->ohi = c -+ h, scaled */
void cbt_cbox_ends(ctx *k, double c, double h)
{
    xu_scaled_d(&k->x, k->t, c);
    xu_scaled_d(&k->x, k->g, h);
    mpz_sub(k->olo, k->t, k->g);
    mpz_add(k->ohi, k->t, k->g);
}

/* One side: gap (scaled, >= 0 when contained) against scale S. Returns the
 * excess in units; sets *sanity_bad. */
double cbt_side_units(ctx *k, const mpz_t gap, const mpz_t S, int tiny,
                         int *sanity_bad)
{
    double u = xu_units(&k->x, gap, S);
    /* gap > max(64 (u S + eta), 2^-1000); for u S >= 2^-1000 the first
     * term decides, below it the absolute 2^-1000 does */
    (void)tiny;
    *sanity_bad = u > SANITY && xu_gap_above_tiny_cap(gap);
    return u;
}

/* gap 2^53 <= 12 S + 2^(XU_SHIFT - 1065 + 53): cbox_tight of cbx_spec.h */
static int within_spec(ctx *k, const mpz_t gap, const mpz_t S)
{
    mpz_mul_2exp(k->p, gap, 53);
    mpz_set_ui(k->t, 1);
    mpz_mul_2exp(k->t, k->t, XU_SHIFT - 1065 + 53);
    mpz_addmul_ui(k->t, S, 12);
    return mpz_cmp(k->p, k->t) <= 0;
}

/* ---------------------------------------------------------------------- */
/* cbx_transform_cbox: oracle and checks                                  */
/* ---------------------------------------------------------------------- */

/* The status by exact_util's rules (A full row, D zero columns dropped,
 * W lost; exact_util.h); *oob = the W axes (losses), kinds = "ADW"-letters
 * per axis ("---" for EINVAL / EMPTY). */
cbx_status cbt_tc_expected(const cbx_affine *a, const cbx_cbox *in, int *oob,
                              char kinds[4])
{
    cbx_status st = xu_cbox_expected_status(a, in);
    *oob = 0;
    strcpy(kinds, "---");
    if (st != CBX_OK && st != CBX_ERANGE) return st;
    *oob = xu_cbox_loss_mask(a, in);
    xu_cbox_kinds_str(a, in, kinds);
    return st;
}

/* C = t + sum m_j c_j, H = sum |m_j h_j|, S = |t| + sum |m_j c_j| + H */
static void tc_row(ctx *k, const cbx_affine *a, const cbx_cbox *in, int i)
{
    int j;
    xu_scaled_d(&k->x, k->C, a->m[i][3]);
    mpz_abs(k->S, k->C);
    mpz_set_ui(k->H, 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(&k->x, k->p, a->m[i][j], in->c[j]);
        mpz_add(k->C, k->C, k->p);
        if (mpz_sgn(k->p) < 0) mpz_sub(k->S, k->S, k->p);
        else mpz_add(k->S, k->S, k->p);
        xu_scaled_mul(&k->x, k->p, a->m[i][j], in->h[j]);
        if (mpz_sgn(k->p) < 0) mpz_sub(k->H, k->H, k->p);
        else mpz_add(k->H, k->H, k->p);
    }
    mpz_add(k->S, k->S, k->H);
    mpz_sub(k->elo, k->C, k->H);
    mpz_add(k->ehi, k->C, k->H);
}

/* mpq image of row i at corner cn (bit j: c_j + h_j, else c_j - h_j) */
static void tc_corner_q(ctx *k, mpq_t r, const cbx_affine *a,
                        const cbx_cbox *in, int i, unsigned cn)
{
    int j;
    mpq_set_d(r, a->m[i][3]);
    for (j = 0; j < 3; j++) {
        mpq_set_d(k->qa, in->c[j]);
        mpq_set_d(k->qb, in->h[j]);
        if ((cn >> j) & 1u) mpq_add(k->qa, k->qa, k->qb);
        else mpq_sub(k->qa, k->qa, k->qb);
        mpq_set_d(k->qb, a->m[i][j]);
        mpq_mul(k->qa, k->qa, k->qb);
        mpq_add(r, r, k->qa);
    }
}

/* in: the input box the row is checked on (the dropped box for D axes,
 * drop != 0: then the D-flags are used). */
static void tc_corners(ctx *k, verdict *v, const cbx_affine *a,
                       const cbx_cbox *in, const cbx_cbox *out, int i, int drop)
{
    int f_corner = drop ? F_DCORNER : F_CORNER, f_cross = drop ? F_DCROSS : F_CROSS;
    unsigned cn;
    int bad = 0;
    char why[120];
    mpq_set_d(k->qlo, out->c[i]);
    mpq_set_d(k->qa, out->h[i]);
    mpq_add(k->qhi, k->qlo, k->qa);
    mpq_sub(k->qlo, k->qlo, k->qa);
    for (cn = 0; cn < 8; cn++) {
        tc_corner_q(k, k->q, a, in, i, cn);
        if (mpq_cmp(k->q, k->qlo) < 0 || mpq_cmp(k->q, k->qhi) > 0) bad++;
        if (cn == 0 || mpq_cmp(k->q, k->qmin) < 0) mpq_set(k->qmin, k->q);
        if (cn == 0 || mpq_cmp(k->q, k->qmax) > 0) mpq_set(k->qmax, k->q);
    }
    v->applied[f_corner]++;
    if (bad) {
        snprintf(why, sizeof why, "axis %d%s: %d corner images outside (mpq)", i,
                 drop ? " (D, dropped box)" : "", bad);
        cbt_v_fail(v, f_corner, why);
    }
    v->applied[f_cross]++;
    xu_scaled_to_q(k->qa, k->elo);
    xu_scaled_to_q(k->qb, k->ehi);
    if (!mpq_equal(k->qa, k->qmin) || !mpq_equal(k->qb, k->qmax)) {
        snprintf(why, sizeof why, "axis %d%s: mpq corners != fixed-point C -+ H", i,
                 drop ? " (D)" : "");
        cbt_v_fail(v, f_cross, why);
    }
}

void cbt_check_cwhole_axis(verdict *v, const cbx_cbox *o, int i, int flag,
                              const char *what)
{
    if (!(o->c[i] == 0 && cbt_is_pinf(o->h[i]))) cbt_v_fail(v, flag, what);
}

/* EINVAL (whole) / EMPTY output of a cbox-valued function */
void cbt_check_cspecial(verdict *v, const cbx_cbox *o, int whole)
{
    int i, ok = 1;
    v->applied[F_SPECIAL]++;
    for (i = 0; i < 3; i++)
        ok &= o->c[i] == 0 && (whole ? cbt_is_pinf(o->h[i]) : cbt_is_ninf(o->h[i]));
    if (!ok)
        cbt_v_fail(v, F_SPECIAL, whole ? "EINVAL: out is not c = 0, h = +inf"
                                   : "EMPTY: out is not c = 0, h = -inf");
}

int cbt_check_unset_c(verdict *v, const cbx_cbox *o)
{
    int i;
    v->applied[F_UNSET]++;
    for (i = 0; i < 3; i++)
        if (xu_is_nan(o->c[i]) || xu_is_nan(o->h[i])) {
            cbt_v_fail(v, F_UNSET, "NaN left in out (field not written)");
            return 1;
        }
    return 0;
}

void cbt_check_status(verdict *v)
{
    char why[96];
    v->applied[F_STATUS]++;
    if (v->got != v->expected) {
        snprintf(why, sizeof why, "status %s (%d), expected %s",
                 cbx_status_name(v->got), (int)v->got, cbx_status_name(v->expected));
        cbt_v_fail(v, F_STATUS, why);
    }
}

/* Run one transform case; adds the excess to g; returns v->failed. */
int cbt_tc_run(ctx *k, group *g, const cbx_affine *a, const cbx_cbox *in,
                  cbx_cbox *out, int corners, verdict *v, double *mx)
{
    cbx_affine a0 = *a;
    cbx_cbox in0 = *in;
    int i, oob;
    char why[160], kinds[4];

    for (i = 0; i < 3; i++) out->c[i] = out->h[i] = NAN;
    cbt_v_init(v);
    v->got = cbx_transform_cbox(a, in, out);
    v->expected = cbt_tc_expected(a, in, &oob, kinds);
    *mx = 0;
    v->applied[F_INPUT]++;
    if (memcmp(&a0, a, sizeof a0) || memcmp(&in0, in, sizeof in0))
        cbt_v_fail(v, F_INPUT, "the call modified its inputs");
    cbt_check_status(v);
    cbt_check_unset_c(v, out);
    if (v->expected == CBX_EINVAL || v->expected == CBX_EMPTY) {
        cbt_check_cspecial(v, out, v->expected == CBX_EINVAL);
        return v->failed;
    }
    for (i = 0; i < 3; i++) {
        int tiny, bad_lo, bad_hi;
        double ulo, uhi;
        int kind = xu_cbox_axis_kind(a, in, i), drop = kind == XU_CAX_DROP;
        int f_fin = drop ? F_DFINITE : F_FINITE, f_cont = drop ? F_DCONTAIN : F_CONTAIN;
        int f_spec = drop ? F_DSPEC : F_SPEC;
        const char *dz = drop ? " (D, zero columns dropped)" : "";
        cbx_cbox dd;
        const cbx_cbox *use = in;  /* the box the row is checked on */
        g->kinds[kind]++;
        if (kind == XU_CAX_LOST) {
            v->applied[F_OOB]++;
            snprintf(why, sizeof why, "axis %d lost (W) but not c = 0, h = +inf", i);
            cbt_check_cwhole_axis(v, out, i, F_OOB, why);
            continue;
        }
        if (drop) {
            xu_cbox_dropped(a, in, i, &dd);
            use = &dd;
        }
        v->applied[f_fin]++;
        if (!isfinite(out->c[i]) || !isfinite(out->h[i]) || out->h[i] < 0) {
            snprintf(why, sizeof why, "axis %d%s: out c = %g, h = %g, not finite with h >= 0",
                     i, dz, out->c[i], out->h[i]);
            cbt_v_fail(v, f_fin, why);
            continue;
        }
        tc_row(k, a, use, i);
        cbt_cbox_ends(k, out->c[i], out->h[i]);
        mpz_sub(k->olo, k->elo, k->olo);   /* gap below: (C - H) - (c - h) */
        mpz_sub(k->ohi, k->ohi, k->ehi);   /* gap above: (c + h) - (C + H) */
        tiny = xu_scale_tiny(k->S);
        ulo = cbt_side_units(k, k->olo, k->S, tiny, &bad_lo);
        uhi = cbt_side_units(k, k->ohi, k->S, tiny, &bad_hi);
        v->applied[f_cont]++;
        if (mpz_sgn(k->olo) < 0 || mpz_sgn(k->ohi) < 0) {
            snprintf(why, sizeof why, "axis %d%s: not contained (excess lo %.3g, hi %.3g)",
                     i, dz, ulo, uhi);
            cbt_v_fail(v, f_cont, why);
        }
        v->applied[f_spec]++;
        if (!within_spec(k, k->olo, k->S) || !within_spec(k, k->ohi, k->S)) {
            snprintf(why, sizeof why, "axis %d%s: beyond 12uS+2^-1065 (excess lo %.3g, hi %.3g)",
                     i, dz, ulo, uhi);
            cbt_v_fail(v, f_spec, why);
        }
        v->applied[tiny ? F_TINYABS : F_SANITY]++;
        if (bad_lo || bad_hi) {
            snprintf(why, sizeof why, "axis %d: sanity bound (excess lo %.3g, hi %.3g%s)",
                     i, ulo, uhi, tiny ? ", tiny scale: gap > 2^-1000" : "");
            cbt_v_fail(v, tiny ? F_TINYABS : F_SANITY, why);
        }
        if (drop) {
            cbt_ex_add(&g->drop, ulo > uhi ? ulo : uhi, tiny,
                   mpz_sgn(k->olo) == 0 && mpz_sgn(k->ohi) == 0);
        } else {
            cbt_ex_add(&g->lo, ulo, tiny, mpz_sgn(k->olo) == 0);
            cbt_ex_add(&g->hi, uhi, tiny, mpz_sgn(k->ohi) == 0);
            cbt_ex_add(&g->main, ulo > uhi ? ulo : uhi, tiny,
                   mpz_sgn(k->olo) == 0 && mpz_sgn(k->ohi) == 0);
        }
        if (!tiny && ulo > *mx) *mx = ulo;
        if (!tiny && uhi > *mx) *mx = uhi;
        if (corners) tc_corners(k, v, a, use, out, i, drop);
    }
    return v->failed;
}
