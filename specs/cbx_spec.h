/*
 * ACSL logic of certbox: every promise the contracts make is built from the
 * definitions here.  Read by Frama-C only (certbox.h includes this file when
 * __FRAMAC__ is defined); a C compiler never sees it.
 *
 * Arithmetic in these definitions is exact real arithmetic on the values of
 * the C doubles: `m*l` is the exact product, not the rounded one.
 */
#ifndef CBX_SPEC_H
#define CBX_SPEC_H

/*@ // ---------------------------------------------------------------------
    // The proven domain of one product m*c: |m*c| <= 2^1018.  A named
    // predicate (not an inline formula) so that the lemmas below have a
    // trigger: the provers instantiate them wherever in_dom(x, y) occurs.
    // ---------------------------------------------------------------------
    predicate in_dom(real x, real y) = -0x1p1018 <= x*y <= 0x1p1018;

    // One magnitude class: |m| <= 2^k and |c| <= 2^(1018-k).
    predicate cls(real m, real c, real bm, real bc) =
      -bm <= m <= bm && -bc <= c <= bc;

    // The domain of a product, checked at run time by cbx_dom_pair():
    // one of 18 magnitude classes (k = 509, 0, 64, ..., 960, 1018).
    predicate dom_pair(real m, real c) =
         cls(m, c, 0x1p509,  0x1p509)
      || cls(m, c, 0x1p0,    0x1p1018) || cls(m, c, 0x1p64,   0x1p954)
      || cls(m, c, 0x1p128,  0x1p890)  || cls(m, c, 0x1p192,  0x1p826)
      || cls(m, c, 0x1p256,  0x1p762)  || cls(m, c, 0x1p320,  0x1p698)
      || cls(m, c, 0x1p384,  0x1p634)  || cls(m, c, 0x1p448,  0x1p570)
      || cls(m, c, 0x1p512,  0x1p506)  || cls(m, c, 0x1p576,  0x1p442)
      || cls(m, c, 0x1p640,  0x1p378)  || cls(m, c, 0x1p704,  0x1p314)
      || cls(m, c, 0x1p768,  0x1p250)  || cls(m, c, 0x1p832,  0x1p186)
      || cls(m, c, 0x1p896,  0x1p122)  || cls(m, c, 0x1p960,  0x1p58)
      || cls(m, c, 0x1p1018, 0x1p0);

    // Nonlinear facts, proven once over the reals (no floats in context).
    lemma cls_509:  \forall real m, c; cls(m, c, 0x1p509, 0x1p509) ==> in_dom(m, c);
    lemma cls_0:    \forall real m, c; cls(m, c, 0x1p0, 0x1p1018) ==> in_dom(m, c);
    lemma cls_64:   \forall real m, c; cls(m, c, 0x1p64, 0x1p954) ==> in_dom(m, c);
    lemma cls_128:  \forall real m, c; cls(m, c, 0x1p128, 0x1p890) ==> in_dom(m, c);
    lemma cls_192:  \forall real m, c; cls(m, c, 0x1p192, 0x1p826) ==> in_dom(m, c);
    lemma cls_256:  \forall real m, c; cls(m, c, 0x1p256, 0x1p762) ==> in_dom(m, c);
    lemma cls_320:  \forall real m, c; cls(m, c, 0x1p320, 0x1p698) ==> in_dom(m, c);
    lemma cls_384:  \forall real m, c; cls(m, c, 0x1p384, 0x1p634) ==> in_dom(m, c);
    lemma cls_448:  \forall real m, c; cls(m, c, 0x1p448, 0x1p570) ==> in_dom(m, c);
    lemma cls_512:  \forall real m, c; cls(m, c, 0x1p512, 0x1p506) ==> in_dom(m, c);
    lemma cls_576:  \forall real m, c; cls(m, c, 0x1p576, 0x1p442) ==> in_dom(m, c);
    lemma cls_640:  \forall real m, c; cls(m, c, 0x1p640, 0x1p378) ==> in_dom(m, c);
    lemma cls_704:  \forall real m, c; cls(m, c, 0x1p704, 0x1p314) ==> in_dom(m, c);
    lemma cls_768:  \forall real m, c; cls(m, c, 0x1p768, 0x1p250) ==> in_dom(m, c);
    lemma cls_832:  \forall real m, c; cls(m, c, 0x1p832, 0x1p186) ==> in_dom(m, c);
    lemma cls_896:  \forall real m, c; cls(m, c, 0x1p896, 0x1p122) ==> in_dom(m, c);
    lemma cls_960:  \forall real m, c; cls(m, c, 0x1p960, 0x1p58) ==> in_dom(m, c);
    lemma cls_1018: \forall real m, c; cls(m, c, 0x1p1018, 0x1p0) ==> in_dom(m, c);

    lemma dom_pair_in_dom: \forall real m, c; dom_pair(m, c) ==> in_dom(m, c);

    // ---------------------------------------------------------------------
    // One term of Arvo's sum: m*c for c in {l, h}.
    // ---------------------------------------------------------------------
    logic real tmin(real m, real l, real h) = \min(m*l, m*h);
    logic real tmax(real m, real l, real h) = \max(m*l, m*h);
    logic real tmag(real m, real l, real h) = \max(\abs(m*l), \abs(m*h));

    // Exact bounds of one output coordinate over the box, and its scale
    // S = |t| + sum_j |m_j| max(|l_j|, |h_j|) used by the tightness bound.
    logic real row_lo(real m0, real m1, real m2, real t,
                      real l0, real h0, real l1, real h1, real l2, real h2) =
      t + tmin(m0, l0, h0) + tmin(m1, l1, h1) + tmin(m2, l2, h2);
    logic real row_hi(real m0, real m1, real m2, real t,
                      real l0, real h0, real l1, real h1, real l2, real h2) =
      t + tmax(m0, l0, h0) + tmax(m1, l1, h1) + tmax(m2, l2, h2);
    logic real row_mag(real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      \abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + tmag(m2, l2, h2);

    // r is below the image of all 8 corners (c_j in {l_j, h_j}).
    predicate below8(real r, real m0, real m1, real m2, real t,
                     real l0, real h0, real l1, real h1, real l2, real h2) =
         r <= m0*l0 + m1*l1 + m2*l2 + t && r <= m0*l0 + m1*l1 + m2*h2 + t
      && r <= m0*l0 + m1*h1 + m2*l2 + t && r <= m0*l0 + m1*h1 + m2*h2 + t
      && r <= m0*h0 + m1*l1 + m2*l2 + t && r <= m0*h0 + m1*l1 + m2*h2 + t
      && r <= m0*h0 + m1*h1 + m2*l2 + t && r <= m0*h0 + m1*h1 + m2*h2 + t;
    // r is above the image of all 8 corners.
    predicate above8(real r, real m0, real m1, real m2, real t,
                     real l0, real h0, real l1, real h1, real l2, real h2) =
         r >= m0*l0 + m1*l1 + m2*l2 + t && r >= m0*l0 + m1*l1 + m2*h2 + t
      && r >= m0*l0 + m1*h1 + m2*l2 + t && r >= m0*l0 + m1*h1 + m2*h2 + t
      && r >= m0*h0 + m1*l1 + m2*l2 + t && r >= m0*h0 + m1*l1 + m2*h2 + t
      && r >= m0*h0 + m1*h1 + m2*l2 + t && r >= m0*h0 + m1*h1 + m2*h2 + t;

    // Tightness: at most 12 u S + 2^-1065 below (above) the exact bound.
    predicate lo_tight(real r, real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      r >= row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           - (0x1.8p-50 * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 0x1p-1065);
    predicate hi_tight(real r, real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      r <= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           + (0x1.8p-50 * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + 0x1p-1065);

    // The inputs of one output row are in the proven domain.
    predicate row_in_dom(real m0, real m1, real m2, real t,
                         real l0, real h0, real l1, real h1, real l2, real h2) =
      dom_pair(m0, l0) && dom_pair(m0, h0) && dom_pair(m1, l1) && dom_pair(m1, h1)
      && dom_pair(m2, l2) && dom_pair(m2, h2) && -0x1p1018 <= t <= 0x1p1018;
*/

