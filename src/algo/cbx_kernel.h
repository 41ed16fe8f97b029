/*
 * The proven kernel of Arvo's interval form (Graphics Gems I, Fig. 1),
 * outward rounded, one output axis at a time, written once for both
 * formats.  Branch-free: every step is a product, a sum, a min or a max
 * (one instruction each), and each product m*l, m*h is computed once.
 *
 * Per output axis: the two ends start at the translation t and add, for each
 * input axis j, the smaller (lower end) or larger (upper end) of m_j l_j and
 * m_j h_j, left to right, in round-to-nearest.  Each end is then widened
 * once by w = 5.5 u R + eta_128, where R = |t| + sum_j max(|m_j l_j|, |m_j h_j|)
 * (computed).  The rounding error of the sum is at most 4 u S (+ the
 * absolute terms), the final widening step adds u S, so one widening per
 * end pays for every rounding.  The error chain of the sum is one function
 * (cbx_sum3) for both ends: `up` picks the end, tsel the exact term.
 */
#ifndef CBX_KERNEL_H
#define CBX_KERNEL_H

#include "certbox.h"
#include "cbx_prec.h"
#include "cbx_round.h"

/* One column of the sum: the smaller and larger of the two products, and
 * the larger magnitude. */
typedef struct cbx_terms { cbx_fp lo; cbx_fp hi; cbx_fp mag; } cbx_terms;

/* Both ends of one output axis. */
typedef struct cbx_ends { cbx_fp lo; cbx_fp hi; } cbx_ends;

/* m*l and m*h, each rounded once; lo and hi within u tmag + eta of the
 * exact smaller and larger product, mag within a relative u of tmag. */
/*@ requires fin: \is_finite(m) && \is_finite(l) && \is_finite(h);
    requires dom: in_dom(m, l) && in_dom(m, h);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi) && \is_finite(\result.mag);
    ensures lo: \abs(\result.lo - tmin(m, l, h)) <= CBX_U * tmag(m, l, h) + CBX_ETA;
    ensures hi: \abs(\result.hi - tmax(m, l, h)) <= CBX_U * tmag(m, l, h) + CBX_ETA;
    ensures mlo: \result.mag >= tmag(m, l, h) - CBX_U * tmag(m, l, h) - CBX_ETA;
    ensures mhi: \result.mag <= tmag(m, l, h) + CBX_U * tmag(m, l, h) + CBX_ETA;
    ensures pos: \result.mag >= 0;
*/
static inline cbx_terms cbx_column(cbx_fp m, cbx_fp l, cbx_fp h)
{
    cbx_terms r;
    cbx_fp p = cbx_mul_rn(m, l);
    cbx_fp q = cbx_mul_rn(m, h);
    r.lo = cbx_min2(p, q);
    r.hi = cbx_max2(q, p); /* (q, p): not p < q twice, which gcc turns into one branch */
    r.mag = cbx_max2(r.hi, cbx_neg(r.lo));
    /*@ assert mag: r.mag == \max(\abs(p), \abs(q)); */
    return r;
}

/* t + d0 + d1 + d2, left to right, rounded to nearest, where each d_j is
 * within u tmag_j + eta of the exact term of the end (tsel): within
 * 4 u (1 + 2^-20) S + 10 eta of the exact end (S = row_mag). */
