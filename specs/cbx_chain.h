/*
 * ACSL logic of map chains (binary64 only: cbx_transform_box_chain): the
 * exact image of a real point under a chain of prepared maps, and what a
 * box's axis promise says about every real point of the box.
 *
 * Included by certbox.h under __FRAMAC__, in its binary64-only part, after
 * specs/cbx_spec.h (ext_in, below8, axis_sound_s).
 */
#ifndef CBX_CHAIN_SPEC_H
#define CBX_CHAIN_SPEC_H

/*@ // The image of the point (p0, p1, p2) under one row (m0, m1, m2, t).
    logic real lin3(real m0, real m1, real m2, real t, real p0, real p1, real p2) =
      m0*p0 + m1*p1 + m2*p2 + t;

    // Coordinate i of the exact image of (x0, x1, x2) under the maps
    // p[k], ..., p[n-1], p[n-1] applied first (the point itself for k >= n):
    // each step is y_i = m_i0 x_0 + m_i1 x_1 + m_i2 x_2 + m_i3 in exact reals.
    logic real chain_x(cbx_prepared *p, integer k, integer n, integer i,
                       real x0, real x1, real x2) =
      k >= n ? (i == 0 ? x0 : (i == 1 ? x1 : x2))
      : lin3(p[k].a.m[i][0], p[k].a.m[i][1], p[k].a.m[i][2], p[k].a.m[i][3],
             chain_x(p, k + 1, n, 0, x0, x1, x2), chain_x(p, k + 1, n, 1, x0, x1, x2),
             chain_x(p, k + 1, n, 2, x0, x1, x2));

    // The real point (x0, x1, x2) is in the box [l0, h0] x [l1, h1] x [l2, h2]
    // (an infinite end is no constraint: ext_in).
    predicate pt_in(real x0, real x1, real x2,
                    double l0, double h0, double l1, double h1, double l2, double h2) =
      ext_in(x0, l0, h0) && ext_in(x1, l1, h1) && ext_in(x2, l2, h2);

    // The image of x under p[k .. n-1], the maps as they are at label L,
    // is in the box (whose ends are values: read where the predicate is used).
    predicate chain_in{L}(cbx_prepared *p, integer k, integer n, real x0, real x1, real x2,
                          double l0, double h0, double l1, double h1, double l2, double h2) =
      pt_in(\at(chain_x(p, k, n, 0, x0, x1, x2), L), \at(chain_x(p, k, n, 1, x0, x1, x2), L),
            \at(chain_x(p, k, n, 2, x0, x1, x2), L), l0, h0, l1, h1, l2, h2);
*/

/* The chain lemmas: only in the units that use them (CBX_CHAIN_LEMMAS: the
 * lemma job L64, which proves them, and job B64a, which proves
 * src/f64/cbx_chain.c), not as hypotheses of every goal of proofs/all.c. */
#ifdef CBX_CHAIN_LEMMAS
/*@ // One column: m v at the vertex v = vlo(m, l, h) (vhi) is m l or m h,
    // and at most (at least) m p for every p of [l, h].
    lemma col_sel_lo: \forall real m, l, h; m * vlo(m, l, h) == m * l || m * vlo(m, l, h) == m * h;
    lemma col_sel_hi: \forall real m, l, h; m * vhi(m, l, h) == m * l || m * vhi(m, l, h) == m * h;
    lemma col_lo: \forall real m, l, h, p; l <= p <= h ==> m * vlo(m, l, h) <= m * p;
    lemma col_hi: \forall real m, l, h, p; l <= p <= h ==> m * p <= m * vhi(m, l, h);

    // Below (above) the 8 corners' images is below (above) the image of the
    // vertex, a corner (col_sel_lo), hence of every point (col_lo).
    lemma below8_vlo: \forall real r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2;
      below8(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      r <= m0 * vlo(m0, l0, h0) + m1 * vlo(m1, l1, h1) + m2 * vlo(m2, l2, h2) + t;
    lemma above8_vhi: \forall real r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2;
      above8(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      r >= m0 * vhi(m0, l0, h0) + m1 * vhi(m1, l1, h1) + m2 * vhi(m2, l2, h2) + t;
    lemma below8_pt: \forall real r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, p0, p1, p2;
      l0 <= p0 <= h0 ==> l1 <= p1 <= h1 ==> l2 <= p2 <= h2 ==>
      below8(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      r <= lin3(m0, m1, m2, t, p0, p1, p2);
    lemma above8_pt: \forall real r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, p0, p1, p2;
      l0 <= p0 <= h0 ==> l1 <= p1 <= h1 ==> l2 <= p2 <= h2 ==>
      above8(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      r >= lin3(m0, m1, m2, t, p0, p1, p2);

    // Each end of a partial row (ext_lo_end, ext_hi_end): -inf (+inf), or
    // finite and below (above) every point's image.
    lemma ext_lo_pt: \forall double lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, real p0, p1, p2;
      ext_lo_end(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      pt_in(p0, p1, p2, l0, h0, l1, h1, l2, h2) ==>
      (\is_finite(lo) ==> lo <= lin3(m0, m1, m2, t, p0, p1, p2));
    lemma ext_hi_pt: \forall double hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, real p0, p1, p2;
      ext_hi_end(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      pt_in(p0, p1, p2, l0, h0, l1, h1, l2, h2) ==>
      (\is_finite(hi) ==> lin3(m0, m1, m2, t, p0, p1, p2) <= hi);

    // The three cases of an axis: a full row (finite box ends, the 8
    // corners), a partial row (each end on its own), the whole line.
    lemma full_box: \forall double m0, m1, m2, t, l0, h0, l1, h1, l2, h2, real p0, p1, p2;
      row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      pt_in(p0, p1, p2, l0, h0, l1, h1, l2, h2) ==>
      (l0 <= p0 <= h0 && l1 <= p1 <= h1 && l2 <= p2 <= h2);
    lemma full_pt: \forall double lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, real p0, p1, p2;
      row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      pt_in(p0, p1, p2, l0, h0, l1, h1, l2, h2) ==>
      (lo <= lin3(m0, m1, m2, t, p0, p1, p2) && lin3(m0, m1, m2, t, p0, p1, p2) <= hi);
    lemma part_pt: \forall double lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, real p0, p1, p2;
      ext_lo_end(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      ext_hi_end(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      pt_in(p0, p1, p2, l0, h0, l1, h1, l2, h2) ==>
      ext_in(lin3(m0, m1, m2, t, p0, p1, p2), lo, hi);

    // An axis of cbx_transform_box's promise (axis_sound_s: the full row's
    // corners, each end of a partial row on its own, or the whole line)
    // holds the image of every real point of the input box.
    lemma axis_sound_pt: \forall double lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2,
                                 real p0, p1, p2;
      axis_sound_s(lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
      pt_in(p0, p1, p2, l0, h0, l1, h1, l2, h2) ==>
      ext_in(lin3(m0, m1, m2, t, p0, p1, p2), lo, hi);
*/
#endif

#endif /* CBX_CHAIN_SPEC_H */
