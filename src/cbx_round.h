/*
 * Rounding primitives: one IEEE-754 binary64 operation each, rounded to
 * nearest, with its error bound in the contract.  Every floating-point
 * operation of the proven kernels goes through one of these, so the
 * rounding reasoning is done once here and the kernels' proofs are linear
 * arithmetic over the contracts.
 *
 * Constants (widening factors) are passed as arguments, never written as
 * literals inside an operation: WP's simplifier evaluates a literal argument
 * at the call site, so the caller's goals see the exact constant.
 *
 * Error bounds (round-to-nearest, no overflow; u = 2^-53, eta = 2^-1074):
 *   |RN(z) - z| <= u |z| + eta/2 <= u |z| + eta
 */
#ifndef CBX_ROUND_H
#define CBX_ROUND_H

#include "certbox.h"

#if defined(__FRAMAC__)
/* The only facts taken without proof from the C side: HUGE_VAL is +inf
 * (C99 7.12p3 with Annex F).  Listed in proofs/README.md. */
/*@ assigns \result \from \nothing;
    ensures \is_plus_infinity(\result); */
double cbx_pinf(void);
/*@ assigns \result \from \nothing;
    ensures \is_minus_infinity(\result); */
double cbx_ninf(void);
#else
#include <math.h>
static inline double cbx_pinf(void) { return HUGE_VAL; }
static inline double cbx_ninf(void) { return -HUGE_VAL; }
#endif

/* Product rounded to nearest; the range precondition rules out overflow. */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    requires rng: in_dom(x, y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - x*y) <= 0x1p-53 * \abs(x*y) + 0x1p-1074;
*/
static inline double cbx_mul_rn(double x, double y) { return x * y; }

/* Sum rounded to nearest. */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    requires rng: -0x1p1021 <= x + y <= 0x1p1021;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - (x + y)) <= 0x1p-53 * \abs(x + y) + 0x1p-1074;
    ensures pos: x + y >= 0 ==> \result >= 0;
*/
static inline double cbx_add_rn(double x, double y) { return x + y; }

/* Difference rounded to nearest. */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    requires rng: -0x1p1021 <= x - y <= 0x1p1021;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - (x - y)) <= 0x1p-53 * \abs(x - y) + 0x1p-1074;
*/
static inline double cbx_sub_rn(double x, double y) { return x - y; }

/* |x|, exact. */
/*@ requires fin: \is_finite(x);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == \abs(x);
*/
static inline double cbx_abs(double x) { return x < 0.0 ? -x : x; }

/* min and max, exact (inputs are never NaN here). */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == \min(x, y);
*/
static inline double cbx_min2(double x, double y) { return x < y ? x : y; }

/*@ requires fin: \is_finite(x) && \is_finite(y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == \max(x, y);
*/
static inline double cbx_max2(double x, double y) { return x < y ? y : x; }

/* One magnitude class: |m| <= bm and |c| <= bc (specs: cls). */
/*@ requires fin: \is_finite(m) && \is_finite(c) && \is_finite(bm) && \is_finite(bc);
    assigns \nothing;
    ensures val: \result != 0 <==> cls(m, c, bm, bc);
*/
static inline int cbx_cls(double m, double c, double bm, double bc)
{
    return m >= -bm && m <= bm && c >= -bc && c <= bc;
}

/* Run-time check of one product's domain class (specs: dom_pair).
 * The common class (both factors at most 2^509) comes first. */
/*@ requires fin: \is_finite(m) && \is_finite(c);
    assigns \nothing;
    ensures val: \result != 0 <==> dom_pair(m, c);
*/
static inline int cbx_dom_pair(double m, double c)
{
    if (cbx_cls(m, c, 0x1p509, 0x1p509)) return 1;
    if (cbx_cls(m, c, 0x1p0, 0x1p1018)) return 1;
    if (cbx_cls(m, c, 0x1p64, 0x1p954)) return 1;
    if (cbx_cls(m, c, 0x1p128, 0x1p890)) return 1;
    if (cbx_cls(m, c, 0x1p192, 0x1p826)) return 1;
    if (cbx_cls(m, c, 0x1p256, 0x1p762)) return 1;
    if (cbx_cls(m, c, 0x1p320, 0x1p698)) return 1;
    if (cbx_cls(m, c, 0x1p384, 0x1p634)) return 1;
    if (cbx_cls(m, c, 0x1p448, 0x1p570)) return 1;
    if (cbx_cls(m, c, 0x1p512, 0x1p506)) return 1;
    if (cbx_cls(m, c, 0x1p576, 0x1p442)) return 1;
    if (cbx_cls(m, c, 0x1p640, 0x1p378)) return 1;
    if (cbx_cls(m, c, 0x1p704, 0x1p314)) return 1;
    if (cbx_cls(m, c, 0x1p768, 0x1p250)) return 1;
    if (cbx_cls(m, c, 0x1p832, 0x1p186)) return 1;
    if (cbx_cls(m, c, 0x1p896, 0x1p122)) return 1;
    if (cbx_cls(m, c, 0x1p960, 0x1p58)) return 1;
    if (cbx_cls(m, c, 0x1p1018, 0x1p0)) return 1;
    return 0;
}

#endif /* CBX_ROUND_H */
