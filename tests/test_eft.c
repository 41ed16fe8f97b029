/*
 * test_eft [N_THOUSANDS] [seed]: the tight mode's error-free products
 * (src/core/cbx_eft.h) against each other and against GMP.
 *
 * For every pair (a, b) in two_prod's contract (finite, |a*b| <= 2^1018,
 * a*b == 0 or |a*b| >= 2^-969, decided exactly with mpq_t):
 *   same    the Dekker/Veltkamp form and the fma form return the same
 *           pair, bit for bit (signed zeros included);
 *   exact   hi + lo == a*b exactly (mpq_t), for each form;
 *   hi      hi == RN(a*b) (MPFR, binary64 with subnormals).
 * Cases (N thousand random, default 1000, plus the fixed ones):
 *   0  hard: powers of two, 1 +- ulp, all-ones mantissas, zeros, the
 *      contract's limits 2^-969 and 2^1018 from both sides, factors near
 *      2^995 / 2^996 (the Dekker form's scaling threshold), subnormal
 *      factors;
 *   1  random mantissas, exponents uniform over the contract's range;
 *   2  products within a factor 2^8 of 2^1018, one factor above 2^995
 *      (the scaled path) on half of them;
 *   3  products within a factor 2^8 of 2^-969, a subnormal factor on a
 *      quarter of them;
 *   4  short mantissas (exact products, lo == 0) and ties.
 * Then the hard-case tables of cbx_ieee_check() (src/core/cbx_ieee_cases.h)
 * are recomputed: fma and sqrt with MPFR (binary64 / binary32 exponent
 * range, subnormalized), the two_prod / two_sum rows with mpq_t.
 * Prints the counts; the last line is "N passed, M failed".
 */
#define CBX_EFT_BOTH 1
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include <gmp.h>
#include <mpfr.h>

#include "exact_util.h"
#include "cbx_eft.h"
#define CBX_IEEE_CASES_ALL 1
#include "cbx_ieee_cases.h"

typedef struct ctx {
    mpq_t qa, qb, qp, qs, lim_lo, lim_hi;
    mpfr_t r;
    long cases[5], skipped, same, exact, hi_ok, scaled, subn, zero_lo, failed;
} ctx;

static int bits_eq(double x, double y)
{
    return memcmp(&x, &y, sizeof x) == 0;
}

/* in two_prod's contract, exactly */
static int in_contract(ctx *k, double a, double b)
{
    int c;
    if (!isfinite(a) || !isfinite(b))
        return 0;
    mpq_set_d(k->qa, a);
    mpq_set_d(k->qb, b);
    mpq_mul(k->qp, k->qa, k->qb);
    if (mpq_sgn(k->qp) == 0)
        return 1;
    mpq_abs(k->qs, k->qp);
    c = mpq_cmp(k->qs, k->lim_hi) <= 0 && mpq_cmp(k->qs, k->lim_lo) >= 0;
    return c;
}

/* hi + lo == k->qp exactly */
static int exact_pair(ctx *k, cbx_dd d)
{
    mpq_t h, l;
    int ok;
    if (!isfinite(d.hi) || !isfinite(d.lo))
        return 0;
    mpq_inits(h, l, (mpq_ptr)0);
    mpq_set_d(h, d.hi);
    mpq_set_d(l, d.lo);
    mpq_add(h, h, l);
    ok = mpq_equal(h, k->qp);
    mpq_clears(h, l, (mpq_ptr)0);
    return ok;
}

static void one(ctx *k, int sec, double a, double b)
{
    cbx_dd d, f;
    int bad = 0;
    if (!in_contract(k, a, b)) {
        k->skipped++;
        return;
    }
    k->cases[sec]++;
    if (fabs(a) > 0x1p995 || fabs(b) > 0x1p995) k->scaled++;
    if ((a != 0.0 && fabs(a) < 0x1p-1022) || (b != 0.0 && fabs(b) < 0x1p-1022)) k->subn++;
    d = cbx_two_prod_dekker(a, b);
    f = cbx_two_prod_fma(a, b);
    if (bits_eq(d.hi, f.hi) && bits_eq(d.lo, f.lo)) k->same++; else bad = 1;
    if (exact_pair(k, d) && exact_pair(k, f)) k->exact++; else bad = 1;
    /* hi == RN(a*b): a*b rounded by MPFR in binary64's range */
    mpfr_set_q(k->r, k->qp, MPFR_RNDN);
    if (mpfr_get_d(k->r, MPFR_RNDN) == d.hi) k->hi_ok++; else bad = 1;
    if (d.lo == 0.0) k->zero_lo++;
    if (bad) {
        if (k->failed < 10)
            printf("  FAIL a = %a, b = %a: Dekker (%a, %a), fma (%a, %a)\n", a, b, d.hi, d.lo, f.hi, f.lo);
        k->failed++;
    }
}

