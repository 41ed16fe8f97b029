/*
 * test_tight [N_THOUSANDS] [seed]: cbx_transform_box_tight against exact
 * arithmetic (GMP fixed point, cross-checked with MPFR and mpq_t).
 *
 * The promise checked (certbox.h): the same status, special outputs and
 * infinite ends as cbx_transform_box on the same input, and every FINITE
 * end the tightest double,
 *     lo_i = RD(E_lo),   hi_i = RU(E_hi),
 * with E the exact value at the end's vertex (exact_util.h rule B: v_j =
 * lo_j for m_j > 0, hi_j for m_j < 0, 0 for m_j == 0; mirrored for the
 * upper end).  On a full row E is the exact bound L_i = t + sum_j
 * min(m_j lo_j, m_j hi_j) (resp. H_i): checked to agree on a subset.
 *
 * Documented exception (certbox.h): an end whose vertex has a nonzero
 * product |m_j v_j| below 2^-968 ("tiny"), or where a magnitude above
 * 2^1015 occurs ("big": |t|, some |m_j v_j| or |E| above 2^1015) may keep
 * cbx_transform_box's end.  There only containment and "never looser than
 * cbx_transform_box" are required; such ends are counted (optimal anyway /
 * the kernel's end / in between).  Non-optimal ends in the exception whose
 * largest magnitude is in (2^1015, 2^1016] are counted apart (allowed by
 * certbox.h's 2^1015, not by a 2^1016 reading).
 *
 * Per case (every check below failing fails the case):
 *   status   tight status == cbx_transform_box's status;
 *   oracle   exact_util's xu_check_result on the tight output: the whole
 *            cbx_transform_box promise (expected status, every field
 *            written, EINVAL / EMPTY outputs, end kinds A F U L W,
 *            containment, proven tightness 12 u S + 2^-1065; mpq corner
 *            checks on every 16th case);
 *   kinds    EINVAL / EMPTY output bit-identical to cbx_transform_box's;
 *            each end infinite exactly where cbx_transform_box's is, and
 *            then bit-identical to it;
 *   contain  each finite lo <= E (hi >= E), exactly (mpz);
 *   looser   lo >= cbx_transform_box's lo (hi <= its hi);
 *   optimal  nextafter(lo, +inf) > E (hi: nextafter(hi, -inf) < E), mpz,
 *            i.e. 0 ulp from RD(E); required outside the exception;
 *   cross    the same optimality decided independently by MPFR (RD / RU
 *            of E in binary64 with subnormals) agrees; on every 8th case
 *            also E recomputed with mpq_t from the vertex, and on full
 *            rows E == the fixed-point L / H of xu_row_bounds;
 *   inplace  on every 4th case cbx_transform_box_tight(a, &b, &b) gives the
 *            same status and bits as the separate output;
 *   inputs   *a and *in unchanged by the call.
 *
 * Sections (N = N_THOUSANDS * 1000, default N_THOUSANDS = 30):
 *   0 hard cases (a table: permutations, 0.1 * 3, exact cancellation,
 *     subnormal results, the boundaries 2^-968 and 2^1015 of the exception);
 *   1 N random full rows over wide exponent ranges (products from 2^-1074
 *     to 2^1018, rows of one scale and rows of mixed scales);
 *   2 N integer-valued and small dyadic inputs (the exact end is often a
 *     double: lo must then equal it), permutations / sign flips, large
 *     integers (sums not representable), powers of two with wide spreads,
 *     all of these scaled by powers of two;
 *   3 N heavy cancellation rows: t = -fl(m.v) (+- a few ulps), exact
 *     cancellation of two products (m_1 v_1 = -m_0 v_0) with a tiny rest,
 *     t = -fl(m_0 v_0) (E = the rounding error of a product), results in
 *     the subnormal range;
 *   4 N/2 half-space / infinite-end boxes, huge (out-of-domain) ends,
 *     zero and -0.0 coefficients, infinite map entries, NaN, empty boxes;
 *   5 N/4 inputs near the exception's boundaries (products around 2^-968,
 *     magnitudes around 2^1015 .. 2^1001).
 * Printed per section and in total: cases, statuses, end kinds, finite
 * ends checked, containment / optimality failures, exception counts; the
 * first failures with their inputs in hex (%a).  Last line "N passed,
 * M failed" (cases); exit status 1 on any failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <time.h>
#include <gmp.h>
#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"
#include "cbx_eft.h" /* only CBX_TWO_PROD_NAME: the form this build's flags select */

#define INF HUGE_VAL
#define MAX_FAIL_LOGS 25
#define ORACLE_CORNER_EVERY 16
#define MPQ_EVERY 8
#define INPLACE_EVERY 4

/* ---------------------------------------------------------------------- */
/* Context and statistics                                                 */
/* ---------------------------------------------------------------------- */

typedef struct tctx {
    xu_exact x;
    mpz_t E, p, tiny, big, big1000, smallE, near967;
    mpq_t q, qa, qb;
    mpfr_t r53;
    xu_rng rng;
    long logs, cat_logs[4], notes;
} tctx;

enum { C_STATUS, C_ORACLE, C_KINDS, C_CONTAIN, C_LOOSER, C_OPTIMAL, C_CROSS,
       C_INPLACE, C_INPUTS, NC };
static const char *const c_name[NC] = { "status", "oracle", "kinds", "contain", "looser",
                                        "optimal", "cross", "inplace", "inputs" };
static const char *const c_unit[NC] = { "cases", "cases", "cases", "finite ends",
                                        "finite ends", "ends outside exc.", "finite ends",
                                        "cases", "cases" };

typedef struct sec {
    const char *title;
    long cases, failed;
    long status_seen[4];         /* by the status cbx_transform_box gave    */
    long kind[XU_NEND];          /* end kinds (inputs without NaN, not empty) */
    long fin;                    /* finite ends checked exactly              */
    long fin_exact;              /* E is a double: the end equals it        */
    long tightened;              /* tight end != cbx_transform_box's end     */
    long nc_ends;                /* ends with 4 |E| >= S > 0 (no cancellation) */
    double base_ulps_max, base_ulps_sum; /* there: cbx_transform_box's end
                                    minus the tight one, in ulps of E      */
    long exc, exc_tiny, exc_big; /* ends in the documented exception         */
    long exc_opt, exc_kernel, exc_between, exc_nonopt_999;
    long checked[NC], fail[NC];
    /* optimality failures outside the exception, by a guess at the cause */
    long opt_near968;            /* smallest nonzero |m_j v_j| in [2^-968, 2^-967) */
    long opt_tiny_e;             /* 0 < |E| < 2^-900                         */
    long opt_other;
    long opt_between;            /* of all those: tighter than cbx_transform_box's end, yet not the tightest */
    long opt_exact_e;            /* of all those: E is a double (the end should be E) */
    long near968_maxlog;         /* largest floor(log2) of that product     */
    long tiny_e_maxlog;          /* largest floor(log2 |E|) in that bucket  */
} sec;

