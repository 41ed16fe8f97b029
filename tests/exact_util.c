/* exact_util: exact GMP oracle for the certbox tests (see exact_util.h). */
#include "exact_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <limits.h>

/* Same order as dom_pair in specs/cbx_spec.h; 509 is in the spec's list
 * even though the comment in certbox.h only names 0, 64, ..., 960, 1018. */
const int xu_class_k[XU_NCLASS] = {
    509, 0, 64, 128, 192, 256, 320, 384, 448, 512,
    576, 640, 704, 768, 832, 896, 960, 1018
};

/* The two formats (include/cbx_prec_begin.h has the library's side). */
const xu_format xu_binary64 = {
    "binary64", 53, 1074, 1018, 1065, 1000, 1023, -1022, 200, 900,
    { 509, 0, 64, 128, 192, 256, 320, 384, 448, 512,
      576, 640, 704, 768, 832, 896, 960, 1018 }
};
const xu_format xu_binary32 = {
    "binary32", 24, 149, 122, 140, 75, 127, -126, 24, 100,
    { 61, 0, 8, 16, 24, 32, 40, 48, 56, 64,
      72, 80, 88, 96, 104, 112, 120, 122 }
};
const xu_format *xu_fmt = &xu_binary64;
void xu_set_format(const xu_format *f) { xu_fmt = f; }

/* The next value of the format above x (x a value of the format). */
double xu_next_up(double x)
{
    if (xu_fmt->p == 24) return (double)nextafterf((float)x, HUGE_VALF);
    return nextafter(x, HUGE_VAL);
}

/* d rounded to the format (to nearest).  Through a volatile float: GCC
 * 12.2 at -O2 drops the rounding of (double)(float)(a * b) in loops its
 * SLP vectorizer packs (observed here; tests/test_ieee.c keeps the
 * reproducer), which would hand the library values that are not floats. */
double xu_round_fmt(double d)
{
    volatile float f;
    if (xu_fmt->p != 24) return d;
    f = (float)d;
    return f;
}

/* The largest finite value of the format. */
double xu_fmt_max(void) { return xu_fmt->p == 24 ? (double)FLT_MAX : DBL_MAX; }

const char *const xu_flag_name[XU_NFLAGS] = {
    "status", "out-set", "special-out", "oob-axes", "finite",
    "containment", "proven-tight", "corners", "cross-LH",
    "inf-end", "end-finite", "end-contain", "end-proven", "end-corners",
    "end-cross", "inputs"
};

const char xu_end_char[XU_NEND + 1] = "AFULW";

/* ---------------------------------------------------------------------- */
/* Domain and expected status                                             */
/* ---------------------------------------------------------------------- */

/* x != x is the portable NaN test; kept in one place so -ffast-math-like
 * surprises would show up in one spot. */
int xu_is_nan(double x) { return x != x; }

int xu_has_nan(const cbx_affine *a, const cbx_box *in)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (xu_is_nan(a->m[i][j])) return 1;
    for (j = 0; j < 3; j++)
        if (xu_is_nan(in->lo[j]) || xu_is_nan(in->hi[j])) return 1;
    return 0;
}

/* isinf() and a sign test: exact, and independent of the library's
 * comparisons with DBL_MAX. */
static int xu_is_pinf(double d) { return d > 0 && isinf(d); }
static int xu_is_ninf(double d) { return d < 0 && isinf(d); }

int xu_is_empty(const cbx_box *in)
{
    int j;
    for (j = 0; j < 3; j++)
        if (in->lo[j] > in->hi[j] || xu_is_pinf(in->lo[j]) || xu_is_ninf(in->hi[j]))
            return 1;
    return 0;
}

/* ldexp(1, k) for 0 <= k <= 1018 is an exact power of two, and comparing
 * fabs(v) (exact) with it is an exact comparison; an infinity is never
 * <= a finite bound, so non-finite inputs fall out by themselves. */
int xu_severity(cbx_status s)
{
    return s == CBX_EINVAL ? 3 : s == CBX_ERANGE ? 2 : s == CBX_EMPTY ? 1 : 0;
}

int xu_pair_in_domain(double m, double c)
{
    int n;
    double am = fabs(m), ac = fabs(c);
    for (n = 0; n < XU_NCLASS; n++) {
        int k = xu_fmt->class_k[n];
        if (am <= ldexp(1.0, k) && ac <= ldexp(1.0, xu_fmt->rt - k)) return 1;
    }
    return 0;
}

int xu_row_in_domain(const cbx_affine *a, const cbx_box *in, int i)
{
    int j;
    for (j = 0; j < 3; j++) {
        if (!xu_pair_in_domain(a->m[i][j], in->lo[j])) return 0;
        if (!xu_pair_in_domain(a->m[i][j], in->hi[j])) return 0;
    }
    return fabs(a->m[i][3]) <= ldexp(1.0, xu_fmt->rt);
}

int xu_oob_mask(const cbx_affine *a, const cbx_box *in)
{
    int i, mask = 0;
    for (i = 0; i < 3; i++)
        if (!xu_row_in_domain(a, in, i)) mask |= 1 << i;
    return mask;
}

int xu_map_row_finite(const cbx_affine *a, int i)
{
    return isfinite(a->m[i][0]) && isfinite(a->m[i][1]) && isfinite(a->m[i][2])
           && isfinite(a->m[i][3]);
}

/* The rule-B vertex: for the lower end the box end where m_j x is least,
 * chosen by the sign of m_j (exact comparisons with 0; -0.0 == 0); m_j == 0
 * contributes 0 whatever the box (0 * inf = 0 over the reals). */
int xu_vertex(const cbx_affine *a, const cbx_box *in, int i, int upper, double v[3])
{
    int j;
    for (j = 0; j < 3; j++) {
        double m = a->m[i][j], c;
        if (m == 0) {
            v[j] = 0.0;
            continue;
        }
        if ((m > 0) != (upper != 0)) c = in->lo[j]; /* m > 0 lower, m < 0 upper */
        else c = in->hi[j];
        if (isinf(c)) return 0; /* -inf below / +inf above: no real point is
                                   outside it, so the image is unbounded */
        v[j] = c;
    }
    return 1;
}

int xu_end_kind(const cbx_affine *a, const cbx_box *in, int i, int upper)
{
    double v[3];
    int j;
    if (xu_row_in_domain(a, in, i)) return XU_END_FULL;
    if (!xu_map_row_finite(a, i)) return XU_END_WHOLE;
    if (!xu_vertex(a, in, i, upper, v)) return XU_END_UNB;
    for (j = 0; j < 3; j++)
        if (!xu_pair_in_domain(a->m[i][j], v[j])) return XU_END_LOST;
    if (!(fabs(a->m[i][3]) <= ldexp(1.0, xu_fmt->rt))) return XU_END_LOST;
    return XU_END_VERTEX;
}

static int xu_kind_is_loss(int k) { return k == XU_END_LOST || k == XU_END_WHOLE; }

int xu_row_loss(const cbx_affine *a, const cbx_box *in, int i)
{
    return xu_kind_is_loss(xu_end_kind(a, in, i, 0))
           || xu_kind_is_loss(xu_end_kind(a, in, i, 1));
}

int xu_loss_mask(const cbx_affine *a, const cbx_box *in)
{
    int i, mask = 0;
    for (i = 0; i < 3; i++)
        if (xu_row_loss(a, in, i)) mask |= 1 << i;
    return mask;
}

void xu_ends_str(const cbx_affine *a, const cbx_box *in, char s[9])
{
    int i, n = 0;
    for (i = 0; i < 3; i++) {
        if (i) s[n++] = ' ';
        s[n++] = xu_end_char[xu_end_kind(a, in, i, 0)];
        s[n++] = xu_end_char[xu_end_kind(a, in, i, 1)];
    }
    s[n] = '\0';
}

cbx_status xu_expected_status(const cbx_affine *a, const cbx_box *in)
{
    if (xu_has_nan(a, in)) return CBX_EINVAL;
    if (xu_is_empty(in)) return CBX_EMPTY;
    return xu_loss_mask(a, in) ? CBX_ERANGE : CBX_OK;
}

/* ---------------------------------------------------------------------- */
/* Fixed-point exact arithmetic                                           */
/* ---------------------------------------------------------------------- */

void xu_init(xu_exact *x)
{
    mpz_inits(x->L, x->H, x->S, x->pl, x->ph, x->t, x->d, x->e,
              x->mm, x->mc, (mpz_ptr)0);
    mpq_inits(x->q, x->qa, x->qb, x->qmin, x->qmax, (mpq_ptr)0);
}

