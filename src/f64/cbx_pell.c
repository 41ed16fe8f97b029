/*
 * An ellipsoid under a projective map (a camera's projection):
 * cbx_project_ellipsoid, binary64.
 *
 * The ellipsoid is {c + M q : |q| <= 1}, M_ij = rot[i][j] radii[j]; output
 * axis i is X_i / W.  In the ellipsoid's frame (specs/cbx_pell.h) it is the
 * unit ball under the rows a' = M^T a, A = X(c) and b' = M^T b, B = W(c),
 * so the projected ball's method (src/f64/cbx_psph.c) applies unchanged:
 * for a real t, X - t W ranges over e(t) -+ |M^T k(t)| on the ellipsoid,
 * e(t) its value at c and k(t) = a - t b; the exact upper end of X / W is
 * the root of e(t) + |M^T k(t)| = 0 (the dual quadric's tangent plane),
 * the lower end the root of e(t) - |M^T k(t)| = 0.
 *
 * M^T a is never rounded: the certificate encloses e(t) (as the ball's)
 * and each entry of M^T k(t) = s_j (r_0j k_0 + r_1j k_1 + r_2j k_2) in
 * outward-rounded interval arithmetic from the enclosures of k(t), then
 * the norm (pe_gap_at).  The candidate ends are the ball's closed form in
 * round-to-nearest on the rows in the frame, rounded (ps_coef, ps_roots:
 * unproven values, checked by the certificate).  The search is the
 * ball's: at t0 + d sound, at t0 - d tight, d from 2^-48 (1 + |t0|) by 4
 * up to 13 times, 2 d <= 2^-20 (1 + |end|).  So the contract states, in
 * exact reals, containment of every point of the ellipsoid and both ends
 * within 2^-20 (1 + |end|) of the exact ends.
 *
 * Statuses: NaN anywhere -> CBX_EINVAL; outside the domain (the ball's for
 * the map and the center; rot's entries and the radii at most 2^30) ->
 * CBX_ERANGE; the ellipsoid not clear of the camera plane W = 0 (its
 * enclosure of min W not positive) -> CBX_EBEHIND; an end beyond 2^100, or
 * one the search cannot certify -> CBX_ERANGE.  Every status but CBX_OK
 * gives the whole space.  Proven in job PE64 (proofs/pell.c), on the
 * enclosures of the projected ball (src/f64/cbx_paff.h, cbx_pgap.h).
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_iv.h"
#include "cbx_paff.h"
#include "cbx_pgap.h"

#define PE_TRIES 14
#define PE_S 0x1p30 /* rot's entries and the radii */

/* ---- the certificate: e(t) and |M^T k(t)| enclosed ----------------------- */
/* One entry of M^T k(t): s (m0 k0 + m1 k1 + m2 k2), (m0, m1, m2) a column
 * of rot and s its radius, from the enclosures of k's entries. */