static int case_failed;
static char case_why[512];
/* log category of the case's first failure: 0 not an optimality failure,
 * 1 product near 2^-968, 2 0 < |E| < 2^-900, 3 other optimality failure */
static int case_cat, pend_cat;
static char case_detail[4096];   /* details of the non-optimal ends */
#define LOGS_PER_CAT 8

static void cfail(sec *s, int c, const char *why)
{
    s->fail[c]++;
    if (!case_failed) {
        case_cat = c == C_OPTIMAL ? pend_cat : 0;
        strncpy(case_why, why, sizeof case_why - 1);
        case_why[sizeof case_why - 1] = '\0';
    }
    case_failed = 1;
}

/* doubles in order: the difference of two is their distance in ulps
 * (both zeros map to 0) */
static int64_t ord(double d)
{
    int64_t b;
    memcpy(&b, &d, sizeof b);
    return b < 0 ? -(b & INT64_MAX) : b;
}

static long ulps_between(double a, double b)
{
    int64_t d = ord(a) - ord(b);
    return (long)(d < 0 ? -d : d);
}

/* RD (up = 0) or RU (up = 1) of E / 2^XU_SHIFT in binary64, subnormals
 * included, by MPFR (independent of the mpz comparisons). */
static double round_E(tctx *k, const mpz_t E, int up)
{
    mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
    mpfr_rnd_t rnd = up ? MPFR_RNDU : MPFR_RNDD;
    int inex;
    double d;
    mpfr_set_emin(-1073);
    mpfr_set_emax(1024);
    inex = mpfr_set_z_2exp(k->r53, E, -(mpfr_exp_t)XU_SHIFT, rnd);
    inex = mpfr_subnormalize(k->r53, inex, rnd);
    (void)inex;
    d = mpfr_get_d(k->r53, rnd);
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
    return d;
}

/* ---------------------------------------------------------------------- */
/* One finite end                                                         */
/* ---------------------------------------------------------------------- */