void xu_clear(xu_exact *x)
{
    mpz_clears(x->L, x->H, x->S, x->pl, x->ph, x->t, x->d, x->e,
               x->mm, x->mc, (mpz_ptr)0);
    mpq_clears(x->q, x->qa, x->qb, x->qmin, x->qmax, (mpq_ptr)0);
}

/* v = z * 2^e with z an integer and e >= -1074 (v finite).  frexp gives
 * |f| in [0.5, 1), so f*2^53 is an integer; for subnormals the exponent
 * can drop below -1074, and then the low bits of the mantissa are zero,
 * so shifting them out with ldexp is exact. */
static long xu_split(mpz_t z, double v)
{
    int E;
    double f, m;
    long e;
    if (v == 0.0) {
        mpz_set_ui(z, 0);
        return 0;
    }
    f = frexp(v, &E);
    m = ldexp(f, 53);
    e = (long)E - 53;
    if (e < -1074) {
        m = ldexp(m, (int)(e + 1074));
        e = -1074;
    }
    mpz_set_d(z, m); /* exact: m is an integer below 2^53 */
    return e;
}

void xu_scaled_d(xu_exact *x, mpz_t z, double v)
{
    long e = xu_split(x->mm, v);
    mpz_mul_2exp(z, x->mm, (mp_bitcnt_t)(e + XU_SHIFT));
}

/* z = m * c * 2^XU_SHIFT; the exponent sum is >= -2148 = -XU_SHIFT. */
static void xu_scaled_prod(xu_exact *x, mpz_t z, double m, double c)
{
    long em = xu_split(x->mm, m);
    long ec = xu_split(x->mc, c);
    mpz_mul(z, x->mm, x->mc);
    mpz_mul_2exp(z, z, (mp_bitcnt_t)(em + ec + XU_SHIFT));
}

/* S += |v| */
static void xu_add_abs(mpz_t S, const mpz_t v)
{
    if (mpz_sgn(v) >= 0) mpz_add(S, S, v);
    else mpz_sub(S, S, v);
}

void xu_row_bounds(xu_exact *x, const cbx_affine *a, const cbx_box *in, int i)
{
    int j;
    xu_scaled_d(x, x->L, a->m[i][3]);
    mpz_set(x->H, x->L);
    mpz_abs(x->S, x->L);
    for (j = 0; j < 3; j++) {
        xu_scaled_prod(x, x->pl, a->m[i][j], in->lo[j]);
        xu_scaled_prod(x, x->ph, a->m[i][j], in->hi[j]);
        /* min/max of the two products by exact comparison, not by the
         * sign of m, so this does not depend on lo <= hi reasoning */
        if (mpz_cmp(x->pl, x->ph) <= 0) {
            mpz_add(x->L, x->L, x->pl);
            mpz_add(x->H, x->H, x->ph);
        } else {
            mpz_add(x->L, x->L, x->ph);
            mpz_add(x->H, x->H, x->pl);
        }
        /* |m| max(|lo|,|hi|) = max(|m lo|, |m hi|) */
        xu_add_abs(x->S, mpz_cmpabs(x->pl, x->ph) >= 0 ? x->pl : x->ph);
    }
}

void xu_vertex_bounds(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                      int i, int upper)
{
    double v[3];
    mpz_ptr V = upper ? x->H : x->L;
    int j;
    if (!xu_vertex(a, in, i, upper, v)) { /* misuse: leave a defined value */
        mpz_set_ui(V, 0);
        mpz_set_ui(x->S, 0);
        return;
    }
    xu_scaled_d(x, V, a->m[i][3]);
    mpz_abs(x->S, V);
    for (j = 0; j < 3; j++) {
        xu_scaled_prod(x, x->pl, a->m[i][j], v[j]);
        mpz_add(V, V, x->pl);
        xu_add_abs(x->S, x->pl);
    }
}

int xu_cmp_scaled_d(xu_exact *x, const mpz_t v, double d)
{
    int c;
    xu_scaled_d(x, x->t, d);
    c = mpz_cmp(v, x->t);
    return (c > 0) - (c < 0);
}

void xu_scaled_to_q(mpq_t q, const mpz_t v)
{
    mpq_set_z(q, v);
    mpq_div_2exp(q, q, XU_SHIFT);
}

/* n * 2^p / den as a double (den > 0, u = 2^-p); relative error a few
 * ulps, which is plenty for statistics.  The exact decisions are made on
 * mpz. */
static double xu_ratio53(const mpz_t n, const mpz_t den)
{
    long en, ed;
    double fn, fd;
    if (mpz_sgn(n) == 0) return 0.0;
    fn = mpz_get_d_2exp(&en, n);
    fd = mpz_get_d_2exp(&ed, den);
    return ldexp(fn / fd, (int)(en - ed + xu_fmt->p));
}

/* x->e = (u S + eta) * 2^(XU_SHIFT + p) = S + 2^(XU_SHIFT - emin + p)
 * (binary64: S + 2^1127). */
static void xu_unit_den(xu_exact *x)
{
    mpz_set_ui(x->e, 1);
    mpz_mul_2exp(x->e, x->e, XU_SHIFT - xu_fmt->emin + xu_fmt->p);
    mpz_add(x->e, x->e, x->S);
}

/* gap = exact distance by which the bound is outside the exact bound,
 * scaled (negative = not contained).  Leaves it in x->d. */
static void xu_gap_lo(xu_exact *x, double lo)
{
    xu_scaled_d(x, x->d, lo);
    mpz_sub(x->d, x->L, x->d);
}

static void xu_gap_hi(xu_exact *x, double hi)
{
    xu_scaled_d(x, x->d, hi);
    mpz_sub(x->d, x->d, x->H);
}

double xu_excess_lo(xu_exact *x, double lo)
{
    xu_gap_lo(x, lo);
    xu_unit_den(x);
    return xu_ratio53(x->d, x->e);
}

double xu_excess_hi(xu_exact *x, double hi)
{
    xu_gap_hi(x, hi);
    xu_unit_den(x);
    return xu_ratio53(x->d, x->e);
}

/* gap * 2^p <= 12 S + 2^(XU_SHIFT - tight_e + p), all scaled by
 * 2^(XU_SHIFT + p): exactly the spec's 12 u S + 2^-tight_e (binary64:
 * 0x1.8p-50 * S + 0x1p-1065). */
static int xu_gap_within_proven(xu_exact *x)
{
    mpz_mul_2exp(x->t, x->d, (mp_bitcnt_t)xu_fmt->p);
    mpz_set_ui(x->e, 1);
    mpz_mul_2exp(x->e, x->e, XU_SHIFT - xu_fmt->tight_e + xu_fmt->p);
    mpz_addmul_ui(x->e, x->S, 12);
    return mpz_cmp(x->t, x->e) <= 0;
}

int xu_lo_within_proven(xu_exact *x, double lo)
{
    xu_gap_lo(x, lo);
    return xu_gap_within_proven(x);
}

int xu_hi_within_proven(xu_exact *x, double hi)
{
    xu_gap_hi(x, hi);
    return xu_gap_within_proven(x);
}

/* ---------------------------------------------------------------------- */
/* Independent mpq path: the 8 corners                                    */
/* ---------------------------------------------------------------------- */

void xu_corner_q(xu_exact *x, mpq_t r, const cbx_affine *a, const cbx_box *in,
                 int i, unsigned c)
{
    int j;
    mpq_set_d(r, a->m[i][3]);
    for (j = 0; j < 3; j++) {
        mpq_set_d(x->qa, a->m[i][j]);
        mpq_set_d(x->qb, (c >> j) & 1u ? in->hi[j] : in->lo[j]);
        mpq_mul(x->qa, x->qa, x->qb);
        mpq_add(r, r, x->qa);
    }
}

int xu_corner_failures(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                       int i, double lo, double hi)
{
    unsigned c;
    int bad = 0;
    mpq_set_d(x->qmin, lo);
    mpq_set_d(x->qmax, hi);
    for (c = 0; c < 8; c++) {
        xu_corner_q(x, x->q, a, in, i, c);
        if (mpq_cmp(x->qmin, x->q) > 0) bad++;
        if (mpq_cmp(x->q, x->qmax) > 0) bad++;
    }
    return bad;
}

int xu_bounds_match_corners(xu_exact *x, const cbx_affine *a,
                            const cbx_box *in, int i)
{
    unsigned c;
    for (c = 0; c < 8; c++) {
        xu_corner_q(x, x->q, a, in, i, c);
        if (c == 0 || mpq_cmp(x->q, x->qmin) < 0) mpq_set(x->qmin, x->q);
        if (c == 0 || mpq_cmp(x->q, x->qmax) > 0) mpq_set(x->qmax, x->q);
    }
    xu_scaled_to_q(x->qa, x->L);
    xu_scaled_to_q(x->qb, x->H);
    return mpq_equal(x->qa, x->qmin) && mpq_equal(x->qb, x->qmax);
}

