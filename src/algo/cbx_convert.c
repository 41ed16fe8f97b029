/*
 * Conversions between the two box forms, rounded outward.
 *   [lo, hi] -> (c, h): c = lo/2 + hi/2 in round-to-nearest (halving first
 *     cannot overflow), h = max(hi - c, c - lo) widened by 2^-50 relative
 *     and 2^-1070 absolute, which covers the two roundings of h's inputs.
 *   (c, h) -> [lo, hi]: lo = RN(c - h) - (3u |RN(c - h)| + 2^-1070), and
 *     symmetrically for hi.
 * Domain: finite inputs of magnitude at most 2^1019 (specs: conv_dom).
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_endpoints.h"

/* One axis, box -> cbox: returns (c, h). */
/*@ requires fin: \is_finite(lo) && \is_finite(hi);
    requires dom: conv_dom(lo, hi);
    requires ord: lo <= hi;
    assigns \nothing;
    ensures fin: \is_finite(\result.a) && \is_finite(\result.b);
    ensures sound: \result.a - \result.b <= lo && hi <= \result.a + \result.b;
    ensures tight: lo - conv_gap(lo, hi) <= \result.a - \result.b
                   && \result.a + \result.b <= hi + conv_gap(lo, hi);
*/
static conv_res b2c(cbx_fp lo, cbx_fp hi)
{
    cbx_fp a = cbx_mul_rn(lo, CBX_C(0.5));
    cbx_fp b = cbx_mul_rn(hi, CBX_C(0.5));
    cbx_fp c = cbx_add_rn(a, b);
    /*@ assert cm: \abs(c - (lo + hi) / 2) <= CBX_U2 * (\abs(lo) + \abs(hi)) + CBX_ETA4; */
    cbx_fp d1 = cbx_sub_rn(hi, c);
    cbx_fp d2 = cbx_sub_rn(c, lo);
    cbx_fp d = cbx_max2(d1, d2);
    /*@ assert x1: hi - c >= 0 ==> d1 >= 0 && (hi - c) * (1 - CBX_U) <= d1 + CBX_ETA; */
    /*@ assert x2: c - lo >= 0 ==> d2 >= 0 && (c - lo) * (1 - CBX_U) <= d2 + CBX_ETA; */
    /*@ assert dpos: d >= 0; */
    /*@ assert up1: hi - c <= d * (1 + CBX_U2) + CBX_ETA2; */
    /*@ assert up2: c - lo <= d * (1 + CBX_U2) + CBX_ETA2; */
    /*@ assert dup: d <= ((hi - lo) / 2 + \abs(c - (lo + hi) / 2)) * (1 + CBX_U) + CBX_ETA; */
    cbx_fp e = cbx_mul_rn(cbx_max2(d, CBX_C(0.0)), CBX_K(U8));
    cbx_fp f = cbx_add_rn(cbx_max2(d, CBX_C(0.0)), e);
    conv_res r;
    r.a = c;
    r.b = cbx_add_rn(f, CBX_K(ETA16));
    /*@ assert hb: r.b >= d * (1 + CBX_U2) + CBX_ETA4; */
    /*@ assert hup: r.b <= d * (1 + CBX_U12) + CBX_ETA64; */
    /*@ assert thi: r.a + r.b <= hi + conv_gap(lo, hi); */
    /*@ assert tlo: lo - conv_gap(lo, hi) <= r.a - r.b; */
    return r;
}

/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(x) && \is_finite(y) && conv_dom(x, y));
*/
static int conv_ok(cbx_fp x, cbx_fp y)
{
    return (x >= -CBX_K(R19)) && (x <= CBX_K(R19)) && (y >= -CBX_K(R19)) && (y <= CBX_K(R19));
}

/* One axis of a conversion, on values (both forms of the plane and of
 * space): the output ends and whether the axis was in the domain. */
typedef struct conv_axis { cbx_fp a; cbx_fp b; int ok; } conv_axis;

/* box -> cbox on one axis: the conversion in the domain, c = 0, h = +inf
 * outside it. */
/*@ requires pt: !\is_NaN(lo) && !\is_NaN(hi) && !no_point(lo, hi);
    assigns \nothing;
    ensures ok: \result.ok != 0 <==> conv_in(lo, hi);
    ensures ax: b2c_v(lo, hi, \result.a, \result.b);
*/
static conv_axis b2c_one(cbx_fp lo, cbx_fp hi)
{
    conv_axis r;
    r.a = CBX_C(0.0);
    r.b = cbx_pinf();
    r.ok = conv_ok(lo, hi);
    if (r.ok != 0) {
        conv_res k = b2c(lo, hi);
        r.a = k.a;
        r.b = k.b;
    }
    return r;
}

/* cbox -> box on one axis: the conversion in the domain, [-inf, +inf]
 * outside it. */
/*@ assigns \nothing;
    ensures ok: \result.ok != 0 <==> conv_in(c, h);
    ensures ax: c2b_v(c, h, \result.a, \result.b);
*/
static conv_axis c2b_one(cbx_fp c, cbx_fp h)
{
    conv_axis r;
    r.a = cbx_ninf();
    r.b = cbx_pinf();
    r.ok = conv_ok(c, h);
    if (r.ok != 0) {
        conv_res k = cbx_c2b(c, h);
        r.a = k.a;
        r.b = k.b;
    }
    return r;
}

