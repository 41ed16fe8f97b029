/*
 * One box of cbx_transform_box, returned by value with its whole promise
 * restated on values (box_done_m, box_sev_v): used where a caller needs
 * the result as a value, not memory (the batch loop, motion's two ends).
 * Both formats; one_box_as (the class kernels) is binary64 only.
 */
#ifndef CBX_ONEBOX_H
#define CBX_ONEBOX_H

#include "certbox.h"
#include "cbx_prec.h"

/* One box, returned by value: cbx_transform_box's promise restated on
 * values (the output is a value, not memory, until put_box writes it). */
typedef struct box_st { cbx_box o; cbx_status s; } box_st;

/*@ requires valid: \valid_read(a) && \valid_read(b);
    assigns \nothing;
    ensures done: box_done_m(CBX_AV(a, Pre), CBX_BV(b, Pre), \result.o);
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(b, Pre), sev(\result.s));
    ensures st: \result.s == CBX_OK || \result.s == CBX_EMPTY || \result.s == CBX_ERANGE
                || \result.s == CBX_EINVAL;
*/
static inline box_st one_box(const cbx_affine *a, const cbx_box *b)
{
    box_st r;
    r.s = cbx_transform_box(a, b, &r.o);
    return r;
}

#if CBX_INST == 64
/* The same through a class kernel (cls: a hint, checked by the kernel). */
/*@ requires valid: \valid_read(a) && \valid_read(b);
    assigns \nothing;
    ensures done: box_done_m(CBX_AV(a, Pre), CBX_BV(b, Pre), \result.o);
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(b, Pre), sev(\result.s));
    ensures st: \result.s == CBX_OK || \result.s == CBX_EMPTY || \result.s == CBX_ERANGE
                || \result.s == CBX_EINVAL;
*/
static inline box_st one_box_as(const cbx_affine *a, cbx_class cls, const cbx_box *b)
{
    box_st r;
    r.s = cbx_transform_box_as(a, cls, b, &r.o);
    return r;
}
#endif

#endif /* CBX_ONEBOX_H */
