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

typedef struct cbox_res { double c, h; } cbox_res;

/* One output axis of the center/half transform. */
/*@ requires fin: \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t);
    requires finb: \is_finite(c0) && \is_finite(c1) && \is_finite(c2)
                   && \is_finite(h0) && \is_finite(h1) && \is_finite(h2);
    requires dom: in_dom(m0, c0) && in_dom(m0, h0) && in_dom(m1, c1) && in_dom(m1, h1)
                  && in_dom(m2, c2) && in_dom(m2, h2);
    requires rt: -0x1p1018 <= t <= 0x1p1018;
    assigns \nothing;
    ensures fin: \is_finite(\result.c) && \is_finite(\result.h);
    ensures core: cbox_core(\result.c, \result.h, m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
    ensures tight: cbox_tight(\result.c, \result.h, m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
*/
static cbox_res cbox_axis(double m0, double m1, double m2, double t,
                          double c0, double c1, double c2, double h0, double h1, double h2)
{
    double p0 = cbx_mul_rn(m0, c0);
    double p1 = cbx_mul_rn(m1, c1);
    double p2 = cbx_mul_rn(m2, c2);
    double q0 = cbx_abs(cbx_mul_rn(m0, h0));
    double q1 = cbx_abs(cbx_mul_rn(m1, h1));
    double q2 = cbx_abs(cbx_mul_rn(m2, h2));
    /*@ assert M: \abs(m0*c0) <= 0x1p1018 && \abs(m1*c1) <= 0x1p1018 && \abs(m2*c2) <= 0x1p1018
                  && \abs(m0*h0) <= 0x1p1018 && \abs(m1*h1) <= 0x1p1018 && \abs(m2*h2) <= 0x1p1018; */
    /*@ assert p0e: -(0x1p-53*\abs(m0*c0) + 0x1p-1074) <= p0 - m0*c0 <= 0x1p-53*\abs(m0*c0) + 0x1p-1074; */
    /*@ assert q0e: -(0x1p-53*\abs(m0*h0) + 0x1p-1074) <= q0 - \abs(m0*h0) <= 0x1p-53*\abs(m0*h0) + 0x1p-1074; */
    /*@ assert p1e: -(0x1p-53*\abs(m1*c1) + 0x1p-1074) <= p1 - m1*c1 <= 0x1p-53*\abs(m1*c1) + 0x1p-1074; */
    /*@ assert q1e: -(0x1p-53*\abs(m1*h1) + 0x1p-1074) <= q1 - \abs(m1*h1) <= 0x1p-53*\abs(m1*h1) + 0x1p-1074; */
    /*@ assert p2e: -(0x1p-53*\abs(m2*c2) + 0x1p-1074) <= p2 - m2*c2 <= 0x1p-53*\abs(m2*c2) + 0x1p-1074; */
    /*@ assert q2e: -(0x1p-53*\abs(m2*h2) + 0x1p-1074) <= q2 - \abs(m2*h2) <= 0x1p-53*\abs(m2*h2) + 0x1p-1074; */
    double s1 = cbx_add_rn(t, p0);
    /*@ assert a1: -(\abs(t) + \abs(m0*c0) + 0x1p-53*\abs(m0*c0) + 0x1p-1074) <= t + p0 <= \abs(t) + \abs(m0*c0) + 0x1p-53*\abs(m0*c0) + 0x1p-1074; */
    /*@ assert r1: -(0x1p-53*(\abs(t) + \abs(m0*c0) + 0x1p-53*\abs(m0*c0) + 0x1p-1074) + 0x1p-1074) <= s1 - (t + p0) <= 0x1p-53*(\abs(t) + \abs(m0*c0) + 0x1p-53*\abs(m0*c0) + 0x1p-1074) + 0x1p-1074; */
    /*@ assert e1: -(0x1.00001p-53*(1*\abs(t) + 2*\abs(m0*c0)) + 3*0x1p-1074) <= s1 - (t + m0*c0) <= 0x1.00001p-53*(1*\abs(t) + 2*\abs(m0*c0)) + 3*0x1p-1074; */
    double s2 = cbx_add_rn(s1, p1);
    /*@ assert a2: -(\abs(t) + \abs(m0*c0) + 0x1.00001p-53*(1*\abs(t) + 2*\abs(m0*c0)) + 3*0x1p-1074 + \abs(m1*c1) + 0x1p-53*\abs(m1*c1) + 0x1p-1074) <= s1 + p1 <= \abs(t) + \abs(m0*c0) + 0x1.00001p-53*(1*\abs(t) + 2*\abs(m0*c0)) + 3*0x1p-1074 + \abs(m1*c1) + 0x1p-53*\abs(m1*c1) + 0x1p-1074; */
    /*@ assert r2: -(0x1p-53*(\abs(t) + \abs(m0*c0) + 0x1.00001p-53*(1*\abs(t) + 2*\abs(m0*c0)) + 3*0x1p-1074 + \abs(m1*c1) + 0x1p-53*\abs(m1*c1) + 0x1p-1074) + 0x1p-1074) <= s2 - (s1 + p1) <= 0x1p-53*(\abs(t) + \abs(m0*c0) + 0x1.00001p-53*(1*\abs(t) + 2*\abs(m0*c0)) + 3*0x1p-1074 + \abs(m1*c1) + 0x1p-53*\abs(m1*c1) + 0x1p-1074) + 0x1p-1074; */
    /*@ assert e2: -(0x1.00001p-53*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*0x1p-1074) <= s2 - (t + m0*c0 + m1*c1) <= 0x1.00001p-53*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*0x1p-1074; */
    double s3 = cbx_add_rn(s2, p2);
    /*@ assert a3: -(\abs(t) + \abs(m0*c0) + \abs(m1*c1) + 0x1.00001p-53*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*0x1p-1074 + \abs(m2*c2) + 0x1p-53*\abs(m2*c2) + 0x1p-1074) <= s2 + p2 <= \abs(t) + \abs(m0*c0) + \abs(m1*c1) + 0x1.00001p-53*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*0x1p-1074 + \abs(m2*c2) + 0x1p-53*\abs(m2*c2) + 0x1p-1074; */
    /*@ assert r3: -(0x1p-53*(\abs(t) + \abs(m0*c0) + \abs(m1*c1) + 0x1.00001p-53*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*0x1p-1074 + \abs(m2*c2) + 0x1p-53*\abs(m2*c2) + 0x1p-1074) + 0x1p-1074) <= s3 - (s2 + p2) <= 0x1p-53*(\abs(t) + \abs(m0*c0) + \abs(m1*c1) + 0x1.00001p-53*(2*\abs(t) + 3*\abs(m0*c0) + 2*\abs(m1*c1)) + 6*0x1p-1074 + \abs(m2*c2) + 0x1p-53*\abs(m2*c2) + 0x1p-1074) + 0x1p-1074; */
    /*@ assert e3: -(0x1.00001p-53*(3*\abs(t) + 4*\abs(m0*c0) + 3*\abs(m1*c1) + 2*\abs(m2*c2)) + 9*0x1p-1074) <= s3 - (t + m0*c0 + m1*c1 + m2*c2) <= 0x1.00001p-53*(3*\abs(t) + 4*\abs(m0*c0) + 3*\abs(m1*c1) + 2*\abs(m2*c2)) + 9*0x1p-1074; */
    /*@ assert e3s: -(0x1.00001p-51 * (\abs(t) + \abs(m0*c0) + \abs(m1*c1) + \abs(m2*c2)) + 10*0x1p-1074) <= s3 - crow_c(m0, m1, m2, t, c0, c1, c2) <= 0x1.00001p-51 * (\abs(t) + \abs(m0*c0) + \abs(m1*c1) + \abs(m2*c2)) + 10*0x1p-1074; */
    double k1 = cbx_add_rn(q0, q1);
    double k2 = cbx_add_rn(k1, q2);
    /*@ assert kk: crow_h(m0, m1, m2, h0, h1, h2) - 3*0x1.00001p-53*crow_h(m0, m1, m2, h0, h1, h2) - 5*0x1p-1074 <= k2 <= crow_h(m0, m1, m2, h0, h1, h2)+ 3*0x1.00001p-53*crow_h(m0, m1, m2, h0, h1, h2) + 6*0x1p-1074; */
    double g0 = cbx_add_rn(cbx_abs(p0), q0);
    /*@ assert g0b: (\abs(m0*c0) + \abs(m0*h0)) * (1 - 0x1p-51) - 3*0x1p-1074 <= g0 <= (\abs(m0*c0) + \abs(m0*h0)) * (1 + 0x1p-51) + 4*0x1p-1074; */
    double g1 = cbx_add_rn(cbx_abs(p1), q1);
    /*@ assert g1b: (\abs(m1*c1) + \abs(m1*h1)) * (1 - 0x1p-51) - 3*0x1p-1074 <= g1 <= (\abs(m1*c1) + \abs(m1*h1)) * (1 + 0x1p-51) + 4*0x1p-1074; */
    double g2 = cbx_add_rn(cbx_abs(p2), q2);
    /*@ assert g2b: (\abs(m2*c2) + \abs(m2*h2)) * (1 - 0x1p-51) - 3*0x1p-1074 <= g2 <= (\abs(m2*c2) + \abs(m2*h2)) * (1 + 0x1p-51) + 4*0x1p-1074; */
    double w = cbx_widening(t, g0, g1, g2);
    /*@ assert w1: w >= 0x1.6p-51 * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) * (1 - 0x1p-49) + 0x1p-1068 - 0x1p-1071; */
    /*@ assert w2: w <= 0x1.6p-51 * crow_mag(m0, m1, m2, t, c0, c1, c2, h0, h1, h2) * (1 + 0x1p-49) + 0x1p-1066 + 0x1p-1071; */
    cbox_res r;
    r.c = s3;
    r.h = cbx_add_rn(k2, w);
    return r;
}

