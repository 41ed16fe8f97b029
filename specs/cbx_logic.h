/*
 * ACSL logic of certbox that does not depend on the floating-point format:
 * real-valued definitions and lemmas over the reals, shared by the binary64
 * and binary32 families (each family's own logic, with its domain and
 * tightness constants, is specs/cbx_spec.h, instantiated once per family).
 * Read by Frama-C only; certbox.h includes this file once.
 *
 * Arithmetic in these definitions is exact real arithmetic: `m*l` is the
 * exact product, not the rounded one.
 */
#ifndef CBX_LOGIC_H
#define CBX_LOGIC_H

/*@ // ---------------------------------------------------------------------
    // One magnitude class: |m| <= bm and |c| <= bc (specs/cbx_spec.h lists
    // the classes of each format's domain).
    // ---------------------------------------------------------------------
    predicate cls(real m, real c, real bm, real bc) =
      -bm <= m <= bm && -bc <= c <= bc;

    // ---------------------------------------------------------------------
    // One term of Arvo's sum: m*c for c in {l, h}.
    // ---------------------------------------------------------------------
    logic real tmin(real m, real l, real h) = \min(m*l, m*h);
    logic real tmax(real m, real l, real h) = \max(m*l, m*h);
    logic real tmag(real m, real l, real h) = \max(\abs(m*l), \abs(m*h));
    // The term of one end: the smaller (up == 0, lower end) or the larger
    // (up != 0, upper end); one error chain serves both ends.
    logic real tsel(integer up, real m, real l, real h) =
      up != 0 ? tmax(m, l, h) : tmin(m, l, h);

    // Exact bounds of one output coordinate over the box, and its scale
    // S = |t| + sum_j |m_j| max(|l_j|, |h_j|) used by the tightness bound.
    logic real row_lo(real m0, real m1, real m2, real t,
                      real l0, real h0, real l1, real h1, real l2, real h2) =
      t + tmin(m0, l0, h0) + tmin(m1, l1, h1) + tmin(m2, l2, h2);
    logic real row_hi(real m0, real m1, real m2, real t,
                      real l0, real h0, real l1, real h1, real l2, real h2) =
      t + tmax(m0, l0, h0) + tmax(m1, l1, h1) + tmax(m2, l2, h2);
    lemma tmin_mag: \forall real m, l, h; -tmag(m, l, h) <= tmin(m, l, h) <= tmag(m, l, h);
    lemma tmax_mag: \forall real m, l, h; -tmag(m, l, h) <= tmax(m, l, h) <= tmag(m, l, h);
    lemma tsel_mag: \forall integer up, real m, l, h;
      -tmag(m, l, h) <= tsel(up, m, l, h) <= tmag(m, l, h);
    logic real row_sel(integer up, real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      t + tsel(up, m0, l0, h0) + tsel(up, m1, l1, h1) + tsel(up, m2, l2, h2);
    logic real row_mag(real m0, real m1, real m2, real t,
                       real l0, real h0, real l1, real h1, real l2, real h2) =
      \abs(t) + tmag(m0, l0, h0) + tmag(m1, l1, h1) + tmag(m2, l2, h2);

    lemma row_lo_mag: \forall real m0, m1, m2, t, l0, h0, l1, h1, l2, h2;
      -row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) <= row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
      <= row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    lemma row_hi_mag: \forall real m0, m1, m2, t, l0, h0, l1, h1, l2, h2;
      -row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) <= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
      <= row_mag(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    // The end of one row chosen by up: the lower (0) or the upper one.
    lemma row_sel_lo: \forall real m0, m1, m2, t, l0, h0, l1, h1, l2, h2;
      row_sel(0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) == row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    lemma row_sel_hi: \forall real m0, m1, m2, t, l0, h0, l1, h1, l2, h2;
      row_sel(1, m0, m1, m2, t, l0, h0, l1, h1, l2, h2) == row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);

    // r is below the image of all 8 corners (c_j in {l_j, h_j}).
    predicate below8(real r, real m0, real m1, real m2, real t,
                     real l0, real h0, real l1, real h1, real l2, real h2) =
         r <= m0*l0 + m1*l1 + m2*l2 + t && r <= m0*l0 + m1*l1 + m2*h2 + t
      && r <= m0*l0 + m1*h1 + m2*l2 + t && r <= m0*l0 + m1*h1 + m2*h2 + t
      && r <= m0*h0 + m1*l1 + m2*l2 + t && r <= m0*h0 + m1*l1 + m2*h2 + t
      && r <= m0*h0 + m1*h1 + m2*l2 + t && r <= m0*h0 + m1*h1 + m2*h2 + t;
    // r is above the image of all 8 corners.
    predicate above8(real r, real m0, real m1, real m2, real t,
                     real l0, real h0, real l1, real h1, real l2, real h2) =
         r >= m0*l0 + m1*l1 + m2*l2 + t && r >= m0*l0 + m1*l1 + m2*h2 + t
      && r >= m0*l0 + m1*h1 + m2*l2 + t && r >= m0*l0 + m1*h1 + m2*h2 + t
      && r >= m0*h0 + m1*l1 + m2*l2 + t && r >= m0*h0 + m1*l1 + m2*h2 + t
      && r >= m0*h0 + m1*h1 + m2*l2 + t && r >= m0*h0 + m1*h1 + m2*h2 + t;


    // Sums of per-column facts, over the reals (products are atoms).
    lemma ext_sum_lo: \forall real r, m0, m1, m2, t, v0, v1, v2, p0, p1, p2;
      r <= m0*v0 + m1*v1 + m2*v2 + t ==>
      m0*v0 <= m0*p0 ==> m1*v1 <= m1*p1 ==> m2*v2 <= m2*p2 ==>
      r <= m0*p0 + m1*p1 + m2*p2 + t;
    lemma ext_sum_hi: \forall real r, m0, m1, m2, t, v0, v1, v2, p0, p1, p2;
      r >= m0*v0 + m1*v1 + m2*v2 + t ==>
      m0*v0 >= m0*p0 ==> m1*v1 >= m1*p1 ==> m2*v2 >= m2*p2 ==>
      r >= m0*p0 + m1*p1 + m2*p2 + t;
    // The one nonlinear fact of the half-space proof, with a product as
    // its trigger (the lemma functions of src/algo/cbx_vertex.h use it; a named
    // predicate, so that WP's simplifier leaves the product as it is and
    // the lemma has a trigger).
    predicate nn_prod(real a, real b) = 0 <= a*b;
    lemma mul_nonneg: \forall real a, b; 0 <= a ==> 0 <= b ==> nn_prod(a, b);
    // The vertex of [l, h] where m*x is least (vlo) or greatest (vhi):
    // an end chosen by the sign of m; 0 when m == 0 (0 * inf = 0).
    logic real vlo(real m, real l, real h) = m > 0 ? l : (m < 0 ? h : 0);
    logic real vhi(real m, real l, real h) = m > 0 ? h : (m < 0 ? l : 0);

    // Severity of a status, for "the most severe status met":
    // CBX_OK 0 < CBX_EMPTY 1 < CBX_ERANGE 2 < CBX_EINVAL 3.
    logic integer sev(integer s) =
      s == CBX_EINVAL ? 3 : (s == CBX_ERANGE ? 2 : (s == CBX_EMPTY ? 1 : 0));

    // ---------------------------------------------------------------------
    // Center/half-diagonal form: the real box [oc - oh, oc + oh] of one
    // output axis and the input box [c_j - h_j, c_j + h_j].
    // ---------------------------------------------------------------------
    logic real crow_c(real m0, real m1, real m2, real t, real c0, real c1, real c2) =
      m0*c0 + m1*c1 + m2*c2 + t;
    logic real crow_h(real m0, real m1, real m2, real h0, real h1, real h2) =
      \abs(m0*h0) + \abs(m1*h1) + \abs(m2*h2);
    logic real crow_mag(real m0, real m1, real m2, real t, real c0, real c1, real c2,
                        real h0, real h1, real h2) =
      \abs(t) + \abs(m0*c0) + \abs(m1*c1) + \abs(m2*c2) + crow_h(m0, m1, m2, h0, h1, h2);

    // |exact center - oc| + exact half <= oh: [oc-oh, oc+oh] holds the image.
    predicate cbox_core(real oc, real oh, real m0, real m1, real m2, real t,
                        real c0, real c1, real c2, real h0, real h1, real h2) =
      \abs(crow_c(m0, m1, m2, t, c0, c1, c2) - oc) + crow_h(m0, m1, m2, h0, h1, h2) <= oh;

    // The same, stated on the 8 corners c_j -+ h_j.
    predicate cbox_corners(real oc, real oh, real m0, real m1, real m2, real t,
                           real c0, real c1, real c2, real h0, real h1, real h2) =
      below8(oc - oh, m0, m1, m2, t, c0 - h0, c0 + h0, c1 - h1, c1 + h1, c2 - h2, c2 + h2)
      && above8(oc + oh, m0, m1, m2, t, c0 - h0, c0 + h0, c1 - h1, c1 + h1, c2 - h2, c2 + h2);

    lemma cbox_core_corners:
      \forall real oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2;
        cbox_core(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2) ==>
        cbox_corners(oc, oh, m0, m1, m2, t, c0, c1, c2, h0, h1, h2);

    // A column whose coefficient is 0 is dropped from a row (0 * inf = 0):
    // its center and half-width count as 0, whatever they are.
    logic real dz(real m, real x) = m == 0 ? 0 : x;
*/

