/*
 * Transform classes: compute only what the map calls for.
 *
 * cbx_classify sorts a map into IDENTITY, TRANSLATE, SCALE, PERMUTE (each
 * row has at most one nonzero linear entry) or GENERAL.
 * cbx_transform_box_as runs, with cbx_transform_box's contract:
 *   IDENTITY   the box itself (exact);
 *   TRANSLATE  per end, t + l rounded outward (cbx_add_dn / cbx_add_up);
 *   SCALE, PERMUTE, GENERAL  cbx_transform_box (on the fast range its
 *              branch-free kernel, faster than a one-product kernel that
 *              branches on the sign of the entry).
 * The class passed is checked against the map (class_checked): a class
 * the map is not in runs cbx_transform_box.  A class kernel runs on its
 * fast range only: every box end finite, ordered and at most 2^1018 in
 * magnitude, |t| <= 2^1018, where every row is full (row_full) and the
 * general kernel would return CBX_OK.  Anything else (NaN, empty, infinite
 * ends, large magnitudes) goes to cbx_transform_box, so the statuses and
 * special outputs are the general kernel's by construction.
 * Never looser than cbx_transform_box: the identity is exact, and a
 * translation's t + l is rounded outward by a margin no larger than the
 * general kernel's widening (GMP-checked in tests/test_classes.c).
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"

typedef struct span { double lo; double hi; } span;

/* |x| <= b, and x is finite (false for NaN and infinities). */
/*@ requires \is_finite(b);
    assigns \nothing;
    ensures \result != 0 ==> \is_finite(x) && -b <= x <= b;
*/
static inline int in_rng(double x, double b)
{
    return (x >= -b) && (x <= b);
}

/* The box end pair (l, h): finite, ordered, |l|, |h| <= b. */
/*@ requires \is_finite(b);
    assigns \nothing;
    ensures \result != 0 ==> \is_finite(l) && \is_finite(h) && -b <= l <= b && -b <= h <= b && l <= h;
*/
static inline int end_pair(double l, double h, double b)
{
    return in_rng(l, b) && in_rng(h, b) && (l <= h);
}

/* The translation column: t + x over x in [l, h], outward. */
/*@ requires fin: \is_finite(t) && \is_finite(l) && \is_finite(h);
    requires rb: -0x1p1018 <= l <= 0x1p1018 && -0x1p1018 <= h <= 0x1p1018;
    requires rt: -0x1p1018 <= t <= 0x1p1018;
    requires ord: l <= h;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures ok: span_ok(\result.lo, \result.hi, 1, t, l, h);
*/
static span span_add(double t, double l, double h)
{
    span r;
    /*@ assert one: tmin(1, l, h) == l && tmax(1, l, h) == h
                    && tmag(1, l, h) == \max(\abs(l), \abs(h)); */
    r.lo = cbx_add_dn(l, t);
    r.hi = cbx_add_up(h, t);
    return r;
}

/* The identity column: [l, h] is its own image (lemma function). */
/*@ requires one: m == 1 && t == 0;
    requires fin: \is_finite(l) && \is_finite(h);
    requires ord: l <= h;
    assigns \nothing;
    ensures ok: span_ok(l, h, m, t, l, h);
*/
static void span_id(double m, double t, double l, double h)
{
    (void)m; (void)t; (void)l; (void)h;
}

/* One output axis from its one nonzero column: the kernel's statement on
 * the whole row.  Lemma functions (no code), one per column: the other two
 * columns have coefficient 0 and contribute nothing. */
/*@ requires col: m1 == 0 && m2 == 0 && span_ok(lo, hi, m0, t, l0, h0);
    assigns \nothing;
    ensures sound: below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                   && above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight: lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                   && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static void col0_sound(double lo, double hi, double m0, double m1, double m2, double t,
                       double l0, double h0, double l1, double h1, double l2, double h2)
{
    (void)lo; (void)hi; (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/*@ requires col: m0 == 0 && m2 == 0 && span_ok(lo, hi, m1, t, l1, h1);
    assigns \nothing;
    ensures sound: below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                   && above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight: lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                   && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static void col1_sound(double lo, double hi, double m0, double m1, double m2, double t,
                       double l0, double h0, double l1, double h1, double l2, double h2)
{
    (void)lo; (void)hi; (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/*@ requires col: m0 == 0 && m1 == 0 && span_ok(lo, hi, m2, t, l2, h2);
    assigns \nothing;
    ensures sound: below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                   && above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures tight: lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                   && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static void col2_sound(double lo, double hi, double m0, double m1, double m2, double t,
                       double l0, double h0, double l1, double h1, double l2, double h2)
{
    (void)lo; (void)hi; (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/* One axis of the fast path: a full row whose ends hold the kernel's
 * statement has cbx_transform_box's promise and status (lemma function). */
