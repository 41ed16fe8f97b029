/*
 * test_sphere [N] [seed]: cbx_sphere_box and cbx_ellipsoid_box against
 * exact rational arithmetic (GMP) and a 256-bit MPFR evaluation.
 *
 * cbx_sphere_box(a): the image of the unit ball under y = M p + T; the
 * exact axis i is t -+ sqrt(s) with t = m[i][3] and
 * s = m[i][0]^2 + m[i][1]^2 + m[i][2]^2.
 * cbx_ellipsoid_box(center, radii, rot): M = rot * diag(radii) taken
 * exactly (a_ij = rot[i][j] * radii[j] as rationals), t = center[i].
 *
 * For each function: a table of hand-picked hard cases (printed row by
 * row), then N random cases (default 200000 each).  Every case checks:
 *   - the status equals the one decided exactly from the contract in
 *     certbox.h (NaN -> EINVAL; a row outside the domain -> ERANGE);
 *   - every output field is written (NaN pre-fill), EINVAL gives exactly
 *     [-inf, +inf]^3, out-of-domain axes are exactly [-inf, +inf];
 *   - in-domain axes are finite, lo <= hi, and contain t -+ sqrt(s)
 *     EXACTLY, on integers: lo <= t - sqrt(s) iff t - lo >= 0 and
 *     (t - lo)^2 >= s, and the same for hi;
 *   - tightness against MPFR (256 bits, raised automatically where t and
 *     sqrt(s) cancel): in ulps of the exact end, and in units of
 *     u*(|t| + sqrt(s)) + eta (u = 2^-53, eta = 2^-1074); the sanity bound
 *     (documented floor: an end may be up to 2^-1064 out, the absolute terms
 *     of src/algo/cbx_sphere.c; a gap must exceed both 64 units and 2^-1064 to fail)
 *     (check "sanity<=64") fails an end more than 64 units out on axes with
 *     u*(|t| + sqrt(s)) >= 2^-1000; on the other axes (check "tiny-abs")
 *     an end fails when its gap is above both 64 units and 2^-1000;
 *   - the proven tightness (check "proven-bound", the contract's ball_tight):
 *     every in-domain end within 80 u (|t| + sqrt(s)) + 2^-1064 of the exact
 *     end, on every axis;
 *   - points: for up to 8 points p with p.p <= 1 (checked exactly; points
 *     that fail are nudged toward 0 or skipped), 6 of them the double
 *     nearest to the maximising directions -+ M_i/|M_i|, the exact image
 *     M p + T lies in the box (exact comparison on integers);
 *   - the inputs are not modified.
 * The last line is "N passed, M failed" (cases); exit status 1 on failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <time.h>

#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"

#define SANITY 64.0
#define MAX_FAIL_LOGS 20
#define PREC0 256    /* MPFR precision of the tightness evaluation        */
#define PRECMAX 6800 /* enough for any cancellation (see mp_row)          */
#define SH_SPHERE 1074UL   /* s scaled by 2^(2*1074): m_j 2^1074 integers */
#define SH_ELL 2148UL      /* a_ij = rot*radius: a 2^2148 integers        */
#define PT_SHIFT 3222UL    /* rot*radius*p: multiples of 2^-3222          */

#define INF HUGE_VAL
#define P509U 0x1.0000000000001p509
#define P254U 0x1.0000000000001p254
#define P1018U 0x1.0000000000001p1018

/* ---------------------------------------------------------------------- */
/* Checks, verdicts, statistics                                           */
/* ---------------------------------------------------------------------- */

enum {
    F_STATUS, F_UNSET, F_SPECIAL, F_OOB, F_FINITE, F_CONTAIN,
    F_SANITY,   /* > 64 units where u*(|t|+sqrt s) >= 2^-1000              */
    F_TINYABS,  /* gap > 2^-1000 where u*(|t|+sqrt s) < 2^-1000            */
    F_PROVEN,   /* gap > 80 u (|t|+sqrt s) + 2^-1064: the proven bound     */
    F_POINT, F_INPUT, NF
};
static const char *const f_name[NF] = {
    "status", "out-set", "special-out", "oob-axes", "finite", "containment",
    "sanity<=64", "tiny-abs", "proven-bound", "points", "inputs"
};
static const char *const f_unit[NF] = {
    "cases", "cases", "cases", "axes", "axes", "axes", "axes", "axes", "axes",
    "pt-axes", "cases"
};

typedef struct verdict {
    cbx_status expected, got;
    int failed;
    int flag[NF], applied[NF];
    char why[200];
} verdict;

typedef struct exstat {
    long n;
    double max, sum;
} exstat;

