/*
 * Arvo's interval form (Graphics Gems I, "Transforming Axis-Aligned
 * Bounding Boxes", Fig. 1), outward rounded.
 *
 * Per output axis: start at the translation t and add, for each input axis
 * j, the smaller (for lo) or larger (for hi) of m_j*l_j and m_j*h_j, all in
 * round-to-nearest.  Then widen once by w = 5.5 u R + 2^-1067, where
 * R = |t| + sum_j max(|m_j l_j|, |m_j h_j|) (computed).  The rounding error
 * of the whole sum is at most about 5 u S (4 u S in the sum, u S in the final
 * widening step), so one widening per bound pays for every rounding; the
 * proof (asserts below) keeps track of it step by step.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_vertex.h"

/* The smaller of m*l and m*h: error u*tmag + eta (one rounding each). */
/*@ requires fin: \is_finite(m) && \is_finite(l) && \is_finite(h);
    requires dom: in_dom(m, l) && in_dom(m, h);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - tmin(m, l, h)) <= CBX_U * tmag(m, l, h) + CBX_ETA;
*/
static inline cbx_fp term_lo(cbx_fp m, cbx_fp l, cbx_fp h)
{
    cbx_fp p = cbx_mul_rn(m, l);
    cbx_fp q = cbx_mul_rn(m, h);
    return cbx_min2(p, q);
}

/* The larger of m*l and m*h. */
/*@ requires fin: \is_finite(m) && \is_finite(l) && \is_finite(h);
    requires dom: in_dom(m, l) && in_dom(m, h);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - tmax(m, l, h)) <= CBX_U * tmag(m, l, h) + CBX_ETA;
*/
static inline cbx_fp term_hi(cbx_fp m, cbx_fp l, cbx_fp h)
{
    cbx_fp p = cbx_mul_rn(m, l);
    cbx_fp q = cbx_mul_rn(m, h);
    return cbx_max2(p, q);
}

/* max(|m*l|, |m*h|), within a relative u of the exact value. */
/*@ requires fin: \is_finite(m) && \is_finite(l) && \is_finite(h);
    requires dom: in_dom(m, l) && in_dom(m, h);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures lo: \result >= tmag(m, l, h) - CBX_U * tmag(m, l, h) - CBX_ETA;
    ensures hi: \result <= tmag(m, l, h) + CBX_U * tmag(m, l, h) + CBX_ETA;
    ensures pos: \result >= 0;
*/
static inline cbx_fp term_mag(cbx_fp m, cbx_fp l, cbx_fp h)
{
    cbx_fp p = cbx_mul_rn(m, l);
    cbx_fp q = cbx_mul_rn(m, h);
    return cbx_max2(cbx_abs(p), cbx_abs(q));
}

