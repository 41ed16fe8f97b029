/*
 * ACSL logic of a ball under a projective map (cbx_project_sphere,
 * src/f64/cbx_psph.c): the exact statement of its bound and the lemmas that
 * reduce it to three quantifier-free inequalities.  Binary64 only; read by
 * Frama-C only (certbox.h includes it once).
 *
 * The ball is {c + r q : |q| <= 1}; one output axis has the map's row
 * X = (a0, a1, a2, a3) and the camera row W = (b0, b1, b2, b3).  For a real
 * t, X - t W is affine in the point, with linear part k(t) = (a_j - t b_j)
 * and value ps_e(t) at the center, so over the ball it ranges over
 * ps_e(t) -+ |r| |k(t)| (Cauchy-Schwarz, equality at q = -+ k / |k|):
 *   - X <= t W on the whole ball  <=>  ps_e(t) + |r| ps_n(t) <= 0;
 *   - X >= t W on the whole ball  <=>  ps_e(t) - |r| ps_n(t) >= 0;
 *   - W > 0 on the whole ball     <=>  W(c) - |r| |(b0, b1, b2)| > 0.
 * With W > 0 the first is "X / W <= t at every point".  Its failure,
 * ps_e(t) + |r| ps_n(t) > 0 (ps_above), says that some point of the ball
 * has X / W > t: the tightness statement.  The code establishes the
 * quantifier-free forms; lemma ps_cover (proven in job L64) turns them
 * into ps_axis, the statement about every point that the contract carries.
 */
#ifndef CBX_PSPH_H
#define CBX_PSPH_H

#include "cbx_iv_logic.h" /* iv_has, iv_root, sq_at, prod_at */

