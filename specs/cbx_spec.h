/*
 * ACSL logic of certbox, per floating-point format: every promise the
 * contracts make is built from the definitions here and from the
 * format-independent ones of specs/cbx_logic.h and specs/cbx_ball.h.
 * Read by Frama-C only: certbox.h includes this file once per format
 * (between cbx_prec_begin.h and cbx_prec_end.h), so that cbx_fp is double
 * or float and every CBX_ constant is that format's (include/cbx_prec_begin.h;
 * in binary64: u = 2^-53, eta = 2^-1074, CBX_RT = 2^1018; in binary32:
 * u = 2^-24, eta = 2^-149, CBX_RT = 2^122).  The binary32 instance's names
 * end in _f (has_nan_f, ...).  The comments give the binary64 values.
 *
 * Arithmetic in these definitions is exact real arithmetic on the values of
 * the C variables: `m*l` is the exact product, not the rounded one.
 */

/* Helpers for the list of magnitude classes (include/cbx_prec_begin.h). */
#define CBX_CLS_P(tag, bm, bc) cls(m, c, bm, bc)
#define CBX_CLS_OR(tag, bm, bc) || cls(m, c, bm, bc)
#define CBX_CLS_LEMMA(tag, bm, bc) \
  lemma cls_##tag: \forall real m, c; cls(m, c, bm, bc) ==> in_dom(m, c);

/*@ // ---------------------------------------------------------------------
    // The proven domain of one product m*c: |m*c| <= 2^1018 (binary64;
    // CBX_RT in general: 2^122 in binary32).  A named
    // predicate (not an inline formula) so that the lemmas below have a
    // trigger: the provers instantiate them wherever in_dom(x, y) occurs.
    // ---------------------------------------------------------------------
    predicate in_dom(real x, real y) = -CBX_RT <= x*y <= CBX_RT;


    // The domain of a product, checked at run time by cbx_dom_pair():
    // one of 18 magnitude classes (binary64: |m| <= 2^k, |c| <= 2^(1018-k)
    // for k = 509, 0, 64, ..., 960, 1018; binary32: 2^k, 2^(122-k) for
    // k = 61, 0, 8, ..., 120, 122).
    predicate dom_pair(real m, real c) =
      CBX_CLASS_HEAD(CBX_CLS_P) CBX_CLASS_TAIL(CBX_CLS_OR);

    // Nonlinear facts, proven once over the reals (no floats in context):
    // cls_<tag>: cls(m, c, bm, bc) ==> in_dom(m, c), one per class.
    CBX_CLASS_HEAD(CBX_CLS_LEMMA) CBX_CLASS_TAIL(CBX_CLS_LEMMA)

    lemma dom_pair_in_dom: \forall real m, c; dom_pair(m, c) ==> in_dom(m, c);

    // Tightness: at most 12 u S + 2^-1065 below (above) the exact bound.
    predicate lo_tight(real r, real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      r >= row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           - (CBX_U12 * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + CBX_ETA512);
    predicate hi_tight(real r, real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      r <= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           + (CBX_U12 * row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) + CBX_ETA512);

    // The inputs of one output row are in the proven domain.
    predicate row_in_dom(real m0, real m1, real m2, real t,
                         real l0, real h0, real l1, real h1, real l2, real h2) =
      dom_pair(m0, l0) && dom_pair(m0, h0) && dom_pair(m1, l1) && dom_pair(m1, h1)
      && dom_pair(m2, l2) && dom_pair(m2, h2) && -CBX_RT <= t <= CBX_RT;
*/

