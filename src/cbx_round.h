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
/* IEEE-754 sqrt is correctly rounded: r = RN(sqrt(x)).  For x > 0 a double,
 * sqrt(x) >= 2^-537 is normal, so |r - sqrt(x)| <= u sqrt(x) and
 * r^2 lies within a factor (1 -+ u)^2 of x; these squared forms are the
 * contract (trusted; listed in proofs/README.md). */
/*@ requires fin: \is_finite(x) && 0 <= x <= 0x1p1021;
    assigns \result \from x;
    ensures fin: \is_finite(\result) && \result >= 0;
    ensures up: x <= \result * \result * (1 + 0x1p-51);
    ensures dn: \result * \result <= x * (1 + 0x1p-51);
*/
double cbx_sqrt_rn(double x);
#else
#include <math.h>
static inline double cbx_pinf(void) { return HUGE_VAL; }
static inline double cbx_ninf(void) { return -HUGE_VAL; }
static inline double cbx_sqrt_rn(double x) { return sqrt(x); }
#endif

/* Product rounded to nearest; the range precondition rules out overflow. */
/*@ requires fin: \is_finite(x) && \is_finite(y);
    requires rng: in_dom(x, y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - x*y) <= 0x1p-53 * \abs(x*y) + 0x1p-1074;
    ensures pos: x*y >= 0 ==> \result >= 0;
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
    ensures pos: x - y >= 0 ==> \result >= 0;
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

/* The one outward widening of a bound: 5.5 u R + 2^-1067 with the computed
 * scale R = |t| + g0 + g1 + g2 (g_j >= 0 the magnitudes of the terms). */
/*@ requires fin: \is_finite(t) && \is_finite(g0) && \is_finite(g1) && \is_finite(g2);
    requires rt: -0x1p1018 <= t <= 0x1p1018;
    requires r0: 0 <= g0 <= 0x1p1019 + 0x1p968;
    requires r1: 0 <= g1 <= 0x1p1019 + 0x1p968;
    requires r2: 0 <= g2 <= 0x1p1019 + 0x1p968;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures lo: \result >= 0x1.6p-51 * (\abs(t) + g0 + g1 + g2) * (1 - 0x1p-50) + 0x1p-1068;
    ensures hi: \result <= 0x1.6p-51 * (\abs(t) + g0 + g1 + g2) * (1 + 0x1p-50) + 0x1p-1066;
*/
static inline double cbx_widening(double t, double g0, double g1, double g2)
{
    double r0 = cbx_abs(t);
    double r1 = cbx_add_rn(r0, g0);
    double r2 = cbx_add_rn(r1, g1);
    double r3 = cbx_add_rn(r2, g2);
    /*@ assert r3lo: r3 >= (\abs(t) + g0 + g1 + g2) * (1 - 0x1p-51) - 0x1p-1072; */
    /*@ assert r3hi: r3 <= (\abs(t) + g0 + g1 + g2) * (1 + 0x1p-51) + 0x1p-1072; */
    double w = cbx_mul_rn(r3, 0x1.6p-51);
    /*@ assert wlo: w >= 0x1.6p-51 * r3 * (1 - 0x1p-53) - 0x1p-1074; */
    return cbx_add_rn(w, 0x1p-1067);
}

/* x + t rounded down (cbx_add_dn) or up (cbx_add_up), with a margin: the
 * result is at least 3 u (|x| + |t|) + 2^-1070 below (above) the exact sum,
 * which pays for a rounding error of x of up to that size (one product
 * rounded to nearest, in the class kernels), and within
 * 8 u (|x| + |t|) + 2^-1066 + 2^-1072 of it.  Four operations and the
 * widening's four. */
/*@ requires fin: \is_finite(x) && \is_finite(t);
    requires rx: -0x1p1019 <= x <= 0x1p1019;
    requires rt: -0x1p1018 <= t <= 0x1p1018;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures below: \result <= x + t - (0x1.8p-52 * (\abs(x) + \abs(t)) + 0x1p-1070);
    ensures near: \result >= x + t - (0x1p-50 * (\abs(x) + \abs(t)) + 0x1p-1066 + 0x1p-1072);
*/
static inline double cbx_add_dn(double x, double t)
{
    double s = cbx_add_rn(x, t);
    double w = cbx_widening(t, cbx_abs(x), 0.0, 0.0);
    /*@ assert se: \abs(s - (x + t)) <= 0x1p-53 * (\abs(x) + \abs(t)) + 0x1p-1074; */
    /*@ assert wl: w >= 0x1.6p-51 * (\abs(x) + \abs(t)) * (1 - 0x1p-50) + 0x1p-1068; */
    /*@ assert wh: w <= 0x1.6p-51 * (\abs(x) + \abs(t)) * (1 + 0x1p-50) + 0x1p-1066; */
    return cbx_sub_rn(s, w);
}

/*@ requires fin: \is_finite(x) && \is_finite(t);
    requires rx: -0x1p1019 <= x <= 0x1p1019;
    requires rt: -0x1p1018 <= t <= 0x1p1018;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures above: \result >= x + t + (0x1.8p-52 * (\abs(x) + \abs(t)) + 0x1p-1070);
    ensures near: \result <= x + t + (0x1p-50 * (\abs(x) + \abs(t)) + 0x1p-1066 + 0x1p-1072);
*/
static inline double cbx_add_up(double x, double t)
{
    double s = cbx_add_rn(x, t);
    double w = cbx_widening(t, cbx_abs(x), 0.0, 0.0);
    /*@ assert se: \abs(s - (x + t)) <= 0x1p-53 * (\abs(x) + \abs(t)) + 0x1p-1074; */
    /*@ assert wl: w >= 0x1.6p-51 * (\abs(x) + \abs(t)) * (1 - 0x1p-50) + 0x1p-1068; */
    /*@ assert wh: w <= 0x1.6p-51 * (\abs(x) + \abs(t)) * (1 + 0x1p-50) + 0x1p-1066; */
    return cbx_add_rn(s, w);
}

#endif /* CBX_ROUND_H */
