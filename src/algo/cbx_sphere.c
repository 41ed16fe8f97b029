/*
 * Exact (dual-quadric) bounds of transformed spheres and ellipsoids.
 *
 * The image of the unit ball under y = M p + T has, on axis i, the exact
 * bounds T_i -+ ||M_i|| (row norm): |M_i . p| <= ||M_i|| ||p|| (Cauchy-
 * Schwarz, specs: cover_ball) with equality at p = M_i / ||M_i||.  Here the
 * row norm is bounded from above in binary64: the squares and their sum in
 * round-to-nearest, widened by 2^-50 relative and 2^-1070 absolute, the
 * square root (correctly rounded), widened by 2^-50 relative; then T_i -+ r
 * is rounded outward.  Rows with every entry below 2^-300 (whose squares
 * may underflow) are scaled by 2^600 first and the radius scaled back, both
 * rounded up (row_radius), so the absolute terms leave no radius floor.
 * An ellipsoid center + rot * diag(radii) * p uses the same kernel on the
 * row |rot_ij * radii_j| rounded up.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_endpoints.h"

/* Lemma functions (empty bodies) on the exact norm rnorm3 = sqrt(b . b)
 * (specs/cbx_ball.h), for the tightness postconditions: each chains
 * one-step lemmas of specs/cbx_ball.h (proven in pass L), one assertion a
 * step, where the float goals need the result. */

/* A number whose square is at most c^2 b.b + a^2 is at most c |b| + a
 * (c = 1 + 10u, a = CBX_SQE: ball_radius's square root). */
/*@ requires pos: 0 <= r;
    requires sq: r * r <= nrm3(b0, b1, b2) * ((1 + 10*CBX_U) * (1 + 10*CBX_U)) + CBX_SQE * CBX_SQE;
    assigns \nothing;
    ensures up: r <= (1 + 10*CBX_U) * rnorm3(b0, b1, b2) + CBX_SQE;
*/
static void rn_up(cbx_fp b0, cbx_fp b1, cbx_fp b2, cbx_fp r)
{
    /*@ assert d: rnorm3(b0, b1, b2) >= 0 && rnorm3(b0, b1, b2) * rnorm3(b0, b1, b2) == nrm3(b0, b1, b2); */
    /*@ assert q: nrm3(b0, b1, b2) * ((1 + 10*CBX_U) * (1 + 10*CBX_U)) + CBX_SQE * CBX_SQE
                  <= ((1 + 10*CBX_U) * rnorm3(b0, b1, b2) + CBX_SQE)
                     * ((1 + 10*CBX_U) * rnorm3(b0, b1, b2) + CBX_SQE); */
    /*@ assert p: (1 + 10*CBX_U) * rnorm3(b0, b1, b2) + CBX_SQE >= 0; */
    /*@ assert s: sq_le(r, (1 + 10*CBX_U) * rnorm3(b0, b1, b2) + CBX_SQE); */
    (void)b0; (void)b1; (void)b2; (void)r;
}

/* A row with an entry of magnitude at least 2^-300 (binary32: 2^-30) has
 * a norm at least that. */
/*@ requires big: CBX_STINY <= \abs(b0) || CBX_STINY <= \abs(b1) || CBX_STINY <= \abs(b2);
    assigns \nothing;
    ensures ge: CBX_STINY <= rnorm3(b0, b1, b2);
*/
static void rn_ge(cbx_fp b0, cbx_fp b1, cbx_fp b2)
{
    /*@ assert d: rnorm3(b0, b1, b2) >= 0 && rnorm3(b0, b1, b2) * rnorm3(b0, b1, b2) == nrm3(b0, b1, b2); */
    /*@ assert z: nrm3(0, b1, b2) >= 0 && nrm3(b0, 0, b2) >= 0 && nrm3(b0, b1, 0) >= 0; */
    /*@ assert s0: CBX_STINY <= \abs(b0) ==> sq_le(CBX_STINY, b0); */
    /*@ assert s1: CBX_STINY <= \abs(b1) ==> sq_le(CBX_STINY, b1); */
    /*@ assert s2: CBX_STINY <= \abs(b2) ==> sq_le(CBX_STINY, b2); */
    /*@ assert n0: sq_le(CBX_STINY, b0) ==> CBX_STINY * CBX_STINY <= nrm3(b0, b1, b2); */
    /*@ assert n1: sq_le(CBX_STINY, b1) ==> CBX_STINY * CBX_STINY <= nrm3(b0, b1, b2); */
    /*@ assert n2: sq_le(CBX_STINY, b2) ==> CBX_STINY * CBX_STINY <= nrm3(b0, b1, b2); */
    /*@ assert s: sq_le(CBX_STINY, rnorm3(b0, b1, b2)); */
    (void)b0; (void)b1; (void)b2;
}