/*@ // ---------------------------------------------------------------------
    // Half-spaces and out-of-domain boxes: each end of an axis on its own.
    // A box whose ends may be infinite is the real set
    //   { p : lo_j <= p_j <= hi_j where that end is finite };
    // (lo = +inf or hi = -inf is an empty box, caught before: no_point).
    // ---------------------------------------------------------------------
    predicate map_fin(double m0, double m1, double m2, double t) =
      \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t);
    predicate row_full(double m0, double m1, double m2, double t,
                       double l0, double h0, double l1, double h1, double l2, double h2) =
      map_fin(m0, m1, m2, t)
      && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
      && \is_finite(l2) && \is_finite(h2)
      && row_in_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);

    // p is in [l, h]; an infinite end is no constraint.
    predicate ext_in(real p, double l, double h) =
      (\is_finite(l) ==> l <= p) && (\is_finite(h) ==> p <= h);

    // r is below (above) t + m.p for every real point p of the box.
    predicate ext_below(real r, real m0, real m1, real m2, real t,
                        double l0, double h0, double l1, double h1, double l2, double h2) =
      \forall real p0, p1, p2;
        ext_in(p0, l0, h0) && ext_in(p1, l1, h1) && ext_in(p2, l2, h2) ==>
        r <= m0*p0 + m1*p1 + m2*p2 + t;
    predicate ext_above(real r, real m0, real m1, real m2, real t,
                        double l0, double h0, double l1, double h1, double l2, double h2) =
      \forall real p0, p1, p2;
        ext_in(p0, l0, h0) && ext_in(p1, l1, h1) && ext_in(p2, l2, h2) ==>
        r >= m0*p0 + m1*p1 + m2*p2 + t;

    // The vertex of [l, h] where m*x is least (vlo) or greatest (vhi):
    // an end chosen by the sign of m; 0 when m == 0 (0 * inf = 0).
    logic real vlo(real m, real l, real h) = m > 0 ? l : (m < 0 ? h : 0);
    logic real vhi(real m, real l, real h) = m > 0 ? h : (m < 0 ? l : 0);

    // m*x is unbounded below (above) on [l, h]: the end it needs is infinite.
    predicate unb_lo(real m, double l, double h) =
      (m > 0 && !\is_finite(l)) || (m < 0 && !\is_finite(h));
    predicate unb_hi(real m, double l, double h) =
      (m > 0 && !\is_finite(h)) || (m < 0 && !\is_finite(l));
    predicate row_unb_lo(real m0, real m1, real m2,
                         double l0, double h0, double l1, double h1, double l2, double h2) =
      unb_lo(m0, l0, h0) || unb_lo(m1, l1, h1) || unb_lo(m2, l2, h2);
    predicate row_unb_hi(real m0, real m1, real m2,
                         double l0, double h0, double l1, double h1, double l2, double h2) =
      unb_hi(m0, l0, h0) || unb_hi(m1, l1, h1) || unb_hi(m2, l2, h2);

    // The point box at the lower (upper) vertex is in the proven domain.
    predicate vdom_lo(real m0, real m1, real m2, real t,
                      double l0, double h0, double l1, double h1, double l2, double h2) =
      row_in_dom(m0, m1, m2, t, vlo(m0, l0, h0), vlo(m0, l0, h0), vlo(m1, l1, h1),
                 vlo(m1, l1, h1), vlo(m2, l2, h2), vlo(m2, l2, h2));
    predicate vdom_hi(real m0, real m1, real m2, real t,
                      double l0, double h0, double l1, double h1, double l2, double h2) =
      row_in_dom(m0, m1, m2, t, vhi(m0, l0, h0), vhi(m0, l0, h0), vhi(m1, l1, h1),
                 vhi(m1, l1, h1), vhi(m2, l2, h2), vhi(m2, l2, h2));

    // One end, computed from its vertex: -inf where the image is unbounded
    // below; else, in the domain, finite, below every point's image and
    // tight (12 u S + 2^-1065, S = |t| + sum_j |m_j v_j|); else -inf.
    predicate ext_lo_end(double r, double m0, double m1, double m2, double t,
                         double l0, double h0, double l1, double h1, double l2, double h2) =
      (row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2) ==> \is_minus_infinity(r))
      && ((!row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==>
          (\is_finite(r) && ext_below(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           && lo_tight(r, m0, m1, m2, t, vlo(m0, l0, h0), vlo(m0, l0, h0), vlo(m1, l1, h1),
                       vlo(m1, l1, h1), vlo(m2, l2, h2), vlo(m2, l2, h2))))
      && ((!row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && !vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==> \is_minus_infinity(r));
    predicate ext_hi_end(double r, double m0, double m1, double m2, double t,
                         double l0, double h0, double l1, double h1, double l2, double h2) =
      (row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2) ==> \is_plus_infinity(r))
      && ((!row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==>
          (\is_finite(r) && ext_above(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           && hi_tight(r, m0, m1, m2, t, vhi(m0, l0, h0), vhi(m0, l0, h0), vhi(m1, l1, h1),
                       vhi(m1, l1, h1), vhi(m2, l2, h2), vhi(m2, l2, h2))))
      && ((!row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && !vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==> \is_plus_infinity(r));

    // Sums of per-column facts, over the reals (products are atoms).
    lemma ext_sum_lo: \forall real r, m0, m1, m2, t, v0, v1, v2, p0, p1, p2;
      r <= m0*v0 + m1*v1 + m2*v2 + t ==>
      m0*v0 <= m0*p0 ==> m1*v1 <= m1*p1 ==> m2*v2 <= m2*p2 ==>
      r <= m0*p0 + m1*p1 + m2*p2 + t;
    lemma ext_sum_hi: \forall real r, m0, m1, m2, t, v0, v1, v2, p0, p1, p2;
      r >= m0*v0 + m1*v1 + m2*v2 + t ==>
      m0*v0 >= m0*p0 ==> m1*v1 >= m1*p1 ==> m2*v2 >= m2*p2 ==>
      r >= m0*p0 + m1*p1 + m2*p2 + t;
    // The one nonlinear fact of the half-space proof, with a product as
    // its trigger (the lemma functions of src/cbx_interval.c use it).
    // (a named predicate, so that WP's simplifier leaves the product as it is
    // and the lemma has a trigger).
    predicate nn_prod(real a, real b) = 0 <= a*b;
    lemma mul_nonneg: \forall real a, b; 0 <= a ==> 0 <= b ==> nn_prod(a, b);
    // One column: how the code picks the vertex v where m*x is least
    // (greatest) on [l, h]: an end by the sign of m, 0 for m == 0.
    predicate sel_lo(real m, real v, double l, double h) =
      (m > 0 ==> v == l && \is_finite(l)) && (m < 0 ==> v == h && \is_finite(h))
      && (m == 0 ==> v == 0);
    predicate sel_hi(real m, real v, double l, double h) =
      (m > 0 ==> v == h && \is_finite(h)) && (m < 0 ==> v == l && \is_finite(l))
      && (m == 0 ==> v == 0);
*/

