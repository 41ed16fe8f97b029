/*
 * ACSL logic of a box under a projective map, clipped at a near plane
 * (cbx_project_box_near, src/f64/cbx_pnear.c): the exact statement of its
 * bound and the lemmas that reduce it to quantifier-free inequalities.
 * Binary64 only; read by Frama-C only (certbox.h includes it once, after
 * specs/cbx_psph.h, whose ps_e and ps_tau it uses).
 *
 * The box is [l0, h0] x [l1, h1] x [l2, h2]; one output axis has the map's
 * row X = (a0, a1, a2, a3) and the camera row W = (b0, b1, b2, b3); the
 * near plane is W = wn > 0.  The part bounded is the box's points with
 * W >= wn (pn_in).  For reals s <= t (the Lagrangian form of the linear
 * program max X / W over that part):
 *   X - s W <= f on the whole box and f <= (t - s) wn
 *     ==>  X - s W <= (t - s) W at every point with W >= wn
 *     ==>  X <= t W there, that is X / W <= t (pn_hi_i);
 * the lower end is the upper end of -X (pn_lo_neg).  With s = t this is the
 * unclipped certificate (X <= t W on the whole box); at an end attained on
 * an edge crossing the plane, s = a_j / b_j, the ratio that makes X - s W
 * constant along that edge.  LP duality makes the exact end reachable this
 * way; the code tries those s.  Tightness is a witness: a point of the box
 * with W >= wn and X - t W > 0 (pn_above).
 */
#ifndef CBX_PNEAR_H
#define CBX_PNEAR_H

