/*
 * ACSL logic of one real interval [lo, hi] (src/f64/cbx_iv.h): membership,
 * the range a primitive accepts, the exact ends of a square, and the
 * statements of containment for a product, a square, a square root and a
 * quotient.  Read by Frama-C only.  The product's exact ends (itmin,
 * itmax, itmag) and bilinearity (iterm_all) are the interval matrices'
 * (specs/cbx_imat_logic.h, included first by certbox.h).
 *
 * Each containment is a named predicate, so that its lemma's trigger is
 * the predicate and not a bare product (as iterm_holds).  The lemmas are
 * compiled only with CBX_IV_LEMMAS: in proofs/lemmas.c (proven there) and
 * proofs/trs.c (used there).
 */
#ifndef CBX_IV_LOGIC_H
#define CBX_IV_LOGIC_H

/*@ // x lies in [lo, hi]
    predicate iv_has(real lo, real hi, real x) = lo <= x <= hi;
    // both ends at most m in magnitude
    predicate iv_rng(real lo, real hi, real m) = -m <= lo <= m && -m <= hi <= m;

    // The exact ends of {x^2 : x in [l, h]} (l <= h).
    logic real sqmin(real l, real h) = l >= 0 ? l*l : (h <= 0 ? h*h : 0);
    logic real sqmax(real l, real h) = \max(l*l, h*h);

    // Containment, for every real point of the operands:
    //   x y in [lo, hi] (x in [al, ah], y in [bl, bh])
    predicate iv_prod(real lo, real hi, real al, real ah, real bl, real bh) =
      \forall real x, y; al <= x <= ah && bl <= y <= bh ==> lo <= x*y <= hi;
    //   one point of it: x y in [lo, hi]
    predicate prod_at(real lo, real hi, real x, real y) = lo <= x*y <= hi;
    //   the product's exact ends for a point a in [0, 1] and an interval
    //   [dl, dh] within e of dd: within e of a dd
    predicate pt_prod_near(real a, real dd, real e, real dl, real dh) =
      itmin(a, a, dl, dh) >= a*dd - e && itmax(a, a, dl, dh) <= a*dd + e
      && itmag(a, a, dl, dh) <= \abs(dd) + e;
    //   one point of it: x^2 in [lo, hi]
    predicate sq_at(real lo, real hi, real x) = lo <= x*x <= hi;
    //   x^2 in [lo, hi] (x in [l, h])
    predicate iv_sq(real lo, real hi, real l, real h) =
      \forall real x; l <= x <= h ==> lo <= x*x <= hi;
    //   y in [lo, hi] for every y >= 0 with y^2 in [l, h] (the square root)
    predicate iv_root(real lo, real hi, real l, real h) =
      \forall real y; 0 <= y && l <= y*y <= h ==> lo <= y <= hi;
    //   lo y <= x <= hi y (x / y in [lo, hi], multiplied out; y > 0)
    predicate iv_quot(real lo, real hi, real al, real ah, real bl, real bh) =
      \forall real x, y; al <= x <= ah && bl <= y <= bh ==> lo*y <= x <= hi*y;
    //   one point of it: lo y <= x <= hi y
    predicate quot_at(real lo, real hi, real x, real y) = lo*y <= x <= hi*y;
    //   k x in [lo, hi] (a multiple of x: a vector before it is normalised)
    predicate sc_has(real lo, real hi, real x, real k) = lo <= k*x <= hi;
    //   lo <= x (the provers' division by k > 0, asked for by name)
    predicate divk(real k, real lo, real x) = 0 < k && lo*k <= k*x ==> lo <= x;
    //   x0 + s D in [lo, hi] for every s in [a, b] (a linear path)
    predicate lerp_in(real lo, real hi, real x0, real d, real a, real b) =
      \forall real s; a <= s <= b ==> lo <= x0 + s*d <= hi;
    //   one point of it: x0 + s D in [lo, hi]
    predicate lerp_pt(real lo, real hi, real x0, real d, real s) = lo <= x0 + s*d <= hi;
    //   u (x0 + s D) in [lo, hi] for every u in [rl, rh] and s in [a, b]
    //   (a product whose second factor is a linear path)
    predicate cell_prod(real lo, real hi, real rl, real rh, real x0, real d, real a, real b) =
      \forall real s, u; a <= s <= b && rl <= u <= rh ==> prod_at(lo, hi, u, x0 + s*d);
    // the exact ends of {x0 + s (x1 - x0) : s in [a, b]}, and iv_lerp's
    // bound on the distance of its ends to them
    logic real lerp_lo(real x0, real x1, real a, real b) = \min(x0 + a*(x1 - x0), x0 + b*(x1 - x0));
    logic real lerp_hi(real x0, real x1, real a, real b) = \max(x0 + a*(x1 - x0), x0 + b*(x1 - x0));
    // (80 u, binary64: CBX_U80 of cbx_prec_begin.h)
    logic real lerp_err(real x0, real x1) = 0x1.4p-47 * (\abs(x0) + \abs(x1)) + 0x1p-1060;
    // those ends widened by that bound: where iv_lerp's ends lie
    logic real lerp_wlo(real x0, real x1, real a, real b) = lerp_lo(x0, x1, a, b) - lerp_err(x0, x1);
    logic real lerp_whi(real x0, real x1, real a, real b) = lerp_hi(x0, x1, a, b) + lerp_err(x0, x1);
    // a product's exact ends over [ml, mh] x [sl, sh], both ends of the
    // second factor in [l, h]: within those over [ml, mh] x [l, h], and
    // its largest corner no larger
    predicate it_sub(real ml, real mh, real sl, real sh, real l, real h) =
      l <= sl <= h && l <= sh <= h ==>
        itmin(ml, mh, l, h) <= itmin(ml, mh, sl, sh) && itmax(ml, mh, sl, sh) <= itmax(ml, mh, l, h)
        && itmag(ml, mh, sl, sh) <= itmag(ml, mh, l, h);
    // c y <= c z for c >= 0 and y <= z; the reverse for c <= 0
    predicate mono(real c, real y, real z) =
      y <= z ==> ((c >= 0 ==> c*y <= c*z) && (c <= 0 ==> c*z <= c*y));
    // the sign of c y for y >= 0
    predicate msign(real c, real y) = 0 <= y ==> ((c <= 0 ==> c*y <= 0) && (c >= 0 ==> 0 <= c*y));
    // squares: nonnegative, growing on y >= 0, and back (the provers'
    // nonlinear facts, each asked for by name where it is used)
    predicate sqp(real y) = 0 <= y*y;
    predicate sqm(real y, real z) = 0 <= y <= z ==> y*y <= z*z;
    predicate sql(real y, real z) = 0 <= z && y*y <= z*z ==> y <= z;
*/