/*@ requires fin: \is_finite(t) && \is_finite(a0) && \is_finite(a1) && \is_finite(a2)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2)
                  && \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(s)
                  && \is_finite(k0.lo) && \is_finite(k0.hi) && \is_finite(k1.lo) && \is_finite(k1.hi)
                  && \is_finite(k2.lo) && \is_finite(k2.hi);
    requires rng: iv_rng(k0.lo, k0.hi, 0x1p162) && iv_rng(k1.lo, k1.hi, 0x1p162)
                  && iv_rng(k2.lo, k2.hi, 0x1p162)
                  && -PE_S <= m0 <= PE_S && -PE_S <= m1 <= PE_S && -PE_S <= m2 <= PE_S && -PE_S <= s <= PE_S;
    requires in: iv_has(k0.lo, k0.hi, a0 - t*b0) && iv_has(k1.lo, k1.hi, a1 - t*b1)
                 && iv_has(k2.lo, k2.hi, a2 - t*b2);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p258);
    ensures in: iv_has(\result.lo, \result.hi, pe_x(m0, m1, m2, s, a0 - t*b0, a1 - t*b1, a2 - t*b2));
*/
static inline cbx_iv pe_col(double t, double a0, double a1, double a2, double b0, double b1, double b2,
                            double m0, double m1, double m2, double s, cbx_iv k0, cbx_iv k1, cbx_iv k2)
{
    cbx_iv q0 = ps_kc(t, a0, b0, k0, m0);
    cbx_iv q1 = ps_kc(t, a1, b1, k1, m1);
    cbx_iv q2 = ps_kc(t, a2, b2, k2, m2);
    cbx_iv d01 = ps_sum(q0, q1, 0x1p223);
    cbx_iv d = ps_sum(d01, q2, 0x1p225);
    cbx_iv v;
    /*@ assert i01: iv_has(d01.lo, d01.hi, (a0 - t*b0)*m0 + (a1 - t*b1)*m1); */
    /*@ assert i: iv_has(d.lo, d.hi, ((a0 - t*b0)*m0 + (a1 - t*b1)*m1) + (a2 - t*b2)*m2); */
    /*@ assert dr: iv_rng(d.lo, d.hi, 0x1p227); */
    v = iv_mul(iv_pt(s), d);
    /*@ assert b1: ps_mb(s, d.lo, PE_S, 0x1p227) && ps_mb(s, d.hi, PE_S, 0x1p227); */
    /*@ assert b1l: -0x1p257 <= s*d.lo <= 0x1p257; */
    /*@ assert b1h: -0x1p257 <= s*d.hi <= 0x1p257; */
    /*@ assert b2: ps_itb(s, s, d.lo, d.hi, 0x1p257); */
    /*@ assert in: prod_at(v.lo, v.hi, s, ((a0 - t*b0)*m0 + (a1 - t*b1)*m1) + (a2 - t*b2)*m2); */
    /*@ assert x: pe_x(m0, m1, m2, s, a0 - t*b0, a1 - t*b1, a2 - t*b2)
                  == s * (((a0 - t*b0)*m0 + (a1 - t*b1)*m1) + (a2 - t*b2)*m2); */
    return v;
}

/* {x^2 : x in v}. */
/*@ requires fin: \is_finite(v.lo) && \is_finite(v.hi);
    requires rng: iv_rng(v.lo, v.hi, 0x1p258) && v.lo <= v.hi;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: 0 <= \result.lo && iv_rng(\result.lo, \result.hi, 0x1p517);
    ensures in: iv_sq(\result.lo, \result.hi, v.lo, v.hi);
*/
static inline cbx_iv pe_sq(cbx_iv v)
{
    cbx_iv q = iv_sqr(v);
    /*@ assert b1: ps_mb(v.lo, v.lo, 0x1p258, 0x1p258) && ps_mb(v.hi, v.hi, 0x1p258, 0x1p258); */
    /*@ assert b2: sqmax(v.lo, v.hi) <= 0x1p516; */
    return q;
}