/*@ // ---------------------------------------------------------------------
    // The domain: each row as ps_row (linear entries at most 2^60,
    // translations at most 2^120), the box's ends at most 2^60, the near
    // plane's value wn in [2^-100, 2^120].
    // ---------------------------------------------------------------------
    predicate pn_bx(real l0, real h0, real l1, real h1, real l2, real h2) =
      -0x1p60 <= l0 <= h0 <= 0x1p60 && -0x1p60 <= l1 <= h1 <= 0x1p60 && -0x1p60 <= l2 <= h2 <= 0x1p60;
    predicate pn_wn(real wn) = 0x1p-100 <= wn <= 0x1p120;
    predicate pn_fin(cbx_proj *p, cbx_box *b, double wn) =
         \is_finite(p->m[0][0]) && \is_finite(p->m[0][1]) && \is_finite(p->m[0][2]) && \is_finite(p->m[0][3])
      && \is_finite(p->m[1][0]) && \is_finite(p->m[1][1]) && \is_finite(p->m[1][2]) && \is_finite(p->m[1][3])
      && \is_finite(p->m[2][0]) && \is_finite(p->m[2][1]) && \is_finite(p->m[2][2]) && \is_finite(p->m[2][3])
      && \is_finite(p->m[3][0]) && \is_finite(p->m[3][1]) && \is_finite(p->m[3][2]) && \is_finite(p->m[3][3])
      && \is_finite(b->lo[0]) && \is_finite(b->hi[0]) && \is_finite(b->lo[1]) && \is_finite(b->hi[1])
      && \is_finite(b->lo[2]) && \is_finite(b->hi[2]) && \is_finite(wn);
    predicate pn_dom(cbx_proj *p, cbx_box *b, double wn) =
      pn_fin(p, b, wn)
      && ps_row(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3])
      && ps_row(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3])
      && ps_row(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3])
      && ps_row(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3])
      && pn_bx(b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      && pn_wn(wn);

    // ---------------------------------------------------------------------
    // Points: of the box, and of its part in front of the near plane.
    // ---------------------------------------------------------------------
    predicate pn_box(real l0, real h0, real l1, real h1, real l2, real h2, real x0, real x1, real x2) =
      l0 <= x0 <= h0 && l1 <= x1 <= h1 && l2 <= x2 <= h2;
    predicate pn_in(real wn, real b0, real b1, real b2, real b3,
                    real l0, real h0, real l1, real h1, real l2, real h2, real x0, real x1, real x2) =
      pn_box(l0, h0, l1, h1, l2, h2, x0, x1, x2) && wn <= aff(b0, b1, b2, b3, x0, x1, x2);

    // ---------------------------------------------------------------------
    // X - s W over the box, quantifier-free: its coefficients are
    // a_j - s b_j, and the largest of k x over [l, h] is max(k l, k h)
    // (pn_mx); pn_le: X - s W <= f on the whole box (lemma pn_le_at).
    // ---------------------------------------------------------------------
    logic real pn_mx(real k, real l, real h) = \max(k*l, k*h);
    predicate pn_le(real f, real s, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real l0, real h0, real l1, real h1, real l2, real h2) =
      pn_mx(a0 - s*b0, l0, h0) + pn_mx(a1 - s*b1, l1, h1) + pn_mx(a2 - s*b2, l2, h2) + (a3 - s*b3) <= f;

    // ---------------------------------------------------------------------
    // The contract of one output axis.  Soundness: at every point of the
    // box with W >= wn, lo W <= X <= hi W (lo <= X / W <= hi, as W > 0).
    // Tightness: some such point has X / W above hi - ps_tau(hi), some
    // below lo + ps_tau(lo) (ps_tau(v) = 2^-20 (1 + |v|)).
    // ---------------------------------------------------------------------
    predicate pn_xhi(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                     real x0, real x1, real x2) =
      aff(a0, a1, a2, a3, x0, x1, x2) <= t * aff(b0, b1, b2, b3, x0, x1, x2);
    predicate pn_xlo(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                     real x0, real x1, real x2) =
      t * aff(b0, b1, b2, b3, x0, x1, x2) <= aff(a0, a1, a2, a3, x0, x1, x2);
    predicate pn_hi(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real l0, real h0, real l1, real h1, real l2, real h2, real wn) =
      \forall real x0, x1, x2; pn_in(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2)
        ==> pn_xhi(t, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2);
    predicate pn_lo(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real l0, real h0, real l1, real h1, real l2, real h2, real wn) =
      \forall real x0, x1, x2; pn_in(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2)
        ==> pn_xlo(t, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2);
    predicate pn_above(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real l0, real h0, real l1, real h1, real l2, real h2, real wn) =
      \exists real x0, x1, x2; pn_in(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2)
        && ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2) > 0;
    predicate pn_below(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real l0, real h0, real l1, real h1, real l2, real h2, real wn) =
      \exists real x0, x1, x2; pn_in(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2)
        && ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2) < 0;
    predicate pn_axis(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                      real l0, real h0, real l1, real h1, real l2, real h2, real wn) =
      pn_lo(lo, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      && pn_hi(hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    predicate pn_tight(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real l0, real h0, real l1, real h1, real l2, real h2, real wn) =
      (\exists real s; hi - ps_tau(hi) <= s
         && pn_above(s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn))
      && (\exists real s; s <= lo + ps_tau(lo)
         && pn_below(s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn));
    // (t - s) wn, the multiplier's share (a named term, for the lemmas'
    // triggers).
    logic real pn_lw(real s, real t, real wn) = (t - s)*wn;
    // lam wn <= (t - s) wn (a named product fact, for the triggers)
    predicate pn_lamle(real lam, real s, real t, real wn) = lam*wn <= pn_lw(s, t, wn);
    // Nothing of the box in front of the near plane: W < wn everywhere.
    predicate pn_void(real wn, real b0, real b1, real b2, real b3,
                      real l0, real h0, real l1, real h1, real l2, real h2) =
      \forall real x0, x1, x2; pn_box(l0, h0, l1, h1, l2, h2, x0, x1, x2) ==> aff(b0, b1, b2, b3, x0, x1, x2) < wn;
*/

