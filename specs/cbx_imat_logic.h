/*
 * ACSL logic of interval matrices that does not depend on the format:
 * real definitions and lemmas over the reals (the binary64 predicates:
 * specs/cbx_imat.h).  Read by Frama-C only; certbox.h includes it first,
 * so its lemmas are proven in a context of their own (the provers time out
 * on irow_in_terms with every later lemma of the project beside it, and
 * prove it in 20 ms alone).  The lemmas are compiled only with
 * CBX_IMAT_LEMMAS (below).
 *
 * Arithmetic here is exact real arithmetic.  One output coordinate of an
 * interval map is
 *     t + m0 x0 + m1 x1 + m2 x2,   t in [tl, th], m_j in [ml_j, mh_j],
 *                                  x_j in [l_j, h_j];
 * its exact range is [irow_lo, irow_hi] (each term on its own: a product of
 * two intervals ranges between the smallest and the largest of its four
 * corner products, and every corner is attained).
 */
#ifndef CBX_IMAT_LOGIC_H
#define CBX_IMAT_LOGIC_H

/*@ // ---------------------------------------------------------------------
    // One term: the product of [ml, mh] and [l, h].
    // ---------------------------------------------------------------------
    logic real itmin(real ml, real mh, real l, real h) = \min(\min(ml*l, ml*h), \min(mh*l, mh*h));
    logic real itmax(real ml, real mh, real l, real h) = \max(\max(ml*l, ml*h), \max(mh*l, mh*h));
    logic real itmag(real ml, real mh, real l, real h) =
      \max(\max(\abs(ml*l), \abs(ml*h)), \max(\abs(mh*l), \abs(mh*h)));
    logic real itsel(integer up, real ml, real mh, real l, real h) =
      up != 0 ? itmax(ml, mh, l, h) : itmin(ml, mh, l, h);

    // ---------------------------------------------------------------------
    // One output coordinate: its exact ends and its scale
    // S = max(|tl|, |th|) + sum_j itmag_j.
    // ---------------------------------------------------------------------
    logic real irow_lo(real ml0, real mh0, real ml1, real mh1, real ml2, real mh2, real tl,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      tl + itmin(ml0, mh0, l0, h0) + itmin(ml1, mh1, l1, h1) + itmin(ml2, mh2, l2, h2);
    logic real irow_hi(real ml0, real mh0, real ml1, real mh1, real ml2, real mh2, real th,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      th + itmax(ml0, mh0, l0, h0) + itmax(ml1, mh1, l1, h1) + itmax(ml2, mh2, l2, h2);
    logic real irow_sel(integer up, real ml0, real mh0, real ml1, real mh1, real ml2, real mh2,
                        real t, real l0, real h0, real l1, real h1, real l2, real h2) =
      t + itsel(up, ml0, mh0, l0, h0) + itsel(up, ml1, mh1, l1, h1) + itsel(up, ml2, mh2, l2, h2);
    logic real irow_mag(real ml0, real mh0, real ml1, real mh1, real ml2, real mh2,
                        real tl, real th, real l0, real h0, real l1, real h1, real l2, real h2) =
      \max(\abs(tl), \abs(th))
      + itmag(ml0, mh0, l0, h0) + itmag(ml1, mh1, l1, h1) + itmag(ml2, mh2, l2, h2);

    // Every point of the image: the real statement of containment.
    predicate irow_in(real lo, real hi, real ml0, real mh0, real ml1, real mh1, real ml2, real mh2,
                      real tl, real th, real l0, real h0, real l1, real h1, real l2, real h2) =
      \forall real m0, m1, m2, t, x0, x1, x2;
        ml0 <= m0 <= mh0 && ml1 <= m1 <= mh1 && ml2 <= m2 <= mh2 && tl <= t <= th
        && l0 <= x0 <= h0 && l1 <= x1 <= h1 && l2 <= x2 <= h2
        ==> lo <= t + m0*x0 + m1*x1 + m2*x2 <= hi;
    // Bilinearity, the fact the interval form rests on: a product of a
    // factor in [ml, mh] and one in [l, h] lies between the smallest and
    // the largest corner product (iterm_all).  A named predicate, so that
    // the lemma's trigger is iterm_holds, not a bare product m*x (which
    // would match every product of every other proof's context); with the
    // three of a row the statement of every point is linear in the
    // products (irow_in_terms).
    predicate iterm_holds(real ml, real mh, real l, real h) =
      \forall real m, x; ml <= m <= mh && l <= x <= h ==>
        itmin(ml, mh, l, h) <= m*x <= itmax(ml, mh, l, h);
*/

/* The lemmas, only in the translation units that prove or use them
 * (proofs/lemmas.c, proofs/imat.c: CBX_IMAT_LEMMAS).  Global lemmas are
 * hypotheses of every goal of their unit, and these (their definitions
 * unfold into products) slowed ball_radius's assertion sq in
 * proofs/all.c from 7 s to past 120 s. */
#ifdef CBX_IMAT_LEMMAS
/*@
    lemma itsel_mag: \forall integer up, real ml, mh, l, h;
      -itmag(ml, mh, l, h) <= itsel(up, ml, mh, l, h) <= itmag(ml, mh, l, h);
    lemma iterm_all: \forall real ml, mh, l, h; iterm_holds(ml, mh, l, h);
    // proof: z3
    lemma irow_in_terms: \forall real lo, hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th,
                                      l0, h0, l1, h1, l2, h2;
      iterm_holds(ml0, mh0, l0, h0) && iterm_holds(ml1, mh1, l1, h1) && iterm_holds(ml2, mh2, l2, h2)
      && lo <= irow_lo(ml0, mh0, ml1, mh1, ml2, mh2, tl, l0, h0, l1, h1, l2, h2)
      && irow_hi(ml0, mh0, ml1, mh1, ml2, mh2, th, l0, h0, l1, h1, l2, h2) <= hi
      ==> irow_in(lo, hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2);
*/
#endif

#endif /* CBX_IMAT_LOGIC_H */
