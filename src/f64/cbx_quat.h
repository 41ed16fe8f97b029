/*
 * Boxes of quaternions, binary64 (the rotation motion of src/f64/cbx_trs.c):
 * the rotation matrix of every unit quaternion of a box, as an interval
 * per entry.  The contract states it in exact reals for every unit
 * quaternion (x, y, z, w) of the box (specs/cbx_quat_logic.h: rot00 ..
 * rot22); each entry is the interval evaluation of its formula through
 * src/f64/cbx_iv.h, cut to [-1, 1] (where every entry of a rotation lies).
 * Proven in job T64 (proofs/trs.c).
 */
#ifndef CBX_QUAT_H
#define CBX_QUAT_H

#include "cbx_iv.h"
#ifdef __FRAMAC__
#include "cbx_quat_logic.h"
#endif

/* A box of R^4 (a quaternion known up to an interval per component). */
typedef struct trs_q { cbx_iv c[4]; } trs_q;

/* Intervals for the nine entries of rotation matrices. */
typedef struct trs_rot { cbx_iv e[3][3]; } trs_rot;

/*@ // (x, y, z, w) lies in the box q
    predicate q_has(trs_q q, real x, real y, real z, real w) =
      iv_has(q.c[0].lo, q.c[0].hi, x) && iv_has(q.c[1].lo, q.c[1].hi, y)
      && iv_has(q.c[2].lo, q.c[2].hi, z) && iv_has(q.c[3].lo, q.c[3].hi, w);
    // finite ends in [-1, 1] (a component of a unit quaternion's box)
    predicate iv_ok1(cbx_iv a) = \is_finite(a.lo) && \is_finite(a.hi) && iv_rng(a.lo, a.hi, 1);
    // an entry cut to [-1, 1]: finite, lo >= -1, hi <= 1 (lo > hi, an
    // empty entry, only where the formula's enclosure is above 1 or below
    // -1, which no unit quaternion's entry is)
    predicate iv_cut(cbx_iv a) = \is_finite(a.lo) && \is_finite(a.hi) && -1 <= a.lo && a.hi <= 1
                                 && iv_rng(a.lo, a.hi, 32);
    // the exact ends of the dot product's interval form over boxes q, r
    logic real qdot_lo(trs_q q, trs_q r) =
      itmin(q.c[0].lo, q.c[0].hi, r.c[0].lo, r.c[0].hi) + itmin(q.c[1].lo, q.c[1].hi, r.c[1].lo, r.c[1].hi)
      + itmin(q.c[2].lo, q.c[2].hi, r.c[2].lo, r.c[2].hi) + itmin(q.c[3].lo, q.c[3].hi, r.c[3].lo, r.c[3].hi);
    logic real qdot_hi(trs_q q, trs_q r) =
      itmax(q.c[0].lo, q.c[0].hi, r.c[0].lo, r.c[0].hi) + itmax(q.c[1].lo, q.c[1].hi, r.c[1].lo, r.c[1].hi)
      + itmax(q.c[2].lo, q.c[2].hi, r.c[2].lo, r.c[2].hi) + itmax(q.c[3].lo, q.c[3].hi, r.c[3].lo, r.c[3].hi);
    // every component finite, in [-1, 1] and ordered
    predicate q_unit_box(trs_q q) =
      iv_ok1(q.c[0]) && iv_ok1(q.c[1]) && iv_ok1(q.c[2]) && iv_ok1(q.c[3])
      && q.c[0].lo <= q.c[0].hi && q.c[1].lo <= q.c[1].hi && q.c[2].lo <= q.c[2].hi && q.c[3].lo <= q.c[3].hi;
*/

/* A diagonal entry 1 - 2 t for t in s (a sum of two squares), rounded
 * outward, cut to [-1, 1]. */
/*@ requires fin: \is_finite(s.lo) && \is_finite(s.hi);
    requires rng: iv_rng(s.lo, s.hi, 8);
    assigns \nothing;
    ensures fin: iv_cut(\result);
    ensures lo: \result.lo <= \max(1 - 2*s.hi, -1);
    ensures hi: \result.hi >= \min(1 - 2*s.lo, 1);
    ensures near: \result.lo >= \max(1 - 2*s.hi - (CBX_U12 * (1 + 2*\abs(s.hi)) + CBX_ETA512), -1)
                  && \result.hi <= \min(1 - 2*s.lo + (CBX_U12 * (1 + 2*\abs(s.lo)) + CBX_ETA512), 1);
*/
static inline cbx_iv rot_diag(cbx_iv s)
{
    cbx_iv e;
    /* the product first: cbx_add_dn pays for its first argument's rounding */
    e.lo = cbx_add_dn(cbx_mul_rn(-2.0, s.hi), 1.0);
    e.hi = cbx_add_up(cbx_mul_rn(-2.0, s.lo), 1.0);
    return iv_unit(e);
}

/* An off-diagonal entry 2 t for t in d, rounded outward (d.lo + d.lo
 * rounded down, d.hi + d.hi up), cut to [-1, 1]. */
