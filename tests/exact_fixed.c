/* exact_fixed: the exact arithmetic of the oracle: the fixed-point path
 * (mpz_t, every value times 2^XU_SHIFT: a row's exact bounds L, H, S, rule
 * B's vertex value, excess in units of u S + eta, the proven tightness),
 * the independent mpq path over the 8 corners, and the GMP helpers of
 * test_cbox, test_sphere and the demo (products, units, tiny scales, the
 * exact square-root side tests of the balls).
 * Part of the oracle declared in exact_util.h (see there for the map). */
#include "exact_util.h"
#include "exact_internal.h"

#include <math.h>

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
double xu_ratio53(const mpz_t n, const mpz_t den)
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
void xu_unit_den(xu_exact *x)
{
    mpz_set_ui(x->e, 1);
    mpz_mul_2exp(x->e, x->e, XU_SHIFT - xu_fmt->emin + xu_fmt->p);
    mpz_add(x->e, x->e, x->S);
}

/* gap = exact distance by which the bound is outside the exact bound,
 * scaled (negative = not contained).  Leaves it in x->d. */
void xu_gap_lo(xu_exact *x, double lo)
{
    xu_scaled_d(x, x->d, lo);
    mpz_sub(x->d, x->L, x->d);
}

void xu_gap_hi(xu_exact *x, double hi)
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
int xu_gap_within_proven(xu_exact *x)
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
