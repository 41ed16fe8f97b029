/*
 * Boxes of quaternions, binary64 (the rotation motion of src/f64/cbx_trs.c):
 * the rotation matrix of every unit quaternion of a box, as an interval
 * per entry.  The contract states it in exact reals for every unit
 * quaternion (x, y, z, w) of the box (specs/cbx_quat_logic.h: rot00 ..
 * rot22); each entry is the interval evaluation of its formula through
 * src/f64/cbx_iv.h, cut to [-1, 1] (where every entry of a rotation lies).
 * Also the quaternion path's steps: normalisation (every unit u with a
 * positive multiple in the box), sums, negation, hulls, nlerp's blend,
 * and the box of the shorter great arc between two boxes (every unit
 * l p + m r, l, m >= 0: specs/cbx_quat_logic.h, arc_pt, lemma arc_lo).
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
    // every component finite, within [-m, m] and ordered
    predicate q_rng(trs_q q, real m) =
      \is_finite(q.c[0].lo) && \is_finite(q.c[0].hi) && \is_finite(q.c[1].lo) && \is_finite(q.c[1].hi)
      && \is_finite(q.c[2].lo) && \is_finite(q.c[2].hi) && \is_finite(q.c[3].lo) && \is_finite(q.c[3].hi)
      && iv_rng(q.c[0].lo, q.c[0].hi, m) && iv_rng(q.c[1].lo, q.c[1].hi, m)
      && iv_rng(q.c[2].lo, q.c[2].hi, m) && iv_rng(q.c[3].lo, q.c[3].hi, m)
      && q.c[0].lo <= q.c[0].hi && q.c[1].lo <= q.c[1].hi && q.c[2].lo <= q.c[2].hi && q.c[3].lo <= q.c[3].hi;
    // k (x, y, z, w) lies in the box q (a multiple of a unit vector)
    predicate q_sc_has(trs_q q, real k, real x, real y, real z, real w) =
      sc_has(q.c[0].lo, q.c[0].hi, x, k) && sc_has(q.c[1].lo, q.c[1].hi, y, k)
      && sc_has(q.c[2].lo, q.c[2].hi, z, k) && sc_has(q.c[3].lo, q.c[3].hi, w, k);
    // the component l p + m r of a point of the arc from p in a to r in b
    // (c = p.r, 1 + c in den)
    // k (x, y, z, w) = (q0, q1, q2, q3)
    predicate q_mul(real k, real x, real y, real z, real w, real q0, real q1, real q2, real q3) =
      k*x == q0 && k*y == q1 && k*z == q2 && k*w == q3;
    // u p + v q with each factor in its interval (nlerp's blend)
    predicate blend_in(cbx_iv w0, cbx_iv w1, cbx_iv x, cbx_iv y, real u, real v, real p, real q) =
      iv_has(w0.lo, w0.hi, u) && iv_has(w1.lo, w1.hi, v) && iv_has(x.lo, x.hi, p) && iv_has(y.lo, y.hi, q);
    predicate arc_in(cbx_iv a, cbx_iv b, cbx_iv den, real p, real r, real c, real l, real m) =
      iv_has(a.lo, a.hi, p) && iv_has(b.lo, b.hi, r) && iv_has(den.lo, den.hi, 1 + c)
      && arc_ok(l, m, c) && -1 <= l*p + m*r <= 1;
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

/* ---- the quaternion path's steps ----------------------------------------- */

/* {x + y : x in a, y in b}, component by component. */
/*@ requires a: \valid_read(a) && q_unit_box(*a);
    requires b: \valid_read(b) && q_unit_box(*b);
    assigns \nothing;
    ensures rng: q_rng(\result, 4);
    ensures in: \forall real x0, x1, x2, x3, y0, y1, y2, y3;
                  q_has(*a, x0, x1, x2, x3) && q_has(*b, y0, y1, y2, y3)
                  ==> q_has(\result, x0 + y0, x1 + y1, x2 + y2, x3 + y3);
*/
static inline trs_q q_add(const trs_q *a, const trs_q *b)
{
    trs_q r;
    r.c[0] = iv_add(a->c[0], b->c[0]);
    r.c[1] = iv_add(a->c[1], b->c[1]);
    r.c[2] = iv_add(a->c[2], b->c[2]);
    r.c[3] = iv_add(a->c[3], b->c[3]);
    return r;
}