/*@ requires fin: \is_finite(d.lo) && \is_finite(d.hi);
    requires rng: iv_rng(d.lo, d.hi, 8);
    assigns \nothing;
    ensures fin: iv_cut(\result);
    ensures lo: \result.lo <= \max(2*d.lo, -1);
    ensures hi: \result.hi >= \min(2*d.hi, 1);
    ensures near: \result.lo >= \max(2*d.lo - (CBX_U16 * \abs(d.lo) + CBX_ETA512), -1)
                  && \result.hi <= \min(2*d.hi + (CBX_U16 * \abs(d.hi) + CBX_ETA512), 1);
*/
static inline cbx_iv rot_off(cbx_iv d)
{
    cbx_iv e;
    e.lo = cbx_add_dn(d.lo, d.lo);
    e.hi = cbx_add_up(d.hi, d.hi);
    return iv_unit(e);
}

/* The entry 1 - 2 (p^2 + q^2) for every p in a, q in b (where it lies in
 * [-1, 1], as for a unit quaternion). */
/*@ requires fin: iv_ok1(a) && iv_ok1(b) && a.lo <= a.hi && b.lo <= b.hi;
    assigns \nothing;
    ensures fin: iv_cut(\result);
    ensures in: \forall real p, q; iv_has(a.lo, a.hi, p) && iv_has(b.lo, b.hi, q)
                  && -1 <= 1 - 2*(p*p + q*q) <= 1
                  ==> iv_has(\result.lo, \result.hi, 1 - 2*(p*p + q*q));
*/
static inline cbx_iv rot_sq(cbx_iv a, cbx_iv b)
{
    cbx_iv aa = iv_sqr(a);
    cbx_iv bb = iv_sqr(b);
    cbx_iv t = iv_add(aa, bb);
    cbx_iv r = rot_diag(t);
    /*@ assert s1: \forall real p; iv_has(a.lo, a.hi, p) ==> sq_at(aa.lo, aa.hi, p); */
    /*@ assert s2: \forall real q; iv_has(b.lo, b.hi, q) ==> sq_at(bb.lo, bb.hi, q); */
    /*@ assert s3: \forall real u, v; aa.lo <= u <= aa.hi && bb.lo <= v <= bb.hi && -1 <= 1 - 2*(u + v) <= 1
                     ==> r.lo <= 1 - 2*(u + v) <= r.hi; */
    return r;
}

/* The entry 2 (u + v) for every u in ab and v in cd (products of
 * components, the second negated for a difference), where it lies in
 * [-1, 1]. */
/*@ requires fin: \is_finite(ab.lo) && \is_finite(ab.hi) && \is_finite(cd.lo) && \is_finite(cd.hi);
    requires rng: iv_rng(ab.lo, ab.hi, 2) && iv_rng(cd.lo, cd.hi, 2);
    assigns \nothing;
    ensures fin: iv_cut(\result);
    ensures in: \forall real u, v; iv_has(ab.lo, ab.hi, u) && iv_has(cd.lo, cd.hi, v) && -1 <= pq2(u, v) <= 1
                  ==> iv_has(\result.lo, \result.hi, pq2(u, v));
*/
static inline cbx_iv rot_pq(cbx_iv ab, cbx_iv cd)
{
    return rot_off(iv_add(ab, cd));
}

/* The rotation matrix of every unit quaternion (x, y, z, w) of the box:
 * R = I - 2 [[y2+z2, zw-xy, -(xz+yw)], ...] written entry by entry. */
