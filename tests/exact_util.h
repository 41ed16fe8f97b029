/*
 * exact_util: the exact (GMP) oracle the certbox tests and the demo compare
 * the library against.  Nothing here calls floating-point arithmetic that
 * rounds: every real number is either a double taken as is, an mpz_t, or an
 * mpq_t.
 *
 * Two independent exact paths are provided on purpose:
 *   - a fast fixed-point path (mpz_t, every value scaled by 2^XU_SHIFT) for
 *     L_i, H_i, S_i and the comparisons made on every case; a product of two
 *     doubles is a multiple of 2^-2148, so after scaling every quantity is
 *     an integer and no gcd (as in mpq_t) is ever needed;
 *   - a plain mpq_t path (mpq_set_d, mpq_mul, mpq_add) for the 8 corners,
 *     used on a subset of cases to check the containment without relying on
 *     "L_i and H_i are the extreme corners", and to cross-check the
 *     fixed-point L_i and H_i themselves; for rule B (below) the corners
 *     are extended reals (an infinite coordinate gives a +-inf term, a zero
 *     coefficient a 0 term), and their inf / sup cross-check the vertex
 *     rule: unbounded exactly when the rule says so, else equal to the
 *     fixed-point vertex value.
 *
 * Units: excess = (L - out.lo) / (u S + eta)  and  (out.hi - H) / (u S + eta)
 * with u = 2^-53, eta = 2^-1074.
 *
 * The rules of cbx_transform_box, per output axis i (row m = m[i][0..2],
 * t = m[i][3]), for an input without NaN whose box has a real point:
 *   (A) "full row": m, t and all six box ends finite and the row in the
 *       proven domain (xu_row_in_domain): the kernel's finite box, the
 *       8 corners inside, tightness 12 u S + 2^-1065;
 *   (B) otherwise, m and t finite: each end on its own, from its vertex
 *       v_j = lo[j] (m_j > 0), hi[j] (m_j < 0), 0 (m_j == 0, also -0.0)
 *       for the lower end, mirrored for the upper end.  A needed v_j that
 *       is infinite: the image is unbounded there, the end is exactly
 *       -inf / +inf and that is no loss ("U").  Else, with every
 *       (m_j, v_j) in a class and |t| <= 2^1018: a finite end, on the
 *       right side of the exact vertex value t + sum_j m_j v_j (the exact
 *       inf / sup of the image over the box, infinite ends read as
 *       half-spaces) and within 12 u S_v + 2^-1065 of it,
 *       S_v = |t| + sum_j |m_j v_j| ("F").  Else -inf / +inf, a loss ("L");
 *   (C) an infinite m_j or t: the whole line [-inf, +inf], a loss ("W").
 * Status CBX_OK iff no axis has a loss, else CBX_ERANGE.  A box end
 * lo = +inf or hi = -inf (or hi < lo) has no real point: CBX_EMPTY.
 *
 * The oracle's files (all in scripts/testutil.sh --oracles; the helpers
 * they share among themselves are in exact_internal.h, not here):
 *   exact_domain.c  the formats, the domain and the expected statuses
 *                   (transform_box and transform_cbox rules)
 *   exact_fixed.c   exact bounds: the fixed-point and mpq corner paths, and
 *                   the GMP helpers of test_cbox, test_sphere and the demo
 *   exact_check.c   checking one call (xu_check_result, xu_run_case)
 *   exact_stats.c   statistics, printing, class values, xu_arg_num
 *   exact_gen.c     the random generator and the random cases
 *   exact_slerp.c   the slerp oracle
 *   exact_proj.c    helpers shared by the projective oracles
 */
#ifndef EXACT_UTIL_H
#define EXACT_UTIL_H

#include <stdint.h>
#include <stdio.h>
#include <gmp.h>
#include <mpfr.h>
#include "certbox.h"

/* Every double is k * 2^-1074 (k integer), so a product of two is a
 * multiple of 2^-2148: scaling by 2^2148 makes all of them integers. */
#define XU_SHIFT 2148

/* Axes with u S < 2^XU_TINY eta are reported apart: there the absolute
 * part of any widening (the spec allows 2^-1065 = 2^9 eta) dominates the
 * excess, which says nothing about the relative tightness. */
#ifndef XU_TINY
#define XU_TINY 10
#endif