/* {-x : x in a}, exact. */
/*@ requires a: \valid_read(a) && q_unit_box(*a);
    assigns \nothing;
    ensures unit: q_unit_box(\result);
    ensures in: \forall real x0, x1, x2, x3; q_has(*a, x0, x1, x2, x3) ==> q_has(\result, -x0, -x1, -x2, -x3);
*/
static inline trs_q q_neg(const trs_q *a)
{
    trs_q r;
    r.c[0] = iv_neg(a->c[0]);
    r.c[1] = iv_neg(a->c[1]);
    r.c[2] = iv_neg(a->c[2]);
    r.c[3] = iv_neg(a->c[3]);
    return r;
}

/* The box of two boxes. */
/*@ requires a: \valid_read(a) && q_unit_box(*a);
    requires b: \valid_read(b) && q_unit_box(*b);
    assigns \nothing;
    ensures unit: q_unit_box(\result);
    ensures in: \forall real x0, x1, x2, x3;
                  q_has(*a, x0, x1, x2, x3) || q_has(*b, x0, x1, x2, x3) ==> q_has(\result, x0, x1, x2, x3);
*/
static inline trs_q q_hull(const trs_q *a, const trs_q *b)
{
    trs_q r;
    r.c[0] = iv_hull(a->c[0], b->c[0]);
    r.c[1] = iv_hull(a->c[1], b->c[1]);
    r.c[2] = iv_hull(a->c[2], b->c[2]);
    r.c[3] = iv_hull(a->c[3], b->c[3]);
    return r;
}

/* u p + v q for u in w0, v in w1, p in x, q in y: one component of
 * nlerp's blend (w0 holding 1 - s, w1 = s). */
/*@ requires w0: \is_finite(w0.lo) && \is_finite(w0.hi) && iv_rng(w0.lo, w0.hi, 2) && w0.lo <= w0.hi;
    requires w1: \is_finite(w1.lo) && \is_finite(w1.hi) && iv_rng(w1.lo, w1.hi, 1) && w1.lo <= w1.hi;
    requires x: iv_ok1(x) && x.lo <= x.hi;
    requires y: iv_ok1(y) && y.lo <= y.hi;
    assigns \nothing;
    ensures rng: \is_finite(\result.lo) && \is_finite(\result.hi) && iv_rng(\result.lo, \result.hi, 4)
                 && \result.lo <= \result.hi;
    ensures in: \forall real u, v, p, q; blend_in(w0, w1, x, y, u, v, p, q)
                  ==> iv_has(\result.lo, \result.hi, u*p + v*q);
*/
static inline cbx_iv blend_comp(cbx_iv w0, cbx_iv w1, cbx_iv x, cbx_iv y)
{
    cbx_iv p0 = iv_mul(w0, x);
    cbx_iv p1 = iv_mul(w1, y);
    /*@ assert m: itmag(w0.lo, w0.hi, x.lo, x.hi) <= 2 && -2 <= itmin(w0.lo, w0.hi, x.lo, x.hi)
                  && itmax(w0.lo, w0.hi, x.lo, x.hi) <= 2
                  && itmag(w1.lo, w1.hi, y.lo, y.hi) <= 1 && -1 <= itmin(w1.lo, w1.hi, y.lo, y.hi)
                  && itmax(w1.lo, w1.hi, y.lo, y.hi) <= 1; */
    /*@ assert r: iv_rng(p0.lo, p0.hi, 2.25) && iv_rng(p1.lo, p1.hi, 1.125); */
    /*@ assert p: \forall real u, v, p, q; blend_in(w0, w1, x, y, u, v, p, q)
                    ==> prod_at(p0.lo, p0.hi, u, p) && prod_at(p1.lo, p1.hi, v, q); */
    /*@ assert o: blend_in(w0, w1, x, y, w0.lo, w1.lo, x.lo, y.lo); */
    return iv_add(p0, p1);
}

/* (1 - s) x + s y for every x of *a and y of *b (s in [0, 1]): nlerp's
 * blend before it is normalised. */
