/*
 * Outward-rounded endpoints of the real interval [c - h, c + h]: shared by
 * the cbox -> box conversion and the sphere and ellipsoid bounds.
 */
#ifndef CBX_ENDPOINTS_H
#define CBX_ENDPOINTS_H

#include "certbox.h"
#include "cbx_prec.h"
#include "cbx_round.h"

typedef struct conv_res { cbx_fp a; cbx_fp b; } conv_res;

/* One axis, cbox -> box: returns (lo, hi). */
/*@ requires fin: \is_finite(c) && \is_finite(h);
    requires dom: conv_dom(c, h);
    assigns \nothing;
    ensures fin: \is_finite(\result.a) && \is_finite(\result.b);
    ensures sound: \result.a <= c - h && c + h <= \result.b;
    ensures tight: (c - h) - conv_gap(c, h) <= \result.a && \result.b <= (c + h) + conv_gap(c, h);
*/
static inline conv_res cbx_c2b(cbx_fp c, cbx_fp h)
{
    cbx_fp s = cbx_sub_rn(c, h);
    /*@ assert s1: s <= (c - h) + CBX_UP * \abs(s) + CBX_ETA2; */
    cbx_fp e = cbx_add_rn(cbx_mul_rn(cbx_abs(s), CBX_K(U3)), CBX_K(ETA16));
    /*@ assert e1: e >= CBX_U3 * \abs(s) * (1 - CBX_U2) + CBX_ETA8; */
    cbx_fp p = cbx_add_rn(c, h);
    /*@ assert p1: p >= (c + h) - CBX_UP * \abs(p) - CBX_ETA2; */
    cbx_fp f = cbx_add_rn(cbx_mul_rn(cbx_abs(p), CBX_K(U3)), CBX_K(ETA16));
    /*@ assert f1: f >= CBX_U3 * \abs(p) * (1 - CBX_U2) + CBX_ETA8; */
    /*@ assert s2: \abs(s) <= (\abs(c) + \abs(h)) * (1 + CBX_U) + CBX_ETA; */
    /*@ assert e2: e <= CBX_U4 * (\abs(c) + \abs(h)) + CBX_ETA64; */
    /*@ assert p2: \abs(p) <= (\abs(c) + \abs(h)) * (1 + CBX_U) + CBX_ETA; */
    /*@ assert f2: f <= CBX_U4 * (\abs(c) + \abs(h)) + CBX_ETA64; */
    conv_res r;
    r.a = cbx_sub_rn(s, e);
    /*@ assert ta: (c - h) - conv_gap(c, h) <= r.a; */
    r.b = cbx_add_rn(p, f);
    /*@ assert tb: r.b <= (c + h) + conv_gap(c, h); */
    return r;
}

#endif /* CBX_ENDPOINTS_H */
