/*
 * ACSL logic of a ball under a projective map, clipped at a near plane
 * (cbx_project_sphere_near, src/f64/cbx_pball.c): the exact statement of
 * its bound and the lemmas that reduce it to quantifier-free inequalities.
 * Binary64 only; read by Frama-C only (certbox.h includes it once, after
 * specs/cbx_psph.h and cbx_pnear.h, whose ps_e, ps_n, ps_tau, pn_wn and
 * pn_lw it uses).
 *
 * The ball is {c + r q : |q| <= 1}; one output axis has the map's row
 * X = (a0, a1, a2, a3) and the camera row W = (b0, b1, b2, b3); the near
 * plane is W = wn > 0.  The part bounded is the ball's points with
 * W >= wn (pb_in).  Over the whole ball X - s W is at most
 * ps_e(s) + |r| ps_n(s) (Cauchy-Schwarz); for reals s <= t (the Lagrangian
 * form of max X / W over the part):
 *   ps_e(s) + |r| ps_n(s) <= f and f <= (t - s) wn
 *     ==>  X - s W <= (t - s) wn <= (t - s) W at every point with W >= wn
 *     ==>  X <= t W there, that is X / W <= t (pb_hi_i).
 * s = t is the unclipped certificate (cbx_project_sphere's); where the
 * near plane cuts the ball below the tangent point, the exact end has the
 * multiplier s* of the closed form in src/f64/cbx_pball.c.  The lower end
 * is the upper end of -X (pb_lo_neg).  Tightness is a witness: a point
 * c + r q of the ball with W >= wn and X - t W > 0 there (pb_above).
 */
#ifndef CBX_PBALL_H
#define CBX_PBALL_H

/*@ // ---------------------------------------------------------------------
    // The domain: the projected ball's (ps_dom: linear entries, center and
    // radius at most 2^60, translations at most 2^120) and the near plane's
    // value wn in [2^-100, 2^120] (pn_wn).
    // ---------------------------------------------------------------------
    predicate pb_dom(cbx_proj *p, double *c, double r, double wn) =
      ps_dom(p, c, r) && \is_finite(wn) && pn_wn(wn);
    predicate pb_nan(cbx_proj *p, double *c, double r, double wn) =
      ps_nan(p, c, r) || \is_NaN(wn);

    // ---------------------------------------------------------------------
    // The point c + r q (q in the unit ball) in front of the near plane.
    // ---------------------------------------------------------------------
    predicate pb_in(real wn, real b0, real b1, real b2, real b3, real c0, real c1, real c2, real r,
                    real q0, real q1, real q2) =
      in_ball(q0, q1, q2) && wn <= aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2);

    // X - s W at c + r q: its value at the center plus r times its linear
    // part at q (lemma pb_v_e: the value at the point).
    logic real pb_v(real s, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2, real r, real q0, real q1, real q2) =
      ps_e(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2)
      + r * dot3(a0 - s*b0, a1 - s*b1, a2 - s*b2, q0, q1, q2);

    // X - s W <= f on the whole ball, quantifier-free (lemma pb_le_pt).
    predicate pb_le(real f, real s, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2, real r) =
      ps_e(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2) + \abs(r) * ps_n(s, a0, a1, a2, b0, b1, b2) <= f;

    // ---------------------------------------------------------------------
    // The contract of one output axis.  Soundness: at every point of the
    // ball with W >= wn, lo W <= X <= hi W (lo <= X / W <= hi, as W > 0
    // there; ps_xlo, ps_xhi of specs/cbx_psph.h).  Tightness: some such
    // point has X / W above hi - ps_tau(hi), some below lo + ps_tau(lo)
    // (ps_tau(v) = 2^-20 (1 + |v|)).
    // ---------------------------------------------------------------------
    predicate pb_hi(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2, real r, real wn) =
      \forall real q0, q1, q2; pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
        ==> ps_xhi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    predicate pb_lo(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2, real r, real wn) =
      \forall real q0, q1, q2; pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
        ==> ps_xlo(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    predicate pb_above(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2, real r, real wn) =
      \exists real q0, q1, q2; pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
        && ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2) > 0;
    predicate pb_below(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2, real r, real wn) =
      \exists real q0, q1, q2; pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
        && ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2) < 0;
    predicate pb_axis(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                      real c0, real c1, real c2, real r, real wn) =
      pb_lo(lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
      && pb_hi(hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    predicate pb_tight(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2, real r, real wn) =
      (\exists real s; hi - ps_tau(hi) <= s
         && pb_above(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn))
      && (\exists real s; s <= lo + ps_tau(lo)
         && pb_below(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn));
    // Nothing of the ball in front of the near plane: W < wn everywhere.
    predicate pb_void(real wn, real b0, real b1, real b2, real b3, real c0, real c1, real c2, real r) =
      \forall real q0, q1, q2; in_ball(q0, q1, q2)
        ==> aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2) < wn;
*/