/* The expansion of sum ((1 + 8u) |a_j| + e)^2 (a_j = r_j d_j). */
/*@ assigns \nothing;
    ensures id: nrm3((1 + 8*CBX_U) * \abs(r0*d0) + CBX_ETA64, (1 + 8*CBX_U) * \abs(r1*d1) + CBX_ETA64, (1 + 8*CBX_U) * \abs(r2*d2) + CBX_ETA64)
                   == ((1 + 8*CBX_U) * (1 + 8*CBX_U)) * nrm3(\abs(r0*d0), \abs(r1*d1), \abs(r2*d2))
                      + (2 * (1 + 8*CBX_U) * CBX_ETA64) * (\abs(r0*d0) + \abs(r1*d1) + \abs(r2*d2))
                      + 3 * CBX_ETA64 * CBX_ETA64;
*/
static void rn_shift(cbx_fp r0, cbx_fp r1, cbx_fp r2, cbx_fp d0, cbx_fp d1, cbx_fp d2)
{
    (void)r0; (void)r1; (void)r2; (void)d0; (void)d1; (void)d2;
}

/* Entries each at most (1 + 8u) |a_j| + 2^-1068 (binary32: 2^-143), as
 * abs_prod_up returns them (a_j = r_j d_j exactly), have a norm at most
 * (1 + 8u) |a| + 2^-1067: s.s <= sum ((1 + 8u) |a_j| + e)^2 =
 * (1 + 8u)^2 |a|^2 + 2 (1 + 8u) e sum |a_j| + 3 e^2, and sum |a_j| <= 2 |a|. */
/*@ requires s: 0 <= s0 <= (1 + 8*CBX_U) * \abs(r0*d0) + CBX_ETA64
                && 0 <= s1 <= (1 + 8*CBX_U) * \abs(r1*d1) + CBX_ETA64
                && 0 <= s2 <= (1 + 8*CBX_U) * \abs(r2*d2) + CBX_ETA64;
    assigns \nothing;
    ensures up: rnorm3(s0, s1, s2) <= (1 + 8*CBX_U) * rnorm3(r0*d0, r1*d1, r2*d2) + CBX_ETA128;
*/
static void rn_pert(cbx_fp r0, cbx_fp r1, cbx_fp r2, cbx_fp d0, cbx_fp d1, cbx_fp d2,
                    cbx_fp s0, cbx_fp s1, cbx_fp s2)
{
    /*@ assert sum4: (\abs(r0*d0) + \abs(r1*d1) + \abs(r2*d2)) * (\abs(r0*d0) + \abs(r1*d1) + \abs(r2*d2))
                     <= 4 * nrm3(\abs(r0*d0), \abs(r1*d1), \abs(r2*d2)); */
    /*@ assert x: nrm3(\abs(r0*d0), \abs(r1*d1), \abs(r2*d2)) == nrm3(r0*d0, r1*d1, r2*d2); */
    /*@ assert da: rnorm3(r0*d0, r1*d1, r2*d2) >= 0
                   && rnorm3(r0*d0, r1*d1, r2*d2) * rnorm3(r0*d0, r1*d1, r2*d2) == nrm3(r0*d0, r1*d1, r2*d2); */
    /*@ assert sum2: sq_le(\abs(r0*d0) + \abs(r1*d1) + \abs(r2*d2), 2 * rnorm3(r0*d0, r1*d1, r2*d2)); */
    /*@ assert ds: rnorm3(s0, s1, s2) >= 0 && rnorm3(s0, s1, s2) * rnorm3(s0, s1, s2) == nrm3(s0, s1, s2); */
    /*@ assert q: sq_le(s0, (1 + 8*CBX_U) * \abs(r0*d0) + CBX_ETA64) && sq_le(s1, (1 + 8*CBX_U) * \abs(r1*d1) + CBX_ETA64)
                  && sq_le(s2, (1 + 8*CBX_U) * \abs(r2*d2) + CBX_ETA64); */
    /*@ assert n: nrm3(s0, s1, s2) <= nrm3((1 + 8*CBX_U) * \abs(r0*d0) + CBX_ETA64, (1 + 8*CBX_U) * \abs(r1*d1) + CBX_ETA64,
                                           (1 + 8*CBX_U) * \abs(r2*d2) + CBX_ETA64); */
    rn_shift(r0, r1, r2, d0, d1, d2);
    /*@ assert m: nrm3(s0, s1, s2) <= ((1 + 8*CBX_U) * rnorm3(r0*d0, r1*d1, r2*d2) + 2 * CBX_ETA64)
                                      * ((1 + 8*CBX_U) * rnorm3(r0*d0, r1*d1, r2*d2) + 2 * CBX_ETA64); */
    /*@ assert r: sq_le(rnorm3(s0, s1, s2), (1 + 8*CBX_U) * rnorm3(r0*d0, r1*d1, r2*d2) + 2 * CBX_ETA64); */
    (void)r0; (void)r1; (void)r2; (void)d0; (void)d1; (void)d2; (void)s0; (void)s1; (void)s2;
}