/*@ // ---------------------------------------------------------------------
    // Half-spaces and out-of-domain boxes: each end of an axis on its own.
    // A box whose ends may be infinite is the real set
    //   { p : lo_j <= p_j <= hi_j where that end is finite };
    // (lo = +inf or hi = -inf is an empty box, caught before: no_point).
    // ---------------------------------------------------------------------
    predicate map_fin(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t) =
      \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t);
    predicate row_full(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                       cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      map_fin(m0, m1, m2, t)
      && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
      && \is_finite(l2) && \is_finite(h2)
      && row_in_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);

    // p is in [l, h]; an infinite end is no constraint.
    predicate ext_in(real p, cbx_fp l, cbx_fp h) =
      (\is_finite(l) ==> l <= p) && (\is_finite(h) ==> p <= h);

    // r is below (above) t + m.p for every real point p of the box.
    predicate ext_below(real r, real m0, real m1, real m2, real t,
                        cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      \forall real p0, p1, p2;
        ext_in(p0, l0, h0) && ext_in(p1, l1, h1) && ext_in(p2, l2, h2) ==>
        r <= m0*p0 + m1*p1 + m2*p2 + t;
    predicate ext_above(real r, real m0, real m1, real m2, real t,
                        cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      \forall real p0, p1, p2;
        ext_in(p0, l0, h0) && ext_in(p1, l1, h1) && ext_in(p2, l2, h2) ==>
        r >= m0*p0 + m1*p1 + m2*p2 + t;

    // m*x is unbounded below (above) on [l, h]: the end it needs is infinite.
    predicate unb_lo(real m, cbx_fp l, cbx_fp h) =
      (m > 0 && !\is_finite(l)) || (m < 0 && !\is_finite(h));
    predicate unb_hi(real m, cbx_fp l, cbx_fp h) =
      (m > 0 && !\is_finite(h)) || (m < 0 && !\is_finite(l));
    predicate row_unb_lo(real m0, real m1, real m2,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      unb_lo(m0, l0, h0) || unb_lo(m1, l1, h1) || unb_lo(m2, l2, h2);
    predicate row_unb_hi(real m0, real m1, real m2,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      unb_hi(m0, l0, h0) || unb_hi(m1, l1, h1) || unb_hi(m2, l2, h2);

    // The point box at the lower (upper) vertex is in the proven domain.
    predicate vdom_lo(real m0, real m1, real m2, real t,
                      cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      row_in_dom(m0, m1, m2, t, vlo(m0, l0, h0), vlo(m0, l0, h0), vlo(m1, l1, h1),
                 vlo(m1, l1, h1), vlo(m2, l2, h2), vlo(m2, l2, h2));
    predicate vdom_hi(real m0, real m1, real m2, real t,
                      cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      row_in_dom(m0, m1, m2, t, vhi(m0, l0, h0), vhi(m0, l0, h0), vhi(m1, l1, h1),
                 vhi(m1, l1, h1), vhi(m2, l2, h2), vhi(m2, l2, h2));

    // One end, computed from its vertex: -inf where the image is unbounded
    // below; else, in the domain, finite, below every point's image and
    // tight (12 u S + 2^-1065, S = |t| + sum_j |m_j v_j|); else -inf.
    predicate ext_lo_end(cbx_fp r, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      (row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2) ==> \is_minus_infinity(r))
      && ((!row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==>
          (\is_finite(r) && ext_below(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           && lo_tight(r, m0, m1, m2, t, vlo(m0, l0, h0), vlo(m0, l0, h0), vlo(m1, l1, h1),
                       vlo(m1, l1, h1), vlo(m2, l2, h2), vlo(m2, l2, h2))))
      && ((!row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && !vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==> \is_minus_infinity(r));
    predicate ext_hi_end(cbx_fp r, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      (row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2) ==> \is_plus_infinity(r))
      && ((!row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==>
          (\is_finite(r) && ext_above(r, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
           && hi_tight(r, m0, m1, m2, t, vhi(m0, l0, h0), vhi(m0, l0, h0), vhi(m1, l1, h1),
                       vhi(m1, l1, h1), vhi(m2, l2, h2), vhi(m2, l2, h2))))
      && ((!row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
           && !vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)) ==> \is_plus_infinity(r));

    // One column: how the code picks the vertex v where m*x is least
    // (greatest) on [l, h]: an end by the sign of m, 0 for m == 0.
    predicate sel_lo(real m, real v, cbx_fp l, cbx_fp h) =
      (m > 0 ==> v == l && \is_finite(l)) && (m < 0 ==> v == h && \is_finite(h))
      && (m == 0 ==> v == 0);
    predicate sel_hi(real m, real v, cbx_fp l, cbx_fp h) =
      (m > 0 ==> v == h && \is_finite(h)) && (m < 0 ==> v == l && \is_finite(l))
      && (m == 0 ==> v == 0);
*/

