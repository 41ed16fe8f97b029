/*
 * ACSL logic of unit quaternions (src/f64/cbx_quat.h): the rotation
 * matrix of q = (x, y, z, w) (w the scalar part), entry by entry, as the
 * renderers and glTF write it for a unit quaternion, and the fact that
 * bounds every entry of it to [-1, 1].  Read by Frama-C only.  The lemma
 * is compiled only with CBX_IV_LEMMAS (proofs/lemmas.c proves it,
 * proofs/trs.c uses it).
 */
#ifndef CBX_QUAT_LOGIC_H
#define CBX_QUAT_LOGIC_H

/*@ predicate unitq(real x, real y, real z, real w) = x*x + y*y + z*z + w*w == 1;
    // a sum of two squares is >= 0 (named: see unit_squares)
    predicate sqs2(real u, real v) = 0 <= u*u + v*v;

    // an off-diagonal entry 2 (u + v), u and v two products (named, so
    // that rot_pq's statement matches the entry it computes)
    logic real pq2(real u, real v) = 2*(u + v);
    logic real rot00(real x, real y, real z, real w) = 1 - 2*(y*y + z*z);
    logic real rot01(real x, real y, real z, real w) = pq2(x*y, -(z*w));
    logic real rot02(real x, real y, real z, real w) = pq2(x*z, y*w);
    logic real rot10(real x, real y, real z, real w) = pq2(x*y, z*w);
    logic real rot11(real x, real y, real z, real w) = 1 - 2*(x*x + z*z);
    logic real rot12(real x, real y, real z, real w) = pq2(y*z, -(x*w));
    logic real rot20(real x, real y, real z, real w) = pq2(x*z, -(y*w));
    logic real rot21(real x, real y, real z, real w) = pq2(y*z, x*w);
    logic real rot22(real x, real y, real z, real w) = 1 - 2*(x*x + y*y);

    // every entry of a unit quaternion's rotation lies in [-1, 1]
    predicate rot_unit(real x, real y, real z, real w) =
      -1 <= rot00(x, y, z, w) <= 1 && -1 <= rot01(x, y, z, w) <= 1 && -1 <= rot02(x, y, z, w) <= 1
      && -1 <= rot10(x, y, z, w) <= 1 && -1 <= rot11(x, y, z, w) <= 1 && -1 <= rot12(x, y, z, w) <= 1
      && -1 <= rot20(x, y, z, w) <= 1 && -1 <= rot21(x, y, z, w) <= 1 && -1 <= rot22(x, y, z, w) <= 1;

    // The shorter great arc from a unit p to a unit r, without an angle:
    // the unit vectors l p + m r with l, m >= 0 (slerp's values for t in
    // [0, 1], and nlerp's, are such points).  c = p.r; arc_ok is what a
    // point's coefficients satisfy (arc_quad: |l p + m r|^2 = 1 written
    // with c), and arc_below says b is below p, r and (p + r) / (1 + c),
    // the point where the tangents at p and r meet: then b is below every
    // point of the arc (the arc lies in the triangle of p, r and that
    // point; lemma arc_lo).
    logic real dot4(real p0, real p1, real p2, real p3, real r0, real r1, real r2, real r3) =
      p0*r0 + p1*r1 + p2*r2 + p3*r3;
    logic real nrm4(real p0, real p1, real p2, real p3) = p0*p0 + p1*p1 + p2*p2 + p3*p3;
    predicate arc_pt(real p0, real p1, real p2, real p3, real r0, real r1, real r2, real r3, real l, real m) =
      unitq(p0, p1, p2, p3) && unitq(r0, r1, r2, r3) && 0 <= l && 0 <= m
      && unitq(l*p0 + m*r0, l*p1 + m*r1, l*p2 + m*r2, l*p3 + m*r3);
    predicate arc_quad(real l, real m, real c) =
      0 <= l && 0 <= m && -1 <= c <= 1 && l*l + m*m + 2*(l*m*c) == 1;
    predicate arc_ok(real l, real m, real c) =
      0 <= l && 0 <= m && 1 <= l + m && l*c + m <= 1 && l + m*c <= 1 && c <= 1;
    predicate arc_below(real l, real m, real c, real p, real r, real b) =
      arc_ok(l, m, c) && b <= p && b <= r && b*(1 + c) <= p + r;
    // the provers' steps, each asked for by name (see unit_squares):
    // |l p + m r|^2 expanded, a product with a factor 1, a division by
    // 1 - c > 0
    predicate arc_exp(real p0, real p1, real p2, real p3, real r0, real r1, real r2, real r3, real l, real m) =
      nrm4(l*p0 + m*r0, l*p1 + m*r1, l*p2 + m*r2, l*p3 + m*r3)
      == l*l*nrm4(p0, p1, p2, p3) + m*m*nrm4(r0, r1, r2, r3) + 2*(l*m*dot4(p0, p1, p2, p3, r0, r1, r2, r3));
    predicate mul1(real a, real x) = x == 1 ==> a*x == a;
    // |k u|^2 = k^2 (u a unit vector)
    predicate sc_unit(real x, real y, real z, real w, real k) =
      (k*x)*(k*x) + (k*y)*(k*y) + (k*z)*(k*z) + (k*w)*(k*w) == k*k;
    predicate arc_div(real c, real x) = c < 1 && 0 <= (1 - c)*x ==> 0 <= x;
*/