/*@ requires q: \valid_read(q) && q_unit_box(*q);
    assigns \nothing;
    ensures fin: iv_cut(\result.e[0][0]) && iv_cut(\result.e[0][1]) && iv_cut(\result.e[0][2])
                 && iv_cut(\result.e[1][0]) && iv_cut(\result.e[1][1]) && iv_cut(\result.e[1][2])
                 && iv_cut(\result.e[2][0]) && iv_cut(\result.e[2][1]) && iv_cut(\result.e[2][2]);
    ensures e00: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[0][0].lo, \result.e[0][0].hi, rot00(x, y, z, w));
    ensures e01: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[0][1].lo, \result.e[0][1].hi, rot01(x, y, z, w));
    ensures e02: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[0][2].lo, \result.e[0][2].hi, rot02(x, y, z, w));
    ensures e10: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[1][0].lo, \result.e[1][0].hi, rot10(x, y, z, w));
    ensures e11: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[1][1].lo, \result.e[1][1].hi, rot11(x, y, z, w));
    ensures e12: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[1][2].lo, \result.e[1][2].hi, rot12(x, y, z, w));
    ensures e20: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[2][0].lo, \result.e[2][0].hi, rot20(x, y, z, w));
    ensures e21: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[2][1].lo, \result.e[2][1].hi, rot21(x, y, z, w));
    ensures e22: \forall real x, y, z, w; q_has(*q, x, y, z, w) && unitq(x, y, z, w)
                   ==> iv_has(\result.e[2][2].lo, \result.e[2][2].hi, rot22(x, y, z, w));
*/
static inline trs_rot q_rotation(const trs_q *q)
{
    cbx_iv x = q->c[0];
    cbx_iv y = q->c[1];
    cbx_iv z = q->c[2];
    cbx_iv w = q->c[3];
    cbx_iv xy = iv_mul(x, y);
    cbx_iv xz = iv_mul(x, z);
    cbx_iv yz = iv_mul(y, z);
    cbx_iv xw = iv_mul(x, w);
    cbx_iv yw = iv_mul(y, w);
    cbx_iv zw = iv_mul(z, w);
    trs_rot r;
    /*@ assert p: \forall real x0, x1, x2, x3; q_has(*q, x0, x1, x2, x3) ==>
                    prod_at(xy.lo, xy.hi, x0, x1) && prod_at(xz.lo, xz.hi, x0, x2) && prod_at(yz.lo, yz.hi, x1, x2)
                    && prod_at(xw.lo, xw.hi, x0, x3) && prod_at(yw.lo, yw.hi, x1, x3) && prod_at(zw.lo, zw.hi, x2, x3); */
    r.e[0][0] = rot_sq(y, z);
    r.e[1][1] = rot_sq(x, z);
    r.e[2][2] = rot_sq(x, y);
    r.e[0][1] = rot_pq(xy, iv_neg(zw));
    r.e[0][2] = rot_pq(xz, yw);
    r.e[1][0] = rot_pq(xy, zw);
    r.e[1][2] = rot_pq(yz, iv_neg(xw));
    r.e[2][0] = rot_pq(xz, iv_neg(yw));
    r.e[2][1] = rot_pq(yz, xw);
    return r;
}

/* The dot product x.y of every x of box a and every y of box b (the
 * keyframes' quaternions: its sign picks the shorter arc). */
/*@ requires a: \valid_read(a) && q_unit_box(*a);
    requires b: \valid_read(b) && q_unit_box(*b);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures in: \forall real x0, x1, x2, x3, y0, y1, y2, y3;
                  q_has(*a, x0, x1, x2, x3) && q_has(*b, y0, y1, y2, y3)
                  ==> iv_has(\result.lo, \result.hi, x0*y0 + x1*y1 + x2*y2 + x3*y3);
    ensures near: \result.lo >= qdot_lo(*a, *b) - 0x1p-45 && \result.hi <= qdot_hi(*a, *b) + 0x1p-45;
*/
static inline cbx_iv q_dot(const trs_q *a, const trs_q *b)
{
    cbx_iv p0 = iv_mul(a->c[0], b->c[0]);
    cbx_iv p1 = iv_mul(a->c[1], b->c[1]);
    cbx_iv p2 = iv_mul(a->c[2], b->c[2]);
    cbx_iv p3 = iv_mul(a->c[3], b->c[3]);
    cbx_iv s01;
    cbx_iv s23;
    /*@ assert one: iv_rng(a->c[0].lo, a->c[0].hi, 1) && iv_rng(b->c[0].lo, b->c[0].hi, 1)
                    && iv_rng(a->c[1].lo, a->c[1].hi, 1) && iv_rng(b->c[1].lo, b->c[1].hi, 1)
                    && iv_rng(a->c[2].lo, a->c[2].hi, 1) && iv_rng(b->c[2].lo, b->c[2].hi, 1)
                    && iv_rng(a->c[3].lo, a->c[3].hi, 1) && iv_rng(b->c[3].lo, b->c[3].hi, 1); */
    /*@ assert rng: iv_rng(p0.lo, p0.hi, 2) && iv_rng(p1.lo, p1.hi, 2) && iv_rng(p2.lo, p2.hi, 2) && iv_rng(p3.lo, p3.hi, 2); */
    /*@ assert p: \forall real x0, x1, x2, x3, y0, y1, y2, y3;
                    q_has(*a, x0, x1, x2, x3) && q_has(*b, y0, y1, y2, y3) ==>
                    prod_at(p0.lo, p0.hi, x0, y0) && prod_at(p1.lo, p1.hi, x1, y1)
                    && prod_at(p2.lo, p2.hi, x2, y2) && prod_at(p3.lo, p3.hi, x3, y3); */
    s01 = iv_add(p0, p1);
    s23 = iv_add(p2, p3);
    /*@ assert srng: iv_rng(s01.lo, s01.hi, 8) && iv_rng(s23.lo, s23.hi, 8); */
    /*@ assert s: \forall real x0, x1, x2, x3, y0, y1, y2, y3;
                    q_has(*a, x0, x1, x2, x3) && q_has(*b, y0, y1, y2, y3) ==>
                    iv_has(s01.lo, s01.hi, x0*y0 + x1*y1) && iv_has(s23.lo, s23.hi, x2*y2 + x3*y3); */
    return iv_add(s01, s23);
}

#endif /* CBX_QUAT_H */
