/*
 * test_halfspace [N] [seed]: cbx_transform_box on boxes with infinite ends
 * (half-spaces) and on finite boxes with a huge end, against exact
 * rational arithmetic (GMP).
 *
 * A box end lo_j = -inf / hi_j = +inf is no constraint: the box is the
 * real set { p : lo_j <= p_j <= hi_j where that end is finite }; an axis
 * with lo_j = +inf or hi_j = -inf (or hi_j < lo_j) has no real point
 * (CBX_EMPTY).  The rules (certbox.h; exact_util.h, rules A, B, C) per
 * output axis i, row m = m[i][0..2], t = m[i][3]:
 *   A  every input of the row finite and in the domain: the kernel;
 *   B  m, t finite, otherwise: each end from its vertex v_j = lo_j
 *      (m_j > 0), hi_j (m_j < 0), 0 (m_j == 0, -0.0 too) for the lower end,
 *      mirrored for the upper one; "U" unbounded (a needed v_j infinite):
 *      exactly -inf / +inf, no loss; "F" vertex in the domain: finite,
 *      on the right side of t + sum m_j v_j and within 12 u S_v + 2^-1065,
 *      S_v = |t| + sum |m_j v_j|; "L" vertex outside: -inf / +inf, a loss;
 *   C  an infinite m_j or t: [-inf, +inf] ("W"), a loss.
 *   Status CBX_OK iff no L or W end, else CBX_ERANGE.
 *
 * Section 1, end patterns: for every map of a list of special maps (rows
 * with exact zeros, -0.0, mixed signs, entries and translations at and
 * beyond the domain limits, tiny entries, an infinite entry) and N random
 * maps (default 150; rows of the same kinds drawn at random), every one of
 * the 3^6 = 729 patterns of the six box ends, each end finite, -inf or
 * +inf (no NaN: that is CBX_EINVAL, test_badinput).  The 665 patterns with
 * some lo_j = +inf or hi_j = -inf are empty and run once; the 64 others
 * run DRAWS = 4 times with fresh finite ends (small, zero, +-1, huge).
 * Section 2, huge unneeded ends: N * 100 random finite boxes (rows with
 * zeros and mixed signs, in the domain) in which one end of one axis is
 * replaced by a huge value (DBL_MAX, 1e308, 2^1019, 2^1018 + 1 ulp, ...):
 * outside every class, so each row loses exactly the ends that need it
 * and proves the others (a zero coefficient needs neither).
 *
 * Checks, per case (a failure of any fails the case):
 *   exact    exact_util's xu_run_case with the mpq corner checks: status,
 *            every field written, EMPTY exact, every end exactly per the
 *            rules (A: finite, containing, 12 u S + 2^-1065; F: finite,
 *            containing the exact vertex value, 12 u S_v + 2^-1065, the
 *            vertex value cross-checked against the extended mpq corners;
 *            U, L: exactly -inf / +inf; W: [-inf, +inf]), inputs unchanged;
 *   rules    this file's own statement of the rules (hs_end_kind, written
 *            from the text above, not calling exact_util) gives the same
 *            kind for all six ends and the same status as exact_util;
 *   samples  SAMPLES = 3 real points of the box, drawn with finite
 *            coordinates inside its constraints (ends, random values
 *            between, and far out up to -+DBL_MAX along half-lines): their
 *            exact images (mpq) lie in [lo, hi] on every axis with a finite
 *            map row (an infinite end contains everything on its side);
 *   witness  for each F end, the vertex itself as a real point of the box
 *            (v_j for m_j != 0, a sampled coordinate for m_j == 0): its
 *            exact image V satisfies lo <= V <= lo + 12 u S_v + 2^-1065
 *            (upper: hi - (12 u S_v + 2^-1065) <= V <= hi), mpq: the end
 *            is attained within the proven bound by a point of the box.
 * Printed per section: cases, expected statuses, ends by kind, exact_util's
 * check table (xu_stats_print) and this file's checks; the first failures
 * with their inputs in hex.  Last line "N passed, M failed" (cases); exit
 * status 1 on failure.
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

#define INF HUGE_VAL
#define DRAWS 4
#define SAMPLES 3
#define MAX_FAIL_LOGS 20
#define P1018U 0x1.0000000000001p1018

/* ---------------------------------------------------------------------- */
/* The rules, written out again (independent of exact_util)               */
/* ---------------------------------------------------------------------- */

/* (m, c) in one class |m| <= 2^k, |c| <= 2^(1018-k), k in {0, 64, ..., 960,
 * 509, 1018}; false for infinities. */
