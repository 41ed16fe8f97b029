/*
 * ACSL logic of the sphere and ellipsoid bounds (src/cbx_sphere.c): unit
 * ball, Cauchy-Schwarz chain, domains.
 *
 * How the proof is split: the code only ever establishes the quantifier-free
 * predicate ball_cover (both ends at least the row norm away from t, in
 * squares); the lemma cover_ball, proven once over the reals in pass L
 * (proofs/lemmas.c) from Cauchy-Schwarz, turns it into the statement about
 * every point of the ball (ball_axis) that the public contracts carry.
 * No float goal ever sees the quantifier over p.
 */
#ifndef CBX_BALL_H
#define CBX_BALL_H

/*@ // ---------------------------------------------------------------------
    // Balls: p is in the closed unit ball; r bounds the row (b0, b1, b2).
    // ---------------------------------------------------------------------
    logic real dot3(real m0, real m1, real m2, real p0, real p1, real p2) =
      m0*p0 + m1*p1 + m2*p2;
    logic real nrm3(real a0, real a1, real a2) = a0*a0 + a1*a1 + a2*a2;
    predicate in_ball(real p0, real p1, real p2) = nrm3(p0, p1, p2) <= 1;
    predicate sq_bound(real b0, real b1, real b2, real r) =
      0 <= r && nrm3(b0, b1, b2) <= r*r;
    predicate sq_le(real a, real b) = a*a <= b*b;

    // Squaring is monotone on nonnegative reals (both directions).
    lemma sq_mono: \forall real a, b; 0 <= a <= b ==> sq_le(a, b);
    lemma sq_mono_inv: \forall real a, b; 0 <= b ==> sq_le(a, b) ==> -b <= a <= b;

    // Cauchy-Schwarz in 3 dimensions, via Lagrange's identity; each step is
    // a separate lemma whose terms (dot3, nrm3) trigger the previous one.
    lemma nrm3_pos: \forall real a0, a1, a2; nrm3(a0, a1, a2) >= 0;
    lemma lagrange: \forall real m0, m1, m2, p0, p1, p2;
      nrm3(m0, m1, m2) * nrm3(p0, p1, p2)
        - dot3(m0, m1, m2, p0, p1, p2) * dot3(m0, m1, m2, p0, p1, p2)
      == nrm3(m0*p1 - m1*p0, m0*p2 - m2*p0, m1*p2 - m2*p1);
    lemma cauchy_schwarz: \forall real m0, m1, m2, p0, p1, p2;
      dot3(m0, m1, m2, p0, p1, p2) * dot3(m0, m1, m2, p0, p1, p2)
        <= nrm3(m0, m1, m2) * nrm3(p0, p1, p2);
    lemma cs_ball: \forall real m0, m1, m2, p0, p1, p2;
      in_ball(p0, p1, p2) ==>
      dot3(m0, m1, m2, p0, p1, p2) * dot3(m0, m1, m2, p0, p1, p2) <= nrm3(m0, m1, m2);

    // [lo, hi] holds t + b.p for every p of the unit ball.
    predicate ball_axis(real lo, real hi, real b0, real b1, real b2, real t) =
      \forall real p0, p1, p2; in_ball(p0, p1, p2) ==>
        lo <= dot3(b0, b1, b2, p0, p1, p2) + t <= hi;

    // The same statement without a quantifier (equivalent to it): both
    // distances from t to the ends are at least the row norm.  The code
    // establishes this form; lemma cover_ball turns it into ball_axis.
    predicate ball_cover(real lo, real hi, real b0, real b1, real b2, real t) =
      lo <= t && t <= hi
      && nrm3(b0, b1, b2) <= (t - lo)*(t - lo)
      && nrm3(b0, b1, b2) <= (hi - t)*(hi - t);

    lemma cover_dot: \forall real lo, hi, b0, b1, b2, t, p0, p1, p2;
      ball_cover(lo, hi, b0, b1, b2, t) ==> in_ball(p0, p1, p2) ==>
      sq_le(dot3(b0, b1, b2, p0, p1, p2), t - lo)
      && sq_le(dot3(b0, b1, b2, p0, p1, p2), hi - t);
    lemma cover_ball: \forall real lo, hi, b0, b1, b2, t;
      ball_cover(lo, hi, b0, b1, b2, t) ==> ball_axis(lo, hi, b0, b1, b2, t);

    // How the code gets ball_cover: a radius r with |b| <= r and [lo, hi]
    // containing [t - r, t + r].
    lemma cover_sq: \forall real lo, hi, b0, b1, b2, t, r;
      sq_bound(b0, b1, b2, r) ==> lo <= t ==> t <= hi ==>
      sq_le(r, t - lo) ==> sq_le(r, hi - t) ==> ball_cover(lo, hi, b0, b1, b2, t);
    lemma cover_intro: \forall real lo, hi, b0, b1, b2, t, r;
      sq_bound(b0, b1, b2, r) ==> lo <= t - r ==> t + r <= hi ==>
      ball_cover(lo, hi, b0, b1, b2, t);
    // A row dominated entrywise in absolute value has the smaller norm.
    lemma sq_abs: \forall real a, b; \abs(a) <= b ==> sq_le(a, b);
    lemma sq_bound_dom: \forall real a0, a1, a2, b0, b1, b2, r;
      sq_le(a0, b0) ==> sq_le(a1, b1) ==> sq_le(a2, b2) ==>
      sq_bound(b0, b1, b2, r) ==> sq_bound(a0, a1, a2, r);
    // Scaling a row by 2^600 scales its norm by 2^600 (row_radius); a
    // larger radius still bounds.
    lemma sq_bound_scale: \forall real b0, b1, b2, r;
      sq_bound(b0*0x1p600, b1*0x1p600, b2*0x1p600, r) ==> sq_bound(b0, b1, b2, r*0x1p-600);
    lemma sq_bound_up: \forall real b0, b1, b2, r, q;
      sq_bound(b0, b1, b2, r) ==> r <= q ==> sq_bound(b0, b1, b2, q);
*/