/* The magnitude classes of the domain: |m| <= 2^k and |c| <= 2^(1018-k).
 * Same list as dom_pair in specs/cbx_spec.h (509 first, then 0..960, 1018). */
#define XU_NCLASS 18
extern const int xu_class_k[XU_NCLASS];

/* The floating-point format whose rules are checked: its unit roundoff
 * u = 2^-p, smallest subnormal eta = 2^-emin, domain exponent rt (|t| and
 * each product at most 2^rt), proven tightness term 2^-tight_e (the bound
 * is 12 u S + 2^-tight_e), tiny-scale cap 2^-tiny_cap (xu_scale_tiny) and
 * the magnitude classes (2^k, 2^(rt - k)).  binary32 values are held in
 * doubles (exactly), so the same oracle checks the float family:
 * xu_set_format(&xu_binary32) before checking a float result.  Everything
 * below reads xu_fmt; the default is binary64. */
typedef struct xu_format {
    const char *name;
    int p, emin, rt, tight_e, tiny_cap;
    /* for the random cases: largest exponent (values < 2^(emax+1)), the
     * smallest normal exponent, where "large" entries and coordinates
     * start (perturbations out of the domain) */
    int emax, norm_min, big_entry, big_coord;
    int class_k[XU_NCLASS];
} xu_format;
extern const xu_format xu_binary64, xu_binary32;
extern const xu_format *xu_fmt;
void xu_set_format(const xu_format *f);
double xu_next_up(double x);   /* the format's next value above x       */
double xu_fmt_max(void);       /* the format's largest finite value     */
double xu_round_fmt(double d); /* d rounded to the format (nearest)     */

/* ---- the domain and the expected status, decided exactly ------------- */

int xu_is_nan(double x);
int xu_has_nan(const cbx_affine *a, const cbx_box *in);
/* Some axis has no real point: hi < lo, lo = +inf or hi = -inf (the
 * empty rule of cbx_transform_box and cbx_box_to_cbox). */
int xu_is_empty(const cbx_box *in);
int xu_severity(cbx_status s);   /* the order of "the most severe status": OK 0, EMPTY 1, ERANGE 2, EINVAL 3 */
/* (m, c) lies in one magnitude class; false for non-finite m or c. */
int xu_pair_in_domain(double m, double c);
/* Row i of the output is in the proven domain (all 10 inputs it reads are
 * finite, each (m[i][j], lo[j]) and (m[i][j], hi[j]) in a class, and
 * |m[i][3]| <= 2^1018): rule (A), a "full row".  Meaningful only without
 * NaN. */
int xu_row_in_domain(const cbx_affine *a, const cbx_box *in, int i);
/* Bit i set when row i is not a full row (rule B or C applies).  Since
 * the half-space rule this is NOT the set of rows with a loss (see
 * xu_loss_mask): a row outside the domain may still have proven ends. */
int xu_oob_mask(const cbx_affine *a, const cbx_box *in);
/* m[i][0..3] all finite (rule C applies to row i otherwise). */
int xu_map_row_finite(const cbx_affine *a, int i);

/* What one end of output axis i must be (input without NaN, not empty). */
enum {
    XU_END_FULL,   /* 'A' rule A: finite, the full-row kernel             */
    XU_END_VERTEX, /* 'F' rule B: finite, from the vertex, proven         */
    XU_END_UNB,    /* 'U' rule B: exact image unbounded there: -inf/+inf,
                          no loss                                         */
    XU_END_LOST,   /* 'L' rule B: vertex outside the domain: -inf/+inf,
                          a loss                                          */
    XU_END_WHOLE,  /* 'W' rule C: infinite map entry: whole line, a loss  */
    XU_NEND
};
extern const char xu_end_char[XU_NEND + 1]; /* "AFULW" */
/* The kind of the lower (upper = 0) or upper (upper = 1) end. */
int xu_end_kind(const cbx_affine *a, const cbx_box *in, int i, int upper);
/* The vertex of rule B for that end: v[j] per the sign of m[i][j] (0 for
 * m[i][j] == 0).  Returns 0 (v partly unset) when a needed v[j] is
 * infinite, i.e. the exact image is unbounded on that side. */