#ifdef CBX_IV_LEMMAS
/*@
    lemma mono_all: \forall real c, y, z; mono(c, y, z);
    lemma msign_all: \forall real c, y; msign(c, y);
    lemma iv_prod_ends: \forall real lo, hi, al, ah, bl, bh;
      lo <= itmin(al, ah, bl, bh) && itmax(al, ah, bl, bh) <= hi ==> iv_prod(lo, hi, al, ah, bl, bh);
    lemma iv_prod_at: \forall real lo, hi, al, ah, bl, bh, x, y;
      iv_prod(lo, hi, al, ah, bl, bh) && al <= x <= ah && bl <= y <= bh ==> prod_at(lo, hi, x, y);
    lemma pt_prod: \forall real a, dd, e, dl, dh;
      0 <= a <= 1 && 0 <= e && dd - e <= dl <= dd <= dh <= dd + e ==> pt_prod_near(a, dd, e, dl, dh);
    // factors in [-1, 1]: the product's exact ends too
    lemma itm_1: \forall real al, ah, bl, bh;
      iv_rng(al, ah, 1) && iv_rng(bl, bh, 1) ==>
        -1 <= itmin(al, ah, bl, bh) && itmax(al, ah, bl, bh) <= 1 && itmag(al, ah, bl, bh) <= 1;
    lemma sqm_1: \forall real l, h; iv_rng(l, h, 1) ==> 0 <= sqmin(l, h) && sqmax(l, h) <= 1;
    lemma iv_sq_at: \forall real lo, hi, l, h, x;
      iv_sq(lo, hi, l, h) && l <= x <= h ==> sq_at(lo, hi, x);
    lemma iv_sq_ends: \forall real lo, hi, l, h;
      lo <= sqmin(l, h) && sqmax(l, h) <= hi ==> iv_sq(lo, hi, l, h);
    lemma sqp_all: \forall real y; sqp(y);
    // proof: z3
    lemma sqm_all: \forall real y, z; sqm(y, z);
    // proof: z3
    lemma sql_all: \forall real y, z; sql(y, z);
    lemma iv_root_ends: \forall real lo, hi, l, h;
      (lo <= 0 || lo*lo <= l) && 0 <= hi && h <= hi*hi ==> iv_root(lo, hi, l, h);
    lemma lerp_ends: \forall real lo, hi, x0, d, a, b;
      lo <= x0 + a*d && lo <= x0 + b*d && x0 + a*d <= hi && x0 + b*d <= hi ==> lerp_in(lo, hi, x0, d, a, b);
    lemma lerp_at: \forall real lo, hi, x0, d, a, b, s;
      lerp_in(lo, hi, x0, d, a, b) && a <= s <= b ==> lerp_pt(lo, hi, x0, d, s);
    lemma lerp_prod: \forall real lo, hi, rl, rh, sl, sh, x0, d, a, b;
      iv_prod(lo, hi, rl, rh, sl, sh) && lerp_in(sl, sh, x0, d, a, b) ==> cell_prod(lo, hi, rl, rh, x0, d, a, b);
    lemma it_sub_all: \forall real ml, mh, sl, sh, l, h; it_sub(ml, mh, sl, sh, l, h);
    lemma iv_quot_ends: \forall real lo, hi, al, ah, bl, bh;
      0 < bl && lo*bl <= al && lo*bh <= al && ah <= hi*bl && ah <= hi*bh ==> iv_quot(lo, hi, al, ah, bl, bh);
*/
#endif

