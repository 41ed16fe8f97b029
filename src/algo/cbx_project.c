/*
 * Boxes under a projective map (a 4x4 matrix, as a camera's projection):
 * cbx_project_box, written once for both formats.
 *
 * Where W > 0 on the box, X_i / W is a ratio of affine functions: X_i - c W
 * is affine for each c, so the bound of X_i / W over the box is reached at
 * one of its 8 corners (specs/cbx_proj_logic.h: plo_box, phi_box).  At each
 * corner the proven interval kernel (src/algo/cbx_kernel.h) on the point
 * box encloses W (once per corner, shared by the three axes) and X_i; the
 * quotient of those enclosures is rounded outward (src/core/cbx_quot.h:
 * cbx_div_dn, cbx_div_up): lower end
 * x_lo / w_hi when x_lo >= 0, else x_lo / w_lo (the upper end mirrored).
 * The axis is the least and the greatest of the 8 corners' ends.
 *
 * A corner whose enclosure of W is not positive is on or behind the camera
 * plane (to within the kernel's rounding): the whole box gets CBX_EBEHIND
 * and the whole space.  A quotient that could leave the range of the
 * format (|X| above about 2^1000 W; binary32 2^120) gives CBX_ERANGE and
 * the whole space, as does a map or box outside the range of the affine
 * fast path (linear entries and box ends at most 2^509, translations at
 * most 2^1018; binary32 2^61, 2^122).
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_quot.h"
#include "cbx_domain.h"
#include "cbx_kernel.h"
#include "cbx_fast.h"

/* ---- input checks ----------------------------------------------------- */
/*@ requires \valid_read(p);
    assigns \nothing;
    ensures \result != 0 <==> proj_nan(p);
*/
static int proj_any_nan(const cbx_proj *p)
{
    return cbx_is_nan(p->m[0][0]) | cbx_is_nan(p->m[0][1]) | cbx_is_nan(p->m[0][2]) | cbx_is_nan(p->m[0][3])
           | cbx_is_nan(p->m[1][0]) | cbx_is_nan(p->m[1][1]) | cbx_is_nan(p->m[1][2]) | cbx_is_nan(p->m[1][3])
           | cbx_is_nan(p->m[2][0]) | cbx_is_nan(p->m[2][1]) | cbx_is_nan(p->m[2][2]) | cbx_is_nan(p->m[2][3])
           | cbx_is_nan(p->m[3][0]) | cbx_is_nan(p->m[3][1]) | cbx_is_nan(p->m[3][2]) | cbx_is_nan(p->m[3][3]);
}

/* 1 exactly when nb <= x <= b (x then finite). */
/*@ requires \is_finite(nb) && \is_finite(b);
    assigns \nothing;
    ensures \result != 0 <==> (\is_finite(x) && nb <= x <= b);
*/
static int proj_rng(cbx_fp x, cbx_fp nb, cbx_fp b)
{
    return (x >= nb) && (x <= b);
}

/*@ assigns \nothing;
    ensures \result != 0 <==> prow_fast(m0, m1, m2, t);
*/
static int prow_in(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t)
{
    int a = proj_rng(m0, -CBX_K(SB), CBX_K(SB));
    int b = proj_rng(m1, -CBX_K(SB), CBX_K(SB));
    int c = proj_rng(m2, -CBX_K(SB), CBX_K(SB));
    int d = proj_rng(t, -CBX_K(RT), CBX_K(RT));
    return a && b && c && d;
}

/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(l) && \is_finite(h) && -CBX_SB <= l && l <= h && h <= CBX_SB);
*/
static int axis_in(cbx_fp l, cbx_fp h)
{
    int a = proj_rng(l, -CBX_K(SB), CBX_K(SB));
    int b = proj_rng(h, -CBX_K(SB), CBX_K(SB));
    return a && b && (l <= h);
}

/*@ requires \valid_read(p) && \valid_read(b);
    assigns \nothing;
    ensures \result != 0 <==> (proj_fast(p) && box_fast(b));
*/
static int proj_in(const cbx_proj *p, const cbx_box *b)
{
    int r0 = prow_in(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3]);
    int r1 = prow_in(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3]);
    int r2 = prow_in(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3]);
    int r3 = prow_in(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);
    int b0 = axis_in(b->lo[0], b->hi[0]);
    int b1 = axis_in(b->lo[1], b->hi[1]);
    int b2 = axis_in(b->lo[2], b->hi[2]);
    return r0 && r1 && r2 && r3 && b0 && b1 && b2;
}

/* ---- one corner --------------------------------------------------------- */
/* Bounds of X / W at the corner (x, y, z): ok 2 with pcorner, or ok 0 (W's
 * enclosure not positive: the corner is not clear of the camera plane), or
 * ok 1 (a quotient out of range: not pnear). */
