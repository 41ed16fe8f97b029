/*
 * The build check: does this build of the library compute the way its
 * proofs assume?  The proofs (Frama-C/WP's float model) take every C
 * operation as one IEEE-754 operation rounded to nearest in its own format,
 * with gradual underflow, infinities, NaN and signed zeros.  A compiler can
 * break that silently: fused multiply-add contraction (GCC's default outside
 * ISO modes, -ffp-contract=fast, on targets with FMA: aarch64, x86 with
 * -mfma), x87 excess precision, -ffast-math and its parts, flush-to-zero
 * modes set at start-up, or a rounding mode changed with fesetround().
 *
 * It also tests what the proofs trust (proofs/README.md): sqrt correctly
 * rounded, the tight mode's EFTs exact, the fma they call (if any)
 * correctly rounded, on hard cases kept as data (cbx_ieee_cases.h).
 *
 * Each check below runs a known case through the library's own rounding
 * primitives (cbx_round.h, inlined exactly as in the kernels, in this
 * translation unit's format) on values the compiler cannot see (volatile),
 * and compares with the IEEE answer.  Written once, instantiated for
 * binary64 (this file) and binary32 (cbx_ieee_f.c); cbx_ieee_check() runs
 * both.  Not part of the proven set: it tests the build, not the algorithm.
 */
#include "certbox.h"
#include "cbx_prec.h"
#include "cbx_round.h"
#include "cbx_quot.h"
#include "cbx_ieee_cases.h"
#if CBX_INST == 64
#include "cbx_eft.h"
#endif

#if CBX_INST == 32
#define cbx_ieee_fmt cbx_ieee_fmt_f
#endif
unsigned cbx_ieee_fmt(void);

/* A value the compiler cannot fold. */
static cbx_fp opaque(cbx_fp x)
{
    volatile cbx_fp v = x;
    return v;
}

/* Bit-identical (signed zeros told apart), and no NaN. */
static int same(cbx_fp x, cbx_fp y)
{
    return (x == y) && ((x != CBX_C(0.0)) || (((CBX_C(1.0) / x) > CBX_C(0.0)) == ((CBX_C(1.0) / y) > CBX_C(0.0))));
}

#if defined(CBX_TEST_NAIVE_SQRT)
/* Test hook only (scripts/ieee.sh): a square root that is not correctly
 * rounded on hard cases: binary64 rounded twice through the x87 format,
 * binary32 by Newton's iteration in the format. */
static cbx_fp check_sqrt(cbx_fp x)
{
#if CBX_INST == 64
    return (cbx_fp)__builtin_sqrtl((long double)x);
#else
    cbx_fp y = x > CBX_C(1.0) ? x : CBX_C(1.0);
    int i;
    for (i = 0; i < 200; i++) {
        y = CBX_C(0.5) * (y + x / y);
    }
    return y;
#endif
}
#else
#define check_sqrt cbx_sqrt_rn /* the library's own square root */
#endif

/* sqrt correctly rounded on the hard cases (cbx_ieee_cases.h) */
static unsigned check_sqrt_cases(void)
{
    unsigned bad = 0;
    unsigned i;
#if CBX_INST == 64
#define SQ cbx_sqrt_cases /* one instance per translation unit */
#else
#define SQ cbx_sqrtf_cases
#endif
    for (i = 0; i < (sizeof(SQ) / sizeof(SQ[0])); i++) {
        if (!same(check_sqrt(opaque(SQ[i][0])), SQ[i][1])) {
            bad |= CBX_IEEE_SQRT;
        }
    }
    return bad;
}

#if defined(CBX_TEST_NAIVE_DIV)
/* Test hook only (scripts/ieee.sh): a division rounded twice, through the
 * reciprocal (what -freciprocal-math builds). */
static cbx_fp check_div(cbx_fp a, cbx_fp b)
{
    return a * (CBX_C(1.0) / b);
}
#else
#define check_div cbx_div_rn /* the library's own division */
#endif

/* division correctly rounded on the hard cases (cbx_ieee_cases.h), through
 * the library's own cbx_div_rn (the projective bounds) */