/*@ requires a: \valid_read(a) && q_unit_box(*a);
    requires b: \valid_read(b) && q_unit_box(*b);
    requires s: \is_finite(s) && 0 <= s <= 1;
    assigns \nothing;
    ensures rng: q_rng(\result, 4);
    ensures in: \forall real x0, x1, x2, x3, y0, y1, y2, y3;
                  q_has(*a, x0, x1, x2, x3) && q_has(*b, y0, y1, y2, y3)
                  ==> q_has(\result, (1 - s)*x0 + s*y0, (1 - s)*x1 + s*y1, (1 - s)*x2 + s*y2, (1 - s)*x3 + s*y3);
*/
static inline trs_q q_blend(const trs_q *a, const trs_q *b, double s)
{
    cbx_iv w0 = iv_add(iv_pt(1.0), iv_pt(-s));
    cbx_iv w1 = iv_pt(s);
    trs_q r;
    /*@ assert w: iv_has(w0.lo, w0.hi, 1 - s) && iv_rng(w0.lo, w0.hi, 2) && w0.lo <= w0.hi; */
    /*@ assert bi: \forall real x0, x1, x2, x3, y0, y1, y2, y3;
                     q_has(*a, x0, x1, x2, x3) && q_has(*b, y0, y1, y2, y3)
                     ==> blend_in(w0, w1, a->c[0], b->c[0], 1 - s, s, x0, y0)
                         && blend_in(w0, w1, a->c[1], b->c[1], 1 - s, s, x1, y1)
                         && blend_in(w0, w1, a->c[2], b->c[2], 1 - s, s, x2, y2)
                         && blend_in(w0, w1, a->c[3], b->c[3], 1 - s, s, x3, y3); */
    r.c[0] = blend_comp(w0, w1, a->c[0], b->c[0]);
    r.c[1] = blend_comp(w0, w1, a->c[1], b->c[1]);
    r.c[2] = blend_comp(w0, w1, a->c[2], b->c[2]);
    r.c[3] = blend_comp(w0, w1, a->c[3], b->c[3]);
    return r;
}

/* [-1, 1]^4: every unit vector's box. */
/*@ assigns \nothing;
    ensures unit: q_unit_box(\result);
    ensures in: \forall real x, y, z, w; unitq(x, y, z, w) ==> q_has(\result, x, y, z, w);
*/
static inline trs_q q_whole(void)
{
    trs_q r;
    r.c[0].lo = -1.0;
    r.c[0].hi = 1.0;
    r.c[1] = r.c[0];
    r.c[2] = r.c[0];
    r.c[3] = r.c[0];
    return r;
}

/* x / n for x in a and n in [n.lo, n.hi] (n.lo > 0): a component of a
 * unit vector, so cut to [-1, 1]; ordered even where the quotient's
 * enclosure lies outside [-1, 1] (no unit vector's component is there). */
/*@ requires a: \is_finite(a.lo) && \is_finite(a.hi) && iv_rng(a.lo, a.hi, 0x1p250);
    requires n: \is_finite(n.lo) && \is_finite(n.hi) && 0x1p-600 <= n.lo <= n.hi;
    assigns \nothing;
    ensures ok: iv_ok1(\result) && \result.lo <= \result.hi;
    ensures in: \forall real x, k; -1 <= x <= 1 && sc_has(a.lo, a.hi, x, k) && iv_has(n.lo, n.hi, k)
                  ==> iv_has(\result.lo, \result.hi, x);
*/
static inline cbx_iv unit_quot(cbx_iv a, cbx_iv n)
{
    cbx_iv d = iv_div(a, n);
    cbx_iv r;
    r.lo = cbx_max2(cbx_min2(d.lo, 1.0), -1.0);
    r.hi = cbx_max2(cbx_min2(d.hi, 1.0), r.lo);
    return r;
}

/* Encloses v / |v| for every v != 0 of the box: every unit u with a
 * positive multiple k u in *v lies in the result.  Where |v| is not
 * clearly positive over the box (below 2^-600, or its enclosure not
 * ordered), the whole [-1, 1]^4. */