typedef struct cbox_axis_result { double c, h; int ok; } cbox_axis_result;

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
static cbox_axis_result cbox_transform_axis(double m0, double m1, double m2, double t,
                                            double c0, double c1, double c2,
                                            double h0, double h1, double h2)
{
    cbox_axis_result r;
    r.c = 0.0;
    r.h = cbx_pinf();
    r.ok = 0;
    if (cbx_row_ok(m0, m1, m2, t, c0, h0, c1, h1, c2, h2)) {
        cbox_res k = cbox_axis(m0, m1, m2, t, c0, c1, c2, h0, h1, h2);
        r.c = k.c;
        r.h = k.h;
        r.ok = 1;
    } else if (cbx_is_fin(m0) && cbx_is_fin(m1) && cbx_is_fin(m2) && cbx_is_fin(t)) {
        double e0 = m0 == 0.0 ? 0.0 : c0, g0 = m0 == 0.0 ? 0.0 : h0;
        double e1 = m1 == 0.0 ? 0.0 : c1, g1 = m1 == 0.0 ? 0.0 : h1;
        double e2 = m2 == 0.0 ? 0.0 : c2, g2 = m2 == 0.0 ? 0.0 : h2;
        /*@ assert dz: e0 == dz(m0, c0) && e1 == dz(m1, c1) && e2 == dz(m2, c2)
                       && g0 == dz(m0, h0) && g1 == dz(m1, h1) && g2 == dz(m2, h2); */
        if (cbx_row_ok(m0, m1, m2, t, e0, g0, e1, g1, e2, g2)) {
            cbox_res k = cbox_axis(m0, m1, m2, t, e0, e1, e2, g0, g1, g2);
            r.c = k.c;
            r.h = k.h;
            r.ok = 1;
        }
    }
    return r;
}

