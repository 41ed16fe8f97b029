/*
 * Batch forms of the interval transform: cbx_transform_boxes (a map) and
 * cbx_transform_boxes_prep (a prepared map), the most severe status met.
 * binary64: the map's class is found once per call (cbx_classify, so a
 * prepared map's recorded class and fast flag are not trusted here).  A
 * general map (every map in binary32) is checked once per call for the fast
 * range; then each box in the fast range goes straight to the branch-free
 * kernel (one check of the box), any other box and every box under a map
 * outside the fast range to cbx_transform_box (the careful path; binary32:
 * cbx_transform_boxf), and a map of a smaller class sends every box to the
 * class kernel (cbx_transform_box_as).  Either way out[k] is exactly
 * cbx_transform_box_as(a, cbx_classify(a), in + k, out + k)'s output
 * (binary32: cbx_transform_boxf's).  The call for box k writes exactly
 * out[k]; the loop invariant carries each finished box's whole promise as a
 * predicate on values (box_done_m), which a write elsewhere cannot touch.
 */
#include "certbox.h"
#include "cbx_onebox.h"
#include "cbx_domain.h"
/* The per-box kernel: the class kernel in binary64, the general one in
 * binary32 (where CBX_CLS_ARG and the class clauses vanish). */
#if CBX_INST == 64
#define CBX_CLS_PARAM , cbx_class cls
#define CBX_CLS_ARG , cls
#define CBX_ONE_BOX(a, b) one_box_as(a, cls, b)
#define CBX_IS_GENERAL (cls == CBX_CLASS_GENERAL)
#else
#define CBX_CLS_PARAM
#define CBX_CLS_ARG
#define CBX_ONE_BOX(a, b) one_box(a, b)
#define CBX_IS_GENERAL 1
#endif

/* Write out[k]; every other out[j] is left alone (a small goal of its own:
 * with the box promise in context the provers do not find this frame). */
/*@ requires valid: \valid(out + (0 .. n - 1));
    requires k: k < n;
    assigns out[k];
    ensures val: out[k] == o;
    ensures frame: \forall integer j; 0 <= j < n && j != k ==> out[j] == \at(out[j], Pre);
*/
static void put_box(cbx_box *out, size_t k, size_t n, cbx_box o)
{
    (void)n;
    out[k] = o;
}

/* Box k of the batch, and what it leaves alone: every other out[j]. */
/*@ requires valid: \valid_read(a) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), a) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    requires k: k < n;
    requires fast: fast != 0 ==> map_fast_v(CBX_AV(a, Here));
    assigns out[k];
    ensures done: box_done_m(CBX_AV(a, Pre), CBX_BV(in + k, Pre), out[k]);
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result));
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE || \result == CBX_EINVAL;
    ensures frame: \forall integer j; 0 <= j < n && j != k ==> out[j] == \at(out[j], Pre);
*/
static cbx_status step(const cbx_affine *a CBX_CLS_PARAM, int fast, const cbx_box *in,
                       cbx_box *out, size_t k, size_t n)
{
    box_st r;
    if (fast != 0) {
        r = one_fast(a, &in[k]);
    } else if (CBX_IS_GENERAL) {
        r = one_box(a, &in[k]);
    } else {
        r = CBX_ONE_BOX(a, &in[k]);
    }
    put_box(out, k, n, r.o);
    return r.s;
}

/* The loop over the boxes under one map, checked by the caller. */
/*@ requires valid: \valid_read(a) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), a) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    requires fast: fast != 0 ==> map_fast(a);
    assigns out[0 .. n - 1];
    CBX_BATCH_POST(a)
*/
static cbx_status batch(const cbx_affine *a CBX_CLS_PARAM, int fast, const cbx_box *in,
                        cbx_box *out, size_t n)
{
    cbx_status worst = CBX_OK;
    size_t k;
    /*@ loop invariant rng: 0 <= k <= n;
        loop invariant done: \forall integer j; 0 <= j < k ==>
          box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]);
        loop invariant sevmax: \forall integer j; 0 <= j < k ==>
          box_sev_le(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst));
        loop invariant met: (k == 0 && worst == CBX_OK)
          || (\exists integer j; 0 <= j < k && box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst)));
        loop invariant stv: worst == CBX_OK || worst == CBX_EMPTY || worst == CBX_ERANGE || worst == CBX_EINVAL;
        loop invariant fst: fast != 0 ==> map_fast_v(CBX_AV(a, Pre));
        loop assigns k, worst, out[0 .. n - 1];
        loop variant n - k;
    */
    for (k = 0; k < n; k++) {
        cbx_status s = step(a CBX_CLS_ARG, fast, in, out, k, n);
        /*@ assert this: \forall integer j; j == k ==>
              box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]); */
        /*@ assert sevk: \forall integer j; j == k ==>
              box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(s)); */
        if (cbx_severity(s) > cbx_severity(worst)) {
            worst = s;
        }
    }
    /*@ assert kn: k == n; */
    return worst;
}

cbx_status cbx_transform_boxes(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t n)
{
#if CBX_INST == 64
    cbx_class cls = cbx_classify(a);   /* once per call */
#endif
    /* a general map is checked once for the fast range, not once per box */
    return batch(a CBX_CLS_ARG, CBX_IS_GENERAL && cbx_map_fast(a), in, out, n);
}

/* Nothing of *p but its map is used (the class is found again, once per
 * call): a prepared map changed by hand still gives sound boxes. */
cbx_status cbx_transform_boxes_prep(const cbx_prepared *p, const cbx_box *in, cbx_box *out, size_t n)
{
    return cbx_transform_boxes(&p->a, in, out, n);
}