/*@ requires v: \valid_read(v) && q_rng(*v, 0x1p250);
    assigns \nothing;
    ensures unit: q_unit_box(\result);
    ensures in: \forall real x, y, z, w, k; 0 < k && unitq(x, y, z, w) && q_sc_has(*v, k, x, y, z, w)
                  ==> q_has(\result, x, y, z, w);
*/
static inline trs_q q_normalise(const trs_q *v)
{
    cbx_iv s0;
    cbx_iv s1;
    cbx_iv s2;
    cbx_iv s3;
    cbx_iv t01;
    cbx_iv t23;
    cbx_iv n2;
    cbx_iv n;
    trs_q r;
    /*@ assert sm: sqm(v->c[0].lo, 0x1p250) && sqm(-v->c[0].lo, 0x1p250) && sqm(v->c[0].hi, 0x1p250) && sqm(-v->c[0].hi, 0x1p250)
                   && sqm(v->c[1].lo, 0x1p250) && sqm(-v->c[1].lo, 0x1p250) && sqm(v->c[1].hi, 0x1p250) && sqm(-v->c[1].hi, 0x1p250)
                   && sqm(v->c[2].lo, 0x1p250) && sqm(-v->c[2].lo, 0x1p250) && sqm(v->c[2].hi, 0x1p250) && sqm(-v->c[2].hi, 0x1p250)
                   && sqm(v->c[3].lo, 0x1p250) && sqm(-v->c[3].lo, 0x1p250) && sqm(v->c[3].hi, 0x1p250) && sqm(-v->c[3].hi, 0x1p250); */
    /*@ assert sx0: sqmax(v->c[0].lo, v->c[0].hi) <= 0x1p500; */
    /*@ assert sx1: sqmax(v->c[1].lo, v->c[1].hi) <= 0x1p500; */
    /*@ assert sx2: sqmax(v->c[2].lo, v->c[2].hi) <= 0x1p500; */
    /*@ assert sx3: sqmax(v->c[3].lo, v->c[3].hi) <= 0x1p500; */
    s0 = iv_sqr(v->c[0]);
    s1 = iv_sqr(v->c[1]);
    s2 = iv_sqr(v->c[2]);
    s3 = iv_sqr(v->c[3]);
    /*@ assert sr0: sqp(v->c[0].lo) && sqp(v->c[0].hi) && 0 <= s0.hi <= 0x1p501 && s0.lo <= 0x1p501; */
    /*@ assert sr1: sqp(v->c[1].lo) && sqp(v->c[1].hi) && 0 <= s1.hi <= 0x1p501 && s1.lo <= 0x1p501; */
    /*@ assert sr2: sqp(v->c[2].lo) && sqp(v->c[2].hi) && 0 <= s2.hi <= 0x1p501 && s2.lo <= 0x1p501; */
    /*@ assert sr3: sqp(v->c[3].lo) && sqp(v->c[3].hi) && 0 <= s3.hi <= 0x1p501 && s3.lo <= 0x1p501; */
    t01 = iv_add(s0, s1);
    t23 = iv_add(s2, s3);
    /*@ assert tr: 0 <= t01.hi <= 0x1p503 && 0 <= t23.hi <= 0x1p503 && t01.lo <= 0x1p503 && t23.lo <= 0x1p503; */
    n2 = iv_add(t01, t23);
    /*@ assert nr: 0 <= n2.hi <= 0x1p505 && n2.lo <= 0x1p505; */
    /*@ assert sq: \forall real x, y, z, w, k; q_sc_has(*v, k, x, y, z, w)
                     ==> sq_at(s0.lo, s0.hi, k*x) && sq_at(s1.lo, s1.hi, k*y) && sq_at(s2.lo, s2.hi, k*z)
                         && sq_at(s3.lo, s3.hi, k*w); */
    /*@ assert n2s: \forall real x, y, z, w, k; q_sc_has(*v, k, x, y, z, w)
                      ==> iv_has(n2.lo, n2.hi, (k*x)*(k*x) + (k*y)*(k*y) + (k*z)*(k*z) + (k*w)*(k*w)); */
    /*@ assert k2: \forall real x, y, z, w, k; unitq(x, y, z, w) && q_sc_has(*v, k, x, y, z, w)
                     ==> sc_unit(x, y, z, w, k); */
    /*@ assert k3: \forall real x, y, z, w, k; unitq(x, y, z, w) && q_sc_has(*v, k, x, y, z, w)
                     ==> sq_at(n2.lo, n2.hi, k); */
    n = iv_sqrt(n2);
    if (!((n.lo >= 0x1p-600) && (n.hi >= n.lo))) {
        return q_whole();
    }
    /*@ assert nk: \forall real x, y, z, w, k; 0 < k && unitq(x, y, z, w) && q_sc_has(*v, k, x, y, z, w)
                     ==> iv_has(n.lo, n.hi, k); */
    r.c[0] = unit_quot(v->c[0], n);
    r.c[1] = unit_quot(v->c[1], n);
    r.c[2] = unit_quot(v->c[2], n);
    r.c[3] = unit_quot(v->c[3], n);
    return r;
}

