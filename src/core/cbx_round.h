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
 * Error bounds (round-to-nearest, no overflow; binary64: u = 2^-53,
 * eta = 2^-1074; binary32: u = 2^-24, eta = 2^-149):
 *   |RN(z) - z| <= u |z| + eta/2 <= u |z| + eta
 * Written once for both formats (include/cbx_prec_begin.h: cbx_fp, CBX_K).
 */
#ifndef CBX_ROUND_H
#define CBX_ROUND_H

#include "certbox.h"
#include "cbx_prec.h"

#if defined(__FRAMAC__)
/* The only facts taken without proof from the C side: HUGE_VAL (HUGE_VALF)
 * is +inf (C99 7.12p3 with Annex F).  Listed in proofs/README.md. */
/*@ assigns \result \from \nothing;
    ensures \is_plus_infinity(\result); */
cbx_fp cbx_pinf(void);
/*@ assigns \result \from \nothing;
    ensures \is_minus_infinity(\result); */
cbx_fp cbx_ninf(void);
/* IEEE-754 sqrt is correctly rounded: r = RN(sqrt(x)).  For x > 0 a double,
 * sqrt(x) >= 2^-537 is normal (a float: sqrt(x) >= 2^-75 is normal), so |r - sqrt(x)| <= u sqrt(x) and
 * r^2 lies within a factor (1 -+ u)^2 of x; these squared forms are the
 * contract (trusted; listed in proofs/README.md). */
/*@ requires fin: \is_finite(x) && 0 <= x <= CBX_R21;
    assigns \result \from x;
    ensures fin: \is_finite(\result) && \result >= 0;
    ensures up: x <= \result * \result * (1 + CBX_U4);
    ensures dn: \result * \result <= x * (1 + CBX_U4);
*/
cbx_fp cbx_sqrt_rn(cbx_fp x);
#else
#if !defined(__GNUC__)
#include <math.h> /* gcc and clang use builtins: the library needs no libc */
#endif
static inline cbx_fp cbx_pinf(void) { return CBX_HUGE; }
static inline cbx_fp cbx_ninf(void) { return -CBX_HUGE; }
static inline cbx_fp cbx_sqrt_rn(cbx_fp x) { return CBX_SQRT(x); }
#endif

/* Product rounded to nearest; the range precondition rules out overflow. */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    requires rng: in_dom(x, y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - x*y) <= CBX_U * \abs(x*y) + CBX_ETA;
    ensures pos: x*y >= 0 ==> \result >= 0;
*/
static inline cbx_fp cbx_mul_rn(cbx_fp x, cbx_fp y) { return x * y; }

/* Sum rounded to nearest. */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    requires rng: -CBX_R21 <= x + y <= CBX_R21;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - (x + y)) <= CBX_U * \abs(x + y) + CBX_ETA;
    ensures pos: x + y >= 0 ==> \result >= 0;
*/
static inline cbx_fp cbx_add_rn(cbx_fp x, cbx_fp y) { return x + y; }

/* Difference rounded to nearest. */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    requires rng: -CBX_R21 <= x - y <= CBX_R21;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - (x - y)) <= CBX_U * \abs(x - y) + CBX_ETA;
    ensures pos: x - y >= 0 ==> \result >= 0;
*/
static inline cbx_fp cbx_sub_rn(cbx_fp x, cbx_fp y) { return x - y; }

/* -x, exact. */
/*@ requires fin: \is_finite(x);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == -x;
*/
static inline cbx_fp cbx_neg(cbx_fp x) { return -x; }

/* |x|, exact.  Written as the larger of x and -x in the form
 * `x < y ? y : x` that compilers turn into one max instruction (maxsd),
 * not a compare-and-branch; the same value as x < 0 ? -x : x, -0 included. */
/*@ requires fin: \is_finite(x);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == \abs(x);
*/
static inline cbx_fp cbx_abs(cbx_fp x)
{
    cbx_fp n = -x;
    return (x < n) ? n : x;
}

/* min and max, exact (inputs are never NaN here). */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == \min(x, y);
*/
static inline cbx_fp cbx_min2(cbx_fp x, cbx_fp y) { return (x < y) ? x : y; }

/*@ requires fin: \is_finite(x) && \is_finite(y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == \max(x, y);
*/
static inline cbx_fp cbx_max2(cbx_fp x, cbx_fp y) { return (x < y) ? y : x; }

/* The one outward widening of a bound: 5.5 u R + 2^-1067 with the computed
 * scale R = |t| + g0 + g1 + g2 (g_j >= 0 the magnitudes of the terms). */
