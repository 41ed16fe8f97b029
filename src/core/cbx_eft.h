/*
 * Error-free transformations (EFT): a sum or a product of two doubles as
 * an unevaluated pair hi + lo, EXACTLY.  They are the only trusted
 * contracts of the tight mode (listed in proofs/README.md):
 *   two_sum  (Knuth, TAOCP vol. 2, 4.2.2 Thm B; Moller 1965): for finite
 *            a, b in binary64 with round to nearest and no overflow,
 *            s = RN(a+b) and the six-operation error term e satisfy
 *            s + e = a + b exactly, at any magnitude (subnormals included).
 *   two_prod p = RN(a*b) and e = a*b - p exactly, in one of two builds:
 *     FMA form: e = fma(a, b, -p).  The error a*b - p is a double whenever
 *            ulp(a) ulp(b) >= 2^-1074, which |a*b| >= 2^-969 guarantees
 *            (Boldo & Daumas, "Representable correcting terms", 2003); a
 *            correctly rounded fma (C99 7.12.13.1, IEEE 754-2008 5.4.1)
 *            returns that error exactly.
 *     Dekker form (no fma): Veltkamp's split of each factor with
 *            C = 2^27 + 1 and Dekker's product (Dekker 1971, mul12):
 *            exact in radix 2 with round to nearest (any tie rule) when
 *            a*b == 0 or |a*b| >= 2^(emin + 2p - 1) = 2^-969 (emin = -1074,
 *            p = 53), subnormal factors included, and no operation
 *            overflows (Flocq, Pff2Flocq.v, Theorem Dekker: Boldo's proof,
 *            "Pitfalls of a full floating-point proof", IJCAR 2006).  The
 *            split's C*x overflows as |x| nears 2^997 (DBL_MAX / C), so a
 *            factor above 2^995 is not split as it is: the contract's
 *            |a*b| <= 2^1018 leaves |other factor| <= 2^23 then, so the
 *            big factor is scaled by 2^-64 and the other by 2^64: both
 *            exact, the exact product unchanged; every other intermediate
 *            is then below 2^1019.  So the Dekker form needs no hypothesis
 *            beyond the contract below.
 *   Which form: CBX_NO_FMA defined -> Dekker; CBX_USE_FMA defined -> fma
 *   (the user vouches for the libm's fma); otherwise fma where it is an
 *   instruction (__FP_FAST_FMA: x86 with -mfma, aarch64, Cortex-M7) or
 *   glibc's correctly rounded software fma (__GLIBC__: x86-64 without
 *   -mfma, armhf), and Dekker everywhere else: freestanding builds, newlib
 *   (whose generic fma is a plain x*y+z: wrong here), the Cortex-M4F (no
 *   double FPU), unknown libraries.  CBX_TWO_PROD_NAME says which.
 *   !defined(FP_FAST_FMA) alone would be the wrong test: glibc's fma is
 *   correct without the instruction, newlib's generic one is wrong on
 *   any CPU that lacks it.
 * Both theorems are machine-checked in Flocq (Boldo, Melquiond); the tests
 * (tests/test_tight.c, tests/test_eft.c) check them against GMP, and
 * cbx_ieee_check() (CBX_IEEE_EFT, CBX_IEEE_FMA) checks the built ones on
 * hard cases at run time.
 */
#ifndef CBX_EFT_H
#define CBX_EFT_H

#include "certbox.h"

typedef struct cbx_dd { double hi; double lo; } cbx_dd;

/* Eight doubles whose exact sum the tight mode's certificate tracks. */
typedef struct cbx_vec8 { double v0; double v1; double v2; double v3; double v4; double v5; double v6; double v7; } cbx_vec8;

#if defined(__FRAMAC__)
/*@ requires fin: \is_finite(a) && \is_finite(b);
    requires rng: -0x1p1019 <= a <= 0x1p1019 && -0x1p1019 <= b <= 0x1p1019;
    assigns \nothing;
    ensures fin: \is_finite(\result.hi) && \is_finite(\result.lo);
    ensures rn: \result.hi == (double)(a + b);
    ensures exact: \result.hi + \result.lo == a + b;
*/
cbx_dd cbx_two_sum(double a, double b);

