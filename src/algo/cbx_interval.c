/*
 * Arvo's interval form (Graphics Gems I, "Transforming Axis-Aligned
 * Bounding Boxes", Fig. 1), outward rounded: cbx_transform_box.
 *
 * The fast range (one check per map, one per box; src/algo/cbx_fast.h) goes
 * straight to the branch-free kernel (src/algo/cbx_kernel.h: per axis, the
 * round-to-nearest sums of Arvo's form widened once by 5.5 u R + 2^-1067).
 * Everything else takes the careful path below, axis by axis: the same
 * kernel on a full row, each end from its vertex on a half-space or
 * out-of-domain row, the whole line on an infinite map entry, and the
 * NaN and empty cases first.  On the fast range both paths give the same
 * bits.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_vertex.h"
#include "cbx_kernel.h"
#include "cbx_fast.h"

/* ---- half-spaces and out-of-domain boxes: one end at a time -----------
 * Where the row is not full (some box end infinite, or a pair outside the
 * domain) but the map row is finite, each end of the axis is computed on
 * its own: the lower end of t + m.x over the box is reached at the vertex
 * v_j = l_j (m_j > 0), h_j (m_j < 0), 0 (m_j == 0, whatever l_j, h_j are:
 * 0 * inf = 0).  If a needed end is infinite the image is unbounded there
 * and the end is -inf, exactly; otherwise the proven kernel runs on the
 * point box v and the per-column facts of vertex_lo / vertex_hi carry its
 * bound from the vertex to every real point of the box (ext_below). */