typedef struct group {
    const char *name;
    long cases, failed, status_seen[4];
    long applied[NF], fails[NF];
    exstat units, units_tiny, units_big, ulps_nocancel;
    double ulps_max;        /* over all ends (huge where an end is ~0)    */
    long ulps_over64;
    long axes, axes_tiny, exact_ends, prec_raised, pts, pts_skipped;
    double worst;           /* largest units (non-tiny) and where         */
    char worst_case[600];
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

static void g_init(group *g, const char *name)
{
    memset(g, 0, sizeof *g);
    g->name = name;
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

static void g_print(const group *g)
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
/* Exact and MPFR context                                                 */
/* ---------------------------------------------------------------------- */

typedef struct ctx {
    xu_exact x;
    mpz_t s[3], z, y, w, q;
    mpfr_t S, R, T, EL, EH, G, D;
} ctx;

static void ctx_init(ctx *k)
{
    int i;
    xu_init(&k->x);
    for (i = 0; i < 3; i++) mpz_init(k->s[i]);
    mpz_inits(k->z, k->y, k->w, k->q, (mpz_ptr)0);
    mpfr_inits2(PREC0, k->S, k->R, k->T, k->EL, k->EH, k->G, k->D, (mpfr_ptr)0);
}

static void ctx_clear(ctx *k)
{
    int i;
    xu_clear(&k->x);
    for (i = 0; i < 3; i++) mpz_clear(k->s[i]);
    mpz_clears(k->z, k->y, k->w, k->q, (mpz_ptr)0);
    mpfr_clears(k->S, k->R, k->T, k->EL, k->EH, k->G, k->D, (mpfr_ptr)0);
}

/* sphere: s_i = sum_j (m_ij 2^1074)^2, i.e. scaled by 2^(2*1074) */
static void sphere_s(ctx *k, const cbx_affine *a, int i)
{
    int j;
    mpz_set_ui(k->s[i], 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_sh(k->z, a->m[i][j], SH_SPHERE);
        mpz_addmul(k->s[i], k->z, k->z);
    }
}

/* ellipsoid: s_i = sum_j (rot_ij radii_j 2^2148)^2 */
static void ell_s(ctx *k, const double radii[3], const double rot[3][3], int i)
{
    int j;
    mpz_set_ui(k->s[i], 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(&k->x, k->z, rot[i][j], radii[j]);
        mpz_addmul(k->s[i], k->z, k->z);
    }
}

/* the double nearest sqrt(s / 2^(2 sh)) (for generators) */
static double sqrt_rn(ctx *k, const mpz_t s, unsigned long sh)
{
    mpfr_set_prec(k->S, PREC0);
    mpfr_set_z(k->S, s, MPFR_RNDN);
    mpfr_div_2ui(k->S, k->S, 2 * sh, MPFR_RNDN);
    mpfr_sqrt(k->S, k->S, MPFR_RNDN);
    return mpfr_get_d(k->S, MPFR_RNDN);
}

typedef struct rowres {
    double units_lo, units_hi, ulps_lo, ulps_hi;
    int tiny, big, exact_lo, exact_hi, cancel_lo, cancel_hi, raised, bad_lo, bad_hi;
    int over_proven;        /* an end beyond the proven bound (ball_gap)  */
} rowres;

/* ulp of the exact end X (the spacing of binary64 at |X|) */
static long ulp_exp(mpfr_t X)
{
    long e;
    if (mpfr_zero_p(X)) return -1074;
    e = (long)mpfr_get_exp(X) - 53; /* |X| in [2^(E-1), 2^E) */
    return e < -1074 ? -1074 : e;
}

/* Compute t -+ sqrt(s') (s' = s / 2^(2 sh)) in MPFR and measure lo, hi.
 * Precision: every end must be known to 2^-128 relative.  A first pass at
 * PREC0 bits; when t and sqrt(s') cancel (the end is 2^-c times the
 * larger of the two), again at c + PREC0 bits.  No end can be smaller than
 * 2^-5316 times the top unless it is 0: s' is a multiple of 2^-4296 and t
 * of 2^-1074, so t^2 - s' != 0 is at least 2^-4296 and the end is at least
 * that over |t| + sqrt(s') <= 2^1020.  PRECMAX covers it, and there s' is
 * held exactly. */
static void mp_row(ctx *k, const mpz_t s, unsigned long sh, double t,
                   double lo, double hi, rowres *r)
{
    mpfr_prec_t prec = PREC0;
    int exS, exR, exL, exH;
    memset(r, 0, sizeof *r);
    for (;;) {
        long top, need = 0;
        int ok = 1;
        mpfr_set_prec(k->S, prec);
        mpfr_set_prec(k->R, prec);
        mpfr_set_prec(k->T, prec);
        mpfr_set_prec(k->EL, prec);
        mpfr_set_prec(k->EH, prec);
        exS = mpfr_set_z(k->S, s, MPFR_RNDN);
        mpfr_div_2ui(k->S, k->S, 2 * sh, MPFR_RNDN); /* exact */
        exR = mpfr_sqrt(k->R, k->S, MPFR_RNDN);
        mpfr_set_d(k->T, t, MPFR_RNDN);               /* exact */
        exL = mpfr_sub(k->EL, k->T, k->R, MPFR_RNDN);
        exH = mpfr_add(k->EH, k->T, k->R, MPFR_RNDN);
        if (mpfr_zero_p(k->R)) break; /* both ends are t, exact */
        top = (long)mpfr_get_exp(k->R);
        if (!mpfr_zero_p(k->T) && (long)mpfr_get_exp(k->T) > top)
            top = (long)mpfr_get_exp(k->T);
        if (!(exS == 0 && exR == 0 && exL == 0)) {
            if (mpfr_zero_p(k->EL)) ok = 0, need = PRECMAX;
            else if (top - (long)mpfr_get_exp(k->EL) + 128 > (long)prec) {
                ok = 0;
                need = top - (long)mpfr_get_exp(k->EL);
            }
        }
        if (!(exS == 0 && exR == 0 && exH == 0)) {
            if (mpfr_zero_p(k->EH)) ok = 0, need = PRECMAX;
            else if (top - (long)mpfr_get_exp(k->EH) + 128 > (long)prec) {
                long nh = top - (long)mpfr_get_exp(k->EH);
                ok = 0;
                if (nh > need) need = nh;
            }
        }
        if (ok || prec >= PRECMAX) break;
        r->raised = 1;
        need += PREC0;
        prec = need > 2 * (long)prec ? (mpfr_prec_t)need : 2 * prec;
        if (prec > PRECMAX) prec = PRECMAX;
    }

    /* scale |t| + sqrt(s'), tiny when u * scale < 2^-1000 */
    mpfr_set_prec(k->D, prec + 8);
    mpfr_abs(k->D, k->T, MPFR_RNDN);
    mpfr_add(k->D, k->D, k->R, MPFR_RNDN);
    r->tiny = mpfr_cmp_ui_2exp(k->D, 1, -947) < 0;
    r->big = mpfr_cmp_ui_2exp(k->D, 1, -480) >= 0;
    /* cancellation: |end| < (|t| + sqrt(s'))/4 */
    r->cancel_lo = mpfr_zero_p(k->EL)
                   || mpfr_get_exp(k->EL) < mpfr_get_exp(k->D) - 2;
    r->cancel_hi = mpfr_zero_p(k->EH)
                   || mpfr_get_exp(k->EH) < mpfr_get_exp(k->D) - 2;
    /* the proven bound (specs/cbx_spec.h, ball_gap): 80 u scale + 2^-1064,
     * rounded up */
    mpfr_t P;
    mpfr_init2(P, 128);
    mpfr_mul_ui(P, k->D, 80, MPFR_RNDU);
    mpfr_mul_2si(P, P, -53, MPFR_RNDU);
    {
        mpfr_t E;
        mpfr_init2(E, 64);
        mpfr_set_ui_2exp(E, 1, -1064, MPFR_RNDN);
        mpfr_add(P, P, E, MPFR_RNDU);
        mpfr_clear(E);
    }
    /* D = u * scale + eta */
    mpfr_mul_2si(k->D, k->D, -53, MPFR_RNDN);
    mpfr_set_prec(k->G, 64);
    mpfr_set_ui_2exp(k->G, 1, -1074, MPFR_RNDN);
    mpfr_add(k->D, k->D, k->G, MPFR_RNDN);

    mpfr_set_prec(k->G, prec + 64);
    /* lower end: exact_lo - lo */
    mpfr_sub_d(k->G, k->EL, lo, MPFR_RNDN);
    r->exact_lo = mpfr_zero_p(k->G);
    r->over_proven = mpfr_cmp(k->G, P) > 0;
    r->bad_lo = mpfr_cmp_ui_2exp(k->G, 1, -1064) > 0;
    mpfr_mul_2si(k->G, k->G, -ulp_exp(k->EL), MPFR_RNDN);
    r->ulps_lo = mpfr_get_d(k->G, MPFR_RNDN);
    mpfr_sub_d(k->G, k->EL, lo, MPFR_RNDN);
    mpfr_div(k->G, k->G, k->D, MPFR_RNDN);
    r->units_lo = mpfr_get_d(k->G, MPFR_RNDN);
    r->bad_lo = r->bad_lo && r->units_lo > SANITY;
    /* upper end: hi - exact_hi */
    mpfr_set_d(k->T, hi, MPFR_RNDN);
    mpfr_sub(k->G, k->T, k->EH, MPFR_RNDN);
    r->exact_hi = mpfr_zero_p(k->G);
    r->over_proven |= mpfr_cmp(k->G, P) > 0;
    mpfr_clear(P);
    r->bad_hi = mpfr_cmp_ui_2exp(k->G, 1, -1064) > 0;
    mpfr_mul_2si(k->G, k->G, -ulp_exp(k->EH), MPFR_RNDN);
    r->ulps_hi = mpfr_get_d(k->G, MPFR_RNDN);
    mpfr_sub(k->G, k->T, k->EH, MPFR_RNDN);
    mpfr_div(k->G, k->G, k->D, MPFR_RNDN);
    r->units_hi = mpfr_get_d(k->G, MPFR_RNDN);
    r->bad_hi = r->bad_hi && r->units_hi > SANITY;
}

/* ---------------------------------------------------------------------- */
/* Points in the unit ball                                                */
/* ---------------------------------------------------------------------- */

/* p.p <= 1, exactly */
static int in_ball(ctx *k, const double p[3])
{
    int j;
    mpz_set_ui(k->w, 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_sh(k->z, p[j], 1074);
        mpz_addmul(k->w, k->z, k->z);
    }
    mpz_set_ui(k->z, 1);
    mpz_mul_2exp(k->z, k->z, 2148);
    return mpz_cmp(k->w, k->z) <= 0;
}

/* p = v/|v| rounded, nudged toward 0 until p.p <= 1 (at most 4 times).
 * v is given as f_j 2^e_j (f_j = 0 allowed).  Returns 0 if skipped. */
static int unit_point(ctx *k, const double f[3], const int e[3], double sign,
                      double p[3])
{
    int j, E = INT_MIN, tries;
    double n2 = 0, n;
    for (j = 0; j < 3; j++)
        if (f[j] != 0 && e[j] > E) E = e[j];
    if (E == INT_MIN) { p[0] = sign; p[1] = p[2] = 0; return 1; }
    for (j = 0; j < 3; j++) {
        p[j] = f[j] != 0 ? ldexp(f[j], e[j] - E) : 0.0; /* |p_j| < 1 */
        n2 += p[j] * p[j];
    }
    n = sqrt(n2);
    for (j = 0; j < 3; j++) p[j] = sign * (p[j] / n);
    for (tries = 0; tries < 4; tries++) {
        if (in_ball(k, p)) return 1;
        for (j = 0; j < 3; j++) p[j] = nextafter(p[j], 0.0);
    }
    return 0;
}

/* exact y = t + sum_j m_j p_j (sphere), scaled by 2^PT_SHIFT, in k->y */
static void sphere_image(ctx *k, const cbx_affine *a, int i, const double p[3])
{
    int j;
    xu_scaled_sh(k->y, a->m[i][3], PT_SHIFT);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(&k->x, k->z, a->m[i][j], p[j]); /* 2^2148 */
        mpz_mul_2exp(k->z, k->z, PT_SHIFT - 2148);
        mpz_add(k->y, k->y, k->z);
    }
}

/* exact y = c + sum_j rot_ij radii_j p_j, scaled by 2^PT_SHIFT */
static void ell_image(ctx *k, const double c[3], const double radii[3],
                      const double rot[3][3], int i, const double p[3])
{
    int j;
    xu_scaled_sh(k->y, c[i], PT_SHIFT);
    for (j = 0; j < 3; j++) {
        long e = xu_split_d(k->z, rot[i][j]);
        e += xu_split_d(k->w, radii[j]);
        mpz_mul(k->z, k->z, k->w);
        e += xu_split_d(k->w, p[j]);
        mpz_mul(k->z, k->z, k->w);
        mpz_mul_2exp(k->z, k->z, (mp_bitcnt_t)(e + (long)PT_SHIFT)); /* e >= -3222 */
        mpz_add(k->y, k->y, k->z);
    }
}

/* ---------------------------------------------------------------------- */
/* One call: status, special outputs, per-axis checks                     */
/* ---------------------------------------------------------------------- */

typedef struct problem {
    int ell;                 /* 0: sphere (a), 1: ellipsoid              */
    cbx_affine a;
    double center[3], radii[3], rot[3][3];
} problem;

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

static cbx_status prob_expected(const problem *P, int *oob)
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
            if (unit_point(k, f, e, s ? -1.0 : 1.0, pts[np])) np++;
            else g->pts_skipped++;
        }
    }
    for (n = 0; n < 2 && r; n++) {
        double f[3], rad;
        int e[3] = { 0, 0, 0 };
        for (j = 0; j < 3; j++)
            f[j] = xu_rng_unit(r) + xu_rng_unit(r) + xu_rng_unit(r) - 1.5;
        rad = n == 0 ? 1.0 : xu_rng_unit(r);
        if (unit_point(k, f, e, 1.0, pts[np])) {
            for (j = 0; j < 3; j++) pts[np][j] *= rad; /* rad <= 1 */
            if (in_ball(k, pts[np])) np++;
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
            if (P->ell) ell_image(k, P->center, P->radii, P->rot, i, pts[n]);
            else sphere_image(k, &P->a, i, pts[n]);
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
static int run_problem(ctx *k, group *g, const problem *P, cbx_box *out,
                       verdict *v, double *mx, xu_rng *r)
{
    problem P0 = *P;
    int i, oob, okmask = 0;
    char why[200];

    for (i = 0; i < 3; i++) out->lo[i] = out->hi[i] = NAN;
    v_init(v);
    v->got = prob_call(P, out);
    v->expected = prob_expected(P, &oob);
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
        if (P->ell) ell_s(k, P->radii, P->rot, i);
        else sphere_s(k, &P->a, i);
        v->applied[F_CONTAIN]++;
        lo_ok = xu_sqrt_lo_ok(&k->x, k->s[i], sh, t, out->lo[i]);
        hi_ok = xu_sqrt_hi_ok(&k->x, k->s[i], sh, t, out->hi[i]);
        mp_row(k, k->s[i], sh, t, out->lo[i], out->hi[i], &rr);
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

static void log_failure(const char *what, long id, const problem *P,
                        const cbx_box *out, const verdict *v)
{
    if (fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL %s %ld: %s (status %s, expected %s)\n", what, id, v->why,
           cbx_status_name(v->got), cbx_status_name(v->expected));
    print_problem(stdout, P);
    xu_print_box(stdout, "out", out);
}

/* ---------------------------------------------------------------------- */
/* Hard cases                                                             */
/* ---------------------------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
#define ID3 MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0))

/* 2 Rx(45) Rz(30): rows (2c, -2s, 0), (2as, 2ac, -2a), (2as, 2ac, 2a) with
 * c = cos 30, s = sin 30, a = cos 45 = sin 45 (rounded literals) */
#define RZX2_T(t0, t1, t2) \
    MAT(ROW(1.7320508075688772, -1.0, 0.0, t0), \
        ROW(0.7071067811865476, 1.224744871391589, -1.4142135623730951, t1), \
        ROW(0.7071067811865476, 1.224744871391589, 1.4142135623730951, t2))

typedef struct sph_case {
    const char *name;
    cbx_affine a;
    cbx_status expect;
    int oob;
} sph_case;

static const sph_case sph_hard[] = {
    /* the unit ball itself: exact box [-1, 1]^3 */
    { "identity (unit ball)", ID3, CBX_OK, 0 },
    /* radius 2, rotated 30 deg about z then 45 deg about x, t = (1, 2, 3) */
    { "radius 2, Rx(45) Rz(30), t = (1,2,3)",
      RZX2_T(1, 2, 3), CBX_OK, 0 },
    /* rank 2: a zero row (that axis is the point t = 5) */
    { "zero row (rank 2), t = 5",
      MAT(ROW(1, 2, 2, 0), ROW(0, 0, 0, 5), ROW(2, -1, 2, -1)), CBX_OK, 0 },
    /* rank 1: every row a multiple of (1, 2, 3) */
    { "rank 1 map",
      MAT(ROW(1, 2, 3, 0), ROW(-2, -4, -6, 1), ROW(0.1, 0.2, 0.30000000000000004, 2)),
      CBX_OK, 0 },
    /* all zeros with every sign: each axis is the point t (+-0) */
    { "all-zero map, signed zeros",
      MAT(ROW(-0.0, -0.0, -0.0, -0.0), ROW(0.0, -0.0, 0.0, 0.0), ROW(-0.0, 0.0, -0.0, 7)),
      CBX_OK, 0 },
    /* Pythagorean rows: sqrt(s) is an integer, the exact box is representable */
    { "Pythagorean rows: norms 7, 3, 13",
      MAT(ROW(2, 3, 6, 0.5), ROW(1, -2, 2, -1), ROW(3, 4, 12, 100)), CBX_OK, 0 },
    /* t = +-sqrt(s) exactly: an end is exactly 0 */
    { "t = +-sqrt(s): ends exactly 0",
      MAT(ROW(3, 4, 0, 5), ROW(3, 4, 0, -5), ROW(0, 0, 2, 2)), CBX_OK, 0 },
    /* t = -fl(sqrt(s)): the lower/upper end is a tiny rounding residue */
    { "t = -+fl(sqrt(s)): ends near 0",
      MAT(ROW(1, 1, 0, -1.4142135623730951), ROW(1, 1, 1, 1.7320508075688772),
          ROW(1e-8, 1, 0, -1)), CBX_OK, 0 },
    /* tiny-angle rotations: s = 1 + theta^2 rounds to 1, sqrt(s) > 1 */
    { "rotation 1e-8 about z",
      MAT(ROW(1.0, -1e-8, 0, 0), ROW(1e-8, 1.0, 0, 0), ROW(0, 0, 1, 0)), CBX_OK, 0 },
    { "rotation 1e-15 about x, translated",
      MAT(ROW(1, 0, 0, 5), ROW(0, 1.0, -1e-15, -1e15), ROW(0, 1e-15, 1.0, 0.25)),
      CBX_OK, 0 },
    { "rotation 1e-300 about y",
      MAT(ROW(1.0, 0, 1e-300, 0), ROW(0, 1, 0, 0), ROW(-1e-300, 0, 1.0, 0)), CBX_OK, 0 },
    /* a huge translation with a tiny radius: sqrt(s) far below ulp(t) */
    { "translation 1e15, radius 1e-10",
      MAT(ROW(1e-10, 0, 0, 1e15), ROW(0, 1e-10, 0, -1e15), ROW(0, 0, 1e-10, 1e15 + 0.125)),
      CBX_OK, 0 },
    /* t = 2^1018 with a subnormal radius: hi must step past 2^1018 */
    { "t = 2^1018, radius 2^-1074",
      MAT(ROW(0x1p-1074, 0, 0, 0x1p1018), ROW(0, 0x1p-1074, 0, -0x1p1018),
          ROW(0, 0, 0x1p-1074, 1)), CBX_OK, 0 },
    /* subnormal entries: s = 3 * 2^-2148 is far below the smallest double */
    { "subnormal entries",
      MAT(ROW(0x1p-1074, 0x1p-1074, 0x1p-1074, 0), ROW(0x1p-1074, 0, 0, 0x1p-1074),
          ROW(0x1.8p-1070, -0x1p-1060, 0x1p-1074, -0x1p-1060)), CBX_OK, 0 },
    /* entries 1e-200: squares underflow to 0 in binary64 */
    { "entries 1e-200 (squares underflow)",
      MAT(ROW(1e-200, 1e-200, 1e-200, 0), ROW(1e-200, 0, 0, 1), ROW(3e-160, 4e-160, 0, 0)),
      CBX_OK, 0 },
    /* 1e-300 next to 1e150 (1e150 < 2^509) */
    { "1e-300 next to 1e150",
      MAT(ROW(1e150, 1e-300, 0, 0), ROW(1e-300, 1e-300, 1e150, 1e300), ROW(1e-300, 0, 0, 0)),
      CBX_OK, 0 },
    /* 1e-200 next to 1e200: 1e200 > 2^509, row 0 out */
    { "1e-200 next to 1e200 (row 0 out)",
      MAT(ROW(1e200, 1e-200, 0, 0), ROW(1e-200, 1, 0, 0), ROW(0, 0, 1e-200, 0)),
      CBX_ERANGE, 1 },
    /* the domain limits themselves: entries 2^509, t = +-2^1018 */
    { "entries 2^509, t = +-2^1018",
      MAT(ROW(0x1p509, 0x1p509, 0x1p509, 0x1p1018),
          ROW(-0x1p509, 0x1p509, -0x1p509, -0x1p1018), ROW(0x1p509, 0, 0, 0)), CBX_OK, 0 },
    /* one ulp beyond */
    { "entry 2^509 + ulp (row 1 out)",
      MAT(ROW(0x1p509, 0, 0, 0), ROW(0, -P509U, 0, 0), ROW(0, 0, 1, 0)), CBX_ERANGE, 2 },
    { "t = 2^1018 + ulp (row 2 out)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, -P1018U)), CBX_ERANGE, 4 },
    { "t = DBL_MAX, entry inf (rows 0, 1 out)",
      MAT(ROW(1, 0, 0, DBL_MAX), ROW(0, INF, 0, 0), ROW(0, 0, 1, 0)), CBX_ERANGE, 3 },
    { "t = -inf (row 0 out)",
      MAT(ROW(1, 0, 0, -INF), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)), CBX_ERANGE, 1 },
    /* NaN: EINVAL wins over everything */
    { "NaN entry", MAT(ROW(1, 0, 0, 0), ROW(0, NAN, 0, 0), ROW(0, 0, 1, 0)), CBX_EINVAL, 0 },
    { "NaN t and inf entry",
      MAT(ROW(INF, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, -NAN)), CBX_EINVAL, 0 },
};
#define N_SPH_HARD ((int)(sizeof sph_hard / sizeof sph_hard[0]))

typedef struct ell_case {
    const char *name;
    double center[3], radii[3], rot[3][3];
    cbx_status expect;
    int oob;
} ell_case;

#define V3(a, b, c) { a, b, c }
#define R3(r0, r1, r2) { r0, r1, r2 }
#define RID R3(V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1))
/* Rx(45) Rz(30) */
#define RZX R3(V3(0.8660254037844387, -0.5, 0), \
               V3(0.3535533905932738, 0.6123724356957945, -0.7071067811865476), \
               V3(0.3535533905932738, 0.6123724356957945, 0.7071067811865476))
/* a rotation by 1e-300 about z, 1e-8 about z, 1e-15 about x */
#define RZ300 R3(V3(1.0, -1e-300, 0), V3(1e-300, 1.0, 0), V3(0, 0, 1))
#define RZ8 R3(V3(1.0, -1e-8, 0), V3(1e-8, 1.0, 0), V3(0, 0, 1))
#define RX15 R3(V3(1, 0, 0), V3(0, 1.0, -1e-15), V3(0, 1e-15, 1.0))

static const ell_case ell_hard[] = {
    /* unit sphere: exact [-1, 1]^3 */
    { "identity rot, unit radii", V3(0, 0, 0), V3(1, 1, 1), RID, CBX_OK, 0 },
    /* the demo's sphere as an ellipsoid: radius 2, Rx(45) Rz(30), (1,2,3) */
    { "radius 2, Rx(45) Rz(30), center (1,2,3)", V3(1, 2, 3), V3(2, 2, 2), RZX, CBX_OK, 0 },
    /* radii 1e-200 next to 1e200: 1e200 > 2^254, every axis out */
    { "radii 1e-200 next to 1e200 (all out)", V3(0, 0, 0), V3(1e-200, 1e200, 1), RZX,
      CBX_ERANGE, 7 },
    /* inside the domain: 1e-200 next to 1e70 */
    { "radii 1e-200 next to 1e70", V3(1, -1, 0), V3(1e-200, 1e70, 1), RZX, CBX_OK, 0 },
    /* 1e-300 next to 2^254 */
    { "radii 1e-300, 2^254, 1", V3(0, 0, 0x1p1018), V3(1e-300, 0x1p254, 1), RZX, CBX_OK, 0 },
    /* tiny-angle rotations */
    { "rotation 1e-8 about z, radii (1, 1e-3, 5)", V3(0, 0, 0), V3(1, 1e-3, 5), RZ8,
      CBX_OK, 0 },
    { "rotation 1e-15 about x, radii (3, 1e15, 1)", V3(5, -1e15, 0.25), V3(3, 1e15, 1),
      RX15, CBX_OK, 0 },
    { "rotation 1e-300 about z, radii (2^254, 1, 1)", V3(0, 0, 0),
      V3(0x1p254, 1, 1), RZ300, CBX_OK, 0 },
    /* a huge centre with tiny radii */
    { "center 1e15, radii 1e-10", V3(1e15, -1e15, 1e15 + 0.125), V3(1e-10, 1e-10, 1e-10),
      RZX, CBX_OK, 0 },
    /* degenerate radii: zero, -0.0, negative (a disc and a segment) */
    { "radii (0, -0.0, -3): a segment", V3(0, 0, 0), V3(0, -0.0, -3), RZX, CBX_OK, 0 },
    { "radii (-1, 2, 0): a disc", V3(1, 2, 3), V3(-1, 2, 0), RZX, CBX_OK, 0 },
    /* rank-deficient rot: a zero row, rank 1 */
    { "rot with a zero row", V3(1, 5, -1), V3(1, 2, 3),
      R3(V3(1, 2, 2), V3(0, -0.0, 0), V3(2, -1, 2)), CBX_OK, 0 },
    { "rot of rank 1", V3(0, 0, 0), V3(1, 0.5, 0.25),
      R3(V3(1, 2, 3), V3(-2, -4, -6), V3(0.1, 0.2, 0.30000000000000004)), CBX_OK, 0 },
    /* a shear: not orthogonal */
    { "shear rot", V3(0, 0, 0), V3(1, 1, 1),
      R3(V3(1, 1e3, 0), V3(0, 1, 1e-3), V3(0, 0, 1)), CBX_OK, 0 },
    /* subnormal rot and radii: a_ij = 2^-2148, sqrt(s) ~ 2^-2147 */
    { "subnormal rot and radii", V3(0, 0x1p-1074, -0.0), V3(0x1p-1074, 0x1p-1074, 0x1p-1074),
      R3(V3(0x1p-1074, 0x1p-1074, 0x1p-1074), V3(0x1p-1074, 0, 0), V3(0x1p-1060, 1, 0)),
      CBX_OK, 0 },
    /* the limits: rot 2^254, radii 2^254, center 2^1018 */
    { "rot, radii 2^254, center +-2^1018", V3(0x1p1018, -0x1p1018, 0), V3(0x1p254, -0x1p254, 0x1p254),
      R3(V3(0x1p254, 0x1p254, 0x1p254), V3(-0x1p254, 0x1p254, 0), V3(1, 1, 1)), CBX_OK, 0 },
    /* one ulp beyond each limit */
    { "rot entry 2^254 + ulp (axis 0 out)", V3(0, 0, 0), V3(1, 1, 1),
      R3(V3(0, P254U, 0), V3(0, 1, 0), V3(0, 0, 1)), CBX_ERANGE, 1 },
    { "radius 2^254 + ulp (all out)", V3(0, 0, 0), V3(1, -P254U, 1), RID, CBX_ERANGE, 7 },
    { "center 2^1018 + ulp (axis 2 out)", V3(0, 0, P1018U), V3(1, 1, 1), RID, CBX_ERANGE, 4 },
    /* infinities */
    { "center -inf (axis 1 out)", V3(0, -INF, 0), V3(1, 1, 1), RID, CBX_ERANGE, 2 },
    { "radius +inf (all out)", V3(0, 0, 0), V3(1, 1, INF), RID, CBX_ERANGE, 7 },
    /* signed zeros everywhere: each axis is the point center */
    { "signed zeros", V3(-0.0, 0.0, -0.0), V3(-0.0, 0.0, -0.0),
      R3(V3(-0.0, 1, -0.0), V3(1, -0.0, 0), V3(0, 0, -1)), CBX_OK, 0 },
    /* centre = +-sqrt(s) exactly: ends exactly 0 */
    { "center = +-sqrt(s): ends exactly 0", V3(5, -5, 0), V3(3, 4, 1),
      R3(V3(1, 1, 0), V3(1, 1, 0), V3(0, 0, 1)), CBX_OK, 0 },
    /* NaN */
    { "NaN radius", V3(0, 0, 0), V3(1, NAN, 1), RID, CBX_EINVAL, 0 },
    { "NaN rot entry", V3(0, 0, 0), V3(1, 1, 1),
      R3(V3(1, 0, 0), V3(0, 1, 0), V3(0, NAN, 1)), CBX_EINVAL, 0 },
    { "NaN center and inf radius", V3(0, -NAN, 0), V3(INF, 1, 1), RID, CBX_EINVAL, 0 },
};
#define N_ELL_HARD ((int)(sizeof ell_hard / sizeof ell_hard[0]))

/* ---------------------------------------------------------------------- */
/* Random generation                                                      */
/* ---------------------------------------------------------------------- */

/* a rotation by a tiny angle (1e-8 .. 1e-300) about a random axis */
static void gen_tiny_rotation(xu_rng *r, double R[3][3])
{
    static const double ang[] = { 1e-8, 1e-15, 1e-300, 1e-20, 1e-100, 1e-4 };
    double th = ang[xu_rng_int(r, 0, 5)] * (0.5 + xu_rng_unit(r));
    /* Taylor series in + and * only (correctly rounded everywhere, so the
     * same doubles on every architecture; libm's cos and sin are not):
     * th <= 1.5e-4, so the omitted terms are below an ulp */
    double t2 = th * th;
    double c = 1.0 - t2 / 2.0 + t2 * t2 / 24.0, s = th - th * t2 / 6.0;
    int ax = xu_rng_int(r, 0, 2), u = (ax + 1) % 3, v = (ax + 2) % 3, i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) R[i][j] = i == j ? 1.0 : 0.0;
    R[u][u] = c; R[u][v] = -s;
    R[v][u] = s; R[v][v] = c;
}

/* a 3x3 "linear part" for either function; entries within 2^emax */
static void gen_linear(xu_rng *r, double L[3][3], int emax)
{
    int i, j, mode = xu_rng_int(r, 0, 99);
    if (mode < 40) { /* rotation times one scale or per-column scales */
        int per_col = xu_rng_int(r, 0, 1), e = xu_rng_int(r, -1074, emax - 1);
        double sc[3];
        xu_rand_rotation(r, L);
        for (j = 0; j < 3; j++)
            sc[j] = per_col ? xu_gen_mag(r, -1074, emax - 1) : ldexp(1.0, e);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] *= sc[j];
    } else if (mode < 50) { /* tiny-angle rotation, scaled */
        double sc = ldexp(1.0, xu_rng_int(r, -1000, emax - 1));
        gen_tiny_rotation(r, L);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] *= sc;
    } else if (mode < 65) { /* narrow random: comparable entries */
        int P = xu_rng_int(r, -1070, emax);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] = xu_gen_signed(r, P - 4, P);
    } else if (mode < 80) { /* wide random: exponents spread */
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] = xu_gen_signed(r, -1074, emax);
    } else if (mode < 90) { /* rank deficient */
        double v[3];
        int kind = xu_rng_int(r, 0, 2);
        for (j = 0; j < 3; j++) v[j] = xu_gen_signed(r, emax - 60, emax - 8);
        for (i = 0; i < 3; i++) {
            double f;
            if (kind == 0) { /* the exponent first: gcc's x86-64 argument order, made explicit */
                int e = -xu_rng_int(r, 0, 8);
                f = ldexp(xu_rng_sign(r), e);
            } else {
                f = xu_rng_unit(r) - 0.5;
            }
            for (j = 0; j < 3; j++) L[i][j] = f * v[j];
        }
        if (kind == 2) { /* plus a zero row */
            i = xu_rng_int(r, 0, 2);
            for (j = 0; j < 3; j++) L[i][j] = xu_rng_sign(r) * 0.0;
        }
    } else { /* signed permutation times scales, with signed zeros */
        int p = xu_rng_int(r, 0, 5);
        static const int perm[6][3] = { {0,1,2}, {0,2,1}, {1,0,2}, {1,2,0}, {2,0,1}, {2,1,0} };
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++)
                L[i][j] = j == perm[p][i] ? xu_gen_signed(r, -1074, emax)
                                          : xu_rng_sign(r) * 0.0;
    }
}

