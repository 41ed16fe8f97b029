/*
 * Affine forms under a projective map, enclosed: the pieces shared by the
 * projected ball (src/f64/cbx_psph.c) and the clipped projected box
 * (src/f64/cbx_pnear.c), binary64.
 *
 * For a row X = (a0, a1, a2, a3) of the map, the camera row W =
 * (b0, b1, b2, b3) and a real t, X - t W is the affine form with
 * coefficients a_j - t b_j (specs/cbx_psph.h: ps_e is its value at a
 * point).  Both bounds certify an end t by enclosing such forms with the
 * proven interval arithmetic of src/f64/cbx_iv.h: at a point (ps_e_at),
 * over a ball (cbx_psph.c) or over a box (cbx_pnear.c).  The domain bounds
 * below keep every enclosure far inside binary64's range.  Also here: the
 * clamped round-to-nearest operations the candidates are computed with,
 * and the test of a certified end's width (ps_span).  Proven in job PS64
 * (proofs/psph.c); the clipped box's job uses these contracts.
 */
#ifndef CBX_PAFF_H
#define CBX_PAFF_H

#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_iv.h"

#define PS_M 0x1p60      /* linear entries, points, radius */
#define PS_T 0x1p120     /* translations */
#define PS_B 0x1p100     /* an end, and every t a form is evaluated at */
#define PS_C 0x1p99      /* a candidate end */
#define PS_L 0x1p509     /* the candidates' clamp */

/* ---- input tests ---------------------------------------------------------- */
/*@ requires \valid_read(p);
    assigns \nothing;
    ensures \result != 0 <==> proj_nan(p);
*/
static inline int ps_proj_nan(const cbx_proj *p)
{
    return cbx_is_nan(p->m[0][0]) | cbx_is_nan(p->m[0][1]) | cbx_is_nan(p->m[0][2]) | cbx_is_nan(p->m[0][3])
           | cbx_is_nan(p->m[1][0]) | cbx_is_nan(p->m[1][1]) | cbx_is_nan(p->m[1][2]) | cbx_is_nan(p->m[1][3])
           | cbx_is_nan(p->m[2][0]) | cbx_is_nan(p->m[2][1]) | cbx_is_nan(p->m[2][2]) | cbx_is_nan(p->m[2][3])
           | cbx_is_nan(p->m[3][0]) | cbx_is_nan(p->m[3][1]) | cbx_is_nan(p->m[3][2]) | cbx_is_nan(p->m[3][3]);
}

/* 1 exactly when -b <= x <= b (x then finite). */
/*@ requires \is_finite(b);
    assigns \nothing;
    ensures \result != 0 <==> (\is_finite(x) && -b <= x <= b);
*/
static inline int ps_in(double x, double b)
{
    return (x >= -b) && (x <= b);
}

/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
                               && ps_row(m0, m1, m2, t));
*/
static inline int ps_row_in(double m0, double m1, double m2, double t)
{
    int a = ps_in(m0, PS_M);
    int b = ps_in(m1, PS_M);
    int d = ps_in(m2, PS_M);
    int e = ps_in(t, PS_T);
    return a && b && d && e;
}

/* ---- enclosures of X - t W ---------------------------------------------- */
/* a_j - t b_j enclosed (one entry of k(t), or its translation). */
/*@ requires fin: \is_finite(t) && \is_finite(a) && \is_finite(b);
    requires rng: -PS_B <= t <= PS_B && -PS_T <= a <= PS_T && -PS_T <= b <= PS_T;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p222);
    ensures lin: -PS_M <= a <= PS_M && -PS_M <= b <= PS_M ==> iv_rng(\result.lo, \result.hi, 0x1p162);
    ensures in: iv_has(\result.lo, \result.hi, a - t*b);
*/
static inline cbx_iv ps_k(double t, double a, double b)
{
    cbx_iv tp = iv_pt(t);
    cbx_iv bp = iv_pt(b);
    cbx_iv p = iv_mul(tp, bp);
    cbx_iv q;
    /*@ assert tb: ps_mb(t, b, PS_B, PS_T); */
    /*@ assert tm: -PS_M <= b <= PS_M ==> ps_mb(t, b, PS_B, PS_M); */
    /*@ assert pv: itmin(t, t, b, b) == t*b && itmax(t, t, b, b) == t*b && itmag(t, t, b, b) == \abs(t*b); */
    /*@ assert pr: iv_rng(p.lo, p.hi, 0x1p221); */
    /*@ assert pm: -PS_M <= b <= PS_M ==> iv_rng(p.lo, p.hi, 0x1p161); */
    /*@ assert pin: p.lo <= t*b <= p.hi; */
    q = iv_add(iv_neg(p), iv_pt(a));
    /*@ assert qin: q.lo <= -(t*b) + a <= q.hi; */
    return q;
}

/* x + y enclosed, both in [-m, m] (1 <= m <= 2^1000): the sum in
 * [-3 m, 3 m]. */
