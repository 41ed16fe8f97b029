/*
 * A ball under a projective map, enclosed: the pieces shared by the
 * projected ball (src/f64/cbx_psph.c) and the projected ball clipped at a
 * near plane (src/f64/cbx_pball.c), binary64.
 *
 * The ball is {c + r q : |q| <= 1}; for an output row X = (a0, a1, a2, a3),
 * the camera row W = (b0, b1, b2, b3) and a real t, X - t W ranges over
 * e(t) -+ |r| |k(t)| on the ball (specs/cbx_psph.h: ps_e, ps_n).  Here:
 * both terms enclosed in outward-rounded interval arithmetic (ps_gap_at),
 * and the closed form of the unclipped ends in round-to-nearest
 * (ps_candidate).  Proven in job PS64 (proofs/psph.c); the clipped ball's
 * job uses these contracts.
 */
#ifndef CBX_PGAP_H
#define CBX_PGAP_H

#include "cbx_paff.h"

/* ---- the certificate: e(t) and |r| |k(t)| enclosed --------------------- */
typedef struct ps_gap { cbx_iv e; cbx_iv k; } ps_gap;

/* (a - t b)^2 enclosed, from the enclosure k of a - t b. */
/*@ requires fin: \is_finite(t) && \is_finite(a) && \is_finite(b)
                  && \is_finite(k.lo) && \is_finite(k.hi);
    requires rng: iv_rng(k.lo, k.hi, 0x1p162);
    requires in: iv_has(k.lo, k.hi, a - t*b);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: 0 <= \result.lo && iv_rng(\result.lo, \result.hi, 0x1p325);
    ensures in: iv_has(\result.lo, \result.hi, (a - t*b)*(a - t*b));
*/
static inline cbx_iv ps_ksq(double t, double a, double b, cbx_iv k)
{
    (void)t; (void)a; (void)b;
    cbx_iv q = iv_sqr(k);
    /*@ assert b1: ps_mb(k.lo, k.lo, 0x1p162, 0x1p162) && ps_mb(k.hi, k.hi, 0x1p162, 0x1p162); */
    /*@ assert b2: sqmax(k.lo, k.hi) <= 0x1p324; */
    /*@ assert in: sq_at(q.lo, q.hi, a - t*b); */
    return q;
}

/* |r| |k(t)| enclosed, from the enclosures of k's three entries.  Its
 * assertion kabs (a product's enclosure restated as the enclosure of the
 * product) Z3 proves in 0.04 s and CVC4 not in 40 s: proven in job PSR64,
 * both provers raced. */
/* proof: race */
/*@ requires fin: \is_finite(t) && \is_finite(a0) && \is_finite(a1) && \is_finite(a2)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(r)
                  && \is_finite(k0.lo) && \is_finite(k0.hi) && \is_finite(k1.lo) && \is_finite(k1.hi)
                  && \is_finite(k2.lo) && \is_finite(k2.hi);
    requires rng: iv_rng(k0.lo, k0.hi, 0x1p162) && iv_rng(k1.lo, k1.hi, 0x1p162)
                  && iv_rng(k2.lo, k2.hi, 0x1p162) && -PS_M <= r <= PS_M;
    requires in: iv_has(k0.lo, k0.hi, a0 - t*b0) && iv_has(k1.lo, k1.hi, a1 - t*b1)
                 && iv_has(k2.lo, k2.hi, a2 - t*b2);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p230);
    ensures in: iv_has(\result.lo, \result.hi, \abs(r) * ps_n(t, a0, a1, a2, b0, b1, b2));
*/
static inline cbx_iv ps_norm(double t, double a0, double a1, double a2, double b0, double b1, double b2,
                      double r, cbx_iv k0, cbx_iv k1, cbx_iv k2)
{
    double ar = cbx_abs(r);
    cbx_iv n0 = ps_ksq(t, a0, b0, k0);
    cbx_iv n1 = ps_ksq(t, a1, b1, k1);
    cbx_iv n2 = ps_ksq(t, a2, b2, k2);
    cbx_iv n01 = ps_sum(n0, n1, 0x1p325);
    cbx_iv n = ps_sum(n01, n2, 0x1p327);
    cbx_iv s;
    cbx_iv g;
    /*@ assert i01: iv_has(n01.lo, n01.hi, (a0 - t*b0)*(a0 - t*b0) + (a1 - t*b1)*(a1 - t*b1)); */
    /*@ assert i: iv_has(n.lo, n.hi, nrm3(a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert rn: rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2) >= 0
                   && rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2) * rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2)
                      == nrm3(a0 - t*b0, a1 - t*b1, a2 - t*b2); */
    /*@ assert nr: 0 <= n.hi <= 0x1p329; */
    s = iv_sqrt(n);
    /*@ assert sq: sq_at(n.lo, n.hi, rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert sin: iv_has(s.lo, s.hi, rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert sb: s.hi <= CBX_ETA512 || (s.hi - CBX_ETA512) * (s.hi - CBX_ETA512) <= 0x1p330; */
    /*@ assert sl: sql(s.hi - CBX_ETA512, 0x1p165); */
    /*@ assert sr: 0 <= s.lo <= s.hi <= 0x1p166; */
    g = iv_mul(iv_pt(ar), s);
    /*@ assert kb: ps_mb(ar, s.lo, PS_M, 0x1p166) && ps_mb(ar, s.hi, PS_M, 0x1p166); */
    /*@ assert kbl: -0x1p226 <= ar*s.lo <= 0x1p226; */
    /*@ assert kbh: -0x1p226 <= ar*s.hi <= 0x1p226; */
    /*@ assert k1: ps_itb(ar, ar, s.lo, s.hi, 0x1p226); */
    /*@ assert kin: prod_at(g.lo, g.hi, ar, rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert kin2: prod_at(g.lo, g.hi, \abs(r), rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert kabs: iv_has(g.lo, g.hi, \abs(r) * rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2)); */
    /*@ assert pn: ps_n(t, a0, a1, a2, b0, b1, b2) == rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2); */
    return g;
}