static int hs_class(double m, double c)
{
    int k;
    if (!isfinite(m) || !isfinite(c)) return 0;
    if (fabs(m) <= 0x1p509 && fabs(c) <= 0x1p509) return 1;
    if (fabs(m) <= 0x1p1018 && fabs(c) <= 1.0) return 1;
    for (k = 0; k <= 960; k += 64)
        if (fabs(m) <= ldexp(1.0, k) && fabs(c) <= ldexp(1.0, 1018 - k)) return 1;
    return 0;
}

static int hs_empty(const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        if (b->hi[j] < b->lo[j] || (isinf(b->lo[j]) && b->lo[j] > 0)
            || (isinf(b->hi[j]) && b->hi[j] < 0))
            return 1;
    return 0;
}

/* The vertex of one end: 0 when the image is unbounded on that side. */
static int hs_vertex(const cbx_affine *a, const cbx_box *b, int i, int upper, double v[3])
{
    int j;
    for (j = 0; j < 3; j++) {
        double m = a->m[i][j];
        if (m > 0) v[j] = upper ? b->hi[j] : b->lo[j];
        else if (m < 0) v[j] = upper ? b->lo[j] : b->hi[j];
        else v[j] = 0.0;
        if (isinf(v[j])) return 0;
    }
    return 1;
}

/* 'A', 'F', 'U', 'L' or 'W' (box not empty, no NaN). */
static char hs_end_kind(const cbx_affine *a, const cbx_box *b, int i, int upper)
{
    double v[3];
    int j, full = fabs(a->m[i][3]) <= 0x1p1018;
    for (j = 0; j < 3; j++)
        full = full && hs_class(a->m[i][j], b->lo[j]) && hs_class(a->m[i][j], b->hi[j]);
    if (full) return 'A';
    for (j = 0; j < 4; j++)
        if (!isfinite(a->m[i][j])) return 'W';
    if (!hs_vertex(a, b, i, upper, v)) return 'U';
    for (j = 0; j < 3; j++)
        if (!hs_class(a->m[i][j], v[j])) return 'L';
    return fabs(a->m[i][3]) <= 0x1p1018 ? 'F' : 'L';
}

/* ---------------------------------------------------------------------- */
/* Inputs                                                                 */
/* ---------------------------------------------------------------------- */

/* Special maps: rows with exact zeros, -0.0, mixed signs, huge and tiny
 * entries, translations at and beyond 2^1018, infinite entries. */
static const cbx_affine special_maps[] = {
    { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } },
    { { { 0, 0, 0, 0 }, { -0.0, -0.0, -0.0, -0.0 }, { 0, -0.0, 0, 5 } } },
    { { { 1, -1, 0.5, 0 }, { -2, 0, 3, 1 }, { 0, -0.0, -1, -1 } } },
    { { { 1e300, 0, 0, 0 }, { 0, -0x1p1018, 1, 0 }, { DBL_MAX, -0.0, 0, 1 } } },
    { { { 1, 0, 0, 0x1p1018 }, { 0, 1, 0, DBL_MAX }, { 0, 0, -1, -P1018U } } },
    { { { 0x1p509, -0x1p509, 0, 0 }, { 0x1p960, 0, -0x1p64, 0 },
        { 0x1p-1074, -0x1p-1074, 0x1p-1022, 0x1p-1074 } } },
    { { { INF, 0, 0, 0 }, { 0, 0, 0, -INF }, { 1, 1, 1, 1 } } },
    { { { -0.0, 0, -0.0, -3 }, { 0, 0, 0, 0x1p1018 }, { 0, 0, 0, -DBL_MAX } } },
    { { { 0.36, -0.48, 0.8, 10 }, { 0.8, 0.6, 0, -3 }, { -0.48, 0.64, 0.6, 0.5 } } },
    { { { 0, 1e300, -0.0, 0 }, { -0.0, 0, 0x1p1018, 1 }, { 3, 0, -0.0, 0 } } },
    { { { -1, -1, -1, -0.0 }, { 1, 1, 1, 0 }, { -0x1p-1074, 0, 0x1p1018, -0x1p1018 } } },
    { { { 0x1p-30, -0x1p30, 0x1p-1060, 1e-300 }, { -7, 0.125, -0.0, 2 },
        { 0, -0x1p509, 0x1p509, 0 } } },
};
#define N_SPECIAL ((int)(sizeof special_maps / sizeof special_maps[0]))