int xu_vertex(const cbx_affine *a, const cbx_box *in, int i, int upper, double v[3]);
/* 1 when output axis i has a loss (an end that is infinite although the
 * exact image is bounded there): kinds L or W. */
int xu_row_loss(const cbx_affine *a, const cbx_box *in, int i);
/* Bit i set when output axis i has a loss; CBX_ERANGE iff nonzero. */
int xu_loss_mask(const cbx_affine *a, const cbx_box *in);
/* The six end kinds as "ab cd ef" (axis 0 lo/hi, axis 1, axis 2), e.g.
 * "AA UF LW"... (s: at least 9 chars).  Input without NaN, not empty. */
void xu_ends_str(const cbx_affine *a, const cbx_box *in, char s[9]);
cbx_status xu_expected_status(const cbx_affine *a, const cbx_box *in);

/* ---- exact bounds ----------------------------------------------------- */

typedef struct xu_exact {
    mpz_t L, H, S;          /* row bounds and scale, times 2^XU_SHIFT      */
    mpz_t pl, ph, t, d, e;  /* scratch, initialised once (speed)           */
    mpz_t mm, mc;           /* scratch: integer mantissas                  */
    mpq_t q, qa, qb, qmin, qmax; /* scratch for the mpq corner path        */
} xu_exact;

void xu_init(xu_exact *x);
void xu_clear(xu_exact *x);

/* z = v * 2^XU_SHIFT, exactly; v finite. */
void xu_scaled_d(xu_exact *x, mpz_t z, double v);
/* Fill x->L, x->H, x->S for row i.  Every input of row i must be finite. */
void xu_row_bounds(xu_exact *x, const cbx_affine *a, const cbx_box *in, int i);
/* sign(v - d) for a scaled exact value v and a finite double d. */
int xu_cmp_scaled_d(xu_exact *x, const mpz_t v, double d);
/* Excess of out.lo / out.hi over the exact bound of the last
 * xu_row_bounds(), in units of u S + eta; negative = not contained.
 * lo, hi finite. */
double xu_excess_lo(xu_exact *x, double lo);
double xu_excess_hi(xu_exact *x, double hi);
/* The proven tightness bound of specs/cbx_spec.h (lo_tight / hi_tight):
 * lo >= L - (12 u S + 2^-1065), hi <= H + (12 u S + 2^-1065). */
int xu_lo_within_proven(xu_exact *x, double lo);
int xu_hi_within_proven(xu_exact *x, double hi);
/* Rule B: the exact vertex value t + sum_j m_j v_j of row i into x->L
 * (upper = 0) or x->H (upper = 1), and S_v = |t| + sum_j |m_j v_j| into
 * x->S (all scaled).  m[i][0..3] finite and xu_vertex() != 0 required. */
void xu_vertex_bounds(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                      int i, int upper);
/* Convert a scaled value to a rational, exactly. */
void xu_scaled_to_q(mpq_t q, const mpz_t v);

/* Exact value of row i at corner c (bit j of c picks hi[j], else lo[j]),
 * computed with mpq_t only. */
void xu_corner_q(xu_exact *x, mpq_t r, const cbx_affine *a, const cbx_box *in,
                 int i, unsigned c);
/* Number of the 16 inequalities lo <= corner <= hi (8 corners) that fail,
 * on the mpq path. */
int xu_corner_failures(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                       int i, double lo, double hi);
/* 1 if min/max over the 8 mpq corners equal the fixed-point L and H of the
 * last xu_row_bounds() (call xu_row_bounds(x, a, in, i) first). */
int xu_bounds_match_corners(xu_exact *x, const cbx_affine *a,
                            const cbx_box *in, int i);

/* ---- checking one call ------------------------------------------------ */

/* The checks; v->flag[f] counts the failed items of check f (cases or
 * axes, see xu_stats_print) and v->applied[f] the items it looked at. */