/*@ requires fin: \is_finite(t) && \is_finite(g0) && \is_finite(g1) && \is_finite(g2);
    requires rt: -CBX_RT <= t <= CBX_RT;
    requires r0: 0 <= g0 <= CBX_R19 + CBX_RW;
    requires r1: 0 <= g1 <= CBX_R19 + CBX_RW;
    requires r2: 0 <= g2 <= CBX_R19 + CBX_RW;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures lo: \result >= CBX_U5H * (\abs(t) + g0 + g1 + g2) * (1 - CBX_U8) + CBX_ETA64;
    ensures hi: \result <= CBX_U5H * (\abs(t) + g0 + g1 + g2) * (1 + CBX_U8) + CBX_ETA256;
*/
static inline cbx_fp cbx_widening(cbx_fp t, cbx_fp g0, cbx_fp g1, cbx_fp g2)
{
    cbx_fp r0 = cbx_abs(t);
    cbx_fp r1 = cbx_add_rn(r0, g0);
    cbx_fp r2 = cbx_add_rn(r1, g1);
    cbx_fp r3 = cbx_add_rn(r2, g2);
    /*@ assert r3lo: r3 >= (\abs(t) + g0 + g1 + g2) * (1 - CBX_U4) - CBX_ETA4; */
    /*@ assert r3hi: r3 <= (\abs(t) + g0 + g1 + g2) * (1 + CBX_U4) + CBX_ETA4; */
    cbx_fp w = cbx_mul_rn(r3, CBX_K(U5H));
    /*@ assert wlo: w >= CBX_U5H * r3 * (1 - CBX_U) - CBX_ETA; */
    return cbx_add_rn(w, CBX_K(ETA128));
}

#if CBX_INST == 64 /* used by the binary64 class kernels only */
/* x + t rounded down (cbx_add_dn) or up (cbx_add_up), with a margin: the
 * result is at least 3 u (|x| + |t|) + 2^-1070 below (above) the exact sum,
 * which pays for a rounding error of x of up to that size (one product
 * rounded to nearest, in the class kernels), and within
 * 8 u (|x| + |t|) + 2^-1066 + 2^-1072 of it.  Four operations and the
 * widening's four. */
/*@ requires fin: \is_finite(x) && \is_finite(t);
    requires rx: -CBX_R19 <= x <= CBX_R19;
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures below: \result <= x + t - (CBX_U3 * (\abs(x) + \abs(t)) + CBX_ETA16);
    ensures near: \result >= x + t - (CBX_U8 * (\abs(x) + \abs(t)) + CBX_ETA256 + CBX_ETA4);
*/
static inline cbx_fp cbx_add_dn(cbx_fp x, cbx_fp t)
{
    cbx_fp s = cbx_add_rn(x, t);
    cbx_fp w = cbx_widening(t, cbx_abs(x), CBX_C(0.0), CBX_C(0.0));
    /*@ assert se: \abs(s - (x + t)) <= CBX_U * (\abs(x) + \abs(t)) + CBX_ETA; */
    /*@ assert wl: w >= CBX_U5H * (\abs(x) + \abs(t)) * (1 - CBX_U8) + CBX_ETA64; */
    /*@ assert wh: w <= CBX_U5H * (\abs(x) + \abs(t)) * (1 + CBX_U8) + CBX_ETA256; */
    return cbx_sub_rn(s, w);
}

/*@ requires fin: \is_finite(x) && \is_finite(t);
    requires rx: -CBX_R19 <= x <= CBX_R19;
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures above: \result >= x + t + (CBX_U3 * (\abs(x) + \abs(t)) + CBX_ETA16);
    ensures near: \result <= x + t + (CBX_U8 * (\abs(x) + \abs(t)) + CBX_ETA256 + CBX_ETA4);
*/
static inline cbx_fp cbx_add_up(cbx_fp x, cbx_fp t)
{
    cbx_fp s = cbx_add_rn(x, t);
    cbx_fp w = cbx_widening(t, cbx_abs(x), CBX_C(0.0), CBX_C(0.0));
    /*@ assert se: \abs(s - (x + t)) <= CBX_U * (\abs(x) + \abs(t)) + CBX_ETA; */
    /*@ assert wl: w >= CBX_U5H * (\abs(x) + \abs(t)) * (1 - CBX_U8) + CBX_ETA64; */
    /*@ assert wh: w <= CBX_U5H * (\abs(x) + \abs(t)) * (1 + CBX_U8) + CBX_ETA256; */
    return cbx_add_rn(s, w);
}
#endif

#endif /* CBX_ROUND_H */