/* One random entry of a map row of a random kind. */
static double gen_entry(xu_rng *r, int kind)
{
    int p = xu_rng_int(r, 0, 99);
    switch (kind) {
    case 0: /* small with exact zeros of both signs */
        if (p < 25) return xu_rng_sign(r) * 0.0;
        if (p < 40) return xu_rng_sign(r) * (double)xu_rng_int(r, 1, 4);
        return xu_gen_signed(r, -20, 10);
    case 1: /* huge, at and beyond the classes */
        if (p < 30) return xu_rng_sign(r) * 0.0;
        if (p < 50) return xu_rng_sign(r) * 0x1p1018;
        if (p < 60) return xu_rng_sign(r) * DBL_MAX;
        if (p < 70) return xu_rng_sign(r) * 1e300;
        return xu_gen_signed(r, 400, 1023);
    case 2: /* tiny */
        if (p < 20) return xu_rng_sign(r) * 0.0;
        return xu_gen_signed(r, -1074, -900);
    default: /* the whole range */
        if (p < 15) return xu_rng_sign(r) * 0.0;
        return xu_gen_signed(r, -1074, 1023);
    }
}

static double gen_t(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 40) return xu_rng_sign(r) * 0.0;
    if (p < 75) return xu_gen_signed(r, -20, 20);
    if (p < 85) return xu_rng_sign(r) * 0x1p1018;
    if (p < 90) return xu_rng_sign(r) * P1018U;
    if (p < 93) return xu_rng_sign(r) * DBL_MAX;
    return xu_gen_signed(r, -1074, 1018);
}

static void gen_map(xu_rng *r, cbx_affine *a)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        int kind = xu_rng_int(r, 0, 9);
        kind = kind < 5 ? 0 : kind < 7 ? 1 : kind < 8 ? 2 : 3;
        for (j = 0; j < 3; j++) a->m[i][j] = gen_entry(r, kind);
        a->m[i][3] = gen_t(r);
        if (xu_rng_int(r, 0, 29) == 0) /* rule C now and then */
            a->m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF;
    }
}

/* A finite box coordinate: small, zero, +-1, or huge (at and beyond the
 * domain limits). */
static double gen_coord(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 30) return xu_gen_signed(r, -10, 3);
    if (p < 42) return xu_rng_sign(r) * 0.0;
    if (p < 52) return xu_rng_sign(r);
    if (p < 67) return xu_gen_signed(r, -1074, 1018);
    if (p < 72) return xu_rng_sign(r) * 0x1p1018;
    if (p < 75) return xu_rng_sign(r) * P1018U;
    if (p < 78) return xu_rng_sign(r) * DBL_MAX;
    if (p < 80) return xu_rng_sign(r) * 1e300;
    return xu_gen_signed(r, -30, 30);
}

/* Axis j of the box from its pattern: 0 finite, 1 -inf, 2 +inf per end. */
static void gen_axis(xu_rng *r, cbx_box *b, int j, int plo, int phi)
{
    double u = gen_coord(r), v = gen_coord(r);
    if (plo == 0 && phi == 0) {
        if (xu_rng_int(r, 0, 9) == 0) v = u;
        b->lo[j] = u < v ? u : v;
        b->hi[j] = u < v ? v : u;
        return;
    }
    b->lo[j] = plo == 0 ? u : plo == 1 ? -INF : INF;
    b->hi[j] = phi == 0 ? v : phi == 1 ? -INF : INF;
}

/* A finite coordinate inside the real set of axis j (not empty). */
static double sample_coord(xu_rng *r, const cbx_box *b, int j)
{
    double lo = b->lo[j], hi = b->hi[j], x;
    int p = xu_rng_int(r, 0, 9);
    if (isfinite(lo) && isfinite(hi)) {
        if (p < 3) return lo;
        if (p < 6) return hi;
        x = lo + (hi - lo) * xu_rng_unit(r);
        if (!isfinite(x)) x = lo / 2 + hi / 2; /* hi - lo overflowed */
    } else if (isfinite(lo)) { /* [lo, +inf) */
        if (p < 3) return lo;
        x = p < 5 ? DBL_MAX : p < 7 ? lo + fabs(xu_gen_signed(r, -20, 40))
                             : fabs(xu_gen_signed(r, -1074, 1023));
    } else if (isfinite(hi)) { /* (-inf, hi] */
        if (p < 3) return hi;
        x = p < 5 ? -DBL_MAX : p < 7 ? hi - fabs(xu_gen_signed(r, -20, 40))
                              : -fabs(xu_gen_signed(r, -1074, 1023));
    } else { /* the whole line */
        x = p < 2 ? xu_rng_sign(r) * DBL_MAX : p < 4 ? xu_rng_sign(r) * 0.0
                                             : xu_gen_signed(r, -1074, 1023);
    }
    if (!isfinite(x)) x = isfinite(lo) ? lo : hi;   /* lo + huge overflowed */
    if (isfinite(lo) && x < lo) x = lo;
    if (isfinite(hi) && x > hi) x = hi;
    return x;
}