/*@ predicate in_dom508(real x, real y) = -0x1p508 <= x*y <= 0x1p508;
    lemma cls_254: \forall real m, c; cls(m, c, 0x1p254, 0x1p254) ==> in_dom508(m, c);

    predicate aff_nan(cbx_affine *a) =
         \is_NaN(a->m[0][0]) || \is_NaN(a->m[0][1]) || \is_NaN(a->m[0][2]) || \is_NaN(a->m[0][3])
      || \is_NaN(a->m[1][0]) || \is_NaN(a->m[1][1]) || \is_NaN(a->m[1][2]) || \is_NaN(a->m[1][3])
      || \is_NaN(a->m[2][0]) || \is_NaN(a->m[2][1]) || \is_NaN(a->m[2][2]) || \is_NaN(a->m[2][3]);

    predicate sph_dom(real m0, real m1, real m2, real t) =
      cls(m0, m0, 0x1p509, 0x1p509) && cls(m1, m1, 0x1p509, 0x1p509)
      && cls(m2, m2, 0x1p509, 0x1p509) && -0x1p1018 <= t <= 0x1p1018;

    predicate sph_axis(cbx_affine *a, cbx_box *o, integer i) =
      ((\is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
        && \is_finite(a->m[i][3]) && sph_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3])) ==>
         (\is_finite(o->lo[i]) && \is_finite(o->hi[i])
          && ball_axis(o->lo[i], o->hi[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3])))
      && (!(\is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
        && \is_finite(a->m[i][3]) && sph_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3])) ==>
         whole_axis(o, i));

    predicate ell_dom(real r0, real r1, real r2, real d0, real d1, real d2, real c) =
      cls(r0, d0, 0x1p254, 0x1p254) && cls(r1, d1, 0x1p254, 0x1p254)
      && cls(r2, d2, 0x1p254, 0x1p254) && -0x1p1018 <= c <= 0x1p1018;
*/

/*@ predicate ell_nan(double *center, double *radii, double (*rot)[3]) =
         \is_NaN(center[0]) || \is_NaN(center[1]) || \is_NaN(center[2])
      || \is_NaN(radii[0]) || \is_NaN(radii[1]) || \is_NaN(radii[2])
      || \is_NaN(rot[0][0]) || \is_NaN(rot[0][1]) || \is_NaN(rot[0][2])
      || \is_NaN(rot[1][0]) || \is_NaN(rot[1][1]) || \is_NaN(rot[1][2])
      || \is_NaN(rot[2][0]) || \is_NaN(rot[2][1]) || \is_NaN(rot[2][2]);

    predicate ell_row_dom(double *center, double *radii, double (*rot)[3], integer i) =
      \is_finite(rot[i][0]) && \is_finite(rot[i][1]) && \is_finite(rot[i][2])
      && \is_finite(radii[0]) && \is_finite(radii[1]) && \is_finite(radii[2])
      && \is_finite(center[i])
      && ell_dom(rot[i][0], rot[i][1], rot[i][2], radii[0], radii[1], radii[2], center[i]);

    // Axis i of o bounds center_i + sum_j rot_ij radii_j p_j over the unit ball.
    predicate ell_axis(double *center, double *radii, double (*rot)[3], cbx_box *o, integer i) =
      (ell_row_dom(center, radii, rot, i) ==>
         (\is_finite(o->lo[i]) && \is_finite(o->hi[i])
          && ball_axis(o->lo[i], o->hi[i], rot[i][0]*radii[0], rot[i][1]*radii[1],
                       rot[i][2]*radii[2], center[i])))
      && (!ell_row_dom(center, radii, rot, i) ==> whole_axis(o, i));

    predicate sph_row_dom(cbx_affine *a, integer i) =
      \is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
      && \is_finite(a->m[i][3]) && sph_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3]);
*/
#endif /* CBX_BALL_H */
