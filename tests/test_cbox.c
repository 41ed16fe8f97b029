/*
 * test_cbox [N] [seed]: the centre/half-diagonal functions against exact
 * rational arithmetic (GMP).
 *
 *   cbx_transform_cbox  (a, (c, h)) -> (c', h')   Arvo's Fig. 2
 *   cbx_box_to_cbox     [lo, hi]    -> (c, h)
 *   cbx_cbox_to_box     (c, h)      -> [lo, hi]
 *
 * A cbx_cbox (c, h) means the exact real box [c - h, c + h].  For each
 * function: first a table of hand-picked hard cases (each printed), then N
 * random cases (default 300000) from a fixed-seed splitmix64 generator.
 * Every case checks: the status equals the one decided exactly from the
 * contract in certbox.h, every output field is written (NaN pre-fill),
 * EINVAL / EMPTY outputs are exactly as specified, lost (out-of-domain)
 * axes are exactly the whole line, the other axes are finite and contain the exact
 * image (exact comparison on integers scaled by 2^2148), the inputs are not
 * modified.  Tightness is measured in units of u*S + eta (u = 2^-53,
 * eta = 2^-1074, S the scale of each function, below), printed as max and
 * mean.  Check "sanity<=64": an end more than 64 units out fails on axes
 * with u*S >= 2^-1000.  Check "tiny-abs": below that scale absolute terms
 * of the widening (2^-1065, ...) dominate, and an end fails only when its
 * gap is above both 64 units and 2^-1000.  Statistics keep the axes with
 * u*S < 2^-1000 apart.
 *
 * transform_cbox also checks the 8 corners c_j -+ h_j with plain mpq_t
 * (hard cases and every CORNER_EVERY-th random case), that the corners'
 * min / max equal the fixed-point C - H / C + H, and the tightness of the
 * contract in specs/cbx_spec.h (cbox_tight): each end within
 * 12 u S + 2^-1065 of the exact end.
 *
 * transform_cbox drops zero-coefficient columns (exact_util.h, specs:
 * crow_dfull): per output axis, kind A (full row: every input finite and
 * in the domain) is the kernel as above; kind D (not full, but full once
 * every column with m_j == 0, also -0.0, takes c_j = h_j = 0 whatever c_j,
 * h_j are, +-inf included) is checked the same way on the DROPPED row: out
 * finite with h >= 0, the exact image contained (a dropped column adds
 * exactly 0), the 8 mpq corners of the dropped box inside, and each end
 * within 12 u S' + 2^-1065 of the exact end, S' = |t| + sum_j |m_j c_j'|
 * + |m_j h_j'| (checks D-finite, D-contain, D-spec-tight, D-corners,
 * D-cross-CH); kind W (still not full) must be exactly c = 0, h = +inf and
 * is a loss (check lost-axes).  CBX_OK iff no axis is W.  A table of
 * hand-picked zero-column cases (zero coefficients against c or h = +-inf,
 * out-of-domain magnitudes in a zero column, -0.0, mixes with an infinite
 * nonzero column, NaN / h < 0 in a zero column) and N/3 random zero-column
 * cases (corners on every 5th) exercise D; the axes are counted by kind.
 *
 * cbx_box_to_cbox is EMPTY when some axis has no real point: hi < lo,
 * lo = +inf or hi = -inf (xu_is_empty); a half-line or the whole line is
 * not empty but outside the domain (that axis c = 0, h = +inf).
 *
 * Round trips: box -> cbox -> box contains the original box, and
 * cbox -> box -> cbox contains the original cbox (exactly), whenever both
 * steps return CBX_OK.
 *
 * The last line is "N passed, M failed" (cases); exit status 1 on failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <time.h>

#include "certbox.h"
#include "exact_util.h"

/* Domain of the conversions: |input| <= 2^CONV_EMAX.  certbox.h and
 * conv_dom in specs/cbx_spec.h say 2^1019 (an earlier draft said 2^1020). */
#ifndef CONV_EMAX
#define CONV_EMAX 1019
#endif
/* 2^CONV_EMAX and one ulp above it, as constant expressions (tables) */
#define XPOW_(e) 0x1p##e
#define XPOW(e) XPOW_(e)
#define CLIM XPOW(CONV_EMAX)
#define CLIMU (CLIM * 0x1.0000000000001p0)
#ifndef CORNER_EVERY
#define CORNER_EVERY 50
#endif
#define SANITY 64.0
#define MAX_FAIL_LOGS 20

#define INF HUGE_VAL
#define TC_UNITS "u*S + eta, S = |t| + sum |m_j|(|c_j| + h_j) (D axes: S' of the dropped row)"

/* ---------------------------------------------------------------------- */
/* Checks, verdicts, statistics                                           */
/* ---------------------------------------------------------------------- */

enum {
    F_STATUS,    /* status differs from the exactly decided one          */
    F_UNSET,     /* NaN pre-fill left in the output                      */
    F_SPECIAL,   /* EINVAL / EMPTY output not exactly as specified       */
    F_OOB,       /* lost axis (W, out of domain) not exactly the whole line */
    F_FINITE,    /* in-domain (A) axis not finite (or lo > hi, h < 0)     */
    F_CONTAIN,   /* the exact image is not contained (exact)             */
    F_SPEC,      /* beyond 12 u S + 2^-1065 (cbox_tight, transform only) */
    F_SANITY,    /* > 64 units where u S >= 2^-1000                      */
    F_TINYABS,   /* gap > max(64 (u S + eta), 2^-1000) where u S < 2^-1000 */
    F_CORNER,    /* an mpq corner image is outside the output            */
    F_CROSS,     /* mpq corner min / max != fixed-point C -+ H           */
    /* transform_cbox, axes of kind D (zero-coefficient columns dropped):
     * the same checks on the dropped row, S' instead of S               */
    F_DFINITE,   /* D axis not finite (or h < 0)                         */
    F_DCONTAIN,  /* D: the exact image (dropped row) not contained       */
    F_DSPEC,     /* D: beyond 12 u S' + 2^-1065                          */
    F_DCORNER,   /* D: an mpq corner of the dropped box maps outside     */
    F_DCROSS,    /* D: mpq corner min / max != fixed-point C' -+ H'      */
    F_ROUND,     /* round trip does not contain the original             */
    F_INPUT,     /* the call modified its input                          */
    F_CSPEC,     /* conversions: beyond 16 u (|x| + |y|) + 2^-1066 (conv_gap) */
    NF
};
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

typedef struct verdict {
    cbx_status expected, got;
    int failed;
    int flag[NF], applied[NF];
    char why[200];
} verdict;

typedef struct exstat {      /* excess of in-domain axes, in units        */
    long n, n_tiny, n_exact, over8;
    double max, sum, max_tiny;
} exstat;

typedef struct group {
    const char *name;
    long cases, failed;
    long status_seen[4];
    long applied[NF], fails[NF];
    exstat lo, hi, main;     /* main: the quantity the sanity bound uses  */
    exstat drop;             /* transform_cbox D axes: max of both ends,
                                units of u S' + eta (not in lo/hi/main)   */
    long kinds[XU_NCAX];     /* transform_cbox axes by kind (A, D, W)     */
    const char *main_what;
    long rt_n, rt_skipped;   /* round trips checked / second step not OK  */
    double rt_max;           /* round-trip excess, units                  */
} group;

static long fail_logs;

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

static void ex_add(exstat *e, double u, int tiny, int exact)
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

static void g_init(group *g, const char *name, const char *main_what)
{
    memset(g, 0, sizeof *g);
    g->name = name;
    g->main_what = main_what;
}

static void g_add(group *g, const verdict *v)
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

static void g_print(const group *g)
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

typedef struct ctx {
    xu_exact x;
    mpz_t C, H, S, p, olo, ohi, elo, ehi, g, t;
    mpq_t q, qa, qb, qlo, qhi, qmin, qmax;
} ctx;

static void ctx_init(ctx *k)
{
    xu_init(&k->x);
    mpz_inits(k->C, k->H, k->S, k->p, k->olo, k->ohi, k->elo, k->ehi, k->g,
              k->t, (mpz_ptr)0);
    mpq_inits(k->q, k->qa, k->qb, k->qlo, k->qhi, k->qmin, k->qmax, (mpq_ptr)0);
}

static void ctx_clear(ctx *k)
{
    xu_clear(&k->x);
    mpz_clears(k->C, k->H, k->S, k->p, k->olo, k->ohi, k->elo, k->ehi, k->g,
               k->t, (mpz_ptr)0);
    mpq_clears(k->q, k->qa, k->qb, k->qlo, k->qhi, k->qmin, k->qmax, (mpq_ptr)0);
}

static int is_pinf(double d) { return d > 0 && isinf(d); }
static int is_ninf(double d) { return d < 0 && isinf(d); }

/* k->olo, k->ohi = c -+ h, scaled */
static void cbox_ends(ctx *k, double c, double h)
{
    xu_scaled_d(&k->x, k->t, c);
    xu_scaled_d(&k->x, k->g, h);
    mpz_sub(k->olo, k->t, k->g);
    mpz_add(k->ohi, k->t, k->g);
}

/* One side: gap (scaled, >= 0 when contained) against scale S. Returns the
 * excess in units; sets *sanity_bad. */