/* |M^T k(t)| enclosed, from the enclosures of its three entries. */
/*@ requires fin: \is_finite(t) && \is_finite(a0) && \is_finite(a1) && \is_finite(a2)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2)
                  && \is_finite(v0.lo) && \is_finite(v0.hi) && \is_finite(v1.lo) && \is_finite(v1.hi)
                  && \is_finite(v2.lo) && \is_finite(v2.hi);
    requires rng: iv_rng(v0.lo, v0.hi, 0x1p258) && iv_rng(v1.lo, v1.hi, 0x1p258)
                  && iv_rng(v2.lo, v2.hi, 0x1p258);
    requires in: iv_has(v0.lo, v0.hi, pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2))
                 && iv_has(v1.lo, v1.hi, pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2))
                 && iv_has(v2.lo, v2.hi, pe_x(r02, r12, r22, s2, a0 - t*b0, a1 - t*b1, a2 - t*b2));
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p262);
    ensures in: iv_has(\result.lo, \result.hi,
                       pe_n(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2));
*/
static inline cbx_iv pe_norm(double t, double a0, double a1, double a2, double b0, double b1, double b2,
                             double r00, double r01, double r02, double r10, double r11, double r12,
                             double r20, double r21, double r22, double s0, double s1, double s2,
                             cbx_iv v0, cbx_iv v1, cbx_iv v2)
{
    cbx_iv n0;
    cbx_iv n1;
    cbx_iv n2;
    cbx_iv n01;
    cbx_iv n;
    cbx_iv g;
    (void)t; (void)a0; (void)a1; (void)a2; (void)b0; (void)b1; (void)b2;
    (void)r00; (void)r01; (void)r02; (void)r10; (void)r11; (void)r12; (void)r20; (void)r21; (void)r22;
    (void)s0; (void)s1; (void)s2;
    /*@ assert o: v0.lo <= v0.hi && v1.lo <= v1.hi && v2.lo <= v2.hi; */
    n0 = pe_sq(v0);
    n1 = pe_sq(v1);
    n2 = pe_sq(v2);
    /*@ assert q0: sq_at(n0.lo, n0.hi, pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert q1: sq_at(n1.lo, n1.hi, pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert q2: sq_at(n2.lo, n2.hi, pe_x(r02, r12, r22, s2, a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    n01 = ps_sum(n0, n1, 0x1p517);
    n = ps_sum(n01, n2, 0x1p519);
    /*@ assert i01: iv_has(n01.lo, n01.hi,
          pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2) * pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2)
          + pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2) * pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert i: iv_has(n.lo, n.hi, nrm3(pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                                         pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                                         pe_x(r02, r12, r22, s2, a0 - t*b0, a1 - t*b1, a2 - t*b2))); */
    /*@ assert nr: 0 <= n.hi <= 0x1p521; */
    g = iv_sqrt(n);
    /*@ assert rn: rnorm3(pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                          pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                          pe_x(r02, r12, r22, s2, a0 - t*b0, a1 - t*b1, a2 - t*b2)) >= 0; */
    /*@ assert sq: sq_at(n.lo, n.hi, rnorm3(pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                                           pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                                           pe_x(r02, r12, r22, s2, a0 - t*b0, a1 - t*b1, a2 - t*b2))); */
    /*@ assert gin: iv_has(g.lo, g.hi, rnorm3(pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                                             pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                                             pe_x(r02, r12, r22, s2, a0 - t*b0, a1 - t*b1, a2 - t*b2))); */
    /*@ assert sb: g.hi <= CBX_ETA512 || (g.hi - CBX_ETA512) * (g.hi - CBX_ETA512) <= 0x1p522; */
    /*@ assert sl: sql(g.hi - CBX_ETA512, 0x1p261); */
    /*@ assert sr: 0 <= g.lo <= g.hi <= 0x1p262; */
    return g;
}

/* e(t) and |M^T k(t)| (specs/cbx_pell.h: pe_e, pe_n), outward-rounded. */
/*@ requires args: pe_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures fin: \is_finite(\result.e.lo) && \is_finite(\result.e.hi)
                 && \is_finite(\result.k.lo) && \is_finite(\result.k.hi);
    ensures rng: iv_rng(\result.e.lo, \result.e.hi, 0x1p230) && iv_rng(\result.k.lo, \result.k.hi, 0x1p262);
    ensures e: iv_has(\result.e.lo, \result.e.hi,
                      pe_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2));
    ensures k: iv_has(\result.k.lo, \result.k.hi,
                      pe_n(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2));
*/
static ps_gap pe_gap_at(double t, double a0, double a1, double a2, double a3,
                        double b0, double b1, double b2, double b3, double c0, double c1, double c2,
                        double r00, double r01, double r02, double r10, double r11, double r12,
                        double r20, double r21, double r22, double s0, double s1, double s2)
{
    ps_gap g;
    cbx_iv k0 = ps_k(t, a0, b0);
    cbx_iv k1 = ps_k(t, a1, b1);
    cbx_iv k2 = ps_k(t, a2, b2);
    cbx_iv k3 = ps_k(t, a3, b3);
    cbx_iv q0 = ps_kc(t, a0, b0, k0, c0);
    cbx_iv q1 = ps_kc(t, a1, b1, k1, c1);
    cbx_iv q2 = ps_kc(t, a2, b2, k2, c2);
    cbx_iv v0 = pe_col(t, a0, a1, a2, b0, b1, b2, r00, r10, r20, s0, k0, k1, k2);
    cbx_iv v1 = pe_col(t, a0, a1, a2, b0, b1, b2, r01, r11, r21, s1, k0, k1, k2);
    cbx_iv v2 = pe_col(t, a0, a1, a2, b0, b1, b2, r02, r12, r22, s2, k0, k1, k2);
    g.e = ps_esum(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, q0, q1, q2, k3);
    g.k = pe_norm(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2, v0, v1, v2);
    /*@ assert e: pe_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                       r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
                  == ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2); */
    return g;
}