static void check_finite_end(tctx *k, sec *s, const cbx_affine *a, const cbx_box *in,
                             int i, int up, double bt, double tt, int deep)
{
    double v[3], nb, rd;
    int j, contain, opt, opt2, tiny = 0, big = 0, big1000 = 0, near968 = 0, cmp;
    long near_log = -100000;
    char why[512];
    const char *nm = up ? "hi" : "lo";
    double gap, ulp;

    if (!xu_vertex(a, in, i, up, v)) {
        snprintf(why, sizeof why, "axis %d %s: finite end %a but the image is unbounded "
                 "there", i, nm, tt);
        cfail(s, C_KINDS, why);
        return;
    }
    xu_vertex_bounds(&k->x, a, in, i, up);
    mpz_set(k->E, up ? k->x.H : k->x.L);
    s->fin++;

    /* the exception */
    xu_scaled_d(&k->x, k->p, a->m[i][3]);
    if (mpz_cmpabs(k->p, k->big) > 0) big = 1;
    if (mpz_cmpabs(k->p, k->big1000) > 0) big1000 = 1;
    for (j = 0; j < 3; j++) {
        if (a->m[i][j] == 0 || v[j] == 0) continue;
        xu_scaled_mul(&k->x, k->p, a->m[i][j], v[j]);
        if (mpz_cmpabs(k->p, k->tiny) < 0) tiny = 1;
        else if (mpz_cmpabs(k->p, k->near967) < 0) {
            long lg = (long)mpz_sizeinbase(k->p, 2) - 1 - XU_SHIFT;
            near968 = 1;
            if (lg > near_log) near_log = lg;
        }
        if (mpz_cmpabs(k->p, k->big) > 0) big = 1;
        if (mpz_cmpabs(k->p, k->big1000) > 0) big1000 = 1;
    }
    if (mpz_cmpabs(k->E, k->big) > 0) big = 1;
    if (mpz_cmpabs(k->E, k->big1000) > 0) big1000 = 1;

    /* containment, never looser, optimality: exact (mpz) */
    cmp = xu_cmp_scaled_d(&k->x, k->E, tt); /* sign(E - tt) */
    contain = up ? cmp <= 0 : cmp >= 0;
    s->checked[C_CONTAIN]++;
    if (!contain) {
        snprintf(why, sizeof why, "axis %d %s: NOT CONTAINED: end %a is %s the exact value",
                 i, nm, tt, up ? "below" : "above");
        cfail(s, C_CONTAIN, why);
    }
    s->checked[C_LOOSER]++;
    if (up ? !(tt <= bt) : !(tt >= bt)) {
        snprintf(why, sizeof why, "axis %d %s: looser than cbx_transform_box: %a vs %a", i, nm,
                 tt, bt);
        cfail(s, C_LOOSER, why);
    }
    if (cmp == 0) s->fin_exact++;
    nb = nextafter(tt, up ? -INF : INF);
    if (!isfinite(nb)) opt = contain;
    else {
        int c2 = xu_cmp_scaled_d(&k->x, k->E, nb);
        opt = contain && (up ? c2 > 0 : c2 < 0);
    }
    /* the same decided by MPFR */
    rd = round_E(k, k->E, up);
    opt2 = tt == rd;
    s->checked[C_CROSS]++;
    if (contain && opt != opt2) {
        snprintf(why, sizeof why, "axis %d %s: oracles disagree: mpz says %s, MPFR rounds E "
                 "to %a, end %a", i, nm, opt ? "optimal" : "not optimal", rd, tt);
        cfail(s, C_CROSS, why);
    }
    if (tt != bt) s->tightened++;
    /* cbx_transform_box's extra width in ulps of E, where E is not small
     * against the scale S of the row (4 |E| >= S, E != 0; S of the full
     * row for rule A as in cbx_transform_box's bound, S_v for rule B) */
    if (xu_row_in_domain(a, in, i)) xu_row_bounds(&k->x, a, in, i);
    mpz_mul_2exp(k->p, k->E, 2);
    if (mpz_sgn(k->E) != 0 && mpz_cmpabs(k->p, k->x.S) >= 0) {
        gap = fabs(bt - tt);
        ulp = tt == 0 ? 0x1p-1074 : ldexp(1.0, ilogb(tt) - 52 < -1074 ? -1074 : ilogb(tt) - 52);
        s->nc_ends++;
        s->base_ulps_sum += gap / ulp;
        if (gap / ulp > s->base_ulps_max) s->base_ulps_max = gap / ulp;
    }

    if (tiny || big) {
        s->exc++;
        if (tiny) s->exc_tiny++;
        if (big) s->exc_big++;
        if (opt) s->exc_opt++;
        else {
            if (tt == bt) s->exc_kernel++;
            else s->exc_between++;
            if (!tiny && !big1000) {
                s->exc_nonopt_999++;
                if (k->notes++ < 3) {
                    printf("NOTE (in the exception, not a failure) %s: axis %d %s not optimal, "
                           "largest magnitude in (2^1015, 2^1016]: end %a, tightest %a\n",
                           s->title, i, nm, tt, rd);
                    xu_print_case(stdout, a, in);
                }
            }
        }
    } else {
        s->checked[C_OPTIMAL]++;
        if (!opt) {
            int tiny_e = mpz_sgn(k->E) != 0 && mpz_cmpabs(k->E, k->smallE) < 0;
            if (near968) {
                s->opt_near968++;
                if (near_log > s->near968_maxlog) s->near968_maxlog = near_log;
            } else if (tiny_e) {
                long lg = (long)mpz_sizeinbase(k->E, 2) - 1 - XU_SHIFT;
                s->opt_tiny_e++;
                if (lg > s->tiny_e_maxlog) s->tiny_e_maxlog = lg;
            } else s->opt_other++;
            pend_cat = near968 ? 1 : tiny_e ? 2 : 3;
            if (tt != bt) s->opt_between++;
            if (cmp == 0) s->opt_exact_e++;
            snprintf(why, sizeof why, "axis %d %s: NOT OPTIMAL: end %a, tightest %a (%ld ulps "
                     "off), cbx_transform_box %a%s%s", i, nm, tt, rd, ulps_between(tt, rd), bt,
                     near968 ? "; a product in [2^-968, 2^-967)" : "",
                     tiny_e ? "; 0 < |E| < 2^-900" : "");
            cfail(s, C_OPTIMAL, why);
            {
                size_t l = strlen(case_detail);
                if (l + 200 < sizeof case_detail) {
                    mpfr_t f;
                    mpfr_init2(f, 128);
                    mpfr_set_z_2exp(f, k->E, -(mpfr_exp_t)XU_SHIFT, MPFR_RNDN);
                    mpfr_snprintf(case_detail + l, sizeof case_detail - l,
                                  "  (not optimal: axis %d %s, vertex (%a, %a, %a), E ~ %.32Ra "
                                  "(%.25Rg))\n", i, nm, v[0], v[1], v[2], f, f);
                    mpfr_clear(f);
                }
            }
        }
    }

    if (deep) { /* E again with mpq_t only, and the full-row L / H */
        mpq_set_d(k->q, a->m[i][3]);
        for (j = 0; j < 3; j++) {
            if (a->m[i][j] == 0) continue;
            mpq_set_d(k->qa, a->m[i][j]);
            mpq_set_d(k->qb, v[j]);
            mpq_mul(k->qa, k->qa, k->qb);
            mpq_add(k->q, k->q, k->qa);
        }
        xu_scaled_to_q(k->qa, k->E);
        if (!mpq_equal(k->q, k->qa)) {
            snprintf(why, sizeof why, "axis %d %s: mpq vertex value != fixed-point E", i, nm);
            cfail(s, C_CROSS, why);
        }
        mpq_set_d(k->qb, tt);
        if (up ? mpq_cmp(k->qb, k->q) < 0 : mpq_cmp(k->qb, k->q) > 0) {
            snprintf(why, sizeof why, "axis %d %s: mpq says not contained", i, nm);
            cfail(s, C_CROSS, why);
        }
        if (isfinite(nb)) {
            mpq_set_d(k->qb, nb);
            if ((up ? mpq_cmp(k->qb, k->q) < 0 : mpq_cmp(k->qb, k->q) > 0) != (opt != 0)
                && contain) {
                snprintf(why, sizeof why, "axis %d %s: mpq optimality differs from mpz", i, nm);
                cfail(s, C_CROSS, why);
            }
        }
        if (xu_row_in_domain(a, in, i)) {
            xu_row_bounds(&k->x, a, in, i);
            if (mpz_cmp(k->E, up ? k->x.H : k->x.L) != 0) {
                snprintf(why, sizeof why, "axis %d %s: full row, vertex value != xu_row_bounds",
                         i, nm);
                cfail(s, C_CROSS, why);
            }
        }
    }
}

/* ---------------------------------------------------------------------- */
/* One case                                                               */
/* ---------------------------------------------------------------------- */