static double side_units(ctx *k, const mpz_t gap, const mpz_t S, int tiny,
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

/* gap <= 16 u (|x| + |y|) + 2^-1066: conv_gap of cbx_spec.h, the proven
 * tightness of both conversions (x, y the axis' two inputs) */
static int within_conv(ctx *k, const mpz_t gap, double x, double y)
{
    xu_scaled_d(&k->x, k->t, fabs(x));
    xu_scaled_d(&k->x, k->p, fabs(y));
    mpz_add(k->t, k->t, k->p);                   /* |x| + |y| */
    mpz_set_ui(k->p, 1);
    mpz_mul_2exp(k->p, k->p, XU_SHIFT - 1066 + 49);
    mpz_add(k->t, k->t, k->p);                   /* + 2^-1066 2^49 */
    mpz_mul_2exp(k->p, gap, 49);                 /* gap / (16 u) */
    return mpz_cmp(k->p, k->t) <= 0;
}

/* ---------------------------------------------------------------------- */
/* cbx_transform_cbox: oracle and checks                                  */
/* ---------------------------------------------------------------------- */

/* The status by exact_util's rules (A full row, D zero columns dropped,
 * W lost; exact_util.h); *oob = the W axes (losses), kinds = "ADW"-letters
 * per axis ("---" for EINVAL / EMPTY). */
static cbx_status tc_expected(const cbx_affine *a, const cbx_cbox *in, int *oob,
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
        v_fail(v, f_corner, why);
    }
    v->applied[f_cross]++;
    xu_scaled_to_q(k->qa, k->elo);
    xu_scaled_to_q(k->qb, k->ehi);
    if (!mpq_equal(k->qa, k->qmin) || !mpq_equal(k->qb, k->qmax)) {
        snprintf(why, sizeof why, "axis %d%s: mpq corners != fixed-point C -+ H", i,
                 drop ? " (D)" : "");
        v_fail(v, f_cross, why);
    }
}

static void check_cwhole_axis(verdict *v, const cbx_cbox *o, int i, int flag,
                              const char *what)
{
    if (!(o->c[i] == 0 && is_pinf(o->h[i]))) v_fail(v, flag, what);
}

/* EINVAL (whole) / EMPTY output of a cbox-valued function */
static void check_cspecial(verdict *v, const cbx_cbox *o, int whole)
{
    int i, ok = 1;
    v->applied[F_SPECIAL]++;
    for (i = 0; i < 3; i++)
        ok &= o->c[i] == 0 && (whole ? is_pinf(o->h[i]) : is_ninf(o->h[i]));
    if (!ok)
        v_fail(v, F_SPECIAL, whole ? "EINVAL: out is not c = 0, h = +inf"
                                   : "EMPTY: out is not c = 0, h = -inf");
}

static int check_unset_c(verdict *v, const cbx_cbox *o)
{
    int i;
    v->applied[F_UNSET]++;
    for (i = 0; i < 3; i++)
        if (xu_is_nan(o->c[i]) || xu_is_nan(o->h[i])) {
            v_fail(v, F_UNSET, "NaN left in out (field not written)");
            return 1;
        }
    return 0;
}

static void check_status(verdict *v)
{
    char why[96];
    v->applied[F_STATUS]++;
    if (v->got != v->expected) {
        snprintf(why, sizeof why, "status %s (%d), expected %s",
                 cbx_status_name(v->got), (int)v->got, cbx_status_name(v->expected));
        v_fail(v, F_STATUS, why);
    }
}

/* Run one transform case; adds the excess to g; returns v->failed. */
static int tc_run(ctx *k, group *g, const cbx_affine *a, const cbx_cbox *in,
                  cbx_cbox *out, int corners, verdict *v, double *mx)
{
    cbx_affine a0 = *a;
    cbx_cbox in0 = *in;
    int i, oob;
    char why[160], kinds[4];

    for (i = 0; i < 3; i++) out->c[i] = out->h[i] = NAN;
    v_init(v);
    v->got = cbx_transform_cbox(a, in, out);
    v->expected = tc_expected(a, in, &oob, kinds);
    *mx = 0;
    v->applied[F_INPUT]++;
    if (memcmp(&a0, a, sizeof a0) || memcmp(&in0, in, sizeof in0))
        v_fail(v, F_INPUT, "the call modified its inputs");
    check_status(v);
    check_unset_c(v, out);
    if (v->expected == CBX_EINVAL || v->expected == CBX_EMPTY) {
        check_cspecial(v, out, v->expected == CBX_EINVAL);
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
            check_cwhole_axis(v, out, i, F_OOB, why);
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
            v_fail(v, f_fin, why);
            continue;
        }
        tc_row(k, a, use, i);
        cbox_ends(k, out->c[i], out->h[i]);
        mpz_sub(k->olo, k->elo, k->olo);   /* gap below: (C - H) - (c - h) */
        mpz_sub(k->ohi, k->ohi, k->ehi);   /* gap above: (c + h) - (C + H) */
        tiny = xu_scale_tiny(k->S);
        ulo = side_units(k, k->olo, k->S, tiny, &bad_lo);
        uhi = side_units(k, k->ohi, k->S, tiny, &bad_hi);
        v->applied[f_cont]++;
        if (mpz_sgn(k->olo) < 0 || mpz_sgn(k->ohi) < 0) {
            snprintf(why, sizeof why, "axis %d%s: not contained (excess lo %.3g, hi %.3g)",
                     i, dz, ulo, uhi);
            v_fail(v, f_cont, why);
        }
        v->applied[f_spec]++;
        if (!within_spec(k, k->olo, k->S) || !within_spec(k, k->ohi, k->S)) {
            snprintf(why, sizeof why, "axis %d%s: beyond 12uS+2^-1065 (excess lo %.3g, hi %.3g)",
                     i, dz, ulo, uhi);
            v_fail(v, f_spec, why);
        }
        v->applied[tiny ? F_TINYABS : F_SANITY]++;
        if (bad_lo || bad_hi) {
            snprintf(why, sizeof why, "axis %d: sanity bound (excess lo %.3g, hi %.3g%s)",
                     i, ulo, uhi, tiny ? ", tiny scale: gap > 2^-1000" : "");
            v_fail(v, tiny ? F_TINYABS : F_SANITY, why);
        }
        if (drop) {
            ex_add(&g->drop, ulo > uhi ? ulo : uhi, tiny,
                   mpz_sgn(k->olo) == 0 && mpz_sgn(k->ohi) == 0);
        } else {
            ex_add(&g->lo, ulo, tiny, mpz_sgn(k->olo) == 0);
            ex_add(&g->hi, uhi, tiny, mpz_sgn(k->ohi) == 0);
            ex_add(&g->main, ulo > uhi ? ulo : uhi, tiny,
                   mpz_sgn(k->olo) == 0 && mpz_sgn(k->ohi) == 0);
        }
        if (!tiny && ulo > *mx) *mx = ulo;
        if (!tiny && uhi > *mx) *mx = uhi;
        if (corners) tc_corners(k, v, a, use, out, i, drop);
    }
    return v->failed;
}

/* ---------------------------------------------------------------------- */
/* Conversions: oracle and checks                                          */
/* ---------------------------------------------------------------------- */

static int conv_ok(double x) { return fabs(x) <= ldexp(1.0, CONV_EMAX); }

static int box_has_nan(const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        if (xu_is_nan(b->lo[j]) || xu_is_nan(b->hi[j])) return 1;
    return 0;
}

static cbx_status b2c_expected(const cbx_box *in, int *oob)
{
    int j;
    *oob = 0;
    if (box_has_nan(in)) return CBX_EINVAL;
    if (xu_is_empty(in)) return CBX_EMPTY;
    for (j = 0; j < 3; j++)
        if (!conv_ok(in->lo[j]) || !conv_ok(in->hi[j])) *oob |= 1 << j;
    return *oob ? CBX_ERANGE : CBX_OK;
}

static cbx_status c2b_expected(const cbx_cbox *in, int *oob)
{
    int j;
    *oob = 0;
    if (xu_cbox_has_nan(NULL, in)) return CBX_EINVAL;
    if (xu_cbox_is_empty(in)) return CBX_EMPTY;
    for (j = 0; j < 3; j++)
        if (!conv_ok(in->c[j]) || !conv_ok(in->h[j])) *oob |= 1 << j;
    return *oob ? CBX_ERANGE : CBX_OK;
}

/* k->S = max(|lo|, |hi|) scaled */
static void abs_max_scaled(ctx *k, double p, double q)
{
    double m = fabs(p) > fabs(q) ? fabs(p) : fabs(q);
    xu_scaled_d(&k->x, k->S, m);
}