/* ---------------------------------------------------------------------- */
/* Checking one call                                                      */
/* ---------------------------------------------------------------------- */

static void xu_fail(xu_verdict *v, int flag, const char *why)
{
    v->flag[flag]++;
    if (!v->failed) {
        size_t n = sizeof v->why - 1;
        strncpy(v->why, why, n);
        v->why[n] = '\0';
    }
    v->failed = 1;
}

/* The whole output must be lo = L0, hi = H0 on every axis (EINVAL/EMPTY). */
static void xu_check_special(xu_verdict *v, const cbx_box *out, int whole)
{
    int i;
    v->applied[XU_F_SPECIAL]++;
    for (i = 0; i < 3; i++) {
        int ok = whole ? xu_is_ninf(out->lo[i]) && xu_is_pinf(out->hi[i])
                       : xu_is_pinf(out->lo[i]) && xu_is_ninf(out->hi[i]);
        if (!ok) {
            xu_fail(v, XU_F_SPECIAL, whole ? "EINVAL: out is not [-inf,+inf]^3"
                                           : "EMPTY: out is not lo=+inf hi=-inf");
            return;
        }
    }
}

/* One in-domain axis: finite, contains [L, H] exactly, within the proven
 * tightness, and (optionally) the mpq corner checks. */
static void xu_check_axis(xu_exact *x, xu_verdict *v, const cbx_affine *a,
                          const cbx_box *in, const cbx_box *out, int i,
                          int corners)
{
    double lo = out->lo[i], hi = out->hi[i];
    char why[160];
    int glo, ghi;

    v->applied[XU_F_FINITE]++;
    if (!isfinite(lo) || !isfinite(hi) || lo > hi) {
        snprintf(why, sizeof why, "axis %d in domain but out = [%.17g, %.17g]", i, lo, hi);
        xu_fail(v, XU_F_FINITE, why);
        return;
    }
    xu_row_bounds(x, a, in, i);
    xu_unit_den(x);

    v->applied[XU_F_CONTAIN]++;
    v->applied[XU_F_PROVEN]++;
    xu_gap_lo(x, lo);
    glo = mpz_sgn(x->d);
    v->ax[i].ex_lo = xu_ratio53(x->d, x->e);
    if (!xu_gap_within_proven(x)) {
        snprintf(why, sizeof why, "axis %d: lo beyond 12uS+2^-%d (excess %.3g)", i, xu_fmt->tight_e,
                v->ax[i].ex_lo);
        xu_fail(v, XU_F_PROVEN, why);
    }
    xu_unit_den(x);
    xu_gap_hi(x, hi);
    ghi = mpz_sgn(x->d);
    v->ax[i].ex_hi = xu_ratio53(x->d, x->e);
    if (!xu_gap_within_proven(x)) {
        snprintf(why, sizeof why, "axis %d: hi beyond 12uS+2^-%d (excess %.3g)", i, xu_fmt->tight_e,
                v->ax[i].ex_hi);
        xu_fail(v, XU_F_PROVEN, why);
    }
    if (glo < 0 || ghi < 0) {
        snprintf(why, sizeof why, "axis %d: not contained (excess lo %.3g, hi %.3g)", i,
                v->ax[i].ex_lo, v->ax[i].ex_hi);
        xu_fail(v, XU_F_CONTAIN, why);
    }
    v->ax[i].checked = 1;
    v->ax[i].exact = glo == 0 && ghi == 0;
    /* u S < 2^XU_TINY eta  <=>  S 2^XU_SHIFT < 2^(XU_SHIFT - emin + p + XU_TINY) */
    v->ax[i].tiny = mpz_sizeinbase(x->S, 2) <= (size_t)(XU_SHIFT - xu_fmt->emin + xu_fmt->p + XU_TINY);

    if (corners) {
        v->applied[XU_F_CROSS]++;
        if (!xu_bounds_match_corners(x, a, in, i)) {
            snprintf(why, sizeof why, "axis %d: mpq corner min/max != fixed-point L/H", i);
            xu_fail(v, XU_F_CROSS, why);
        }
        v->applied[XU_F_CORNER]++;
        if (xu_corner_failures(x, a, in, i, lo, hi)) {
            snprintf(why, sizeof why, "axis %d: a corner image is outside out (mpq)", i);
            xu_fail(v, XU_F_CORNER, why);
        }
    }
}

/* Rule B, the mpq path (independent of xu_vertex): the 8 corners of the
 * box in extended arithmetic.  Term j of corner c is 0 for m_j == 0 (0 * inf
 * = 0), +-inf for an infinite coordinate (the sign of m_j times that of the
 * coordinate), else the exact m_j c_j.  A corner with both a +inf and a
 * -inf term has no value (skipped; such a row is unbounded on both sides,
 * which other corners show).  The least (greatest) corner value is the
 * exact inf (sup) of the image over the real points of the box.
 * Sets x->qmin / x->qmax when finite; *min_inf = 1 when the inf is -inf,
 * *max_inf = 1 when the sup is +inf. */
static void xu_ext_corners(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                           int i, int *min_inf, int *max_inf)
{
    unsigned c;
    int j, have_min = 0, have_max = 0;
    *min_inf = *max_inf = 0;
    for (c = 0; c < 8; c++) {
        int neg = 0, pos = 0;
        mpq_set_d(x->q, a->m[i][3]);
        for (j = 0; j < 3; j++) {
            double m = a->m[i][j], cj = (c >> j) & 1u ? in->hi[j] : in->lo[j];
            if (m == 0) continue;
            if (isinf(cj)) {
                if ((m > 0) == (cj > 0)) pos = 1;
                else neg = 1;
                continue;
            }
            mpq_set_d(x->qa, m);
            mpq_set_d(x->qb, cj);
            mpq_mul(x->qa, x->qa, x->qb);
            mpq_add(x->q, x->q, x->qa);
        }
        if (neg && pos) continue;
        if (neg) *min_inf = 1;
        else if (pos) *max_inf = 1;
        else {
            if (!have_min || mpq_cmp(x->q, x->qmin) < 0) mpq_set(x->qmin, x->q);
            if (!have_max || mpq_cmp(x->q, x->qmax) > 0) mpq_set(x->qmax, x->q);
            have_min = have_max = 1;
        }
    }
    /* every column has an end whose term is not +inf (not -inf): the
     * corner of those ends has a value, so a finite inf exists whenever
     * *min_inf is 0 (have_min); the same for the sup */
    if (!have_min) *min_inf = 1;
    if (!have_max) *max_inf = 1;
}

static const char *const xu_end_word[XU_NEND] = {
    "full-row", "vertex", "unbounded", "lost", "whole-line"
};

