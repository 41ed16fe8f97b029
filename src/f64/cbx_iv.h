/*
 * Outward-rounded interval arithmetic, binary64 (the rotation motion of
 * src/f64/cbx_trs.c).  Each operation's contract states, in exact reals,
 * that the result holds the exact result for every real point of its
 * operands (containment), and how far each end may be from the exact end
 * (tightness).  The rounding reasoning is the primitives' (src/core/:
 * cbx_mul_rn, cbx_add_dn / cbx_add_up, cbx_div_dn / cbx_div_up,
 * cbx_sqrt_rn); the logic is in specs/cbx_iv_logic.h and, for products, the
 * interval matrices' itmin / itmax / iterm_all (specs/cbx_imat_logic.h).
 * Proven in job T64 (proofs/trs.c).
 */
#ifndef CBX_IV_H
#define CBX_IV_H

#include "certbox.h"
#include "cbx_round.h"
#include "cbx_quot.h"
#ifdef __FRAMAC__
#include "cbx_iv_logic.h"
#endif

/* An interval [lo, hi] of reals. */
typedef struct cbx_iv {
    double lo;
    double hi;
} cbx_iv;

/*@ requires fin: \is_finite(x);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures val: \result.lo == x && \result.hi == x;
*/
static inline cbx_iv iv_pt(double x)
{
    cbx_iv r;
    r.lo = x;
    r.hi = x;
    return r;
}

/* The smallest interval holding a and b. */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi) && \is_finite(b.lo) && \is_finite(b.hi);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures val: \result.lo == \min(a.lo, b.lo) && \result.hi == \max(a.hi, b.hi);
*/
static inline cbx_iv iv_hull(cbx_iv a, cbx_iv b)
{
    cbx_iv r;
    r.lo = cbx_min2(a.lo, b.lo);
    r.hi = cbx_max2(a.hi, b.hi);
    return r;
}

/* a intersected with [-1, 1] (a component of a unit vector, or an entry
 * of a rotation matrix, lies there). */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures val: \result.lo == \max(a.lo, -1) && \result.hi == \min(a.hi, 1);
*/
static inline cbx_iv iv_unit(cbx_iv a)
{
    cbx_iv r;
    r.lo = cbx_max2(a.lo, -1.0);
    r.hi = cbx_min2(a.hi, 1.0);
    return r;
}

/* {-x : x in a}, exact. */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures val: \result.lo == -a.hi && \result.hi == -a.lo;
*/
static inline cbx_iv iv_neg(cbx_iv a)
{
    cbx_iv r;
    r.lo = -a.hi;
    r.hi = -a.lo;
    return r;
}

/* {x + y : x in a, y in b}: each end the exact end moved outward by at
 * least 3 u of the operands' magnitudes (cbx_add_dn / cbx_add_up). */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi) && \is_finite(b.lo) && \is_finite(b.hi);
    requires rng: iv_rng(a.lo, a.hi, CBX_R19) && iv_rng(b.lo, b.hi, CBX_RT);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures lo: \result.lo <= a.lo + b.lo;
    ensures hi: \result.hi >= a.hi + b.hi;
    ensures in: \forall real x, y; iv_has(a.lo, a.hi, x) && iv_has(b.lo, b.hi, y)
                  ==> iv_has(\result.lo, \result.hi, x + y);
    ensures near: \result.lo >= a.lo + b.lo - (CBX_U8 * (\abs(a.lo) + \abs(b.lo)) + CBX_ETA512)
                  && \result.hi <= a.hi + b.hi + (CBX_U8 * (\abs(a.hi) + \abs(b.hi)) + CBX_ETA512);
*/
static inline cbx_iv iv_add(cbx_iv a, cbx_iv b)
{
    cbx_iv r;
    r.lo = cbx_add_dn(a.lo, b.lo);
    r.hi = cbx_add_up(a.hi, b.hi);
    return r;
}

/* {x y : x in a, y in b}: the four corner products rounded to nearest,
 * the least rounded down and the greatest up (cbx_add_dn / cbx_add_up
 * with t = 0 pay for the product's rounding). */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi) && \is_finite(b.lo) && \is_finite(b.hi);
    requires rng: iv_rng(a.lo, a.hi, CBX_SB) && iv_rng(b.lo, b.hi, CBX_SB);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, CBX_R19);
    ensures lo: \result.lo <= itmin(a.lo, a.hi, b.lo, b.hi);
    ensures hi: \result.hi >= itmax(a.lo, a.hi, b.lo, b.hi);
    ensures in: iv_prod(\result.lo, \result.hi, a.lo, a.hi, b.lo, b.hi);
    ensures near: \result.lo >= itmin(a.lo, a.hi, b.lo, b.hi) - (CBX_U12 * itmag(a.lo, a.hi, b.lo, b.hi) + CBX_ETA512)
                  && \result.hi <= itmax(a.lo, a.hi, b.lo, b.hi) + (CBX_U12 * itmag(a.lo, a.hi, b.lo, b.hi) + CBX_ETA512);
