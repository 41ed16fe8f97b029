/*
 * ACSL logic of an ellipsoid under a projective map
 * (cbx_project_ellipsoid, src/f64/cbx_pell.c): the exact statement of its
 * bound, reduced to the ball's (specs/cbx_psph.h).  Binary64 only; read by
 * Frama-C only (certbox.h includes it once).
 *
 * The ellipsoid is {c + M q : |q| <= 1}, M_ij = rot[i][j] s_j (rot the
 * 3x3 matrix r_ij, s the radii; rot need not be orthogonal).  For a map
 * row X = (a0, a1, a2, a3), X at c + M q is A + a'.q with A = X(c) and
 * a'_j = s_j (r_0j a0 + r_1j a1 + r_2j a2) (pe_x: the row's j-th entry
 * in the ellipsoid's frame, M^T a).  So the ellipsoid's image under the
 * rows (X, W) is the unit ball's under the rows (a', A) and (b', B): every
 * statement of specs/cbx_psph.h holds with those rows, the center 0 and
 * the radius 1.  pe_e and pe_n are ps_e and ps_n there, X - t W at c and
 * |M^T (a - t b)|; pe_hi, pe_lo, pe_front, pe_above, pe_below and
 * pe_tight the ball's predicates there.  The contract's containment,
 * pe_axis, is stated on the ellipsoid's own points (pe_pt) and follows
 * from the ball's by lemma pe_cover (proven in job LP64).
 */
#ifndef CBX_PELL_H
#define CBX_PELL_H

