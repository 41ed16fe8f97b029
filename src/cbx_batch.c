/*
 * Batch form of the interval transform: one call per box of the proven
 * single-box function, and the most severe status met.  The call for box
 * k writes exactly out[k]; the loop invariant carries each finished box's whole promise as
 * a predicate on values (box_done_v), which a write elsewhere cannot touch.
 */
#include "certbox.h"

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

/* One box: cbx_transform_box's promise restated on values. */
/*@ requires valid: \valid_read(a) && \valid_read(b) && \valid(o);
    requires sep: \separated(o, a) && \separated(o, b);
    assigns *o;
    ensures done: box_done_v(CBX_AV(a, Pre), CBX_BV(b, Pre), CBX_BV(o, Here));
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(b, Pre), sev(\result));
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE || \result == CBX_EINVAL;
*/
static cbx_status one_box(const cbx_affine *a, const cbx_box *b, cbx_box *o)
{
    return cbx_transform_box(a, b, o);
}

cbx_status cbx_transform_boxes(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t n)
{
    cbx_status worst = CBX_OK;
    size_t k;
    /*@ loop invariant rng: 0 <= k <= n;
        loop invariant done: \forall integer j; 0 <= j < k ==>
          box_done_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), CBX_BV(out + j, Here));
        loop invariant sevmax: \forall integer j, s; 0 <= j < k ==>
          box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), s) ==> s <= sev(worst);
        loop invariant met: (k == 0 && worst == CBX_OK)
          || (\exists integer j; 0 <= j < k && box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst)));
        loop invariant stv: worst == CBX_OK || worst == CBX_EMPTY || worst == CBX_ERANGE || worst == CBX_EINVAL;
        loop assigns k, worst, out[0 .. n - 1];
        loop variant n - k;
    */
    for (k = 0; k < n; k++) {
        cbx_status s = one_box(a, in + k, out + k);
        if (severity(s) > severity(worst))
            worst = s;
    }
    return worst;
}
