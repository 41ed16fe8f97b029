/*
 * ACSL logic of interval matrices (src/f64/cbx_imat.c): an affine map whose
 * every entry is only known to lie in an interval [lo, hi], as a chain of
 * rounded transforms produces (glTF node chains, rotations built from
 * quaternions).  Read by Frama-C only; certbox.h includes it in the
 * binary64 instance (CBX_ constants of binary64).
 *
 * The real definitions (itmin, irow_lo, irow_in, ...) and their lemmas:
 * specs/cbx_imat_logic.h.
 */
#ifndef CBX_IMAT_SPEC_H
#define CBX_IMAT_SPEC_H

/*@ // Tightness: each end within 12 u S + 2^-1065 of the exact end.
    predicate irow_tight(real lo, real hi, real ml0, real mh0, real ml1, real mh1, real ml2, real mh2,
                         real tl, real th, real l0, real h0, real l1, real h1, real l2, real h2) =
      lo >= irow_lo(ml0, mh0, ml1, mh1, ml2, mh2, tl, l0, h0, l1, h1, l2, h2)
            - (CBX_U12 * irow_mag(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2)
               + CBX_ETA512)
      && hi <= irow_hi(ml0, mh0, ml1, mh1, ml2, mh2, th, l0, h0, l1, h1, l2, h2)
            + (CBX_U12 * irow_mag(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2)
               + CBX_ETA512);

    // ---------------------------------------------------------------------
    // The fast range of one coordinate: every end finite, every interval
    // ordered, linear entries and box ends at most 2^509 in magnitude, the
    // translation at most 2^1018.  Outside it the coordinate is the whole
    // line (CBX_ERANGE).
    // ---------------------------------------------------------------------
    predicate iv_fast(cbx_fp l, cbx_fp h, real b) =
      \is_finite(l) && \is_finite(h) && -b <= l && l <= h && h <= b;
    predicate irow_fast(cbx_fp ml0, cbx_fp mh0, cbx_fp ml1, cbx_fp mh1, cbx_fp ml2, cbx_fp mh2,
                        cbx_fp tl, cbx_fp th, cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1,
                        cbx_fp l2, cbx_fp h2) =
      iv_fast(ml0, mh0, CBX_SB) && iv_fast(ml1, mh1, CBX_SB) && iv_fast(ml2, mh2, CBX_SB)
      && iv_fast(tl, th, CBX_RT)
      && iv_fast(l0, h0, CBX_SB) && iv_fast(l1, h1, CBX_SB) && iv_fast(l2, h2, CBX_SB);

    // What one output coordinate [lo, hi] promises: in the fast range,
    // finite ends that contain every point of the image and are tight;
    // outside it, the whole line.
    predicate icoord(cbx_fp lo, cbx_fp hi, cbx_fp ml0, cbx_fp mh0, cbx_fp ml1, cbx_fp mh1,
                     cbx_fp ml2, cbx_fp mh2, cbx_fp tl, cbx_fp th, cbx_fp l0, cbx_fp h0,
                     cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      (irow_fast(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2) ==>
         \is_finite(lo) && \is_finite(hi)
         && irow_in(lo, hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2)
         && irow_tight(lo, hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2))
      && (!irow_fast(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2) ==>
         \is_minus_infinity(lo) && \is_plus_infinity(hi));

    // ---------------------------------------------------------------------
    // The public structure.  A bad interval matrix: a NaN end, or an
    // interval with hi < lo (no matrix at all: a caller's mistake).
    // ---------------------------------------------------------------------
    predicate iv_bad(cbx_fp l, cbx_fp h) = \is_NaN(l) || \is_NaN(h) || CBX_LT(h, l);
    predicate imat_bad_row(cbx_imat *a, integer i) =
      iv_bad(a->lo[i][0], a->hi[i][0]) || iv_bad(a->lo[i][1], a->hi[i][1])
      || iv_bad(a->lo[i][2], a->hi[i][2]) || iv_bad(a->lo[i][3], a->hi[i][3]);
    predicate imat_bad(cbx_imat *a) =
      imat_bad_row(a, 0) || imat_bad_row(a, 1) || imat_bad_row(a, 2);
    // Entry (i, j) of the composition o of a after b: row i of a applied
    // to column j of b, plus a's translation when j = 3 (else 0).  For every
    // real map A in a and B in b, (A B)_ij is such a point, so icoord says
    // o_ij contains it.
    // (o is a value, a and b pointers: a contract reads the output at
    // Post and the inputs at Pre, \let o = *out; \at(icol_s(o, a, b, j), Pre).)
    predicate ient_v(cbx_fp lo, cbx_fp hi, cbx_imat *a, cbx_imat *b, integer i, integer j) =
      icoord(lo, hi, a->lo[i][0], a->hi[i][0], a->lo[i][1], a->hi[i][1], a->lo[i][2], a->hi[i][2],
             (j == 3 ? a->lo[i][3] : (cbx_fp)0.0), (j == 3 ? a->hi[i][3] : (cbx_fp)0.0),
             b->lo[0][j], b->hi[0][j], b->lo[1][j], b->hi[1][j], b->lo[2][j], b->hi[2][j]);
    predicate ient_fast(cbx_imat *a, cbx_imat *b, integer i, integer j) =
      irow_fast(a->lo[i][0], a->hi[i][0], a->lo[i][1], a->hi[i][1], a->lo[i][2], a->hi[i][2],
                (j == 3 ? a->lo[i][3] : (cbx_fp)0.0), (j == 3 ? a->hi[i][3] : (cbx_fp)0.0),
                b->lo[0][j], b->hi[0][j], b->lo[1][j], b->hi[1][j], b->lo[2][j], b->hi[2][j]);
    // Column j of the composition o: its three entries.
    predicate icol_s(cbx_imat o, cbx_imat *a, cbx_imat *b, integer j) =
      ient_v(o.lo[0][j], o.hi[0][j], a, b, 0, j) && ient_v(o.lo[1][j], o.hi[1][j], a, b, 1, j)
      && ient_v(o.lo[2][j], o.hi[2][j], a, b, 2, j);
    predicate icol_fast(cbx_imat *a, cbx_imat *b, integer j) =
      ient_fast(a, b, 0, j) && ient_fast(a, b, 1, j) && ient_fast(a, b, 2, j);
    predicate iv_whole(cbx_fp l, cbx_fp h) = \is_minus_infinity(l) && \is_plus_infinity(h);
    predicate imat_whole_row(cbx_imat *o, integer i) =
      iv_whole(o->lo[i][0], o->hi[i][0]) && iv_whole(o->lo[i][1], o->hi[i][1])
      && iv_whole(o->lo[i][2], o->hi[i][2]) && iv_whole(o->lo[i][3], o->hi[i][3]);
    predicate imat_whole(cbx_imat *o) =
      imat_whole_row(o, 0) && imat_whole_row(o, 1) && imat_whole_row(o, 2);
*/

/* Row i of the interval matrix *a at label L, as the eight values of
 * icoord and irow_fast (ml0, mh0, ml1, mh1, ml2, mh2, tl, th). */
#define CBX_IROWV(a, i, L) \
  \at((a)->lo[i][0], L), \at((a)->hi[i][0], L), \at((a)->lo[i][1], L), \at((a)->hi[i][1], L), \
  \at((a)->lo[i][2], L), \at((a)->hi[i][2], L), \at((a)->lo[i][3], L), \at((a)->hi[i][3], L)

#endif /* CBX_IMAT_SPEC_H */