/*@ requires fin: \is_finite(x.lo) && \is_finite(x.hi) && \is_finite(y.lo) && \is_finite(y.hi)
                  && \is_finite(m);
    requires rng: 1 <= m <= 0x1p1000 && iv_rng(x.lo, x.hi, m) && iv_rng(y.lo, y.hi, m);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 3*m);
    ensures lo: \result.lo <= x.lo + y.lo;
    ensures hi: \result.hi >= x.hi + y.hi;
    ensures in: \forall real u, v; iv_has(x.lo, x.hi, u) && iv_has(y.lo, y.hi, v)
                  ==> iv_has(\result.lo, \result.hi, u + v);
*/
static inline cbx_iv ps_sum(cbx_iv x, cbx_iv y, double m)
{
    (void)m;
    return iv_add(x, y);
}

/* (a - t b) c enclosed, from the enclosure k of a - t b. */
/*@ requires fin: \is_finite(t) && \is_finite(a) && \is_finite(b) && \is_finite(c)
                  && \is_finite(k.lo) && \is_finite(k.hi);
    requires rng: iv_rng(k.lo, k.hi, 0x1p162) && -PS_M <= c <= PS_M;
    requires in: iv_has(k.lo, k.hi, a - t*b);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p223);
    ensures in: iv_has(\result.lo, \result.hi, (a - t*b)*c);
*/
static inline cbx_iv ps_kc(double t, double a, double b, cbx_iv k, double c)
{
    (void)t; (void)a; (void)b;
    cbx_iv q = iv_mul(k, iv_pt(c));
    /*@ assert b1: ps_mb(k.lo, c, 0x1p162, PS_M) && ps_mb(k.hi, c, 0x1p162, PS_M); */
    /*@ assert b1l: -0x1p222 <= k.lo*c <= 0x1p222; */
    /*@ assert b1h: -0x1p222 <= k.hi*c <= 0x1p222; */
    /*@ assert b2: ps_itb(k.lo, k.hi, c, c, 0x1p222); */
    /*@ assert in: prod_at(q.lo, q.hi, a - t*b, c); */
    return q;
}

/* e(t) = sum_j (a_j - t b_j) c_j + (a3 - t b3) enclosed, from the
 * enclosures of its four terms. */
/*@ requires fin: \is_finite(t) && \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
                  && \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
                  && \is_finite(q0.lo) && \is_finite(q0.hi) && \is_finite(q1.lo) && \is_finite(q1.hi)
                  && \is_finite(q2.lo) && \is_finite(q2.hi) && \is_finite(k3.lo) && \is_finite(k3.hi);
    requires rng: iv_rng(q0.lo, q0.hi, 0x1p223) && iv_rng(q1.lo, q1.hi, 0x1p223)
                  && iv_rng(q2.lo, q2.hi, 0x1p223) && iv_rng(k3.lo, k3.hi, 0x1p222);
    requires in: iv_has(q0.lo, q0.hi, (a0 - t*b0)*c0) && iv_has(q1.lo, q1.hi, (a1 - t*b1)*c1)
                 && iv_has(q2.lo, q2.hi, (a2 - t*b2)*c2) && iv_has(k3.lo, k3.hi, a3 - t*b3);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p230);
    ensures in: iv_has(\result.lo, \result.hi, ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2));
*/
static inline cbx_iv ps_esum(double t, double a0, double a1, double a2, double a3,
                      double b0, double b1, double b2, double b3, double c0, double c1, double c2,
                      cbx_iv q0, cbx_iv q1, cbx_iv q2, cbx_iv k3)
{
    (void)t; (void)a0; (void)a1; (void)a2; (void)a3; (void)b0; (void)b1; (void)b2; (void)b3;
    (void)c0; (void)c1; (void)c2;
    cbx_iv e01 = ps_sum(q0, q1, 0x1p223);
    cbx_iv e23 = ps_sum(q2, k3, 0x1p223);
    cbx_iv e = ps_sum(e01, e23, 0x1p225);
    /*@ assert i01: iv_has(e01.lo, e01.hi, (a0 - t*b0)*c0 + (a1 - t*b1)*c1); */
    /*@ assert i23: iv_has(e23.lo, e23.hi, (a2 - t*b2)*c2 + (a3 - t*b3)); */
    /*@ assert i: iv_has(e.lo, e.hi, ((a0 - t*b0)*c0 + (a1 - t*b1)*c1) + ((a2 - t*b2)*c2 + (a3 - t*b3))); */
    return e;
}

/* X - t W at the point (c0, c1, c2) (ps_e), enclosed. */
/*@ requires rows: ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3);
    requires pt: ps_ctr(c0, c1, c2, 0);
    requires fin: \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
                  && \is_finite(c0) && \is_finite(c1) && \is_finite(c2);
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p230);
    ensures e: iv_has(\result.lo, \result.hi, ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2));
*/
static inline cbx_iv ps_e_at(double t, double a0, double a1, double a2, double a3,
                             double b0, double b1, double b2, double b3, double c0, double c1, double c2)
{
    cbx_iv k0 = ps_k(t, a0, b0);
    cbx_iv k1 = ps_k(t, a1, b1);
    cbx_iv k2 = ps_k(t, a2, b2);
    cbx_iv k3 = ps_k(t, a3, b3);
    cbx_iv q0 = ps_kc(t, a0, b0, k0, c0);
    cbx_iv q1 = ps_kc(t, a1, b1, k1, c1);
    cbx_iv q2 = ps_kc(t, a2, b2, k2, c2);
    return ps_esum(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, q0, q1, q2, k3);
}