/*@ requires fin: \is_finite(a) && \is_finite(b);
    requires rng: -0x1p1018 <= a*b <= 0x1p1018;
    requires low: a*b == 0 || a*b >= 0x1p-969 || a*b <= -0x1p-969;
    assigns \nothing;
    ensures fin: \is_finite(\result.hi) && \is_finite(\result.lo);
    ensures rn: \result.hi == (double)(a*b);
    ensures exact: \result.hi + \result.lo == a*b;
*/
cbx_dd cbx_two_prod(double a, double b);
#else
#if defined(CBX_NO_FMA) && defined(CBX_USE_FMA)
#error "certbox: CBX_NO_FMA and CBX_USE_FMA both defined"
#endif
#if !defined(CBX_NO_FMA) && !defined(CBX_USE_FMA) && defined(__STDC_HOSTED__) && __STDC_HOSTED__
#include <math.h> /* a hosted C library: glibc defines __GLIBC__ here */
#endif
#if defined(CBX_NO_FMA)
#define CBX_EFT_DEKKER 1
#elif defined(CBX_USE_FMA) || defined(__FP_FAST_FMA) || defined(__GLIBC__)
#define CBX_EFT_DEKKER 0
#else
#define CBX_EFT_DEKKER 1
#endif

#if CBX_EFT_DEKKER
#define CBX_TWO_PROD_NAME "Dekker/Veltkamp (no fma)"
#else
#define CBX_TWO_PROD_NAME "fma"
#endif
/* The fma form is compiled where it is selected, and in the test that
 * compares both forms (CBX_EFT_BOTH, tests/test_eft.c). */
#if !CBX_EFT_DEKKER || defined(CBX_EFT_BOTH)
#if defined(CBX_TEST_NAIVE_FMA)
/* test hook only (scripts/ieee.sh): an fma rounded twice, as newlib's
 * generic fma; cbx_ieee_check() must set CBX_IEEE_FMA and CBX_IEEE_EFT */
#define CBX_FMA(x, y, z) ((x) * (y) + (z))
#elif defined(__GNUC__)
#define CBX_FMA __builtin_fma /* gcc and clang: no <math.h> (freestanding) */
#else
#include <math.h>
#define CBX_FMA fma
#endif
#endif

static inline cbx_dd cbx_two_sum(double a, double b)
{
    cbx_dd r;
    double s = a + b;
    double bb = s - a;
    double ab = s - bb;
    r.hi = s;
    r.lo = (a - ab) + (b - bb);
    return r;
}

/* Veltkamp's split: x = h + t, h on 26 bits, t on 26 bits (|x| <= 2^996). */
static inline cbx_dd cbx_split(double x)
{
    cbx_dd r;
    double p = x * 134217729.0; /* 2^27 + 1 */
    double q = x - p;
    r.hi = q + p;
    r.lo = x - r.hi;
    return r;
}

/* Dekker's mul12: x*y - r for r = RN(x*y), in the operation order of
 * Flocq's proof (Pff2Flocq.v, Dekker). */
static inline double cbx_dekker_err(double x, double y, double r)
{
    cbx_dd sx = cbx_split(x);
    cbx_dd sy = cbx_split(y);
    double x1y1 = sx.hi * sy.hi;
    double x1y2 = sx.hi * sy.lo;
    double x2y1 = sx.lo * sy.hi;
    double x2y2 = sx.lo * sy.lo;
    double t1 = -r + x1y1;
    double t2 = t1 + x1y2;
    double t3 = t2 + x2y1;
    return t3 + x2y2;
}

static inline cbx_dd cbx_two_prod_dekker(double a, double b)
{
    cbx_dd r;
    r.hi = a * b;
    /* keep both factors <= 2^995: |a*b| <= 2^1018 makes the other <= 2^23,
     * so a power-of-two exchange is exact and leaves a*b unchanged */
    if ((a > 0x1p995) || (a < -0x1p995))
        r.lo = cbx_dekker_err(a * 0x1p-64, b * 0x1p64, r.hi);
    else if ((b > 0x1p995) || (b < -0x1p995))
        r.lo = cbx_dekker_err(a * 0x1p64, b * 0x1p-64, r.hi);
    else
        r.lo = cbx_dekker_err(a, b, r.hi);
    return r;
}

#if !CBX_EFT_DEKKER || defined(CBX_EFT_BOTH)
static inline cbx_dd cbx_two_prod_fma(double a, double b)
{
    cbx_dd r;
    r.hi = a * b;
    r.lo = CBX_FMA(a, b, -r.hi);
    return r;
}
#endif

static inline cbx_dd cbx_two_prod(double a, double b)
{
#if CBX_EFT_DEKKER
    return cbx_two_prod_dekker(a, b);
#else
    return cbx_two_prod_fma(a, b);
#endif
}
#endif

#endif /* CBX_EFT_H */
