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
*/
#endif

#endif /* CBX_QUAT_LOGIC_H */