/*@ requires full: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires fin: \is_finite(lo) && \is_finite(hi);
    requires sound: below8(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                    && above8(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires tight: lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                    && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    assigns \nothing;
    ensures sound: axis_sound_s(lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures ok: axis_ok_s(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static void axis_full(double lo, double hi, double m0, double m1, double m2, double t,
                      double l0, double h0, double l1, double h1, double l2, double h2)
{
    (void)lo; (void)hi; (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/* The row is full: finite, and every pair in the domain (magnitude class
 * 2^509 x 2^509, or 2^0 x 2^1018 for entries 0 and 1). */
/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(l0) && \is_finite(h0)
                  && \is_finite(l1) && \is_finite(h1) && \is_finite(l2) && \is_finite(h2);
    requires rt: -0x1p1018 <= t <= 0x1p1018;
    requires dom: (-0x1p509 <= m0 <= 0x1p509 && -0x1p509 <= m1 <= 0x1p509 && -0x1p509 <= m2 <= 0x1p509
                   && -0x1p509 <= l0 <= 0x1p509 && -0x1p509 <= h0 <= 0x1p509
                   && -0x1p509 <= l1 <= 0x1p509 && -0x1p509 <= h1 <= 0x1p509
                   && -0x1p509 <= l2 <= 0x1p509 && -0x1p509 <= h2 <= 0x1p509)
               || (-1 <= m0 <= 1 && -1 <= m1 <= 1 && -1 <= m2 <= 1
                   && -0x1p1018 <= l0 <= 0x1p1018 && -0x1p1018 <= h0 <= 0x1p1018
                   && -0x1p1018 <= l1 <= 0x1p1018 && -0x1p1018 <= h1 <= 0x1p1018
                   && -0x1p1018 <= l2 <= 0x1p1018 && -0x1p1018 <= h2 <= 0x1p1018);
    assigns \nothing;
    ensures full: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static void full_row(double m0, double m1, double m2, double t,
                     double l0, double h0, double l1, double h1, double l2, double h2)
{
    (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/* The identity on a fast box: the box itself. */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    requires cls: is_identity(a);
    requires fast: fast_ends(in, 0x1p1018);
    assigns *out;
    CBX_FAST_POST(a, in, out)
*/
static cbx_status fast_identity(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    double l0 = in->lo[0];
    double l1 = in->lo[1];
    double l2 = in->lo[2];
    double h0 = in->hi[0];
    double h1 = in->hi[1];
    double h2 = in->hi[2];
    double a00 = a->m[0][0];
    double a01 = a->m[0][1];
    double a02 = a->m[0][2];
    double a03 = a->m[0][3];
    double a10 = a->m[1][0];
    double a11 = a->m[1][1];
    double a12 = a->m[1][2];
    double a13 = a->m[1][3];
    double a20 = a->m[2][0];
    double a21 = a->m[2][1];
    double a22 = a->m[2][2];
    double a23 = a->m[2][3];
    span_id(a00, a03, l0, h0);
    span_id(a11, a13, l1, h1);
    span_id(a22, a23, l2, h2);
    full_row(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    full_row(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    full_row(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    col0_sound(l0, h0, a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    col1_sound(l1, h1, a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    col2_sound(l2, h2, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    axis_full(l0, h0, a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    axis_full(l1, h1, a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    axis_full(l2, h2, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    out->lo[0] = l0; out->hi[0] = h0;
    out->lo[1] = l1; out->hi[1] = h1;
    out->lo[2] = l2; out->hi[2] = h2;
    return CBX_OK;
}

/* A translation on a fast box: six outward-rounded additions. */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    requires cls: is_translate(a);
    requires fast: fast_ends(in, 0x1p1018) && fast_tr(a);
    assigns *out;
    CBX_FAST_POST(a, in, out)
*/
static cbx_status fast_translate(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    double l0 = in->lo[0];
    double l1 = in->lo[1];
    double l2 = in->lo[2];
    double h0 = in->hi[0];
    double h1 = in->hi[1];
    double h2 = in->hi[2];
    double a00 = a->m[0][0];
    double a01 = a->m[0][1];
    double a02 = a->m[0][2];
    double a03 = a->m[0][3];
    double a10 = a->m[1][0];
    double a11 = a->m[1][1];
    double a12 = a->m[1][2];
    double a13 = a->m[1][3];
    double a20 = a->m[2][0];
    double a21 = a->m[2][1];
    double a22 = a->m[2][2];
    double a23 = a->m[2][3];
    span r0 = span_add(a03, l0, h0);
    span r1 = span_add(a13, l1, h1);
    span r2 = span_add(a23, l2, h2);
    full_row(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    full_row(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    full_row(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    col0_sound(r0.lo, r0.hi, a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    col1_sound(r1.lo, r1.hi, a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    col2_sound(r2.lo, r2.hi, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    axis_full(r0.lo, r0.hi, a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    axis_full(r1.lo, r1.hi, a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    axis_full(r2.lo, r2.hi, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    out->lo[0] = r0.lo; out->hi[0] = r0.hi;
    out->lo[1] = r1.lo; out->hi[1] = r1.hi;
    out->lo[2] = r2.lo; out->hi[2] = r2.hi;
    return CBX_OK;
}

/* The fast-range checks (comparisons are false on NaN and infinities). */
/*@ requires valid: \valid_read(in);
    requires b: \is_finite(b) && b > 0;
    assigns \nothing;
    ensures \result != 0 ==> fast_ends(in, b);
*/
static int ends_ok(const cbx_box *in, double b)
{
    return end_pair(in->lo[0], in->hi[0], b) && end_pair(in->lo[1], in->hi[1], b)
           && end_pair(in->lo[2], in->hi[2], b);
}

/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures \result != 0 ==> fast_tr(a);
*/
static int tr_ok(const cbx_affine *a)
{
    const double T = 0x1p1018;
    return in_rng(a->m[0][3], T) && in_rng(a->m[1][3], T) && in_rng(a->m[2][3], T);
}

/* The class kernels: the fast path on its range, the general kernel
 * otherwise. */
/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    requires cls: is_identity(a);
    assigns *out;
    CBX_BOX_BEHAVIORS(a, in, out)
*/
static cbx_status kern_identity(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    if (ends_ok(in, 0x1p1018) != 0) {
        return fast_identity(a, in, out);
    }
    return cbx_transform_box(a, in, out);
}

/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    requires cls: is_translate(a);
    assigns *out;
    CBX_BOX_BEHAVIORS(a, in, out)
*/
static cbx_status kern_translate(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    if (ends_ok(in, 0x1p1018) && tr_ok(a)) {
        return fast_translate(a, in, out);
    }
    return cbx_transform_box(a, in, out);
}

/* The class tests, one predicate of specs/cbx_class.h each (one call per
 * test keeps cbx_classify's goals linear). */
/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures \result != 0 <==> aff_fin(a);
*/
static int aff_all_fin(const cbx_affine *a)
{
    return cbx_fin4(a->m[0][0], a->m[0][1], a->m[0][2], a->m[0][3])
           && cbx_fin4(a->m[1][0], a->m[1][1], a->m[1][2], a->m[1][3])
           && cbx_fin4(a->m[2][0], a->m[2][1], a->m[2][2], a->m[2][3]);
}

/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures \result != 0 <==> (a->m[0][1] == 0 && a->m[0][2] == 0 && a->m[1][0] == 0
                               && a->m[1][2] == 0 && a->m[2][0] == 0 && a->m[2][1] == 0);
*/
static int off_diag_zero(const cbx_affine *a)
{
    return (a->m[0][1] == 0.0) && (a->m[0][2] == 0.0) && (a->m[1][0] == 0.0)
           && (a->m[1][2] == 0.0) && (a->m[2][0] == 0.0) && (a->m[2][1] == 0.0);
}

/*@ requires valid: \valid_read(a);
    requires i: 0 <= i <= 2;
    assigns \nothing;
    ensures \result != 0 <==> row_sparse(a, i);
*/
static int row_has_one(const cbx_affine *a, int i)
{
    double x = a->m[i][0];
    double y = a->m[i][1];
    double z = a->m[i][2];
    return ((y == 0.0) && (z == 0.0)) || ((x == 0.0) && (z == 0.0)) || ((x == 0.0) && (y == 0.0));
}

cbx_class cbx_classify(const cbx_affine *a)
{
    if (!aff_all_fin(a)) {
        return CBX_CLASS_GENERAL;
    }
    if (off_diag_zero(a) != 0) {
        if (!((a->m[0][0] == 1.0) && (a->m[1][1] == 1.0) && (a->m[2][2] == 1.0))) {
            return CBX_CLASS_SCALE;
        }
        if ((a->m[0][3] == 0.0) && (a->m[1][3] == 0.0) && (a->m[2][3] == 0.0)) {
            return CBX_CLASS_IDENTITY;
        }
        return CBX_CLASS_TRANSLATE;
    }
    if (row_has_one(a, 0) && row_has_one(a, 1) && row_has_one(a, 2)) {
        return CBX_CLASS_PERMUTE;
    }
    return CBX_CLASS_GENERAL;
}

/* 1 when x == v (v = 0 or 1; x is then finite), else 0: no branch. */
/*@ requires \is_finite(v);
    assigns \nothing;
    ensures \result == 0 || \result == 1;
    ensures \result == 1 ==> \is_finite(x) && x == v;
*/
static inline int is_val(double x, double v) { return x == v; }

/* The identity and translation classes, checked with equalities only (the
 * entries compared with 0 and 1 are then finite; a translation's t is
 * checked finite too): cheaper than cbx_classify, whose finiteness tests
 * come first. */
/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures \result != 0 ==> is_translate(a);
*/
static int translate_holds(const cbx_affine *a)
{
    int n = is_val(a->m[0][0], 1.0) + is_val(a->m[0][1], 0.0) + is_val(a->m[0][2], 0.0)
          + is_val(a->m[1][0], 0.0) + is_val(a->m[1][1], 1.0) + is_val(a->m[1][2], 0.0)
          + is_val(a->m[2][0], 0.0) + is_val(a->m[2][1], 0.0) + is_val(a->m[2][2], 1.0);
    return (n == 9) && cbx_is_fin(a->m[0][3]) && cbx_is_fin(a->m[1][3]) && cbx_is_fin(a->m[2][3]);
}

/* The class a caller passed, checked against the map: IDENTITY or
 * TRANSLATE if the map is in it (equalities only: translate_holds), the
 * general class otherwise, so a class passed apart from its map (an easy
 * mix-up) costs speed, never soundness.  SCALE and PERMUTE run the general
 * kernel: on the fast range it is branch-free and faster than their
 * one-product kernels were (which branched on the sign of the entry). */
/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures ok: class_ok(a, \result);
*/
static cbx_class class_checked(const cbx_affine *a, cbx_class cls)
{
    if ((cls != CBX_CLASS_IDENTITY) && (cls != CBX_CLASS_TRANSLATE)) {
        return CBX_CLASS_GENERAL;
    }
    if (!translate_holds(a)) {
        return CBX_CLASS_GENERAL;
    }
    if (cls == CBX_CLASS_TRANSLATE) {
        return CBX_CLASS_TRANSLATE;
    }
    if ((a->m[0][3] == 0.0) && (a->m[1][3] == 0.0) && (a->m[2][3] == 0.0)) {
        return CBX_CLASS_IDENTITY;
    }
    return CBX_CLASS_GENERAL;
}

cbx_status cbx_transform_box_as(const cbx_affine *a, cbx_class cls0, const cbx_box *in, cbx_box *out)
{
    cbx_status r;
    cbx_class cls = class_checked(a, cls0);
    if (cls == CBX_CLASS_IDENTITY) {
        r = kern_identity(a, in, out);
    } else if (cls == CBX_CLASS_TRANSLATE) {
        r = kern_translate(a, in, out);
    } else {
        r = cbx_transform_box(a, in, out);
    }
    return r;
}
