/*
 * Arvo's center/half-diagonal form (Graphics Gems I, Fig. 2), outward
 * rounded, and the two conversions between the forms.
 *
 * A cbx_cbox means the exact real box [c - h, c + h].  Per output axis the
 * center c' = t + sum_j m_j c_j is computed in round-to-nearest and left as
 * it is; its rounding error (at most about 4 u S), the error of the computed
 * |M| h, and the final addition are all paid for in the half-diagonal, which
 * is widened once by 5.5 u R + 2^-1067, R the computed scale.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"

typedef struct cbox_res { cbx_fp c; cbx_fp h; } cbox_res;

/* One output axis of the center/half transform. */
/* proof: -wp-split */
/*@ requires fin: \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t);
    requires finb: \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
                   && \is_finite(h0) && \is_finite(h1) && \is_finite(h2);
    requires dom: in_dom(m0, c0) && in_dom(m0, h0) && in_dom(m1, c1) && in_dom(m1, h1)
                  && in_dom(m2, c2) && in_dom(m2, h2);
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures fin: \is_finite(\result.c) && \is_finite(\result.h);
    ensures core: cbox_core(\result.c, \result.h, m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
    ensures tight: cbox_tight(\result.c, \result.h, m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
*/
static cbox_res cbox_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                          cbx_fp c0, cbx_fp c1, cbx_fp c2, cbx_fp h0, cbx_fp h1, cbx_fp h2)
{
    cbx_fp p0 = cbx_mul_rn(m0, c0);
    cbx_fp p1 = cbx_mul_rn(m1, c1);
    cbx_fp p2 = cbx_mul_rn(m2, c2);
    cbx_fp q0 = cbx_abs(cbx_mul_rn(m0, h0));
    cbx_fp q1 = cbx_abs(cbx_mul_rn(m1, h1));
    cbx_fp q2 = cbx_abs(cbx_mul_rn(m2, h2));
    /*@ assert M: \abs(m0*c0) <= CBX_RT && \abs(m1*c1) <= CBX_RT && \abs(m2*c2) <= CBX_RT
                  && \abs(m0*h0) <= CBX_RT && \abs(m1*h1) <= CBX_RT && \abs(m2*h2) <= CBX_RT; */
    /*@ assert p0e: -(CBX_U*\abs(m0*c0) + CBX_ETA) <= p0 - m0*c0 <= CBX_U*\abs(m0*c0) + CBX_ETA; */
    /*@ assert q0e: -(CBX_U*\abs(m0*h0) + CBX_ETA) <= q0 - \abs(m0*h0) <= CBX_U*\abs(m0*h0) + CBX_ETA; */
    /*@ assert p1e: -(CBX_U*\abs(m1*c1) + CBX_ETA) <= p1 - m1*c1 <= CBX_U*\abs(m1*c1) + CBX_ETA; */
    /*@ assert q1e: -(CBX_U*\abs(m1*h1) + CBX_ETA) <= q1 - \abs(m1*h1) <= CBX_U*\abs(m1*h1) + CBX_ETA; */
    /*@ assert p2e: -(CBX_U*\abs(m2*c2) + CBX_ETA) <= p2 - m2*c2 <= CBX_U*\abs(m2*c2) + CBX_ETA; */
    /*@ assert q2e: -(CBX_U*\abs(m2*h2) + CBX_ETA) <= q2 - \abs(m2*h2) <= CBX_U*\abs(m2*h2) + CBX_ETA; */
    cbx_fp s1 = cbx_add_rn(t, p0);
    /*@ assert a1: -(\abs(t) + \abs(m0*c0) + CBX_U*\abs(m0*c0) + CBX_ETA) <= t + p0 <= \abs(t) + \abs(m0*c0) + CBX_U*\abs(m0*c0) + CBX_ETA; */
    /*@ assert r1: -(CBX_U*(\abs(t) + \abs(m0*c0) + CBX_U*\abs(m0*c0) + CBX_ETA) + CBX_ETA) <= s1 - (t + p0) <= CBX_U*(\abs(t) + \abs(m0*c0) + CBX_U*\abs(m0*c0) + CBX_ETA) + CBX_ETA; */
    /*@ assert e1: -(CBX_UP*(1*\abs(t) + 2*\abs(m0*c0)) + 3*CBX_ETA) <= s1 - (t + m0*c0) <= CBX_UP*(1*\abs(t) + 2*\abs(m0*c0)) + 3*CBX_ETA; */
    cbx_fp s2 = cbx_add_rn(s1, p1);
    /*@ assert a2: -(\abs(t) + \abs(m0*c0) + CBX_UP*(1*\abs(t) + 2*\abs(m0*c0)) + 3*CBX_ETA + \abs(m1*c1) + CBX_U*\abs(m1*c1) + CBX_ETA) <= s1 + p1 <= \abs(t) + \abs(m0*c0) + CBX_UP*(1*\abs(t) + 2*\abs(m0*c0)) + 3*CBX_ETA + \abs(m1*c1) + CBX_U*\abs(m1*c1) + CBX_ETA; */
    /*@ assert r2: -(CBX_U*(\abs(t) + \abs(m0*c0) + CBX_UP*(1*\abs(t) + 2*\abs(m0*c0)) + 3*CBX_ETA + \abs(m1*c1) + CBX_U*\abs(m1*c1) + CBX_ETA) + CBX_ETA) <= s2 - (s1 + p1) <= CBX_U*(\abs(t) + \abs(m0*c0) + CBX_UP*(1*\abs(t) + 2*\abs(m0*c0)) + 3*CBX_ETA + \abs(m1*c1) + CBX_U*\abs(m1*c1) + CBX_ETA) + CBX_ETA; */
    /*@ assert e2: -(CBX_UP*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*CBX_ETA) <= s2 - (t + m0*c0 + m1*c1) <= CBX_UP*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*CBX_ETA; */
    cbx_fp s3 = cbx_add_rn(s2, p2);
    /*@ assert a3: -(\abs(t) + \abs(m0*c0) + \abs(m1*c1) + CBX_UP*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*CBX_ETA + \abs(m2*c2) + CBX_U*\abs(m2*c2) + CBX_ETA) <= s2 + p2 <= \abs(t) + \abs(m0*c0) + \abs(m1*c1) + CBX_UP*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*CBX_ETA + \abs(m2*c2) + CBX_U*\abs(m2*c2) + CBX_ETA; */
    /*@ assert r3: -(CBX_U*(\abs(t) + \abs(m0*c0) + \abs(m1*c1) + CBX_UP*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*CBX_ETA + \abs(m2*c2) + CBX_U*\abs(m2*c2) + CBX_ETA) + CBX_ETA) <= s3 - (s2 + p2) <= CBX_U*(\abs(t) + \abs(m0*c0) + \abs(m1*c1) + CBX_UP*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*CBX_ETA + \abs(m2*c2) + CBX_U*\abs(m2*c2) + CBX_ETA) + CBX_ETA; */
    /*@ assert e3: -(CBX_UP*(3*\abs(t) + 4*\abs(m0*c0) + 3*\abs(m1*c1) + 2*\abs(m2*c2)) + 9*CBX_ETA) <= s3 - (t + m0*c0 + m1*c1 + m2*c2) <= CBX_UP*(3*\abs(t) + 4*\abs(m0*c0) + 3*\abs(m1*c1) + 2*\abs(m2*c2)) + 9*CBX_ETA; */
    /*@ assert e3s: -(CBX_U4P * (\abs(t) + \abs(m0*c0) + \abs(m1*c1) + \abs(m2*c2)) + 10*CBX_ETA) <= s3 - crow_c(m0, m1, m2, t, c0, c1, c2) <= CBX_U4P * (\abs(t) + \abs(m0*c0) + \abs(m1*c1) + \abs(m2*c2)) + 10*CBX_ETA; */
    cbx_fp k1 = cbx_add_rn(q0, q1);
    cbx_fp k2 = cbx_add_rn(k1, q2);
    /*@ assert kk: crow_h(m0, m1, m2, h0, h1, h2) - 3*CBX_UP*crow_h(m0, m1, m2, h0, h1, h2) - 5*CBX_ETA <= k2 <= crow_h(m0, m1, m2, h0, h1, h2)+ 3*CBX_UP*crow_h(m0, m1, m2, h0, h1, h2) + 6*CBX_ETA; */
    cbx_fp g0 = cbx_add_rn(cbx_abs(p0), q0);
    /*@ assert g0b: (\abs(m0*c0) + \abs(m0*h0)) * (1 - CBX_U4) - 3*CBX_ETA <= g0 <= (\abs(m0*c0) + \abs(m0*h0)) * (1 + CBX_U4) + 4*CBX_ETA; */
    cbx_fp g1 = cbx_add_rn(cbx_abs(p1), q1);
    /*@ assert g1b: (\abs(m1*c1) + \abs(m1*h1)) * (1 - CBX_U4) - 3*CBX_ETA <= g1 <= (\abs(m1*c1) + \abs(m1*h1)) * (1 + CBX_U4) + 4*CBX_ETA; */
    cbx_fp g2 = cbx_add_rn(cbx_abs(p2), q2);
    /*@ assert g2b: (\abs(m2*c2) + \abs(m2*h2)) * (1 - CBX_U4) - 3*CBX_ETA <= g2 <= (\abs(m2*c2) + \abs(m2*h2)) * (1 + CBX_U4) + 4*CBX_ETA; */
    /* the computed scale against the exact one (w2 in one step took 18 s) */
    /*@ assert gs: \abs(t) + g0 + g1 + g2
                   <= crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) * (1 + CBX_U4) + 12*CBX_ETA; */
    cbx_fp w = cbx_widening(t, g0, g1, g2);
    /*@ assert w1: w >= CBX_U5H * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) * (1 - CBX_U16) + CBX_ETA64 - CBX_ETA8; */
    /*@ assert w2: w <= CBX_U5H * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) * (1 + CBX_U16) + CBX_ETA256 + CBX_ETA8; */
    cbox_res r;
    r.c = s3;
    r.h = cbx_add_rn(k2, w);
    return r;
}