/* translation for row i given the exact s (scaled by 2^(2 sh)) */
static double gen_t(xu_rng *r, ctx *k, const mpz_t s, unsigned long sh)
{
    int p = xu_rng_int(r, 0, 99);
    double q;
    if (p < 15) { /* -+fl(sqrt(s)): an end nearly cancels */
        q = sqrt_rn(k, s, sh);
        if (xu_rng_int(r, 0, 3) == 0) q = nextafter(q, xu_rng_sign(r) * INF);
        return xu_rng_sign(r) * q;
    }
    if (p < 25) return xu_rng_sign(r) * 0.0;
    if (p < 45) { /* comparable with sqrt(s) */
        int e;
        q = sqrt_rn(k, s, sh);
        if (q == 0) return xu_gen_signed(r, -1074, 1018);
        frexp(q, &e);
        return xu_gen_signed(r, e - 8, e + 8 < 1018 ? e + 8 : 1018);
    }
    if (p < 55) return xu_gen_signed(r, 40, 1018); /* huge vs the radius */
    return xu_gen_signed(r, -1074, 1018);
}

static void gen_sphere(xu_rng *r, ctx *k, problem *P)
{
    double L[3][3];
    int i, j, p = xu_rng_int(r, 0, 999);
    memset(P, 0, sizeof *P);
    P->ell = 0;
    if (xu_rng_int(r, 0, 9) == 0) { /* tiny radius, huge translation */
        gen_linear(r, L, -20);
    } else {
        gen_linear(r, L, 509);
    }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) P->a.m[i][j] = L[i][j];
        sphere_s(k, &P->a, i);
        P->a.m[i][3] = gen_t(r, k, k->s[i], SH_SPHERE);
    }
    i = xu_rng_int(r, 0, 2);
    j = xu_rng_int(r, 0, 2);
    if (p < 100) { /* to or beyond the domain's edge */
        switch (xu_rng_int(r, 0, 6)) {
        case 0: P->a.m[i][j] = xu_rng_sign(r) * P509U; break;
        case 1: P->a.m[i][j] = xu_rng_sign(r) * 0x1p509; break; /* in */
        case 2: P->a.m[i][j] = xu_gen_signed(r, 509, 1023); break;
        case 3: P->a.m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF; break;
        case 4: P->a.m[i][3] = xu_rng_sign(r) * P1018U; break;
        case 5: P->a.m[i][3] = xu_rng_sign(r) * 0x1p1018; break; /* in */
        default: P->a.m[i][3] = xu_rng_sign(r) * (xu_rng_int(r, 0, 1) ? DBL_MAX
                                                  : xu_gen_mag(r, 1018, 1023));
            break;
        }
    } else if (p < 115) {
        P->a.m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * NAN;
    }
}