/* The steps of the quaternion path's normalisation (src/f64/cbx_quat.h):
 * compiled with CBX_IV_QUOT_LEMMAS, in proofs/lemmas.c (proven there) and
 * proofs/trs.c (used there) only, so that the projective jobs, which use
 * this file's other lemmas, do not carry them. */
#ifdef CBX_IV_QUOT_LEMMAS
/*@
    lemma iv_quot_at: \forall real lo, hi, al, ah, bl, bh, x, y;
      iv_quot(lo, hi, al, ah, bl, bh) && al <= x <= ah && bl <= y <= bh ==> quot_at(lo, hi, x, y);
    lemma divk_all: \forall real k, lo, x; divk(k, lo, x);
    // x in [lo, hi] when k x / k is: the quotient of a multiple of x by k
    lemma quot_sc_h: \forall real lo, hi, al, ah, bl, bh, x, k;
      iv_quot(lo, hi, al, ah, bl, bh) && sc_has(al, ah, x, k) && bl <= k <= bh && 0 < bl
      && quot_at(lo, hi, k*x, k) && divk(k, lo, x) && divk(k, -hi, -x) ==> lo <= x <= hi;
    lemma quot_sc: \forall real lo, hi, al, ah, bl, bh, x, k;
      iv_quot(lo, hi, al, ah, bl, bh) && sc_has(al, ah, x, k) && bl <= k <= bh && 0 < bl ==> lo <= x <= hi;
    // one point of a square root's enclosure (as ps_root_at, specs/cbx_psph.h)
    // proof: z3
    lemma iv_root_at: \forall real lo, hi, l, h, y;
      iv_root(lo, hi, l, h) && 0 <= y && sq_at(l, h, y) ==> lo <= y <= hi;
*/
#endif

#endif /* CBX_IV_LOGIC_H */
