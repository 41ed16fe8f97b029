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

#include <stddef.h>

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

/* the real box [c - h, c + h] per axis; h >= 0 (h < 0: empty) */
typedef struct cbx_cbox { double c[3], h[3]; } cbx_cbox;

typedef enum cbx_status {
    CBX_OK = 0,      /* result proven to contain the exact image           */
    CBX_EMPTY = 1,   /* input box empty (lo > hi on some axis): out empty  */
    CBX_EINVAL = -1, /* NaN in the input: out is the whole space           */
    CBX_ERANGE = -2  /* input outside the proven domain on some axis: those
                        axes are [-inf, +inf], the others are proven       */
} cbx_status;

/* Transform classes (cbx_classify).  Each class is contained in the next:
 * IDENTITY c TRANSLATE c SCALE c PERMUTE c GENERAL. */
typedef enum cbx_class {
    CBX_CLASS_GENERAL = 0,   /* any map (or an entry NaN or infinite)           */
    CBX_CLASS_PERMUTE = 1,   /* each row of the linear part has at most one
                                nonzero entry: signed permutation with scale
                                (and projections), + translation             */
    CBX_CLASS_SCALE = 2,     /* linear part diagonal, + translation            */
    CBX_CLASS_TRANSLATE = 3, /* linear part the identity, + translation        */
    CBX_CLASS_IDENTITY = 4   /* the identity map                               */
} cbx_class;

#ifdef __FRAMAC__
#include "cbx_spec.h"
#include "cbx_ball.h"
#include "cbx_class.h"
#endif

/* Transform an axis-aligned box by an affine map (Arvo's interval form,
 * outward rounded).  Status and output:
 *   NaN anywhere in *a or *in       -> CBX_EINVAL, *out = [-inf, +inf]^3
 *   lo[j] > hi[j] for some j        -> CBX_EMPTY,  *out = lo +inf, hi -inf
 *   some axis outside the domain    -> CBX_ERANGE, that axis [-inf, +inf]
 *   otherwise                       -> CBX_OK, every axis proven sound
 * out may be in itself (in-place update); otherwise *out may not overlap
 * *a or *in. */