/* Lemma function: scaling a row by 2^k scales its squared norm by 2^2k
 * (in row_radius's context the step timed out). */
/*@ assigns \nothing;
    ensures sc: nrm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP) == nrm3(b0, b1, b2) * (CBX_SUP*CBX_SUP);
*/
static void nrm3_up(cbx_fp b0, cbx_fp b1, cbx_fp b2)
{
    (void)b0; (void)b1; (void)b2;
}

/* Scaling a row by 2^600 (binary32: 2^90) scales its norm by 2^600. */
/*@ assigns \nothing;
    ensures sc: rnorm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP) == CBX_SUP * rnorm3(b0, b1, b2);
*/
static void rn_scale(cbx_fp b0, cbx_fp b1, cbx_fp b2)
{
    nrm3_up(b0, b1, b2);
    /*@ assert d: rnorm3(b0, b1, b2) >= 0 && rnorm3(b0, b1, b2) * rnorm3(b0, b1, b2) == nrm3(b0, b1, b2); */
    /*@ assert e: rnorm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP) >= 0
                  && rnorm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP) * rnorm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP)
                     == nrm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP); */
    /*@ assert f: sq_le(rnorm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP), CBX_SUP * rnorm3(b0, b1, b2))
                  && sq_le(CBX_SUP * rnorm3(b0, b1, b2), rnorm3(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP)); */
    (void)b0; (void)b1; (void)b2;
}

/* An upper bound r of the norm of (b0, b1, b2): b . b <= r^2. */
/* proof: -wp-split */
/*@ requires fin: \is_finite(b0) && \is_finite(b1) && \is_finite(b2);
    requires rng: cls(b0, b0, CBX_SB, CBX_SB) && cls(b1, b1, CBX_SB, CBX_SB)
                  && cls(b2, b2, CBX_SB, CBX_SB);
    assigns \nothing;
    ensures fin: \is_finite(\result) && 0 <= \result <= CBX_SR2;
    ensures bound: sq_bound(b0, b1, b2, \result);
    ensures tight: \result <= (1 + 22*CBX_U) * rnorm3(b0, b1, b2) + CBX_SA;
*/
static cbx_fp ball_radius(cbx_fp b0, cbx_fp b1, cbx_fp b2)
{
    /* the squares' signs from lemma nrm3_pos (CVC4 does not find x*x >= 0
     * by itself in WP's float context: it timed out, and Z3 took 7 s) */
    /*@ assert sq0: nrm3(b0, 0, 0) >= 0 && nrm3(b1, 0, 0) >= 0 && nrm3(b2, 0, 0) >= 0; */
    /*@ assert sq: b0*b0 >= 0 && b1*b1 >= 0 && b2*b2 >= 0; */
    cbx_fp q0 = cbx_mul_rn(b0, b0);
    cbx_fp q1 = cbx_mul_rn(b1, b1);
    cbx_fp q2 = cbx_mul_rn(b2, b2);
    /*@ assert q: q0 >= b0*b0 * (1 - CBX_U) - CBX_ETA && q1 >= b1*b1 * (1 - CBX_U) - CBX_ETA
                  && q2 >= b2*b2 * (1 - CBX_U) - CBX_ETA; */
    /*@ assert qpos: q0 >= 0 && q1 >= 0 && q2 >= 0; */
    cbx_fp s1 = cbx_add_rn(q0, q1);
    cbx_fp s2 = cbx_add_rn(s1, q2);
    /*@ assert s: s2 >= nrm3(b0, b1, b2) * (1 - CBX_U4) - CBX_ETA8 && s2 >= 0; */
    /*@ assert smax: s2 <= CBX_R20; */
    cbx_fp e = cbx_mul_rn(s2, CBX_K(U8));
    cbx_fp f = cbx_add_rn(s2, e);
    cbx_fp su = cbx_add_rn(f, CBX_K(ETA16));
    /*@ assert su: su >= nrm3(b0, b1, b2) && su <= CBX_R21; */
    /*@ assert qu: q0 <= b0*b0 * (1 + CBX_U) + CBX_ETA && q1 <= b1*b1 * (1 + CBX_U) + CBX_ETA
                   && q2 <= b2*b2 * (1 + CBX_U) + CBX_ETA; */
    /*@ assert s2u: s2 <= nrm3(b0, b1, b2) * (1 + CBX_U4) + CBX_ETA8; */
    /*@ assert suu: su <= nrm3(b0, b1, b2) * (1 + 16*CBX_U) + CBX_ETA64; */
    cbx_fp r = cbx_sqrt_rn(su);
    /*@ assert rb: sq_le(r, CBX_SR1); */
    /*@ assert rb2: r <= CBX_SR1; */
    cbx_fp e2 = cbx_mul_rn(r, CBX_K(U8));
    cbx_fp ru = cbx_add_rn(cbx_add_rn(r, e2), CBX_K(ETA16));
    /*@ assert ru1: ru >= r * (1 + CBX_U2); */
    /*@ assert ru2: sq_le(r * (1 + CBX_U2), ru); */
    /*@ assert ru3: ru * ru >= su; */
    /*@ assert rr: r * r <= nrm3(b0, b1, b2) * ((1 + 10*CBX_U) * (1 + 10*CBX_U)) + CBX_SQE * CBX_SQE; */
    rn_up(b0, b1, b2, r);
    /*@ assert ruu: ru <= r * (1 + 11*CBX_U) + CBX_ETA64; */
    /*@ assert rn: rnorm3(b0, b1, b2) >= 0; */
    return ru;
}