/*@ // ---------------------------------------------------------------------
    // The domain: the map's rows and the center as for the ball (ps_row,
    // ps_ctr); rot's entries and the radii at most 2^30 in magnitude.
    // ---------------------------------------------------------------------
    predicate pe_sh(real r00, real r01, real r02, real r10, real r11, real r12,
                    real r20, real r21, real r22, real s0, real s1, real s2) =
      -0x1p30 <= r00 <= 0x1p30 && -0x1p30 <= r01 <= 0x1p30 && -0x1p30 <= r02 <= 0x1p30
      && -0x1p30 <= r10 <= 0x1p30 && -0x1p30 <= r11 <= 0x1p30 && -0x1p30 <= r12 <= 0x1p30
      && -0x1p30 <= r20 <= 0x1p30 && -0x1p30 <= r21 <= 0x1p30 && -0x1p30 <= r22 <= 0x1p30
      && -0x1p30 <= s0 <= 0x1p30 && -0x1p30 <= s1 <= 0x1p30 && -0x1p30 <= s2 <= 0x1p30;
    predicate pe_shf(double r00, double r01, double r02, double r10, double r11, double r12,
                     double r20, double r21, double r22, double s0, double s1, double s2) =
      \is_finite(r00) && \is_finite(r01) && \is_finite(r02) && \is_finite(r10) && \is_finite(r11)
      && \is_finite(r12) && \is_finite(r20) && \is_finite(r21) && \is_finite(r22)
      && \is_finite(s0) && \is_finite(s1) && \is_finite(s2)
      && pe_sh(r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    // the arguments of an axis's computation: the rows a (X) and b (W),
    // the center and the shape, finite and in the domain
    predicate pe_args(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                      double c0, double c1, double c2,
                      double r00, double r01, double r02, double r10, double r11, double r12,
                      double r20, double r21, double r22, double s0, double s1, double s2) =
      \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
      && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
      && \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
      && ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3) && ps_ctr(c0, c1, c2, 0)
      && pe_shf(r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    predicate pe_nan(cbx_proj *p, double *c, double *s, double (*r)[3]) =
      proj_nan(p) || \is_NaN(c[0]) || \is_NaN(c[1]) || \is_NaN(c[2])
      || \is_NaN(s[0]) || \is_NaN(s[1]) || \is_NaN(s[2])
      || \is_NaN(r[0][0]) || \is_NaN(r[0][1]) || \is_NaN(r[0][2]) || \is_NaN(r[1][0]) || \is_NaN(r[1][1])
      || \is_NaN(r[1][2]) || \is_NaN(r[2][0]) || \is_NaN(r[2][1]) || \is_NaN(r[2][2]);
    predicate pe_dom(cbx_proj *p, double *c, double *s, double (*r)[3]) =
      ps_fin(p, c, c[0])
      && ps_row(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3])
      && ps_row(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3])
      && ps_row(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3])
      && ps_row(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3])
      && ps_ctr(c[0], c[1], c[2], 0)
      && pe_shf(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2],
                s[0], s[1], s[2]);

    // ---------------------------------------------------------------------
    // A row's j-th entry in the ellipsoid's frame: s (m0 x0 + m1 x1 + m2 x2)
    // with (m0, m1, m2) column j of rot and s the j-th radius.
    // ---------------------------------------------------------------------
    logic real pe_x(real m0, real m1, real m2, real s, real x0, real x1, real x2) =
      s * (m0*x0 + m1*x1 + m2*x2);

    // X - t W at the center, and |M^T (a - t b)|: the ball's ps_e, ps_n
    // with the rows in the ellipsoid's frame.
    logic real pe_e(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2,
                    real r00, real r01, real r02, real r10, real r11, real r12,
                    real r20, real r21, real r22, real s0, real s1, real s2) =
      ps_e(t, pe_x(r00, r10, r20, s0, a0, a1, a2), pe_x(r01, r11, r21, s1, a0, a1, a2),
              pe_x(r02, r12, r22, s2, a0, a1, a2), aff(a0, a1, a2, a3, c0, c1, c2),
              pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
              pe_x(r02, r12, r22, s2, b0, b1, b2), aff(b0, b1, b2, b3, c0, c1, c2), 0, 0, 0);
    logic real pe_n(real t, real a0, real a1, real a2, real b0, real b1, real b2,
                    real r00, real r01, real r02, real r10, real r11, real r12,
                    real r20, real r21, real r22, real s0, real s1, real s2) =
      ps_n(t, pe_x(r00, r10, r20, s0, a0, a1, a2), pe_x(r01, r11, r21, s1, a0, a1, a2),
              pe_x(r02, r12, r22, s2, a0, a1, a2),
              pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
              pe_x(r02, r12, r22, s2, b0, b1, b2));

    // X <= t W (hi), X >= t W (lo) on the whole ellipsoid; some point with
    // X / W > t (above), < t (below); W > 0 on the whole ellipsoid (front).
    predicate pe_hi(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2,
                    real r00, real r01, real r02, real r10, real r11, real r12,
                    real r20, real r21, real r22, real s0, real s1, real s2) =
      pe_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      + pe_n(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2) <= 0;
    predicate pe_lo(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real c0, real c1, real c2,
                    real r00, real r01, real r02, real r10, real r11, real r12,
                    real r20, real r21, real r22, real s0, real s1, real s2) =
      pe_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      - pe_n(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2) >= 0;
    predicate pe_above(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2,
                       real r00, real r01, real r02, real r10, real r11, real r12,
                       real r20, real r21, real r22, real s0, real s1, real s2) =
      pe_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      + pe_n(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2) > 0;
    predicate pe_below(real t, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2,
                       real r00, real r01, real r02, real r10, real r11, real r12,
                       real r20, real r21, real r22, real s0, real s1, real s2) =
      pe_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      - pe_n(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2) < 0;
    predicate pe_front(real b0, real b1, real b2, real b3, real c0, real c1, real c2,
                       real r00, real r01, real r02, real r10, real r11, real r12,
                       real r20, real r21, real r22, real s0, real s1, real s2) =
      aff(b0, b1, b2, b3, c0, c1, c2)
      - rnorm3(pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
               pe_x(r02, r12, r22, s2, b0, b1, b2)) > 0;

    // ---------------------------------------------------------------------
    // The contract of one output axis.  Soundness: at every point x =
    // c + M q of the ellipsoid (pe_pt: row i of rot, the radii, q), W > 0
    // and lo W <= X <= hi W.  Tightness: some point has X / W above
    // hi - ps_tau(hi), some below lo + ps_tau(lo) (2^-20 (1 + |end|)).
    // ---------------------------------------------------------------------
    logic real pe_pt(real c, real m0, real m1, real m2, real s0, real s1, real s2,
                     real q0, real q1, real q2) =
      c + m0*(s0*q0) + m1*(s1*q1) + m2*(s2*q2);
    predicate pe_at(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                    real x0, real x1, real x2) =
      0 < aff(b0, b1, b2, b3, x0, x1, x2)
      && lo * aff(b0, b1, b2, b3, x0, x1, x2) <= aff(a0, a1, a2, a3, x0, x1, x2)
      && aff(a0, a1, a2, a3, x0, x1, x2) <= hi * aff(b0, b1, b2, b3, x0, x1, x2);
    predicate pe_axis(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                      real c0, real c1, real c2,
                      real r00, real r01, real r02, real r10, real r11, real r12,
                      real r20, real r21, real r22, real s0, real s1, real s2) =
      \forall real q0, q1, q2; in_ball(q0, q1, q2) ==>
        pe_at(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3,
              pe_pt(c0, r00, r01, r02, s0, s1, s2, q0, q1, q2),
              pe_pt(c1, r10, r11, r12, s0, s1, s2, q0, q1, q2),
              pe_pt(c2, r20, r21, r22, s0, s1, s2, q0, q1, q2));
    predicate pe_tight(real lo, real hi, real a0, real a1, real a2, real a3, real b0, real b1, real b2, real b3,
                       real c0, real c1, real c2,
                       real r00, real r01, real r02, real r10, real r11, real r12,
                       real r20, real r21, real r22, real s0, real s1, real s2) =
      (\exists real u; hi - ps_tau(hi) <= u
         && pe_above(u, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2))
      && (\exists real u; u <= lo + ps_tau(lo)
         && pe_below(u, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2));
*/

