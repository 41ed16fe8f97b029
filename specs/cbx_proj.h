/*
 * ACSL logic of the projective bound (cbx_project_box), per floating-point
 * format (included by certbox.h after specs/cbx_spec.h, once per format;
 * the binary32 names end in _f, include/cbx_names_f.h).  The real-valued
 * part, with the corner argument, is specs/cbx_proj_logic.h.
 *
 * A projective map (cbx_proj) has rows X_0, X_1, X_2 and W, each
 * m_i0 x + m_i1 y + m_i2 z + m_i3 (aff).  Output axis i is X_i / W.
 * Arithmetic is exact real arithmetic on the values of the C variables.
 */

/*@ // ---------------------------------------------------------------------
    // Special inputs, and the range the bound is computed in: every linear
    // entry at most CBX_SB (2^509; binary32 2^61), every translation at
    // most CBX_RT (2^1018; binary32 2^122), as the fast range of the affine
    // transform (map_fast), for all four rows.
    // ---------------------------------------------------------------------
    predicate proj_nan(cbx_proj *p) =
         \is_NaN(p->m[0][0]) || \is_NaN(p->m[0][1]) || \is_NaN(p->m[0][2]) || \is_NaN(p->m[0][3])
      || \is_NaN(p->m[1][0]) || \is_NaN(p->m[1][1]) || \is_NaN(p->m[1][2]) || \is_NaN(p->m[1][3])
      || \is_NaN(p->m[2][0]) || \is_NaN(p->m[2][1]) || \is_NaN(p->m[2][2]) || \is_NaN(p->m[2][3])
      || \is_NaN(p->m[3][0]) || \is_NaN(p->m[3][1]) || \is_NaN(p->m[3][2]) || \is_NaN(p->m[3][3]);
    predicate prow_fast(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t) =
         \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
      && -CBX_SB <= m0 <= CBX_SB && -CBX_SB <= m1 <= CBX_SB && -CBX_SB <= m2 <= CBX_SB
      && -CBX_RT <= t <= CBX_RT;
    predicate proj_fast(cbx_proj *p) =
         prow_fast(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3])
      && prow_fast(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3])
      && prow_fast(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3])
      && prow_fast(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);

    // ---------------------------------------------------------------------
    // One corner (x, y, z).  perr: the rounding of the interval kernel on
    // a row there (12 u S + 2^-1065, S = pmag).  pclear: W there exceeds
    // it (the camera plane is clear of the corner).  pnear: X_i / W there
    // is far inside the range of the quotient (|X| at most 2^999 W,
    // binary32 2^119, with the roundings), which implies pclear.
    // ---------------------------------------------------------------------
    logic real perr(real m0, real m1, real m2, real t, real x, real y, real z) =
      CBX_U12 * pmag(m0, m1, m2, t, x, y, z) + CBX_ETA512;
    predicate pclear(real w0, real w1, real w2, real wt, real x, real y, real z) =
      aff(w0, w1, w2, wt, x, y, z) > perr(w0, w1, w2, wt, x, y, z);
    // [wl, wh] encloses W at the corner to within the kernel's rounding
    // (what the interval kernel returns there: computed once per corner and
    // shared by the three output axes).
    predicate wenc(real wl, real wh, real w0, real w1, real w2, real wt, real x, real y, real z) =
      wl <= aff(w0, w1, w2, wt, x, y, z) <= wh
      && aff(w0, w1, w2, wt, x, y, z) - wl <= perr(w0, w1, w2, wt, x, y, z)
      && wh - aff(w0, w1, w2, wt, x, y, z) <= perr(w0, w1, w2, wt, x, y, z);
    predicate pnear(real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                    real x, real y, real z) =
      (\abs(aff(m0, m1, m2, t, x, y, z)) + perr(m0, m1, m2, t, x, y, z)) * (2*CBX_QS) + CBX_ETA
      <= aff(w0, w1, w2, wt, x, y, z) - perr(w0, w1, w2, wt, x, y, z);

    // Tightness at a corner: r W is within 24 u (S_X + |r| S_W) + 2^-1064
    // (1 + |r| + S_W) of X (binary32: 2^-139): r is X/W to within that
    // divided by W.
    logic real ptol(real r, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                    real x, real y, real z) =
      2*CBX_U12 * (pmag(m0, m1, m2, t, x, y, z) + \abs(r) * pmag(w0, w1, w2, wt, x, y, z))
      + CBX_ETA1024 * (1 + \abs(r) + pmag(w0, w1, w2, wt, x, y, z));
    predicate pt_lo(real r, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                    real x, real y, real z) =
      aff(m0, m1, m2, t, x, y, z) - r * aff(w0, w1, w2, wt, x, y, z)
      <= ptol(r, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    predicate pt_hi(real r, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                    real x, real y, real z) =
      r * aff(w0, w1, w2, wt, x, y, z) - aff(m0, m1, m2, t, x, y, z)
      <= ptol(r, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);

    // What one corner's computation gives: W at least wl > 0 there, lo W
    // <= X <= hi W there, each end tight there, in the quotient's range.
    predicate pcorner(cbx_fp lo, cbx_fp hi, cbx_fp wl,
                      real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                      real x, real y, real z) =
      \is_finite(lo) && \is_finite(hi) && \is_finite(wl)
      && 0 < wl <= aff(w0, w1, w2, wt, x, y, z)
      && plo(lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
      && phi(hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
      && pt_lo(lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
      && pt_hi(hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
      && -2*CBX_QR <= lo <= 2*CBX_QR && -2*CBX_QR <= hi <= 2*CBX_QR;

    // ---------------------------------------------------------------------
    // The 8 corners of [l0, h0] x [l1, h1] x [l2, h2].
    // ---------------------------------------------------------------------
    predicate pclear8(real w0, real w1, real w2, real wt,
                      real l0, real h0, real l1, real h1, real l2, real h2) =
         pclear(w0, w1, w2, wt, l0, l1, l2) && pclear(w0, w1, w2, wt, h0, l1, l2)
      && pclear(w0, w1, w2, wt, l0, h1, l2) && pclear(w0, w1, w2, wt, h0, h1, l2)
      && pclear(w0, w1, w2, wt, l0, l1, h2) && pclear(w0, w1, w2, wt, h0, l1, h2)
      && pclear(w0, w1, w2, wt, l0, h1, h2) && pclear(w0, w1, w2, wt, h0, h1, h2);
    predicate pfront8(real w0, real w1, real w2, real wt,
                      real l0, real h0, real l1, real h1, real l2, real h2) =
         ppos(w0, w1, w2, wt, l0, l1, l2) && ppos(w0, w1, w2, wt, h0, l1, l2)
      && ppos(w0, w1, w2, wt, l0, h1, l2) && ppos(w0, w1, w2, wt, h0, h1, l2)
      && ppos(w0, w1, w2, wt, l0, l1, h2) && ppos(w0, w1, w2, wt, h0, l1, h2)
      && ppos(w0, w1, w2, wt, l0, h1, h2) && ppos(w0, w1, w2, wt, h0, h1, h2);
    predicate pnear8(real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                     real l0, real h0, real l1, real h1, real l2, real h2) =
         pnear(m0, m1, m2, t, w0, w1, w2, wt, l0, l1, l2) && pnear(m0, m1, m2, t, w0, w1, w2, wt, h0, l1, l2)
      && pnear(m0, m1, m2, t, w0, w1, w2, wt, l0, h1, l2) && pnear(m0, m1, m2, t, w0, w1, w2, wt, h0, h1, l2)
      && pnear(m0, m1, m2, t, w0, w1, w2, wt, l0, l1, h2) && pnear(m0, m1, m2, t, w0, w1, w2, wt, h0, l1, h2)
      && pnear(m0, m1, m2, t, w0, w1, w2, wt, l0, h1, h2) && pnear(m0, m1, m2, t, w0, w1, w2, wt, h0, h1, h2);
    predicate pt_lo8(real r, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                     real l0, real h0, real l1, real h1, real l2, real h2) =
         pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, l2) || pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, l2)
      || pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, l2) || pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, l2)
      || pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, h2) || pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, h2)
      || pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, h2) || pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, h2);
    predicate pt_hi8(real r, real m0, real m1, real m2, real t, real w0, real w1, real w2, real wt,
                     real l0, real h0, real l1, real h1, real l2, real h2) =
         pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, l2) || pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, l2)
      || pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, l2) || pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, l2)
      || pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, h2) || pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, h2)
      || pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, h2) || pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, h2);

    // ---------------------------------------------------------------------
    // The promise on one output axis (X = row m, W = row w): finite ends;
    // at every real point of the box W > 0 (ppos) and lo <= X / W <= hi
    // (plo, phi: lo W <= X <= hi W); each end
    // tight at some corner (the exact bound is at a corner).
    // ---------------------------------------------------------------------
    predicate paxis(cbx_fp lo, cbx_fp hi, real m0, real m1, real m2, real t,
                    real w0, real w1, real w2, real wt,
                    real l0, real h0, real l1, real h1, real l2, real h2) =
      \is_finite(lo) && \is_finite(hi)
      && (\forall real x, y, z; l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2 ==>
            ppos(w0, w1, w2, wt, x, y, z) && plo(lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
            && phi(hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z))
      && pt_lo8(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2)
      && pt_hi8(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);

    predicate proj_clear(cbx_proj *p, cbx_box *b) =
      pclear8(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3],
              b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);
    // In front of the camera plane: W > 0 at the 8 corners (hence on the box).
    predicate proj_front(cbx_proj *p, cbx_box *b) =
      pfront8(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3],
              b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);
    predicate proj_near(cbx_proj *p, cbx_box *b, integer i) =
      pnear8(p->m[i][0], p->m[i][1], p->m[i][2], p->m[i][3], p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3],
             b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);
    // Every case the bound is computed for (CBX_OK): the range, and every
    // corner clear of the camera plane with every quotient in range.
    predicate proj_ok(cbx_proj *p, cbx_box *b) =
      proj_fast(p) && box_fast(b) && proj_near(p, b, 0) && proj_near(p, b, 1) && proj_near(p, b, 2);
*/