/*@ // ---------------------------------------------------------------------
    // The same notions on the public structures.
    // ---------------------------------------------------------------------
    predicate has_nan(cbx_affine *a, cbx_box *b) =
         \is_NaN(a->m[0][0]) || \is_NaN(a->m[0][1]) || \is_NaN(a->m[0][2]) || \is_NaN(a->m[0][3])
      || \is_NaN(a->m[1][0]) || \is_NaN(a->m[1][1]) || \is_NaN(a->m[1][2]) || \is_NaN(a->m[1][3])
      || \is_NaN(a->m[2][0]) || \is_NaN(a->m[2][1]) || \is_NaN(a->m[2][2]) || \is_NaN(a->m[2][3])
      || \is_NaN(b->lo[0]) || \is_NaN(b->lo[1]) || \is_NaN(b->lo[2])
      || \is_NaN(b->hi[0]) || \is_NaN(b->hi[1]) || \is_NaN(b->hi[2]);

    // No real point on axis j: hi < lo (IEEE comparison), or lo = +inf,
    // or hi = -inf (the set { x real : +inf <= x } is empty).
    predicate no_point(double l, double h) =
      \lt_double(h, l) || \is_plus_infinity(l) || \is_minus_infinity(h);
    predicate is_empty(cbx_box *b) =
      no_point(b->lo[0], b->hi[0]) || no_point(b->lo[1], b->hi[1])
      || no_point(b->lo[2], b->hi[2]);

    predicate whole_axis(cbx_box *o, integer i) =
      \is_minus_infinity(o->lo[i]) && \is_plus_infinity(o->hi[i]);
    predicate whole_space(cbx_box *o) =
      whole_axis(o, 0) && whole_axis(o, 1) && whole_axis(o, 2);
    predicate empty_out(cbx_box *o) =
         \is_plus_infinity(o->lo[0]) && \is_minus_infinity(o->hi[0])
      && \is_plus_infinity(o->lo[1]) && \is_minus_infinity(o->hi[1])
      && \is_plus_infinity(o->lo[2]) && \is_minus_infinity(o->hi[2]);

    // All inputs of row i are finite and in the proven domain.
    predicate row_dom(cbx_affine *a, cbx_box *b, integer i) =
      \is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
      && \is_finite(a->m[i][3])
      && \is_finite(b->lo[0]) && \is_finite(b->hi[0]) && \is_finite(b->lo[1])
      && \is_finite(b->hi[1]) && \is_finite(b->lo[2]) && \is_finite(b->hi[2])
      && row_in_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                    b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);

    // Axis i of o is finite, contains the image of the 8 corners, and is tight.
    predicate axis_proven(cbx_affine *a, cbx_box *b, cbx_box *o, integer i) =
      \is_finite(o->lo[i]) && \is_finite(o->hi[i])
      && below8(o->lo[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      && above8(o->hi[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      && lo_tight(o->lo[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                  b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      && hi_tight(o->hi[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                  b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);

    // What the function promises on one axis, on the values themselves.
    //  full row (every input finite, in the domain): Arvo's kernel, the
    //    8-corner statement and the tightness bound;
    //  otherwise, finite map row: each end on its own (ext_lo_end,
    //    ext_hi_end): infinite box ends are half-spaces, a zero
    //    coefficient contributes nothing (0 * inf = 0);
    //  an infinite map entry: the whole line [-inf, +inf].
    predicate axis_sound_s(double lo, double hi, double m0, double m1, double m2, double t,
                           double l0, double h0, double l1, double h1, double l2, double h2) =
      (row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
         (\is_finite(lo) && \is_finite(hi)
          && below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)))
      && ((!row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) && map_fin(m0, m1, m2, t)) ==>
         (ext_lo_end(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && ext_hi_end(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)))
      && (!map_fin(m0, m1, m2, t) ==>
         (\is_minus_infinity(lo) && \is_plus_infinity(hi)));

    // The axis is computed without loss: every finite end is proven and
    // every infinite end is one where the exact image is unbounded.
    predicate axis_ok_s(double m0, double m1, double m2, double t,
                        double l0, double h0, double l1, double h1, double l2, double h2) =
      row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
      || (map_fin(m0, m1, m2, t)
          && (row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
              || vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2))
          && (row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
              || vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)));

    // Axis i is computed without loss (status CBX_OK): see axis_ok_s.
    predicate row_ok(cbx_affine *a, cbx_box *b, integer i) =
      axis_ok_s(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);

    // ---- one box's whole promise on values, for the batch form -------
    // Inputs: the 12 map entries a_ij, the box l_j, h_j; output: o_i, p_i
    // (lo, hi of axis i).  The same cases as cbx_transform_box's behaviors.
    predicate nan_v(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13, double a20, double a21, double a22, double a23,
                    double l0, double h0, double l1, double h1, double l2, double h2) =
         \is_NaN(a00) || \is_NaN(a01) || \is_NaN(a02) || \is_NaN(a03)
      || \is_NaN(a10) || \is_NaN(a11) || \is_NaN(a12) || \is_NaN(a13)
      || \is_NaN(a20) || \is_NaN(a21) || \is_NaN(a22) || \is_NaN(a23)
      || \is_NaN(l0) || \is_NaN(l1) || \is_NaN(l2) || \is_NaN(h0) || \is_NaN(h1) || \is_NaN(h2);
    predicate empty_v(double l0, double h0, double l1, double h1, double l2, double h2) =
      no_point(l0, h0) || no_point(l1, h1) || no_point(l2, h2);
    predicate ok_v(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13, double a20, double a21, double a22, double a23,
                   double l0, double h0, double l1, double h1, double l2, double h2) =
      axis_ok_s(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
      && axis_ok_s(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
      && axis_ok_s(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    predicate box_done_v(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13, double a20, double a21, double a22, double a23,
                         double l0, double h0, double l1, double h1, double l2, double h2,
                         double o0, double p0, double o1, double p1, double o2, double p2) =
      (nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) ==>
         (\is_minus_infinity(o0) && \is_plus_infinity(p0) && \is_minus_infinity(o1)
          && \is_plus_infinity(p1) && \is_minus_infinity(o2) && \is_plus_infinity(p2)))
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && empty_v(l0, h0, l1, h1, l2, h2)) ==>
         (\is_plus_infinity(o0) && \is_minus_infinity(p0) && \is_plus_infinity(o1)
          && \is_minus_infinity(p1) && \is_plus_infinity(o2) && \is_minus_infinity(p2)))
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2)) ==>
         (axis_sound_s(o0, p0, a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(o1, p1, a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(o2, p2, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)));

    // Severity of a status, for "the most severe status met":
    // CBX_OK 0 < CBX_EMPTY 1 < CBX_ERANGE 2 < CBX_EINVAL 3.
    logic integer sev(integer s) =
      s == CBX_EINVAL ? 3 : (s == CBX_ERANGE ? 2 : (s == CBX_EMPTY ? 1 : 0));

    // k is the severity of the status cbx_transform_box returns.
    predicate box_sev_v(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13, double a20, double a21, double a22, double a23,
                        double l0, double h0, double l1, double h1, double l2, double h2, integer k) =
      (nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && k == 3)
      || (!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && empty_v(l0, h0, l1, h1, l2, h2) && k == 1)
      || (!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2) && ok_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && k == 0)
      || (!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2) && !ok_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && k == 2);

    // The severity of the status for this box is at most w.  (Stated without
    // a quantifier over severities: a global lemma "box_sev_v is a
    // function" made the provers time out on unrelated lemmas.)
    predicate box_sev_le(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13, double a20, double a21, double a22, double a23,
                         double l0, double h0, double l1, double h1, double l2, double h2, integer w) =
      0 <= w
      && (nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) ==> 3 <= w)
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && empty_v(l0, h0, l1, h1, l2, h2)) ==> 1 <= w)
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2) && !ok_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)) ==> 2 <= w);

    // The same with the output box as one struct value: the batch loop's
    // invariant then frames (a write of out[k] leaves the value out[j]
    // unchanged) where six separate fields did not.
    predicate box_done_m(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13, double a20, double a21, double a22, double a23,
                         double l0, double h0, double l1, double h1, double l2, double h2, cbx_box O) =
      box_done_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2,
                 O.lo[0], O.hi[0], O.lo[1], O.hi[1], O.lo[2], O.hi[2]);
*/