/*@ // ---------------------------------------------------------------------
    // The domain: each row's linear entries at most 2^60 in magnitude, its
    // translation at most 2^120; the center's coordinates and the radius
    // at most 2^60.  Every intermediate value of the bound is then far
    // inside the range of binary64 (src/f64/cbx_psph.c).
    // ---------------------------------------------------------------------
    predicate ps_row(real m0, real m1, real m2, real t) =
      -0x1p60 <= m0 <= 0x1p60 && -0x1p60 <= m1 <= 0x1p60 && -0x1p60 <= m2 <= 0x1p60
      && -0x1p120 <= t <= 0x1p120;
    predicate ps_ctr(real c0, real c1, real c2, real r) =
      -0x1p60 <= c0 <= 0x1p60 && -0x1p60 <= c1 <= 0x1p60 && -0x1p60 <= c2 <= 0x1p60
      && -0x1p60 <= r <= 0x1p60;
    // the arguments of an axis's computation: the rows a (X) and b (W) and
    // the ball, finite and in the domain
    predicate ps_args(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                      double c0, double c1, double c2, double r) =
      \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
      && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
      && \is_finite(c0) && \is_finite(c1) && \is_finite(c2) && \is_finite(r)
      && ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3) && ps_ctr(c0, c1, c2, r);
    predicate ps_fin(cbx_proj *p, double *c, double r) =
         \is_finite(p->m[0][0]) && \is_finite(p->m[0][1]) && \is_finite(p->m[0][2]) && \is_finite(p->m[0][3])
      && \is_finite(p->m[1][0]) && \is_finite(p->m[1][1]) && \is_finite(p->m[1][2]) && \is_finite(p->m[1][3])
      && \is_finite(p->m[2][0]) && \is_finite(p->m[2][1]) && \is_finite(p->m[2][2]) && \is_finite(p->m[2][3])
      && \is_finite(p->m[3][0]) && \is_finite(p->m[3][1]) && \is_finite(p->m[3][2]) && \is_finite(p->m[3][3])
      && \is_finite(c[0]) && \is_finite(c[1]) && \is_finite(c[2]) && \is_finite(r);
    predicate ps_dom(cbx_proj *p, double *c, double r) =
      ps_fin(p, c, r)
      && ps_row(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3])
      && ps_row(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3])
      && ps_row(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3])
      && ps_row(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3])
      && ps_ctr(c[0], c[1], c[2], r);
    predicate ps_nan(cbx_proj *p, double *c, double r) =
      proj_nan(p) || \is_NaN(c[0]) || \is_NaN(c[1]) || \is_NaN(c[2]) || \is_NaN(r);

    // ---------------------------------------------------------------------
    // X - t W at the center, and the norm of its linear part.
    // ---------------------------------------------------------------------
    logic real ps_e(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2) =
      aff(a0 - t*b0, a1 - t*b1, a2 - t*b2, a3 - t*b3, c0, c1, c2);
    logic real ps_n(real t, real a0, real a1, real a2, real b0, real b1, real b2) =
      rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2);

    // X <= t W (hi), X >= t W (lo), W > 0 (front) on the whole ball, in
    // the quantifier-free form.
    predicate ps_hi(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2, real r) =
      ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2) + \abs(r) * ps_n(t, a0, a1, a2, b0, b1, b2) <= 0;
    predicate ps_lo(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2, real r) =
      ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2) - \abs(r) * ps_n(t, a0, a1, a2, b0, b1, b2) >= 0;
    predicate ps_front(real b0, real b1, real b2, real b3, real c0, real c1, real c2, real r) =
      aff(b0, b1, b2, b3, c0, c1, c2) - \abs(r) * rnorm3(b0, b1, b2) > 0;

    // r d within |r| n of 0 (a named product fact, for the lemmas' triggers)
    predicate ps_sc(real r, real d, real n) = -(\abs(r)*n) <= r*d <= \abs(r)*n;

    // a product's exact ends (specs/cbx_imat_logic.h) within [-m, m]
    predicate ps_itb(real ml, real mh, real l, real h, real m) =
      -m <= itmin(ml, mh, l, h) && itmax(ml, mh, l, h) <= m && itmag(ml, mh, l, h) <= m;
    // |x y| <= mx my (a named product bound, asked for where it is used)
    predicate ps_mb(real x, real y, real mx, real my) = -(mx*my) <= x*y <= mx*my;

    // Some point of the ball has X / W > t (above), < t (below).
    predicate ps_above(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2, real r) =
      ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2) + \abs(r) * ps_n(t, a0, a1, a2, b0, b1, b2) > 0;
    predicate ps_below(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2, real r) =
      ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2) - \abs(r) * ps_n(t, a0, a1, a2, b0, b1, b2) < 0;

    // ---------------------------------------------------------------------
    // The contract of one output axis.  Soundness: every point of the ball
    // has W > 0 and lo W <= X <= hi W (lo <= X / W <= hi).  Tightness: the
    // exact ends are within ps_tau of lo and hi (2^-20 (1 + |end|)): some
    // point has X / W above hi - ps_tau(hi), some below lo + ps_tau(lo).
    // ---------------------------------------------------------------------
    predicate ps_xw(real b0, real b1, real b2, real b3, real c0, real c1, real c2, real r,
                    real q0, real q1, real q2) =
      0 < aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2);
    predicate ps_xlo(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                     real c0, real c1, real c2, real r, real q0, real q1, real q2) =
      t * aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2)
      <= aff(a0, a1, a2, a3, c0 + r*q0, c1 + r*q1, c2 + r*q2);
    predicate ps_xhi(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                     real c0, real c1, real c2, real r, real q0, real q1, real q2) =
      aff(a0, a1, a2, a3, c0 + r*q0, c1 + r*q1, c2 + r*q2)
      <= t * aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2);
    predicate ps_axis(real lo, real hi, real a0, real a1, real a2, real a3,
                      real b0, real b1, real b2, real b3, real c0, real c1, real c2, real r) =
      \forall real q0, q1, q2; in_ball(q0, q1, q2) ==>
        ps_xw(b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
        && ps_xlo(lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2)
        && ps_xhi(hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    logic real ps_tau(real v) = 0x1p-20 * (1 + \abs(v));
    predicate ps_tight(real lo, real hi, real a0, real a1, real a2, real a3,
                       real b0, real b1, real b2, real b3, real c0, real c1, real c2, real r) =
      (\exists real s; hi - ps_tau(hi) <= s && ps_above(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r))
      && (\exists real s; s <= lo + ps_tau(lo) && ps_below(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r));
*/