/*@ // ---------------------------------------------------------------------
    // Tightness of one corner's quotient, over the reals: a the kernel's
    // end of X (within 12 u S_X + eta_512), the divisor the end of W's
    // enclosure [wl, wh] chosen by the sign of a, r the quotient rounded
    // outward (cbx_div_dn / cbx_div_up, multiplied out).  One lemma per
    // case: lower end with a >= 0 (r >= 0 or r < 0) and a < 0; upper end
    // with a >= 0, and a < 0 (r <= 0 or r > 0).
    // ---------------------------------------------------------------------

    // The conclusions name every variable (ptlw, pthw: the divisor's end
    // d and a appear in no formula of theirs), so that a use gives the
    // provers the whole instance.
    predicate ptlw(real r, real a, real d, real X, real W, real SX, real SW) =
      X - r*W <= 2*CBX_U12*(SX + \abs(r)*SW) + CBX_ETA1024*(1 + \abs(r) + SW);
    predicate pthw(real r, real a, real d, real X, real W, real SX, real SW) =
      r*W - X <= 2*CBX_U12*(SX + \abs(r)*SW) + CBX_ETA1024*(1 + \abs(r) + SW);
    // The products are hypotheses in prod_le form (prod_le_nn proves them
    // at the call site); each lemma is then linear in its products.
    predicate ptl_pos_h(real r, real a, real X, real W, real wh, real SX, real SW) =
         0 < W <= wh
      && wh - W <= CBX_U12*SW + CBX_ETA512
      && 0 <= a <= X
      && X - a <= CBX_U12*SX + CBX_ETA512
      && X <= SX
      && W <= SW
      && r*wh <= a
      && a - r*wh <= CBX_U8*a + CBX_ETA16*wh
      && (r >= 0 ==> prod_le(wh - W, CBX_U12*SW + CBX_ETA512, r))
      && (r < 0 ==> prod_le(W, wh, -r));
    predicate ptl_neg_h(real r, real a, real X, real W, real wl, real SX, real SW) =
         0 < wl <= W
      && W - wl <= CBX_U12*SW + CBX_ETA512
      && a < 0
      && a <= X
      && X - a <= CBX_U12*SX + CBX_ETA512
      && -SX <= X
      && W <= SW
      && r < 0
      && r*wl <= a
      && a - r*wl <= CBX_U8*(-a) + CBX_ETA16*wl
      && prod_le(W - wl, CBX_U12*SW + CBX_ETA512, -r);
    predicate pth_pos_h(real r, real a, real X, real W, real wl, real SX, real SW) =
         0 < wl <= W
      && W - wl <= CBX_U12*SW + CBX_ETA512
      && 0 <= a
      && X <= a
      && a - X <= CBX_U12*SX + CBX_ETA512
      && -SX <= X <= SX
      && W <= SW
      && 0 <= r
      && a <= r*wl
      && r*wl - a <= CBX_U8*a + CBX_ETA16*wl
      && prod_le(W - wl, CBX_U12*SW + CBX_ETA512, r);
    predicate pth_neg_h(real r, real a, real X, real W, real wh, real SX, real SW) =
         0 < W <= wh
      && wh - W <= CBX_U12*SW + CBX_ETA512
      && a < 0
      && X <= a
      && a - X <= CBX_U12*SX + CBX_ETA512
      && -SX <= X
      && W <= SW
      && a <= r*wh
      && r*wh - a <= CBX_U8*(-a) + CBX_ETA16*wh
      && (r <= 0 ==> prod_le(wh - W, CBX_U12*SW + CBX_ETA512, -r))
      && (r > 0 ==> prod_le(W, wh, r) && prod_le(0, wh, r));
*/

/* The tightness lemmas, only where CBX_PROJ_LEMMAS is defined (as the
 * lemmas of specs/cbx_proj_logic.h, which says why). */
#ifdef CBX_PROJ_LEMMAS
/*@
    lemma ptl_pos: \forall real r, a, X, W, wh, SX, SW;
      ptl_pos_h(r, a, X, W, wh, SX, SW) ==> ptlw(r, a, wh, X, W, SX, SW);
    lemma ptl_neg: \forall real r, a, X, W, wl, SX, SW;
      ptl_neg_h(r, a, X, W, wl, SX, SW) ==> ptlw(r, a, wl, X, W, SX, SW);
    lemma pth_pos: \forall real r, a, X, W, wl, SX, SW;
      pth_pos_h(r, a, X, W, wl, SX, SW) ==> pthw(r, a, wl, X, W, SX, SW);
    lemma pth_neg: \forall real r, a, X, W, wh, SX, SW;
      pth_neg_h(r, a, X, W, wh, SX, SW) ==> pthw(r, a, wh, X, W, SX, SW);
*/
#endif