/*@ // ---------------------------------------------------------------------
    // Center/half-diagonal form: the real box [oc - oh, oc + oh] of one
    // output axis and the input box [c_j - h_j, c_j + h_j].
    // ---------------------------------------------------------------------
    logic real crow_c(real m0, real m1, real m2, real t, real c0, real c1, real c2) =
      m0*c0 + m1*c1 + m2*c2 + t;
    logic real crow_h(real m0, real m1, real m2, real h0, real h1, real h2) =
      \abs(m0*h0) + \abs(m1*h1) + \abs(m2*h2);
    logic real crow_mag(real m0, real m1, real m2, real t, real c0, real c1, real c2,
                        real h0, real h1, real h2) =
      \abs(t) + \abs(m0*c0) + \abs(m1*c1) + \abs(m2*c2) + crow_h(m0, m1, m2, h0, h1, h2);

    // |exact center - oc| + exact half <= oh: [oc-oh, oc+oh] holds the image.
    predicate cbox_core(real oc, real oh, real m0, real m1, real m2, real t,
                        real c0, real c1, real c2, real h0, real h1, real h2) =
      \abs(crow_c(m0, m1, m2, t, c0, c1, c2) - oc) + crow_h(m0, m1, m2, h0, h1, h2) <= oh;

    // The same, stated on the 8 corners c_j -+ h_j.
    predicate cbox_corners(real oc, real oh, real m0, real m1, real m2, real t,
                           real c0, real c1, real c2, real h0, real h1, real h2) =
      below8(oc - oh, m0, m1, m2, t, c0 - h0, c0 + h0, c1 - h1, c1 + h1, c2 - h2, c2 + h2)
      && above8(oc + oh, m0, m1, m2, t, c0 - h0, c0 + h0, c1 - h1, c1 + h1, c2 - h2, c2 + h2);

    lemma cbox_core_corners:
      \forall real oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2;
        cbox_core(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2) ==>
        cbox_corners(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2);

    // Tightness: each end within 12 u S + 2^-1065 of the exact end.
    predicate cbox_tight(real oc, real oh, real m0, real m1, real m2, real t,
                         real c0, real c1, real c2, real h0, real h1, real h2) =
      oc - oh >= crow_c(m0, m1, m2, t, c0, c1, c2) - crow_h(m0, m1, m2, h0, h1, h2)
                 - (0x1.8p-50 * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) + 0x1p-1065)
      && oc + oh <= crow_c(m0, m1, m2, t, c0, c1, c2) + crow_h(m0, m1, m2, h0, h1, h2)
                 + (0x1.8p-50 * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) + 0x1p-1065);

    predicate crow_in_dom(real m0, real m1, real m2, real t,
                          real c0, real c1, real c2, real h0, real h1, real h2) =
      dom_pair(m0, c0) && dom_pair(m0, h0) && dom_pair(m1, c1) && dom_pair(m1, h1)
      && dom_pair(m2, c2) && dom_pair(m2, h2) && -0x1p1018 <= t <= 0x1p1018;
*/