/* Rule B, one end (upper = 0: lower end). */
static void xu_check_end(xu_exact *x, xu_verdict *v, const cbx_affine *a,
                         const cbx_box *in, const cbx_box *out, int i, int upper,
                         int corners)
{
    double e = upper ? out->hi[i] : out->lo[i];
    const char *nm = upper ? "hi" : "lo";
    int k = v->ax[i].end_kind[upper];
    char why[200];

    if (k == XU_END_UNB || k == XU_END_LOST) {
        v->applied[XU_F_INFEND]++;
        if (!(upper ? xu_is_pinf(e) : xu_is_ninf(e))) {
            snprintf(why, sizeof why, "axis %d: %s end must be %s (%s) but is %.17g", i, nm,
                     upper ? "+inf" : "-inf", xu_end_word[k], e);
            xu_fail(v, XU_F_INFEND, why);
        }
    } else {
        int g;
        v->applied[XU_F_ENDFIN]++;
        if (!isfinite(e)) {
            snprintf(why, sizeof why, "axis %d: %s end must be finite (vertex in the domain) "
                     "but is %.17g", i, nm, e);
            xu_fail(v, XU_F_ENDFIN, why);
            return;
        }
        xu_vertex_bounds(x, a, in, i, upper);
        xu_unit_den(x);
        v->applied[XU_F_ENDCONT]++;
        v->applied[XU_F_ENDPROVEN]++;
        if (upper) xu_gap_hi(x, e);
        else xu_gap_lo(x, e);
        g = mpz_sgn(x->d);
        v->ax[i].ex_end[upper] = xu_ratio53(x->d, x->e);
        v->ax[i].end_checked[upper] = 1;
        v->ax[i].end_tiny[upper] = mpz_sizeinbase(x->S, 2) <= (size_t)(XU_SHIFT - xu_fmt->emin + xu_fmt->p + XU_TINY);
        if (g < 0) {
            snprintf(why, sizeof why, "axis %d: %s end %s the exact vertex value (excess %.3g)",
                     i, nm, upper ? "below" : "above", v->ax[i].ex_end[upper]);
            xu_fail(v, XU_F_ENDCONT, why);
        }
        if (!xu_gap_within_proven(x)) {
            snprintf(why, sizeof why, "axis %d: %s end beyond 12uS_v+2^-%d (excess %.3g)", i,
                     nm, xu_fmt->tight_e, v->ax[i].ex_end[upper]);
            xu_fail(v, XU_F_ENDPROVEN, why);
        }
    }

    if (corners) {
        int min_inf, max_inf, unb;
        xu_ext_corners(x, a, in, i, &min_inf, &max_inf);
        unb = upper ? max_inf : min_inf;
        v->applied[XU_F_ENDCROSS]++;
        if (unb != (k == XU_END_UNB)) {
            snprintf(why, sizeof why, "axis %d: mpq corners say the image is %s on the %s "
                     "side, the vertex rule says %s", i, unb ? "unbounded" : "bounded", nm,
                     xu_end_word[k]);
            xu_fail(v, XU_F_ENDCROSS, why);
        } else if (k == XU_END_VERTEX) {
            xu_vertex_bounds(x, a, in, i, upper);
            xu_scaled_to_q(x->qa, upper ? x->H : x->L);
            if (!mpq_equal(x->qa, upper ? x->qmax : x->qmin)) {
                snprintf(why, sizeof why, "axis %d: mpq corner %s != the fixed-point vertex "
                         "value", i, upper ? "sup" : "inf");
                xu_fail(v, XU_F_ENDCROSS, why);
            }
        }
        if (isfinite(e)) {
            v->applied[XU_F_ENDCORNER]++;
            mpq_set_d(x->qb, e);
            if (unb || (upper ? mpq_cmp(x->qb, x->qmax) < 0 : mpq_cmp(x->qb, x->qmin) > 0)) {
                snprintf(why, sizeof why, "axis %d: an extended corner image is %s the finite "
                         "%s end (mpq)", i, upper ? "above" : "below", nm);
                xu_fail(v, XU_F_ENDCORNER, why);
            }
        }
    }
}

static void xu_check_box_result(xu_exact *x, xu_verdict *v,
                                const cbx_affine *a, const cbx_box *in,
                                const cbx_box *out, int corners)
{
    int i;
    char why[96];
    v->oob_mask = xu_oob_mask(a, in);
    v->loss_mask = xu_loss_mask(a, in);
    for (i = 0; i < 3; i++) {
        int klo = xu_end_kind(a, in, i, 0), khi = xu_end_kind(a, in, i, 1);
        v->ax[i].end_kind[0] = klo;
        v->ax[i].end_kind[1] = khi;
        if (klo == XU_END_WHOLE) {
            v->applied[XU_F_OOB]++;
            if (!xu_is_ninf(out->lo[i]) || !xu_is_pinf(out->hi[i])) {
                snprintf(why, sizeof why, "axis %d: infinite map entry but not [-inf,+inf]", i);
                xu_fail(v, XU_F_OOB, why);
            }
        } else if (klo == XU_END_FULL) {
            xu_check_axis(x, v, a, in, out, i, corners);
        } else {
            xu_check_end(x, v, a, in, out, i, 0, corners);
            xu_check_end(x, v, a, in, out, i, 1, corners);
        }
    }
}

int xu_check_result(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                    const cbx_box *out, cbx_status got, int corners,
                    xu_verdict *v)
{
    int i;
    char why[96];

    memset(v, 0, sizeof *v);
    for (i = 0; i < 3; i++) v->ax[i].end_kind[0] = v->ax[i].end_kind[1] = -1;
    v->got = got;
    v->expected = xu_expected_status(a, in);

    v->applied[XU_F_STATUS]++;
    if (v->got != v->expected) {
        snprintf(why, sizeof why, "status %s (%d), expected %s", cbx_status_name(v->got),
                (int)v->got, cbx_status_name(v->expected));
        xu_fail(v, XU_F_STATUS, why);
    }
    v->applied[XU_F_UNSET]++;
    for (i = 0; i < 3; i++)
        if (xu_is_nan(out->lo[i]) || xu_is_nan(out->hi[i])) {
            xu_fail(v, XU_F_UNSET, "NaN left in out (field not written)");
            break;
        }

    if (v->expected == CBX_EINVAL) xu_check_special(v, out, 1);
    else if (v->expected == CBX_EMPTY) xu_check_special(v, out, 0);
    else xu_check_box_result(x, v, a, in, out, corners);
    return v->failed;
}

int xu_run_case(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                cbx_box *out, int corners, xu_verdict *v)
{
    cbx_affine a0 = *a;
    cbx_box in0 = *in;
    cbx_status got;
    int i, changed;

    /* NaN pre-fill: any field the library forgets to write stays NaN */
    for (i = 0; i < 3; i++) out->lo[i] = out->hi[i] = NAN;

    got = cbx_transform_box(a, in, out);
    changed = memcmp(&a0, a, sizeof a0) != 0 || memcmp(&in0, in, sizeof in0) != 0;
    /* check against the inputs as given (a call that changed them is
     * reported below; the oracle must not read the changed ones) */
    xu_check_result(x, &a0, &in0, out, got, corners, v);
    v->applied[XU_F_INPUT]++;
    if (changed) xu_fail(v, XU_F_INPUT, "the call modified its inputs");
    return v->failed;
}

/* ---------------------------------------------------------------------- */
/* Statistics                                                             */
/* ---------------------------------------------------------------------- */

static const double xu_bin_top[XU_NBINS - 1] = { 0, 0.5, 1, 2, 4, 6, 8, 12 };

void xu_stats_init(xu_stats *s) { memset(s, 0, sizeof *s); }

static void xu_stats_excess(xu_stats *s, double e)
{
    int b = 0;
    while (b < XU_NBINS - 1 && !(e < xu_bin_top[b])) b++;
    s->hist[b]++;
    if (e > 8) s->over_target++;
}

/* max/mean split by scale (call before s->axes++). */
static void xu_stats_scale(xu_stats *s, const xu_axis *ax, int i,
                           const cbx_affine *a, const cbx_box *in)
{
    double m = ax->ex_lo > ax->ex_hi ? ax->ex_lo : ax->ex_hi;
    long n_norm = s->axes - s->axes_tiny;
    if (ax->tiny) {
        if (s->axes_tiny == 0 || m > s->max_tiny) s->max_tiny = m;
        s->sum_tiny += ax->ex_lo + ax->ex_hi;
        s->axes_tiny++;
    } else {
        if (n_norm == 0 || m > s->max_norm) {
            s->max_norm = m;
            s->worst_a = *a;
            s->worst_in = *in;
            s->worst_axis = i;
        }
        s->sum_norm += ax->ex_lo + ax->ex_hi;
        s->over_target_norm += (ax->ex_lo > 8) + (ax->ex_hi > 8);
    }
}

void xu_stats_add(xu_stats *s, const xu_verdict *v, const cbx_affine *a,
                  const cbx_box *in)
{
    int f, i, si = xu_status_index(v->expected);
    s->cases++;
    if (v->failed) s->failed++;
    if (si >= 0) s->status_seen[si]++;
    for (f = 0; f < XU_NFLAGS; f++) {
        s->flag_fail[f] += v->flag[f];
        s->flag_checked[f] += v->applied[f];
    }
    for (i = 0; i < 3; i++) {
        const xu_axis *ax = &v->ax[i];
        int e;
        for (e = 0; e < 2; e++) {
            if (ax->end_kind[e] >= 0 && ax->end_kind[e] < XU_NEND)
                s->ends_kind[ax->end_kind[e]]++;
            if (!ax->end_checked[e]) continue;
            if (ax->end_tiny[e]) {
                if (s->vends_tiny == 0 || ax->ex_end[e] > s->max_vend_tiny)
                    s->max_vend_tiny = ax->ex_end[e];
                s->vends_tiny++;
            } else {
                if (s->vends == 0 || ax->ex_end[e] > s->max_vend) s->max_vend = ax->ex_end[e];
                s->sum_vend += ax->ex_end[e];
                s->vends++;
            }
        }
        if (!ax->checked) continue;
        if (s->axes == 0 || ax->ex_lo > s->max_lo) s->max_lo = ax->ex_lo;
        if (s->axes == 0 || ax->ex_hi > s->max_hi) s->max_hi = ax->ex_hi;
        s->sum_lo += ax->ex_lo;
        s->sum_hi += ax->ex_hi;
        xu_stats_scale(s, ax, i, a, in);
        s->axes++;
        s->axes_exact += ax->exact;
        xu_stats_excess(s, ax->ex_lo);
        xu_stats_excess(s, ax->ex_hi);
    }
}