static int b2c_run(ctx *k, group *g, const cbx_box *in, cbx_cbox *out,
                   verdict *v, double *mx)
{
    cbx_box in0 = *in;
    int i, oob;
    char why[160];

    for (i = 0; i < 3; i++) out->c[i] = out->h[i] = NAN;
    v_init(v);
    v->got = cbx_box_to_cbox(in, out);
    v->expected = b2c_expected(in, &oob);
    *mx = 0;
    v->applied[F_INPUT]++;
    if (memcmp(&in0, in, sizeof in0)) v_fail(v, F_INPUT, "the call modified its input");
    check_status(v);
    check_unset_c(v, out);
    if (v->expected == CBX_EINVAL || v->expected == CBX_EMPTY) {
        check_cspecial(v, out, v->expected == CBX_EINVAL);
        return v->failed;
    }
    for (i = 0; i < 3; i++) {
        int tiny, bad_lo, bad_hi, bad;
        double ulo, uhi, avg;
        if (oob & (1 << i)) {
            v->applied[F_OOB]++;
            snprintf(why, sizeof why, "axis %d out of domain but not c = 0, h = +inf", i);
            check_cwhole_axis(v, out, i, F_OOB, why);
            continue;
        }
        v->applied[F_FINITE]++;
        if (!isfinite(out->c[i]) || !isfinite(out->h[i])) {
            snprintf(why, sizeof why, "axis %d in domain but out c = %g, h = %g", i,
                     out->c[i], out->h[i]);
            v_fail(v, F_FINITE, why);
            continue;
        }
        cbox_ends(k, out->c[i], out->h[i]);
        xu_scaled_d(&k->x, k->elo, in->lo[i]);
        xu_scaled_d(&k->x, k->ehi, in->hi[i]);
        mpz_sub(k->olo, k->elo, k->olo);   /* lo - (c - h) */
        mpz_sub(k->ohi, k->ohi, k->ehi);   /* (c + h) - hi */
        abs_max_scaled(k, in->lo[i], in->hi[i]);
        tiny = xu_scale_tiny(k->S);
        ulo = side_units(k, k->olo, k->S, tiny, &bad_lo);
        uhi = side_units(k, k->ohi, k->S, tiny, &bad_hi);
        /* the brief's measure: ((c+h) - hi + lo - (c-h)) / 2 */
        mpz_add(k->g, k->olo, k->ohi);
        mpz_tdiv_q_2exp(k->g, k->g, 1);
        avg = side_units(k, k->g, k->S, tiny, &bad);
        v->applied[F_CONTAIN]++;
        if (mpz_sgn(k->olo) < 0 || mpz_sgn(k->ohi) < 0) {
            snprintf(why, sizeof why, "axis %d: [c-h, c+h] does not contain [lo, hi] "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            v_fail(v, F_CONTAIN, why);
        }
        v->applied[F_CSPEC]++;
        if (!within_conv(k, k->olo, in->lo[i], in->hi[i])
            || !within_conv(k, k->ohi, in->lo[i], in->hi[i])) {
            snprintf(why, sizeof why, "axis %d: beyond the proven conv_gap "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            v_fail(v, F_CSPEC, why);
        }
        v->applied[tiny ? F_TINYABS : F_SANITY]++;
        if (bad) {
            snprintf(why, sizeof why, "axis %d: sanity bound (mean excess %.3g%s)", i,
                     avg, tiny ? ", tiny scale: gap > 2^-1000" : "");
            v_fail(v, tiny ? F_TINYABS : F_SANITY, why);
        }
        ex_add(&g->lo, ulo, tiny, mpz_sgn(k->olo) == 0);
        ex_add(&g->hi, uhi, tiny, mpz_sgn(k->ohi) == 0);
        ex_add(&g->main, avg, tiny, mpz_sgn(k->g) == 0);
        if (!tiny && avg > *mx) *mx = avg;
    }
    return v->failed;
}

static int c2b_run(ctx *k, group *g, const cbx_cbox *in, cbx_box *out,
                   verdict *v, double *mx)
{
    cbx_cbox in0 = *in;
    int i, oob;
    char why[160];

    for (i = 0; i < 3; i++) out->lo[i] = out->hi[i] = NAN;
    v_init(v);
    v->got = cbx_cbox_to_box(in, out);
    v->expected = c2b_expected(in, &oob);
    *mx = 0;
    v->applied[F_INPUT]++;
    if (memcmp(&in0, in, sizeof in0)) v_fail(v, F_INPUT, "the call modified its input");
    check_status(v);
    v->applied[F_UNSET]++;
    for (i = 0; i < 3; i++)
        if (xu_is_nan(out->lo[i]) || xu_is_nan(out->hi[i])) {
            v_fail(v, F_UNSET, "NaN left in out (field not written)");
            break;
        }
    if (v->expected == CBX_EINVAL || v->expected == CBX_EMPTY) {
        int whole = v->expected == CBX_EINVAL, ok = 1;
        v->applied[F_SPECIAL]++;
        for (i = 0; i < 3; i++)
            ok &= whole ? is_ninf(out->lo[i]) && is_pinf(out->hi[i])
                        : is_pinf(out->lo[i]) && is_ninf(out->hi[i]);
        if (!ok)
            v_fail(v, F_SPECIAL, whole ? "EINVAL: out is not [-inf,+inf]^3"
                                       : "EMPTY: out is not lo = +inf, hi = -inf");
        return v->failed;
    }
    for (i = 0; i < 3; i++) {
        int tiny, bad_lo, bad_hi;
        double ulo, uhi;
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
        cbox_ends(k, in->c[i], in->h[i]);
        xu_scaled_d(&k->x, k->elo, out->lo[i]);
        xu_scaled_d(&k->x, k->ehi, out->hi[i]);
        mpz_sub(k->olo, k->olo, k->elo);   /* (c - h) - lo */
        mpz_sub(k->ohi, k->ehi, k->ohi);   /* hi - (c + h) */
        /* S = |c| + h */
        xu_scaled_d(&k->x, k->S, fabs(in->c[i]));
        xu_scaled_d(&k->x, k->g, in->h[i]);
        mpz_add(k->S, k->S, k->g);
        tiny = xu_scale_tiny(k->S);
        ulo = side_units(k, k->olo, k->S, tiny, &bad_lo);
        uhi = side_units(k, k->ohi, k->S, tiny, &bad_hi);
        v->applied[F_CONTAIN]++;
        if (mpz_sgn(k->olo) < 0 || mpz_sgn(k->ohi) < 0) {
            snprintf(why, sizeof why, "axis %d: [lo, hi] does not contain [c-h, c+h] "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            v_fail(v, F_CONTAIN, why);
        }
        v->applied[F_CSPEC]++;
        if (!within_conv(k, k->olo, in->c[i], in->h[i])
            || !within_conv(k, k->ohi, in->c[i], in->h[i])) {
            snprintf(why, sizeof why, "axis %d: beyond the proven conv_gap "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            v_fail(v, F_CSPEC, why);
        }
        v->applied[tiny ? F_TINYABS : F_SANITY]++;
        if (bad_lo || bad_hi) {
            snprintf(why, sizeof why, "axis %d: sanity bound (excess lo %.3g, hi %.3g%s)",
                     i, ulo, uhi, tiny ? ", tiny scale: gap > 2^-1000" : "");
            v_fail(v, tiny ? F_TINYABS : F_SANITY, why);
        }
        ex_add(&g->lo, ulo, tiny, mpz_sgn(k->olo) == 0);
        ex_add(&g->hi, uhi, tiny, mpz_sgn(k->ohi) == 0);
        ex_add(&g->main, ulo > uhi ? ulo : uhi, tiny,
               mpz_sgn(k->olo) == 0 && mpz_sgn(k->ohi) == 0);
        if (!tiny && ulo > *mx) *mx = ulo;
        if (!tiny && uhi > *mx) *mx = uhi;
    }
    return v->failed;
}

/* box -> cbox -> box must contain the box (b2c OK assumed by the caller). */
static void roundtrip_box(ctx *k, group *g, const cbx_box *in,
                          const cbx_cbox *cb, verdict *v)
{
    cbx_box back;
    int j;
    cbx_status s = cbx_cbox_to_box(cb, &back);
    if (s != CBX_OK) { g->rt_skipped++; return; }
    g->rt_n++;
    v->applied[F_ROUND]++;
    for (j = 0; j < 3; j++) {
        if (!(back.lo[j] <= in->lo[j] && in->hi[j] <= back.hi[j])) {
            v_fail(v, F_ROUND, "box -> cbox -> box does not contain the box");
            return;
        }
        /* widening in units of u max(|lo|,|hi|) + eta */
        abs_max_scaled(k, in->lo[j], in->hi[j]);
        if (!xu_scale_tiny(k->S)) {
            double u;
            xu_scaled_d(&k->x, k->olo, in->lo[j]);
            xu_scaled_d(&k->x, k->g, back.lo[j]);
            mpz_sub(k->olo, k->olo, k->g);
            u = xu_units(&k->x, k->olo, k->S);
            if (u > g->rt_max) g->rt_max = u;
            xu_scaled_d(&k->x, k->ohi, in->hi[j]);
            xu_scaled_d(&k->x, k->g, back.hi[j]);
            mpz_sub(k->ohi, k->g, k->ohi);
            u = xu_units(&k->x, k->ohi, k->S);
            if (u > g->rt_max) g->rt_max = u;
        }
    }
}

/* cbox -> box -> cbox must contain the cbox (exactly). */
static void roundtrip_cbox(ctx *k, group *g, const cbx_cbox *in,
                           const cbx_box *bx, verdict *v)
{
    cbx_cbox back;
    int j;
    cbx_status s = cbx_box_to_cbox(bx, &back);
    if (s != CBX_OK) { g->rt_skipped++; return; }
    g->rt_n++;
    v->applied[F_ROUND]++;
    for (j = 0; j < 3; j++) {
        cbox_ends(k, in->c[j], in->h[j]);
        mpz_set(k->elo, k->olo);
        mpz_set(k->ehi, k->ohi);
        cbox_ends(k, back.c[j], back.h[j]);
        if (mpz_cmp(k->olo, k->elo) > 0 || mpz_cmp(k->ohi, k->ehi) < 0) {
            v_fail(v, F_ROUND, "cbox -> box -> cbox does not contain the cbox");
            return;
        }
        xu_scaled_d(&k->x, k->S, fabs(in->c[j]));
        xu_scaled_d(&k->x, k->g, in->h[j]);
        mpz_add(k->S, k->S, k->g);
        if (!xu_scale_tiny(k->S)) {
            double u;
            mpz_sub(k->g, k->elo, k->olo);
            u = xu_units(&k->x, k->g, k->S);
            if (u > g->rt_max) g->rt_max = u;
            mpz_sub(k->g, k->ohi, k->ehi);
            u = xu_units(&k->x, k->g, k->S);
            if (u > g->rt_max) g->rt_max = u;
        }
    }
}

/* ---------------------------------------------------------------------- */
/* Printing reproducers (hex)                                             */
/* ---------------------------------------------------------------------- */

static void print_cbox(const char *label, const cbx_cbox *b)
{
    int j;
    for (j = 0; j < 3; j++)
        printf("  %s[%d]: c = %a, h = %a   (%.17g, %.17g)\n", label, j, b->c[j],
               b->h[j], b->c[j], b->h[j]);
}

static void print_affine(const cbx_affine *a)
{
    int i;
    for (i = 0; i < 3; i++)
        printf("  m[%d] = {%a, %a, %a | %a}\n", i, a->m[i][0], a->m[i][1],
               a->m[i][2], a->m[i][3]);
}

static int log_head(const char *what, long id, const verdict *v)
{
    if (fail_logs++ >= MAX_FAIL_LOGS) return 0;
    printf("FAIL %s %ld: %s (status %s, expected %s)\n", what, id, v->why,
           cbx_status_name(v->got), cbx_status_name(v->expected));
    return 1;
}

/* ---------------------------------------------------------------------- */
/* Hard cases                                                             */
/* ---------------------------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
/* cbox per axis: (c0, h0, c1, h1, c2, h2) */
#define CB(c0, h0, c1, h1, c2, h2) { { c0, c1, c2 }, { h0, h1, h2 } }
/* box per axis: (lo0, hi0, lo1, hi1, lo2, hi2) */
#define BOX(l0, h0, l1, h1, l2, h2) { { l0, l1, l2 }, { h0, h1, h2 } }
#define ID3 MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0))

/* 2^509 (1 + 2^-52), 2^1018 (1 + 2^-52), 2^CONV_EMAX (1 + 2^-52) */
#define P509U 0x1.0000000000001p509
#define P1018U 0x1.0000000000001p1018
#define P1019U CLIMU

typedef struct tc_case {
    const char *name;
    cbx_affine a;
    cbx_cbox in;
    cbx_status expect;
    int oob;            /* the lost (W) axes                             */
    const char *kinds;  /* per axis A, D or W ("---": EINVAL / EMPTY)     */
} tc_case;

static const tc_case tc_hard[] = {
    /* identity on the cbox (0, 1)^3 = [-1, 1]^3 */
    { "identity, c = 0, h = 1", ID3, CB(0, 1, 0, 1, 0, 1), CBX_OK, 0, "AAA" },
    /* identity on a point cbox (h = 0): the image is a point */
    { "identity, point cbox (h = 0)", ID3, CB(1.5, 0, -2, 0, 3, 0), CBX_OK, 0, "AAA" },
    /* h = -0.0 is not < 0: a point, not empty; -0.0 entries and t */
    { "signed permutation with -0.0, h = -0.0",
      MAT(ROW(-0.0, 1, -0.0, -0.0), ROW(-0.0, -0.0, -1, 0), ROW(1, -0.0, 0, -0.0)),
      CB(-0.0, -0.0, 2, 0.5, -0.0, 0.0), CBX_OK, 0, "AAA" },
    /* all zeros, every sign: image exactly {0}, S = 0 */
    { "all-zero map, signed zeros",
      MAT(ROW(-0.0, -0.0, -0.0, -0.0), ROW(0.0, -0.0, 0.0, 0.0), ROW(-0.0, 0.0, -0.0, 0.0)),
      CB(-0.0, 0.0, 3, 1, -5, -0.0), CBX_OK, 0, "AAA" },
    /* rank deficient: row 1 is zero (image of row 1 is the point t = 5) */
    { "zero row (rank 2) with t = 5",
      MAT(ROW(1, 2, 3, 0), ROW(0, 0, 0, 5), ROW(-1, 0.5, 2, -1)),
      CB(0.1, 0.2, -0.3, 0.4, 0.5, 0.6), CBX_OK, 0, "AAA" },
    /* rank 1: every row a multiple of (1, 2, 3) */
    { "rank 1 map",
      MAT(ROW(1, 2, 3, 0), ROW(-2, -4, -6, 1), ROW(0.1, 0.2, 0.30000000000000004, 2)),
      CB(1e3, 1e-3, -7, 0.25, 0.1, 0.1), CBX_OK, 0, "AAA" },
    /* tiny-angle rotations: cos rounds to 1.0, sin to the angle */
    { "rotation 1e-8 about z",
      MAT(ROW(1.0, -1e-8, 0, 0), ROW(1e-8, 1.0, 0, 0), ROW(0, 0, 1, 0)),
      CB(0, 1e6, 0, 1, 0, 0), CBX_OK, 0, "AAA" },
    { "rotation 1e-15 about x, translated",
      MAT(ROW(1, 0, 0, 5), ROW(0, 1.0, -1e-15, -1e15), ROW(0, 1e-15, 1.0, 0.25)),
      CB(0, 1, 1e15, 0, 0, 1e15), CBX_OK, 0, "AAA" },
    { "rotation 1e-300 about y",
      MAT(ROW(1.0, 0, 1e-300, 0), ROW(0, 1, 0, 0), ROW(-1e-300, 0, 1.0, 0)),
      CB(0, 1e300, 1.5, 0.5, 0, 1e-300), CBX_OK, 0, "AAA" },
    /* a huge translation with a tiny box */
    { "translation 1e15, h = 1e-10",
      MAT(ROW(1, 0, 0, 1e15), ROW(0, 1, 0, -1e15), ROW(0.5, 0.5, 0, 1e15)),
      CB(0.3, 1e-10, -0.7, 1e-10, 0, 1e-10), CBX_OK, 0, "AAA" },
    /* 1e-200 next to 1e200: 1e200 needs class k >= 704, so |c|, |h| <= 2^314 */
    { "1e-200 next to 1e200",
      MAT(ROW(1e200, 1e-200, 1, 0), ROW(-1e-200, 1e200, 0, 1e-200), ROW(1, 1, 1, 0)),
      CB(1e-200, 1e-200, 3e-201, 2e-200, 1e200, 1e199), CBX_OK, 0, "AAA" },
    /* subnormal entries, centres and half-diagonals */
    { "subnormals everywhere",
      MAT(ROW(0x1p-1074, -0x1p-1074, 0x1p-1060, 0x1p-1074),
          ROW(-0x1p-1074, 0x1.8p-1070, 0, -0x1p-1074), ROW(1, -1, 0.5, 0)),
      CB(0x1p-1074, 0x1p-1074, -0x1p-1073, 0x1p-1074, 0x1p-1022, 0x1p-1030), CBX_OK, 0, "AAA" },
    /* unit entries, subnormal cbox: c +- h exact, centre of 0.5 * 2^-1074 */
    { "subnormal cbox, entry 0.5",
      MAT(ROW(0.5, 0, 0, 0), ROW(0, 0.5, 0, 0x1p-1074), ROW(0.5, 0.5, 0.5, 0)),
      CB(0x1p-1074, 0, 0x1p-1074, 0x1p-1074, -0x1p-1074, 0x1p-1074), CBX_OK, 0, "AAA" },
    /* class 509 at its corner: m = 2^509, c = h = 2^509 */
    { "m = 2^509, c = h = 2^509",
      MAT(ROW(0x1p509, 0, 0, 0), ROW(-0x1p509, 0x1p509, 0, 0),
          ROW(0x1p509, 0x1p509, 0x1p509, 0x1p1018)),
      CB(0x1p509, 0x1p509, -0x1p509, 0x1p509, 0, 0x1p509), CBX_OK, 0, "AAA" },
    /* class 1018: m = 2^1018 with |c|, h <= 1; t = -2^1018 */
    { "m = 2^1018, |c|, h <= 1, t = -2^1018",
      MAT(ROW(0x1p1018, 0, 0, 0), ROW(0, -0x1p1018, 0, 0x1p1018),
          ROW(0x1p1018, 0, 0, -0x1p1018)),
      CB(1, 0, -0.5, 0.5, 0, 1), CBX_OK, 0, "AAA" },
    /* class 0: m = 1 with c, h = 2^1018; every term 2^1018 */
    { "m = 1, c = h = 2^1018",
      MAT(ROW(1, 1, 1, 0x1p1018), ROW(1, -1, 0, 0), ROW(0, 0, -1, -0x1p1018)),
      CB(0x1p1018, 0x1p1018, -0x1p1018, 0x1p1018, 0, 0x1p1018), CBX_OK, 0, "AAA" },
    /* near cancellation: point cbox and t = -fl(m.c) */
    { "near cancellation t = -fl(m.c), h = 0",
      MAT(ROW(0.1, 0.2, 0.3, -0.6000000000000001),
          ROW(1e-3, 1.1, -0.7, -0.024499999999999966), ROW(1, 1, 1, -3)),
      CB(1, 0, 1, 0, 1, 0), CBX_OK, 0, "AAA" },
    /* --- outside the domain ------------------------------------------ */
    /* m = 2^509 with h one ulp beyond 2^509: neither class 509 nor 512 */
    { "m = 2^509, h = 2^509 + ulp (row 2 out)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0x1p509, 0, 0, 0)),
      CB(0, P509U, 0, 1, 0, 1), CBX_ERANGE, 4, "AAW" },
    /* m = 2^509 with c one ulp beyond 2^509 */
    { "m = 2^509, c = 2^509 + ulp (rows 0, 2 out)",
      MAT(ROW(0x1p509, 0, 0, 0), ROW(0, 1, 0, 0), ROW(-0x1p509, 0, 0, 0)),
      CB(P509U, 0, 0, 1, 0, 1), CBX_ERANGE, 5, "WAW" },
    /* t one ulp beyond 2^1018 */
    { "t = 2^1018 + ulp (row 1 out)",
      MAT(ROW(1, 0, 0, 0x1p1018), ROW(0, 1, 0, -P1018U), ROW(0, 0, 1, 0)),
      CB(0, 1, 0, 1, 0, 1), CBX_ERANGE, 2, "AWA" },
    /* m one ulp beyond 2^1018 even with c = h = 0 */
    { "m = 2^1018 + ulp, c = h = 0 (row 0 out)",
      MAT(ROW(P1018U, 0, 0, 0), ROW(0x1p1018, 0, 0, 0), ROW(0, 0, 0, 0)),
      CB(0, 0, 1, 1, 1, 1), CBX_ERANGE, 1, "WAA" },
    /* h one ulp beyond 2^1018: outside every class; rows 0 and 1 have a
     * zero coefficient there and drop the column (D), row 2 is lost */
    { "h2 = 2^1018 + ulp (row 2 lost, rows 0, 1 drop)", ID3,
      CB(0, 1, 0, 1, 0, P1018U), CBX_ERANGE, 4, "DDW" },
    /* h = +inf: not empty; only the row with m_11 != 0 is lost */
    { "h1 = +inf (row 1 lost, rows 0, 2 drop)", ID3, CB(0, 1, 0, INF, 0, 1),
      CBX_ERANGE, 2, "DWD" },
    /* c = -inf: only the row with m_00 != 0 is lost */
    { "c0 = -inf (row 0 lost, rows 1, 2 drop)", ID3, CB(-INF, 0, 0, 1, 0, 1),
      CBX_ERANGE, 1, "WDD" },
    /* an infinite translation: only its row */
    { "t = +inf (row 2 out)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, INF)),
      CB(0, 1, 0, 1, 0, 1), CBX_ERANGE, 4, "AAW" },
    /* --- empty and NaN ----------------------------------------------- */
    { "h = -2^-1074 (empty)", ID3, CB(0, 1, 0, -0x1p-1074, 0, 1), CBX_EMPTY, 0, "---" },
    { "h = -inf (empty)", ID3, CB(0, 1, 0, 1, 0, -INF), CBX_EMPTY, 0, "---" },
    /* empty wins over out-of-domain */
    { "h < 0 and t = +inf (empty)",
      MAT(ROW(1, 0, 0, INF), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      CB(0, -1, 0, 1, 0, 1), CBX_EMPTY, 0, "---" },
    { "NaN in h", ID3, CB(0, 1, 0, NAN, 0, 1), CBX_EINVAL, 0, "---" },
    { "NaN in t", MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, NAN), ROW(0, 0, 1, 0)),
      CB(0, 1, 0, 1, 0, 1), CBX_EINVAL, 0, "---" },
    /* NaN wins over empty */
    { "NaN in c and h < 0", ID3, CB(NAN, 1, 0, -1, 0, 1), CBX_EINVAL, 0, "---" },
};
#define N_TC_HARD ((int)(sizeof tc_hard / sizeof tc_hard[0]))

/* Zero-coefficient columns are dropped (0 * x = 0 for every real x): a
 * row that is not full but whose dropped row is full (kind D) is computed
 * by the kernel on the dropped row; a row still not full after dropping is
 * lost (W: c = 0, h = +inf, CBX_ERANGE).  -0.0 counts as zero; a
 * subnormal coefficient does not.  NaN and h < 0 in a dropped column still
 * give EINVAL / EMPTY. */
static const tc_case tc_drop[] = {
    /* every row has m_0 == 0: column 0 (c = -inf, h = +inf) is dropped */
    { "column 0 zero everywhere, c0 = -inf, h0 = +inf",
      MAT(ROW(0, 1, 2, 3), ROW(0, -1, 0.5, 0), ROW(0, 0.25, -4, -1)),
      CB(-INF, INF, 1, 0.5, -2, 1), CBX_OK, 0, "DDD" },
    /* -0.0 coefficients against h = +inf and c = +inf */
    { "-0.0 coefficients against c1 = +inf, h2 = +inf",
      MAT(ROW(1, -0.0, -0.0, 0.5), ROW(-2, -0.0, -0.0, -0.0), ROW(3, -0.0, -0.0, 1e300)),
      CB(0.75, 0.25, INF, 0, 1, INF), CBX_OK, 0, "DDD" },
    /* +0 and -0 mixed in one column, c = h = +inf */
    { "+0 / -0 in column 2, c2 = h2 = +inf",
      MAT(ROW(1, 2, 0.0, 0), ROW(-1, 0.5, -0.0, 7), ROW(0.125, -8, 0.0, -7)),
      CB(3, 1, -1, 2, INF, INF), CBX_OK, 0, "DDD" },
    /* huge (out-of-domain) but finite entries in a zero column */
    { "zero column, c0 = DBL_MAX, h0 = 2^1023",
      MAT(ROW(0, 1, 0, 0), ROW(-0.0, 0, 1, 0), ROW(0, 1, 1, 1)),
      CB(DBL_MAX, 0x1p1023, 2, 1, -3, 0.5), CBX_OK, 0, "DDD" },
    { "zero column, c1 = -(2^1018 + ulp), h1 = 2^1018 + ulp",
      MAT(ROW(1, 0, 0, 0), ROW(0, 0, 1, 0), ROW(1, -0.0, 1, 0)),
      CB(1, 1, -P1018U, P1018U, 1, 1), CBX_OK, 0, "DDD" },
    /* an all-zero map: every column dropped, the image is the point t */
    { "all-zero map, c = +-inf / DBL_MAX, h = +inf (points t)",
      MAT(ROW(0, -0.0, 0, 5), ROW(-0.0, 0, -0.0, -0x1p1018), ROW(0, 0, 0, -0.0)),
      CB(INF, INF, -INF, INF, DBL_MAX, INF), CBX_OK, 0, "DDD" },
    /* two zero columns in every row, one against c = +inf, one against
     * h = +inf */
    { "two zero columns (c0 = inf, h1 = inf) in every row",
      MAT(ROW(0, 0, 1, 0), ROW(0, -0.0, 2, 1), ROW(-0.0, 0, 3, -1)),
      CB(INF, 0, 0, INF, 0.5, 0.5), CBX_OK, 0, "DDD" },
    /* the dropped row at a class corner: m = 2^509, c = h = 2^509, and
     * t = 2^1018; row 1 has m_0 != 0 against c0 = inf: lost */
    { "drop, rest at m = 2^509, c = h = 2^509 (row 1 lost)",
      MAT(ROW(0, 0x1p509, 0, 0x1p1018), ROW(0x1p509, 0, 0, 0), ROW(0, 0, 0x1p509, 0)),
      CB(INF, INF, 0x1p509, 0x1p509, -0x1p509, 0x1p509), CBX_ERANGE, 2, "DWD" },
    /* mixes: one zero column dropped, but a nonzero column infinite */
    { "zero column 0 dropped, nonzero column 2 with h2 = +inf (lost)",
      MAT(ROW(0, 1, 1, 0), ROW(0, 1, 0, 0), ROW(-0.0, 0, 2, 0)),
      CB(INF, 1, 0, 1, 0, INF), CBX_ERANGE, 5, "WDW" },
    { "c0 = -inf: dropped where m_0 = 0, lost where not",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 1, 0), ROW(1, 1, 0, 0)),
      CB(-INF, 0, 2, 1, 3, 0), CBX_ERANGE, 5, "WDW" },
    { "each row drops a different column, c0 = +inf",
      MAT(ROW(0, 1, 1, 0), ROW(1, 0, 1, 0), ROW(1, 1, 0, 0)),
      CB(INF, 0, 1, 1, 1, 1), CBX_ERANGE, 6, "DWW" },
    /* dropped, but the rest of the row is outside the domain */
    { "drop, but t = +inf (lost)",
      MAT(ROW(0, 1, 0, INF), ROW(0, 1, 0, 0), ROW(0, 0, 1, -INF)),
      CB(INF, 0, 1, 1, 1, 1), CBX_ERANGE, 5, "WDW" },
    { "drop, but t = 2^1018 + ulp (lost)",
      MAT(ROW(0, 1, 0, P1018U), ROW(0, 1, 0, 0x1p1018), ROW(0, 0, 1, 0)),
      CB(-INF, INF, 1, 1, 1, 1), CBX_ERANGE, 1, "WDD" },
    { "drop, but m = 2^509 with c = 2^509 + ulp (lost)",
      MAT(ROW(0, 0x1p509, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0x1p509, 0, 0)),
      CB(INF, 0, P509U, 0, 1, 1), CBX_ERANGE, 5, "WDW" },
    { "drop, but an infinite coefficient (lost)",
      MAT(ROW(0, INF, 0, 0), ROW(0, 1, 0, 0), ROW(0, -INF, 0, 0)),
      CB(INF, INF, 1, 0, 1, 1), CBX_ERANGE, 5, "WDW" },
    /* a subnormal coefficient is not zero: not dropped */
    { "m = 2^-1074 against c0 = +inf (not dropped: lost)",
      MAT(ROW(0x1p-1074, 1, 0, 0), ROW(-0x1p-1074, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(INF, 0, 1, 1, 1, 1), CBX_ERANGE, 3, "WWD" },
    /* near cancellation: t = -fl(m.c), h = 0; first with every column
     * finite (full rows, A: the zero columns change nothing), then with
     * column 2 infinite (dropped in row 0, lost in rows 1, 2) */
    { "full rows with -0.0, near cancellation (A)",
      MAT(ROW(0.1, 0.2, -0.0, -0.30000000000000004), ROW(1e-3, 0, 1.1, -1.1009999999999998),
          ROW(0, 1, 1, -2)),
      CB(1, 0, 1, 0, 1, 0), CBX_OK, 0, "AAA" },
    { "drop infinite column, near cancellation, h = 0",
      MAT(ROW(0.1, 0.2, -0.0, -0.30000000000000004), ROW(1e-3, 0, 1.1, -1.1009999999999998),
          ROW(0, 1, 1, -2)),
      CB(1, 0, 1, 0, INF, INF), CBX_ERANGE, 6, "DWW" },
    /* subnormal scale in the dropped row */
    { "drop, subnormal remaining row",
      MAT(ROW(0x1p-1074, 0, -0x1p-1074, 0x1p-1074), ROW(0, 0, 0x1p-1060, 0), ROW(0, 0, 0, 0)),
      CB(0x1p-1074, 0x1p-1074, -INF, INF, 0x1p-1022, 0x1p-1030), CBX_OK, 0, "DDD" },
    /* h = -0.0 in a dropped column is not negative */
    { "h0 = -0.0 and c0 = -inf in a zero column",
      MAT(ROW(0, 1, 0, 0), ROW(-0.0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(-INF, -0.0, 1, 1, 1, 1), CBX_OK, 0, "DDD" },
    /* NaN / h < 0 in a dropped column still decide the status */
    { "NaN c in a zero column (EINVAL)",
      MAT(ROW(0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(NAN, 0, 1, 1, 1, 1), CBX_EINVAL, 0, "---" },
    { "NaN h in a zero column (EINVAL)",
      MAT(ROW(0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(INF, NAN, 1, 1, 1, 1), CBX_EINVAL, 0, "---" },
    { "h = -1 in a zero column (EMPTY)",
      MAT(ROW(0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(0, -1, 1, 1, 1, 1), CBX_EMPTY, 0, "---" },
    { "h = -inf, c = +inf in a zero column (EMPTY)",
      MAT(ROW(-0.0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(INF, -INF, 1, 1, 1, 1), CBX_EMPTY, 0, "---" },
};
#define N_TC_DROP ((int)(sizeof tc_drop / sizeof tc_drop[0]))

typedef struct b2c_case {
    const char *name;
    cbx_box in;
    cbx_status expect;
    int oob;
} b2c_case;

static const b2c_case b2c_hard[] = {
    /* representable centre and half: exact conversion is possible */
    { "[0,1], [-1,1], [2,6]", BOX(0, 1, -1, 1, 2, 6), CBX_OK, 0 },
    /* point boxes and signed zeros ([+0, -0] is not empty) */
    { "points, [-0,+0], [+0,-0]", BOX(3, 3, -0.0, 0.0, 0.0, -0.0), CBX_OK, 0 },
    /* one ulp wide: the centre 1 + 2^-53 is not representable */
    { "one ulp wide at 1 and at -2^100",
      BOX(1, 0x1.0000000000001p0, -0x1.0000000000001p100, -0x1p100, 0.1, 0.1),
      CBX_OK, 0 },
    /* subnormals: centre 1.5 * 2^-1074 not representable */
    { "subnormal ends", BOX(0x1p-1074, 0x1p-1073, -0x1p-1074, 0x1p-1074, -0x1p-1022,
                           0x1p-1074), CBX_OK, 0 },
    /* huge with a tiny width; translated unit box */
    { "1e15 with width 0.125, tiny at 1e15",
      BOX(1e15, 1e15 + 0.125, -1e15, -1e15 + 1e-10, 1e15 - 1, 1e15 + 1), CBX_OK, 0 },
    /* 1e-300 next to 1e300 */
    { "[-1e300, 1e-300], [1e-300, 1e300]",
      BOX(-1e300, 1e-300, 1e-300, 1e300, -1e-300, 1e-300), CBX_OK, 0 },
    /* the domain limit 2^CONV_EMAX exactly, full range */
    { "[-2^CONV_EMAX, 2^CONV_EMAX] and [2^CONV_EMAX, 2^CONV_EMAX]",
      BOX(-CLIM, CLIM, CLIM, CLIM, -CLIM, -CLIM), CBX_OK, 0 },
    { "near the limit, one ulp wide",
      BOX((CLIM * 0x1.fffffffffffffp-1), CLIM, -CLIM, -(CLIM * 0x1.fffffffffffffp-1), 0, CLIM),
      CBX_OK, 0 },
    /* one ulp beyond 2^CONV_EMAX */
    { "hi = 2^CONV_EMAX + ulp (axis 1 out)", BOX(0, 1, 0, P1019U, 0, 1), CBX_ERANGE, 2 },
    { "lo = -2^CONV_EMAX - ulp (axis 0 out)", BOX(-P1019U, 0, 0, 1, 0, 1), CBX_ERANGE, 1 },
    /* 2^1020, DBL_MAX, 1e308 */
    { "2^(CONV_EMAX+1), DBL_MAX, 1e308 (all out)",
      BOX((2 * CLIM), (2 * CLIM), -DBL_MAX, DBL_MAX, 1e308, 1e308), CBX_ERANGE, 7 },
    /* infinite ends: a half-line or the whole line is not empty, but out */
    { "[-inf, inf], [-inf, 0] (axes 0, 2 out)",
      BOX(-INF, INF, 0, 1, -INF, 0), CBX_ERANGE, 5 },
    { "[2, +inf] (axis 1 out)", BOX(0, 1, 2, INF, 0, 1), CBX_ERANGE, 2 },
    /* lo = +inf or hi = -inf: no real point, empty even when lo <= hi */
    { "[+inf, +inf] (no real point: empty)", BOX(-INF, INF, 0, 1, INF, INF), CBX_EMPTY, 0 },
    { "[-inf, -inf] (no real point: empty)", BOX(0, 1, -INF, -INF, 0, 1), CBX_EMPTY, 0 },
    /* empty */
    { "lo one ulp above hi (empty)", BOX(0, 1, 0x1.0000000000001p0, 1, 0, 1), CBX_EMPTY, 0 },
    { "[+inf, -inf] (empty)", BOX(0, 1, 0, 1, INF, -INF), CBX_EMPTY, 0 },
    { "empty and out of domain (empty)", BOX(1, 0, -INF, INF, 0, 1), CBX_EMPTY, 0 },
    /* NaN */
    { "NaN lo", BOX(NAN, 1, 0, 1, 0, 1), CBX_EINVAL, 0 },
    { "NaN hi and empty axis", BOX(1, 0, 0, NAN, 0, 1), CBX_EINVAL, 0 },
};
#define N_B2C_HARD ((int)(sizeof b2c_hard / sizeof b2c_hard[0]))

typedef struct c2b_case {
    const char *name;
    cbx_cbox in;
    cbx_status expect;
    int oob;
} c2b_case;

static const c2b_case c2b_hard[] = {
    /* exact: (0,1) -> [-1,1], (0.5,0.5) -> [0,1] */
    { "(0,1), (0.5,0.5), (3,4)", CB(0, 1, 0.5, 0.5, 3, 4), CBX_OK, 0 },
    /* point cboxes, h = -0.0 is not empty, c = -0.0 */
    { "h = 0, h = -0.0, c = -0.0", CB(7, 0, -3, -0.0, -0.0, 2), CBX_OK, 0 },
    /* 1 + 2^-53 is not representable: hi must round up */
    { "(1, 2^-53): c + h between doubles", CB(1, 0x1p-53, -1, 0x1p-53, 0x1p52, 0.5),
      CBX_OK, 0 },
    /* huge centre with tiny half, tiny centre with huge half */
    { "(1e15, 1e-10), (1e-300, 1e300)", CB(1e15, 1e-10, 1e-300, 1e300, -1e15, 1e-10),
      CBX_OK, 0 },
    /* subnormals */
    { "subnormal c and h", CB(0x1p-1074, 0x1p-1074, -0x1.8p-1073, 0x1p-1074, 0x1p-1022,
                              0x1p-1060), CBX_OK, 0 },
    /* the limit 2^CONV_EMAX: c + h = 2^1020 still finite */
    { "c = h = 2^CONV_EMAX, c = -2^CONV_EMAX", CB(CLIM, CLIM, -CLIM, CLIM,
                                        -CLIM, 0), CBX_OK, 0 },
    /* one ulp beyond */
    { "c = 2^CONV_EMAX + ulp (axis 0 out)", CB(P1019U, 0, 0, 1, 0, 1), CBX_ERANGE, 1 },
    { "h = 2^CONV_EMAX + ulp (axis 2 out)", CB(0, 1, 0, 1, 0, P1019U), CBX_ERANGE, 4 },
    { "c = DBL_MAX, h = 1e308 (axes 0, 1 out)", CB(DBL_MAX, 0, 0, 1e308, 0, 1),
      CBX_ERANGE, 3 },
    { "h = +inf, c = -inf (axes 1, 2 out)", CB(0, 1, 0, INF, -INF, 0), CBX_ERANGE, 6 },
    /* empty */
    { "h = -2^-1074 (empty)", CB(0, 1, 0, -0x1p-1074, 0, 1), CBX_EMPTY, 0 },
    { "h = -inf and c = inf (empty)", CB(INF, -INF, 0, 1, 0, 1), CBX_EMPTY, 0 },
    /* NaN */
    { "NaN c", CB(0, 1, NAN, 1, 0, 1), CBX_EINVAL, 0 },
    { "NaN h and h < 0 elsewhere", CB(0, -1, 0, 1, 0, NAN), CBX_EINVAL, 0 },
};
#define N_C2B_HARD ((int)(sizeof c2b_hard / sizeof c2b_hard[0]))

/* ---------------------------------------------------------------------- */
/* Random generation                                                      */
/* ---------------------------------------------------------------------- */

/* half-diagonal in [0, 2^hmax] (with -0.0 and exact zeros) */
static double gen_half(xu_rng *r, int hmin, int hmax)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 8) return 0.0;
    if (p < 12) return -0.0;
    return xu_gen_mag(r, hmin, hmax);
}

/* cbox case inside the domain by construction (per column a class k),
 * "narrow" mode: all products of one size P (cancellation happens). */
static void gen_tc_in_domain(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int narrow = xu_rng_int(r, 0, 1);
    int P = xu_rng_int(r, -1070, 1016);
    int i, j;
    for (j = 0; j < 3; j++) {
        int k = xu_class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        int mlo = -1074, mhi = k, clo = -1074, chi = 1018 - k;
        if (narrow) {
            int lo = P - 1018 + k > -1074 ? P - 1018 + k : -1074;
            int hi = k < P + 1074 ? k : P + 1074;
            int am = xu_rng_int(r, lo, hi);
            mhi = am;
            mlo = am - 4;
            chi = P - am;
            clo = chi - 4;
        }
        for (i = 0; i < 3; i++) a->m[i][j] = xu_gen_signed(r, mlo, mhi);
        b->c[j] = xu_gen_signed(r, clo, chi);
        switch (xu_rng_int(r, 0, 9)) {
        case 0: b->h[j] = fabs(b->c[j]); break;               /* c-h = 0 */
        case 1: b->h[j] = gen_half(r, -1074, chi - 30); break; /* h << c */
        default: b->h[j] = gen_half(r, clo, chi); break;
        }
    }
    for (i = 0; i < 3; i++) {
        int p = xu_rng_int(r, 0, 9);
        if (p < 2) { /* t = -fl(m.c): the centre nearly cancels */
            double s = 0;
            for (j = 0; j < 3; j++) s += a->m[i][j] * b->c[j];
            a->m[i][3] = -s;
        } else if (p < 3) a->m[i][3] = xu_rng_sign(r) * 0.0;
        else if (narrow) a->m[i][3] = xu_gen_signed(r, P - 4, P);
        else a->m[i][3] = xu_gen_signed(r, -1074, 1018);
    }
}

static void perturb_tc(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 2), k;
    switch (xu_rng_int(r, 0, 7)) {
    case 0: a->m[i][j] = xu_gen_signed(r, 200, 1023); break;
    case 1: b->c[j] = xu_gen_signed(r, 900, 1023); break;
    case 2: b->h[j] = xu_gen_mag(r, 900, 1023); break;
    case 3: /* infinities: c = -+inf, h = +inf, entry or t */
        switch (xu_rng_int(r, 0, 2)) {
        case 0: b->c[j] = xu_rng_sign(r) * INF; break;
        case 1: b->h[j] = INF; break;
        default: a->m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF; break;
        }
        break;
    case 4: /* translation beyond 2^1018 */
        k = xu_rng_int(r, 0, 2);
        a->m[i][3] = xu_rng_sign(r) * (k == 0 ? P1018U : k == 1 ? DBL_MAX
                                       : xu_gen_mag(r, 1019, 1023));
        break;
    case 5: /* one ulp outward on an entry */
        a->m[i][j] = nextafter(a->m[i][j], a->m[i][j] < 0 ? -INF : INF);
        break;
    default: /* exact class corner, then c or h one ulp beyond (or not) */
        k = xu_class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        a->m[i][j] = xu_rng_sign(r) * ldexp(1.0, k);
        b->c[j] = xu_rng_sign(r) * ldexp(1.0, 1018 - k);
        b->h[j] = ldexp(1.0, 1018 - k);
        if (xu_rng_int(r, 0, 1)) {
            if (xu_rng_int(r, 0, 1)) b->h[j] = nextafter(b->h[j], INF);
            else b->c[j] = nextafter(b->c[j], b->c[j] < 0 ? -INF : INF);
        }
        break;
    }
}

static void inject_neg_h(xu_rng *r, cbx_cbox *b)
{
    int j = xu_rng_int(r, 0, 2);
    switch (xu_rng_int(r, 0, 4)) {
    case 0: b->h[j] = -0x1p-1074; break;
    case 1: b->h[j] = -1.0; break;
    case 2: b->h[j] = -INF; break;
    case 3: b->h[j] = -DBL_MAX; break;
    default: b->h[j] = b->h[j] > 0 ? -b->h[j] : -0x1p-1022; break;
    }
}

/* ~87% in domain, ~10% pushed out (or to the edge), ~1.5% NaN, ~1.5% empty */
static void gen_tc_case(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int p = xu_rng_int(r, 0, 999);
    gen_tc_in_domain(r, a, b);
    if (p < 100) perturb_tc(r, a, b);
    else if (p < 115) xu_inject_nan(r, a, b->c, b->h);
    else if (p < 130) {
        inject_neg_h(r, b);
        if (p < 118) xu_inject_nan(r, a, b->c, b->h);
    }
}

/* A value no row could use unless its coefficient is zero: +-inf or a
 * magnitude outside every class (|x| > 2^1018); sg: the sign (h >= 0). */
static double gen_unusable(xu_rng *r, double sg)
{
    switch (xu_rng_int(r, 0, 5)) {
    case 0: case 1: return sg * INF;
    case 2: return sg * DBL_MAX;
    case 3: return sg * P1018U;
    case 4: return sg * 0x1p1023;
    default: return sg * xu_gen_mag(r, 1019, 1023);
    }
}

/* Zero-coefficient columns (kind D and its neighbours): an in-domain case,
 * then 1 to 3 columns j get m_ij = +-0.0 in some rows (random sign, so
 * -0.0 is frequent) and c_j and / or h_j a value outside the domain
 * (+-inf, DBL_MAX, 2^1018 + ulp, ...) or left ordinary; sometimes a
 * nonzero column gets such a value too (those rows are lost), t leaves the
 * domain, or a NaN / a negative h lands in a zero column. */
static void gen_tc_drop_case(xu_rng *r, cbx_affine *a, cbx_cbox *b)
{
    int nz = xu_rng_int(r, 0, 9) < 7 ? 1 : xu_rng_int(r, 2, 3);
    int first = xu_rng_int(r, 0, 2), n, i, j, p;
    gen_tc_in_domain(r, a, b);
    for (n = 0; n < nz; n++) {
        int rows = xu_rng_int(r, 1, 7);       /* nonempty set of rows */
        if (xu_rng_int(r, 0, 3) == 0) rows = 7;
        j = (first + n) % 3;
        for (i = 0; i < 3; i++)
            if (rows & (1 << i)) a->m[i][j] = xu_rng_sign(r) * 0.0;
        switch (xu_rng_int(r, 0, 5)) {
        case 0: b->c[j] = gen_unusable(r, xu_rng_sign(r)); break;
        case 1: b->h[j] = gen_unusable(r, 1.0); break;
        case 2: case 3:
            b->c[j] = gen_unusable(r, xu_rng_sign(r));
            b->h[j] = gen_unusable(r, 1.0);
            break;
        case 4: b->h[j] = xu_rng_int(r, 0, 1) ? -0.0 : INF;
                b->c[j] = xu_rng_sign(r) * INF; break;
        default: break;                        /* ordinary values: A rows */
        }
    }
    p = xu_rng_int(r, 0, 99);
    j = (first + nz) % 3;                      /* a column not zeroed above */
    i = xu_rng_int(r, 0, 2);
    if (p < 20 && nz < 3) {                    /* mix: a nonzero column unusable */
        if (xu_rng_int(r, 0, 1)) b->c[j] = gen_unusable(r, xu_rng_sign(r));
        else b->h[j] = gen_unusable(r, 1.0);
    } else if (p < 25) {                       /* t out of the domain */
        a->m[i][3] = xu_rng_int(r, 0, 1) ? xu_rng_sign(r) * INF : xu_rng_sign(r) * P1018U;
    } else if (p < 28) {                       /* a coefficient not quite zero */
        a->m[i][first] = xu_rng_sign(r) * 0x1p-1074;
    } else if (p < 30) {                       /* an infinite coefficient */
        a->m[i][xu_rng_int(r, 0, 2)] = xu_rng_sign(r) * INF;
    } else if (p < 32) {                       /* NaN in a zero column */
        if (xu_rng_int(r, 0, 1)) b->c[first] = xu_rng_sign(r) * NAN;
        else b->h[first] = NAN;
    } else if (p < 34) {                       /* h < 0 in a zero column */
        b->h[first] = xu_rng_int(r, 0, 1) ? -INF : -0x1p-1074;
    }
}

/* an ordered pair of doubles within 2^emax (never empty) */
static void gen_conv_interval(xu_rng *r, double *lo, double *hi, int emax)
{
    int p = xu_rng_int(r, 0, 99);
    double u, v;
    if (p < 10) { *lo = *hi = xu_gen_signed(r, -1074, emax); return; }
    if (p < 15) { *lo = xu_rng_sign(r) * 0.0; *hi = xu_rng_sign(r) * 0.0; return; }
    if (p < 25) { u = xu_gen_mag(r, -1074, emax); *lo = -u; *hi = u; return; }
    if (p < 35) { /* k ulps wide */
        int n = xu_rng_int(r, 1, 3);
        u = xu_gen_signed(r, -1074, emax);
        v = u;
        while (n--) v = nextafter(v, INF);
        if (fabs(v) > ldexp(1.0, emax)) v = u;
        *lo = u; *hi = v; return;
    }
    if (p < 50) { /* similar magnitudes */
        int e = xu_rng_int(r, -1070, emax);
        u = xu_gen_signed(r, e - 3, e);
        v = xu_gen_signed(r, e - 3, e);
    } else {
        u = xu_gen_signed(r, -1074, emax);
        v = xu_gen_signed(r, -1074, emax);
    }
    *lo = u < v ? u : v;
    *hi = u < v ? v : u;
}

static double beyond_conv(xu_rng *r)
{
    switch (xu_rng_int(r, 0, 4)) {
    case 0: return nextafter(ldexp(1.0, CONV_EMAX), INF);
    case 1: return DBL_MAX;
    case 2: return INF;
    case 3: return ldexp(1.0, CONV_EMAX); /* the limit itself: in domain */
    default: return xu_gen_mag(r, CONV_EMAX, 1024);
    }
}

static void gen_b2c_case(xu_rng *r, cbx_box *b)
{
    int j, p = xu_rng_int(r, 0, 999);
    for (j = 0; j < 3; j++) gen_conv_interval(r, &b->lo[j], &b->hi[j], CONV_EMAX);
    j = xu_rng_int(r, 0, 2);
    if (p < 100) {
        double big = beyond_conv(r);
        switch (xu_rng_int(r, 0, 3)) {
        case 0: b->hi[j] = big; if (b->lo[j] > big) b->lo[j] = -big; break;
        case 1: b->lo[j] = -big; if (b->hi[j] < -big) b->hi[j] = big; break;
        case 2: b->lo[j] = -big; b->hi[j] = big; break;
        default: b->lo[j] = b->hi[j] = xu_rng_sign(r) * big; break;
        }
    } else if (p < 115) {
        double nan = xu_rng_sign(r) * NAN;
        if (xu_rng_int(r, 0, 1)) b->lo[j] = nan; else b->hi[j] = nan;
    } else if (p < 130) {
        switch (xu_rng_int(r, 0, 2)) {
        case 0: b->lo[j] = nextafter(b->hi[j], INF); break;
        case 1: b->lo[j] = INF; b->hi[j] = -INF; break;
        default: b->lo[j] = 1.0; b->hi[j] = -1.0; break;
        }
        if (p < 118) b->hi[(j + 1) % 3] = NAN;
    }
}

static void gen_c2b_case(xu_rng *r, cbx_cbox *b)
{
    int j, p = xu_rng_int(r, 0, 999);
    for (j = 0; j < 3; j++) {
        switch (xu_rng_int(r, 0, 5)) {
        case 0: /* c - h or c + h exactly 0 */
            b->c[j] = xu_gen_signed(r, -1074, CONV_EMAX);
            b->h[j] = fabs(b->c[j]);
            break;
        case 1: { /* similar magnitudes */
            int e = xu_rng_int(r, -1070, CONV_EMAX);
            b->c[j] = xu_gen_signed(r, e - 3, e);
            b->h[j] = gen_half(r, e - 3, e);
            break;
        }
        default:
            b->c[j] = xu_gen_signed(r, -1074, CONV_EMAX);
            b->h[j] = gen_half(r, -1074, CONV_EMAX);
            break;
        }
    }
    j = xu_rng_int(r, 0, 2);
    if (p < 100) {
        double big = beyond_conv(r);
        if (xu_rng_int(r, 0, 1)) b->c[j] = xu_rng_sign(r) * big;
        else b->h[j] = big;
    } else if (p < 115) {
        double nan = xu_rng_sign(r) * NAN;
        if (xu_rng_int(r, 0, 1)) b->c[j] = nan; else b->h[j] = nan;
    } else if (p < 130) {
        inject_neg_h(r, b);
        if (p < 118) b->c[(j + 1) % 3] = NAN;
    }
}

/* ---------------------------------------------------------------------- */
/* Drivers                                                                */
/* ---------------------------------------------------------------------- */

static void tc_log(long id, const char *what, const cbx_affine *a,
                   const cbx_cbox *in, const cbx_cbox *out, const verdict *v)
{
    if (!log_head(what, id, v)) return;
    print_affine(a);
    print_cbox("in ", in);
    print_cbox("out", out);
}

/* One table of hand-picked cases; each is also checked against the
 * table's own status, lost axes and kinds. */
static void run_tc_table(ctx *k, group *g, const char *title, const tc_case *tab, int n)
{
    int h;
    printf("-- cbx_transform_cbox: %s (%d; kinds per axis: A full row, D zero columns "
           "dropped, W lost) --\n", title, n);
    for (h = 0; h < n; h++) {
        const tc_case *t = &tab[h];
        cbx_cbox out;
        verdict v;
        double mx;
        int oob;
        char kinds[4];
        tc_run(k, g, &t->a, &t->in, &out, 1, &v, &mx);
        if (tc_expected(&t->a, &t->in, &oob, kinds) != t->expect || oob != t->oob
            || strcmp(kinds, t->kinds) != 0) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/lost %d/%s, oracle lost %d/%s",
                         cbx_status_name(t->expect), t->oob, t->kinds, oob, kinds);
            v.failed = 1;
        }
        g_add(g, &v);
        printf("  %-52s %-10s %s  max excess %7.3f  %s\n", t->name,
               cbx_status_name(v.got), kinds, mx, v.failed ? "FAIL" : "ok");
        if (v.failed) tc_log(h, title, &t->a, &t->in, &out, &v);
    }
}

static void run_tc(ctx *k, group *gh, group *gd, group *gr, group *grd, long n,
                   uint64_t seed)
{
    long c;
    xu_rng r;
    fail_logs = 0; /* MAX_FAIL_LOGS per function */
    run_tc_table(k, gh, "hard cases", tc_hard, N_TC_HARD);
    run_tc_table(k, gd, "zero columns dropped", tc_drop, N_TC_DROP);
    r.s = seed;
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_cbox in, out;
        verdict v;
        double mx;
        gen_tc_case(&r, &a, &in);
        if (tc_run(k, gr, &a, &in, &out, c % CORNER_EVERY == 0, &v, &mx))
            tc_log(c, "transform_cbox random", &a, &in, &out, &v);
        g_add(gr, &v);
    }
    /* zero-column cases: a third of N, corners on every 5th */
    r.s = seed ^ UINT64_C(0xd00dd00dd00d);
    for (c = 0; c < n / 3; c++) {
        cbx_affine a;
        cbx_cbox in, out;
        verdict v;
        double mx;
        gen_tc_drop_case(&r, &a, &in);
        if (tc_run(k, grd, &a, &in, &out, c % 5 == 0, &v, &mx))
            tc_log(c, "transform_cbox random zero-column", &a, &in, &out, &v);
        g_add(grd, &v);
    }
}

static void b2c_log(long id, const char *what, const cbx_box *in,
                    const cbx_cbox *out, const verdict *v)
{
    if (!log_head(what, id, v)) return;
    xu_print_box(stdout, "in ", in);
    print_cbox("out", out);
}

static void c2b_log(long id, const char *what, const cbx_cbox *in,
                    const cbx_box *out, const verdict *v)
{
    if (!log_head(what, id, v)) return;
    print_cbox("in ", in);
    xu_print_box(stdout, "out", out);
}

static void run_b2c(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    fail_logs = 0; /* MAX_FAIL_LOGS per function */
    printf("-- cbx_box_to_cbox: hard cases (%d) --\n", N_B2C_HARD);
    for (h = 0; h < N_B2C_HARD; h++) {
        const b2c_case *t = &b2c_hard[h];
        cbx_cbox out;
        verdict v;
        double mx;
        int oob;
        b2c_run(k, gh, &t->in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) roundtrip_box(k, gh, &t->in, &out, &v);
        if (b2c_expected(&t->in, &oob) != t->expect || oob != t->oob) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/oob %d, oracle oob %d",
                         cbx_status_name(t->expect), t->oob, oob);
            v.failed = 1;
        }
        g_add(gh, &v);
        printf("  %-44s %-10s max excess %7.3f  %s\n", t->name,
               cbx_status_name(v.got), mx, v.failed ? "FAIL" : "ok");
        if (v.failed) b2c_log(h, "box_to_cbox hard", &t->in, &out, &v);
    }
    r.s = seed ^ UINT64_C(0xb2cb2cb2c);
    for (c = 0; c < n; c++) {
        cbx_box in;
        cbx_cbox out;
        verdict v;
        double mx;
        gen_b2c_case(&r, &in);
        b2c_run(k, gr, &in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) roundtrip_box(k, gr, &in, &out, &v);
        if (v.failed) b2c_log(c, "box_to_cbox random", &in, &out, &v);
        g_add(gr, &v);
    }
}

static void run_c2b(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    fail_logs = 0; /* MAX_FAIL_LOGS per function */
    printf("-- cbx_cbox_to_box: hard cases (%d) --\n", N_C2B_HARD);
    for (h = 0; h < N_C2B_HARD; h++) {
        const c2b_case *t = &c2b_hard[h];
        cbx_box out;
        verdict v;
        double mx;
        int oob;
        c2b_run(k, gh, &t->in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) roundtrip_cbox(k, gh, &t->in, &out, &v);
        if (c2b_expected(&t->in, &oob) != t->expect || oob != t->oob) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/oob %d, oracle oob %d",
                         cbx_status_name(t->expect), t->oob, oob);
            v.failed = 1;
        }
        g_add(gh, &v);
        printf("  %-44s %-10s max excess %7.3f  %s\n", t->name,
               cbx_status_name(v.got), mx, v.failed ? "FAIL" : "ok");
        if (v.failed) c2b_log(h, "cbox_to_box hard", &t->in, &out, &v);
    }
    r.s = seed ^ UINT64_C(0xc2bc2bc2b);
    for (c = 0; c < n; c++) {
        cbx_cbox in;
        cbx_box out;
        verdict v;
        double mx;
        gen_c2b_case(&r, &in);
        c2b_run(k, gr, &in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) roundtrip_cbox(k, gr, &in, &out, &v);
        if (v.failed) c2b_log(c, "cbox_to_box random", &in, &out, &v);
        g_add(gr, &v);
    }
}

static unsigned long long arg_num(int argc, char **argv, int k,
                                  unsigned long long dflt)
{
    char *end;
    unsigned long long v;
    if (argc <= k) return dflt;
    v = strtoull(argv[k], &end, 0);
    if (*argv[k] == '\0' || *argv[k] == '-' || *end != '\0') {
        fprintf(stderr, "usage: %s [N] [seed]\n", argv[0]);
        exit(2);
    }
    return v;
}

int main(int argc, char **argv)
{
    long n = (long)arg_num(argc, argv, 1, 300000ULL);
    uint64_t seed = (uint64_t)arg_num(argc, argv, 2, 0xcb0c5eed2024ULL);
    ctx k;
    group g[8];
    long passed = 0, failed = 0;
    int i;
    clock_t t0 = clock();

    ctx_init(&k);
    g_init(&g[0], "cbx_transform_cbox, hard cases", TC_UNITS);
    g_init(&g[1], "cbx_transform_cbox, zero columns dropped (hand-picked)", TC_UNITS);
    g_init(&g[2], "cbx_transform_cbox, random cases", TC_UNITS);
    g_init(&g[3], "cbx_transform_cbox, random zero-column cases", TC_UNITS);
    g_init(&g[4], "cbx_box_to_cbox, hard cases", "u*max(|lo|,|hi|) + eta (sanity on the mean of both ends)");
    g_init(&g[5], "cbx_box_to_cbox, random cases", "u*max(|lo|,|hi|) + eta (sanity on the mean of both ends)");
    g_init(&g[6], "cbx_cbox_to_box, hard cases", "u*(|c| + h) + eta");
    g_init(&g[7], "cbx_cbox_to_box, random cases", "u*(|c| + h) + eta");

    printf("test_cbox: N = %ld random cases per function, seed 0x%llx, conversion "
           "domain 2^%d, sanity bound %g units, corners every %d-th random case\n\n",
           n, (unsigned long long)seed, CONV_EMAX, SANITY, CORNER_EVERY);
    run_tc(&k, &g[0], &g[1], &g[2], &g[3], n, seed);
    run_b2c(&k, &g[4], &g[5], n, seed);
    run_c2b(&k, &g[6], &g[7], n, seed);

    printf("\n");
    for (i = 0; i < 8; i++) {
        g_print(&g[i]);
        passed += g[i].cases - g[i].failed;
        failed += g[i].failed;
    }
    printf("spec-tight = cbox_tight of specs/cbx_spec.h: each end within "
           "12 u S + 2^-1065 of the exact end\n");
    printf("D-* = the same checks on a D axis, on the dropped row (c_j = h_j = 0 where "
           "m_j == 0): S' instead of S\n");
    printf("CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    ctx_clear(&k);
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