enum {
    XU_F_STATUS,     /* status differs from the exactly computed one       */
    XU_F_UNSET,      /* a NaN (our pre-fill) is left in *out               */
    XU_F_SPECIAL,    /* EINVAL / EMPTY output not exactly as specified     */
    XU_F_OOB,        /* rule C axis (infinite map entry) not exactly
                        [-inf, +inf]                                       */
    XU_F_FINITE,     /* full-row (rule A) axis not finite (or lo > hi)     */
    XU_F_CONTAIN,    /* rule A: out.lo > L or out.hi < H (exact)           */
    XU_F_PROVEN,     /* rule A: beyond 12 u S + 2^-1065 (proven tightness) */
    XU_F_CORNER,     /* rule A: mpq 8-corner check failed (subset)         */
    XU_F_CROSS,      /* rule A: mpq corners disagree with fixed-point L/H  */
    XU_F_INFEND,     /* rule B end that must be infinite (U or L) is not
                        exactly -inf (lower) / +inf (upper)                */
    XU_F_ENDFIN,     /* rule B end that must be finite (F) is not          */
    XU_F_ENDCONT,    /* rule B finite end on the wrong side of the exact
                        vertex value (not containing the image)            */
    XU_F_ENDPROVEN,  /* rule B end beyond 12 u S_v + 2^-1065               */
    XU_F_ENDCORNER,  /* rule B: a finite end fails against the 8 extended
                        corners, mpq (subset)                              */
    XU_F_ENDCROSS,   /* rule B: the mpq extended corners' inf / sup (or
                        unboundedness) disagree with the vertex (subset)   */
    XU_F_INPUT,      /* *a or *in changed by the call                      */
    XU_NFLAGS
};
extern const char *const xu_flag_name[XU_NFLAGS];

typedef struct xu_axis {
    int checked;        /* rule A, finite output: excess is meaningful    */
    double ex_lo, ex_hi;
    int exact;          /* out.lo == L and out.hi == H exactly            */
    int tiny;           /* u S < 2^XU_TINY eta                            */
    int end_kind[2];    /* XU_END_* of the lower / upper end (-1: none,
                           i.e. EINVAL or EMPTY)                          */
    int end_checked[2]; /* rule B finite end: ex_end is meaningful        */
    double ex_end[2];   /* its excess, units of u S_v + eta               */
    int end_tiny[2];    /* u S_v < 2^XU_TINY eta                          */
} xu_axis;

typedef struct xu_verdict {
    cbx_status expected, got;
    int oob_mask;       /* rows not full (rule B or C)                     */
    int loss_mask;      /* rows with a loss (kinds L, W)                   */
    int flag[XU_NFLAGS];
    int applied[XU_NFLAGS];
    int failed;         /* any flag set                                    */
    xu_axis ax[3];
    char why[256];      /* first failure, for the log                      */
} xu_verdict;

/* Pre-fill *out with NaN, call cbx_transform_box, check everything.
 * corners != 0 adds the mpq corner and cross checks.  Returns v->failed. */
int xu_run_case(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                cbx_box *out, int corners, xu_verdict *v);
/* The checks of xu_run_case on a result already computed (status got,
 * output *out) without calling the library (the input check is not
 * made).  Clears *v first.  Returns v->failed. */
int xu_check_result(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                    const cbx_box *out, cbx_status got, int corners,
                    xu_verdict *v);

/* ---- statistics ------------------------------------------------------- */

#define XU_NBINS 9
typedef struct xu_stats {
    long cases, failed;
    long flag_fail[XU_NFLAGS];
    long flag_checked[XU_NFLAGS]; /* how many cases (axes for per-axis
                                     checks) each check looked at         */
    long status_seen[4];          /* OK, EMPTY, EINVAL, ERANGE expected    */
    long ends_kind[XU_NEND];      /* ends by expected kind (A F U L W)     */
    long vends, vends_tiny;       /* rule B finite ends with an excess     */
    double max_vend, sum_vend;    /* over the ends with u S_v >= 2^XU_TINY eta */
    double max_vend_tiny;
    long axes;                    /* rule A axes with an excess value      */
    long axes_exact;
    long over_target;             /* axis sides with excess > 8            */
    double max_lo, max_hi, sum_lo, sum_hi;
    /* the same split by scale: u S >= 2^XU_TINY eta ("normal") or not */
    long axes_tiny, over_target_norm;
    double max_norm, sum_norm, max_tiny, sum_tiny;
    /* the input with the largest normal-scale excess, to reproduce it */
    cbx_affine worst_a;
    cbx_box worst_in;
    int worst_axis;
    long hist[XU_NBINS];          /* of both sides together                */
} xu_stats;

void xu_stats_init(xu_stats *s);
void xu_stats_add(xu_stats *s, const xu_verdict *v, const cbx_affine *a,
                  const cbx_box *in);