static const char *const xu_flag_unit[XU_NFLAGS] = {
    "cases", "cases", "cases", "axes", "axes",
    "axes", "axes", "axes", "axes",
    "ends", "ends", "ends", "ends", "ends", "ends", "cases"
};

void xu_stats_print(FILE *f, const char *title, const xu_stats *s)
{
    int k;
    double n = s->axes ? (double)s->axes : 1.0;
    double mx = s->max_lo > s->max_hi ? s->max_lo : s->max_hi;
    fprintf(f, "== %s: %ld cases (expected OK %ld, EMPTY %ld, EINVAL %ld, "
               "ERANGE %ld)\n", title, s->cases, s->status_seen[0],
            s->status_seen[1], s->status_seen[2], s->status_seen[3]);
    for (k = 0; k < XU_NFLAGS; k++)
        fprintf(f, "  check %-12s %10ld %-5s checked, %6ld failed\n",
                xu_flag_name[k], s->flag_checked[k], xu_flag_unit[k],
                s->flag_fail[k]);
    fprintf(f, "  ends by rule: full-row A %ld, vertex F %ld, unbounded U %ld, "
               "lost L %ld, whole-line W %ld\n", s->ends_kind[XU_END_FULL],
            s->ends_kind[XU_END_VERTEX], s->ends_kind[XU_END_UNB], s->ends_kind[XU_END_LOST],
            s->ends_kind[XU_END_WHOLE]);
    if (s->vends + s->vends_tiny)
        fprintf(f, "  vertex ends (rule B, finite) checked: %ld; excess (units of u*S_v + "
                   "2^-%d): max %.4f mean %.4f over %ld ends with u*S_v >= 2^%d*eta, "
                   "max %.4f over %ld below\n", s->vends + s->vends_tiny, xu_fmt->emin, s->max_vend,
                s->vends ? s->sum_vend / (double)s->vends : 0.0, s->vends, XU_TINY,
                s->max_vend_tiny, s->vends_tiny);
    fprintf(f, "  in-domain (full-row) axes checked: %ld (exactly equal to the exact "
               "image: %ld)\n", s->axes, s->axes_exact);
    if (s->axes == 0) return;
    fprintf(f, "  excess lo: max %.4f  mean %.4f   (units of u*S + 2^-%d, u = 2^-%d)\n",
            s->max_lo, s->sum_lo / n, xu_fmt->emin, xu_fmt->p);
    fprintf(f, "  excess hi: max %.4f  mean %.4f\n", s->max_hi, s->sum_hi / n);
    fprintf(f, "  excess   : max %.4f  mean %.4f   target <= 8: %s (%ld sides "
               "above 8)\n", mx, (s->sum_lo + s->sum_hi) / (2 * n),
            mx <= 8 ? "met" : "NOT met", s->over_target);
    if (s->axes > s->axes_tiny)
        fprintf(f, "  excess, axes with u*S >= 2^%d*eta: max %.4f  mean %.4f  "
                   "(%ld axes, %ld sides above 8)\n", XU_TINY, s->max_norm,
                s->sum_norm / (2.0 * (double)(s->axes - s->axes_tiny)),
                s->axes - s->axes_tiny, s->over_target_norm);
    if (s->axes_tiny)
        fprintf(f, "  excess, axes with u*S <  2^%d*eta: max %.4f  mean %.4f  "
                   "(%ld axes)\n", XU_TINY, s->max_tiny,
                s->sum_tiny / (2.0 * (double)s->axes_tiny), s->axes_tiny);
    fprintf(f, "  (the proven bound 12 u S + 2^-%d is checked exactly as "
               "proven-tight; 2^-%d = 512 eta, so where u*S is tiny an "
               "excess above 12 is allowed)\n", xu_fmt->tight_e, xu_fmt->tight_e);
    fprintf(f, "  histogram (both sides):");
    for (k = 0; k < XU_NBINS; k++) {
        if (k == 0) fprintf(f, " <0:%ld", s->hist[k]);
        else if (k == XU_NBINS - 1) fprintf(f, " >=12:%ld", s->hist[k]);
        else fprintf(f, " [%g,%g):%ld", xu_bin_top[k - 1], xu_bin_top[k],
                     s->hist[k]);
    }
    fprintf(f, "\n");
}

/* ---------------------------------------------------------------------- */
/* Printing                                                               */
/* ---------------------------------------------------------------------- */

int xu_status_index(cbx_status s)
{
    switch (s) {
    case CBX_OK: return 0;
    case CBX_EMPTY: return 1;
    case CBX_EINVAL: return 2;
    case CBX_ERANGE: return 3;
    case CBX_EBEHIND: return -1; /* cbx_project_box only: not a status of the affine forms */
    }
    return -1;
}

void xu_print_box(FILE *f, const char *label, const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        fprintf(f, "  %s[%d] = [%.17g, %.17g]  (%a, %a)\n", label, j,
                b->lo[j], b->hi[j], b->lo[j], b->hi[j]);
}

void xu_print_case(FILE *f, const cbx_affine *a, const cbx_box *in)
{
    int i;
    for (i = 0; i < 3; i++)
        fprintf(f, "  m[%d] = {%a, %a, %a | %a}\n", i, a->m[i][0],
                a->m[i][1], a->m[i][2], a->m[i][3]);
    xu_print_box(f, "in", in);
}

/* ---------------------------------------------------------------------- */
/* Helpers for test_cbox, test_sphere and the demo                        */
/* ---------------------------------------------------------------------- */

long xu_split_d(mpz_t z, double v) { return xu_split(z, v); }

void xu_scaled_mul(xu_exact *x, mpz_t z, double m, double c)
{
    xu_scaled_prod(x, z, m, c);
}

double xu_units(xu_exact *x, const mpz_t gap, const mpz_t S)
{
    /* x->e = (u S + eta) 2^(XU_SHIFT + p) = S + 2^(XU_SHIFT - emin + p),
     * as in xu_unit_den but without touching x->S */
    mpz_set_ui(x->e, 1);
    mpz_mul_2exp(x->e, x->e, XU_SHIFT - xu_fmt->emin + xu_fmt->p);
    mpz_add(x->e, x->e, S);
    return xu_ratio53(gap, x->e);
}

/* u S < 2^-cap  <=>  S 2^XU_SHIFT < 2^(XU_SHIFT + p - cap)
 * (binary64: u S < 2^-1000, S 2^XU_SHIFT < 2^(XU_SHIFT - 947)) */
int xu_scale_tiny(const mpz_t S)
{
    return mpz_sgn(S) == 0
           || mpz_sizeinbase(S, 2) <= (size_t)(XU_SHIFT + xu_fmt->p - xu_fmt->tiny_cap);
}

/* gap 2^XU_SHIFT > 2^(XU_SHIFT - cap) */
int xu_gap_above_tiny_cap(const mpz_t gap)
{
    size_t c = (size_t)(XU_SHIFT - xu_fmt->tiny_cap);
    return mpz_sgn(gap) > 0
           && (mpz_sizeinbase(gap, 2) > c + 1
               || (mpz_sizeinbase(gap, 2) == c + 1 && mpz_scan1(gap, 0) < c));
}

int xu_cbox_has_nan(const cbx_affine *a, const cbx_cbox *in)
{
    int i, j;
    if (a)
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++)
                if (xu_is_nan(a->m[i][j])) return 1;
    for (j = 0; j < 3; j++)
        if (xu_is_nan(in->c[j]) || xu_is_nan(in->h[j])) return 1;
    return 0;
}

int xu_cbox_is_empty(const cbx_cbox *in)
{
    return in->h[0] < 0.0 || in->h[1] < 0.0 || in->h[2] < 0.0;
}

int xu_cbox_row_in_domain(const cbx_affine *a, const cbx_cbox *in, int i)
{
    int j;
    for (j = 0; j < 3; j++) {
        if (!xu_pair_in_domain(a->m[i][j], in->c[j])) return 0;
        if (!xu_pair_in_domain(a->m[i][j], in->h[j])) return 0;
    }
    return fabs(a->m[i][3]) <= ldexp(1.0, xu_fmt->rt);
}

const char xu_cax_char[XU_NCAX + 1] = "ADW";

void xu_cbox_dropped(const cbx_affine *a, const cbx_cbox *in, int i, cbx_cbox *d)
{
    int j;
    for (j = 0; j < 3; j++) {
        int z = a->m[i][j] == 0; /* exact; true for -0.0, false for NaN */
        d->c[j] = z ? 0.0 : in->c[j];
        d->h[j] = z ? 0.0 : in->h[j];
    }
}