/*@ // ---------------------------------------------------------------------
    // The same notions on the public structures.
    // ---------------------------------------------------------------------
    // A NaN entry of the map, of a box, of a centre/half-size box.
    predicate aff_nan(cbx_affine *a) =
         \is_NaN(a->m[0][0]) || \is_NaN(a->m[0][1]) || \is_NaN(a->m[0][2]) || \is_NaN(a->m[0][3])
      || \is_NaN(a->m[1][0]) || \is_NaN(a->m[1][1]) || \is_NaN(a->m[1][2]) || \is_NaN(a->m[1][3])
      || \is_NaN(a->m[2][0]) || \is_NaN(a->m[2][1]) || \is_NaN(a->m[2][2]) || \is_NaN(a->m[2][3]);
    predicate box_nan(cbx_box *b) =
      \is_NaN(b->lo[0]) || \is_NaN(b->lo[1]) || \is_NaN(b->lo[2])
      || \is_NaN(b->hi[0]) || \is_NaN(b->hi[1]) || \is_NaN(b->hi[2]);
    predicate cbox_nan(cbx_cbox *b) =
      \is_NaN(b->c[0]) || \is_NaN(b->c[1]) || \is_NaN(b->c[2])
      || \is_NaN(b->h[0]) || \is_NaN(b->h[1]) || \is_NaN(b->h[2]);
    predicate has_nan(cbx_affine *a, cbx_box *b) = aff_nan(a) || box_nan(b);

    // No real point on axis j: hi < lo (IEEE comparison), or lo = +inf,
    // or hi = -inf (the set { x real : +inf <= x } is empty).
    predicate no_point(cbx_fp l, cbx_fp h) =
      CBX_LT(h, l) || \is_plus_infinity(l) || \is_minus_infinity(h);
    predicate is_empty(cbx_box *b) =
      no_point(b->lo[0], b->hi[0]) || no_point(b->lo[1], b->hi[1])
      || no_point(b->lo[2], b->hi[2]);

    predicate whole_axis(cbx_box *o, integer i) =
      \is_minus_infinity(o->lo[i]) && \is_plus_infinity(o->hi[i]);
    predicate whole_space(cbx_box *o) =
      whole_axis(o, 0) && whole_axis(o, 1) && whole_axis(o, 2);
    predicate empty_out(cbx_box *o) =
         \is_plus_infinity(o->lo[0]) && \is_minus_infinity(o->hi[0])
      && \is_plus_infinity(o->lo[1]) && \is_minus_infinity(o->hi[1])
      && \is_plus_infinity(o->lo[2]) && \is_minus_infinity(o->hi[2]);

    // All inputs of row i are finite and in the proven domain.
    predicate row_dom(cbx_affine *a, cbx_box *b, integer i) =
      \is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
      && \is_finite(a->m[i][3])
      && \is_finite(b->lo[0]) && \is_finite(b->hi[0]) && \is_finite(b->lo[1])
      && \is_finite(b->hi[1]) && \is_finite(b->lo[2]) && \is_finite(b->hi[2])
      && row_in_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                    b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);

    // Axis i of o is finite, contains the image of the 8 corners, and is tight.
    predicate axis_proven(cbx_affine *a, cbx_box *b, cbx_box *o, integer i) =
      \is_finite(o->lo[i]) && \is_finite(o->hi[i])
      && below8(o->lo[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      && above8(o->hi[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      && lo_tight(o->lo[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                  b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2])
      && hi_tight(o->hi[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                  b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);

    // What the function promises on one axis, on the values themselves.
    //  full row (every input finite, in the domain): Arvo's kernel, the
    //    8-corner statement and the tightness bound;
    //  otherwise, finite map row: each end on its own (ext_lo_end,
    //    ext_hi_end): infinite box ends are half-spaces, a zero
    //    coefficient contributes nothing (0 * inf = 0);
    //  an infinite map entry: the whole line [-inf, +inf].
    predicate axis_sound_s(cbx_fp lo, cbx_fp hi, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                           cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      (row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==>
         (\is_finite(lo) && \is_finite(hi)
          && below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)))
      && ((!row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) && map_fin(m0, m1, m2, t)) ==>
         (ext_lo_end(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
          && ext_hi_end(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)))
      && (!map_fin(m0, m1, m2, t) ==>
         (\is_minus_infinity(lo) && \is_plus_infinity(hi)));

    // The axis is computed without loss: every finite end is proven and
    // every infinite end is one where the exact image is unbounded.
    predicate axis_ok_s(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                        cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
      || (map_fin(m0, m1, m2, t)
          && (row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
              || vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2))
          && (row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
              || vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)));

    // The fast range, checked once per map and once per box: every linear
    // entry and every box end at most CBX_SB (2^509; binary32 2^61) in
    // magnitude, every box axis ordered, every translation at most CBX_RT.
    // Every pair then lies in the first magnitude class: the row is full.
    // map_fast_v is the check on the twelve values (the batch loop carries
    // it on the values read at entry, which no write to out can change);
    // map_fast is map_fast_v of the map's entries.
    predicate map_fast_v(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13,
                         cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23) =
         -CBX_SB <= a00 <= CBX_SB && -CBX_SB <= a01 <= CBX_SB && -CBX_SB <= a02 <= CBX_SB && -CBX_RT <= a03 <= CBX_RT
      && -CBX_SB <= a10 <= CBX_SB && -CBX_SB <= a11 <= CBX_SB && -CBX_SB <= a12 <= CBX_SB && -CBX_RT <= a13 <= CBX_RT
      && -CBX_SB <= a20 <= CBX_SB && -CBX_SB <= a21 <= CBX_SB && -CBX_SB <= a22 <= CBX_SB && -CBX_RT <= a23 <= CBX_RT
      && \is_finite(a00) && \is_finite(a01) && \is_finite(a02) && \is_finite(a03)
      && \is_finite(a10) && \is_finite(a11) && \is_finite(a12) && \is_finite(a13)
      && \is_finite(a20) && \is_finite(a21) && \is_finite(a22) && \is_finite(a23);
    predicate map_fast{L}(cbx_affine *a) = map_fast_v(CBX_AV(a, L));
    predicate box_fast(cbx_box *b) =
         -CBX_SB <= b->lo[0] && b->lo[0] <= b->hi[0] && b->hi[0] <= CBX_SB
      && -CBX_SB <= b->lo[1] && b->lo[1] <= b->hi[1] && b->hi[1] <= CBX_SB
      && -CBX_SB <= b->lo[2] && b->lo[2] <= b->hi[2] && b->hi[2] <= CBX_SB
      && \is_finite(b->lo[0]) && \is_finite(b->hi[0]) && \is_finite(b->lo[1])
      && \is_finite(b->hi[1]) && \is_finite(b->lo[2]) && \is_finite(b->hi[2]);

    // A prepared map: its fast flag is set only if its map is in the fast
    // range (the class is checked where it is used).
    predicate prepared(cbx_prepared *p) = p->fast != 0 ==> map_fast(&p->a);

    // Axis i is computed without loss (status CBX_OK): see axis_ok_s.
    predicate row_ok(cbx_affine *a, cbx_box *b, integer i) =
      axis_ok_s(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->lo[0], b->hi[0], b->lo[1], b->hi[1], b->lo[2], b->hi[2]);

    // ---- one box's whole promise on values, for the batch form -------
    // Inputs: the 12 map entries a_ij, the box l_j, h_j; output: o_i, p_i
    // (lo, hi of axis i).  The same cases as cbx_transform_box's behaviors.
    predicate nan_v(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13, cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23,
                    cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
         \is_NaN(a00) || \is_NaN(a01) || \is_NaN(a02) || \is_NaN(a03)
      || \is_NaN(a10) || \is_NaN(a11) || \is_NaN(a12) || \is_NaN(a13)
      || \is_NaN(a20) || \is_NaN(a21) || \is_NaN(a22) || \is_NaN(a23)
      || \is_NaN(l0) || \is_NaN(l1) || \is_NaN(l2) || \is_NaN(h0) || \is_NaN(h1) || \is_NaN(h2);
    predicate empty_v(cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      no_point(l0, h0) || no_point(l1, h1) || no_point(l2, h2);
    predicate ok_v(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13, cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23,
                   cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2) =
      axis_ok_s(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
      && axis_ok_s(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
      && axis_ok_s(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    predicate box_done_v(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13, cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                         cbx_fp o0, cbx_fp p0, cbx_fp o1, cbx_fp p1, cbx_fp o2, cbx_fp p2) =
      (nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) ==>
         (\is_minus_infinity(o0) && \is_plus_infinity(p0) && \is_minus_infinity(o1)
          && \is_plus_infinity(p1) && \is_minus_infinity(o2) && \is_plus_infinity(p2)))
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && empty_v(l0, h0, l1, h1, l2, h2)) ==>
         (\is_plus_infinity(o0) && \is_minus_infinity(p0) && \is_plus_infinity(o1)
          && \is_minus_infinity(p1) && \is_plus_infinity(o2) && \is_minus_infinity(p2)))
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2)) ==>
         (axis_sound_s(o0, p0, a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(o1, p1, a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(o2, p2, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)));

    // k is the severity of the status cbx_transform_box returns.
    predicate box_sev_v(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13, cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23,
                        cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2, integer k) =
      (nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && k == 3)
      || (!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && empty_v(l0, h0, l1, h1, l2, h2) && k == 1)
      || (!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2) && ok_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && k == 0)
      || (!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2) && !ok_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && k == 2);

    // The severity of the status for this box is at most w.  (Stated without
    // a quantifier over severities: a global lemma "box_sev_v is a
    // function" made the provers time out on unrelated lemmas.)
    predicate box_sev_le(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13, cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2, integer w) =
      0 <= w
      && (nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) ==> 3 <= w)
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && empty_v(l0, h0, l1, h1, l2, h2)) ==> 1 <= w)
      && ((!nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) && !empty_v(l0, h0, l1, h1, l2, h2) && !ok_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)) ==> 2 <= w);

    // The same with the output box as one struct value: the batch loop's
    // invariant then frames (a write of out[k] leaves the value out[j]
    // unchanged) where six separate fields did not.
    predicate box_done_m(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13, cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2, cbx_box O) =
      box_done_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2,
                 O.lo[0], O.hi[0], O.lo[1], O.hi[1], O.lo[2], O.hi[2]);
*/