/* The input checks (box_any_nan, box_any_empty, cbox_any_neg and their 2D
 * forms) are in src/core/cbx_domain.h: each is one predicate of the
 * contracts, and one call in the public functions keeps their goals small. */

/* One axis of cbx_box_to_cbox: the conversion in the domain, the whole
 * line outside it; 1 when in the domain. */
/*@ requires \valid_read(in) && \valid(out) && \separated(in, out);
    requires i: 0 <= i <= 2;
    requires pt: !\is_NaN(in->lo[i]) && !\is_NaN(in->hi[i]) && !no_point(in->lo[i], in->hi[i]);
    assigns out->c[i], out->h[i];
    ensures ok: \result != 0 <==> b2c_dom(in, i);
    ensures ax: b2c_axis(in, out, i);
*/
static int b2c_set(const cbx_box *in, cbx_cbox *out, int i)
{
    conv_axis r = b2c_one(in->lo[i], in->hi[i]);
    out->c[i] = r.a;
    out->h[i] = r.b;
    return r.ok;
}

cbx_status cbx_box_to_cbox(const cbx_box *in, cbx_cbox *out)
{
    if (box_any_nan(in) != 0) {
        out->c[0] = CBX_C(0.0); out->h[0] = cbx_pinf();
        out->c[1] = CBX_C(0.0); out->h[1] = cbx_pinf();
        out->c[2] = CBX_C(0.0); out->h[2] = cbx_pinf();
        return CBX_EINVAL;
    }
    if (box_any_empty(in) != 0) {
        out->c[0] = CBX_C(0.0); out->h[0] = cbx_ninf();
        out->c[1] = CBX_C(0.0); out->h[1] = cbx_ninf();
        out->c[2] = CBX_C(0.0); out->h[2] = cbx_ninf();
        return CBX_EMPTY;
    }
    int k0 = b2c_set(in, out, 0);
    int k1 = b2c_set(in, out, 1);
    int k2 = b2c_set(in, out, 2);
    return (k0 && k1 && k2) ? CBX_OK : CBX_ERANGE;
}


/* One axis of cbx_cbox_to_box: the conversion in the domain, the whole
 * line outside it; 1 when in the domain. */
/*@ requires \valid_read(in) && \valid(out) && \separated(in, out);
    requires i: 0 <= i <= 2;
    assigns out->lo[i], out->hi[i];
    ensures ok: \result != 0 <==> c2b_dom(in, i);
    ensures ax: c2b_axis(in, out, i);
*/
static int c2b_set(const cbx_cbox *in, cbx_box *out, int i)
{
    conv_axis r = c2b_one(in->c[i], in->h[i]);
    out->lo[i] = r.a;
    out->hi[i] = r.b;
    return r.ok;
}

cbx_status cbx_cbox_to_box(const cbx_cbox *in, cbx_box *out)
{
    if (cbox_any_nan_in(in) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (cbox_any_neg(in) != 0) {
        set_empty(out);
        return CBX_EMPTY;
    }
    int k0 = c2b_set(in, out, 0);
    int k1 = c2b_set(in, out, 1);
    int k2 = c2b_set(in, out, 2);
    return (k0 && k1 && k2) ? CBX_OK : CBX_ERANGE;
}


/* ---- the conversions of the plane (specs/cbx_plane.h) ------------------ */

cbx_status cbx_box2_to_cbox2(const cbx_box2 *in, cbx_cbox2 *out)
{
    if (box2_any_nan(in) != 0) {
        out->c[0] = CBX_C(0.0); out->h[0] = cbx_pinf();
        out->c[1] = CBX_C(0.0); out->h[1] = cbx_pinf();
        return CBX_EINVAL;
    }
    if (plane_any_empty(in) != 0) {
        out->c[0] = CBX_C(0.0); out->h[0] = cbx_ninf();
        out->c[1] = CBX_C(0.0); out->h[1] = cbx_ninf();
        return CBX_EMPTY;
    }
    conv_axis r0 = b2c_one(in->lo[0], in->hi[0]);
    conv_axis r1 = b2c_one(in->lo[1], in->hi[1]);
    out->c[0] = r0.a; out->h[0] = r0.b;
    out->c[1] = r1.a; out->h[1] = r1.b;
    return (r0.ok && r1.ok) ? CBX_OK : CBX_ERANGE;
}

cbx_status cbx_cbox2_to_box2(const cbx_cbox2 *in, cbx_box2 *out)
{
    if (cbox2_any_nan_in(in) != 0) {
        set_whole2(out);
        return CBX_EINVAL;
    }
    if (cbox2_any_neg(in) != 0) {
        set_empty2(out);
        return CBX_EMPTY;
    }
    conv_axis r0 = c2b_one(in->c[0], in->h[0]);
    conv_axis r1 = c2b_one(in->c[1], in->h[1]);
    out->lo[0] = r0.a; out->hi[0] = r0.b;
    out->lo[1] = r1.a; out->hi[1] = r1.b;
    return (r0.ok && r1.ok) ? CBX_OK : CBX_ERANGE;
}