/* Argument lists of the value predicates of specs/cbx_spec.h, read at
 * label L (the 12 map entries; the 6 box ends). */
#define CBX_AV(a, L) \
  \at((a)->m[0][0], L), \at((a)->m[0][1], L), \at((a)->m[0][2], L), \at((a)->m[0][3], L), \
  \at((a)->m[1][0], L), \at((a)->m[1][1], L), \at((a)->m[1][2], L), \at((a)->m[1][3], L), \
  \at((a)->m[2][0], L), \at((a)->m[2][1], L), \at((a)->m[2][2], L), \at((a)->m[2][3], L)
#define CBX_BV(b, L) \
  \at((b)->lo[0], L), \at((b)->hi[0], L), \at((b)->lo[1], L), \at((b)->hi[1], L), \
  \at((b)->lo[2], L), \at((b)->hi[2], L)

/* Row i of *a at label L, as the four values (m_i0, m_i1, m_i2, t_i). */
#define CBX_ROWV(a, i, L) \
  \at((a)->m[i][0], L), \at((a)->m[i][1], L), \at((a)->m[i][2], L), \at((a)->m[i][3], L)

/* What a class kernel's fast path promises: cbx_transform_box's box_input
 * case, on values read at Pre, and that the input is that case. */
#define CBX_FAST_POST(a, in, out) \
    ensures ok: \result == CBX_OK; \
    ensures case: \at(!has_nan(a, in) && !is_empty(in), Pre); \
    ensures axis0: axis_sound_s(out->lo[0], out->hi[0], CBX_ROWV(a, 0, Pre), CBX_BV(in, Pre)); \
    ensures axis1: axis_sound_s(out->lo[1], out->hi[1], CBX_ROWV(a, 1, Pre), CBX_BV(in, Pre)); \
    ensures axis2: axis_sound_s(out->lo[2], out->hi[2], CBX_ROWV(a, 2, Pre), CBX_BV(in, Pre)); \
    ensures rows: \at(row_ok(a, in, 0) && row_ok(a, in, 1) && row_ok(a, in, 2), Pre);

