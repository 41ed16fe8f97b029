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
 * Proven domain (see docs/guide.md, "Domain"): every input is finite and, for
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
typedef struct cbx_box { double lo[3]; double hi[3]; } cbx_box;

/* the real box [c - h, c + h] per axis; h >= 0 (h < 0: empty) */
typedef struct cbx_cbox { double c[3]; double h[3]; } cbx_cbox;

/* The binary32 (float) family: the same types and functions with float
 * numbers, every name ending in f (see cbx_api.h). */
typedef struct cbx_affinef { float m[3][4]; } cbx_affinef;
typedef struct cbx_boxf { float lo[3]; float hi[3]; } cbx_boxf;
typedef struct cbx_cboxf { float c[3]; float h[3]; } cbx_cboxf;

/* The 2D family (both formats): y_i = m[i][0]*x_0 + m[i][1]*x_1 + m[i][2]
 * (i = 0, 1), the closed box [lo[0],hi[0]] x [lo[1],hi[1]], and the box
 * [c - h, c + h] per axis (h < 0: empty). */
typedef struct cbx_affine2 { double m[2][3]; } cbx_affine2;
typedef struct cbx_box2 { double lo[2]; double hi[2]; } cbx_box2;
typedef struct cbx_cbox2 { double c[2]; double h[2]; } cbx_cbox2;
typedef struct cbx_affine2f { float m[2][3]; } cbx_affine2f;
typedef struct cbx_box2f { float lo[2]; float hi[2]; } cbx_box2f;
typedef struct cbx_cbox2f { float c[2]; float h[2]; } cbx_cbox2f;

/* A projective map of space (both formats): X_i = m[i][0]*x_0 + m[i][1]*x_1
 * + m[i][2]*x_2 + m[i][3] for i = 0..3, the point (X_0/X_3, X_1/X_3,
 * X_2/X_3); a 4x4 matrix, row-major, acting on column vectors (x, 1). */
typedef struct cbx_proj { double m[4][4]; } cbx_proj;
typedef struct cbx_projf { float m[4][4]; } cbx_projf;

/* An interval matrix (binary64): the set of affine maps whose entry (i, j)
 * lies in [lo[i][j], hi[i][j]], the translation in column 3; what a chain
 * of rounded transforms or a rotation built from a quaternion is known to
 * be (cbx_transform_box_imat, cbx_imat_compose). */
typedef struct cbx_imat { double lo[3][4]; double hi[3][4]; } cbx_imat;

/* A keyframe of a motion (binary64): x -> t + R(q) diag(s) x, where R(q)
 * is the rotation of the unit quaternion q / |q| (q = (x, y, z, w), glTF's
 * order; any nonzero q) and s a scale per axis (negative flips). */
typedef struct cbx_trs { double t[3]; double q[4]; double s[3]; } cbx_trs;

/* How a motion interpolates the rotation between two keyframes: slerp (pbrt,
 * Embree, Mitsuba) or normalised linear blend (Cycles' GPU path), both on
 * the normalised keyframe quaternions along the shorter arc. */
typedef enum cbx_interp { CBX_SLERP = 0, CBX_NLERP = 1 } cbx_interp;

/* A map prepared once for many boxes (cbx_prepare, cbx_preparef): a copy
 * of the map, and whether it lies in the fast range (every linear entry at
 * most 2^509 in magnitude, every translation at most 2^1018; binary32:
 * 2^61 and 2^122), and its transform class (binary64; cbx_classify).  The
 * class travels with the map it was computed from.  Fill it only with
 * cbx_prepare; a zero-initialised one is valid too (it takes the careful
 * path and the general kernel), so is a copy of a prepared one. */
typedef struct cbx_prepared { cbx_affine a; int fast; int cls; } cbx_prepared;
typedef struct cbx_preparedf { cbx_affinef a; int fast; int cls; } cbx_preparedf;