/*@ // ---------------------------------------------------------------------
    // Center/half-diagonal form (the real definitions: specs/cbx_logic.h).
    // Tightness: each end within 12 u S + 2^-1065 of the exact end.
    // ---------------------------------------------------------------------
    predicate cbox_tight(real oc, real oh, real m0, real m1, real m2, real t,
                         real c0, real c1, real c2, real h0, real h1, real h2) =
      oc - oh >= crow_c(m0, m1, m2, t, c0, c1, c2) - crow_h(m0, m1, m2, h0, h1, h2)
                 - (CBX_U12 * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) + CBX_ETA512)
      && oc + oh <= crow_c(m0, m1, m2, t, c0, c1, c2) + crow_h(m0, m1, m2, h0, h1, h2)
                 + (CBX_U12 * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) + CBX_ETA512);

    predicate crow_in_dom(real m0, real m1, real m2, real t,
                          real c0, real c1, real c2, real h0, real h1, real h2) =
      dom_pair(m0, c0) && dom_pair(m0, h0) && dom_pair(m1, c1) && dom_pair(m1, h1)
      && dom_pair(m2, c2) && dom_pair(m2, h2) && -CBX_RT <= t <= CBX_RT;
*/

/*@ predicate cbox_has_nan(cbx_affine *a, cbx_cbox *b) = aff_nan(a) || cbox_nan(b);
    // h < 0 on some axis (IEEE comparison; -0 is not negative)
    predicate cbox_empty(cbx_cbox *b) =
      CBX_LT(b->h[0], (cbx_fp)0.0) || CBX_LT(b->h[1], (cbx_fp)0.0)
      || CBX_LT(b->h[2], (cbx_fp)0.0);
    predicate cwhole_axis(cbx_cbox *o, integer i) =
      o->c[i] == 0 && \is_plus_infinity(o->h[i]);
    predicate cwhole(cbx_cbox *o) = cwhole_axis(o, 0) && cwhole_axis(o, 1) && cwhole_axis(o, 2);
    predicate cempty(cbx_cbox *o) =
         o->c[0] == 0 && \is_minus_infinity(o->h[0]) && o->c[1] == 0 && \is_minus_infinity(o->h[1])
      && o->c[2] == 0 && \is_minus_infinity(o->h[2]);

    predicate crow_dom(cbx_affine *a, cbx_cbox *b, integer i) =
      \is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
      && \is_finite(a->m[i][3])
      && \is_finite(b->c[0]) && \is_finite(b->c[1]) && \is_finite(b->c[2])
      && \is_finite(b->h[0]) && \is_finite(b->h[1]) && \is_finite(b->h[2])
      && crow_in_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                     b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2]);

    predicate caxis_proven(cbx_affine *a, cbx_cbox *b, cbx_cbox *o, integer i) =
      \is_finite(o->c[i]) && \is_finite(o->h[i])
      && cbox_corners(o->c[i], o->h[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                      b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2])
      && cbox_tight(o->c[i], o->h[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                    b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2]);

    predicate crow_full(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                        cbx_fp c0, cbx_fp c1, cbx_fp c2, cbx_fp h0, cbx_fp h1, cbx_fp h2) =
      \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
      && \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
      && \is_finite(h0) && \is_finite(h1) && \is_finite(h2)
      && crow_in_dom(m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
    // The row with its zero-coefficient columns dropped is finite and in
    // the domain.
    predicate crow_dfull(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                         cbx_fp c0, cbx_fp c1, cbx_fp c2, cbx_fp h0, cbx_fp h1, cbx_fp h2) =
      map_fin(m0, m1, m2, t)
      && (m0 != 0 ==> \is_finite(c0) && \is_finite(h0))
      && (m1 != 0 ==> \is_finite(c1) && \is_finite(h1))
      && (m2 != 0 ==> \is_finite(c2) && \is_finite(h2))
      && crow_in_dom(m0, m1, m2, t, dz(m0, c0), dz(m1, c1), dz(m2, c2),
                     dz(m0, h0), dz(m1, h1), dz(m2, h2));

    // One axis on the values: the kernel's statement on a full row; on a
    // row that is full once its zero-coefficient columns are dropped, the
    // same statement on the dropped row; (0, +inf) otherwise.
    predicate caxis_sound_s(cbx_fp oc, cbx_fp oh, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                            cbx_fp c0, cbx_fp c1, cbx_fp c2, cbx_fp h0, cbx_fp h1, cbx_fp h2) =
      (crow_full(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) ==>
         (\is_finite(oc) && \is_finite(oh)
          && cbox_corners(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
          && cbox_tight(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2)))
      && ((!crow_full(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
           && crow_dfull(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)) ==>
         (\is_finite(oc) && \is_finite(oh)
          && cbox_corners(oc, oh, m0, m1, m2, t, dz(m0, c0), dz(m1, c1), dz(m2, c2),
                          dz(m0, h0), dz(m1, h1), dz(m2, h2))
          && cbox_tight(oc, oh, m0, m1, m2, t, dz(m0, c0), dz(m1, c1), dz(m2, c2),
                        dz(m0, h0), dz(m1, h1), dz(m2, h2))))
      && ((!crow_full(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
           && !crow_dfull(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)) ==>
         (oc == 0 && \is_plus_infinity(oh)));

    // Axis i is computed without loss (status CBX_OK).
    predicate crow_ok(cbx_affine *a, cbx_cbox *b, integer i) =
      crow_full(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2])
      || crow_dfull(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3],
                    b->c[0], b->c[1], b->c[2], b->h[0], b->h[1], b->h[2]);


    // Conversions: one axis in their domain (finite, magnitude <= 2^1019).
    predicate conv_dom(real x, real y) = -CBX_R19 <= x <= CBX_R19 && -CBX_R19 <= y <= CBX_R19;

    // Tightness of a converted end: within 16u (|x| + |y|) + 2^-1066 of the
    // exact end (binary32: 16u and 2^-141), x, y the axis' two inputs.
    logic real conv_gap(real x, real y) = CBX_U16 * (\abs(x) + \abs(y)) + CBX_ETA256;

    // One axis of a conversion, on values (the 3D and the 2D forms share
    // it): the input axis (x, y) = (lo, hi) or (c, h) in the domain (status
    // CBX_OK), and the output (p, q) = (c, h) or (lo, hi).
    predicate conv_in(cbx_fp x, cbx_fp y) = \is_finite(x) && \is_finite(y) && conv_dom(x, y);
    // box -> cbox: [c - h, c + h] contains [lo, hi], each end within
    // conv_gap; outside the domain c = 0, h = +inf (the whole line).
    predicate b2c_v(cbx_fp lo, cbx_fp hi, cbx_fp c, cbx_fp h) =
      (conv_in(lo, hi) ==>
         (\is_finite(c) && \is_finite(h) && c - h <= lo && hi <= c + h
          && lo - conv_gap(lo, hi) <= c - h && c + h <= hi + conv_gap(lo, hi)))
      && (!conv_in(lo, hi) ==> c == 0 && \is_plus_infinity(h));
    // cbox -> box: [lo, hi] contains [c - h, c + h], each end within
    // conv_gap; outside the domain [-inf, +inf].
    predicate c2b_v(cbx_fp c, cbx_fp h, cbx_fp lo, cbx_fp hi) =
      (conv_in(c, h) ==>
         (\is_finite(lo) && \is_finite(hi) && lo <= c - h && c + h <= hi
          && (c - h) - conv_gap(c, h) <= lo && hi <= (c + h) + conv_gap(c, h)))
      && (!conv_in(c, h) ==> \is_minus_infinity(lo) && \is_plus_infinity(hi));

    // Every axis of the input in the conversions' domain: status CBX_OK.
    predicate b2c_dom(cbx_box *in, integer i) = conv_in(in->lo[i], in->hi[i]);
    predicate c2b_dom(cbx_cbox *in, integer i) = conv_in(in->c[i], in->h[i]);
    predicate b2c_ok(cbx_box *in) = b2c_dom(in, 0) && b2c_dom(in, 1) && b2c_dom(in, 2);
    predicate c2b_ok(cbx_cbox *in) = c2b_dom(in, 0) && c2b_dom(in, 1) && c2b_dom(in, 2);

    predicate b2c_axis(cbx_box *in, cbx_cbox *out, integer i) =
      b2c_v(in->lo[i], in->hi[i], out->c[i], out->h[i]);
    predicate c2b_axis(cbx_cbox *in, cbx_box *out, integer i) =
      c2b_v(in->c[i], in->h[i], out->lo[i], out->hi[i]);
*/

