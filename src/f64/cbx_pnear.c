/*
 * A box under a projective map, clipped at a near plane:
 * cbx_project_box_near, binary64.
 *
 * The part bounded is the box's points with W >= wn (wn > 0, the near
 * plane); output axis i is X_i / W there.  That part is a convex polytope
 * whose vertices are the box's corners with W >= wn and the crossings of
 * its 12 edges with the plane W = wn; X_i / W is linear-fractional, so its
 * ends over the part are at those vertices.
 *
 * The candidate ends are computed at the vertices in round-to-nearest
 * (pn_cands: clamped so that nothing overflows, otherwise unproven); each
 * upper end is then certified (pn_find, pn_try), the lower end being the
 * upper end of -X_i (specs/cbx_pnear.h: pn_lo_neg):
 *   - sound at t = t0 + d: for some s <= t, the outward-rounded interval
 *     enclosure of X - s W over the whole box is at most (t - s) wn
 *     (rounded down).  Then X - s W <= (t - s) wn <= (t - s) W at every
 *     point with W >= wn, so X <= t W there (the Lagrangian form of the
 *     linear program; lemma pn_hi_i).  s = t is the unclipped certificate;
 *     at an end on an edge along axis j, the exact certificate has
 *     s = a_j / b_j (X - s W constant along that edge).  pn_sound tries
 *     those four;
 *   - tight at t0 - 64 d (t0 - d where that span is too wide; only
 *     t0 + d is returned, so the witness's room costs nothing): a point of
 *     the box, the candidate's vertex moved a little toward larger W
 *     (pn_nudge), with W >= wn and X - (t0 - 64 d) W > 0 in interval
 *     arithmetic (pn_wit);
 *   - the span t0 + d - (t0 - 64 d) <= 2^-20 (1 + |end|) (ps_span), tested
 *     first.
 * d starts at 2^-48 (1 + |t0|) and grows by 4 up to 13 times.  The
 * witness is moved the least fraction of the way to its target (0, then
 * 2^-60, 2^-56, ..., 1) that puts it in front of the near plane in
 * interval arithmetic (pn_witness), before the search.
 *
 * Statuses: NaN anywhere -> CBX_EINVAL, whole space; an empty box ->
 * CBX_EMPTY, empty; outside the domain (pn_dom: linear entries and box ends
 * at most 2^60, translations at most 2^120, wn in [2^-100, 2^120]) ->
 * CBX_ERANGE, whole space; W < wn on the whole box (certified: the box lies
 * behind the near plane) -> CBX_EMPTY, empty; an end beyond 2^99, or one
 * the search cannot certify within 2^-20 -> CBX_ERANGE, whole space.
 * Proven in job PN64 (proofs/pnear.c), on the enclosures of
 * src/f64/cbx_paff.h (job PS64).
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_iv.h"
#include "cbx_paff.h"

#define PN_WLO 0x1p-100  /* the least near plane */
#define PN_WHI 0x1p120   /* the largest */
#define PN_TRIES 14

/* The arguments of an axis's computation: the rows a (X) and b (W), the
 * box and the near plane, finite and in the domain. */
/*@ predicate pn_args(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                      double l0, double h0, double l1, double h1, double l2, double h2, double wn) =
      \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
      && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
      && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
      && \is_finite(l2) && \is_finite(h2) && \is_finite(wn)
      && ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3) && pn_bx(l0, h0, l1, h1, l2, h2) && pn_wn(wn);
*/

/* ---- input checks ----------------------------------------------------- */
/*@ requires \valid_read(p) && \valid_read(b);
    assigns \nothing;
    ensures \result != 0 <==> pn_dom(p, b, wn);
*/
static int pn_dom_in(const cbx_proj *p, const cbx_box *b, double wn)
{
    int r0 = ps_row_in(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3]);
    int r1 = ps_row_in(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3]);
    int r2 = ps_row_in(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3]);
    int r3 = ps_row_in(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);
    int x0 = ps_in(b->lo[0], PS_M) && ps_in(b->hi[0], PS_M) && (b->lo[0] <= b->hi[0]);
    int x1 = ps_in(b->lo[1], PS_M) && ps_in(b->hi[1], PS_M) && (b->lo[1] <= b->hi[1]);
    int x2 = ps_in(b->lo[2], PS_M) && ps_in(b->hi[2], PS_M) && (b->lo[2] <= b->hi[2]);
    int w = (wn >= PN_WLO) && (wn <= PN_WHI);
    return r0 && r1 && r2 && r3 && x0 && x1 && x2 && w;
}

