/*
 * Run-time domain and special-value checks.  Each returns 1 exactly when
 * the matching predicate of specs/cbx_spec.h holds; the kernels are called
 * only where they hold.  Comparisons are IEEE: -B <= x <= B is false for
 * NaN and infinities.
 */
#ifndef CBX_DOMAIN_H
#define CBX_DOMAIN_H

#include "certbox.h"
#include "cbx_prec.h"

/* One magnitude class: |m| <= bm and |c| <= bc (specs: cls). */
/*@ requires fin: \is_finite(m) && \is_finite(c) && \is_finite(bm) && \is_finite(bc);
    assigns \nothing;
    ensures val: \result != 0 <==> cls(m, c, bm, bc);
*/
static inline int cbx_cls(cbx_fp m, cbx_fp c, cbx_fp bm, cbx_fp bc)
{
    return (m >= -bm) && (m <= bm) && (c >= -bc) && (c <= bc);
}

/* Run-time check of one product's domain class (specs: dom_pair), the
 * classes of include/cbx_prec_begin.h in order.  The common class (both
 * factors at most 2^509; 2^61 in binary32) comes first, and the first
 * class that holds ends the search: an or of all 18 (no branch, fewer
 * proof paths) made the careful paths that check every pair 7x slower
 * (cbx_transform_cbox 62 ns -> 462 ns per box, make bench 2026-11-25). */
#define CBX_CLS_TRY(tag, bm, bc) if (cbx_cls(m, c, CBX_C(bm), CBX_C(bc)) != 0) { return 1; }
/*@ requires fin: \is_finite(m) && \is_finite(c);
    assigns \nothing;
    ensures val: \result != 0 <==> dom_pair(m, c);
*/
static inline int cbx_dom_pair(cbx_fp m, cbx_fp c)
{
    CBX_CLASS_HEAD(CBX_CLS_TRY)
    CBX_CLASS_TAIL(CBX_CLS_TRY)
    return 0;
}

/* 1 if x is finite: comparisons with NaN and infinities are false. */
/*@ assigns \nothing;
    ensures \result != 0 <==> \is_finite(x);
*/
static inline int cbx_is_fin(cbx_fp x) { return (x >= -CBX_K(FMAX)) && (x <= CBX_K(FMAX)); }

/* 1 if the four are finite (one call: the callers' goals stay linear). */
/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(x0) && \is_finite(x1) && \is_finite(x2) && \is_finite(x3));
*/
static inline int cbx_fin4(cbx_fp x0, cbx_fp x1, cbx_fp x2, cbx_fp x3)
{
    return cbx_is_fin(x0) && cbx_is_fin(x1) && cbx_is_fin(x2) && cbx_is_fin(x3);
}

/* 1 when every input of one output row is finite and in the proven domain
 * (specs: row_in_dom).  One early return per test keeps the proof linear. */
/*@ assigns \nothing;
    ensures ok: \result != 0 <==>
      (\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
       && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
       && \is_finite(l2) && \is_finite(h2)
       && row_in_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2));
*/
static inline int cbx_row_ok(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                  cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    if (!cbx_is_fin(m0)) return 0;
    if (!cbx_is_fin(m1)) return 0;
    if (!cbx_is_fin(m2)) return 0;
    if (!cbx_is_fin(t)) return 0;
    if (!cbx_is_fin(l0)) return 0;
    if (!cbx_is_fin(h0)) return 0;
    if (!cbx_is_fin(l1)) return 0;
    if (!cbx_is_fin(h1)) return 0;
    if (!cbx_is_fin(l2)) return 0;
    if (!cbx_is_fin(h2)) return 0;
    if (!((t >= -CBX_K(RT)) && (t <= CBX_K(RT)))) return 0;
    if (!cbx_dom_pair(m0, l0)) return 0;
    if (!cbx_dom_pair(m0, h0)) return 0;
    if (!cbx_dom_pair(m1, l1)) return 0;
    if (!cbx_dom_pair(m1, h1)) return 0;
    if (!cbx_dom_pair(m2, l2)) return 0;
    if (!cbx_dom_pair(m2, h2)) return 0;
    return 1;
}

/* 1 if x is NaN (x != x holds only for NaN). */
/*@ assigns \nothing;
    ensures \result != 0 <==> \is_NaN(x);
*/
static inline int cbx_is_nan(cbx_fp x) { return x != x; }

/* 1 if hi < lo in IEEE comparison (the box is empty on that axis). */
/*@ assigns \nothing;
    ensures \result != 0 <==> CBX_LT(hi, lo);
*/
static inline int cbx_is_inverted(cbx_fp lo, cbx_fp hi) { return hi < lo; }

/* 1 if [lo, hi] has no real point: hi < lo, lo = +inf or hi = -inf. */
/*@ assigns \nothing;
    ensures \result != 0 <==> no_point(lo, hi);
*/
static inline int cbx_no_point(cbx_fp lo, cbx_fp hi)
{
    return (hi < lo) || (lo > CBX_K(FMAX)) || (hi < -CBX_K(FMAX));
}

/* The input checks of a box, each one predicate of the contracts (one call
 * in the public functions keeps their goals small). */