void xu_stats_print(FILE *f, const char *title, const xu_stats *s);

/* ---- printing --------------------------------------------------------- */

int xu_status_index(cbx_status s);  /* 0..3, or -1 if not a known value */
void xu_print_case(FILE *f, const cbx_affine *a, const cbx_box *in);
void xu_print_box(FILE *f, const char *label, const cbx_box *b);

/* Shared by the projective oracles (tests/psph_oracle.c, pnear_oracle.c,
 * pball_oracle.c): the special outputs, an affine row at a rational point,
 * the dot product of two rows' linear parts, a rational point of a ball,
 * and qsort's order on doubles. */
int xu_whole_box(const cbx_box *o);   /* every axis [-inf, +inf] */
int xu_empty_box(const cbx_box *o);   /* every axis lo = +inf, hi = -inf */
int xu_whole_boxf(const cbx_boxf *o); /* the same, binary32 */
int xu_empty_boxf(const cbx_boxf *o);
void xu_aff_q(mpq_t q, const double m[4], mpq_t const x[3]);   /* m0 x0 + m1 x1 + m2 x2 + m3, exactly */
void xu_dot3_q(mpq_t q, const double u[4], const double v[4]);  /* u0 v0 + u1 v1 + u2 v2, exactly */
/* x = c + r s q, q = (2u, 2v, u^2 + v^2 - 1) / (1 + u^2 + v^2) on the unit
 * sphere (exactly): a rational point of the ball |x - c| <= |r| for s in
 * [0, 1] (x initialised by the caller) */
void xu_ball_point(mpq_t x[3], const double c[3], double r, double u, double v, double s);
int xu_cmp_double(const void *a, const void *b);
/* Each end's distance to its exact end, in units of 2^-52 (1 + |end|), kept
 * for a projective oracle's summary (zero-initialised: empty). */
typedef struct xu_dists { double *v, worst; long n, cap; } xu_dists;
void xu_dists_add(xu_dists *d, double u);
void xu_dists_print(FILE *f, xu_dists *d);   /* median, 99th, 99.9th, largest (sorts d->v); nothing when empty */
void xu_dists_free(xu_dists *d);

/* ---- helpers for test_cbox, test_sphere and the demo (GMP only) --------
 * None of these calls the library, so test_exact / test_badinput still link
 * against a library without the cbox and sphere sources. */

/* v = z * 2^e exactly, e >= -1074 returned (v finite; z = 0 for v = 0). */
long xu_split_d(mpz_t z, double v);
/* z = m * c * 2^XU_SHIFT, exactly (m, c finite). */
void xu_scaled_mul(xu_exact *x, mpz_t z, double m, double c);
/* gap / (u S + eta) as a double (a few ulps of error; statistics only);
 * gap and S are scaled by 2^XU_SHIFT, S >= 0.  Uses x->e as scratch
 * (gap and S must not be x->e). */
double xu_units(xu_exact *x, const mpz_t gap, const mpz_t S);
/* 1 if u S < 2^-1000 for a scaled S: where absolute terms of a widening
 * (2^-1065 and friends) dominate, a relative excess means nothing. */
int xu_scale_tiny(const mpz_t S);
/* 1 if a scaled gap is above 2^-1000 (absolute sanity bound there). */
int xu_gap_above_tiny_cap(const mpz_t gap);

/* The centre/half-diagonal form (struct cbx_cbox in certbox.h). */
int xu_cbox_has_nan(const cbx_affine *a, const cbx_cbox *in); /* a may be 0 */
int xu_cbox_is_empty(const cbx_cbox *in);        /* some h[j] < 0 (IEEE)   */
/* Row i of cbx_transform_cbox in the domain: m[i][0..3], c[], h[] finite,
 * every (m[i][j], c[j]) and (m[i][j], h[j]) in a class, |m[i][3]| <= 2^1018
 * (rule A below, a "full row"; specs: crow_full). */
int xu_cbox_row_in_domain(const cbx_affine *a, const cbx_cbox *in, int i);