*/
static inline cbx_iv iv_mul(cbx_iv a, cbx_iv b)
{
    double p0 = cbx_mul_rn(a.lo, b.lo);
    double p1 = cbx_mul_rn(a.lo, b.hi);
    double p2 = cbx_mul_rn(a.hi, b.lo);
    double p3 = cbx_mul_rn(a.hi, b.hi);
    double m = cbx_min2(cbx_min2(p0, p1), cbx_min2(p2, p3));
    double n = cbx_max2(cbx_max2(p0, p1), cbx_max2(p2, p3));
    cbx_iv r;
    /*@ assert mag: \abs(m) <= itmag(a.lo, a.hi, b.lo, b.hi) * (1 + CBX_U) + CBX_ETA
                    && \abs(n) <= itmag(a.lo, a.hi, b.lo, b.hi) * (1 + CBX_U) + CBX_ETA; */
    r.lo = cbx_add_dn(m, 0.0);
    r.hi = cbx_add_up(n, 0.0);
    /*@ assert c0: r.lo <= a.lo * b.lo && r.hi >= a.lo * b.lo; */
    /*@ assert c1: r.lo <= a.lo * b.hi && r.hi >= a.lo * b.hi; */
    /*@ assert c2: r.lo <= a.hi * b.lo && r.hi >= a.hi * b.lo; */
    /*@ assert c3: r.lo <= a.hi * b.hi && r.hi >= a.hi * b.hi; */
    /*@ assert ends: r.lo <= itmin(a.lo, a.hi, b.lo, b.hi) && r.hi >= itmax(a.lo, a.hi, b.lo, b.hi); */
    return r;
}

/* {x^2 : x in a}; lo >= 0. */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi);
    requires rng: iv_rng(a.lo, a.hi, CBX_SB);
    requires ord: a.lo <= a.hi;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: 0 <= \result.lo && \result.hi <= CBX_R19;
    ensures lo: \result.lo <= sqmin(a.lo, a.hi);
    ensures hi: \result.hi >= sqmax(a.lo, a.hi);
    ensures in: iv_sq(\result.lo, \result.hi, a.lo, a.hi);
    ensures near: \result.lo >= sqmin(a.lo, a.hi) * (1 - CBX_U12) - CBX_ETA512
                  && \result.hi <= sqmax(a.lo, a.hi) * (1 + CBX_U12) + CBX_ETA512;
*/
static inline cbx_iv iv_sqr(cbx_iv a)
{
    double l2 = cbx_mul_rn(a.lo, a.lo);
    double h2 = cbx_mul_rn(a.hi, a.hi);
    cbx_iv r;
    /*@ assert p: sqp(a.lo) && sqp(a.hi) && sqm(a.lo, a.hi) && sqm(-a.hi, -a.lo); */
    if (a.lo >= 0.0) {
        /*@ assert e: sqmin(a.lo, a.hi) == a.lo * a.lo && sqmax(a.lo, a.hi) == a.hi * a.hi; */
        r.lo = cbx_add_dn(l2, 0.0);
        r.hi = cbx_add_up(h2, 0.0);
    } else if (a.hi <= 0.0) {
        /*@ assert e: sqmin(a.lo, a.hi) == a.hi * a.hi && sqmax(a.lo, a.hi) == a.lo * a.lo; */
        r.lo = cbx_add_dn(h2, 0.0);
        r.hi = cbx_add_up(l2, 0.0);
    } else {
        /*@ assert e: sqmin(a.lo, a.hi) == 0 && sqmax(a.lo, a.hi) == \max(a.lo * a.lo, a.hi * a.hi); */
        r.lo = 0.0;
        r.hi = cbx_add_up(cbx_max2(l2, h2), 0.0);
    }
    r.lo = cbx_max2(r.lo, 0.0);
    /*@ assert ends: r.lo <= sqmin(a.lo, a.hi) && r.hi >= sqmax(a.lo, a.hi); */
    return r;
}

