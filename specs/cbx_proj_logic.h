/*
 * ACSL logic of the projective bounds (cbx_project_box) that does not
 * depend on the floating-point format: real-valued definitions and the
 * one geometric fact the proofs need, proven once over the reals.
 *
 * A projective map sends p = (x, y, z) to (X_0/W, X_1/W, X_2/W) with
 * X_i = m_i0 x + m_i1 y + m_i2 z + m_i3 and W the fourth row.  Where W > 0
 * on a box, lo <= X_i/W <= hi at a point is lo W <= X_i <= hi W there, and
 * X_i - lo W is affine in p: its least value on a box is at a corner
 * (lemma aff_box).  So a bound that holds at the 8 corners holds at every
 * point of the box (plo_box, phi_box, pw_box): the image of the box is in
 * the hull of its 8 projected corners.
 *
 * The definitions are global (the public contract of cbx_project_box uses
 * them); the lemmas are in the block at the end, compiled only where
 * CBX_PROJ_LEMMAS is defined.
 */

/*@ // ---------------------------------------------------------------------
    // An affine function of a point; at least v at the 4 corners of a
    // face (face_ge).
    // ---------------------------------------------------------------------
    logic real aff(real k0, real k1, real k2, real k3, real x, real y, real z) =
      k0*x + k1*y + k2*z + k3;
    predicate face_ge(real k0, real k1, real k2, real k3, real x,
                      real l1, real h1, real l2, real h2, real v) =
         aff(k0, k1, k2, k3, x, l1, l2) >= v && aff(k0, k1, k2, k3, x, h1, l2) >= v
      && aff(k0, k1, k2, k3, x, l1, h2) >= v && aff(k0, k1, k2, k3, x, h1, h2) >= v;

    // ---------------------------------------------------------------------
    // One row of the map at a point, its exact magnitude (the scale of its
    // rounding), and the three statements the projective bound needs:
    // W >= v > 0, lo W <= X, X <= hi W.
    // ---------------------------------------------------------------------
    logic real pmag(real m0, real m1, real m2, real t, real x, real y, real z) =
      \abs(m0*x) + \abs(m1*y) + \abs(m2*z) + \abs(t);
    predicate ppos(real w0, real w1, real w2, real wt, real x, real y, real z) =
      0 < aff(w0, w1, w2, wt, x, y, z);
    predicate plo(real lo, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                  real x, real y, real z) =
      lo * aff(w0, w1, w2, wt, x, y, z) <= aff(m0, m1, m2, t, x, y, z);
    predicate phi(real hi, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                  real x, real y, real z) =
      aff(m0, m1, m2, t, x, y, z) <= hi * aff(w0, w1, w2, wt, x, y, z);

    // lo W <= X (X <= hi W) at the 8 corners: X - lo W (hi W - X) at least
    // 0 on both faces x = l0 and x = h0.
    predicate plo8(real lo, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                   real l0, real h0, real l1, real h1, real l2, real h2) =
         face_ge(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, l0, l1, h1, l2, h2, 0)
      && face_ge(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, h0, l1, h1, l2, h2, 0);
    predicate phi8(real hi, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                   real l0, real h0, real l1, real h1, real l2, real h2) =
         face_ge(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, l0, l1, h1, l2, h2, 0)
      && face_ge(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, h0, l1, h1, l2, h2, 0);

    // W at least v > 0 at the 8 corners.
    predicate pw8(real v, real w0, real w1, real w2, real wt,
                  real l0, real h0, real l1, real h1, real l2, real h2) =
         face_ge(w0, w1, w2, wt, l0, l1, h1, l2, h2, v) && face_ge(w0, w1, w2, wt, h0, l1, h1, l2, h2, v);

    // ---------------------------------------------------------------------
    // Quotients (src/core/cbx_quot.h: cbx_div_dn, cbx_div_up): their
    // statements are multiplied out by the divisor b > 0.  Named
    // predicates, so that the lemmas below have a trigger.
    // ---------------------------------------------------------------------
    predicate prod_le(real x, real y, real b) = x*b <= y*b;
    predicate abs_prod(real x, real b) = \abs(x)*b == \abs(x*b);
*/