/*@ requires \valid_read(a);
    assigns \nothing;
    ensures \result != 0 <==> aff_nan(a);
*/
static inline int aff_any_nan(const cbx_affine *a)
{
    return cbx_is_nan(a->m[0][0]) | cbx_is_nan(a->m[0][1]) | cbx_is_nan(a->m[0][2]) | cbx_is_nan(a->m[0][3])
           | cbx_is_nan(a->m[1][0]) | cbx_is_nan(a->m[1][1]) | cbx_is_nan(a->m[1][2]) | cbx_is_nan(a->m[1][3])
           | cbx_is_nan(a->m[2][0]) | cbx_is_nan(a->m[2][1]) | cbx_is_nan(a->m[2][2]) | cbx_is_nan(a->m[2][3]);
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox_nan(in);
*/
static inline int cbox_any_nan_in(const cbx_cbox *in)
{
    return cbx_is_nan(in->c[0]) | cbx_is_nan(in->c[1]) | cbx_is_nan(in->c[2])
           | cbx_is_nan(in->h[0]) | cbx_is_nan(in->h[1]) | cbx_is_nan(in->h[2]);
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> box_nan(in);
*/
static inline int box_any_nan(const cbx_box *in)
{
    return cbx_is_nan(in->lo[0]) | cbx_is_nan(in->lo[1]) | cbx_is_nan(in->lo[2])
           | cbx_is_nan(in->hi[0]) | cbx_is_nan(in->hi[1]) | cbx_is_nan(in->hi[2]);
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> is_empty(in);
*/
static inline int box_any_empty(const cbx_box *in)
{
    return cbx_no_point(in->lo[0], in->hi[0]) | cbx_no_point(in->lo[1], in->hi[1])
           | cbx_no_point(in->lo[2], in->hi[2]);
}

/* The special outputs: the whole space (CBX_EINVAL, whole axes) and the
 * empty box (CBX_EMPTY). */
/*@ requires \valid(out);
    assigns *out;
    ensures whole_space(out);
*/
static inline void set_whole(cbx_box *out)
{
    out->lo[0] = cbx_ninf(); out->hi[0] = cbx_pinf();
    out->lo[1] = cbx_ninf(); out->hi[1] = cbx_pinf();
    out->lo[2] = cbx_ninf(); out->hi[2] = cbx_pinf();
}

/*@ requires \valid(out);
    assigns *out;
    ensures empty_out(out);
*/
static inline void set_empty(cbx_box *out)
{
    out->lo[0] = cbx_pinf(); out->hi[0] = cbx_ninf();
    out->lo[1] = cbx_pinf(); out->hi[1] = cbx_ninf();
    out->lo[2] = cbx_pinf(); out->hi[2] = cbx_ninf();
}

/* The same checks and special outputs for the 2D form (specs/cbx_plane.h). */
/*@ requires \valid_read(a);
    assigns \nothing;
    ensures \result != 0 <==> aff2_nan(a);
*/
static inline int aff2_any_nan(const cbx_affine2 *a)
{
    return cbx_is_nan(a->m[0][0]) | cbx_is_nan(a->m[0][1]) | cbx_is_nan(a->m[0][2])
           | cbx_is_nan(a->m[1][0]) | cbx_is_nan(a->m[1][1]) | cbx_is_nan(a->m[1][2]);
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> box2_nan(in);
*/
static inline int box2_any_nan(const cbx_box2 *in)
{
    return cbx_is_nan(in->lo[0]) | cbx_is_nan(in->lo[1]) | cbx_is_nan(in->hi[0]) | cbx_is_nan(in->hi[1]);
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> is_empty2(in);
*/
static inline int plane_any_empty(const cbx_box2 *in)
{
    return cbx_no_point(in->lo[0], in->hi[0]) | cbx_no_point(in->lo[1], in->hi[1]);
}

/* The empty and NaN checks of the center forms (h < 0 on an axis is an
 * empty box). */
/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox_empty(in);
*/
static inline int cbox_any_neg(const cbx_cbox *in)
{
    return cbx_is_inverted(CBX_C(0.0), in->h[0]) | cbx_is_inverted(CBX_C(0.0), in->h[1])
           | cbx_is_inverted(CBX_C(0.0), in->h[2]);
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox2_nan(in);
*/
static inline int cbox2_any_nan_in(const cbx_cbox2 *in)
{
    return cbx_is_nan(in->c[0]) | cbx_is_nan(in->c[1]) | cbx_is_nan(in->h[0]) | cbx_is_nan(in->h[1]);
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox2_empty(in);
*/
static inline int cbox2_any_neg(const cbx_cbox2 *in)
{
    return cbx_is_inverted(CBX_C(0.0), in->h[0]) | cbx_is_inverted(CBX_C(0.0), in->h[1]);
}

/*@ requires \valid(out);
    assigns *out;
    ensures whole_plane(out);
*/
static inline void set_whole2(cbx_box2 *out)
{
    out->lo[0] = cbx_ninf(); out->hi[0] = cbx_pinf();
    out->lo[1] = cbx_ninf(); out->hi[1] = cbx_pinf();
}

/*@ requires \valid(out);
    assigns *out;
    ensures empty_out2(out);
*/
static inline void set_empty2(cbx_box2 *out)
{
    out->lo[0] = cbx_pinf(); out->hi[0] = cbx_ninf();
    out->lo[1] = cbx_pinf(); out->hi[1] = cbx_ninf();
}

/* The severity order of the statuses (specs: sev), for "the most severe
 * status met" of the batch and chain functions. */
/*@ assigns \nothing;
    ensures val: \result == sev(s);
*/
static inline int cbx_severity(cbx_status s)
{
    int r = 0;
    if (s == CBX_EINVAL) {
        r = 3;
    } else if (s == CBX_ERANGE) {
        r = 2;
    } else if (s == CBX_EMPTY) {
        r = 1;
    } else {
        /* CBX_OK: severity 0, r's initial value */
    }
    return r;
}

#endif /* CBX_DOMAIN_H */
