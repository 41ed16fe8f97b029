/*
 * tight_check.c: part of tests/test_tight.c (tight_parts.h): the checks of
 * one finite end (containment, never looser, optimality by mpz, MPFR and
 * mpq, the documented exception) and of one case (status, the oracle of
 * exact_util, end kinds, in place, inputs), the statistics per section and
 * their report.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <gmp.h>
#include <mpfr.h>

#include "tight_parts.h"

#define MAX_FAIL_LOGS 25
#define ORACLE_CORNER_EVERY 16
#define MPQ_EVERY 8
#define INPLACE_EVERY 4

/* ---------------------------------------------------------------------- */
/* Context and statistics                                                 */
/* ---------------------------------------------------------------------- */

static const char *const c_name[NC] = { "status", "oracle", "kinds", "contain", "looser",
                                        "optimal", "cross", "inplace", "inputs", "gap" };
static const char *const c_unit[NC] = { "cases", "cases", "cases", "finite ends",
                                        "finite ends", "ends outside exc.", "finite ends",
                                        "cases", "cases", "ends in range" };

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
/* The proven accuracy (specs/cbx_tight_gap.h)                            */
/* ---------------------------------------------------------------------- */

/* |x| <= 2^e */
static int mag_le(double x, int e) { return fabs(x) <= ldexp(1.0, e); }

/* q = |m x| (exact) */
static void abs_prod(mpq_t q, double m, double x)
{
    mpq_t t;
    mpq_init(t);
    mpq_set_d(q, m);
    mpq_set_d(t, x);
    mpq_mul(q, q, t);
    mpq_abs(q, q);
    mpq_clear(t);
}

/* The promise's range: map and box in the fast range (map_fast, box_fast)
 * and row i in trow_dom (every product at the box's ends with a zero
 * factor or of magnitude in [2^-967, 2^1013], |t| <= 2^1015). */
static int in_tight_range(tctx *k, const cbx_affine *a, const cbx_box *in, int i)
{
    int r, j, e;
    mpq_t lim;
    for (r = 0; r < 3; r++) {
        for (j = 0; j < 3; j++)
            if (!isfinite(a->m[r][j]) || !mag_le(a->m[r][j], 509)) return 0;
        if (!isfinite(a->m[r][3]) || !mag_le(a->m[r][3], 1018)) return 0;
    }
    for (j = 0; j < 3; j++)
        if (!isfinite(in->lo[j]) || !isfinite(in->hi[j]) || !(in->lo[j] <= in->hi[j])
            || !mag_le(in->lo[j], 509) || !mag_le(in->hi[j], 509)) return 0;
    if (!mag_le(a->m[i][3], 1015)) return 0;
    mpq_init(lim);
    for (j = 0; j < 3; j++) {
        for (e = 0; e < 2; e++) {
            double x = e ? in->hi[j] : in->lo[j];
            if (a->m[i][j] == 0 || x == 0) continue;
            abs_prod(k->qa, a->m[i][j], x);
            mpq_set_d(lim, 0x1p-967);
            if (mpq_cmp(k->qa, lim) < 0) { mpq_clear(lim); return 0; }
            mpq_set_d(lim, 0x1p1013);
            if (mpq_cmp(k->qa, lim) > 0) { mpq_clear(lim); return 0; }
        }
    }
    mpq_clear(lim);
    return 1;
}

/* |E - end| <= 2^-50 |E| + 2^-96 S + 2^-1050, S = |t| + sum_j max(|m_j l_j|,
 * |m_j h_j|) (xu_row_bounds' S: the row is full in the range), in mpq: 1
 * when it holds. */
static int within_gap(tctx *k, const cbx_affine *a, const cbx_box *in, int i, double tt)
{
    int ok;
    mpq_t S, g, d;
    mpq_inits(S, g, d, (mpq_ptr)0);
    xu_row_bounds(&k->x, a, in, i);
    xu_scaled_to_q(S, k->x.S);
    xu_scaled_to_q(k->qa, k->E);               /* E */
    mpq_set_d(d, tt);
    mpq_sub(d, k->qa, d);
    mpq_abs(d, d);                              /* |E - end| */
    mpq_abs(g, k->qa);
    mpq_set_d(k->qb, 0x1p-50);
    mpq_mul(g, g, k->qb);
    mpq_set_d(k->qb, 0x1p-96);
    mpq_mul(S, S, k->qb);
    mpq_add(g, g, S);
    mpq_set_d(k->qb, 0x1p-1050);
    mpq_add(g, g, k->qb);
    ok = mpq_cmp(d, g) <= 0;
    mpq_clears(S, g, d, (mpq_ptr)0);
    return ok;
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
    if (in_tight_range(k, a, in, i)) {
        s->checked[C_GAP]++;
        if (!within_gap(k, a, in, i, tt)) {
            snprintf(why, sizeof why, "axis %d %s: OUTSIDE THE PROVEN GAP: end %a", i, nm, tt);
            cfail(s, C_GAP, why);
        }
        if (!within_gap(k, a, in, i, bt)) s->gap_kernel_out++; /* the check's teeth */
    }
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

void tgt_run_case(tctx *k, sec *s, const cbx_affine *a, const cbx_box *in)
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
/* Report                                                                 */
/* ---------------------------------------------------------------------- */

void tgt_sec_init(sec *s, const char *title)
{
    memset(s, 0, sizeof *s);
    s->title = title;
    s->near968_maxlog = s->tiny_e_maxlog = -100000;
}

void tgt_sec_add(sec *t, const sec *s)
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
    t->gap_kernel_out += s->gap_kernel_out;
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

void tgt_sec_print(const sec *s)
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
    printf("  proven gap (2^-50 |E| + 2^-96 S + 2^-1050): %ld of %ld ends in range outside it; "
           "cbx_transform_box's end outside it on %ld of them (the check can fail)\n",
           s->fail[C_GAP], s->checked[C_GAP], s->gap_kernel_out);
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