static void run_case(tctx *k, sec *s, const cbx_affine *a, const cbx_box *in)
{
    cbx_affine a0 = *a;
    cbx_box in0 = *in, base, out, b2;
    cbx_status sb, st;
    xu_verdict v;
    int i, up;
    long idx = s->cases;
    char why[300];

    case_failed = 0;
    case_cat = 0;
    case_why[0] = '\0';
    case_detail[0] = '\0';
    s->cases++;
    for (i = 0; i < 3; i++) {
        base.lo[i] = base.hi[i] = NAN;
        out.lo[i] = out.hi[i] = NAN;
    }
    sb = cbx_transform_box(&a0, &in0, &base);
    st = cbx_transform_box_tight(a, in, &out);

    s->checked[C_INPUTS]++;
    if (memcmp(&a0, a, sizeof a0) || memcmp(&in0, in, sizeof in0))
        cfail(s, C_INPUTS, "the call modified its inputs");
    if (xu_status_index(sb) >= 0) s->status_seen[xu_status_index(sb)]++;

    s->checked[C_STATUS]++;
    if (st != sb) {
        snprintf(why, sizeof why, "status %s, cbx_transform_box gives %s", cbx_status_name(st),
                 cbx_status_name(sb));
        cfail(s, C_STATUS, why);
    }
    s->checked[C_ORACLE]++;
    if (xu_check_result(&k->x, &a0, &in0, &out, st, idx % ORACLE_CORNER_EVERY == 0, &v)) {
        snprintf(why, sizeof why, "oracle: %s", v.why);
        cfail(s, C_ORACLE, why);
    }

    s->checked[C_KINDS]++;
    if (sb == CBX_EINVAL || sb == CBX_EMPTY || xu_has_nan(&a0, &in0) || xu_is_empty(&in0)) {
        if (memcmp(&out, &base, sizeof out))
            cfail(s, C_KINDS, "EINVAL / EMPTY output differs from cbx_transform_box's");
    } else {
        for (i = 0; i < 3; i++)
            for (up = 0; up < 2; up++) {
                double bt = up ? base.hi[i] : base.lo[i], tt = up ? out.hi[i] : out.lo[i];
                s->kind[xu_end_kind(&a0, &in0, i, up)]++;
                if (!isfinite(bt)) {
                    if (memcmp(&bt, &tt, sizeof bt)) {
                        snprintf(why, sizeof why, "axis %d %s: cbx_transform_box end %a, tight "
                                 "end %a", i, up ? "hi" : "lo", bt, tt);
                        cfail(s, C_KINDS, why);
                    }
                    continue;
                }
                if (!isfinite(tt)) {
                    snprintf(why, sizeof why, "axis %d %s: cbx_transform_box end finite (%a), "
                             "tight end %a", i, up ? "hi" : "lo", bt, tt);
                    cfail(s, C_KINDS, why);
                    continue;
                }
                check_finite_end(k, s, &a0, &in0, i, up, bt, tt, idx % MPQ_EVERY == 0);
            }
    }

    if (idx % INPLACE_EVERY == 0) {
        cbx_status s2;
        s->checked[C_INPLACE]++;
        b2 = in0;
        s2 = cbx_transform_box_tight(&a0, &b2, &b2);
        if (s2 != st || memcmp(&b2, &out, sizeof out))
            cfail(s, C_INPLACE, "in-place call differs from the separate output");
    }

    if (case_failed) {
        s->failed++;
        if (k->logs < MAX_FAIL_LOGS && k->cat_logs[case_cat] < (case_cat ? LOGS_PER_CAT : MAX_FAIL_LOGS)) {
            k->logs++;
            k->cat_logs[case_cat]++;
            printf("FAIL %s case %ld: %s (status %s, cbx_transform_box %s)\n", s->title, idx,
                   case_why, cbx_status_name(st), cbx_status_name(sb));
            xu_print_case(stdout, &a0, &in0);
            xu_print_box(stdout, "tight", &out);
            xu_print_box(stdout, "box", &base);
            fputs(case_detail, stdout);
        }
    }
}

/* ---------------------------------------------------------------------- */
/* Generators                                                             */
/* ---------------------------------------------------------------------- */

/* a full-mantissa value in [2^e, 2^(e+1)) (rounded when subnormal) */
static double gm(xu_rng *r, int e)
{
    double f = 1.0 + ldexp((double)(xu_rng_next(r) >> 12), -52);
    if (e > 1023) e = 1023;
    if (e < -1074) e = -1074;
    return ldexp(f, e);
}

static double sgm(xu_rng *r, int e) { return xu_rng_sign(r) * gm(r, e); }

static int clampi(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

/* Callers draw w before u: the order gcc gives sort_axis(b, j, U, W) on
 * x86-64 (arguments right to left), made explicit so that ARM draws the
 * same cases. */
static void sort_axis(cbx_box *b, int j, double u, double w)
{
    b->lo[j] = u < w ? u : w;
    b->hi[j] = u < w ? w : u;
}

/* Section 1: random full rows, exponents over the whole range. */
static void gen_wide(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int ec[3], i, j;
    for (j = 0; j < 3; j++) {
        int p = xu_rng_int(r, 0, 99);
        double c1, c2;
        ec[j] = p < 55 ? xu_rng_int(r, -40, 40) : p < 85 ? xu_rng_int(r, -1060, 1010)
                                                         : xu_rng_int(r, -300, 300);
        c1 = sgm(r, ec[j]);
        p = xu_rng_int(r, 0, 99);
        if (p < 10) c2 = c1;                       /* flat axis */
        else if (p < 20) c2 = xu_rng_sign(r) * 0.0;
        else if (p < 30) c2 = -c1;
        else c2 = sgm(r, ec[j] - xu_rng_int(r, 0, 12));
        sort_axis(b, j, c1, c2);
    }
    for (i = 0; i < 3; i++) {
        int p = xu_rng_int(r, 0, 99), R;
        R = p < 45 ? xu_rng_int(r, -80, 80) : p < 80 ? xu_rng_int(r, -960, 995)
                                                     : xu_rng_int(r, -1074, 1018);
        for (j = 0; j < 3; j++) {
            int em;
            if (xu_rng_int(r, 0, 99) < 8) {
                a->m[i][j] = xu_rng_sign(r) * 0.0;
                continue;
            }
            em = p < 90 ? R - ec[j] + xu_rng_int(r, -30, 30) : xu_rng_int(r, -1074, 1018);
            em = clampi(em, -1074, 1016 - ec[j]);
            em = clampi(em, -1074, 1018);
            a->m[i][j] = sgm(r, em);
        }
        p = xu_rng_int(r, 0, 99);
        if (p < 20) a->m[i][3] = xu_rng_sign(r) * 0.0;
        else if (p < 65) a->m[i][3] = sgm(r, clampi(R + xu_rng_int(r, -60, 10), -1074, 1017));
        else if (p < 85) a->m[i][3] = xu_gen_signed(r, -1074, 1017);
        else a->m[i][3] = xu_gen_signed(r, -20, 20);
    }
}

/* Section 2: integers and small dyadics, often with a representable E. */
static double dy(xu_rng *r, int range, int den_log2)
{
    return ldexp((double)xu_rng_int(r, -range, range), -den_log2);
}

static void gen_int(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int p = xu_rng_int(r, 0, 99), i, j, sm = 0, sc = 0;
    if (p < 25) { /* small integers */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = (double)xu_rng_int(r, -4, 4);
            a->m[i][3] = (double)xu_rng_int(r, -1000000, 1000000);
        }
        for (j = 0; j < 3; j++) { double w = dy(r, 1000, 0); sort_axis(b, j, dy(r, 1000, 0), w); }
    } else if (p < 45) { /* small dyadics */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = dy(r, 64, 3);
            a->m[i][3] = dy(r, 1 << 20, 2);
        }
        for (j = 0; j < 3; j++) { double w = dy(r, 1 << 20, 4); sort_axis(b, j, dy(r, 1 << 20, 4), w); }
    } else if (p < 60) { /* permutation / sign flip, scales 2^s */
        int perm[3] = { 0, 1, 2 };
        for (j = 2; j > 0; j--) {
            int q = xu_rng_int(r, 0, j), t = perm[j];
            perm[j] = perm[q];
            perm[q] = t;
        }
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = xu_rng_int(r, 0, 1) ? 0.0 : -0.0;
            a->m[i][perm[i]] = xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -3, 3));
            a->m[i][3] = xu_rng_int(r, 0, 3) ? dy(r, 1 << 24, 3) : 0.0;
        }
        for (j = 0; j < 3; j++) { double w = dy(r, 1 << 30, 6); sort_axis(b, j, dy(r, 1 << 30, 6), w); }
    } else if (p < 80) { /* large integers: sums beyond 2^53 */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                a->m[i][j] = (double)xu_rng_int(r, -(1 << 26), 1 << 26);
            int e = xu_rng_int(r, 0, 30);
            a->m[i][3] = ldexp((double)xu_rng_int(r, -(1 << 30), 1 << 30), e);
        }
        for (j = 0; j < 3; j++) {
            double w = (double)xu_rng_int(r, -(1 << 30), 1 << 30);
            sort_axis(b, j, (double)xu_rng_int(r, -(1 << 30), 1 << 30), w);
        }
    } else { /* powers of two with wide spreads */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                a->m[i][j] = xu_rng_int(r, 0, 5) ? xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -40, 40))
                                                 : 0.0;
            a->m[i][3] = xu_rng_int(r, 0, 3) ? xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -80, 80))
                                             : 0.0;
        }
        for (j = 0; j < 3; j++) {
            double w = xu_rng_int(r, 0, 2) ? xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -40, 40)) : 0.0;
            sort_axis(b, j, xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -40, 40)), w);
        }
    }
    /* scale by powers of two (exact unless a value becomes subnormal) */
    if (xu_rng_int(r, 0, 2) == 0) {
        sm = xu_rng_int(r, -480, 480);
        sc = xu_rng_int(r, -480, 480);
        if (sm + sc > 900) sc = 900 - sm;
        if (sm + sc < -900) sc = -900 - sm;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = ldexp(a->m[i][j], sm);
            a->m[i][3] = ldexp(a->m[i][3], sm + sc);
        }
        for (j = 0; j < 3; j++) {
            b->lo[j] = ldexp(b->lo[j], sc);
            b->hi[j] = ldexp(b->hi[j], sc);
        }
    }
}