/* An upper bound of |r * d| (exact product): the ellipsoid's rows, and the
 * scalings of row_radius. */
/*@ requires fin: \is_finite(r) && \is_finite(d);
    requires rng: in_dom508(r, d);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures up: \abs(r*d) <= \result <= CBX_SB;
    ensures tight: \result <= (1 + 8*CBX_U) * \abs(r*d) + CBX_ETA64;
*/
static cbx_fp abs_prod_up(cbx_fp r, cbx_fp d)
{
    cbx_fp e = cbx_abs(cbx_mul_rn(r, d));
    /*@ assert eu: e <= \abs(r*d) * (1 + CBX_U) + CBX_ETA; */
    cbx_fp f = cbx_add_rn(e, cbx_mul_rn(e, CBX_K(U4)));
    /*@ assert fu: f <= e * (1 + 6*CBX_U) + CBX_ETA4; */
    return cbx_add_rn(f, CBX_K(ETA16));
}

/* An upper bound r of the norm of (b0, b1, b2), accurate for every row: a
 * row with all |b_j| < 2^-300 (whose squares may underflow) is first scaled
 * by 2^600, and its radius scaled back by 2^-600, both rounded up. */
/* proof: -wp-split */
/*@ requires fin: \is_finite(b0) && \is_finite(b1) && \is_finite(b2);
    requires rng: cls(b0, b0, CBX_SB, CBX_SB) && cls(b1, b1, CBX_SB, CBX_SB)
                  && cls(b2, b2, CBX_SB, CBX_SB);
    assigns \nothing;
    ensures fin: \is_finite(\result) && 0 <= \result <= CBX_SR2;
    ensures bound: sq_bound(b0, b1, b2, \result);
    ensures tight: \result <= (1 + 40*CBX_U) * rnorm3(b0, b1, b2) + CBX_ETA128;
*/
static cbx_fp row_radius(cbx_fp b0, cbx_fp b1, cbx_fp b2)
{
    if (!cbx_cls(b0, b1, CBX_K(STINY), CBX_K(STINY)) || !cbx_cls(b2, b2, CBX_K(STINY), CBX_K(STINY))) {
        cbx_fp rb = ball_radius(b0, b1, b2);
        /*@ assert big: CBX_STINY <= \abs(b0) || CBX_STINY <= \abs(b1) || CBX_STINY <= \abs(b2); */
        rn_ge(b0, b1, b2);
        return rb;
    }
    cbx_fp s0 = abs_prod_up(b0, CBX_K(SUP));
    cbx_fp s1 = abs_prod_up(b1, CBX_K(SUP));
    cbx_fp s2 = abs_prod_up(b2, CBX_K(SUP));
    cbx_fp rs = ball_radius(s0, s1, s2);
    /*@ assert sq0: sq_le(b0*CBX_SUP, s0) && sq_le(b1*CBX_SUP, s1) && sq_le(b2*CBX_SUP, s2); */
    /*@ assert sbs: sq_bound(b0*CBX_SUP, b1*CBX_SUP, b2*CBX_SUP, rs); */
    /* the scaling as two identities (one step from sbs to sb timed out):
     * the squared norm's (lemma function nrm3_up) and the radius's */
    nrm3_up(b0, b1, b2);
    /*@ assert sb2: (rs*CBX_SDN)*(rs*CBX_SDN) == (rs*rs) * (CBX_SDN*CBX_SDN); */
    /*@ assert sb: sq_bound(b0, b1, b2, rs*CBX_SDN); */
    cbx_fp r = abs_prod_up(rs, CBX_K(SDN));
    /*@ assert rr: rs*CBX_SDN <= r; */
    /*@ assert su: s0 <= (1 + 8*CBX_U) * \abs(b0*CBX_SUP) + CBX_ETA64
                   && s1 <= (1 + 8*CBX_U) * \abs(b1*CBX_SUP) + CBX_ETA64
                   && s2 <= (1 + 8*CBX_U) * \abs(b2*CBX_SUP) + CBX_ETA64
                   && 0 <= s0 && 0 <= s1 && 0 <= s2; */
    rn_pert(b0, b1, b2, CBX_K(SUP), CBX_K(SUP), CBX_K(SUP), s0, s1, s2);
    rn_scale(b0, b1, b2);
    /*@ assert rsn: rnorm3(s0, s1, s2) <= (1 + 8*CBX_U) * CBX_SUP * rnorm3(b0, b1, b2) + CBX_ETA128; */
    /*@ assert rn: rnorm3(b0, b1, b2) >= 0 && rs >= 0; */
    /*@ assert rsu: rs <= (1 + 22*CBX_U) * ((1 + 8*CBX_U) * CBX_SUP * rnorm3(b0, b1, b2) + CBX_ETA128) + CBX_SA; */
    /*@ assert ru: r <= (1 + 8*CBX_U) * (rs * CBX_SDN) + CBX_ETA64; */
    return r;
}