/* The rules of cbx_transform_cbox, per output axis i (row m = m[i][0..2],
 * t = m[i][3]), for an input without NaN and with every h[j] >= 0 (IEEE;
 * -0.0 is not negative), where the input box is [c_j - h_j, c_j + h_j]:
 *   'A' full row (xu_cbox_row_in_domain): the kernel; finite, the 8
 *       corners c_j -+ h_j inside, each end within 12 u S + 2^-1065 of the
 *       exact end (cbox_tight), S = |t| + sum_j |m_j c_j| + |m_j h_j|;
 *   'D' not full, but the DROPPED row is: every column j with m_j == 0
 *       (also -0.0) takes c_j' = h_j' = 0 whatever c_j, h_j are (+-inf and
 *       out-of-domain magnitudes included: 0 * x = 0 for every real x, and
 *       the image does not depend on x_j), the other columns keep c_j, h_j;
 *       m, t finite and every (m_j, c_j'), (m_j, h_j') in a class,
 *       |t| <= 2^1018 (specs: crow_dfull).  The kernel on the dropped row:
 *       finite, the 8 corners of the dropped box inside (a dropped column
 *       contributes exactly 0), cbox_tight with S' of the dropped row;
 *   'W' otherwise (an infinite or out-of-domain entry in a column with
 *       m_j != 0, an infinite map entry, |t| > 2^1018): exactly c = 0,
 *       h = +inf, a loss.
 * Status CBX_OK iff no axis is 'W', else CBX_ERANGE; NaN anywhere (a dropped
 * column included) -> CBX_EINVAL; some h[j] < 0 (a dropped column included)
 * -> CBX_EMPTY. */
enum { XU_CAX_FULL, XU_CAX_DROP, XU_CAX_LOST, XU_NCAX };
extern const char xu_cax_char[XU_NCAX + 1]; /* "ADW" */
/* *d = the input with row i's zero-coefficient columns dropped (c = h = 0
 * where m[i][j] == 0; the other columns copied). */
void xu_cbox_dropped(const cbx_affine *a, const cbx_cbox *in, int i, cbx_cbox *d);
/* The kind of output axis i (XU_CAX_*); input without NaN, not empty. */
int xu_cbox_axis_kind(const cbx_affine *a, const cbx_cbox *in, int i);
/* Bit i set when axis i is 'W' (a loss). */
int xu_cbox_loss_mask(const cbx_affine *a, const cbx_cbox *in);
/* The three kinds as "ADW"-letters, e.g. "ADW" (s: at least 4 chars). */
void xu_cbox_kinds_str(const cbx_affine *a, const cbx_cbox *in, char s[4]);
cbx_status xu_cbox_expected_status(const cbx_affine *a, const cbx_cbox *in);

/* Exact containment of t -+ sqrt(s') where s' = s / 2^(2 sh) (s an integer
 * >= 0, sh >= 1074 so that every double times 2^sh is an integer):
 *   xu_sqrt_lo_ok: lo <= t - sqrt(s')  <=>  t - lo >= 0 and (t - lo)^2 >= s'
 *   xu_sqrt_hi_ok: hi >= t + sqrt(s')  <=>  hi - t >= 0 and (hi - t)^2 >= s'
 * lo, hi, t finite.  Use x->d and x->t as scratch (s must be neither). */
int xu_sqrt_lo_ok(xu_exact *x, const mpz_t s, unsigned long sh, double t,
                  double lo);
int xu_sqrt_hi_ok(xu_exact *x, const mpz_t s, unsigned long sh, double t,
                  double hi);
/* The proven tightness of a ball's end (specs/cbx_spec.h, ball_tight):
 * |end - t| <= sqrt(s') + K 2^-uexp (|t| + sqrt(s')) + 2^-eexp, exactly
 * (s' = s / 2^(2 sh) as above; exact when t 2^(sh - uexp) is an integer,
 * as for a float t and sh >= 1074, and sh >= eexp).  Uses x->d, x->t, x->e. */
int xu_sqrt_gap_ok(xu_exact *x, const mpz_t s, unsigned long sh, double t, double end,
                   unsigned long k, unsigned long uexp, unsigned long eexp);
/* z = v * 2^sh exactly (sh >= 1074, v finite). */
void xu_scaled_sh(mpz_t z, double v, unsigned long sh);