/* the vertex of one end of row i (0 where m_j == 0); finite box assumed */
static void vertex_of(const cbx_affine *a, const cbx_box *b, int i, int up, double v[3])
{
    int j;
    for (j = 0; j < 3; j++) {
        double m = a->m[i][j];
        v[j] = m == 0 ? 0.0 : ((m > 0) != (up != 0)) ? b->lo[j] : b->hi[j];
    }
}

/* Section 3: heavy cancellation at one end of each row. */
static void gen_cancel(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i, j, ec[3];
    int scale = xu_rng_int(r, 0, 3) == 0 ? xu_rng_int(r, -900, 900) : xu_rng_int(r, -30, 30);
    for (j = 0; j < 3; j++) {
        double c1, c2;
        ec[j] = scale / 2 + xu_rng_int(r, -20, 20);
        c1 = sgm(r, ec[j]);
        c2 = xu_rng_int(r, 0, 3) ? sgm(r, ec[j] - xu_rng_int(r, 0, 10)) : c1;
        sort_axis(b, j, c1, c2);
    }
    for (i = 0; i < 3; i++) {
        int up = xu_rng_int(r, 0, 1), p = xu_rng_int(r, 0, 99);
        double v[3], t;
        a->m[i][3] = 0.0;
        for (j = 0; j < 3; j++)
            a->m[i][j] = sgm(r, clampi(scale - ec[j] + xu_rng_int(r, -20, 20), -1074, 1000));
        if (p < 35) {
            /* t = -fl(m.v), then maybe a few ulps off */
            vertex_of(a, b, i, up, v);
            t = -(a->m[i][0] * v[0] + a->m[i][1] * v[1] + a->m[i][2] * v[2]);
            if (xu_rng_int(r, 0, 1)) {
                int n = xu_rng_int(r, 1, 3), d = xu_rng_int(r, 0, 1);
                while (n--) t = nextafter(t, d ? INF : -INF);
            }
            a->m[i][3] = t;
        } else if (p < 55) {
            /* t = -fl(m_0 v_0); the other products much smaller or zero */
            a->m[i][1] = xu_rng_int(r, 0, 1) ? 0.0 : ldexp(a->m[i][1], -xu_rng_int(r, 40, 70));
            a->m[i][2] = xu_rng_int(r, 0, 1) ? 0.0 : ldexp(a->m[i][2], -xu_rng_int(r, 40, 70));
            vertex_of(a, b, i, up, v);
            a->m[i][3] = -(a->m[i][0] * v[0]);
        } else if (p < 80) {
            /* exact cancellation: m_1 = +-v_0 2^s, v_1 = -+m_0 2^-s, so
             * m_1 v_1 = -m_0 v_0; the rest tiny or zero */
            int s = xu_rng_int(r, -8, 8);
            double sg = xu_rng_sign(r), c;
            vertex_of(a, b, i, up, v);
            if (v[0] == 0 || a->m[i][0] == 0) continue;
            a->m[i][1] = sg * ldexp(v[0], s);
            c = -sg * ldexp(a->m[i][0], -s);
            /* v_1 = c must be the box end the sign of m_1 selects */
            if ((a->m[i][1] > 0) != (up != 0)) {
                b->lo[1] = c;
                if (b->hi[1] < c) b->hi[1] = c;
            } else {
                b->hi[1] = c;
                if (b->lo[1] > c) b->lo[1] = c;
            }
            switch (xu_rng_int(r, 0, 3)) {
            case 0: a->m[i][2] = xu_rng_sign(r) * 0.0; a->m[i][3] = 0.0; break;
            case 1: a->m[i][2] = ldexp(a->m[i][2], -xu_rng_int(r, 30, 80));
                    a->m[i][3] = 0.0; break;
            case 2: vertex_of(a, b, i, up, v);
                    a->m[i][3] = -(a->m[i][2] * v[2]); break;
            default: a->m[i][3] = xu_gen_signed(r, -1074, -1000); break;
            }
        } else {
            /* products near 2^-960 and t = -fl(sum): E deep in the subnormals */
            for (j = 0; j < 3; j++)
                a->m[i][j] = sgm(r, clampi(-958 - ec[j] + xu_rng_int(r, 0, 6), -1074, 1000));
            vertex_of(a, b, i, up, v);
            a->m[i][3] = -(a->m[i][0] * v[0] + a->m[i][1] * v[1] + a->m[i][2] * v[2]);
        }
    }
}