/* q / |q| for a quaternion q of doubles (a keyframe's rotation; not 0):
 * every unit u with a positive multiple equal to q lies in the result. */
/*@ requires q: \valid_read(q + (0 .. 3));
    requires rng: \is_finite(q[0]) && \is_finite(q[1]) && \is_finite(q[2]) && \is_finite(q[3])
                  && \abs(q[0]) <= 0x1p250 && \abs(q[1]) <= 0x1p250 && \abs(q[2]) <= 0x1p250
                  && \abs(q[3]) <= 0x1p250;
    assigns \nothing;
    ensures unit: q_unit_box(\result);
    ensures in: \forall real x, y, z, w, k; 0 < k && unitq(x, y, z, w) && q_mul(k, x, y, z, w, q[0], q[1], q[2], q[3])
                  ==> q_has(\result, x, y, z, w);
*/
static inline trs_q q_unit_of(const double q[4])
{
    trs_q v;
    v.c[0] = iv_pt(q[0]);
    v.c[1] = iv_pt(q[1]);
    v.c[2] = iv_pt(q[2]);
    v.c[3] = iv_pt(q[3]);
    /*@ assert sc: \forall real x, y, z, w, k; q_mul(k, x, y, z, w, q[0], q[1], q[2], q[3])
                     ==> q_sc_has(v, k, x, y, z, w); */
    return q_normalise(&v);
}

/* One component of the arc box: a, b and (a + b) / den, den holding
 * 1 + p.r (>= 1/2), hulled and cut to [-1, 1]. */
/*@ requires a: iv_ok1(a) && a.lo <= a.hi;
    requires b: iv_ok1(b) && b.lo <= b.hi;
    requires den: \is_finite(den.lo) && \is_finite(den.hi) && 0.5 <= den.lo <= den.hi;
    assigns \nothing;
    ensures ok: iv_ok1(\result) && \result.lo <= \result.hi;
    ensures in: \forall real p, r, c, l, m; arc_in(a, b, den, p, r, c, l, m)
                  ==> iv_has(\result.lo, \result.hi, l*p + m*r);
*/
static inline cbx_iv arc_comp(cbx_iv a, cbx_iv b, cbx_iv den)
{
    cbx_iv s = iv_add(a, b);
    cbx_iv q = iv_div(s, den);
    cbx_iv h = iv_hull(iv_hull(a, b), q);
    /*@ assert b: \forall real p, r, c, l, m; arc_in(a, b, den, p, r, c, l, m)
                    ==> quot_at(q.lo, q.hi, p + r, 1 + c) && mono(1 + c, h.lo, q.lo) && mono(1 + c, q.hi, h.hi)
                        && arc_below(l, m, c, p, r, h.lo) && arc_below(l, m, c, -p, -r, -h.hi); */
    return iv_unit(h);
}

/* A box of R^4 holding the shorter great arc from every unit p of *a to
 * every unit r of *b (the unit vectors l p + m r, l, m >= 0): the box of
 * p, r and the tangents' meeting point (p + r) / (1 + p.r) (lemma arc_lo).
 * All of [-1, 1]^4 where 1 + p.r is not clearly positive (below 1/2). */