static unsigned check_div_cases(void)
{
    unsigned bad = 0;
    unsigned i;
#if CBX_INST == 64
#define DV cbx_div_cases
#else
#define DV cbx_divf_cases
#endif
    for (i = 0; i < (sizeof(DV) / sizeof(DV[0])); i++) {
        if (!same(check_div(opaque(DV[i][0]), opaque(DV[i][1])), DV[i][2])) {
            bad |= CBX_IEEE_DIV;
        }
    }
    return bad;
}

#if CBX_INST == 64
/* The tight mode's EFTs exact on hard cases, and the fma two_prod calls
 * (if it calls one) correctly rounded: double rounding, near-midpoint
 * cancellation, a subnormal result, the sign of an exact zero. */
static unsigned check_eft(void)
{
    unsigned bad = 0;
    unsigned i;
    for (i = 0; i < (sizeof(cbx_prod_cases) / sizeof(cbx_prod_cases[0])); i++) {
        cbx_dd d = cbx_two_prod(opaque(cbx_prod_cases[i][0]), opaque(cbx_prod_cases[i][1]));
        if (!same(d.hi, cbx_prod_cases[i][2]) || !same(d.lo, cbx_prod_cases[i][3])) {
            bad |= CBX_IEEE_EFT;
        }
    }
    for (i = 0; i < (sizeof(cbx_sum_cases) / sizeof(cbx_sum_cases[0])); i++) {
        cbx_dd d = cbx_two_sum(opaque(cbx_sum_cases[i][0]), opaque(cbx_sum_cases[i][1]));
        if (!same(d.hi, cbx_sum_cases[i][2]) || !same(d.lo, cbx_sum_cases[i][3])) {
            bad |= CBX_IEEE_EFT;
        }
    }
#if !CBX_EFT_DEKKER
    for (i = 0; i < (sizeof(cbx_fma_cases) / sizeof(cbx_fma_cases[0])); i++) {
        cbx_fp r = CBX_FMA(opaque(cbx_fma_cases[i][0]), opaque(cbx_fma_cases[i][1]),
                           opaque(cbx_fma_cases[i][2]));
        if (!same(r, cbx_fma_cases[i][3])) {
            bad |= CBX_IEEE_FMA;
        }
    }
#endif
    return bad;
}
#endif

