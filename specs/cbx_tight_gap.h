/*
 * ACSL logic of the tight mode's accuracy promise (include/certbox.h,
 * cbx_transform_box_tight; proven in src/f64/cbx_tight.c): where every
 * product of a row is zero or a normal double's size, each end is within
 * twice the compensated dot product's error of the exact end: 2^-50 |E| +
 * 2^-96 S + 2^-1050, E the exact end, S the row's magnitude (row_mag).
 * That is about 4 units in the last place of E when the row does not
 * cancel, and 2^-96 S when it does (cbx_transform_box promises 12 u S).
 * binary64 only, as the tight mode.
 */
#ifndef CBX_TIGHT_GAP_H
#define CBX_TIGHT_GAP_H

/*@ // One product of the tight mode's range: zero, or of magnitude in
    // [2^-967, 2^1013] (two_prod splits it exactly; room for its rounding).
    predicate tprod(real m, real x) = (m != 0 && x != 0) ==> (0x1p-967 <= \abs(m*x) && \abs(m*x) <= 0x1p1013);

    // The distance allowed between an end and the exact end e, on a row
    // of magnitude s.
    logic real tgap(real e, real s) = 0x1p-50 * \abs(e) + 0x1p-96 * s + 0x1p-1050;

    // A row in the tight mode's range: every product at the box's ends,
    // and the translation below 2^1015.
    predicate trow_dom(real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      tprod(m0, l0) && tprod(m0, h0) && tprod(m1, l1) && tprod(m1, h1)
      && tprod(m2, l2) && tprod(m2, h2) && -0x1p1015 <= t <= 0x1p1015;

    // Both ends of an axis within tgap of the exact ends.
    predicate trow_near(real lo, real hi, real m0, real m1, real m2, real t,
                        real l0, real h0, real l1, real h1, real l2, real h2) =
      row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
        - tgap(row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2),
               row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) <= lo
      && hi <= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
        + tgap(row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2),
               row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2));
*/

/* The promise on the three axes of *out, for a map and box of the fast
 * range (map_fast, box_fast) whose row is in the tight mode's range. */
#define CBX_TIGHT_NEAR(a, in, out) \
    ensures near0: \at(map_fast(a) && box_fast(in), Pre) && trow_dom(CBX_ROWV(a, 0, Pre), CBX_BV(in, Pre)) \
            ==> trow_near(out->lo[0], out->hi[0], CBX_ROWV(a, 0, Pre), CBX_BV(in, Pre)); \
    ensures near1: \at(map_fast(a) && box_fast(in), Pre) && trow_dom(CBX_ROWV(a, 1, Pre), CBX_BV(in, Pre)) \
            ==> trow_near(out->lo[1], out->hi[1], CBX_ROWV(a, 1, Pre), CBX_BV(in, Pre)); \
    ensures near2: \at(map_fast(a) && box_fast(in), Pre) && trow_dom(CBX_ROWV(a, 2, Pre), CBX_BV(in, Pre)) \
            ==> trow_near(out->lo[2], out->hi[2], CBX_ROWV(a, 2, Pre), CBX_BV(in, Pre));

#endif /* CBX_TIGHT_GAP_H */