/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
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
      ensures axis0: axis_sound_s(out->lo[0], out->hi[0],
        \at(a->m[0][0], Pre), \at(a->m[0][1], Pre), \at(a->m[0][2], Pre), \at(a->m[0][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures axis1: axis_sound_s(out->lo[1], out->hi[1],
        \at(a->m[1][0], Pre), \at(a->m[1][1], Pre), \at(a->m[1][2], Pre), \at(a->m[1][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures axis2: axis_sound_s(out->lo[2], out->hi[2],
        \at(a->m[2][0], Pre), \at(a->m[2][1], Pre), \at(a->m[2][2], Pre), \at(a->m[2][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures ok_iff: \result == CBX_OK <==>
        \at(row_ok(a, in, 0) && row_ok(a, in, 1) && row_ok(a, in, 2), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_transform_box(const cbx_affine *a, const cbx_box *in, cbx_box *out);


/* Tight mode: the same status, special cases and infinite ends as
 * cbx_transform_box, and every finite end the tightest double: lo = the
 * exact lower end rounded down, hi = the exact upper end rounded up.
 * Proven: the same statement as cbx_transform_box (containment of the
 * exact image for every real point, the tightness bound), given the
 * exactness of two_sum and two_prod (trusted, proofs/README.md).
 * Optimality is checked against GMP on every test case.  Ends where a
 * nonzero product m_ij v_j is below 2^-968 in magnitude, or |t|, a product or
 * the exact end is above 2^1015, keep cbx_transform_box's end (sound, maybe not the
 * tightest).  About 20 to 40 times slower than cbx_transform_box. */
/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
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
      ensures axis0: axis_sound_s(out->lo[0], out->hi[0],
        \at(a->m[0][0], Pre), \at(a->m[0][1], Pre), \at(a->m[0][2], Pre), \at(a->m[0][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures axis1: axis_sound_s(out->lo[1], out->hi[1],
        \at(a->m[1][0], Pre), \at(a->m[1][1], Pre), \at(a->m[1][2], Pre), \at(a->m[1][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures axis2: axis_sound_s(out->lo[2], out->hi[2],
        \at(a->m[2][0], Pre), \at(a->m[2][1], Pre), \at(a->m[2][2], Pre), \at(a->m[2][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures ok_iff: \result == CBX_OK <==>
        \at(row_ok(a, in, 0) && row_ok(a, in, 1) && row_ok(a, in, 2), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_transform_box_tight(const cbx_affine *a, const cbx_box *in, cbx_box *out);

/* ---- transform classes: compute only what the map calls for -----------
 * cbx_classify sorts a map into the smallest class that holds it (every
 * entry finite; zeros and ones compared exactly, -0 is 0).
 * cbx_transform_box_as runs the class's own kernel: IDENTITY copies the
 * box, TRANSLATE does 6 outward-rounded additions, SCALE and PERMUTE one
 * product and one outward-rounded addition per end, GENERAL is
 * cbx_transform_box.  Its contract is cbx_transform_box's, word for word
 * (same statuses, same special and infinite cases, the same containment and
 * tightness statement), proven for every class; the result is never looser
 * than cbx_transform_box's (GMP-checked).  Inputs outside a class kernel's
 * fast range (any end infinite or above 2^509 in magnitude for SCALE and
 * PERMUTE, 2^1018 for IDENTITY and TRANSLATE; empty or NaN boxes) take the
 * general kernel.
 * cls must be cbx_classify(a) or a larger class (GENERAL is always
 * allowed): classify once, then apply to many boxes (the prepared form;
 * cbx_transform_boxes does this itself). */
/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures holds: class_ok(a, \result);
    ensures least: class_least(a, \result);
*/
cbx_class cbx_classify(const cbx_affine *a);

/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    requires cls: class_ok(a, cls);
    assigns *out;
    CBX_BOX_BEHAVIORS(a, in, out)
*/
cbx_status cbx_transform_box_as(const cbx_affine *a, cbx_class cls, const cbx_box *in, cbx_box *out);

/* ---- motion: a box over a shutter interval ------------------------------
 * The map at time s in [0, 1] is the linear interpolation of two affine
 * maps, M(s) = (1 - s) M0 + s M1 (entry by entry, translations included).
 * The image of a point p is then (1 - s)(M0 p) + s (M1 p), between its two
 * end images, so the union of the two end boxes is the exact bound over
 * the interval; cbx_motion_box returns that union, outward rounded.
 * Proven: on every axis where both rows are full (finite, in the domain),
 * for every real s in [0, 1] and every corner c of the box,
 *     out->lo[i] <= (M(s) c)_i <= out->hi[i]   (exact reals);
 * on axes where neither row is full (half-spaces, out-of-domain pairs)
 * every finite end bounds (M(s) p)_i for every real point p and s; where
 * one row is full and the other not, or a row has an infinite entry, the
 * axis is [-inf, +inf].  Status: CBX_EINVAL (NaN) and CBX_EMPTY as
 * cbx_transform_box; CBX_OK when both ends' calls would return CBX_OK and
 * no axis mixes a full row with a non-full one; CBX_ERANGE otherwise.  Not covered: rotations interpolated otherwise
 * (slerp, screw motion); bound those by sampling with a proven margin, or
 * by the box of the swept rotation, before calling this. */
/*@ requires valid: \valid_read(a0) && \valid_read(a1) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a0) && \separated(out, a1) && (\separated(out, in) || out == in);
    assigns *out;
    behavior nan_input:
      assumes has_nan(a0, in) || has_nan(a1, in);
      ensures \result == CBX_EINVAL;
      ensures whole_space(out);
    behavior empty_input:
      assumes !has_nan(a0, in) && !has_nan(a1, in) && is_empty(in);
      ensures \result == CBX_EMPTY;
      ensures empty_out(out);
    behavior box_input:
      assumes !has_nan(a0, in) && !has_nan(a1, in) && !is_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: mot_axis(out->lo[0], out->hi[0], CBX_ROWV(a0, 0, Pre), CBX_ROWV(a1, 0, Pre), CBX_BV(in, Pre));
      ensures axis1: mot_axis(out->lo[1], out->hi[1], CBX_ROWV(a0, 1, Pre), CBX_ROWV(a1, 1, Pre), CBX_BV(in, Pre));
      ensures axis2: mot_axis(out->lo[2], out->hi[2], CBX_ROWV(a0, 2, Pre), CBX_ROWV(a1, 2, Pre), CBX_BV(in, Pre));
      ensures ok_iff: \result == CBX_OK <==>
        \at(row_ok(a0, in, 0) && row_ok(a0, in, 1) && row_ok(a0, in, 2)
            && row_ok(a1, in, 0) && row_ok(a1, in, 1) && row_ok(a1, in, 2)
            && mot_same(a0, a1, in, 0) && mot_same(a0, a1, in, 1) && mot_same(a0, a1, in, 2), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_motion_box(const cbx_affine *a0, const cbx_affine *a1, const cbx_box *in, cbx_box *out);

/* Batch form: out[k] = the box of in[k] under *a, for k = 0 .. n-1, each with
 * cbx_transform_box's promise (proven for every k): the map is classified
 * once and every box goes through the class kernel, so out[k] is exactly
 * cbx_transform_box_as(a, cbx_classify(a), in + k, out + k)'s output.
 * Returns the most severe status met (CBX_EINVAL, then CBX_ERANGE, then
 * CBX_EMPTY, then CBX_OK; CBX_OK when n == 0).  Every out[k] is written.
 * The arrays in and out may not overlap, and out may not overlap *a. */
/*@ requires valid: \valid_read(a) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), a) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    assigns out[0 .. n - 1];
    ensures done: \forall integer k; 0 <= k < n ==>
      box_done_m(CBX_AV(a, Pre), CBX_BV(in + k, Pre), out[k]);
    ensures worst: \forall integer k; 0 <= k < n ==>
      box_sev_le(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result));
    ensures met: n > 0 ==> \exists integer k; 0 <= k < n &&
      box_sev_v(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result));
    ensures none: n == 0 ==> \result == CBX_OK;
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE || \result == CBX_EINVAL;
*/
cbx_status cbx_transform_boxes(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t n);

/* ---- center/half-diagonal form (Arvo's Fig. 2) -------------------------
 * A cbx_cbox means the exact real box [c - h, c + h] (per axis); h >= 0.
 * h < 0 on some axis means an empty box.  Every function below is sound for
 * that meaning: the rounding of the center is paid for in the half-diagonal.
 * Status and output follow cbx_transform_box:
 *   NaN anywhere           -> CBX_EINVAL, out: c = 0, h = +inf on every axis
 *   h < 0 on some axis     -> CBX_EMPTY,  out: c = 0, h = -inf on every axis
 *   axis outside domain    -> CBX_ERANGE, that axis c = 0, h = +inf
 * Domain of cbx_transform_cbox: as for cbx_transform_box with the pairs
 * (m[i][j], c[j]) and (m[i][j], h[j]).  Domain of the conversions: every
 * input finite with magnitude <= 2^1019. */

/* Arvo's center/half-diagonal form: c' = M c + T, h' = |M| h, outward. */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    assigns *out;
    behavior nan_input:
      assumes cbox_has_nan(a, in);
      ensures \result == CBX_EINVAL && cwhole(out);
    behavior empty_input:
      assumes !cbox_has_nan(a, in) && cbox_empty(in);
      ensures \result == CBX_EMPTY && cempty(out);
    behavior box_input:
      assumes !cbox_has_nan(a, in) && !cbox_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: caxis_sound_s(out->c[0], out->h[0],
        \at(a->m[0][0], Pre), \at(a->m[0][1], Pre), \at(a->m[0][2], Pre), \at(a->m[0][3], Pre),
        \at(in->c[0], Pre), \at(in->c[1], Pre), \at(in->c[2], Pre),
        \at(in->h[0], Pre), \at(in->h[1], Pre), \at(in->h[2], Pre));
      ensures axis1: caxis_sound_s(out->c[1], out->h[1],
        \at(a->m[1][0], Pre), \at(a->m[1][1], Pre), \at(a->m[1][2], Pre), \at(a->m[1][3], Pre),
        \at(in->c[0], Pre), \at(in->c[1], Pre), \at(in->c[2], Pre),
        \at(in->h[0], Pre), \at(in->h[1], Pre), \at(in->h[2], Pre));
      ensures axis2: caxis_sound_s(out->c[2], out->h[2],
        \at(a->m[2][0], Pre), \at(a->m[2][1], Pre), \at(a->m[2][2], Pre), \at(a->m[2][3], Pre),
        \at(in->c[0], Pre), \at(in->c[1], Pre), \at(in->c[2], Pre),
        \at(in->h[0], Pre), \at(in->h[1], Pre), \at(in->h[2], Pre));
      ensures ok_iff: \result == CBX_OK <==>
        \at(crow_ok(a, in, 0) && crow_ok(a, in, 1) && crow_ok(a, in, 2), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_transform_cbox(const cbx_affine *a, const cbx_cbox *in, cbx_cbox *out);

/* [lo, hi] -> (c, h) with [c - h, c + h] containing [lo, hi]. */
/*@ requires valid: \valid_read(in) && \valid(out);
    requires sep: \separated(out, in);
    assigns *out;
    behavior nan_input:
      assumes box_nan(in);
      ensures \result == CBX_EINVAL && cwhole(out);
    behavior empty_input:
      assumes !box_nan(in) && is_empty(in);
      ensures \result == CBX_EMPTY && cempty(out);
    behavior box_input:
      assumes !box_nan(in) && !is_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures ax0: b2c_axis(in, out, 0);
      ensures ax1: b2c_axis(in, out, 1);
      ensures ax2: b2c_axis(in, out, 2);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_box_to_cbox(const cbx_box *in, cbx_cbox *out);

/* (c, h) -> [lo, hi] containing [c - h, c + h]. */
/*@ requires valid: \valid_read(in) && \valid(out);
    requires sep: \separated(out, in);
    assigns *out;
    behavior nan_input:
      assumes cbox_nan(in);
      ensures \result == CBX_EINVAL && whole_space(out);
    behavior empty_input:
      assumes !cbox_nan(in) && cbox_empty(in);
      ensures \result == CBX_EMPTY && empty_out(out);
    behavior box_input:
      assumes !cbox_nan(in) && !cbox_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures ax0: c2b_axis(in, out, 0);
      ensures ax1: c2b_axis(in, out, 1);
      ensures ax2: c2b_axis(in, out, 2);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_cbox_to_box(const cbx_cbox *in, cbx_box *out);

/* ---- spheres and ellipsoids: exact (dual-quadric) bounds ---------------
 * cbx_sphere_box: the image of the unit ball {p : |p| <= 1} under the affine
 * map: axis i is m[i][3] -+ sqrt(m[i][0]^2 + m[i][1]^2 + m[i][2]^2), rounded
 * outward.  Domain: every entry finite, |m[i][j]| <= 2^509 (j < 3),
 * |m[i][3]| <= 2^1018.
 * cbx_ellipsoid_box: the ellipsoid center + rot * diag(radii) * p, |p| <= 1
 * (rot need not be orthogonal; radii may be negative or zero).  Domain:
 * |rot[i][j]| <= 2^254, |radii[j]| <= 2^254, |center[i]| <= 2^1018.
 * NaN -> CBX_EINVAL and the whole space; outside the domain -> CBX_ERANGE
 * and those axes [-inf, +inf].  Proven: on every axis in the domain, for
 * every real point p with p.p <= 1, lo_i <= (M p + T)_i <= hi_i (exact reals;
 * for the ellipsoid M_ij = rot[i][j] * radii[j] exactly): specs/cbx_ball.h. */
/*@ requires valid: \valid_read(a) && \valid(out) && \separated(a, out);
    assigns *out;
    behavior nan_input:
      assumes aff_nan(a);
      ensures \result == CBX_EINVAL && whole_space(out);
    behavior map_input:
      assumes !aff_nan(a);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: sph_axis(a, out, 0);
      ensures axis1: sph_axis(a, out, 1);
      ensures axis2: sph_axis(a, out, 2);
      ensures ok_iff: \result == CBX_OK <==>
        (sph_row_dom(a, 0) && sph_row_dom(a, 1) && sph_row_dom(a, 2));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_sphere_box(const cbx_affine *a, cbx_box *out);

/*@ requires valid: \valid_read(center + (0 .. 2)) && \valid_read(radii + (0 .. 2))
                    && \valid_read(rot + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, center + (0 .. 2), radii + (0 .. 2), rot + (0 .. 2));
    assigns *out;
    behavior nan_input:
      assumes ell_nan(center, radii, rot);
      ensures \result == CBX_EINVAL && whole_space(out);
    behavior ellipsoid_input:
      assumes !ell_nan(center, radii, rot);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: ell_axis(center, radii, rot, out, 0);
      ensures axis1: ell_axis(center, radii, rot, out, 1);
      ensures axis2: ell_axis(center, radii, rot, out, 2);
      ensures ok_iff: \result == CBX_OK <==>
        (ell_row_dom(center, radii, rot, 0) && ell_row_dom(center, radii, rot, 1)
         && ell_row_dom(center, radii, rot, 2));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_ellipsoid_box(const double center[3], const double radii[3],
                             const double rot[3][3], cbx_box *out);

/* Human-readable name of a status ("CBX_OK", ...). */
const char *cbx_status_name(cbx_status s);

#ifdef __cplusplus
}
#endif
#endif /* CERTBOX_H */