/* e(t) and |r| |k(t)| (specs/cbx_psph.h: ps_e, ps_n), outward-rounded. */
/*@ requires rows: ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3);
    requires ctr: ps_ctr(c0, c1, c2, r);
    requires fin: \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
                  && \is_finite(c0) && \is_finite(c1) && \is_finite(c2) && \is_finite(r);
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures fin: \is_finite(\result.e.lo) && \is_finite(\result.e.hi)
                 && \is_finite(\result.k.lo) && \is_finite(\result.k.hi);
    ensures rng: iv_rng(\result.e.lo, \result.e.hi, 0x1p230) && iv_rng(\result.k.lo, \result.k.hi, 0x1p230);
    ensures e: iv_has(\result.e.lo, \result.e.hi, ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2));
    ensures k: iv_has(\result.k.lo, \result.k.hi, \abs(r) * ps_n(t, a0, a1, a2, b0, b1, b2));
*/
static inline ps_gap ps_gap_at(double t, double a0, double a1, double a2, double a3,
                        double b0, double b1, double b2, double b3,
                        double c0, double c1, double c2, double r)
{
    ps_gap g;
    cbx_iv k0 = ps_k(t, a0, b0);
    cbx_iv k1 = ps_k(t, a1, b1);
    cbx_iv k2 = ps_k(t, a2, b2);
    cbx_iv k3 = ps_k(t, a3, b3);
    cbx_iv q0 = ps_kc(t, a0, b0, k0, c0);
    cbx_iv q1 = ps_kc(t, a1, b1, k1, c1);
    cbx_iv q2 = ps_kc(t, a2, b2, k2, c2);
    g.e = ps_esum(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, q0, q1, q2, k3);
    g.k = ps_norm(t, a0, a1, a2, b0, b1, b2, r, k0, k1, k2);
    return g;
}

/* ---- the candidate: the closed form in round-to-nearest ---------------- */
/* The ends of axis (a, b) are the roots of (A - t B)^2 = r^2 |a - t b|^2
 * (A = X(c), B = W(c)), that is t = (h -+ sqrt(D)) / den with
 * den = B^2 - r^2 |b|^2, h = A B - r^2 a.b,
 * D = r^2 (|A b - B a|^2 - r^2 |a x b|^2): its three coefficients in
 * round-to-nearest (ps_quad, clamped), and the ends where den is well
 * above 0, the ball clear of the camera plane (ps_candidate; ok 0 when
 * den is not well above 0 or an end is beyond 2^99). */
typedef struct ps_qd { double h; double sq; double den; } ps_qd;

/* The three coefficients from A = X(c), B = W(c), the linear parts a, b
 * and r2 = r^2 (the ellipsoid's candidate, src/f64/cbx_pell.c, passes its
 * rows in its own frame and r2 = 1). */
