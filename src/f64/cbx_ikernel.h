/*
 * The proven kernel of the interval form with an interval matrix: one
 * output coordinate
 *     [tl, th] + [ml0, mh0] [l0, h0] + [ml1, mh1] [l1, h1] + [ml2, mh2] [l2, h2]
 * outward rounded (specs/cbx_imat.h: irow_lo, irow_hi).  The same design as
 * src/algo/cbx_kernel.h, of which it reuses the column (cbx_column, two products
 * each) and the widening: a term's four corner products are the two
 * columns of ml and mh; its smaller end is the smaller of their smaller
 * ends, its magnitude the larger magnitude.  Each end is the rounded sum
 * moved out once by w = 5.5 u R + eta_128 (R = max(|tl|, |th|) + the
 * computed magnitudes), which pays for every rounding: within 12 u S +
 * 2^-1065 of the exact end.  Branch-free.  Written once for both formats
 * (today instantiated for binary64: src/f64/cbx_imat.c).
 */
#ifndef CBX_IKERNEL_H
#define CBX_IKERNEL_H

#include "certbox.h"
#include "cbx_prec.h"
#include "cbx_kernel.h"
#include "cbx_fast.h"

/* One term [ml, mh] x [l, h]: its smaller and larger corner products, each
 * within u itmag + eta of the exact one, and its magnitude within a
 * relative u of itmag. */
/*@ requires fin: \is_finite(ml) && \is_finite(mh) && \is_finite(l) && \is_finite(h);
    requires dom: in_dom(ml, l) && in_dom(ml, h) && in_dom(mh, l) && in_dom(mh, h);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi) && \is_finite(\result.mag);
    ensures lo: \abs(\result.lo - itmin(ml, mh, l, h)) <= CBX_U * itmag(ml, mh, l, h) + CBX_ETA;
    ensures hi: \abs(\result.hi - itmax(ml, mh, l, h)) <= CBX_U * itmag(ml, mh, l, h) + CBX_ETA;
    ensures mlo: \result.mag >= itmag(ml, mh, l, h) - CBX_U * itmag(ml, mh, l, h) - CBX_ETA;
    ensures mhi: \result.mag <= itmag(ml, mh, l, h) + CBX_U * itmag(ml, mh, l, h) + CBX_ETA;
    ensures mag: 0 <= itmag(ml, mh, l, h) <= CBX_RT;
    ensures rng: 0 <= \result.mag <= CBX_R19 + CBX_RW;
*/
static inline cbx_terms cbx_icolumn(cbx_fp ml, cbx_fp mh, cbx_fp l, cbx_fp h)
{
    cbx_terms a = cbx_column(ml, l, h);
    cbx_terms b = cbx_column(mh, l, h);
    cbx_terms r;
    r.lo = cbx_min2(a.lo, b.lo);
    r.hi = cbx_max2(b.hi, a.hi);
    r.mag = cbx_max2(b.mag, a.mag);
    return r;
}

/* t + d0 + d1 + d2, left to right, rounded to nearest (t = tl for the
 * lower end, th for the upper), each d_j within u itmag_j + eta of the
 * exact term of that end: within 4 u (1 + 2^-20) S + 10 eta of the exact
 * end (S = irow_mag). */