int xu_cbox_axis_kind(const cbx_affine *a, const cbx_cbox *in, int i)
{
    cbx_cbox d;
    if (xu_cbox_row_in_domain(a, in, i)) return XU_CAX_FULL;
    /* xu_pair_in_domain is false for an infinite m or coordinate, and the
     * bound on t is false for an infinite t: no separate finiteness test */
    xu_cbox_dropped(a, in, i, &d);
    if (xu_cbox_row_in_domain(a, &d, i)) return XU_CAX_DROP;
    return XU_CAX_LOST;
}

int xu_cbox_loss_mask(const cbx_affine *a, const cbx_cbox *in)
{
    int i, mask = 0;
    for (i = 0; i < 3; i++)
        if (xu_cbox_axis_kind(a, in, i) == XU_CAX_LOST) mask |= 1 << i;
    return mask;
}

void xu_cbox_kinds_str(const cbx_affine *a, const cbx_cbox *in, char s[4])
{
    int i;
    for (i = 0; i < 3; i++) s[i] = xu_cax_char[xu_cbox_axis_kind(a, in, i)];
    s[3] = '\0';
}

cbx_status xu_cbox_expected_status(const cbx_affine *a, const cbx_cbox *in)
{
    if (xu_cbox_has_nan(a, in)) return CBX_EINVAL;
    if (xu_cbox_is_empty(in)) return CBX_EMPTY;
    return xu_cbox_loss_mask(a, in) ? CBX_ERANGE : CBX_OK;
}

void xu_scaled_sh(mpz_t z, double v, unsigned long sh)
{
    long e = xu_split(z, v);
    mpz_mul_2exp(z, z, (mp_bitcnt_t)((long)sh + e));
}

/* d = (p - q) 2^sh; d >= 0 and d^2 >= s */
static int xu_sqrt_side_ok(xu_exact *x, const mpz_t s, unsigned long sh,
                           double p, double q)
{
    xu_scaled_sh(x->d, p, sh);
    xu_scaled_sh(x->t, q, sh);
    mpz_sub(x->d, x->d, x->t);
    if (mpz_sgn(x->d) < 0) return 0;
    mpz_mul(x->d, x->d, x->d);
    return mpz_cmp(x->d, s) >= 0;
}

int xu_sqrt_lo_ok(xu_exact *x, const mpz_t s, unsigned long sh, double t,
                  double lo)
{
    return xu_sqrt_side_ok(x, s, sh, t, lo);
}

int xu_sqrt_hi_ok(xu_exact *x, const mpz_t s, unsigned long sh, double t,
                  double hi)
{
    return xu_sqrt_side_ok(x, s, sh, hi, t);
}

/* X = |end - t| - K u |t| - E (times 2^sh); X <= (1 + K u) sqrt(s') iff
 * X <= 0 or X^2 2^(2 uexp) <= (2^uexp + K)^2 s (s' = s 2^-2sh). */
int xu_sqrt_gap_ok(xu_exact *x, const mpz_t s, unsigned long sh, double t, double end,
                   unsigned long k, unsigned long uexp, unsigned long eexp)
{
    xu_scaled_sh(x->d, end, sh);
    xu_scaled_sh(x->t, t, sh);
    mpz_sub(x->d, x->d, x->t);
    mpz_abs(x->d, x->d);                       /* |end - t| 2^sh        */
    mpz_abs(x->t, x->t);
    mpz_mul_ui(x->t, x->t, k);
    mpz_fdiv_q_2exp(x->e, x->t, uexp);         /* exact: sh >= uexp + 1074 */
    mpz_sub(x->d, x->d, x->e);                 /* - K u |t| 2^sh        */
    mpz_set_ui(x->e, 1);
    mpz_mul_2exp(x->e, x->e, sh - eexp);
    mpz_sub(x->d, x->d, x->e);                 /* - 2^-eexp 2^sh        */
    if (mpz_sgn(x->d) <= 0) return 1;
    mpz_mul(x->d, x->d, x->d);
    mpz_mul_2exp(x->d, x->d, 2 * uexp);        /* X^2 2^(2 uexp)        */
    mpz_set_ui(x->e, 1);
    mpz_mul_2exp(x->e, x->e, uexp);
    mpz_add_ui(x->e, x->e, k);
    mpz_mul(x->e, x->e, x->e);
    mpz_mul(x->e, x->e, s);                    /* (2^uexp + K)^2 s      */
    return mpz_cmp(x->d, x->e) <= 0;
}

