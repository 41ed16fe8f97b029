/*
 * ACSL logic of the transform classes and of motion (src/f64/cbx_class.c,
 * src/f64/cbx_motion.c).  Read by Frama-C only.
 */
#ifndef CBX_CLASS_SPEC_H
#define CBX_CLASS_SPEC_H

/*@ // ---------------------------------------------------------------------
    // The classes, on the map's entries (zeros and ones compared as reals:
    // -0 is 0).  Each is contained in the next.
    // ---------------------------------------------------------------------
    predicate aff_fin(cbx_affine *a) =
         \is_finite(a->m[0][0]) && \is_finite(a->m[0][1]) && \is_finite(a->m[0][2]) && \is_finite(a->m[0][3])
      && \is_finite(a->m[1][0]) && \is_finite(a->m[1][1]) && \is_finite(a->m[1][2]) && \is_finite(a->m[1][3])
      && \is_finite(a->m[2][0]) && \is_finite(a->m[2][1]) && \is_finite(a->m[2][2]) && \is_finite(a->m[2][3]);

    // Row i has at most one nonzero linear entry.
    predicate row_sparse(cbx_affine *a, integer i) =
         (a->m[i][1] == 0 && a->m[i][2] == 0)
      || (a->m[i][0] == 0 && a->m[i][2] == 0)
      || (a->m[i][0] == 0 && a->m[i][1] == 0);
    predicate is_permute(cbx_affine *a) =
      aff_fin(a) && row_sparse(a, 0) && row_sparse(a, 1) && row_sparse(a, 2);
    predicate is_scale(cbx_affine *a) =
      aff_fin(a) && a->m[0][1] == 0 && a->m[0][2] == 0 && a->m[1][0] == 0
      && a->m[1][2] == 0 && a->m[2][0] == 0 && a->m[2][1] == 0;
    predicate is_translate(cbx_affine *a) =
      is_scale(a) && a->m[0][0] == 1 && a->m[1][1] == 1 && a->m[2][2] == 1;
    predicate is_identity(cbx_affine *a) =
      is_translate(a) && a->m[0][3] == 0 && a->m[1][3] == 0 && a->m[2][3] == 0;

    // The map is in class c (GENERAL holds for every map).
    predicate class_ok(cbx_affine *a, integer c) =
         c == CBX_CLASS_GENERAL
      || (c == CBX_CLASS_PERMUTE && is_permute(a))
      || (c == CBX_CLASS_SCALE && is_scale(a))
      || (c == CBX_CLASS_TRANSLATE && is_translate(a))
      || (c == CBX_CLASS_IDENTITY && is_identity(a));

    // c is the smallest class that holds.
    predicate class_least(cbx_affine *a, integer c) =
         (c == CBX_CLASS_GENERAL ==> !is_permute(a))
      && (c == CBX_CLASS_PERMUTE ==> !is_scale(a))
      && (c == CBX_CLASS_SCALE ==> !is_translate(a))
      && (c == CBX_CLASS_TRANSLATE ==> !is_identity(a));

    // The fast range of the class kernels: every box end finite, ordered,
    // |end| <= B; linear entries |m| <= B; translations |t| <= 2^1018.
    predicate fast_ends(cbx_box *b, real B) =
         \is_finite(b->lo[0]) && \is_finite(b->hi[0]) && \is_finite(b->lo[1])
      && \is_finite(b->hi[1]) && \is_finite(b->lo[2]) && \is_finite(b->hi[2])
      && -B <= b->lo[0] <= B && -B <= b->hi[0] <= B && -B <= b->lo[1] <= B
      && -B <= b->hi[1] <= B && -B <= b->lo[2] <= B && -B <= b->hi[2] <= B
      && b->lo[0] <= b->hi[0] && b->lo[1] <= b->hi[1] && b->lo[2] <= b->hi[2];
    predicate fast_lin(cbx_affine *a, real B) =
         -B <= a->m[0][0] <= B && -B <= a->m[0][1] <= B && -B <= a->m[0][2] <= B
      && -B <= a->m[1][0] <= B && -B <= a->m[1][1] <= B && -B <= a->m[1][2] <= B
      && -B <= a->m[2][0] <= B && -B <= a->m[2][1] <= B && -B <= a->m[2][2] <= B;
    predicate fast_tr(cbx_affine *a) =
         -0x1p1018 <= a->m[0][3] <= 0x1p1018 && -0x1p1018 <= a->m[1][3] <= 0x1p1018
      && -0x1p1018 <= a->m[2][3] <= 0x1p1018;

    // ---------------------------------------------------------------------
    // One output end of a class kernel: one column (m, l, h) and t.
    // lo <= the exact lower end, and no more than 12 u S + 2^-1065 below it
    // (S = |t| + max(|m l|, |m h|)); hi the mirror.
    // ---------------------------------------------------------------------
    predicate span_ok(real lo, real hi, real m, real t, real l, real h) =
      lo <= t + tmin(m, l, h) && hi >= t + tmax(m, l, h)
      && lo >= t + tmin(m, l, h) - (0x1.8p-50 * (\abs(t) + tmag(m, l, h)) + 0x1p-1065)
      && hi <= t + tmax(m, l, h) + (0x1.8p-50 * (\abs(t) + tmag(m, l, h)) + 0x1p-1065);

    // ---------------------------------------------------------------------
    // Motion: the row of M(s) = (1 - s) M0 + s M1.
    // ---------------------------------------------------------------------
    logic real lerp(real s, real x, real y) = (1 - s) * x + s * y;

    // r is below (above) both ends: then below (above) every point between
    // (lemmas lerp_below, lerp_above, below).  Named predicates: the lemmas'
    // conclusions are their triggers.
    predicate between_lo(real r, real x, real y, real s) = r <= lerp(s, x, y);
    predicate between_hi(real r, real x, real y, real s) = lerp(s, x, y) <= r;

    // The value of row M(s) at point p (lemma mrow_split, below: its split
    // into the two ends').
    logic real mrow(real s, real m0, real m1, real m2, real t, real n0, real n1, real n2, real u,
                    real p0, real p1, real p2) =
      lerp(s, m0, n0) * p0 + lerp(s, m1, n1) * p1 + lerp(s, m2, n2) * p2 + lerp(s, t, u);

    // r <= (M(s) p)_i, r >= (M(s) p)_i: named, so that the lemmas below
    // (mrow_below, mrow_ge_lerp, mrow_above) have a trigger holding all
    // their variables.
    predicate mrow_le(real r, real s, real m0, real m1, real m2, real t,
                      real n0, real n1, real n2, real u, real p0, real p1, real p2) =
      r <= mrow(s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2);
    predicate mrow_ge(real r, real s, real m0, real m1, real m2, real t,
                      real n0, real n1, real n2, real u, real p0, real p1, real p2) =
      mrow(s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2) <= r;

    // r is below (above) M(s) c for every corner c of the box.
    predicate mot_below8(real r, real s, real m0, real m1, real m2, real t,
                         real n0, real n1, real n2, real u,
                         real l0, real h0, real l1, real h1, real l2, real h2) =
         mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, l1, l2)
      && mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, l1, h2)
      && mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, h1, l2)
      && mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, h1, h2)
      && mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, l1, l2)
      && mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, l1, h2)
      && mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, h1, l2)
      && mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, h1, h2);
    predicate mot_above8(real r, real s, real m0, real m1, real m2, real t,
                         real n0, real n1, real n2, real u,
                         real l0, real h0, real l1, real h1, real l2, real h2) =
         mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, l1, l2)
      && mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, l1, h2)
      && mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, h1, l2)
      && mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, l0, h1, h2)
      && mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, l1, l2)
      && mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, l1, h2)
      && mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, h1, l2)
      && mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, h0, h1, h2);

    // A finite end r bounds M(s) p for every real point p of the box
    // (infinite box ends are no constraint).
    predicate mot_ext_below(double r, real s, real m0, real m1, real m2, real t,
                            real n0, real n1, real n2, real u,
                            double l0, double h0, double l1, double h1, double l2, double h2) =
      \is_finite(r) ==> \forall real p0, p1, p2;
        ext_in(p0, l0, h0) && ext_in(p1, l1, h1) && ext_in(p2, l2, h2) ==>
        mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2);
    predicate mot_ext_above(double r, real s, real m0, real m1, real m2, real t,
                            real n0, real n1, real n2, real u,
                            double l0, double h0, double l1, double h1, double l2, double h2) =
      \is_finite(r) ==> \forall real p0, p1, p2;
        ext_in(p0, l0, h0) && ext_in(p1, l1, h1) && ext_in(p2, l2, h2) ==>
        mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2);

    // One output axis of cbx_motion_box: rows (m, t) of M0 and (n, u) of M1.
    predicate mot_axis(double lo, double hi,
                       double m0, double m1, double m2, double t,
                       double n0, double n1, double n2, double u,
                       double l0, double h0, double l1, double h1, double l2, double h2) =
      ((row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
        && row_full(n0, n1, n2, u, l0, h0, l1, h1, l2, h2)) ==>
         (\is_finite(lo) && \is_finite(hi)
          && \forall real s; 0 <= s <= 1 ==>
               mot_below8(lo, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2)
               && mot_above8(hi, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2)))
      && ((!(row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
             && row_full(n0, n1, n2, u, l0, h0, l1, h1, l2, h2))
           && map_fin(m0, m1, m2, t) && map_fin(n0, n1, n2, u)) ==>
          \forall real s; 0 <= s <= 1 ==>
            mot_ext_below(lo, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2)
            && mot_ext_above(hi, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2))
      && ((!map_fin(m0, m1, m2, t) || !map_fin(n0, n1, n2, u)) ==>
          (\is_minus_infinity(lo) && \is_plus_infinity(hi)));

    // Tightness of one full axis of cbx_motion_box: the exact end over the
    // shutter interval is the smaller (larger) of the two rows' exact ends
    // (M(s) p is affine in s, so its extremes are at s = 0 or s = 1); each
    // end within 12 u S + 2^-1065 of it, S the larger row magnitude.
    predicate mot_tight(double lo, double hi,
                        double m0, double m1, double m2, double t,
                        double n0, double n1, double n2, double u,
                        double l0, double h0, double l1, double h1, double l2, double h2) =
      (row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
       && row_full(n0, n1, n2, u, l0, h0, l1, h1, l2, h2)) ==>
        (lo >= \min(row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2),
                    row_lo(n0, n1, n2, u, l0, h0, l1, h1, l2, h2))
               - (0x1.8p-50 * \max(row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2),
                                   row_mag(n0, n1, n2, u, l0, h0, l1, h1, l2, h2)) + 0x1p-1065)
         && hi <= \max(row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2),
                       row_hi(n0, n1, n2, u, l0, h0, l1, h1, l2, h2))
               + (0x1.8p-50 * \max(row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2),
                                   row_mag(n0, n1, n2, u, l0, h0, l1, h1, l2, h2)) + 0x1p-1065));

    // Axis i: both rows full, or neither (cbx_motion_box's CBX_OK needs it).
    predicate mot_same(cbx_affine *a0, cbx_affine *a1, cbx_box *b, integer i) =
      row_full(a0->m[i][0], a0->m[i][1], a0->m[i][2], a0->m[i][3],
               b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      <==> row_full(a1->m[i][0], a1->m[i][1], a1->m[i][2], a1->m[i][3],
                    b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);
*/