static void gen_ellipsoid(xu_rng *r, ctx *k, problem *P)
{
    double L[3][3];
    int i, j, p = xu_rng_int(r, 0, 999), mode = xu_rng_int(r, 0, 9);
    memset(P, 0, sizeof *P);
    P->ell = 1;
    if (mode < 6) { /* a rotation, optionally scaled */
        if (xu_rng_int(r, 0, 3)) xu_rand_rotation(r, L);
        else gen_tiny_rotation(r, L);
        if (xu_rng_int(r, 0, 2) == 0) {
            double sc = ldexp(1.0, xu_rng_int(r, -1074, 253));
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) L[i][j] *= sc;
        }
    } else {
        gen_linear(r, L, 254);
    }
    memcpy(P->rot, L, sizeof L);
    switch (xu_rng_int(r, 0, 5)) {
    case 0: /* a sphere */
        P->radii[0] = P->radii[1] = P->radii[2] = xu_gen_signed(r, -1074, 254);
        break;
    case 1: { /* comparable radii */
        int e = xu_rng_int(r, -1070, 254);
        for (j = 0; j < 3; j++) P->radii[j] = xu_gen_signed(r, e - 6, e);
        break;
    }
    case 2: /* extreme ratio: 1e-200-like next to 1e70-like */
        P->radii[0] = xu_gen_signed(r, -1074, -600);
        P->radii[1] = xu_gen_signed(r, 200, 254);
        P->radii[2] = xu_gen_signed(r, -1074, 254);
        break;
    case 3: /* tiny radii (huge centres below) */
        for (j = 0; j < 3; j++) P->radii[j] = xu_gen_signed(r, -1074, -20);
        break;
    default:
        for (j = 0; j < 3; j++) P->radii[j] = xu_gen_signed(r, -1074, 254);
        break;
    }
    for (i = 0; i < 3; i++) {
        /* double[3][3] -> const double (*)[3] needs a cast in ISO C < C2X */
        ell_s(k, P->radii, (const double (*)[3])P->rot, i);
        P->center[i] = gen_t(r, k, k->s[i], SH_ELL);
    }
    i = xu_rng_int(r, 0, 2);
    j = xu_rng_int(r, 0, 2);
    if (p < 100) {
        switch (xu_rng_int(r, 0, 8)) {
        case 0: P->rot[i][j] = xu_rng_sign(r) * P254U; break;
        case 1: P->rot[i][j] = xu_rng_sign(r) * 0x1p254; break; /* in */
        case 2: P->radii[j] = xu_rng_sign(r) * P254U; break;
        case 3: P->radii[j] = xu_rng_sign(r) * 0x1p254; break;  /* in */
        case 4: P->center[i] = xu_rng_sign(r) * P1018U; break;
        case 5: P->center[i] = xu_rng_sign(r) * 0x1p1018; break; /* in */
        case 6: P->rot[i][j] = xu_gen_signed(r, 254, 1023); break;
        case 7: P->radii[j] = xu_gen_signed(r, 254, 1023); break;
        default:
            switch (xu_rng_int(r, 0, 2)) {
            case 0: P->rot[i][j] = xu_rng_sign(r) * INF; break;
            case 1: P->radii[j] = xu_rng_sign(r) * INF; break;
            default: P->center[i] = xu_rng_sign(r) * INF; break;
            }
            break;
        }
    } else if (p < 115) {
        double nan = xu_rng_sign(r) * NAN;
        switch (xu_rng_int(r, 0, 2)) {
        case 0: P->rot[i][j] = nan; break;
        case 1: P->radii[j] = nan; break;
        default: P->center[i] = nan; break;
        }
    }
}