/* ---------------------------------------------------------------------- */
/* Checks of this file                                                    */
/* ---------------------------------------------------------------------- */

enum { K_EXACT, K_RULES, K_SAMPLES, K_WITNESS, NK };
static const char *const k_name[NK] = { "exact", "rules", "samples", "witness" };
static const char *const k_unit[NK] = { "cases", "cases", "points x axes", "ends" };

typedef struct section {
    const char *title;
    xu_stats st;
    long cases, failed, status_seen[4];
    long ends[XU_NEND];          /* by hs_end_kind (non-empty cases)      */
    long checked[NK], fail[NK];
    long fin_box_f;              /* F ends of finite boxes (section 2)    */
} section;

typedef struct ctx {
    xu_exact x;
    mpq_t q, qa, qb, qs, tol;
    xu_rng rng;
    long logs;
} ctx;

static int case_failed;
static char case_why[200];

static void kfail(section *s, int k, const char *why)
{
    s->fail[k]++;
    if (!case_failed) {
        strncpy(case_why, why, sizeof case_why - 1);
        case_why[sizeof case_why - 1] = '\0';
    }
    case_failed = 1;
}

/* q = t + sum_j m_j p_j (exact); qs = |t| + sum_j |m_j p_j| */
static void image_q(ctx *k, const cbx_affine *a, int i, const double p[3])
{
    int j;
    mpq_set_d(k->q, a->m[i][3]);
    mpq_abs(k->qs, k->q);
    for (j = 0; j < 3; j++) {
        mpq_set_d(k->qa, a->m[i][j]);
        mpq_set_d(k->qb, p[j]);
        mpq_mul(k->qa, k->qa, k->qb);
        mpq_add(k->q, k->q, k->qa);
        mpq_abs(k->qa, k->qa);
        mpq_add(k->qs, k->qs, k->qa);
    }
}

static int row_finite(const cbx_affine *a, int i)
{
    return isfinite(a->m[i][0]) && isfinite(a->m[i][1]) && isfinite(a->m[i][2])
           && isfinite(a->m[i][3]);
}

