/*
 * Motion blur bounds: the box of a box over a shutter interval, the map at
 * time s in [0, 1] being M(s) = (1 - s) M0 + s M1 (entry by entry).
 *
 * For every point p, M(s) p = (1 - s)(M0 p) + s (M1 p) lies between the two
 * end images, so the union of the two end boxes (cbx_transform_box at
 * s = 0 and s = 1) bounds every image, and it is the exact bound over the
 * interval (each end is reached at s = 0 or s = 1).  The union takes no
 * rounding: min and max are exact.  Per axis: both rows full, the corner
 * statement of the two kernels carries over to every s (lemma lerp_below);
 * both rows not full, the same for the half-space ends and every real point;
 * one row full and the other not (a domain mismatch between the two maps),
 * the axis is [-inf, +inf] and the status CBX_ERANGE.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_onebox.h"

typedef struct mspan { double lo; double hi; int ok; } mspan;

/* Lemma function: a value r below (q above) both end images of the point
 * p is below (above) its image under M(s) for every s in [0, 1]
 * (lemmas mrow_below, mrow_above). */
/*@ requires a: r <= m0*p0 + m1*p1 + m2*p2 + t && q >= m0*p0 + m1*p1 + m2*p2 + t;
    requires b: r <= n0*p0 + n1*p1 + n2*p2 + u && q >= n0*p0 + n1*p1 + n2*p2 + u;
    assigns \nothing;
    ensures \forall real s; 0 <= s <= 1 ==>
      mrow_le(r, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2)
      && mrow_ge(q, s, m0, m1, m2, t, n0, n1, n2, u, p0, p1, p2);
*/
static void lerp_pt(double r, double q, double m0, double m1, double m2, double t,
                    double n0, double n1, double n2, double u, double p0, double p1, double p2)
{
    (void)r; (void)q; (void)m0; (void)m1; (void)m2; (void)t;
    (void)n0; (void)n1; (void)n2; (void)u; (void)p0; (void)p1; (void)p2;
}

/* Lemma function: both rows full, the union's ends bound M(s) at every
 * corner for every s in [0, 1]. */
/*@ requires a: below8(r0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                && above8(q0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires b: below8(r1, n0, n1, n2, u, l0, h0, l1, h1, l2, h2)
                && above8(q1, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
    requires r: lo <= r0 && lo <= r1 && hi >= q0 && hi >= q1;
    assigns \nothing;
    ensures \forall real s; 0 <= s <= 1 ==>
      mot_below8(lo, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2)
      && mot_above8(hi, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
*/
static void mot_corners(double lo, double hi, double r0, double q0, double r1, double q1,
                        double m0, double m1, double m2, double t,
                        double n0, double n1, double n2, double u,
                        double l0, double h0, double l1, double h1, double l2, double h2)
{
    (void)r0; (void)q0; (void)r1; (void)q1;
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, l0, l1, l2);
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, l0, l1, h2);
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, l0, h1, l2);
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, l0, h1, h2);
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, h0, l1, l2);
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, h0, l1, h2);
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, h0, h1, l2);
    lerp_pt(lo, hi, m0, m1, m2, t, n0, n1, n2, u, h0, h1, h2);
}

/* Lemma functions: the same for every real point of a box with infinite
 * ends, from the half-space statement of the two ends (lower, upper). */
