/*
 * Run-time domain and special-value checks.  Each returns 1 exactly when
 * the matching predicate of specs/cbx_spec.h holds; the kernels are called
 * only where they hold.  Comparisons are IEEE: -B <= x <= B is false for
 * NaN and infinities.
 */
#ifndef CBX_DOMAIN_H
#define CBX_DOMAIN_H

#include "certbox.h"

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

/* 1 if x is finite: comparisons with NaN and infinities are false. */
/*@ assigns \nothing;
    ensures \result != 0 <==> \is_finite(x);
*/
static inline int cbx_is_fin(double x) { return x >= -0x1.fffffffffffffp1023 && x <= 0x1.fffffffffffffp1023; }

/* 1 when every input of one output row is finite and in the proven domain
 * (specs: row_in_dom).  One early return per test keeps the proof linear. */
/*@ assigns \nothing;
    ensures ok: \result != 0 <==>
      (\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
       && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
       && \is_finite(l2) && \is_finite(h2)
       && row_in_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2));
*/
static inline int cbx_row_ok(double m0, double m1, double m2, double t,
                  double l0, double h0, double l1, double h1, double l2, double h2)
{
    if (!cbx_is_fin(m0)) return 0;
    if (!cbx_is_fin(m1)) return 0;
    if (!cbx_is_fin(m2)) return 0;
    if (!cbx_is_fin(t)) return 0;
    if (!cbx_is_fin(l0)) return 0;
    if (!cbx_is_fin(h0)) return 0;
    if (!cbx_is_fin(l1)) return 0;
    if (!cbx_is_fin(h1)) return 0;
    if (!cbx_is_fin(l2)) return 0;
    if (!cbx_is_fin(h2)) return 0;
    if (!(t >= -0x1p1018 && t <= 0x1p1018)) return 0;
    if (!cbx_dom_pair(m0, l0)) return 0;
    if (!cbx_dom_pair(m0, h0)) return 0;
    if (!cbx_dom_pair(m1, l1)) return 0;
    if (!cbx_dom_pair(m1, h1)) return 0;
    if (!cbx_dom_pair(m2, l2)) return 0;
    if (!cbx_dom_pair(m2, h2)) return 0;
    return 1;
}

/* 1 if x is NaN (x != x holds only for NaN). */
/*@ assigns \nothing;
    ensures \result != 0 <==> \is_NaN(x);
*/
static inline int cbx_is_nan(double x) { return x != x; }

/* 1 if hi < lo in IEEE comparison (the box is empty on that axis). */
/*@ assigns \nothing;
    ensures \result != 0 <==> \lt_double(hi, lo);
*/
static inline int cbx_is_inverted(double lo, double hi) { return hi < lo; }

/* 1 if [lo, hi] has no real point: hi < lo, lo = +inf or hi = -inf. */
/*@ assigns \nothing;
    ensures \result != 0 <==> no_point(lo, hi);
*/
static inline int cbx_no_point(double lo, double hi)
{
    return hi < lo || lo > 0x1.fffffffffffffp1023 || hi < -0x1.fffffffffffffp1023;
}

#endif /* CBX_DOMAIN_H */