/* ---------------------------------------------------------------------- */
/* Drivers                                                                */
/* ---------------------------------------------------------------------- */

static void hard_row(ctx *k, group *g, const char *what, int h, const char *name,
                     const problem *P, cbx_status expect, int oob_tab)
{
    cbx_box out;
    verdict v;
    double mx;
    int oob;
    run_problem(k, g, P, &out, &v, &mx, NULL);
    if (prob_expected(P, &oob) != expect || oob != oob_tab) {
        if (!v.failed)
            snprintf(v.why, sizeof v.why, "table says %s/oob %d, oracle oob %d",
                     cbx_status_name(expect), oob_tab, oob);
        v.failed = 1;
    }
    g_add(g, &v);
    printf("  %-46s %-10s max units %9.4g  %s\n", name, cbx_status_name(v.got), mx,
           v.failed ? "FAIL" : "ok");
    if (v.failed) log_failure(what, h, P, &out, &v);
}

static void run_sphere(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    fail_logs = 0;
    printf("-- cbx_sphere_box: hard cases (%d) --\n", N_SPH_HARD);
    for (h = 0; h < N_SPH_HARD; h++) {
        problem P;
        memset(&P, 0, sizeof P);
        P.a = sph_hard[h].a;
        hard_row(k, gh, "sphere hard", h, sph_hard[h].name, &P, sph_hard[h].expect,
                 sph_hard[h].oob);
    }
    r.s = seed;
    for (c = 0; c < n; c++) {
        problem P;
        cbx_box out;
        verdict v;
        double mx;
        gen_sphere(&r, k, &P);
        if (run_problem(k, gr, &P, &out, &v, &mx, &r))
            log_failure("sphere random", c, &P, &out, &v);
        g_add(gr, &v);
    }
}

