/*
 * A ball under a projective map (a camera's projection): cbx_project_sphere,
 * binary64.
 *
 * The ball is {c + r q : |q| <= 1}; output axis i is X_i / W, X_i row i of
 * the map and W row 3.  For a real t, X_i - t W is affine in the point with
 * linear part k(t) = a - t b (a, b the rows' linear parts), so over the
 * ball it ranges over e(t) -+ |r| |k(t)|, e(t) its value at the center
 * (specs/cbx_psph.h).  With W > 0 on the ball (W(c) - |r| |b| > 0), the
 * exact upper end of X_i / W is the root t* of e(t) + |r| |k(t)| = 0 (the
 * tangent plane of the dual quadric, Mara and McGuire's bound in closed
 * form), and the lower end the root of e(t) - |r| |k(t)| = 0.
 *
 * The closed form is computed in round-to-nearest (ps_candidate: clamped so
 * that no operation can overflow, but otherwise unproven); the bound is then
 * certified: at t = t0 + d the outward-rounded interval enclosure of
 * e(t) + |r| |k(t)| (ps_gap_at, on the proven interval arithmetic of
 * src/f64/cbx_iv.h) must be <= 0 (X <= t W on the whole ball: sound), and
 * at t = t0 - d it must be > 0 (some point has X / W > t0 - d: tight), with
 * 2 d <= 2^-20 (1 + |t0 + d|).  d starts at 2^-48 (1 + |t0|) (16 units in
 * the last place: the first try succeeds for nearly every ball; at 2^-50
 * half of them needed a second) and grows by 4 up to 13
 * times.  The lower end likewise.  So the contract states, in exact reals,
 * containment of every point of the ball and both ends within
 * 2^-20 (1 + |end|) of the exact ends; the measured distance is far below
 * (tests/test_psphere.c prints it).
 *
 * Statuses: NaN anywhere -> CBX_EINVAL; outside the domain (ps_dom: linear
 * entries, center and radius at most 2^60, translations at most 2^120) ->
 * CBX_ERANGE; the ball not clear of the camera plane W = 0 (its enclosure
 * of min W not positive) -> CBX_EBEHIND; an end beyond 2^100 in magnitude,
 * or one the search cannot certify within 2^-20 (the enclosures' rounding,
 * about 2^-48 of the rows' magnitudes at c, above 2^-22 of W's least value
 * on the ball: a ball very near the camera plane for its distance from the
 * origin) -> CBX_ERANGE.  Every status but
 * CBX_OK gives the whole space.  Proven in job PS64 (proofs/psph.c), with
 * the enclosures of X - t W it shares with the clipped box
 * (src/f64/cbx_paff.h).
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_iv.h"
#include "cbx_paff.h"
#include "cbx_pgap.h"

#define PS_TRIES 14

/* ---- input checks ----------------------------------------------------- */
/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> ps_nan(p, c, r);
*/
static int ps_any_nan(const cbx_proj *p, const double c[3], double r)
{
    return ps_proj_nan(p) | cbx_is_nan(c[0]) | cbx_is_nan(c[1]) | cbx_is_nan(c[2]) | cbx_is_nan(r);
}



/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> ps_dom(p, c, r);
*/
static int ps_dom_in(const cbx_proj *p, const double c[3], double r)
{
    int r0 = ps_row_in(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3]);
    int r1 = ps_row_in(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3]);
    int r2 = ps_row_in(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3]);
    int r3 = ps_row_in(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);
    int ct = ps_in(c[0], PS_M) && ps_in(c[1], PS_M) && ps_in(c[2], PS_M) && ps_in(r, PS_M);
    return r0 && r1 && r2 && r3 && ct;
}

/* ---- the search --------------------------------------------------------- */
/* One try of an end, at th = t0 + d and tl = t0 - d: the enclosure of
 * e(t) + |r| |k(t)| (up != 0: the upper end) or e(t) - |r| |k(t)| (up ==
 * 0: the lower end) at the end, then at the other point.  1 when the end (th for up, tl for down) is
 * sound, the other point shows tightness, and they are within ps_tau of
 * the end. */