#ifdef CBX_IV_LEMMAS
/*@ // Each entry's bound is a sum of two squares >= 0 expanded: for
    // 01, 2 (x y - z w) <= x^2 + y^2 + z^2 + w^2 = 1 is
    // (x - y)^2 + (z + w)^2 >= 0.  The squares' facts are named (sqs2),
    // so the provers instantiate them only where a lemma names them.
    lemma sqs2_all: \forall real u, v; sqs2(u, v);
    lemma unit_squares: \forall real x, y, z, w; unitq(x, y, z, w) ==>
      sqs2(x - y, z + w) && sqs2(x + y, z - w) && sqs2(x - z, y - w) && sqs2(x + z, y + w)
      && sqs2(x - y, z - w) && sqs2(x + y, z + w) && sqs2(y - z, x + w) && sqs2(y + z, x - w)
      && sqs2(x - z, y + w) && sqs2(x + z, y - w) && sqs2(y - z, x - w) && sqs2(y + z, x + w)
      && sqs2(x, w) && sqs2(y, z) && sqs2(y, w) && sqs2(x, z) && sqs2(z, w) && sqs2(x, y);
    lemma unit_rot: \forall real x, y, z, w; unitq(x, y, z, w) ==> rot_unit(x, y, z, w);

    // A factor in [-2, 2] times one in [-1, 1] (nlerp's blend weights
    // times a unit vector's components): the product's exact ends.
    lemma itm_21: \forall real al, ah, bl, bh;
      iv_rng(al, ah, 2) && iv_rng(bl, bh, 1) ==>
        -2 <= itmin(al, ah, bl, bh) && itmax(al, ah, bl, bh) <= 2 && itmag(al, ah, bl, bh) <= 2;
    // A unit vector's components lie in [-1, 1].
    lemma unit_comp_h: \forall real x, y, z, w; unitq(x, y, z, w)
      && sqs2(y, z) && sqs2(x, w) && sqp(x) && sqp(y) && sqp(z) && sqp(w) && sql(x, 1) && sql(-x, 1) && sql(y, 1) && sql(-y, 1)
      && sql(z, 1) && sql(-z, 1) && sql(w, 1) && sql(-w, 1)
      ==> -1 <= x <= 1 && -1 <= y <= 1 && -1 <= z <= 1 && -1 <= w <= 1;
    lemma unit_comp: \forall real x, y, z, w; unitq(x, y, z, w)
      ==> -1 <= x <= 1 && -1 <= y <= 1 && -1 <= z <= 1 && -1 <= w <= 1;

    // The arc: (l + m)^2 = 1 + 2 l m (1 - c) >= 1; (l c + m)^2 =
    // 1 - l^2 (1 - c^2) <= 1, and the mirror.
    lemma arc_quad_h: \forall real l, m, c; arc_quad(l, m, c)
      && msign(l*m, 1 - c) && sql(1, l + m) && msign(1 - c, 1 + c) && msign(l*l, (1 - c)*(1 + c))
      && msign(m*m, (1 - c)*(1 + c)) && sql(l*c + m, 1) && sql(l + m*c, 1) ==> arc_ok(l, m, c);
    lemma arc_coef: \forall real l, m, c; arc_quad(l, m, c) ==> arc_ok(l, m, c);
    lemma mul1_all: \forall real a, x; mul1(a, x);
    // proof: z3
    lemma unit_scale_h: \forall real x, y, z, w, k;
      unitq(x, y, z, w) && mul1(k*k, nrm4(x, y, z, w)) ==> sc_unit(x, y, z, w, k);
    lemma unit_scale: \forall real x, y, z, w, k; unitq(x, y, z, w) ==> sc_unit(x, y, z, w, k);
    // proof: z3
    lemma arc_exp_all: \forall real p0, p1, p2, p3, r0, r1, r2, r3, l, m;
      arc_exp(p0, p1, p2, p3, r0, r1, r2, r3, l, m);
    // |l p + m r|^2 = l^2 + m^2 + 2 l m c for unit p, r
    lemma arc_nrm_h: \forall real p0, p1, p2, p3, r0, r1, r2, r3, l, m;
      arc_pt(p0, p1, p2, p3, r0, r1, r2, r3, l, m) && arc_exp(p0, p1, p2, p3, r0, r1, r2, r3, l, m)
      && mul1(l*l, nrm4(p0, p1, p2, p3)) && mul1(m*m, nrm4(r0, r1, r2, r3))
      ==> l*l + m*m + 2*(l*m*dot4(p0, p1, p2, p3, r0, r1, r2, r3)) == 1;
    // -1 <= p.r <= 1: |p - r|^2 >= 0 and |p + r|^2 >= 0
    lemma arc_cs_h: \forall real p0, p1, p2, p3, r0, r1, r2, r3, l, m;
      arc_pt(p0, p1, p2, p3, r0, r1, r2, r3, l, m)
      && sqs2(p0 - r0, p1 - r1) && sqs2(p2 - r2, p3 - r3) && sqs2(p0 + r0, p1 + r1) && sqs2(p2 + r2, p3 + r3)
      ==> -1 <= dot4(p0, p1, p2, p3, r0, r1, r2, r3) <= 1;
    lemma arc_pt_ok: \forall real p0, p1, p2, p3, r0, r1, r2, r3, l, m;
      arc_pt(p0, p1, p2, p3, r0, r1, r2, r3, l, m) ==> arc_ok(l, m, dot4(p0, p1, p2, p3, r0, r1, r2, r3));
    // (1 - c) (l p + m r - b) = (1 - l c - m) (p - b) + (1 - l - m c) (r - b)
    //   + (l + m - 1) (p + r - (1 + c) b), each product >= 0; at c = 1,
    //   l + m = 1
    lemma arc_div_all: \forall real c, x; arc_div(c, x);
    lemma arc_lo_h: \forall real l, m, c, p, r, b;
      arc_below(l, m, c, p, r, b)
      && msign(1 - l*c - m, p - b) && msign(1 - l - m*c, r - b) && msign(l + m - 1, p + r - (1 + c)*b)
      && arc_div(c, l*p + m*r - b) && msign(l, p - b) && msign(m, r - b) ==> b <= l*p + m*r;
    lemma arc_lo: \forall real l, m, c, p, r, b; arc_below(l, m, c, p, r, b) ==> b <= l*p + m*r;
    lemma arc_hi: \forall real l, m, c, p, r, b; arc_below(l, m, c, -p, -r, -b) ==> l*p + m*r <= b;
*/
#endif

#endif /* CBX_QUAT_LOGIC_H */