unsigned cbx_ieee_fmt(void)
{
    unsigned bad = 0;
#if CBX_INST == 64
    const cbx_fp half_eps = 0x1p-30;
    const cbx_fp tiny = 0x1p-60; /* (1+e)(1-e) = 1 - e^2 = 1 - tiny */
    const cbx_fp big = 0x1p53;
    const cbx_fp tie = 0x1p-53;
    const cbx_fp tie_up = 0x1.8p-53;
    const cbx_fp step = 0x1p-52;
    const cbx_fp xtra = 0x1p-78;                      /* below the x87 mantissa */
#else
    const cbx_fp half_eps = 0x1p-14f;
    const cbx_fp tiny = 0x1p-28f;
    const cbx_fp big = 0x1p24f;
    const cbx_fp tie = 0x1p-24f;
    const cbx_fp tie_up = 0x1.8p-24f;
    const cbx_fp step = 0x1p-23f;
    const cbx_fp xtra = 0x1p-47f; /* tie + xtra is a float; evaluating float
                                     sums in double is exact, so only the
                                     overflow case below sees excess range */
#endif
    const cbx_fp one = opaque(CBX_C(1.0));
    const cbx_fp zero = opaque(CBX_C(0.0));
    cbx_fp r;

    /* contraction: RN(RN(a*b) + c) = 0, the fused result is -e^2 */
    r = cbx_add_rn(cbx_mul_rn(opaque(CBX_C(1.0) + half_eps), opaque(CBX_C(1.0) - half_eps)),
                   opaque(-CBX_C(1.0)));
    if (r != CBX_C(0.0)) {
        bad |= CBX_IEEE_CONTRACT;
    }
    (void)tiny;

    /* excess precision: 1 + (tie + xtra) rounds up to 1 + step in the
     * format, but to 1 + tie first and then (a tie) to 1 with a wider
     * intermediate; and max * 2 * 0.5 must overflow */
    r = cbx_sub_rn(cbx_add_rn(one, opaque(tie + xtra)), opaque(CBX_C(1.0)));
    if (r != step) {
        bad |= CBX_IEEE_EXCESS;
    }
    r = cbx_mul_rn(cbx_mul_rn(opaque(CBX_K(FMAX)), opaque(CBX_C(2.0))), opaque(CBX_C(0.5)));
    if (!(r > CBX_K(FMAX))) {
        bad |= CBX_IEEE_EXCESS;
    }

    /* gradual underflow.  Flush-to-zero (results) and denormals-are-zero
     * (inputs, comparisons included: a subnormal compares equal to 0 under
     * DAZ) are told apart by scaling every subnormal up to a normal number
     * before it is compared: the smallest normal halved must stay > 0
     * (FTZ); eta read as an input and scaled by 2^100 must give
     * eta * 2^100 (DAZ); eta + eta, scaled, must give 2 eta * 2^100 (both). */
#if CBX_INST == 64
    r = cbx_mul_rn(opaque(0x1p-1022), opaque(CBX_C(0.5)));
#else
    r = cbx_mul_rn(opaque(0x1p-126f), opaque(CBX_C(0.5)));
#endif
    if (!(r > CBX_C(0.0))) {
        bad |= CBX_IEEE_FTZ;
    }
    r = cbx_mul_rn(opaque(CBX_K(ETA)), opaque(CBX_C(0x1p100)));
    if (r != (CBX_K(ETA) * CBX_C(0x1p100))) {
        bad |= CBX_IEEE_FTZ;
    }
    r = cbx_mul_rn(cbx_add_rn(opaque(CBX_K(ETA)), opaque(CBX_K(ETA))), opaque(CBX_C(0x1p100)));
    if (r != (CBX_K(ETA2) * CBX_C(0x1p100))) {
        bad |= CBX_IEEE_FTZ;
    }

    /* round to nearest: 1 + 1.5 ulp/2 rounds up (not toward zero or down),
     * 1 + ulp/4 rounds down (not up), and -1 - 1.5 ulp/2 away from zero */
    r = cbx_sub_rn(cbx_add_rn(one, opaque(tie_up)), opaque(CBX_C(1.0)));
    if (r != step) {
        bad |= CBX_IEEE_ROUNDING;
    }
    r = cbx_sub_rn(cbx_add_rn(one, opaque(tie * CBX_C(0.5))), opaque(CBX_C(1.0)));
    if (r != CBX_C(0.0)) {
        bad |= CBX_IEEE_ROUNDING;
    }
    r = cbx_add_rn(cbx_sub_rn(opaque(-CBX_C(1.0)), opaque(tie_up)), opaque(CBX_C(1.0)));
    if (r != -step) {
        bad |= CBX_IEEE_ROUNDING;
    }

    /* special values: NaN unequal to itself, infinity beyond the largest
     * finite value, -0 + -0 = -0 with its sign */
    r = cbx_mul_rn(opaque(CBX_HUGE), zero);
    if (r == r) {
        bad |= CBX_IEEE_SPECIAL;
    }
    r = opaque(-CBX_HUGE);
    if (!(r < -CBX_K(FMAX))) {
        bad |= CBX_IEEE_SPECIAL;
    }
    r = cbx_add_rn(opaque(-CBX_C(0.0)), opaque(-CBX_C(0.0)));
    if ((r != CBX_C(0.0)) || ((CBX_C(1.0) / r) > CBX_C(0.0))) {
        bad |= CBX_IEEE_SPECIAL;
    }

    /* no reassociation: (b + 1) - b is 0 for b = 2^p, not 1 (the same
     * value b twice: what a reassociating compiler would simplify) */
    r = opaque(big);
    r = cbx_sub_rn(cbx_add_rn(r, one), r);
    if (r != CBX_C(0.0)) {
        bad |= CBX_IEEE_ASSOC;
    }

    /* what the proofs trust: sqrt correctly rounded; the EFTs exact and
     * fma correctly rounded (binary64: the tight mode is binary64 only) */
    bad |= check_sqrt_cases();
    bad |= check_div_cases();
#if CBX_INST == 64
    bad |= check_eft();
#endif
    return bad;
}

#if CBX_INST == 64
unsigned cbx_ieee_fmt_f(void);

unsigned cbx_ieee_check(void)
{
    return cbx_ieee_fmt() | cbx_ieee_fmt_f();
}
#endif