#ifdef CBX_PELL_LEMMAS
/*@ // X at the point c + M q is A + a'.q: the ellipsoid's point of q is
    // the ball's point q in the ellipsoid's frame.
    // proof: z3
    lemma pe_aff: \forall real a0, a1, a2, a3, c0, c1, c2, r00, r01, r02, r10, r11, r12,
                          r20, r21, r22, s0, s1, s2, q0, q1, q2;
      aff(a0, a1, a2, a3, pe_pt(c0, r00, r01, r02, s0, s1, s2, q0, q1, q2),
          pe_pt(c1, r10, r11, r12, s0, s1, s2, q0, q1, q2), pe_pt(c2, r20, r21, r22, s0, s1, s2, q0, q1, q2))
      == aff(pe_x(r00, r10, r20, s0, a0, a1, a2), pe_x(r01, r11, r21, s1, a0, a1, a2),
             pe_x(r02, r12, r22, s2, a0, a1, a2), aff(a0, a1, a2, a3, c0, c1, c2),
             0 + 1*q0, 0 + 1*q1, 0 + 1*q2);
    // The three inequalities at one point, from the ball's in the frame.
    // proof: z3
    lemma pe_at_ps: \forall real lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                            r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2, q0, q1, q2;
      ps_xw(pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
            pe_x(r02, r12, r22, s2, b0, b1, b2), aff(b0, b1, b2, b3, c0, c1, c2), 0, 0, 0, 1, q0, q1, q2)
      ==> ps_xlo(lo, pe_x(r00, r10, r20, s0, a0, a1, a2), pe_x(r01, r11, r21, s1, a0, a1, a2),
                 pe_x(r02, r12, r22, s2, a0, a1, a2), aff(a0, a1, a2, a3, c0, c1, c2),
                 pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
                 pe_x(r02, r12, r22, s2, b0, b1, b2), aff(b0, b1, b2, b3, c0, c1, c2), 0, 0, 0, 1, q0, q1, q2)
      ==> ps_xhi(hi, pe_x(r00, r10, r20, s0, a0, a1, a2), pe_x(r01, r11, r21, s1, a0, a1, a2),
                 pe_x(r02, r12, r22, s2, a0, a1, a2), aff(a0, a1, a2, a3, c0, c1, c2),
                 pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
                 pe_x(r02, r12, r22, s2, b0, b1, b2), aff(b0, b1, b2, b3, c0, c1, c2), 0, 0, 0, 1, q0, q1, q2)
      ==> pe_at(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3,
                pe_pt(c0, r00, r01, r02, s0, s1, s2, q0, q1, q2),
                pe_pt(c1, r10, r11, r12, s0, s1, s2, q0, q1, q2),
                pe_pt(c2, r20, r21, r22, s0, s1, s2, q0, q1, q2));
    // The ball's statement in the frame gives the ellipsoid's.
    lemma pe_axis_ps: \forall real lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                              r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2;
      ps_axis(lo, hi, pe_x(r00, r10, r20, s0, a0, a1, a2), pe_x(r01, r11, r21, s1, a0, a1, a2),
              pe_x(r02, r12, r22, s2, a0, a1, a2), aff(a0, a1, a2, a3, c0, c1, c2),
              pe_x(r00, r10, r20, s0, b0, b1, b2), pe_x(r01, r11, r21, s1, b0, b1, b2),
              pe_x(r02, r12, r22, s2, b0, b1, b2), aff(b0, b1, b2, b3, c0, c1, c2), 0, 0, 0, 1)
      ==> pe_axis(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                  r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    // The statement about every point, from the quantifier-free forms.
    lemma pe_cover: \forall real lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                            r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2;
      pe_front(b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      ==> pe_lo(lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      ==> pe_hi(hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      ==> pe_axis(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                  r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    // Tightness from one witness each.
    lemma pe_tight_intro: \forall real lo, hi, ul, uh, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                                  r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2;
      hi - ps_tau(hi) <= uh
      ==> pe_above(uh, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      ==> ul <= lo + ps_tau(lo)
      ==> pe_below(ul, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      ==> pe_tight(lo, hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                   r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2);
    // X - t W at c is the same in both frames; |M^T (a - t b)| column by
    // column (the enclosures of src/f64/cbx_pell.c).
    lemma pe_e_eq: \forall real t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2;
      pe_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      == ps_e(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2);
    // proof: z3
    lemma pe_n_eq: \forall real t, a0, a1, a2, b0, b1, b2,
                           r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2;
      pe_n(t, a0, a1, a2, b0, b1, b2, r00, r01, r02, r10, r11, r12, r20, r21, r22, s0, s1, s2)
      == rnorm3(pe_x(r00, r10, r20, s0, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                pe_x(r01, r11, r21, s1, a0 - t*b0, a1 - t*b1, a2 - t*b2),
                pe_x(r02, r12, r22, s2, a0 - t*b0, a1 - t*b1, a2 - t*b2));
*/
#endif /* CBX_PELL_LEMMAS */
#endif /* CBX_PELL_H */