/*@ // ---------------------------------------------------------------------
    // Spheres and ellipsoids (src/algo/cbx_sphere.c); the format-independent
    // Cauchy-Schwarz chain is specs/cbx_ball.h.
    // (The lemmas, scaling by 2^600 and the ellipsoid's domain: below.)
    // ---------------------------------------------------------------------
    // |x y| <= 2^508 (CBX_EP): the products of an ellipsoid's rows.
    predicate in_dom508(real x, real y) = -CBX_EP <= x*y <= CBX_EP;

    // Tightness of a ball's axis: each end within 80u (|t| + |b|) + 2^-1064
    // of the exact end t -+ |b| (binary32: 80u and 2^-139).
    logic real ball_gap(real t, real rho) = CBX_U80 * (\abs(t) + rho) + CBX_ETA1024;
    predicate ball_tight(real lo, real hi, real b0, real b1, real b2, real t) =
      (t - rnorm3(b0, b1, b2)) - ball_gap(t, rnorm3(b0, b1, b2)) <= lo
      && hi <= (t + rnorm3(b0, b1, b2)) + ball_gap(t, rnorm3(b0, b1, b2));

    predicate sph_dom(real m0, real m1, real m2, real t) =
      cls(m0, m0, CBX_SB, CBX_SB) && cls(m1, m1, CBX_SB, CBX_SB)
      && cls(m2, m2, CBX_SB, CBX_SB) && -CBX_RT <= t <= CBX_RT;

    predicate sph_axis(cbx_affine *a, cbx_box *o, integer i) =
      ((\is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
        && \is_finite(a->m[i][3]) && sph_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3])) ==>
         (\is_finite(o->lo[i]) && \is_finite(o->hi[i])
          && ball_axis(o->lo[i], o->hi[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3])
          && ball_tight(o->lo[i], o->hi[i], a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3])))
      && (!(\is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
        && \is_finite(a->m[i][3]) && sph_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3])) ==>
         whole_axis(o, i));

    predicate ell_dom(real r0, real r1, real r2, real d0, real d1, real d2, real c) =
      cls(r0, d0, CBX_EB, CBX_EB) && cls(r1, d1, CBX_EB, CBX_EB)
      && cls(r2, d2, CBX_EB, CBX_EB) && -CBX_RT <= c <= CBX_RT;
*/