/*@ predicate cbox_has_nan(cbx_affine *a, cbx_cbox *b) =
         \is_NaN(a->m[0][0]) || \is_NaN(a->m[0][1]) || \is_NaN(a->m[0][2]) || \is_NaN(a->m[0][3])
      || \is_NaN(a->m[1][0]) || \is_NaN(a->m[1][1]) || \is_NaN(a->m[1][2]) || \is_NaN(a->m[1][3])
      || \is_NaN(a->m[2][0]) || \is_NaN(a->m[2][1]) || \is_NaN(a->m[2][2]) || \is_NaN(a->m[2][3])
      || \is_NaN(b->c[0]) || \is_NaN(b->c[1]) || \is_NaN(b->c[2])
      || \is_NaN(b->h[0]) || \is_NaN(b->h[1]) || \is_NaN(b->h[2]);
    predicate cbox_nan(cbx_cbox *b) =
      \is_NaN(b->c[0]) || \is_NaN(b->c[1]) || \is_NaN(b->c[2])
      || \is_NaN(b->h[0]) || \is_NaN(b->h[1]) || \is_NaN(b->h[2]);
    predicate box_nan(cbx_box *b) =
      \is_NaN(b->lo[0]) || \is_NaN(b->lo[1]) || \is_NaN(b->lo[2])
      || \is_NaN(b->hi[0]) || \is_NaN(b->hi[1]) || \is_NaN(b->hi[2]);
    // h < 0 on some axis (IEEE comparison; -0 is not negative)
    predicate cbox_empty(cbx_cbox *b) =
      \lt_double(b->h[0], (double)0.0) || \lt_double(b->h[1], (double)0.0)
      || \lt_double(b->h[2], (double)0.0);
    predicate cwhole_axis(cbx_cbox *o, integer i) =
      o->c[i] == 0 && \is_plus_infinity(o->h[i]);
    predicate cwhole(cbx_cbox *o) = cwhole_axis(o, 0) && cwhole_axis(o, 1) && cwhole_axis(o, 2);
    predicate cempty(cbx_cbox *o) =
         o->c[0] == 0 && \is_minus_infinity(o->h[0]) && o->c[1] == 0 && \is_minus_infinity(o->h[1])
      && o->c[2] == 0 && \is_minus_infinity(o->h[2]);

    predicate crow_dom(cbx_affine *a, cbx_cbox *b, integer i) =
      \is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
      && \is_finite(a->m[i][3])
      && \is_finite(b->c[0]) && \is_finite(b->c[1]) && \is_finite(b->c[2])
      && \is_finite(b->h[0]) && \is_finite(b->h[1]) && \is_finite(b->h[2])
      && crow_in_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                     b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2]);

    predicate caxis_proven(cbx_affine *a, cbx_cbox *b, cbx_cbox *o, integer i) =
      \is_finite(o->c[i]) && \is_finite(o->h[i])
      && cbox_corners(o->c[i], o->h[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                      b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2])
      && cbox_tight(o->c[i], o->h[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                    b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2]);

    // A column whose coefficient is 0 is dropped from a row (0 * inf = 0):
    // its center and half-width count as 0, whatever they are.
    logic real dz(real m, real x) = m == 0 ? 0 : x;

    predicate crow_full(double m0, double m1, double m2, double t,
                        double c0, double c1, double c2, double h0, double h1, double h2) =
      \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
      && \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
      && \is_finite(h0) && \is_finite(h1) && \is_finite(h2)
      && crow_in_dom(m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
    // The row with its zero-coefficient columns dropped is finite and in
    // the domain.
    predicate crow_dfull(double m0, double m1, double m2, double t,
                         double c0, double c1, double c2, double h0, double h1, double h2) =
      map_fin(m0, m1, m2, t)
      && (m0 != 0 ==> \is_finite(c0) && \is_finite(h0))
      && (m1 != 0 ==> \is_finite(c1) && \is_finite(h1))
      && (m2 != 0 ==> \is_finite(c2) && \is_finite(h2))
      && crow_in_dom(m0, m1, m2, t, dz(m0, c0), dz(m1, c1), dz(m2, c2),
                     dz(m0, h0), dz(m1, h1), dz(m2, h2));

    // One axis on the values: the kernel's statement on a full row; on a
    // row that is full once its zero-coefficient columns are dropped, the
    // same statement on the dropped row; (0, +inf) otherwise.
    predicate caxis_sound_s(double oc, double oh, double m0, double m1, double m2, double t,
                            double c0, double c1, double c2, double h0, double h1, double h2) =
      (crow_full(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) ==>
         (\is_finite(oc) && \is_finite(oh)
          && cbox_corners(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
          && cbox_tight(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2)))
      && ((!crow_full(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
           && crow_dfull(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)) ==>
         (\is_finite(oc) && \is_finite(oh)
          && cbox_corners(oc, oh, m0, m1, m2, t, dz(m0, c0), dz(m1, c1), dz(m2, c2),
                          dz(m0, h0), dz(m1, h1), dz(m2, h2))
          && cbox_tight(oc, oh, m0, m1, m2, t, dz(m0, c0), dz(m1, c1), dz(m2, c2),
                        dz(m0, h0), dz(m1, h1), dz(m2, h2))))
      && ((!crow_full(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
           && !crow_dfull(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)) ==>
         (oc == 0 && \is_plus_infinity(oh)));

    // Axis i is computed without loss (status CBX_OK).
    predicate crow_ok(cbx_affine *a, cbx_cbox *b, integer i) =
      crow_full(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2])
      || crow_dfull(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                    b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2]);


    // Conversions: one axis in their domain (finite, magnitude <= 2^1019).
    predicate conv_dom(real x, real y) = -0x1p1019 <= x <= 0x1p1019 && -0x1p1019 <= y <= 0x1p1019;

    predicate b2c_axis(cbx_box *in, cbx_cbox *out, integer i) =
      ((\is_finite(in->lo[i]) && \is_finite(in->hi[i]) && conv_dom(in->lo[i], in->hi[i])) ==>
         (\is_finite(out->c[i]) && \is_finite(out->h[i])
          && out->c[i] - out->h[i] <= in->lo[i] && in->hi[i] <= out->c[i] + out->h[i]))
      && (!(\is_finite(in->lo[i]) && \is_finite(in->hi[i]) && conv_dom(in->lo[i], in->hi[i])) ==>
          cwhole_axis(out, i));
    predicate c2b_axis(cbx_cbox *in, cbx_box *out, integer i) =
      ((\is_finite(in->c[i]) && \is_finite(in->h[i]) && conv_dom(in->c[i], in->h[i])) ==>
         (\is_finite(out->lo[i]) && \is_finite(out->hi[i])
          && out->lo[i] <= in->c[i] - in->h[i] && in->c[i] + in->h[i] <= out->hi[i]))
      && (!(\is_finite(in->c[i]) && \is_finite(in->h[i]) && conv_dom(in->c[i], in->h[i])) ==>
          whole_axis(out, i));
*/

/* Argument lists of the value predicates above, read at label L. */
#define CBX_AV(a, L) \
  \at((a)->m[0][0], L), \at((a)->m[0][1], L), \at((a)->m[0][2], L), \at((a)->m[0][3], L), \
  \at((a)->m[1][0], L), \at((a)->m[1][1], L), \at((a)->m[1][2], L), \at((a)->m[1][3], L), \
  \at((a)->m[2][0], L), \at((a)->m[2][1], L), \at((a)->m[2][2], L), \at((a)->m[2][3], L)
#define CBX_BV(b, L) \
  \at((b)->lo[0], L), \at((b)->hi[0], L), \at((b)->lo[1], L), \at((b)->hi[1], L), \
  \at((b)->lo[2], L), \at((b)->hi[2], L)

#endif /* CBX_SPEC_H */