/* cbx_transform_box's promise, written once: the behaviors of every
 * function (a, in, out) that returns one box of the map *a (in
 * include/: cbx_transform_box, cbx_transform_box_prep, the tight mode,
 * cbx_transform_box_as; in src/: the one-box helpers).  In words: NaN in
 * *a or *in -> CBX_EINVAL and the whole space; else an empty *in ->
 * CBX_EMPTY and the empty box; else every axis i satisfies axis_sound_s
 * (the exact image of every corner inside [lo_i, hi_i], each finite end
 * within the tightness bound) and the status is CBX_OK exactly when every
 * row is computed without loss (row_ok). */
#define CBX_BOX_BEHAVIORS(a, in, out) \
    behavior nan_input: \
      assumes has_nan(a, in); \
      ensures \result == CBX_EINVAL; \
      ensures whole_space(out); \
    behavior empty_input: \
      assumes !has_nan(a, in) && is_empty(in); \
      ensures \result == CBX_EMPTY; \
      ensures empty_out(out); \
    behavior box_input: \
      assumes !has_nan(a, in) && !is_empty(in); \
      ensures \result == CBX_OK || \result == CBX_ERANGE; \
      ensures axis0: axis_sound_s(out->lo[0], out->hi[0], CBX_ROWV(a, 0, Pre), CBX_BV(in, Pre)); \
      ensures axis1: axis_sound_s(out->lo[1], out->hi[1], CBX_ROWV(a, 1, Pre), CBX_BV(in, Pre)); \
      ensures axis2: axis_sound_s(out->lo[2], out->hi[2], CBX_ROWV(a, 2, Pre), CBX_BV(in, Pre)); \
      ensures ok_iff: \result == CBX_OK <==> \
        \at(row_ok(a, in, 0) && row_ok(a, in, 1) && row_ok(a, in, 2), Pre); \
    complete behaviors; \
    disjoint behaviors;

/* One box of cbx_transform_box returned by value (src/algo/cbx_onebox.h):
 * its whole promise restated on the values of *a and *b at Pre. */
#define CBX_ONE_POST(a, b) \
    ensures done: box_done_m(CBX_AV(a, Pre), CBX_BV(b, Pre), \result.o); \
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(b, Pre), sev(\result.s)); \
    ensures st: \result.s == CBX_OK || \result.s == CBX_EMPTY || \result.s == CBX_ERANGE \
                || \result.s == CBX_EINVAL;

/* What the batch forms promise for the map *a: for every k < n, out[k] is
 * cbx_transform_box's output for in[k] (box_done_m), and the result is the
 * most severe status met (CBX_OK when n == 0). */
#define CBX_BATCH_POST(a) \
    ensures done: \forall integer k; 0 <= k < n ==> \
      box_done_m(CBX_AV(a, Pre), CBX_BV(in + k, Pre), out[k]); \
    ensures worst: \forall integer k; 0 <= k < n ==> \
      box_sev_le(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result)); \
    ensures met: n > 0 ==> \exists integer k; 0 <= k < n && \
      box_sev_v(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result)); \
    ensures none: n == 0 ==> \result == CBX_OK; \
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE || \result == CBX_EINVAL;

#endif /* CBX_LOGIC_H */