/* {sqrt(x) : x in a, x >= 0}, stated squared: every y >= 0 with y^2 in a
 * lies in the result; a.hi >= 0. */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi);
    requires rng: a.lo <= CBX_R21 && 0 <= a.hi <= CBX_R21;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures pos: 0 <= \result.lo;
    ensures in: iv_root(\result.lo, \result.hi, a.lo, a.hi);
    ensures near: \max(a.lo, 0) <= (\result.lo * (1 + CBX_U16) + CBX_ETA512) * (\result.lo * (1 + CBX_U16) + CBX_ETA512)
                  && (\result.hi <= CBX_ETA512
                      || (\result.hi - CBX_ETA512) * (\result.hi - CBX_ETA512) <= a.hi * (1 + CBX_U16 + CBX_U8));
*/
static inline cbx_iv iv_sqrt(cbx_iv a)
{
    double x = cbx_max2(a.lo, 0.0);
    double sl = cbx_sqrt_rn(x);
    double sh = cbx_sqrt_rn(a.hi);
    double dl;
    cbx_iv r;
    /*@ assert sr: sl*sl <= 0x1p511*0x1p511 && sh*sh <= 0x1p511*0x1p511; */
    /*@ assert sq: sql(sl, 0x1p511) && sql(sh, 0x1p511); */
    /*@ assert sm: sl <= 0x1p511 && sh <= 0x1p511; */
    dl = cbx_add_dn(sl, 0.0);
    r.lo = cbx_max2(dl, 0.0);
    r.hi = cbx_add_up(sh, 0.0);
    /*@ assert h1: 0 <= sh * (1 + CBX_U3) <= r.hi; */
    /*@ assert h15: sqm(sh * (1 + CBX_U3), r.hi); */
    /*@ assert h2: (sh * (1 + CBX_U3)) * (sh * (1 + CBX_U3)) <= r.hi * r.hi; */
    /*@ assert h3: a.hi <= r.hi * r.hi; */
    /*@ assert l1: r.lo > 0 ==> 0 <= r.lo <= sl * (1 - CBX_U3); */
    /*@ assert l15: sqm(r.lo, sl * (1 - CBX_U3)); */
    /*@ assert l2: r.lo > 0 ==> r.lo * r.lo <= (sl * (1 - CBX_U3)) * (sl * (1 - CBX_U3)); */
    /*@ assert l3: r.lo <= 0 || r.lo * r.lo <= a.lo; */
    /*@ assert n1: 0 <= sl * (1 + CBX_U2) <= r.lo * (1 + CBX_U16) + CBX_ETA512; */
    /*@ assert n2: x <= (sl * (1 + CBX_U2)) * (sl * (1 + CBX_U2)); */
    /*@ assert n25: sqm(sl * (1 + CBX_U2), r.lo * (1 + CBX_U16) + CBX_ETA512); */
    /*@ assert n3: (sl * (1 + CBX_U2)) * (sl * (1 + CBX_U2))
                   <= (r.lo * (1 + CBX_U16) + CBX_ETA512) * (r.lo * (1 + CBX_U16) + CBX_ETA512); */
    /*@ assert n4: r.hi > CBX_ETA512 ==> 0 <= r.hi - CBX_ETA512 <= sh * (1 + CBX_U8); */
    /*@ assert n45: sqm(r.hi - CBX_ETA512, sh * (1 + CBX_U8)); */
    /*@ assert n5: r.hi > CBX_ETA512 ==> (r.hi - CBX_ETA512) * (r.hi - CBX_ETA512)
                                        <= (sh * (1 + CBX_U8)) * (sh * (1 + CBX_U8)); */
    return r;
}

/* {x / y : x in a, y in b}, stated multiplied out: lo y <= x <= hi y;
 * b.lo > 0 and the quotients in range (|a| <= 2^1002 b.lo). */
