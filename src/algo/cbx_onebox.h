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
#include "cbx_fast.h"

/* One box, returned by value: cbx_transform_box's promise restated on
 * values (the output is a value, not memory, until put_box writes it). */
typedef struct box_st { cbx_box o; cbx_status s; } box_st;

/*@ requires valid: \valid_read(a) && \valid_read(b);
    assigns \nothing;
    CBX_ONE_POST(a, b)
*/
static inline box_st one_box(const cbx_affine *a, const cbx_box *b)
{
    box_st r;
    r.s = cbx_transform_box(a, b, &r.o);
    return r;
}

/* The branch-free kernel with cbx_transform_box's box_input promise (the
 * form one_kernel's proof needs), on a map and a box in the fast range:
 * there no input is NaN or empty, so the other two behaviors of
 * CBX_BOX_BEHAVIORS would be dead (the smoke tests flag them). */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && \separated(out, in);
    requires fast: map_fast(a) && box_fast(in);
    assigns *out;
    ensures case: \at(!has_nan(a, in) && !is_empty(in), Pre);
    ensures st: \result == CBX_OK || \result == CBX_ERANGE;
    ensures axis0: axis_sound_s(out->lo[0], out->hi[0], CBX_ROWV(a, 0, Pre), CBX_BV(in, Pre));
    ensures axis1: axis_sound_s(out->lo[1], out->hi[1], CBX_ROWV(a, 1, Pre), CBX_BV(in, Pre));
    ensures axis2: axis_sound_s(out->lo[2], out->hi[2], CBX_ROWV(a, 2, Pre), CBX_BV(in, Pre));
    ensures ok_iff: \result == CBX_OK <==>
      \at(row_ok(a, in, 0) && row_ok(a, in, 1) && row_ok(a, in, 2), Pre);
*/
static inline cbx_status fast_box_b(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    return cbx_fast_box(a, in, out);
}

/* one_box on a map and a box in the fast range: the kernel alone. */
/*@ requires valid: \valid_read(a) && \valid_read(b);
    requires fast: map_fast(a) && box_fast(b);
    assigns \nothing;
    CBX_ONE_POST(a, b)
*/
static inline box_st one_kernel(const cbx_affine *a, const cbx_box *b)
{
    box_st r;
    r.s = fast_box_b(a, b, &r.o);
    return r;
}

/* The same under a map checked once to be in the fast range (the batch
 * loop): a box in the fast range goes straight to the branch-free kernel,
 * any other to cbx_transform_box.  The output is cbx_transform_box's, bit
 * for bit: it takes the same kernel on the same inputs. */
/*@ requires valid: \valid_read(a) && \valid_read(b);
    requires fast: map_fast(a);
    assigns \nothing;
    CBX_ONE_POST(a, b)
*/
static inline box_st one_fast(const cbx_affine *a, const cbx_box *b)
{
    if (cbx_box_fast(b) != 0) {
        return one_kernel(a, b);
    }
    return one_box(a, b);
}

#if CBX_INST == 64
/* The same through a class kernel (cls: a hint, checked by the kernel). */
/*@ requires valid: \valid_read(a) && \valid_read(b);
    assigns \nothing;
    CBX_ONE_POST(a, b)
*/
static inline box_st one_box_as(const cbx_affine *a, cbx_class cls, const cbx_box *b)
{
    box_st r;
    r.s = cbx_transform_box_as(a, cls, b, &r.o);
    return r;
}
#endif

#endif /* CBX_ONEBOX_H */