typedef struct cbx_qcorner { cbx_fp lo; cbx_fp hi; cbx_fp wl; int ok; } cbx_qcorner;

/* W's enclosure at a corner (the interval kernel on the point box), computed
 * once per corner and shared by the three output axes: 8 kernel rows for W
 * per box instead of 24. */
typedef struct cbx_wc { cbx_fp lo; cbx_fp hi; } cbx_wc;

/* Lemma functions (no code): one corner's ends, sound and tight, from the
 * kernel's enclosures [a, .] of X and [wl, wh] of W, the quotient's
 * multiplied-out bounds, and the products of the case analysis (prod_le:
 * lemma prod_le_nn at the call); the lemmas ptl_pos ... pth_neg of
 * specs/cbx_proj.h.  PX, PW, PEW: X and W at the corner, W's rounding. */
#define PX aff(m0, m1, m2, t, x, y, z)
#define PW aff(w0, w1, w2, wt, x, y, z)
#define PEW perr(w0, w1, w2, wt, x, y, z)
/*@ requires fin: prow_fast(w0, w1, w2, wt);
    requires finp: \is_finite(x) && \is_finite(y) && \is_finite(z);
    requires rp: -CBX_SB <= x <= CBX_SB && -CBX_SB <= y <= CBX_SB && -CBX_SB <= z <= CBX_SB;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures enc: wenc(\result.lo, \result.hi, w0, w1, w2, wt, x, y, z);
*/
static cbx_wc proj_wc(cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt, cbx_fp x, cbx_fp y, cbx_fp z)
{
    cbx_wc r;
    cbx_fast_row(w0, w1, w2, wt, x, x, y, y, z, z);
    cbx_ends we = cbx_axis(w0, w1, w2, wt, x, x, y, y, z, z);
    /*@ assert ew: we.lo <= PW <= we.hi && PW - we.lo <= PEW && we.hi - PW <= PEW; */
    r.lo = we.lo;
    r.hi = we.hi;
    return r;
}