/* ---- the certificate over the box --------------------------------------- */
/* (a - s b) x over x in [l, h] enclosed above (pn_mx), from the enclosure
 * k of a - s b. */
/*@ requires fin: \is_finite(s) && \is_finite(a) && \is_finite(b) && \is_finite(l) && \is_finite(h)
                  && \is_finite(k.lo) && \is_finite(k.hi);
    requires rng: iv_rng(k.lo, k.hi, 0x1p162) && -PS_M <= l <= h <= PS_M;
    requires in: iv_has(k.lo, k.hi, a - s*b);
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures rng: iv_rng(\result.lo, \result.hi, 0x1p223);
    ensures mx: pn_mx(a - s*b, l, h) <= \result.hi;
*/
static cbx_iv pn_kb(double s, double a, double b, cbx_iv k, double l, double h)
{
    cbx_iv x;
    cbx_iv q;
    (void)s; (void)a; (void)b;
    x.lo = l;
    x.hi = h;
    q = iv_mul(k, x);
    /*@ assert b1: ps_mb(k.lo, l, 0x1p162, PS_M) && ps_mb(k.lo, h, 0x1p162, PS_M)
                   && ps_mb(k.hi, l, 0x1p162, PS_M) && ps_mb(k.hi, h, 0x1p162, PS_M); */
    /*@ assert b2: ps_itb(k.lo, k.hi, l, h, 0x1p222); */
    /*@ assert mx: pn_mx(a - s*b, l, h) <= itmax(k.lo, k.hi, l, h); */
    return q;
}

/* X - s W over the whole box, enclosed above: the upper end f with
 * X - s W <= f at every point of the box (pn_le, lemma pn_le_at). */
/*@ requires rows: ps_row(a0, a1, a2, a3) && ps_row(b0, b1, b2, b3);
    requires box: pn_bx(l0, h0, l1, h1, l2, h2);
    requires fin: \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(a3)
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(b3)
                  && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                  && \is_finite(l2) && \is_finite(h2);
    requires s: \is_finite(s) && -PS_B <= s <= PS_B;
    assigns \nothing;
    ensures fin: \is_finite(\result) && -0x1p230 <= \result <= 0x1p230;
    ensures le: pn_le(\result, s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2);
*/
static double pn_fbox(double s, double a0, double a1, double a2, double a3,
                      double b0, double b1, double b2, double b3,
                      double l0, double h0, double l1, double h1, double l2, double h2)
{
    cbx_iv k0 = ps_k(s, a0, b0);
    cbx_iv k1 = ps_k(s, a1, b1);
    cbx_iv k2 = ps_k(s, a2, b2);
    cbx_iv k3 = ps_k(s, a3, b3);
    cbx_iv q0 = pn_kb(s, a0, b0, k0, l0, h0);
    cbx_iv q1 = pn_kb(s, a1, b1, k1, l1, h1);
    cbx_iv q2 = pn_kb(s, a2, b2, k2, l2, h2);
    cbx_iv e01 = ps_sum(q0, q1, 0x1p223);
    cbx_iv e23 = ps_sum(q2, k3, 0x1p223);
    cbx_iv e = ps_sum(e01, e23, 0x1p225);
    /*@ assert sum: q0.hi + q1.hi + q2.hi + k3.hi <= e.hi; */
    /*@ assert k3: a3 - s*b3 <= k3.hi; */
    return e.hi;
}

/* 1 only if X <= t W at every point of the box with W >= wn, by the
 * certificate at s (s <= t): the enclosure of X - s W over the box at most
 * (t - s) wn, both rounded against the claim. */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires t: \is_finite(t) && \is_finite(s) && -PS_B <= s <= t <= PS_B;
    assigns \nothing;
    ensures hi: \result != 0 ==> pn_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
static int pn_cert(double t, double s, double a0, double a1, double a2, double a3,
                   double b0, double b1, double b2, double b3,
                   double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    double f = pn_fbox(s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2);
    double lam = cbx_add_dn(t, -s);
    cbx_iv m;
    if (!(lam >= 0.0)) {
        lam = 0.0;   /* s = t, or t - s below the rounding margin */
    }
    m = iv_mul(iv_pt(lam), iv_pt(wn));
    /*@ assert lam: 0 <= lam <= t - s; */
    /*@ assert mb: ps_mb(lam, wn, 0x1p102, PN_WHI); */
    /*@ assert pv: itmin(lam, lam, wn, wn) == lam*wn; */
    /*@ assert ml: m.lo <= lam*wn; */
    /*@ assert lw0: pn_lamle(lam, s, t, wn); */
    /*@ assert lw: m.lo <= pn_lw(s, t, wn); */
    return f <= m.lo;
}

