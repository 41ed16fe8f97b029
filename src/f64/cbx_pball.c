/*
 * A ball under a projective map, clipped at a near plane:
 * cbx_project_sphere_near, binary64.
 *
 * The ball is {c + r q : |q| <= 1}; the part bounded is its points with
 * W >= wn (wn > 0, the near plane); output axis i is X_i / W there.  Over
 * the whole ball X - s W is at most h(s) = e(s) + |r| |k(s)| (e its value
 * at c, k(s) = a - s b its linear part: specs/cbx_psph.h), so for s <= t,
 * h(s) <= (t - s) wn makes X <= t W at every point with W >= wn (the
 * Lagrangian form of max X / W over the part: specs/cbx_pball.h).  The
 * exact upper end is min over s of max(s, s + h(s) / wn):
 *   - where the tangent point of the unclipped bound is in front of the
 *     plane, s = t and t the unclipped end (cbx_project_sphere's closed
 *     form, ps_candidate);
 *   - otherwise the end is on the circle where the plane cuts the ball,
 *     at the minimiser s* of s + h(s) / wn: with alpha = a.b / |b|^2,
 *     u = a - alpha b and g = (W(c) - wn) / (|r| |b|) in (-1, 1),
 *     s* = alpha + g |u| / (|b| sqrt(1 - g^2)), and the end is
 *     s* + h(s*) / wn (pb_clip).
 * Both candidates are computed in round-to-nearest (clamped so that
 * nothing overflows, otherwise unproven) and certified (pb_find):
 *   - sound at t = t0 + d: the outward-rounded enclosure of h(s) at most
 *     (t - s) wn rounded down (pb_cert), s = s* or s = t;
 *   - tight at t0 - 64 d (t0 - d where that span is too wide; only
 *     t0 + d is returned, so the witness's room costs nothing): a point
 *     c + r q of the ball, q the direction sign(r) k(s) / |k(s)| that
 *     attains h(s) (shrunk by 2^-47), moved the least fraction toward the
 *     direction of largest W that puts it in front of the plane
 *     (pb_witness: 0, then a first guess from W's shortfall there, then 16
 *     times the last), with X - (t0 - 64 d) W > 0 there, all in interval
 *     arithmetic (pb_wit);
 *   - the span t0 + d - (t0 - 64 d) <= 2^-20 (1 + |end|) (ps_span), tested
 *     first.
 * d starts at 2^-48 (1 + |t0|) and grows by 4 up to 13 times.
 * The lower end is the upper end of -X_i (specs/cbx_pball.h: pb_lo_neg).
 *
 * Statuses: NaN anywhere (wn included) -> CBX_EINVAL, whole space; outside
 * the domain (pb_dom: linear entries, center and radius at most 2^60,
 * translations at most 2^120, wn in [2^-100, 2^120]) -> CBX_ERANGE, whole
 * space; W < wn on the whole ball (certified) -> CBX_EMPTY, empty; an end
 * beyond 2^99, or one the search cannot certify within 2^-20 ->
 * CBX_ERANGE, whole space.  Proven in job PB64 (proofs/pball.c), on the
 * enclosures of src/f64/cbx_paff.h and cbx_pgap.h (job PS64).
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_iv.h"
#include "cbx_paff.h"
#include "cbx_pgap.h"

#define PB_WLO 0x1p-100  /* the least near plane */
#define PB_WHI 0x1p120   /* the largest */
#define PB_TRIES 14
#define PB_SHRINK 0x1.fffffffffffcp-1   /* 1 - 2^-47: a witness inside the ball */

/* The arguments of an axis's computation: the rows a (X) and b (W), the
 * ball and the near plane, finite and in the domain. */
/*@ predicate pb_args(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                      double c0, double c1, double c2, double r, double wn) =
      ps_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r) && \is_finite(wn) && pn_wn(wn);
*/

/* ---- input checks ----------------------------------------------------- */
/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> pb_nan(p, c, r, wn);
*/
static int pb_any_nan(const cbx_proj *p, const double c[3], double r, double wn)
{
    return ps_proj_nan(p) | cbx_is_nan(c[0]) | cbx_is_nan(c[1]) | cbx_is_nan(c[2]) | cbx_is_nan(r)
           | cbx_is_nan(wn);
}

/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> pb_dom(p, c, r, wn);
*/
static int pb_dom_in(const cbx_proj *p, const double c[3], double r, double wn)
{
    int r0 = ps_row_in(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3]);
    int r1 = ps_row_in(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3]);
    int r2 = ps_row_in(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3]);
    int r3 = ps_row_in(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);
    int ct = ps_in(c[0], PS_M) && ps_in(c[1], PS_M) && ps_in(c[2], PS_M) && ps_in(r, PS_M);
    int w = (wn >= PB_WLO) && (wn <= PB_WHI);
    return r0 && r1 && r2 && r3 && ct && w;
}

