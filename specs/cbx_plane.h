/*
 * ACSL logic of the 2D family, per floating-point format (included by
 * certbox.h after specs/cbx_spec.h, once per format, like it; the
 * binary32 names end in _f, include/cbx_names_f.h).
 *
 * A 2D map (cbx_affine2) is y_i = m_i0 x_0 + m_i1 x_1 + m_i2, i = 0, 1; a
 * 2D box (cbx_box2) is [lo_0, hi_0] x [lo_1, hi_1].  Each output axis of
 * the 2D form is stated as the same axis of the 3D statement
 * (specs/cbx_spec.h: axis_sound_s, axis_ok_s) with a zero third column
 * and a third box axis [0, 0]: the exact image m_i0 x_0 + m_i1 x_1 + 0 * 0
 * + m_i2 of every point (x_0, x_1) of the box is the 2D image, and the
 * tightness bound is the same (a zero term adds nothing to row_mag).  So
 * the 2D promise is the 3D one, word for word, on the plane z = 0.
 *
 * Arithmetic is exact real arithmetic on the values of the C variables.
 */

/*@ // ---------------------------------------------------------------------
    // The special inputs and outputs of the 2D form.
    // ---------------------------------------------------------------------
    predicate aff2_nan(cbx_affine2 *a) =
         \is_NaN(a->m[0][0]) || \is_NaN(a->m[0][1]) || \is_NaN(a->m[0][2])
      || \is_NaN(a->m[1][0]) || \is_NaN(a->m[1][1]) || \is_NaN(a->m[1][2]);
    predicate box2_nan(cbx_box2 *b) =
      \is_NaN(b->lo[0]) || \is_NaN(b->lo[1]) || \is_NaN(b->hi[0]) || \is_NaN(b->hi[1]);
    predicate has_nan2(cbx_affine2 *a, cbx_box2 *b) = aff2_nan(a) || box2_nan(b);
    predicate is_empty2(cbx_box2 *b) =
      no_point(b->lo[0], b->hi[0]) || no_point(b->lo[1], b->hi[1]);
    predicate whole_plane(cbx_box2 *o) =
         \is_minus_infinity(o->lo[0]) && \is_plus_infinity(o->hi[0])
      && \is_minus_infinity(o->lo[1]) && \is_plus_infinity(o->hi[1]);
    predicate empty_out2(cbx_box2 *o) =
         \is_plus_infinity(o->lo[0]) && \is_minus_infinity(o->hi[0])
      && \is_plus_infinity(o->lo[1]) && \is_minus_infinity(o->hi[1]);

    // ---------------------------------------------------------------------
    // One output axis of the 2D interval form: the row (m0, m1, t) of the
    // map on the box [l0, h0] x [l1, h1], stated as cbx_transform_box's
    // axis with the zero column (0) and the box axis [0, 0].
    // ---------------------------------------------------------------------
    predicate axis2_sound(cbx_fp lo, cbx_fp hi, cbx_fp m0, cbx_fp m1, cbx_fp t,
                          cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1) =
      axis_sound_s(lo, hi, m0, m1, (cbx_fp)0.0, t, l0, h0, l1, h1, (cbx_fp)0.0, (cbx_fp)0.0);
    predicate axis2_ok(cbx_fp m0, cbx_fp m1, cbx_fp t, cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1) =
      axis_ok_s(m0, m1, (cbx_fp)0.0, t, l0, h0, l1, h1, (cbx_fp)0.0, (cbx_fp)0.0);
    predicate row2_ok(cbx_affine2 *a, cbx_box2 *b, integer i) =
      axis2_ok(a->m[i][0], a->m[i][1], a->m[i][2], b->lo[0], b->hi[0], b->lo[1], b->hi[1]);

    // ---------------------------------------------------------------------
    // The center/half-diagonal form of the plane (cbx_cbox2): the 3D
    // form's statement (specs/cbx_spec.h: caxis_sound_s, crow_full,
    // crow_dfull) with the zero third column and c_2 = h_2 = 0.
    // ---------------------------------------------------------------------
    predicate cbox2_nan(cbx_cbox2 *b) =
      \is_NaN(b->c[0]) || \is_NaN(b->c[1]) || \is_NaN(b->h[0]) || \is_NaN(b->h[1]);
    predicate cbox2_has_nan(cbx_affine2 *a, cbx_cbox2 *b) = aff2_nan(a) || cbox2_nan(b);
    // h < 0 on some axis (IEEE comparison; -0 is not negative)
    predicate cbox2_empty(cbx_cbox2 *b) =
      CBX_LT(b->h[0], (cbx_fp)0.0) || CBX_LT(b->h[1], (cbx_fp)0.0);
    predicate cwhole2(cbx_cbox2 *o) =
      o->c[0] == 0 && \is_plus_infinity(o->h[0]) && o->c[1] == 0 && \is_plus_infinity(o->h[1]);
    predicate cempty2(cbx_cbox2 *o) =
      o->c[0] == 0 && \is_minus_infinity(o->h[0]) && o->c[1] == 0 && \is_minus_infinity(o->h[1]);
    predicate caxis2_sound(cbx_fp oc, cbx_fp oh, cbx_fp m0, cbx_fp m1, cbx_fp t,
                           cbx_fp c0, cbx_fp c1, cbx_fp h0, cbx_fp h1) =
      caxis_sound_s(oc, oh, m0, m1, (cbx_fp)0.0, t, c0, c1, (cbx_fp)0.0, h0, h1, (cbx_fp)0.0);
    predicate caxis2_ok(cbx_fp m0, cbx_fp m1, cbx_fp t, cbx_fp c0, cbx_fp c1, cbx_fp h0, cbx_fp h1) =
      crow_full(m0, m1, (cbx_fp)0.0, t, c0, c1, (cbx_fp)0.0, h0, h1, (cbx_fp)0.0)
      || crow_dfull(m0, m1, (cbx_fp)0.0, t, c0, c1, (cbx_fp)0.0, h0, h1, (cbx_fp)0.0);
    predicate crow2_ok(cbx_affine2 *a, cbx_cbox2 *b, integer i) =
      caxis2_ok(a->m[i][0], a->m[i][1], a->m[i][2], b->c[0], b->c[1], b->h[0], b->h[1]);

    // ---------------------------------------------------------------------
    // Disks and ellipses: the image of the unit disk p0^2 + p1^2 <= 1 under
    // a 2D map, one axis (b0, b1) . p + t.  The code computes the 3D ball's
    // axis with a zero third entry (specs/cbx_ball.h: ball_axis, whose
    // third coordinate then adds nothing); lemma ball_disk turns that into
    // the 2D statement, and the tightness is ball_tight with that zero
    // (rnorm3(b0, b1, 0) is the exact 2D row norm).
    // ---------------------------------------------------------------------
    // Written with the ball's own terms: in_ball(p0, p1, 0) is
    // p0^2 + p1^2 <= 1 and dot3(b0, b1, 0, p0, p1, 0) is b0 p0 + b1 p1
    // (specs/cbx_ball.h), so lemma ball_disk is one instance of ball_axis
    // (p2 = 0) and lemma disk_plain restates it in plain terms.
    predicate disk_cover(real lo, real hi, real b0, real b1, real t) =
      \forall real p0, p1; in_ball(p0, p1, 0) ==> lo <= dot3(b0, b1, 0, p0, p1, 0) + t <= hi;

    // Axis i of the disk's box: inside the sphere's domain (specs/cbx_spec.h:
    // sph_dom) finite, covering the disk's image, within ball_tight of the
    // exact ends t -+ sqrt(m0^2 + m1^2); outside it [-inf, +inf].
    predicate disk_dom(cbx_fp m0, cbx_fp m1, cbx_fp t) =
      \is_finite(m0) && \is_finite(m1) && \is_finite(t) && sph_dom(m0, m1, 0, t);
    predicate disk_axis(cbx_fp lo, cbx_fp hi, cbx_fp m0, cbx_fp m1, cbx_fp t) =
      (disk_dom(m0, m1, t) ==>
         (\is_finite(lo) && \is_finite(hi) && disk_cover(lo, hi, m0, m1, t)
          && ball_tight(lo, hi, m0, m1, 0, t)))
      && (!disk_dom(m0, m1, t) ==> \is_minus_infinity(lo) && \is_plus_infinity(hi));

    // The ellipse center + rot diag(radii) p, |p| <= 1: axis i is the disk
    // axis of the row (rot_i0 radii_0, rot_i1 radii_1) (exact products).
    predicate ell2_nan(cbx_fp *center, cbx_fp *radii, cbx_fp (*rot)[2]) =
         \is_NaN(center[0]) || \is_NaN(center[1]) || \is_NaN(radii[0]) || \is_NaN(radii[1])
      || \is_NaN(rot[0][0]) || \is_NaN(rot[0][1]) || \is_NaN(rot[1][0]) || \is_NaN(rot[1][1]);
    predicate ell2_dom(cbx_fp r0, cbx_fp r1, cbx_fp d0, cbx_fp d1, cbx_fp c) =
      \is_finite(r0) && \is_finite(r1) && \is_finite(d0) && \is_finite(d1) && \is_finite(c)
      && ell_dom(r0, r1, 0, d0, d1, 0, c);
    predicate ell2_axis(cbx_fp lo, cbx_fp hi, cbx_fp r0, cbx_fp r1, cbx_fp d0, cbx_fp d1, cbx_fp c) =
      (ell2_dom(r0, r1, d0, d1, c) ==>
         (\is_finite(lo) && \is_finite(hi) && disk_cover(lo, hi, r0*d0, r1*d1, c)
          && ball_tight(lo, hi, r0*d0, r1*d1, 0, c)))
      && (!ell2_dom(r0, r1, d0, d1, c) ==> \is_minus_infinity(lo) && \is_plus_infinity(hi));
*/

/* The disk's lemmas (above: ball_disk, disk_plain), with specs/cbx_ball.h's
 * only in the proof jobs of src/algo/cbx_sphere.c and the lemma jobs
 * (CBX_BALL_LEMMAS). */
#ifdef CBX_BALL_LEMMAS
/*@
    lemma ball_disk: \forall real lo, hi, b0, b1, t;
      ball_axis(lo, hi, b0, b1, 0, t) ==> disk_cover(lo, hi, b0, b1, t);
    // proof: z3
    lemma disk_plain: \forall real lo, hi, b0, b1, t, p0, p1;
      disk_cover(lo, hi, b0, b1, t) ==> p0*p0 + p1*p1 <= 1 ==> lo <= b0*p0 + b1*p1 + t <= hi;
*/
#endif
