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
    return x >= -CBX_K(R19) && x <= CBX_K(R19) && y >= -CBX_K(R19) && y <= CBX_K(R19);
}

/*@ requires \valid(out);
    requires i: 0 <= i <= 2;
    assigns out->c[i], out->h[i];
    ensures cwhole_axis(out, i);
*/
static void cwhole_set(cbx_cbox *out, int i)
{
    out->c[i] = CBX_C(0.0);
    out->h[i] = cbx_pinf();
}

/* The input checks, each one predicate of the contract (one call in the
 * public functions keeps their goals small; box_any_nan, box_any_empty:
 * src/core/cbx_domain.h). */

/*@ requires \valid_read(in);
    assigns \nothing;
    ensures \result != 0 <==> cbox_empty(in);
*/
static int cbox_any_neg(const cbx_cbox *in)
{
    return cbx_is_inverted(CBX_C(0.0), in->h[0]) | cbx_is_inverted(CBX_C(0.0), in->h[1])
           | cbx_is_inverted(CBX_C(0.0), in->h[2]);
}

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
    if (conv_ok(in->lo[i], in->hi[i])) {
        conv_res r = b2c(in->lo[i], in->hi[i]);
        out->c[i] = r.a;
        out->h[i] = r.b;
        return 1;
    }
    cwhole_set(out, i);
    return 0;
}

cbx_status cbx_box_to_cbox(const cbx_box *in, cbx_cbox *out)
{
    if (box_any_nan(in)) {
        out->c[0] = CBX_C(0.0); out->h[0] = cbx_pinf();
        out->c[1] = CBX_C(0.0); out->h[1] = cbx_pinf();
        out->c[2] = CBX_C(0.0); out->h[2] = cbx_pinf();
        return CBX_EINVAL;
    }
    if (box_any_empty(in)) {
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

/*@ requires \valid(out);
    requires i: 0 <= i <= 2;
    assigns out->lo[i], out->hi[i];
    ensures whole_axis(out, i);
*/
static void whole_set(cbx_box *out, int i)
{
    out->lo[i] = cbx_ninf();
    out->hi[i] = cbx_pinf();
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
    if (conv_ok(in->c[i], in->h[i])) {
        conv_res r = cbx_c2b(in->c[i], in->h[i]);
        out->lo[i] = r.a;
        out->hi[i] = r.b;
        return 1;
    }
    whole_set(out, i);
    return 0;
}

cbx_status cbx_cbox_to_box(const cbx_cbox *in, cbx_box *out)
{
    if (cbox_any_nan_in(in)) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (cbox_any_neg(in)) {
        set_empty(out);
        return CBX_EMPTY;
    }
    int k0 = c2b_set(in, out, 0);
    int k1 = c2b_set(in, out, 1);
    int k2 = c2b_set(in, out, 2);
    return (k0 && k1 && k2) ? CBX_OK : CBX_ERANGE;
}
