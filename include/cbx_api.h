/*
 * The public API of one floating-point family, written once for binary64
 * (double) and instantiated for binary32 (float) by certbox.h: in the
 * float family every type and function name ends in f (cbx_affinef,
 * cbx_boxf, cbx_cboxf, cbx_transform_boxf, cbx_transform_boxesf,
 * cbx_transform_cboxf, cbx_box_to_cboxf, cbx_cbox_to_boxf,
 * cbx_sphere_boxf, cbx_ellipsoid_boxf), the arguments are float, and the
 * constants of the statements are binary32's: u = 2^-24 instead of 2^-53,
 * eta = 2^-149 instead of 2^-1074, and the domain bounds given in
 * parentheses below (2^122 where binary64 has 2^1018).  The contracts
 * (ACSL, proven by Frama-C/WP for both families) use the logic of
 * specs/cbx_spec.h in the same way.
 *
 * Do not include this file directly: include certbox.h.  No include guard
 * (certbox.h includes it once per family, between cbx_prec_begin.h and
 * cbx_prec_end.h).
 */

/* Transform an axis-aligned box by an affine map (Arvo's interval form,
 * outward rounded).  Status and output:
 *   NaN anywhere in *a or *in       -> CBX_EINVAL, *out = [-inf, +inf]^3
 *   lo[j] > hi[j] for some j        -> CBX_EMPTY,  *out = lo +inf, hi -inf
 *   some axis outside the domain    -> CBX_ERANGE, that axis [-inf, +inf]
 * (the domain and the proven statement: certbox.h's header comment; in the
 * float family the bounds 2^1018, 2^509 become 2^122, 2^61, u = 2^-24 and
 * the tightness term 2^-1065 becomes 2^-140)
 *   otherwise                       -> CBX_OK, every axis proven sound
 * out may be in itself (in-place update); otherwise *out may not overlap
 * *a or *in.  The contract's behaviors are CBX_BOX_BEHAVIORS
 * (specs/cbx_logic.h), the one statement of this promise, which the
 * prepared, class and tight forms share. */
/*@ requires valid_a:   \valid_read(a);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    assigns *out;
    CBX_BOX_BEHAVIORS(a, in, out)
*/
cbx_status cbx_transform_box(const cbx_affine *a, const cbx_box *in, cbx_box *out);

/* Batch form: out[k] = the box of in[k] under *a, for k = 0 .. n-1, each with
 * cbx_transform_box's promise (proven for every k).  binary64: the map is
 * classified once and every box goes through the class kernel, so out[k]
 * is exactly cbx_transform_box_as(a, cbx_classify(a), in + k, out + k)'s
 * output; binary32: out[k] is exactly cbx_transform_boxf(a, in + k, out + k)'s.
 * Returns the most severe status met (CBX_EINVAL, then CBX_ERANGE, then
 * CBX_EMPTY, then CBX_OK; CBX_OK when n == 0).  Every out[k] is written.
 * The arrays in and out may not overlap, and out may not overlap *a. */
/*@ requires valid: \valid_read(a) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), a) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    assigns out[0 .. n - 1];
    CBX_BATCH_POST(a)
*/
cbx_status cbx_transform_boxes(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t n);

/* ---- prepared maps: the per-map work done once -------------------------
 * cbx_prepare copies the map into *p and records whether it lies in the
 * fast range (the one check per map) and, in binary64, its class
 * (cbx_classify).  cbx_transform_box_prep then checks only the box (one
 * check per box) and runs the branch-free kernel, or the class kernel, or
 * the careful path: the same statuses, special outputs and promise as
 * cbx_transform_box on p->a (proven).  The class is checked against the
 * map where it is used (a wrong class falls back to the general kernel),
 * so only the fast flag is taken from *p: it must come from cbx_prepare (or
 * be 0, as in a zero-initialised struct).  cbx_transform_boxes_prep is the
 * batch form: it checks the fast flag and the class again once per call,
 * so even a *p changed by hand gives sound boxes; then every box as
 * cbx_transform_box_prep.  Its promise is cbx_transform_boxes' on p->a. */