/* Lower bound of one output axis. */
/*@ requires fin: \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t);
    requires finb: \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                   && \is_finite(l2) && \is_finite(h2);
    requires dom: in_dom(m0, l0) && in_dom(m0, h0) && in_dom(m1, l1) && in_dom(m1, h1)
                  && in_dom(m2, l2) && in_dom(m2, h2);
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures sound: \result <= row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight: lo_tight(\result, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static cbx_fp axis_lo(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                      cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    cbx_fp d0 = term_lo(m0, l0, h0);
    cbx_fp d1 = term_lo(m1, l1, h1);
    cbx_fp d2 = term_lo(m2, l2, h2);
    cbx_fp g0 = term_mag(m0, l0, h0);
    cbx_fp g1 = term_mag(m1, l1, h1);
    cbx_fp g2 = term_mag(m2, l2, h2);
    /*@ assert M: 0 <= tmag(m0, l0, h0) <= CBX_RT && 0 <= tmag(m1, l1, h1) <= CBX_RT
                  && 0 <= tmag(m2, l2, h2) <= CBX_RT; */
    /*@ assert X0: -(tmag(m0, l0, h0)) <= tmin(m0, l0, h0) <= tmag(m0, l0, h0); */
    /*@ assert d0e: -(CBX_U*tmag(m0, l0, h0) + CBX_ETA) <= d0 - tmin(m0, l0, h0) <= CBX_U*tmag(m0, l0, h0) + CBX_ETA; */
    /*@ assert X1: -(tmag(m1, l1, h1)) <= tmin(m1, l1, h1) <= tmag(m1, l1, h1); */
    /*@ assert d1e: -(CBX_U*tmag(m1, l1, h1) + CBX_ETA) <= d1 - tmin(m1, l1, h1) <= CBX_U*tmag(m1, l1, h1) + CBX_ETA; */
    /*@ assert X2: -(tmag(m2, l2, h2)) <= tmin(m2, l2, h2) <= tmag(m2, l2, h2); */
    /*@ assert d2e: -(CBX_U*tmag(m2, l2, h2) + CBX_ETA) <= d2 - tmin(m2, l2, h2) <= CBX_U*tmag(m2, l2, h2) + CBX_ETA; */
    cbx_fp s1 = cbx_add_rn(t, d0);
    /*@ assert a1: -(\abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA) <= t + d0 <= \abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA; */
    /*@ assert r1: -(CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA) + CBX_ETA) <= s1 - (t + d0) <= CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA) + CBX_ETA; */
    /*@ assert e1: -(CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA) <= s1 - (t + tmin(m0, l0, h0)) <= CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA; */
    cbx_fp s2 = cbx_add_rn(s1, d1);
    /*@ assert a2: -(\abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA) <= s1 + d1 <= \abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA; */
    /*@ assert r2: -(CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA) + CBX_ETA) <= s2 - (s1 + d1) <= CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA) + CBX_ETA; */
    /*@ assert e2: -(CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA) <= s2 - (t + tmin(m0, l0, h0) + tmin(m1, l1, h1)) <= CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA; */
    cbx_fp s3 = cbx_add_rn(s2, d2);
    /*@ assert a3: -(\abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA) <= s2 + d2 <= \abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA; */
    /*@ assert r3: -(CBX_U*(\abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA) + CBX_ETA) <= s3 - (s2 + d2) <= CBX_U*(\abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA) + CBX_ETA; */
    /*@ assert e3: -(CBX_UP*(3*\abs(t) + 4*tmag(m0, l0, h0) + 3*tmag(m1, l1, h1) + 2*tmag(m2, l2, h2)) + 9*CBX_ETA) <= s3 - (t + tmin(m0, l0, h0) + tmin(m1, l1, h1) + tmin(m2, l2, h2)) <= CBX_UP*(3*\abs(t) + 4*tmag(m0, l0, h0) + 3*tmag(m1, l1, h1) + 2*tmag(m2, l2, h2)) + 9*CBX_ETA; */
    /*@ assert e3s: -(CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA) <= s3 - row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) <= CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA; */
    cbx_fp w = cbx_widening(t, g0, g1, g2);
    /*@ assert w1: w >= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 - CBX_U16)
                        + CBX_ETA64 - CBX_ETA8; */
    /*@ assert w2: w <= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 + CBX_U16)
                        + CBX_ETA256 + CBX_ETA8; */
    return cbx_sub_rn(s3, w);
}

