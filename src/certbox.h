/*
 * certbox: axis-aligned bounding boxes of transformed objects, proven to
 * contain the exact image (Frama-C/WP, IEEE-754 binary64 float model) and
 * tested to be tight against exact rational arithmetic (GMP).
 *
 * Conventions
 *   - An affine map y = M x + T is stored row-major in cbx_affine:
 *       y_i = m[i][0]*x_0 + m[i][1]*x_1 + m[i][2]*x_2 + m[i][3].
 *   - A box is the closed real set { x : lo[j] <= x_j <= hi[j] }.
 *   - The output box is the last argument; it is always written, whatever
 *     the status.
 *
 * Proven domain (see README.md, "Domain"): every input is finite and, for
 * every row i and column j, the pair (m[i][j], c) with c = lo[j] and
 * c = hi[j] lies in one of the magnitude classes
 *       |m[i][j]| <= 2^k  and  |c| <= 2^(1018-k),  k in {0,64,...,960,509,1018}
 * (so |m[i][j]*c| <= 2^1018), and |m[i][3]| <= 2^1018.  Inside the domain
 * an axis is computed by the proven kernel; outside it the axis is set to
 * [-inf, +inf] and the status is CBX_ERANGE.
 *
 * Proven statement (cbx_transform_box, in exact real arithmetic on the
 * input values): for each axis i in the domain and each of the 8 corners
 * c of the input box,
 *     out->lo[i] <= m[i][0]*c_0 + m[i][1]*c_1 + m[i][2]*c_2 + m[i][3] <= out->hi[i]
 * and the bounds are tight:
 *     out->lo[i] >= L_i - (12 u S_i + 2^-1065),  out->hi[i] <= H_i + (12 u S_i + 2^-1065)
 * with L_i, H_i the exact bounds of the image, u = 2^-53 and
 * S_i = |m[i][3]| + sum_j |m[i][j]| max(|lo_j|, |hi_j|).
 *
 * Every function is reentrant: no global state, no allocation.
 * Compile with an ISO mode (-std=c99) or -ffp-contract=off, without
 * -ffast-math, and with SSE2 (not x87) on x86: the proof assumes every
 * operation rounds once to nearest in binary64.
 */
#ifndef CERTBOX_H
#define CERTBOX_H

#ifdef __cplusplus
extern "C" {
#endif

#define CBX_VERSION_MAJOR 0
#define CBX_VERSION_MINOR 1
#define CBX_VERSION_PATCH 0
#define CBX_VERSION_STRING "0.1.0"

/* y_i = m[i][0]*x_0 + m[i][1]*x_1 + m[i][2]*x_2 + m[i][3] */
typedef struct cbx_affine { double m[3][4]; } cbx_affine;

/* the closed box [lo[0],hi[0]] x [lo[1],hi[1]] x [lo[2],hi[2]] */
typedef struct cbx_box { double lo[3], hi[3]; } cbx_box;

typedef enum cbx_status {
    CBX_OK = 0,      /* result proven to contain the exact image           */
    CBX_EMPTY = 1,   /* input box empty (lo > hi on some axis): out empty  */
    CBX_EINVAL = -1, /* NaN in the input: out is the whole space           */
    CBX_ERANGE = -2  /* input outside the proven domain on some axis: those
                        axes are [-inf, +inf], the others are proven       */
} cbx_status;

#ifdef __FRAMAC__
#include "cbx_spec.h"
#endif

/* Transform an axis-aligned box by an affine map (Arvo's interval form,
 * outward rounded).  Status and output:
 *   NaN anywhere in *a or *in       -> CBX_EINVAL, *out = [-inf, +inf]^3
 *   lo[j] > hi[j] for some j        -> CBX_EMPTY,  *out = lo +inf, hi -inf
 *   some axis outside the domain    -> CBX_ERANGE, that axis [-inf, +inf]
 *   otherwise                       -> CBX_OK, every axis proven sound
 * *out may not overlap *a or *in. */
/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && \separated(out, in);
    assigns *out;

    behavior nan_input:
      assumes has_nan(a, in);
      ensures \result == CBX_EINVAL;
      ensures whole_space(out);
    behavior empty_input:
      assumes !has_nan(a, in) && is_empty(in);
      ensures \result == CBX_EMPTY;
      ensures empty_out(out);
    behavior box_input:
      assumes !has_nan(a, in) && !is_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: axis_sound(a, in, out, 0);
      ensures axis1: axis_sound(a, in, out, 1);
      ensures axis2: axis_sound(a, in, out, 2);
      ensures ok_iff: \result == CBX_OK <==>
        (row_dom(a, in, 0) && row_dom(a, in, 1) && row_dom(a, in, 2));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_transform_box(const cbx_affine *a, const cbx_box *in, cbx_box *out);

/* Human-readable name of a status ("CBX_OK", ...). */
const char *cbx_status_name(cbx_status s);

#ifdef __cplusplus
}
#endif
#endif /* CERTBOX_H */