static double mant(xu_rng *r)
{
    return 1.0 + (double)(xu_rng_next(r) >> 12) * 0x1p-52; /* [1, 2), 53 bits */
}

static double scaled(xu_rng *r, int e)
{
    return xu_rng_sign(r) * ldexp(mant(r), e);
}

/* a subnormal of random width */
static double subnormal(xu_rng *r)
{
    int w = xu_rng_int(r, 1, 52);
    uint64_t m = (xu_rng_next(r) >> (64 - w)) | ((uint64_t)1 << (w - 1));
    return xu_rng_sign(r) * ldexp((double)m, -1074);
}

static void hard(ctx *k)
{
    static const double ms[] = { 1.0, 0x1.0000000000001p+0, 0x1.fffffffffffffp+0, 0x1.8p+0,
                                 0x1.0000000000003p+0, 0x1.ffffffep+0, 0x1.5555555555555p+0 };
    static const int es[] = { -1074, -1060, -1022, -1000, -969, -600, -485, -100, 0, 100,
                              485, 509, 900, 994, 995, 996, 1000, 1018, 1023 };
    unsigned i, j, p, q;
    int sa, sb;
    for (i = 0; i < sizeof ms / sizeof ms[0]; i++)
        for (j = 0; j < sizeof ms / sizeof ms[0]; j++)
            for (p = 0; p < sizeof es / sizeof es[0]; p++)
                for (q = 0; q < sizeof es / sizeof es[0]; q++)
                    for (sa = -1; sa <= 1; sa += 2)
                        for (sb = -1; sb <= 1; sb += 2) {
                            double a = sa * ldexp(ms[i], es[p]), b = sb * ldexp(ms[j], es[q]);
                            one(k, 0, a, b);
                            /* the other factor chosen so that the product
                             * sits at the contract's limits */
                            if (a != 0.0) {
                                one(k, 0, a, sb * ldexp(ms[j], -969 - ilogb(a)));
                                one(k, 0, a, sb * ldexp(ms[j], -970 - ilogb(a)));
                                one(k, 0, a, sb * ldexp(ms[j], 1017 - ilogb(a)));
                                one(k, 0, a, nextafter(ldexp(1.0, -969 - ilogb(a)), 0.0));
                            }
                        }
    one(k, 0, 0.0, 0x1p1000);
    one(k, 0, -0.0, 0x1p1000);
    one(k, 0, 0x1p-1074, -0.0);
    one(k, 0, 0.0, 0.0);
    one(k, 0, 0x1.fffffffffffffp+1023, 0x1p-6);   /* the largest finite factor */
    one(k, 0, 0x1p-6, -0x1.fffffffffffffp+1023);
    one(k, 0, 0x1p-1074, 0x1p+105);               /* the smallest factor */
    one(k, 0, 0x1p-1074, 0x1.fffffffffffffp+1023);
}