/* splitmix64, the generator of test_exact, shared by the newer tests. */
typedef struct xu_rng { uint64_t s; } xu_rng;
uint64_t xu_rng_next(xu_rng *r);
int xu_rng_int(xu_rng *r, int lo, int hi);          /* uniform in [lo, hi] */
double xu_rng_sign(xu_rng *r);                      /* -1.0 or 1.0         */
double xu_rng_unit(xu_rng *r);                      /* [0, 1), 53 bits     */
/* |v| in [0, 2^emax]: 4% zero, 4% exactly 2^emax, some subnormals (when
 * emin <= -1022), otherwise a full mantissa with exponent in [emin, emax). */
double xu_gen_mag(xu_rng *r, int emin, int emax);
double xu_gen_signed(xu_rng *r, int emin, int emax); /* with -0.0 */
/* A random case of cbx_transform_box in the current format (the values
 * are the format's): ~82% in the domain by construction (classes, narrow
 * exponents, cancelling translations), ~10% pushed out of it, ~5%
 * half-spaces, ~1.5% NaN, ~1.5% empty.  The draws of test_exact. */
void xu_gen_case(xu_rng *r, cbx_affine *a, cbx_box *b);
/* A signed NaN in one of the 18 numbers: a's 12 entries, v0[0..2], v1[0..2]
 * (a box's lo and hi, or a cbox's c and h); the NaN draws of xu_gen_case. */
void xu_inject_nan(xu_rng *r, cbx_affine *a, double v0[3], double v1[3]);
/* A uniformly random rotation: a unit quaternion drawn by rejection from
 * [-1, 1)^4 (four xu_rng_unit draws per try), then its rotation matrix. */
void xu_rand_rotation(xu_rng *r, double R[3][3]);

/* Every value a caller may pass as a class (the cls of
 * cbx_transform_box_as, or the cls field of a cbx_prepared, set by hand):
 * the five cbx_class values GENERAL .. IDENTITY (0 .. 4) first, then ints
 * outside the enum: 5, 7, -1, -3, INT_MAX, INT_MIN.  A value v is a class
 * of a map of smallest class c (each class is contained in the next) iff
 * 0 <= v <= c. */
#define XU_NCLS_VALUES 11
extern const int xu_cls_values[XU_NCLS_VALUES];
/* Its name: "GENERAL" .. "IDENTITY", else the number ("7", "INT_MIN"). */
const char *xu_cls_str(int cls, char buf[16]);

/* Command-line argument n as an unsigned number (decimal, 0x.. hex), or
 * dflt when absent; anything else prints "usage: PROG usage" and exits 2. */
unsigned long long xu_arg_num(int argc, char **argv, int n, unsigned long long dflt,
                              const char *usage);

/* Literal maps and boxes for hard-case tables: a row is {m[i][0], m[i][1],
 * m[i][2], t_i}; a box is given per axis as (lo0, hi0, lo1, hi1, lo2, hi2). */
#define XU_ROW(a, b, c, t) { a, b, c, t }
#define XU_MAT(r0, r1, r2) { { r0, r1, r2 } }
#define XU_BOX(l0, h0, l1, h1, l2, h2) { { l0, l1, l2 }, { h0, h1, h2 } }

/* The slerp (or nlerp) oracle of the rotation-motion tests (test_trs,
 * test_scene, test_gltf).  xu_slerp_keys: the unit quaternions q0/|q0|
 * and q1/|q1|, q1 negated when the exact q0.q1 is negative (arc = +1 or -1
 * forces the sign instead: the two arcs of a tie; dot_neg records the
 * exact sign), and the angle th between them, all in MPFR at the
 * precision given to xu_slerp_init.  xu_slerp_at: the unit quaternion at
 * s, (sin((1-s) th) q0 + sin(s th) q1) / sin th, or (1-s) q0 + s q1 for
 * nlerp or th < 2^-200, normalised; q[] at the caller's precision. */
typedef struct xu_slerp {
    mpfr_t q0[4], q1[4], th, sth, w0, w1, n;
    int nlerp, small, dot_neg;
} xu_slerp;
void xu_slerp_init(xu_slerp *e, mpfr_prec_t prec);
void xu_slerp_clear(xu_slerp *e);
void xu_slerp_keys(xu_slerp *e, const double q0[4], const double q1[4], int nlerp, int arc);
void xu_slerp_at(xu_slerp *e, mpfr_srcptr s, mpfr_t q[4]);

#endif /* EXACT_UTIL_H */