#ifdef CBX_PBALL_LEMMAS
/*@ // Every hypothesis below is quantifier-free (specs/cbx_pnear.h says
    // why).

    // X - s W at c + r q is pb_v.
    // proof: z3
    lemma pb_v_e: \forall real s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      pb_v(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      == aff(a0, a1, a2, a3, c0 + r*q0, c1 + r*q1, c2 + r*q2)
         - s * aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2);
    lemma pb_v_pe: \forall real s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      pb_v(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      == ps_e(s, a0, a1, a2, a3, b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2);
    // The certificate at one point of the ball, from the Cauchy-Schwarz
    // instance there (ps_sc), then from q in the ball.
    // proof: z3
    lemma pb_le_sc: \forall real f, s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      ps_sc(r, dot3(a0 - s*b0, a1 - s*b1, a2 - s*b2, q0, q1, q2), rnorm3(a0 - s*b0, a1 - s*b1, a2 - s*b2))
      ==> pb_le(f, s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> pb_v(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2) <= f;
    lemma pb_le_pt: \forall real f, s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      in_ball(q0, q1, q2)
      ==> pb_le(f, s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> pb_v(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2) <= f;
    // X - s W <= (t - s) wn <= (t - s) W at a point in front: X <= t W.
    lemma pb_xhi_i: \forall real f, s, t, wn, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      pb_le(f, s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      ==> s <= t ==> f <= pn_lw(s, t, wn)
      ==> ps_xhi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    // The statement about every point in front of the near plane.
    lemma pb_hi_i: \forall real f, s, t, wn, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r;
      pb_le(f, s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r) ==> s <= t ==> f <= pn_lw(s, t, wn)
      ==> pb_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    // W below wn on the whole ball (X = W, s = 0).
    lemma pb_void_i: \forall real f, wn, b0, b1, b2, b3, c0, c1, c2, r;
      pb_le(f, 0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r) ==> f < wn
      ==> pb_void(wn, b0, b1, b2, b3, c0, c1, c2, r);
    // A witness: q in the ball, W >= wn at c + r q (pb_v with X = W,
    // s = 0), X - t W > 0 there.
    lemma pb_in_i: \forall real wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      in_ball(q0, q1, q2)
      ==> wn <= pb_v(0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      ==> pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    lemma pb_above_i: \forall real t, wn, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      ==> 0 < pb_v(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
      ==> pb_above(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    // The lower end from the upper end of -X.
    lemma pb_lo_neg: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn;
      pb_hi(-t, -a0, -a1, -a2, -a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
      ==> pb_lo(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    lemma pb_below_neg: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn;
      pb_above(-t, -a0, -a1, -a2, -a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
      ==> pb_below(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    lemma pb_tight_i: \forall real lo, hi, sl, sh, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn;
      hi - ps_tau(hi) <= sh ==> pb_above(sh, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
      ==> sl <= lo + ps_tau(lo) ==> pb_below(sl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
      ==> pb_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
*/
#endif /* CBX_PBALL_LEMMAS */
#endif /* CBX_PBALL_H */