/*@ requires fin: \is_finite(t) && \is_finite(d0) && \is_finite(d1) && \is_finite(d2);
    requires dom: in_dom(m0, l0) && in_dom(m0, h0) && in_dom(m1, l1) && in_dom(m1, h1)
                  && in_dom(m2, l2) && in_dom(m2, h2);
    requires rt: -CBX_RT <= t <= CBX_RT;
    requires d0: \abs(d0 - tsel(up, m0, l0, h0)) <= CBX_U * tmag(m0, l0, h0) + CBX_ETA;
    requires d1: \abs(d1 - tsel(up, m1, l1, h1)) <= CBX_U * tmag(m1, l1, h1) + CBX_ETA;
    requires d2: \abs(d2 - tsel(up, m2, l2, h2)) <= CBX_U * tmag(m2, l2, h2) + CBX_ETA;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: -(CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA)
                 <= \result - row_sel(up, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                 <= CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA;
*/
static inline cbx_fp cbx_sum3(int up, cbx_fp t, cbx_fp m0, cbx_fp m1, cbx_fp m2,
                              cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                              cbx_fp d0, cbx_fp d1, cbx_fp d2)
{
    (void)up; (void)m0; (void)m1; (void)m2; (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    /*@ assert M: 0 <= tmag(m0, l0, h0) <= CBX_RT && 0 <= tmag(m1, l1, h1) <= CBX_RT
                  && 0 <= tmag(m2, l2, h2) <= CBX_RT; */
    /*@ assert X: -(tmag(m0, l0, h0)) <= tsel(up, m0, l0, h0) <= tmag(m0, l0, h0)
                  && -(tmag(m1, l1, h1)) <= tsel(up, m1, l1, h1) <= tmag(m1, l1, h1)
                  && -(tmag(m2, l2, h2)) <= tsel(up, m2, l2, h2) <= tmag(m2, l2, h2); */
    cbx_fp s1 = cbx_add_rn(t, d0);
    /*@ assert e1: \let G0 = tmag(m0, l0, h0); \let X0 = tsel(up, m0, l0, h0);
          -(CBX_UP*(\abs(t) + 2*G0) + 3*CBX_ETA) <= s1 - (t + X0) <= CBX_UP*(\abs(t) + 2*G0) + 3*CBX_ETA; */
    cbx_fp s2 = cbx_add_rn(s1, d1);
    /*@ assert e2: \let G0 = tmag(m0, l0, h0); \let X0 = tsel(up, m0, l0, h0);
                   \let G1 = tmag(m1, l1, h1); \let X1 = tsel(up, m1, l1, h1);
          -(CBX_UP*(2*\abs(t) + 3*G0 + 2*G1) + 6*CBX_ETA) <= s2 - (t + X0 + X1)
          <= CBX_UP*(2*\abs(t) + 3*G0 + 2*G1) + 6*CBX_ETA; */
    cbx_fp s3 = cbx_add_rn(s2, d2);
    /*@ assert e3: \let G0 = tmag(m0, l0, h0); \let X0 = tsel(up, m0, l0, h0);
                   \let G1 = tmag(m1, l1, h1); \let X1 = tsel(up, m1, l1, h1);
                   \let G2 = tmag(m2, l2, h2); \let X2 = tsel(up, m2, l2, h2);
          -(CBX_UP*(3*\abs(t) + 4*G0 + 3*G1 + 2*G2) + 9*CBX_ETA) <= s3 - (t + X0 + X1 + X2)
          <= CBX_UP*(3*\abs(t) + 4*G0 + 3*G1 + 2*G2) + 9*CBX_ETA; */
    return s3;
}

/* One end: s (the rounded sum, within 4 u (1 + 2^-20) S + 10 eta of the
 * exact end) moved outward by the widening w (about 5.5 u S): down for
 * the lower end (up == 0), up for the upper end; beyond the exact end and
 * within 12 u S + eta_512 of it.  Written once for both ends (cbx_axis
 * calls it with a constant up, so the compiled kernel has no branch). */
/*@ requires fin: \is_finite(s) && \is_finite(w);
    requires rs: -row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) <= row_sel(up, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                 <= row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) <= 4*CBX_RT;
    requires se: -(CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA)
                 <= s - row_sel(up, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                 <= CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA;
    requires w1: w >= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 - CBX_U16)
                      + CBX_ETA64 - CBX_ETA8;
    requires w2: w <= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 + CBX_U16)
                      + CBX_ETA256 + CBX_ETA8;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures sound_lo: up == 0 ==> \result <= row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures sound_hi: up != 0 ==> \result >= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight_lo: up == 0 ==> lo_tight(\result, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight_hi: up != 0 ==> hi_tight(\result, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static inline cbx_fp cbx_end(int up, cbx_fp s, cbx_fp w, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                             cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    (void)m0; (void)m1; (void)m2; (void)t; (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    return (up != 0) ? cbx_add_rn(s, w) : cbx_sub_rn(s, w);
}

/* Both ends of one output axis: below (above) the exact end, and within
 * 12 u S + eta_512 of it (lo_tight, hi_tight). */
/*@ requires fin: \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t);
    requires finb: \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                   && \is_finite(l2) && \is_finite(h2);
    requires dom: in_dom(m0, l0) && in_dom(m0, h0) && in_dom(m1, l1) && in_dom(m1, h1)
                  && in_dom(m2, l2) && in_dom(m2, h2);
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures sound_lo: \result.lo <= row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures sound_hi: \result.hi >= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight_lo: lo_tight(\result.lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight_hi: hi_tight(\result.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static inline cbx_ends cbx_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                                cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    cbx_ends r;
    cbx_terms c0 = cbx_column(m0, l0, h0);
    cbx_terms c1 = cbx_column(m1, l1, h1);
    cbx_terms c2 = cbx_column(m2, l2, h2);
    cbx_fp slo = cbx_sum3(0, t, m0, m1, m2, l0, h0, l1, h1, l2, h2, c0.lo, c1.lo, c2.lo);
    cbx_fp shi = cbx_sum3(1, t, m0, m1, m2, l0, h0, l1, h1, l2, h2, c0.hi, c1.hi, c2.hi);
    /*@ assert M: 0 <= tmag(m0, l0, h0) <= CBX_RT && 0 <= tmag(m1, l1, h1) <= CBX_RT
                  && 0 <= tmag(m2, l2, h2) <= CBX_RT; */
    cbx_fp w = cbx_widening(t, c0.mag, c1.mag, c2.mag);
    /*@ assert w1: w >= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 - CBX_U16)
                        + CBX_ETA64 - CBX_ETA8; */
    /*@ assert w2: w <= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 + CBX_U16)
                        + CBX_ETA256 + CBX_ETA8; */
    r.lo = cbx_end(0, slo, w, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    r.hi = cbx_end(1, shi, w, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    return r;
}

#endif /* CBX_KERNEL_H */