/* Section 4: half-spaces, huge ends, zeros, infinities, NaN, empty. */
static double gen_entry4(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 20) return xu_rng_sign(r) * 0.0;
    if (p < 60) return xu_gen_signed(r, -20, 10);
    if (p < 70) return xu_gen_signed(r, -1074, -900);
    if (p < 80) return xu_rng_sign(r) * (xu_rng_int(r, 0, 1) ? 0x1p1018 : 1e300);
    if (p < 83) return xu_rng_sign(r) * DBL_MAX;
    return xu_gen_signed(r, -1074, 1023);
}

static double gen_coord4(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 40) return xu_gen_signed(r, -10, 10);
    if (p < 50) return xu_rng_sign(r) * 0.0;
    if (p < 60) return xu_rng_sign(r);
    if (p < 75) return xu_gen_signed(r, -1074, 1018);
    if (p < 80) return xu_rng_sign(r) * 0x1p1018;
    if (p < 85) return xu_rng_sign(r) * DBL_MAX;
    return xu_gen_signed(r, -30, 30);
}

static void gen_special(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) a->m[i][j] = gen_entry4(r);
        a->m[i][3] = xu_rng_int(r, 0, 2) ? xu_gen_signed(r, -20, 20) : gen_entry4(r);
        if (xu_rng_int(r, 0, 24) == 0) a->m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF;
    }
    for (j = 0; j < 3; j++) {
        int p = xu_rng_int(r, 0, 99);
        double w = gen_coord4(r);
        sort_axis(b, j, gen_coord4(r), w);
        if (p < 20) b->lo[j] = -INF;
        else if (p < 40) b->hi[j] = INF;
        else if (p < 45) { b->lo[j] = -INF; b->hi[j] = INF; }
        else if (p < 47) b->lo[j] = INF;      /* empty */
        else if (p < 49) b->hi[j] = -INF;     /* empty */
        else if (p < 51) { double t = b->lo[j]; b->lo[j] = b->hi[j]; b->hi[j] = t; } /* maybe empty */
    }
    if (xu_rng_int(r, 0, 29) == 0) {
        if (xu_rng_int(r, 0, 1)) a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
        else if (xu_rng_int(r, 0, 1)) b->lo[xu_rng_int(r, 0, 2)] = NAN;
        else b->hi[xu_rng_int(r, 0, 2)] = NAN;
    }
}

/* Section 5: near the exception's boundaries. */
static void gen_boundary(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i, j, kind = xu_rng_int(r, 0, 2);
    for (j = 0; j < 3; j++) { double w = xu_gen_signed(r, -4, 4); sort_axis(b, j, xu_gen_signed(r, -4, 4), w); }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            int e;
            if (xu_rng_int(r, 0, 9) == 0) {
                a->m[i][j] = 0.0;
                continue;
            }
            if (kind == 0) e = xu_rng_int(r, -974, -962) - ilogb(fmax(fabs(b->lo[j]), 0x1p-1000));
            else if (kind == 1) e = xu_rng_int(r, 1006, 1017);
            else e = xu_rng_int(r, -60, 60);
            a->m[i][j] = sgm(r, clampi(e, -1074, 1018));
        }
        if (kind == 0)
            a->m[i][3] = xu_rng_int(r, 0, 1) ? 0.0 : sgm(r, xu_rng_int(r, -1000, -955));
        else if (kind == 1)
            a->m[i][3] = xu_rng_int(r, 0, 2) ? sgm(r, xu_rng_int(r, 1011, 1017)) : 0.0;
        else
            a->m[i][3] = xu_rng_int(r, 0, 1) ? xu_rng_sign(r) * 0x1p1015
                         : sgm(r, xu_rng_int(r, 1013, 1018));
    }
}