/* One case: the library call through xu_run_case, then this file's checks. */
static void run_one(ctx *k, section *s, const cbx_affine *a, const cbx_box *b)
{
    cbx_box out;
    xu_verdict v;
    int i, e, n, loss = 0, empty = hs_empty(b);
    char why[200];

    case_failed = 0;
    case_why[0] = '\0';
    s->cases++;

    s->checked[K_EXACT]++;
    if (xu_run_case(&k->x, a, b, &out, 1, &v)) kfail(s, K_EXACT, v.why);
    xu_stats_add(&s->st, &v, a, b);
    if (xu_status_index(v.expected) >= 0) s->status_seen[xu_status_index(v.expected)]++;

    /* rules: the status and the six kinds */
    s->checked[K_RULES]++;
    if (empty) {
        if (v.expected != CBX_EMPTY) kfail(s, K_RULES, "rules: empty box, exact_util not EMPTY");
    } else {
        for (i = 0; i < 3; i++)
            for (e = 0; e < 2; e++) {
                char c = hs_end_kind(a, b, i, e);
                const char *pc = strchr(xu_end_char, c);
                if (pc) s->ends[pc - xu_end_char]++;
                if (c == 'L' || c == 'W') loss = 1;
                if (v.ax[i].end_kind[e] < 0 || xu_end_char[v.ax[i].end_kind[e]] != c) {
                    snprintf(why, sizeof why, "rules: axis %d %s end: this file says %c, "
                             "exact_util %c", i, e ? "upper" : "lower", c,
                             v.ax[i].end_kind[e] < 0 ? '-' : xu_end_char[v.ax[i].end_kind[e]]);
                    kfail(s, K_RULES, why);
                }
            }
        if (v.expected != (loss ? CBX_ERANGE : CBX_OK))
            kfail(s, K_RULES, "rules: the status differs from exact_util's");
    }

    if (!empty) {
        double p[3];
        /* samples: real points of the box map inside [lo, hi] */
        for (n = 0; n < SAMPLES; n++) {
            for (i = 0; i < 3; i++) p[i] = sample_coord(&k->rng, b, i);
            for (i = 0; i < 3; i++) {
                if (!row_finite(a, i)) continue;
                s->checked[K_SAMPLES]++;
                image_q(k, a, i, p);
                if (isinf(out.lo[i]) ? out.lo[i] > 0
                                     : (mpq_set_d(k->qa, out.lo[i]), mpq_cmp(k->qa, k->q) > 0)) {
                    snprintf(why, sizeof why, "samples: axis %d: point (%a, %a, %a) maps below "
                             "lo", i, p[0], p[1], p[2]);
                    kfail(s, K_SAMPLES, why);
                } else if (isinf(out.hi[i]) ? out.hi[i] < 0
                                            : (mpq_set_d(k->qa, out.hi[i]),
                                               mpq_cmp(k->qa, k->q) < 0)) {
                    snprintf(why, sizeof why, "samples: axis %d: point (%a, %a, %a) maps above "
                             "hi", i, p[0], p[1], p[2]);
                    kfail(s, K_SAMPLES, why);
                }
            }
        }
        /* witness: the vertex of each F end attains it within the bound */
        for (i = 0; i < 3; i++)
            for (e = 0; e < 2; e++) {
                double d = e ? out.hi[i] : out.lo[i], vtx[3];
                int j;
                if (hs_end_kind(a, b, i, e) != 'F') continue;
                s->checked[K_WITNESS]++;
                if (isfinite(b->lo[0]) && isfinite(b->hi[0]) && isfinite(b->lo[1])
                    && isfinite(b->hi[1]) && isfinite(b->lo[2]) && isfinite(b->hi[2]))
                    s->fin_box_f++;
                hs_vertex(a, b, i, e, vtx);
                for (j = 0; j < 3; j++)
                    if (a->m[i][j] == 0) vtx[j] = sample_coord(&k->rng, b, j);
                if (!isfinite(d)) {
                    kfail(s, K_WITNESS, "witness: an F end is not finite");
                    continue;
                }
                image_q(k, a, i, vtx);
                /* tol = 12 u S_v + 2^-1065 = 3 * 2^-51 S_v + 2^-1065 */
                mpq_set_ui(k->tol, 3, 1);
                mpq_mul(k->tol, k->tol, k->qs);
                mpq_div_2exp(k->tol, k->tol, 51);
                mpq_set_ui(k->qb, 1, 1);
                mpq_div_2exp(k->qb, k->qb, 1065);
                mpq_add(k->tol, k->tol, k->qb);
                mpq_set_d(k->qa, d);
                /* qb = V - d (lower) or d - V (upper): must be in [0, tol] */
                if (e) mpq_sub(k->qb, k->qa, k->q);
                else mpq_sub(k->qb, k->q, k->qa);
                if (mpq_sgn(k->qb) < 0 || mpq_cmp(k->qb, k->tol) > 0) {
                    snprintf(why, sizeof why, "witness: axis %d %s end %.17g not within "
                             "[0, 12 u S_v + 2^-1065] of the vertex's image", i,
                             e ? "upper" : "lower", d);
                    kfail(s, K_WITNESS, why);
                }
            }
    }

    if (case_failed) {
        s->failed++;
        if (k->logs++ < MAX_FAIL_LOGS) {
            printf("FAIL %s case %ld: %s (status %s, expected %s)\n", s->title, s->cases - 1,
                   case_why, cbx_status_name(v.got), cbx_status_name(v.expected));
            xu_print_case(stdout, a, b);
            xu_print_box(stdout, "out", &out);
        }
    }
}

static void section_init(section *s, const char *title)
{
    memset(s, 0, sizeof *s);
    s->title = title;
    xu_stats_init(&s->st);
}

static void section_print(const section *s)
{
    int c;
    printf("  %ld cases: expected OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld; %ld failed\n",
           s->cases, s->status_seen[0], s->status_seen[1], s->status_seen[2],
           s->status_seen[3], s->failed);
    printf("  ends of the non-empty cases by kind (this file's rules):");
    for (c = 0; c < XU_NEND; c++) printf(" %c %ld", xu_end_char[c], s->ends[c]);
    printf("\n");
    if (s->fin_box_f)
        printf("  F ends (proven from the vertex) of finite boxes: %ld\n", s->fin_box_f);
    for (c = 0; c < NK; c++)
        printf("  check %-8s %9ld %-13s checked, %ld failed\n", k_name[c], s->checked[c],
               k_unit[c], s->fail[c]);
    xu_stats_print(stdout, s->title, &s->st);
}