/* Upper bound of one output axis (mirror of axis_lo). */
/*@ requires fin: \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t);
    requires finb: \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                   && \is_finite(l2) && \is_finite(h2);
    requires dom: in_dom(m0, l0) && in_dom(m0, h0) && in_dom(m1, l1) && in_dom(m1, h1)
                  && in_dom(m2, l2) && in_dom(m2, h2);
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures sound: \result >= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight: hi_tight(\result, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static cbx_fp axis_hi(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                      cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    cbx_fp d0 = term_hi(m0, l0, h0);
    cbx_fp d1 = term_hi(m1, l1, h1);
    cbx_fp d2 = term_hi(m2, l2, h2);
    cbx_fp g0 = term_mag(m0, l0, h0);
    cbx_fp g1 = term_mag(m1, l1, h1);
    cbx_fp g2 = term_mag(m2, l2, h2);
    /*@ assert M: 0 <= tmag(m0, l0, h0) <= CBX_RT && 0 <= tmag(m1, l1, h1) <= CBX_RT
                  && 0 <= tmag(m2, l2, h2) <= CBX_RT; */
    /*@ assert X0: -(tmag(m0, l0, h0)) <= tmax(m0, l0, h0) <= tmag(m0, l0, h0); */
    /*@ assert d0e: -(CBX_U*tmag(m0, l0, h0) + CBX_ETA) <= d0 - tmax(m0, l0, h0) <= CBX_U*tmag(m0, l0, h0) + CBX_ETA; */
    /*@ assert X1: -(tmag(m1, l1, h1)) <= tmax(m1, l1, h1) <= tmag(m1, l1, h1); */
    /*@ assert d1e: -(CBX_U*tmag(m1, l1, h1) + CBX_ETA) <= d1 - tmax(m1, l1, h1) <= CBX_U*tmag(m1, l1, h1) + CBX_ETA; */
    /*@ assert X2: -(tmag(m2, l2, h2)) <= tmax(m2, l2, h2) <= tmag(m2, l2, h2); */
    /*@ assert d2e: -(CBX_U*tmag(m2, l2, h2) + CBX_ETA) <= d2 - tmax(m2, l2, h2) <= CBX_U*tmag(m2, l2, h2) + CBX_ETA; */
    cbx_fp s1 = cbx_add_rn(t, d0);
    /*@ assert a1: -(\abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA) <= t + d0 <= \abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA; */
    /*@ assert r1: -(CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA) + CBX_ETA) <= s1 - (t + d0) <= CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_U*tmag(m0, l0, h0) + CBX_ETA) + CBX_ETA; */
    /*@ assert e1: -(CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA) <= s1 - (t + tmax(m0, l0, h0)) <= CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA; */
    cbx_fp s2 = cbx_add_rn(s1, d1);
    /*@ assert a2: -(\abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA) <= s1 + d1 <= \abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA; */
    /*@ assert r2: -(CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA) + CBX_ETA) <= s2 - (s1 + d1) <= CBX_U*(\abs(t) + tmag(m0, l0, h0) + CBX_UP*(1*\abs(t) + 2*tmag(m0, l0, h0)) + 3*CBX_ETA + tmag(m1, l1, h1) + CBX_U*tmag(m1, l1, h1) + CBX_ETA) + CBX_ETA; */
    /*@ assert e2: -(CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA) <= s2 - (t + tmax(m0, l0, h0) + tmax(m1, l1, h1)) <= CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA; */
    cbx_fp s3 = cbx_add_rn(s2, d2);
    /*@ assert a3: -(\abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA) <= s2 + d2 <= \abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA; */
    /*@ assert r3: -(CBX_U*(\abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA) + CBX_ETA) <= s3 - (s2 + d2) <= CBX_U*(\abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + CBX_UP*(2*\abs(t) + 3*tmag(m0, l0, h0) + 2*tmag(m1, l1, h1)) + 6*CBX_ETA + tmag(m2, l2, h2) + CBX_U*tmag(m2, l2, h2) + CBX_ETA) + CBX_ETA; */
    /*@ assert e3: -(CBX_UP*(3*\abs(t) + 4*tmag(m0, l0, h0) + 3*tmag(m1, l1, h1) + 2*tmag(m2, l2, h2)) + 9*CBX_ETA) <= s3 - (t + tmax(m0, l0, h0) + tmax(m1, l1, h1) + tmax(m2, l2, h2)) <= CBX_UP*(3*\abs(t) + 4*tmag(m0, l0, h0) + 3*tmag(m1, l1, h1) + 2*tmag(m2, l2, h2)) + 9*CBX_ETA; */
    /*@ assert e3s: -(CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA) <= s3 - row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) <= CBX_U4P * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 10*CBX_ETA; */
    cbx_fp w = cbx_widening(t, g0, g1, g2);
    /*@ assert w1: w >= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 - CBX_U16)
                        + CBX_ETA64 - CBX_ETA8; */
    /*@ assert w2: w <= CBX_U5H * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) * (1 + CBX_U16)
                        + CBX_ETA256 + CBX_ETA8; */
    return cbx_add_rn(s3, w);
}

/*@ requires \valid(out);
    assigns *out;
    ensures whole_space(out);
*/
static void set_whole(cbx_box *out)
{
    out->lo[0] = cbx_ninf(); out->hi[0] = cbx_pinf();
    out->lo[1] = cbx_ninf(); out->hi[1] = cbx_pinf();
    out->lo[2] = cbx_ninf(); out->hi[2] = cbx_pinf();
}

/*@ requires \valid(out);
    assigns *out;
    ensures empty_out(out);
*/
static void set_empty(cbx_box *out)
{
    out->lo[0] = cbx_pinf(); out->hi[0] = cbx_ninf();
    out->lo[1] = cbx_pinf(); out->hi[1] = cbx_ninf();
    out->lo[2] = cbx_pinf(); out->hi[2] = cbx_ninf();
}

