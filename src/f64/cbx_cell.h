/*
 * One cell of a rotation motion (src/f64/cbx_trs.c): the interval matrix of
 * every map T(s) R S(s) for s in [a, b], where T(s) and S(s) are the
 * keyframes' translations and scales interpolated linearly and R is any
 * matrix whose entries lie in the intervals r (q_rotation's enclosure of
 * the rotations of a box of unit quaternions, src/f64/cbx_quat.h).  The
 * contract states, in exact reals, that every such map's entries lie in
 * the result (containment) and how far each end may be from the exact
 * ends of the interval forms (tightness).  Proven in job T64
 * (proofs/trs.c).
 */
#ifndef CBX_CELL_H
#define CBX_CELL_H

#include "certbox.h"
#include "cbx_iv.h"
#include "cbx_quat.h"

/*@ // a keyframe's translation and scale as cbx_trs.c's range check
    // leaves them: finite, |t| <= 2^500, |s| <= 2^250
    predicate key_ts(cbx_trs *k) = \forall integer i; 0 <= i < 3 ==>
      \is_finite(k->t[i]) && \is_finite(k->s[i]) && \abs(k->t[i]) <= 0x1p500 && \abs(k->s[i]) <= 0x1p250;
    // every entry of r finite and cut to [-1, 1]
    predicate rot_cut(trs_rot *r) = \forall integer i, j; 0 <= i < 3 && 0 <= j < 3 ==> iv_cut(r->e[i][j]);
    // An entry [lo, hi] of column j < 3: finite; it holds u (x0 + s (x1 -
    // x0)) for every u in r (r_ij) and every s in [a, b] (containment);
    // each end within 12 u of the exact end of r times [L - e, H + e],
    // where [L, H] is the exact range of the linear path and e iv_lerp's
    // error bound (tightness)
    predicate cell_v(double lo, double hi, cbx_iv r, real x0, real x1, real a, real b) =
      \is_finite(lo) && \is_finite(hi) && cell_prod(lo, hi, r.lo, r.hi, x0, x1 - x0, a, b)
      && lo >= itmin(r.lo, r.hi, lerp_wlo(x0, x1, a, b), lerp_whi(x0, x1, a, b))
                - (CBX_U12 * itmag(r.lo, r.hi, lerp_wlo(x0, x1, a, b), lerp_whi(x0, x1, a, b))
                   + CBX_ETA512)
      && hi <= itmax(r.lo, r.hi, lerp_wlo(x0, x1, a, b), lerp_whi(x0, x1, a, b))
                + (CBX_U12 * itmag(r.lo, r.hi, lerp_wlo(x0, x1, a, b), lerp_whi(x0, x1, a, b))
                   + CBX_ETA512);
    // An entry [lo, hi] of column 3: finite; it holds x0 + s (x1 - x0) for
    // every s in [a, b]; each end within e of the exact end
    predicate cell_t(double lo, double hi, real x0, real x1, real a, real b) =
      \is_finite(lo) && \is_finite(hi) && lerp_in(lo, hi, x0, x1 - x0, a, b)
      && lo >= lerp_wlo(x0, x1, a, b) && hi <= lerp_whi(x0, x1, a, b);
*/

/* Three entries of a column. */
typedef struct trs_col { cbx_iv e[3]; } trs_col;

/* Column j < 3 of the cell: the interval products of r_ij and the scale
 * x0 + s (x1 - x0) over s in [a, b]. */
/*@ requires j: 0 <= j < 3;
    requires r: \valid_read(r) && \forall integer i; 0 <= i < 3 ==> iv_cut(r->e[i][j]);
    requires x: \is_finite(x0) && \is_finite(x1) && \abs(x0) <= 0x1p250 && \abs(x1) <= 0x1p250;
    requires s: \is_finite(a) && \is_finite(b) && 0 <= a <= b <= 1;
    assigns \nothing;
    ensures col: \forall integer i; 0 <= i < 3 ==> cell_v(\result.e[i].lo, \result.e[i].hi, r->e[i][j], x0, x1, a, b);
*/
static inline trs_col cell_col(const trs_rot *r, int j, double x0, double x1, double a, double b)
{
    cbx_iv sc = iv_lerp(x0, x1, a, b);
    trs_col c;
    int i;
    /*@ assert m: mono(x1 - x0, a, 1) && msign(x1 - x0, a) && mono(x1 - x0, b, 1) && msign(x1 - x0, b); */
    /*@ assert ab: lerp_pt(sc.lo, sc.hi, x0, x1 - x0, a) && lerp_pt(sc.lo, sc.hi, x0, x1 - x0, b); */
    /*@ assert w: lerp_wlo(x0, x1, a, b) <= sc.lo <= lerp_whi(x0, x1, a, b)
                  && lerp_wlo(x0, x1, a, b) <= sc.hi <= lerp_whi(x0, x1, a, b); */
    /*@ assert rng: iv_rng(sc.lo, sc.hi, CBX_SB); */
    /*@ loop invariant i: 0 <= i <= 3;
        loop invariant done: \forall integer k; 0 <= k < i ==> cell_v(c.e[k].lo, c.e[k].hi, r->e[k][j], x0, x1, a, b);
        loop assigns i, c;
        loop variant 3 - i;
    */
    for (i = 0; i < 3; i++) {
        cbx_iv e = iv_mul(r->e[i][j], sc);
        /*@ assert sub: it_sub(r->e[i][j].lo, r->e[i][j].hi, sc.lo, sc.hi,
                               lerp_wlo(x0, x1, a, b), lerp_whi(x0, x1, a, b)); */
        /*@ assert in: cell_prod(e.lo, e.hi, r->e[i][j].lo, r->e[i][j].hi, x0, x1 - x0, a, b); */
        /*@ assert v: cell_v(e.lo, e.hi, r->e[i][j], x0, x1, a, b); */
        c.e[i] = e;
    }
    return c;
}