uint64_t xu_rng_next(xu_rng *r)
{
    uint64_t z = (r->s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* 64-bit arithmetic throughout: long is 32 bits on 32-bit targets, where
 * hi - lo + 1 overflows for spans above 2^31 (found by make check-cross) */
int xu_rng_int(xu_rng *r, int lo, int hi)
{
    uint64_t span = (uint64_t)((int64_t)hi - (int64_t)lo + 1);
    return (int)((int64_t)lo + (int64_t)(xu_rng_next(r) % span));
}

double xu_rng_sign(xu_rng *r) { return (xu_rng_next(r) >> 63) ? -1.0 : 1.0; }

double xu_rng_unit(xu_rng *r)
{
    return ldexp((double)(xu_rng_next(r) >> 11), -53);
}

double xu_gen_mag(xu_rng *r, int emin, int emax)
{
    int p = xu_rng_int(r, 0, 99), e;
    int mb = xu_fmt->p - 1; /* mantissa bits after the leading one */
    double frac;
    if (emin < -xu_fmt->emin) emin = -xu_fmt->emin;
    if (emax > xu_fmt->emax) emax = xu_fmt->emax;
    if (emax < emin) emax = emin;
    if (p < 4) return 0.0;
    if (p < 8) return ldexp(1.0, emax);
    if (p < 12 && emin <= xu_fmt->norm_min && emax >= xu_fmt->norm_min)
        return ldexp((double)((xu_rng_next(r) >> (64 - mb)) | 1u), -xu_fmt->emin);
    e = xu_rng_int(r, emin - 1, emax - 1);
    frac = 1.0 + ldexp((double)(xu_rng_next(r) >> (64 - mb)), -mb);
    /* < 2^emax; a subnormal result rounds in double, so round it to the
     * format (a no-op in binary64) */
    frac = ldexp(frac, e);
    return xu_round_fmt(frac);
}

/* Every draw of the generators below is its own statement: C leaves the
 * order of the operands of * and of function arguments unspecified, and
 * gcc orders them differently on x86-64 and ARM (found by check-cross). */
double xu_gen_signed(xu_rng *r, int emin, int emax)
{
    double s = xu_rng_sign(r);
    return s * xu_gen_mag(r, emin, emax);
}

const int xu_cls_values[XU_NCLS_VALUES] = {
    CBX_CLASS_GENERAL, CBX_CLASS_PERMUTE, CBX_CLASS_SCALE, CBX_CLASS_TRANSLATE,
    CBX_CLASS_IDENTITY, 5, 7, -1, -3, INT_MAX, INT_MIN
};

const char *xu_cls_str(int cls, char buf[16])
{
    static const char *const names[5] = { "GENERAL", "PERMUTE", "SCALE", "TRANSLATE",
                                          "IDENTITY" };
    if (cls >= 0 && cls < 5) return names[cls];
    if (cls == INT_MAX) return "INT_MAX";
    if (cls == INT_MIN) return "INT_MIN";
    snprintf(buf, 16, "%d", cls);
    return buf;
}

unsigned long long xu_arg_num(int argc, char **argv, int n, unsigned long long dflt,
                              const char *usage)
{
    char *end;
    unsigned long long v;
    if (argc <= n) return dflt;
    v = strtoull(argv[n], &end, 0);
    if (*argv[n] == '\0' || *argv[n] == '-' || *end != '\0') {
        fprintf(stderr, "usage: %s %s\n", argv[0], usage);
        exit(2);
    }
    return v;
}

void xu_rand_rotation(xu_rng *r, double R[3][3])
{
    double w, x, y, z, n;
    do {
        w = 2 * xu_rng_unit(r) - 1;
        x = 2 * xu_rng_unit(r) - 1;
        y = 2 * xu_rng_unit(r) - 1;
        z = 2 * xu_rng_unit(r) - 1;
        n = w * w + x * x + y * y + z * z;
    } while (n > 1 || n < 1e-6);
    n = sqrt(n);
    w /= n; x /= n; y /= n; z /= n;
    R[0][0] = 1 - 2 * (y * y + z * z);
    R[0][1] = 2 * (x * y - w * z);
    R[0][2] = 2 * (x * z + w * y);
    R[1][0] = 2 * (x * y + w * z);
    R[1][1] = 1 - 2 * (x * x + z * z);
    R[1][2] = 2 * (y * z - w * x);
    R[2][0] = 2 * (x * z - w * y);
    R[2][1] = 2 * (y * z + w * x);
    R[2][2] = 1 - 2 * (x * x + y * y);
}

/* ---------------------------------------------------------------------- */
/* Random cases of cbx_transform_box (test_exact) and of the float family  */
/* (test_float): the format's values, drawn the same way                   */
/* ---------------------------------------------------------------------- */

/* Interval on axis j with |lo|, |hi| <= 2^chi. */
static void xu_gen_interval(xu_rng *r, cbx_box *b, int j, int clo, int chi)
{
    int p = xu_rng_int(r, 0, 99);
    double u, v;
    if (p < 10) { /* point box */
        b->lo[j] = b->hi[j] = xu_gen_signed(r, clo, chi);
    } else if (p < 15) { /* signed zeros, any order: never empty */
        b->lo[j] = xu_rng_sign(r) * 0.0;
        b->hi[j] = xu_rng_sign(r) * 0.0;
    } else if (p < 25) { /* symmetric */
        u = xu_gen_mag(r, clo, chi);
        b->lo[j] = -u;
        b->hi[j] = u;
    } else if (p < 32) { /* one ulp wide */
        u = xu_gen_signed(r, clo, chi);
        v = xu_next_up(u);
        if (fabs(v) > ldexp(1.0, chi)) v = u;
        b->lo[j] = u;
        b->hi[j] = v;
    } else {
        u = xu_gen_signed(r, clo, chi);
        v = xu_gen_signed(r, clo, chi);
        b->lo[j] = u < v ? u : v;
        b->hi[j] = u < v ? v : u;
    }
}

/* t = -fl(sum_j m_j c_j) at a random corner: the image nearly cancels. */
static double xu_cancelling_t(xu_rng *r, const cbx_affine *a, const cbx_box *b, int i)
{
    double s = 0.0;
    int j;
    for (j = 0; j < 3; j++)
        s += a->m[i][j] * ((xu_rng_next(r) >> 63) ? b->hi[j] : b->lo[j]);
    return -xu_round_fmt(s); /* a value of the format */
}

/* A case inside the domain by construction: per column a magnitude class
 * k, entries within 2^k and coordinates within 2^(rt-k) (binary64:
 * 2^(1018-k)).  In "narrow"
 * mode all products share an exponent P (so terms are comparable and
 * cancellation happens); otherwise exponents are spread over the class. */
static void xu_gen_in_domain(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int narrow = xu_rng_int(r, 0, 1);
    int E = xu_fmt->emin, RT = xu_fmt->rt;
    int P = xu_rng_int(r, -E + 4, RT - 2);
    int i, j;
    for (j = 0; j < 3; j++) {
        int k = xu_fmt->class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        int mlo = -E, mhi = k, clo = -E, chi = RT - k;
        if (narrow) {
            int lo = P - RT + k > -E ? P - RT + k : -E;
            int hi = k < P + E ? k : P + E;
            int am = xu_rng_int(r, lo, hi);
            mhi = am;
            mlo = am - 4;
            chi = P - am;
            clo = chi - 4;
        }
        for (i = 0; i < 3; i++) a->m[i][j] = xu_gen_signed(r, mlo, mhi);
        xu_gen_interval(r, b, j, clo, chi);
    }
    for (i = 0; i < 3; i++) {
        int p = xu_rng_int(r, 0, 9);
        if (p < 2) a->m[i][3] = xu_cancelling_t(r, a, b, i);
        else if (p < 3) a->m[i][3] = xu_rng_sign(r) * 0.0;
        else if (narrow) a->m[i][3] = xu_gen_signed(r, P - 4, P);
        else a->m[i][3] = xu_gen_signed(r, -E, RT);
    }
}

/* Push one input out of (or to the edge of) the domain. */
static void xu_perturb_out(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 2), k;
    double big;
    int RT = xu_fmt->rt, EX = xu_fmt->emax;
    switch (xu_rng_int(r, 0, 6)) {
    case 0: /* large entry: may or may not still fit a class */
        a->m[i][j] = xu_gen_signed(r, xu_fmt->big_entry, EX);
        break;
    case 1: /* large coordinate */
        big = xu_gen_mag(r, xu_fmt->big_coord, EX);
        if (xu_rng_int(r, 0, 1)) { if (big > b->lo[j]) b->hi[j] = big; }
        else if (-big < b->hi[j]) b->lo[j] = -big;
        break;
    case 2: /* infinite coordinate(s) */
        switch (xu_rng_int(r, 0, 3)) {
        case 0: b->lo[j] = -HUGE_VAL; break;
        case 1: b->hi[j] = HUGE_VAL; break;
        case 2: b->lo[j] = b->hi[j] = HUGE_VAL; break;
        default: b->lo[j] = -HUGE_VAL; b->hi[j] = HUGE_VAL; break;
        }
        break;
    case 3: /* infinite entry or translation */
        big = xu_rng_sign(r) * HUGE_VAL;
        k = xu_rng_int(r, 0, 3);
        a->m[i][k] = big;
        break;
    case 4: /* translation beyond 2^rt (binary64: 2^1018) */
        k = xu_rng_int(r, 0, 2);
        big = k == 0 ? xu_next_up(ldexp(1.0, RT))
            : k == 1 ? xu_fmt_max() : xu_gen_mag(r, RT + 1, EX);
        a->m[i][3] = xu_rng_sign(r) * big;
        break;
    case 5: /* one ulp outward on an entry: crosses a class boundary when
               the entry sat on it */
        a->m[i][j] = a->m[i][j] < 0 ? -xu_next_up(-a->m[i][j]) : xu_next_up(a->m[i][j]);
        break;
    default: /* exact class corner, then one coordinate one ulp beyond */
        k = xu_fmt->class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        a->m[i][j] = xu_rng_sign(r) * ldexp(1.0, k);
        b->lo[j] = -ldexp(1.0, RT - k);
        b->hi[j] = ldexp(1.0, RT - k);
        if (xu_rng_int(r, 0, 1)) b->hi[j] = xu_next_up(b->hi[j]);
        break;
    }
}

/* Half-spaces (rule B): 1 to 4 box ends made infinite on their own side
 * (lo = -inf, hi = +inf), some map entries set to +-0 (a zero column
 * against an infinite end counts as 0) and, sometimes, one end of a
 * finite axis made huge (beyond every class: lost only where needed). */
static void xu_perturb_half(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int n = xu_rng_int(r, 1, 4), k;
    for (k = 0; k < n; k++) {
        int j = xu_rng_int(r, 0, 2);
        if (xu_rng_int(r, 0, 1)) b->lo[j] = -HUGE_VAL;
        else b->hi[j] = HUGE_VAL;
    }
    n = xu_rng_int(r, 0, 4);
    for (k = 0; k < n; k++)
    {
        double z = xu_rng_sign(r) * 0.0;
        int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 2);
        a->m[i][j] = z;
    }
    if (xu_rng_int(r, 0, 3) == 0) {
        int j = xu_rng_int(r, 0, 2);
        double big = xu_rng_int(r, 0, 1) ? xu_fmt_max() : xu_gen_mag(r, xu_fmt->rt + 1, xu_fmt->emax);
        if (xu_rng_int(r, 0, 1)) { if (isfinite(b->lo[j])) b->hi[j] = big; }
        else if (isfinite(b->hi[j])) b->lo[j] = -big;
    }
}

void xu_inject_nan(xu_rng *r, cbx_affine *a, double v0[3], double v1[3])
{
    int p = xu_rng_int(r, 0, 17);
    double nan = xu_rng_sign(r) * NAN;
    if (p < 12) a->m[p / 4][p % 4] = nan;
    else if (p < 15) v0[p - 12] = nan;
    else v1[p - 15] = nan;
}

static void xu_inject_empty(xu_rng *r, cbx_box *b)
{
    int j = xu_rng_int(r, 0, 2);
    switch (xu_rng_int(r, 0, 4)) {
    case 0: /* one ulp inverted */
        b->lo[j] = xu_next_up(b->hi[j]);
        break;
    case 1: /* inverted infinities */
        b->lo[j] = HUGE_VAL;
        b->hi[j] = -HUGE_VAL;
        break;
    case 2: /* lo = +inf: no real point, even with hi = +inf */
        b->lo[j] = HUGE_VAL;
        if (xu_rng_int(r, 0, 1)) b->hi[j] = HUGE_VAL;
        break;
    case 3: /* hi = -inf: no real point, even with lo = -inf */
        b->hi[j] = -HUGE_VAL;
        if (xu_rng_int(r, 0, 1)) b->lo[j] = -HUGE_VAL;
        break;
    default: /* swapped ends, made distinct */
        b->lo[j] = 1.0;
        b->hi[j] = -1.0;
        break;
    }
}