/* Bounds [lo, hi] of t + b . p over the unit ball. */
/*@ requires fin: \is_finite(b0) && \is_finite(b1) && \is_finite(b2) && \is_finite(t);
    requires rng: cls(b0, b0, CBX_SB, CBX_SB) && cls(b1, b1, CBX_SB, CBX_SB)
                  && cls(b2, b2, CBX_SB, CBX_SB);
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures fin: \is_finite(\result.a) && \is_finite(\result.b);
    ensures ball: ball_cover(\result.a, \result.b, b0, b1, b2, t);
    ensures tight: ball_tight(\result.a, \result.b, b0, b1, b2, t);
*/
static conv_res ball_axis_bounds(cbx_fp b0, cbx_fp b1, cbx_fp b2, cbx_fp t)
{
    cbx_fp r = row_radius(b0, b1, b2);
    conv_res lh = cbx_c2b(t, r);
    /*@ assert lh: lh.a <= t - r && t + r <= lh.b; */
    /*@ assert rn: rnorm3(b0, b1, b2) >= 0 && r >= 0; */
    /*@ assert g: conv_gap(t, r) <= CBX_U16 * \abs(t) + CBX_U16 * ((1 + 40*CBX_U) * rnorm3(b0, b1, b2) + CBX_ETA128) + CBX_ETA256; */
    /*@ assert ta: (t - rnorm3(b0, b1, b2)) - ball_gap(t, rnorm3(b0, b1, b2)) <= lh.a; */
    /*@ assert tb: lh.b <= (t + rnorm3(b0, b1, b2)) + ball_gap(t, rnorm3(b0, b1, b2)); */
    return lh;
}

/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(m0) && \is_finite(m1) && \is_finite(m2)
                               && \is_finite(t) && sph_dom(m0, m1, m2, t));
*/
static int sph_ok(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t)
{
    if (!cbx_is_fin(m0) || !cbx_is_fin(m1) || !cbx_is_fin(m2) || !cbx_is_fin(t)) {
        return 0;
    }
    if (!cbx_cls(m0, m0, CBX_K(SB), CBX_K(SB))) {
        return 0;
    }
    if (!cbx_cls(m1, m1, CBX_K(SB), CBX_K(SB))) {
        return 0;
    }
    if (!cbx_cls(m2, m2, CBX_K(SB), CBX_K(SB))) {
        return 0;
    }
    return (t >= -CBX_K(RT)) && (t <= CBX_K(RT));
}

/*@ requires \valid(out) && 0 <= i <= 2;
    assigns out->lo[i], out->hi[i];
    ensures whole_axis(out, i);
*/
static void sph_whole(cbx_box *out, int i)
{
    out->lo[i] = cbx_ninf();
    out->hi[i] = cbx_pinf();
}

/* One axis of a ball's box (sphere or ellipsoid): its ends, and whether
 * the row was in the domain. */
typedef struct ball_res { cbx_fp lo; cbx_fp hi; int ok; } ball_res;

/* One axis of the sphere: the kernel inside the domain, [-inf, +inf]
 * outside it (values in and out, as for the ellipsoid: the status's goal
 * then needs no reasoning about memory). */
/*@ assigns \nothing;
    ensures ok: \result.ok != 0 <==> (\is_finite(m0) && \is_finite(m1) && \is_finite(m2)
      && \is_finite(t) && sph_dom(m0, m1, m2, t));
    ensures in: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
      && ball_axis(\result.lo, \result.hi, m0, m1, m2, t)
      && ball_tight(\result.lo, \result.hi, m0, m1, m2, t);
    ensures out: \result.ok == 0 ==>
      \is_minus_infinity(\result.lo) && \is_plus_infinity(\result.hi);
*/
static ball_res sphere_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t)
{
    ball_res e;
    e.ok = sph_ok(m0, m1, m2, t);
    if (e.ok != 0) {
        conv_res lh = ball_axis_bounds(m0, m1, m2, t);
        e.lo = lh.a;
        e.hi = lh.b;
    } else {
        e.lo = cbx_ninf();
        e.hi = cbx_pinf();
    }
    return e;
}

