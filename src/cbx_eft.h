/*
 * Error-free transformations (EFT): a sum or a product of two doubles as
 * an unevaluated pair hi + lo, EXACTLY.  They are the only trusted
 * contracts of the tight mode (listed in proofs/README.md):
 *   two_sum  (Knuth, TAOCP vol. 2, 4.2.2 Thm B; Moller 1965): for finite
 *            a, b in binary64 with round to nearest and no overflow,
 *            s = RN(a+b) and the six-operation error term e satisfy
 *            s + e = a + b exactly, at any magnitude (subnormals included).
 *   two_prod (the FMA form): p = RN(a*b), e = fma(a, b, -p).  The error
 *            a*b - p is a double whenever ulp(a) ulp(b) >= 2^-1074, which
 *            |a*b| >= 2^-969 guarantees (Boldo & Daumas, "Representable
 *            correcting terms", 2003); fma rounds once (C99 7.12.13.1), so
 *            it returns that error exactly.
 * Both theorems are machine-checked in Flocq (Boldo, Melquiond); the tests
 * (tests/test_tight.c) check them against GMP as well.
 */
#ifndef CBX_EFT_H
#define CBX_EFT_H

#include "certbox.h"

typedef struct cbx_dd { double hi, lo; } cbx_dd;

/* Eight doubles whose exact sum the tight mode's certificate tracks. */
typedef struct cbx_vec8 { double v0, v1, v2, v3, v4, v5, v6, v7; } cbx_vec8;

#if defined(__FRAMAC__)
/*@ requires fin: \is_finite(a) && \is_finite(b);
    requires rng: -0x1p1019 <= a <= 0x1p1019 && -0x1p1019 <= b <= 0x1p1019;
    assigns \nothing;
    ensures fin: \is_finite(\result.hi) && \is_finite(\result.lo);
    ensures exact: \result.hi + \result.lo == a + b;
*/
cbx_dd cbx_two_sum(double a, double b);

/*@ requires fin: \is_finite(a) && \is_finite(b);
    requires rng: -0x1p1018 <= a*b <= 0x1p1018;
    requires low: a*b == 0 || a*b >= 0x1p-969 || a*b <= -0x1p-969;
    assigns \nothing;
    ensures fin: \is_finite(\result.hi) && \is_finite(\result.lo);
    ensures exact: \result.hi + \result.lo == a*b;
*/
cbx_dd cbx_two_prod(double a, double b);
#else
#if defined(__GNUC__)
#define CBX_FMA __builtin_fma /* gcc and clang: no <math.h> (freestanding) */
#else
#include <math.h>
#define CBX_FMA fma
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

static inline cbx_dd cbx_two_prod(double a, double b)
{
    cbx_dd r;
    r.hi = a * b;
    r.lo = CBX_FMA(a, b, -r.hi);
    return r;
}
#endif

#endif /* CBX_EFT_H */