/* a_j / b_j (rounded; any value serves the certificate), or 0 with ok 0
 * when |b_j| < 2^-400 or the ratio is beyond 2^100. */
typedef struct pn_s { double s; int ok; } pn_s;

/*@ requires fin: \is_finite(a) && \is_finite(b) && -PS_M <= a <= PS_M && -PS_M <= b <= PS_M;
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.s) && -PS_B <= \result.s <= PS_B;
*/
static pn_s pn_ratio(double a, double b)
{
    pn_s r;
    double ab = cbx_abs(b);
    double an = (b < 0.0) ? -a : a;
    r.s = 0.0;
    r.ok = 0;
    if (ab >= 0x1p-400) {
        cbx_iv q = iv_div(iv_pt(an), iv_pt(ab));
        if (ps_in(q.lo, PS_B) != 0) {
            r.s = q.lo;
            r.ok = 1;
        }
    }
    return r;
}

/* The certificate at s = a_j / b_j, when that is in range and <= t. */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires j: -PS_M <= aj <= PS_M && -PS_M <= bj <= PS_M && \is_finite(aj) && \is_finite(bj);
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures hi: \result != 0 ==> pn_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
static int pn_cert_at(double t, double aj, double bj, double a0, double a1, double a2, double a3,
                      double b0, double b1, double b2, double b3,
                      double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    pn_s r = pn_ratio(aj, bj);
    return (r.ok != 0) && (r.s <= t)
           && pn_cert(t, r.s, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
}

/* 1 only if X <= t W at every point of the box with W >= wn: the
 * certificate at s = a_e / b_e first when the candidate came from an edge
 * along axis e (e in 0..2; 3 for a corner), then at s = t, then at the
 * other ratios. */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures hi: \result != 0 ==> pn_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
static int pn_sound(double t, int e, double a0, double a1, double a2, double a3,
                    double b0, double b1, double b2, double b3,
                    double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    int ok = 0;
    if (e == 0) {
        ok = pn_cert_at(t, a0, b0, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    } else if (e == 1) {
        ok = pn_cert_at(t, a1, b1, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    } else if (e == 2) {
        ok = pn_cert_at(t, a2, b2, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    } else {
        /* e is 0, 1 or 2 (precondition); nothing to certify otherwise */
    }
    if (!ok) {
        ok = pn_cert(t, t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    }
    if (!ok && (e != 0)) {
        ok = pn_cert_at(t, a0, b0, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    }
    if (!ok && (e != 1)) {
        ok = pn_cert_at(t, a1, b1, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    }
    if (!ok && (e != 2)) {
        ok = pn_cert_at(t, a2, b2, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    }
    return ok;
}

/* 1 only if X - t W > 0 at the point (y0, y1, y2) of the box, in front of
 * the near plane (so some point in front has X / W > t). */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires fin: \is_finite(y0) && \is_finite(y1) && \is_finite(y2);
    requires pt: pn_box(l0, h0, l1, h1, l2, h2, y0, y1, y2);
    requires front: wn <= ps_e(0, b0, b1, b2, b3, b0, b1, b2, b3, y0, y1, y2);
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures above: \result != 0 ==> pn_above(t, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
static int pn_wit(double t, double y0, double y1, double y2, double a0, double a1, double a2, double a3,
                  double b0, double b1, double b2, double b3,
                  double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    cbx_iv g = ps_e_at(t, a0, a1, a2, a3, b0, b1, b2, b3, y0, y1, y2);
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2; (void)wn;
    return g.lo > 0.0;
}

/* ---- the candidates: the vertices in round-to-nearest --------------------- */
/* A vertex: X / W there (v, rounded), the point, the axis j along which a
 * witness moves toward larger W and the coordinate g it moves toward, e
 * the axis of its edge (3 for a corner), ok 0 for none. */
typedef struct pn_vx { double v; double x0; double x1; double x2; double g; int j; int e; int ok; } pn_vx;

/*@ predicate pn_vok(pn_vx w, real l0, real h0, real l1, real h1, real l2, real h2) =
      w.ok != 0 ==>
        \is_finite(w.v) && \is_finite(w.x0) && \is_finite(w.x1) && \is_finite(w.x2) && \is_finite(w.g)
        && -PS_C <= w.v <= PS_C && pn_box(l0, h0, l1, h1, l2, h2, w.x0, w.x1, w.x2)
        && 0 <= w.j <= 2 && 0 <= w.e <= 3
        && (w.j == 0 ==> l0 <= w.g <= h0) && (w.j == 1 ==> l1 <= w.g <= h1)
        && (w.j == 2 ==> l2 <= w.g <= h2);
*/

/* X and W at a point, in round-to-nearest (clamped). */
/*@ requires rows: ps_row(m0, m1, m2, m3) && \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(m3);
    requires pt: \is_finite(x0) && \is_finite(x1) && \is_finite(x2) && ps_ctr(x0, x1, x2, 0);
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static double pn_rn(double m0, double m1, double m2, double m3, double x0, double x1, double x2)
{
    return ps_add(ps_dot(m0, m1, m2, x0, x1, x2), m3);
}

/* The better of the candidates c and w for the upper end. */
/*@ requires pn_vok(c, l0, h0, l1, h1, l2, h2) && pn_vok(w, l0, h0, l1, h1, l2, h2);
    assigns \nothing;
    ensures pn_vok(\result, l0, h0, l1, h1, l2, h2);
*/
static pn_vx pn_best(pn_vx c, pn_vx w, double l0, double h0, double l1, double h1, double l2, double h2)
{
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    return ((w.ok != 0) && ((c.ok == 0) || (w.v > c.v))) ? w : c;
}

/* The corner (x0, x1, x2), if W >= wn there (in round-to-nearest); its
 * witness moves along axis j toward g. */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires fin: \is_finite(x0) && \is_finite(x1) && \is_finite(x2) && \is_finite(g);
    requires pt: pn_box(l0, h0, l1, h1, l2, h2, x0, x1, x2);
    requires j: 0 <= j <= 2 && (j == 0 ==> l0 <= g <= h0) && (j == 1 ==> l1 <= g <= h1)
                && (j == 2 ==> l2 <= g <= h2);
    assigns \nothing;
    ensures pn_vok(\result, l0, h0, l1, h1, l2, h2);
*/
static pn_vx pn_corner(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                       double l0, double h0, double l1, double h1, double l2, double h2, double wn,
                       double x0, double x1, double x2, int j, double g)
{
    pn_vx w;
    double X = pn_rn(a0, a1, a2, a3, x0, x1, x2);
    double W = pn_rn(b0, b1, b2, b3, x0, x1, x2);
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    w.v = 0.0;
    w.x0 = x0;
    w.x1 = x1;
    w.x2 = x2;
    w.g = g;
    w.j = j;
    w.e = 3;
    w.ok = 0;
    if (W >= wn) {
        cbx_iv q = iv_div(iv_pt(X), iv_pt(W));
        if (ps_in(q.hi, PS_C) != 0) {
            w.v = q.hi;
            w.ok = 1;
        }
    }
    return w;
}

/* x clamped to the interval between p and q. */
/*@ requires \is_finite(p) && \is_finite(q);
    assigns \nothing;
    ensures \is_finite(\result) && \min(p, q) <= \result <= \max(p, q);
*/
static double pn_between(double x, double p, double q)
{
    double lo = (p < q) ? p : q;
    double hi = (p < q) ? q : p;
    double r = x;
    if (!(r >= lo)) {
        r = lo;
    }
    if (r > hi) {
        r = hi;
    }
    return r;
}

/* The point u of the way from corner o (W below wn) to corner i (W at
 * least wn) along axis j, u = num / den (in round-to-nearest), and X / wn
 * there: the edge's crossing with the near plane; its witness moves toward
 * i. */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires fin: \is_finite(o0) && \is_finite(o1) && \is_finite(o2)
                  && \is_finite(i0) && \is_finite(i1) && \is_finite(i2) && \is_finite(num) && \is_finite(den);
    requires pt: pn_box(l0, h0, l1, h1, l2, h2, o0, o1, o2) && pn_box(l0, h0, l1, h1, l2, h2, i0, i1, i2);
    requires u: 0 <= num <= PS_L && 0x1p-400 <= den <= PS_L;
    requires j: 0 <= j <= 2;
    assigns \nothing;
    ensures pn_vok(\result, l0, h0, l1, h1, l2, h2);
*/
static pn_vx pn_cross(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                      double l0, double h0, double l1, double h1, double l2, double h2, double wn,
                      double o0, double o1, double o2, double i0, double i1, double i2, int j,
                      double num, double den)
{
    pn_vx w;
    cbx_iv uq = iv_div(iv_pt(num), iv_pt(den));
    double u = pn_between(uq.lo, 0.0, 1.0);
    double x0;
    double x1;
    double x2;
    double X;
    cbx_iv q;
    (void)b0; (void)b1; (void)b2; (void)b3; (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    /*@ assert u: 0 <= u <= 1; */
    x0 = pn_between(ps_add(o0, ps_mul(u, ps_sub(i0, o0))), o0, i0);
    x1 = pn_between(ps_add(o1, ps_mul(u, ps_sub(i1, o1))), o1, i1);
    x2 = pn_between(ps_add(o2, ps_mul(u, ps_sub(i2, o2))), o2, i2);
    X = pn_rn(a0, a1, a2, a3, x0, x1, x2);
    q = iv_div(iv_pt(X), iv_pt(wn));
    w.v = q.hi;
    w.x0 = x0;
    w.x1 = x1;
    w.x2 = x2;
    w.g = (j == 0) ? i0 : (j == 1) ? i1 : i2;
    w.j = j;
    w.e = j;
    w.ok = ps_in(q.hi, PS_C);
    return w;
}

/* The crossing of the edge from corner p to corner q (along axis j) with
 * W = wn, if W is below wn at one end and not at the other (in
 * round-to-nearest); none (ok 0) otherwise. */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires fin: \is_finite(p0) && \is_finite(p1) && \is_finite(p2)
                  && \is_finite(q0) && \is_finite(q1) && \is_finite(q2);
    requires pt: pn_box(l0, h0, l1, h1, l2, h2, p0, p1, p2) && pn_box(l0, h0, l1, h1, l2, h2, q0, q1, q2);
    requires j: 0 <= j <= 2;
    assigns \nothing;
    ensures pn_vok(\result, l0, h0, l1, h1, l2, h2);
*/
static pn_vx pn_edge(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                     double l0, double h0, double l1, double h1, double l2, double h2, double wn,
                     double p0, double p1, double p2, double q0, double q1, double q2, int j)
{
    pn_vx w;
    double wp = pn_rn(b0, b1, b2, b3, p0, p1, p2);
    double wq = pn_rn(b0, b1, b2, b3, q0, q1, q2);
    w.v = 0.0;
    w.x0 = p0;
    w.x1 = p1;
    w.x2 = p2;
    w.g = p0;
    w.j = 0;
    w.e = 3;
    w.ok = 0;
    if ((wp < wn) && (wq >= wn)) {
        double num = ps_sub(wn, wp);
        double den = ps_sub(wq, wp);
        if ((num >= 0.0) && (den >= 0x1p-400)) {
            w = pn_cross(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, p0, p1, p2, q0, q1, q2, j,
                         num, den);
        }
    } else if ((wq < wn) && (wp >= wn)) {
        double num = ps_sub(wn, wq);
        double den = ps_sub(wp, wq);
        if ((num >= 0.0) && (den >= 0x1p-400)) {
            w = pn_cross(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, q0, q1, q2, p0, p1, p2, j,
                         num, den);
        }
    }
    return w;
}

/* The largest of X / W over the vertices (in round-to-nearest): the 8
 * corners and the 12 edges' crossings; a corner's witness moves along
 * axis jc toward gc. */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn) && \is_finite(gc);
    requires j: 0 <= jc <= 2 && (jc == 0 ==> l0 <= gc <= h0) && (jc == 1 ==> l1 <= gc <= h1)
                && (jc == 2 ==> l2 <= gc <= h2);
    assigns \nothing;
    ensures pn_vok(\result, l0, h0, l1, h1, l2, h2);
*/
static pn_vx pn_cands(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                      double l0, double h0, double l1, double h1, double l2, double h2, double wn,
                      int jc, double gc)
{
    pn_vx c;
    int k;
    c.v = 0.0;
    c.x0 = l0;
    c.x1 = l1;
    c.x2 = l2;
    c.g = gc;
    c.j = jc;
    c.e = 3;
    c.ok = 0;
    /*@ loop invariant k: 0 <= k <= 8;
        loop invariant c: pn_vok(c, l0, h0, l1, h1, l2, h2);
        loop assigns k, c;
        loop variant 8 - k;
    */
    for (k = 0; k < 8; k++) {   /* corner k, and its edges toward the corners with one more bit set */
        double x0 = ((k & 1) != 0) ? h0 : l0;
        double x1 = ((k & 2) != 0) ? h1 : l1;
        double x2 = ((k & 4) != 0) ? h2 : l2;
        pn_vx w = pn_corner(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, x0, x1, x2, jc, gc);
        c = pn_best(c, w, l0, h0, l1, h1, l2, h2);
        if ((k & 1) == 0) {
            w = pn_edge(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, x0, x1, x2, h0, x1, x2, 0);
            c = pn_best(c, w, l0, h0, l1, h1, l2, h2);
        }
        if ((k & 2) == 0) {
            w = pn_edge(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, x0, x1, x2, x0, h1, x2, 1);
            c = pn_best(c, w, l0, h0, l1, h1, l2, h2);
        }
        if ((k & 4) == 0) {
            w = pn_edge(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, x0, x1, x2, x0, x1, h2, 2);
            c = pn_best(c, w, l0, h0, l1, h1, l2, h2);
        }
    }
    return c;
}

/* ---- the search --------------------------------------------------------- */
typedef struct pn_pt { double y0; double y1; double y2; } pn_pt;

/* The candidate's point moved the fraction frac of the way to its target
 * along its axis (toward larger W). */
/*@ requires ok: w.ok != 0 && pn_vok(w, l0, h0, l1, h1, l2, h2);
    requires frac: \is_finite(frac) && 0 <= frac <= 1;
    requires box: pn_bx(l0, h0, l1, h1, l2, h2);
    assigns \nothing;
    ensures fin: \is_finite(\result.y0) && \is_finite(\result.y1) && \is_finite(\result.y2);
    ensures pt: pn_box(l0, h0, l1, h1, l2, h2, \result.y0, \result.y1, \result.y2);
*/
static pn_pt pn_nudge(pn_vx w, double frac, double l0, double h0, double l1, double h1, double l2, double h2)
{
    pn_pt y;
    double x = (w.j == 0) ? w.x0 : (w.j == 1) ? w.x1 : w.x2;
    double m;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    /*@ assert xr: -PS_M <= x <= PS_M && -PS_M <= w.g <= PS_M; */
    m = pn_between(ps_add(x, ps_mul(frac, ps_sub(w.g, x))), x, w.g);
    y.y0 = (w.j == 0) ? m : w.x0;
    y.y1 = (w.j == 1) ? m : w.x1;
    y.y2 = (w.j == 2) ? m : w.x2;
    return y;
}

/* The rate of W per unit of the witness's fraction: b_j (g - x_j) along
 * the candidate's axis j, in round-to-nearest (for ps_frac). */
/*@ requires ok: c.ok != 0 && pn_vok(c, l0, h0, l1, h1, l2, h2);
    requires box: pn_bx(l0, h0, l1, h1, l2, h2);
    requires b: \is_finite(b0) && \is_finite(b1) && \is_finite(b2)
                && -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M;
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static double pn_rate(pn_vx c, double b0, double b1, double b2,
                      double l0, double h0, double l1, double h1, double l2, double h2)
{
    double x = (c.j == 0) ? c.x0 : (c.j == 1) ? c.x1 : c.x2;
    double bj = (c.j == 0) ? b0 : (c.j == 1) ? b1 : b2;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    /*@ assert xr: -PS_M <= x <= PS_M && -PS_M <= c.g <= PS_M; */
    return ps_mul(bj, ps_sub(c.g, x));
}

/* The witness point: the candidate's point moved the least fraction
 * (0, then the first guess of ps_frac or 2^-60 if larger, then 16 times
 * the last, up to 1) toward its target for which W >= wn there
 * in interval arithmetic; ok 0 when none. */
typedef struct pn_wp { pn_pt y; int ok; } pn_wp;

/*@ requires args: pn_args(b0, b1, b2, b3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires c: c.ok != 0 && pn_vok(c, l0, h0, l1, h1, l2, h2);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.y.y0) && \is_finite(\result.y.y1)
      && \is_finite(\result.y.y2) && pn_box(l0, h0, l1, h1, l2, h2, \result.y.y0, \result.y.y1, \result.y.y2)
      && wn <= ps_e(0, b0, b1, b2, b3, b0, b1, b2, b3, \result.y.y0, \result.y.y1, \result.y.y2);
*/
static pn_wp pn_witness(pn_vx c, double b0, double b1, double b2, double b3,
                        double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    pn_wp r;
    double frac = 0.0;
    int k;
    r.y.y0 = 0.0;
    r.y.y1 = 0.0;
    r.y.y2 = 0.0;
    r.ok = 0;
    /*@ loop invariant k: 0 <= k <= 17;
        loop invariant frac: \is_finite(frac) && 0 <= frac <= 1;
        loop invariant r: r.ok == 0;
        loop assigns k, frac, r;
        loop variant 17 - k;
    */
    for (k = 0; k < 17; k++) {
        pn_pt y = pn_nudge(c, frac, l0, h0, l1, h1, l2, h2);
        cbx_iv w = ps_e_at(0.0, b0, b1, b2, b3, b0, b1, b2, b3, y.y0, y.y1, y.y2);
        double nx = (frac == 0.0) ? 0x1p-60 : pn_between(cbx_mul_rn(frac, 16.0), 0.0, 1.0);
        if (w.lo >= wn) {
            r.y = y;
            r.ok = 1;
            break;
        }
        if (frac == 0.0) {
            double gs = ps_frac(w, wn, pn_rate(c, b0, b1, b2, l0, h0, l1, h1, l2, h2));
            nx = (gs > nx) ? gs : nx;
        }
        frac = nx;
    }
    return r;
}

/* One try: sound at th, the witness y above tl, th - tl within
 * ps_tau(th). */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires fin: \is_finite(y.y0) && \is_finite(y.y1) && \is_finite(y.y2);
    requires pt: pn_box(l0, h0, l1, h1, l2, h2, y.y0, y.y1, y.y2);
    requires front: wn <= ps_e(0, b0, b1, b2, b3, b0, b1, b2, b3, y.y0, y.y1, y.y2);
    requires t: \is_finite(th) && \is_finite(tl) && -PS_B <= th <= PS_B && -PS_B <= tl <= PS_B;
    assigns \nothing;
    ensures hi: \result != 0 ==> pn_hi(th, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      && th - ps_tau(th) <= tl && pn_above(tl, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
static int pn_try(double th, double tl, int e, pn_pt y, double a0, double a1, double a2, double a3,
                  double b0, double b1, double b2, double b3,
                  double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    return ps_span(th, tl, th)
           && pn_sound(th, e, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
           && pn_wit(tl, y.y0, y.y1, y.y2, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
}

typedef struct pn_fin { double v; double w; int ok; } pn_fin;

/* The upper end from the candidate w: v with X <= v W at every point in
 * front, w with some point in front above it, v - w <= ps_tau(v). */
/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    requires c: c.ok != 0 && pn_vok(c, l0, h0, l1, h1, l2, h2);
    assigns \nothing;
    ensures fin: \result.ok != 0 ==> \is_finite(\result.v) && \is_finite(\result.w)
      && -PS_B <= \result.v <= PS_B;
    ensures hi: \result.ok != 0 ==>
      pn_hi(\result.v, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      && \result.v - ps_tau(\result.v) <= \result.w
      && pn_above(\result.w, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
static pn_fin pn_find(pn_vx c, double a0, double a1, double a2, double a3,
                      double b0, double b1, double b2, double b3,
                      double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    pn_fin f;
    double t0 = c.v;
    double d = cbx_mul_rn(cbx_add_rn(1.0, cbx_abs(t0)), 0x1p-48);
    pn_wp y = pn_witness(c, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    int k;
    f.v = 0.0;
    f.w = 0.0;
    f.ok = 0;
    /*@ loop invariant k: 0 <= k <= PN_TRIES;
        loop invariant d: \is_finite(d) && 0 <= d <= 0x1p93;
        loop invariant f: f.ok == 0;
        loop assigns k, d, f;
        loop variant PN_TRIES - k;
    */
    for (k = 0; k < PN_TRIES && d <= 0x1p90 && y.ok != 0; k++) {
        double th = t0 + d;
        double tw = ps_sub(t0, ps_mul(d, 64.0));   /* the witness's room: only th is returned */
        double tl = (ps_in(th, PS_B) && ps_in(tw, PS_B) && ps_span(th, tw, th)) ? tw : (t0 - d);
        if (ps_in(th, PS_B) && ps_in(tl, PS_B)
            && pn_try(th, tl, c.e, y.y, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)) {
            f.v = th;
            f.w = tl;
            f.ok = 1;
            break;
        }
        d = cbx_mul_rn(d, 4.0);
    }
    return f;
}

/* ---- one output axis ---------------------------------------------------- */

/*@ requires args: pn_args(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn) && \is_finite(gc);
    requires j: 0 <= jc <= 2 && (jc == 0 ==> l0 <= gc <= h0) && (jc == 1 ==> l1 <= gc <= h1)
                && (jc == 2 ==> l2 <= gc <= h2);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
      && pn_axis(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn)
      && pn_tight(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
*/
static ps_ax pn_axis_of(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                        double l0, double h0, double l1, double h1, double l2, double h2, double wn,
                        int jc, double gc)
{
    ps_ax x;
    pn_vx ch = pn_cands(a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, jc, gc);
    pn_vx cl = pn_cands(-a0, -a1, -a2, -a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn, jc, gc);
    x.lo = 0.0;
    x.hi = 0.0;
    x.ok = 0;
    if ((ch.ok != 0) && (cl.ok != 0)) {
        pn_fin h = pn_find(ch, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
        pn_fin l = pn_find(cl, -a0, -a1, -a2, -a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
        if ((h.ok != 0) && (l.ok != 0)) {
            x.lo = -l.v;
            x.hi = h.v;
            x.ok = 1;
            /*@ assert lo: pn_lo(x.lo, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn); */
            /*@ assert below: pn_below(-l.w, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn); */
            /*@ assert tl: -l.w <= x.lo + ps_tau(x.lo); */
            /*@ assert cov: pn_axis(x.lo, x.hi, a0, a1, a2, a3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn); */
        }
    }
    return x;
}

/* W < wn on the whole box: nothing of it in front of the near plane. */
/*@ requires args: pn_args(b0, b1, b2, b3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2, wn);
    assigns \nothing;
    ensures void: \result != 0 ==> pn_void(wn, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2);
*/
static int pn_behind(double b0, double b1, double b2, double b3,
                     double l0, double h0, double l1, double h1, double l2, double h2, double wn)
{
    double f = pn_fbox(0.0, b0, b1, b2, b3, b0, b1, b2, b3, l0, h0, l1, h1, l2, h2);
    return f < wn;
}

/* The axis along which a corner's witness moves: the one where W varies
 * most over the box (|b_j| (h_j - l_j), round-to-nearest), toward its end
 * with the larger W. */
typedef struct pn_dir { double g; int j; } pn_dir;

/*@ requires row: -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M
                  && \is_finite(b0) && \is_finite(b1) && \is_finite(b2);
    requires box: pn_bx(l0, h0, l1, h1, l2, h2) && \is_finite(l0) && \is_finite(h0) && \is_finite(l1)
                  && \is_finite(h1) && \is_finite(l2) && \is_finite(h2);
    assigns \nothing;
    ensures fin: \is_finite(\result.g) && 0 <= \result.j <= 2;
    ensures g: (\result.j == 0 ==> l0 <= \result.g <= h0) && (\result.j == 1 ==> l1 <= \result.g <= h1)
               && (\result.j == 2 ==> l2 <= \result.g <= h2);
*/
static pn_dir pn_dir_of(double b0, double b1, double b2,
                        double l0, double h0, double l1, double h1, double l2, double h2)
{
    pn_dir r;
    double s0 = ps_mul(cbx_abs(b0), ps_sub(h0, l0));
    double s1 = ps_mul(cbx_abs(b1), ps_sub(h1, l1));
    double s2 = ps_mul(cbx_abs(b2), ps_sub(h2, l2));
    r.j = 0;
    r.g = (b0 >= 0.0) ? h0 : l0;
    if ((s1 > s0) && (s1 >= s2)) {
        r.j = 1;
        r.g = (b1 >= 0.0) ? h1 : l1;
    } else if (s2 > s0) {   /* then s2 > s1 too: s1 <= s0 here */
        r.j = 2;
        r.g = (b2 >= 0.0) ? h2 : l2;
    } else {
        /* axis 0 has the widest span: r as initialised */
    }
    return r;
}

/* ---- the public function ------------------------------------------------ */
cbx_status cbx_project_box_near(const cbx_proj *p, const cbx_box *in, double wn, cbx_box *out)
{
    if ((ps_proj_nan(p) | box_any_nan(in) | cbx_is_nan(wn)) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (box_any_empty(in) != 0) {
        set_empty(out);
        return CBX_EMPTY;
    }
    if (!pn_dom_in(p, in, wn)) {
        set_whole(out);
        return CBX_ERANGE;
    }
    {
        double l0 = in->lo[0];
        double h0 = in->hi[0];
        double l1 = in->lo[1];
        double h1 = in->hi[1];
        double l2 = in->lo[2];
        double h2 = in->hi[2];
        double w0 = p->m[3][0];
        double w1 = p->m[3][1];
        double w2 = p->m[3][2];
        double wt = p->m[3][3];
        ps_ax x0;
        ps_ax x1;
        ps_ax x2;
        pn_dir dc;
        if (pn_behind(w0, w1, w2, wt, l0, h0, l1, h1, l2, h2, wn) != 0) {
            set_empty(out);
            return CBX_EMPTY;
        }
        dc = pn_dir_of(w0, w1, w2, l0, h0, l1, h1, l2, h2);
        x0 = pn_axis_of(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3], w0, w1, w2, wt,
                        l0, h0, l1, h1, l2, h2, wn, dc.j, dc.g);
        x1 = pn_axis_of(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3], w0, w1, w2, wt,
                        l0, h0, l1, h1, l2, h2, wn, dc.j, dc.g);
        x2 = pn_axis_of(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3], w0, w1, w2, wt,
                        l0, h0, l1, h1, l2, h2, wn, dc.j, dc.g);
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
