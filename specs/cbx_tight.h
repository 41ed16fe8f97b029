/*
 * ACSL logic of the tight mode (src/f64/cbx_tight.c): a vector of eight
 * doubles whose exact real sum is what the certification tracks, and the
 * range of a product split exactly that the compensated dot product
 * (dot_sum) takes: a pair hi + lo with lo at most 2^-52 |hi| (two_prod's
 * rounding error, the product being normal).
 */
#ifndef CBX_TIGHT_SPEC_H
#define CBX_TIGHT_SPEC_H

/*@ predicate vfin(cbx_vec8 z) =
      \is_finite(z.v0) && \is_finite(z.v1) && \is_finite(z.v2) && \is_finite(z.v3)
      && \is_finite(z.v4) && \is_finite(z.v5) && \is_finite(z.v6) && \is_finite(z.v7);
    logic real vsum(cbx_vec8 z) = z.v0 + z.v1 + z.v2 + z.v3 + z.v4 + z.v5 + z.v6 + z.v7;

    predicate dd_in(cbx_dd p) =
      \is_finite(p.hi) && \is_finite(p.lo)
      && -0x1.01p1015 <= p.hi <= 0x1.01p1015 && -0x1p1000 <= p.lo <= 0x1p1000
      && \abs(p.lo) <= 0x1p-52 * \abs(p.hi);

*/

#endif /* CBX_TIGHT_SPEC_H */