/* ---------------------------------------------------------------------- */
/* Hard cases                                                             */
/* ---------------------------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
#define BOX(l0, h0, l1, h1, l2, h2) { { l0, l1, l2 }, { h0, h1, h2 } }

typedef struct hard { const char *name; cbx_affine a; cbx_box in; } hard;

static const hard hard_cases[] = {
    { "identity, unit cube", MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(0, 1, 0, 1, 0, 1) },
    { "cyclic permutation + integer t", MAT(ROW(0, 1, 0, 5), ROW(0, 0, 1, -7), ROW(1, 0, 0, 0)),
      BOX(-1, 2, 3, 4, -6, -5) },
    { "signed permutation, scales 2,3",
      MAT(ROW(0, -2, 0, 1), ROW(0, 0, 3, 0), ROW(-1, 0, 0, -4)),
      BOX(1, 2, -5, 7, -0.5, 0.25) },
    { "0.1 * 3 and 0.1 * -3", MAT(ROW(0.1, 0, 0, 0), ROW(-0.1, 0, 0, 0), ROW(0.1, 0.2, 0, 0)),
      BOX(3, 3, 1, 1, 0, 0) },
    { "permutation with -0.0, box [+0,-0]",
      MAT(ROW(-0.0, 1, -0.0, -0.0), ROW(-0.0, -0.0, -1, 0), ROW(1, -0.0, 0, -0.0)),
      BOX(-0.0, 0.0, -2, -1, 0.0, -0.0) },
    { "2^52-size integers, sum 2^53 + 1",
      MAT(ROW(1, 1, 0, 0), ROW(1, 1, 1, 0x1p53), ROW(-1, 0, 0, 0x1p53)),
      BOX(0x1p52, 0x1p52, 0x1p52 + 1, 0x1p52 + 1, 0.5, 0.5) },
    { "exact cancellation to 0", MAT(ROW(0.1, 0, 0, -0.1), ROW(3, -7, 0.5, 3.5), ROW(-1, 1, 1, -1)),
      BOX(1, 1, 1, 1, 1, 1) },
    { "near cancellation t = -fl(m.x)",
      MAT(ROW(0.1, 0.2, 0.3, -0.6000000000000001),
          ROW(1e-3, 1.1, -0.7, -0.024499999999999966), ROW(0.1, 0, 0, -0.10000000000000002)),
      BOX(1, 1, 1, 1, 1, 1) },
    { "near cancellation at 1e200",
      MAT(ROW(1e100, 3e99, -7e98, 8.9e199), ROW(1e100, 0, 0, -1e200),
          ROW(-1e100, -3e99, 7e98, -8.9e199)),
      BOX(1e100, 1e100, 7e99, 7e99, 3e101, 3e101) },
    { "E = rounding error of 0.1 * 0.1",
      MAT(ROW(0.1, 0, 0, -0.010000000000000002), ROW(0.1, 0, 0, -0.01), ROW(-0.1, 0, 0, 0.01)),
      BOX(0.1, 0.1, 0, 0, 0, 0) },
    { "E = -2^-1074 and +2^-1074",
      MAT(ROW(1, -1, 0, -0x1p-1074), ROW(1, -1, 0, 0x1p-1074), ROW(0x1p-1074, 0, 0, 0)),
      BOX(1, 1, 1, 1, 0, 0) },
    { "E = 2^-1074 * 0.5 (a half of the smallest subnormal)",
      MAT(ROW(0.5, 0, 0, 0), ROW(-0.5, 0, 0, 0), ROW(0.75, 0, 0, 0)),
      BOX(0x1p-1074, 0x1p-1074, 0, 0, 0x1p-1074, 0x1p-1074) },
    { "1 + 2^-1000 - 1 (exact, tiny)",
      MAT(ROW(1, 1, 0, -1), ROW(1, -1, 0, 0), ROW(1, 1, 1, -2)),
      BOX(1, 1, 0x1p-1000, 0x1p-1000, 0x1p-1020, 0x1p-1020) },
    { "boundary: product exactly 2^-968 (outside the exception)",
      MAT(ROW(0x1p-968, 0, 0, 0), ROW(0x1p-968, 0, 0, 1), ROW(0x1p-484, 0, 0, 0)),
      BOX(1, 1, 0, 0, 0x1p-484, 0x1p-484) },
    { "boundary: product 2^-968 * 1.5 (outside the exception)",
      MAT(ROW(0x1.8p-968, 0, 0, 0), ROW(0x1p-968, 0x1.8p-968, 0, 0), ROW(3, 0, 0, 0)),
      BOX(1, 1, 1, 1, 0x1p-969, 0x1p-969) },
    { "boundary: product 2^-969 (in the exception)",
      MAT(ROW(0x1p-969, 0, 0, 0), ROW(0x1p-969, 0, 0, 1), ROW(0x1p-1074, 0, 0, 0)),
      BOX(1, 1, 0, 0, 1, 1) },
    { "boundary: t = 2^1015 exactly (outside the exception)",
      MAT(ROW(0.1, 0, 0, 0x1p1015), ROW(-0.1, 0, 0, -0x1p1015), ROW(1, 0, 0, 0x1p1015)),
      BOX(3, 3, 0, 0, -1, -1) },
    { "boundary: t = 2^1015 + ulp (in the exception)",
      MAT(ROW(0.1, 0, 0, 0x1.0000000000001p1015), ROW(0, 0, 0, -0x1.0000000000001p1015),
          ROW(1, 0, 0, 0x1p1016)),
      BOX(3, 3, 0, 0, -1, -1) },
    { "boundary: E just below 2^1015",
      MAT(ROW(0x1p1014, 0x1p1013, 0, 0), ROW(0x1p1014, 0x1p1013, 0.1, 0), ROW(0, 0, 0, 0)),
      BOX(1, 1, 0.5, 0.5, -1, -1) },
    { "all zeros with signs",
      MAT(ROW(-0.0, -0.0, -0.0, -0.0), ROW(0.0, -0.0, 0.0, 0.0), ROW(-0.0, 0.0, -0.0, 0.0)),
      BOX(-0.0, -0.0, -0.0, 0.0, 0.0, -0.0) },
    { "decimal rotation-like matrix, point box",
      MAT(ROW(0.36, -0.48, 0.8, 10), ROW(0.8, 0.6, 0, -3), ROW(-0.48, 0.64, 0.6, 0.5)),
      BOX(0.3, 0.3, -1.7, -1.7, 2.5, 2.5) },
    { "half-spaces with zero columns",
      MAT(ROW(1, 0, -0.0, 0.1), ROW(0, -3, 0, 0), ROW(0.1, 0.2, 0.3, 0)),
      BOX(-INF, 1, 0.1, INF, -INF, INF) },
    { "half-space, finite ends from the vertex",
      MAT(ROW(0.1, -0.2, 0, 1), ROW(-0.1, 0.2, 0, -1), ROW(0, 0, 0.3, 0.7)),
      BOX(0.3, INF, -INF, 0.7, 1, 1) },
    { "huge unneeded end (out of the domain)",
      MAT(ROW(0.1, 0, 0, 0), ROW(-0.1, 0, 0, 0), ROW(0.1, 0.3, 0, 0)),
      BOX(0.7, DBL_MAX, 0, 0, 0, 0) },
    { "infinite map entry", MAT(ROW(INF, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, -INF)),
      BOX(1, 2, 3, 4, 5, 6) },
    { "NaN in the map", MAT(ROW(NAN, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(1, 2, 3, 4, 5, 6) },
    { "NaN in the box", MAT(ROW(1, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(1, 2, NAN, 4, 5, 6) },
    { "empty box (hi < lo)", MAT(ROW(1, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(1, 2, 4, 3, 5, 6) },
    { "empty box (lo = +inf)", MAT(ROW(1, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(INF, INF, 3, 4, 5, 6) },
};
#define N_HARD ((int)(sizeof hard_cases / sizeof hard_cases[0]))

/* ---------------------------------------------------------------------- */
/* Report                                                                 */
/* ---------------------------------------------------------------------- */

static void sec_init(sec *s, const char *title)
{
    memset(s, 0, sizeof *s);
    s->title = title;
    s->near968_maxlog = s->tiny_e_maxlog = -100000;
}

static void sec_add(sec *t, const sec *s)
{
    int c;
    t->cases += s->cases;
    t->failed += s->failed;
    for (c = 0; c < 4; c++) t->status_seen[c] += s->status_seen[c];
    for (c = 0; c < XU_NEND; c++) t->kind[c] += s->kind[c];
    t->fin += s->fin;
    t->fin_exact += s->fin_exact;
    t->tightened += s->tightened;
    if (s->base_ulps_max > t->base_ulps_max) t->base_ulps_max = s->base_ulps_max;
    t->base_ulps_sum += s->base_ulps_sum;
    t->nc_ends += s->nc_ends;
    if (s->near968_maxlog > t->near968_maxlog) t->near968_maxlog = s->near968_maxlog;
    if (s->tiny_e_maxlog > t->tiny_e_maxlog) t->tiny_e_maxlog = s->tiny_e_maxlog;
    t->exc += s->exc;
    t->exc_tiny += s->exc_tiny;
    t->exc_big += s->exc_big;
    t->exc_opt += s->exc_opt;
    t->exc_kernel += s->exc_kernel;
    t->exc_between += s->exc_between;
    t->exc_nonopt_999 += s->exc_nonopt_999;
    for (c = 0; c < NC; c++) {
        t->checked[c] += s->checked[c];
        t->fail[c] += s->fail[c];
    }
    t->opt_near968 += s->opt_near968;
    t->opt_tiny_e += s->opt_tiny_e;
    t->opt_other += s->opt_other;
    t->opt_between += s->opt_between;
    t->opt_exact_e += s->opt_exact_e;
}