/*@ requires a: ext_lo_end(r0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires b: ext_lo_end(r1, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
    requires lo: \is_finite(lo) ==> \is_finite(r0) && \is_finite(r1) && lo <= r0 && lo <= r1;
    assigns \nothing;
    ensures \forall real s; 0 <= s <= 1 ==>
      mot_ext_below(lo, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
*/
static void mot_points_lo(double lo, double r0, double r1,
                          double m0, double m1, double m2, double t,
                          double n0, double n1, double n2, double u,
                          double l0, double h0, double l1, double h1, double l2, double h2)
{
    /*@ assert e0: \is_finite(r0) ==> ext_below(r0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert e1: \is_finite(r1) ==> ext_below(r1, n0, n1, n2, u, l0, h0, l1, h1, l2, h2); */
    (void)lo; (void)r0; (void)r1; (void)m0; (void)m1; (void)m2; (void)t;
    (void)n0; (void)n1; (void)n2; (void)u;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/*@ requires a: ext_hi_end(q0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires b: ext_hi_end(q1, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
    requires hi: \is_finite(hi) ==> \is_finite(q0) && \is_finite(q1) && hi >= q0 && hi >= q1;
    assigns \nothing;
    ensures \forall real s; 0 <= s <= 1 ==>
      mot_ext_above(hi, s, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
*/
static void mot_points_hi(double hi, double q0, double q1,
                          double m0, double m1, double m2, double t,
                          double n0, double n1, double n2, double u,
                          double l0, double h0, double l1, double h1, double l2, double h2)
{
    /*@ assert e0: \is_finite(q0) ==> ext_above(q0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert e1: \is_finite(q1) ==> ext_above(q1, n0, n1, n2, u, l0, h0, l1, h1, l2, h2); */
    (void)hi; (void)q0; (void)q1; (void)m0; (void)m1; (void)m2; (void)t;
    (void)n0; (void)n1; (void)n2; (void)u;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/* One output axis: the union of the two end axes (r0, q0) and (r1, q1). */
/*@ requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    requires a: axis_sound_s(r0, q0, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires b: axis_sound_s(r1, q1, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
    requires nna: !\is_NaN(r0) && !\is_NaN(q0) && !\is_NaN(r1) && !\is_NaN(q1);
    assigns \nothing;
    ensures sound: mot_axis(\result.lo, \result.hi, m0, m1, m2, t, n0, n1, n2, u,
                            l0, h0, l1, h1, l2, h2);
    ensures tight: mot_tight(\result.lo, \result.hi, m0, m1, m2, t, n0, n1, n2, u,
                             l0, h0, l1, h1, l2, h2);
    ensures ok: \result.ok != 0 <==>
      (row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
       <==> row_full(n0, n1, n2, u, l0, h0, l1, h1, l2, h2));
*/
static mspan mot_axis_union(double r0, double q0, double r1, double q1,
                            double m0, double m1, double m2, double t,
                            double n0, double n1, double n2, double u,
                            double l0, double h0, double l1, double h1, double l2, double h2)
{
    mspan r;
    int fa = cbx_row_ok(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    int fb = cbx_row_ok(n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
    int ma = cbx_fin4(m0, m1, m2, t);
    int mb = cbx_fin4(n0, n1, n2, u);
    if (fa && fb) {
        r.lo = cbx_min2(r0, r1);
        r.hi = cbx_max2(q0, q1);
        mot_corners(r.lo, r.hi, r0, q0, r1, q1, m0, m1, m2, t, n0, n1, n2, u,
                    l0, h0, l1, h1, l2, h2);
        r.ok = 1;
    } else if (!fa && !fb && ma && mb) {
        /* an infinite end is -inf (+inf): the union's end is too */
        r.lo = (cbx_is_fin(r0) && cbx_is_fin(r1)) ? cbx_min2(r0, r1) : cbx_ninf();
        r.hi = (cbx_is_fin(q0) && cbx_is_fin(q1)) ? cbx_max2(q0, q1) : cbx_pinf();
        mot_points_lo(r.lo, r0, r1, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
        mot_points_hi(r.hi, q0, q1, m0, m1, m2, t, n0, n1, n2, u, l0, h0, l1, h1, l2, h2);
        r.ok = 1;
    } else {
        r.lo = cbx_ninf();
        r.hi = cbx_pinf();
        r.ok = !fa && !fb;
    }
    return r;
}

/* The union of the two end boxes, axis by axis, for a box that is neither
 * NaN nor empty (values only: no memory in the goals). */
typedef struct mot_box { cbx_box o; int ok; } mot_box;

/*@ requires nn: !nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)
                 && !nan_v(b00, b01, b02, b03, b10, b11, b12, b13, b20, b21, b22, b23, l0, h0, l1, h1, l2, h2)
                 && !empty_v(l0, h0, l1, h1, l2, h2);
    requires e0: box_done_m(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2, E0);
    requires e1: box_done_m(b00, b01, b02, b03, b10, b11, b12, b13, b20, b21, b22, b23, l0, h0, l1, h1, l2, h2, E1);
    assigns \nothing;
    ensures ax0: mot_axis(\result.o.lo[0], \result.o.hi[0], a00, a01, a02, a03, b00, b01, b02, b03, l0, h0, l1, h1, l2, h2);
    ensures ax1: mot_axis(\result.o.lo[1], \result.o.hi[1], a10, a11, a12, a13, b10, b11, b12, b13, l0, h0, l1, h1, l2, h2);
    ensures ax2: mot_axis(\result.o.lo[2], \result.o.hi[2], a20, a21, a22, a23, b20, b21, b22, b23, l0, h0, l1, h1, l2, h2);
    ensures t0: mot_tight(\result.o.lo[0], \result.o.hi[0], a00, a01, a02, a03, b00, b01, b02, b03, l0, h0, l1, h1, l2, h2);
    ensures t1: mot_tight(\result.o.lo[1], \result.o.hi[1], a10, a11, a12, a13, b10, b11, b12, b13, l0, h0, l1, h1, l2, h2);
    ensures t2: mot_tight(\result.o.lo[2], \result.o.hi[2], a20, a21, a22, a23, b20, b21, b22, b23, l0, h0, l1, h1, l2, h2);
    ensures ok: \result.ok != 0 <==>
      ((row_full(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2) <==> row_full(b00, b01, b02, b03, l0, h0, l1, h1, l2, h2))
       && (row_full(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2) <==> row_full(b10, b11, b12, b13, l0, h0, l1, h1, l2, h2))
       && (row_full(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2) <==> row_full(b20, b21, b22, b23, l0, h0, l1, h1, l2, h2)));
*/
static mot_box mot_union(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13,
                         double a20, double a21, double a22, double a23,
                         double b00, double b01, double b02, double b03, double b10, double b11, double b12, double b13,
                         double b20, double b21, double b22, double b23,
                         double l0, double h0, double l1, double h1, double l2, double h2, cbx_box E0, cbx_box E1)
{
    mot_box r;
    /*@ assert s0: axis_sound_s(E0.lo[0], E0.hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(E0.lo[1], E0.hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(E0.lo[2], E0.hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2); */
    /*@ assert s1: axis_sound_s(E1.lo[0], E1.hi[0], b00, b01, b02, b03, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(E1.lo[1], E1.hi[1], b10, b11, b12, b13, l0, h0, l1, h1, l2, h2)
          && axis_sound_s(E1.lo[2], E1.hi[2], b20, b21, b22, b23, l0, h0, l1, h1, l2, h2); */
    mspan r0 = mot_axis_union(E0.lo[0], E0.hi[0], E1.lo[0], E1.hi[0], a00, a01, a02, a03,
                              b00, b01, b02, b03, l0, h0, l1, h1, l2, h2);
    mspan r1 = mot_axis_union(E0.lo[1], E0.hi[1], E1.lo[1], E1.hi[1], a10, a11, a12, a13,
                              b10, b11, b12, b13, l0, h0, l1, h1, l2, h2);
    mspan r2 = mot_axis_union(E0.lo[2], E0.hi[2], E1.lo[2], E1.hi[2], a20, a21, a22, a23,
                              b20, b21, b22, b23, l0, h0, l1, h1, l2, h2);
    r.o.lo[0] = r0.lo; r.o.hi[0] = r0.hi;
    r.o.lo[1] = r1.lo; r.o.hi[1] = r1.hi;
    r.o.lo[2] = r2.lo; r.o.hi[2] = r2.hi;
    r.ok = r0.ok && r1.ok && r2.ok;
    return r;
}

cbx_status cbx_motion_box(const cbx_affine *a0, const cbx_affine *a1, const cbx_box *in, cbx_box *out)
{
    box_st e0 = one_box(a0, in);
    box_st e1 = one_box(a1, in);
    if (e0.s == CBX_EINVAL) {
        *out = e0.o;
        return CBX_EINVAL;
    }
    if (e1.s == CBX_EINVAL) {
        *out = e1.o;
        return CBX_EINVAL;
    }
    if (e0.s == CBX_EMPTY) {
        *out = e0.o;
        return CBX_EMPTY;
    }
    mot_box u = mot_union(a0->m[0][0], a0->m[0][1], a0->m[0][2], a0->m[0][3],
                          a0->m[1][0], a0->m[1][1], a0->m[1][2], a0->m[1][3],
                          a0->m[2][0], a0->m[2][1], a0->m[2][2], a0->m[2][3],
                          a1->m[0][0], a1->m[0][1], a1->m[0][2], a1->m[0][3],
                          a1->m[1][0], a1->m[1][1], a1->m[1][2], a1->m[1][3],
                          a1->m[2][0], a1->m[2][1], a1->m[2][2], a1->m[2][3],
                          in->lo[0], in->hi[0], in->lo[1], in->hi[1], in->lo[2], in->hi[2],
                          e0.o, e1.o);
    *out = u.o;
    return ((e0.s == CBX_OK) && (e1.s == CBX_OK) && u.ok) ? CBX_OK : CBX_ERANGE;
}