typedef enum cbx_status {
    CBX_OK = 0,      /* result proven to contain the exact image           */
    CBX_EMPTY = 1,   /* input box empty (lo > hi on some axis): out empty  */
    CBX_EINVAL = -1, /* NaN in the input: out is the whole space           */
    CBX_ERANGE = -2, /* input outside the proven domain on some axis: those
                        axes are [-inf, +inf], the others are proven       */
    CBX_EBEHIND = -3 /* projective map: part of the box on or behind the
                        camera plane (w <= 0): out is the whole space      */
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

/* The API of each family, written once (cbx_api.h) and instantiated for
 * binary64 and binary32; under Frama-C with the logic of each (specs/).
 * A proof of one family alone defines CBX_FRAMAC_ONLY_64 or
 * CBX_FRAMAC_ONLY_32 (proofs/run.sh): the other family's lemmas then stay
 * out of its provers' context. */
#ifdef __FRAMAC__
#if !defined(CBX_FRAMAC_ONLY_32)    /* binary64 only (interval matrices) */
#include "cbx_imat_logic.h" /* first: its lemmas need a context of their own */
#endif
#include "cbx_logic.h"
#include "cbx_ball.h"
#include "cbx_proj_logic.h"
#endif
#if !defined(__FRAMAC__) || !defined(CBX_FRAMAC_ONLY_32)
#define CBX_INST 64
#include "cbx_prec_begin.h"
#ifdef __FRAMAC__
#include "cbx_spec.h"
#include "cbx_plane.h"
#include "cbx_proj.h"
#include "cbx_imat.h"
#endif
#include "cbx_api.h"
#include "cbx_prec_end.h"
#endif
#if !defined(__FRAMAC__) || !defined(CBX_FRAMAC_ONLY_64)
#define CBX_INST 32
#include "cbx_prec_begin.h"
#ifdef __FRAMAC__
#include "cbx_spec.h"
#include "cbx_plane.h"
#include "cbx_proj.h"
#endif
#include "cbx_api.h"
#include "cbx_prec_end.h"
#endif

/* ---- binary64 only: tight mode, transform classes, motion -------------- */
#if !defined(__FRAMAC__) || !defined(CBX_FRAMAC_ONLY_32)
#ifdef __FRAMAC__
#include "cbx_class.h"
#include "cbx_chain.h"
#include "cbx_tight_gap.h"
#include "cbx_psph.h"
#include "cbx_pnear.h"
#include "cbx_pball.h"
#include "cbx_pell.h"
#include "cbx_pwide.h"
#endif



/* Tight mode: the same status, special cases and infinite ends as
 * cbx_transform_box, and every finite end the tightest double: lo = the
 * exact lower end rounded down, hi = the exact upper end rounded up.
 * Proven: the same statement as cbx_transform_box (containment of the
 * exact image for every real point, the tightness bound), given the
 * exactness of two_sum and two_prod (trusted, proofs/README.md), and,
 * for maps and boxes of the fast range whose row has every product at the
 * box's ends zero or in [2^-967, 2^1013] and |t| <= 2^1015 (trow_dom),
 * each end within 2^-50 |E| + 2^-96 S + 2^-1050 of the exact end E
 * (specs/cbx_tight_gap.h: about 4 ulps of E, or 2^-96 S under
 * cancellation; cbx_transform_box's bound is 12 u S).  Optimality is
 * checked against GMP on every test case.  Ends where a
 * nonzero product m_ij v_j is below 2^-968 in magnitude, or |t|, a product or
 * the exact end is above 2^1015, keep cbx_transform_box's end (sound, maybe not the
 * tightest).  Maps and boxes in the fast range (every entry and end at most
 * 2^509 in magnitude) take a path with no branch on signs or certificates:
 * about 9 times cbx_transform_box's time, 20 times a round-to-nearest Arvo
 * (make bench, row 3t; docs/measurements.md). */
/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    assigns *out;
    CBX_TIGHT_NEAR(a, in, out)
    CBX_BOX_BEHAVIORS(a, in, out)
*/
cbx_status cbx_transform_box_tight(const cbx_affine *a, const cbx_box *in, cbx_box *out);

/* ---- transform classes: compute only what the map calls for -----------
 * cbx_classify sorts a map into the smallest class that holds it (every
 * entry finite; zeros and ones compared exactly, -0 is 0).
 * cbx_transform_box_as runs the class's own kernel: IDENTITY copies the
 * box, TRANSLATE does 6 outward-rounded additions; SCALE, PERMUTE and
 * GENERAL run cbx_transform_box (its branch-free kernel is faster than a
 * one-product kernel that branches on signs).  Its contract is
 * cbx_transform_box's, word for word (same statuses, same special and
 * infinite cases, the same containment and tightness statement), proven
 * for every value of cls; the result is never looser than
 * cbx_transform_box's (GMP-checked).  Inputs outside a class kernel's fast
 * range (any end infinite or above 2^1018 in magnitude, |t| above 2^1018;
 * empty or NaN boxes) take the general kernel.
 * cls is a hint: classify once, then apply to many boxes.  It is checked
 * against the map on every call (IDENTITY and TRANSLATE by 9 equalities and
 * 3 finiteness tests): a class the map is not in (a class kept apart from
 * its map and mixed up) runs the general kernel, so the box is sound for
 * any cls.  cbx_prepare keeps the class with its map. */
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
 *     out->lo[i] <= (M(s) c)_i <= out->hi[i]   (exact reals),
 * and each end is within 12 u S + 2^-1065 of the exact end over the
 * interval (the smaller lower, the larger upper end of the two rows' exact
 * ends; S the larger of the two rows' magnitudes, u = 2^-53);
 * on axes where neither row is full (half-spaces, out-of-domain pairs)
 * every finite end bounds (M(s) p)_i for every real point p and s; where
 * one row is full and the other not, or a row has an infinite entry, the
 * axis is [-inf, +inf].  Status: CBX_EINVAL (NaN) and CBX_EMPTY as
 * cbx_transform_box; CBX_OK when both ends' calls would return CBX_OK and
 * no axis mixes a full row with a non-full one; CBX_ERANGE otherwise.  Not covered: rotations interpolated otherwise
 * (slerp, screw motion): for slerp and nlerp keyframes, cbx_motion_trs_box. */
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
      ensures tight0: mot_tight(out->lo[0], out->hi[0], CBX_ROWV(a0, 0, Pre), CBX_ROWV(a1, 0, Pre), CBX_BV(in, Pre));
      ensures tight1: mot_tight(out->lo[1], out->hi[1], CBX_ROWV(a0, 1, Pre), CBX_ROWV(a1, 1, Pre), CBX_BV(in, Pre));
      ensures tight2: mot_tight(out->lo[2], out->hi[2], CBX_ROWV(a0, 2, Pre), CBX_ROWV(a1, 2, Pre), CBX_BV(in, Pre));
      ensures ok_iff: \result == CBX_OK <==>
        \at(row_ok(a0, in, 0) && row_ok(a0, in, 1) && row_ok(a0, in, 2)
            && row_ok(a1, in, 0) && row_ok(a1, in, 1) && row_ok(a1, in, 2)
            && mot_same(a0, a1, in, 0) && mot_same(a0, a1, in, 1) && mot_same(a0, a1, in, 2), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_motion_box(const cbx_affine *a0, const cbx_affine *a1, const cbx_box *in, cbx_box *out);


/* ---- interval matrices: maps known up to an interval per entry ---------
 * cbx_transform_box_imat: out contains the image of the box under every
 * map of the interval matrix *a: for each axis i, every real map M with
 * a->lo[i][j] <= M_ij <= a->hi[i][j] and every real point x of the box,
 *     out->lo[i] <= M_i0 x_0 + M_i1 x_1 + M_i2 x_2 + M_i3 <= out->hi[i],
 * and each end is within 12 u S_i + 2^-1065 of the exact end of that set
 * (S_i = max(|M_i3| ends) + sum_j the largest corner product |M_ij x_j|;
 * specs/cbx_imat.h: irow_lo, irow_hi, irow_mag).  Proven.  Status and
 * output:
 *   NaN in *a or *in, or an entry of *a with hi < lo -> CBX_EINVAL, whole space
 *   an axis of *in with no real point              -> CBX_EMPTY, lo +inf, hi -inf
 *   otherwise CBX_OK, or CBX_ERANGE where an axis has an infinite end, a
 *   linear entry or box end above 2^509 or a translation above 2^1018 in
 *   magnitude: that axis is [-inf, +inf].
 * out may be in itself; otherwise *out may not overlap *a or *in. */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    assigns *out;
    behavior bad_input:
      assumes imat_bad(a) || box_nan(in);
      ensures \result == CBX_EINVAL;
      ensures whole_space(out);
    behavior empty_input:
      assumes !imat_bad(a) && !box_nan(in) && is_empty(in);
      ensures \result == CBX_EMPTY;
      ensures empty_out(out);
    behavior box_input:
      assumes !imat_bad(a) && !box_nan(in) && !is_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: icoord(out->lo[0], out->hi[0], CBX_IROWV(a, 0, Pre), CBX_BV(in, Pre));
      ensures axis1: icoord(out->lo[1], out->hi[1], CBX_IROWV(a, 1, Pre), CBX_BV(in, Pre));
      ensures axis2: icoord(out->lo[2], out->hi[2], CBX_IROWV(a, 2, Pre), CBX_BV(in, Pre));
      ensures ok_iff: \result == CBX_OK <==>
        (irow_fast(CBX_IROWV(a, 0, Pre), CBX_BV(in, Pre)) && irow_fast(CBX_IROWV(a, 1, Pre), CBX_BV(in, Pre))
         && irow_fast(CBX_IROWV(a, 2, Pre), CBX_BV(in, Pre)));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_transform_box_imat(const cbx_imat *a, const cbx_box *in, cbx_box *out);

/* cbx_imat_compose: *out encloses every map A B (B applied first) with A
 * in *a and B in *b: entry (i, j) contains (A B)_ij = sum_k A_ik B_kj
 * (+ A_i3 when j = 3), each end within 12 u S + 2^-1065 of the exact end
 * of that set, as above.  Proven.  Status: CBX_EINVAL (every entry
 * [-inf, +inf]) if *a or *b has a NaN or an entry with hi < lo; else
 * CBX_OK, or CBX_ERANGE where an entry's inputs leave the range above:
 * that entry is [-inf, +inf] (a sound, unbounded entry: a box mapped by it
 * gets the whole line on that axis).  *out may not overlap *a or *b. */
/*@ requires valid: \valid_read(a) && \valid_read(b) && \valid(out);
    requires sep: \separated(out, a) && \separated(out, b);
    assigns *out;
    behavior bad_input:
      assumes imat_bad(a) || imat_bad(b);
      ensures \result == CBX_EINVAL;
      ensures imat_whole(out);
    behavior maps:
      assumes !imat_bad(a) && !imat_bad(b);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures col0: \let o = *out; \at(icol_s(o, a, b, 0), Pre);
      ensures col1: \let o = *out; \at(icol_s(o, a, b, 1), Pre);
      ensures col2: \let o = *out; \at(icol_s(o, a, b, 2), Pre);
      ensures col3: \let o = *out; \at(icol_s(o, a, b, 3), Pre);
      ensures ok_iff: \result == CBX_OK <==>
        \at(icol_fast(a, b, 0) && icol_fast(a, b, 1) && icol_fast(a, b, 2) && icol_fast(a, b, 3), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_imat_compose(const cbx_imat *a, const cbx_imat *b, cbx_imat *out);

/* ---- chains of maps: a node's transforms, applied level by level --------
 * cbx_transform_box_chain: the box of *in under p[0] p[1] ... p[n-1]
 * (p[n-1] applied first, p[0] last: a scene node's list of transforms, or
 * a path from a leaf up to the root), one map at a time with
 * cbx_transform_box_as with the class cbx_prepare recorded (the same box as
 * cbx_transform_box_prep), each step's box the next step's input.  Proven:
 * the image of every real point of *in under the exact product of the
 * given double matrices lies in *out (specs/cbx_chain.h: chain_x, an
 * infinite end no constraint), whatever the maps, the box and the statuses
 * of the steps.  Each step has cbx_transform_box's promise, tightness
 * included, against the step's input box; the chain's box is the last
 * step's, which can be wider than the box of the exact product (a rotation
 * by 45 degrees and back widens a box; cbx_imat_compose composes first).
 * Status: CBX_EINVAL with the whole space when n == 0; else the most
 * severe status of the steps (CBX_EINVAL, then CBX_ERANGE, then CBX_EMPTY,
 * then CBX_OK; checked by tests/test_chain.c).  The step is
 * cbx_transform_box_as with p[k]'s class, so a p[k] changed by hand still
 * gives a sound box.  out may be in; otherwise *out may not overlap *in,
 * and it may not overlap p[0 .. n-1]. */
/*@ requires valid: \valid_read(p + (0 .. n - 1)) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, p + (0 .. n - 1)) && (\separated(out, in) || out == in);
    assigns *out;
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE
                || \result == CBX_EINVAL;
    ensures none: n == 0 ==> (\result == CBX_EINVAL && whole_space(out));
    ensures contain: \forall real x0, x1, x2;
      pt_in(x0, x1, x2, CBX_BV(in, Pre)) ==>
      chain_in{Pre}(p, 0, n, x0, x1, x2, out->lo[0], out->hi[0], out->lo[1], out->hi[1],
                    out->lo[2], out->hi[2]);
*/
cbx_status cbx_transform_box_chain(const cbx_prepared *p, size_t n, const cbx_box *in, cbx_box *out);


/* ---- motion with rotation: translation, rotation, scale keyframes -------
 * The motion between keyframes k0 and k1 at time s in [0, 1] is the map
 *     x -> T(s) + R(s) diag(S(s)) x,
 * T and S interpolated linearly ((1 - s) k0 + s k1), R the rotation of
 * slerp (or nlerp) from q0 / |q0| to q1 / |q1|, q1 negated first when the
 * exact dot product q0.q1 is negative (the renderers' shorter arc); where
 * the computed dot product cannot decide its sign, both arcs are covered.
 *
 * cbx_motion_trs_box: *out contains the image of every real point of the
 * box under the motion at every real s in [s0, s1] (0 <= s0 <= s1 <= 1).
 * The shutter [s0, s1] is covered by about 2^depth dyadic cells (depth
 * <= 16; 2^depth to 2^(depth+1) + 1 of them); each contributes the box of
 * an interval matrix enclosing every map of the cell (cbx_trs_pieces), so
 * the excess about halves per extra level (docs/guide.md: 3.4% of the
 * box's side at 16 cells for a 90-degree turn).  Tested against MPFR
 * (tests/test_trs.c); partly proven: each cell's box is
 * cbx_transform_box_imat's, and its interval arithmetic, rotation
 * matrices, quaternion normalisation and arc boxes are proven; the
 * bisection walk and the cells' loop are not yet.  Status and
 * output:
 *   NaN in a keyframe, s0, s1 or *in; s0, s1 not 0 <= s0 <= s1 <= 1;
 *   depth > 16; a zero quaternion      -> CBX_EINVAL, *out the whole space
 *   a translation above 2^500, a scale above 2^250 or a quaternion
 *   component above 2^250 in magnitude, or a quaternion whose largest
 *   component is below 2^-120 (or any infinite entry)
 *                                      -> CBX_ERANGE, *out the whole space
 *   an axis of *in with no real point  -> CBX_EMPTY, *out empty
 *   otherwise CBX_OK, or CBX_ERANGE on the axes cbx_transform_box_imat
 *   leaves whole (an infinite box end, box ends above 2^509).
 * out may be in itself. */
cbx_status cbx_motion_trs_box(const cbx_trs *k0, const cbx_trs *k1, cbx_interp mode, double s0, double s1,
                              unsigned depth, const cbx_box *in, cbx_box *out);

/* cbx_motion_trs_path: the same over keyframes keys[0..n-1] at the evenly
 * spaced times i / (n - 1) (Embree's time steps), each segment cut into
 * 2^depth cells; n = 1 is a still keyframe, n = 0 CBX_EINVAL. */
cbx_status cbx_motion_trs_path(const cbx_trs *keys, size_t n, cbx_interp mode, double s0, double s1,
                               unsigned depth, const cbx_box *in, cbx_box *out);

/* cbx_trs_pieces: the interval matrices of those cells, once for many
 * boxes: pieces[k] encloses every map of the motion at every s of its cell
 * within [s0, s1].  *count is how many were written (at most
 * 2^(depth+1) + 1); CBX_EINVAL (and none) when more than cap are needed, with
 * the statuses above otherwise.  cbx_transform_box_pieces: the hull of
 * cbx_transform_box_imat over n pieces (n = 0: CBX_EINVAL, whole space),
 * the most severe status met (CBX_EINVAL: whole space, CBX_EMPTY: empty). */
/* cbx_motion_trs_ball: the same for the ball |x - c| <= |r| (object
 * space): *out contains T(s) + R(s) diag(S(s)) x for every such x and
 * every s in [s0, s1].  Statuses as cbx_motion_trs_box, with c and r
 * (NaN: CBX_EINVAL; above 2^500 in magnitude: CBX_ERANGE) in place of the
 * box.  cbx_ball_pieces: the same from prepared pieces (n = 0: CBX_EINVAL). */
cbx_status cbx_motion_trs_ball(const cbx_trs *k0, const cbx_trs *k1, cbx_interp mode, double s0, double s1,
                               unsigned depth, const double c[3], double r, cbx_box *out);
cbx_status cbx_ball_pieces(const cbx_imat *pieces, size_t n, const double c[3], double r, cbx_box *out);

cbx_status cbx_trs_pieces(const cbx_trs *k0, const cbx_trs *k1, cbx_interp mode, double s0, double s1,
                          unsigned depth, cbx_imat *pieces, size_t cap, size_t *count);
cbx_status cbx_transform_box_pieces(const cbx_imat *pieces, size_t n, const cbx_box *in, cbx_box *out);

/* ---- a ball under a projective map (a camera's projection) -------------
 * cbx_project_sphere: the box of {(X_0/W, X_1/W, X_2/W)} over every real
 * point of the ball |x - c| <= |r|, X_i = m[i][0] x + m[i][1] y +
 * m[i][2] z + m[i][3] and W row 3 (the projected sphere's screen or NDC
 * box: the bound of its outline, an ellipse, in closed form; Mara and
 * McGuire, JCGT 2013).  Each end is the exact end of the image rounded
 * outward and certified in outward-rounded interval arithmetic.  Proven
 * (specs/cbx_psph.h: ps_axis, ps_tight): with CBX_OK, W > 0 at every real
 * point of the ball and lo_i W <= X_i <= hi_i W there, and some point has
 * X_i / W above hi_i - 2^-20 (1 + |hi_i|) (below lo_i + 2^-20 (1 + |lo_i|));
 * measured, the ends are within a few units in the last place
 * (tests/test_psphere.c).
 *   NaN in *p, c or r                   -> CBX_EINVAL, *out the whole space
 *   a linear entry, a center coordinate or r above 2^60 in magnitude, a
 *   translation above 2^120 (or infinite)
 *                                       -> CBX_ERANGE, *out the whole space
 *   the ball not clear of the camera plane W = 0 (W's least value on it,
 *   enclosed, not above 0; always when the ball touches or crosses the
 *   plane or lies behind it: proven) -> CBX_EBEHIND, *out the whole space
 *   an end above 2^99 in magnitude, W(c)^2 - r^2 |(m30, m31, m32)|^2 below
 *   2^-400, or an end that cannot be certified within 2^-20 (about 2^-48
 *   of the rows' magnitudes at c above 2^-22 of W's least value on the
 *   ball: a ball very near the camera plane for its distance from the
 *   origin)
 *                                       -> CBX_ERANGE, *out the whole space
 * Binary64 (binary32 twin: cbx_project_spheref, below).  *out may not
 * overlap *p or c. */
/*@ requires valid: \valid_read(p) && \valid_read(c + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, p) && \separated(out, c + (0 .. 2));
    assigns *out;
    behavior nan_input:
      assumes ps_nan(p, c, r);
      ensures \result == CBX_EINVAL && whole_space(out);
    behavior ball_input:
      assumes !ps_nan(p, c, r);
      ensures st: \result == CBX_OK || \result == CBX_ERANGE || \result == CBX_EBEHIND;
      ensures whole: \result != CBX_OK ==> whole_space(out);
      ensures dom: \result != CBX_ERANGE ==> \old(ps_dom(p, c, r));
      ensures behind: \old(ps_dom(p, c, r))
        && !ps_front(\old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                     \old(c[0]), \old(c[1]), \old(c[2]), r) ==> \result == CBX_EBEHIND;
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && ps_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]), \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r)
        && ps_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]), \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r);
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && ps_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]), \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r)
        && ps_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]), \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r);
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && ps_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]), \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r)
        && ps_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]), \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_sphere(const cbx_proj *p, const double c[3], double r, cbx_box *out);

/* ---- a box under a projective map, clipped at a near plane -------------
 * cbx_project_box_near: the box of {(X_0/W, X_1/W, X_2/W)} over the real
 * points of the box *in with W >= wn (the part in front of the near plane
 * W = wn > 0; X_i and W the rows of *p as for cbx_project_box).  A box
 * that crosses or lies behind the camera plane gets the bound of its
 * visible part instead of CBX_EBEHIND.  The exact ends are at the corners
 * in front and at the crossings of the box's edges with the near plane;
 * each is computed in round-to-nearest and certified in outward-rounded
 * interval arithmetic (a Lagrangian certificate: X - s W <= (t - s) wn on
 * the whole box).  Proven (specs/cbx_pnear.h: pn_axis, pn_tight): with
 * CBX_OK, lo_i W <= X_i <= hi_i W at every real point of the box with
 * W >= wn, and some such point has X_i / W above hi_i - 2^-20 (1 + |hi_i|)
 * (below lo_i + 2^-20 (1 + |lo_i|)); measured (tests/test_pnear.c), the
 * median end is 66 units of 2^-52 (1 + |end|) from the exact end, the
 * worst about 2^-22 relative, where W varies over the box far more than
 * wn (the certificate's rounding against a slack of d wn).
 *   NaN in *p, *in or wn               -> CBX_EINVAL, *out the whole space
 *   an axis of *in with no point       -> CBX_EMPTY,  *out empty
 *   a linear entry or a box end above 2^60 in magnitude, a translation
 *   above 2^120 (or infinite), wn outside [2^-100, 2^120] (wn <= 0
 *   included)                          -> CBX_ERANGE, *out the whole space
 *   W < wn on the whole box (certified: nothing in front of the near
 *   plane; proven)                     -> CBX_EMPTY,  *out empty
 *   an end above 2^99 in magnitude, or one that cannot be certified
 *   within 2^-20 (measured: only where W's magnitude on the box is above
 *   about 2^16 wn, the near plane close to the rounding of W there)
 *                                      -> CBX_ERANGE, *out the whole space
 * Binary64 (twin: cbx_project_box_nearf).  out may be in itself;
 * otherwise *out may not overlap *p or *in. */
/*@ requires valid: \valid_read(p) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, p) && (\separated(out, in) || out == in);
    assigns *out;
    behavior nan_input:
      assumes proj_nan(p) || box_nan(in) || \is_NaN(wn);
      ensures \result == CBX_EINVAL && whole_space(out);
    behavior empty_input:
      assumes !proj_nan(p) && !box_nan(in) && !\is_NaN(wn) && is_empty(in);
      ensures \result == CBX_EMPTY && empty_out(out);
    behavior box_input:
      assumes !proj_nan(p) && !box_nan(in) && !\is_NaN(wn) && !is_empty(in);
      ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE;
      ensures whole: \result == CBX_ERANGE ==> whole_space(out);
      ensures dom: \result != CBX_ERANGE ==> \old(pn_dom(p, in, wn));
      ensures void: \result == CBX_EMPTY ==> empty_out(out)
        && pn_void(wn, \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                   \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]));
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && pn_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                   \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn)
        && pn_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                    \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                    \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn);
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && pn_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                   \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn)
        && pn_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                    \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                    \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn);
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && pn_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                   \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn)
        && pn_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                    \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                    \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_box_near(const cbx_proj *p, const cbx_box *in, double wn, cbx_box *out);

/* ---- a ball under a projective map, clipped at a near plane ------------
 * cbx_project_sphere_near: the box of {(X_0/W, X_1/W, X_2/W)} over the
 * real points of the ball |x - c| <= |r| with W >= wn (the part in front
 * of the near plane W = wn > 0; X_i and W the rows of *p as for
 * cbx_project_sphere).  A ball that touches, crosses or lies behind the
 * camera plane gets the bound of its visible part instead of CBX_EBEHIND.
 * The exact ends are at the tangent points of the unclipped bound when
 * they are in front, otherwise on the circle where the near plane cuts the
 * ball; each is computed in closed form in round-to-nearest and certified
 * in outward-rounded interval arithmetic (a Lagrangian certificate:
 * X - s W <= (t - s) wn on the whole ball).  Proven (specs/cbx_pball.h:
 * pb_axis, pb_tight): with CBX_OK, lo_i W <= X_i <= hi_i W at every real
 * point of the ball with W >= wn, and some such point has X_i / W above
 * hi_i - 2^-20 (1 + |hi_i|) (below lo_i + 2^-20 (1 + |lo_i|)); measured
 * (tests/test_pball.c), the median end is 63 units of 2^-52 (1 + |end|)
 * from the exact end, the worst about 2^-22 relative: the depth row of a
 * camera (X parallel to W) on a ball the near plane cuts, where the end
 * sits at a kink of the certificate and the rounding of its multiplier
 * costs first-order error.
 *   NaN in *p, c, r or wn               -> CBX_EINVAL, *out the whole space
 *   a linear entry, a center coordinate or r above 2^60 in magnitude, a
 *   translation above 2^120 (or infinite), wn outside [2^-100, 2^120]
 *   (wn <= 0 included)                  -> CBX_ERANGE, *out the whole space
 *   W < wn on the whole ball (certified: nothing in front of the near
 *   plane; proven)                      -> CBX_EMPTY,  *out empty
 *   an end above 2^99 in magnitude, or one that cannot be certified
 *   within 2^-20                        -> CBX_ERANGE, *out the whole space
 * Binary64 (twin: cbx_project_sphere_nearf).  *out may not overlap *p
 * or c. */
/*@ requires valid: \valid_read(p) && \valid_read(c + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, p) && \separated(out, c + (0 .. 2));
    assigns *out;
    behavior nan_input:
      assumes pb_nan(p, c, r, wn);
      ensures \result == CBX_EINVAL && whole_space(out);
    behavior ball_input:
      assumes !pb_nan(p, c, r, wn);
      ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE;
      ensures whole: \result == CBX_ERANGE ==> whole_space(out);
      ensures dom: \result != CBX_ERANGE ==> \old(pb_dom(p, c, r, wn));
      ensures void: \result == CBX_EMPTY ==> empty_out(out)
        && pb_void(wn, \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                   \old(c[0]), \old(c[1]), \old(c[2]), r);
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && pb_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn)
        && pb_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                    \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn);
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && pb_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn)
        && pb_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                    \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn);
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && pb_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn)
        && pb_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                    \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_sphere_near(const cbx_proj *p, const double c[3], double r, double wn, cbx_box *out);

/* ---- an ellipsoid under a projective map --------------------------------
 * cbx_project_ellipsoid: the box of {(X_0/W, X_1/W, X_2/W)} over every real
 * point of the ellipsoid center + rot * diag(radii) * q, |q| <= 1 (as
 * cbx_ellipsoid_box: rot need not be orthogonal, radii may be negative or
 * zero), X_i and W the rows of *p as for cbx_project_sphere: the projected
 * ellipsoid's screen or NDC box, the bound of its outline (a conic) in
 * closed form.  In the ellipsoid's frame it is the unit ball under the rows
 * M^T X, M = rot * diag(radii), so the method and the guarantees are those
 * of cbx_project_sphere; M^T X is never rounded (every enclosure is of the
 * exact value).  Proven (specs/cbx_pell.h: pe_axis, pe_tight): with CBX_OK,
 * W > 0 at every real point of the ellipsoid and lo_i W <= X_i <= hi_i W
 * there, and some point has X_i / W above hi_i - 2^-20 (1 + |hi_i|) (below
 * lo_i + 2^-20 (1 + |lo_i|)); measured, the ends are within a few units in
 * the last place (tests/test_pell.c).
 *   NaN in *p, center, radii or rot     -> CBX_EINVAL, *out the whole space
 *   a linear entry of *p or a center coordinate above 2^60 in magnitude, a
 *   translation above 2^120, an entry of rot or a radius above 2^30 (or
 *   infinite)                           -> CBX_ERANGE, *out the whole space
 *   the ellipsoid not clear of the camera plane W = 0 (W's least value on
 *   it, enclosed, not above 0; always when it touches or crosses the plane
 *   or lies behind it: proven)          -> CBX_EBEHIND, *out the whole space
 *   an end above 2^99 in magnitude, or one that cannot be certified within
 *   2^-20 (an ellipsoid very near the camera plane for its distance from
 *   the origin, as for cbx_project_sphere)
 *                                       -> CBX_ERANGE, *out the whole space
 * Binary64 (binary32 twin: cbx_project_ellipsoidf, below).  *out may not
 * overlap the inputs. */
/*@ requires valid: \valid_read(p) && \valid_read(center + (0 .. 2)) && \valid_read(radii + (0 .. 2))
                    && \valid_read(rot + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, p) && \separated(out, center + (0 .. 2))
                  && \separated(out, radii + (0 .. 2)) && \separated(out, rot + (0 .. 2));
    assigns *out;
    behavior nan_input:
      assumes pe_nan(p, center, radii, rot);
      ensures \result == CBX_EINVAL && whole_space(out);
    behavior ellipsoid_input:
      assumes !pe_nan(p, center, radii, rot);
      ensures st: \result == CBX_OK || \result == CBX_ERANGE || \result == CBX_EBEHIND;
      ensures whole: \result != CBX_OK ==> whole_space(out);
      ensures dom: \result != CBX_ERANGE ==> \old(pe_dom(p, center, radii, rot));
      ensures behind: \old(pe_dom(p, center, radii, rot))
        && !pe_front(\old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
                     \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
                     \old(radii[0]), \old(radii[1]), \old(radii[2])) ==> \result == CBX_EBEHIND;
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && pe_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]))
        && pe_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]));
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && pe_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]))
        && pe_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]));
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && pe_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]))
        && pe_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_ellipsoid(const cbx_proj *p, const double center[3], const double radii[3],
                                 const double rot[3][3], cbx_box *out);

#endif /* binary64 only */

/* ---- binary32 twins of the binary64-only projective bounds ------------
 * cbx_project_spheref, cbx_project_box_nearf, cbx_project_sphere_nearf,
 * cbx_project_ellipsoidf: the bounds of cbx_project_sphere,
 * cbx_project_box_near, cbx_project_sphere_near and cbx_project_ellipsoid
 * for float inputs, with the same statuses, special
 * cases and domain (read on the float values).  Each widens its inputs to
 * double (exact), calls the binary64 function and rounds each end outward
 * to float: at most 2^-22 |end| + 2^-147 further out (one or two units in
 * the last place of float).  Proven (specs/cbx_pwide.h) on the binary64
 * contracts: with CBX_OK, the same containment of every real point
 * (ps_axis, pn_axis, pb_axis on the float values) and tightness within
 * 2^-19 (1 + |end|) (twice the binary64 slack; psf_tight, pnf_tight,
 * pbf_tight).  An end of the binary64 result above 2^100 in magnitude
 * (never returned with CBX_OK: such ends give CBX_ERANGE there) would give
 * CBX_ERANGE and the whole space.  They need the binary64 arithmetic of the
 * machine (no binary32-only path).  *out may not overlap the inputs
 * (cbx_project_box_nearf: out may be in itself). */
#if !defined(__FRAMAC__) || (!defined(CBX_FRAMAC_ONLY_32) && !defined(CBX_FRAMAC_ONLY_64))
/*@ requires valid: \valid_read(p) && \valid_read(c + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, p) && \separated(out, c + (0 .. 2));
    assigns *out;
    behavior nan_input:
      assumes psf_nan(p, c, r);
      ensures \result == CBX_EINVAL && whole_space_f(out);
    behavior ball_input:
      assumes !psf_nan(p, c, r);
      ensures st: \result == CBX_OK || \result == CBX_ERANGE || \result == CBX_EBEHIND;
      ensures whole: \result != CBX_OK ==> whole_space_f(out);
      ensures dom: \result != CBX_ERANGE ==> \old(psf_dom(p, c, r));
      ensures behind: \old(psf_dom(p, c, r))
        && !ps_front(\old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                     \old(c[0]), \old(c[1]), \old(c[2]), r) ==> \result == CBX_EBEHIND;
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && ps_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r)
        && psf_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r);
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && ps_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r)
        && psf_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r);
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && ps_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r)
        && psf_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_spheref(const cbx_projf *p, const float c[3], float r, cbx_boxf *out);

/* cbx_project_box_nearf: cbx_project_box_near for float inputs (above). */
/*@ requires valid: \valid_read(p) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, p) && (\separated(out, in) || out == in);
    assigns *out;
    behavior nan_input:
      assumes pnf_nan(p, in, wn);
      ensures \result == CBX_EINVAL && whole_space_f(out);
    behavior empty_input:
      assumes !pnf_nan(p, in, wn) && is_empty_f(in);
      ensures \result == CBX_EMPTY && empty_out_f(out);
    behavior box_input:
      assumes !pnf_nan(p, in, wn) && !is_empty_f(in);
      ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE;
      ensures whole: \result == CBX_ERANGE ==> whole_space_f(out);
      ensures dom: \result != CBX_ERANGE ==> \old(pnf_dom(p, in, wn));
      ensures void: \result == CBX_EMPTY ==> empty_out_f(out)
        && pn_void(wn, \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                   \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]));
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && pn_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn)
        && pnf_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn);
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && pn_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn)
        && pnf_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn);
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && pn_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn)
        && pnf_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(in->lo[0]), \old(in->hi[0]), \old(in->lo[1]), \old(in->hi[1]), \old(in->lo[2]), \old(in->hi[2]), wn);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_box_nearf(const cbx_projf *p, const cbx_boxf *in, float wn, cbx_boxf *out);

/* cbx_project_sphere_nearf: cbx_project_sphere_near for float inputs
 * (above). */
/*@ requires valid: \valid_read(p) && \valid_read(c + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, p) && \separated(out, c + (0 .. 2));
    assigns *out;
    behavior nan_input:
      assumes pbf_nan(p, c, r, wn);
      ensures \result == CBX_EINVAL && whole_space_f(out);
    behavior ball_input:
      assumes !pbf_nan(p, c, r, wn);
      ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE;
      ensures whole: \result == CBX_ERANGE ==> whole_space_f(out);
      ensures dom: \result != CBX_ERANGE ==> \old(pbf_dom(p, c, r, wn));
      ensures void: \result == CBX_EMPTY ==> empty_out_f(out)
        && pb_void(wn, \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]),
                   \old(c[0]), \old(c[1]), \old(c[2]), r);
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && pb_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn)
        && pbf_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn);
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && pb_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn)
        && pbf_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn);
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && pb_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn)
        && pbf_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
                   \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(c[0]), \old(c[1]), \old(c[2]), r, wn);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_sphere_nearf(const cbx_projf *p, const float c[3], float r, float wn, cbx_boxf *out);

/* cbx_project_ellipsoidf: cbx_project_ellipsoid for float inputs (above;
 * binary64 section): the same statuses and domain on the float values,
 * each end of the binary64 bound rounded outward to float; tightness
 * within 2^-19 (1 + |end|) (pef_tight). */
/*@ requires valid: \valid_read(p) && \valid_read(center + (0 .. 2)) && \valid_read(radii + (0 .. 2))
                    && \valid_read(rot + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, p) && \separated(out, center + (0 .. 2))
                  && \separated(out, radii + (0 .. 2)) && \separated(out, rot + (0 .. 2));
    assigns *out;
    behavior nan_input:
      assumes pef_nan(p, center, radii, rot);
      ensures \result == CBX_EINVAL && whole_space_f(out);
    behavior ellipsoid_input:
      assumes !pef_nan(p, center, radii, rot);
      ensures st: \result == CBX_OK || \result == CBX_ERANGE || \result == CBX_EBEHIND;
      ensures whole: \result != CBX_OK ==> whole_space_f(out);
      ensures dom: \result != CBX_ERANGE ==> \old(pef_dom(p, center, radii, rot));
      ensures behind: \old(pef_dom(p, center, radii, rot))
        && !pe_front(\old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
                     \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
                     \old(radii[0]), \old(radii[1]), \old(radii[2])) ==> \result == CBX_EBEHIND;
      ensures ok0: \result == CBX_OK ==> \is_finite(out->lo[0]) && \is_finite(out->hi[0])
        && pe_axis(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]))
        && pef_tight(out->lo[0], out->hi[0], \old(p->m[0][0]), \old(p->m[0][1]), \old(p->m[0][2]), \old(p->m[0][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]));
      ensures ok1: \result == CBX_OK ==> \is_finite(out->lo[1]) && \is_finite(out->hi[1])
        && pe_axis(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]))
        && pef_tight(out->lo[1], out->hi[1], \old(p->m[1][0]), \old(p->m[1][1]), \old(p->m[1][2]), \old(p->m[1][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]));
      ensures ok2: \result == CBX_OK ==> \is_finite(out->lo[2]) && \is_finite(out->hi[2])
        && pe_axis(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]))
        && pef_tight(out->lo[2], out->hi[2], \old(p->m[2][0]), \old(p->m[2][1]), \old(p->m[2][2]), \old(p->m[2][3]),
          \old(p->m[3][0]), \old(p->m[3][1]), \old(p->m[3][2]), \old(p->m[3][3]), \old(center[0]), \old(center[1]), \old(center[2]),
          \old(rot[0][0]), \old(rot[0][1]), \old(rot[0][2]), \old(rot[1][0]), \old(rot[1][1]), \old(rot[1][2]), \old(rot[2][0]), \old(rot[2][1]), \old(rot[2][2]),
          \old(radii[0]), \old(radii[1]), \old(radii[2]));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_ellipsoidf(const cbx_projf *p, const float center[3], const float radii[3],
                                  const float rot[3][3], cbx_boxf *out);
#endif /* binary32 twins */

/* ---- the build check ---------------------------------------------------
 * The proofs assume every C operation rounds once, to nearest, in its own
 * format (binary64 or binary32), with gradual underflow, infinities, NaN
 * and signed zeros.  cbx_ieee_check() tests, at run time and in both
 * formats, that this build of the library computes that way: it runs known
 * cases through the library's own rounding primitives, compiled with the
 * library's flags, and returns 0 when all hold, else the CBX_IEEE_* bits of
 * the failed checks.  It also checks what the proofs trust: sqrt and sqrtf
 * correctly rounded, division correctly rounded (the projective bounds), the error-free transformations of the tight mode exact
 * (cbx_two_sum, cbx_two_prod in the form this build selected: fma or
 * Dekker, src/core/cbx_eft.h) and, where two_prod calls it, fma correctly
 * rounded: all on hard cases (src/core/cbx_ieee_cases.h).  Call it once at
 * start-up (a power-on self-test); make check runs it.  Not part of the
 * proven set: it tests the build.  No allocation, no state. */
#define CBX_IEEE_CONTRACT 0x01u /* a*b + c fused into an FMA (-ffp-contract=fast) */
#define CBX_IEEE_EXCESS   0x02u /* excess precision or range (x87, FLT_EVAL_METHOD != 0) */
#define CBX_IEEE_FTZ      0x04u /* subnormals flushed to zero (FTZ/DAZ modes) */
#define CBX_IEEE_ROUNDING 0x08u /* a rounding mode other than to nearest */
#define CBX_IEEE_SPECIAL  0x10u /* NaN, infinity or -0 not IEEE (-ffinite-math-only, ...) */
#define CBX_IEEE_ASSOC    0x20u /* operations reassociated (-fassociative-math) */
#define CBX_IEEE_FMA      0x40u /* fma not correctly rounded (builds whose two_prod calls fma) */
#define CBX_IEEE_SQRT     0x80u /* sqrt or sqrtf not correctly rounded on hard cases */
#define CBX_IEEE_EFT      0x100u /* two_sum or two_prod (fma or Dekker form) not exact */
#define CBX_IEEE_DIV      0x200u /* division not correctly rounded on hard cases */
unsigned cbx_ieee_check(void);

/* Human-readable name of a status ("CBX_OK", ...). */
const char *cbx_status_name(cbx_status s);

#ifdef __cplusplus
}
#endif
#endif /* CERTBOX_H */