static void run_ellipsoid(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    fail_logs = 0;
    printf("-- cbx_ellipsoid_box: hard cases (%d) --\n", N_ELL_HARD);
    for (h = 0; h < N_ELL_HARD; h++) {
        const ell_case *e = &ell_hard[h];
        problem P;
        memset(&P, 0, sizeof P);
        P.ell = 1;
        memcpy(P.center, e->center, sizeof P.center);
        memcpy(P.radii, e->radii, sizeof P.radii);
        memcpy(P.rot, e->rot, sizeof P.rot);
        hard_row(k, gh, "ellipsoid hard", h, e->name, &P, e->expect, e->oob);
    }
    r.s = seed ^ UINT64_C(0xe111950d);
    for (c = 0; c < n; c++) {
        problem P;
        cbx_box out;
        verdict v;
        double mx;
        gen_ellipsoid(&r, k, &P);
        if (run_problem(k, gr, &P, &out, &v, &mx, &r))
            log_failure("ellipsoid random", c, &P, &out, &v);
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
    long n = (long)arg_num(argc, argv, 1, 200000ULL);
    uint64_t seed = (uint64_t)arg_num(argc, argv, 2, 0x5fe5eed0e11ULL);
    ctx k;
    group g[4];
    long passed = 0, failed = 0;
    int i;
    clock_t t0 = clock();

    ctx_init(&k);
    g_init(&g[0], "cbx_sphere_box, hard cases");
    g_init(&g[1], "cbx_sphere_box, random cases");
    g_init(&g[2], "cbx_ellipsoid_box, hard cases");
    g_init(&g[3], "cbx_ellipsoid_box, random cases");
    printf("test_sphere: N = %ld random cases per function, seed 0x%llx, sanity "
           "bound %g units, MPFR %d bits (up to %d on cancellation)\n\n", n,
           (unsigned long long)seed, SANITY, PREC0, PRECMAX);
    run_sphere(&k, &g[0], &g[1], n, seed);
    run_ellipsoid(&k, &g[2], &g[3], n, seed);
    printf("\n");
    for (i = 0; i < 4; i++) {
        g_print(&g[i]);
        passed += g[i].cases - g[i].failed;
        failed += g[i].failed;
    }
    printf("units = gap / (u*(|t| + sqrt(s)) + 2^-1074); ulps = gap / ulp(exact end); "
           "\"no cancellation\" = |exact end| >= (|t| + sqrt(s))/4\n");
    printf("CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    ctx_clear(&k);
    mpfr_free_cache();
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