/* The sphere's lemmas, with specs/cbx_ball.h's (CBX_BALL_LEMMAS: the proof
 * jobs of src/algo/cbx_sphere.c and the lemma jobs only). */
#ifdef CBX_BALL_LEMMAS
/*@ // Scaling a row by 2^600 scales its norm by 2^600 (row_radius; CBX_SUP,
    // 2^90 in binary32).
    lemma sq_bound_scale: \forall real b0, b1, b2, r;
      sq_bound(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP, r) ==> sq_bound(b0, b1, b2, r*CBX_SDN);
    // The ellipsoid's classes keep its rows' products within 2^508.
    lemma cls_254: \forall real m, c; cls(m, c, CBX_EB, CBX_EB) ==> in_dom508(m, c);
*/
#endif

/*@ predicate ell_nan(cbx_fp *center, cbx_fp *radii, cbx_fp (*rot)[3]) =
         \is_NaN(center[0]) || \is_NaN(center[1]) || \is_NaN(center[2])
      || \is_NaN(radii[0]) || \is_NaN(radii[1]) || \is_NaN(radii[2])
      || \is_NaN(rot[0][0]) || \is_NaN(rot[0][1]) || \is_NaN(rot[0][2])
      || \is_NaN(rot[1][0]) || \is_NaN(rot[1][1]) || \is_NaN(rot[1][2])
      || \is_NaN(rot[2][0]) || \is_NaN(rot[2][1]) || \is_NaN(rot[2][2]);

    predicate ell_row_dom(cbx_fp *center, cbx_fp *radii, cbx_fp (*rot)[3], integer i) =
      \is_finite(rot[i][0]) && \is_finite(rot[i][1]) && \is_finite(rot[i][2])
      && \is_finite(radii[0]) && \is_finite(radii[1]) && \is_finite(radii[2])
      && \is_finite(center[i])
      && ell_dom(rot[i][0], rot[i][1], rot[i][2], radii[0], radii[1], radii[2], center[i]);

    // Axis i of o bounds center_i + sum_j rot_ij radii_j p_j over the unit ball.
    predicate ell_axis(cbx_fp *center, cbx_fp *radii, cbx_fp (*rot)[3], cbx_box *o, integer i) =
      (ell_row_dom(center, radii, rot, i) ==>
         (\is_finite(o->lo[i]) && \is_finite(o->hi[i])
          && ball_axis(o->lo[i], o->hi[i], rot[i][0]*radii[0], rot[i][1]*radii[1],
                       rot[i][2]*radii[2], center[i])
          && ball_tight(o->lo[i], o->hi[i], rot[i][0]*radii[0], rot[i][1]*radii[1],
                        rot[i][2]*radii[2], center[i])))
      && (!ell_row_dom(center, radii, rot, i) ==> whole_axis(o, i));

    predicate sph_row_dom(cbx_affine *a, integer i) =
      \is_finite(a->m[i][0]) && \is_finite(a->m[i][1]) && \is_finite(a->m[i][2])
      && \is_finite(a->m[i][3]) && sph_dom(a->m[i][0], a->m[i][1], a->m[i][2], a->m[i][3]);
*/