/* The kernels on the point box v (every l_j == h_j == v_j). */
/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires dom: row_in_dom(m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures sound: \result <= m0*v0 + m1*v1 + m2*v2 + t;
    ensures tight: lo_tight(\result, m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
*/
static cbx_fp point_lo(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t, cbx_fp v0, cbx_fp v1, cbx_fp v2)
{
    return cbx_axis(m0, m1, m2, t, v0, v0, v1, v1, v2, v2).lo;
}

/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires dom: row_in_dom(m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures sound: \result >= m0*v0 + m1*v1 + m2*v2 + t;
    ensures tight: hi_tight(\result, m0, m1, m2, t, v0, v0, v1, v1, v2, v2);
*/
static cbx_fp point_hi(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t, cbx_fp v0, cbx_fp v1, cbx_fp v2)
{
    return cbx_axis(m0, m1, m2, t, v0, v0, v1, v1, v2, v2).hi;
}

/* Lower end of one output axis from its vertex; ok == 0: lost to the domain. */
/*@ requires fin: map_fin(m0, m1, m2, t);
    requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    assigns \nothing;
    ensures end: ext_lo_end(\result.v, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures ok: \result.ok != 0 <==> (row_unb_lo(m0, m1, m2, l0, h0, l1, h1, l2, h2)
                                      || vdom_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2));
*/
static end_result ext_lo(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    end_result r;
    end_result v0 = vertex_lo(m0, l0, h0);
    end_result v1 = vertex_lo(m1, l1, h1);
    end_result v2 = vertex_lo(m2, l2, h2);
    if (!v0.ok || !v1.ok || !v2.ok) {
        r.v = cbx_ninf();
        r.ok = 1;
        return r;
    }
    if (!cbx_row_ok(m0, m1, m2, t, v0.v, v0.v, v1.v, v1.v, v2.v, v2.v)) {
        r.v = cbx_ninf();
        r.ok = 0;
        return r;
    }
    r.v = point_lo(m0, m1, m2, t, v0.v, v1.v, v2.v);
    r.ok = 1;
    return r;
}

/* Upper end of one output axis from its vertex (mirror of ext_lo). */
/*@ requires fin: map_fin(m0, m1, m2, t);
    requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    assigns \nothing;
    ensures end: ext_hi_end(\result.v, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures ok: \result.ok != 0 <==> (row_unb_hi(m0, m1, m2, l0, h0, l1, h1, l2, h2)
                                      || vdom_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2));
*/
static end_result ext_hi(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                         cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    end_result r;
    end_result v0 = vertex_hi(m0, l0, h0);
    end_result v1 = vertex_hi(m1, l1, h1);
    end_result v2 = vertex_hi(m2, l2, h2);
    if (!v0.ok || !v1.ok || !v2.ok) {
        r.v = cbx_pinf();
        r.ok = 1;
        return r;
    }
    if (!cbx_row_ok(m0, m1, m2, t, v0.v, v0.v, v1.v, v1.v, v2.v, v2.v)) {
        r.v = cbx_pinf();
        r.ok = 0;
        return r;
    }
    r.v = point_hi(m0, m1, m2, t, v0.v, v1.v, v2.v);
    r.ok = 1;
    return r;
}

/* One output axis: the proven kernel on a full row, each end from its
 * vertex on a finite map row, the whole line [-inf, +inf] otherwise. */
typedef struct axis_result { cbx_fp lo; cbx_fp hi; int ok; } axis_result;

/*@ requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    assigns \nothing;
    ensures ok: \result.ok != 0 <==> axis_ok_s(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures sound: axis_sound_s(\result.lo, \result.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static axis_result transform_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                                  cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1,
                                  cbx_fp l2, cbx_fp h2)
{
    axis_result r;
    if (cbx_row_ok(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) != 0) {
        cbx_ends e = cbx_axis(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
        r.lo = e.lo;
        r.hi = e.hi;
        r.ok = 1;
    } else if (cbx_fin4(m0, m1, m2, t) != 0) {
        end_result lo = ext_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
        end_result hi = ext_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
        r.lo = lo.v;
        r.hi = hi.v;
        r.ok = lo.ok && hi.ok;
    } else {
        r.lo = cbx_ninf();
        r.hi = cbx_pinf();
        r.ok = 0;
    }
    return r;
}

/* 1 if some input is NaN (specs: has_nan). */
/*@ requires \valid_read(a) && \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> has_nan(a, in);
*/
static int any_nan(const cbx_affine *a, const cbx_box *in)
{
    return aff_any_nan(a) | box_any_nan(in);
}

/* One check per map and per box: the branch-free kernel on the fast range
 * (src/algo/cbx_fast.h); otherwise the careful path: NaN, empty, then axis by
 * axis (the same kernel on a full row, each end from its vertex on a
 * half-space or out-of-domain row, the whole line on an infinite entry). */
/* proof: -wp-split */
cbx_status cbx_transform_box(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    if (cbx_map_fast(a) && cbx_box_fast(in)) {
        return cbx_fast_box(a, in, out);
    }
    if (any_nan(a, in) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (box_any_empty(in) != 0) {
        set_empty(out);
        return CBX_EMPTY;
    }
    cbx_fp l0 = in->lo[0];
    cbx_fp l1 = in->lo[1];
    cbx_fp l2 = in->lo[2];
    cbx_fp h0 = in->hi[0];
    cbx_fp h1 = in->hi[1];
    cbx_fp h2 = in->hi[2];
    cbx_fp a00 = a->m[0][0];
    cbx_fp a01 = a->m[0][1];
    cbx_fp a02 = a->m[0][2];
    cbx_fp a03 = a->m[0][3];
    cbx_fp a10 = a->m[1][0];
    cbx_fp a11 = a->m[1][1];
    cbx_fp a12 = a->m[1][2];
    cbx_fp a13 = a->m[1][3];
    cbx_fp a20 = a->m[2][0];
    cbx_fp a21 = a->m[2][1];
    cbx_fp a22 = a->m[2][2];
    cbx_fp a23 = a->m[2][3];
    axis_result r0 = transform_axis(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    axis_result r1 = transform_axis(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    axis_result r2 = transform_axis(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    out->lo[0] = r0.lo; out->hi[0] = r0.hi;
    out->lo[1] = r1.lo; out->hi[1] = r1.hi;
    out->lo[2] = r2.lo; out->hi[2] = r2.hi;
    /* the values used are the inputs of the pre-state (out may be in) */
    /*@ assert same_in: \at(a->m[0][0], Pre) == a00 && \at(a->m[0][1], Pre) == a01 && \at(a->m[0][2], Pre) == a02
          && \at(a->m[0][3], Pre) == a03 && \at(a->m[1][0], Pre) == a10 && \at(a->m[1][1], Pre) == a11
          && \at(a->m[1][2], Pre) == a12 && \at(a->m[1][3], Pre) == a13 && \at(a->m[2][0], Pre) == a20
          && \at(a->m[2][1], Pre) == a21 && \at(a->m[2][2], Pre) == a22 && \at(a->m[2][3], Pre) == a23
          && \at(in->lo[0], Pre) == l0 && \at(in->lo[1], Pre) == l1 && \at(in->lo[2], Pre) == l2
          && \at(in->hi[0], Pre) == h0 && \at(in->hi[1], Pre) == h1 && \at(in->hi[2], Pre) == h2; */
    /*@ assert same_out: out->lo[0] == r0.lo && out->hi[0] == r0.hi
          && out->lo[1] == r1.lo && out->hi[1] == r1.hi
          && out->lo[2] == r2.lo && out->hi[2] == r2.hi; */
    /*@ assert as0: axis_sound_s(out->lo[0], out->hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2); */
    /*@ assert as1: axis_sound_s(out->lo[1], out->hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2); */
    /*@ assert as2: axis_sound_s(out->lo[2], out->hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2); */
    return (r0.ok && r1.ok && r2.ok) ? CBX_OK : CBX_ERANGE;
}


/* The 2D form: each axis is the 3D careful path's axis with a zero third
 * column and a third box axis [0, 0] (specs/cbx_plane.h). */
/*@ requires \valid_read(a) && \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> has_nan2(a, in);
*/
static int any_nan2(const cbx_affine2 *a, const cbx_box2 *in)
{
    return aff2_any_nan(a) | box2_any_nan(in);
}

cbx_status cbx_transform_box2(const cbx_affine2 *a, const cbx_box2 *in, cbx_box2 *out)
{
    if (any_nan2(a, in) != 0) {
        set_whole2(out);
        return CBX_EINVAL;
    }
    if (plane_any_empty(in) != 0) {
        set_empty2(out);
        return CBX_EMPTY;
    }
    cbx_fp z = CBX_C(0.0);
    cbx_fp l0 = in->lo[0];
    cbx_fp l1 = in->lo[1];
    cbx_fp h0 = in->hi[0];
    cbx_fp h1 = in->hi[1];
    cbx_fp a00 = a->m[0][0];
    cbx_fp a01 = a->m[0][1];
    cbx_fp a02 = a->m[0][2];
    cbx_fp a10 = a->m[1][0];
    cbx_fp a11 = a->m[1][1];
    cbx_fp a12 = a->m[1][2];
    axis_result r0 = transform_axis(a00, a01, z, a02, l0, h0, l1, h1, z, z);
    axis_result r1 = transform_axis(a10, a11, z, a12, l0, h0, l1, h1, z, z);
    out->lo[0] = r0.lo; out->hi[0] = r0.hi;
    out->lo[1] = r1.lo; out->hi[1] = r1.hi;
    /*@ assert same_in: \at(a->m[0][0], Pre) == a00 && \at(a->m[0][1], Pre) == a01
          && \at(a->m[0][2], Pre) == a02 && \at(a->m[1][0], Pre) == a10
          && \at(a->m[1][1], Pre) == a11 && \at(a->m[1][2], Pre) == a12
          && \at(in->lo[0], Pre) == l0 && \at(in->lo[1], Pre) == l1
          && \at(in->hi[0], Pre) == h0 && \at(in->hi[1], Pre) == h1; */
    /*@ assert same_out: out->lo[0] == r0.lo && out->hi[0] == r0.hi
          && out->lo[1] == r1.lo && out->hi[1] == r1.hi; */
    return (r0.ok && r1.ok) ? CBX_OK : CBX_ERANGE;
}

/* ---- prepared maps ---------------------------------------------------- */

void cbx_prepare(const cbx_affine *a, cbx_prepared *p)
{
    /* entry by entry: a struct copy may compile to a call to memcpy, and
     * the library needs no libc (make embedded) */
    cbx_fp a00 = a->m[0][0];
    cbx_fp a01 = a->m[0][1];
    cbx_fp a02 = a->m[0][2];
    cbx_fp a03 = a->m[0][3];
    cbx_fp a10 = a->m[1][0];
    cbx_fp a11 = a->m[1][1];
    cbx_fp a12 = a->m[1][2];
    cbx_fp a13 = a->m[1][3];
    cbx_fp a20 = a->m[2][0];
    cbx_fp a21 = a->m[2][1];
    cbx_fp a22 = a->m[2][2];
    cbx_fp a23 = a->m[2][3];
    p->a.m[0][0] = a00; p->a.m[0][1] = a01; p->a.m[0][2] = a02; p->a.m[0][3] = a03;
    p->a.m[1][0] = a10; p->a.m[1][1] = a11; p->a.m[1][2] = a12; p->a.m[1][3] = a13;
    p->a.m[2][0] = a20; p->a.m[2][1] = a21; p->a.m[2][2] = a22; p->a.m[2][3] = a23;
    p->fast = cbx_map_fast(&p->a);
#if CBX_INST == 64
    p->cls = (int)cbx_classify(&p->a);
#else
    p->cls = 0;
#endif
}

/* The box check only: the map's was done by cbx_prepare (p->fast).  A
 * class other than GENERAL goes to the class kernel, which checks it
 * against the map. */
/* proof: -wp-split */
cbx_status cbx_transform_box_prep(const cbx_prepared *p, const cbx_box *in, cbx_box *out)
{
#if CBX_INST == 64
    if (p->cls != (int)CBX_CLASS_GENERAL) {
        return cbx_transform_box_as(&p->a, (cbx_class)p->cls, in, out);
    }
#endif
    if (p->fast && cbx_box_fast(in)) {
        return cbx_fast_box(&p->a, in, out);
    }
    return cbx_transform_box(&p->a, in, out);
}