#ifdef CBX_PNEAR_LEMMAS
/*@ // Every hypothesis below is quantifier-free: a lemma whose hypothesis
    // is quantified (as "for every x of [l, h]") is not instantiated by the
    // provers (it is an existential in disguise), so the code establishes
    // quantifier-free facts and the lemmas carry the quantifiers.

    // One term: k x <= max(k l, k h) on [l, h]; max(k l, k h) at most the
    // product enclosure's exact upper end (specs/cbx_imat_logic.h: itmax).
    lemma pn_mx_pt: \forall real k, l, h, x; l <= x <= h ==> k*x <= pn_mx(k, l, h);
    lemma pn_mx_it: \forall real k, kl, kh, l, h;
      kl <= k <= kh ==> pn_mx(k, l, h) <= itmax(kl, kh, l, h);
    // An affine form at a point of the box, at most its terms' maxima.
    lemma pn_aff_le: \forall real k0, k1, k2, k3, l0, h0, l1, h1, l2, h2, x0, x1, x2;
      pn_box(l0, h0, l1, h1, l2, h2, x0, x1, x2)
      ==> aff(k0, k1, k2, k3, x0, x1, x2) <= pn_mx(k0, l0, h0) + pn_mx(k1, l1, h1) + pn_mx(k2, l2, h2) + k3;
    // X - s W at a point is X - s W.
    // proof: z3
    lemma pn_e: \forall real s, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2;
      ps_e(s, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2)
      == aff(a0, a1, a2, a3, x0, x1, x2) - s * aff(b0, b1, b2, b3, x0, x1, x2);
    // A rounded-down multiplier: lam wn <= (t - s) wn.
    lemma pn_lam: \forall real lam, s, t, wn; 0 <= lam <= t - s ==> 0 <= wn ==> pn_lamle(lam, s, t, wn);
    // (t - s) wn <= (t - s) W at a point in front of the near plane.
    lemma pn_sw_i: \forall real s, t, wn, b0, b1, b2, b3, x0, x1, x2;
      s <= t ==> wn <= aff(b0, b1, b2, b3, x0, x1, x2)
      ==> pn_lw(s, t, wn) <= (t - s)*aff(b0, b1, b2, b3, x0, x1, x2);
    // The certificate at one point: X - s W <= (t - s) wn <= (t - s) W.
    // proof: z3
    lemma pn_xhi_pt: \forall real s, t, wn, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2;
      aff(a0 - s*b0, a1 - s*b1, a2 - s*b2, a3 - s*b3, x0, x1, x2) <= pn_lw(s, t, wn)
      ==> pn_lw(s, t, wn) <= (t - s)*aff(b0, b1, b2, b3, x0, x1, x2)
      ==> pn_xhi(t, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2);
    // The same from the certificate over the box, at one point in front.
    lemma pn_le_at: \forall real f, s, wn, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2;
      pn_le(f, s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2)
      ==> pn_in(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2)
      ==> aff(a0 - s*b0, a1 - s*b1, a2 - s*b2, a3 - s*b3, x0, x1, x2) <= f;
    lemma pn_xhi_box: \forall real f, s, t, wn, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2;
      pn_le(f, s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2)
      ==> pn_in(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2)
      ==> s <= t ==> f <= pn_lw(s, t, wn)
      ==> pn_xhi(t, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2);
    // The statement about every point in front of the near plane.
    lemma pn_hi_i: \forall real f, s, t, wn, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2;
      pn_le(f, s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2) ==> s <= t ==> f <= pn_lw(s, t, wn)
      ==> pn_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    // W below wn on the whole box (X = W, s = 0).
    lemma pn_void_i: \forall real f, wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2;
      pn_le(f, 0, b0, b1, b2, b3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2) ==> f < wn
      ==> pn_void(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2);
    // A witness in front of the near plane (its W as ps_e with X = W, t = 0).
    lemma pn_above_i: \forall real t, wn, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, x0, x1, x2;
      pn_box(l0, h0, l1, h1, l2, h2, x0, x1, x2)
      ==> wn <= ps_e(0, b0, b1, b2, b3, b0, b1, b2, b3, x0, x1, x2)
      ==> 0 < ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, x0, x1, x2)
      ==> pn_above(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    // The lower end from the upper end of -X: X >= t W at every point in
    // front iff -X <= -t W there; some point has X - t W < 0 iff one has
    // -X - (-t) W > 0.
    lemma pn_lo_neg: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn;
      pn_hi(-t, -a0, -a1, -a2, -a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      ==> pn_lo(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    lemma pn_below_neg: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn;
      pn_above(-t, -a0, -a1, -a2, -a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      ==> pn_below(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    lemma pn_tight_i: \forall real lo, hi, sl, sh, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn;
      hi - ps_tau(hi) <= sh ==> pn_above(sh, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      ==> sl <= lo + ps_tau(lo) ==> pn_below(sl, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      ==> pn_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
#endif /* CBX_PNEAR_LEMMAS */
#endif /* CBX_PNEAR_H */