/*@ requires valid: \valid_read(a) && \valid(p) && \separated(a, p);
    assigns *p;
    ensures copy: p->a.m[0][0] == \at(a->m[0][0], Pre) && p->a.m[0][1] == \at(a->m[0][1], Pre)
      && p->a.m[0][2] == \at(a->m[0][2], Pre) && p->a.m[0][3] == \at(a->m[0][3], Pre)
      && p->a.m[1][0] == \at(a->m[1][0], Pre) && p->a.m[1][1] == \at(a->m[1][1], Pre)
      && p->a.m[1][2] == \at(a->m[1][2], Pre) && p->a.m[1][3] == \at(a->m[1][3], Pre)
      && p->a.m[2][0] == \at(a->m[2][0], Pre) && p->a.m[2][1] == \at(a->m[2][1], Pre)
      && p->a.m[2][2] == \at(a->m[2][2], Pre) && p->a.m[2][3] == \at(a->m[2][3], Pre);
    ensures prep: prepared(p);
*/
void cbx_prepare(const cbx_affine *a, cbx_prepared *p);

/*@ requires valid_p:   \valid_read(p);
    requires valid_in:  \valid_read(in);
    requires valid_out: \valid(out);
    requires sep: \separated(out, p) && (\separated(out, in) || out == in);
    requires prep: prepared(p);
    assigns *out;
    CBX_BOX_BEHAVIORS(&p->a, in, out)
*/
cbx_status cbx_transform_box_prep(const cbx_prepared *p, const cbx_box *in, cbx_box *out);

/*@ requires valid: \valid_read(p) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), p) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    assigns out[0 .. n - 1];
    CBX_BATCH_POST(&p->a)
*/
cbx_status cbx_transform_boxes_prep(const cbx_prepared *p, const cbx_box *in, cbx_box *out, size_t n);

