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
    // The same notions on the public structures.
    // ---------------------------------------------------------------------
    predicate has_nan(cbx_affine *a, cbx_box *b) =
         \is_NaN(a->m[0][0]) || \is_NaN(a->m[0][1]) || \is_NaN(a->m[0][2]) || \is_NaN(a->m[0][3])
      || \is_NaN(a->m[1][0]) || \is_NaN(a->m[1][1]) || \is_NaN(a->m[1][2]) || \is_NaN(a->m[1][3])
      || \is_NaN(a->m[2][0]) || \is_NaN(a->m[2][1]) || \is_NaN(a->m[2][2]) || \is_NaN(a->m[2][3])
      || \is_NaN(b->lo[0]) || \is_NaN(b->lo[1]) || \is_NaN(b->lo[2])
      || \is_NaN(b->hi[0]) || \is_NaN(b->hi[1]) || \is_NaN(b->hi[2]);

    // IEEE comparison (also meaningful for infinite bounds).
    predicate is_empty(cbx_box *b) =
      \lt_double(b->hi[0], b->lo[0]) || \lt_double(b->hi[1], b->lo[1])
      || \lt_double(b->hi[2], b->lo[2]);

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

    // What the function promises on one axis, on the values themselves:
    // proven inside the domain, the whole line [-inf, +inf] outside it.
    predicate axis_sound_s(double lo, double hi, double m0, double m1, double m2, double t,
                           double l0, double h0, double l1, double h1, double l2, double h2) =
      ((\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
        && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
        && \is_finite(l2) && \is_finite(h2)
        && row_in_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==>
         (\is_finite(lo) && \is_finite(hi)
          && below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)))
      && (!(\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
        && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
        && \is_finite(l2) && \is_finite(h2)
        && row_in_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==>
         (\is_minus_infinity(lo) && \is_plus_infinity(hi)));

    // The same on the public structures: the inputs read at label I, the
    // output at label O (the output may be the input box itself).
    predicate axis_sound{I,O}(cbx_affine *a, cbx_box *b, cbx_box *o, integer i) =
      axis_sound_s(\at(o->lo[i], O), \at(o->hi[i], O),
                   \at(a->m[i][0], I), \at(a->m[i][1], I), \at(a->m[i][2], I), \at(a->m[i][3], I),
                   \at(b->lo[0], I), \at(b->hi[0], I), \at(b->lo[1], I), \at(b->hi[1], I),
                   \at(b->lo[2], I), \at(b->hi[2], I));
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

    // One axis on the values: the kernel's statement inside the domain,
    // (0, +inf) outside it.
    predicate caxis_sound_s(double oc, double oh, double m0, double m1, double m2, double t,
                            double c0, double c1, double c2, double h0, double h1, double h2) =
      ((\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
        && \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
        && \is_finite(h0) && \is_finite(h1) && \is_finite(h2)
        && crow_in_dom(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)) ==>
         (\is_finite(oc) && \is_finite(oh)
          && cbox_corners(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
          && cbox_tight(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2)))
      && (!(\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
        && \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
        && \is_finite(h0) && \is_finite(h1) && \is_finite(h2)
        && crow_in_dom(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)) ==>
         (oc == 0 && \is_plus_infinity(oh)));

    // The same on the public structures: inputs at label I, output at O
    // (the output may be the input cbox itself).
    predicate caxis_sound{I,O}(cbx_affine *a, cbx_cbox *b, cbx_cbox *o, integer i) =
      caxis_sound_s(\at(o->c[i], O), \at(o->h[i], O),
                    \at(a->m[i][0], I), \at(a->m[i][1], I), \at(a->m[i][2], I), \at(a->m[i][3], I),
                    \at(b->c[0], I), \at(b->c[1], I), \at(b->c[2], I),
                    \at(b->h[0], I), \at(b->h[1], I), \at(b->h[2], I));

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

#endif /* CBX_SPEC_H */