/* The cell's interval matrix: column j < 3 the products r_ij S_j, column 3
 * the translation T, over s in [a, b].  Every input is read before the
 * first write to *out. */
/*@ requires k: \valid_read(k0) && \valid_read(k1) && key_ts(k0) && key_ts(k1);
    requires r: \valid_read(r) && rot_cut(r);
    requires s: \is_finite(a) && \is_finite(b) && 0 <= a <= b <= 1;
    requires out: \valid(out) && \separated(out, k0, k1, r);
    assigns *out;
    ensures lin: \forall integer i, j; 0 <= i < 3 && 0 <= j < 3 ==>
                   cell_v(out->lo[i][j], out->hi[i][j], \old(r->e[i][j]), \old(k0->s[j]), \old(k1->s[j]), a, b);
    ensures tr: \forall integer i; 0 <= i < 3 ==>
                  cell_t(out->lo[i][3], out->hi[i][3], \old(k0->t[i]), \old(k1->t[i]), a, b);
*/
static void cell_imat(const cbx_trs *k0, const cbx_trs *k1, const trs_rot *r, double a, double b, cbx_imat *out)
{
    trs_col c[3];
    cbx_iv t[3];
    int j;
    /*@ loop invariant j: 0 <= j <= 3;
        loop invariant lin: \forall integer i, k; 0 <= i < 3 && 0 <= k < j ==> cell_v(c[k].e[i].lo, c[k].e[i].hi, r->e[i][k], k0->s[k], k1->s[k], a, b);
        loop invariant tr: \forall integer k; 0 <= k < j ==> cell_t(t[k].lo, t[k].hi, k0->t[k], k1->t[k], a, b);
        loop assigns j, c[0..2], t[0..2];
        loop variant 3 - j;
    */
    for (j = 0; j < 3; j++) {
        /*@ assert k: \is_finite(k0->t[j]) && \is_finite(k0->s[j]) && \abs(k0->t[j]) <= 0x1p500 && \abs(k0->s[j]) <= 0x1p250
                      && \is_finite(k1->t[j]) && \is_finite(k1->s[j]) && \abs(k1->t[j]) <= 0x1p500 && \abs(k1->s[j]) <= 0x1p250; */
        t[j] = iv_lerp(k0->t[j], k1->t[j], a, b);
        c[j] = cell_col(r, j, k0->s[j], k1->s[j], a, b);
    }
    /*@ loop invariant j: 0 <= j <= 3;
        loop invariant lin: \forall integer i, k; 0 <= i < 3 && 0 <= k < j ==>
                              cell_v(out->lo[i][k], out->hi[i][k], \at(r->e[i][k], Pre), \at(k0->s[k], Pre), \at(k1->s[k], Pre), a, b);
        loop invariant tr: \forall integer k; 0 <= k < j ==>
                             cell_t(out->lo[k][3], out->hi[k][3], \at(k0->t[k], Pre), \at(k1->t[k], Pre), a, b);
        loop assigns j, *out;
        loop variant 3 - j;
    */
    for (j = 0; j < 3; j++) {
        out->lo[0][j] = c[j].e[0].lo;
        out->hi[0][j] = c[j].e[0].hi;
        out->lo[1][j] = c[j].e[1].lo;
        out->hi[1][j] = c[j].e[1].hi;
        out->lo[2][j] = c[j].e[2].lo;
        out->hi[2][j] = c[j].e[2].hi;
        out->lo[j][3] = t[j].lo;
        out->hi[j][3] = t[j].hi;
    }
}

#endif /* CBX_CELL_H */