/* ---- the certificate over the ball ------------------------------------ */
/* 1 only if X <= t W at every point of the ball with W >= wn, by the
 * certificate at s (s <= t): the enclosure of h(s) at most (t - s) wn,
 * both rounded against the claim. */
/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    requires t: \is_finite(t) && \is_finite(s) && -PS_B <= s <= t <= PS_B;
    assigns \nothing;
    ensures hi: \result != 0 ==> pb_hi(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
*/
static int pb_cert(double t, double s, double a0, double a1, double a2, double a3,
                   double b0, double b1, double b2, double b3,
                   double c0, double c1, double c2, double r, double wn)
{
    ps_gap g = ps_gap_at(s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    cbx_iv f = iv_add(g.e, g.k);
    double lam = cbx_add_dn(t, -s);
    cbx_iv m;
    if (!(lam >= 0.0)) {
        lam = 0.0;   /* s = t, or t - s below the rounding margin */
    }
    m = iv_mul(iv_pt(lam), iv_pt(wn));
    /*@ assert le: pb_le(f.hi, s, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r); */
    /*@ assert lam: 0 <= lam <= t - s; */
    /*@ assert mb: ps_mb(lam, wn, 0x1p102, PB_WHI); */
    /*@ assert pv: itmin(lam, lam, wn, wn) == lam*wn; */
    /*@ assert ml: m.lo <= lam*wn; */
    /*@ assert lw0: pn_lamle(lam, s, t, wn); */
    /*@ assert lw: m.lo <= pn_lw(s, t, wn); */
    return f.hi <= m.lo;
}

/* ---- the witness: a point c + r q ------------------------------------- */
/* X - t W at c + r q (pb_v), enclosed: its value at c plus r times its
 * linear part at q. */
/*@ requires args: ps_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    requires q: \is_finite(q0) && \is_finite(q1) && \is_finite(q2)
                && -1 <= q0 <= 1 && -1 <= q1 <= 1 && -1 <= q2 <= 1;
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures fin: \is_finite(\result.lo) && \is_finite(\result.hi);
    ensures v: iv_has(\result.lo, \result.hi, pb_v(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2));
*/
static cbx_iv pb_val(double t, double a0, double a1, double a2, double a3,
                     double b0, double b1, double b2, double b3,
                     double c0, double c1, double c2, double r, double q0, double q1, double q2)
{
    cbx_iv e = ps_e_at(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2);
    cbx_iv k0 = ps_k(t, a0, b0);
    cbx_iv k1 = ps_k(t, a1, b1);
    cbx_iv k2 = ps_k(t, a2, b2);
    cbx_iv p0 = ps_kc(t, a0, b0, k0, q0);
    cbx_iv p1 = ps_kc(t, a1, b1, k1, q1);
    cbx_iv p2 = ps_kc(t, a2, b2, k2, q2);
    cbx_iv s01 = ps_sum(p0, p1, 0x1p223);
    cbx_iv s = ps_sum(s01, p2, 0x1p225);
    cbx_iv g;
    /*@ assert i01: iv_has(s01.lo, s01.hi, (a0 - t*b0)*q0 + (a1 - t*b1)*q1); */
    /*@ assert i: iv_has(s.lo, s.hi, dot3(a0 - t*b0, a1 - t*b1, a2 - t*b2, q0, q1, q2)); */
    g = iv_mul(iv_pt(r), s);
    /*@ assert kb: ps_mb(r, s.lo, PS_M, 0x1p227) && ps_mb(r, s.hi, PS_M, 0x1p227); */
    /*@ assert kbl: -0x1p287 <= r*s.lo <= 0x1p287; */
    /*@ assert kbh: -0x1p287 <= r*s.hi <= 0x1p287; */
    /*@ assert k1: ps_itb(r, r, s.lo, s.hi, 0x1p287); */
    /*@ assert kin: prod_at(g.lo, g.hi, r, dot3(a0 - t*b0, a1 - t*b1, a2 - t*b2, q0, q1, q2)); */
    /*@ assert gr: iv_rng(g.lo, g.hi, 0x1p288); */
    return ps_sum(e, g, 0x1p288);
}

/* 1 only if |q| <= 1 (the unit ball, in interval arithmetic). */
/*@ requires q: \is_finite(q0) && \is_finite(q1) && \is_finite(q2);
    assigns \nothing;
    ensures ok: \result != 0 ==> in_ball(q0, q1, q2)
      && -1 <= q0 <= 1 && -1 <= q1 <= 1 && -1 <= q2 <= 1;
*/
static int pb_unit(double q0, double q1, double q2)
{
    int ok = 0;
    if (ps_in(q0, 1.0) && ps_in(q1, 1.0) && ps_in(q2, 1.0)) {
        cbx_iv s0 = iv_sqr(iv_pt(q0));
        cbx_iv s1 = iv_sqr(iv_pt(q1));
        cbx_iv s2 = iv_sqr(iv_pt(q2));
        cbx_iv s01;
        cbx_iv s;
        /*@ assert r0: sqmax(q0, q0) <= 1 && sqmax(q1, q1) <= 1 && sqmax(q2, q2) <= 1; */
        /*@ assert in0: sq_at(s0.lo, s0.hi, q0) && sq_at(s1.lo, s1.hi, q1) && sq_at(s2.lo, s2.hi, q2); */
        /*@ assert rg: iv_rng(s0.lo, s0.hi, 3) && iv_rng(s1.lo, s1.hi, 3) && iv_rng(s2.lo, s2.hi, 3); */
        s01 = ps_sum(s0, s1, 3.0);
        /*@ assert i01: iv_has(s01.lo, s01.hi, q0*q0 + q1*q1); */
        /*@ assert r01: iv_rng(s01.lo, s01.hi, 9); */
        s = ps_sum(s01, s2, 9.0);
        /*@ assert i: iv_has(s.lo, s.hi, nrm3(q0, q1, q2)); */
        ok = s.hi <= 1.0;
    }
    return ok;
}

/* 1 only if X - t W > 0 at the point c + r q of the ball, in front of the
 * near plane (so some point in front has X / W > t). */
/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    requires q: \is_finite(q0) && \is_finite(q1) && \is_finite(q2)
                && -1 <= q0 <= 1 && -1 <= q1 <= 1 && -1 <= q2 <= 1;
    requires front: pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    requires t: \is_finite(t) && -PS_B <= t <= PS_B;
    assigns \nothing;
    ensures above: \result != 0 ==> pb_above(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
*/
static int pb_wit(double t, double q0, double q1, double q2, double a0, double a1, double a2, double a3,
                  double b0, double b1, double b2, double b3,
                  double c0, double c1, double c2, double r, double wn)
{
    cbx_iv g = pb_val(t, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, q0, q1, q2);
    (void)wn;
    return g.lo > 0.0;
}

/* ---- round-to-nearest pieces of the candidates and the witness --------- */
/* sqrt(max(x, 0)) rounded. */
/*@ requires \is_finite(x) && -PS_L <= x <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result) && 0 <= \result <= PS_L;
*/
static double pb_sqrt(double x)
{
    double s = 0.0;
    if (x > 0.0) {
        s = cbx_sqrt_rn(x);
    }
    /*@ assert sqq: sql(s, PS_L); */
    return s;
}

/* x clamped to [-1, 1]. */
/*@ requires \is_finite(x);
    assigns \nothing;
    ensures \is_finite(\result) && -1 <= \result <= 1;
*/
static double pb_c1(double x)
{
    return (x > 1.0) ? 1.0 : (x < -1.0) ? -1.0 : x;
}

/* A direction: sign(r) v / |v| shrunk by PB_SHRINK, 0 when |v| < 2^-400. */
typedef struct pb_q { double q0; double q1; double q2; int ok; } pb_q;

/*@ requires \is_finite(v0) && \is_finite(v1) && \is_finite(v2) && \is_finite(r);
    requires -PS_L <= v0 <= PS_L && -PS_L <= v1 <= PS_L && -PS_L <= v2 <= PS_L;
    assigns \nothing;
    ensures \is_finite(\result.q0) && \is_finite(\result.q1) && \is_finite(\result.q2);
    ensures -1 <= \result.q0 <= 1 && -1 <= \result.q1 <= 1 && -1 <= \result.q2 <= 1;
*/
static pb_q pb_unitv(double v0, double v1, double v2, double r)
{
    pb_q q;
    double n = pb_sqrt(ps_dot(v0, v1, v2, v0, v1, v2));
    double f = (r < 0.0) ? -PB_SHRINK : PB_SHRINK;
    q.q0 = 0.0;
    q.q1 = 0.0;
    q.q2 = 0.0;
    q.ok = 1;
    if (n >= 0x1p-400) {
        q.q0 = pb_c1(ps_mul(ps_qt(v0, n), f));
        q.q1 = pb_c1(ps_mul(ps_qt(v1, n), f));
        q.q2 = pb_c1(ps_mul(ps_qt(v2, n), f));
    }
    return q;
}

/* The next fraction of the witness's search: 0, 2^-60, 2^-56, ..., 1. */
/*@ requires \is_finite(f) && 0 <= f <= 1;
    assigns \nothing;
    ensures \is_finite(\result) && 0 <= \result <= 1;
*/
static double pb_next(double f)
{
    double n = 0x1p-60;
    if (f != 0.0) {
        n = cbx_mul_rn(f, 16.0);
    }
    return (n > 1.0) ? 1.0 : n;
}

/* The rate of W at c + r q per unit of the witness's fraction along
 * g - k: r b.(g - k), in round-to-nearest (for ps_frac). */
/*@ requires k: \is_finite(k.q0) && \is_finite(k.q1) && \is_finite(k.q2)
                && -1 <= k.q0 <= 1 && -1 <= k.q1 <= 1 && -1 <= k.q2 <= 1;
    requires g: \is_finite(g.q0) && \is_finite(g.q1) && \is_finite(g.q2)
                && -1 <= g.q0 <= 1 && -1 <= g.q1 <= 1 && -1 <= g.q2 <= 1;
    requires b: \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(r)
                && -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M
                && -PS_M <= r <= PS_M;
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static double pb_rate(pb_q k, pb_q g, double b0, double b1, double b2, double r)
{
    return ps_mul(r, ps_dot(b0, b1, b2, ps_sub(g.q0, k.q0), ps_sub(g.q1, k.q1), ps_sub(g.q2, k.q2)));
}

/* The witness: the start direction k (the point of the ball where the
 * candidate end is attained, in round-to-nearest), moved the least
 * fraction (0, then the first guess of ps_frac or 2^-60 if larger, then
 * 16 times the last, up to 1) toward the direction of largest
 * W for which c + r q is in the ball and in front of the near plane in
 * interval arithmetic; ok 0 when none. */
/*@ requires args: pb_args(b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    requires k: \is_finite(k.q0) && \is_finite(k.q1) && \is_finite(k.q2)
                && -1 <= k.q0 <= 1 && -1 <= k.q1 <= 1 && -1 <= k.q2 <= 1;
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.q0) && \is_finite(\result.q1) && \is_finite(\result.q2)
      && -1 <= \result.q0 <= 1 && -1 <= \result.q1 <= 1 && -1 <= \result.q2 <= 1
      && pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, \result.q0, \result.q1, \result.q2);
*/
static pb_q pb_witness(pb_q k, double b0, double b1, double b2, double b3,
                       double c0, double c1, double c2, double r, double wn)
{
    pb_q g = pb_unitv(b0, b1, b2, r);
    pb_q o;
    double frac = 0.0;
    int i;
    o.q0 = 0.0;
    o.q1 = 0.0;
    o.q2 = 0.0;
    o.ok = 0;
    /*@ loop invariant i: 0 <= i <= 17;
        loop invariant frac: \is_finite(frac) && 0 <= frac <= 1;
        loop invariant o: o.ok == 0;
        loop assigns i, frac, o;
        loop variant 17 - i;
    */
    for (i = 0; i < 17; i++) {
        double y0 = pb_c1(ps_add(k.q0, ps_mul(frac, ps_sub(g.q0, k.q0))));
        double y1 = pb_c1(ps_add(k.q1, ps_mul(frac, ps_sub(g.q1, k.q1))));
        double y2 = pb_c1(ps_add(k.q2, ps_mul(frac, ps_sub(g.q2, k.q2))));
        double nx = pb_next(frac);
        if (pb_unit(y0, y1, y2) != 0) {
            cbx_iv w = pb_val(0.0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r, y0, y1, y2);
            if (w.lo >= wn) {
                /*@ assert in: pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, y0, y1, y2); */
                o.q0 = y0;
                o.q1 = y1;
                o.q2 = y2;
                o.ok = 1;
                break;
            }
            if (frac == 0.0) {
                double gs = ps_frac(w, wn, pb_rate(k, g, b0, b1, b2, r));
                nx = (gs > nx) ? gs : nx;
            }
        }
        frac = nx;
    }
    return o;
}

/* ---- the candidates ------------------------------------------------------ */
/* An upper end t0 with the multiplier s of its certificate (clip != 0:
 * s = s*, else s = t) and, for a clipped end, the direction q of its point
 * on the near plane's circle; ok 0 for none. */
typedef struct pb_cand { double t; double s; pb_q q; int clip; int ok; } pb_cand;

/* A candidate's direction in range: each entry in [-1, 1]. */
/*@ predicate pb_qok(pb_q q) = \is_finite(q.q0) && \is_finite(q.q1) && \is_finite(q.q2)
      && -1 <= q.q0 <= 1 && -1 <= q.q1 <= 1 && -1 <= q.q2 <= 1;
    predicate pb_cok(pb_cand c) = pb_qok(c.q) && (c.ok != 0 ==> \is_finite(c.t) && \is_finite(c.s)
      && -PS_C <= c.t <= PS_C && -PS_C <= c.s <= PS_C);
*/

/* No candidate (clip: its kind). */
/*@ assigns \nothing;
    ensures pb_cok(\result) && \result.ok == 0 && \result.clip == clip;
*/
static pb_cand pb_none(int clip)
{
    pb_cand o;
    o.t = 0.0;
    o.s = 0.0;
    o.q.q0 = 0.0;
    o.q.q1 = 0.0;
    o.q.q2 = 0.0;
    o.q.ok = 0;
    o.clip = clip;
    o.ok = 0;
    return o;
}

/* A unit vector orthogonal to (b0, b1, b2) (|b| >= 2^-400, rounded): b
 * crossed with the axis where |b_j| is least. */
/*@ requires \is_finite(b0) && \is_finite(b1) && \is_finite(b2);
    requires -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M;
    assigns \nothing;
    ensures pb_qok(\result);
*/
static pb_q pb_perp(double b0, double b1, double b2)
{
    double x0 = 0.0;
    double x1 = b2;
    double x2 = -b1;                      /* b x e0 */
    if ((cbx_abs(b1) <= cbx_abs(b0)) && (cbx_abs(b1) <= cbx_abs(b2))) {
        x0 = -b2;
        x1 = 0.0;
        x2 = b0;                          /* b x e1 */
    } else if ((cbx_abs(b2) <= cbx_abs(b0)) && (cbx_abs(b2) < cbx_abs(b1))) {
        x0 = b1;
        x1 = -b0;
        x2 = 0.0;                         /* b x e2 */
    }
    return pb_unitv(x0, x1, x2, 1.0);
}

/* The pieces of the clipped end (the header comment), each in
 * round-to-nearest, clamped: the direction of u = a - alpha b and its
 * norm (pb_uperp); the multiplier s* with the circle's g and
 * rho = sqrt(1 - g^2) (pb_mult); the end s* + h(s*) / wn (pb_tend); the
 * direction of the end's point (pb_cdir).  Small functions: WP's work on
 * a goal grows with the code before it. */
typedef struct pb_uv { pb_q d; double n; } pb_uv;

/* u = a - alpha b: its norm, and its direction, unless u is the rounding
 * of a ~ b (|u| <= 2^-20 |a|): then any unit vector orthogonal to b. */
/*@ requires \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(b0) && \is_finite(b1)
             && \is_finite(b2) && \is_finite(al);
    requires -PS_M <= a0 <= PS_M && -PS_M <= a1 <= PS_M && -PS_M <= a2 <= PS_M;
    requires -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M && -PS_L <= al <= PS_L;
    assigns \nothing;
    ensures pb_qok(\result.d) && \is_finite(\result.n) && 0 <= \result.n <= PS_L;
*/
static pb_uv pb_uperp(double a0, double a1, double a2, double b0, double b1, double b2, double al)
{
    pb_uv o;
    double u0 = ps_sub(a0, ps_mul(al, b0));
    double u1 = ps_sub(a1, ps_mul(al, b1));
    double u2 = ps_sub(a2, ps_mul(al, b2));
    double na = pb_sqrt(ps_dot(a0, a1, a2, a0, a1, a2));
    o.n = pb_sqrt(ps_dot(u0, u1, u2, u0, u1, u2));
    o.d = ((o.n > ps_mul(na, 0x1p-20)) && (o.n >= 0x1p-400)) ? pb_unitv(u0, u1, u2, 1.0) : pb_perp(b0, b1, b2);
    return o;
}

/* s* = alpha + g |u| / (|b| rho), g = (W(c) - wn) / (|r| |b|); ok 0
 * when the plane misses the ball (g not in (-1, 1)) or a divisor is below
 * 2^-400. */
typedef struct pb_mu { double s; double g; double rho; pb_q uh; int ok; } pb_mu;

/*@ requires \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(b0) && \is_finite(b1)
             && \is_finite(b2) && \is_finite(B) && \is_finite(r) && \is_finite(wn);
    requires -PS_M <= a0 <= PS_M && -PS_M <= a1 <= PS_M && -PS_M <= a2 <= PS_M;
    requires -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M;
    requires -PS_L <= B <= PS_L && -PS_M <= r <= PS_M && pn_wn(wn);
    assigns \nothing;
    ensures \result.ok != 0 ==> \is_finite(\result.s) && \is_finite(\result.g) && \is_finite(\result.rho)
      && -PS_L <= \result.s <= PS_L && -1 <= \result.g <= 1 && 0 <= \result.rho <= PS_L
      && pb_qok(\result.uh);
*/
static pb_mu pb_mult(double a0, double a1, double a2, double b0, double b1, double b2,
                     double B, double r, double wn)
{
    pb_mu m;
    double nb2 = ps_dot(b0, b1, b2, b0, b1, b2);
    double nb = pb_sqrt(nb2);
    double rb = ps_mul(cbx_abs(r), nb);
    m.s = 0.0;
    m.g = 0.0;
    m.rho = 0.0;
    m.ok = 0;
    m.uh = pb_perp(1.0, 0.0, 0.0);
    if ((nb2 >= 0x1p-400) && (rb >= 0x1p-400)) {
        double al = ps_qt(ps_dot(a0, a1, a2, b0, b1, b2), nb2);
        double g = ps_qt(ps_sub(B, wn), rb);
        if ((g > -1.0) && (g < 1.0)) {
            double rho = pb_sqrt(ps_sub(1.0, ps_mul(g, g)));
            double den = ps_mul(nb, rho);
            if (den >= 0x1p-400) {
                pb_uv u = pb_uperp(a0, a1, a2, b0, b1, b2, al);
                m.s = ps_add(al, ps_qt(ps_mul(g, u.n), den));
                m.g = g;
                m.rho = rho;
                m.uh = u.d;
                m.ok = 1;
            }
        }
    }
    return m;
}

/* s + h(s) / wn, h(s) = A - s B + |r| |a - s b|. */
/*@ requires \is_finite(s) && \is_finite(a0) && \is_finite(a1) && \is_finite(a2) && \is_finite(b0)
             && \is_finite(b1) && \is_finite(b2) && \is_finite(A) && \is_finite(B) && \is_finite(r)
             && \is_finite(wn);
    requires -PS_L <= s <= PS_L && -PS_M <= a0 <= PS_M && -PS_M <= a1 <= PS_M && -PS_M <= a2 <= PS_M;
    requires -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M;
    requires -PS_L <= A <= PS_L && -PS_L <= B <= PS_L && -PS_M <= r <= PS_M && pn_wn(wn);
    assigns \nothing;
    ensures \is_finite(\result) && -PS_L <= \result <= PS_L;
*/
static double pb_tend(double s, double a0, double a1, double a2, double b0, double b1, double b2,
                      double A, double B, double r, double wn)
{
    double k0 = ps_sub(a0, ps_mul(s, b0));
    double k1 = ps_sub(a1, ps_mul(s, b1));
    double k2 = ps_sub(a2, ps_mul(s, b2));
    double n = pb_sqrt(ps_dot(k0, k1, k2, k0, k1, k2));
    double h = ps_add(ps_sub(A, ps_mul(s, B)), ps_mul(cbx_abs(r), n));
    return ps_add(s, ps_qt(h, wn));
}

/* The end's point on the circle: sign(r) (rho u / |u| - g b / |b|). */
/*@ requires \is_finite(g) && \is_finite(rho) && -1 <= g <= 1 && 0 <= rho <= PS_L && pb_qok(uh);
    requires \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(r);
    requires -PS_M <= b0 <= PS_M && -PS_M <= b1 <= PS_M && -PS_M <= b2 <= PS_M;
    assigns \nothing;
    ensures pb_qok(\result);
*/
static pb_q pb_cdir(double g, double rho, pb_q uh, double b0, double b1, double b2, double r)
{
    pb_q bh = pb_unitv(b0, b1, b2, 1.0);
    pb_q q;
    double sg = (r < 0.0) ? -1.0 : 1.0;
    q.q0 = pb_c1(ps_mul(sg, ps_sub(ps_mul(rho, uh.q0), ps_mul(g, bh.q0))));
    q.q1 = pb_c1(ps_mul(sg, ps_sub(ps_mul(rho, uh.q1), ps_mul(g, bh.q1))));
    q.q2 = pb_c1(ps_mul(sg, ps_sub(ps_mul(rho, uh.q2), ps_mul(g, bh.q2))));
    q.ok = 1;
    return q;
}

/* The end on the circle where the near plane cuts the ball, with the
 * direction of its point; ok 0 when the plane misses the ball or the end
 * is below s* (the unclipped end is the answer then). */
/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    assigns \nothing;
    ensures ok: pb_cok(\result) && \result.clip != 0;
*/
static pb_cand pb_clip(double a0, double a1, double a2, double a3,
                       double b0, double b1, double b2, double b3,
                       double c0, double c1, double c2, double r, double wn)
{
    double A = ps_add(ps_dot(a0, a1, a2, c0, c1, c2), a3);
    double B = ps_add(ps_dot(b0, b1, b2, c0, c1, c2), b3);
    pb_mu m = pb_mult(a0, a1, a2, b0, b1, b2, B, r, wn);
    pb_cand o = pb_none(1);
    if (m.ok != 0) {
        double t = pb_tend(m.s, a0, a1, a2, b0, b1, b2, A, B, r, wn);
        o.q = pb_cdir(m.g, m.rho, m.uh, b0, b1, b2, r);
        if (ps_in(t, PS_C) && ps_in(m.s, PS_C) && (t >= m.s)) {
            o.t = t;
            o.s = m.s;
            o.ok = 1;
        }
    }
    return o;
}

/* ---- the search --------------------------------------------------------- */
typedef struct pb_fin { double v; double w; int ok; } pb_fin;

/* The promise of a found upper end (pb_find, pb_upper), written once: v
 * finite with X <= v W at every point in front, w with some point in front
 * above it, v - w <= ps_tau(v).  A macro, not a predicate: WP then hands
 * the provers the conjuncts themselves (with a predicate over the struct,
 * CVC4 did not unfold it for pb_axis_of's assertion lo within 40 s). */
#define PB_FOUND \
    ensures fin: \result.ok != 0 ==> \is_finite(\result.v) && \is_finite(\result.w) \
      && -PS_B <= \result.v <= PS_B; \
    ensures hi: \result.ok != 0 ==> \
      pb_hi(\result.v, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn) \
      && \result.v - ps_tau(\result.v) <= \result.w \
      && pb_above(\result.w, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);

/* One try: sound at th (with s = s* for a clipped candidate, s = th
 * otherwise), the witness q above tl, th - tl within ps_tau(th) (the
 * cheap span first). */
/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    requires q: \is_finite(q.q0) && \is_finite(q.q1) && \is_finite(q.q2)
                && -1 <= q.q0 <= 1 && -1 <= q.q1 <= 1 && -1 <= q.q2 <= 1;
    requires front: pb_in(wn, b0, b1, b2, b3, c0, c1, c2, r, q.q0, q.q1, q.q2);
    requires t: \is_finite(th) && \is_finite(tl) && \is_finite(s)
                && -PS_B <= th <= PS_B && -PS_B <= tl <= PS_B && -PS_B <= s <= PS_B;
    assigns \nothing;
    ensures hi: \result != 0 ==> pb_hi(th, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
      && th - ps_tau(th) <= tl && pb_above(tl, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
*/
static int pb_try(double th, double tl, double s, int clip, pb_q q, double a0, double a1, double a2, double a3,
                  double b0, double b1, double b2, double b3,
                  double c0, double c1, double c2, double r, double wn)
{
    double m = (clip != 0) ? s : th;
    return (m <= th) && ps_span(th, tl, th)
           && pb_cert(th, m, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
           && pb_wit(tl, q.q0, q.q1, q.q2, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
}

/* The upper end from the candidate c: v with X <= v W at every point in
 * front, w with some point in front above it, v - w <= ps_tau(v). */
/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    requires c: pb_cok(c);
    assigns \nothing;
    PB_FOUND
*/
static pb_fin pb_find(pb_cand c, double a0, double a1, double a2, double a3,
                      double b0, double b1, double b2, double b3,
                      double c0, double c1, double c2, double r, double wn)
{
    pb_fin f;
    double t0 = (c.ok != 0) ? c.t : 0.0;
    double d = cbx_mul_rn(cbx_add_rn(1.0, cbx_abs(t0)), 0x1p-48);
    pb_q q;
    int k;
    f.v = 0.0;
    f.w = 0.0;
    f.ok = 0;
    q.ok = 0;
    if (c.ok != 0) {
        pb_q dir = (c.clip != 0) ? c.q
                 : pb_unitv(ps_sub(a0, ps_mul(t0, b0)), ps_sub(a1, ps_mul(t0, b1)), ps_sub(a2, ps_mul(t0, b2)), r);
        q = pb_witness(dir, b0, b1, b2, b3, c0, c1, c2, r, wn);
    }
    /*@ loop invariant k: 0 <= k <= PB_TRIES;
        loop invariant d: \is_finite(d) && 0 <= d <= 0x1p93;
        loop invariant f: f.ok == 0;
        loop assigns k, d, f;
        loop variant PB_TRIES - k;
    */
    for (k = 0; k < PB_TRIES && d <= 0x1p90 && q.ok != 0; k++) {
        double th = t0 + d;
        double tw = ps_sub(t0, ps_mul(d, 64.0));   /* the witness's room: only th is returned */
        double tl = (ps_in(th, PS_B) && ps_in(tw, PS_B) && ps_span(th, tw, th)) ? tw : (t0 - d);
        if (ps_in(th, PS_B) && ps_in(tl, PS_B)
            && pb_try(th, tl, c.s, c.clip, q, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn)) {
            f.v = th;
            f.w = tl;
            f.ok = 1;
            break;
        }
        d = cbx_mul_rn(d, 4.0);
    }
    return f;
}

/* The roots of the unclipped bound's quadratic (ps_quad), larger first;
 * any sign of den (the ball may cross the camera plane: an end whose
 * tangent point is in front is still a root).  ok 0 when |den| < 2^-400
 * or a root is beyond 2^99. */
typedef struct pb_rts { pb_cand hi; pb_cand lo; } pb_rts;

/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    assigns \nothing;
    ensures hi: pb_cok(\result.hi);
    ensures lo: pb_cok(\result.lo);
*/
static pb_rts pb_roots(double a0, double a1, double a2, double a3,
                       double b0, double b1, double b2, double b3,
                       double c0, double c1, double c2, double r, double wn)
{
    pb_rts o;
    ps_qd e = ps_quad(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r);
    double den = cbx_abs(e.den);
    double h = (e.den < 0.0) ? -e.h : e.h;   /* t = (h -+ sq) / den, den > 0 */
    (void)wn;
    o.hi = pb_none(0);
    o.lo = o.hi;
    if (den >= 0x1p-400) {
        double th = ps_qt(ps_add(h, e.sq), den);
        double tl = ps_qt(ps_sub(h, e.sq), den);
        if (ps_in(th, PS_C) && ps_in(tl, PS_C)) {
            o.hi.t = th;
            o.hi.s = th;
            o.hi.ok = 1;
            o.lo.t = tl;
            o.lo.s = tl;
            o.lo.ok = 1;
        }
    }
    return o;
}

/* The upper end of X / W over the part in front: the clipped candidate
 * first, then the roots of the unclipped bound. */
/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    assigns \nothing;
    PB_FOUND
*/
static pb_fin pb_upper(double a0, double a1, double a2, double a3,
                       double b0, double b1, double b2, double b3,
                       double c0, double c1, double c2, double r, double wn)
{
    pb_cand cc = pb_clip(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    pb_fin f = pb_find(cc, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    if (f.ok == 0) {
        pb_rts u = pb_roots(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
        f = pb_find(u.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
        if (f.ok == 0) {
            f = pb_find(u.lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
        }
    }
    return f;
}

/* ---- one output axis ---------------------------------------------------- */
/*@ requires args: pb_args(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
      && pb_axis(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn)
      && pb_tight(\result.lo, \result.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
*/
static ps_ax pb_axis_of(double a0, double a1, double a2, double a3, double b0, double b1, double b2, double b3,
                        double c0, double c1, double c2, double r, double wn)
{
    ps_ax x;
    pb_fin h = pb_upper(a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    pb_fin l = pb_upper(-a0, -a1, -a2, -a3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    x.lo = 0.0;
    x.hi = 0.0;
    x.ok = 0;
    if ((h.ok != 0) && (l.ok != 0)) {
        x.lo = -l.v;
        x.hi = h.v;
        x.ok = 1;
        /*@ assert lo: pb_lo(x.lo, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn); */
        /*@ assert below: pb_below(-l.w, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn); */
        /*@ assert tl: -l.w <= x.lo + ps_tau(x.lo); */
        /*@ assert cov: pb_axis(x.lo, x.hi, a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, r, wn); */
    }
    return x;
}

/* W < wn on the whole ball: nothing of it in front of the near plane. */
/*@ requires args: pb_args(b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r, wn);
    assigns \nothing;
    ensures void: \result != 0 ==> pb_void(wn, b0, b1, b2, b3, c0, c1, c2, r);
*/
static int pb_behind(double b0, double b1, double b2, double b3,
                     double c0, double c1, double c2, double r, double wn)
{
    ps_gap g = ps_gap_at(0.0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r);
    cbx_iv f = iv_add(g.e, g.k);
    /*@ assert le: pb_le(f.hi, 0, b0, b1, b2, b3, b0, b1, b2, b3, c0, c1, c2, r); */
    return f.hi < wn;
}

/* ---- the public function ------------------------------------------------ */
cbx_status cbx_project_sphere_near(const cbx_proj *p, const double c[3], double r, double wn, cbx_box *out)
{
    if (pb_any_nan(p, c, r, wn) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (!pb_dom_in(p, c, r, wn)) {
        set_whole(out);
        return CBX_ERANGE;
    }
    {
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
        if (pb_behind(w0, w1, w2, wt, c0, c1, c2, r, wn) != 0) {
            set_empty(out);
            return CBX_EMPTY;
        }
        x0 = pb_axis_of(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3], w0, w1, w2, wt, c0, c1, c2, r, wn);
        x1 = pb_axis_of(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3], w0, w1, w2, wt, c0, c1, c2, r, wn);
        x2 = pb_axis_of(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3], w0, w1, w2, wt, c0, c1, c2, r, wn);
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