/*@ requires a: \valid_read(a) && q_unit_box(*a);
    requires b: \valid_read(b) && q_unit_box(*b);
    assigns \nothing;
    ensures unit: q_unit_box(\result);
    ensures arc: \forall real p0, p1, p2, p3, r0, r1, r2, r3, l, m;
                   q_has(*a, p0, p1, p2, p3) && q_has(*b, r0, r1, r2, r3)
                   && arc_pt(p0, p1, p2, p3, r0, r1, r2, r3, l, m)
                   ==> q_has(\result, l*p0 + m*r0, l*p1 + m*r1, l*p2 + m*r2, l*p3 + m*r3);
*/
static inline trs_q q_arc_box(const trs_q *a, const trs_q *b)
{
    cbx_iv dt = q_dot(a, b);
    cbx_iv den;
    trs_q r;
    /*@ assert w: q_has(*a, a->c[0].lo, a->c[1].lo, a->c[2].lo, a->c[3].lo)
                  && q_has(*b, b->c[0].lo, b->c[1].lo, b->c[2].lo, b->c[3].lo); */
    /*@ assert dw: iv_has(dt.lo, dt.hi, a->c[0].lo*b->c[0].lo + a->c[1].lo*b->c[1].lo
                                        + a->c[2].lo*b->c[2].lo + a->c[3].lo*b->c[3].lo); */
    /*@ assert dm: -1 <= itmin(a->c[0].lo, a->c[0].hi, b->c[0].lo, b->c[0].hi) && itmax(a->c[0].lo, a->c[0].hi, b->c[0].lo, b->c[0].hi) <= 1
                   && -1 <= itmin(a->c[1].lo, a->c[1].hi, b->c[1].lo, b->c[1].hi) && itmax(a->c[1].lo, a->c[1].hi, b->c[1].lo, b->c[1].hi) <= 1
                   && -1 <= itmin(a->c[2].lo, a->c[2].hi, b->c[2].lo, b->c[2].hi) && itmax(a->c[2].lo, a->c[2].hi, b->c[2].lo, b->c[2].hi) <= 1
                   && -1 <= itmin(a->c[3].lo, a->c[3].hi, b->c[3].lo, b->c[3].hi) && itmax(a->c[3].lo, a->c[3].hi, b->c[3].lo, b->c[3].hi) <= 1; */
    /*@ assert dr: iv_rng(dt.lo, dt.hi, 8) && dt.lo <= dt.hi; */
    den = iv_add(iv_pt(1.0), dt);
    /*@ assert d: \forall real p0, p1, p2, p3, r0, r1, r2, r3;
                    q_has(*a, p0, p1, p2, p3) && q_has(*b, r0, r1, r2, r3)
                    ==> iv_has(den.lo, den.hi, 1 + dot4(p0, p1, p2, p3, r0, r1, r2, r3)); */
    if (!(den.lo >= 0.5)) {
        return q_whole();
    }
    /*@ assert in: \forall real p0, p1, p2, p3, r0, r1, r2, r3, l, m;
                     q_has(*a, p0, p1, p2, p3) && q_has(*b, r0, r1, r2, r3)
                     && arc_pt(p0, p1, p2, p3, r0, r1, r2, r3, l, m)
                     ==> arc_in(a->c[0], b->c[0], den, p0, r0, dot4(p0, p1, p2, p3, r0, r1, r2, r3), l, m)
                         && arc_in(a->c[1], b->c[1], den, p1, r1, dot4(p0, p1, p2, p3, r0, r1, r2, r3), l, m)
                         && arc_in(a->c[2], b->c[2], den, p2, r2, dot4(p0, p1, p2, p3, r0, r1, r2, r3), l, m)
                         && arc_in(a->c[3], b->c[3], den, p3, r3, dot4(p0, p1, p2, p3, r0, r1, r2, r3), l, m); */
    r.c[0] = arc_comp(a->c[0], b->c[0], den);
    r.c[1] = arc_comp(a->c[1], b->c[1], den);
    r.c[2] = arc_comp(a->c[2], b->c[2], den);
    r.c[3] = arc_comp(a->c[3], b->c[3], den);
    return r;
}

#endif /* CBX_QUAT_H */