static void randoms(ctx *k, xu_rng *r, long n)
{
    long c;
    for (c = 0; c < n; c++) {
        int ea, eb;
        double a, b;
        switch (c % 4) {
        case 0: /* wide: the product's exponent uniform in the contract */
            ea = xu_rng_int(r, -1074, 1023);
            eb = xu_rng_int(r, -969, 1017) - ea;
            if (eb < -1074 || eb > 1023) eb = xu_rng_int(r, -500, 500);
            a = scaled(r, ea); b = scaled(r, eb);
            one(k, 1, a, b);
            break;
        case 1: /* near 2^1018, one factor above 2^995 on half of them */
            ea = (c & 4) ? xu_rng_int(r, 996, 1023) : xu_rng_int(r, -52, 995);
            eb = xu_rng_int(r, 1009, 1017) - ea;
            a = scaled(r, ea); b = scaled(r, eb);
            if (c & 8) one(k, 2, a, b); else one(k, 2, b, a);
            break;
        case 2: /* near 2^-969, a subnormal factor on a quarter of them */
            if ((c & 12) == 0) {
                a = subnormal(r);
                b = scaled(r, xu_rng_int(r, -969, -961) - ilogb(a));
            } else {
                ea = xu_rng_int(r, -1022, 53);
                a = scaled(r, ea);
                b = scaled(r, xu_rng_int(r, -969, -961) - ea);
            }
            if (c & 16) one(k, 3, a, b); else one(k, 3, b, a);
            break;
        default: { /* short mantissas: exact products, lo == 0, and ties */
            int w = xu_rng_int(r, 1, 30);
            uint64_t ma = (xu_rng_next(r) >> (64 - w)) | 1u, mb = (xu_rng_next(r) >> (64 - 54 + w)) | 1u;
            ea = xu_rng_int(r, -500, 500);
            a = xu_rng_sign(r) * ldexp((double)ma, ea);
            b = xu_rng_sign(r) * ldexp((double)mb, xu_rng_int(r, -500, 500));
            one(k, 4, a, b);
        }
        }
    }
}

/* the hard-case tables of cbx_ieee_check(), recomputed */
static long tables(ctx *k, long *checked)
{
    long bad = 0;
    unsigned i;
    mpfr_t x, y, z, w;
    mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
    mpfr_inits2(53, x, y, z, w, (mpfr_ptr)0);
    mpfr_set_emin(-1073);
    mpfr_set_emax(1024);
    for (i = 0; i < sizeof cbx_fma_cases / sizeof cbx_fma_cases[0]; i++) {
        const double *c = cbx_fma_cases[i];
        int t;
        mpfr_set_d(x, c[0], MPFR_RNDN); mpfr_set_d(y, c[1], MPFR_RNDN); mpfr_set_d(z, c[2], MPFR_RNDN);
        t = mpfr_fma(w, x, y, z, MPFR_RNDN);
        mpfr_subnormalize(w, t, MPFR_RNDN);
        if (!bits_eq(mpfr_get_d(w, MPFR_RNDN), c[3])) { bad++; printf("  FAIL fma row %u\n", i); }
        /* and x*y+z rounded twice differs (the point of the row), but for
         * the exact-zero row */
        if (c[3] != 0.0) {
            volatile double p = c[0] * c[1];
            if (p + c[2] == c[3]) { bad++; printf("  FAIL fma row %u: not a double-rounding case\n", i); }
        }
        (*checked)++;
    }
    for (i = 0; i < sizeof cbx_sqrt_cases / sizeof cbx_sqrt_cases[0]; i++) {
        int t;
        mpfr_set_d(x, cbx_sqrt_cases[i][0], MPFR_RNDN);
        t = mpfr_sqrt(w, x, MPFR_RNDN);
        mpfr_subnormalize(w, t, MPFR_RNDN);
        if (mpfr_get_d(w, MPFR_RNDN) != cbx_sqrt_cases[i][1]) { bad++; printf("  FAIL sqrt row %u\n", i); }
        (*checked)++;
    }
    for (i = 0; i < sizeof cbx_div_cases / sizeof cbx_div_cases[0]; i++) {
        int t;
        mpfr_set_d(x, cbx_div_cases[i][0], MPFR_RNDN);
        mpfr_set_d(y, cbx_div_cases[i][1], MPFR_RNDN);
        t = mpfr_div(w, x, y, MPFR_RNDN);
        mpfr_subnormalize(w, t, MPFR_RNDN);
        if (mpfr_get_d(w, MPFR_RNDN) != cbx_div_cases[i][2]) { bad++; printf("  FAIL div row %u\n", i); }
        (*checked)++;
    }
    mpfr_set_emin(-148);
    mpfr_set_emax(128);
    mpfr_set_prec(w, 24);
    for (i = 0; i < sizeof cbx_divf_cases / sizeof cbx_divf_cases[0]; i++) {
        int t;
        mpfr_set_d(x, cbx_divf_cases[i][0], MPFR_RNDN);
        mpfr_set_d(y, cbx_divf_cases[i][1], MPFR_RNDN);
        t = mpfr_div(w, x, y, MPFR_RNDN);
        mpfr_subnormalize(w, t, MPFR_RNDN);
        if (mpfr_get_flt(w, MPFR_RNDN) != cbx_divf_cases[i][2]) { bad++; printf("  FAIL divf row %u\n", i); }
        (*checked)++;
    }
    for (i = 0; i < sizeof cbx_sqrtf_cases / sizeof cbx_sqrtf_cases[0]; i++) {
        int t;
        mpfr_set_d(x, cbx_sqrtf_cases[i][0], MPFR_RNDN);
        t = mpfr_sqrt(w, x, MPFR_RNDN);
        mpfr_subnormalize(w, t, MPFR_RNDN);
        if (mpfr_get_flt(w, MPFR_RNDN) != cbx_sqrtf_cases[i][1]) { bad++; printf("  FAIL sqrtf row %u\n", i); }
        (*checked)++;
    }
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
    mpfr_clears(x, y, z, w, (mpfr_ptr)0);
    for (i = 0; i < sizeof cbx_prod_cases / sizeof cbx_prod_cases[0]; i++) {
        const double *c = cbx_prod_cases[i];
        cbx_dd d;
        d.hi = c[2]; d.lo = c[3];
        if (!in_contract(k, c[0], c[1]) || !exact_pair(k, d) || c[0] * c[1] != c[2]) {
            bad++; printf("  FAIL two_prod row %u\n", i);
        }
        (*checked)++;
    }
    for (i = 0; i < sizeof cbx_sum_cases / sizeof cbx_sum_cases[0]; i++) {
        const double *c = cbx_sum_cases[i];
        cbx_dd d;
        mpq_set_d(k->qa, c[0]); mpq_set_d(k->qb, c[1]); mpq_add(k->qp, k->qa, k->qb);
        d.hi = c[2]; d.lo = c[3];
        if (!exact_pair(k, d) || c[0] + c[1] != c[2]) { bad++; printf("  FAIL two_sum row %u\n", i); }
        (*checked)++;
    }
    return bad;
}