/* ---- the 2D form: boxes of the plane under 2x3 affine maps --------------
 * cbx_transform_box2: the box [lo_0, hi_0] x [lo_1, hi_1] under the map
 * y_i = m[i][0] x_0 + m[i][1] x_1 + m[i][2] (Arvo's interval form, outward
 * rounded), with cbx_transform_box's statuses, special outputs, domain and
 * proven statement on each of its two axes: each axis is the 3D axis with
 * a zero third column and a third box axis [0, 0] (specs/cbx_plane.h), so
 * for every real point of the box the exact image lies in [lo_i, hi_i],
 * each finite end within 12 u S + 2^-1065 of the exact end (binary32:
 * 12 u S + 2^-140), CBX_OK exactly when both rows are full.
 *   NaN anywhere in *a or *in       -> CBX_EINVAL, *out = [-inf, +inf]^2
 *   lo[j] > hi[j] for some j        -> CBX_EMPTY,  *out = lo +inf, hi -inf
 *   some axis outside the domain    -> CBX_ERANGE, that axis bounded as in
 *                                      the 3D form (or [-inf, +inf])
 * out may be in itself; otherwise *out may not overlap *a or *in. */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    assigns *out;
    behavior nan_input:
      assumes has_nan2(a, in);
      ensures \result == CBX_EINVAL;
      ensures whole_plane(out);
    behavior empty_input:
      assumes !has_nan2(a, in) && is_empty2(in);
      ensures \result == CBX_EMPTY;
      ensures empty_out2(out);
    behavior box_input:
      assumes !has_nan2(a, in) && !is_empty2(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: axis2_sound(out->lo[0], out->hi[0],
        \at(a->m[0][0], Pre), \at(a->m[0][1], Pre), \at(a->m[0][2], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre));
      ensures axis1: axis2_sound(out->lo[1], out->hi[1],
        \at(a->m[1][0], Pre), \at(a->m[1][1], Pre), \at(a->m[1][2], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre));
      ensures ok_iff: \result == CBX_OK <==> \at(row2_ok(a, in, 0) && row2_ok(a, in, 1), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_transform_box2(const cbx_affine2 *a, const cbx_box2 *in, cbx_box2 *out);

/* cbx_transform_cbox2: the center/half-diagonal form of the plane,
 * c' = M c + T, h' = |M| h outward, with cbx_transform_cbox's statuses,
 * special outputs, domain and proven statement on each of its two axes
 * (the 3D axis with a zero third column and c_2 = h_2 = 0,
 * specs/cbx_plane.h).  out may be in itself. */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    assigns *out;
    behavior nan_input:
      assumes cbox2_has_nan(a, in);
      ensures \result == CBX_EINVAL && cwhole2(out);
    behavior empty_input:
      assumes !cbox2_has_nan(a, in) && cbox2_empty(in);
      ensures \result == CBX_EMPTY && cempty2(out);
    behavior box_input:
      assumes !cbox2_has_nan(a, in) && !cbox2_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: caxis2_sound(out->c[0], out->h[0],
        \at(a->m[0][0], Pre), \at(a->m[0][1], Pre), \at(a->m[0][2], Pre),
        \at(in->c[0], Pre), \at(in->c[1], Pre), \at(in->h[0], Pre), \at(in->h[1], Pre));
      ensures axis1: caxis2_sound(out->c[1], out->h[1],
        \at(a->m[1][0], Pre), \at(a->m[1][1], Pre), \at(a->m[1][2], Pre),
        \at(in->c[0], Pre), \at(in->c[1], Pre), \at(in->h[0], Pre), \at(in->h[1], Pre));
      ensures ok_iff: \result == CBX_OK <==> \at(crow2_ok(a, in, 0) && crow2_ok(a, in, 1), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_transform_cbox2(const cbx_affine2 *a, const cbx_cbox2 *in, cbx_cbox2 *out);

/* The conversions of the plane, with cbx_box_to_cbox's and
 * cbx_cbox_to_box's statuses, special outputs, domain and statement on
 * each of their two axes (b2c_v, c2b_v: specs/cbx_spec.h). */
/*@ requires valid: \valid_read(in) && \valid(out);
    requires sep: \separated(out, in);
    assigns *out;
    behavior nan_input:
      assumes box2_nan(in);
      ensures \result == CBX_EINVAL && cwhole2(out);
    behavior empty_input:
      assumes !box2_nan(in) && is_empty2(in);
      ensures \result == CBX_EMPTY && cempty2(out);
    behavior box_input:
      assumes !box2_nan(in) && !is_empty2(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures ax0: b2c_v(in->lo[0], in->hi[0], out->c[0], out->h[0]);
      ensures ax1: b2c_v(in->lo[1], in->hi[1], out->c[1], out->h[1]);
      ensures ok_iff: \result == CBX_OK <==> (conv_in(in->lo[0], in->hi[0]) && conv_in(in->lo[1], in->hi[1]));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_box2_to_cbox2(const cbx_box2 *in, cbx_cbox2 *out);

/*@ requires valid: \valid_read(in) && \valid(out);
    requires sep: \separated(out, in);
    assigns *out;
    behavior nan_input:
      assumes cbox2_nan(in);
      ensures \result == CBX_EINVAL && whole_plane(out);
    behavior empty_input:
      assumes !cbox2_nan(in) && cbox2_empty(in);
      ensures \result == CBX_EMPTY && empty_out2(out);
    behavior box_input:
      assumes !cbox2_nan(in) && !cbox2_empty(in);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures ax0: c2b_v(in->c[0], in->h[0], out->lo[0], out->hi[0]);
      ensures ax1: c2b_v(in->c[1], in->h[1], out->lo[1], out->hi[1]);
      ensures ok_iff: \result == CBX_OK <==> (conv_in(in->c[0], in->h[0]) && conv_in(in->c[1], in->h[1]));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_cbox2_to_box2(const cbx_cbox2 *in, cbx_box2 *out);

/* cbx_disk_box2: the image of the unit disk {p : p_0^2 + p_1^2 <= 1} under
 * the 2D map: axis i is m[i][2] -+ sqrt(m[i][0]^2 + m[i][1]^2), rounded
 * outward (the dual conic; the sphere's kernel with a zero third entry).
 * cbx_ellipse_box2: the ellipse center + rot * diag(radii) * p, |p| <= 1
 * (rot need not be orthogonal; radii may be negative or zero).  Domains,
 * statuses and the proven statement are those of cbx_sphere_box and
 * cbx_ellipsoid_box on the plane (specs/cbx_plane.h: disk_axis,
 * ell2_axis): on every axis in the domain, for every real p with
 * p_0^2 + p_1^2 <= 1, lo_i <= (M p + T)_i <= hi_i (exact reals; for the
 * ellipse M_ij = rot[i][j] * radii[j] exactly), and each end within
 * 80 u (|T_i| + |M_i|) + 2^-1064 of the exact end T_i -+ |M_i| (binary32:
 * 2^-139); NaN -> CBX_EINVAL and the whole plane; outside the domain ->
 * CBX_ERANGE and those axes [-inf, +inf]. */
/*@ requires valid: \valid_read(a) && \valid(out) && \separated(a, out);
    assigns *out;
    behavior nan_input:
      assumes aff2_nan(a);
      ensures \result == CBX_EINVAL && whole_plane(out);
    behavior map_input:
      assumes !aff2_nan(a);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: disk_axis(out->lo[0], out->hi[0], a->m[0][0], a->m[0][1], a->m[0][2]);
      ensures axis1: disk_axis(out->lo[1], out->hi[1], a->m[1][0], a->m[1][1], a->m[1][2]);
      ensures ok_iff: \result == CBX_OK <==>
        (disk_dom(a->m[0][0], a->m[0][1], a->m[0][2]) && disk_dom(a->m[1][0], a->m[1][1], a->m[1][2]));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_disk_box2(const cbx_affine2 *a, cbx_box2 *out);

/*@ requires valid: \valid_read(center + (0 .. 1)) && \valid_read(radii + (0 .. 1))
                    && \valid_read(rot + (0 .. 1)) && \valid(out);
    requires sep: \separated(out, center + (0 .. 1)) && \separated(out, radii + (0 .. 1))
                  && \separated(out, rot + (0 .. 1));
    assigns *out;
    behavior nan_input:
      assumes ell2_nan(center, radii, rot);
      ensures \result == CBX_EINVAL && whole_plane(out);
    behavior ellipse_input:
      assumes !ell2_nan(center, radii, rot);
      ensures \result == CBX_OK || \result == CBX_ERANGE;
      ensures axis0: ell2_axis(out->lo[0], out->hi[0], rot[0][0], rot[0][1], radii[0], radii[1], center[0]);
      ensures axis1: ell2_axis(out->lo[1], out->hi[1], rot[1][0], rot[1][1], radii[0], radii[1], center[1]);
      ensures ok_iff: \result == CBX_OK <==>
        (ell2_dom(rot[0][0], rot[0][1], radii[0], radii[1], center[0])
         && ell2_dom(rot[1][0], rot[1][1], radii[0], radii[1], center[1]));
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_ellipse_box2(const cbx_fp center[2], const cbx_fp radii[2],
                            const cbx_fp rot[2][2], cbx_box2 *out);

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
 * input finite with magnitude <= 2^1019 (binary32: 2^123). */

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
      ensures ok_iff: \result == CBX_OK <==> \at(b2c_ok(in), Pre);
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
      ensures ok_iff: \result == CBX_OK <==> \at(c2b_ok(in), Pre);
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_cbox_to_box(const cbx_cbox *in, cbx_box *out);

/* ---- spheres and ellipsoids: exact (dual-quadric) bounds ---------------
 * cbx_sphere_box: the image of the unit ball {p : |p| <= 1} under the affine
 * map: axis i is m[i][3] -+ sqrt(m[i][0]^2 + m[i][1]^2 + m[i][2]^2), rounded
 * outward.  Domain: every entry finite, |m[i][j]| <= 2^509 (j < 3),
 * |m[i][3]| <= 2^1018 (binary32: 2^61 and 2^122).
 * cbx_ellipsoid_box: the ellipsoid center + rot * diag(radii) * p, |p| <= 1
 * (rot need not be orthogonal; radii may be negative or zero).  Domain:
 * |rot[i][j]| <= 2^254, |radii[j]| <= 2^254, |center[i]| <= 2^1018
 * (binary32: 2^30, 2^30 and 2^122).
 * NaN -> CBX_EINVAL and the whole space; outside the domain -> CBX_ERANGE
 * and those axes [-inf, +inf].  Proven: on every axis in the domain, for
 * every real point p with p.p <= 1, lo_i <= (M p + T)_i <= hi_i (exact reals;
 * for the ellipsoid M_ij = rot[i][j] * radii[j] exactly): specs/cbx_ball.h;
 * and each end within 80 u (|T_i| + |M_i|) + 2^-1064 of the exact end
 * T_i -+ |M_i| (|M_i| the exact row norm; binary32: 2^-139): ball_tight. */
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
cbx_status cbx_ellipsoid_box(const cbx_fp center[3], const cbx_fp radii[3],
                             const cbx_fp rot[3][3], cbx_box *out);

/* ---- projective maps (a camera's projection) ----------------------------
 * cbx_project_box: the box of {(X_0/W, X_1/W, X_2/W)} over every real point
 * of the box *in, where X_i = m[i][0] x + m[i][1] y + m[i][2] z + m[i][3]
 * and W is row 3 (NDC or screen space).  Computed at the 8 corners (the
 * image is in their hull where W > 0) with the proven interval kernel and
 * outward-rounded quotients.  Proven (specs/cbx_proj.h: paxis): with
 * CBX_OK, W > 0 at every real point of the box and lo_i <= X_i/W <= hi_i
 * there, every end finite, and each end tight at some corner:
 * |X - end W| <= 24 u (S_X + |end| S_W) + 2^-1064 (1 + |end| + S_W)
 * (S the row's exact magnitude |m0 x| + |m1 y| + |m2 z| + |t| there;
 * binary32: 2^-139).
 *   NaN anywhere in *p or *in       -> CBX_EINVAL, *out the whole space
 *   an axis of *in with no point    -> CBX_EMPTY,  *out empty (lo +inf, hi -inf)
 *   W not above its rounding at some corner (the box touches or crosses
 *   the camera plane W = 0, or lies behind it)
 *                                   -> CBX_EBEHIND, *out the whole space
 *   an entry, a box end or a quotient outside the range (linear entries
 *   and box ends above 2^509 in magnitude, translations above 2^1018,
 *   |X| above about 2^999 W; binary32 2^61, 2^122, 2^119)
 *                                   -> CBX_ERANGE, *out the whole space
 * CBX_OK whenever every input is in that range and every quotient is
 * (proj_ok: a box clear of the camera plane, every corner's W above the
 * rounding of its enclosure); CBX_ERANGE for inputs in the range only
 * with W > 0 at every corner (a box touching or behind the camera plane
 * gets CBX_EBEHIND).  out may be in itself; otherwise *out may
 * not overlap *p or *in. */
/*@ requires valid: \valid_read(p) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, p) && (\separated(out, in) || out == in);
    assigns *out;
    behavior nan_input:
      assumes proj_nan(p) || box_nan(in);
      ensures \result == CBX_EINVAL;
      ensures whole_space(out);
    behavior empty_input:
      assumes !proj_nan(p) && !box_nan(in) && is_empty(in);
      ensures \result == CBX_EMPTY;
      ensures empty_out(out);
    behavior box_input:
      assumes !proj_nan(p) && !box_nan(in) && !is_empty(in);
      ensures st: \result == CBX_OK || \result == CBX_ERANGE || \result == CBX_EBEHIND;
      ensures whole: \result != CBX_OK ==> whole_space(out);
      ensures axis0: \result == CBX_OK ==> paxis(out->lo[0], out->hi[0],
        \at(p->m[0][0], Pre), \at(p->m[0][1], Pre), \at(p->m[0][2], Pre), \at(p->m[0][3], Pre),
        \at(p->m[3][0], Pre), \at(p->m[3][1], Pre), \at(p->m[3][2], Pre), \at(p->m[3][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures axis1: \result == CBX_OK ==> paxis(out->lo[1], out->hi[1],
        \at(p->m[1][0], Pre), \at(p->m[1][1], Pre), \at(p->m[1][2], Pre), \at(p->m[1][3], Pre),
        \at(p->m[3][0], Pre), \at(p->m[3][1], Pre), \at(p->m[3][2], Pre), \at(p->m[3][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures axis2: \result == CBX_OK ==> paxis(out->lo[2], out->hi[2],
        \at(p->m[2][0], Pre), \at(p->m[2][1], Pre), \at(p->m[2][2], Pre), \at(p->m[2][3], Pre),
        \at(p->m[3][0], Pre), \at(p->m[3][1], Pre), \at(p->m[3][2], Pre), \at(p->m[3][3], Pre),
        \at(in->lo[0], Pre), \at(in->hi[0], Pre), \at(in->lo[1], Pre), \at(in->hi[1], Pre),
        \at(in->lo[2], Pre), \at(in->hi[2], Pre));
      ensures behind: \result == CBX_EBEHIND ==> \at(proj_fast(p) && box_fast(in) && !proj_clear(p, in), Pre);
      ensures range: \result == CBX_ERANGE ==> \at(!(proj_fast(p) && box_fast(in)) || proj_front(p, in), Pre);
      ensures ok: \at(proj_ok(p, in), Pre) ==> \result == CBX_OK;
    complete behaviors;
    disjoint behaviors;
*/
cbx_status cbx_project_box(const cbx_proj *p, const cbx_box *in, cbx_box *out);
