/*
 * Outward-rounded endpoints of the real interval [c - h, c + h]: shared by
 * the cbox -> box conversion and the sphere and ellipsoid bounds.
 */
#ifndef CBX_ENDPOINTS_H
#define CBX_ENDPOINTS_H

#include "certbox.h"
#include "cbx_round.h"

typedef struct conv_res { double a, b; } conv_res;

/* One axis, cbox -> box: returns (lo, hi). */
/*@ requires fin: \is_finite(c) && \is_finite(h);
    requires dom: conv_dom(c, h);
    assigns \nothing;
    ensures fin: \is_finite(\result.a) && \is_finite(\result.b);
    ensures sound: \result.a <= c - h && c + h <= \result.b;
*/
static inline conv_res cbx_c2b(double c, double h)
{
    double s = cbx_sub_rn(c, h);
    /*@ assert s1: s <= (c - h) + 0x1.00001p-53 * \abs(s) + 0x1p-1073; */
    double e = cbx_add_rn(cbx_mul_rn(cbx_abs(s), 0x1.8p-52), 0x1p-1070);
    /*@ assert e1: e >= 0x1.8p-52 * \abs(s) * (1 - 0x1p-52) + 0x1p-1071; */
    double p = cbx_add_rn(c, h);
    /*@ assert p1: p >= (c + h) - 0x1.00001p-53 * \abs(p) - 0x1p-1073; */
    double f = cbx_add_rn(cbx_mul_rn(cbx_abs(p), 0x1.8p-52), 0x1p-1070);
    /*@ assert f1: f >= 0x1.8p-52 * \abs(p) * (1 - 0x1p-52) + 0x1p-1071; */
    conv_res r;
    r.a = cbx_sub_rn(s, e);
    r.b = cbx_add_rn(p, f);
    return r;
}

#endif /* CBX_ENDPOINTS_H */