/*@ requires \valid_read(a) && \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox_has_nan(a, in);
*/
static int cbox_any_nan(const cbx_affine *a, const cbx_cbox *in)
{
    if (cbx_is_nan(a->m[0][0]) || cbx_is_nan(a->m[0][1]) || cbx_is_nan(a->m[0][2]) || cbx_is_nan(a->m[0][3]))
        return 1;
    if (cbx_is_nan(a->m[1][0]) || cbx_is_nan(a->m[1][1]) || cbx_is_nan(a->m[1][2]) || cbx_is_nan(a->m[1][3]))
        return 1;
    if (cbx_is_nan(a->m[2][0]) || cbx_is_nan(a->m[2][1]) || cbx_is_nan(a->m[2][2]) || cbx_is_nan(a->m[2][3]))
        return 1;
    if (cbx_is_nan(in->c[0]) || cbx_is_nan(in->c[1]) || cbx_is_nan(in->c[2]))
        return 1;
    if (cbx_is_nan(in->h[0]) || cbx_is_nan(in->h[1]) || cbx_is_nan(in->h[2]))
        return 1;
    return 0;
}

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox_empty(in);
*/
static int cbox_any_negative(const cbx_cbox *in)
{
    return cbx_is_inverted(0.0, in->h[0]) || cbx_is_inverted(0.0, in->h[1])
           || cbx_is_inverted(0.0, in->h[2]);
}

/*@ requires \valid(out);
    assigns *out;
    ensures cwhole(out);
*/
static void cbox_set_whole(cbx_cbox *out)
{
    out->c[0] = 0.0; out->h[0] = cbx_pinf();
    out->c[1] = 0.0; out->h[1] = cbx_pinf();
    out->c[2] = 0.0; out->h[2] = cbx_pinf();
}

/*@ requires \valid(out);
    assigns *out;
    ensures cempty(out);
*/
static void cbox_set_empty(cbx_cbox *out)
{
    out->c[0] = 0.0; out->h[0] = cbx_ninf();
    out->c[1] = 0.0; out->h[1] = cbx_ninf();
    out->c[2] = 0.0; out->h[2] = cbx_ninf();
}

cbx_status cbx_transform_cbox(const cbx_affine *a, const cbx_cbox *in, cbx_cbox *out)
{
    if (cbox_any_nan(a, in)) {
        cbox_set_whole(out);
        return CBX_EINVAL;
    }
    if (cbox_any_negative(in)) {
        cbox_set_empty(out);
        return CBX_EMPTY;
    }
    double c0 = in->c[0], c1 = in->c[1], c2 = in->c[2];
    double h0 = in->h[0], h1 = in->h[1], h2 = in->h[2];
    double a00 = a->m[0][0], a01 = a->m[0][1], a02 = a->m[0][2], a03 = a->m[0][3];
    double a10 = a->m[1][0], a11 = a->m[1][1], a12 = a->m[1][2], a13 = a->m[1][3];
    double a20 = a->m[2][0], a21 = a->m[2][1], a22 = a->m[2][2], a23 = a->m[2][3];
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