/* ---- round-to-nearest helpers for the candidates ------------------------ */
/* x clamped to [-2^509, 2^509] (NaN to -2^509): a product of two clamped
 * values cannot overflow.  In the domain no intermediate value reaches the
 * clamp (they stay below 2^490); it only makes the absence of overflow
 * provable without tracking each value. */
/*@ assigns \nothing;
    ensures fin: \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static inline double ps_cl(double x)
{
    double r = -PS_L;
    if ((x >= -PS_L) && (x <= PS_L)) {
        r = x;
    } else if (x > PS_L) {
        r = PS_L;
    } else {
        /* x < -PS_L or NaN: r keeps -PS_L */
    }
    return r;
}

/*@ requires \is_finite(x) && \is_finite(y) && -PS_L <= x <= PS_L && -PS_L <= y <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static inline double ps_mul(double x, double y)
{
    /*@ assert b: ps_mb(x, y, PS_L, PS_L); */
    return ps_cl(x * y);
}

/*@ requires \is_finite(x) && \is_finite(y) && -PS_L <= x <= PS_L && -PS_L <= y <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static inline double ps_add(double x, double y)
{
    return ps_cl(x + y);
}

/*@ requires \is_finite(x) && \is_finite(y) && -PS_L <= x <= PS_L && -PS_L <= y <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static inline double ps_sub(double x, double y)
{
    return ps_cl(x - y);
}

/*@ requires \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(n0) && \is_finite(n1) && \is_finite(n2);
    requires -PS_L <= m0 <= PS_L && -PS_L <= m1 <= PS_L && -PS_L <= m2 <= PS_L;
    requires -PS_L <= n0 <= PS_L && -PS_L <= n1 <= PS_L && -PS_L <= n2 <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static inline double ps_dot(double m0, double m1, double m2, double n0, double n1, double n2)
{
    return ps_add(ps_add(ps_mul(m0, n0), ps_mul(m1, n1)), ps_mul(m2, n2));
}

/* x / y rounded (clamped), for y >= 2^-400. */
/*@ requires \is_finite(x) && \is_finite(y) && -PS_L <= x <= PS_L && 0x1p-400 <= y <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static inline double ps_qt(double x, double y)
{
    cbx_iv q;
    /*@ assert r: \abs(x) <= CBX_QR * y; */
    q = iv_div(iv_pt(x), iv_pt(y));
    return ps_cl(q.lo);
}

/* A first guess at a witness's fraction of the way toward larger W, in
 * round-to-nearest (the clipped bounds' searches check whatever it gives):
 * twice what lifts an enclosure w of W by its shortfall under wn plus its
 * width, at the rate of W per unit of the fraction; clamped to [0, 1], 0
 * when the rate is below 2^-400 or nothing is short. */
/*@ requires \is_finite(w.lo) && \is_finite(w.hi) && \is_finite(wn);
    requires \is_finite(rate) && -PS_L <= rate <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result) && 0 <= \result <= 1;
*/
static inline double ps_frac(cbx_iv w, double wn, double rate)
{
    double lo = ps_cl(w.lo);
    double need = ps_add(ps_sub(ps_cl(wn), lo), ps_sub(ps_cl(w.hi), lo));
    double f = 0.0;
    if ((rate >= 0x1p-400) && (need > 0.0)) {
        f = ps_qt(ps_mul(need, 2.0), rate);
    }
    return (f > 1.0) ? 1.0 : (f > 0.0) ? f : 0.0;
}

/* ---- the width of a certified end ---------------------------------------- */
/* 1 only if x - y <= 2^-20 (1 + |v|) (specs/cbx_psph.h: ps_tau). */
/*@ requires fin: \is_finite(x) && \is_finite(y) && \is_finite(v);
    requires rng: -PS_B <= x <= PS_B && -PS_B <= y <= PS_B && -PS_B <= v <= PS_B;
    assigns \nothing;
    ensures span: \result != 0 ==> x - y <= ps_tau(v);
*/
static inline int ps_span(double x, double y, double v)
{
    double s = cbx_add_up(x, -y);
    double w = cbx_add_dn(1.0, cbx_abs(v));
    double q = cbx_mul_rn(w, 0x1p-21);
    /*@ assert w: 0 <= w <= 1 + \abs(v); */
    /*@ assert q: q <= w * 0x1p-21 * (1 + CBX_U) + CBX_ETA; */
    return s <= q;
}

/* ---- the three output axes ------------------------------------------------- */
/* One output axis: its ends, ok 0 when it could not be certified. */
typedef struct ps_ax { double lo; double hi; int ok; } ps_ax;

/* One certified end v, its witness of tightness w (the searches of
 * src/f64/cbx_psph.c and cbx_pell.c); ok 0 when none was found. */
typedef struct ps_fin { double v; double w; int ok; } ps_fin;

#endif /* CBX_PAFF_H */