/* ~82% in domain by construction, ~10% pushed out, ~5% half-spaces,
 * ~1.5% NaN, ~1.5% empty (some of those also NaN: EINVAL must win). */
void xu_gen_case(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int p = xu_rng_int(r, 0, 999);
    xu_gen_in_domain(r, a, b);
    if (p < 100) xu_perturb_out(r, a, b);
    else if (p < 115) xu_inject_nan(r, a, b->lo, b->hi);
    else if (p < 130) {
        xu_inject_empty(r, b);
        if (p < 118) xu_inject_nan(r, a, b->lo, b->hi);
    } else if (p < 180) {
        xu_perturb_half(r, a, b);
        if (p < 140) xu_perturb_out(r, a, b);
    }
}

/* ---- the slerp oracle --------------------------------------------------- */
void xu_slerp_init(xu_slerp *e, mpfr_prec_t prec)
{
    for (int i = 0; i < 4; i++) mpfr_inits2(prec, e->q0[i], e->q1[i], (mpfr_ptr)0);
    mpfr_inits2(prec, e->th, e->sth, e->w0, e->w1, e->n, (mpfr_ptr)0);
    e->nlerp = e->small = e->dot_neg = 0;
}

void xu_slerp_clear(xu_slerp *e)
{
    for (int i = 0; i < 4; i++) mpfr_clears(e->q0[i], e->q1[i], (mpfr_ptr)0);
    mpfr_clears(e->th, e->sth, e->w0, e->w1, e->n, (mpfr_ptr)0);
}

void xu_slerp_keys(xu_slerp *e, const double q0[4], const double q1[4], int nlerp, int arc)
{
    mpfr_t *q[2] = { e->q0, e->q1 };
    const double *k[2] = { q0, q1 };
    for (int j = 0; j < 2; j++) {
        mpfr_set_ui(e->n, 0, MPFR_RNDN);
        for (int i = 0; i < 4; i++) {
            mpfr_set_d(q[j][i], k[j][i], MPFR_RNDN);
            mpfr_fma(e->n, q[j][i], q[j][i], e->n, MPFR_RNDN);
        }
        mpfr_sqrt(e->n, e->n, MPFR_RNDN);
        for (int i = 0; i < 4; i++) mpfr_div(q[j][i], q[j][i], e->n, MPFR_RNDN);
    }
    /* the exact sign of q0.q1: every product of two doubles and their sum
     * are exact at 2400 bits */
    mpfr_t d, t;
    mpfr_inits2(2400, d, t, (mpfr_ptr)0);
    mpfr_set_ui(d, 0, MPFR_RNDN);
    for (int i = 0; i < 4; i++) {
        mpfr_set_d(t, q0[i], MPFR_RNDN);
        mpfr_mul_d(t, t, q1[i], MPFR_RNDN);
        mpfr_add(d, d, t, MPFR_RNDN);
    }
    e->dot_neg = mpfr_sgn(d) < 0;
    mpfr_clears(d, t, (mpfr_ptr)0);
    if ((arc == 0 && e->dot_neg) || arc < 0)
        for (int i = 0; i < 4; i++) mpfr_neg(e->q1[i], e->q1[i], MPFR_RNDN);
    mpfr_set_ui(e->n, 0, MPFR_RNDN);
    for (int i = 0; i < 4; i++) mpfr_fma(e->n, e->q0[i], e->q1[i], e->n, MPFR_RNDN);
    if (mpfr_cmp_ui(e->n, 1) > 0) mpfr_set_ui(e->n, 1, MPFR_RNDN);
    mpfr_acos(e->th, e->n, MPFR_RNDN);
    mpfr_sin(e->sth, e->th, MPFR_RNDN);
    e->small = mpfr_cmp_d(e->th, 0x1p-200) < 0;
    e->nlerp = nlerp;
}

void xu_slerp_at(xu_slerp *e, mpfr_srcptr s, mpfr_t q[4])
{
    mpfr_ui_sub(e->w0, 1, s, MPFR_RNDN);
    mpfr_set(e->w1, s, MPFR_RNDN);
    if (!e->nlerp && !e->small) {
        mpfr_mul(e->w0, e->w0, e->th, MPFR_RNDN);
        mpfr_sin(e->w0, e->w0, MPFR_RNDN);
        mpfr_div(e->w0, e->w0, e->sth, MPFR_RNDN);
        mpfr_mul(e->w1, s, e->th, MPFR_RNDN);
        mpfr_sin(e->w1, e->w1, MPFR_RNDN);
        mpfr_div(e->w1, e->w1, e->sth, MPFR_RNDN);
    }
    mpfr_set_ui(e->n, 0, MPFR_RNDN);
    for (int i = 0; i < 4; i++) {
        mpfr_mul(q[i], e->q0[i], e->w0, MPFR_RNDN);
        mpfr_fma(q[i], e->q1[i], e->w1, q[i], MPFR_RNDN);
        mpfr_fma(e->n, q[i], q[i], e->n, MPFR_RNDN);
    }
    mpfr_sqrt(e->n, e->n, MPFR_RNDN);
    for (int i = 0; i < 4; i++) mpfr_div(q[i], q[i], e->n, MPFR_RNDN);
}

/* ---- shared by the projective oracles -------------------------------------- */
int xu_whole_box(const cbx_box *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(o->lo[i]) && o->lo[i] < 0 && isinf(o->hi[i]) && o->hi[i] > 0))
            return 0;
    return 1;
}

int xu_empty_box(const cbx_box *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(o->lo[i]) && o->lo[i] > 0 && isinf(o->hi[i]) && o->hi[i] < 0))
            return 0;
    return 1;
}

void xu_aff_q(mpq_t q, const double m[4], mpq_t const x[3])
{
    mpq_t t;
    int j;
    mpq_init(t);
    mpq_set_d(q, m[3]);
    for (j = 0; j < 3; j++) {
        mpq_set_d(t, m[j]);
        mpq_mul(t, t, x[j]);
        mpq_add(q, q, t);
    }
    mpq_clear(t);
}

void xu_dot3_q(mpq_t q, const double u[4], const double v[4])
{
    mpq_t t, w;
    int j;
    mpq_inits(t, w, NULL);
    mpq_set_ui(q, 0, 1);
    for (j = 0; j < 3; j++) {
        mpq_set_d(t, u[j]);
        mpq_set_d(w, v[j]);
        mpq_mul(t, t, w);
        mpq_add(q, q, t);
    }
    mpq_clears(t, w, NULL);
}

void xu_ball_point(mpq_t x[3], const double c[3], double r, double u, double v, double s)
{
    mpq_t q, uq, vq, den, t;
    int j;
    mpq_inits(q, uq, vq, den, t, NULL);
    mpq_set_d(uq, u);
    mpq_set_d(vq, v);
    mpq_mul(den, uq, uq);
    mpq_mul(t, vq, vq);
    mpq_add(den, den, t);
    mpq_set_ui(t, 1, 1);
    mpq_add(den, den, t);                    /* 1 + u^2 + v^2 */
    for (j = 0; j < 3; j++) {
        if (j == 0) {
            mpq_add(q, uq, uq);
        } else if (j == 1) {
            mpq_add(q, vq, vq);
        } else {
            mpq_set_ui(t, 2, 1);
            mpq_sub(q, den, t);              /* u^2 + v^2 - 1 */
        }
        mpq_div(q, q, den);
        mpq_set_d(t, r);
        mpq_mul(q, q, t);
        mpq_set_d(t, s);
        mpq_mul(q, q, t);
        mpq_set_d(t, c[j]);
        mpq_add(x[j], t, q);
    }
    mpq_clears(q, uq, vq, den, t, NULL);
}

void xu_dists_add(xu_dists *d, double u)
{
    if (d->n == d->cap) {
        d->cap = d->cap ? 2 * d->cap : 1024;
        d->v = realloc(d->v, (size_t)d->cap * sizeof *d->v);
        if (!d->v)
            abort();
    }
    d->v[d->n++] = u;
    if (u > d->worst)
        d->worst = u;
}

void xu_dists_print(FILE *f, xu_dists *d)
{
    if (d->n > 0) {
        qsort(d->v, (size_t)d->n, sizeof *d->v, xu_cmp_double);
        fprintf(f, "  distance of an end to the exact end, in units of 2^-52 (1 + |end|) (proven: at most 2^32):\n"
                   "    median %.1f, 99th percentile %.1f, 99.9th %.1f, largest %.3g (%ld ends)\n",
                d->v[d->n / 2], d->v[d->n * 99 / 100], d->v[d->n * 999 / 1000], d->worst, d->n);
    }
}

void xu_dists_free(xu_dists *d)
{
    free(d->v);
    d->v = NULL;
    d->n = d->cap = 0;
}

int xu_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}