int main(int argc, char **argv)
{
    long nth = (long)xu_arg_num(argc, argv, 1, 1000, "[N_THOUSANDS] [seed]"), tot, tbad, tn = 0;
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N_THOUSANDS] [seed]");
    static ctx k;
    xu_rng r;
    clock_t t0 = clock();
    int s;
    mpq_inits(k.qa, k.qb, k.qp, k.qs, k.lim_lo, k.lim_hi, (mpq_ptr)0);
    mpq_set_d(k.lim_lo, 0x1p-969);
    mpq_set_d(k.lim_hi, 0x1p1018);
    mpfr_init2(k.r, 53);
    r.s = UINT64_C(0x13198a2e03707344) ^ seed;
    printf("test_eft: this build's two_prod: %s\n", CBX_TWO_PROD_NAME);
    hard(&k);
    randoms(&k, &r, nth * 1000);
    tot = 0;
    for (s = 0; s < 5; s++) tot += k.cases[s];
    printf("test_eft: %ld pairs in two_prod's contract (hard %ld, wide %ld, near 2^1018 %ld, "
           "near 2^-969 %ld, short mantissas %ld; %ld drawn outside the contract, skipped)\n",
           tot, k.cases[0], k.cases[1], k.cases[2], k.cases[3], k.cases[4], k.skipped);
    printf("test_eft: Dekker == fma bit for bit: %ld of %ld; hi + lo == a*b exactly (GMP), both forms: "
           "%ld; hi == RN(a*b) (MPFR): %ld\n", k.same, tot, k.exact, k.hi_ok);
    printf("test_eft: of them %ld through the Dekker form's scaled path (a factor above 2^995), "
           "%ld with a subnormal factor, %ld with lo == 0\n", k.scaled, k.subn, k.zero_lo);
    tbad = tables(&k, &tn);
    printf("test_eft: cbx_ieee_check's hard-case tables (src/core/cbx_ieee_cases.h): %ld rows recomputed "
           "with MPFR / GMP, %ld wrong\n", tn, tbad);
    printf("  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    mpfr_clear(k.r);
    mpq_clears(k.qa, k.qb, k.qp, k.qs, k.lim_lo, k.lim_hi, (mpq_ptr)0);
    mpfr_free_cache();
    printf("%ld passed, %ld failed\n", tot - k.failed + tn - tbad, k.failed + tbad);
    return k.failed || tbad ? 1 : 0;
}