/*@ requires w: 0 < wl <= PW <= wh && PW - wl <= PEW && wh - PW <= PEW;
    requires x: a <= PX && PX - a <= perr(m0, m1, m2, t, x, y, z);
    requires pos: a >= 0 ==> r*wh <= a && a - r*wh <= CBX_U8*a + CBX_ETA16*wh
                  && (r >= 0 ==> prod_le(PW, wh, r) && prod_le(wh - PW, PEW, r))
                  && (r < 0 ==> prod_le(0, PW, -r) && prod_le(PW, wh, -r));
    requires neg: a < 0 ==> r < 0 && r*wl <= a && a - r*wl <= CBX_U8*(-a) + CBX_ETA16*wl
                  && prod_le(wl, PW, -r) && prod_le(PW - wl, PEW, -r);
    assigns \nothing;
    ensures sound: plo(r, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures tight: pt_lo(r, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
*/
static void corner_lo(cbx_fp r, cbx_fp a, cbx_fp wl, cbx_fp wh, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                      cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt, cbx_fp x, cbx_fp y, cbx_fp z)
{
    (void)r; (void)a; (void)wl; (void)wh; (void)m0; (void)m1; (void)m2; (void)t;
    (void)w0; (void)w1; (void)w2; (void)wt; (void)x; (void)y; (void)z;
    /*@ assert sm: \abs(PX) <= pmag(m0, m1, m2, t, x, y, z) && \abs(PW) <= pmag(w0, w1, w2, wt, x, y, z); */
    /*@ assert e: PW - wl <= CBX_U12*pmag(w0, w1, w2, wt, x, y, z) + CBX_ETA512
                  && wh - PW <= CBX_U12*pmag(w0, w1, w2, wt, x, y, z) + CBX_ETA512
                  && PX - a <= CBX_U12*pmag(m0, m1, m2, t, x, y, z) + CBX_ETA512; */
    /*@ assert h1: a >= 0 ==> ptl_pos_h(r, a, PX, PW, wh, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
    /*@ assert t1: a >= 0 ==> ptlw(r, a, wh, PX, PW, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
    /*@ assert h2: a < 0 ==> ptl_neg_h(r, a, PX, PW, wl, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
    /*@ assert t2: a < 0 ==> ptlw(r, a, wl, PX, PW, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
}

/*@ requires w: 0 < wl <= PW <= wh && PW - wl <= PEW && wh - PW <= PEW;
    requires x: PX <= a && a - PX <= perr(m0, m1, m2, t, x, y, z);
    requires pos: a >= 0 ==> r >= 0 && a <= r*wl && r*wl - a <= CBX_U8*a + CBX_ETA16*wl
                  && prod_le(wl, PW, r) && prod_le(PW - wl, PEW, r);
    requires neg: a < 0 ==> a <= r*wh && r*wh - a <= CBX_U8*(-a) + CBX_ETA16*wh
                  && (r <= 0 ==> prod_le(PW, wh, -r) && prod_le(wh - PW, PEW, -r))
                  && (r > 0 ==> prod_le(0, PW, r) && prod_le(PW, wh, r) && prod_le(0, wh, r));
    assigns \nothing;
    ensures sound: phi(r, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures tight: pt_hi(r, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
*/
static void corner_hi(cbx_fp r, cbx_fp a, cbx_fp wl, cbx_fp wh, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                      cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt, cbx_fp x, cbx_fp y, cbx_fp z)
{
    (void)r; (void)a; (void)wl; (void)wh; (void)m0; (void)m1; (void)m2; (void)t;
    (void)w0; (void)w1; (void)w2; (void)wt; (void)x; (void)y; (void)z;
    /*@ assert sm: \abs(PX) <= pmag(m0, m1, m2, t, x, y, z) && \abs(PW) <= pmag(w0, w1, w2, wt, x, y, z); */
    /*@ assert e: PW - wl <= CBX_U12*pmag(w0, w1, w2, wt, x, y, z) + CBX_ETA512
                  && wh - PW <= CBX_U12*pmag(w0, w1, w2, wt, x, y, z) + CBX_ETA512
                  && a - PX <= CBX_U12*pmag(m0, m1, m2, t, x, y, z) + CBX_ETA512; */
    /*@ assert s1: a >= 0 ==> PX <= r*PW; */
    /*@ assert s2: a < 0 && r <= 0 ==> PX <= r*PW; */
    /*@ assert s3: a < 0 && r > 0 ==> PX <= r*PW; */
    /*@ assert h1: a >= 0 ==> pth_pos_h(r, a, PX, PW, wl, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
    /*@ assert t1: a >= 0 ==> pthw(r, a, wl, PX, PW, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
    /*@ assert h2: a < 0 ==> pth_neg_h(r, a, PX, PW, wh, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
    /*@ assert t2: a < 0 ==> pthw(r, a, wh, PX, PW, pmag(m0, m1, m2, t, x, y, z), pmag(w0, w1, w2, wt, x, y, z)); */
}

/* proof: -wp-split */
/*@ requires fin: prow_fast(m0, m1, m2, t) && prow_fast(w0, w1, w2, wt);
    requires finp: \is_finite(x) && \is_finite(y) && \is_finite(z);
    requires rp: -CBX_SB <= x <= CBX_SB && -CBX_SB <= y <= CBX_SB && -CBX_SB <= z <= CBX_SB;
    requires wf: \is_finite(we.lo) && \is_finite(we.hi);
    requires we: wenc(we.lo, we.hi, w0, w1, w2, wt, x, y, z);
    assigns \nothing;
    ensures st: 0 <= \result.ok <= 2;
    ensures behind: \result.ok == 0 ==> !pclear(w0, w1, w2, wt, x, y, z);
    ensures far: \result.ok == 1 ==> !pnear(m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures front: \result.ok >= 1 ==> ppos(w0, w1, w2, wt, x, y, z);
    ensures w: \result.ok == 2 ==> \is_finite(\result.wl) && 0 < \result.wl <= aff(w0, w1, w2, wt, x, y, z);
    ensures lo: \result.ok == 2 ==> \is_finite(\result.lo) && -2*CBX_QR <= \result.lo <= 2*CBX_QR
                && plo(\result.lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures hi: \result.ok == 2 ==> \is_finite(\result.hi) && -2*CBX_QR <= \result.hi <= 2*CBX_QR
                && phi(\result.hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures tlo: \result.ok == 2 ==> pt_lo(\result.lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures thi: \result.ok == 2 ==> pt_hi(\result.hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
*/
static cbx_qcorner proj_corner(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                               cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt,
                               cbx_fp x, cbx_fp y, cbx_fp z, cbx_wc we)
{
    cbx_qcorner r;
    cbx_fast_row(m0, m1, m2, t, x, x, y, y, z, z);
    cbx_ends xe = cbx_axis(m0, m1, m2, t, x, x, y, y, z, z);
    /*@ assert ex: xe.lo <= PX <= xe.hi && PX - xe.lo <= perr(m0, m1, m2, t, x, y, z)
                  && xe.hi - PX <= perr(m0, m1, m2, t, x, y, z); */
    /*@ assert ew: we.lo <= PW <= we.hi && PW - we.lo <= PEW && we.hi - PW <= PEW; */
    /*@ assert sm: \abs(PX) <= pmag(m0, m1, m2, t, x, y, z) && \abs(PW) <= pmag(w0, w1, w2, wt, x, y, z); */
    r.lo = CBX_C(0.0);
    r.hi = CBX_C(0.0);
    r.wl = we.lo;
    r.ok = 0;
    if (we.lo > CBX_C(0.0)) {
        cbx_fp bl; /* the divisor of each end */
        cbx_fp bh;
        int ql;
        int qh;
        if (xe.lo >= CBX_C(0.0)) {
            bl = we.hi;
        } else {
            bl = we.lo;
        }
        if (xe.hi >= CBX_C(0.0)) {
            bh = we.lo;
        } else {
            bh = we.hi;
        }
        ql = cbx_quot_ok(xe.lo, bl);
        qh = cbx_quot_ok(xe.hi, bh);
        r.ok = 1;
        if ((ql != 0) && (qh != 0)) {
            cbx_fp lo = cbx_div_dn(xe.lo, bl);
            cbx_fp hi = cbx_div_up(xe.hi, bh);
            /* the products of the case analysis (lemma prod_le_nn) */
            /*@ assert pl1: xe.lo >= 0 && lo >= 0 ==> prod_le(PW, we.hi, lo) && prod_le(we.hi - PW, PEW, lo); */
            /*@ assert pl2: xe.lo >= 0 && lo < 0 ==> prod_le(0, PW, -lo) && prod_le(PW, we.hi, -lo); */
            /*@ assert pl3: xe.lo < 0 ==> prod_le(we.lo, PW, -lo) && prod_le(PW - we.lo, PEW, -lo); */
            /*@ assert ph1: xe.hi >= 0 ==> prod_le(we.lo, PW, hi) && prod_le(PW - we.lo, PEW, hi); */
            /*@ assert ph2: xe.hi < 0 && hi <= 0 ==> prod_le(PW, we.hi, -hi) && prod_le(we.hi - PW, PEW, -hi); */
            /*@ assert ph3: xe.hi < 0 && hi > 0 ==> prod_le(0, PW, hi) && prod_le(PW, we.hi, hi) && prod_le(0, we.hi, hi); */
            corner_lo(lo, xe.lo, we.lo, we.hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
            corner_hi(hi, xe.hi, we.lo, we.hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
            r.lo = lo;
            r.hi = hi;
            r.ok = 2;
        }
    }
    return r;
}
#undef PX
#undef PW
#undef PEW

/* ---- the hull of the corners: lemma functions (no code) -----------------
 * W at least the least corner's wl > 0 on the box; lo (hi) the least
 * (greatest) corner end: below (above) X / W at every corner, hence on the
 * box (plo_box, phi_box), and tight where it was taken. */
#define CBX_CORNERS(P, l0, h0, l1, h1, l2, h2) \
    P(l0, l1, l2, 0) && P(h0, l1, l2, 1) && P(l0, h1, l2, 2) && P(h0, h1, l2, 3) && \
    P(l0, l1, h2, 4) && P(h0, l1, h2, 5) && P(l0, h1, h2, 6) && P(h0, h1, h2, 7)
#define CBX_WPOS(x, y, z, k) 0 < v##k <= aff(w0, w1, w2, wt, x, y, z)
#define CBX_WENC(x, y, z, k) \is_finite(v##k.lo) && \is_finite(v##k.hi) \
    && wenc(v##k.lo, v##k.hi, w0, w1, w2, wt, x, y, z)
/*@ requires pos: CBX_CORNERS(CBX_WPOS, l0, h0, l1, h1, l2, h2);
    requires rb: l0 <= h0 && l1 <= h1 && l2 <= h2;
    assigns \nothing;
    ensures pos: \forall real x, y, z; l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2 ==>
                 ppos(w0, w1, w2, wt, x, y, z);
*/
static void hull_w(cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt,
                   cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                   cbx_fp v0, cbx_fp v1, cbx_fp v2, cbx_fp v3, cbx_fp v4, cbx_fp v5, cbx_fp v6, cbx_fp v7)
{
    (void)w0; (void)w1; (void)w2; (void)wt; (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    (void)v0; (void)v1; (void)v2; (void)v3; (void)v4; (void)v5; (void)v6; (void)v7;
    /*@ assert v: pw8(\min(\min(\min(v0, v1), \min(v2, v3)), \min(\min(v4, v5), \min(v6, v7))),
                      w0, w1, w2, wt, l0, h0, l1, h1, l2, h2); */
}

#define CBX_LO_AT(x, y, z, k) 0 < aff(w0, w1, w2, wt, x, y, z) \
    && plo(r##k, m0, m1, m2, t, w0, w1, w2, wt, x, y, z) && pt_lo(r##k, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
#define CBX_HI_AT(x, y, z, k) 0 < aff(w0, w1, w2, wt, x, y, z) \
    && phi(r##k, m0, m1, m2, t, w0, w1, w2, wt, x, y, z) && pt_hi(r##k, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
/*@ requires at: CBX_CORNERS(CBX_LO_AT, l0, h0, l1, h1, l2, h2);
    requires rb: l0 <= h0 && l1 <= h1 && l2 <= h2;
    requires lo: lo == \min(\min(\min(r0, r1), \min(r2, r3)), \min(\min(r4, r5), \min(r6, r7)));
    assigns \nothing;
    ensures sound: \forall real x, y, z; l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2 ==>
                   plo(lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures tight: pt_lo8(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
*/
static void hull_lo(cbx_fp lo, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                    cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt,
                    cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                    cbx_fp r0, cbx_fp r1, cbx_fp r2, cbx_fp r3, cbx_fp r4, cbx_fp r5, cbx_fp r6, cbx_fp r7)
{
    (void)lo; (void)m0; (void)m1; (void)m2; (void)t; (void)w0; (void)w1; (void)w2; (void)wt;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    (void)r0; (void)r1; (void)r2; (void)r3; (void)r4; (void)r5; (void)r6; (void)r7;
    /*@ assert p0: prod_le(lo, r0, aff(w0, w1, w2, wt, l0, l1, l2)); */
    /*@ assert s0: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, l2); */
    /*@ assert p1: prod_le(lo, r1, aff(w0, w1, w2, wt, h0, l1, l2)); */
    /*@ assert s1: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, l2); */
    /*@ assert p2: prod_le(lo, r2, aff(w0, w1, w2, wt, l0, h1, l2)); */
    /*@ assert s2: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, l2); */
    /*@ assert p3: prod_le(lo, r3, aff(w0, w1, w2, wt, h0, h1, l2)); */
    /*@ assert s3: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, l2); */
    /*@ assert p4: prod_le(lo, r4, aff(w0, w1, w2, wt, l0, l1, h2)); */
    /*@ assert s4: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, h2); */
    /*@ assert p5: prod_le(lo, r5, aff(w0, w1, w2, wt, h0, l1, h2)); */
    /*@ assert s5: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, h2); */
    /*@ assert p6: prod_le(lo, r6, aff(w0, w1, w2, wt, l0, h1, h2)); */
    /*@ assert s6: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, h2); */
    /*@ assert p7: prod_le(lo, r7, aff(w0, w1, w2, wt, h0, h1, h2)); */
    /*@ assert s7: plo(lo, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, h2); */
    /*@ assert q0: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, l0, l1, l2) >= 0; */
    /*@ assert q1: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, h0, l1, l2) >= 0; */
    /*@ assert q2: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, l0, h1, l2) >= 0; */
    /*@ assert q3: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, h0, h1, l2) >= 0; */
    /*@ assert q4: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, l0, l1, h2) >= 0; */
    /*@ assert q5: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, h0, l1, h2) >= 0; */
    /*@ assert q6: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, l0, h1, h2) >= 0; */
    /*@ assert q7: aff(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, h0, h1, h2) >= 0; */
    /*@ assert f0: face_ge(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, l0, l1, h1, l2, h2, 0); */
    /*@ assert f1: face_ge(m0 - lo*w0, m1 - lo*w1, m2 - lo*w2, t - lo*wt, h0, l1, h1, l2, h2, 0); */
    /*@ assert c8: plo8(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2); */
}

/*@ requires at: CBX_CORNERS(CBX_HI_AT, l0, h0, l1, h1, l2, h2);
    requires rb: l0 <= h0 && l1 <= h1 && l2 <= h2;
    requires hi: hi == \max(\max(\max(r0, r1), \max(r2, r3)), \max(\max(r4, r5), \max(r6, r7)));
    assigns \nothing;
    ensures sound: \forall real x, y, z; l0 <= x <= h0 ==> l1 <= y <= h1 ==> l2 <= z <= h2 ==>
                   phi(hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z);
    ensures tight: pt_hi8(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
*/
static void hull_hi(cbx_fp hi, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                    cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt,
                    cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                    cbx_fp r0, cbx_fp r1, cbx_fp r2, cbx_fp r3, cbx_fp r4, cbx_fp r5, cbx_fp r6, cbx_fp r7)
{
    (void)hi; (void)m0; (void)m1; (void)m2; (void)t; (void)w0; (void)w1; (void)w2; (void)wt;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    (void)r0; (void)r1; (void)r2; (void)r3; (void)r4; (void)r5; (void)r6; (void)r7;
    /*@ assert p0: prod_le(r0, hi, aff(w0, w1, w2, wt, l0, l1, l2)); */
    /*@ assert s0: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, l2); */
    /*@ assert p1: prod_le(r1, hi, aff(w0, w1, w2, wt, h0, l1, l2)); */
    /*@ assert s1: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, l2); */
    /*@ assert p2: prod_le(r2, hi, aff(w0, w1, w2, wt, l0, h1, l2)); */
    /*@ assert s2: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, l2); */
    /*@ assert p3: prod_le(r3, hi, aff(w0, w1, w2, wt, h0, h1, l2)); */
    /*@ assert s3: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, l2); */
    /*@ assert p4: prod_le(r4, hi, aff(w0, w1, w2, wt, l0, l1, h2)); */
    /*@ assert s4: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, l1, h2); */
    /*@ assert p5: prod_le(r5, hi, aff(w0, w1, w2, wt, h0, l1, h2)); */
    /*@ assert s5: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, h0, l1, h2); */
    /*@ assert p6: prod_le(r6, hi, aff(w0, w1, w2, wt, l0, h1, h2)); */
    /*@ assert s6: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h1, h2); */
    /*@ assert p7: prod_le(r7, hi, aff(w0, w1, w2, wt, h0, h1, h2)); */
    /*@ assert s7: phi(hi, m0, m1, m2, t, w0, w1, w2, wt, h0, h1, h2); */
    /*@ assert q0: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, l0, l1, l2) >= 0; */
    /*@ assert q1: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, h0, l1, l2) >= 0; */
    /*@ assert q2: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, l0, h1, l2) >= 0; */
    /*@ assert q3: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, h0, h1, l2) >= 0; */
    /*@ assert q4: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, l0, l1, h2) >= 0; */
    /*@ assert q5: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, h0, l1, h2) >= 0; */
    /*@ assert q6: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, l0, h1, h2) >= 0; */
    /*@ assert q7: aff(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, h0, h1, h2) >= 0; */
    /*@ assert f0: face_ge(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, l0, l1, h1, l2, h2, 0); */
    /*@ assert f1: face_ge(hi*w0 - m0, hi*w1 - m1, hi*w2 - m2, hi*wt - t, h0, l1, h1, l2, h2, 0); */
    /*@ assert c8: phi8(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2); */
}

/* The three together: the axis's promise (paxis) from the 8 corners. */
#define CBX_GOOD(x, y, z, k) \is_finite(c##k.wl) && 0 < c##k.wl <= aff(w0, w1, w2, wt, x, y, z) \
    && \is_finite(c##k.lo) && plo(c##k.lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z) \
    && \is_finite(c##k.hi) && phi(c##k.hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z) \
    && pt_lo(c##k.lo, m0, m1, m2, t, w0, w1, w2, wt, x, y, z) \
    && pt_hi(c##k.hi, m0, m1, m2, t, w0, w1, w2, wt, x, y, z)
/*@ requires at: CBX_CORNERS(CBX_GOOD, l0, h0, l1, h1, l2, h2);
    requires rb: l0 <= h0 && l1 <= h1 && l2 <= h2;
    requires fin: \is_finite(lo) && \is_finite(hi);
    requires lo: lo == \min(\min(\min(c0.lo, c1.lo), \min(c2.lo, c3.lo)), \min(\min(c4.lo, c5.lo), \min(c6.lo, c7.lo)));
    requires hi: hi == \max(\max(\max(c0.hi, c1.hi), \max(c2.hi, c3.hi)), \max(\max(c4.hi, c5.hi), \max(c6.hi, c7.hi)));
    assigns \nothing;
    ensures good: paxis(lo, hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
*/
static void proj_hull(cbx_fp lo, cbx_fp hi, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                      cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt,
                      cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                      cbx_qcorner c0, cbx_qcorner c1, cbx_qcorner c2, cbx_qcorner c3,
                      cbx_qcorner c4, cbx_qcorner c5, cbx_qcorner c6, cbx_qcorner c7)
{
    hull_w(w0, w1, w2, wt, l0, h0, l1, h1, l2, h2, c0.wl, c1.wl, c2.wl, c3.wl, c4.wl, c5.wl, c6.wl, c7.wl);
    hull_lo(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2,
            c0.lo, c1.lo, c2.lo, c3.lo, c4.lo, c5.lo, c6.lo, c7.lo);
    hull_hi(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2,
            c0.hi, c1.hi, c2.hi, c3.hi, c4.hi, c5.hi, c6.hi, c7.hi);
    /*@ assert tl: pt_lo8(lo, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2); */
    /*@ assert th: pt_hi8(hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2); */
}

/* ---- one output axis: the 8 corners ------------------------------------- */
/* The least of the eight corners' statuses.  A function of its own so
 * that the seven conditional minima stay out of the axis's goals (they
 * had cost WP's simplifier about 2 s per goal of proj_axis). */
/*@ assigns \nothing;
    ensures le: \result <= a0 && \result <= a1 && \result <= a2 && \result <= a3
                && \result <= a4 && \result <= a5 && \result <= a6 && \result <= a7;
    ensures one: \result == a0 || \result == a1 || \result == a2 || \result == a3
                 || \result == a4 || \result == a5 || \result == a6 || \result == a7;
*/
static int proj_ok8(int a0, int a1, int a2, int a3, int a4, int a5, int a6, int a7)
{
    int m = a0;
    m = (a1 < m) ? a1 : m;
    m = (a2 < m) ? a2 : m;
    m = (a3 < m) ? a3 : m;
    m = (a4 < m) ? a4 : m;
    m = (a5 < m) ? a5 : m;
    m = (a6 < m) ? a6 : m;
    m = (a7 < m) ? a7 : m;
    return m;
}

typedef struct cbx_paxis { cbx_fp lo; cbx_fp hi; int ok; } cbx_paxis;

/*@ requires fin: prow_fast(m0, m1, m2, t) && prow_fast(w0, w1, w2, wt);
    requires finb: \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                   && \is_finite(l2) && \is_finite(h2);
    requires rb: -CBX_SB <= l0 <= h0 <= CBX_SB && -CBX_SB <= l1 <= h1 <= CBX_SB
                 && -CBX_SB <= l2 <= h2 <= CBX_SB;
    requires we: CBX_CORNERS(CBX_WENC, l0, h0, l1, h1, l2, h2);
    assigns \nothing;
    ensures st: 0 <= \result.ok <= 2;
    ensures behind: \result.ok == 0 ==> !pclear8(w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    ensures far: \result.ok == 1 ==> !pnear8(m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    ensures front: \result.ok >= 1 ==> pfront8(w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    ensures good: \result.ok == 2 ==>
      paxis(\result.lo, \result.hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
*/
static cbx_paxis proj_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                           cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt,
                           cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                           cbx_wc v0, cbx_wc v1, cbx_wc v2, cbx_wc v3,
                           cbx_wc v4, cbx_wc v5, cbx_wc v6, cbx_wc v7)
{
    cbx_paxis r;
    cbx_qcorner c0 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, l0, l1, l2, v0);
    cbx_qcorner c1 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, h0, l1, l2, v1);
    cbx_qcorner c2 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, l0, h1, l2, v2);
    cbx_qcorner c3 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, h0, h1, l2, v3);
    cbx_qcorner c4 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, l0, l1, h2, v4);
    cbx_qcorner c5 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, h0, l1, h2, v5);
    cbx_qcorner c6 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, l0, h1, h2, v6);
    cbx_qcorner c7 = proj_corner(m0, m1, m2, t, w0, w1, w2, wt, h0, h1, h2, v7);
    int ok = proj_ok8(c0.ok, c1.ok, c2.ok, c3.ok, c4.ok, c5.ok, c6.ok, c7.ok);
    r.lo = CBX_C(0.0);
    r.hi = CBX_C(0.0);
    r.ok = ok;
    if (ok == 2) {
        r.lo = cbx_min2(cbx_min2(cbx_min2(c0.lo, c1.lo), cbx_min2(c2.lo, c3.lo)),
                        cbx_min2(cbx_min2(c4.lo, c5.lo), cbx_min2(c6.lo, c7.lo)));
        r.hi = cbx_max2(cbx_max2(cbx_max2(c0.hi, c1.hi), cbx_max2(c2.hi, c3.hi)),
                        cbx_max2(cbx_max2(c4.hi, c5.hi), cbx_max2(c6.hi, c7.hi)));
        proj_hull(r.lo, r.hi, m0, m1, m2, t, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2,
                  c0, c1, c2, c3, c4, c5, c6, c7);
    }
    return r;
}

/* The three axes written out, each with its promise on the values. */
/*@ requires valid: \valid(out);
    requires g0: r0.ok == 2 && paxis(r0.lo, r0.hi, a00, a01, a02, a03, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    requires g1: r1.ok == 2 && paxis(r1.lo, r1.hi, a10, a11, a12, a13, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    requires g2: r2.ok == 2 && paxis(r2.lo, r2.hi, a20, a21, a22, a23, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    assigns *out;
    ensures o0: paxis(out->lo[0], out->hi[0], a00, a01, a02, a03, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    ensures o1: paxis(out->lo[1], out->hi[1], a10, a11, a12, a13, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
    ensures o2: paxis(out->lo[2], out->hi[2], a20, a21, a22, a23, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
*/
static void proj_put(cbx_box *out, cbx_paxis r0, cbx_paxis r1, cbx_paxis r2,
                     cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11, cbx_fp a12, cbx_fp a13,
                     cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23, cbx_fp w0, cbx_fp w1, cbx_fp w2, cbx_fp wt,
                     cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    (void)a00; (void)a01; (void)a02; (void)a03; (void)a10; (void)a11; (void)a12; (void)a13;
    (void)a20; (void)a21; (void)a22; (void)a23; (void)w0; (void)w1; (void)w2; (void)wt;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    out->lo[0] = r0.lo; out->hi[0] = r0.hi;
    out->lo[1] = r1.lo; out->hi[1] = r1.hi;
    out->lo[2] = r2.lo; out->hi[2] = r2.hi;
}

/* ---- the public function ------------------------------------------------ */
/* proof: -wp-split */
cbx_status cbx_project_box(const cbx_proj *p, const cbx_box *in, cbx_box *out)
{
    if ((proj_any_nan(p) | box_any_nan(in)) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (box_any_empty(in) != 0) {
        set_empty(out);
        return CBX_EMPTY;
    }
    if (!proj_in(p, in)) {
        set_whole(out);
        return CBX_ERANGE;
    }
    {
        cbx_fp l0 = in->lo[0];
        cbx_fp l1 = in->lo[1];
        cbx_fp l2 = in->lo[2];
        cbx_fp h0 = in->hi[0];
        cbx_fp h1 = in->hi[1];
        cbx_fp h2 = in->hi[2];
        cbx_fp a00 = p->m[0][0];
        cbx_fp a01 = p->m[0][1];
        cbx_fp a02 = p->m[0][2];
        cbx_fp a03 = p->m[0][3];
        cbx_fp a10 = p->m[1][0];
        cbx_fp a11 = p->m[1][1];
        cbx_fp a12 = p->m[1][2];
        cbx_fp a13 = p->m[1][3];
        cbx_fp a20 = p->m[2][0];
        cbx_fp a21 = p->m[2][1];
        cbx_fp a22 = p->m[2][2];
        cbx_fp a23 = p->m[2][3];
        cbx_fp w0 = p->m[3][0];
        cbx_fp w1 = p->m[3][1];
        cbx_fp w2 = p->m[3][2];
        cbx_fp wt = p->m[3][3];
        cbx_wc v0 = proj_wc(w0, w1, w2, wt, l0, l1, l2);
        cbx_wc v1 = proj_wc(w0, w1, w2, wt, h0, l1, l2);
        cbx_wc v2 = proj_wc(w0, w1, w2, wt, l0, h1, l2);
        cbx_wc v3 = proj_wc(w0, w1, w2, wt, h0, h1, l2);
        cbx_wc v4 = proj_wc(w0, w1, w2, wt, l0, l1, h2);
        cbx_wc v5 = proj_wc(w0, w1, w2, wt, h0, l1, h2);
        cbx_wc v6 = proj_wc(w0, w1, w2, wt, l0, h1, h2);
        cbx_wc v7 = proj_wc(w0, w1, w2, wt, h0, h1, h2);
        cbx_paxis r0 = proj_axis(a00, a01, a02, a03, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2,
                                 v0, v1, v2, v3, v4, v5, v6, v7);
        cbx_paxis r1 = proj_axis(a10, a11, a12, a13, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2,
                                 v0, v1, v2, v3, v4, v5, v6, v7);
        cbx_paxis r2 = proj_axis(a20, a21, a22, a23, w0, w1, w2, wt, l0, h0, l1, h1, l2, h2,
                                 v0, v1, v2, v3, v4, v5, v6, v7);
        if ((r0.ok == 0) || (r1.ok == 0) || (r2.ok == 0)) {
            set_whole(out);
            return CBX_EBEHIND;
        }
        if ((r0.ok == 1) || (r1.ok == 1) || (r2.ok == 1)) {
            set_whole(out);
            return CBX_ERANGE;
        }
        proj_put(out, r0, r1, r2, a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23,
                 w0, w1, w2, wt, l0, h0, l1, h1, l2, h2);
        /*@ assert same_in: \at(p->m[0][0], Pre) == a00 && \at(p->m[0][1], Pre) == a01 && \at(p->m[0][2], Pre) == a02
              && \at(p->m[0][3], Pre) == a03 && \at(p->m[1][0], Pre) == a10 && \at(p->m[1][1], Pre) == a11
              && \at(p->m[1][2], Pre) == a12 && \at(p->m[1][3], Pre) == a13 && \at(p->m[2][0], Pre) == a20
              && \at(p->m[2][1], Pre) == a21 && \at(p->m[2][2], Pre) == a22 && \at(p->m[2][3], Pre) == a23
              && \at(p->m[3][0], Pre) == w0 && \at(p->m[3][1], Pre) == w1 && \at(p->m[3][2], Pre) == w2
              && \at(p->m[3][3], Pre) == wt
              && \at(in->lo[0], Pre) == l0 && \at(in->lo[1], Pre) == l1 && \at(in->lo[2], Pre) == l2
              && \at(in->hi[0], Pre) == h0 && \at(in->hi[1], Pre) == h1 && \at(in->hi[2], Pre) == h2; */
        return CBX_OK;
    }
}
