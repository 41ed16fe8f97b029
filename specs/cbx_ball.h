/*
 * ACSL logic of the sphere and ellipsoid bounds (src/algo/cbx_sphere.c) that
 * does not depend on the floating-point format: unit ball, Cauchy-Schwarz
 * chain (over the reals).  The domains and the row rescaling of each format
 * are in specs/cbx_spec.h.  certbox.h includes this file once.
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

    // [lo, hi] holds t + b.p for every p of the unit ball.
    predicate ball_axis(real lo, real hi, real b0, real b1, real b2, real t) =
      \forall real p0, p1, p2; in_ball(p0, p1, p2) ==>
        lo <= dot3(b0, b1, b2, p0, p1, p2) + t <= hi;

    // The same statement without a quantifier (equivalent to it): both
    // distances from t to the ends are at least the row norm.  The code
    // establishes this form; lemma cover_ball (below) turns it into ball_axis.
    predicate ball_cover(real lo, real hi, real b0, real b1, real b2, real t) =
      lo <= t && t <= hi
      && nrm3(b0, b1, b2) <= (t - lo)*(t - lo)
      && nrm3(b0, b1, b2) <= (hi - t)*(hi - t);

    // The exact row norm |b| = sqrt(b.b) (the exact half-width of axis i):
    // the tightness statements (specs/cbx_spec.h, ball_tight) compare the
    // ends with it; the lemmas of rnorm3 below (abs_sq, rnorm3_def,
    // ...) are what src/algo/cbx_sphere.c uses of it (proven in pass L: in
    // WP's float context CVC4 does not even find |x| |x| = x x).
    logic real rnorm3(real a0, real a1, real a2) = \sqrt(nrm3(a0, a1, a2));
*/

/* The lemmas: only in the proof units that use them (CBX_BALL_LEMMAS: the
 * lemma jobs, which prove them, and the jobs of src/algo/cbx_sphere.c).  A
 * global lemma is a hypothesis of every goal of its unit: with these 22 in
 * every goal of proofs/all.c, the prover time of goals that never use them
 * grew by a fifth (measured 2026-11-27: 70 s against 55 s on the same 384
 * goals of the interval and center kernels). */
#ifdef CBX_BALL_LEMMAS
/*@
    // Squaring is monotone on nonnegative reals (both directions).
    lemma sq_mono: \forall real a, b; 0 <= a <= b ==> sq_le(a, b);
    lemma sq_mono_inv: \forall real a, b; 0 <= b ==> sq_le(a, b) ==> -b <= a <= b;

    // Cauchy-Schwarz in 3 dimensions, via Lagrange's identity; each step is
    // a separate lemma whose terms (dot3, nrm3) trigger the previous one.
    lemma nrm3_pos: \forall real a0, a1, a2; nrm3(a0, a1, a2) >= 0;
    // proof: z3
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

    // ball_cover gives ball_axis (the quantifier over p stays in these two).
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
    // A larger radius still bounds.
    lemma sq_bound_up: \forall real b0, b1, b2, r, q;
      sq_bound(b0, b1, b2, r) ==> r <= q ==> sq_bound(b0, b1, b2, q);

    // One step each (the provers do not chain instances in the float context).
    lemma abs_sq: \forall real x; \abs(x) * \abs(x) == x * x;
    lemma rnorm3_def: \forall real a0, a1, a2;
      rnorm3(a0, a1, a2) >= 0 && rnorm3(a0, a1, a2) * rnorm3(a0, a1, a2) == nrm3(a0, a1, a2);
    // (c rho + e)^2 >= c^2 rho^2 + e^2 for nonnegative c, rho, e.
    lemma sq_sum_up: \forall real n, rho, c, e;
      0 <= rho ==> rho * rho == n ==> 0 <= c ==> 0 <= e ==>
      n * (c * c) + e * e <= (c * rho + e) * (c * rho + e);
    // An entry at least m in magnitude has a square at least m^2.
    lemma sq_ge: \forall real x, m; 0 <= m <= \abs(x) ==> sq_le(m, x);
    // (x0 + x1 + x2)^2 <= 4 |x|^2 (Cauchy-Schwarz with (1, 1, 1), 3 <= 4),
    // from its sum-of-squares identity.
    lemma sum4_id: \forall real x0, x1, x2;
      4 * nrm3(x0, x1, x2) - (x0 + x1 + x2) * (x0 + x1 + x2)
      == nrm3(x0 - x1, x0 - x2, x1 - x2) + nrm3(x0, x1, x2);
    lemma sum4: \forall real x0, x1, x2;
      (x0 + x1 + x2) * (x0 + x1 + x2) <= 4 * nrm3(x0, x1, x2);
    // |(|a0|, |a1|, |a2|)| = |a|.
    lemma nrm3_abs_t: \forall real a0, a1, a2;
      \abs(a0) * \abs(a0) == a0 * a0 ==> \abs(a1) * \abs(a1) == a1 * a1 ==>
      \abs(a2) * \abs(a2) == a2 * a2 ==>
      nrm3(\abs(a0), \abs(a1), \abs(a2)) == nrm3(a0, a1, a2);
    // proof: z3
    lemma nrm3_abs: \forall real a0, a1, a2;
      nrm3(\abs(a0), \abs(a1), \abs(a2)) == nrm3(a0, a1, a2);
    // Entrywise squares summed.
    lemma sq_le_sum: \forall real s0, s1, s2, y0, y1, y2;
      sq_le(s0, y0) ==> sq_le(s1, y1) ==> sq_le(s2, y2) ==> nrm3(s0, s1, s2) <= nrm3(y0, y1, y2);
*/
#endif /* CBX_BALL_LEMMAS */
#endif /* CBX_BALL_H */