static void sec_print(const sec *s)
{
    int c;
    printf("\n%s\n", s->title);
    printf("  %ld cases (cbx_transform_box: OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld); "
           "%ld failed\n", s->cases, s->status_seen[0], s->status_seen[1], s->status_seen[2],
           s->status_seen[3], s->failed);
    printf("  ends by kind:");
    for (c = 0; c < XU_NEND; c++) printf(" %c %ld", xu_end_char[c], s->kind[c]);
    printf("\n");
    printf("  finite ends checked exactly: %ld (exact value a double, end equal to it: %ld); "
           "tighter than cbx_transform_box: %ld\n", s->fin, s->fin_exact, s->tightened);
    printf("  cbx_transform_box's end beyond the tight one, in ulps of the exact end, on the %ld "
           "ends with 4|E| >= S > 0: max %.2f, mean %.2f\n", s->nc_ends, s->base_ulps_max,
           s->nc_ends ? s->base_ulps_sum / (double)s->nc_ends : 0.0);
    printf("  containment failures: %ld; optimality failures outside the exception: %ld "
           "(of %ld ends)\n", s->fail[C_CONTAIN], s->fail[C_OPTIMAL], s->checked[C_OPTIMAL]);
    if (s->fail[C_OPTIMAL])
        printf("    by cause: a nonzero product in [2^-968, 2^-967) %ld (largest such product "
               "< 2^%ld), 0 < |E| < 2^-900 %ld (largest such |E| < 2^%ld), other %ld\n",
               s->opt_near968, s->opt_near968 ? s->near968_maxlog + 1 : 0, s->opt_tiny_e,
               s->opt_tiny_e ? s->tiny_e_maxlog + 1 : 0, s->opt_other);
    if (s->fail[C_OPTIMAL])
        printf("    of these: tighter than cbx_transform_box's end but not the tightest %ld; "
               "exact value a double (yet the end differs from it) %ld\n", s->opt_between,
               s->opt_exact_e);
    printf("  documented exception: %ld ends (tiny product %ld, magnitude > 2^1015 %ld): "
           "optimal anyway %ld, cbx_transform_box's end %ld, in between %ld; not optimal with "
           "max magnitude in (2^1015, 2^1016]: %ld\n", s->exc, s->exc_tiny, s->exc_big,
           s->exc_opt, s->exc_kernel, s->exc_between, s->exc_nonopt_999);
    for (c = 0; c < NC; c++)
        printf("  check %-8s %9ld %-18s checked, %ld failed\n", c_name[c], s->checked[c],
               c_unit[c], s->fail[c]);
}

typedef void (*gen_fn)(xu_rng *, cbx_affine *, cbx_box *);

int main(int argc, char **argv)
{
    long nth = (long)xu_arg_num(argc, argv, 1, 30, "[N_THOUSANDS] [seed]"), n, c;
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N_THOUSANDS] [seed]");
    static tctx k;
    static sec s[6], tot;
    static const char *const titles[6] = {
        "section 0: hard cases",
        "section 1: random full rows, wide exponent ranges",
        "section 2: integers, small dyadics, permutations, powers of two",
        "section 3: heavy cancellation",
        "section 4: half-spaces, huge ends, infinite entries, NaN, empty",
        "section 5: near the exception's boundaries (2^-968, 2^1015)"
    };
    static const gen_fn gens[6] = { 0, gen_wide, gen_int, gen_cancel, gen_special, gen_boundary };
    int q;
    clock_t t0 = clock();

    n = nth * 1000;
    xu_init(&k.x);
    mpz_inits(k.E, k.p, k.tiny, k.big, k.big1000, k.smallE, k.near967, (mpz_ptr)0);
    mpz_setbit(k.tiny, XU_SHIFT - 968);      /* 2^-968, scaled  */
    mpz_setbit(k.near967, XU_SHIFT - 967);   /* 2^-967, scaled  */
    mpz_setbit(k.big, XU_SHIFT + 1015);      /* 2^1015, scaled  */
    mpz_setbit(k.big1000, XU_SHIFT + 1016);  /* 2^1016, scaled  */
    mpz_setbit(k.smallE, XU_SHIFT - 900); /* 2^-900, scaled  */
    mpq_inits(k.q, k.qa, k.qb, (mpq_ptr)0);
    mpfr_init2(k.r53, 53);
    k.rng.s = UINT64_C(0x243f6a8885a308d3) ^ seed;
    k.logs = 0;
    k.notes = 0;

    printf("-- test_tight: cbx_transform_box_tight against GMP, %ld thousand cases per random "
           "section, seed %llu --\n", nth, (unsigned long long)seed);
    for (q = 0; q < 6; q++) sec_init(&s[q], titles[q]);
    sec_init(&tot, "totals");
    for (q = 0; q < N_HARD; q++) {
        const char *nm = hard_cases[q].name;
        long before = s[0].failed;
        run_case(&k, &s[0], &hard_cases[q].a, &hard_cases[q].in);
        if (s[0].failed != before) printf("  (hard case \"%s\")\n", nm);
    }
    for (q = 1; q < 6; q++) {
        long m = q == 4 ? n / 2 : q == 5 ? n / 4 : n;
        for (c = 0; c < m; c++) {
            cbx_affine a;
            cbx_box b;
            gens[q](&k.rng, &a, &b);
            run_case(&k, &s[q], &a, &b);
        }
    }
    for (q = 0; q < 6; q++) {
        sec_print(&s[q]);
        sec_add(&tot, &s[q]);
    }
    sec_print(&tot);
    printf("\n  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    printf("tight: two_prod form (src/core/cbx_eft.h, as this test's flags select it): %s\n",
           CBX_TWO_PROD_NAME);
    printf("tight: %ld cases, %ld finite ends, %ld containment failures, %ld optimality "
           "failures, %ld ends in the exception\n", tot.cases, tot.fin, tot.fail[C_CONTAIN],
           tot.fail[C_OPTIMAL], tot.exc);

    mpfr_clear(k.r53);
    mpq_clears(k.q, k.qa, k.qb, (mpq_ptr)0);
    mpz_clears(k.E, k.p, k.tiny, k.big, k.big1000, k.smallE, k.near967, (mpz_ptr)0);
    xu_clear(&k.x);
    mpfr_free_cache();
    printf("%ld passed, %ld failed\n", tot.cases - tot.failed, tot.failed);
    return tot.failed ? 1 : 0;
}