/* contract: include/certbox.h */
cbx_status cbx_sphere_box(const cbx_affine *a, cbx_box *out)
{
    if (aff_any_nan(a) != 0) {
        sph_whole(out, 0);
        sph_whole(out, 1);
        sph_whole(out, 2);
        return CBX_EINVAL;
    }
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
    ball_res e0 = sphere_axis(a00, a01, a02, a03);
    ball_res e1 = sphere_axis(a10, a11, a12, a13);
    ball_res e2 = sphere_axis(a20, a21, a22, a23);
    out->lo[0] = e0.lo; out->hi[0] = e0.hi;
    out->lo[1] = e1.lo; out->hi[1] = e1.hi;
    out->lo[2] = e2.lo; out->hi[2] = e2.hi;
    /* the proof reads the map again in the final state: it is unchanged */
    /*@ assert same_in: a->m[0][0] == a00 && a->m[0][1] == a01 && a->m[0][2] == a02
          && a->m[0][3] == a03 && a->m[1][0] == a10 && a->m[1][1] == a11
          && a->m[1][2] == a12 && a->m[1][3] == a13 && a->m[2][0] == a20
          && a->m[2][1] == a21 && a->m[2][2] == a22 && a->m[2][3] == a23; */
    /*@ assert same_out: out->lo[0] == e0.lo && out->hi[0] == e0.hi
          && out->lo[1] == e1.lo && out->hi[1] == e1.hi
          && out->lo[2] == e2.lo && out->hi[2] == e2.hi; */
    /* the status's facts before the status (ok_iff took 10 to 14 s whole) */
    /*@ assert ok: (e0.ok != 0 <==> sph_row_dom(a, 0)) && (e1.ok != 0 <==> sph_row_dom(a, 1))
          && (e2.ok != 0 <==> sph_row_dom(a, 2)); */
    return (e0.ok && e1.ok && e2.ok) ? CBX_OK : CBX_ERANGE;
}

/* Bounds of center + (r0 d0, r1 d1, r2 d2) . p over the unit ball. */
/*@ requires fin: \is_finite(r0) && \is_finite(r1) && \is_finite(r2)
                  && \is_finite(d0) && \is_finite(d1) && \is_finite(d2) && \is_finite(c);
    requires dom: ell_dom(r0, r1, r2, d0, d1, d2, c);
    assigns \nothing;
    ensures fin: \is_finite(\result.a) && \is_finite(\result.b);
    ensures ball: ball_cover(\result.a, \result.b, r0*d0, r1*d1, r2*d2, c);
    ensures tight: ball_tight(\result.a, \result.b, r0*d0, r1*d1, r2*d2, c);
*/
static conv_res ell_axis_bounds(cbx_fp r0, cbx_fp r1, cbx_fp r2,
                                cbx_fp d0, cbx_fp d1, cbx_fp d2, cbx_fp c)
{
    cbx_fp b0 = abs_prod_up(r0, d0);
    cbx_fp b1 = abs_prod_up(r1, d1);
    cbx_fp b2 = abs_prod_up(r2, d2);
    cbx_fp r = row_radius(b0, b1, b2);
    /*@ assert sq0: sq_le(r0*d0, b0) && sq_le(r1*d1, b1) && sq_le(r2*d2, b2); */
    /*@ assert sb: sq_bound(r0*d0, r1*d1, r2*d2, r); */
    conv_res lh = cbx_c2b(c, r);
    /*@ assert lh: lh.a <= c - r && c + r <= lh.b; */
    rn_pert(r0, r1, r2, d0, d1, d2, b0, b1, b2);
    /*@ assert rn: rnorm3(r0*d0, r1*d1, r2*d2) >= 0 && r >= 0; */
    /*@ assert rb: rnorm3(b0, b1, b2) <= (1 + 8*CBX_U) * rnorm3(r0*d0, r1*d1, r2*d2) + CBX_ETA128; */
    /*@ assert ru: r <= (1 + 49*CBX_U) * rnorm3(r0*d0, r1*d1, r2*d2) + CBX_ETA256 + 48*CBX_U*CBX_ETA128; */
    /*@ assert g: conv_gap(c, r) <= CBX_U16 * \abs(c) + CBX_U16 * ((1 + 49*CBX_U) * rnorm3(r0*d0, r1*d1, r2*d2) + CBX_ETA512) + CBX_ETA256; */
    /*@ assert ta: (c - rnorm3(r0*d0, r1*d1, r2*d2)) - ball_gap(c, rnorm3(r0*d0, r1*d1, r2*d2)) <= lh.a; */
    /*@ assert tb: lh.b <= (c + rnorm3(r0*d0, r1*d1, r2*d2)) + ball_gap(c, rnorm3(r0*d0, r1*d1, r2*d2)); */
    return lh;
}

/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(r0) && \is_finite(r1) && \is_finite(r2)
      && \is_finite(d0) && \is_finite(d1) && \is_finite(d2) && \is_finite(c)
      && ell_dom(r0, r1, r2, d0, d1, d2, c));