/* ---- half-spaces and out-of-domain boxes: one end at a time -----------
 * Where the row is not full (some box end infinite, or a pair outside the
 * domain) but the map row is finite, each end of the axis is computed on
 * its own: the lower end of t + m.x over the box is reached at the vertex
 * v_j = l_j (m_j > 0), h_j (m_j < 0), 0 (m_j == 0, whatever l_j, h_j are:
 * 0 * inf = 0).  If a needed end is infinite the image is unbounded there
 * and the end is -inf, exactly; otherwise the proven kernel runs on the
 * point box v and the per-column facts of vertex_lo / vertex_hi carry its
 * bound from the vertex to every real point of the box (ext_below). */
/* The kernels on the point box v (every l_j == h_j == v_j). */
/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires dom: row_in_dom(m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures sound: \result <= m0*v0 + m1*v1 + m2*v2 + t;
    ensures tight: lo_tight(\result, m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
*/
static cbx_fp point_lo(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t, cbx_fp v0, cbx_fp v1, cbx_fp v2)
{
    return axis_lo(m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
}

/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires dom: row_in_dom(m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures sound: \result >= m0*v0 + m1*v1 + m2*v2 + t;
    ensures tight: hi_tight(\result, m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
*/
static cbx_fp point_hi(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t, cbx_fp v0, cbx_fp v1, cbx_fp v2)
{
    return axis_hi(m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
}

/* Lower end of one output axis from its vertex; ok == 0: lost to the domain. */
/*@ requires fin: map_fin(m0, m1, m2, t);
    requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    assigns \nothing;
    ensures end: ext_lo_end(\result.v, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures ok: \result.ok != 0 <==> (row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
                                      || vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2));
*/
static end_result ext_lo(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    end_result r;
    end_result v0 = vertex_lo(m0, l0, h0);
    end_result v1 = vertex_lo(m1, l1, h1);
    end_result v2 = vertex_lo(m2, l2, h2);
    if (!v0.ok || !v1.ok || !v2.ok) {
        r.v = cbx_ninf();
        r.ok = 1;
        return r;
    }
    if (!cbx_row_ok(m0, m1, m2, t, v0.v, v0.v, v1.v, v1.v, v2.v, v2.v)) {
        r.v = cbx_ninf();
        r.ok = 0;
        return r;
    }
    r.v = point_lo(m0, m1, m2, t, v0.v, v1.v, v2.v);
    r.ok = 1;
    return r;
}

/* Upper end of one output axis from its vertex (mirror of ext_lo). */
/*@ requires fin: map_fin(m0, m1, m2, t);
    requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    assigns \nothing;
    ensures end: ext_hi_end(\result.v, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures ok: \result.ok != 0 <==> (row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
                                      || vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2));
*/
static end_result ext_hi(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    end_result r;
    end_result v0 = vertex_hi(m0, l0, h0);
    end_result v1 = vertex_hi(m1, l1, h1);
    end_result v2 = vertex_hi(m2, l2, h2);
    if (!v0.ok || !v1.ok || !v2.ok) {
        r.v = cbx_pinf();
        r.ok = 1;
        return r;
    }
    if (!cbx_row_ok(m0, m1, m2, t, v0.v, v0.v, v1.v, v1.v, v2.v, v2.v)) {
        r.v = cbx_pinf();
        r.ok = 0;
        return r;
    }
    r.v = point_hi(m0, m1, m2, t, v0.v, v1.v, v2.v);
    r.ok = 1;
    return r;
}

/* One output axis: the proven kernel on a full row, each end from its
 * vertex on a finite map row, the whole line [-inf, +inf] otherwise. */
typedef struct axis_result { cbx_fp lo, hi; int ok; } axis_result;

/*@ requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    assigns \nothing;
    ensures ok: \result.ok != 0 <==> axis_ok_s(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures sound: axis_sound_s(\result.lo, \result.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static axis_result transform_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                                  cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1,
                                  cbx_fp l2, cbx_fp h2)
{
    axis_result r;
    if (cbx_row_ok(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) {
        r.lo = axis_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
        r.hi = axis_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
        r.ok = 1;
    } else if (cbx_is_fin(m0) && cbx_is_fin(m1) && cbx_is_fin(m2) && cbx_is_fin(t)) {
        end_result lo = ext_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
        end_result hi = ext_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
        r.lo = lo.v;
        r.hi = hi.v;
        r.ok = lo.ok && hi.ok;
    } else {
        r.lo = cbx_ninf();
        r.hi = cbx_pinf();
        r.ok = 0;
    }
    return r;
}

/* 1 if some input is NaN (specs: has_nan). */
/*@ requires \valid_read(a) && \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> has_nan(a, in);
*/
static int any_nan(const cbx_affine *a, const cbx_box *in)
{
    if (cbx_is_nan(a->m[0][0]) || cbx_is_nan(a->m[0][1]) || cbx_is_nan(a->m[0][2]) || cbx_is_nan(a->m[0][3]))
        return 1;
    if (cbx_is_nan(a->m[1][0]) || cbx_is_nan(a->m[1][1]) || cbx_is_nan(a->m[1][2]) || cbx_is_nan(a->m[1][3]))
        return 1;
    if (cbx_is_nan(a->m[2][0]) || cbx_is_nan(a->m[2][1]) || cbx_is_nan(a->m[2][2]) || cbx_is_nan(a->m[2][3]))
        return 1;
    if (cbx_is_nan(in->lo[0]) || cbx_is_nan(in->lo[1]) || cbx_is_nan(in->lo[2]))
        return 1;
    if (cbx_is_nan(in->hi[0]) || cbx_is_nan(in->hi[1]) || cbx_is_nan(in->hi[2]))
        return 1;
    return 0;
}

/* 1 if some axis has no real point (specs: is_empty). */
/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> is_empty(in);
*/
static int any_inverted(const cbx_box *in)
{
    return cbx_no_point(in->lo[0], in->hi[0]) || cbx_no_point(in->lo[1], in->hi[1])
           || cbx_no_point(in->lo[2], in->hi[2]);
}

cbx_status cbx_transform_box(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    if (any_nan(a, in)) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (any_inverted(in)) {
        set_empty(out);
        return CBX_EMPTY;
    }
    cbx_fp l0 = in->lo[0], l1 = in->lo[1], l2 = in->lo[2];
    cbx_fp h0 = in->hi[0], h1 = in->hi[1], h2 = in->hi[2];
    cbx_fp a00 = a->m[0][0], a01 = a->m[0][1], a02 = a->m[0][2], a03 = a->m[0][3];
    cbx_fp a10 = a->m[1][0], a11 = a->m[1][1], a12 = a->m[1][2], a13 = a->m[1][3];
    cbx_fp a20 = a->m[2][0], a21 = a->m[2][1], a22 = a->m[2][2], a23 = a->m[2][3];
    axis_result r0 = transform_axis(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    axis_result r1 = transform_axis(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    axis_result r2 = transform_axis(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    out->lo[0] = r0.lo; out->hi[0] = r0.hi;
    out->lo[1] = r1.lo; out->hi[1] = r1.hi;
    out->lo[2] = r2.lo; out->hi[2] = r2.hi;
    /* the values used are the inputs of the pre-state (out may be in) */
    /*@ assert same_in: \at(a->m[0][0], Pre) == a00 && \at(a->m[0][1], Pre) == a01 && \at(a->m[0][2], Pre) == a02
          && \at(a->m[0][3], Pre) == a03 && \at(a->m[1][0], Pre) == a10 && \at(a->m[1][1], Pre) == a11
          && \at(a->m[1][2], Pre) == a12 && \at(a->m[1][3], Pre) == a13 && \at(a->m[2][0], Pre) == a20
          && \at(a->m[2][1], Pre) == a21 && \at(a->m[2][2], Pre) == a22 && \at(a->m[2][3], Pre) == a23
          && \at(in->lo[0], Pre) == l0 && \at(in->lo[1], Pre) == l1 && \at(in->lo[2], Pre) == l2
          && \at(in->hi[0], Pre) == h0 && \at(in->hi[1], Pre) == h1 && \at(in->hi[2], Pre) == h2; */
    /*@ assert same_out: out->lo[0] == r0.lo && out->hi[0] == r0.hi
          && out->lo[1] == r1.lo && out->hi[1] == r1.hi
          && out->lo[2] == r2.lo && out->hi[2] == r2.hi; */
    /*@ assert as0: axis_sound_s(out->lo[0], out->hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2); */
    /*@ assert as1: axis_sound_s(out->lo[1], out->hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2); */
    /*@ assert as2: axis_sound_s(out->lo[2], out->hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2); */
    return (r0.ok && r1.ok && r2.ok) ? CBX_OK : CBX_ERANGE;
}