/* The lemmas, only in the translation units that prove or use them
 * (proofs/lemmas.c, lemmas_f.c, proj.c, proj_f.c: CBX_PROJ_LEMMAS).  A
 * global lemma is a hypothesis of every goal of its unit: with these in
 * proofs/all.c and all_f.c, the same machine took 428 s for job K64
 * against 367 s, and 978 s for B64b against 679 s (the sphere's slowest
 * goals were pushed to pass 2), 2026-11-27. */
#ifdef CBX_PROJ_LEMMAS
/*@ // The corner argument, one axis at a time: at least v at both ends of
    // a segment, at least v on it; at the 4 corners of a face, on the face;
    // at the 8 corners, on the box.
    lemma aff_x: \forall real k0, k1, k2, k3, l, h, x, y, z, v;
      l <= x <= h ==> aff(k0, k1, k2, k3, l, y, z) >= v ==> aff(k0, k1, k2, k3, h, y, z) >= v
      ==> aff(k0, k1, k2, k3, x, y, z) >= v;
    lemma aff_y: \forall real k0, k1, k2, k3, l, h, x, y, z, v;
      l <= y <= h ==> aff(k0, k1, k2, k3, x, l, z) >= v ==> aff(k0, k1, k2, k3, x, h, z) >= v
      ==> aff(k0, k1, k2, k3, x, y, z) >= v;
    lemma aff_z: \forall real k0, k1, k2, k3, l, h, x, y, z, v;
      l <= z <= h ==> aff(k0, k1, k2, k3, x, y, l) >= v ==> aff(k0, k1, k2, k3, x, y, h) >= v
      ==> aff(k0, k1, k2, k3, x, y, z) >= v;
    lemma aff_face: \forall real k0, k1, k2, k3, x, l1, h1, l2, h2, y, z, v;
      face_ge(k0, k1, k2, k3, x, l1, h1, l2, h2, v)
      ==> l1 <= y <= h1 ==> l2 <= z <= h2 ==> aff(k0, k1, k2, k3, x, y, z) >= v;
    lemma aff_box: \forall real k0, k1, k2, k3, l0, h0, l1, h1, l2, h2, x, y, z, v;
      face_ge(k0, k1, k2, k3, l0, l1, h1, l2, h2, v) ==> face_ge(k0, k1, k2, k3, h0, l1, h1, l2, h2, v)
      ==> l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2 ==> aff(k0, k1, k2, k3, x, y, z) >= v;

    lemma aff_pmag: \forall real m0, m1, m2, t, x, y, z;
      \abs(aff(m0, m1, m2, t, x, y, z)) <= pmag(m0, m1, m2, t, x, y, z);

    // proof: z3
    lemma plo_aff: \forall real lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z;
      plo(lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
      <==> aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, x, y, z) >= 0;
    // proof: z3
    lemma phi_aff: \forall real hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z;
      phi(hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
      <==> aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, x, y, z) >= 0;

    lemma plo_box: \forall real lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2, x, y, z;
      plo8(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2)
      ==> l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2
      ==> plo(lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    lemma phi_box: \forall real hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2, x, y, z;
      phi8(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2)
      ==> l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2
      ==> phi(hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);

    // W at least v > 0 at the 8 corners, hence on the box.
    lemma pw_box: \forall real v, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2, x, y, z;
      pw8(v, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2)
      ==> l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2
      ==> aff(w0, w1, w2, wt, x, y, z) >= v;
*/

/*@ // The interval kernel on a one-point box [x, x] x [y, y] x [z, z] is the
    // row's value there, and its scale the row's magnitude there.
    lemma row_lo_point: \forall real m0, m1, m2, t, x, y, z;
      row_lo(m0, m1, m2, t, x, x, y, y, z, z) == aff(m0, m1, m2, t, x, y, z);
    lemma row_hi_point: \forall real m0, m1, m2, t, x, y, z;
      row_hi(m0, m1, m2, t, x, x, y, y, z, z) == aff(m0, m1, m2, t, x, y, z);
    lemma row_mag_point: \forall real m0, m1, m2, t, x, y, z;
      row_mag(m0, m1, m2, t, x, x, y, y, z, z) == pmag(m0, m1, m2, t, x, y, z);
*/

/*@ // The quotients' product steps (prod_le, abs_prod above).
    lemma prod_le_nn: \forall real x, y, b; b >= 0 ==> x <= y ==> prod_le(x, y, b);
    lemma abs_prod_pos: \forall real x, b; b > 0 ==> abs_prod(x, b);
*/
#endif
