/*
 * Batch form of the interval transform: one call per box of the proven
 * kernel, and the most severe status met.  binary64: the map is classified
 * once (cbx_classify) and every box goes through the class kernel
 * (cbx_transform_box_as, cbx_transform_box's promise); binary32 (the
 * float family has no class kernels): cbx_transform_boxf.  The call for
 * box k writes exactly out[k]; the loop invariant carries each finished
 * box's whole promise as a predicate on values (box_done_m), which a write
 * elsewhere cannot touch.
 */
#include "certbox.h"
#include "cbx_onebox.h"

/* The per-box kernel: the class kernel in binary64, the general one in
 * binary32 (where CBX_CLS_ARG and the class clauses vanish). */
#if CBX_INST == 64
#define CBX_CLS_PARAM , cbx_class cls
#define CBX_CLS_ARG , cls
#define CBX_CLS_REQ requires cls: class_ok(a, cls);
#define CBX_CLS_ENS ensures cls: class_ok(a, cls);
#define CBX_CLS_INV loop invariant cls: class_ok(a, cls);
#define CBX_ONE_BOX(a, b) one_box_as(a, cls, b)
#else
#define CBX_CLS_PARAM
#define CBX_CLS_ARG
#define CBX_CLS_REQ
#define CBX_CLS_ENS
#define CBX_CLS_INV
#define CBX_ONE_BOX(a, b) one_box(a, b)
#endif

/* Severity order of the statuses (specs: sev). */
/*@ assigns \nothing;
    ensures \result == sev(s);
*/
static int severity(cbx_status s)
{
    if (s == CBX_EINVAL) return 3;
    if (s == CBX_ERANGE) return 2;
    if (s == CBX_EMPTY) return 1;
    return 0;
}

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
    CBX_CLS_REQ
    assigns out[k];
    ensures done: box_done_m(CBX_AV(a, Pre), CBX_BV(in + k, Pre), out[k]);
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result));
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE || \result == CBX_EINVAL;
    ensures frame: \forall integer j; 0 <= j < n && j != k ==> out[j] == \at(out[j], Pre);
    CBX_CLS_ENS
*/
static cbx_status step(const cbx_affine *a CBX_CLS_PARAM, const cbx_box *in, cbx_box *out,
                       size_t k, size_t n)
{
    box_st r = CBX_ONE_BOX(a, in + k);
    put_box(out, k, n, r.o);
    return r.s;
}

cbx_status cbx_transform_boxes(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t n)
{
    cbx_status worst = CBX_OK;
#if CBX_INST == 64
    cbx_class cls = cbx_classify(a);   /* classify once: the prepared form */
#endif
    size_t k;
    /*@ loop invariant rng: 0 <= k <= n;
        CBX_CLS_INV
        loop invariant done: \forall integer j; 0 <= j < k ==>
          box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]);
        loop invariant sevmax: \forall integer j; 0 <= j < k ==>
          box_sev_le(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst));
        loop invariant met: (k == 0 && worst == CBX_OK)
          || (\exists integer j; 0 <= j < k && box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst)));
        loop invariant stv: worst == CBX_OK || worst == CBX_EMPTY || worst == CBX_ERANGE || worst == CBX_EINVAL;
        loop assigns k, worst, out[0 .. n - 1];
        loop variant n - k;
    */
    for (k = 0; k < n; k++) {
        cbx_status s = step(a CBX_CLS_ARG, in, out, k, n);
        /*@ assert this: \forall integer j; j == k ==>
              box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]); */
        /*@ assert sevk: \forall integer j; j == k ==>
              box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(s)); */
        if (severity(s) > severity(worst))
            worst = s;
    }
    /*@ assert kn: k == n; */
    return worst;
}