#ifdef CBX_PSPH_LEMMAS
/*@ // X - t W at c + r q: its value at the center plus r k(t).q.
    // proof: z3
    lemma ps_split: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      aff(a0, a1, a2, a3, c0 + r*q0, c1 + r*q1, c2 + r*q2)
        - t * aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2)
      == ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2)
         + r * dot3(a0 - t*b0, a1 - t*b1, a2 - t*b2, q0, q1, q2);
    // proof: z3
    lemma ps_split1: \forall real b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      aff(b0, b1, b2, b3, c0 + r*q0, c1 + r*q1, c2 + r*q2)
      == aff(b0, b1, b2, b3, c0, c1, c2) + r * dot3(b0, b1, b2, q0, q1, q2);
    // |r k.q| <= |r| |k| on the unit ball (Cauchy-Schwarz).
    lemma ps_dot_sq: \forall real k0, k1, k2, q0, q1, q2;
      in_ball(q0, q1, q2) ==> sq_le(dot3(k0, k1, k2, q0, q1, q2), rnorm3(k0, k1, k2));
    lemma ps_dot: \forall real k0, k1, k2, q0, q1, q2;
      in_ball(q0, q1, q2) ==>
        -rnorm3(k0, k1, k2) <= dot3(k0, k1, k2, q0, q1, q2) <= rnorm3(k0, k1, k2);
    // |r d| <= |r| n when |d| <= n (a named instance: ps_sc).
    lemma ps_scale: \forall real r, d, n;
      -n <= d <= n ==> ps_sc(r, d, n);
    lemma ps_rdot: \forall real k0, k1, k2, q0, q1, q2, r;
      in_ball(q0, q1, q2) ==> ps_sc(r, dot3(k0, k1, k2, q0, q1, q2), rnorm3(k0, k1, k2));
    // The three inequalities at one point q of the ball, first from the
    // Cauchy-Schwarz instance at q (ps_sc), then from q in the ball.
    // proof: z3
    lemma ps_xhi_sc: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      ps_sc(r, dot3(a0 - t*b0, a1 - t*b1, a2 - t*b2, q0, q1, q2), rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2))
      ==> ps_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_xhi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    // proof: z3
    lemma ps_xlo_sc: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      ps_sc(r, dot3(a0 - t*b0, a1 - t*b1, a2 - t*b2, q0, q1, q2), rnorm3(a0 - t*b0, a1 - t*b1, a2 - t*b2))
      ==> ps_lo(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_xlo(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    // proof: z3
    lemma ps_xw_sc: \forall real b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      ps_sc(r, dot3(b0, b1, b2, q0, q1, q2), rnorm3(b0, b1, b2))
      ==> ps_front(b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_xw(b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    lemma ps_xhi_pt: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      in_ball(q0, q1, q2) ==> ps_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_xhi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    lemma ps_xlo_pt: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      in_ball(q0, q1, q2) ==> ps_lo(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_xlo(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    lemma ps_xw_pt: \forall real b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2;
      in_ball(q0, q1, q2) ==> ps_front(b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_xw(b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    // The statement about every point.
    lemma ps_cover: \forall real lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r;
      ps_front(b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_lo(lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_hi(hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_axis(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    // Tightness from one witness each.
    lemma ps_tight_intro: \forall real lo, hi, sl, sh, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r;
      hi - ps_tau(hi) <= sh ==> ps_above(sh, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> sl <= lo + ps_tau(lo) ==> ps_below(sl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      ==> ps_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    // One point of a square root's enclosure (iv_root, specs/cbx_iv_logic.h).
    // proof: z3
    lemma ps_root_at: \forall real lo, hi, l, h, y;
      iv_root(lo, hi, l, h) ==> 0 <= y ==> sq_at(l, h, y) ==> iv_has(lo, hi, y);
    // Bounds of products (the ranges of src/f64/cbx_psph.c).
    lemma ps_itb_i: \forall real ml, mh, l, h, m;
      -m <= ml*l <= m ==> -m <= ml*h <= m ==> -m <= mh*l <= m ==> -m <= mh*h <= m
      ==> ps_itb(ml, mh, l, h, m);
    lemma ps_mul_le: \forall real x, y, mx, my;
      -mx <= x <= mx ==> -my <= y <= my ==> ps_mb(x, y, mx, my);
*/
#endif /* CBX_PSPH_LEMMAS */
#endif /* CBX_PSPH_H */