/*@ requires fin: \is_finite(A) && \is_finite(B) && \is_finite(a0) && \is_finite(a1) && \is_finite(a2)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(r2);
    requires rng: -PS_L <= A <= PS_L && -PS_L <= B <= PS_L && -PS_L <= r2 <= PS_L
                  && -PS_L <= a0 <= PS_L && -PS_L <= a1 <= PS_L && -PS_L <= a2 <= PS_L
                  && -PS_L <= b0 <= PS_L && -PS_L <= b1 <= PS_L && -PS_L <= b2 <= PS_L;
    assigns \nothing;
    ensures fin: \is_finite(\result.h) && \is_finite(\result.sq) && \is_finite(\result.den);
    ensures rng: -PS_L <= \result.h <= PS_L && 0 <= \result.sq <= PS_L && -PS_L <= \result.den <= PS_L;
*/
static inline ps_qd ps_coef(double A, double B, double a0, double a1, double a2,
                            double b0, double b1, double b2, double r2)
{
    ps_qd q;
    double nb = ps_dot(b0, b1, b2, b0, b1, b2);
    double ab = ps_dot(a0, a1, a2, b0, b1, b2);
    double v0 = ps_sub(ps_mul(A, b0), ps_mul(B, a0));
    double v1 = ps_sub(ps_mul(A, b1), ps_mul(B, a1));
    double v2 = ps_sub(ps_mul(A, b2), ps_mul(B, a2));
    double x0 = ps_sub(ps_mul(a1, b2), ps_mul(a2, b1));
    double x1 = ps_sub(ps_mul(a2, b0), ps_mul(a0, b2));
    double x2 = ps_sub(ps_mul(a0, b1), ps_mul(a1, b0));
    double vv = ps_dot(v0, v1, v2, v0, v1, v2);
    double xx = ps_dot(x0, x1, x2, x0, x1, x2);
    double dd = ps_mul(r2, ps_sub(vv, ps_mul(r2, xx)));
    double sq = 0.0;
    if (dd > 0.0) {
        sq = cbx_sqrt_rn(dd);
    }
    /*@ assert sqq: sql(sq, PS_L); */
    /*@ assert sq: \is_finite(sq) && 0 <= sq <= PS_L; */
    q.h = ps_sub(ps_mul(A, B), ps_mul(r2, ab));
    q.sq = sq;
    q.den = ps_sub(ps_mul(B, B), ps_mul(r2, nb));
    return q;
}

/*@ requires rows: ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3);
    requires ctr: ps_ctr(c0, c1, c2, r);
    requires fin: \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
                  && \is_finite(c0) && \is_finite(c1) && \is_finite(c2) && \is_finite(r);
    assigns \nothing;
    ensures fin: \is_finite(\result.h) && \is_finite(\result.sq) && \is_finite(\result.den);
    ensures rng: -PS_L <= \result.h <= PS_L && 0 <= \result.sq <= PS_L && -PS_L <= \result.den <= PS_L;
*/
static inline ps_qd ps_quad(double a0, double a1, double a2, double a3,
                            double b0, double b1, double b2, double b3,
                            double c0, double c1, double c2, double r)
{
    double A = ps_add(ps_dot(a0, a1, a2, c0, c1, c2), a3);
    double B = ps_add(ps_dot(b0, b1, b2, c0, c1, c2), b3);
    double r2 = ps_mul(r, r);
    return ps_coef(A, B, a0, a1, a2, b0, b1, b2, r2);
}

typedef struct ps_cand { double lo; double hi; int ok; } ps_cand;

/* The ends (h -+ sq) / den where den is well above 0 (ok 0 otherwise, or
 * when an end is beyond 2^99). */
/*@ requires fin: \is_finite(e.h) && \is_finite(e.sq) && \is_finite(e.den);
    requires rng: -PS_L <= e.h <= PS_L && 0 <= e.sq <= PS_L && -PS_L <= e.den <= PS_L;
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
                && -PS_C <= \result.lo <= PS_C && -PS_C <= \result.hi <= PS_C;
*/
static inline ps_cand ps_roots(ps_qd e)
{
    ps_cand q;
    q.lo = 0.0;
    q.hi = 0.0;
    q.ok = 0;
    if (e.den >= 0x1p-400) {
        double nl = ps_sub(e.h, e.sq);
        double nh = ps_add(e.h, e.sq);
        cbx_iv tl = iv_div(iv_pt(nl), iv_pt(e.den));
        cbx_iv th = iv_div(iv_pt(nh), iv_pt(e.den));
        if (ps_in(tl.lo, PS_C) && ps_in(th.hi, PS_C)) {
            q.lo = tl.lo;
            q.hi = th.hi;
            q.ok = 1;
        }
    }
    return q;
}

/*@ requires rows: ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3);
    requires ctr: ps_ctr(c0, c1, c2, r);
    requires fin: \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
                  && \is_finite(c0) && \is_finite(c1) && \is_finite(c2) && \is_finite(r);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
                && -PS_C <= \result.lo <= PS_C && -PS_C <= \result.hi <= PS_C;
*/
static inline ps_cand ps_candidate(double a0, double a1, double a2, double a3,
                                   double b0, double b1, double b2, double b3,
                                   double c0, double c1, double c2, double r)
{
    return ps_roots(ps_quad(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r));
}

#endif /* CBX_PGAP_H */