typedef struct cbox_axis_result { cbx_fp c; cbx_fp h; int ok; } cbox_axis_result;

/* The kernel on a full row; else, on a finite map row, the kernel on the
 * row with its zero-coefficient columns dropped (their c and h count as 0:
 * 0 * inf = 0); (0, +inf) otherwise. */
/*@ requires nan: !\is_NaN(c0) && !\is_NaN(c1) && !\is_NaN(c2)
                  && !\is_NaN(h0) && !\is_NaN(h1) && !\is_NaN(h2);
    assigns \nothing;
    ensures ok: \result.ok != 0 <==>
      (crow_full(m0, m1, m2, t, c0, c1, c2, h0, h1, h2)
       || crow_dfull(m0, m1, m2, t, c0, c1, c2, h0, h1, h2));
    ensures sound: caxis_sound_s(\result.c, \result.h, m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
*/
static cbox_axis_result cbox_transform_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                                            cbx_fp c0, cbx_fp c1, cbx_fp c2,
                                            cbx_fp h0, cbx_fp h1, cbx_fp h2)
{
    cbox_axis_result r;
    r.c = CBX_C(0.0);
    r.h = cbx_pinf();
    r.ok = 0;
    if (cbx_row_ok(m0, m1, m2, t, c0, h0, c1, h1, c2, h2) != 0) {
        cbox_res k = cbox_axis(m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
        r.c = k.c;
        r.h = k.h;
        r.ok = 1;
    } else if (cbx_fin4(m0, m1, m2, t) != 0) {
        cbx_fp e0 = (m0 == CBX_C(0.0)) ? CBX_C(0.0) : c0;
        cbx_fp g0 = (m0 == CBX_C(0.0)) ? CBX_C(0.0) : h0;
        cbx_fp e1 = (m1 == CBX_C(0.0)) ? CBX_C(0.0) : c1;
        cbx_fp g1 = (m1 == CBX_C(0.0)) ? CBX_C(0.0) : h1;
        cbx_fp e2 = (m2 == CBX_C(0.0)) ? CBX_C(0.0) : c2;
        cbx_fp g2 = (m2 == CBX_C(0.0)) ? CBX_C(0.0) : h2;
        /*@ assert dz: e0 == dz(m0, c0) && e1 == dz(m1, c1) && e2 == dz(m2, c2)
                       && g0 == dz(m0, h0) && g1 == dz(m1, h1) && g2 == dz(m2, h2); */
        if (cbx_row_ok(m0, m1, m2, t, e0, g0, e1, g1, e2, g2) != 0) {
            cbox_res k = cbox_axis(m0, m1, m2, t, e0, e1, e2, g0, g1, g2);
            r.c = k.c;
            r.h = k.h;
            r.ok = 1;
        }
    } else {
        /* r stays unbounded: an input is not finite */
    }
    return r;
}

/*@ requires \valid_read(a) && \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox_has_nan(a, in);
*/
static int cbox_any_nan(const cbx_affine *a, const cbx_cbox *in)
{
    return aff_any_nan(a) | cbox_any_nan_in(in);
}


/*@ requires \valid(out);
    assigns *out;
    ensures cwhole(out);
*/
static void cbox_set_whole(cbx_cbox *out)
{
    out->c[0] = CBX_C(0.0); out->h[0] = cbx_pinf();
    out->c[1] = CBX_C(0.0); out->h[1] = cbx_pinf();
    out->c[2] = CBX_C(0.0); out->h[2] = cbx_pinf();
}

/*@ requires \valid(out);
    assigns *out;
    ensures cempty(out);
*/
static void cbox_set_empty(cbx_cbox *out)
{
    out->c[0] = CBX_C(0.0); out->h[0] = cbx_ninf();
    out->c[1] = CBX_C(0.0); out->h[1] = cbx_ninf();
    out->c[2] = CBX_C(0.0); out->h[2] = cbx_ninf();
}

cbx_status cbx_transform_cbox(const cbx_affine *a, const cbx_cbox *in, cbx_cbox *out)
{
    if (cbox_any_nan(a, in) != 0) {
        cbox_set_whole(out);
        return CBX_EINVAL;
    }
    if (cbox_any_neg(in) != 0) {
        cbox_set_empty(out);
        return CBX_EMPTY;
    }
    cbx_fp c0 = in->c[0];
    cbx_fp c1 = in->c[1];
    cbx_fp c2 = in->c[2];
    cbx_fp h0 = in->h[0];
    cbx_fp h1 = in->h[1];
    cbx_fp h2 = in->h[2];
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
    cbox_axis_result r0 = cbox_transform_axis(a00, a01, a02, a03, c0, c1, c2, h0, h1, h2);
    cbox_axis_result r1 = cbox_transform_axis(a10, a11, a12, a13, c0, c1, c2, h0, h1, h2);
    cbox_axis_result r2 = cbox_transform_axis(a20, a21, a22, a23, c0, c1, c2, h0, h1, h2);
    out->c[0] = r0.c; out->h[0] = r0.h;
    out->c[1] = r1.c; out->h[1] = r1.h;
    out->c[2] = r2.c; out->h[2] = r2.h;
    /* the values used are the inputs of the pre-state (out may be in) */
    /*@ assert same_in: \at(a->m[0][0], Pre) == a00 && \at(a->m[0][1], Pre) == a01 && \at(a->m[0][2], Pre) == a02
          && \at(a->m[0][3], Pre) == a03 && \at(a->m[1][0], Pre) == a10 && \at(a->m[1][1], Pre) == a11
          && \at(a->m[1][2], Pre) == a12 && \at(a->m[1][3], Pre) == a13 && \at(a->m[2][0], Pre) == a20
          && \at(a->m[2][1], Pre) == a21 && \at(a->m[2][2], Pre) == a22 && \at(a->m[2][3], Pre) == a23
          && \at(in->c[0], Pre) == c0 && \at(in->c[1], Pre) == c1 && \at(in->c[2], Pre) == c2
          && \at(in->h[0], Pre) == h0 && \at(in->h[1], Pre) == h1 && \at(in->h[2], Pre) == h2; */
    /*@ assert same_out: out->c[0] == r0.c && out->h[0] == r0.h
          && out->c[1] == r1.c && out->h[1] == r1.h
          && out->c[2] == r2.c && out->h[2] == r2.h; */
    /*@ assert cs0: caxis_sound_s(out->c[0], out->h[0], a00, a01, a02, a03, c0, c1, c2, h0, h1, h2); */
    /*@ assert cs1: caxis_sound_s(out->c[1], out->h[1], a10, a11, a12, a13, c0, c1, c2, h0, h1, h2); */
    /*@ assert cs2: caxis_sound_s(out->c[2], out->h[2], a20, a21, a22, a23, c0, c1, c2, h0, h1, h2); */
    return (r0.ok && r1.ok && r2.ok) ? CBX_OK : CBX_ERANGE;
}


/* ---- the center/half-diagonal form of the plane (specs/cbx_plane.h) ----
 * Each axis is the 3D axis function with a zero third column and
 * c_2 = h_2 = 0. */

/*@ requires \valid_read(a) && \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox2_has_nan(a, in);
*/
static int cbox2_any_nan(const cbx_affine2 *a, const cbx_cbox2 *in)
{
    return aff2_any_nan(a) | cbox2_any_nan_in(in);
}


/*@ requires \valid(out);
    assigns *out;
    ensures cwhole2(out);
*/
static void cbox2_set_whole(cbx_cbox2 *out)
{
    out->c[0] = CBX_C(0.0); out->h[0] = cbx_pinf();
    out->c[1] = CBX_C(0.0); out->h[1] = cbx_pinf();
}

/*@ requires \valid(out);
    assigns *out;
    ensures cempty2(out);
*/
static void cbox2_set_empty(cbx_cbox2 *out)
{
    out->c[0] = CBX_C(0.0); out->h[0] = cbx_ninf();
    out->c[1] = CBX_C(0.0); out->h[1] = cbx_ninf();
}

cbx_status cbx_transform_cbox2(const cbx_affine2 *a, const cbx_cbox2 *in, cbx_cbox2 *out)
{
    if (cbox2_any_nan(a, in) != 0) {
        cbox2_set_whole(out);
        return CBX_EINVAL;
    }
    if (cbox2_any_neg(in) != 0) {
        cbox2_set_empty(out);
        return CBX_EMPTY;
    }
    cbx_fp z = CBX_C(0.0);
    cbx_fp c0 = in->c[0];
    cbx_fp c1 = in->c[1];
    cbx_fp h0 = in->h[0];
    cbx_fp h1 = in->h[1];
    cbx_fp a00 = a->m[0][0];
    cbx_fp a01 = a->m[0][1];
    cbx_fp a02 = a->m[0][2];
    cbx_fp a10 = a->m[1][0];
    cbx_fp a11 = a->m[1][1];
    cbx_fp a12 = a->m[1][2];
    cbox_axis_result r0 = cbox_transform_axis(a00, a01, z, a02, c0, c1, z, h0, h1, z);
    cbox_axis_result r1 = cbox_transform_axis(a10, a11, z, a12, c0, c1, z, h0, h1, z);
    out->c[0] = r0.c; out->h[0] = r0.h;
    out->c[1] = r1.c; out->h[1] = r1.h;
    /*@ assert same_in: \at(a->m[0][0], Pre) == a00 && \at(a->m[0][1], Pre) == a01
          && \at(a->m[0][2], Pre) == a02 && \at(a->m[1][0], Pre) == a10
          && \at(a->m[1][1], Pre) == a11 && \at(a->m[1][2], Pre) == a12
          && \at(in->c[0], Pre) == c0 && \at(in->c[1], Pre) == c1
          && \at(in->h[0], Pre) == h0 && \at(in->h[1], Pre) == h1; */
    /*@ assert same_out: out->c[0] == r0.c && out->h[0] == r0.h
          && out->c[1] == r1.c && out->h[1] == r1.h; */
    return (r0.ok && r1.ok) ? CBX_OK : CBX_ERANGE;
}