*/
static int ell_ok(cbx_fp r0, cbx_fp r1, cbx_fp r2, cbx_fp d0, cbx_fp d1, cbx_fp d2, cbx_fp c)
{
    if (!cbx_is_fin(r0) || !cbx_is_fin(r1) || !cbx_is_fin(r2)) {
        return 0;
    }
    if (!cbx_is_fin(d0) || !cbx_is_fin(d1) || !cbx_is_fin(d2) || !cbx_is_fin(c)) {
        return 0;
    }
    if (!cbx_cls(r0, d0, CBX_K(EB), CBX_K(EB))) {
        return 0;
    }
    if (!cbx_cls(r1, d1, CBX_K(EB), CBX_K(EB))) {
        return 0;
    }
    if (!cbx_cls(r2, d2, CBX_K(EB), CBX_K(EB))) {
        return 0;
    }
    return (c >= -CBX_K(RT)) && (c <= CBX_K(RT));
}

/*@ requires \valid_read(center + (0 .. 2)) && \valid_read(radii + (0 .. 2))
             && \valid_read(rot + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> ell_nan(center, radii, rot);
*/
static int ell_any_nan(const cbx_fp *center, const cbx_fp *radii, const cbx_fp (*rot)[3])
{
    return cbx_is_nan(center[0]) | cbx_is_nan(center[1]) | cbx_is_nan(center[2]) | cbx_is_nan(radii[0])
           | cbx_is_nan(radii[1]) | cbx_is_nan(radii[2]) | cbx_is_nan(rot[0][0]) | cbx_is_nan(rot[0][1])
           | cbx_is_nan(rot[0][2]) | cbx_is_nan(rot[1][0]) | cbx_is_nan(rot[1][1]) | cbx_is_nan(rot[1][2])
           | cbx_is_nan(rot[2][0]) | cbx_is_nan(rot[2][1]) | cbx_is_nan(rot[2][2]);
}

/* One axis of the ellipsoid: the kernel inside the domain, [-inf, +inf]
 * outside it. */
/*@ assigns \nothing;
    ensures ok: \result.ok != 0 <==> (\is_finite(r0) && \is_finite(r1) && \is_finite(r2)
      && \is_finite(d0) && \is_finite(d1) && \is_finite(d2) && \is_finite(c)
      && ell_dom(r0, r1, r2, d0, d1, d2, c));
    ensures in: \result.ok != 0 ==> \is_finite(\result.lo) && \is_finite(\result.hi)
      && ball_axis(\result.lo, \result.hi, r0*d0, r1*d1, r2*d2, c)
      && ball_tight(\result.lo, \result.hi, r0*d0, r1*d1, r2*d2, c);
    ensures out: \result.ok == 0 ==>
      \is_minus_infinity(\result.lo) && \is_plus_infinity(\result.hi);
*/
static ball_res ellipsoid_axis(cbx_fp r0, cbx_fp r1, cbx_fp r2,
                              cbx_fp d0, cbx_fp d1, cbx_fp d2, cbx_fp c)
{
    ball_res e;
    e.ok = ell_ok(r0, r1, r2, d0, d1, d2, c);
    if (e.ok != 0) {
        conv_res lh = ell_axis_bounds(r0, r1, r2, d0, d1, d2, c);
        e.lo = lh.a;
        e.hi = lh.b;
    } else {
        e.lo = cbx_ninf();
        e.hi = cbx_pinf();
    }
    return e;
}

/* contract: include/certbox.h */
cbx_status cbx_ellipsoid_box(const cbx_fp center[3], const cbx_fp radii[3],
                             const cbx_fp rot[3][3], cbx_box *out)
{
    if (ell_any_nan(center, radii, rot) != 0) {
        sph_whole(out, 0);
        sph_whole(out, 1);
        sph_whole(out, 2);
        return CBX_EINVAL;
    }
    cbx_fp d0 = radii[0];
    cbx_fp d1 = radii[1];
    cbx_fp d2 = radii[2];
    cbx_fp c0 = center[0];
    cbx_fp c1 = center[1];
    cbx_fp c2 = center[2];
    cbx_fp r00 = rot[0][0];
    cbx_fp r01 = rot[0][1];
    cbx_fp r02 = rot[0][2];
    cbx_fp r10 = rot[1][0];
    cbx_fp r11 = rot[1][1];
    cbx_fp r12 = rot[1][2];
    cbx_fp r20 = rot[2][0];
    cbx_fp r21 = rot[2][1];
    cbx_fp r22 = rot[2][2];
    ball_res e0 = ellipsoid_axis(r00, r01, r02, d0, d1, d2, c0);
    ball_res e1 = ellipsoid_axis(r10, r11, r12, d0, d1, d2, c1);
    ball_res e2 = ellipsoid_axis(r20, r21, r22, d0, d1, d2, c2);
    out->lo[0] = e0.lo; out->hi[0] = e0.hi;
    out->lo[1] = e1.lo; out->hi[1] = e1.hi;
    out->lo[2] = e2.lo; out->hi[2] = e2.hi;
    /* the proof reads the inputs again in the final state: they are unchanged */
    /*@ assert same_in: rot[0][0] == r00 && rot[0][1] == r01 && rot[0][2] == r02
          && rot[1][0] == r10 && rot[1][1] == r11 && rot[1][2] == r12
          && rot[2][0] == r20 && rot[2][1] == r21 && rot[2][2] == r22
          && radii[0] == d0 && radii[1] == d1 && radii[2] == d2
          && center[0] == c0 && center[1] == c1 && center[2] == c2; */
    /*@ assert same_out: out->lo[0] == e0.lo && out->hi[0] == e0.hi
          && out->lo[1] == e1.lo && out->hi[1] == e1.hi
          && out->lo[2] == e2.lo && out->hi[2] == e2.hi; */
    return (e0.ok && e1.ok && e2.ok) ? CBX_OK : CBX_ERANGE;
}