/*@ requires fin: \is_finite(tl) && \is_finite(th)
                  && \is_finite(d0) && \is_finite(d1) && \is_finite(d2);
    requires rt: -CBX_RT <= tl <= th <= CBX_RT;
    requires M: 0 <= itmag(ml0, mh0, l0, h0) <= CBX_RT && 0 <= itmag(ml1, mh1, l1, h1) <= CBX_RT
                && 0 <= itmag(ml2, mh2, l2, h2) <= CBX_RT;
    requires d0: \abs(d0 - itsel(up, ml0, mh0, l0, h0)) <= CBX_U * itmag(ml0, mh0, l0, h0) + CBX_ETA;
    requires d1: \abs(d1 - itsel(up, ml1, mh1, l1, h1)) <= CBX_U * itmag(ml1, mh1, l1, h1) + CBX_ETA;
    requires d2: \abs(d2 - itsel(up, ml2, mh2, l2, h2)) <= CBX_U * itmag(ml2, mh2, l2, h2) + CBX_ETA;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \let S = irow_mag(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2);
                 \let E = irow_sel(up, ml0, mh0, ml1, mh1, ml2, mh2, (up != 0 ? th : tl),
                                   l0, h0, l1, h1, l2, h2);
                 -(CBX_U4P * S + 10*CBX_ETA) <= \result - E <= CBX_U4P * S + 10*CBX_ETA;
*/
static inline cbx_fp cbx_isum3(int up, cbx_fp tl, cbx_fp th,
                               cbx_fp ml0, cbx_fp mh0, cbx_fp ml1, cbx_fp mh1, cbx_fp ml2, cbx_fp mh2,
                               cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                               cbx_fp d0, cbx_fp d1, cbx_fp d2)
{
    (void)ml0; (void)mh0; (void)ml1; (void)mh1; (void)ml2; (void)mh2;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    cbx_fp t = (up != 0) ? th : tl;
    /*@ assert T: \abs(t) <= \max(\abs(tl), \abs(th)) && -CBX_RT <= t <= CBX_RT; */
    /*@ assert X: -(itmag(ml0, mh0, l0, h0)) <= itsel(up, ml0, mh0, l0, h0) <= itmag(ml0, mh0, l0, h0)
                  && -(itmag(ml1, mh1, l1, h1)) <= itsel(up, ml1, mh1, l1, h1) <= itmag(ml1, mh1, l1, h1)
                  && -(itmag(ml2, mh2, l2, h2)) <= itsel(up, ml2, mh2, l2, h2) <= itmag(ml2, mh2, l2, h2); */
    cbx_fp s1 = cbx_add_rn(t, d0);
    /*@ assert e1: \let G0 = itmag(ml0, mh0, l0, h0); \let X0 = itsel(up, ml0, mh0, l0, h0);
          -(CBX_UP*(\abs(t) + 2*G0) + 3*CBX_ETA) <= s1 - (t + X0) <= CBX_UP*(\abs(t) + 2*G0) + 3*CBX_ETA; */
    cbx_fp s2 = cbx_add_rn(s1, d1);
    /*@ assert e2: \let G0 = itmag(ml0, mh0, l0, h0); \let X0 = itsel(up, ml0, mh0, l0, h0);
                   \let G1 = itmag(ml1, mh1, l1, h1); \let X1 = itsel(up, ml1, mh1, l1, h1);
          -(CBX_UP*(2*\abs(t) + 3*G0 + 2*G1) + 6*CBX_ETA) <= s2 - (t + X0 + X1)
          <= CBX_UP*(2*\abs(t) + 3*G0 + 2*G1) + 6*CBX_ETA; */
    cbx_fp s3 = cbx_add_rn(s2, d2);
    /*@ assert e3: \let G0 = itmag(ml0, mh0, l0, h0); \let X0 = itsel(up, ml0, mh0, l0, h0);
                   \let G1 = itmag(ml1, mh1, l1, h1); \let X1 = itsel(up, ml1, mh1, l1, h1);
                   \let G2 = itmag(ml2, mh2, l2, h2); \let X2 = itsel(up, ml2, mh2, l2, h2);
          -(CBX_UP*(3*\abs(t) + 4*G0 + 3*G1 + 2*G2) + 9*CBX_ETA) <= s3 - (t + X0 + X1 + X2)
          <= CBX_UP*(3*\abs(t) + 4*G0 + 3*G1 + 2*G2) + 9*CBX_ETA; */
    return s3;
}

/* One output coordinate in the fast range: finite ends below (above) the
 * exact ends and within 12 u S + 2^-1065 of them. */
/*@ requires fast: iv_fast(ml0, mh0, CBX_SB) && iv_fast(ml1, mh1, CBX_SB) && iv_fast(ml2, mh2, CBX_SB)
                   && iv_fast(tl, th, CBX_RT)
                   && iv_fast(l0, h0, CBX_SB) && iv_fast(l1, h1, CBX_SB) && iv_fast(l2, h2, CBX_SB);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures sound: \result.lo <= irow_lo(ml0, mh0, ml1, mh1, ml2, mh2, tl, l0, h0, l1, h1, l2, h2)
                   && \result.hi >= irow_hi(ml0, mh0, ml1, mh1, ml2, mh2, th, l0, h0, l1, h1, l2, h2);
    ensures tight: irow_tight(\result.lo, \result.hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th,
                              l0, h0, l1, h1, l2, h2);
*/
static inline cbx_ends cbx_irow(cbx_fp ml0, cbx_fp mh0, cbx_fp ml1, cbx_fp mh1, cbx_fp ml2, cbx_fp mh2,
                                cbx_fp tl, cbx_fp th,
                                cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    cbx_ends r;
    cbx_fast_row(ml0, ml1, ml2, tl, l0, h0, l1, h1, l2, h2);
    cbx_fast_row(mh0, mh1, mh2, th, l0, h0, l1, h1, l2, h2);
    cbx_terms c0 = cbx_icolumn(ml0, mh0, l0, h0);
    cbx_terms c1 = cbx_icolumn(ml1, mh1, l1, h1);
    cbx_terms c2 = cbx_icolumn(ml2, mh2, l2, h2);
    cbx_fp slo = cbx_isum3(0, tl, th, ml0, mh0, ml1, mh1, ml2, mh2, l0, h0, l1, h1, l2, h2,
                           c0.lo, c1.lo, c2.lo);
    cbx_fp shi = cbx_isum3(1, tl, th, ml0, mh0, ml1, mh1, ml2, mh2, l0, h0, l1, h1, l2, h2,
                           c0.hi, c1.hi, c2.hi);
    cbx_fp tm = cbx_max2(cbx_abs(tl), cbx_abs(th));
    /*@ assert tm: tm == \max(\abs(tl), \abs(th)) && 0 <= tm <= CBX_RT; */
    cbx_fp w = cbx_widening(tm, c0.mag, c1.mag, c2.mag);
    /*@ assert w1: w >= CBX_U5H * irow_mag(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2)
                        * (1 - CBX_U16) + CBX_ETA64 - CBX_ETA8; */
    /*@ assert w2: w <= CBX_U5H * irow_mag(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2)
                        * (1 + CBX_U16) + CBX_ETA256 + CBX_ETA8; */
    /*@ assert S: irow_mag(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2) <= 4*CBX_RT; */
    r.lo = cbx_sub_rn(slo, w);
    r.hi = cbx_add_rn(shi, w);
    return r;
}

#endif /* CBX_IKERNEL_H */