/* Section 1: the 729 patterns of the six ends for one map. */
static void run_patterns(ctx *k, section *s, const cbx_affine *a)
{
    int pat;
    for (pat = 0; pat < 729; pat++) {
        int d, ends[6], q = pat, j, nonempty = 1;
        for (j = 0; j < 6; j++) {
            ends[j] = q % 3;
            q /= 3;
        }
        /* ends[2j] is lo_j, ends[2j+1] hi_j: 0 finite, 1 -inf, 2 +inf */
        for (j = 0; j < 3; j++)
            if (ends[2 * j] == 2 || ends[2 * j + 1] == 1) nonempty = 0;
        for (d = 0; d < (nonempty ? DRAWS : 1); d++) {
            cbx_box b;
            for (j = 0; j < 3; j++) gen_axis(&k->rng, &b, j, ends[2 * j], ends[2 * j + 1]);
            run_one(k, s, a, &b);
        }
    }
}

/* Section 2: a finite in-domain box with one huge end. */
static void run_huge_end(ctx *k, section *s)
{
    static const double huge[] = { DBL_MAX, 1e308, 0x1p1019, P1018U, 0x1p1020,
                                   0x1.fffffffffffffp1022 };
    cbx_affine a;
    cbx_box b;
    int i, j;
    double h;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) a.m[i][j] = gen_entry(&k->rng, 0);
        a.m[i][3] = xu_rng_int(&k->rng, 0, 1) ? xu_gen_signed(&k->rng, -20, 20) : 0.0;
    }
    for (j = 0; j < 3; j++) {
        double u = xu_gen_signed(&k->rng, -20, 20), v = xu_gen_signed(&k->rng, -20, 20);
        b.lo[j] = u < v ? u : v;
        b.hi[j] = u < v ? v : u;
    }
    j = xu_rng_int(&k->rng, 0, 2);
    h = huge[xu_rng_int(&k->rng, 0, (int)(sizeof huge / sizeof huge[0]) - 1)];
    switch (xu_rng_int(&k->rng, 0, 3)) {
    case 0: b.hi[j] = h; break;
    case 1: b.lo[j] = -h; break;
    case 2: b.lo[j] = -h; b.hi[j] = h; break; /* both ends huge */
    default: /* one huge end and a zero column against it */
        b.hi[j] = h;
        a.m[xu_rng_int(&k->rng, 0, 2)][j] = xu_rng_sign(&k->rng) * 0.0;
        break;
    }
    run_one(k, s, &a, &b);
}

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 150, "[N] [seed]"), m, c;
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N] [seed]");
    static section s1, s2;
    ctx k;
    long failed, cases;
    clock_t t0 = clock();

    xu_init(&k.x);
    mpq_inits(k.q, k.qa, k.qb, k.qs, k.tol, (mpq_ptr)0);
    k.rng.s = UINT64_C(0x6a09e667f3bcc909) ^ seed;
    k.logs = 0;
    section_init(&s1, "section 1: end patterns");
    section_init(&s2, "section 2: huge ends");

    printf("-- test_halfspace: cbx_transform_box on half-space boxes, seed %llu --\n",
           (unsigned long long)seed);
    for (m = 0; m < N_SPECIAL; m++) run_patterns(&k, &s1, &special_maps[m]);
    for (m = 0; m < n; m++) {
        cbx_affine a;
        gen_map(&k.rng, &a);
        run_patterns(&k, &s1, &a);
    }
    for (c = 0; c < 100 * n; c++) run_huge_end(&k, &s2);

    printf("\nsection 1: %d special + %ld random maps x 729 end patterns (64 non-empty x %d "
           "draws of the finite ends, 665 empty x 1)\n", N_SPECIAL, n, DRAWS);
    section_print(&s1);
    printf("\nsection 2: %ld finite boxes with one huge end (DBL_MAX, 1e308, 2^1019, "
           "2^1018 + ulp, ...)\n", 100 * n);
    section_print(&s2);
    printf("\n  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);

    mpq_clears(k.q, k.qa, k.qb, k.qs, k.tol, (mpq_ptr)0);
    xu_clear(&k.x);
    cases = s1.cases + s2.cases;
    failed = s1.failed + s2.failed;
    printf("%ld passed, %ld failed\n", cases - failed, failed);
    return failed ? 1 : 0;
}