/* ---- the 2D forms: disk and ellipse (specs/cbx_plane.h) ------------------
 * Each axis is the sphere's or the ellipsoid's axis function with a zero
 * third entry; lemma ball_disk turns its 3D cover into the disk's. */

/* contract: include/cbx_api.h */
cbx_status cbx_disk_box2(const cbx_affine2 *a, cbx_box2 *out)
{
    if (aff2_any_nan(a) != 0) {
        set_whole2(out);
        return CBX_EINVAL;
    }
    cbx_fp z = CBX_C(0.0);
    cbx_fp a00 = a->m[0][0];
    cbx_fp a01 = a->m[0][1];
    cbx_fp a02 = a->m[0][2];
    cbx_fp a10 = a->m[1][0];
    cbx_fp a11 = a->m[1][1];
    cbx_fp a12 = a->m[1][2];
    ball_res e0 = sphere_axis(a00, a01, z, a02);
    ball_res e1 = sphere_axis(a10, a11, z, a12);
    out->lo[0] = e0.lo; out->hi[0] = e0.hi;
    out->lo[1] = e1.lo; out->hi[1] = e1.hi;
    /*@ assert same_in: a->m[0][0] == a00 && a->m[0][1] == a01 && a->m[0][2] == a02
          && a->m[1][0] == a10 && a->m[1][1] == a11 && a->m[1][2] == a12; */
    /*@ assert same_out: out->lo[0] == e0.lo && out->hi[0] == e0.hi
          && out->lo[1] == e1.lo && out->hi[1] == e1.hi; */
    return (e0.ok && e1.ok) ? CBX_OK : CBX_ERANGE;
}

/*@ requires \valid_read(center + (0 .. 1)) && \valid_read(radii + (0 .. 1))
             && \valid_read(rot + (0 .. 1));
    assigns \nothing;
    ensures \result != 0 <==> ell2_nan(center, radii, rot);
*/
static int ell2_any_nan(const cbx_fp *center, const cbx_fp *radii, const cbx_fp (*rot)[2])
{
    return cbx_is_nan(center[0]) | cbx_is_nan(center[1]) | cbx_is_nan(radii[0]) | cbx_is_nan(radii[1])
           | cbx_is_nan(rot[0][0]) | cbx_is_nan(rot[0][1]) | cbx_is_nan(rot[1][0]) | cbx_is_nan(rot[1][1]);
}

/* contract: include/cbx_api.h */
cbx_status cbx_ellipse_box2(const cbx_fp center[2], const cbx_fp radii[2],
                            const cbx_fp rot[2][2], cbx_box2 *out)
{
    if (ell2_any_nan(center, radii, rot) != 0) {
        set_whole2(out);
        return CBX_EINVAL;
    }
    cbx_fp z = CBX_C(0.0);
    cbx_fp d0 = radii[0];
    cbx_fp d1 = radii[1];
    cbx_fp c0 = center[0];
    cbx_fp c1 = center[1];
    cbx_fp r00 = rot[0][0];
    cbx_fp r01 = rot[0][1];
    cbx_fp r10 = rot[1][0];
    cbx_fp r11 = rot[1][1];
    ball_res e0 = ellipsoid_axis(r00, r01, z, d0, d1, z, c0);
    ball_res e1 = ellipsoid_axis(r10, r11, z, d0, d1, z, c1);
    out->lo[0] = e0.lo; out->hi[0] = e0.hi;
    out->lo[1] = e1.lo; out->hi[1] = e1.hi;
    /*@ assert same_in: rot[0][0] == r00 && rot[0][1] == r01 && rot[1][0] == r10
          && rot[1][1] == r11 && radii[0] == d0 && radii[1] == d1
          && center[0] == c0 && center[1] == c1; */
    /*@ assert same_out: out->lo[0] == e0.lo && out->hi[0] == e0.hi
          && out->lo[1] == e1.lo && out->hi[1] == e1.hi; */
    return (e0.ok && e1.ok) ? CBX_OK : CBX_ERANGE;
}