/* The motion lemmas: only in the units that use them (CBX_MOTION_LEMMAS: the
 * lemma job L64, which proves them, and job B64a, which proves
 * src/f64/cbx_motion.c), not as hypotheses of every goal of proofs/all.c. */
#ifdef CBX_MOTION_LEMMAS
/*@ // r below (above) both ends is below (above) every point between.
    lemma lerp_below: \forall real r, x, y, s;
      0 <= s <= 1 ==> r <= x ==> r <= y ==> between_lo(r, x, y, s);
    // proof: z3
    lemma lerp_above: \forall real r, x, y, s;
      0 <= s <= 1 ==> r >= x ==> r >= y ==> between_hi(r, x, y, s);

    // Row M(s) at p is the interpolation of the two ends' values at p.
    // proof: z3
    lemma mrow_split: \forall real s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2;
      mrow(s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2)
        == lerp(s, m0*p0 + m1*p1 + m2*p2 + t, n0*p0 + n1*p1 + n2*p2 + u);

    // A value below (above) both end images of p is below (above) its image
    // under M(s), 0 <= s <= 1.
    lemma mrow_below: \forall real r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2;
      0 <= s <= 1 ==> r <= m0*p0 + m1*p1 + m2*p2 + t ==> r <= n0*p0 + n1*p1 + n2*p2 + u ==>
      mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2);
    lemma mrow_ge_lerp: \forall real r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2;
      between_hi(r, m0*p0 + m1*p1 + m2*p2 + t, n0*p0 + n1*p1 + n2*p2 + u, s) ==>
      mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2);
    lemma mrow_above: \forall real r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2;
      0 <= s <= 1 ==> r >= m0*p0 + m1*p1 + m2*p2 + t ==> r >= n0*p0 + n1*p1 + n2*p2 + u ==>
      mrow_ge(r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2);
*/
#endif
#endif /* CBX_CLASS_SPEC_H */