/*@ requires args: ps_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    requires t: \is_finite(th) && \is_finite(tl) && -PS_B <= th <= PS_B && -PS_B <= tl <= PS_B;
    assigns \nothing;
    ensures hi: up != 0 && \result != 0 ==>
      ps_hi(th, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      && th - ps_tau(th) <= tl && ps_above(tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    ensures lo: up == 0 && \result != 0 ==>
      ps_lo(tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      && th <= tl + ps_tau(tl) && ps_below(th, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
*/
static int ps_try(int up, double th, double tl, double a0, double a1, double a2, double a3,
                  double b0, double b1, double b2, double b3, double c0, double c1, double c2, double r)
{
    int ok = 0;
    /* up: sound at th, tight at tl; down: sound at tl, tight at th.  The
     * span first, the tight side only where the end is sound (most tries
     * fail on soundness: one enclosure instead of two). */
    if (ps_span(th, tl, (up != 0) ? th : tl) != 0) {
        ps_gap gs = ps_gap_at((up != 0) ? th : tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
        cbx_iv ss = iv_add(gs.e, (up != 0) ? gs.k : iv_neg(gs.k));
        if ((up != 0) ? (ss.hi <= 0.0) : (ss.lo >= 0.0)) {
            ps_gap gw = ps_gap_at((up != 0) ? tl : th, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
            cbx_iv sw = iv_add(gw.e, (up != 0) ? gw.k : iv_neg(gw.k));
            ok = (up != 0) ? (sw.lo > 0.0) : (sw.hi < 0.0);
        }
    }
    return ok;
}

/* One end from the candidate t0.  up != 0, the upper end: v = t0 + d with
 * X <= v W on the whole ball, w = t0 - d with some point above w, and
 * v - w <= ps_tau(v).  up == 0, the lower end: v = t0 - d with X >= v W
 * on the whole ball, w = t0 + d with some point below w, w - v <=
 * ps_tau(v).  d grows by 4 per try (ps_try). */
/*@ requires args: ps_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    requires t0: \is_finite(t0) && -PS_C <= t0 <= PS_C;
    assigns \nothing;
    ensures fin: \result.ok != 0 ==> \is_finite(\result.v) && -PS_B <= \result.v <= PS_B;
    ensures hi: up != 0 && \result.ok != 0 ==>
      ps_hi(\result.v, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      && \result.v - ps_tau(\result.v) <= \result.w
      && ps_above(\result.w, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    ensures lo: up == 0 && \result.ok != 0 ==>
      ps_lo(\result.v, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      && \result.w <= \result.v + ps_tau(\result.v)
      && ps_below(\result.w, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
*/
static ps_fin ps_find(int up, double t0, double a0, double a1, double a2, double a3,
                      double b0, double b1, double b2, double b3,
                      double c0, double c1, double c2, double r)
{
    ps_fin f;
    double d = cbx_mul_rn(cbx_add_rn(1.0, cbx_abs(t0)), 0x1p-48);
    int k;
    f.v = 0.0;
    f.w = 0.0;
    f.ok = 0;
    /*@ loop invariant k: 0 <= k <= PS_TRIES;
        loop invariant d: \is_finite(d) && 0 <= d <= 0x1p93;
        loop invariant f: f.ok == 0;
        loop assigns k, d, f;
        loop variant PS_TRIES - k;
    */
    for (k = 0; k < PS_TRIES && d <= 0x1p90; k++) {
        double th = t0 + d;
        double tl = t0 - d;
        if (ps_in(th, PS_B) && ps_in(tl, PS_B)
            && ps_try(up, th, tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)) {
            f.v = (up != 0) ? th : tl;
            f.w = (up != 0) ? tl : th;
            f.ok = 1;
            break;
        }
        d = cbx_mul_rn(d, 4.0);
    }
    return f;
}

/* ---- one output axis ---------------------------------------------------- */

/*@ requires args: ps_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    requires front: ps_front(b0, b1, b2, b3, c0, c1, c2, r);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
      && ps_axis(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r)
      && ps_tight(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
*/
static ps_ax ps_axis_of(double a0, double a1, double a2, double a3,
                        double b0, double b1, double b2, double b3,
                        double c0, double c1, double c2, double r)
{
    ps_ax x;
    ps_cand q = ps_candidate(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    x.lo = 0.0;
    x.hi = 0.0;
    x.ok = 0;
    if (q.ok != 0) {
        ps_fin h = ps_find(1, q.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
        ps_fin l = ps_find(0, q.lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
        if ((h.ok != 0) && (l.ok != 0)) {
            x.lo = l.v;
            x.hi = h.v;
            x.ok = 1;
            /*@ assert cov: ps_axis(x.lo, x.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r); */
            /*@ assert tight: ps_tight(x.lo, x.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r); */
        }
    }
    return x;
}

/* W > 0 on the whole ball (ps_front): e(0) - |r| |k(0)| of the row W
 * itself (a = b = W: X - 0 W is W) enclosed above 0. */
/*@ requires args: ps_args(b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r);
    assigns \nothing;
    ensures front: \result != 0 ==> ps_front(b0, b1, b2, b3, c0, c1, c2, r);
*/
static int ps_in_front(double b0, double b1, double b2, double b3, double c0, double c1, double c2, double r)
{
    ps_gap g = ps_gap_at(0.0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r);
    cbx_iv f = iv_add(g.e, iv_neg(g.k));
    /*@ assert e0: ps_e(0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2) == aff(b0, b1, b2, b3, c0, c1, c2); */
    /*@ assert n0: ps_n(0, b0, b1, b2, b0, b1, b2) == rnorm3(b0, b1, b2); */
    /*@ assert k0: prod_at(g.k.lo, g.k.hi, \abs(r), ps_n(0, b0, b1, b2, b0, b1, b2)); */
    /*@ assert k1: prod_at(g.k.lo, g.k.hi, \abs(r), rnorm3(b0, b1, b2)); */
    /*@ assert e1: iv_has(g.e.lo, g.e.hi, aff(b0, b1, b2, b3, c0, c1, c2)); */
    /*@ assert fl: f.lo <= g.e.lo - g.k.hi; */
    return f.lo > 0.0;
}

/* ---- the public function ------------------------------------------------ */
cbx_status cbx_project_sphere(const cbx_proj *p, const double c[3], double r, cbx_box *out)
{
    if (ps_any_nan(p, c, r) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (!ps_dom_in(p, c, r)) {
        set_whole(out);
        return CBX_ERANGE;
    }
    {
        double a00 = p->m[0][0];
        double a01 = p->m[0][1];
        double a02 = p->m[0][2];
        double a03 = p->m[0][3];
        double a10 = p->m[1][0];
        double a11 = p->m[1][1];
        double a12 = p->m[1][2];
        double a13 = p->m[1][3];
        double a20 = p->m[2][0];
        double a21 = p->m[2][1];
        double a22 = p->m[2][2];
        double a23 = p->m[2][3];
        double w0 = p->m[3][0];
        double w1 = p->m[3][1];
        double w2 = p->m[3][2];
        double wt = p->m[3][3];
        double c0 = c[0];
        double c1 = c[1];
        double c2 = c[2];
        ps_ax x0;
        ps_ax x1;
        ps_ax x2;
        if (!ps_in_front(w0, w1, w2, wt, c0, c1, c2, r)) {
            set_whole(out);
            return CBX_EBEHIND;
        }
        x0 = ps_axis_of(a00, a01, a02, a03, w0, w1, w2, wt, c0, c1, c2, r);
        x1 = ps_axis_of(a10, a11, a12, a13, w0, w1, w2, wt, c0, c1, c2, r);
        x2 = ps_axis_of(a20, a21, a22, a23, w0, w1, w2, wt, c0, c1, c2, r);
        if ((x0.ok == 0) || (x1.ok == 0) || (x2.ok == 0)) {
            set_whole(out);
            return CBX_ERANGE;
        }
        out->lo[0] = x0.lo;
        out->hi[0] = x0.hi;
        out->lo[1] = x1.lo;
        out->hi[1] = x1.hi;
        out->lo[2] = x2.lo;
        out->hi[2] = x2.hi;
        return CBX_OK;
    }
}