/* ---- the search ----------------------------------------------------------- */
/* One try of an end, at th = t0 + d and tl = t0 - d, as the ball's
 * (src/f64/cbx_psph.c: ps_try): 1 when the end (th for up, tl for down) is
 * sound, the other point shows tightness, and they are within ps_tau of
 * the end. */
/*@ requires args: pe_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    requires t: \is_finite(th) && \is_finite(tl) && -PS_B <= th <= PS_B && -PS_B <= tl <= PS_B;
    assigns \nothing;
    ensures hi: up != 0 && \result != 0 ==>
      pe_hi(th, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      && th - ps_tau(th) <= tl
      && pe_above(tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    ensures lo: up == 0 && \result != 0 ==>
      pe_lo(tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      && th <= tl + ps_tau(tl)
      && pe_below(th, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
*/
static int pe_try(int up, double th, double tl, double a0, double a1, double a2, double a3,
                  double b0, double b1, double b2, double b3, double c0, double c1, double c2,
                  double r00, double r01, double r02, double r10, double r11, double r12,
                  double r20, double r21, double r22, double s0, double s1, double s2)
{
    int ok = 0;
    if (ps_span(th, tl, (up != 0) ? th : tl) != 0) {
        ps_gap gs = pe_gap_at((up != 0) ? th : tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                              r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
        cbx_iv ss = iv_add(gs.e, (up != 0) ? gs.k : iv_neg(gs.k));
        if ((up != 0) ? (ss.hi <= 0.0) : (ss.lo >= 0.0)) {
            ps_gap gw = pe_gap_at((up != 0) ? tl : th, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                                  r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
            cbx_iv sw = iv_add(gw.e, (up != 0) ? gw.k : iv_neg(gw.k));
            ok = (up != 0) ? (sw.lo > 0.0) : (sw.hi < 0.0);
        }
    }
    return ok;
}

/* One end from the candidate t0, as the ball's (ps_find). */
/*@ requires args: pe_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    requires t0: \is_finite(t0) && -PS_C <= t0 <= PS_C;
    assigns \nothing;
    ensures fin: \result.ok != 0 ==> \is_finite(\result.v) && -PS_B <= \result.v <= PS_B;
    ensures hi: up != 0 && \result.ok != 0 ==>
      pe_hi(\result.v, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
            r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      && \result.v - ps_tau(\result.v) <= \result.w
      && pe_above(\result.w, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                  r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    ensures lo: up == 0 && \result.ok != 0 ==>
      pe_lo(\result.v, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
            r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      && \result.w <= \result.v + ps_tau(\result.v)
      && pe_below(\result.w, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                  r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
*/
static ps_fin pe_find(int up, double t0, double a0, double a1, double a2, double a3,
                      double b0, double b1, double b2, double b3, double c0, double c1, double c2,
                      double r00, double r01, double r02, double r10, double r11, double r12,
                      double r20, double r21, double r22, double s0, double s1, double s2)
{
    ps_fin f;
    double d = cbx_mul_rn(cbx_add_rn(1.0, cbx_abs(t0)), 0x1p-48);
    int k;
    f.v = 0.0;
    f.w = 0.0;
    f.ok = 0;
    /*@ loop invariant k: 0 <= k <= PE_TRIES;
        loop invariant d: \is_finite(d) && 0 <= d <= 0x1p93;
        loop invariant f: f.ok == 0;
        loop assigns k, d, f;
        loop variant PE_TRIES - k;
    */
    for (k = 0; k < PE_TRIES && d <= 0x1p90; k++) {
        double th = t0 + d;
        double tl = t0 - d;
        if (ps_in(th, PS_B) && ps_in(tl, PS_B)
            && pe_try(up, th, tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                      r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)) {
            f.v = (up != 0) ? th : tl;
            f.w = (up != 0) ? tl : th;
            f.ok = 1;
            break;
        }
        d = cbx_mul_rn(d, 4.0);
    }
    return f;
}

/* ---- one output axis ---------------------------------------------------- */
/* The candidate: the ball's closed form on the rows in the ellipsoid's
 * frame, in round-to-nearest (clamped; any value is checked). */
/*@ requires args: pe_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
                && -PS_C <= \result.lo <= PS_C && -PS_C <= \result.hi <= PS_C;
*/
static ps_cand pe_candidate(double a0, double a1, double a2, double a3,
                            double b0, double b1, double b2, double b3, double c0, double c1, double c2,
                            double r00, double r01, double r02, double r10, double r11, double r12,
                            double r20, double r21, double r22, double s0, double s1, double s2)
{
    double A = ps_add(ps_dot(a0, a1, a2, c0, c1, c2), a3);
    double B = ps_add(ps_dot(b0, b1, b2, c0, c1, c2), b3);
    double x0 = ps_mul(s0, ps_dot(r00, r10, r20, a0, a1, a2));
    double x1 = ps_mul(s1, ps_dot(r01, r11, r21, a0, a1, a2));
    double x2 = ps_mul(s2, ps_dot(r02, r12, r22, a0, a1, a2));
    double y0 = ps_mul(s0, ps_dot(r00, r10, r20, b0, b1, b2));
    double y1 = ps_mul(s1, ps_dot(r01, r11, r21, b0, b1, b2));
    double y2 = ps_mul(s2, ps_dot(r02, r12, r22, b0, b1, b2));
    return ps_roots(ps_coef(A, B, x0, x1, x2, y0, y1, y2, 1.0));
}

/*@ requires args: pe_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    requires front: pe_front(b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
      && pe_axis(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                 r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      && pe_tight(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                  r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
*/
static ps_ax pe_axis_of(double a0, double a1, double a2, double a3,
                        double b0, double b1, double b2, double b3, double c0, double c1, double c2,
                        double r00, double r01, double r02, double r10, double r11, double r12,
                        double r20, double r21, double r22, double s0, double s1, double s2)
{
    ps_ax x;
    ps_cand q = pe_candidate(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                             r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    x.lo = 0.0;
    x.hi = 0.0;
    x.ok = 0;
    if (q.ok != 0) {
        ps_fin h = pe_find(1, q.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
        ps_fin l = pe_find(0, q.lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
        if ((h.ok != 0) && (l.ok != 0)) {
            x.lo = l.v;
            x.hi = h.v;
            x.ok = 1;
            /*@ assert cov: pe_axis(x.lo, x.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                                    r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2); */
            /*@ assert tight: pe_tight(x.lo, x.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                                       r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2); */
        }
    }
    return x;
}

/* W > 0 on the whole ellipsoid (pe_front): e(0) - |M^T k(0)| of the row W
 * itself (a = b = W: X - 0 W is W) enclosed above 0. */
/*@ requires args: pe_args(b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    assigns \nothing;
    ensures front: \result != 0 ==>
      pe_front(b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
*/
static int pe_in_front(double b0, double b1, double b2, double b3, double c0, double c1, double c2,
                       double r00, double r01, double r02, double r10, double r11, double r12,
                       double r20, double r21, double r22, double s0, double s1, double s2)
{
    ps_gap g = pe_gap_at(0.0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2,
                         r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    cbx_iv f = iv_add(g.e, iv_neg(g.k));
    /*@ assert e0: pe_e(0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2,
                        r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
                   == aff(b0, b1, b2, b3, c0, c1, c2); */
    /*@ assert n0: pe_n(0, b0, b1, b2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
                   == rnorm3(pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
                             pe_x(r02, r12, r22, s2, b0, b1, b2)); */
    /*@ assert fl: f.lo <= g.e.lo - g.k.hi; */
    return f.lo > 0.0;
}

/* ---- input checks ----------------------------------------------------- */
/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2)) && \valid_read(s + (0 .. 2))
             && \valid_read(r + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> pe_nan(p, c, s, r);
*/
static int pe_any_nan(const cbx_proj *p, const double c[3], const double s[3], const double r[3][3])
{
    return ps_proj_nan(p) | cbx_is_nan(c[0]) | cbx_is_nan(c[1]) | cbx_is_nan(c[2])
           | cbx_is_nan(s[0]) | cbx_is_nan(s[1]) | cbx_is_nan(s[2])
           | cbx_is_nan(r[0][0]) | cbx_is_nan(r[0][1]) | cbx_is_nan(r[0][2])
           | cbx_is_nan(r[1][0]) | cbx_is_nan(r[1][1]) | cbx_is_nan(r[1][2])
           | cbx_is_nan(r[2][0]) | cbx_is_nan(r[2][1]) | cbx_is_nan(r[2][2]);
}

/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2)) && \valid_read(s + (0 .. 2))
             && \valid_read(r + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> pe_dom(p, c, s, r);
*/
static int pe_dom_in(const cbx_proj *p, const double c[3], const double s[3], const double r[3][3])
{
    /* every input read before the first test: a read after the tests of
     * && carries their paths into its validity goal (2026-11-30: 2 s of
     * WP's simplifier for each of 30 reads) */
    int w0 = ps_row_in(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3]);
    int w1 = ps_row_in(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3]);
    int w2 = ps_row_in(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3]);
    int w3 = ps_row_in(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);
    const double c0 = c[0];
    const double c1 = c[1];
    const double c2 = c[2];
    const double s0 = s[0];
    const double s1 = s[1];
    const double s2 = s[2];
    const double r00 = r[0][0];
    const double r01 = r[0][1];
    const double r02 = r[0][2];
    const double r10 = r[1][0];
    const double r11 = r[1][1];
    const double r12 = r[1][2];
    const double r20 = r[2][0];
    const double r21 = r[2][1];
    const double r22 = r[2][2];
    int ct = ps_in(c0, PS_M) && ps_in(c1, PS_M) && ps_in(c2, PS_M);
    int rs = ps_in(s0, PE_S) && ps_in(s1, PE_S) && ps_in(s2, PE_S);
    int m0 = ps_in(r00, PE_S) && ps_in(r01, PE_S) && ps_in(r02, PE_S);
    int m1 = ps_in(r10, PE_S) && ps_in(r11, PE_S) && ps_in(r12, PE_S);
    int m2 = ps_in(r20, PE_S) && ps_in(r21, PE_S) && ps_in(r22, PE_S);
    return w0 && w1 && w2 && w3 && ct && rs && m0 && m1 && m2;
}

/* ---- the public function ------------------------------------------------ */
cbx_status cbx_project_ellipsoid(const cbx_proj *p, const double center[3], const double radii[3],
                                 const double rot[3][3], cbx_box *out)
{
    if (pe_any_nan(p, center, radii, rot) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (!pe_dom_in(p, center, radii, rot)) {
        set_whole(out);
        return CBX_ERANGE;
    }
    {
        double w0 = p->m[3][0];
        double w1 = p->m[3][1];
        double w2 = p->m[3][2];
        double wt = p->m[3][3];
        double c0 = center[0];
        double c1 = center[1];
        double c2 = center[2];
        double r00 = rot[0][0];
        double r01 = rot[0][1];
        double r02 = rot[0][2];
        double r10 = rot[1][0];
        double r11 = rot[1][1];
        double r12 = rot[1][2];
        double r20 = rot[2][0];
        double r21 = rot[2][1];
        double r22 = rot[2][2];
        double s0 = radii[0];
        double s1 = radii[1];
        double s2 = radii[2];
        ps_ax x0;
        ps_ax x1;
        ps_ax x2;
        if (!pe_in_front(w0, w1, w2, wt, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)) {
            set_whole(out);
            return CBX_EBEHIND;
        }
        x0 = pe_axis_of(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3], w0, w1, w2, wt, c0, c1, c2,
                        r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
        x1 = pe_axis_of(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3], w0, w1, w2, wt, c0, c1, c2,
                        r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
        x2 = pe_axis_of(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3], w0, w1, w2, wt, c0, c1, c2,
                        r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
        if ((x0.ok == 0) || (x1.ok == 0) || (x2.ok == 0)) {
            set_whole(out);
            return CBX_ERANGE;
        }
        out->lo[0] = x0.lo;
        out->hi[0] = x0.hi;
        out->lo[1] = x1.lo;
        out->hi[1] = x1.hi;
        out->lo[2] = x2.lo;
        out->hi[2] = x2.hi;
        return CBX_OK;
    }
}