/*@ requires fin: \is_finite(a.lo) && \is_finite(a.hi) && \is_finite(b.lo) && \is_finite(b.hi);
    requires pos: CBX_ETA <= b.lo <= b.hi;
    requires rng: \abs(a.lo) <= CBX_QR * b.lo && \abs(a.hi) <= CBX_QR * b.lo;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures in: iv_quot(\result.lo, \result.hi, a.lo, a.hi, b.lo, b.hi);
    ensures near: (a.lo >= 0 ==> a.lo - \result.lo * b.hi <= CBX_U8 * a.lo + CBX_ETA16 * b.hi)
                  && (a.lo < 0 ==> a.lo - \result.lo * b.lo <= CBX_U8 * \abs(a.lo) + CBX_ETA16 * b.lo)
                  && (a.hi >= 0 ==> \result.hi * b.lo - a.hi <= CBX_U8 * a.hi + CBX_ETA16 * b.lo)
                  && (a.hi < 0 ==> \result.hi * b.hi - a.hi <= CBX_U8 * \abs(a.hi) + CBX_ETA16 * b.hi);
*/
static inline cbx_iv iv_div(cbx_iv a, cbx_iv b)
{
    double lo;
    double hi;
    cbx_iv r;
    if (a.lo >= 0.0) {
        lo = cbx_div_dn(a.lo, b.hi);
    } else {
        lo = cbx_div_dn(a.lo, b.lo);
    }
    if (a.hi >= 0.0) {
        hi = cbx_div_up(a.hi, b.lo);
    } else {
        hi = cbx_div_up(a.hi, b.hi);
    }
    /*@ assert m: mono(lo, b.lo, b.hi) && msign(lo, b.lo) && mono(hi, b.lo, b.hi) && msign(hi, b.lo); */
    /*@ assert q: lo * b.lo <= a.lo && lo * b.hi <= a.lo && a.hi <= hi * b.lo && a.hi <= hi * b.hi; */
    r.lo = lo;
    r.hi = hi;
    return r;
}

/* {x0 + s (x1 - x0) : s in [a, b]} (0 <= a <= b <= 1): the values of a
 * linear path (a keyframe's translation or scale) over part of it, the
 * hull of the two ends' enclosures. */
/*@ requires fin: \is_finite(x0) && \is_finite(x1) && \is_finite(a) && \is_finite(b);
    requires rng: \abs(x0) <= CBX_SB / 4 && \abs(x1) <= CBX_SB / 4;
    requires s: 0 <= a <= b <= 1;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures in: lerp_in(\result.lo, \result.hi, x0, x1 - x0, a, b);
    ensures near: \result.lo >= lerp_lo(x0, x1, a, b) - lerp_err(x0, x1) && \result.hi <= lerp_hi(x0, x1, a, b) + lerp_err(x0, x1);
*/
static inline cbx_iv iv_lerp(double x0, double x1, double a, double b)
{
    cbx_iv d;
    cbx_iv pa;
    cbx_iv pb;
    cbx_iv va;
    cbx_iv vb;
    d.lo = cbx_add_dn(x1, -x0);
    d.hi = cbx_add_up(x1, -x0);
    /*@ assert d: x1 - x0 - (CBX_U8 * (\abs(x0) + \abs(x1)) + CBX_ETA512) <= d.lo <= x1 - x0
                  <= d.hi <= x1 - x0 + (CBX_U8 * (\abs(x0) + \abs(x1)) + CBX_ETA512); */
    pa = iv_mul(iv_pt(a), d);
    pb = iv_mul(iv_pt(b), d);
    /*@ assert pa: iv_prod(pa.lo, pa.hi, a, a, d.lo, d.hi) && iv_prod(pb.lo, pb.hi, b, b, d.lo, d.hi); */
    /*@ assert at: prod_at(pa.lo, pa.hi, a, x1 - x0) && prod_at(pb.lo, pb.hi, b, x1 - x0); */
    /*@ assert pd: pa.lo <= a * (x1 - x0) <= pa.hi && pb.lo <= b * (x1 - x0) <= pb.hi; */
    /*@ assert near: pt_prod_near(a, x1 - x0, (CBX_U8 * (\abs(x0) + \abs(x1)) + CBX_ETA512), d.lo, d.hi)
                     && pt_prod_near(b, x1 - x0, (CBX_U8 * (\abs(x0) + \abs(x1)) + CBX_ETA512), d.lo, d.hi); */
    va = iv_add(pa, iv_pt(x0)); /* pa first: cbx_add_dn's wider argument */
    vb = iv_add(pb, iv_pt(x0));
    /*@ assert v: va.lo <= x0 + a * (x1 - x0) <= va.hi && vb.lo <= x0 + b * (x1 - x0) <= vb.hi; */
    /*@ assert va: va.lo >= x0 + a * (x1 - x0) - lerp_err(x0, x1) && va.hi <= x0 + a * (x1 - x0) + lerp_err(x0, x1); */
    /*@ assert vb: vb.lo >= x0 + b * (x1 - x0) - lerp_err(x0, x1) && vb.hi <= x0 + b * (x1 - x0) + lerp_err(x0, x1); */
    return iv_hull(va, vb);
}

#endif /* CBX_IV_H */
