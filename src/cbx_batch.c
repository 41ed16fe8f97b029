/*
 * Batch form of the interval transform: the map is classified once
 * (cbx_classify), then one call per box of the proven class kernel
 * (cbx_transform_box_as, cbx_transform_box's promise), and the most severe
 * status met.  The call for box
 * k writes exactly out[k]; the loop invariant carries each finished box's whole promise as
 * a predicate on values (box_done_v), which a write elsewhere cannot touch.
 */
#include "certbox.h"
#include "cbx_onebox.h"

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
    requires cls: class_ok(a, cls);
    assigns out[k];
    ensures done: box_done_m(CBX_AV(a, Pre), CBX_BV(in + k, Pre), out[k]);
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result));
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE || \result == CBX_EINVAL;
    ensures frame: \forall integer j; 0 <= j < n && j != k ==> out[j] == \at(out[j], Pre);
    ensures cls: class_ok(a, cls);
*/
static cbx_status step(const cbx_affine *a, cbx_class cls, const cbx_box *in, cbx_box *out,
                       size_t k, size_t n)
{
    box_st r = one_box_as(a, cls, in + k);
    put_box(out, k, n, r.o);
    return r.s;
}

cbx_status cbx_transform_boxes(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t n)
{
    cbx_status worst = CBX_OK;
    cbx_class cls = cbx_classify(a);   /* classify once: the prepared form */
    size_t k;
    /*@ loop invariant rng: 0 <= k <= n;
        loop invariant cls: class_ok(a, cls);
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
        cbx_status s = step(a, cls, in, out, k, n);
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
